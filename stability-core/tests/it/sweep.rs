//! The library sweep (`stability_core::design::sweep`): each point's values are
//! those `case::evaluate_point` gives that design point alone — for the
//! slender and faired models (the faired model's frequency iteration
//! interpolated in the lattice's tables), the lifting surface (solved once per planform
//! and Mach number, reused across c.g., μ₁ and i_B), and the frequency
//! iteration (with direct solves exactly; interpolated within the table's
//! accuracy) — its errors are the points', and the columns line up.

use stability_core::aerodynamics::damping::Theory;
use stability_core::aerodynamics::lifting_surface::Harmonic;
use stability_core::aerodynamics::models::aero::{AeroModel, AeroModelName};
use stability_core::design::case::{
    Case, DampingModel, FrequencyMethod, evaluate_point, evaluate_point_with,
};
use stability_core::design::study::report_wing;
use stability_core::design::sweep::{Axes, PointError, Points, Sweep, SweepError};

fn base(damping: DampingModel, aero: AeroModelName) -> Case {
    Case {
        damping,
        aero: AeroModel::default().with_name(aero),
        ..report_wing(60.0, 0.8)
    }
}

/// 3 Mach numbers (one supersonic) × 2 sweeps × 2 c.g. × 3 μ₁ × 2 i_B.
fn axes() -> Axes {
    Axes {
        mach: vec![0.6, 0.9, 1.3],
        sweep_deg: vec![45.0, 60.0],
        cg: vec![0.15, 0.3],
        mu1: vec![30.0, 120.0, 400.0],
        i_b: vec![0.05, 0.1],
        ..Axes::default()
    }
}

/// Every point of `sweep` against `evaluate_point_with` alone: the same
/// numbers (to `tol`, relative; 0 is bit for bit) and the same errors.
fn assert_alone(sweep: &Sweep, points: &Points, harmonic: Harmonic, tol: f64) {
    assert_eq!(points.len(), sweep.len());
    let close = |a: f64, b: f64| {
        (a.is_nan() && b.is_nan()) || a == b || (a - b).abs() <= tol * a.abs().max(b.abs())
    };
    for i in 0..sweep.len() {
        let case = sweep.case(i);
        let err = points.errors.iter().find(|(k, _)| *k == i).map(|(_, e)| e);
        match evaluate_point_with(&case, harmonic) {
            Ok(r) => {
                assert!(err.is_none(), "point {i}: {err:?}");
                let sp = r.analysis.modes.short_period();
                let nan = f64::NAN;
                assert!(
                    close(points.sp_re[i], sp.map_or(nan, |m| m.re)),
                    "point {i} sp_re"
                );
                assert!(
                    close(points.sp_im[i], sp.map_or(nan, |m| m.im)),
                    "point {i} sp_im"
                );
                let overall = stability_core::analysis::verdict::overall(&r.analysis);
                assert_eq!(points.verdict[i], Some(overall), "point {i}");
                assert_eq!(points.stable[i], Some(r.analysis.routh.stable), "point {i}");
                let ds = points.derivatives.as_ref().unwrap();
                assert!(close(ds[i].m_q, r.derivatives.m_q), "point {i} m_q");
                assert!(
                    close(ds[i].z_wdot, r.derivatives.z_wdot),
                    "point {i} z_wdot"
                );
                assert!(close(
                    points.m_thetadot[i],
                    r.analysis.damping_standard.m_thetadot
                ));
            }
            Err(e) => {
                assert_eq!(err, Some(&PointError::Case(e)), "point {i}");
                assert!(points.sp_re[i].is_nan() && points.stable[i].is_none());
            }
        }
        assert_eq!(
            [points.mach[i], points.cg[i], points.mu1[i], points.i_b[i]],
            [case.mach, case.h, case.mu1, case.i_b]
        );
    }
}

