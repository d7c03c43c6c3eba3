//! All four roots of a real quartic, accurately and without allocation.
//!
//! The method follows the plan of A.G. Orellana and C. De Michele,
//! "Algorithm 1010: Boosting efficiency in solving quartic equations with no
//! compromise in accuracy", ACM TOMS 46(2), 2020: factor the monic quartic
//! into two real quadratics, `(x² + αx + β)(x² + γx + δ)`, from a root of a
//! resolvent cubic, then refine the factorization by Newton's method on the
//! four Vieta equations until its backward error stops decreasing; the
//! roots are those of the two quadratics, by the cancellation-free formulas.
//! (Written from the description in the paper and in the classical
//! literature — Ferrari's resolvent; Newton on the factorization as in
//! Strobach, J. Comput. Appl. Math. 234, 2010 — not from any code.)
//!
//! Details:
//! 1. The coefficients are divided by A and λ is scaled by
//!    s = max |cₖ/A|^(1/k), so that the scaled quartic has coefficients of
//!    order one; roots are scaled back at the end.
//! 2. Ferrari: x⁴ + ax³ + bx² + cx + d = (x² + ax/2 + y/2)² − (px + q)²
//!    when y is a root of the resolvent y³ − by² + (ac − 4d)y + (4bd − a²d − c²) = 0,
//!    with p² = a²/4 + y − b, q² = y²/4 − d, pq = ay/4 − c/2. The largest
//!    real root y is taken (it makes p² and q² non-negative): by Cardano's
//!    formula when it is the only real root, else by Halley's iteration
//!    from above — from y = b when that is above it (y = β + δ = b − αγ, so
//!    b is close when a factor's linear coefficient is small, as for a
//!    lightly damped mode), else from the bound 2√(−p/3) of the depressed
//!    cubic.
//! 3. Of β and δ the larger in magnitude is kept and the other is d/(it),
//!    and α, γ are re-solved from the linear pair α + γ = a,
//!    αδ + βγ = c when that is better conditioned (as in Algorithm 1010).
//! 4. Newton on F(α, β, γ, δ) = (α+γ−a, β+δ+αγ−b, αδ+βγ−c, βδ−d), at most
//!    16 steps, stopping when the relative backward error no longer falls.
//! 5. When a root is ill-conditioned (condition number κ > 16, e.g. one of
//!    a cluster) or its residual exceeds 8ε·Σ|cₖ||λ|ᵏ (the factorization was
//!    inaccurate, as for some biquadratics), all four are polished by the Aberth–Ehrlich simultaneous
//!    iteration on the given (unrounded) coefficients, with P(λ) evaluated
//!    by the compensated Horner scheme (S. Graillat,
//!    N. Louvet, Ph. Langlois, "Compensated Horner scheme", 2005; in
//!    complex arithmetic after S. Graillat and V. Ménissier-Morain, Inf.
//!    Comput. 216, 2012): P is then evaluated as if in twice the working
//!    precision, and the iteration converges to the roots of the given
//!    coefficients with a relative error of about ε + κε² instead of κε (as
//!    for Newton's method in Graillat,
//!    "Accurate simple zeros of polynomials in floating point arithmetic",
//!    Comput. Math. Appl. 56, 2008).
//!
//! Complex roots come in exact conjugate pairs (each is a quadratic's);
//! real roots have an imaginary part of exactly 0.
//!
//! # Multiple roots
//! A root of multiplicity m is ill-conditioned: a perturbation ε of the
//! coefficients moves it by ~ε^(1/m). Without the compensated polish a
//! double root comes back to ~1e-8 relative and a quadruple one such as
//! (λ − 1000)⁴ to ~1e-4; the polish improves on that where Newton's
//! (linear) convergence allows, but a multiple root is returned as a tight
//! cluster (possibly as a pair with a tiny imaginary part), never exactly.
//! The results are always finite.

pub use num_complex::Complex64;

/// Why a quartic has no roots to report.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum RootsError {
    /// A = 0: the polynomial is not a quartic.
    #[error("the leading coefficient A is zero: not a quartic (solve the cubic instead)")]
    LeadingZero,
    /// A coefficient is NaN or infinite.
    #[error("coefficient {0} is not a finite number")]
    NonFinite(&'static str),
    /// The roots' scale overflows f64.
    #[error("the roots are too large to represent (coefficient ratios overflow f64)")]
    Overflow,
}

