//! `roots::solve_quartics` (four quartics per SIMD vector) against the
//! scalar `roots::solve_quartic` and against the 60-digit mpmath reference
//! roots of `tests/data/quartic_reference.csv` (`scripts/quartic_reference.py`);
//! also on the badly scaled fixtures (`tests/data/badly_scaled.csv`).
//!
//! The batch path promises the scalar path's answer bit for bit (the same
//! operations in the same order, lane by lane, and the scalar path itself
//! where its first factorization does not settle), so the comparisons with
//! `solve_quartic` are exact; the comparison with mpmath is the independent
//! one, with `roots_accuracy.rs`'s targets.

use crate::allocations::allocations_in;
use crate::support;
use num_complex::Complex64;
use proptest::prelude::*;
use stability_core::numerics::roots::{RootsError, solve_quartic, solve_quartics};
use support::{case_error, cases};

type Answer = Result<[Complex64; 4], RootsError>;

fn batch(coeffs: &[[f64; 5]]) -> Vec<Answer> {
    let mut out = vec![Err(RootsError::LeadingZero); coeffs.len()];
    assert_eq!(solve_quartics(coeffs, &mut out), coeffs.len());
    out
}

#[test]
fn the_reference_sets_agree_with_mpmath_and_with_the_scalar_path() {
    let all = cases(include_str!("../data/quartic_reference.csv"));
    let coeffs: Vec<[f64; 5]> = all.iter().map(|c| c.coeffs).collect();
    let got = batch(&coeffs);
    for set in [
        "hard",
        "real4",
        "pair_real2",
        "pairs2",
        "real4_s",
        "pair_real2_s",
        "pairs2_s",
        "stability",
    ] {
        let mut errs = Vec::new();
        for (case, answer) in all.iter().zip(&got).filter(|(c, _)| c.set == set) {
            assert_eq!(*answer, solve_quartic(case.coeffs), "{set} {}", case.name);
            let roots = answer
                .as_ref()
                .unwrap_or_else(|e| panic!("{set} {}: {e}", case.name));
            errs.push(case_error(roots, &case.roots));
        }
        errs.sort_by(f64::total_cmp);
        let (median, worst) = (errs[errs.len() / 2], errs[errs.len() - 1]);
        println!(
            "{set:<14} {:>4} median {median:.3e} worst {worst:.3e}",
            errs.len()
        );
        if set != "hard" {
            // roots_accuracy.rs's targets for the random sets
            assert!(median <= 1e-14, "{set}: median {median:e}");
            assert!(worst <= 1e-12, "{set}: worst {worst:e}");
        }
    }
}

#[test]
fn the_badly_scaled_fixtures_come_back_as_the_scalar_path_gives_them() {
    let all = cases(include_str!("../data/badly_scaled.csv"));
    let coeffs: Vec<[f64; 5]> = all.iter().map(|c| c.coeffs).collect();
    assert!(coeffs.len() >= 100);
    for (case, answer) in all.iter().zip(batch(&coeffs)) {
        assert_eq!(
            answer,
            solve_quartic(case.coeffs),
            "{} {}",
            case.set,
            case.name
        );
    }
}

#[test]
fn errors_and_odd_lengths_come_back_as_the_scalar_path_gives_them() {
    let coeffs = [
        [0.0, 1.0, 2.0, 3.0, 4.0],        // not a quartic
        [1.0, f64::NAN, 2.0, 3.0, 4.0],   // not finite
        [1.0, 0.0, 0.0, 0.0, 0.0],        // λ⁴ = 0
        [1e-300, 1e300, 0.0, 0.0, 0.0],   // roots beyond f64
        [1.0, -6.0, 11.0, -6.0, 0.0],     // a zero root
        [1.0, 10.1, 455.4, 40.9, 8.1],    // two complex pairs
        [1.0, -10.0, 35.0, -50.0, 24.0],  // four reals: Cardano's resolvent
        [1.0, -4000.0, 6e6, -4e9, 1e12],  // (λ − 1000)⁴
        [2.0, 0.04, 0.5, 0.0021, 0.0003], // a fifth: a chunk of one
    ];
    let got = batch(&coeffs);
    for (c, answer) in coeffs.iter().zip(&got) {
        // by their Debug text: exact, and NaN (in an error) equals itself
        assert_eq!(format!("{answer:?}"), format!("{:?}", solve_quartic(*c)));
    }
    assert_eq!(got[0], Err(RootsError::LeadingZero));
    assert!(got[5].is_ok() && got[8].is_ok());
}

