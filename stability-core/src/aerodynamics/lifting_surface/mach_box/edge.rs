//! The diaphragm's edge singularity: box-averaged upwash near a subsonic
//! leading edge or a tip.
//!
//! Beside a subsonic edge the diaphragm's upwash is singular like 1/√d,
//! d the distance from the edge (the edge of a conical flow, H.J. Stewart,
//! Q. Appl. Math. 4, 1946; Ribner & Malvestuto, NACA Rep. 908, 1948), so
//! the classic Mach box — one upwash per box, sampled at its centre —
//! mis-weights the boxes next to the edge by an amount that depends on
//! where the edge cuts them, and converges irregularly (Pines, Dugundji &
//! Neuringer, J. Aero. Sci. 22(10), 1955; the "smoothing" of Donato &
//! Huhn and the leading-edge and diaphragm box weighting of Ii, Borland &
//! Hogley, AFFDL-TR-71-108, 1971, address the same defect). Here the
//! singular factor is carried exactly: the upwash is written
//!
//! w̄(ξ, η) = a(ξ, η)/√d,  d = η − η_w(ξ) > 0,
//!
//! η_w(ξ) = min(s, ξ cot Λ) the wing's half-width, and the box's unknown
//! is the smooth factor a. A box's source (its mean upwash over its whole
//! area, what the translation-invariant coefficients
//! [`super::influence::Influence`] multiply) is then a·q with
//!
//! q = (1/ΔxΔy) ∬_{box, d > 0} dξ dη/√d   ([`weight`]),
//!
//! and its influence on its own centre — where the kernel is singular and
//! the edge may cross the box — is a·S with ([`self_influence`])
//!
//! S = ∫₀^{½} e^{−iσ̂X} ∫ cos(ν̂X cos θ)/√d dθ dX   (Y = X sin θ),
//!
//! both by quadratures that remove the 1/√d and the Mach-line
//! singularities. Receivers farther off see the box through its mean, as
//! before (the kernel is smooth across a box there).

use super::grid::Grid;
use super::influence::GAUSS_8;
use crate::geometry::Trapezoid;
use num_complex::Complex64;
use std::f64::consts::FRAC_PI_2;

/// The wing's half-width η_w(ξ) = min(s, ξ cot Λ) (Λ > 0; the full span
/// for an unswept leading edge).
pub fn half_width(w: &Trapezoid, xi: f64) -> f64 {
    let t = w.sweep_le.tan();
    if t <= 0.0 {
        w.semi_span
    } else {
        w.semi_span.min(xi.max(0.0) / t)
    }
}

/// ∫ f over [p, q] split at `cuts`, each piece by 8-point Gauss–Legendre
/// after ξ = p + (q − p)(3u² − 2u³) (square-root end behaviour smoothed).
fn integrate<T, F>(p: f64, q: f64, cuts: &[f64], mut f: F) -> T
where
    T: Default + std::ops::AddAssign + std::ops::Mul<f64, Output = T>,
    F: FnMut(f64) -> T,
{
    let mut points: arrayvec::ArrayVec<f64, 12> = arrayvec::ArrayVec::new();
    points.push(p);
    for &c in cuts.iter().take(10) {
        if c > p && c < q {
            points.push(c);
        }
    }
    points.push(q);
    points.sort_by(f64::total_cmp);
    let mut sum = T::default();
    for pair in points.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        if b - a <= 1e-15 * (1.0 + b.abs()) {
            continue;
        }
        for &(g, wt) in &GAUSS_8 {
            let u = 0.5 * (g + 1.0);
            let x = a + (b - a) * u * u * (3.0 - 2.0 * u);
            let jac = (b - a) * 6.0 * u * (1.0 - u) * 0.5 * wt;
            sum += f(x) * jac;
        }
    }
    sum
}

/// q of box (i, j): (1/ΔxΔy)∬ dξ dη/√d over its part off the wing
/// (d > 0), in units of 1/√length (module doc).
pub fn weight(w: &Trapezoid, grid: &Grid, i: usize, j: usize) -> f64 {
    let (x0, x1) = (i as f64 * grid.dx, (i as f64 + 1.0) * grid.dx);
    let (y0, y1) = (
        (j as f64 - 0.5).max(0.0) * grid.dy,
        (j as f64 + 0.5) * grid.dy,
    );
    let t = w.sweep_le.tan();
    // where η_w(ξ) crosses y0, y1 and the tip's corner
    let cuts = [y0 * t, y1 * t, w.semi_span * t];
    let f = |xi: f64| {
        let hw = half_width(w, xi);
        if hw >= y1 {
            0.0
        } else {
            2.0 * ((y1 - hw).sqrt() - (y0.max(hw) - hw).sqrt())
        }
    };
    integrate(x0, x1, &cuts, f) / (grid.dx * grid.dy)
}

/// S of box (i, j) at its own centre (module doc), σ̂ = σΔx, ν̂ = νΔx: the
/// potential there, over Δy/π, of the upwash 1/√d on the off-wing part
/// of the box's forward half.
pub fn self_influence(
    w: &Trapezoid,
    grid: &Grid,
    i: usize,
    j: usize,
    sigma_hat: f64,
    nu_hat: f64,
) -> Complex64 {
    coefficient(w, grid, grid.centre(i, j), (i, j), sigma_hat, nu_hat)
}

