//! The quartic at any finite scale, when one scaling λ = 2^σ·x cannot
//! bring every coefficient into range (roots of widely different sizes,
//! e.g. 1e160 beside 7 and 0.1, or coefficients beyond 1e308 / 1e-308):
//! the Aberth–Ehrlich iteration on the given coefficients, started from the
//! Newton polygon, with P evaluated at each iterate on its own scale.
//!
//! After D.A. Bini, "Numerical computation of polynomial zeros by means of
//! Aberth's method", Numer. Algorithms 13, 1996: the upper convex hull of
//! the points (i, log|aᵢ|) (aᵢ the coefficient of λⁱ) groups the roots by
//! size — an edge from i to j holds j − i roots of modulus about
//! (|aᵢ|/|aⱼ|)^(1/(j−i)) — and the iteration starts from circles of those
//! radii. Where P(z) is evaluated, z = 2^k·x with |x| ~ 1 and every term
//! cₘzᵐ is scaled by one common power of two, so that no term overflows and
//! the ones that matter do not underflow; P/P′ comes back as 2^k times the
//! scaled quotient. Limits: a root whose modulus is beyond f64's range is
//! an error ([`RootsError::Overflow`], [`RootsError::Underflow`]); the
//! evaluation is plain Horner (not compensated), so a root is as accurate
//! as its condition allows in working precision.

use super::binary::{cdiv, exponent, ldexp, ldexp_c, log2_abs};
use super::{RootsError, TOLERANCE};
use num_complex::Complex64;

/// P(z) of P = Σ cₘ z^(4−m) on a common scale: z = 2^k·x, every term
/// divided by 2^M (M the largest term's exponent).
struct Scaled {
    /// 2^−M·P(z).
    p: Complex64,
    /// 2^−M·dP/dx = 2^(k−M)·P′(z).
    dp: Complex64,
    /// 2^−M·Σ|cₘ||z|^(4−m).
    abs: f64,
    k: i32,
}

fn eval(c: &[f64; 5], z: Complex64) -> Scaled {
    let big = z.re.abs().max(z.im.abs());
    let k = if big == 0.0 { 0 } else { exponent(big) };
    let x = ldexp_c(z, -k);
    let top = (0..5)
        .filter(|&m| c[m] != 0.0)
        .map(|m| exponent(c[m]) + k * (4 - m as i32))
        .max()
        .unwrap_or(0);
    let s: [f64; 5] = std::array::from_fn(|m| ldexp(c[m], k * (4 - m as i32) - top));
    let n = x.norm();
    let (mut p, mut dp, mut abs) = (
        Complex64::new(s[0], 0.0),
        Complex64::new(0.0, 0.0),
        s[0].abs(),
    );
    for &sm in &s[1..] {
        dp = dp * x + p;
        p = p * x + sm;
        abs = abs * n + sm.abs();
    }
    Scaled { p, dp, abs, k }
}

/// The backward error |P(z)|/Σ|cₘ||z|^(4−m) of z, at any scale.
pub(super) fn backward_error(c: &[f64; 5], z: Complex64) -> f64 {
    if z == Complex64::new(0.0, 0.0) {
        // P(0) = E, Σ|cₖ||0|^(4−k) = |E|
        return if c[4] == 0.0 { 0.0 } else { 1.0 };
    }
    let e = eval(c, z);
    if e.abs == 0.0 {
        return 0.0;
    }
    e.p.norm() / e.abs
}

/// The Newton polygon's starting points for the roots of the non-zero
/// part c[0..=last] (c[last] ≠ 0), or the error if a group of roots lies
/// beyond f64's range.
fn starts(c: &[f64; 5], last: usize) -> Result<[Complex64; 4], RootsError> {
    // points (i, log₂|aᵢ|), aᵢ = c[last − i], i = 0 … last; their upper
    // convex hull by the monotone chain, held inline
    let mut hull = [(0usize, 0.0f64); 5];
    let mut len = 0;
    for i in (0..=last).filter(|&i| c[last - i] != 0.0) {
        let p = (i, log2_abs(c[last - i]));
        while len >= 2 {
            let (a, b) = (hull[len - 2], hull[len - 1]);
            let cross = (b.0 - a.0) as f64 * (p.1 - a.1) - (b.1 - a.1) * (p.0 - a.0) as f64;
            if cross < 0.0 {
                break;
            }
            len -= 1;
        }
        hull[len] = p;
        len += 1;
    }
    let hull = &hull[..len];
    let mut out = [Complex64::new(0.0, 0.0); 4];
    let mut slot = 0;
    for (edge, w) in hull.windows(2).enumerate() {
        let (i, j) = (w[0].0, w[1].0);
        let n = j - i;
        let log_r = (w[0].1 - w[1].1) / n as f64;
        if log_r > 1024.0 {
            return Err(RootsError::Overflow {
                log2_modulus: log_r.round() as i32,
            });
        }
        if log_r < -1074.0 {
            return Err(RootsError::Underflow {
                log2_modulus: log_r.round() as i32,
            });
        }
        let whole = log_r.floor();
        for m in 0..n {
            let angle = std::f64::consts::TAU * (m as f64 / n as f64 + edge as f64 / 4.0) + 0.4;
            out[slot] = ldexp_c(
                Complex64::from_polar((log_r - whole).exp2(), angle),
                whole as i32,
            );
            slot += 1;
        }
    }
    Ok(out)
}

