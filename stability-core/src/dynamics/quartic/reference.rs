//! Independent routes to the quartic's coefficients, for cross-checks and
//! benchmarks. None of them uses the symbolic engine.
//!
//! - [`eq6_by_hand`]: eq (6) typed by hand in the report's grouped form,
//!   with the three corrections of `docs/errata.md`; generic over the number
//!   type so that tests can push dual numbers through it.
//! - [`coefficients_by_interpolation`]: the determinant of eq (4) evaluated
//!   numerically at five points and interpolated.

use num_complex::Complex64;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// The arithmetic [`eq6_by_hand`] needs.
pub trait Scalar:
    Copy
    + From<f64>
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
}
impl<T> Scalar for T where
    T: Copy
        + From<f64>
        + Add<Output = T>
        + Sub<Output = T>
        + Mul<Output = T>
        + Div<Output = T>
        + Neg<Output = T>
{
}

/// Eq (6) by hand, corrected: `[A, B, C, D, E]` from the inputs in the order
/// `x_u x_w x_wdot x_q z_u z_w z_wdot z_q m_u m_w m_wdot m_q c_l mu1 i_b`.
///
/// The report's grouped form, with B's `+z_w` → `−z_w` and `−z_w x_ẇ/μ₁` →
/// `−z_u x_ẇ/μ₁`, and D's `x_q m_w/(i_B μ₁)` → `x_q m_w/i_B`.
#[inline]
pub fn eq6_by_hand<T: Scalar>(v: &[T; 15]) -> [T; 5] {
    let [
        x_u,
        x_w,
        x_wd,
        x_q,
        z_u,
        z_w,
        z_wd,
        z_q,
        m_u,
        m_w,
        m_wd,
        m_q,
        c_l,
        mu1,
        i_b,
    ] = *v;
    let one = T::from(1.0);
    let zwd_mu = z_wd / mu1 - one; // (z_ẇ/μ₁ − 1)
    let zq_mu = z_q / mu1 + one; // (z_q/μ₁ + 1)
    let mq_ib = m_q / i_b;
    let a = one - z_wd / mu1;
    let b = -z_w + zwd_mu * (x_u + mq_ib) - zq_mu * m_wd / i_b - z_u * x_wd / mu1;
    let c = z_w * (x_u + mq_ib)
        + zwd_mu * (x_q / i_b * m_u - x_u * mq_ib)
        + zq_mu * (m_wd / i_b * x_u - mu1 * m_w / i_b - x_wd / i_b * m_u)
        + z_u * (x_wd / mu1 * mq_ib - x_w - m_wd / i_b * x_q / mu1);
    let d = z_w * (x_q / i_b * m_u - x_u * mq_ib)
        + zwd_mu * (-(c_l * mu1 * m_u / i_b))
        + zq_mu * (x_u * mu1 * m_w / i_b - x_w * mu1 * m_u / i_b)
        + z_u * (m_wd / i_b * c_l + mq_ib * x_w - x_q / i_b * m_w);
    let e = mu1 / i_b * c_l * (m_w * z_u - z_w * m_u);
    [a, b, c, d, e]
}

/// The matrix of eq (4) at λ, for the inputs in [`eq6_by_hand`]'s order.
pub fn eq4_matrix(v: &[f64; 15], lam: Complex64) -> [[Complex64; 3]; 3] {
    let [
        x_u,
        x_w,
        x_wd,
        x_q,
        z_u,
        z_w,
        z_wd,
        z_q,
        m_u,
        m_w,
        m_wd,
        m_q,
        c_l,
        mu1,
        i_b,
    ] = *v;
    let c = |x: f64| Complex64::new(x, 0.0);
    [
        [
            lam - x_u,
            -(c(x_w) + lam * (x_wd / mu1)),
            c(c_l) - lam * (x_q / mu1),
        ],
        [
            c(-z_u),
            -(c(z_w) + lam * (z_wd / mu1 - 1.0)),
            -(lam * (z_q / mu1 + 1.0)),
        ],
        [
            c(-mu1 / i_b * m_u),
            -(c(mu1 / i_b * m_w) + lam * (m_wd / i_b)),
            lam * lam - lam * (m_q / i_b),
        ],
    ]
}