const NAMES: [&str; 5] = ["A", "B", "C", "D", "E"];

/// The four roots of `A λ⁴ + B λ³ + C λ² + D λ + E` with `coeffs = [A, B, C, D, E]`.
///
/// Order: by descending modulus; a complex pair is adjacent, the root with
/// positive imaginary part first; real roots have `im == 0.0`.
pub fn solve_quartic(coeffs: [f64; 5]) -> Result<[Complex64; 4], RootsError> {
    for (c, name) in coeffs.iter().zip(NAMES) {
        if !c.is_finite() {
            return Err(RootsError::NonFinite(name));
        }
    }
    let [a0, b0, c0, d0, e0] = coeffs;
    if a0 == 0.0 {
        return Err(RootsError::LeadingZero);
    }
    // Monic, then scaled: λ = s·x.
    let m = [b0 / a0, c0 / a0, d0 / a0, e0 / a0];
    if m.iter().any(|v| !v.is_finite()) {
        return Err(RootsError::Overflow);
    }
    if m.iter().all(|&v| v == 0.0) {
        return Ok([Complex64::new(0.0, 0.0); 4]);
    }
    // Scale by the power of two nearest max |mₖ|^(1/k) (from the binary
    // exponents; exact).
    let s = scale_exponent(&m);
    let (a, b, c, d) = (
        m[0] / s,
        m[1] / (s * s),
        m[2] / (s * s * s),
        m[3] / (s * s * s * s),
    );
    // The given quartic scaled by powers of two (exactly): s⁻⁴-scaled P(s·x).
    let scaled = [
        a0,
        b0 / s,
        c0 / (s * s),
        d0 / (s * s * s),
        e0 / (s * s * s * s),
    ];
    let exact = if scaled.iter().all(|v| v.is_finite()) {
        scaled
    } else {
        [1.0, a, b, c, d]
    };
    let (mut x, settled) = factored_roots(a, b, c, d, &exact);
    if !settled {
        polish(&mut x, &exact);
    }
    let mut roots = x.map(|z| z * s);
    if roots
        .iter()
        .any(|z| !(z.re.is_finite() && z.im.is_finite()))
    {
        return Err(RootsError::Overflow);
    }
    sort_roots(&mut roots);
    Ok(roots)
}

/// 2^e with e = max over k of ⌊exponent(|mₖ|)/(k + 1)⌉: within a factor ~2
/// of max |mₖ|^(1/(k+1)), from the binary exponents alone (no libm).
fn scale_exponent(m: &[f64; 4]) -> f64 {
    let mut e = i32::MIN;
    for (k, &v) in m.iter().enumerate() {
        if v != 0.0 {
            // v is finite and non-zero: its binary exponent (subnormals: −1023)
            let ex = ((v.to_bits() >> 52) & 0x7ff) as i32 - 1023;
            let n = k as i32 + 1;
            e = e.max((ex + n / 2).div_euclid(n));
        }
    }
    f64::from_bits(((e.clamp(-1022, 1023) + 1023) as u64) << 52)
}

/// |re| + |im|: a magnitude within a factor √2 of the modulus, without the
/// cost of `hypot`.
#[inline]
fn l1(z: Complex64) -> f64 {
    z.re.abs() + z.im.abs()
}

/// Error-free product: a·b = p + e exactly (Dekker; with an FMA).
#[inline]
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

