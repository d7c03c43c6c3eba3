//! The report's own method for the roots (§4, eq 7): a first approximation
//! from the separation of the modes, then successive approximation.
//!
//! # First approximation, eq (7)
//! With the short period fast and the phugoid slow, the quartic
//! Aλ⁴ + Bλ³ + Cλ² + Dλ + E splits approximately into
//! `Aλ² + Bλ + C` (short period) and `Cλ² + (D − BE/C)λ + E` (phugoid), so
//! `r₁ = −B/(2A)`, `s₁ = √(C/A − (B/2A)²)`,
//! `r₂ = −½(D/C − BE/C²)`, `s₂ = √(E/C − ¼(D/C − BE/C²)²)`.
//! (The phugoid's formulas do not contain A; the report's are the same for
//! any A.) Where a square root's argument is negative, that quadratic's
//! roots are real and are returned as such.
//!
//! # Refinement, for general A
//! The report asks that the roots be "improved until 2r₁ + 2r₂ = −B and
//! (r₁² + s₁²)(r₂² + s₂²) = E" — written for A = 1. For any A the quartic is
//! A(λ² + p₁λ + q₁)(λ² + p₂λ + q₂) with pᵢ = −2rᵢ, qᵢ = rᵢ² + sᵢ², and the
//! four Vieta relations are
//! (1) `p₁ + p₂ = B/A`, (2) `q₁ + q₂ + p₁p₂ = C/A`, (3) `p₁q₂ + p₂q₁ = D/A`,
//! (4) `q₁q₂ = E/A` (the report's two conditions are (1) and (4):
//! 2r₁ + 2r₂ = −B/A and (r₁² + s₁²)(r₂² + s₂²) = E/A). The classical
//! successive approximation (as in the stability texts of the period, e.g.
//! W.J. Duncan, *The principles of the control and stability of aircraft*,
//! 1952; compare Lin's method, J. Math. Phys. 20, 1941) solves each relation
//! for its dominant unknown, in turn:
//! `p₁ = B/A − p₂`, `q₁ = C/A − q₂ − p₁p₂`, `q₂ = (E/A)/q₁`,
//! `p₂ = (D/A − p₁q₂)/q₁`, until nothing changes. It converges when the
//! modes are well separated (q₂ ≪ q₁), as for the aircraft of the report;
//! solving (3) for p₁ instead divides by the small q₂ and diverges.

use num_complex::Complex64;

/// A pair of roots r ± is from a quadratic; `im` is 0 and `split` holds the
/// two real roots when the quadratic's roots are real.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ApproxPair {
    pub re: f64,
    pub im: f64,
    /// The two real roots when the pair splits.
    pub split: Option<(f64, f64)>,
}

impl ApproxPair {
    /// The pair of λ² + pλ + q = 0.
    pub fn of_quadratic(p: f64, q: f64) -> ApproxPair {
        let r = -p / 2.0;
        let disc = q - r * r;
        if disc >= 0.0 {
            ApproxPair {
                re: r,
                im: disc.sqrt(),
                split: None,
            }
        } else {
            let (a, b) = crate::numerics::roots::quadratic(p, q);
            ApproxPair {
                re: r,
                im: 0.0,
                split: Some((a.re, b.re)),
            }
        }
    }

    /// The two roots.
    pub fn roots(&self) -> [Complex64; 2] {
        match self.split {
            Some((a, b)) => [Complex64::new(a, 0.0), Complex64::new(b, 0.0)],
            None => [
                Complex64::new(self.re, self.im),
                Complex64::new(self.re, -self.im),
            ],
        }
    }

    /// The root with s ≥ 0 (or the slower real root of a split pair).
    pub fn root(&self) -> Complex64 {
        match self.split {
            Some((a, b)) => Complex64::new(if a.abs() < b.abs() { a } else { b }, 0.0),
            None => Complex64::new(self.re, self.im),
        }
    }
}

/// The classical roots: short period (1) and phugoid (2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClassicalRoots {
    pub short_period: ApproxPair,
    pub phugoid: ApproxPair,
}

impl ClassicalRoots {
    fn from_factors(p1: f64, q1: f64, p2: f64, q2: f64) -> ClassicalRoots {
        ClassicalRoots {
            short_period: ApproxPair::of_quadratic(p1, q1),
            phugoid: ApproxPair::of_quadratic(p2, q2),
        }
    }

    /// All four roots, short period first.
    pub fn roots(&self) -> [Complex64; 4] {
        let [a, b] = self.short_period.roots();
        let [c, d] = self.phugoid.roots();
        [a, b, c, d]
    }
}

