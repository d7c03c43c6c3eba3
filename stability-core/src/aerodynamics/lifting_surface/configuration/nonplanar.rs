//! The non-planar kernel between two parallel horizontal surfaces at a
//! vertical distance z₀, and its integral across a doublet line.
//!
//! For surfaces without dihedral Landahl's directional factors are
//! T₁ = cos(γᵣ − γₛ) = 1 and T₂ = z₀², so the kernel of the planar lattice
//! ([`crate::aerodynamics::lifting_surface::kernel`]) becomes, with r² = y₀² + z₀²,
//! K = e^{−iκx₀}[K₁/r² + K₂z₀²/r⁴] (M.T. Landahl, "Kernel function for
//! nonplanar oscillating surfaces in a subsonic flow", AIAA J. 5(5), 1967,
//! pp. 1045–1046; E. Albano and W.P. Rodden, AIAA J. 7(2), 1969, eqs 5–9):
//!
//! K₂ = 3I₂ + ik₁M²r²e^{−ik₁u₁}/(R²√(1 + u₁²))
//!      + (Mr/R)[(1 + u₁²)β²r²/R² + 2 + Mru₁/R] e^{−ik₁u₁}/(1 + u₁²)^{3/2},
//! I₂ = ∫_{u₁}^∞ e^{−ik₁u}(1 + u²)^{−5/2} du,
//!
//! with K₁, R, u₁, k₁ as in the planar kernel (r now the distance above).
//! Integrating by parts twice, with g(u) = 1 − u/√(1 + u²) and its
//! exponential approximation g ≈ Σ aₙe^{−pₙu} (Desmarais' or Laschka's):
//! 3I₂ = e^{−ik₁u₁}[(2 + ik₁u₁)g(u₁) − u₁/(1 + u₁²)^{3/2} − ik₁S₀ + k₁²S₁],
//! S₀ = Σ aₙe^{−pₙu₁}/(pₙ + ik₁), S₁ = Σ aₙe^{−pₙu₁}[1/(pₙ + ik₁)² + u₁/(pₙ + ik₁)]
//! (W.P. Rodden, J.P. Giesing and T.P. Kálmán, AGARD CP-80-71, 1971, eq A.6
//! in this form), u₁ < 0 by the reflection I(u₁) = 2 Re I(0) − conj I(−u₁).
//!
//! Closed forms used (derived from the above, checked symbolically):
//! - steady: K₁₀ = −(1 + x₀/R), K₂₀ = 2 + (x₀/R)(2 + β²r²/R²), so that
//!   K₂₀ + 2K₁₀ = β²x₀r²/R³;
//! - first order in κ (K e^{−iκx₀} = N₀ + iκN₁ + …): N₁₁ = x₀ + (x₀² + r²)/R
//!   (as the planar one) and N₂₁ + 2N₁₁ = r²(R² + M²x₀²)/R³.
//!
//! # Across a line
//! Writing K₂ = −2K₁ + (K₂ + 2K₁), the integrand is
//! ΔK₁(u² − z₀²)/(u² + z₀²)² + Q z₀²/(u² + z₀²), u = ȳ − η′, Q = (ΔK₂ + 2ΔK₁)/r²
//! (Δ: the oscillatory increment over the steady kernel, whose part the
//! 3-D horseshoe carries). The first weight tends to the planar finite part
//! 1/u² as z₀ → 0 and the second to nothing (K₂ + 2K₁ = O(r² ln r)), so the
//! non-planar line tends continuously to the planar one. Both numerators
//! are fitted by Rodden, Taylor & McIntosh's quartic through five stations
//! (J. Aircraft 35(5), 1998, eqs 15–19 and their non-planar integrals,
//! eq 20 with z̄ ≠ 0), the moments of the weights in closed form
//! ([`moments`]); beyond √(ȳ² + z₀²) = [`GAUSS_BEYOND`]·e by two-point
//! Gauss, as the planar graded rule does.

