//! A design's own report (`delta-stability report CONFIG`): the config's
//! design point — any planform, flight condition (physical or
//! non-dimensional) and model — evaluated across Mach number exactly as
//! `analyze --mach M` evaluates it ([`stability_io::design_point::at_mach`]),
//! then drawn as the note's study is: the roots and modes (eq 8's cycles
//! to half amplitude, ζ, ωₙ, period and time to half or double — in
//! seconds where the flight condition is physical), §8's standard and its
//! margin Δm_θ̇ (eq 41), the MIL-F-8785C levels and CAP, §9's margins
//! (eq 42) and the aerodynamic centre, every derivative with its source
//! ([`figures`]); the page ([`page`]); and `summary.json`, the per-Mach
//! table ([`stability_io::views::DesignReportJson`]).
//!
//! Everything here computes; writing the files is `cmd::report`'s.

pub mod configuration;
pub mod figures;
pub mod page;

use rayon::prelude::*;
use stability_core::dynamics::modes::Mode;
use stability_core::geometry::sonic_leading_edge_mach;
use stability_core::numerics::grid::grid;
use stability_io::class::ClassChoice;
use stability_io::config::Config;
use stability_io::design_point::{Results, at_mach};
use stability_io::plot::{Band, Figure, Series};

/// The default Mach numbers of a design's report: 0.5 to 2.0 in steps of
/// 0.05, widened (in the same steps) to take in the config's own Mach
/// number.
pub fn default_machs(own: f64) -> Vec<f64> {
    const STEP: f64 = 0.05;
    let from = (own / STEP).floor() * STEP;
    let to = (own / STEP).ceil() * STEP;
    grid(from.clamp(STEP, 0.5), to.max(2.0), STEP)
}

/// The most Mach numbers one report takes (each is a full design point:
/// beyond this the page and its figures say no more).
pub const MAX_MACHS: usize = 2001;

/// A design evaluated across Mach number.
pub struct Design {
    pub cfg: Config,
    /// The airplane class of the CAP levels (MIL-F-8785C §1.3).
    pub class: ClassChoice,
    /// Each Mach number with its results, or why it has none.
    pub points: Vec<(f64, Result<Results, String>)>,
}

impl Design {
    /// `cfg` at each Mach number of `machs` (in parallel).
    pub fn new(cfg: Config, machs: &[f64], class: ClassChoice) -> Design {
        let points = machs
            .par_iter()
            .map(|&m| (m, at_mach(&cfg, m, class.class).map_err(|e| e.to_string())))
            .collect();
        Design { cfg, class, points }
    }

    /// Whether the flight condition is physical (times in seconds).
    pub fn physical(&self) -> bool {
        self.cfg.physical.is_some()
    }

