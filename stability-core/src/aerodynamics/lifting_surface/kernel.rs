//! The kernel of the subsonic lifting-surface integral equation for a
//! planar wing in harmonic motion (time factor e^{iωt}), in the form the
//! doublet-lattice method integrates along each box's doublet line.
//!
//! The normalwash w̄ = w/V (positive downwards, i.e. an incidence) at a
//! receiving point due to a lifting-pressure coefficient Δc_p acting on an
//! element dξ dη at a distance (x₀, y₀) = (x − ξ, y − η) upstream of it is
//! w̄ = (1/8π) Δc_p K dξ dη with, for a planar wing,
//! K = N/y₀², N = K₁ e^{−iκx₀}, κ = ω/V (per unit length), after
//! M.T. Landahl, "Kernel function for nonplanar oscillating surfaces in a
//! subsonic flow", AIAA J. 5(5), 1967, pp. 1045–1046, in the notation of
//! E. Albano and W.P. Rodden, "A doublet-lattice method for calculating lift
//! distributions on oscillating surfaces in subsonic flows", AIAA J. 7(2),
//! 1969, pp. 279–285 (their eqs 5–9) and of W.P. Rodden, J.P. Giesing and
//! T.P. Kálmán, AGARD CP-80-71 (1971):
//!
//! K₁ = −I₁ − M r e^{−ik₁u₁} / (R √(1 + u₁²)),
//! I₁ = ∫_{u₁}^∞ e^{−ik₁u} (1 + u²)^{−3/2} du,
//! r = |y₀|, R = √(x₀² + β²r²), β² = 1 − M², u₁ = (MR − x₀)/(β²r), k₁ = κr.
//!
//! Only the planar term (Landahl's K₁, with T₁ = 1) is needed: the wing is
//! flat, so the non-planar K₂T₂ term vanishes identically.
//!
//! Identities used throughout (exact, and free of the overflow of u₁ as
//! r → 0): β²r√(1 + u₁²) = R − Mx₀, and k₁u₁ + κx₀ = κM(R − Mx₀)/β².

use num_complex::Complex64;
use wide::f64x4;

/// I.E. Laschka's eleven-term exponential approximation
/// u/√(1 + u²) ≈ 1 − Σ aₙ e^{−ncu}, c = 0.372, u ≥ 0: B. Laschka, "Zur
/// Theorie der harmonisch schwingenden tragenden Fläche bei
/// Unterschallanströmung", Z. Flugwiss. 11(7), 1963, pp. 265–292, with the
/// coefficients as W.P. Rodden, J.P. Giesing and T.P. Kálmán (AGARD CP-80-71,
/// 1971, eq A.4) and M. Blair (WL-TR-92-3028, 1992, p. 89) print them. Their
/// sum is 1.0000185, so the fit is off by 2·10⁻⁵ at u = 0; its largest
/// error on u ≥ 0 is 1.3·10⁻³, near u = 15, where the exponentials have
/// died away faster than 1/(2u²) (tested).
pub(crate) const LASCHKA_A: [f64; 11] = [
    0.241_861_98,
    -2.791_802_7,
    24.991_079,
    -111.591_96,
    271.435_49,
    -305.752_88,
    -41.183_63,
    545.985_37,
    -644.781_55,
    328.727_55,
    -64.279_511,
];
pub(crate) const LASCHKA_C: f64 = 0.372;

/// R.N. Desmarais' twelve-term approximation
/// u/√(1 + u²) ≈ 1 − Σ aₙ e^{−2ⁿbu}, b = 0.009054814793: R.N. Desmarais,
/// "An accurate method for evaluating the kernel of the integral equation
/// relating lift to downwash in unsteady potential flow", AIAA Paper
/// 82-0687 (1982), as W.P. Rodden, P.F. Taylor and S.C. McIntosh, "Further
/// refinement of the subsonic doublet-lattice method", J. Aircraft 35(5),
/// 1998, pp. 720–727, use it. Its largest error on u ≥ 0 is 2.5·10⁻⁵
/// (tested), fifty times smaller than Laschka's; the exponents are powers
/// of two, so the twelve exponentials come from one by squaring.
pub(crate) const DESMARAIS_A: [f64; 12] = [
    0.000_319_759_140,
    -0.000_055_461_471,
    0.002_726_074_362,
    0.005_749_551_566,
    0.031_455_895_072,
    0.106_031_126_212,
    0.406_838_011_567,
    0.798_112_357_155,
    -0.417_749_229_098,
    0.077_480_713_894,
    -0.012_677_284_771,
    0.001_787_032_960,
];
pub(crate) const DESMARAIS_B: f64 = 0.009_054_814_793;

