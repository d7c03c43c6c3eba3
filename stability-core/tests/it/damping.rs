//! The damping derivatives of §7 against independent routes: values worked
//! by hand, the limits the report states, the kinematics of a shift of the
//! pitching axis, and the elliptic-integral functions of Fig 18 against
//! mpmath (30 digits, quoted to f64 precision).
#![allow(clippy::excessive_precision)]

use stability_core::aerodynamics::damping::{
    DampingDerivatives, DampingError, Fig18, Theory, WingInput, damping_derivatives, eq36,
    mangler_k,
};
use std::f64::consts::PI;

fn wing(deg: f64, taper: f64) -> WingInput {
    let sweep = deg.to_radians();
    WingInput {
        aspect_ratio: 4.0 / sweep.tan() * (1.0 - taper) / (1.0 + taper),
        sweep_le: sweep,
        taper,
    }
}

fn close(a: f64, b: f64, tol: f64, what: &str) {
    assert!((a - b).abs() <= tol * (1.0 + b.abs()), "{what}: {a} vs {b}");
}

fn same(a: &DampingDerivatives, b: &DampingDerivatives, tol: f64, what: &str) {
    close(a.z_q, b.z_q, tol, &format!("{what} z_q"));
    close(a.z_wdot, b.z_wdot, tol, &format!("{what} z_wdot"));
    close(a.m_q, b.m_q, tol, &format!("{what} m_q"));
    close(a.m_wdot, b.m_wdot, tol, &format!("{what} m_wdot"));
}

#[test]
fn slender_values_by_hand() {
    // 45° true delta, A = 4, h = 0.25:
    // z_q = −2π(0.75) = −4.71239, z_ẇ = −π, m_q = −π(0.125 − 0.75 + 1.375) = −0.75π,
    // m_ẇ = −π(0.375), m_θ̇ = −2π(0.5625) = −1.125π, z_θ̇ = −π(2.5) (eqs 32–33)
    let d = damping_derivatives(Theory::Slender, &wing(45.0, 0.0), 0.25, 0.5, None)
        .unwrap()
        .derivatives;
    close(d.z_q, -1.5 * PI, 1e-15, "z_q");
    close(d.z_wdot, -PI, 1e-15, "z_wdot");
    close(d.m_q, -0.75 * PI, 1e-15, "m_q");
    close(d.m_wdot, -0.375 * PI, 1e-15, "m_wdot");
    close(d.m_thetadot(), -1.125 * PI, 1e-15, "m_thetadot (33)");
    close(d.z_thetadot(), -2.5 * PI, 1e-15, "z_thetadot (32)");
    // 60°: A = 4 cot 60° = 2.3094; m_θ̇ = −(πA/2)(0.75)² = −2.04045
    let d = damping_derivatives(Theory::Slender, &wing(60.0, 0.0), 0.25, 0.5, None)
        .unwrap()
        .derivatives;
    close(
        d.m_thetadot(),
        -PI * 4.0 / 3f64.sqrt() / 2.0 * 0.5625,
        1e-14,
        "60° m_thetadot",
    );
}

#[test]
fn garrick_is_slender_wing_theory() {
    // The report: (36)–(37) "are identical with the results of the Low
    // Aspect Ratio theory of Garrick".
    for h in [0.0, 0.25, 0.5, 1.0] {
        let g = damping_derivatives(Theory::Garrick, &wing(55.0, 0.0), h, 0.3, None)
            .unwrap()
            .derivatives;
        let s = damping_derivatives(Theory::Slender, &wing(55.0, 0.0), h, 0.3, None)
            .unwrap()
            .derivatives;
        same(&g, &s, 1e-14, "garrick vs slender");
        // m_θ̇ vanishes with the axis at the trailing edge, h = 1 (§7)
        if h == 1.0 {
            assert!(g.m_thetadot().abs() < 1e-14);
        }
    }
}

#[test]
fn garner_taper_reproduces_the_printed_34_and_35() {
    let w = wing(45.0, 1.0 / 7.0);
    let a = w.aspect_ratio;
    for h in [0.1, 0.25, 0.4] {
        let d = damping_derivatives(Theory::GarnerTaper, &w, h, 0.3, None)
            .unwrap()
            .derivatives;
        // (34): z_θ̇ = −πA(0.728 − 0.446h), printed to three figures
        close(d.z_thetadot(), -PI * a * (0.728 - 0.446 * h), 0.003, "(34)");
        // (35): m_θ̇ = −0.4πA(h − 1)², printed to one figure
        close(
            d.m_thetadot(),
            -0.4 * PI * a * (h - 1.0).powi(2),
            0.01,
            "(35)",
        );
    }
    assert_eq!(
        damping_derivatives(Theory::GarnerTaper, &wing(45.0, 0.0), 0.25, 0.3, None).unwrap_err(),
        DampingError::Taper { taper: 0.0 }
    );
}