/// Error-free sum: a + b = s + e exactly (Knuth's TwoSum).
#[inline]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// P(z) for P = c₀x⁴ + c₁x³ + c₂x² + c₃x + c₄ by the compensated Horner
/// scheme in complex arithmetic with real coefficients (Graillat &
/// Ménissier-Morain 2012): the rounding errors of every product and sum are
/// captured exactly and summed into a correction polynomial.
fn comp_horner(c: &[f64; 5], z: Complex64) -> Complex64 {
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
fn derivative(c: &[f64; 5], z: Complex64) -> Complex64 {
    ((z * (4.0 * c[0]) + 3.0 * c[1]) * z + 2.0 * c[2]) * z + c[3]
}

/// Σ|cₖ||z|^(4−k): the scale of P's rounding error at z (|z| as |re| + |im|).
fn abs_sum(c: &[f64; 5], z: Complex64) -> f64 {
    let n = l1(z);
    c.iter().fold(0.0, |acc, ck| acc * n + ck.abs())
}

/// Plain Horner's P(z).
fn horner(c: &[f64; 5], z: Complex64) -> Complex64 {
    (((z * c[0] + c[1]) * z + c[2]) * z + c[3]) * z + c[4]
}

/// The largest relative residual |P(zᵢ)|/Σ|cₖ||zᵢ|^(4−k) of a root set
/// (its backward error), by plain or compensated evaluation.
fn residual(c: &[f64; 5], x: &[Complex64; 4], compensated: bool) -> f64 {
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

/// The roots of the factorization from each real root of the resolvent,
/// raw and repaired, each refined by Newton's method; the set with the
/// smallest residual wins. The first candidate (the largest resolvent root,
/// raw then repaired) usually settles it.
fn factored_roots(a: f64, b: f64, c: f64, d: f64, exact: &[f64; 5]) -> ([Complex64; 4], bool) {
    let m = Monic::new(a, b, c, d);
    // Ferrari's resolvent: y³ − b y² + (ac − 4d) y + (4bd − a²d − c²) = 0.
    let (e2, e1, e0) = (-b, a * c - 4.0 * d, 4.0 * b * d - a * a * d - c * c);
    let mut best = ([Complex64::new(0.0, 0.0); 4], f64::INFINITY);
    let try_root = |y: f64, best: &mut ([Complex64; 4], f64)| {
        let raw = from_resolvent(y, &m);
        for pass in 0..2 {
            let f = if pass == 0 { raw } else { repair(raw, &m) };
            let (al, be, ga, de) = newton_factor(f, &m);
            let q1 = quadratic(al, be);
            let q2 = quadratic(ga, de);
            let (c1, c2) = (check_pair(exact, q1), check_pair(exact, q2));
            let res = c1.residual().max(c2.residual());
            if res < best.1 {
                *best = ([q1.0, q1.1, q2.0, q2.1], res);
                if c1.settled() && c2.settled() {
                    return true;
                }
            }
        }
        false
    };
    // The largest root first: it usually settles everything.
    if try_root(largest_cubic_root(e2, e1, e0), &mut best) {
        return (best.0, true);
    }
    let (ys, n) = real_cubic_roots(e2, e1, e0);
    for &y in &ys[..n] {
        if try_root(y, &mut best) {
            return (best.0, true);
        }
    }
    (best.0, false)
}

/// The residual of a quadratic's roots, |P(z)| against its rounding scale
/// Σ|cₖ||z|^(4−k), and their condition number κ = Σ|cₖ||z|^(4−k)/(|z||P′(z)|)
/// as a ratio, divided only when asked for (the usual case is settled by
/// comparisons alone).
#[derive(Clone, Copy)]
struct PairCheck {
    /// The larger |P(z)| / Σ|cₖ||z|^(4−k) of the two roots, as (|P|, Σ).
    residual: (f64, f64),
    /// Whether κ ≤ 16 for both.
    well_conditioned: bool,
}

impl PairCheck {
    fn residual(&self) -> f64 {
        self.residual.0 / self.residual.1
    }

    /// Residual within 8ε of rounding and κ ≤ 16: nothing to polish.
    fn settled(&self) -> bool {
        self.residual.0 <= 8.0 * f64::EPSILON * self.residual.1 && self.well_conditioned
    }
}

/// The check of a quadratic's roots: once for a conjugate pair (both share
/// it), in real arithmetic for reals.
fn check_pair(c: &[f64; 5], (z1, z2): (Complex64, Complex64)) -> PairCheck {
    let real = |x: f64| {
        let p = (((c[0] * x + c[1]) * x + c[2]) * x + c[3]) * x + c[4];
        let ax = x.abs();
        let s = (((c[0].abs() * ax + c[1].abs()) * ax + c[2].abs()) * ax + c[3].abs()) * ax
            + c[4].abs();
        let dp = ((4.0 * c[0] * x + 3.0 * c[1]) * x + 2.0 * c[2]) * x + c[3];
        let s = s.max(f64::MIN_POSITIVE);
        ((p.abs(), s), ax == 0.0 || s <= 16.0 * ax * dp.abs())
    };
    if z1.im == 0.0 {
        let (r1, k1) = real(z1.re);
        let (r2, k2) = real(z2.re);
        // the larger ratio, compared without dividing
        let residual = if r1.0 * r2.1 >= r2.0 * r1.1 { r1 } else { r2 };
        PairCheck {
            residual,
            well_conditioned: k1 && k2,
        }
    } else {
        let s = abs_sum(c, z1).max(f64::MIN_POSITIVE);
        let n = l1(z1);
        PairCheck {
            residual: (l1(horner(c, z1)), s),
            well_conditioned: n == 0.0 || s <= 16.0 * n * l1(derivative(c, z1)),
        }
    }
}

/// The largest real root of y³ + e2·y² + e1·y + e0, cheaply: Cardano for a
/// single real root; for three, Halley's iteration on the depressed cubic
/// t³ + pt + q from t₀ = 2√(−p/3) — the largest root lies in [√(−p/3),
/// 2√(−p/3)], where the cubic is increasing and convex, so the iteration
/// falls monotonically onto it — instead of acos and cos. Not polished
/// further: Newton on the factorization follows.
fn largest_cubic_root(e2: f64, e1: f64, e0: f64) -> f64 {
    let sh = e2 / 3.0;
    let p = e1 - e2 * sh;
    let q = e0 - sh * e1 + 2.0 * sh * sh * sh;
    let disc = (q / 2.0) * (q / 2.0) + (p / 3.0) * (p / 3.0) * (p / 3.0);
    let t = if disc >= 0.0 {
        let sq = disc.sqrt();
        let u = (-q / 2.0 + if q <= 0.0 { sq } else { -sq }).cbrt();
        if u != 0.0 {
            u - p / (3.0 * u)
        } else {
            (-q).cbrt()
        }
    } else {
        let mut t = 2.0 * (-p / 3.0).sqrt();
        // y = b (t = −2e₂/3) lies just above the root when a factor's
        // linear coefficient is small (b − y = αγ, e.g. a lightly damped
        // mode): a closer start, if it is right of the local minimum and
        // f > 0 there.
        let tb = -2.0 * sh;
        if tb < t && 3.0 * tb * tb >= -p && tb > 0.0 && (tb * tb + p) * tb + q > 0.0 {
            t = tb;
        }
        for _ in 0..8 {
            let f = (t * t + p) * t + q;
            let df = 3.0 * t * t + p;
            let den = 2.0 * df * df - f * 6.0 * t;
            if f <= 0.0 || den <= 0.0 {
                break;
            }
            let next = t - 2.0 * f * df / den;
            if next >= t || next.is_nan() {
                break;
            }
            // cubic convergence: after a step this small, ~ε is left
            let settled = t - next <= 1e-6 * next.abs();
            t = next;
            if settled {
                break;
            }
        }
        t
    };
    t - sh
}

/// The largest relative Newton correction |P(zᵢ)/P′(zᵢ)|/|zᵢ| of a root set,
/// with the compensated P: ~κε² at converged simple roots, large where an
/// approximation has the wrong structure (say, two reals for a close
/// complex pair). An exact zero residual counts as converged.
fn correction(c: &[f64; 5], x: &[Complex64; 4]) -> f64 {
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
fn polish(x: &mut [Complex64; 4], c: &[f64; 5]) {
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
fn partners(x: &[Complex64; 4]) -> [usize; 4] {
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
fn aberth_step(c: &[f64; 5], z: &[Complex64; 4], i: usize) -> Option<Complex64> {
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
fn aberth(x: [Complex64; 4], c: &[f64; 5], iterations: usize) -> ([Complex64; 4], f64) {
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
fn aberth_free(x: [Complex64; 4], c: &[f64; 5], iterations: usize) -> ([Complex64; 4], f64) {
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

/// Roots of x² + p x + q without cancellation: for real roots the larger
/// is −p/2 − sign(p)√(p²/4 − q) and the smaller q over it; a complex pair is
/// −p/2 ± i√(q − p²/4), positive imaginary part first.
pub fn quadratic(p: f64, q: f64) -> (Complex64, Complex64) {
    let h = -p / 2.0;
    let disc = h * h - q;
    if disc >= 0.0 {
        let big = h + h.signum() * disc.sqrt();
        let big = if h == 0.0 { disc.sqrt() } else { big };
        let small = if big != 0.0 { q / big } else { 0.0 };
        (Complex64::new(big, 0.0), Complex64::new(small, 0.0))
    } else {
        let w = (-disc).sqrt();
        (Complex64::new(h, w), Complex64::new(h, -w))
    }
}

/// Order roots: descending modulus, conjugate pairs adjacent (+i first).
fn sort_roots(r: &mut [Complex64; 4]) {
    // Insertion sort on |λ|² (no hypot), then real part, then −im.
    let key = |z: &Complex64| (z.norm_sqr(), z.re, -z.im);
    let before = |x: &Complex64, y: &Complex64| {
        let (a, b) = (key(x), key(y));
        a.0 > b.0 || (a.0 == b.0 && (a.1 < b.1 || (a.1 == b.1 && a.2 < b.2)))
    };
    // Two conjugate pairs, each +i first (the usual stability quartic, as
    // the factorization returns it): order the pairs by their first roots.
    if r[0].im > 0.0 && r[1] == r[0].conj() && r[2].im > 0.0 && r[3] == r[2].conj() {
        if before(&r[2], &r[0]) {
            r.swap(0, 2);
            r.swap(1, 3);
        }
        return;
    }
    for i in 1..4 {
        let mut j = i;
        while j > 0 && before(&r[j], &r[j - 1]) {
            r.swap(j, j - 1);
            j -= 1;
        }
    }
    // Keep conjugates adjacent even when moduli tie with another root.
    for i in 0..3 {
        if r[i].im > 0.0
            && r[i + 1] != r[i].conj()
            && let Some(j) = (i + 2..4).find(|&j| r[j] == r[i].conj())
        {
            r.swap(i + 1, j);
        }
    }
}

/// The real roots of y³ + e2·y² + e1·y + e0 (Cardano or the trigonometric
/// form, each polished by Newton's method): up to three, and their count.
///
/// With one real root t and a complex pair of real part −t/2 (Cardano's
/// discriminant ≥ 0), the pair may in fact be a (near-)double real root:
/// −t/2 is returned too when it is a root to within rounding.
fn real_cubic_roots(e2: f64, e1: f64, e0: f64) -> ([f64; 3], usize) {
    // Depressed: y = t − e2/3, t³ + P t + Q = 0.
    let sh = e2 / 3.0;
    let p = e1 - e2 * sh;
    let q = e0 - sh * e1 + 2.0 * sh * sh * sh;
    let f = |y: f64| ((y + e2) * y + e1) * y + e0;
    let scale = |y: f64| ((y.abs() + e2.abs()) * y.abs() + e1.abs()) * y.abs() + e0.abs();
    let polish = |mut y: f64| {
        for _ in 0..4 {
            let fy = f(y);
            let df = (3.0 * y + 2.0 * e2) * y + e1;
            if df == 0.0 || !fy.is_finite() {
                break;
            }
            let next = y - fy / df;
            if !next.is_finite() || f(next).abs() >= fy.abs() {
                break;
            }
            y = next;
        }
        y
    };
    if p == 0.0 && q == 0.0 {
        return ([-sh, 0.0, 0.0], 1);
    }
    let disc = (q / 2.0) * (q / 2.0) + (p / 3.0) * (p / 3.0) * (p / 3.0);
    if disc >= 0.0 {
        let sq = disc.sqrt();
        let u = (-q / 2.0 + if q <= 0.0 { sq } else { -sq }).cbrt();
        let t = if u != 0.0 {
            u - p / (3.0 * u)
        } else {
            (-q).cbrt()
        };
        let y = polish(t - sh);
        let y2 = polish(-t / 2.0 - sh);
        if f(y2).abs() <= 1e-8 * scale(y2) {
            ([y, y2, 0.0], 2)
        } else {
            ([y, 0.0, 0.0], 1)
        }
    } else {
        let r = (-p / 3.0).sqrt();
        let phi = (-q / 2.0 / (r * r * r)).clamp(-1.0, 1.0).acos() / 3.0;
        let third = 2.0 * std::f64::consts::PI / 3.0;
        (
            [
                polish(2.0 * r * phi.cos() - sh),
                polish(2.0 * r * (phi + third).cos() - sh),
                polish(2.0 * r * (phi - third).cos() - sh),
            ],
            3,
        )
    }
}

/// The scaled monic quartic x⁴ + ax³ + bx² + cx + d, with the reciprocals
/// of its coefficients (0 for a zero coefficient) for the backward error.
#[derive(Clone, Copy)]
struct Monic {
    a: f64,
    b: f64,
    c: f64,
    d: f64,
    inv: [f64; 4],
}

impl Monic {
    fn new(a: f64, b: f64, c: f64, d: f64) -> Monic {
        let r = |x: f64| if x != 0.0 { 1.0 / x } else { 0.0 };
        Monic {
            a,
            b,
            c,
            d,
            inv: [r(a), r(b), r(c), r(d)],
        }
    }

    /// Relative backward error of a factorization: Σ|residualₖ/coefₖ|
    /// (absolute for a zero coefficient).
    fn backward_error(&self, f: (f64, f64, f64, f64)) -> f64 {
        let (al, be, ga, de) = f;
        let rel = |got: f64, want: f64, inv: f64| {
            let r = got - want;
            if inv != 0.0 { (r * inv).abs() } else { r.abs() }
        };
        rel(al + ga, self.a, self.inv[0])
            + rel(be + de + al * ga, self.b, self.inv[1])
            + rel(al * de + be * ga, self.c, self.inv[2])
            + rel(be * de, self.d, self.inv[3])
    }
}

/// The factorization (x² + ax/2 + y/2)² − (px + q)² for a resolvent root y.
fn from_resolvent(y: f64, m: &Monic) -> (f64, f64, f64, f64) {
    let (a, b, c, d) = (m.a, m.b, m.c, m.d);
    let p = (a * a / 4.0 + y - b).max(0.0).sqrt();
    let mut q = (y * y / 4.0 - d).max(0.0).sqrt();
    // sign(pq) = sign(ay/4 − c/2)
    if a * y / 4.0 - c / 2.0 < 0.0 {
        q = -q;
    }
    (a / 2.0 + p, y / 2.0 + q, a / 2.0 - p, y / 2.0 - q)
}

/// Algorithm 1010's repair: βδ = d exactly from the larger of β, δ, and α,
/// γ re-solved from α + γ = a, αδ + βγ = c when that lowers the backward
/// error.
fn repair(f: (f64, f64, f64, f64), m: &Monic) -> (f64, f64, f64, f64) {
    let (al, be, ga, de) = f;
    let (be2, de2) = if be.abs() >= de.abs() {
        (be, if be != 0.0 { m.d / be } else { de })
    } else {
        (if de != 0.0 { m.d / de } else { be }, de)
    };
    let mut best = f;
    let mut best_err = m.backward_error(f);
    let mut consider = |g: (f64, f64, f64, f64)| {
        let e = m.backward_error(g);
        if e < best_err {
            best = g;
            best_err = e;
        }
    };
    consider((al, be2, ga, de2));
    if (de2 - be2).abs() > 1e-8 * (de2.abs() + be2.abs()) {
        let al2 = (m.c - be2 * m.a) / (de2 - be2);
        consider((al2, be2, m.a - al2, de2));
    }
    best
}

/// Newton's method on the four Vieta equations of the factorization,
/// stopping when the backward error no longer decreases.
fn newton_factor(mut f: (f64, f64, f64, f64), m: &Monic) -> (f64, f64, f64, f64) {
    let (a, b, c, d) = (m.a, m.b, m.c, m.d);
    let mut err = m.backward_error(f);
    for _ in 0..16 {
        if err <= 2.0 * f64::EPSILON {
            break;
        }
        let (al, be, ga, de) = f;
        let r = [
            al + ga - a,
            be + de + al * ga - b,
            al * de + be * ga - c,
            be * de - d,
        ];
        // J·Δ = r with J's columns ∂/∂α = (1, γ, δ, 0), ∂/∂β = (0, 1, γ, δ),
        // ∂/∂γ = (1, α, β, 0), ∂/∂δ = (0, 1, α, β). With Δγ = r₀ − Δα the
        // rest is a 3×3 system in (Δα, Δβ, Δδ), solved by Cramer's rule:
        //   (γ−α)Δα + Δβ + Δδ = r₁ − αr₀
        //   (δ−β)Δα + γΔβ + αΔδ = r₂ − βr₀
        //              δΔβ + βΔδ = r₃
        let (m11, m12, m13, k1) = (ga - al, 1.0, 1.0, r[1] - al * r[0]);
        let (m21, m22, m23, k2) = (de - be, ga, al, r[2] - be * r[0]);
        let (m31, m32, m33, k3) = (0.0, de, be, r[3]);
        let det3 =
            |a1: f64, a2: f64, a3: f64, b1: f64, b2: f64, b3: f64, c1: f64, c2: f64, c3: f64| {
                a1 * (b2 * c3 - b3 * c2) - a2 * (b1 * c3 - b3 * c1) + a3 * (b1 * c2 - b2 * c1)
            };
        let det = det3(m11, m12, m13, m21, m22, m23, m31, m32, m33);
        if det == 0.0 || !det.is_finite() {
            break;
        }
        let inv = 1.0 / det;
        let x1 = det3(k1, m12, m13, k2, m22, m23, k3, m32, m33) * inv;
        let x2 = det3(m11, k1, m13, m21, k2, m23, m31, k3, m33) * inv;
        let x4 = det3(m11, m12, k1, m21, m22, k2, m31, m32, k3) * inv;
        let step = [x1, x2, r[0] - x1, x4];
        let next = (al - step[0], be - step[1], ga - step[2], de - step[3]);
        let next_err = m.backward_error(next);
        if next_err >= err || next_err.is_nan() {
            break;
        }
        f = next;
        err = next_err;
    }
    f
}

#[cfg(test)]
mod tests {
    use super::*;

    fn poly_from_roots(r: [Complex64; 4]) -> [f64; 5] {
        // (x − r1)(x − r2)(x − r3)(x − r4), real when roots are closed under conjugation
        let mut c = [
            Complex64::new(1.0, 0.0),
            Complex64::new(0.0, 0.0),
            Complex64::new(0.0, 0.0),
            Complex64::new(0.0, 0.0),
            Complex64::new(0.0, 0.0),
        ];
        for (k, root) in r.iter().enumerate() {
            for j in (1..=k + 1).rev() {
                c[j] -= c[j - 1] * root;
            }
        }
        c.map(|z| z.re)
    }

    #[test]
    fn integer_roots_within_their_condition() {
        // (x−1)(x−2)(x−3)(x−4) = x⁴ − 10x³ + 35x² − 50x + 24. The root 4 has
        // condition Σ|cₖ|4ᵏ/(4|P′(4)|) = 1680/24 = 70, so ~70ε is the best
        // any f64 method can promise.
        let r = solve_quartic([1.0, -10.0, 35.0, -50.0, 24.0]).unwrap();
        for (z, want) in r.iter().zip([4.0, 3.0, 2.0, 1.0]) {
            assert_eq!(z.im, 0.0);
            assert!(
                (z.re - want).abs() <= 100.0 * f64::EPSILON * want,
                "{z} vs {want}"
            );
        }
    }

    #[test]
    fn two_complex_pairs_are_exact_conjugates() {
        let roots = [
            Complex64::new(-1.0, 5.0),
            Complex64::new(-1.0, -5.0),
            Complex64::new(-0.01, 0.05),
            Complex64::new(-0.01, -0.05),
        ];
        let r = solve_quartic(poly_from_roots(roots)).unwrap();
        assert_eq!(r[1], r[0].conj());
        assert_eq!(r[3], r[2].conj());
        assert!(r[0].im > 0.0);
        for (got, want) in r.iter().zip(roots) {
            assert!(
                (got - want).norm() <= 1e-14 * want.norm(),
                "{got} vs {want}"
            );
        }
    }

    #[test]
    fn errors_and_degenerate_cases() {
        assert_eq!(
            solve_quartic([0.0, 1.0, 2.0, 3.0, 4.0]),
            Err(RootsError::LeadingZero)
        );
        assert_eq!(
            solve_quartic([1.0, f64::NAN, 2.0, 3.0, 4.0]),
            Err(RootsError::NonFinite("B"))
        );
        assert_eq!(
            solve_quartic([1.0, 0.0, 0.0, 0.0, 0.0]).unwrap(),
            [Complex64::new(0.0, 0.0); 4]
        );
        assert_eq!(
            solve_quartic([1e-300, 1e300, 0.0, 0.0, 0.0]),
            Err(RootsError::Overflow)
        );
        // a zero root: x(x−1)(x−2)(x−3)
        let r = solve_quartic([1.0, -6.0, 11.0, -6.0, 0.0]).unwrap();
        assert!(r.iter().any(|z| z.norm() < 1e-15));
    }

    #[test]
    fn a_quadruple_root_from_perturbed_coefficients_is_a_tight_cluster() {
        // (λ − 1000)⁴ with E moved by one ulp: the roots move by up to
        // ~1000·ε^(1/4) ≈ 0.12; they must stay finite and within 2ε^(1/4).
        let e = 1e12_f64;
        let coeffs = [1.0, -4000.0, 6e6, -4e9, e * (1.0 + f64::EPSILON)];
        let r = solve_quartic(coeffs).unwrap();
        for z in r {
            assert!(z.re.is_finite() && z.im.is_finite());
            assert!(
                (z - 1000.0).norm() <= 2.0 * f64::EPSILON.powf(0.25) * 1000.0,
                "{z}"
            );
        }
    }

    proptest::proptest! {
        #[test]
        fn random_quartics_have_small_residuals(
            c in proptest::array::uniform5(-1e6f64..1e6),
            e in proptest::array::uniform5(-8i32..8),
        ) {
            let coeffs: [f64; 5] = std::array::from_fn(|k| c[k] * 10f64.powi(e[k]));
            match solve_quartic(coeffs) {
                Err(RootsError::LeadingZero) => proptest::prop_assert_eq!(coeffs[0], 0.0),
                Err(other) => proptest::prop_assert!(false, "{other}"),
                Ok(roots) => {
                    for z in roots {
                        proptest::prop_assert!(z.re.is_finite() && z.im.is_finite());
                        let p = comp_horner(&coeffs, z).norm();
                        let scale = abs_sum(&coeffs, z);
                        proptest::prop_assert!(p <= 1e-12 * scale, "P({z}) = {p:e}, scale {scale:e}");
                    }
                }
            }
        }
    }

    #[test]
    fn two_pairs_sort_as_the_general_sort_does() {
        let c = Complex64::new;
        for (a, b) in [
            (c(-1.0, 5.0), c(-0.01, 0.05)),
            (c(-0.01, 0.05), c(-1.0, 5.0)),
            (c(1.0, 2.0), c(2.0, 1.0)), // equal moduli: smaller real part first
            (c(2.0, 1.0), c(1.0, 2.0)),
            (c(-3.0, 4.0), c(-3.0, 4.0)),
        ] {
            let mut fast = [a, a.conj(), b, b.conj()];
            // interleaved, so that the general insertion sort runs
            let mut general = [a, b, a.conj(), b.conj()];
            sort_roots(&mut fast);
            sort_roots(&mut general);
            assert_eq!(fast, general, "{a} {b}");
            assert!(fast[0].norm_sqr() >= fast[2].norm_sqr());
            assert_eq!(fast[1], fast[0].conj());
        }
    }

    #[test]
    fn quadratic_is_cancellation_free() {
        // x² − 1e8 x + 1 = 0: roots 1e8 and 1e-8 (to 16 digits)
        let (big, small) = quadratic(-1e8, 1.0);
        assert_eq!(big.re, 1e8);
        assert!((small.re - 1e-8).abs() < 1e-24);
    }
}