/// How the kernel's integral I₁ is evaluated: both replace
/// 1 − u/√(1 + u²) by a sum of exponentials, which makes I₁ closed-form
/// (the approximation only touches the frequency-dependent term, so the
/// steady kernel is exact either way).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize)]
pub enum I1Approximation {
    /// Laschka (1963), eleven terms, the classical doublet-lattice choice.
    Laschka,
    /// Desmarais (1982), twelve terms, fifty times more accurate.
    #[default]
    Desmarais,
    /// No approximation: I₁ by numerical quadrature ([`i1_by_quadrature`]),
    /// to about 10⁻¹² — a reference, some hundred times slower.
    Quadrature,
}

/// 1 − u/√(1 + u²) for u ≥ 0 without cancellation:
/// 1/(√(1 + u²)(√(1 + u²) + u)).
pub(crate) fn one_minus_u_over_root(u: f64) -> f64 {
    let q = (1.0 + u * u).sqrt();
    1.0 / (q * (q + u))
}

/// I₁(u₁, k₁) = ∫_{u₁}^∞ e^{−ik₁u}(1 + u²)^{−3/2} du for any real u₁, with
/// Rodden, Giesing & Kálmán's reflection for u₁ < 0 (1971, eq A.5):
/// I₁(u₁) = 2 Re I₁(0) − conj I₁(−u₁).
pub fn i1(u1: f64, k1: f64, approx: I1Approximation) -> Complex64 {
    if approx == I1Approximation::Quadrature {
        return i1_by_quadrature(u1, k1);
    }
    let radial = Radial::for_k1(0.0, k1, approx);
    let phase = Complex64::from_polar(1.0, -k1 * u1);
    if u1 >= 0.0 {
        phase * radial.i1_reduced(u1, approx)
    } else {
        // conj(e^{−ik₁|u₁|} J) = e^{−ik₁u₁} conj(J)
        let j = radial.i1_reduced(-u1, approx).conj();
        Complex64::new(radial.twice_re_at_zero, 0.0) - phase * j
    }
}

/// Gauss–Legendre nodes and weights on [0, 1], n = 64 (Newton's method on
/// P₆₄ from Tricomi's initial guesses; computed once).
pub(crate) fn gauss_legendre_64() -> &'static [(f64, f64)] {
    static RULE: std::sync::OnceLock<Vec<(f64, f64)>> = std::sync::OnceLock::new();
    RULE.get_or_init(|| {
        let n = 64;
        (0..n)
            .map(|i| {
                let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
                let mut dp = 1.0;
                for _ in 0..100 {
                    // P_n(x) and P_n'(x) by the three-term recurrence
                    let (mut p0, mut p1) = (1.0, x);
                    for k in 2..=n {
                        let p2 = ((2 * k - 1) as f64 * x * p1 - (k - 1) as f64 * p0) / k as f64;
                        p0 = p1;
                        p1 = p2;
                    }
                    dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
                    let dx = p1 / dp;
                    x -= dx;
                    if dx.abs() < 1e-16 {
                        break;
                    }
                }
                let w = 2.0 / ((1.0 - x * x) * dp * dp);
                (0.5 * (1.0 + x), 0.5 * w)
            })
            .collect()
    })
}

