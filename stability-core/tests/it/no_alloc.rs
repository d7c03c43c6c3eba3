//! The hot path allocates nothing: the generated coefficient and gradient
//! functions, the quartic's roots and a derivative set's whole analysis
//! (roots at any scale, modes, Routh, §8 criteria, eq 7 check), and a
//! design point's evaluation from its planform (coefficients, derivatives
//! of every model, the supersonic theory's own coefficients and their
//! numerical Mach derivatives, the frequency iteration, warnings). A
//! counting global allocator sees no allocation while they run
//! ([`allocations_in`]: the allocations of the thread that asked).
//!
//! The lifting surface's design points are included once its solves are in
//! the cache (allocation on first use is allowed; after it, a design point
//! is a cache lookup and an axis transfer, and a sweep's frequency
//! iteration an interpolation).

use crate::allocations::allocations_in;
use stability_core::{Quartic, QuarticGradient};
use std::hint::black_box;

/// The lifting surface's design points: damping and coefficients, at a
/// given ω̄, and iterated (directly and interpolated).
fn lifting_surface_cases() -> Vec<LiftingCase> {
    use stability_core::aerodynamics::damping::Theory;
    use stability_core::aerodynamics::lifting_surface::Harmonic;
    use stability_core::aerodynamics::models::aero::{AeroModel, AeroModelName};
    use stability_core::design::case::{Case, DampingModel};
    let at = |deg: f64, mach: f64, t: Theory, omega_bar: Option<f64>| Case {
        damping: DampingModel::Theory(t),
        aero: AeroModel::default().with_name(AeroModelName::LiftingSurface),
        omega_bar,
        ..stability_core::design::study::report_wing(deg, mach)
    };
    vec![
        (
            at(45.0, 0.6, Theory::LiftingSurface, None),
            Harmonic::Direct,
        ),
        (
            at(60.0, 0.5, Theory::LiftingSurface, Some(0.3)),
            Harmonic::Direct,
        ),
        (
            at(60.0, 0.8, Theory::LiftingSurfaceFrequency, None),
            Harmonic::Direct,
        ),
        (
            at(45.0, 0.7, Theory::LiftingSurfaceFrequency, None),
            Harmonic::Interpolated,
        ),
    ]
}

#[test]
fn the_hot_path_does_not_allocate() {
    // the lifting surface's solves, into the cache (allocating, once): its
    // own cases and the faired model's subsonic and transonic points
    let lifting = lifting_surface_cases();
    black_box(design_points(&lifting));
    let (acc, n) = allocations_in(|| hot_path(&lifting));
    black_box(acc);
    assert_eq!(n, 0, "allocations in the hot path");
}

type LiftingCase = (
    stability_core::design::case::Case,
    stability_core::aerodynamics::lifting_surface::Harmonic,
);

fn hot_path(lifting: &[LiftingCase]) -> f64 {
    let d = stability_core::design::examples::tailless_delta_45_coupled();
    let mut acc = 0.0;
    for i in 0..1000 {
        let mut di = d;
        di.mu1 += i as f64;
        let q = Quartic::from_derivatives(black_box(&di));
        let g = QuarticGradient::of(black_box(&di));
        acc += q.b + g.rows[5][1];
        let r = stability_core::numerics::roots::solve_quartic(q.to_array()).expect("roots");
        let a = stability_core::analysis::Analysis::of(black_box(&di)).expect("analysis");
        let lean = stability_core::analysis::Analysis::without_classical(black_box(&di))
            .expect("analysis");
        acc += r[0].re + a.modes.len() as f64 + lean.routh.discriminant;
    }
    // the badly scaled, whose roots take the Newton-polygon path
    for i_b in [1e-160, 1e308] {
        let di = stability_core::Derivatives { i_b, ..d };
        let a = stability_core::analysis::Analysis::of(black_box(&di)).expect("analysis");
        acc += a.roots[0].re;
    }
    acc + design_points(lifting)
}

fn design_points(lifting: &[LiftingCase]) -> f64 {
    use stability_core::aerodynamics::damping::Theory;
    use stability_core::design::case::{DampingModel, evaluate};
    use stability_core::geometry::{Planform, Size};
    let supersonic = DampingModel::Theory(Theory::Supersonic);
    let mut warned = 0;
    let mut acc = 0.0;
    for (deg, taper, mach, damping) in [
        (60.0, 0.0, 0.6, DampingModel::Faired),
        (60.0, 0.0, 1.1, DampingModel::Faired),
        (60.0, 0.0, 1.8, DampingModel::Faired),
        (45.0, 0.0, 1.8, DampingModel::Faired),
        (45.0, 0.0, 1.8, DampingModel::FairedSlender),
        (45.0, 0.0, 1.3, supersonic),
        (60.0, 0.0, 2.0, supersonic),
        (45.0, 1.0 / 7.0, 1.2, supersonic),
        // the cropped wing past the sonic edge: Evvard's integrals and the
        // numerical Mach derivatives
        (45.0, 1.0 / 7.0, 1.8, supersonic),
        (60.0, 1.0 / 7.0, 2.0, supersonic),
        (
            45.0,
            0.0,
            1.0,
            DampingModel::Theory(Theory::TransonicFrequency),
        ),
        (45.0, 0.0, 0.9, DampingModel::Theory(Theory::Garrick)),
    ] {
        let mut case = stability_core::design::study::report_wing(deg, mach);
        case.planform =
            Planform::new(f64::to_radians(deg), taper, Size::RootChord(10.0)).expect("a planform");
        case.damping = damping;
        let r = evaluate(black_box(&case)).expect("a design point");
        warned += r.warnings.len();
        acc += r.analysis.quartic.e;
    }
    assert!(warned > 0, "the cases raise warnings too");
    for (case, harmonic) in lifting {
        let r = stability_core::design::case::evaluate_point_with(black_box(case), *harmonic)
            .expect("a design point");
        acc += r.analysis.quartic.e + r.derivatives.m_q;
    }
    acc
}
