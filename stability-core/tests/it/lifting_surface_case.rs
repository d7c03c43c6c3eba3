//! The lifting surface in a design point (`--damping lifting-surface`,
//! `lifting-surface-frequency`, `--aero lifting-surface`): the case's
//! derivatives are the lattice's own by axis transfer, its coefficients the
//! steady solve's with their Mach derivatives, the frequency iteration ends
//! where ω̄ = s/μ₁, the subsonic limit is an error naming it; and the issue's
//! headline — the 45° delta's short period at M = 0.5.

use stability_core::aerodynamics::damping::{DampingError, Theory, WingInput, damping_derivatives};
use stability_core::aerodynamics::lifting_surface::{Harmonic, LiftingSurfaceError, store};
use stability_core::aerodynamics::models::aero::{AeroModel, AeroModelName};
use stability_core::design::case::{
    Case, CaseError, DampingModel, FrequencyMethod, evaluate, evaluate_point_with,
};
use stability_core::design::study::report_wing;
use stability_core::dynamics::modes::ModeName;
use stability_core::geometry::{Planform, Size};

fn case(deg: f64, mach: f64, damping: Theory, aero: AeroModelName) -> Case {
    Case {
        damping: DampingModel::Theory(damping),
        aero: AeroModel::default().with_name(aero),
        ..report_wing(deg, mach)
    }
}

fn shape(c: &Case) -> stability_core::geometry::Trapezoid {
    let p = &c.planform;
    store::unit_wing(p.aspect_ratio(), p.taper, p.sweep_le).unwrap()
}

#[test]
fn the_case_takes_the_lattices_derivatives_about_its_cg() {
    for (deg, taper, mach, h) in [
        (45.0, 0.0, 0.5, 0.25),
        (60.0, 0.0, 0.8, 0.4),
        (55.0, 0.2, 0.3, -0.1),
    ] {
        let mut c = case(deg, mach, Theory::LiftingSurface, AeroModelName::Default);
        c.planform = Planform::new(deg.to_radians(), taper, Size::RootChord(3.0)).unwrap();
        c.h = h;
        let r = evaluate(&c).unwrap();
        let s = store::lattice(&shape(&c), mach, 0.0, Harmonic::Direct).unwrap();
        let d = s.derivatives(h, 0.0).unwrap();
        let got = r.derivatives;
        assert_eq!(
            [got.z_q, got.m_q, got.z_wdot, got.m_wdot],
            [d.z_q, d.m_q, d.z_wdot, d.m_wdot],
            "{deg}° M {mach} h {h}"
        );
        assert_eq!(r.damping.theory, Theory::LiftingSurface);
        assert!(r.frequency.is_none());
        // a tapered wing is no warning for the lifting surface
        assert!(r.warnings.is_empty(), "{:?}", r.warnings);
        // at a given ω̄: the harmonic solve there
        c.omega_bar = Some(0.3);
        let r = evaluate(&c).unwrap();
        let s = store::lattice(&shape(&c), mach, 0.3, Harmonic::Direct).unwrap();
        assert_eq!(r.derivatives.m_wdot, s.derivatives(h, 0.0).unwrap().m_wdot);
    }
}

#[test]
fn the_aerodynamic_model_takes_the_steady_solve_with_its_mach_derivatives() {
    let c = case(45.0, 0.6, Theory::Slender, AeroModelName::LiftingSurface);
    let r = evaluate(&c).unwrap();
    let s = store::lattice_steady(&shape(&c), 0.6).unwrap();
    let a = r.coefficients.lift_slope;
    let h0 = r.coefficients.aerodynamic_centre;
    assert_eq!((a.value, a.d_mach), s.lift_slope());
    assert_eq!((h0.value, h0.d_mach), s.aerodynamic_centre());
    // K = 1/a of the lattice's a (no leading-edge suction), C_D0 the default
    let k = r.coefficients.drag_due_to_lift;
    assert!((k.value - 1.0 / a.value).abs() < 1e-15);
    assert!((k.d_mach + a.d_mach / (a.value * a.value)).abs() < 1e-15);
    assert_eq!(r.coefficients.zero_lift_drag.value, 0.01);
    // the stiffness derivatives are eqs (12), (14) with the lattice's a, H₀
    let d = &r.derivatives;
    let c_d = 0.01 + k.value * r.c_l * r.c_l;
    assert!((d.z_w + a.value + c_d).abs() < 1e-12);
    assert!((d.m_w - (0.25 - h0.value) * (a.value + c_d)).abs() < 1e-12);
    // a table still wins for its coefficient
    let mut tabled = c.clone();
    tabled.aero.lift_slope = stability_core::aerodynamics::models::aero::Source::Table(
        stability_core::aerodynamics::models::aero::Table::new(vec![0.5, 0.7], vec![3.0, 3.2])
            .unwrap(),
    );
    let t = evaluate(&tabled).unwrap().coefficients;
    assert!((t.lift_slope.value - 3.1).abs() < 1e-12);
    assert_eq!(t.aerodynamic_centre.value, h0.value);
}