#[test]
fn eq36_reduces_to_eq37_with_h_and_e_equal_to_one() {
    // The report: "the theories of Mangler, Ribner and Malvestuto reduce to
    // the above simple relations when we set H = E = 1".
    for (deg, h, mach) in [(45.0, 0.25, 1.3), (60.0, 0.4, 1.1), (70.0, 0.1, 2.0)] {
        let w = wing(deg, 0.0);
        let s = damping_derivatives(Theory::Slender, &w, h, mach, None)
            .unwrap()
            .derivatives;
        same(
            &eq36(w.aspect_ratio, h, mach, 1.0, 1.0),
            &s,
            1e-14,
            "(36) with H = E = 1",
        );
    }
}

#[test]
fn eq36_obeys_the_kinematics_of_a_shift_of_axis() {
    // About an axis moved aft by Δh (chords): z_q(h) = z_q(0) − h z_w,
    // m_q(h) = m_q(0) − h(z_q(0) + m_w(0)) + h² z_w, m_ẇ(h) = m_ẇ(0) − h z_ẇ,
    // with z_w = −πA/(2E) (the lift slope 2π cot Λ/E) and m_w(0) = z_w/2.
    // This pins the h-dependence of the recovered (36) independently of
    // its OCR text.
    let w = wing(50.0, 0.0);
    let mach = 1.25;
    let at = |h| damping_derivatives(Theory::Supersonic, &w, h, mach, None).unwrap();
    let d0 = at(0.0);
    let e = d0.fig18.unwrap().e;
    let z_w = -PI * w.aspect_ratio / (2.0 * e);
    for h in [0.2, 0.35, 0.6] {
        let d = at(h).derivatives;
        close(d.z_q, d0.derivatives.z_q - h * z_w, 1e-13, "z_q shift");
        close(
            d.m_q,
            d0.derivatives.m_q - h * (d0.derivatives.z_q + z_w / 2.0) + h * h * z_w,
            1e-13,
            "m_q shift",
        );
        close(
            d.m_wdot,
            d0.derivatives.m_wdot - h * d0.derivatives.z_wdot,
            1e-13,
            "m_wdot shift",
        );
    }
}

#[test]
fn fig18_functions_against_mpmath() {
    // mpmath (30 digits): k² = 1 − (β cot Λ)², E = ellipe(k²), K = ellipk(k²),
    // G = k²/((2k² − 1)E + (1 − k²)K), H = E·G
    let reference = [
        (
            0.2,
            1.050_502_226_984_45,
            0.883_078_113_458_811_27,
            0.927_675_524_789_708_09,
        ),
        (
            0.5,
            1.211_056_027_568_459_5,
            0.655_218_155_927_479_43,
            0.793_505_897_108_264_74,
        ),
        (
            0.9,
            1.493_290_108_131_207_2,
            0.458_494_613_823_917_44,
            0.684_665_471_454_693_75,
        ),
    ];
    for (bc, e, g, h) in reference {
        let f = Fig18::at(bc);
        close(f.e, e, 1e-14, "E");
        close(f.g, g, 1e-13, "G");
        close(f.h, h, 1e-13, "H");
    }
    // H → 1, E → 1 as M → 1 (β cot Λ → 0); H → 2/3, E → π/2 as the leading
    // edge turns sonic (β cot Λ → 1): continuous there.
    let f = Fig18::at(1e-4);
    assert!(
        (f.e - 1.0).abs() < 1e-6 && (f.h - 1.0).abs() < 1e-6,
        "{f:?}"
    );
    let near = Fig18::at(1.0 - 1e-6);
    let at = Fig18::at(1.0);
    assert!(
        (near.h - 2.0 / 3.0).abs() < 1e-5 && (at.h - 2.0 / 3.0).abs() < 1e-12,
        "{near:?} {at:?}"
    );
    assert!((at.e - PI / 2.0).abs() < 1e-12);
}

#[test]
fn the_report_on_the_45_and_60_degree_deltas_at_m_1_2() {
    // "The results indicate that the 45° delta has negative damping for the
    // specified practical C.G. range of 0.4 < x₀/c₀ < 0.6 at M = 1.2"
    // (h = 1.5(x₀/c₀ − 1/3): 0.1 … 0.4); §10: "this is not the case for the
    // 60° delta".
    for xo in [0.4, 0.5, 0.6] {
        let h = 1.5 * (xo - 1.0 / 3.0);
        let d45 = damping_derivatives(Theory::Supersonic, &wing(45.0, 0.0), h, 1.2, None).unwrap();
        assert!(
            d45.derivatives.m_thetadot() > 0.0,
            "45°, x₀/c₀ = {xo}: m_θ̇ = {}",
            d45.derivatives.m_thetadot()
        );
        let d60 = damping_derivatives(Theory::Supersonic, &wing(60.0, 0.0), h, 1.2, None).unwrap();
        assert!(
            d60.derivatives.m_thetadot() < 0.0,
            "60°, x₀/c₀ = {xo}: m_θ̇ = {}",
            d60.derivatives.m_thetadot()
        );
    }
}

