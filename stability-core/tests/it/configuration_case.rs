//! A configuration through the design-point pipeline (issue 21): the
//! increment over the wing reaches the coefficients, the damping, the
//! neutral point and the `configuration` shares, checked against hand
//! formulas, subsonic (the multi-surface lattice) and supersonic.

use stability_core::aerodynamics::lifting_surface::Harmonic;
use stability_core::aerodynamics::lifting_surface::{Lattice, LatticeSpec};
use stability_core::design::case::{Case, DampingModel, evaluate};
use stability_core::design::study::report_wing;
use stability_core::geometry::configuration::Body;
use stability_core::geometry::configuration::Configuration;
use stability_core::geometry::configuration::Part;
use stability_core::geometry::configuration::Surface;
use stability_core::geometry::configuration::SurfaceKind;
use stability_core::geometry::{Planform, Size, Trapezoid};
use std::f64::consts::PI;
use std::sync::Arc;

/// The report's 45° delta (c₀ = 10) with a 45° delta tail of root chord
/// 2.5 whose apex is 15 aft of the wing's, in the wing's plane.
fn tailed(mach: f64) -> (Case, Configuration) {
    let mut case = report_wing(45.0, mach);
    case.planform = Planform::new(45f64.to_radians(), 0.0, Size::RootChord(10.0)).unwrap();
    // the note's fairing: linear theory's exact a = 4/β and H₀ = ½ at
    // M = 2, which the classical formula below takes
    case.damping = DampingModel::FairedTheories;
    let tail = Planform::new(45f64.to_radians(), 0.0, Size::RootChord(2.5)).unwrap();
    let config = Configuration {
        tailplane: Some(Surface {
            kind: SurfaceKind::Tailplane,
            shape: Trapezoid::from(&tail),
            x: 15.0,
            z: 0.0,
            incidence: 0.0,
        }),
        ..Configuration::wing_alone(Trapezoid::from(&case.planform))
    };
    (case, config)
}

#[test]
fn a_tail_at_m2_moves_the_neutral_point_as_the_classical_formula_says() {
    let mach = 2.0;
    let (alone, config) = tailed(mach);
    let mut with = alone.clone();
    with.aero.configuration = Some(Arc::new(config));
    let (r0, r) = (evaluate(&alone).unwrap(), evaluate(&with).unwrap());
    // M = 2, 45°: both surfaces' leading edges supersonic, a = 4/β, the
    // centre of pressure at ⅔ of the root chord; dε/dα = 2a_w/(πA), A = 4
    let beta = 3f64.sqrt();
    let (a_w, a_t, de) = (4.0 / beta, 4.0 / beta, 2.0 * 4.0 / beta / (PI * 4.0));
    let (c0, ct) = (10.0, 2.5);
    let (cbar, x_mac) = (2.0 / 3.0 * c0, c0 / 3.0);
    let r_area = (ct / c0) * (ct / c0);
    let tail_lift = a_t * r_area * (1.0 - de);
    // h_n = (a_w H₀,w + a_T′ x_T)/(a_w + a_T′), x_T the tail's centre of
    // pressure on the wing's M.A.C.
    let x_t = (15.0 + 2.0 / 3.0 * ct - x_mac) / cbar;
    let h_n = (a_w * 0.5 + tail_lift * x_t) / (a_w + tail_lift);
    let got = r.coefficients.aerodynamic_centre.value;
    assert!((got - h_n).abs() < 1e-12, "H₀ {got} against {h_n}");
    assert!((r.coefficients.lift_slope.value - (a_w + tail_lift)).abs() < 1e-12);
    let margins = r.margins(&with);
    eprintln!(
        "neutral point {:?} (wing alone {:?}); H₀ {got:.6} against the classical {h_n:.6}",
        margins.neutral_point,
        r0.margins(&alone).neutral_point
    );
    // the shares sum to what the case used
    let s = r.configuration.as_ref().unwrap();
    assert_eq!(s.parts[0].part, Part::Wing);
    assert_eq!(s.parts[1].part, Part::Tailplane);
    for (sum, used) in [
        (s.m_q, r.derivatives.m_q),
        (s.z_q, r.derivatives.z_q),
        (s.m_wdot, r.derivatives.m_wdot),
        (s.z_wdot, r.derivatives.z_wdot),
        (s.lift_slope, r.coefficients.lift_slope.value),
        (s.aerodynamic_centre, got),
    ] {
        assert!(
            (sum - used).abs() < 1e-12 * (1.0 + used.abs()),
            "{sum} vs {used}"
        );
    }
    // the wing's share is the wing alone's
    assert!((s.parts[0].m_q - r0.derivatives.m_q).abs() < 1e-12);
    assert!((s.aerodynamic_centre_shift - (h_n - 0.5)).abs() < 1e-12);
    assert!(r0.configuration.is_none());
}

