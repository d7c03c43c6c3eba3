//! The lift slope a and aerodynamic centre H₀ of [`super::edge_theory`],
//! each with its Mach derivative: what the stiffness derivatives x_u, z_u,
//! m_u need (eqs 27–29: (∂C_L/∂M)_α = (C_L/a) da/dM,
//! (∂C_m/∂M)_α = −C_L dH₀/dM + (h − H₀)(C_L/a) da/dM) when a case takes its
//! coefficients from its damping theory (`aero::Source::Default` under
//! `--damping supersonic`).
//!
//! - Subsonic leading edges, eq (36) (Mangler; Ribner & Malvestuto):
//!   a = πA/(2E(k)), k² = 1 − β²cot²Λ, so with dE/dm = (E − K)/(2m)
//!   (m = k², `aero::defaults::ellip_e_and_slope`) and dk²/dM = −2M cot²Λ,
//!   da/dM = (πA/(2E²))·(dE/dm)·2M cot²Λ; H₀ = ½, dH₀/dM = 0. As M → 1⁺,
//!   K grows like ln(4/k′) and da/dM like −ln(1/β): linear theory's
//!   logarithm again (see [`super::transonic`]).
//! - Sonic or supersonic leading edges, true delta ([`super::strip`]):
//!   a = 4/β, da/dM = −4M/β³; H₀ = ½.
//! - Supersonic leading edges, cropped delta ([`super::evvard`]): no closed
//!   form for H₀ (nor for a where a tip's reach crosses the root), so both
//!   derivatives are numerical — the fourth-order five-point difference of
//!   the Evvard integrals with step [`STEP`] in M, central where the stencil
//!   stays in the theory's domain (β cot Λ ≥ 1, 2βs ≥ c₀) and one-sided
//!   forward within 2·[`STEP`] of its lower end (the sonic edge, where the
//!   derivative is the supersonic side's). The integrals' quadrature is a
//!   fixed tanh-sinh rule, a smooth function of M accurate to about 1e-11,
//!   so the difference is accurate to about 1e-8 (tests/supersonic.rs:
//!   against the derivative of the closed-form lift slope
//!   `evvard::lift_slope_closed` and a central difference of the
//!   independent direct source integral).
//!
//! The slope of a has a kink at the sonic edge in linear theory: aβ against
//! m = β cot Λ rises with slope 2 below m = 1 (E ≈ (π/2)(1 − k²/4)) and is
//! flat above, so for the true delta da/dM is −2M/β³ on the subsonic side
//! and −4M/β³ on the supersonic side. a and H₀ are continuous there; their
//! Mach derivatives, and with them x_u, z_u, m_u, are not.

use super::eq36::Fig18;
use super::{EdgeRegime, SupersonicError, Wing, check_mach, evvard};
use crate::aero::{Value, defaults::ellip_e_and_slope};
use serde::Serialize;
use std::f64::consts::PI;

/// The step in Mach number of the numerical derivative: the five-point
/// rule's truncation error, h⁴f⁽⁵⁾/30, is then below 1e-10 for these smooth
/// functions, and the quadrature's 1e-11 contributes about 1e-8.
pub const STEP: f64 = 1e-3;

/// The result of [`edge_coefficients`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct EdgeCoefficients {
    pub regime: EdgeRegime,
    /// a = ∂C_L/∂α per radian, and da/dM.
    pub lift_slope: Value,
    /// H₀ (aft of the M.A.C.'s leading edge, in M.A.C.), and dH₀/dM.
    pub aerodynamic_centre: Value,
}

/// The lift slope and aerodynamic centre of [`super::edge_theory`] at
/// `mach` — the same values — with their Mach derivatives (module doc).
pub fn edge_coefficients(wing: &Wing, mach: f64) -> Result<EdgeCoefficients, SupersonicError> {
    let beta = check_mach(mach)?;
    let regime = EdgeRegime::of(beta * wing.cot());
    let (lift_slope, aerodynamic_centre) = match regime {
        EdgeRegime::SubsonicEdge => (eq36_lift_slope(wing, mach), Value::new(0.5, 0.0)),
        _ if wing.taper == 0.0 => (
            Value::new(4.0 / beta, -4.0 * mach / (beta * beta * beta)),
            Value::new(0.5, 0.0),
        ),
        _ => cropped(wing, mach)?,
    };
    Ok(EdgeCoefficients {
        regime,
        lift_slope,
        aerodynamic_centre,
    })
}

/// (36)'s a = πA/(2E) and its exact Mach derivative.
fn eq36_lift_slope(wing: &Wing, mach: f64) -> Value {
    let f = Fig18::at(wing.beta_cot(mach));
    let a = PI * wing.aspect_ratio() / (2.0 * f.e);
    let (_, de_dm) = ellip_e_and_slope(f.k2);
    let cot2 = wing.cot() * wing.cot();
    // da/dM = −a/E · dE/dm · dk²/dM, dk²/dM = −2M cot²Λ
    Value::new(a, a / f.e * de_dm * 2.0 * mach * cot2)
}

/// a and H₀ of the cropped delta from the Evvard integrals.
fn cropped_values(wing: &Wing, mach: f64) -> Result<[f64; 2], SupersonicError> {
    let d = evvard::integrals(wing, mach)?.derivatives(wing, mach, 0.0);
    Ok([d.lift_slope, d.aerodynamic_centre])
}

/// The lowest Mach number at which the cropped delta's supersonic-edge
/// theory holds: the sonic edge, or where 2βs = c₀ if later.
pub fn domain_start(wing: &Wing) -> f64 {
    let two_s = 2.0 * wing.semi_span();
    wing.sonic_mach().max((1.0 + 1.0 / (two_s * two_s)).sqrt())
}

/// The cropped delta's a and H₀ with their five-point numerical
/// derivatives (module doc).
fn cropped(wing: &Wing, mach: f64) -> Result<(Value, Value), SupersonicError> {
    let f0 = cropped_values(wing, mach)?;
    let at = |k: f64| cropped_values(wing, mach + k * STEP);
    let d: [f64; 2] = if mach - 2.0 * STEP >= domain_start(wing) {
        let (m2, m1, p1, p2) = (at(-2.0)?, at(-1.0)?, at(1.0)?, at(2.0)?);
        std::array::from_fn(|i| (m2[i] - 8.0 * m1[i] + 8.0 * p1[i] - p2[i]) / (12.0 * STEP))
    } else {
        let (p1, p2, p3, p4) = (at(1.0)?, at(2.0)?, at(3.0)?, at(4.0)?);
        std::array::from_fn(|i| {
            (-25.0 * f0[i] + 48.0 * p1[i] - 36.0 * p2[i] + 16.0 * p3[i] - 3.0 * p4[i])
                / (12.0 * STEP)
        })
    };
    Ok((Value::new(f0[0], d[0]), Value::new(f0[1], d[1])))
}
