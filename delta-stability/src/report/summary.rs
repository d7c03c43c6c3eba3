//! What the study found, as numbers: for each wing, the Mach numbers where
//! its short period diverges or takes more than one cycle to halve, and the
//! largest μ₁ meeting the standard (`summary.json`); and the further
//! findings the note's conclusions are checked against.

use super::Study;
use super::quartic::cycles;
use super::standard::margin;
use super::study::{WINGS, across};
use rayon::prelude::*;
use serde::Serialize;
use stability_core::case::{Case, CaseResult};
use stability_core::criteria::Verdict;
use stability_core::damping::{Theory, WingInput, damping_derivatives};
use stability_core::study::{grid, intervals, max_mu1_one_cycle, report_wing};
use std::collections::BTreeMap;

/// One wing's findings.
#[derive(Debug, Clone, PartialEq)]
pub struct Wing {
    pub sweep_deg: f64,
    /// Mach intervals where the short period diverges …
    pub unstable: Vec<[f64; 2]>,
    /// … and where it takes more than one cycle to halve.
    pub fails: Vec<[f64; 2]>,
    /// The largest μ₁ meeting the standard at each Mach number (0.05 apart).
    pub max_mu1: Vec<(f64, Option<f64>)>,
    /// The smallest of those, and its Mach number.
    pub least_max_mu1: Option<(f64, f64)>,
    /// The most cycles to half amplitude, and its Mach number.
    pub most_cycles: Option<(f64, f64)>,
}

/// Everything the conclusions are checked against.
#[derive(Debug, Clone, PartialEq)]
pub struct Findings {
    /// The wings of [`WINGS`].
    pub wings: [Wing; 2],
    /// For each wing, the relative error of §9's √(−m_w/(μ₁i_B)) against
    /// the exact short period's ω̄, by Mach number (where it oscillates).
    pub omega_approx_error: [Vec<(f64, f64)>; 2],
    /// The largest ω̄ of the short period (both wings, μ₁ = 50), its wing
    /// and Mach number; and the largest ω̄ Mangler's theory converges to
    /// near M = 1 (45°).
    pub omega_max: Option<(f64, f64, f64)>,
    pub omega_mangler_max: Option<f64>,
    /// −m_θ̇ of theory (36) for the 45° delta at M = 1.2, at the ends and
    /// middle of the practical c.g. range 0.4 < x₀/c₀ < 0.6: (x₀/c₀, −m_θ̇).
    pub supersonic_damping_45: Vec<(f64, f64)>,
    /// Whether the 45° delta's margin Δm_θ̇ (eq 41) is larger with the c.g.
    /// forward (h = 0.15) than aft (h = 0.35), by Mach number.
    pub forward_cg_better: Vec<(f64, bool)>,
}

/// The point of the largest finite value, with what it carries.
fn largest<T>(points: impl Iterator<Item = (f64, T)>) -> Option<(f64, T)> {
    points
        .filter(|(v, _)| v.is_finite())
        .fold(None, |acc, p| match acc {
            Some(best) if best.0 >= p.0 => Some(best),
            _ => Some(p),
        })
}

fn wing(study: &Study, k: usize) -> Wing {
    let deg = WINGS[k];
    let rs = &study.results[k];
    let verdict_is = |v: Verdict| -> Vec<bool> {
        rs.iter()
            .map(|r| r.as_ref().map(|r| r.analysis.verdict) == Some(v))
            .collect()
    };
    let max_mu1: Vec<(f64, Option<f64>)> = grid(0.5, 2.0, 0.05)
        .par_iter()
        .map(|&m| (m, max_mu1_one_cycle(&report_wing(deg, m))))
        .collect();
    // the smallest limit: the largest of its negative
    let least =
        largest(max_mu1.iter().filter_map(|(m, v)| v.map(|v| (-v, *m)))).map(|(neg, m)| (m, -neg));
    let most = largest(
        study
            .ms
            .iter()
            .zip(rs)
            .filter_map(|(&m, r)| r.as_ref().and_then(cycles).map(|c| (c, m))),
    );
    Wing {
        sweep_deg: deg,
        unstable: intervals(&study.ms, &verdict_is(Verdict::Divergent)),
        fails: intervals(&study.ms, &verdict_is(Verdict::Fails)),
        max_mu1,
        least_max_mu1: least,
        most_cycles: most.map(|(c, m)| (m, c)),
    }
}

