//! Issue 10: fuzzing found wrong roots with exit 0 on badly scaled inputs —
//! any input beyond about 1e54 or below 1e-150 gave roots of ±5.8e-308
//! where −6.74 and −0.108 are right, a root without its conjugate, a
//! divergent root missing from the mode table, and Routh's verdict
//! contradicting the roots (i_B = 1e308).
//!
//! Reference roots at 1600 digits (mpmath, the companion matrix's
//! eigenvalues polished by Newton; `scripts/badly_scaled_reference.py` →
//! `tests/data/badly_scaled.csv`) for the README's aircraft with one input
//! extreme, its quartic scaled across f64's range, and roots of widely
//! different sizes. Every case must come back to 1e-12 (relative, per
//! root), conjugates complete, with each root's real part of the
//! reference's sign, and Routh's verdict agreeing with the roots.

use crate::support;

use stability_core::analysis::Analysis;
use stability_core::criteria::Routh;
use stability_core::design::examples::tailless_delta_45;
use stability_core::numerics::roots::{RootsError, solve_quartic};
use stability_core::{Derivatives, Quartic};
use support::{Case, case_error, cases};

fn all() -> Vec<Case> {
    cases(include_str!("../data/badly_scaled.csv"))
}

fn stable(roots: &[num_complex::Complex64; 4]) -> bool {
    roots.iter().all(|z| z.re < 0.0)
}

#[test]
fn badly_scaled_quartics_are_solved_accurately() {
    let cases = all();
    assert!(cases.len() >= 120, "{} cases", cases.len());
    let mut worst = (0.0, String::new());
    for c in &cases {
        let got = solve_quartic(c.coeffs).unwrap_or_else(|e| panic!("{}: {e}", c.name));
        let err = case_error(&got, &c.roots);
        if err > worst.0 {
            worst = (err, c.name.clone());
        }
        assert!(
            err <= 1e-12,
            "{} {}: error {err:e}\n{got:?}\n{:?}",
            c.set,
            c.name,
            c.roots
        );
        // conjugates complete: the imaginary parts cancel exactly
        let im: f64 = got.iter().map(|z| z.im).sum();
        assert_eq!(im, 0.0, "{}: {got:?}", c.name);
        // every real part of the reference's sign (tiny ones included:
        // i_B = 1e308 has a divergent pair with r = 1.3e-306, s = 4.5e-154)
        let mut want: Vec<f64> = c.roots.iter().map(|z| z.re).collect();
        let mut have: Vec<f64> = got.iter().map(|z| z.re).collect();
        want.sort_by(f64::total_cmp);
        have.sort_by(f64::total_cmp);
        for (h, w) in have.iter().zip(&want) {
            assert_eq!(h.signum(), w.signum(), "{}: re {h:e} vs {w:e}", c.name);
        }
        let routh = Routh::of(&Quartic::from_array(c.coeffs));
        if !routh.marginal {
            assert_eq!(
                routh.stable,
                stable(&c.roots),
                "{}: Routh {routh:?}",
                c.name
            );
        }
    }
    println!("worst: {:e} ({})", worst.0, worst.1);
}

/// A fuzzed case: i_B = 1e−160 gave −8.4e159, 0, 0, 0 (three roots lost
/// below the scaling's range); the reference has −8.3962e159, −33.653 and
/// the pair −0.014781 ± 0.42268i, and every one is in the mode table.
#[test]
fn a_tiny_inertia_keeps_its_modes() {
    let d = Derivatives {
        i_b: 1e-160,
        ..tailless_delta_45()
    };
    let a = Analysis::of(&d).unwrap();
    let c = all()
        .into_iter()
        .find(|c| c.name == "i_b = 1e-160")
        .unwrap();
    assert_eq!(c.coeffs, a.quartic.to_array());
    assert!(case_error(&a.roots, &c.roots) <= 1e-12, "{:?}", a.roots);
    assert!((a.roots[1].re + 33.653).abs() < 1e-3, "{:?}", a.roots);
    assert!((a.roots[2].re + 0.014_781).abs() < 1e-6, "{:?}", a.roots);
    assert!((a.roots[2].im - 0.422_68).abs() < 1e-5, "{:?}", a.roots);
    assert_eq!(a.modes.len(), 3, "{:?}", a.modes);
}

/// i_B = 1e308: Routh said unstable while every printed root decayed. The
/// slow pair is divergent (r = +1.3e-306): roots and Routh agree, and the
/// divergent mode is in the table.
#[test]
fn an_enormous_inertia_agrees_with_routh() {
    let d = Derivatives {
        i_b: 1e308,
        ..tailless_delta_45()
    };
    let a = Analysis::of(&d).unwrap();
    assert!(!a.routh.stable && !a.routh.marginal, "{:?}", a.routh);
    assert!(a.roots.iter().any(|z| z.re > 0.0), "{:?}", a.roots);
    assert!(a.modes.any_divergent(), "{:?}", a.modes);
}

/// Roots beyond f64's range are typed errors, not wrong answers.
#[test]
fn roots_beyond_f64_are_errors() {
    assert!(matches!(
        solve_quartic([1e-300, 1e300, 0.0, 0.0, 0.0]),
        Err(RootsError::Overflow { .. })
    ));
    assert!(matches!(
        solve_quartic([1.0, 0.0, 0.0, 1e300, 1e-300]),
        Err(RootsError::Underflow { .. })
    ));
    // roots as large as f64 allows are returned
    let r = solve_quartic([1e-300, 1e5, 0.0, 0.0, 0.0]).unwrap();
    assert!((r[0].re + 1e305).abs() <= 1e-15 * 1e305, "{r:?}");
}
