//! The cropped delta with supersonic leading edges: two-dimensional strip
//! values less the deficits of the tip Mach cones.
//!
//! H.J. Evvard, "Use of source distributions for evaluating theoretical
//! aerodynamics of thin finite wings at supersonic speeds", NACA Rep. 951
//! (1950): at a point P behind a streamwise (subsonic) tip the potential is
//! the source integral over the wing in P's forecone *less* the region
//! between the tip, the leading edge and the Mach line from T, where P's
//! outboard forward Mach line meets the tip. In characteristic coordinates
//! u = (x − ξ) − β(y − η), v = (x − ξ) + β(y − η) about P that reduced area is
//! the rectangle u ≤ 2β(s − y), v ≤ 2β(s + y) clipped by the leading edge.
//!
//! Exchanging the order of integration (each source's contribution to the
//! receivers of its aft Mach cone; the reverse-flow theorem in another
//! guise), a source Q = (ξ, η) at distance δ = β(s − η) from the right tip
//! contributes to the receivers of a chordwise station x (d = x − ξ)
//! ∫ dy/R = π − D(δ, d) per tip, with the closed-form deficit
//! D(δ, d) = 2 arccos √(δ/d) for d > δ, 0 otherwise — the rectangular
//! wing's tip function 1 − (2/π) arcsin √(δ/d), here in source form. Its
//! chordwise integrals to the trailing edge are closed too:
//! K_j(δ, D) = ∫_δ^D dʲ D(δ, d) dd = [D^{j+1}·2 arccos √(δ/D) − √δ P_j]/(j + 1),
//! P₀ = 2√T, P₁ = (2/3)T^{3/2} + 2δ√T, T = D − δ.
//! What remains is a double integral of these weights over the region the
//! tip reaches (ξ < 1 − δ), done by tanh-sinh quadrature; the strip part is
//! closed (`strip::strip_integrals`).
//!
//! Limits: both tips are treated by one reflection each, which needs
//! 2βs ≥ c₀ (no source's aft cone reaches both tips' reflections; it also
//! keeps the Mach waves of one tip's diaphragm off the other's, c_t ≤ 2βs).
//! Beyond that an error, not a quiet answer.

use super::quadrature::tanh_sinh;
use super::strip::strip_integrals;
use super::{PotentialIntegrals, SupersonicError, Wing};
use std::f64::consts::PI;

/// Nodes per unit of the tanh-sinh variable (≈ 6.8·LEVEL + 1 nodes per
/// interval): 12 gives the integrals to about 1e-11.
const LEVEL: usize = 12;

/// The tip deficit D(δ, d) = 2 arccos √(δ/d), d > δ.
fn deficit(delta: f64, d: f64) -> f64 {
    2.0 * (delta / d).sqrt().min(1.0).acos()
}

/// K₀ and K₁ of the module doc at (δ, D).
fn chordwise(delta: f64, big_d: f64) -> (f64, f64) {
    let t = (big_d - delta).max(0.0);
    let a = deficit(delta, big_d);
    let sd = delta.sqrt();
    let st = t.sqrt();
    let k0 = big_d * a - sd * 2.0 * st;
    let k1 = (big_d * big_d * a - sd * (2.0 / 3.0 * t * st + 2.0 * delta * st)) / 2.0;
    (k0, k1)
}

/// The right tip's deficit weights at the source (ξ, η), in the order of
/// the [`PotentialIntegrals`] fields.
fn weights(wing: &Wing, beta: f64, xi: f64, eta: f64) -> [f64; 7] {
    let delta = beta * (wing.semi_span() - eta);
    let d = 1.0 - xi;
    if d <= delta {
        return [0.0; 7];
    }
    let d1 = deficit(delta, d);
    let (k0, k1) = chordwise(delta, d);
    [d1, xi * d1, k0, xi * k0, xi * k0 + k1, (xi - 1.0) * d1, -k1]
}

/// The η-intervals of the sources the right tip reaches (ξ < 1 − β(s − η)
/// behind the leading edge ξ = |η| tan Λ), split at the apex's η = 0.
fn tip_reach(wing: &Wing, beta: f64) -> [(f64, f64); 2] {
    let s = wing.semi_span();
    let tan = wing.sweep_le.tan();
    let lead = beta * s - 1.0;
    let left = ((lead / (beta + tan)).max(-s), 0.0);
    let right_from = if lead > 0.0 { lead / (beta - tan) } else { 0.0 };
    [left, (right_from.max(0.0), s)]
}

/// The [`PotentialIntegrals`] of the cropped delta at Mach `mach`
/// (β cot Λ ≥ 1 assumed, checked by the caller): strip values plus
/// (2/(πβ)) ∫∫ (the right tip's deficit weights) dS, both tips alike.
pub fn integrals(wing: &Wing, mach: f64) -> Result<PotentialIntegrals, SupersonicError> {
    let beta = (mach * mach - 1.0).sqrt();
    let two_beta_s = 2.0 * beta * wing.semi_span();
    if two_beta_s < 1.0 {
        return Err(SupersonicError::TipsInteract {
            mach,
            taper: wing.taper,
            two_beta_s,
            limit: 1.0,
        });
    }
    let strip = strip_integrals(wing, mach);
    if wing.taper == 0.0 {
        return Ok(strip);
    }
    let s = wing.semi_span();
    let tan = wing.sweep_le.tan();
    let mut sum = [0.0; 7];
    for (lo, hi) in tip_reach(wing, beta) {
        if hi <= lo {
            continue;
        }
        let part = tanh_sinh(
            |eta| {
                let from = eta.abs() * tan;
                let to = 1.0 - beta * (s - eta);
                tanh_sinh(|xi| weights(wing, beta, xi, eta), from, to, LEVEL)
            },
            lo,
            hi,
            LEVEL,
        );
        for (acc, p) in sum.iter_mut().zip(part) {
            *acc += p;
        }
    }
    let k = 2.0 / (PI * beta);
    Ok(PotentialIntegrals {
        te0: strip.te0 + k * sum[0],
        te1: strip.te1 + k * sum[1],
        ar0: strip.ar0 + k * sum[2],
        ar1: strip.ar1 + k * sum[3],
        arx0: strip.arx0 + k * sum[4],
        te_f: strip.te_f + k * sum[5],
        ar_f: strip.ar_f + k * sum[6],
    })
}

/// The lift slope of the cropped delta in closed form where the right tip's
/// reach stays on its own half-wing (βs ≥ c₀) and β cot Λ = m > 1: the
/// deficit region is the triangle between the tip, the Mach line from the
/// trailing-edge tip corner and the leading edge, and
/// a = (4/β)[1 − (m c_t²/(βS))(√(m/(m − 1)) − 1)],
/// from ∫₀¹ arccos √t (1 − t/m)⁻² dt = (πm/2)(1/√(1 − 1/m) − 1). As m → ∞
/// with λ → 1 it is the rectangular wing's (4/β)(1 − 1/(2βA)). `None` outside
/// its range.
pub fn lift_slope_closed(wing: &Wing, mach: f64) -> Option<f64> {
    let beta = (mach * mach - 1.0).sqrt();
    let m = beta * wing.cot();
    if !(m > 1.0 && beta * wing.semi_span() >= 1.0) {
        return None;
    }
    let ct = wing.taper;
    Some(4.0 / beta * (1.0 - m * ct * ct / (beta * wing.area()) * ((m / (m - 1.0)).sqrt() - 1.0)))
}