/// Why the classical method cannot start.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum ClassicalError {
    #[error("A = 0: not a quartic")]
    LeadingZero,
    #[error("C = 0: eq (7) divides by C")]
    ZeroC,
    #[error("a coefficient is not finite")]
    NonFinite,
}

/// Eq (7): the first approximation, `coeffs = [A, B, C, D, E]`.
pub fn first_approximation(coeffs: [f64; 5]) -> Result<ClassicalRoots, ClassicalError> {
    let [a, b, c, d, e] = coeffs;
    if !coeffs.iter().all(|x| x.is_finite()) {
        return Err(ClassicalError::NonFinite);
    }
    if a == 0.0 {
        return Err(ClassicalError::LeadingZero);
    }
    if c == 0.0 {
        return Err(ClassicalError::ZeroC);
    }
    // short period: Aλ² + Bλ + C; phugoid: λ² + (D/C − BE/C²)λ + E/C
    Ok(ClassicalRoots::from_factors(
        b / a,
        c / a,
        d / c - b * e / (c * c),
        e / c,
    ))
}

/// The result of the successive approximation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Refinement {
    pub roots: ClassicalRoots,
    pub iterations: usize,
    pub converged: bool,
    /// The largest relative residual of the four Vieta relations at the end.
    pub residual: f64,
}

/// Refine eq (7)'s roots by successive approximation (see the module
/// documentation) until the factors change by less than `tol` (relative),
/// at most `max_iter` times.
pub fn refine(
    coeffs: [f64; 5],
    start: &ClassicalRoots,
    max_iter: usize,
    tol: f64,
) -> Result<Refinement, ClassicalError> {
    let [a, b, c, d, e] = coeffs;
    if !coeffs.iter().all(|x| x.is_finite()) {
        return Err(ClassicalError::NonFinite);
    }
    if a == 0.0 {
        return Err(ClassicalError::LeadingZero);
    }
    let (b, c, d, e) = (b / a, c / a, d / a, e / a);
    let factors = |pair: &ApproxPair| {
        let [x, y] = pair.roots();
        (-(x + y).re, (x * y).re)
    };
    let (mut p1, mut q1) = factors(&start.short_period);
    let (mut p2, mut q2) = factors(&start.phugoid);
    let mut iterations = 0;
    let mut converged = false;
    while iterations < max_iter {
        iterations += 1;
        // Each relation solved for its dominant unknown (q₂ ≪ q₁, p₂ ≪ p₁):
        // (1) for p₁, (2) for q₁, (3) for p₂ (its term p₂q₁ dominates p₁q₂),
        // (4) for q₂; Gauss–Seidel order.
        let np1 = b - p2;
        let nq1 = c - q2 - np1 * p2;
        if nq1 == 0.0 {
            break;
        }
        let nq2 = e / nq1;
        let np2 = (d - np1 * nq2) / nq1;
        if ![np1, nq1, np2, nq2].iter().all(|x| x.is_finite()) {
            break;
        }
        let change = [(np1, p1), (nq1, q1), (np2, p2), (nq2, q2)]
            .iter()
            .map(|(n, o)| (n - o).abs() / n.abs().max(f64::MIN_POSITIVE))
            .fold(0.0, f64::max);
        (p1, q1, p2, q2) = (np1, nq1, np2, nq2);
        if change <= tol {
            converged = true;
            break;
        }
    }
    let rel = |got: f64, want: f64| {
        if want != 0.0 {
            ((got - want) / want).abs()
        } else {
            got.abs()
        }
    };
    let residual = [
        rel(p1 + p2, b),
        rel(q1 + q2 + p1 * p2, c),
        rel(p1 * q2 + p2 * q1, d),
        rel(q1 * q2, e),
    ]
    .into_iter()
    .fold(0.0, f64::max);
    Ok(Refinement {
        roots: ClassicalRoots::from_factors(p1, q1, p2, q2),
        iterations,
        converged,
        residual,
    })
}

