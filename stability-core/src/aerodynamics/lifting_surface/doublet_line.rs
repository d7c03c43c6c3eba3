//! One box's doublet line: its normalwash factor at a receiving point, the
//! steady part from a horseshoe vortex and the oscillatory increment from
//! the kernel integrated across the line (E. Albano and W.P. Rodden, AIAA
//! J. 7(2), 1969, eqs 17–22; W.P. Rodden, P.F. Taylor and S.C. McIntosh,
//! J. Aircraft 35(5), 1998, eqs 15–20).
//!
//! The line is the box's quarter-chord line, straight, of half-width e
//! (spanwise) and slope tan λ = dξ/dη, centred at (ξ, η); Δx is the box's
//! chord at mid-span. For a receiving point at (x̄, ȳ) from the centre the
//! normalwash factor is D = (Δx/8π) FP∫_{−e}^{e} N(x̄ − η′ tan λ, ȳ − η′)/(ȳ − η′)² dη′,
//! a Hadamard finite-part integral (Mangler's) where the point lies on the
//! line's streamwise strip.

use super::kernel::{self, KernelFlow};
use num_complex::Complex64;
use std::f64::consts::PI;

/// How the kernel's oscillatory part is integrated across a line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize)]
pub enum LineRule {
    /// Rodden, Taylor & McIntosh's quartic across every line, as they (and
    /// panelaero, and Nastran) do.
    Quartic,
    /// The quartic, but on graded pieces on the receiving point's own strip
    /// (the central one [`GRADING`]·|a|/β wide each side, a the point's
    /// streamwise distance from the line) and by two-point Gauss far from it
    /// (beyond [`GAUSS_BEYOND`]·e): as exact near the singular strip,
    /// cheaper far from it.
    #[default]
    Graded,
}

/// A doublet line, the quarter-chord line of a box (or of its mirror image).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DoubletLine {
    /// Centre ξ (streamwise) and η (spanwise).
    pub xi: f64,
    pub eta: f64,
    /// Half-width e.
    pub e: f64,
    /// dξ/dη along the line.
    pub tan_sweep: f64,
    /// The box's chord Δx at mid-span.
    pub chord: f64,
}

/// The sample stations η′ = −e, −e/2, 0, e/2, e of the quartic fit, in
/// units of e.
const STATIONS: [f64; 5] = [-1.0, -0.5, 0.0, 0.5, 1.0];

/// Beyond |ȳ| = FAR·e the finite-part formulas lose up to (|ȳ|/e)⁴ to
/// cancellation; there the integrals are summed as a series instead.
const FAR: f64 = 4.0;

/// The half-width of the central piece of a graded line, in units of the
/// kernel's own length scale |a|/β there, a the receiving point's
/// streamwise distance from the line at its own station (each next piece is
/// twice as wide; [`LineRule::Graded`]).
pub const GRADING: f64 = 1.0;

/// Beyond |ȳ| = GAUSS_BEYOND·e the oscillatory part is integrated by
/// two-point Gauss–Legendre instead of the quartic ([`LineRule::Graded`]):
/// the integrand is smooth on the scale |ȳ| there, and the error is of
/// relative order (e/ȳ)⁴/135 of the line's own contribution.
pub const GAUSS_BEYOND: f64 = 6.0;

/// 1/√3, the two-point Gauss–Legendre station on [−1, 1].
pub const FRAC_1_SQRT_3: f64 = 0.577_350_269_189_625_8;

