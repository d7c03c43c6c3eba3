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
//! 1. The coefficients are divided by A and λ is scaled by the power of two
//!    s = 2^σ nearest max |cₖ/A|^(1/k), so that the scaled quartic has
//!    coefficients of order one; roots are scaled back at the end. Powers
//!    of two are exact (`binary`); where this scaling cannot bring every
//!    coefficient into range (roots of widely different sizes, or
//!    coefficient ratios beyond f64), the quartic is solved on its own
//!    coefficients instead, by the Aberth–Ehrlich iteration from the Newton
//!    polygon (`wide`).
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
//! # Every root is checked
//! A root is returned only if its backward error
//! |P(λ)|/Σ|cₖ||λ|^(4−k) — the smallest relative change of the
//! coefficients that makes it exact — is at most [`TOLERANCE`], evaluated
//! at the root's own scale; otherwise the answer is an error
//! ([`RootsError::Inaccurate`]), as it is for roots beyond f64's range
//! ([`RootsError::Overflow`], [`RootsError::Underflow`]): a root that
//! fails the check is never returned as an answer. (`tests/it/roots_fuzz.rs`
//! holds the solver to this over f64's whole range.)
//!
//! Modules: `binary` (exact scaling), `factor` (steps 2–4), `aberth`
//! (step 5), `horner` (evaluation), `wide` (any scale), `batch` (many
//! quartics at once).
//!
//! # Many quartics at once
//! [`solve_quartics`] returns, for a slice of quartics, exactly what
//! [`solve_quartic`] returns for each (bit for bit, errors included), four
//! at a time: steps 1–4 run on SIMD vectors of four lanes (`wide::f64x4`),
//! each lane doing the scalar path's operations in the same order with its
//! branches turned into masks, and a lane whose first factorization does
//! not settle is handed to [`solve_quartic`]. Measured with divan
//! (`cargo bench -p stability-core --bench roots`, 256 quartics a batch;
//! ratios within one run, medians of three runs, on a shared 2-core AMD
//! EPYC with SSE2 code): on the stability set (two complex pairs)
//! [`solve_quartics`] takes 0.116 of the time of nalgebra's
//! companion-matrix eigenvalues (8.6× faster; about 90 ns a quartic here,
//! up to ~105 ns in runs disturbed by other jobs) and 0.55 of the time of
//! one [`solve_quartic`] call each (1.8×); on the mixed set (every root
//! structure; 255 of its 256 settle in the lanes) 0.18 of nalgebra's time
//! and 0.72 of the scalar calls'. The scalar path alone is 4.7× faster
//! than nalgebra on the stability set.
//!
//! # Multiple roots
//! A root of multiplicity m is ill-conditioned: a perturbation ε of the
//! coefficients moves it by ~ε^(1/m). Without the compensated polish a
//! double root comes back to ~1e-8 relative and a quadruple one such as
//! (λ − 1000)⁴ to ~1e-4; the polish improves on that where Newton's
//! (linear) convergence allows, but a multiple root is returned as a tight
//! cluster (possibly as a pair with a tiny imaginary part), never exactly.
//! The results are always finite.

mod aberth;
mod batch;
pub(crate) mod binary;
mod factor;
mod horner;
mod wide;

use crate::numerics::display::Num;
pub use batch::solve_quartics;
pub use num_complex::Complex64;

/// The largest backward error of a root returned (see the module
/// documentation); the solver reaches a few ε on every quartic it has
/// been given.
pub const TOLERANCE: f64 = 1e-12;

