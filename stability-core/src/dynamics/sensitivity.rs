//! Sensitivity of a mode to each derivative and parameter: which derivative
//! drives the short period's damping — the question the report keeps asking
//! (§7 conclusions, §8, §10).
//!
//! For a simple root λ of P(λ) = Aλ⁴ + Bλ³ + Cλ² + Dλ + E and an input p,
//! implicit differentiation of P(λ(p); p) = 0 gives
//! `dλ/dp = −(Σₖ ∂cₖ/∂p · λ^(4−k)) / P′(λ)`, with the ∂cₖ/∂p exact from the
//! generated gradient (`Derivatives::quartic_gradient`).

use crate::dynamics::modes::{CYCLES_CONSTANT, Mode};
use crate::{Derivatives, Quartic, QuarticGradient};
use num_complex::Complex64;
use serde::Serialize;

/// dλ/dp for every input p of [`Derivatives::QUARTIC_INPUTS`], at a simple
/// root `lam`. `None` when P′(λ) vanishes (a multiple root, where λ is not
/// differentiable in p).
pub fn root_sensitivities(
    q: &Quartic,
    grad: &QuarticGradient,
    lam: Complex64,
) -> Option<[Complex64; 15]> {
    let dp = q.eval_derivative(lam);
    let scale = 4.0 * q.a.abs() * lam.norm().powi(3)
        + 3.0 * q.b.abs() * lam.norm_sqr()
        + 2.0 * q.c.abs() * lam.norm()
        + q.d.abs();
    // (written so that a NaN scale also refuses)
    let simple = dp.norm() > 1e-12 * scale;
    if !simple {
        return None;
    }
    let powers = [
        lam.powi(4),
        lam.powi(3),
        lam * lam,
        lam,
        Complex64::new(1.0, 0.0),
    ];
    Some(std::array::from_fn(|i| {
        let row = grad.rows[i];
        let dpdp: Complex64 = (0..5).map(|k| powers[k] * row[k]).sum();
        -dpdp / dp
    }))
}

/// How one mode responds to one input.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ModeSensitivity {
    /// The input's name (`"m_q"`, `"mu1"`, …).
    pub input: &'static str,
    /// The input's value.
    pub value: f64,
    /// ∂r/∂p and ∂s/∂p (1/τ per unit of p).
    pub d_re: f64,
    pub d_im: f64,
    /// ∂ζ/∂p.
    pub d_damping_ratio: f64,
    /// ∂(cycles to half amplitude)/∂p, for a decaying oscillation.
    pub d_cycles_to_half: Option<f64>,
    /// p·∂r/∂p: the first-order change of r if p doubled — the measure by
    /// which inputs are ranked (larger |·| drives the damping more).
    pub damping_drive: f64,
}

/// The sensitivities of `mode` (one root of the pair, s ≥ 0) to every
/// input, ranked by |p·∂r/∂p|, largest first. `None` at a multiple root.
pub fn mode_sensitivities(d: &Derivatives, mode: &Mode) -> Option<Vec<ModeSensitivity>> {
    let q = Quartic::from_derivatives(d);
    let grad = QuarticGradient::of(d);
    let lam = Complex64::new(mode.re, mode.im);
    let dl = root_sensitivities(&q, &grad, lam)?;
    let values = d.quartic_input_values();
    let (r, s) = (lam.re, lam.im);
    let n = lam.norm();
    let k = CYCLES_CONSTANT;
    let mut out: Vec<ModeSensitivity> = (0..15)
        .map(|i| {
            let (dr, ds) = (dl[i].re, dl[i].im);
            // ζ = −r/|λ|, ∂ζ = −∂r/|λ| + r(r∂r + s∂s)/|λ|³
            let dz = if n > 0.0 {
                -dr / n + r * (r * dr + s * ds) / n.powi(3)
            } else {
                0.0
            };
            // cycles = k·s/(−r), ∂ = k(−r∂s + s∂r)/r²
            let dc = (s > 0.0 && r < 0.0).then(|| k * (-r * ds + s * dr) / (r * r));
            ModeSensitivity {
                input: Derivatives::QUARTIC_INPUTS[i],
                value: values[i],
                d_re: dr,
                d_im: ds,
                d_damping_ratio: dz,
                d_cycles_to_half: dc,
                damping_drive: values[i] * dr,
            }
        })
        .collect();
    out.sort_by(|a, b| b.damping_drive.abs().total_cmp(&a.damping_drive.abs()));
    Some(out)
}
