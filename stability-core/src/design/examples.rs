//! Example aircraft: the derivative sets of `examples/*.toml`, for the
//! README, the documentation and the tests (defined here once).
//!
//! [`tailless_delta_45`] is the README's aircraft and
//! `examples/tailless-delta-45.toml`: a derivative set of the kind the
//! report studies (a tailless 45° delta near M = 0.9 at μ₁ = 50, §9,
//! Figs 27–31), illustrative values of the right size and sign.
//! [`tailless_delta_60`] with [`tailless_delta_60_flight`] is
//! `examples/tailless-delta-60-dimensional.toml`: a 60° delta at M = 0.8,
//! 11 000 m, with its dimensional flight condition (times in seconds).
//! `tests/it/examples.rs` checks both against the files.

use crate::Derivatives;
use crate::analysis::Dimensional;

/// A tailless 45° delta near M = 0.9, μ₁ = 50, in the report's notation
/// (§3): `examples/tailless-delta-45.toml`. Its short period is
/// −6.8297 ± 17.509i (1/τ), stable, 0.11 cycles to half amplitude.
///
/// x_ẇ, x_q and m_u are zero, as the report takes them (eqs 30, 31, 13);
/// tests that must exercise every term of the quartic set them with
/// struct-update syntax, `Derivatives { x_wdot: 0.01, ..tailless_delta_45() }`.
pub const fn tailless_delta_45() -> Derivatives {
    Derivatives {
        x_u: -0.03,
        x_w: 0.25,
        x_wdot: 0.0,
        x_q: 0.0,
        z_u: -0.62,
        z_w: -3.2,
        z_wdot: -0.6,
        z_q: -1.5,
        m_u: 0.0,
        m_w: -0.55,
        m_wdot: -0.25,
        m_q: -0.6,
        c_l: 0.3,
        mu1: 50.0,
        i_b: 0.08,
    }
}

/// [`tailless_delta_45`] with the small derivatives the report neglects
/// made non-zero (x_ẇ = 0.01, x_q = 0.02, m_u = 0.01), so that every term
/// of eqs (2)–(6) takes part.
pub const fn tailless_delta_45_coupled() -> Derivatives {
    Derivatives {
        x_wdot: 0.01,
        x_q: 0.02,
        m_u: 0.01,
        ..tailless_delta_45()
    }
}

/// A tailless 60° delta (A = 4 cot 60° = 2.31) at M = 0.8, 11 000 m:
/// slender-wing damping derivatives (eq 37) at h = 0.25, illustrative
/// stiffness derivatives; `examples/tailless-delta-60-dimensional.toml`.
pub const fn tailless_delta_60() -> Derivatives {
    Derivatives {
        x_u: -0.02,
        x_w: 0.08,
        x_wdot: 0.0,
        x_q: 0.0,
        z_u: -0.24,
        z_w: -3.65,
        z_wdot: -1.81,
        z_q: -2.72,
        m_u: 0.0,
        m_w: -0.91,
        m_wdot: -0.68,
        m_q: -1.36,
        c_l: 0.121,
        mu1: 138.2,
        i_b: 0.06,
    }
}

/// The dimensional flight condition of [`tailless_delta_60`]: V = 280 m/s,
/// ρ = 0.4135 kg/m³, S = 60 m², c̄ = 7 m, m = 12 000 kg (τ = 3.455 s).
pub const fn tailless_delta_60_flight() -> Dimensional {
    Dimensional {
        v: 280.0,
        rho: 0.4135,
        s: 60.0,
        chord: 7.0,
        mass: 12000.0,
    }
}