use crate::aerodynamics::lifting_surface::doublet_line::{
    DoubletLine, FRAC_1_SQRT_3, GAUSS_BEYOND, quartic_weights_of,
};
use crate::aerodynamics::lifting_surface::kernel::{
    self, DESMARAIS_A, DESMARAIS_B, I1Approximation, KernelFlow, LASCHKA_A, LASCHKA_C, Radial,
    gauss_legendre_64, one_minus_u_over_root,
};
use num_complex::Complex64;

/// The normalwash (positive downwards, per unit circulation/4π) at
/// (x, y, z₀ above the vortex's plane) of a horseshoe vortex: bound from
/// a = (xₐ, yₐ) to b, trailing to x = +∞, by the Biot–Savart law in three
/// dimensions (J. Katz and A. Plotkin, *Low-speed aerodynamics*, 2nd ed.,
/// 2001, eq 10.115 for a segment and §10.4.7 for a horseshoe). At z₀ = 0 it
/// is [`crate::aerodynamics::lifting_surface::doublet_line::horseshoe`].
pub fn horseshoe_3d(x: f64, y: f64, z0: f64, a: (f64, f64), b: (f64, f64)) -> f64 {
    let r1 = [x - a.0, y - a.1, z0];
    let r2 = [x - b.0, y - b.1, z0];
    let n1 = (r1[0] * r1[0] + r1[1] * r1[1] + z0 * z0).sqrt();
    let n2 = (r2[0] * r2[0] + r2[1] * r2[1] + z0 * z0).sqrt();
    let c = [
        r1[1] * r2[2] - r1[2] * r2[1],
        r1[2] * r2[0] - r1[0] * r2[2],
        r1[0] * r2[1] - r1[1] * r2[0],
    ];
    let c2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
    let r0 = [b.0 - a.0, b.1 - a.1, 0.0];
    let bound = if c2 > (1e-14 * n1 * n2).powi(2) {
        let dot: f64 = (0..3).map(|k| r0[k] * (r1[k] / n1 - r2[k] / n2)).sum();
        c[2] * dot / c2
    } else {
        0.0
    };
    // a leg from P to +∞ gives r_y(1 + r_x/|r|)/(r_y² + z₀²), r = X − P
    let leg = |r: [f64; 3], n: f64| {
        let d = r[1] * r[1] + z0 * z0;
        if d > 0.0 {
            r[1] * (1.0 + r[0] / n) / d
        } else {
            0.0
        }
    };
    -(bound + leg(r2, n2) - leg(r1, n1))
}

/// The steady normalwash factor D₀ of `line` at (x, y) and z₀ above it, in
/// Prandtl–Glauert coordinates x/β (as [`DoubletLine::steady`]).
pub fn steady(line: &DoubletLine, x: f64, y: f64, z0: f64, beta: f64) -> f64 {
    let ((xa, ya), (xb, yb)) = line.ends();
    line.factor() * horseshoe_3d(x / beta, y, z0, (xa / beta, ya), (xb / beta, yb))
}

/// What the second numerator needs of r alone: k₁ = κr and, per term of
/// the exponential sum, pₙ, aₙ/(pₙ + ik₁) and aₙ/(pₙ + ik₁)², with
/// Re J₂(0) for the reflection.
#[derive(Debug, Clone)]
pub struct Radial2 {
    r: f64,
    k1: f64,
    /// e^{−pₙu} = qₙ from q₀ by squaring (Desmarais: pₙ = 2ⁿ⁺¹b) or by
    /// powers (Laschka: pₙ = (n + 1)c); Laschka's eleven terms padded.
    squaring: bool,
    p0: f64,
    w: [Complex64; 12],
    v: [Complex64; 12],
    re_at_zero: f64,
    /// The planar kernel's factors at the same r (for K₁).
    radial: Radial,
}

