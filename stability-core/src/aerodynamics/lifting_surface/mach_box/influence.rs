//! The Mach box's influence coefficients: the oscillatory supersonic
//! source kernel integrated over one box of the characteristic grid.
//!
//! With the potential of the harmonic (e^{iωt}) normalwash w̄ (positive
//! down, per unit V) on the plane z = 0 (Garrick & Rubinow, NACA Rep. 846,
//! 1946, eq 3 in three dimensions; Miles 1959, ch. 5; Pines, Dugundji &
//! Neuringer, J. Aero. Sci. 22(10), 1955, eq 4)
//!
//! φ/V = (1/π) ∬ w̄(ξ, η) e^{−iσ(x−ξ)} cos(νR)/R dξ dη,
//! R = √((x−ξ)² − β²(y−η)²), σ = (ω/V)M²/β², ν = (ω/V)M/β²,
//!
//! over the forward Mach cone, and boxes Δx = βΔy, the coordinates
//! X = (x − ξ)/Δx, Y = (y − η)/Δy make the cone |Y| ≤ X and
//! dξ dη/R = Δy dX dY/√(X² − Y²): the potential at a box centre is
//! (Δy/π) Σ w̄ⱼ C(i − i′, j − j′) with
//!
//! C(m, n) = ∫∫_box e^{−iσ̂X} cos(ν̂√(X² − Y²)) / √(X² − Y²) dX dY,
//! σ̂ = σΔx, ν̂ = νΔx,
//!
//! over X ∈ [m − ½, m + ½] (the box's own forward half, [0, ½], for m = 0),
//! Y ∈ [n − ½, n + ½], inside the cone. Inner integral exactly regular by
//! Y = X sin θ (dY/√(X² − Y²) = dθ); the outer one split where the cone's
//! edges enter the box (square-root kinks, removed by X = p + (q − p)u²),
//! each piece by 8-point Gauss–Legendre; the inner integral by its power
//! series where ν̂X ≤ 4 ([`super::across`]). C(m, −n) = C(m, n).

use super::across::{SERIES_UP_TO, by_series};
use num_complex::Complex64;
use rayon::prelude::*;

/// The two right-hand sides: unit incidence, unit rate (x − x̄)/c̄.
pub type Pair = [Complex64; 2];