/// I₁(u₁, k₁) without approximation, for reference: for u₁ ≥ 0 the
/// integral over [u₁, u₁ + 2] by 64-point Gauss–Legendre, and beyond
/// U = u₁ + 2 along the rotated path v = U − it, where the integrand
/// decays as e^{−k₁t} (the integrand (1 + v²)^{−3/2} is analytic for
/// Re v > 0, and the arc at infinity contributes nothing for k₁ ≥ 0):
/// ∫_U^∞ = −i e^{−ik₁U} ∫₀^∞ e^{−k₁t}(1 + (U − it)²)^{−3/2} dt, mapped by
/// t = Us/(1 − s) onto the same rule. u₁ < 0 by the reflection of [`i1`].
/// Accurate to about 10⁻¹² for k₁ ≤ 20 (tested against mpmath).
pub fn i1_by_quadrature(u1: f64, k1: f64) -> Complex64 {
    if u1 < 0.0 {
        let at0 = i1_by_quadrature(0.0, k1);
        return Complex64::new(2.0 * at0.re, 0.0) - i1_by_quadrature(-u1, k1).conj();
    }
    let rule = gauss_legendre_64();
    let f = |v: Complex64| (v * v + 1.0).powf(-1.5);
    let big_u = u1 + 2.0;
    let mut near = Complex64::new(0.0, 0.0);
    for &(s, w) in rule {
        let v = u1 + 2.0 * s;
        near += Complex64::from_polar(w * 2.0 * (1.0 + v * v).powf(-1.5), -k1 * v);
    }
    let mut tail = Complex64::new(0.0, 0.0);
    for &(s, w) in rule {
        let t = big_u * s / (1.0 - s);
        let dt = big_u / ((1.0 - s) * (1.0 - s));
        tail += f(Complex64::new(big_u, -t)) * ((-k1 * t).exp() * dt * w);
    }
    near + Complex64::new(0.0, -1.0) * Complex64::from_polar(1.0, -k1 * big_u) * tail
}

/// The flow a kernel is evaluated in: Mach number, β² = 1 − M², and
/// κ = ω/V per unit length.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KernelFlow {
    pub mach: f64,
    pub beta2: f64,
    pub kappa: f64,
    pub approx: I1Approximation,
}

impl KernelFlow {
    pub fn new(mach: f64, kappa: f64, approx: I1Approximation) -> KernelFlow {
        KernelFlow {
            mach,
            beta2: 1.0 - mach * mach,
            kappa,
            approx,
        }
    }
}

/// Below this |y₀|/(|x₀| + |y₀|) the receiving point is on the sending
/// element's streamwise line, and the kernel takes its limit r → 0.
const ON_LINE: f64 = 1e-13;

/// The steady kernel numerator N₀ = K₁₀ = −(1 + x₀/R) (Albano & Rodden
/// 1969, eq 11; exact). On the line r = 0 it is −2 downstream of the
/// element and 0 upstream.
pub fn steady_numerator(x0: f64, y0: f64, beta2: f64) -> f64 {
    let r = y0.abs();
    if r <= ON_LINE * (x0.abs() + r) {
        return if x0 > 0.0 { -2.0 } else { 0.0 };
    }
    let big_r = (x0 * x0 + beta2 * r * r).sqrt();
    -(1.0 + x0 / big_r)
}

/// What the numerator needs of the spanwise distance r = |y₀| alone, for
/// every x₀ at that r: k₁ = κr and the exponential sum's coefficients
/// cₙ = aₙ/(pₙ² + k₁²) as cₙpₙ and cₙ — so that a lattice, whose rows and
/// columns share r strip by strip, divides once per strip pair and not
/// once per box pair.
#[derive(Debug, Clone, Copy)]
pub struct Radial {
    r: f64,
    k1: f64,
    cp: [f64; 12],
    c: [f64; 12],
    /// 2 Re I₁(0, k₁), the reflection's constant.
    twice_re_at_zero: f64,
}

impl Radial {
    pub fn new(y0: f64, flow: &KernelFlow) -> Radial {
        Radial::for_k1(y0.abs(), flow.kappa * y0.abs(), flow.approx)
    }

    fn for_k1(r: f64, k1: f64, approx: I1Approximation) -> Radial {
        let mut cp = [0.0; 12];
        let mut c = [0.0; 12];
        let mut fill = |n: usize, a: f64, p: f64| {
            let cn = a / (p * p + k1 * k1);
            cp[n] = cn * p;
            c[n] = cn;
        };
        match approx {
            I1Approximation::Laschka => {
                for (n, &a) in LASCHKA_A.iter().enumerate() {
                    fill(n, a, (n + 1) as f64 * LASCHKA_C);
                }
            }
            I1Approximation::Desmarais | I1Approximation::Quadrature => {
                let mut p = 2.0 * DESMARAIS_B;
                for (n, &a) in DESMARAIS_A.iter().enumerate() {
                    fill(n, a, p);
                    p *= 2.0;
                }
            }
        }
        // I₁(0, k₁) = 1 − k₁² Σcₙ − ik₁ Σcₙpₙ (u = 0: all exponentials 1)
        let twice_re_at_zero = 2.0 * (1.0 - k1 * k1 * c.iter().sum::<f64>());
        Radial {
            r,
            k1,
            cp,
            c,
            twice_re_at_zero,
        }
    }