impl Radial2 {
    pub fn new(r: f64, flow: &KernelFlow) -> Radial2 {
        let k1 = flow.kappa * r;
        let mut a = [0.0; 12];
        let mut p = [0.0; 12];
        let squaring = flow.approx != I1Approximation::Laschka;
        if squaring {
            a = DESMARAIS_A;
            let mut pn = 2.0 * DESMARAIS_B;
            for slot in &mut p {
                *slot = pn;
                pn *= 2.0;
            }
        } else {
            a[..LASCHKA_A.len()].copy_from_slice(&LASCHKA_A);
            for (n, slot) in p.iter_mut().enumerate() {
                *slot = (n + 1) as f64 * LASCHKA_C;
            }
        }
        let w: [Complex64; 12] = std::array::from_fn(|n| a[n] / Complex64::new(p[n], k1));
        let v: [Complex64; 12] = std::array::from_fn(|n| w[n] / Complex64::new(p[n], k1));
        let mut out = Radial2 {
            r,
            k1,
            squaring,
            p0: p[0],
            w,
            v,
            re_at_zero: 0.0,
            radial: Radial::new(r, flow),
        };
        out.re_at_zero = out.j2(0.0).re;
        out
    }

    /// J₂(u) = e^{ik₁u}·3I₂(u) for u ≥ 0 (the module's formula).
    fn j2(&self, u: f64) -> Complex64 {
        let k = self.k1;
        let (mut s0, mut s1) = (Complex64::new(0.0, 0.0), Complex64::new(0.0, 0.0));
        let step = (-self.p0 * u).exp();
        let mut q = step;
        for (w, v) in self.w.iter().zip(&self.v) {
            s0 += w * q;
            s1 += (v + w * u) * q;
            q = if self.squaring { q * q } else { q * step };
        }
        let q3 = (1.0 + u * u).powf(1.5);
        let g = one_minus_u_over_root(u);
        Complex64::new(2.0 * g - u / q3, k * u * g) - Complex64::new(0.0, k) * s0 + s1 * (k * k)
    }
}

/// 3I₂(u₁, k₁) by quadrature (the reference of
/// [`I1Approximation::Quadrature`]): as [`kernel::i1_by_quadrature`], for
/// the power −5/2.
fn three_i2_by_quadrature(u1: f64, k1: f64) -> Complex64 {
    if u1 < 0.0 {
        let at0 = three_i2_by_quadrature(0.0, k1);
        return Complex64::new(2.0 * at0.re, 0.0) - three_i2_by_quadrature(-u1, k1).conj();
    }
    let rule = gauss_legendre_64();
    let f = |v: Complex64| (v * v + 1.0).powf(-2.5);
    let big_u = u1 + 2.0;
    let mut near = Complex64::new(0.0, 0.0);
    for &(s, w) in rule {
        let v = u1 + 2.0 * s;
        near += Complex64::from_polar(w * 2.0 * (1.0 + v * v).powf(-2.5), -k1 * v);
    }
    let mut tail = Complex64::new(0.0, 0.0);
    for &(s, w) in rule {
        let t = big_u * s / (1.0 - s);
        let dt = big_u / ((1.0 - s) * (1.0 - s));
        tail += f(Complex64::new(big_u, -t)) * ((-k1 * t).exp() * dt * w);
    }
    let far = Complex64::new(0.0, -1.0) * Complex64::from_polar(1.0, -k1 * big_u) * tail;
    (near + far) * 3.0
}

/// e^{−iκx₀}K₂ at (x₀, r) (r > 0).
pub fn second_numerator(x0: f64, radial: &Radial2, flow: &KernelFlow) -> Complex64 {
    let (m, b2, kappa, r) = (flow.mach, flow.beta2, flow.kappa, radial.r);
    let big_r = (x0 * x0 + b2 * r * r).sqrt();
    let r_minus = big_r - m * x0; // β²r√(1 + u₁²)
    let u1 = (m * big_r - x0) / (b2 * r);
    let inv_q = b2 * r / r_minus;
    let k = radial.k1;
    let bracket =
        r_minus * r_minus / (b2 * big_r * big_r) + 2.0 + m * (m * big_r - x0) / (b2 * big_r);
    let b = m * r / big_r * bracket * inv_q * inv_q * inv_q;
    let term2 = Complex64::new(0.0, k * m * m * r * r * inv_q / (big_r * big_r));
    let both = Complex64::from_polar(1.0, -kappa * m * r_minus / b2); // e^{−ik₁u₁ − iκx₀}
    let lag = Complex64::from_polar(1.0, -kappa * x0);
    let three_i2 = if flow.approx == I1Approximation::Quadrature {
        lag * three_i2_by_quadrature(u1, k)
    } else if u1 >= 0.0 {
        both * radial.j2(u1)
    } else {
        lag * (2.0 * radial.re_at_zero) - both * radial.j2(-u1).conj()
    };
    three_i2 + both * (term2 + b)
}

