//! The generated quartic coefficients and gradient against routes that do
//! not use the symbolic engine:
//!
//! 1. eq (6) typed by hand (corrected), `stability_core::dynamics::quartic::reference::eq6_by_hand`;
//! 2. the determinant of eq (4) evaluated numerically at five points on a
//!    circle and interpolated (inverse DFT);
//! 3. the *dimensional* equations of motion, eq (1): the 4×4 state matrix
//!    built from dimensional derivatives, its characteristic polynomial by
//!    the Faddeev–LeVerrier recurrence, converted to the time unit τ. This
//!    checks eq (4) itself (and the reading of its entry (1, 3)).
//! 4. the gradient against dual-number differentiation of route 1.
//!
//! On 200 random derivative sets plus edge cases.

use stability_core::dynamics::quartic::reference::{
    coefficients_by_interpolation, eq6_by_hand, gradient_by_dual_numbers, natural_radius,
};
use stability_core::{Derivatives, Quartic};
use workspace_tests::{SplitMix64, quartic_model, random_derivatives};

/// Σ|terms| of each coefficient at `d`: the scale of its rounding error.
fn scales(d: &Derivatives) -> [f64; 5] {
    let model = quartic_model();
    let mut v = d.quartic_input_values().to_vec();
    v.push(0.0); // the variable λ (absent from the coefficients)
    let mut s = [0.0; 5];
    for (k, c) in model.coefficients.iter().enumerate() {
        s[k] = c.expansion.eval_abs(&v);
    }
    s
}

fn cases() -> Vec<(String, Derivatives)> {
    let mut rng = SplitMix64(0x5EED_2026_1123);
    let mut out: Vec<(String, Derivatives)> = (0..200)
        .map(|i| (format!("random #{i}"), random_derivatives(&mut rng)))
        .collect();
    let base = random_derivatives(&mut rng);
    let mut zeros = Derivatives::from_quartic_input_values([0.0; 15]);
    zeros.mu1 = 50.0;
    zeros.i_b = 0.08;
    out.push(("all derivatives zero".into(), zeros));
    out.push(("all zero but C_L".into(), Derivatives { c_l: 0.3, ..zeros }));
    out.push(("mu1 = 1e6".into(), Derivatives { mu1: 1e6, ..base }));
    out.push(("i_b = 1e-3".into(), Derivatives { i_b: 1e-3, ..base }));
    out.push((
        "z_wdot = mu1 (A = 0)".into(),
        Derivatives {
            z_wdot: base.mu1,
            ..base
        },
    ));
    // The report's kind of case: a tailless delta at μ₁ = 50.
    let delta = Derivatives {
        x_u: -0.02,
        x_w: 0.15,
        x_wdot: 0.0,
        x_q: 0.0,
        z_u: -0.6,
        z_w: -2.0,
        z_wdot: -0.6,
        z_q: -1.3,
        m_u: 0.0,
        m_w: -0.35,
        m_wdot: -0.2,
        m_q: -0.5,
        c_l: 0.3,
        mu1: 50.0,
        i_b: 0.08,
    };
    out.push(("tailless delta, mu1 = 50".into(), delta));
    out
}

#[test]
fn generated_coefficients_match_eq6_by_hand() {
    for (name, d) in cases() {
        let generated = d.quartic_coefficients();
        let hand = eq6_by_hand(&d.quartic_input_values());
        let s = scales(&d);
        for k in 0..5 {
            let tol = 8.0 * f64::EPSILON * s[k];
            assert!(
                (generated[k] - hand[k]).abs() <= tol,
                "{name}: coefficient {} generated {} by hand {} (tolerance {tol:e})",
                ["A", "B", "C", "D", "E"][k],
                generated[k],
                hand[k]
            );
        }
    }
}

#[test]
fn generated_coefficients_match_the_interpolated_determinant() {
    for (name, d) in cases() {
        let v = d.quartic_input_values();
        let generated = d.quartic_coefficients();
        let (numeric, bound) = coefficients_by_interpolation(&v, natural_radius(&v));
        let s = scales(&d);
        for k in 0..5 {
            let tol = bound[k] + 8.0 * f64::EPSILON * s[k];
            assert!(
                (generated[k] - numeric[k]).abs() <= tol,
                "{name}: coefficient {} generated {} interpolated {} (tolerance {tol:e})",
                ["A", "B", "C", "D", "E"][k],
                generated[k],
                numeric[k]
            );
        }
    }
}

/// A misprint of eq (6) is caught by the interpolated determinant: the
/// report's B as printed (with `+z_w`) differs from it by 2·z_w.
#[test]
fn the_interpolation_route_detects_the_printed_sign_of_z_w_in_b() {
    let (_, d) = cases().pop().expect("cases");
    let v = d.quartic_input_values();
    let (numeric, bound) = coefficients_by_interpolation(&v, natural_radius(&v));
    let generated_b = d.quartic_coefficients()[1];
    let printed_b = generated_b + 2.0 * d.z_w; // +z_w where the expansion has −z_w
    assert!((printed_b - numeric[1]).abs() > 1e3 * bound[1]);
    assert!((generated_b - numeric[1]).abs() <= bound[1] + 1e-14);
}