#[test]
fn the_tail_damps_the_45_degree_delta_at_m_1_5() {
    // Fig 33's remedy: the tailless 45° delta's m_θ̇ at M = 1.5, then with
    // the tail the tail-volume estimate −a_T V̄_T l_T/c̄ more negative
    let (alone, config) = tailed(1.5);
    let mut with = alone.clone();
    with.aero.configuration = Some(Arc::new(config));
    let (r0, r) = (evaluate(&alone).unwrap(), evaluate(&with).unwrap());
    let dm = r.derivatives.m_q - r0.derivatives.m_q;
    let beta = (1.25f64).sqrt();
    let a_t = 4.0 / beta; // β cot 45° = 1.118 > 1
    let cbar = 20.0 / 3.0;
    let l_t = (15.0 + 2.5 * 2.0 / 3.0 - (10.0 / 3.0 + alone.h * cbar)) / cbar;
    let estimate = -a_t * (2.5f64 * 2.5 / 100.0) * l_t * l_t;
    eprintln!("Δm_q {dm:.4} against the tail-volume estimate {estimate:.4}");
    // the estimate neglects the tail's own damping about its centre and
    // the downwash of the wing's pitch-rate lift: within 15 %
    assert!((dm / estimate - 1.0).abs() < 0.15, "{dm} vs {estimate}");
    assert!(
        r.analysis.modes.short_period().unwrap().re < r0.analysis.modes.short_period().unwrap().re
    );
}

#[test]
fn a_body_adds_eq_43_through_the_pipeline() {
    let (alone, config) = tailed(2.0);
    let body = Configuration {
        tailplane: None,
        body: Some(Body {
            length_ahead: 4.0,
            diameter: 2.0,
        }),
        ..config
    };
    let mut with = alone.clone();
    with.aero.configuration = Some(Arc::new(body));
    let (r0, r) = (evaluate(&alone).unwrap(), evaluate(&with).unwrap());
    let p = &alone.planform;
    let x = 4.0 + p.x_mac() + alone.h * p.mac();
    let eq43 =
        stability_core::aerodynamics::damping::fuselage_increment(2.0, 4.0, x, p.area(), p.mac());
    let got = r.damping.derivatives.m_thetadot() - r0.damping.derivatives.m_thetadot();
    assert!((got - eq43).abs() < 1e-12, "{got} vs eq (43) {eq43}");
}