/// How good the classical roots are: the relative error |λ − λ_exact|/|λ_exact|
/// of the short-period and phugoid roots (with s ≥ 0) against exact ones.
pub fn relative_errors(
    classical: &ClassicalRoots,
    exact_short: Complex64,
    exact_phugoid: Complex64,
) -> (f64, f64) {
    let rel = |a: Complex64, b: Complex64| (a - b).norm() / b.norm().max(f64::MIN_POSITIVE);
    (
        rel(classical.short_period.root(), exact_short),
        rel(classical.phugoid.root(), exact_phugoid),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// (λ² + 2λ + 26)(λ² + 0.02λ + 0.0101): roots −1 ± 5i and −0.01 ± 0.1i.
    /// A=1, B=2.02, C=26.0501, D=0.5402, E=0.2626 (worked by hand).
    const Q: [f64; 5] = [1.0, 2.02, 26.0501, 0.5402, 0.2626];

    /// The fixture's roots are what the tests below measure against: each
    /// must make Q vanish, to the rounding of Q's decimal coefficients
    /// (|Q(λ)| ≤ 4ε·Σ|cₖ||λ|^(4−k)), and a root moved by 1e-9 must not.
    #[test]
    fn the_fixture_has_the_roots_it_claims() {
        let q = |z: Complex64| (((z * Q[0] + Q[1]) * z + Q[2]) * z + Q[3]) * z + Q[4];
        let scale = |z: Complex64| {
            let n = z.norm();
            Q.iter().fold(0.0, |acc, c| acc * n + c.abs())
        };
        for root in [
            Complex64::new(-1.0, 5.0),
            Complex64::new(-1.0, -5.0),
            Complex64::new(-0.01, 0.1),
            Complex64::new(-0.01, -0.1),
        ] {
            assert!(
                q(root).norm() <= 4.0 * f64::EPSILON * scale(root),
                "Q({root}) = {}",
                q(root)
            );
            let moved = root * (1.0 + 1e-9);
            assert!(
                q(moved).norm() > 1e3 * f64::EPSILON * scale(moved),
                "{moved}"
            );
        }
    }

    #[test]
    fn first_approximation_by_hand() {
        let r = first_approximation(Q).unwrap();
        // r₁ = −B/2 = −1.01; s₁ = √(26.0501 − 1.0201) = √25.03 = 5.003
        assert!((r.short_period.re + 1.01).abs() < 1e-15);
        assert!((r.short_period.im - 25.03f64.sqrt()).abs() < 1e-13);
        // D/C − BE/C² = 0.5402/26.0501 − 2.02·0.2626/26.0501²
        let k = 0.5402 / 26.0501 - 2.02 * 0.2626 / (26.0501 * 26.0501);
        assert!((r.phugoid.re + k / 2.0).abs() < 1e-15);
        assert!((r.phugoid.im - (0.2626 / 26.0501 - k * k / 4.0).sqrt()).abs() < 1e-15);
        // within 1 % of the exact roots
        let (e1, e2) = relative_errors(&r, Complex64::new(-1.0, 5.0), Complex64::new(-0.01, 0.1));
        assert!(e1 < 0.01 && e2 < 0.01, "{e1} {e2}");
    }

    #[test]
    fn refinement_converges_to_the_exact_roots() {
        let start = first_approximation(Q).unwrap();
        let r = refine(Q, &start, 100, 1e-15).unwrap();
        assert!(r.converged, "{r:?}");
        let (e1, e2) = relative_errors(
            &r.roots,
            Complex64::new(-1.0, 5.0),
            Complex64::new(-0.01, 0.1),
        );
        assert!(e1 < 1e-13 && e2 < 1e-12, "{e1} {e2}");
        // general A: the same quartic times 3
        let q3 = Q.map(|c| 3.0 * c);
        let r3 = refine(q3, &first_approximation(q3).unwrap(), 100, 1e-15).unwrap();
        let (e1, e2) = relative_errors(
            &r3.roots,
            Complex64::new(-1.0, 5.0),
            Complex64::new(-0.01, 0.1),
        );
        assert!(e1 < 1e-13 && e2 < 1e-12, "{e1} {e2}");
    }

    #[test]
    fn the_first_approximation_improves_as_the_modes_separate() {
        // short period −1 ± 5i·k, phugoid −0.01 ± 0.1i: the error falls as k grows.
        let mut last = f64::INFINITY;
        for k in [1.0, 3.0, 10.0, 30.0] {
            let (p1, q1) = (2.0, 1.0 + 25.0 * k * k);
            let (p2, q2) = (0.02, 0.0101);
            let q = [1.0, p1 + p2, q1 + q2 + p1 * p2, p1 * q2 + p2 * q1, q1 * q2];
            let r = first_approximation(q).unwrap();
            let (_, e2) = relative_errors(
                &r,
                Complex64::new(-1.0, (q1 - 1.0).sqrt()),
                Complex64::new(-0.01, 0.1),
            );
            assert!(e2 < last, "k = {k}: {e2} ≥ {last}");
            last = e2;
        }
    }

    #[test]
    fn split_pairs_are_real_roots_not_nan() {
        // short period (λ + 1)(λ + 4) = λ² + 5λ + 4: real
        let q = [1.0, 5.02, 4.1101, 0.1305, 0.0404];
        let r = first_approximation(q).unwrap();
        assert!(r.short_period.split.is_some());
        assert!(
            r.roots()
                .iter()
                .all(|z| z.re.is_finite() && z.im.is_finite())
        );
    }
}
