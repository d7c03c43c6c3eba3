//! The report's study (§8–9, Figs 25–33): the built-in cases, and the
//! questions asked of them — where the short period diverges, where it fails
//! the one-cycle standard, and the largest μ₁ that meets it.

use crate::aerodynamics::lifting_surface::Harmonic;
use crate::aerodynamics::models::aero::AeroModel;
use crate::design::case::{Case, DampingModel, evaluate_point_with};
use crate::geometry::{Planform, Size};

/// The report's tailless true delta of leading-edge sweep `deg`: c.g. at
/// h = 0.25 (x₀/c₀ = 0.5), μ₁ = 50 (Figs 27–31), i_B = 0.08 and
/// C_L·M² = 0.05 (neither stated by the report; see docs/models.md), the
/// default damping model (`faired`: one lifting surface through M = 1).
pub fn report_wing(deg: f64, mach: f64) -> Case {
    Case {
        planform: Planform::new(deg.to_radians(), 0.0, Size::RootChord(10.0))
            .expect("a valid delta"),
        mach,
        h: 0.25,
        mu1: 50.0,
        i_b: 0.08,
        cl_m2: 0.05,
        aero: AeroModel::default(),
        damping: DampingModel::Faired,
        omega_bar: None,
        iterate_frequency: true,
        frequency_method: Default::default(),
    }
}

pub use crate::numerics::grid::{GRID_DIGITS, grid};

/// The intervals [from, to] of consecutive grid points where `flag` holds.
pub fn intervals(x: &[f64], flag: &[bool]) -> Vec<[f64; 2]> {
    let mut out = Vec::new();
    let mut start: Option<f64> = None;
    for (i, (&xi, &f)) in x.iter().zip(flag).enumerate() {
        match (f, start) {
            (true, None) => start = Some(xi),
            (false, Some(s)) => {
                out.push([s, x[i - 1]]);
                start = None;
            }
            _ => {}
        }
    }
    if let (Some(s), Some(&last)) = (start, x.last()) {
        out.push([s, last]);
    }
    out
}

/// The scan of [`max_mu1_one_cycle`]: log₁₀μ₁ from 0 to [`LOG_MU1_TOP`] in
/// steps of 0.05.
const LOG_MU1_STEP: f64 = 0.05;
const LOG_MU1_STEPS: usize = 80;
/// The largest μ₁ asked about: 10⁴.
const LOG_MU1_TOP: f64 = LOG_MU1_STEP * LOG_MU1_STEPS as f64;
/// The bisection stops when the bracket of log₁₀μ₁ is this narrow: μ₁ to
/// one part in a million (17 halvings of a step).
const LOG_MU1_TOLERANCE: f64 = 4e-7;

/// The largest μ₁ in [1, 10⁴] at which `case` meets the one-cycle standard:
/// a scan of log₁₀μ₁ in steps of 0.05 from the top down stops at the first
/// (largest) μ₁ that meets it, then bisection refines the boundary above it
/// to one part in 10⁶. (The standard gets harder as μ₁ grows, §8, but not
/// monotonically at very small μ₁, where the short period may not
/// oscillate: hence the scan, whose first hit from the top is the last hit
/// of a scan from the bottom — the same bracket, in far fewer evaluations
/// where the limit is large.) `None` when no μ₁ in the range meets it; 10⁴
/// when every one does. A frequency-dependent damping model (the default
/// `faired` below M = 1.2) has its lattice interpolated between tabled ω̄
/// ([`Harmonic::Interpolated`]).
pub fn max_mu1_one_cycle(case: &Case) -> Option<f64> {
    let meets = |log_mu1: f64| meets_at(case, log_mu1);
    let log_mu1 = |i: usize| i as f64 * LOG_MU1_STEP;
    let last = (0..=LOG_MU1_STEPS).rev().find(|&i| meets(log_mu1(i)))?;
    if last == LOG_MU1_STEPS {
        return Some(10f64.powf(LOG_MU1_TOP));
    }
    Some(10f64.powf(refine(meets, log_mu1(last), log_mu1(last + 1))))
}