#[test]
fn each_point_is_the_design_point_alone() {
    // the faired model iterates each point's ω̄, in a sweep by the lattice's
    // frequency tables (`Harmonic::Interpolated`): its points are
    // `evaluate_point_with` the same, bit for bit
    for (damping, aero, harmonic) in [
        (
            DampingModel::Faired,
            AeroModelName::Default,
            Harmonic::Interpolated,
        ),
        (
            DampingModel::FairedSlender,
            AeroModelName::Default,
            Harmonic::Direct,
        ),
        (
            DampingModel::Theory(Theory::Slender),
            AeroModelName::Default,
            Harmonic::Direct,
        ),
        (
            DampingModel::Theory(Theory::LiftingSurface),
            AeroModelName::Default,
            Harmonic::Direct,
        ),
        (
            DampingModel::Theory(Theory::LiftingSurface),
            AeroModelName::LiftingSurface,
            Harmonic::Direct,
        ),
    ] {
        let b = base(damping, aero);
        let sweep = Sweep::new(b.clone(), axes()).unwrap();
        let points = sweep.run(true);
        assert_alone(&sweep, &points, harmonic, 0.0);
        // evaluated in pieces, the same columns
        let mut again = sweep.evaluate(0..17, true);
        let rest = sweep.evaluate(17..sweep.len(), true);
        assert_eq!(rest.start, 17);
        assert_eq!(again.sp_re.len() + rest.sp_re.len(), points.len());
        again.sp_re.extend(&rest.sp_re);
        let same = again
            .sp_re
            .iter()
            .zip(&points.sp_re)
            .all(|(a, b)| a == b || (a.is_nan() && b.is_nan()));
        assert!(same, "{}", damping.name());
    }
}

#[test]
fn the_lattice_at_mach_one_is_an_error_at_those_points_only() {
    // quasi-steady at M = 1: the damping refused (the α̇ derivatives are
    // infinite there; the aero model's lift slope and aerodynamic centre
    // are joined through the sonic point); above M = 1 the Mach box
    // (tests/it/lifting_surface_mach_range.rs)
    let b = base(
        DampingModel::Theory(Theory::LiftingSurface),
        AeroModelName::LiftingSurface,
    );
    let axes = Axes {
        mach: vec![0.6, 0.9, 1.0],
        ..axes()
    };
    let points = Sweep::new(b.clone(), axes).unwrap().run(false);
    let per_mach = points.len() / 3;
    assert_eq!(points.errors.len(), per_mach);
    assert!(points.errors.iter().all(|(k, _)| *k >= 2 * per_mach));
    let msg = points.errors[0].1.to_string();
    assert!(msg.contains("give --omega-bar 0.3 or more"), "{msg}");
    assert!(points.derivatives.is_none());
}

#[test]
fn the_frequency_iteration_in_a_sweep() {
    // the k-method: the short period's ω̄ is the iteration's fixed point
    let b = Case {
        frequency_method: FrequencyMethod::K,
        ..base(
            DampingModel::Theory(Theory::LiftingSurfaceFrequency),
            AeroModelName::LiftingSurface,
        )
    };
    let axes = Axes {
        mach: vec![0.7],
        mu1: vec![40.0, 200.0],
        ..Axes::around(&b)
    };
    // direct solves at every iterate: the design points exactly
    let direct = Sweep::new(b.clone(), axes.clone())
        .unwrap()
        .with_harmonic(Harmonic::Direct);
    assert_alone(&direct, &direct.run(true), Harmonic::Direct, 0.0);
    // interpolated (the default for an iterated theory): the same within
    // the table's accuracy, and exactly what the interpolated point gives
    let sweep = Sweep::new(b.clone(), axes).unwrap();
    let points = sweep.run(true);
    assert_alone(&sweep, &points, Harmonic::Interpolated, 0.0);
    assert_alone(&sweep, &points, Harmonic::Direct, 2e-4);
    // at a fixed ω̄ the derivatives are shared across μ₁ and i_B, and each
    // point is still the design point alone (a direct solve at that ω̄)
    let fixed = Case {
        omega_bar: Some(0.25),
        iterate_frequency: false,
        ..b.clone()
    };
    let many = Axes {
        i_b: vec![0.05, 0.1],
        ..Sweep::new(b.clone(), Axes::around(&b))
            .unwrap()
            .axes()
            .clone()
    };
    let many = Axes {
        mach: vec![0.7],
        mu1: vec![40.0, 200.0],
        ..many
    };
    let s = Sweep::new(fixed, many).unwrap();
    assert_alone(&s, &s.run(true), Harmonic::Direct, 0.0);
    for i in 0..points.len() {
        // the short period's ω̄ is the converged one
        let r = evaluate_point_with(&sweep.case(i), Harmonic::Interpolated).unwrap();
        let f = r.frequency.unwrap();
        assert!((points.sp_omega_bar[i] - f.converged).abs() < 1e-11 * f.converged);
    }
}