/// The two numerators of the oscillatory increment at (x₀, r):
/// (ΔK₁, Q) = (e^{−iκx₀}K₁ − K₁₀, (ΔK₂ + 2ΔK₁)/r²).
pub fn increments(x0: f64, radial: &Radial2, flow: &KernelFlow) -> (Complex64, Complex64) {
    let r = radial.r;
    let big_r = (x0 * x0 + flow.beta2 * r * r).sqrt();
    let dk1 = kernel::increment_at(x0, &radial.radial, flow);
    let k20 = 2.0 + x0 / big_r * (2.0 + flow.beta2 * r * r / (big_r * big_r));
    let dk2 = second_numerator(x0, radial, flow) - k20;
    (dk1, (dk2 + dk1 * 2.0) / (r * r))
}

/// The two numerators of the first-order term per unit iκ at (x₀, r):
/// (N₁₁, (N₂₁ + 2N₁₁)/r²) = (x₀ + (x₀² + r²)/R, (R² + M²x₀²)/R³).
pub fn first_order(x0: f64, r: f64, beta2: f64) -> (f64, f64) {
    let big_r2 = x0 * x0 + beta2 * r * r;
    let big_r = big_r2.sqrt();
    let m2 = 1.0 - beta2;
    (
        x0 + (x0 * x0 + r * r) / big_r,
        (big_r2 + m2 * x0 * x0) / (big_r2 * big_r),
    )
}

/// The steady numerators (K₁₀, (K₂₀ + 2K₁₀)/r²) = (−(1 + x₀/R), β²x₀/R³):
/// what the horseshoe carries in closed form (a check of the line rule).
pub fn steady_numerators(x0: f64, r: f64, beta2: f64) -> (f64, f64) {
    let big_r = (x0 * x0 + beta2 * r * r).sqrt();
    (-(1.0 + x0 / big_r), beta2 * x0 / (big_r * big_r * big_r))
}