/// The potential at `receiver` (over Δy/π) of the upwash 1/√d on the
/// off-wing part of box `(i, j)` inside the receiver's forward Mach cone:
/// [`super::influence`]'s C(m, n) with the edge's weighting, for the near
/// field, where neither the kernel nor 1/√d is smooth across the box. In
/// X = (x − ξ)/Δx, u = sin θ = (y − η)/(XΔy), d = XΔy(t − u) with
/// t = (y − η_w(ξ))/(XΔy); the X-integral split where the box's sides, the
/// edge and the cone's sides cross.
pub fn coefficient(
    w: &Trapezoid,
    grid: &Grid,
    (xc, yc): (f64, f64),
    (i, j): (usize, usize),
    sigma_hat: f64,
    nu_hat: f64,
) -> Complex64 {
    let (dx, dy) = (grid.dx, grid.dy);
    let x_lo = ((xc - (i as f64 + 1.0) * dx) / dx).max(0.0);
    let x_hi = (xc - i as f64 * dx) / dx;
    if x_hi <= x_lo {
        return Complex64::default();
    }
    let (y_lo, y_hi) = (
        (yc - (j as f64 + 0.5) * dy) / dy,
        (yc - (j as f64 - 0.5).max(0.0) * dy) / dy,
    );
    let t = w.sweep_le.tan();
    let mut cuts: arrayvec::ArrayVec<f64, 10> = arrayvec::ArrayVec::new();
    cuts.extend([y_lo.abs(), y_hi.abs()]);
    if t > 0.0 {
        let m = dx / (dy * t);
        let d = yc - xc / t;
        cuts.extend([d / ((1.0 - m) * dy), -d / ((1.0 + m) * dy)]);
        cuts.push((xc - w.semi_span * t) / dx);
        cuts.extend([(y_lo * dy - d) * t / dx, (y_hi * dy - d) * t / dx]);
    }
    cuts.extend([(yc - w.semi_span) / dy, (w.semi_span - yc) / dy]);
    let f = |x: f64| {
        let hw = half_width(w, xc - x * dx);
        let tt = (yc - hw) / (x * dy);
        let (lo, hi) = ((y_lo / x).max(-1.0), (y_hi / x).min(1.0).min(tt));
        Complex64::from_polar(1.0, -sigma_hat * x) * across(lo, hi, tt, nu_hat * x)
            / (x * dy).sqrt()
    };
    integrate(x_lo, x_hi, &cuts, f)
}

/// ∫ cos(z√(1 − u²))/(√(1 − u²)√(tt − u)) du over u ∈ [lo, hi]
/// (hi ≤ tt; the inner integral of [`coefficient`] times √(XΔy)), by
/// u = c + h sin φ, which removes inverse square roots at either end.
fn across(lo: f64, hi: f64, tt: f64, z: f64) -> f64 {
    if hi <= lo {
        return 0.0;
    }
    let h = 0.5 * (hi - lo);
    GAUSS_8
        .iter()
        .map(|&(g, wt)| {
            let (sin, cos) = (FRAC_PI_2 * g).sin_cos();
            // 1 ± u and tt − u as sums of non-negative parts (no
            // cancellation next to the ends)
            let below = (1.0 + lo) + h * (1.0 + sin);
            let above = (1.0 - hi) + h * (1.0 - sin);
            let edge = (tt - hi) + h * (1.0 - sin);
            let root = (below * above).sqrt();
            wt * FRAC_PI_2 * h * cos * (z * root).cos() / (root * edge.sqrt())
        })
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// By hand, beside a rectangle's tip (η_w = s): the box whose inner
    /// side is the tip has q = (1/ΔxΔy)·Δx·∫₀^{Δy} dη/√η = 2/√Δy; a box
    /// far outboard (d ≫ Δy) has q = 1/√d_c and S = C(0, 0)/√d_c = (π/2)/√d_c
    /// (steady) to second order in Δy/d_c.
    #[test]
    fn weights_by_hand() {
        let w = Trapezoid::new(1.0, 1.0, 1.0, 0.0).unwrap();
        let grid = Grid::new(&w, 1.0, 8);
        let dy = grid.dy;
        // the box whose inner side is on the tip: j − ½ = s/Δy = 7.5
        let q = weight(&w, &grid, 3, 8);
        assert!((q - 2.0 * dy.sqrt() / dy).abs() < 1e-10, "{q}");
        // far box: j = 40, d_c = 40Δy − s = 32.5Δy
        let d = 40.0 * dy - 1.0;
        let q = weight(&w, &grid, 3, 40);
        assert!((q * d.sqrt() - 1.0).abs() < 1e-4, "{q}");
        let s = self_influence(&w, &grid, 3, 40, 0.0, 0.0);
        assert!((s.re * d.sqrt() - PI / 2.0).abs() < 1e-3, "{s}");
        assert!(s.im.abs() < 1e-14);
    }

    /// Far from the edge the weighted coefficient is the uniform box's
    /// C(m, n) of [`super::super::influence`] (an independent quadrature)
    /// times 1/√d at the box: oscillatory, rows 1–3 back, n = 0…m.
    #[test]
    fn far_from_the_edge_it_is_the_uniform_coefficient() {
        let w = Trapezoid::new(1.0, 1.0, 1.0, 0.0).unwrap();
        let grid = Grid::new(&w, 1.0, 8);
        let (sh, nh) = (0.3, 0.2);
        let (i, j) = (6, 60);
        for m in 1..=3usize {
            for n in 0..=m {
                let jp = j + n;
                let d = jp as f64 * grid.dy - 1.0;
                let got = coefficient(&w, &grid, grid.centre(i, j), (i - m, jp), sh, nh);
                let want = crate::aerodynamics::lifting_surface::mach_box::influence::coefficient(
                    m, n, sh, nh,
                ) / d.sqrt();
                assert!(
                    (got - want).norm() < 2e-3 * want.norm(),
                    "m {m} n {n}: {got} vs {want}"
                );
            }
        }
    }
}