/// A 3×3 complex determinant (rule of Sarrus) and the sum of the moduli of
/// its six products (the scale of its rounding error).
pub fn det3(m: &[[Complex64; 3]; 3]) -> (Complex64, f64) {
    let p = [
        m[0][0] * m[1][1] * m[2][2],
        m[0][1] * m[1][2] * m[2][0],
        m[0][2] * m[1][0] * m[2][1],
        m[0][2] * m[1][1] * m[2][0],
        m[0][0] * m[1][2] * m[2][1],
        m[0][1] * m[1][0] * m[2][2],
    ];
    let det = p[0] + p[1] + p[2] - p[3] - p[4] - p[5];
    (det, p.iter().map(|z| z.norm()).sum())
}

/// `[A, B, C, D, E]` by evaluating the determinant of eq (4) at the five
/// points λₖ = r·e^{2πik/5} and inverting the discrete Fourier transform:
/// `cₙ = (1/5) Σₖ det(λₖ) e^{−2πikn/5} / rⁿ`. Exact for a polynomial of
/// degree ≤ 4 up to rounding; the second array bounds that rounding error
/// (a few ε times the size of the products summed, per coefficient).
///
/// `r` should be near the roots' scale; [`natural_radius`] gives one.
pub fn coefficients_by_interpolation(v: &[f64; 15], r: f64) -> ([f64; 5], [f64; 5]) {
    let mut vals = [Complex64::new(0.0, 0.0); 5];
    let mut scale = 0.0;
    for (k, val) in vals.iter_mut().enumerate() {
        let w = Complex64::from_polar(1.0, 2.0 * std::f64::consts::PI * k as f64 / 5.0);
        let (d, s) = det3(&eq4_matrix(v, w * r));
        *val = d;
        scale += s;
    }
    let mut coef = [0.0; 5];
    let mut bound = [0.0; 5];
    for n in 0..5 {
        let mut acc = Complex64::new(0.0, 0.0);
        for (k, val) in vals.iter().enumerate() {
            let w = Complex64::from_polar(1.0, -2.0 * std::f64::consts::PI * (k * n) as f64 / 5.0);
            acc += val * w;
        }
        let rn = r.powi(n as i32);
        // power n of λ is the coefficient index 4 − n in [A..E]
        coef[4 - n] = acc.re / 5.0 / rn;
        bound[4 - n] = 64.0 * f64::EPSILON * scale / 5.0 / rn;
    }
    (coef, bound)
}

/// A radius for [`coefficients_by_interpolation`]: the geometric mean of the
/// magnitudes that the diagonal entries of eq (4) suggest, at least 1.
pub fn natural_radius(v: &[f64; 15]) -> f64 {
    let [x_u, _, _, _, _, z_w, _, _, _, m_w, _, m_q, _, mu1, i_b] = *v;
    let s1 = (x_u.abs() + z_w.abs() + (m_q / i_b).abs()).max(1.0);
    let s2 = (mu1 / i_b * m_w).abs().sqrt().max(1.0);
    (s1 * s2).sqrt().max(1.0)
}

/// A dual number a + bε with ε² = 0: pushing one through [`eq6_by_hand`]
/// gives a coefficient and its derivative along the seeded direction
/// (forward-mode differentiation), independently of the symbolic engine.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dual(pub f64, pub f64);

impl From<f64> for Dual {
    fn from(x: f64) -> Self {
        Dual(x, 0.0)
    }
}

impl Add for Dual {
    type Output = Dual;
    fn add(self, o: Dual) -> Dual {
        Dual(self.0 + o.0, self.1 + o.1)
    }
}

impl Sub for Dual {
    type Output = Dual;
    fn sub(self, o: Dual) -> Dual {
        Dual(self.0 - o.0, self.1 - o.1)
    }
}

impl Mul for Dual {
    type Output = Dual;
    fn mul(self, o: Dual) -> Dual {
        Dual(self.0 * o.0, self.0 * o.1 + self.1 * o.0)
    }
}

impl Div for Dual {
    type Output = Dual;
    fn div(self, o: Dual) -> Dual {
        Dual(self.0 / o.0, (self.1 * o.0 - self.0 * o.1) / (o.0 * o.0))
    }
}

impl Neg for Dual {
    type Output = Dual;
    fn neg(self) -> Dual {
        Dual(-self.0, -self.1)
    }
}

/// The gradient of [`eq6_by_hand`] by fifteen dual-number passes: row `i`
/// is ∂[A..E]/∂(input `i`).
pub fn gradient_by_dual_numbers(v: &[f64; 15]) -> [[f64; 5]; 15] {
    std::array::from_fn(|i| {
        let seeded: [Dual; 15] =
            std::array::from_fn(|j| Dual(v[j], if i == j { 1.0 } else { 0.0 }));
        eq6_by_hand(&seeded).map(|d| d.1)
    })
}