/// ∫_{−e}^{e} η′ⁿ W(η′) dη′, n = 0…4, for the two weights
/// W₁ = (u² − z²)/(u² + z²)² and W₂ = z²/(u² + z²), u = ȳ − η′ (z ≠ 0).
///
/// With aₖ = ∫uᵏ/(u² + z²) du and cₖ = ∫uᵏW₁ du over u ∈ [ȳ − e, ȳ + e]:
/// a₀ = [atan(u/z)]/z, a₁ = ½[ln(u² + z²)], aₖ = [uᵏ⁻¹]/(k − 1) − z²aₖ₋₂;
/// c₀ = −[u/(u² + z²)], c₁ = a₁ + [z²/(u² + z²)],
/// cₖ = [uᵏ⁻¹]/(k − 1) − 2z²aₖ₋₂ − z²cₖ₋₂; then η′ⁿ = (ȳ − u)ⁿ binomially.
/// (As z → 0, the cₖ become the planar finite parts of
/// [`crate::aerodynamics::lifting_surface::doublet_line::moment_integrals`].)
pub fn moments(ybar: f64, e: f64, z: f64) -> ([f64; 5], [f64; 5]) {
    let z = z.abs();
    let z2 = z * z;
    let (ua, ub) = (ybar - e, ybar + e);
    let power = |k: usize| (ub.powi(k as i32) - ua.powi(k as i32)) / k as f64;
    let mut a = [0.0; 5];
    let mut c = [0.0; 5];
    a[0] = (z * (ub - ua)).atan2(z2 + ua * ub) / z;
    a[1] = 0.5 * ((ub * ub + z2) / (ua * ua + z2)).ln();
    c[0] = ua / (ua * ua + z2) - ub / (ub * ub + z2);
    c[1] = a[1] + z2 / (ub * ub + z2) - z2 / (ua * ua + z2);
    for k in 2..5 {
        a[k] = power(k - 1) - z2 * a[k - 2];
        c[k] = power(k - 1) - 2.0 * z2 * a[k - 2] - z2 * c[k - 2];
    }
    // ∫η′ⁿW = Σⱼ C(n, j) ȳⁿ⁻ʲ(−1)ʲ ∫uʲW
    const BINOMIAL: [[f64; 5]; 5] = [
        [1.0, 0.0, 0.0, 0.0, 0.0],
        [1.0, 1.0, 0.0, 0.0, 0.0],
        [1.0, 2.0, 1.0, 0.0, 0.0],
        [1.0, 3.0, 3.0, 1.0, 0.0],
        [1.0, 4.0, 6.0, 4.0, 1.0],
    ];
    let mut w1 = [0.0; 5];
    let mut w2 = [0.0; 5];
    for n in 0..5 {
        for j in 0..=n {
            let f =
                BINOMIAL[n][j] * ybar.powi((n - j) as i32) * if j % 2 == 0 { 1.0 } else { -1.0 };
            w1[n] += f * c[j];
            w2[n] += f * z2 * a[j];
        }
    }
    (w1, w2)
}

/// A station of the rule across a line: its offset η′ along the line, its
/// spanwise distance y₀ = ȳ − η′ and the weights of the two numerators.
#[derive(Debug, Clone, Copy, Default)]
pub struct Station {
    pub eta: f64,
    pub y0: f64,
    pub w1: f64,
    pub w2: f64,
}