#[test]
fn slices_of_different_lengths_solve_the_shorter_and_leave_the_rest() {
    let coeffs = [[1.0, 10.1, 455.4, 40.9, 8.1]; 3];
    let mut out: Vec<Answer> = vec![Err(RootsError::LeadingZero); 5];
    assert_eq!(solve_quartics(&coeffs, &mut out), 3);
    assert!(out[..3].iter().all(|a| *a == solve_quartic(coeffs[0])));
    assert!(out[3..].iter().all(|a| *a == Err(RootsError::LeadingZero)));
    assert_eq!(solve_quartics(&coeffs[..0], &mut out), 0);
}

#[test]
fn a_batch_allocates_nothing() {
    // settled lanes, fallbacks to the scalar path (Cardano's resolvent,
    // the polish, the wide path) and errors, in one batch
    let coeffs = [
        [1.0, 10.1, 455.4, 40.9, 8.1],
        [1.0, -10.0, 35.0, -50.0, 24.0],
        [1.0, -4000.0, 6e6, -4e9, 1e12],
        [1.0, -1.0e160, 7.0, 0.1, 1.0],
        [0.0, 1.0, 2.0, 3.0, 4.0],
        [2.0, 0.04, 0.5, 0.0021, 0.0003],
    ];
    let mut out = [Err(RootsError::LeadingZero); 6];
    let (n, allocations) =
        allocations_in(|| solve_quartics(std::hint::black_box(&coeffs), &mut out));
    assert_eq!((n, allocations), (6, 0));
    assert!(out[0].is_ok() && out[3].is_ok());
}

/// (λ² + p₁λ + q₁)(λ² + p₂λ + q₂)·A with the pairs' sizes apart by up to
/// 10⁸ and damping ratios from 10⁻⁶ to nearly 1: the vector path's case.
fn two_pairs() -> impl Strategy<Value = [f64; 5]> {
    (
        (-4.0f64..4.0, 1e-6f64..1.0),
        (-4.0f64..4.0, 1e-6f64..1.0),
        -3.0f64..3.0,
    )
        .prop_map(|((r1, z1), (r2, z2), a)| {
            let (w1, w2) = (10f64.powf(r1), 10f64.powf(r2));
            let (p1, q1) = (2.0 * z1 * w1, w1 * w1);
            let (p2, q2) = (2.0 * z2 * w2, w2 * w2);
            let a = 10f64.powf(a);
            [
                a,
                a * (p1 + p2),
                a * (q1 + q2 + p1 * p2),
                a * (p1 * q2 + p2 * q1),
                a * q1 * q2,
            ]
        })
}

proptest! {
    #[test]
    fn random_quartics_in_batches_match_the_scalar_path(
        c in proptest::collection::vec(
            (proptest::array::uniform5(-1e6f64..1e6), proptest::array::uniform5(-8i32..8)),
            1..11,
        ),
    ) {
        let coeffs: Vec<[f64; 5]> = c
            .iter()
            .map(|(m, e)| std::array::from_fn(|k| m[k] * 10f64.powi(e[k])))
            .collect();
        for (q, answer) in coeffs.iter().zip(batch(&coeffs)) {
            prop_assert_eq!(answer, solve_quartic(*q), "{:?}", q);
        }
    }

    #[test]
    fn two_complex_pairs_in_batches_match_the_scalar_path(
        coeffs in proptest::collection::vec(two_pairs(), 1..11),
    ) {
        for (q, answer) in coeffs.iter().zip(batch(&coeffs)) {
            prop_assert_eq!(answer, solve_quartic(*q), "{:?}", q);
        }
    }
}