/// The characteristic polynomial of a real n×n matrix by the
/// Faddeev–LeVerrier recurrence: `[1, p₁, …, pₙ]` of sⁿ + p₁sⁿ⁻¹ + … + pₙ.
fn faddeev_leverrier(a: &nalgebra::Matrix4<f64>) -> [f64; 5] {
    let id = nalgebra::Matrix4::<f64>::identity();
    let mut m = nalgebra::Matrix4::<f64>::zeros();
    let mut c = [0.0; 5];
    c[0] = 1.0;
    for k in 1..=4 {
        m = a * m + id * c[k - 1];
        c[k] = -(a * m).trace() / k as f64;
    }
    c
}

/// Route 3: eq (1) with dimensional derivatives (§3's definitions), wind
/// axes, level flight: state (u, w, q, θ).
fn dimensional_characteristic(d: &Derivatives) -> (f64, [f64; 5]) {
    let (rho, s, v, c) = (0.6, 30.0, 180.0, 4.0);
    let h = 0.5 * rho * s; // ½ρS
    let mass = d.mu1 * h * c;
    let inertia = d.i_b * mass * c * c;
    let tau = mass / (h * v);
    let weight = h * v * v * d.c_l; // W = mg = ½ρV²S·C_L, eq (24)
    let (xu, xw, xwd, xq) = (
        d.x_u * h * v,
        d.x_w * h * v,
        d.x_wdot * h * c,
        d.x_q * h * v * c,
    );
    let (zu, zw, zwd, zq) = (
        d.z_u * h * v,
        d.z_w * h * v,
        d.z_wdot * h * c,
        d.z_q * h * v * c,
    );
    let (mu, mw, mwd, mq) = (
        d.m_u * h * v * c,
        d.m_w * h * v * c,
        d.m_wdot * h * c * c,
        d.m_q * h * v * c * c,
    );
    // ẇ = (Z_u u + Z_w w + (Z_q + mV) q) / (m − Z_ẇ)
    let wdot = [zu, zw, zq + mass * v, 0.0].map(|x| x / (mass - zwd));
    let udot = [
        (xu + xwd * wdot[0]) / mass,
        (xw + xwd * wdot[1]) / mass,
        (xq + xwd * wdot[2]) / mass,
        -weight / mass,
    ];
    let qdot = [
        (mu + mwd * wdot[0]) / inertia,
        (mw + mwd * wdot[1]) / inertia,
        (mq + mwd * wdot[2]) / inertia,
        0.0,
    ];
    let a = nalgebra::Matrix4::from_row_slice(&[
        udot[0], udot[1], udot[2], udot[3], //
        wdot[0], wdot[1], wdot[2], wdot[3], //
        qdot[0], qdot[1], qdot[2], qdot[3], //
        0.0, 0.0, 1.0, 0.0,
    ]);
    // Balance before the recurrence: the similarity x' = Dx with
    // D = diag(1/V, 1/V, τ, 1) and the time scaling by τ leave the roots
    // (in units of 1/τ) unchanged and make the entries comparable in size.
    let dm = nalgebra::Matrix4::from_diagonal(&nalgebra::Vector4::new(1.0 / v, 1.0 / v, tau, 1.0));
    let dinv = nalgebra::Matrix4::from_diagonal(&nalgebra::Vector4::new(v, v, 1.0 / tau, 1.0));
    let balanced = dm * a * dinv * tau;
    (tau, faddeev_leverrier(&balanced))
}

#[test]
fn eq4_agrees_with_the_dimensional_equations_of_motion() {
    for (name, d) in cases() {
        if (d.mu1 - d.z_wdot).abs() < 1e-9 * d.mu1 {
            continue; // A = 0: the dimensional system has no state form
        }
        let q = Quartic::from_derivatives(&d).to_array();
        let (_tau, p) = dimensional_characteristic(&d);
        let s = scales(&d);
        for k in 1..5 {
            let ours = q[k] / q[0];
            let theirs = p[k];
            // The Faddeev–LeVerrier recurrence loses digits as ‖A‖⁴ (it is
            // not backward stable); seven digits still cannot agree by chance.
            let tol = 1e-7 * (s[k] + s[0] * ours.abs()) / q[0].abs();
            assert!(
                (ours - theirs).abs() <= tol,
                "{name}: {}/A = {ours} from eq (4) but {theirs} from eq (1) (tolerance {tol:e})",
                ["A", "B", "C", "D", "E"][k]
            );
        }
    }
}

#[test]
fn generated_gradient_matches_dual_number_differentiation() {
    let model = quartic_model();
    for (name, d) in cases() {
        let grad = d.quartic_gradient();
        let v = d.quartic_input_values();
        let mut at = v.to_vec();
        at.push(0.0);
        let dual = gradient_by_dual_numbers(&v);
        for (i, row) in grad.iter().enumerate() {
            for k in 0..5 {
                let scale = model.coefficients[k].expansion.derivative(i).eval_abs(&at);
                let tol = 16.0 * f64::EPSILON * scale;
                assert!(
                    (row[k] - dual[i][k]).abs() <= tol,
                    "{name}: ∂{}/∂{} generated {} dual {} (tolerance {tol:e})",
                    Derivatives::QUARTIC_COEFFICIENTS[k],
                    Derivatives::QUARTIC_INPUTS[i],
                    row[k],
                    dual[i][k]
                );
            }
        }
    }
}

#[test]
fn input_values_round_trip_in_spec_order() {
    let mut rng = SplitMix64(7);
    let d = random_derivatives(&mut rng);
    assert_eq!(
        Derivatives::from_quartic_input_values(d.quartic_input_values()),
        d
    );
    assert_eq!(
        d.quartic_input_values()[Derivatives::QUARTIC_INPUTS
            .iter()
            .position(|n| *n == "m_q")
            .unwrap()],
        d.m_q
    );
}