/// ∫_{−e}^{e} η′ⁿ/(ȳ − η′)² dη′, n = 0…4, as finite parts (|ȳ| < e) or
/// ordinary integrals (|ȳ| > e). With F₂ = 2e/(ȳ² − e²) (the finite part of
/// ∫dη′/(ȳ − η′)²) and F₁ = ln|(ȳ + e)/(ȳ − e)| (the principal value of
/// ∫dη′/(ȳ − η′)), writing η′ = ȳ − u:
/// I₀ = F₂, I₁ = ȳF₂ − F₁, I₂ = ȳ²F₂ − 2ȳF₁ + 2e,
/// I₃ = ȳ³F₂ − 3ȳ²F₁ + 4eȳ, I₄ = ȳ⁴F₂ − 4ȳ³F₁ + 6eȳ² + (2/3)e³
/// — Rodden, Taylor & McIntosh's eq 20 for z̄ = 0, term by term. Far away,
/// with t = e/ȳ, Iₙ = (eⁿ⁺¹/ȳ²) Σ_{m: n+m even} (m + 1)tᵐ · 2/(n + m + 1).
pub fn moment_integrals(ybar: f64, e: f64) -> [f64; 5] {
    if ybar.abs() > FAR * e {
        return far_moment_integrals(ybar, e);
    }
    let f2 = 2.0 * e / (ybar * ybar - e * e);
    let f1 = ((ybar + e) / (ybar - e)).abs().ln();
    let y2 = ybar * ybar;
    [
        f2,
        ybar * f2 - f1,
        y2 * f2 - 2.0 * ybar * f1 + 2.0 * e,
        y2 * ybar * f2 - 3.0 * y2 * f1 + 4.0 * e * ybar,
        y2 * y2 * f2 - 4.0 * y2 * ybar * f1 + 6.0 * e * y2 + 2.0 / 3.0 * e * e * e,
    ]
}

fn far_moment_integrals(ybar: f64, e: f64) -> [f64; 5] {
    let t = e / ybar;
    let mut out = [0.0; 5];
    let mut scale = e / (ybar * ybar);
    for (n, slot) in out.iter_mut().enumerate() {
        let mut sum = 0.0;
        let mut tm = if n % 2 == 0 { 1.0 } else { t };
        let mut m = n % 2;
        // |t| ≤ 1/4: 30 terms reach 1e-18
        while m < 32 {
            sum += (m + 1) as f64 * tm * 2.0 / (n + m + 1) as f64;
            tm *= t * t;
            m += 2;
        }
        *slot = scale * sum;
        scale *= e;
    }
    out
}

/// The weights wₖ with FP∫ Q(η′)/(ȳ − η′)² dη′ = Σ wₖ pₖ for the quartic Q
/// through the samples pₖ at the five stations: Rodden, Taylor & McIntosh's
/// quartic (1998, eqs 15–19),
/// C = p₂, B = (p₀ − 8p₁ + 8p₃ − p₄)/6e, A = −(p₀ − 16p₁ + 30p₂ − 16p₃ + p₄)/6e²,
/// D = −2(p₀ − 2p₁ + 2p₃ − p₄)/3e³, E = 2(p₀ − 4p₁ + 6p₂ − 4p₃ + p₄)/3e⁴,
/// Q = C + Bη′ + Aη′² + Dη′³ + Eη′⁴, integrated by [`moment_integrals`].
pub fn quartic_weights(ybar: f64, e: f64) -> [f64; 5] {
    quartic_weights_of(moment_integrals(ybar, e), e)
}

/// The weights wₖ with ∫ Q(η′)W(η′) dη′ = Σ wₖ pₖ for the quartic Q through
/// the samples pₖ at the five stations, from the moments ∫ η′ⁿW(η′) dη′,
/// n = 0…4, of any weight W ([`quartic_weights`] for W = 1/(ȳ − η′)²; the
/// non-planar lattice of `crate::geometry::configuration` for its two weights).
pub fn quartic_weights_of(moments: [f64; 5], e: f64) -> [f64; 5] {
    let [i0, i1, i2, i3, i4] = moments;
    let b = i1 / (6.0 * e);
    let a = i2 / (6.0 * e * e);
    let d = 2.0 * i3 / (3.0 * e * e * e);
    let q = 2.0 * i4 / (3.0 * e * e * e * e);
    [
        b - a - d + q,
        -8.0 * b + 16.0 * a + 2.0 * d - 4.0 * q,
        i0 - 30.0 * a + 6.0 * q,
        8.0 * b + 16.0 * a - 2.0 * d - 4.0 * q,
        -b - a + d + q,
    ]
}