    /// e^{ik₁u} I₁(u, k₁) for u ≥ 0 (Rodden, Giesing & Kálmán 1971,
    /// eq A.1): 1 − u/√(1 + u²) − ik₁ Σ aₙe^{−pₙu}/(pₙ + ik₁)
    /// = 1 − u/√(1 + u²) − k₁² Σ cₙqₙ − ik₁ Σ cₙpₙqₙ, qₙ = e^{−pₙu}.
    fn i1_reduced(&self, u: f64, approx: I1Approximation) -> Complex64 {
        let (mut a, mut b) = (0.0, 0.0);
        match approx {
            I1Approximation::Laschka => {
                let step = (-LASCHKA_C * u).exp();
                let mut q = step;
                for n in 0..LASCHKA_A.len() {
                    a += self.cp[n] * q;
                    b += self.c[n] * q;
                    q *= step;
                }
            }
            I1Approximation::Desmarais | I1Approximation::Quadrature => {
                let mut q = (-2.0 * DESMARAIS_B * u).exp();
                for n in 0..DESMARAIS_A.len() {
                    a += self.cp[n] * q;
                    b += self.c[n] * q;
                    q *= q;
                }
            }
        }
        let k = self.k1;
        Complex64::new(one_minus_u_over_root(u) - k * k * b, -k * a)
    }

    /// [`Radial::i1_reduced`]'s sums Σcₙpₙqₙ and Σcₙqₙ at four u ≥ 0.
    fn sums_x4(&self, u: f64x4, approx: I1Approximation) -> (f64x4, f64x4) {
        let (mut a, mut b) = (f64x4::ZERO, f64x4::ZERO);
        match approx {
            I1Approximation::Laschka => {
                let step = (f64x4::splat(-LASCHKA_C) * u).exp();
                let mut q = step;
                for n in 0..LASCHKA_A.len() {
                    a += f64x4::splat(self.cp[n]) * q;
                    b += f64x4::splat(self.c[n]) * q;
                    q *= step;
                }
            }
            I1Approximation::Desmarais | I1Approximation::Quadrature => {
                let mut q = (f64x4::splat(-2.0 * DESMARAIS_B) * u).exp();
                for n in 0..DESMARAIS_A.len() {
                    a += f64x4::splat(self.cp[n]) * q;
                    b += f64x4::splat(self.c[n]) * q;
                    q *= q;
                }
            }
        }
        (a, b)
    }
}

/// The full planar numerator N = K₁ e^{−iκx₀} (Landahl 1967). On the line
/// r = 0 it is −2e^{−iκx₀} downstream and 0 upstream (I₁ → 2, the
/// second term → 0).
pub fn numerator(x0: f64, y0: f64, flow: &KernelFlow) -> Complex64 {
    numerator_at(x0, &Radial::new(y0, flow), flow)
}

/// [`numerator`] with the spanwise distance's factors given.
pub fn numerator_at(x0: f64, radial: &Radial, flow: &KernelFlow) -> Complex64 {
    numerator_and_steady(x0, radial, flow).0
}

