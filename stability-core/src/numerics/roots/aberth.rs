//! Polishing roots that the factorization did not settle: the
//! Aberth–Ehrlich simultaneous iteration with compensated residuals (step 5
//! of the module documentation).

use super::horner::{comp_horner, derivative, residual};
use num_complex::Complex64;

/// The largest relative Newton correction |P(zᵢ)/P′(zᵢ)|/|zᵢ| of a root set,
/// with the compensated P: ~κε² at converged simple roots, large where an
/// approximation has the wrong structure (say, two reals for a close
/// complex pair). An exact zero residual counts as converged.
pub(super) fn correction(c: &[f64; 5], x: &[Complex64; 4]) -> f64 {
    x.iter()
        .map(|&z| {
            let p = comp_horner(c, z);
            if p == Complex64::new(0.0, 0.0) {
                return 0.0;
            }
            let w = (p / derivative(c, z)).norm() / z.norm().max(f64::MIN_POSITIVE);
            if w.is_finite() { w } else { f64::INFINITY }
        })
        .fold(0.0, f64::max)
}

/// Polish roots that are not settled (ill-conditioned, or with residuals
/// above rounding) by the Aberth–Ehrlich
/// iteration with compensated residuals: first keeping their structure
/// (reals real, pairs conjugate); if that does not converge (rounding may
/// have turned two close reals into a pair, or a close pair into two equal
/// reals), without constraints from slightly perturbed starting points,
/// symmetrized at the end; and if that fails too, from a circle. The result
/// with the smallest Newton correction wins.
pub(super) fn polish(x: &mut [Complex64; 4], c: &[f64; 5]) {
    let converged = |w: f64| w <= 1e-14;
    let (mut best, _) = aberth(*x, c, 64);
    let mut best_w = correction(c, &best);
    if converged(best_w) {
        *x = best;
        return;
    }
    let start: [Complex64; 4] = std::array::from_fn(|k| {
        let z = x[k];
        z + Complex64::from_polar(1e-7 * z.norm().max(f64::MIN_POSITIVE), 0.7 + 1.9 * k as f64)
    });
    let (y, _) = aberth_free(start, c, 200);
    let w = correction(c, &y);
    if w < best_w {
        best = y;
        best_w = w;
    }
    if best_w > 1e-10 {
        // The factorization failed: start from a circle (after Bini 1996:
        // radius from the coefficients, angles off the axes).
        let r = (c[4].abs() / c[0].abs())
            .sqrt()
            .sqrt()
            .max(f64::MIN_POSITIVE);
        let start = std::array::from_fn(|k| {
            Complex64::from_polar(r, 0.4 + std::f64::consts::FRAC_PI_2 * k as f64)
        });
        let (y, _) = aberth_free(start, c, 500);
        if correction(c, &y) < best_w {
            best = y;
        }
    }
    *x = best;
}

/// The partner of each root: its own conjugate's index (matched one to
/// one), or itself if real.
pub(super) fn partners(x: &[Complex64; 4]) -> [usize; 4] {
    let mut partner = [0, 1, 2, 3];
    let mut taken = [false; 4];
    for i in 0..4 {
        if x[i].im > 0.0
            && !taken[i]
            && let Some(j) = (0..4).find(|&j| !taken[j] && j != i && x[j] == x[i].conj())
        {
            partner[i] = j;
            partner[j] = i;
            taken[i] = true;
            taken[j] = true;
        }
    }
    partner
}

/// One Aberth–Ehrlich correction of root i:
/// zᵢ − wᵢ/(1 − wᵢ Σⱼ≠ᵢ 1/(zᵢ − zⱼ)), wᵢ = P(zᵢ)/P′(zᵢ), compensated P.
pub(super) fn aberth_step(c: &[f64; 5], z: &[Complex64; 4], i: usize) -> Option<Complex64> {
    let dp = derivative(c, z[i]);
    if dp == Complex64::new(0.0, 0.0) {
        return None;
    }
    let w = comp_horner(c, z[i]) / dp;
    let mut repulsion = Complex64::new(0.0, 0.0);
    for j in 0..4 {
        if j != i && z[j] != z[i] {
            repulsion += (z[i] - z[j]).inv();
        }
    }
    let zi = z[i] - w / (Complex64::new(1.0, 0.0) - w * repulsion);
    (zi.re.is_finite() && zi.im.is_finite()).then_some(zi)
}

/// The Aberth–Ehrlich iteration (O. Aberth, Math. Comp. 27, 1973;
/// L.W. Ehrlich, Comm. ACM 10, 1967) with compensated residuals, keeping
/// real roots real and conjugate pairs exact conjugates; returns the iterate
/// with the smallest residual, and that residual.
pub(super) fn aberth(x: [Complex64; 4], c: &[f64; 5], iterations: usize) -> ([Complex64; 4], f64) {
    let partner = partners(&x);
    let mut best = x;
    let mut best_res = residual(c, &x, true);
    let mut z = x;
    for _ in 0..iterations {
        let mut next = z;
        for i in 0..4 {
            if partner[i] != i && z[i].im < 0.0 {
                continue; // the conjugate follows its partner
            }
            if let Some(mut zi) = aberth_step(c, &z, i) {
                if partner[i] == i {
                    zi.im = 0.0;
                }
                next[i] = zi;
                next[partner[i]] = zi.conj();
            }
        }
        z = next;
        let res = residual(c, &z, true);
        if res < best_res {
            best = z;
            best_res = res;
        } else if res >= 1e6 * best_res {
            break; // diverging
        }
        if best_res <= f64::EPSILON * f64::EPSILON {
            break;
        }
    }
    (best, best_res)
}

/// The Aberth–Ehrlich iteration without constraints (from a circle), then
/// conjugate pairs made exact and near-real roots real.
pub(super) fn aberth_free(
    x: [Complex64; 4],
    c: &[f64; 5],
    iterations: usize,
) -> ([Complex64; 4], f64) {
    let mut z = x;
    for _ in 0..iterations {
        let mut moved = 0.0f64;
        for i in 0..4 {
            if let Some(zi) = aberth_step(c, &z, i) {
                moved = moved.max((zi - z[i]).norm() / zi.norm().max(f64::MIN_POSITIVE));
                z[i] = zi;
            }
        }
        if moved <= 4.0 * f64::EPSILON {
            break;
        }
    }
    // Symmetrize: pair each upper root with its nearest lower one.
    let mut out = z;
    let mut used = [false; 4];
    for i in 0..4 {
        if used[i] {
            continue;
        }
        used[i] = true;
        if out[i].im.abs() <= 1e-10 * out[i].norm() {
            out[i].im = 0.0;
            continue;
        }
        let j = (0..4).filter(|&j| !used[j]).min_by(|&p, &q| {
            (out[p] - out[i].conj())
                .norm()
                .total_cmp(&(out[q] - out[i].conj()).norm())
        });
        if let Some(j) = j {
            used[j] = true;
            let m = Complex64::new(
                (out[i].re + out[j].re) / 2.0,
                (out[i].im.abs() + out[j].im.abs()) / 2.0,
            );
            out[i] = m;
            out[j] = m.conj();
        }
    }
    let res = residual(c, &out, true);
    (out, res)
}