/// The normalwash (positive downwards, per unit circulation/4π) at (x, y)
/// of a planar horseshoe vortex: bound from a = (xₐ, yₐ) to b = (x_b, y_b)
/// (yₐ < y_b), trailing from both ends to x = +∞; by the Biot–Savart law
/// (J. Katz and A. Plotkin, *Low-speed aerodynamics*, 2nd ed., 2001,
/// §10.4.5 and §10.4.7, restricted to z = 0). This is the finite part of
/// ∫ N₀/(ȳ − η′)² dη′ in closed form: positive circulation along +y lifts,
/// and induces a downwash behind the line.
pub fn horseshoe(x: f64, y: f64, a: (f64, f64), b: (f64, f64)) -> f64 {
    let (r1x, r1y) = (x - a.0, y - a.1);
    let (r2x, r2y) = (x - b.0, y - b.1);
    let r1 = (r1x * r1x + r1y * r1y).sqrt();
    let r2 = (r2x * r2x + r2y * r2y).sqrt();
    let cz = r1x * r2y - r1y * r2x;
    let (r0x, r0y) = (b.0 - a.0, b.1 - a.1);
    // the bound segment; nothing on its own line
    let bound = if cz.abs() > 1e-14 * r1 * r2 {
        (r0x * (r1x / r1 - r2x / r2) + r0y * (r1y / r1 - r2y / r2)) / cz
    } else {
        0.0
    };
    // trailing legs: from b to +∞, and from +∞ to a
    let leg_b = if r2y != 0.0 {
        (1.0 + r2x / r2) / r2y
    } else {
        0.0
    };
    let leg_a = if r1y != 0.0 {
        -(1.0 + r1x / r1) / r1y
    } else {
        0.0
    };
    -(bound + leg_b + leg_a)
}

/// [`horseshoe`] and its rate under a stretching of every streamwise
/// coordinate: with g(s) = horseshoe(s·x, y, (s·xₐ, yₐ), (s·x_b, y_b)),
/// returns (g(1), dg/ds at s = 1). Differentiated by hand term by term (each
/// x-difference rₓ scales with s, so r′ = rₓ²/r, (rₓ/r)′ = (rₓ/r)(r_y/r)²,
/// (r_y/r)′ = −(r_y/r)(rₓ/r)², and the cross product r₁ × r₂ scales as s);
/// the same branches as [`horseshoe`]. The Prandtl–Glauert coordinates x/β
/// are such a stretching, so this is what the lattice's Mach derivative
/// needs ([`DoubletLine::steady_mach_rate`]).
pub fn horseshoe_x_rate(x: f64, y: f64, a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
    let (r1x, r1y) = (x - a.0, y - a.1);
    let (r2x, r2y) = (x - b.0, y - b.1);
    let r1 = (r1x * r1x + r1y * r1y).sqrt();
    let r2 = (r2x * r2x + r2y * r2y).sqrt();
    let (u1, v1, u2, v2) = (r1x / r1, r1y / r1, r2x / r2, r2y / r2);
    let (du1, dv1) = (u1 * v1 * v1, -v1 * u1 * u1);
    let (du2, dv2) = (u2 * v2 * v2, -v2 * u2 * u2);
    let cz = r1x * r2y - r1y * r2x;
    let (r0x, r0y) = (b.0 - a.0, b.1 - a.1);
    let (bound, d_bound) = if cz.abs() > 1e-14 * r1 * r2 {
        let n = r0x * (u1 - u2) + r0y * (v1 - v2);
        let dn = r0x * (u1 - u2) + r0x * (du1 - du2) + r0y * (dv1 - dv2);
        // (N/cz)′ = (N′ − N)/cz, since cz′ = cz
        (n / cz, (dn - n) / cz)
    } else {
        (0.0, 0.0)
    };
    let (leg_b, d_leg_b) = if r2y != 0.0 {
        ((1.0 + u2) / r2y, du2 / r2y)
    } else {
        (0.0, 0.0)
    };
    let (leg_a, d_leg_a) = if r1y != 0.0 {
        (-(1.0 + u1) / r1y, -du1 / r1y)
    } else {
        (0.0, 0.0)
    };
    (-(bound + leg_b + leg_a), -(d_bound + d_leg_b + d_leg_a))
}

impl DoubletLine {
    /// The line's ends, inner (smaller η) first.
    pub fn ends(&self) -> ((f64, f64), (f64, f64)) {
        let dx = self.e * self.tan_sweep;
        (
            (self.xi - dx, self.eta - self.e),
            (self.xi + dx, self.eta + self.e),
        )
    }

    /// The mirror image in the plane of symmetry y = 0.
    pub fn mirrored(&self) -> DoubletLine {
        DoubletLine {
            eta: -self.eta,
            tan_sweep: -self.tan_sweep,
            ..*self
        }
    }