/// N and N₀ together (they share R).
fn numerator_and_steady(x0: f64, radial: &Radial, flow: &KernelFlow) -> (Complex64, f64) {
    let r = radial.r;
    if r <= ON_LINE * (x0.abs() + r) {
        return if x0 > 0.0 {
            (Complex64::from_polar(-2.0, -flow.kappa * x0), -2.0)
        } else {
            (Complex64::new(0.0, 0.0), 0.0)
        };
    }
    let (m, b2, kappa) = (flow.mach, flow.beta2, flow.kappa);
    let big_r = (x0 * x0 + b2 * r * r).sqrt();
    let steady = -(1.0 + x0 / big_r);
    let r_minus = big_r - m * x0; // β²r√(1 + u₁²) > 0
    let u1 = (m * big_r - x0) / (b2 * r);
    // M r/(R√(1+u₁²)) = Mβ²r²/(R(R − Mx₀)), times e^{−ik₁u₁}
    let second = m * b2 * r * r / (big_r * r_minus);
    let both = Complex64::from_polar(1.0, -kappa * m * r_minus / b2); // e^{−ik₁u₁ − iκx₀}
    let n = if flow.approx == I1Approximation::Quadrature {
        let lag = Complex64::from_polar(1.0, -kappa * x0);
        -(lag * i1_by_quadrature(u1, radial.k1) + both * second)
    } else if u1 >= 0.0 {
        -(both * (radial.i1_reduced(u1, flow.approx) + second))
    } else {
        let lag = Complex64::from_polar(1.0, -kappa * x0);
        let j = radial.i1_reduced(-u1, flow.approx).conj();
        -(lag * radial.twice_re_at_zero + both * (second - j))
    };
    (n, steady)
}

/// [`increment_at`] at every x₀ of `x0` (one spanwise distance), into
/// `out`: four at a time in the lanes of `f64x4` (`increment_x4`), the
/// rest one by one.
pub fn increments_at(x0: &[f64], radial: &Radial, flow: &KernelFlow, out: &mut [Complex64]) {
    let mut xs = x0.chunks_exact(4);
    let mut outs = out.chunks_exact_mut(4);
    for (x, o) in (&mut xs).zip(&mut outs) {
        match increment_x4([x[0], x[1], x[2], x[3]], radial, flow) {
            Some(v) => o.copy_from_slice(&v),
            None => {
                for (o, &x) in o.iter_mut().zip(x) {
                    *o = increment_at(x, radial, flow);
                }
            }
        }
    }
    let rest = outs.into_remainder().iter_mut().zip(xs.remainder());
    for (o, &x) in rest {
        *o = increment_at(x, radial, flow);
    }
}

/// [`increment_at`] at four x₀ at once: the same formulas, lane by lane
/// (wide's `exp` and `sin_cos`, within a few units in the last place of
/// libm's). None for [`I1Approximation::Quadrature`] or a lane on the
/// sending element's line (their own branches, one by one).
fn increment_x4(x0: [f64; 4], radial: &Radial, flow: &KernelFlow) -> Option<[Complex64; 4]> {
    let r = radial.r;
    let on_line = x0.iter().any(|x| r <= ON_LINE * (x.abs() + r));
    if flow.approx == I1Approximation::Quadrature || on_line {
        return None;
    }
    let (m, b2, kappa) = (flow.mach, flow.beta2, flow.kappa);
    let (one, zero, s) = (f64x4::ONE, f64x4::ZERO, f64x4::splat);
    let x = f64x4::new(x0);
    let big_r = (x * x + s(b2 * r * r)).sqrt();
    let steady = -(one + x / big_r);
    let r_minus = big_r - s(m) * x;
    let u1 = (s(m) * big_r - x) / s(b2 * r);
    let second = s(m * b2 * r * r) / (big_r * r_minus);
    // e^{−ik₁u₁ − iκx₀}
    let (both_im, both_re) = (s(-kappa * m / b2) * r_minus).sin_cos();
    // I₁'s reduced form at |u₁| (reflected below for u₁ < 0)
    let u = u1.abs();
    let (a, b) = radial.sums_x4(u, flow.approx);
    let root = (one + u * u).sqrt();
    let k = radial.k1;
    let (i_re, i_im) = (one / (root * (root + u)) - s(k * k) * b, -s(k) * a);
    // downstream: I + second; upstream: second − conj(I)
    let downstream = u1.simd_ge(zero);
    let p_re = downstream.select(i_re + second, second - i_re);
    let mut n_re = -(both_re * p_re - both_im * i_im);
    let mut n_im = -(both_im * p_re + both_re * i_im);
    if !downstream.all() {
        // −e^{−iκx₀}·2 Re I₁(0, k₁) upstream
        let (lag_im, lag_re) = (-s(kappa) * x).sin_cos();
        let twice = s(radial.twice_re_at_zero);
        n_re = downstream.select(n_re, n_re - lag_re * twice);
        n_im = downstream.select(n_im, n_im - lag_im * twice);
    }
    let (re, im) = ((n_re - steady).to_array(), n_im.to_array());
    Some(std::array::from_fn(|l| Complex64::new(re[l], im[l])))
}