/// Why a quartic has no roots to report.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum RootsError {
    /// A = 0: the polynomial is not a quartic.
    #[error("the leading coefficient A is zero: not a quartic (solve the cubic instead)")]
    LeadingZero,
    /// A coefficient is NaN or infinite.
    #[error("coefficient {coefficient} = {} is not a finite number", Num(*value))]
    NonFinite {
        coefficient: &'static str,
        value: f64,
    },
    /// Some roots are too large for f64.
    #[error(
        "some roots are too large to represent (|λ| ≈ 2^{log2_modulus}, beyond f64's {}): the coefficient ratios are too extreme",
        Num(f64::MAX)
    )]
    Overflow { log2_modulus: i32 },
    /// Some roots are too small for f64.
    #[error(
        "some roots are too small to represent (|λ| ≈ 2^{log2_modulus}, below f64's {}): the coefficient ratios are too extreme",
        Num(f64::from_bits(1))
    )]
    Underflow { log2_modulus: i32 },
    /// A root failed its backward-error check.
    #[error(
        "the root {} {} {}i could not be computed accurately: its backward error |P(λ)|/Σ|cₖ||λ|^(4−k) is {}, above {}",
        Num(root.re), if root.im < 0.0 { "−" } else { "+" }, Num(root.im.abs()),
        Num(*backward_error), Num(TOLERANCE)
    )]
    Inaccurate {
        root: Complex64,
        backward_error: f64,
    },
}

const NAMES: [&str; 5] = ["A", "B", "C", "D", "E"];

/// The four roots of `A λ⁴ + B λ³ + C λ² + D λ + E` with `coeffs = [A, B, C, D, E]`.
///
/// Order: by descending modulus; a complex pair is adjacent, the root with
/// positive imaginary part first; real roots have `im == 0.0`.
pub fn solve_quartic(coeffs: [f64; 5]) -> Result<[Complex64; 4], RootsError> {
    for (&value, coefficient) in coeffs.iter().zip(NAMES) {
        if !value.is_finite() {
            return Err(RootsError::NonFinite { coefficient, value });
        }
    }
    if coeffs[0] == 0.0 {
        return Err(RootsError::LeadingZero);
    }
    if coeffs[1..].iter().all(|&v| v == 0.0) {
        return Ok([Complex64::new(0.0, 0.0); 4]);
    }
    let mut roots = match Scaling::of(&coeffs).and_then(|s| s.roots()) {
        Some(r) => r,
        None => wide::roots(&coeffs)?,
    };
    sort_roots(&mut roots);
    Ok(roots)
}

/// Step 1: the quartic scaled by λ = 2^σ·x and divided by 2^(e₀ + 4σ)
/// (e₀ the exponent of A), exactly, when that brings every coefficient
/// into range.
struct Scaling {
    sigma: i32,
    /// x⁴ + ax³ + bx² + cx + d, the scaled monic quartic.
    monic: [f64; 4],
    /// The given coefficients scaled (exactly), for residuals and polish.
    exact: [f64; 5],
}

impl Scaling {
    /// `None` where the scaling is not exact or leaves a coefficient too
    /// small for the rounding of its terms to stay relative (below 2⁻⁹⁶⁹,
    /// 2⁵³ above the subnormals), and for E = 0. Then at every root the
    /// terms' sum Σ|cₖ||x|^(4−k) ≥ |E| ≥ 2⁻⁹⁶⁹, so terms that underflow are
    /// negligible and every residual below is relative.
    #[inline]
    fn of(c: &[f64; 5]) -> Option<Scaling> {
        if c[4] == 0.0 {
            // a zero root: its terms vanish with it, so no coefficient
            // bounds them from below (`wide` takes it exactly)
            return None;
        }
        let m = [c[1] / c[0], c[2] / c[0], c[3] / c[0], c[4] / c[0]];
        // each ratio finite, and normal exactly where its coefficient is
        // non-zero
        let mut ok = true;
        for (v, orig) in m.iter().zip(&c[1..]) {
            ok &= v.is_finite() && (v.abs() >= f64::MIN_POSITIVE || *orig == 0.0);
        }
        if !ok {
            return None;
        }
        let sigma = scale_exponent(&m);
        let e0 = binary::exponent(c[0]);
        let monic: [f64; 4] = std::array::from_fn(|k| binary::ldexp(m[k], -(k as i32 + 1) * sigma));
        let exact: [f64; 5] =
            std::array::from_fn(|k| binary::ldexp(c[k], -(k as i32) * sigma - e0));
        // (all bounded above by the choice of σ) zero where the original
        // is zero, else ≥ 2⁻⁹⁶⁹
        const SMALLEST: f64 = binary::pow2(-969);
        for k in 0..4 {
            ok &= monic[k].abs() >= SMALLEST || m[k] == 0.0;
            ok &= exact[k + 1].abs() >= SMALLEST || c[k + 1] == 0.0;
        }
        ok.then_some(Scaling {
            sigma,
            monic,
            exact,
        })
    }

