//! Evaluating the quartic: Horner's rule, plain and compensated, and the
//! backward error of a root set.

use num_complex::Complex64;

/// |re| + |im|: a magnitude within a factor √2 of the modulus, without the
/// cost of `hypot`.
#[inline]
pub(super) fn l1(z: Complex64) -> f64 {
    z.re.abs() + z.im.abs()
}

/// Error-free product: a·b = p + e exactly (Dekker; with an FMA).
#[inline]
pub(super) fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

/// Error-free sum: a + b = s + e exactly (Knuth's TwoSum).
#[inline]
pub(super) fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// P(z) for P = c₀x⁴ + c₁x³ + c₂x² + c₃x + c₄ by the compensated Horner
/// scheme in complex arithmetic with real coefficients (Graillat &
/// Ménissier-Morain 2012): the rounding errors of every product and sum are
/// captured exactly and summed into a correction polynomial.
#[inline]
pub(super) fn comp_horner(c: &[f64; 5], z: Complex64) -> Complex64 {
    let (xr, xi) = (z.re, z.im);
    let (mut sr, mut si) = (c[0], 0.0);
    let (mut cr, mut ci) = (0.0, 0.0);
    for &coef in &c[1..] {
        let (t1, e1) = two_prod(sr, xr);
        let (t2, e2) = two_prod(si, xi);
        let (pr, e3) = two_sum(t1, -t2);
        let (t3, e4) = two_prod(sr, xi);
        let (t4, e5) = two_prod(si, xr);
        let (pi, e6) = two_sum(t3, t4);
        let (nr, e7) = two_sum(pr, coef);
        let (er, ei) = (e1 - e2 + e3 + e7, e4 + e5 + e6);
        // correction: c ← c·z + err
        let ncr = cr * xr - ci * xi + er;
        let nci = cr * xi + ci * xr + ei;
        (cr, ci) = (ncr, nci);
        (sr, si) = (nr, pi);
    }
    Complex64::new(sr + cr, si + ci)
}

/// P′(z), by Horner's rule.
#[inline]
pub(super) fn derivative(c: &[f64; 5], z: Complex64) -> Complex64 {
    ((z * (4.0 * c[0]) + 3.0 * c[1]) * z + 2.0 * c[2]) * z + c[3]
}

/// Σ|cₖ||z|^(4−k): the scale of P's rounding error at z (|z| as |re| + |im|).
#[inline]
pub(super) fn abs_sum(c: &[f64; 5], z: Complex64) -> f64 {
    let n = l1(z);
    c.iter().fold(0.0, |acc, ck| acc * n + ck.abs())
}

/// Plain Horner's P(z).
#[inline]
pub(super) fn horner(c: &[f64; 5], z: Complex64) -> Complex64 {
    (((z * c[0] + c[1]) * z + c[2]) * z + c[3]) * z + c[4]
}

/// The largest relative residual |P(zᵢ)|/Σ|cₖ||zᵢ|^(4−k) of a root set
/// (its backward error), by plain or compensated evaluation.
#[inline]
pub(super) fn residual(c: &[f64; 5], x: &[Complex64; 4], compensated: bool) -> f64 {
    x.iter()
        .map(|&z| {
            let p = if compensated {
                comp_horner(c, z)
            } else {
                horner(c, z)
            };
            l1(p) / abs_sum(c, z).max(f64::MIN_POSITIVE)
        })
        .fold(0.0, f64::max)
}

/// The backward error |P(z)|/Σ|cₖ||z|^(4−k) of one root, with moduli (the
/// measure [`super::TOLERANCE`] bounds) and the compensated P.
#[inline]
pub(super) fn backward_error(c: &[f64; 5], z: Complex64) -> f64 {
    let n = z.norm();
    let scale = c.iter().fold(0.0, |acc, ck| acc * n + ck.abs());
    if scale == 0.0 {
        0.0
    } else {
        comp_horner(c, z).norm() / scale
    }
}
