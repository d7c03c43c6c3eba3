//! The lift slope a and aerodynamic centre H₀ of [`super::edge_theory`],
//! each with its Mach derivative: what the stiffness derivatives x_u, z_u,
//! m_u need (eqs 27–29: (∂C_L/∂M)_α = (C_L/a) da/dM,
//! (∂C_m/∂M)_α = −C_L dH₀/dM + (h − H₀)(C_L/a) da/dM) when a case takes its
//! coefficients from its damping theory (`aero::Source::Default` under
//! `--damping supersonic`).
//!
//! - Subsonic leading edges, true delta, eq (36) (Mangler; Ribner &
//!   Malvestuto): a = πA/(2E(k)), k² = 1 − β²cot²Λ, so with
//!   dE/dm = (E − K)/(2m) (m = k², `aero::defaults::ellip_e_and_slope`) and
//!   dk²/dM = −2M cot²Λ, da/dM = (πA/(2E²))·(dE/dm)·2M cot²Λ; H₀ = ½,
//!   dH₀/dM = 0. As M → 1⁺, K grows like ln(4/k′) and da/dM like
//!   −ln(1/β): linear theory's logarithm again (see [`super::transonic`]).
//! - Sonic or supersonic leading edges, true delta ([`super::strip`]):
//!   a = 4/β, da/dM = −4M/β³; H₀ = ½.
//! - Cropped delta, either side ([`super::subsonic_edge`] with subsonic
//!   leading edges, [`super::evvard`] with supersonic ones): no closed
//!   form for H₀ (nor for a but where a tip's reach stays on its own
//!   half-wing, supersonic edges), so both derivatives are numerical — the
//!   fourth-order five-point difference of the potential integrals with
//!   step [`STEP`] in M, central where the stencil stays on one side of the
//!   sonic edge and in that side's domain (subsonic edges: 2βs ≥ c_t;
//!   supersonic: 2βs ≥ c₀), else one-sided: forward near a side's lower
//!   end (the sonic edge, where in its band of [`super::SONIC_EDGE_TOLERANCE`]
//!   the derivative is the supersonic side's), backward near its upper end
//!   (the sonic edge seen from below). The integrals' quadrature is a fixed
//!   tanh-sinh rule, a smooth function of M accurate to about 1e-11, so the
//!   difference is accurate to about 1e-8 (tests/it/supersonic.rs: against
//!   the derivative of the closed-form lift slope
//!   `evvard::lift_slope_closed`, a central difference of the independent
//!   direct source integral, and Richardson-extrapolated differences of
//!   the subsonic side's values).
//!
//! The slope of a has a kink at the sonic edge in linear theory: aβ against
//! m = β cot Λ rises with slope 2 below m = 1 (E ≈ (π/2)(1 − k²/4)) and is
//! flat above, so for the true delta da/dM is −2M/β³ on the subsonic side
//! and −4M/β³ on the supersonic side (a cropped delta's likewise differ).
//! a and H₀ are continuous there, for every taper; their Mach derivatives,
//! and with them x_u, z_u, m_u, are not.

use super::eq36::Fig18;
use super::{EdgeRegime, SupersonicError, Wing, check_mach};
use crate::numerics::elliptic::ellip_e_and_slope;
use crate::numerics::interpolation::Value;
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
        _ if wing.taper > 0.0 => cropped(wing, mach, regime)?,
        EdgeRegime::SubsonicEdge => (eq36_lift_slope(wing, mach), Value::new(0.5, 0.0)),
        _ => (
            Value::new(4.0 / beta, -4.0 * mach / (beta * beta * beta)),
            Value::new(0.5, 0.0),
        ),
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

/// a and H₀ of the cropped delta from its potential integrals
/// ([`super::subsonic_edge`] or [`super::evvard`], as [`super::edge_theory`]).
fn cropped_values(wing: &Wing, mach: f64) -> Result<[f64; 2], SupersonicError> {
    let d = super::edge_theory(wing, mach, 0.0)?.derivatives;
    Ok([d.lift_slope, d.aerodynamic_centre])
}

/// The lowest Mach number at which the cropped delta's supersonic-edge
/// theory holds: the sonic edge, or where 2βs = c₀ if later.
pub fn domain_start(wing: &Wing) -> f64 {
    let two_s = 2.0 * wing.semi_span();
    wing.sonic_mach().max((1.0 + 1.0 / (two_s * two_s)).sqrt())
}

/// Whether the cropped delta's theory at `mach` is the one of the side
/// `subsonic` (subsonic leading edges, [`super::subsonic_edge`], which
/// needs 2βs ≥ c_t; or sonic and supersonic ones, [`super::evvard`], which needs
/// 2βs ≥ c₀): a stencil stays on one side, since a and H₀ have a kink at
/// the sonic edge.
fn on_side(wing: &Wing, subsonic: bool, mach: f64) -> bool {
    if mach.is_nan() || mach <= 1.0 {
        return false;
    }
    let beta = (mach * mach - 1.0).sqrt();
    let two_beta_s = 2.0 * beta * wing.semi_span();
    if subsonic {
        EdgeRegime::of(beta * wing.cot()) == EdgeRegime::SubsonicEdge && two_beta_s >= wing.taper
    } else {
        EdgeRegime::of(beta * wing.cot()) != EdgeRegime::SubsonicEdge && two_beta_s >= 1.0
    }
}

/// The cropped delta's a and H₀ with their five-point numerical
/// derivatives (module doc): central where the stencil stays on the side
/// of the sonic edge `regime` is on and in its domain, else one-sided
/// forward, else backward.
fn cropped(wing: &Wing, mach: f64, regime: EdgeRegime) -> Result<(Value, Value), SupersonicError> {
    let f0 = cropped_values(wing, mach)?;
    let at = |k: f64| cropped_values(wing, mach + k * STEP);
    let subsonic = regime == EdgeRegime::SubsonicEdge;
    let fits = |ks: &[f64]| ks.iter().all(|&k| on_side(wing, subsonic, mach + k * STEP));
    let d: [f64; 2] = if fits(&[-2.0, -1.0, 1.0, 2.0]) {
        let (m2, m1, p1, p2) = (at(-2.0)?, at(-1.0)?, at(1.0)?, at(2.0)?);
        std::array::from_fn(|i| (m2[i] - 8.0 * m1[i] + 8.0 * p1[i] - p2[i]) / (12.0 * STEP))
    } else {
        // forward (k = 1…4), or backward (k = −1…−4: the same weights,
        // negated)
        let sign = if fits(&[1.0, 2.0, 3.0, 4.0]) {
            1.0
        } else {
            -1.0
        };
        let (p1, p2, p3, p4) = (at(sign)?, at(2.0 * sign)?, at(3.0 * sign)?, at(4.0 * sign)?);
        std::array::from_fn(|i| {
            sign * (-25.0 * f0[i] + 48.0 * p1[i] - 36.0 * p2[i] + 16.0 * p3[i] - 3.0 * p4[i])
                / (12.0 * STEP)
        })
    };
    Ok((Value::new(f0[0], d[0]), Value::new(f0[1], d[1])))
}