/// §9's ω̄ approximation against the exact ω̄: (Mach, relative error).
fn omega_approx_error(study: &Study, k: usize) -> Vec<(f64, f64)> {
    study
        .ms
        .iter()
        .zip(&study.results[k])
        .filter_map(|(&m, r)| {
            let r = r.as_ref()?;
            let exact = r.analysis.modes.short_period()?.frequency_parameter?;
            let approx = r.analysis.short_period_approximation.frequency_parameter?;
            Some((m, (approx - exact).abs() / exact))
        })
        .collect()
}

fn omega_max(study: &Study) -> Option<(f64, f64, f64)> {
    let all = WINGS.iter().zip(&study.results).flat_map(|(&deg, rs)| {
        study.ms.iter().zip(rs).filter_map(move |(&m, r)| {
            let w = r
                .as_ref()?
                .analysis
                .modes
                .short_period()?
                .frequency_parameter?;
            Some((w, (deg, m)))
        })
    });
    largest(all).map(|(w, (deg, m))| (w, deg, m))
}

fn supersonic_damping_45() -> Vec<(f64, f64)> {
    let case = report_wing(45.0, 1.2);
    let wing = WingInput::from(&case.planform);
    [0.4, 0.5, 0.6]
        .iter()
        .filter_map(|&xo| {
            let h = case.planform.h_from_xo_over_root_chord(xo);
            let d = damping_derivatives(Theory::Supersonic, &wing, h, 1.2, None).ok()?;
            Some((xo, -d.derivatives.m_thetadot()))
        })
        .collect()
}

fn forward_cg_better(study: &Study) -> Vec<(f64, bool)> {
    let at = |h: f64| -> Vec<Option<CaseResult>> { across(45.0, &study.ms, |c| Case { h, ..c }) };
    let (fwd, aft) = (at(0.15), at(0.35));
    study
        .ms
        .iter()
        .zip(fwd.iter().zip(&aft))
        .filter_map(|(&m, (a, b))| Some((m, margin(a.as_ref()?)? > margin(b.as_ref()?)?)))
        .collect()
}

pub fn findings(study: &Study) -> Findings {
    Findings {
        wings: [wing(study, 0), wing(study, 1)],
        omega_approx_error: [omega_approx_error(study, 0), omega_approx_error(study, 1)],
        omega_max: omega_max(study),
        omega_mangler_max: largest(
            study
                .mangler
                .iter()
                .filter_map(|r| r.as_ref()?.frequency.map(|f| (f.converged, ()))),
        )
        .map(|(w, _)| w),
        supersonic_damping_45: supersonic_damping_45(),
        forward_cg_better: forward_cg_better(study),
    }
}

/// One wing in `summary.json` (its keys in the file's order).
#[derive(Serialize)]
pub struct WingJson<'a> {
    cg: f64,
    fails_one_cycle_mach: &'a [[f64; 2]],
    /// (Mach, largest μ₁ or null), as pairs.
    max_mu1_one_cycle: &'a [(f64, Option<f64>)],
    mu1: f64,
    sweep_deg: f64,
    unstable_mach: &'a [[f64; 2]],
}

/// `summary.json`: for each wing (`delta_45`, `delta_60`) its sweep, c.g.,
/// μ₁, the Mach intervals where it diverges and fails the standard, and the
/// largest μ₁ meeting it by Mach number.
pub fn summary_json(f: &Findings) -> BTreeMap<String, WingJson<'_>> {
    f.wings
        .iter()
        .map(|w| {
            let case = report_wing(w.sweep_deg, 1.0);
            let json = WingJson {
                cg: case.h,
                fails_one_cycle_mach: &w.fails,
                max_mu1_one_cycle: &w.max_mu1,
                mu1: case.mu1,
                sweep_deg: w.sweep_deg,
                unstable_mach: &w.unstable,
            };
            (format!("delta_{}", w.sweep_deg), json)
        })
        .collect()
}

/// Mach intervals in words: `1.16–2.00, 2.10` or `none`.
pub fn show_intervals(v: &[[f64; 2]]) -> String {
    if v.is_empty() {
        return "none".into();
    }
    v.iter()
        .map(|[a, b]| {
            if (a - b).abs() < 1e-9 {
                format!("{a:.2}")
            } else {
                format!("{a:.2}–{b:.2}")
            }
        })
        .collect::<Vec<_>>()
        .join(", ")
}