/// One Aberth–Ehrlich step of root i, zᵢ − wᵢ/(1 − wᵢΣⱼ≠ᵢ 1/(zᵢ − zⱼ))
/// with wᵢ = P(zᵢ)/P′(zᵢ), formed in units of zᵢ's own scale 2^k (roots
/// far larger than zᵢ contribute nothing there, as they should), and
/// halved while it would leave f64's range. Returns the new iterate and
/// the step's size relative to it; `None` at an exact zero of P.
fn aberth_step(c: &[f64; 5], z: &[Complex64; 4], i: usize) -> Option<(Complex64, f64)> {
    let e = eval(c, z[i]);
    if e.p == Complex64::new(0.0, 0.0) {
        return None;
    }
    let one = Complex64::new(1.0, 0.0);
    let w = cdiv(e.p, e.dp);
    let x = ldexp_c(z[i], -e.k);
    let mut repulsion = Complex64::new(0.0, 0.0);
    for (j, zj) in z.iter().enumerate() {
        let y = ldexp_c(*zj, -e.k);
        if j != i && *zj != z[i] && y.re.is_finite() && y.im.is_finite() {
            repulsion += cdiv(one, x - y);
        }
    }
    let mut step = cdiv(w, one - w * repulsion);
    if !(step.re.is_finite() && step.im.is_finite()) {
        return None;
    }
    for _ in 0..64 {
        let next = x - step;
        let z_next = ldexp_c(next, e.k);
        if z_next.re.is_finite() && z_next.im.is_finite() {
            let size = next.re.abs().max(next.im.abs()).max(f64::MIN_POSITIVE);
            return Some((z_next, (step.re.abs() + step.im.abs()) / size));
        }
        step *= 0.5;
    }
    None
}

/// Conjugate pairs made exact, near-real roots real (an odd one out, the
/// nearest to the axis, too).
fn symmetrize(z: &mut [Complex64; 4]) {
    let mut used = [false; 4];
    let near_real = |w: Complex64| w.im.abs() <= 1e-10 * w.re.abs().max(w.im.abs());
    for i in 0..4 {
        if used[i] {
            continue;
        }
        used[i] = true;
        if near_real(z[i]) {
            z[i].im = 0.0;
            continue;
        }
        let conj = z[i].conj();
        let j = (0..4)
            .filter(|&j| !used[j] && !near_real(z[j]))
            .min_by(|&p, &q| (z[p] - conj).norm().total_cmp(&(z[q] - conj).norm()));
        match j {
            Some(j) => {
                used[j] = true;
                let m = Complex64::new(
                    (z[i].re + z[j].re) / 2.0,
                    (z[i].im.abs() + z[j].im.abs()) / 2.0,
                );
                z[i] = m;
                z[j] = m.conj();
            }
            None => z[i].im = 0.0,
        }
    }
}

/// Newton's method on one root until each of its parts settles (relative
/// to itself, not to |z|): a real part far smaller than the imaginary one
/// — a lightly damped mode, r = 1e-249 beside s = 1e-124 — is set by the
/// imaginary part of P, which the scaled evaluation keeps accurate, while
/// Aberth's normwise stop does not see it. Each step is kept only if the
/// backward error does not grow.
fn newton_parts(c: &[f64; 5], mut z: Complex64) -> Complex64 {
    let mut err = backward_error(c, z);
    for _ in 0..8 {
        let e = eval(c, z);
        if e.p == Complex64::new(0.0, 0.0) || e.dp == Complex64::new(0.0, 0.0) {
            break;
        }
        let step = ldexp_c(cdiv(e.p, e.dp), e.k);
        let mut next = z - step;
        if z.im == 0.0 {
            next.im = 0.0;
        }
        let next_err = backward_error(c, next);
        let better = next_err <= err && next.re.is_finite() && next.im.is_finite();
        if !better {
            break;
        }
        let settled = step.re.abs() <= 4.0 * f64::EPSILON * next.re.abs()
            && step.im.abs() <= 4.0 * f64::EPSILON * next.im.abs();
        z = next;
        err = next_err;
        if settled {
            break;
        }
    }
    z
}

/// All four roots of the quartic `c` (finite, c[0] ≠ 0), at any scale.
pub(super) fn roots(c: &[f64; 5]) -> Result<[Complex64; 4], RootsError> {
    // exact zero roots: trailing zero coefficients
    let last = (0..5).rev().find(|&m| c[m] != 0.0).unwrap_or(0);
    let mut z = starts(c, last)?;
    let free = last; // roots 0..last are iterated, the rest are exactly 0
    for _ in 0..500 {
        let mut moved = 0.0f64;
        for i in 0..free {
            if let Some((next, step)) = aberth_step(c, &z, i) {
                moved = moved.max(step);
                z[i] = next;
            }
        }
        if moved <= 4.0 * f64::EPSILON {
            break;
        }
    }
    symmetrize(&mut z);
    for i in 0..free {
        let old = z[i];
        if old.im < 0.0 {
            continue; // follows its partner
        }
        let new = newton_parts(c, old);
        z[i] = new;
        if old.im > 0.0
            && let Some(j) = (0..free).find(|&j| z[j] == old.conj())
        {
            z[j] = new.conj();
        }
    }
    for root in z {
        if !(root.re.is_finite() && root.im.is_finite()) {
            return Err(RootsError::Overflow { log2_modulus: 1024 });
        }
        let backward_error = backward_error(c, root);
        let accurate = backward_error <= TOLERANCE;
        let size = root.re.abs().max(root.im.abs());
        if !accurate && size > 0.0 && size < f64::MIN_POSITIVE {
            // a subnormal root, with too few bits left to meet the check
            return Err(RootsError::Underflow {
                log2_modulus: exponent(size),
            });
        }
        if !accurate {
            return Err(RootsError::Inaccurate {
                root,
                backward_error,
            });
        }
    }
    Ok(z)
}
