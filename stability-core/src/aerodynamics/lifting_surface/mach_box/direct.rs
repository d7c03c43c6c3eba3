//! The wing's own part of the potential by direct quadrature: where the
//! normalwash is known (on the wing; w̄ = 1 and w̄ = (ξ − x̄)/c̄ depend on ξ
//! alone), the source integral of [`super::influence`] is evaluated at the
//! receiving point itself instead of box by box, so that the wing's edges
//! are the true ones — the classic Mach box's staircase edge, an O(Δ)
//! irregular error, is gone.
//!
//! φ̂(x, y) = (1/π) ∫ w̄(ξ) e^{−iσ(x−ξ)} (1/β) ∫_{θ₀}^{θ₁} cos(ν(x − ξ)cos θ) dθ dξ,
//!
//! η = y − r sin θ, r = (x − ξ)/β, the θ-range the part of the cone's
//! chord [y − r, y + r] on the wing's section |η| ≤ η_w(ξ) =
//! min(s, ξ cot Λ). The outer integral is split where the cone's edges
//! cross the leading edge or the tip and at the tip's leading corner
//! (square-root kinks, smoothed by ξ = p + (q − p)(3t² − 2t³)), each piece
//! by 8-point Gauss–Legendre. With supersonic trailing edges no point of
//! the cone lies behind the trailing edge.

use super::across::{SERIES_UP_TO, by_series};
use super::influence::GAUSS_8;
use super::influence::Pair;
use crate::geometry::Trapezoid;
use num_complex::Complex64;
use std::f64::consts::{FRAC_PI_2, PI};
use wide::f64x4;

/// The flow of one solve: β, σ, ν, and the rate's x̄ and c̄.
#[derive(Debug, Clone, Copy)]
pub struct Flow {
    pub beta: f64,
    pub sigma: f64,
    pub nu: f64,
    pub x_mac: f64,
    pub mac: f64,
}

/// The wing's half-width at ξ (the section |η| ≤ η_w), for Λ ≥ 0
/// (t = tan Λ).
fn half_width(w: &Trapezoid, t: f64, xi: f64) -> f64 {
    if t <= 0.0 {
        w.semi_span
    } else {
        w.semi_span.min(xi / t)
    }
}

/// φ̂ of the wing's normalwash (unit incidence, unit rate) at (x, y ≥ 0).
pub fn wing_potential(w: &Trapezoid, f: &Flow, x: f64, y: f64) -> Pair {
    let zero = [Complex64::default(); 2];
    if x <= 0.0 {
        return zero;
    }
    let t = w.sweep_le.tan();
    let (b, s) = (f.beta, w.semi_span);
    let k = if t > 0.0 { 1.0 / t } else { f64::INFINITY };
    let corner = if t > 0.0 { s * t } else { 0.0 };
    let mut cuts: arrayvec::ArrayVec<f64, 12> = arrayvec::ArrayVec::new();
    cuts.extend([0.0, x, corner]);
    if k.is_finite() {
        // y ± r = ±kξ and y − r = kξ on the leading edge
        cuts.push((y + x / b) / (k + 1.0 / b));
        cuts.push((x / b - y) / (k + 1.0 / b));
        if (k - 1.0 / b).abs() > 1e-12 {
            cuts.push((y - x / b) / (k - 1.0 / b));
        }
    }
    // y ± r = ±s on the tip
    cuts.extend([x - b * (s - y), x - b * (s + y), x - b * (y - s)]);
    let mut cuts: arrayvec::ArrayVec<f64, 12> = cuts.into_iter().map(|c| c.clamp(0.0, x)).collect();
    cuts.sort_by(f64::total_cmp);
    let mut sum = zero;
    for pair in cuts.windows(2) {
        let (p0, q0) = (pair[0], pair[1]);
        if q0 - p0 <= 1e-14 * x.max(1.0) {
            continue;
        }
        // the phases σ(x − ξ) and ν(x − ξ)cos θ turn by at most (σ + ν)
        // per unit ξ: pieces of at most PHASE_PER_PIECE
        let pieces = pieces((q0 - p0) * (f.sigma + f.nu));
        let length = (q0 - p0) / pieces as f64;
        for piece in 0..pieces {
            let p = p0 + piece as f64 * length;
            let q = p + length;
            quadrature(w, f, t, (x, y), (p, q), &mut sum);
        }
    }
    sum
}

/// The largest phase, in radians, one 8-point Gauss–Legendre rule takes of
/// the oscillatory kernel (e^{−iσ(x−ξ)} along ξ, cos(z cos θ) along θ):
/// its error for e^{iΦt} over a span Φ is about (Φ/2)¹⁶/16! ≈ 3·10⁻¹¹ at 3.
/// Near M = 1 the phases grow as 1/β² (σ = κM²/β², ν = κM/β²): at
/// M = 1.03, ω̄ = 1 they turn through some 26 radians along a delta's root
/// chord, and one rule per piece put the 10° delta's z_θ̇ 21 % off the exact
/// reverse-flow value (0.14 % now; `tests/it/supersonic_oscillatory.rs`) and
/// made the 45° delta's derivatives at M = 1.03 jump by ±5 % from one ω̄ to
/// the next (`docs/supersonic-oscillatory.md`, "Near M = 1").
pub const PHASE_PER_PIECE: f64 = 3.0;