#[test]
fn a_small_distant_tail_at_m_0_5_follows_the_tail_volume_formulas() {
    // subsonic: a 45° delta tail of root chord 2.5 (S_T/S = 1/16) 40 wing
    // root chords aft; its lift slope on its own area from the single-wing
    // lattice (DATCOM's Helmbold form, 3.88 here, overstates a delta's by
    // 8 %). A pitch rate q gives the tail the incidence
    // q·l_T/V; the wing's downwash there comes from its own q-lift, which
    // is small about an axis near its centre, so Δm_q ≈ −a_T(S_T/S)(l_T/c̄)²
    // with no (1 − dε/dα) factor (that factor belongs to m_w; the lag to
    // m_ẇ), l_T from the c.g. to the tail's quarter-M.A.C. point.
    let (mut alone, _) = tailed(0.5);
    alone.damping =
        DampingModel::Theory(stability_core::aerodynamics::damping::Theory::LiftingSurface);
    let tail = Planform::new(45f64.to_radians(), 0.0, Size::RootChord(2.5)).unwrap();
    let config = Configuration {
        tailplane: Some(Surface {
            kind: SurfaceKind::Tailplane,
            shape: Trapezoid::from(&tail),
            x: 400.0,
            z: 0.0,
            incidence: 0.0,
        }),
        ..Configuration::wing_alone(Trapezoid::from(&alone.planform))
    };
    let mut with = alone.clone();
    with.aero.configuration = Some(Arc::new(config));
    let (r0, r) = (evaluate(&alone).unwrap(), evaluate(&with).unwrap());
    let tail_wing = Trapezoid::from(&tail);
    let lattice = Lattice::new(&tail_wing, LatticeSpec::for_wing(&tail_wing)).unwrap();
    let a_t = lattice.solve(0.5, 0.0).unwrap().lift_alpha;
    let cbar = 20.0 / 3.0;
    let tail_quarter = 400.0 + tail.x_mac() + 0.25 * tail.mac();
    let l_t = (tail_quarter - (10.0 / 3.0 + alone.h * cbar)) / cbar;
    let est = -a_t * (1.0 / 16.0) * l_t * l_t;
    let dm = r.derivatives.m_q - r0.derivatives.m_q;
    assert!((dm / est - 1.0).abs() < 0.05, "{dm} vs {est}");
}

#[test]
fn the_configurations_lift_slope_and_centre_carry_their_mach_derivatives() {
    // eqs 25–29 take d a/dM and dH₀/dM: with the tail they must be the
    // derivatives of the configuration's a and H₀, checked here against a
    // central difference of the pipeline's own values (step 10⁻⁴)
    let (mut case, config) = tailed(1.6);
    case.aero.configuration = Some(Arc::new(config));
    let at = |m: f64| {
        let mut c = case.clone();
        c.mach = m;
        evaluate(&c).unwrap().coefficients
    };
    let (k, h) = (at(1.6), 1e-4);
    let (lo, hi) = (at(1.6 - h), at(1.6 + h));
    let da = (hi.lift_slope.value - lo.lift_slope.value) / (2.0 * h);
    let dh = (hi.aerodynamic_centre.value - lo.aerodynamic_centre.value) / (2.0 * h);
    eprintln!(
        "d a/dM {} against {da}; dH₀/dM {} against {dh}",
        k.lift_slope.d_mach, k.aerodynamic_centre.d_mach
    );
    assert!((k.lift_slope.d_mach - da).abs() < 1e-5 * da.abs().max(1.0));
    assert!((k.aerodynamic_centre.d_mach - dh).abs() < 1e-5 * dh.abs().max(1e-2));
}

#[test]
fn the_transonic_fairing_meets_the_lattice_and_the_supersonic_theory() {
    // the increment is continuous at both ends of the faired band
    let (_, config) = tailed(1.0);
    for (inside, end) in [(0.900_001, 0.9), (1.199_999, 1.2)] {
        let a = DampingModel::FairedTheories
            .increment(&config, inside, 0.0, Harmonic::Direct, true)
            .unwrap()
            .solution;
        let b = DampingModel::FairedTheories
            .increment(&config, end, 0.0, Harmonic::Direct, true)
            .unwrap()
            .solution;
        assert!((a.lift_alpha - b.lift_alpha).abs() < 1e-4 * b.lift_alpha.abs());
        assert!((a.moment_q - b.moment_q).abs() < 1e-4 * b.moment_q.abs());
    }
}

