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