#[test]
fn above_mach_one_the_case_takes_the_mach_box_and_at_one_asks_for_a_frequency() {
    // --aero lifting-surface at M = 2 on the 45° delta (supersonic leading
    // edge): the lift slope 4/β exactly, H₀ = ½ (a delta's centre of
    // pressure at 2/3 of the root chord)
    let c = case(45.0, 2.0, Theory::Supersonic, AeroModelName::LiftingSurface);
    let r = evaluate(&c).unwrap();
    let beta = 3f64.sqrt();
    let (cla, h0) = (
        r.coefficients.lift_slope.value,
        r.coefficients.aerodynamic_centre.value,
    );
    assert!((cla * beta / 4.0 - 1.0).abs() < 2e-3, "{cla}");
    assert!((h0 - 0.5).abs() < 2e-3, "{h0}");
    // --damping lifting-surface at M = 1 without ω̄: an error saying what to give
    let c = case(45.0, 1.0, Theory::LiftingSurface, AeroModelName::Default);
    let e = evaluate(&c).unwrap_err();
    assert!(
        matches!(
            e,
            CaseError::Damping(DampingError::LiftingSurface(
                LiftingSurfaceError::SonicFrequency { .. }
            ))
        ),
        "{e:?}"
    );
    assert!(e.to_string().contains("--omega-bar 0.3"), "{e}");
    // the standalone function too, and the frequency theory needs an ω̄
    let wing = WingInput::from(&c.planform);
    assert!(damping_derivatives(Theory::LiftingSurface, &wing, 0.25, 1.5, None).is_ok());
    assert!(damping_derivatives(Theory::LiftingSurface, &wing, 0.25, 3.5, None).is_err());
    assert!(matches!(
        damping_derivatives(Theory::LiftingSurfaceFrequency, &wing, 0.25, 0.5, None),
        Err(DampingError::Frequency {
            theory: Theory::LiftingSurfaceFrequency,
            omega_bar: None
        })
    ));
}

#[test]
fn the_frequency_iteration_ends_at_the_short_periods_own_frequency() {
    for (theory, deg, mach) in [
        (Theory::LiftingSurfaceFrequency, 45.0, 0.5),
        (Theory::LiftingSurfaceFrequency, 60.0, 0.8),
        (Theory::TransonicFrequency, 45.0, 1.0),
    ] {
        // (the k-method: its roots are the quartic's at the converged ω̄)
        let c = Case {
            frequency_method: FrequencyMethod::K,
            ..case(deg, mach, theory, AeroModelName::Default)
        };
        let r = evaluate(&c).unwrap();
        let f = r.frequency.unwrap();
        let sp = r.analysis.modes.short_period().unwrap();
        assert!(f.converged_ok && f.iterations < 12, "{theory} {f:?}");
        assert!(
            (f.converged - sp.im / c.mu1).abs() <= 1e-11 * f.converged,
            "{theory}: ω̄ {} against s/μ₁ {}",
            f.converged,
            sp.im / c.mu1
        );
        // the derivatives are the theory's at the converged ω̄
        let wing = WingInput::from(&c.planform);
        let at = damping_derivatives(theory, &wing, c.h, mach, Some(f.converged)).unwrap();
        assert_eq!(r.damping.derivatives, at.derivatives);
        // and not iterated, at the ω̄ given
        let fixed = Case {
            omega_bar: Some(0.2),
            iterate_frequency: false,
            ..c.clone()
        };
        let r = evaluate(&fixed).unwrap();
        let at = damping_derivatives(theory, &wing, c.h, mach, Some(0.2)).unwrap();
        assert_eq!(r.damping.derivatives, at.derivatives);
        assert_eq!(r.frequency.unwrap().iterations, 0);
    }
}

#[test]
fn interpolated_the_iteration_lands_where_the_direct_one_does() {
    for (deg, mach) in [(45.0, 0.5), (60.0, 0.8)] {
        let c = case(
            deg,
            mach,
            Theory::LiftingSurfaceFrequency,
            AeroModelName::LiftingSurface,
        );
        let direct = evaluate_point_with(&c, Harmonic::Direct).unwrap();
        let table = evaluate_point_with(&c, Harmonic::Interpolated).unwrap();
        let (a, b) = (direct.frequency.unwrap(), table.frequency.unwrap());
        assert!(b.converged_ok);
        assert!(
            (a.converged - b.converged).abs() < 1e-4 * a.converged,
            "{a:?} {b:?}"
        );
        let (sa, sb) = (
            direct.analysis.modes.short_period().unwrap(),
            table.analysis.modes.short_period().unwrap(),
        );
        assert!(
            (sa.re - sb.re).abs() < 1e-3 * sa.re.abs(),
            "{} {}",
            sa.re,
            sb.re
        );
        assert!((sa.im - sb.im).abs() < 1e-4 * sa.im, "{} {}", sa.im, sb.im);
    }
}

/// The headline symptom: slender-wing theory gives the 45° delta at
/// M = 0.5 two real short-period roots; the lifting surface (damping and
/// the lift slope and aerodynamic centre) an oscillation.
#[test]
fn the_45_degree_delta_at_mach_half_oscillates_by_lifting_surface_theory() {
    let slender = evaluate(&case(45.0, 0.5, Theory::Slender, AeroModelName::Default)).unwrap();
    assert!(slender.analysis.modes.short_period().is_none());
    let aperiodic = slender
        .analysis
        .modes
        .iter()
        .filter(|m| m.name == ModeName::Aperiodic)
        .count();
    assert_eq!(aperiodic, 2);
    let ls = case(
        45.0,
        0.5,
        Theory::LiftingSurface,
        AeroModelName::LiftingSurface,
    );
    let r = evaluate(&ls).unwrap();
    let sp = r.analysis.modes.short_period().unwrap();
    // −m_q is 3.7 times smaller than (37)'s, H₀ 0.09c̄ further forward
    assert!(sp.re < 0.0 && sp.im > 0.0, "{sp:?}");
    assert!(
        (-r.derivatives.m_q - 0.6412).abs() < 1e-3,
        "{}",
        r.derivatives.m_q
    );
    assert!((r.coefficients.aerodynamic_centre.value - 0.3529).abs() < 1e-3);
    assert!(sp.damping_ratio.unwrap() > 0.3 && sp.damping_ratio.unwrap() < 0.6);
}