#[test]
fn a_tail_inside_the_tips_mach_lines_is_warned_of() {
    use stability_core::aerodynamics::warnings::Warning;
    // the tail's centre at 15 + ⅔·2.5 = 16.7 (2.5 c̄); the tips' Mach lines
    // (tip trailing edge at x = 10, s = 10) meet the centre line at
    // 10 + β·10 = 27.3 at M = 2 (4.10 c̄): warned; 400 aft: not
    let (mut near, config) = tailed(2.0);
    near.aero.configuration = Some(Arc::new(config.clone()));
    let r = evaluate(&near).unwrap();
    let found = r.warnings.iter().find_map(|w| match *w {
        Warning::DownwashNearWing { at, from, .. } => Some((at, from)),
        _ => None,
    });
    let (at, from) = found.expect("warned");
    let cbar = 20.0 / 3.0;
    assert!((at - (15.0 + 2.5 * 2.0 / 3.0) / cbar).abs() < 1e-12, "{at}");
    assert!(
        (from - (10.0 + 3f64.sqrt() * 10.0) / cbar).abs() < 1e-12,
        "{from}"
    );
    let mut far = near.clone();
    let mut c = config;
    c.tailplane.as_mut().unwrap().x = 400.0;
    far.aero.configuration = Some(Arc::new(c));
    let r = evaluate(&far).unwrap();
    assert!(
        !r.warnings
            .iter()
            .any(|w| matches!(w, Warning::DownwashNearWing { .. }))
    );
}

/// Under the default `faired` model a configuration's increment is one
/// lifting surface through M = 1, as the wing's damping is: the
/// multi-surface lattice to 0.99 (the same numbers as the note's bands give
/// at M ≤ 0.9, the same lattice), a straight bridge from 0.99 to the first
/// Mach number where every surface has its Mach box, continuous at both
/// ends, and the Mach box for every surface beyond — which at M = 2, where
/// the 45° surfaces' leading edges are supersonic and linear theory is
/// exact for them, meets the supersonic-edge theory's increment within the
/// Mach box's tabled error.
#[test]
fn the_faired_increment_is_one_lifting_surface_through_m_1() {
    use stability_core::aerodynamics::models::faired::{SONIC_JOIN, increment_mach_box_from};
    let (_, config) = tailed(1.0);
    let at = |model: DampingModel, m: f64, w: f64| {
        model
            .increment(&config, m, w, Harmonic::Direct, false)
            .unwrap()
            .solution
    };
    let close = |a: f64, b: f64, tol: f64| (a - b).abs() <= tol * b.abs().max(1e-3);
    let lattice = at(DampingModel::Faired, 0.5, 0.0);
    assert_eq!(lattice, at(DampingModel::FairedTheories, 0.5, 0.0));
    let from = increment_mach_box_from(&config);
    assert!(from > 1.0 && from < 1.1, "{from}");
    for w in [0.0] {
        let (lo, lo_in) = (
            at(DampingModel::Faired, SONIC_JOIN, w),
            at(DampingModel::Faired, SONIC_JOIN + 1e-7, w),
        );
        let (hi, hi_in) = (
            at(DampingModel::Faired, from, w),
            at(DampingModel::Faired, from - 1e-7, w),
        );
        for (a, b) in [(lo_in, lo), (hi_in, hi)] {
            assert!(
                close(a.lift_alpha, b.lift_alpha, 1e-4),
                "ω̄ {w}: {a:?} {b:?}"
            );
            assert!(close(a.moment_q, b.moment_q, 1e-4), "ω̄ {w}: {a:?} {b:?}");
        }
    }
    let mach_box = at(DampingModel::Faired, 2.0, 0.0);
    let theory = at(DampingModel::FairedTheories, 2.0, 0.0);
    for (a, b) in [
        (mach_box.lift_alpha, theory.lift_alpha),
        (mach_box.moment_alpha, theory.moment_alpha),
        (mach_box.lift_q, theory.lift_q),
        (mach_box.moment_q, theory.moment_q),
    ] {
        assert!(
            close(a, b, 2e-2),
            "M = 2: Mach box {a} against linear theory {b}"
        );
    }
}
