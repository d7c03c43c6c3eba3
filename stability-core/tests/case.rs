//! Design points end to end: the faired damping model's continuity, the
//! frequency iteration's consistency, and the report's headline conclusions
//! under our models.

use stability_core::aero::AeroModel;
use stability_core::case::{Case, DampingModel, evaluate};
use stability_core::damping::Theory;
use stability_core::geometry::{Planform, Size};

fn case(deg: f64, mach: f64, mu1: f64, damping: DampingModel) -> Case {
    Case {
        planform: Planform::new(deg.to_radians(), 0.0, Size::RootChord(10.0)).unwrap(),
        mach,
        h: 0.25,
        mu1,
        i_b: 0.08,
        cl_m2: 0.05,
        aero: AeroModel::default(),
        damping,
        omega_bar: None,
        iterate_frequency: true,
    }
}

#[test]
fn the_faired_model_joins_its_theories_continuously() {
    for deg in [45.0, 60.0] {
        let at = |m: f64, d| {
            evaluate(&case(deg, m, 50.0, d))
                .unwrap()
                .damping
                .derivatives
        };
        // = slender at and below M = 1, = supersonic from M = 1.2
        assert_eq!(
            at(0.8, DampingModel::Faired),
            at(0.8, DampingModel::Theory(Theory::Slender))
        );
        let s = at(1.25, DampingModel::Theory(Theory::Supersonic));
        assert_eq!(at(1.25, DampingModel::Faired), s);
        // continuous across M = 1 and M = 1.2
        for m in [1.0, 1.2] {
            let (a, b) = (
                at(m - 1e-7, DampingModel::Faired),
                at(m + 1e-7, DampingModel::Faired),
            );
            assert!(
                (a.m_q - b.m_q).abs() < 1e-5 && (a.m_wdot - b.m_wdot).abs() < 1e-5,
                "{deg}° M {m}: {a:?} {b:?}"
            );
        }
    }
}

#[test]
fn the_frequency_iteration_reaches_the_short_periods_own_frequency() {
    let r = evaluate(&case(
        45.0,
        1.0,
        50.0,
        DampingModel::Theory(Theory::TransonicFrequency),
    ))
    .unwrap();
    let f = r.frequency.expect("iterated");
    assert!(f.converged_ok, "{f:?}");
    let sp = r.analysis.modes.short_period().expect("oscillatory");
    // ω̄ = s/μ₁ (§9)
    assert!(
        (f.converged - sp.im / 50.0).abs() < 1e-9 * f.converged,
        "{f:?} vs {}",
        sp.im / 50.0
    );
    // The report: "the frequency parameter for the short period oscillation
    // has in fact a maximum value of 0.6" — ours lands near it.
    assert!(f.converged > 0.4 && f.converged < 0.8, "{}", f.converged);
}

fn cycles(deg: f64, mach: f64, mu1: f64) -> f64 {
    let r = evaluate(&case(deg, mach, mu1, DampingModel::Faired)).unwrap();
    match r.analysis.modes.short_period() {
        Some(m) if m.re < 0.0 => m.cycles_to_half.unwrap(),
        Some(_) => f64::INFINITY, // divergent
        None => 0.0,              // non-oscillatory: damped without overshoot
    }
}

#[test]
fn the_60_degree_delta_meets_the_standard_at_mu1_50_but_not_at_400() {
    // Report §9: "μ₁ should not exceed 200 for the tailless 60° delta to
    // remain adequately damped".
    let machs: Vec<f64> = (0..=30).map(|i| 0.5 + 0.05 * i as f64).collect();
    assert!(machs.iter().all(|&m| cycles(60.0, m, 50.0) <= 1.0));
    assert!(machs.iter().any(|&m| cycles(60.0, m, 400.0) > 1.0));
}

#[test]
fn the_45_degree_delta_is_poorly_damped_at_low_supersonic_speeds() {
    // Report §9: the 45° delta needs a tailplane "to correct the serious
    // instability in the range 0.97 < M < 1.5". Our models put its worst
    // damping just above M = 1.15; subsonic it meets the standard easily.
    assert!(cycles(45.0, 0.8, 50.0) < 0.2);
    let worst = (0..=20)
        .map(|i| cycles(45.0, 1.0 + 0.025 * i as f64, 50.0))
        .fold(0.0, f64::max);
    assert!(worst > 1.0, "{worst}");
}

/// μ₁ and i_B enter the equations of motion, not the derivatives (what a
/// sweep relies on to evaluate the aerodynamics once per Mach number and
/// c.g.) — except through ω̄ = s/μ₁ for a frequency-dependent theory.
#[test]
fn the_derivatives_depend_on_mass_only_through_the_frequency() {
    for (damping, depends) in [
        (DampingModel::Faired, false),
        (DampingModel::Theory(Theory::Slender), false),
        (DampingModel::Theory(Theory::Supersonic), false),
        (DampingModel::Theory(Theory::TransonicFrequency), true),
    ] {
        assert_eq!(damping.depends_on_mass(), depends, "{}", damping.name());
        let mach = if damping == DampingModel::Theory(Theory::Supersonic) {
            1.3
        } else {
            1.0
        };
        let light = evaluate(&case(60.0, mach, 50.0, damping)).unwrap();
        let mut heavy_case = case(60.0, mach, 400.0, damping);
        heavy_case.i_b = 0.12;
        let heavy = evaluate(&heavy_case).unwrap();
        let (a, b) = (light.derivatives, heavy.derivatives);
        assert_eq!((b.mu1, b.i_b), (400.0, 0.12));
        let same = a.quartic_input_values()[..13] == b.quartic_input_values()[..13];
        assert_eq!(same, !depends, "{}: {a:?} vs {b:?}", damping.name());
    }
}