/// Whether `case` at μ₁ = 10^`log_mu1` meets the one-cycle standard (§8).
fn meets_at(case: &Case, log_mu1: f64) -> bool {
    let mut c = case.clone();
    c.mu1 = 10f64.powf(log_mu1);
    // the lattice of a frequency-dependent model interpolated between its
    // tabled ω̄: every μ₁ tried has its own
    evaluate_point_with(&c, Harmonic::Interpolated)
        .map(|r| r.analysis.verdict.is_met())
        .unwrap_or(false)
}

/// Bisection of [lo, hi] (`meets` at lo, not at hi) to [`LOG_MU1_TOLERANCE`];
/// the last lo, which meets it.
fn refine(meets: impl Fn(f64) -> bool, mut lo: f64, mut hi: f64) -> f64 {
    while hi - lo > LOG_MU1_TOLERANCE {
        let mid = 0.5 * (lo + hi);
        if meets(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::criteria::Verdict;

    #[test]
    fn intervals_of_a_flag() {
        let x = [1.0, 2.0, 3.0, 4.0, 5.0];
        assert_eq!(
            intervals(&x, &[false, true, true, false, true]),
            vec![[2.0, 3.0], [5.0, 5.0]]
        );
        assert!(intervals(&x, &[false; 5]).is_empty());
    }

    #[test]
    fn the_largest_mu1_is_on_the_boundary_of_the_standard() {
        let case = report_wing(60.0, 1.5);
        let mu = max_mu1_one_cycle(&case).unwrap();
        // as the search evaluates (the lifting surface interpolated)
        let at = |m: f64| {
            let mut c = case.clone();
            c.mu1 = m;
            evaluate_point_with(&c, Harmonic::Interpolated)
                .unwrap()
                .analysis
                .verdict
        };
        assert_eq!(at(mu * 0.999), Verdict::Meets);
        assert_ne!(at(mu * 1.001), Verdict::Meets);
    }

    /// The scan from the top finds the bracket that a whole scan from the
    /// bottom (the previous algorithm: every step, then the last that
    /// meets) finds, so the answer is the same: where the limit is large,
    /// where it is small, and where no μ₁ meets the standard.
    #[test]
    fn the_scan_from_the_top_finds_the_whole_scans_bracket() {
        let whole_scan = |case: &Case| -> Option<f64> {
            let flags: Vec<bool> = (0..=LOG_MU1_STEPS)
                .map(|i| meets_at(case, i as f64 * LOG_MU1_STEP))
                .collect();
            let last = flags.iter().rposition(|&f| f)?;
            if last == LOG_MU1_STEPS {
                return Some(10f64.powf(LOG_MU1_TOP));
            }
            let (lo, hi) = (last as f64 * LOG_MU1_STEP, (last + 1) as f64 * LOG_MU1_STEP);
            Some(10f64.powf(refine(|x| meets_at(case, x), lo, hi)))
        };
        // The scan is the question, not the model: the default model on a
        // subsonic wing (its lattice interpolated in ω̄, as the report has
        // it), and the quasi-steady faired-slender model (closed forms:
        // the 81 steps and the bisection of the whole scan cost nothing)
        // through M = 1 to 2, where the limit is large, small or absent.
        let mut found = (false, false);
        for (deg, mach, damping) in [
            (60.0, 0.8, DampingModel::Faired),
            (60.0, 1.5, DampingModel::FairedSlender),
            (45.0, 1.4, DampingModel::FairedSlender),
            (45.0, 1.25, DampingModel::FairedSlender),
            (45.0, 1.0, DampingModel::FairedSlender),
            (70.0, 2.0, DampingModel::FairedSlender),
        ] {
            let case = Case {
                damping,
                ..report_wing(deg, mach)
            };
            let (top, whole) = (max_mu1_one_cycle(&case), whole_scan(&case));
            assert_eq!(top, whole, "{deg}° at M = {mach}, {damping:?}");
            match top {
                Some(mu1) if mu1 < 10f64.powf(LOG_MU1_TOP) => found.0 = true,
                None => found.1 = true,
                _ => {}
            }
        }
        assert_eq!(found, (true, true), "(a largest μ₁ inside the range, none)");
    }
}