/// The rule across a line of half-width `e` for a point at ȳ from its
/// centre and z₀ above it: the quartic (five stations) within
/// [`GAUSS_BEYOND`]·e, two-point Gauss beyond. Returns the stations and
/// how many are used.
pub fn rule(ybar: f64, e: f64, z0: f64) -> ([Station; 5], usize) {
    let mut out = [Station::default(); 5];
    let z2 = z0 * z0;
    if ybar.hypot(z0) > GAUSS_BEYOND * e {
        for (k, s) in [-FRAC_1_SQRT_3, FRAC_1_SQRT_3].into_iter().enumerate() {
            let u = ybar - s * e;
            let r2 = u * u + z2;
            out[k] = Station {
                eta: s * e,
                y0: u,
                w1: e * (u * u - z2) / (r2 * r2),
                w2: e * z2 / r2,
            };
        }
        return (out, 2);
    }
    let (m1, m2) = moments(ybar, e, z0);
    let (w1, w2) = (quartic_weights_of(m1, e), quartic_weights_of(m2, e));
    for (k, s) in [-1.0, -0.5, 0.0, 0.5, 1.0].into_iter().enumerate() {
        out[k] = Station {
            eta: s * e,
            y0: ybar - s * e,
            w1: w1[k],
            w2: w2[k],
        };
    }
    (out, 5)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::aerodynamics::lifting_surface::doublet_line::{horseshoe, moment_integrals};

    #[test]
    fn the_3d_horseshoe_is_the_planar_one_in_the_plane_and_continuous_off_it() {
        let (a, b) = ((0.1, 0.05), (0.3, 0.25));
        for (x, y) in [(0.6, 0.2), (0.2, 0.18), (-0.3, 0.1), (0.9, -0.4)] {
            let planar = horseshoe(x, y, a, b);
            assert!((horseshoe_3d(x, y, 0.0, a, b) - planar).abs() < 1e-12 * (1.0 + planar.abs()));
            let near = horseshoe_3d(x, y, 1e-7, a, b);
            assert!(
                (near - planar).abs() < 1e-5 * (1.0 + planar.abs()),
                "{near} {planar}"
            );
        }
    }

    /// The steady kernel (K₁₀ and K₂₀, closed forms) integrated across a
    /// line by the module's rule on many pieces is the Biot–Savart
    /// horseshoe: the non-planar weights, the K₂ term's sign and scale.
    #[test]
    fn the_steady_kernel_across_a_line_is_the_3d_horseshoe() {
        let line = DoubletLine {
            xi: 0.1,
            eta: 0.2,
            e: 0.15,
            tan_sweep: 0.8,
            chord: 0.2,
        };
        for m in [0.0, 0.6] {
            let beta2: f64 = 1.0 - m * m;
            for (x, y, z0) in [
                (0.6, 0.2, 0.1),
                (0.3, 0.33, 0.02),
                (-0.4, 0.25, 0.3),
                (1.5, -0.3, 0.5),
            ] {
                let exact = horseshoe_3d(
                    x / beta2.sqrt(),
                    y,
                    z0,
                    (
                        (line.xi - line.e * line.tan_sweep) / beta2.sqrt(),
                        line.eta - line.e,
                    ),
                    (
                        (line.xi + line.e * line.tan_sweep) / beta2.sqrt(),
                        line.eta + line.e,
                    ),
                );
                let pieces = 400;
                let h = line.e / pieces as f64;
                let mut sum = 0.0;
                for p in 0..pieces {
                    let c = -line.e + (2 * p + 1) as f64 * h;
                    let (xi, eta) = (line.xi + c * line.tan_sweep, line.eta + c);
                    let (st, n) = rule(y - eta, h, z0);
                    for s in &st[..n] {
                        let x0 = x - xi - s.eta * line.tan_sweep;
                        let r = s.y0.hypot(z0);
                        let (k10, q0) = steady_numerators(x0, r, beta2);
                        sum += s.w1 * k10 + s.w2 * q0;
                    }
                }
                assert!(
                    (sum - exact).abs() < 1e-6 * (1.0 + exact.abs()),
                    "{m} ({x}, {y}, {z0}): {sum} {exact}"
                );
            }
        }
    }

    #[test]
    fn the_moments_tend_to_the_planar_finite_parts() {
        for (ybar, e) in [(0.3, 0.1), (0.05, 0.1), (-0.2, 0.15), (0.0, 0.1)] {
            let planar = moment_integrals(ybar, e);
            let (w1, w2) = moments(ybar, e, 1e-7);
            for n in 0..5 {
                assert!(
                    (w1[n] - planar[n]).abs() < 1e-5 * (1.0 + planar[n].abs()),
                    "{n}"
                );
                assert!(w2[n].abs() < 1e-5);
            }
        }
    }

    #[test]
    fn the_moments_are_the_integrals() {
        // midpoint rule with 200000 points
        for (ybar, e, z) in [(0.3, 0.1, 0.05), (0.02, 0.1, 0.03), (-0.5, 0.2, 0.4)] {
            let (w1, w2) = moments(ybar, e, z);
            let n = 200_000;
            let mut q1 = [0.0; 5];
            let mut q2 = [0.0; 5];
            for i in 0..n {
                let eta = -e + 2.0 * e * (i as f64 + 0.5) / n as f64;
                let u = ybar - eta;
                let r2 = u * u + z * z;
                for k in 0..5 {
                    let p = eta.powi(k as i32) * 2.0 * e / n as f64;
                    q1[k] += p * (u * u - z * z) / (r2 * r2);
                    q2[k] += p * z * z / r2;
                }
            }
            for k in 0..5 {
                assert!(
                    (w1[k] - q1[k]).abs() < 1e-6 * (1.0 + q1[k].abs()),
                    "{k} {} {}",
                    w1[k],
                    q1[k]
                );
                assert!((w2[k] - q2[k]).abs() < 1e-6 * (1.0 + q2[k].abs()), "{k}");
            }
        }
    }
}