    /// Δx/8π.
    pub fn factor(&self) -> f64 {
        self.chord / (8.0 * PI)
    }

    /// The steady normalwash factor D₀ at (x, y), in a subsonic stream of
    /// β = √(1 − M²): the horseshoe in Prandtl–Glauert coordinates x/β
    /// (N₀(x₀, r; M) = N₀(x₀/β, r; 0), so no other factor appears).
    pub fn steady(&self, x: f64, y: f64, beta: f64) -> f64 {
        let ((xa, ya), (xb, yb)) = self.ends();
        let g = horseshoe(x / beta, y, (xa / beta, ya), (xb / beta, yb));
        self.factor() * g
    }

    /// d[`Self::steady`]/dM at Mach `mach` (0 ≤ M < 1): with X = x/β the
    /// horseshoe g(X) gives dg/dβ = −g_s/β (g_s its rate under a stretching
    /// of X, [`horseshoe_x_rate`]) and dβ/dM = −M/β, so
    /// dD₀/dM = (Δx/8π)·g_s·M/β². The exact derivative of the lattice's
    /// steady matrix: what the aerodynamic model's da/dM and dH₀/dM (eqs
    /// 27–29) are made of.
    pub fn steady_mach_rate(&self, x: f64, y: f64, mach: f64) -> f64 {
        let beta2 = 1.0 - mach * mach;
        let beta = beta2.sqrt();
        let ((xa, ya), (xb, yb)) = self.ends();
        let (_, g_s) = horseshoe_x_rate(x / beta, y, (xa / beta, ya), (xb / beta, yb));
        self.factor() * g_s * mach / beta2
    }

    /// The sub-line of half-width `e` centred `c` from this line's centre.
    fn piece(&self, c: f64, e: f64) -> DoubletLine {
        DoubletLine {
            xi: self.xi + c * self.tan_sweep,
            eta: self.eta + c,
            e,
            ..*self
        }
    }

    /// Σ wₖ f(x₀ₖ, y₀ₖ): the quartic through `f` at the five stations,
    /// integrated against 1/(ȳ − η′)² (without the factor Δx/8π).
    fn quartic<T>(&self, x: f64, y: f64, f: &impl Fn(f64, f64) -> T) -> T
    where
        T: Copy + Default + std::ops::Add<Output = T> + std::ops::Mul<f64, Output = T>,
    {
        let (xbar, ybar) = (x - self.xi, y - self.eta);
        let w = quartic_weights(ybar, self.e);
        let mut acc = T::default();
        for (s, wk) in STATIONS.iter().zip(w) {
            let eta = s * self.e;
            acc = acc + f(xbar - eta * self.tan_sweep, ybar - eta) * wk;
        }
        acc
    }

    /// ∫ f/(ȳ − η′)² dη′ by two-point Gauss–Legendre, for a line far from
    /// the receiving point (|ȳ| > [`GAUSS_BEYOND`]·e), where the integrand is
    /// smooth on the scale |ȳ|: the error is of relative order (e/ȳ)⁴/135
    /// of the line's own contribution (measured on the 45° delta at
    /// M = 0.8: 4·10⁻⁴ of z_ẇ, < 10⁻⁵ of the others).
    fn gauss<T>(&self, x: f64, y: f64, f: &impl Fn(f64, f64) -> T) -> T
    where
        T: Copy + Default + std::ops::Add<Output = T> + std::ops::Mul<f64, Output = T>,
    {
        let (xbar, ybar) = (x - self.xi, y - self.eta);
        let mut acc = T::default();
        for s in [-FRAC_1_SQRT_3, FRAC_1_SQRT_3] {
            let eta = s * self.e;
            let u = ybar - eta;
            acc = acc + f(xbar - eta * self.tan_sweep, u) * (self.e / (u * u));
        }
        acc
    }