/// The oscillatory increment N − N₀ that the doublet lattice integrates
/// along each doublet line (Albano & Rodden 1969, eq 21), the steady part
/// being carried by horseshoe vortices.
pub fn increment(x0: f64, y0: f64, flow: &KernelFlow) -> Complex64 {
    increment_at(x0, &Radial::new(y0, flow), flow)
}

/// [`increment`] with the spanwise distance's factors given (r = |y₀|).
pub fn increment_at(x0: f64, radial: &Radial, flow: &KernelFlow) -> Complex64 {
    let (n, n0) = numerator_and_steady(x0, radial, flow);
    n - n0
}

/// The first-order term of the numerator in frequency,
/// N = N₀ + iκN₁ + O(κ² ln κ), exact:
/// N₁ = x₀ + (x₀² + r²)/R.
///
/// From I₁ = I₁⁰ − ik₁/√(1 + u₁²) + O(k₁² ln k₁) and
/// e^{−ik₁u₁} = 1 − ik₁u₁ + …, with the identities above; the quasi-steady
/// derivatives (the report's "neglecting terms of second order in
/// frequency", §7) are the lattice's response to this term. On the line
/// r = 0: 2x₀ downstream, 0 upstream.
pub fn first_order_numerator(x0: f64, y0: f64, beta2: f64) -> f64 {
    let r = y0.abs();
    if r <= ON_LINE * (x0.abs() + r) {
        return if x0 > 0.0 { 2.0 * x0 } else { 0.0 };
    }
    let big_r = (x0 * x0 + beta2 * r * r).sqrt();
    x0 + (x0 * x0 + r * r) / big_r
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Four lanes at a time are the pointwise kernel: both approximations,
    /// downstream and upstream of the element (u₁ of either sign), near and
    /// far, a low and a near-sonic Mach number, within 10⁻¹³ of the
    /// kernel's scale (wide's exp and sin_cos against libm's); lanes on the
    /// element's line and the remainder beyond a multiple of four take the
    /// pointwise branch itself.
    #[test]
    fn four_lanes_are_the_pointwise_kernel() {
        let x0: Vec<f64> = (0..203).map(|k| -3.0 + 0.031 * k as f64).collect();
        for approx in [I1Approximation::Desmarais, I1Approximation::Laschka] {
            for (mach, kappa) in [(0.5, 0.7), (0.99, 2.3), (0.998, 0.4)] {
                let flow = KernelFlow::new(mach, kappa, approx);
                for y0 in [0.0, 1e-3, 0.05, 0.8, -2.5] {
                    let radial = Radial::new(y0, &flow);
                    let mut out = vec![Complex64::default(); x0.len()];
                    increments_at(&x0, &radial, &flow, &mut out);
                    for (&x, &o) in x0.iter().zip(&out) {
                        let one = increment_at(x, &radial, &flow);
                        let scale = one.norm().max(1.0);
                        assert!(
                            (o - one).norm() <= 1e-13 * scale,
                            "{approx:?} M {mach} y₀ {y0} x₀ {x}: {o} {one}"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn the_approximations_sum_to_one_at_u_zero() {
        // 1 − Σaₙ is the fit's error at u = 0 (the exact value there is 0).
        let l: f64 = LASCHKA_A.iter().sum();
        let d: f64 = DESMARAIS_A.iter().sum();
        assert!((l - 1.0).abs() < 2e-5, "{l}");
        assert!((d - 1.0).abs() < 2e-5, "{d}");
    }

    #[test]
    fn the_approximations_fit_u_over_root() {
        for (approx, tol) in [
            (I1Approximation::Laschka, 1.4e-3),
            (I1Approximation::Desmarais, 2.6e-5),
        ] {
            let mut worst: f64 = 0.0;
            for i in 0..=4000 {
                let u = i as f64 * 0.01;
                let fit = match approx {
                    I1Approximation::Laschka => LASCHKA_A
                        .iter()
                        .enumerate()
                        .map(|(n, a)| a * (-((n + 1) as f64) * LASCHKA_C * u).exp())
                        .sum::<f64>(),
                    I1Approximation::Desmarais => DESMARAIS_A
                        .iter()
                        .enumerate()
                        .map(|(n, a)| a * (-(2f64.powi(n as i32 + 1)) * DESMARAIS_B * u).exp())
                        .sum::<f64>(),
                    I1Approximation::Quadrature => continue,
                };
                worst = worst.max((fit - one_minus_u_over_root(u)).abs());
            }
            assert!(worst < tol, "{approx:?}: {worst}");
        }
    }

    /// I₁(u₁, k₁) by mpmath (30 digits, `quadosc`), from
    /// `scripts/lifting_surface_reference.py`.
    fn i1_mpmath() -> Vec<(f64, f64, f64, f64)> {
        let text = include_str!("../../../tests/data/lifting_surface/reference.json");
        let v: serde_json::Value = serde_json::from_str(text).unwrap();
        v["i1"]
            .as_array()
            .unwrap()
            .iter()
            .map(|r| {
                let g = |k: &str| r[k].as_f64().unwrap();
                (g("u1"), g("k1"), g("re"), g("im"))
            })
            .collect()
    }

    #[test]
    fn i1_against_mpmath() {
        // largest error found, for each method: the approximations' errors
        // are k₁ times their integrated fit errors
        for (approx, tol) in [
            (I1Approximation::Quadrature, 1e-12),
            (I1Approximation::Desmarais, 2e-4),
            (I1Approximation::Laschka, 2e-3),
        ] {
            for (u, k, re, im) in i1_mpmath() {
                let v = i1(u, k, approx);
                let err = (v - Complex64::new(re, im)).norm();
                assert!(
                    err < tol,
                    "{approx:?} I₁({u}, {k}) = {v}, mpmath {re} {im}i: {err:e}"
                );
            }
        }
    }

    #[test]
    fn at_zero_frequency_the_numerator_is_the_steady_one() {
        for m in [0.0, 0.5, 0.9] {
            let flow = KernelFlow::new(m, 0.0, I1Approximation::Desmarais);
            for (x0, y0) in [
                (0.3, 0.2),
                (-0.4, 0.1),
                (2.0, -1.5),
                (1e-3, 0.7),
                (-3.0, 0.01),
            ] {
                let n = numerator(x0, y0, &flow);
                let n0 = steady_numerator(x0, y0, flow.beta2);
                assert!(
                    (n.re - n0).abs() < 1e-14 && n.im.abs() < 1e-14,
                    "{m} {x0} {y0}: {n} {n0}"
                );
            }
        }
    }

    #[test]
    fn the_first_order_term_is_the_numerators_slope_in_frequency() {
        for m in [0.0, 0.6] {
            for (x0, y0) in [(0.3, 0.2), (-0.4, 0.1), (2.0, -1.5), (-3.0, 0.5)] {
                let kappa = 1e-5;
                let flow = KernelFlow::new(m, kappa, I1Approximation::Desmarais);
                let slope = increment(x0, y0, &flow) / Complex64::new(0.0, kappa);
                let exact = first_order_numerator(x0, y0, flow.beta2);
                // the fit's error, integrated, enters the slope at ~1e-3
                assert!(
                    (slope.re - exact).abs() < 2e-3 * (1.0 + exact.abs()),
                    "{slope} {exact}"
                );
                assert!(slope.im.abs() < 1e-3 * (1.0 + exact.abs()), "{slope}");
            }
        }
    }

    #[test]
    fn the_line_limits_are_the_limits() {
        let flow = KernelFlow::new(0.5, 0.8, I1Approximation::Desmarais);
        for x0 in [0.2, -0.2] {
            let at = numerator(x0, 0.0, &flow);
            let near = numerator(x0, 1e-7, &flow);
            assert!((at - near).norm() < 1e-5, "{x0}: {at} {near}");
            let q0 = first_order_numerator(x0, 0.0, flow.beta2);
            let q = first_order_numerator(x0, 1e-7, flow.beta2);
            assert!((q0 - q).abs() < 1e-6);
        }
    }
}