#[test]
fn eq39_reduces_to_eq38_when_k_is_one_and_k_prime_zero() {
    // k = 1 and k′ = 0 where 3 ln(ω̄ cot²Λ) = 4.959; dropping (9/64)π cot³Λ
    // then leaves (38), i.e. (37).
    for deg in [45.0, 60.0] {
        let w = wing(deg, 0.0);
        let cot2 = 1.0 / w.sweep_le.tan().powi(2);
        let omega = (4.959f64 / 3.0).exp() / cot2;
        let (k, kp) = mangler_k(omega, w.sweep_le);
        assert!((k - 1.0).abs() < 1e-12 && kp.abs() < 1e-12);
        let f = damping_derivatives(Theory::TransonicFrequency, &w, 0.25, 1.0, Some(omega))
            .unwrap()
            .derivatives;
        let t = damping_derivatives(Theory::Transonic, &w, 0.25, 1.0, None)
            .unwrap()
            .derivatives;
        let extra = 9.0 / 64.0 * PI * cot2.powf(1.5);
        close(f.z_q, t.z_q, 1e-14, "z_q");
        close(f.z_wdot, t.z_wdot, 1e-12, "z_wdot");
        close(f.m_q, t.m_q, 1e-14, "m_q");
        close(f.m_wdot + extra, t.m_wdot, 1e-12, "m_wdot + (9/64)π cot³Λ");
    }
}

#[test]
fn eq39_damping_in_pitch_as_printed() {
    // z_θ̇ = −(πA/4)(3 − 2h) + k′, m_θ̇ = −(πA/2)(h − 1)² + (5/8 − h)k′ − (9/64)π cot³Λ
    let w = wing(45.0, 0.0);
    for (omega, h) in [(0.05, 0.25), (0.3, 0.4), (1.2, 0.1)] {
        let d = damping_derivatives(Theory::TransonicFrequency, &w, h, 1.0, Some(omega))
            .unwrap()
            .derivatives;
        let (_, kp) = mangler_k(omega, w.sweep_le);
        let a = w.aspect_ratio;
        let cot = 1.0 / w.sweep_le.tan();
        close(
            d.z_thetadot(),
            -PI * a / 4.0 * (3.0 - 2.0 * h) + kp,
            1e-13,
            "z_θ̇ (39)",
        );
        close(
            d.m_thetadot(),
            -PI * a / 2.0 * (h - 1.0).powi(2) + (5.0 / 8.0 - h) * kp
                - 9.0 / 64.0 * PI * cot.powi(3),
            1e-13,
            "m_θ̇ (39)",
        );
    }
}

#[test]
fn theories_outside_their_validity_are_errors_not_nan() {
    let w = wing(45.0, 0.0);
    assert_eq!(
        damping_derivatives(Theory::Supersonic, &w, 0.25, 0.9, None).unwrap_err(),
        DampingError::SubsonicMach { mach: 0.9 }
    );
    // 45°: the leading edge is sonic at M = √2; beyond it the supersonic-edge
    // theory, which for a true delta is the strip integral of Ackeret's
    // plate: z_q = −(4/β)(½ − h), z_ẇ = 2/β³ (β² = 1.56)
    let d = damping_derivatives(Theory::Supersonic, &w, 0.25, 1.6, None).unwrap();
    let beta = 1.56f64.sqrt();
    close(
        d.derivatives.z_q,
        -4.0 / beta * 0.25,
        1e-14,
        "z_q beyond the sonic edge",
    );
    close(
        d.derivatives.z_wdot,
        2.0 / beta.powi(3),
        1e-14,
        "z_ẇ beyond the sonic edge",
    );
    assert!(d.fig18.is_none(), "no Fig 18 past the sonic edge");
    // a wing input whose aspect ratio is not its planform's
    let odd = WingInput {
        aspect_ratio: 3.0,
        ..w
    };
    assert!(matches!(
        damping_derivatives(Theory::Supersonic, &odd, 0.25, 1.2, None),
        Err(DampingError::AspectRatio { .. })
    ));
    assert!(matches!(
        damping_derivatives(Theory::TransonicFrequency, &w, 0.25, 1.0, None),
        Err(DampingError::Frequency {
            omega_bar: None,
            ..
        })
    ));
    assert!(matches!(
        damping_derivatives(Theory::TransonicFrequency, &w, 0.25, 1.0, Some(-1.0)),
        Err(DampingError::Frequency {
            omega_bar: Some(_),
            ..
        })
    ));
    let bad = WingInput { sweep_le: 0.0, ..w };
    assert!(matches!(
        damping_derivatives(Theory::Slender, &bad, 0.25, 0.5, None),
        Err(DampingError::Sweep { .. })
    ));
    // with no frequency to check the low-frequency rule against, the
    // largest ω̄ at which it holds: 0.5·(2/3)·(1.05² − 1)/1.05² = 0.0310
    let d = damping_derivatives(Theory::Supersonic, &w, 0.25, 1.05, None).unwrap();
    assert!(
        d.warnings
            .iter()
            .any(|m| m.to_string().contains("holds for ω̄ ≤ 0.031")),
        "{:?}",
        d.warnings
    );
}
