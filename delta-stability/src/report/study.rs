//! What every section draws on: the two wings of the note (45° and 60°
//! tailless deltas) evaluated across Mach number, and the same near M = 1
//! with Mangler's frequency-dependent theory.

use crate::plot::{Figure, Series};
use rayon::prelude::*;
use stability_core::case::{Case, CaseResult, DampingModel, evaluate};
use stability_core::damping::Theory;
use stability_core::study::{grid, report_wing};

/// The note's two wings, by leading-edge sweep (degrees).
pub const WINGS: [f64; 2] = [45.0, 60.0];

/// The Mach numbers of the figures: 0.5 to 2.0.
pub fn machs() -> Vec<f64> {
    grid(0.5, 2.0, 0.01)
}

/// Each case's result (`None` where a theory does not apply), in parallel.
pub fn eval_all(cases: Vec<Case>) -> Vec<Option<CaseResult>> {
    cases.par_iter().map(|c| evaluate(c).ok()).collect()
}

/// The note's wing of sweep `deg` across the Mach numbers `ms`, varied by
/// `vary`.
pub fn across(deg: f64, ms: &[f64], vary: impl Fn(Case) -> Case) -> Vec<Option<CaseResult>> {
    eval_all(ms.iter().map(|&m| vary(report_wing(deg, m))).collect())
}

/// A curve of `f` over a Mach grid of results (non-finite where no result).
pub fn curve(
    label: &str,
    ms: &[f64],
    rs: &[Option<CaseResult>],
    f: impl Fn(&CaseResult) -> Option<f64>,
) -> Series {
    Series::new(
        label,
        ms.iter()
            .zip(rs)
            .map(|(&m, r)| (m, r.as_ref().and_then(&f).unwrap_or(f64::NAN)))
            .collect(),
    )
}

/// A figure against Mach number.
pub fn mach_fig(id: &str, title: &str, y: &str) -> Figure {
    Figure::new(id, title, "Mach number M", y)
}

/// A wing's label in the legends.
pub fn label(deg: f64) -> String {
    format!("{deg}° delta")
}

/// The shared results.
pub struct Study {
    /// The Mach numbers of the figures.
    pub ms: Vec<f64>,
    /// Each wing of [`WINGS`] at each Mach number, as the note builds it.
    pub results: [Vec<Option<CaseResult>>; 2],
    /// Mach numbers near 1, and the 45° wing there with Mangler's
    /// frequency-dependent theory (39)–(40), ω̄ iterated to consistency.
    pub near_sonic: Vec<f64>,
    pub mangler: Vec<Option<CaseResult>>,
}

impl Default for Study {
    fn default() -> Self {
        Self::new()
    }
}

impl Study {
    pub fn new() -> Study {
        let ms = machs();
        let results = WINGS.map(|deg| across(deg, &ms, |c| c));
        let near_sonic = grid(0.9, 1.1, 0.01);
        let mangler = across(45.0, &near_sonic, |c| Case {
            damping: DampingModel::Theory(Theory::TransonicFrequency),
            ..c
        });
        Study {
            ms,
            results,
            near_sonic,
            mangler,
        }
    }

    /// A figure with one curve of `f` per wing.
    pub fn pair(
        &self,
        id: &str,
        title: &str,
        y: &str,
        f: &dyn Fn(&CaseResult) -> Option<f64>,
    ) -> Figure {
        let mut fig = mach_fig(id, title, y);
        for (k, &deg) in WINGS.iter().enumerate() {
            fig = fig.with(curve(&label(deg), &self.ms, &self.results[k], f));
        }
        fig
    }
}
