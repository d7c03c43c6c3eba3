//! The derive on the project's own spec, checked against a hand expansion.

use derive_quartic::Quartic;

#[derive(Quartic)]
#[quartic(spec = "../stability-core/specs/quartic.toml")]
#[allow(dead_code)]
struct D {
    x_u: f64,
    x_w: f64,
    x_wdot: f64,
    x_q: f64,
    z_u: f64,
    z_w: f64,
    z_wdot: f64,
    z_q: f64,
    m_u: f64,
    m_w: f64,
    m_wdot: f64,
    m_q: f64,
    c_l: f64,
    mu1: f64,
    i_b: f64,
}

#[test]
fn names_follow_the_spec() {
    assert_eq!(D::QUARTIC_COEFFICIENTS, ["A", "B", "C", "D", "E"]);
    assert_eq!(D::QUARTIC_INPUTS.len(), 15);
    assert_eq!(D::QUARTIC_INPUTS[0], "x_u");
    assert_eq!(D::QUARTIC_INPUTS[14], "i_b");
}

#[test]
fn a_short_period_only_case_by_hand() {
    // Only z_w, m_w, m_q, z_q non-zero, mu1 = 10, i_b = 0.5, c_l = 0:
    // A = 1, B = -z_w - m_q/i_b, C = z_w m_q/i_b - m_w (mu1 + z_q)/i_b,
    // D = E = 0 (no u coupling, no gravity).
    let d = D {
        x_u: 0.0,
        x_w: 0.0,
        x_wdot: 0.0,
        x_q: 0.0,
        z_u: 0.0,
        z_w: -2.0,
        z_wdot: 0.0,
        z_q: -1.0,
        m_u: 0.0,
        m_w: -0.3,
        m_wdot: 0.0,
        m_q: -0.4,
        c_l: 0.0,
        mu1: 10.0,
        i_b: 0.5,
    };
    let [a, b, c, dd, e] = d.quartic_coefficients();
    assert_eq!(a, 1.0);
    assert!((b - (2.0 + 0.8)).abs() < 1e-15);
    assert!((c - (-2.0 * -0.4 / 0.5 + 0.3 * (10.0 - 1.0) / 0.5)).abs() < 1e-14);
    assert_eq!(dd, 0.0);
    assert_eq!(e, 0.0);
}

/// `quartic_coefficients_of` over complex inputs (the p-method's air forces
/// at a complex frequency) against the determinant of eq (4) expanded by
/// cofactors here, entry by entry as the spec writes its rows, at several
/// complex λ; and over f64 it is `quartic_coefficients`, bit for bit.
#[test]
fn the_generic_coefficients_are_the_determinant_over_complex_numbers() {
    use num_complex::Complex64 as C;
    let real = [
        -0.02, -0.01, 0.006, -0.003, -0.008, -2.3, 0.36, -0.58, 0.004, -0.58, 0.13, -0.43, 0.0125,
        50.0, 0.08,
    ];
    let d = D {
        x_u: real[0],
        x_w: real[1],
        x_wdot: real[2],
        x_q: real[3],
        z_u: real[4],
        z_w: real[5],
        z_wdot: real[6],
        z_q: real[7],
        m_u: real[8],
        m_w: real[9],
        m_wdot: real[10],
        m_q: real[11],
        c_l: real[12],
        mu1: real[13],
        i_b: real[14],
    };
    let same = D::quartic_coefficients_of(real).map(f64::to_bits);
    assert_eq!(same, d.quartic_coefficients().map(f64::to_bits));
    let mut v = real.map(|x| C::new(x, 0.0));
    // complex damping derivatives, as at a complex frequency
    v[6] = C::new(0.36, -0.05);
    v[7] = C::new(-0.58, 0.02);
    v[10] = C::new(0.13, 0.03);
    v[11] = C::new(-0.43, -0.01);
    let coefficients = D::quartic_coefficients_of(v);
    let [
        x_u,
        x_w,
        x_wdot,
        x_q,
        z_u,
        z_w,
        z_wdot,
        z_q,
        m_u,
        m_w,
        m_wdot,
        m_q,
        c_l,
        mu1,
        i_b,
    ] = v;
    for lam in [C::new(-3.0, 19.0), C::new(-0.01, 0.03), C::new(0.5, 0.0)] {
        let m = [
            [
                lam - x_u,
                -(x_w + x_wdot / mu1 * lam),
                c_l - x_q / mu1 * lam,
            ],
            [
                -z_u,
                -(z_w + (z_wdot / mu1 - 1.0) * lam),
                -(z_q / mu1 + 1.0) * lam,
            ],
            [
                -mu1 / i_b * m_u,
                -(mu1 / i_b * m_w + m_wdot / i_b * lam),
                lam * lam - m_q / i_b * lam,
            ],
        ];
        let det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
        let poly = coefficients
            .iter()
            .fold(C::new(0.0, 0.0), |acc, &c| acc * lam + c);
        // eq (6) is the determinant itself (its λ⁴ coefficient A = 1 − z_ẇ/μ₁)
        assert!(
            (poly / det - 1.0).norm() < 1e-12,
            "λ = {lam}: {poly} vs {det}"
        );
    }
}