/// 8-point Gauss–Legendre nodes and weights on [−1, 1] (Abramowitz &
/// Stegun, Table 25.4); the Mach box's rules (`direct.rs`, `edge.rs`) share it.
pub(super) const GAUSS_8: [(f64, f64); 8] = [
    (-0.960_289_856_497_536_2, 0.101_228_536_290_376_26),
    (-0.796_666_477_413_626_7, 0.222_381_034_453_374_47),
    (-0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (-0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_47),
    (0.960_289_856_497_536_2, 0.101_228_536_290_376_26),
];

/// The coefficients C(m, n), 0 ≤ n ≤ m ≤ `rows`, of one (grid, M, ω̄).
#[derive(Debug, Clone)]
pub struct Influence {
    rows: usize,
    c: Vec<Complex64>,
}

impl Influence {
    /// The table for m up to `rows` at σ̂ = σΔx and ν̂ = νΔx, its rows in
    /// parallel.
    pub fn new(rows: usize, sigma_hat: f64, nu_hat: f64) -> Influence {
        let mut c = vec![Complex64::default(); (rows + 1) * (rows + 1)];
        c.par_chunks_mut(rows + 1).enumerate().for_each(|(m, row)| {
            for (n, slot) in row.iter_mut().enumerate().take(m + 1) {
                *slot = coefficient(m, n, sigma_hat, nu_hat);
            }
        });
        Influence { rows, c }
    }

    /// C(m, 0..=m): row m of the table.
    #[inline]
    pub fn row(&self, m: usize) -> &[Complex64] {
        let start = m * (self.rows + 1);
        &self.c[start..=start + m]
    }

    /// C(m, n) (zero outside the cone, |n| > m).
    #[inline]
    pub fn get(&self, m: usize, n: usize) -> Complex64 {
        if n > m || m > self.rows {
            Complex64::default()
        } else {
            self.c[m * (self.rows + 1) + n]
        }
    }
}

/// C(m, n) for n ≥ 0 by the split quadrature of the module doc.
pub fn coefficient(m: usize, n: usize, sigma_hat: f64, nu_hat: f64) -> Complex64 {
    let (x0, x1) = if m == 0 {
        (0.0, 0.5)
    } else {
        (m as f64 - 0.5, m as f64 + 0.5)
    };
    let (a, b) = (n as f64 - 0.5, n as f64 + 0.5);
    // where the cone's edges |Y| = X cross the box's sides Y = a, Y = b
    let mut cuts = [x0, x1, x1, x1];
    if n >= 1 && a > x0 && a < x1 {
        cuts[1] = a;
    }
    if b > x0 && b < x1 {
        cuts[2] = b;
    }
    cuts.sort_by(f64::total_cmp);
    let mut sum = Complex64::default();
    for w in cuts.windows(2) {
        let (p, q) = (w[0], w[1]);
        if q <= p {
            continue;
        }
        for &(t, wt) in &GAUSS_8 {
            let u = 0.5 * (t + 1.0);
            let x = p + (q - p) * u * u;
            let jac = 2.0 * (q - p) * u * 0.5 * wt;
            let phase = Complex64::from_polar(1.0, -sigma_hat * x);
            sum += phase * (jac * inner(x, a, b, nu_hat));
        }
    }
    sum
}

/// ∫ cos(ν̂√(X² − Y²))/√(X² − Y²) dY over Y ∈ [a, b] ∩ [−X, X], by
/// Y = X sin θ.
/// Up to ν̂X = [`SERIES_UP_TO`] by its power series ([`by_series`], exact
/// to rounding), beyond by one 8-point rule over the θ-range.
fn inner(x: f64, a: f64, b: f64, nu_hat: f64) -> f64 {
    let sin_lo = (a.max(-x) / x).clamp(-1.0, 1.0);
    let sin_hi = (b.min(x) / x).clamp(-1.0, 1.0);
    let (lo, hi) = (sin_lo.asin(), sin_hi.asin());
    if hi <= lo {
        return 0.0;
    }
    if nu_hat * x <= SERIES_UP_TO {
        return by_series(nu_hat * x, (lo, sin_lo), (hi, sin_hi));
    }
    let (mid, half) = (0.5 * (hi + lo), 0.5 * (hi - lo));
    GAUSS_8
        .iter()
        .map(|&(t, wt)| wt * (nu_hat * x * (mid + half * t).cos()).cos())
        .sum::<f64>()
        * half
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// Steady: a full row of boxes (every n) covers the cone's width, and
    /// ∫ dY/√(X² − Y²) over [−X, X] = π, so Σₙ C(m, n) = π (π/2 for the
    /// box's own half, m = 0).
    #[test]
    fn a_steady_row_sums_to_pi() {
        let table = Influence::new(12, 0.0, 0.0);
        for m in 0..=12usize {
            let row: f64 = (-(m as i64)..=m as i64)
                .map(|n| table.get(m, n.unsigned_abs() as usize).re)
                .sum();
            let want = if m == 0 { PI / 2.0 } else { PI };
            assert!((row - want).abs() < 1e-6 * PI, "m = {m}: {row} vs {want}");
        }
    }

    /// Oscillatory: a full row is the two-dimensional kernel's
    /// ∫ e^{−iσ̂X} J₀(ν̂X)·π dX over the row (∫cos(ν̂X cos θ)dθ = πJ₀(ν̂X)),
    /// checked against J₀ by its power series at row 3, σ̂ = 0.3, ν̂ = 0.4.
    #[test]
    fn an_oscillatory_row_is_the_bessel_kernel() {
        let (s, nu) = (0.3, 0.4);
        let table = Influence::new(3, s, nu);
        let row: Complex64 = (-3i64..=3)
            .map(|n| table.get(3, n.unsigned_abs() as usize))
            .sum();
        let j0 = |z: f64| {
            (0..30)
                .fold((0.0, 1.0), |(sum, term), k| {
                    let next = -term * z * z / (4.0 * ((k + 1) * (k + 1)) as f64);
                    (sum + term, next)
                })
                .0
        };
        // Simpson over [2.5, 3.5] with 200 intervals
        let n = 200;
        let h = 1.0 / n as f64;
        let want: Complex64 = (0..=n)
            .map(|k| {
                let x = 2.5 + k as f64 * h;
                let w = if k == 0 || k == n {
                    1.0
                } else if k % 2 == 1 {
                    4.0
                } else {
                    2.0
                };
                Complex64::from_polar(1.0, -s * x) * (w * h / 3.0 * PI * j0(nu * x))
            })
            .sum();
        assert!((row - want).norm() < 1e-6, "{row} vs {want}");
    }
}