    /// The unit of the times: seconds, or τ = m/(½ρSV).
    pub fn time_unit(&self) -> &'static str {
        if self.physical() { "s" } else { "τ" }
    }

    /// The unit of the rates: rad/s, or 1/τ.
    pub fn rate_unit(&self) -> &'static str {
        if self.physical() { "rad/s" } else { "1/τ" }
    }

    /// The points with results.
    pub fn results(&self) -> impl Iterator<Item = (f64, &Results)> {
        self.points
            .iter()
            .filter_map(|(m, r)| r.as_ref().ok().map(|r| (*m, r)))
    }

    /// A curve of `f` across the Mach numbers (a gap where no result, or
    /// no value).
    pub fn curve(&self, label: &str, f: impl Fn(&Results) -> Option<f64>) -> Series {
        Series::new(
            label,
            self.points
                .iter()
                .map(|(m, r)| (*m, r.as_ref().ok().and_then(&f).unwrap_or(f64::NAN)))
                .collect(),
        )
    }

    /// Runs of consecutive Mach numbers with results over which `f` says
    /// the same, each `(what, first, last)`.
    pub fn runs(&self, f: impl Fn(&Results) -> String) -> Vec<(String, f64, f64)> {
        let mut out: Vec<(String, f64, f64)> = Vec::new();
        let mut open = false;
        for (m, r) in &self.points {
            let Ok(r) = r else {
                open = false;
                continue;
            };
            let what = f(r);
            match out.last_mut() {
                Some(last) if open && last.0 == what => last.2 = *m,
                _ => out.push((what, *m, *m)),
            }
            open = true;
        }
        out
    }

    /// `f`'s runs in words: "lifting-surface for M 0.5–0.85; method for
    /// M 0.9–2".
    pub fn sources(&self, f: impl Fn(&Results) -> String) -> String {
        let runs: Vec<String> = self
            .runs(f)
            .into_iter()
            .map(|(what, a, b)| match a == b {
                true => format!("{what} at M {}", stability_io::plot::short(a)),
                false => format!(
                    "{what} for M {}–{}",
                    stability_io::plot::short(a),
                    stability_io::plot::short(b)
                ),
            })
            .collect();
        runs.join("; ")
    }

    /// A figure against Mach number, named `file`, with the regimes behind
    /// it: the bands where the design's coefficients or damping
    /// derivatives are faired between theories
    /// ([`stability_study::regimes::shaded`]), the damping theory of each Mach
    /// number named along the top, and where the leading edge turns sonic.
    pub fn figure(&self, title: &str, y: &str) -> Figure {
        let mut fig = Figure::new("design", title, "Mach number M", y);
        let planform = self.cfg.case.planform;
        let mut joins = stability_study::regimes::coefficient_joins(
            self.results().map(|(_, r)| &r.result),
            std::slice::from_ref(&planform),
            true,
        );
        joins.extend(stability_study::regimes::model_damping_joins(
            self.cfg.case.damping,
            &planform,
        ));
        let (lo, hi) = self.mach_range();
        let joins: Vec<(f64, f64)> = stability_study::regimes::merged(joins)
            .into_iter()
            .filter(|&(a, b)| b > lo && a < hi)
            .collect();
        fig = stability_study::regimes::shaded(fig, &joins);
        fig.regions = self.theory_regions();
        let edge = sonic_leading_edge_mach(self.cfg.case.planform.sweep_le);
        if edge > lo && edge < hi {
            fig.markers.push(stability_io::plot::VerticalLine {
                x: edge,
                label: "leading edge sonic".into(),
            });
        }
        fig
    }

    /// The Mach numbers' range.
    fn mach_range(&self) -> (f64, f64) {
        let ms = self.points.iter().map(|p| p.0);
        let lo = ms.clone().fold(f64::INFINITY, f64::min);
        (lo, ms.fold(f64::NEG_INFINITY, f64::max))
    }

    /// The damping theory of each run of Mach numbers, as regions along
    /// the top (each reaching halfway to its neighbours' Mach numbers).
    fn theory_regions(&self) -> Vec<Band> {
        let runs = self.runs(|r| r.result.damping.theory.name().to_string());
        if runs.len() < 2 {
            return Vec::new();
        }
        let mut out: Vec<Band> = Vec::new();
        for (k, (what, a, b)) in runs.iter().enumerate() {
            let from = match k {
                0 => f64::NEG_INFINITY,
                _ => 0.5 * (runs[k - 1].2 + a),
            };
            let to = runs.get(k + 1).map_or(f64::INFINITY, |n| 0.5 * (b + n.1));
            out.push(Band {
                from,
                to,
                label: what.clone(),
            });
        }
        out
    }
}

/// The short period of a result, and its phugoid.
pub fn short_period(r: &Results) -> Option<&Mode> {
    r.result.analysis.modes.short_period()
}

pub fn phugoid(r: &Results) -> Option<&Mode> {
    r.result.analysis.modes.phugoid()
}

/// A mode's times and rates in the design's unit: seconds (and rad/s)
/// where τ is known, else τ (and 1/τ).
pub fn times(r: &Results, m: &Mode) -> stability_core::dynamics::modes::ModeTimes {
    let t = m.times();
    r.tau().map_or(t, |tau| t.in_units_of(tau))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_machs_take_in_the_configs_own() {
        let ms = default_machs(0.9);
        assert_eq!((ms[0], *ms.last().unwrap(), ms.len()), (0.5, 2.0, 31));
        let ms = default_machs(2.43);
        assert_eq!((ms[0], *ms.last().unwrap()), (0.5, 2.45));
        let ms = default_machs(0.32);
        assert_eq!((ms[0], *ms.last().unwrap()), (0.3, 2.0));
        assert!(ms.windows(2).all(|w| (w[1] - w[0] - 0.05).abs() < 1e-12));
    }
}