    /// Steps 2–5 on the scaled quartic, and the roots scaled back; `None`
    /// where a root fails the backward-error check, a conjugate is missing,
    /// or a root leaves f64's range when scaled back (then `wide` decides).
    #[inline]
    fn roots(&self) -> Option<[Complex64; 4]> {
        let [a, b, c, d] = self.monic;
        let (mut x, settled) = factor::factored_roots(a, b, c, d, &self.exact);
        if !settled {
            aberth::polish(&mut x, &self.exact);
            let ok = x
                .iter()
                .all(|&z| horner::backward_error(&self.exact, z) <= TOLERANCE);
            if !(ok && conjugates_complete(&x)) {
                return None;
            }
        }
        self.scale_back(x)
    }

    /// The roots x of the scaled quartic as roots λ = 2^σ·x of the given
    /// one; `None` where one leaves f64's range.
    #[inline]
    fn scale_back(&self, x: [Complex64; 4]) -> Option<[Complex64; 4]> {
        scale_back(self.sigma, x)
    }
}

/// [`Scaling::scale_back`] for a given σ.
#[inline]
fn scale_back(sigma: i32, x: [Complex64; 4]) -> Option<[Complex64; 4]> {
    let roots = x.map(|z| binary::ldexp_c(z, sigma));
    // The scaled roots lie in 2⁻⁹⁷³ ≤ |x| < 9 (Cauchy's bounds with
    // |a|, |b|, |c|, |d| < 8 and |d| ≥ 2⁻⁹⁶⁹), so the roots scaled
    // back are normal unless σ is extreme.
    if (-49..=1019).contains(&sigma) {
        return Some(roots);
    }
    let representable = |z: &Complex64| {
        let m = z.re.abs().max(z.im.abs());
        m.is_finite() && m >= f64::MIN_POSITIVE
    };
    roots.iter().all(representable).then_some(roots)
}

/// Every non-real root has its exact conjugate among the others (counted
/// one to one).
fn conjugates_complete(x: &[Complex64; 4]) -> bool {
    let mut used = [false; 4];
    for i in 0..4 {
        if x[i].im == 0.0 || used[i] {
            continue;
        }
        match (0..4).find(|&j| j != i && !used[j] && x[j] == x[i].conj()) {
            Some(j) => {
                used[i] = true;
                used[j] = true;
            }
            None => return false,
        }
    }
    true
}

/// σ = max over k of ⌊exponent(|mₖ|)/(k + 1)⌉: 2^σ is within a factor ~2
/// of max |mₖ|^(1/(k+1)), from the binary exponents alone (no libm).
fn scale_exponent(m: &[f64; 4]) -> i32 {
    let mut e = i32::MIN;
    for (k, &v) in m.iter().enumerate() {
        if v != 0.0 {
            let n = k as i32 + 1;
            e = e.max((binary::exponent(v) + n / 2).div_euclid(n));
        }
    }
    e
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

#[cfg(test)]
mod tests {
    use super::horner::{abs_sum, comp_horner};
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
        assert!(matches!(
            solve_quartic([1.0, f64::NAN, 2.0, 3.0, 4.0]),
            Err(RootsError::NonFinite {
                coefficient: "B",
                ..
            })
        ));
        assert_eq!(
            solve_quartic([1.0, 0.0, 0.0, 0.0, 0.0]).unwrap(),
            [Complex64::new(0.0, 0.0); 4]
        );
        assert!(matches!(
            solve_quartic([1e-300, 1e300, 0.0, 0.0, 0.0]),
            Err(RootsError::Overflow { log2_modulus: 1993 })
        ));
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