/// How many equal pieces a span of `phase` radians takes.
fn pieces(phase: f64) -> usize {
    if phase.is_finite() && phase > PHASE_PER_PIECE {
        (phase / PHASE_PER_PIECE).ceil().min(1e4) as usize
    } else {
        1
    }
}

/// Adds to `sum` the source integral over ξ ∈ [p, q] at (x, y), by the
/// 8-point rule on ξ = p + (q − p)(3u² − 2u³) (which removes a square-root
/// kink at either end).
fn quadrature(
    w: &Trapezoid,
    f: &Flow,
    t: f64,
    (x, y): (f64, f64),
    (p, q): (f64, f64),
    sum: &mut Pair,
) {
    for &(g, wt) in &GAUSS_8 {
        let u = 0.5 * (g + 1.0);
        let xi = p + (q - p) * u * u * (3.0 - 2.0 * u);
        let jac = (q - p) * 6.0 * u * (1.0 - u) * 0.5 * wt;
        let v = section(w, f, t, x, y, xi) * (jac / (PI * f.beta));
        let rate = (xi - f.x_mac) / f.mac;
        sum[0] += v;
        sum[1] += v * rate;
    }
}

/// e^{−iσ(x−ξ)} ∫ cos(ν(x − ξ)cos θ) dθ over the cone's chord on the section.
fn section(w: &Trapezoid, f: &Flow, t: f64, x: f64, y: f64, xi: f64) -> Complex64 {
    let r = (x - xi) / f.beta;
    if r <= 0.0 {
        return Complex64::default();
    }
    let eta = half_width(w, t, xi);
    // η = y − r sin θ ∈ [−η_w, η_w]  ⇔  sin θ ∈ [(y − η_w)/r, (y + η_w)/r]
    let sin_lo = ((y - eta) / r).clamp(-1.0, 1.0);
    let sin_hi = ((y + eta) / r).clamp(-1.0, 1.0);
    let (lo, hi) = (arcsine(sin_lo), arcsine(sin_hi));
    if hi <= lo {
        return Complex64::default();
    }
    let z = f.nu * (x - xi);
    let inner = if z <= SERIES_UP_TO {
        by_series(z, (lo, sin_lo), (hi, sin_hi))
    } else {
        by_rule(z, lo, hi)
    };
    Complex64::from_polar(inner, -f.sigma * (x - xi))
}

/// asin, ±π/2 at ±1 without the call: where the cone's chord lies within
/// the wing's section (most points near the receiving one) both ends are
/// clamped there.
fn arcsine(s: f64) -> f64 {
    if s == 1.0 {
        FRAC_PI_2
    } else if s == -1.0 {
        -FRAC_PI_2
    } else {
        s.asin()
    }
}

/// ∫_{lo}^{hi} cos(z cos θ) dθ by the 8-point rule on pieces of at most
/// [`PHASE_PER_PIECE`] radians of z cos θ (which turns by at most z per
/// unit θ).
fn by_rule(z: f64, lo: f64, hi: f64) -> f64 {
    let n = pieces(z * (hi - lo));
    let width = (hi - lo) / n as f64;
    let half = 0.5 * width;
    (0..n)
        .map(|k| across(z, lo + (k as f64 + 0.5) * width, half))
        .sum::<f64>()
        * half
}

/// Σ wₖ cos(z cos(mid + half·gₖ)) over the 8-point Gauss–Legendre rule
/// ([`GAUSS_8`]), four nodes at a time (the cosines are most of a
/// solve's time).
fn across(z: f64, mid: f64, half: f64) -> f64 {
    let lanes = |k: usize| {
        let g = f64x4::new(std::array::from_fn(|l| GAUSS_8[4 * k + l].0));
        let w = f64x4::new(std::array::from_fn(|l| GAUSS_8[4 * k + l].1));
        let theta = f64x4::splat(half).mul_add(g, f64x4::splat(mid));
        w * (f64x4::splat(z) * theta.cos()).cos()
    };
    (lanes(0) + lanes(1)).reduce_add()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Steady, at a rectangle's mid-span, where the forward cone stays
    /// inside the tips: the plate's φ̂ = x/β (w̄ = 1), and for w̄ = ξ
    /// (x̄ = 0, c̄ = 1) φ̂ = x²/(2β).
    #[test]
    fn mid_span_of_a_rectangle_is_the_plate() {
        let w = Trapezoid::new(1.0, 1.0, 5.0, 0.0).unwrap();
        let f = Flow {
            beta: 1.5,
            sigma: 0.0,
            nu: 0.0,
            x_mac: 0.0,
            mac: 1.0,
        };
        let p = wing_potential(&w, &f, 0.7, 1.0);
        assert!((p[0].re - 0.7 / 1.5).abs() < 1e-12, "{:?}", p[0]);
        assert!((p[1].re - 0.49 / 2.0 / 1.5).abs() < 1e-12, "{:?}", p[1]);
    }
}
