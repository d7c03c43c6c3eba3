//! Accuracy of `roots::solve_quartic` against reference roots computed at
//! 60 digits by mpmath from the same f64 coefficients
//! (`scripts/quartic_reference.py` → `tests/data/quartic_reference.csv`).
//!
//! Error of a case: the largest relative error over its four roots, after
//! matching computed to reference roots by the best of the 24 pairings
//! (Orellana & De Michele's measure). Run with `--nocapture` for the table.

use crate::support;

use num_complex::Complex64;
use stability_core::numerics::roots::solve_quartic;
use support::{case_error, cases as read};

fn cases() -> Vec<support::Case> {
    read(include_str!("../data/quartic_reference.csv"))
}

/// The condition number of each reference root:
/// κ = Σ|cₖ||r|^(4−k) / (|r|·|P′(r)|) — the relative forward error per unit
/// relative backward error.
fn condition(coeffs: &[f64; 5], r: Complex64) -> f64 {
    let n = r.norm();
    let abs_sum: f64 = coeffs
        .iter()
        .enumerate()
        .map(|(k, c)| c.abs() * n.powi(4 - k as i32))
        .sum();
    let dp = ((r * (4.0 * coeffs[0]) + 3.0 * coeffs[1]) * r + 2.0 * coeffs[2]) * r + coeffs[3];
    if n == 0.0 {
        1.0
    } else {
        abs_sum / (n * dp.norm())
    }
}

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

#[test]
fn random_sets_meet_the_targets() {
    let all = cases();
    println!(
        "{:<14} {:>6} {:>12} {:>12} {:>12}",
        "set", "cases", "median", "90%", "worst"
    );
    for set in [
        "real4",
        "pair_real2",
        "pairs2",
        "real4_s",
        "pair_real2_s",
        "pairs2_s",
        "stability",
    ] {
        let mut errs: Vec<f64> = all
            .iter()
            .filter(|c| c.set == set)
            .map(|c| {
                let got =
                    solve_quartic(c.coeffs).unwrap_or_else(|e| panic!("{set} {}: {e}", c.name));
                case_error(&got, &c.roots)
            })
            .collect();
        let n = errs.len();
        assert!(n >= 400, "{set}: {n} cases");
        let med = median(&mut errs);
        let p90 = errs[n * 9 / 10];
        let worst = errs[n - 1];
        println!("{set:<14} {n:>6} {med:>12.3e} {p90:>12.3e} {worst:>12.3e}");
        assert!(med <= 1e-14, "{set}: median {med:e}");
        assert!(worst <= 1e-12, "{set}: worst {worst:e}");
    }
}

#[test]
fn hard_cases_are_as_accurate_as_their_conditioning_allows() {
    println!("{:<48} {:>11} {:>11}", "hard case", "error", "ε·κ_max");
    for c in cases().iter().filter(|c| c.set == "hard") {
        let got = solve_quartic(c.coeffs).unwrap_or_else(|e| panic!("{}: {e}", c.name));
        assert!(
            got.iter().all(|z| z.re.is_finite() && z.im.is_finite()),
            "{}",
            c.name
        );
        let err = case_error(&got, &c.roots);
        let kappa = c
            .roots
            .iter()
            .map(|&r| condition(&c.coeffs, r))
            .fold(0.0, f64::max);
        println!(
            "{:<48} {err:>11.3e} {:>11.3e}",
            c.name,
            f64::EPSILON * kappa
        );
        // Simple roots, however clustered (κ up to 1e11 here): the compensated
        // polish makes them accurate to ~ε + κε², so 1e-14 whatever κ. A
        // multiple root (κ = ∞): the ε^(1/m) law would allow 2ε^(1/4); these
        // exact multiple roots come back exactly, but only the law is promised.
        let bound = if kappa.is_finite() {
            1e-14
        } else {
            2.0 * f64::EPSILON.powf(0.25)
        };
        assert!(err <= bound, "{}: error {err:e} > bound {bound:e}", c.name);
    }
}