    /// FP∫ f/(ȳ − η′)² dη′ across the line (without Δx/8π), by the quartic
    /// rule — on pieces graded towards the receiving point's station where
    /// the point lies on the line's own strip closer to the line than the
    /// line is wide.
    ///
    /// There the kernel changes on the scale |a|/β, a the point's
    /// streamwise distance from the line at its own station: the numerator
    /// is smooth in η′ only on that scale (√(a² + β²r²) and u₁ ∝ 1/r), and a
    /// single quartic across a box much wider than it is long (e ≫ Δx) fits
    /// it badly — Rodden's limit on the boxes' aspect ratio. The graded
    /// pieces (half-width GRADING·|a|/β at the station, each next one twice
    /// as wide) lift that limit; the analytic finite part is kept on the
    /// central piece.
    fn integrate<T>(
        &self,
        x: f64,
        y: f64,
        beta: f64,
        rule: LineRule,
        f: impl Fn(f64, f64) -> T,
    ) -> T
    where
        T: Copy + Default + std::ops::Add<Output = T> + std::ops::Mul<f64, Output = T>,
    {
        let (xbar, ybar) = (x - self.xi, y - self.eta);
        if rule == LineRule::Quartic {
            return self.quartic(x, y, &f);
        }
        if ybar.abs() > GAUSS_BEYOND * self.e {
            return self.gauss(x, y, &f);
        }
        let h0 = GRADING * (xbar - ybar * self.tan_sweep).abs() / beta;
        if ybar.abs() >= self.e || h0 >= self.e - ybar.abs() {
            return self.quartic(x, y, &f);
        }
        let mut acc = self.piece(ybar, h0).quartic(x, y, &f);
        for (side, reach) in [(1.0, self.e - ybar), (-1.0, self.e + ybar)] {
            // pieces from d to 2d + h0 (distances from the station)
            let mut d = h0;
            while d < reach {
                let mut next = (2.0 * d + h0).min(reach);
                if reach - next < 0.5 * (next - d) {
                    next = reach; // no sliver at the end
                }
                let c = ybar + side * 0.5 * (d + next);
                acc = acc + self.piece(c, 0.5 * (next - d)).quartic(x, y, &f);
                d = next;
            }
        }
        acc
    }

    /// The oscillatory increment D − D₀ at (x, y): N − N₀ integrated
    /// across the line by `rule` ([`LineRule`]).
    pub fn oscillatory(&self, x: f64, y: f64, flow: &KernelFlow, rule: LineRule) -> Complex64 {
        let beta = flow.beta2.sqrt();
        self.integrate(x, y, beta, rule, |x0, y0| kernel::increment(x0, y0, flow)) * self.factor()
    }

    /// The first-order term D₁ per unit iκ (κ = ω/V), N₁ integrated across
    /// the line by `rule` ([`LineRule`]); D = D₀ + iκD₁ + O(κ² ln κ).
    pub fn first_order(&self, x: f64, y: f64, beta2: f64, rule: LineRule) -> f64 {
        self.integrate(x, y, beta2.sqrt(), rule, |x0, y0| {
            kernel::first_order_numerator(x0, y0, beta2)
        }) * self.factor()
    }