#[test]
fn bad_grids_are_errors_of_the_sweep() {
    let b = report_wing(45.0, 0.9);
    let empty = Axes {
        cg: vec![],
        ..Axes::around(&b)
    };
    assert_eq!(
        Sweep::new(b.clone(), empty).unwrap_err(),
        SweepError::Empty { axis: "cg" }
    );
    let bad = Axes {
        sweep_deg: vec![45.0, 90.0],
        ..Axes::around(&b)
    };
    assert!(matches!(
        Sweep::new(b.clone(), bad),
        Err(SweepError::Planform {
            sweep_deg: 90.0,
            ..
        })
    ));
    let huge = Axes {
        mach: vec![0.5; 100_000],
        cg: vec![0.25; 10_000],
        ..Axes::around(&b)
    };
    assert!(matches!(
        Sweep::new(b.clone(), huge),
        Err(SweepError::TooLarge {
            points: Some(1_000_000_000)
        })
    ));
    // a bad value is the point's error, as evaluate_point's
    let negative = Axes {
        mu1: vec![50.0, -1.0],
        ..Axes::around(&b)
    };
    let points = Sweep::new(b.clone(), negative).unwrap().run(false);
    let mut c = b.clone();
    c.mu1 = -1.0;
    assert_eq!(
        points.errors,
        vec![(1, PointError::Case(evaluate_point(&c).unwrap_err()))]
    );
}

/// A physical flight condition: each planform's μ₁, i_B and C_L·M² are the
/// condition's with that planform (its area and M.A.C. change with the
/// sweep at a fixed root chord), every point equals `evaluate_point` of that
/// case, and τ scales as 1/M (C_L·M² constant, eq 24).
#[test]
fn a_physical_sweep_gives_each_planform_its_own_flight_parameters() {
    use stability_core::design::flight::{Air, Altitude, FlightCondition, Mass, Units};
    let flight = FlightCondition {
        units: Units::Si,
        air: Air::Standard(Altitude::Pressure(11_000.0)),
        mass: Mass::Mass(12_000.0),
        pitch_inertia: 70_000.0,
    };
    let base = report_wing(60.0, 0.9);
    let axes = Axes {
        // (the flight parameters are the question: subsonic Mach numbers,
        // whose lattices are quick)
        mach: vec![0.6, 0.9],
        sweep_deg: vec![50.0, 60.0, 70.0],
        ..Axes::around(&base)
    };
    let sweep = Sweep::new(base.clone(), axes.clone())
        .unwrap()
        .with_flight(&flight)
        .unwrap();
    let points = sweep.run(false);
    assert!(points.errors.is_empty(), "{:?}", points.errors);
    for i in 0..sweep.len() {
        let case = sweep.case(i);
        let own = flight.for_planform(&case.planform).unwrap();
        assert_eq!(
            (case.mu1, case.i_b, case.cl_m2),
            (own.mu1(), own.i_b(), own.cl_m2())
        );
        assert_eq!(points.mu1[i], own.mu1());
        // (the faired model: its lattice interpolated, as the sweep has it)
        let alone = evaluate_point_with(&case, Harmonic::Interpolated).unwrap();
        assert_eq!(
            points.sp_re[i].to_bits(),
            alone.analysis.modes.short_period().unwrap().re.to_bits()
        );
        let p = sweep.flight_point(i).unwrap();
        assert!((p.tau * case.mach - own.at_mach(1.0).unwrap().tau).abs() < 1e-12 * p.tau);
    }
    // μ₁ differs between the sweeps (S and c̄ do)
    assert!(points.mu1[0] != points.mu1[2]);
    // the μ₁ and i_B axes are the condition's, not a range
    let ranged = Axes {
        mu1: vec![50.0, 100.0],
        ..axes
    };
    assert!(matches!(
        Sweep::new(base, ranged).unwrap().with_flight(&flight),
        Err(SweepError::FixedByFlight { axis: "mu1", n: 2 })
    ));
}