    /// The steady factor by the quartic rule on `pieces` equal sub-lines (a
    /// check of [`Self::steady`]: it converges to it as the pieces shrink).
    #[cfg(test)]
    pub fn steady_by_quadrature(&self, x: f64, y: f64, beta2: f64, pieces: usize) -> f64 {
        let e = self.e / pieces as f64;
        let f = |x0, y0| kernel::steady_numerator(x0, y0, beta2);
        (0..pieces)
            .map(|i| {
                self.piece(-self.e + (2 * i + 1) as f64 * e, e)
                    .quartic(x, y, &f)
            })
            .sum::<f64>()
            * self.factor()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_quartic_rule_is_exact_for_quartics() {
        // Σwₖ Q(ηₖ) against the moment integrals, for Q = η′ⁿ
        for ybar in [0.0, 0.3, -0.7, 1.7, -3.9, 4.5, -40.0] {
            let e = 1.0;
            let w = quartic_weights(ybar, e);
            let mi = moment_integrals(ybar, e);
            for (n, m) in mi.iter().enumerate() {
                let s: f64 = (0..5).map(|k| w[k] * STATIONS[k].powi(n as i32)).sum();
                assert!((s - m).abs() < 1e-12 * (1.0 + m.abs()), "{ybar} {n}");
            }
        }
    }

    #[test]
    fn near_and_far_forms_agree_where_they_meet() {
        for ybar in [3.9, 4.1, 6.0, -5.0] {
            let a = moment_integrals(ybar, 1.0);
            let b = far_moment_integrals(ybar, 1.0);
            let f2 = 2.0 / (ybar * ybar - 1.0);
            let f1 = ((ybar + 1.0) / (ybar - 1.0)).abs().ln();
            let y2 = ybar * ybar;
            let near = [
                f2,
                ybar * f2 - f1,
                y2 * f2 - 2.0 * ybar * f1 + 2.0,
                y2 * ybar * f2 - 3.0 * y2 * f1 + 4.0 * ybar,
                y2 * y2 * f2 - 4.0 * y2 * ybar * f1 + 6.0 * y2 + 2.0 / 3.0,
            ];
            for n in 0..5 {
                assert!(
                    (near[n] - b[n]).abs() < 1e-11,
                    "{ybar} {n}: {} {}",
                    near[n],
                    b[n]
                );
                assert!((a[n] - b[n]).abs() < 1e-11);
            }
        }
    }

    #[test]
    fn an_infinite_bound_vortex_gives_the_two_dimensional_downwash() {
        // Γ/(2πx₀) per Γ/4π: 2/x₀ downstream, −2/|x₀| upstream
        let g = horseshoe(0.5, 0.0, (0.0, -1e7), (0.0, 1e7));
        assert!((g - 4.0).abs() < 1e-6, "{g}");
        let g = horseshoe(-0.25, 0.0, (0.0, -1e7), (0.0, 1e7));
        assert!((g + 8.0).abs() < 1e-6, "{g}");
    }

    #[test]
    fn the_horseshoes_stretching_rate_is_its_derivative() {
        // against a central difference of `horseshoe` with every x stretched
        let (a, b) = ((0.1, 0.05), (0.35, 0.3));
        for (x, y) in [
            (0.6, 0.2),
            (0.2, 0.18),
            (-0.3, 0.1),
            (0.9, -0.4),
            (0.3, 0.3),
        ] {
            let (g, g_s) = horseshoe_x_rate(x, y, a, b);
            assert_eq!(g, horseshoe(x, y, a, b));
            let at = |s: f64| horseshoe(s * x, y, (s * a.0, a.1), (s * b.0, b.1));
            let d = 1e-5;
            let fd = (at(1.0 + d) - at(1.0 - d)) / (2.0 * d);
            assert!(
                (g_s - fd).abs() < 1e-7 * (1.0 + fd.abs()),
                "({x}, {y}): {g_s} {fd}"
            );
        }
    }

    #[test]
    fn the_lines_mach_rate_is_the_derivative_of_its_steady_factor() {
        let line = DoubletLine {
            xi: 0.1,
            eta: 0.2,
            e: 0.15,
            tan_sweep: 0.8,
            chord: 0.2,
        };
        for m in [0.0, 0.3, 0.85] {
            for (x, y) in [(0.25, 0.2), (0.3, 0.33), (0.9, 0.1), (-0.4, 0.25)] {
                let at = |m: f64| line.steady(x, y, (1.0 - m * m).sqrt());
                let d = 1e-5;
                let fd = (at(m + d) - at(m - d)) / (2.0 * d);
                let rate = line.steady_mach_rate(x, y, m);
                assert!(
                    (rate - fd).abs() < 1e-7 * (1.0 + fd.abs()),
                    "{m} ({x}, {y}): {rate} {fd}"
                );
            }
        }
    }

    #[test]
    fn the_horseshoe_is_the_finite_part_of_the_steady_kernel() {
        let line = DoubletLine {
            xi: 0.1,
            eta: 0.2,
            e: 0.15,
            tan_sweep: 0.8,
            chord: 0.2,
        };
        for m in [0.0, 0.7] {
            let beta2: f64 = 1.0 - m * m;
            // own strip (finite part), neighbours, downstream, upstream, mirror side
            for (x, y) in [
                (0.25, 0.2),
                (0.3, 0.33),
                (0.9, 0.1),
                (-0.4, 0.25),
                (0.5, -0.3),
                (0.2, 0.5),
            ] {
                let exact = line.steady(x, y, beta2.sqrt());
                let quad = line.steady_by_quadrature(x, y, beta2, 401);
                assert!(
                    (exact - quad).abs() < 1e-6 * (1.0 + exact.abs()),
                    "{m} ({x}, {y}): {exact} {quad}"
                );
            }
        }
    }
}
