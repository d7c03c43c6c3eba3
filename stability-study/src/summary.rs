//! What the study found, as numbers: for each wing, the Mach numbers where
//! its short period diverges or takes more than one cycle to halve, and the
//! largest μ₁ meeting the standard (`summary.json`); and the further
//! findings the note's conclusions are checked against.
//!
//! [`Findings`] holds a [`Study`] — ours, or the same under other values of
//! the unstated inputs, which the conclusions are swept over — and works out
//! what it is asked: what needs no further case is found at once, what
//! evaluates further cases (the largest μ₁, other c.g. positions, sweeps and
//! planforms) when first asked, once. [`summary_file`] writes the file
//! whole, with how sure the headlines are and the tail the 45° delta needs.

use super::Study;
use super::conclusions::{ConclusionJson, Judged, conclusions_json};
use super::quartic::cycles;
use super::standard::{CGS, margin};
use super::study::{Assumed, WINGS};
use crate::certainty::{Certainty, CertaintyJson};
use crate::study::{NOTE_SUPERSONIC, SUBCRITICAL};
use crate::tail::{TailJson, TailNeeded};
use rayon::prelude::*;
use serde::Serialize;
use stability_core::aerodynamics::damping::{Theory, WingInput, damping_derivatives};
use stability_core::criteria::Verdict;
use stability_core::design::case::{Case, CaseResult};
use stability_core::design::study::{grid, intervals, max_mu1_one_cycle, report_wing};
use stability_core::dynamics::response::TwoDof;
use stability_core::geometry::{Planform, Size, cropped_h};
use stability_io::diag::InputError;
use std::sync::OnceLock;

/// The Mach numbers (0.5 to 2, 0.05 apart) at which the largest μ₁ meeting
/// the standard is found.
pub fn mu1_machs() -> Vec<f64> {
    grid(0.5, 2.0, 0.05)
}

/// The sweeps §8's diminishing returns are judged on: its 60°, and Fig 25's
/// sweeps either side of it.
pub const SWEEPS_ABOUT_60: [f64; 3] = [45.0, 60.0, 75.0];

/// §10's cropped tips: taper λ = 1/7 (as Fig 36).
pub const CROPPED_TAPER: f64 = 1.0 / 7.0;

/// §7's practical c.g. range 0.4 < x₀/c₀ < 0.6, sampled 0.02 apart.
pub fn practical_cg_range() -> Vec<f64> {
    grid(0.4, 0.6, 0.02)
}

/// One wing's short period at μ₁ = 50 across Mach number.
#[derive(Debug, Clone, PartialEq)]
pub struct Wing {
    pub sweep_deg: f64,
    /// Mach intervals where the short period diverges …
    pub unstable: Vec<[f64; 2]>,
    /// … and where it takes more than one cycle to halve.
    pub fails: Vec<[f64; 2]>,
    /// The Mach numbers of the study, and whether the short period diverges
    /// or fails the standard there.
    pub inadequate: Vec<(f64, bool)>,
    /// The most cycles to half amplitude, and its Mach number.
    pub most_cycles: Option<(f64, f64)>,
}

/// The largest μ₁ meeting the one-cycle standard, by Mach number.
#[derive(Debug, Clone, PartialEq)]
pub struct MaxMu1 {
    /// (Mach, the largest μ₁ in 1–10⁴, or `None` where no μ₁ meets it).
    pub by_mach: Vec<(f64, Option<f64>)>,
}

/// The worst case of [`MaxMu1`] over Mach number.
#[derive(Debug, Clone, PartialEq)]
pub enum Worst {
    /// At these Mach numbers no μ₁ meets the standard: the worst case,
    /// whatever the largest μ₁ elsewhere.
    NoneMeets(Vec<[f64; 2]>),
    /// Some μ₁ meets it at every Mach number: the smallest largest μ₁.
    Least { mach: f64, mu1: f64 },
}

impl MaxMu1 {
    /// The worst case: the Mach numbers where no μ₁ meets the standard if
    /// there are any, else the smallest largest μ₁; `None` with no Mach
    /// numbers.
    pub fn worst(&self) -> Option<Worst> {
        let (ms, none): (Vec<f64>, Vec<bool>) =
            self.by_mach.iter().map(|(m, v)| (*m, v.is_none())).unzip();
        if none.iter().any(|&n| n) {
            return Some(Worst::NoneMeets(intervals(&ms, &none)));
        }
        let least = largest(self.by_mach.iter().filter_map(|(m, v)| v.map(|v| (-v, *m))));
        least.map(|(neg, mach)| Worst::Least { mach, mu1: -neg })
    }
}

impl Worst {
    /// In words: "no μ₁ meets it at M 1.20–1.30" or "99.6 at M = 2.00".
    pub fn describe(&self) -> String {
        match self {
            Worst::NoneMeets(at) => format!("no μ₁ meets it at M {}", show_intervals(at)),
            Worst::Least { mach, mu1 } => {
                format!(
                    "{} at M = {mach:.2}",
                    stability_core::numerics::display::sig(*mu1, 3)
                )
            }
        }
    }
}

/// The 45° and 60° deltas with their tips cropped (§10, Fig 36) at
/// M = 1.2: −m_θ̇ of the true delta and of the cropped one, c.g. in place.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cropping {
    pub sweep_deg: f64,
    pub true_delta: f64,
    pub cropped: f64,
}

impl Cropping {
    /// The gain in −m_θ̇ from cropping.
    pub fn gain(&self) -> f64 {
        self.cropped - self.true_delta
    }
}

/// §11's two-degree-of-freedom short period (eq 45) at one Mach number, per
/// unit t̂ (Fig 37's time): the damping b/2 and the frequency
/// √(k − b²/4) (0 where the pair does not oscillate).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TwoDofPoint {
    pub mach: f64,
    pub damping: f64,
    pub frequency: f64,
}

/// Everything the conclusions are checked against, for one [`Study`].
pub struct Findings {
    pub study: Study,
    /// The wings of [`WINGS`].
    pub wings: [Wing; 2],
    /// For each wing, the relative error of §9's √(−m_w/(μ₁i_B)) against
    /// the exact short period's ω̄, by Mach number (where it oscillates).
    pub omega_approx_error: [Vec<(f64, f64)>; 2],
    /// The largest ω̄ of the short period (both wings, μ₁ = 50), its wing
    /// and Mach number; and the largest ω̄ Mangler's theory converges to
    /// near M = 1 (45°; ours only).
    pub omega_max: Option<(f64, f64, f64)>,
    pub omega_mangler_max: Option<f64>,
    /// The 45° delta's short period by eq (45) at subcritical speeds
    /// (M ≤ 0.9, §7: where lifting-surface theory holds), Fig 37's.
    pub subcritical: Vec<TwoDofPoint>,
    /// For each wing at subcritical speeds, m_ẇ's share of the short
    /// period's damping b (eq 45): 1 − b(m_ẇ = 0)/b.
    pub mwdot_share: [Vec<(f64, f64)>; 2],
    max_mu1: [OnceLock<MaxMu1>; 2],
    forward_cg_better: OnceLock<Vec<(f64, bool)>>,
    m_thetadot_36: OnceLock<Vec<(f64, f64)>>,
    cropping: OnceLock<Option<[Cropping; 2]>>,
    sweep_margins: OnceLock<Vec<(f64, [f64; 3])>>,
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
    let rs = &study.results[k];
    let verdicts: Vec<Option<Verdict>> = rs
        .iter()
        .map(|r| r.as_ref().map(|r| r.analysis.verdict))
        .collect();
    let is = |v: Verdict| -> Vec<bool> { verdicts.iter().map(|x| *x == Some(v)).collect() };
    let most = largest(
        study
            .ms
            .iter()
            .zip(rs)
            .filter_map(|(&m, r)| r.as_ref().and_then(cycles).map(|c| (c, m))),
    );
    Wing {
        sweep_deg: WINGS[k],
        unstable: intervals(&study.ms, &is(Verdict::Divergent)),
        fails: intervals(&study.ms, &is(Verdict::Fails)),
        inadequate: study
            .ms
            .iter()
            .zip(&verdicts)
            .map(|(&m, v)| (m, matches!(v, Some(Verdict::Divergent | Verdict::Fails))))
            .collect(),
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

/// The study's results of wing `k` at subcritical speeds (M ≤ 0.9).
fn subcritical_results(study: &Study, k: usize) -> impl Iterator<Item = (f64, &CaseResult)> {
    study
        .ms
        .iter()
        .zip(&study.results[k])
        .filter(|(m, _)| {
            stability_core::numerics::grid::within(**m, f64::NEG_INFINITY, SUBCRITICAL)
        })
        .filter_map(|(&m, r)| Some((m, r.as_ref()?)))
}

fn subcritical(study: &Study) -> Vec<TwoDofPoint> {
    subcritical_results(study, 0)
        .map(|(mach, r)| {
            let two = TwoDof::of(&r.derivatives);
            TwoDofPoint {
                mach,
                damping: two.b / 2.0,
                frequency: (two.k - two.b * two.b / 4.0).max(0.0).sqrt(),
            }
        })
        .collect()
}

fn mwdot_share(study: &Study, k: usize) -> Vec<(f64, f64)> {
    subcritical_results(study, k)
        .map(|(m, r)| {
            let without = stability_core::Derivatives {
                m_wdot: 0.0,
                ..r.derivatives
            };
            (
                m,
                1.0 - TwoDof::of(&without).b / TwoDof::of(&r.derivatives).b,
            )
        })
        .collect()
}

impl Findings {
    /// What `study` found; the rest is found when first asked.
    pub fn new(study: Study) -> Findings {
        Findings {
            wings: [wing(&study, 0), wing(&study, 1)],
            omega_approx_error: [omega_approx_error(&study, 0), omega_approx_error(&study, 1)],
            omega_max: omega_max(&study),
            omega_mangler_max: largest(
                study
                    .mangler
                    .iter()
                    .filter_map(|r| r.as_ref()?.frequency.map(|f| (f.converged, ()))),
            )
            .map(|(w, _)| w),
            subcritical: subcritical(&study),
            mwdot_share: [mwdot_share(&study, 0), mwdot_share(&study, 1)],
            max_mu1: Default::default(),
            forward_cg_better: OnceLock::new(),
            m_thetadot_36: OnceLock::new(),
            cropping: OnceLock::new(),
            sweep_margins: OnceLock::new(),
            study,
        }
    }

    /// The values of the unstated inputs behind these findings.
    pub fn assumed(&self) -> Assumed {
        self.study.assumed
    }

    /// The largest μ₁ meeting the standard for wing `k`, at
    /// [`mu1_machs`] (bisection, `stability_core::design::study`).
    pub fn max_mu1(&self, k: usize) -> &MaxMu1 {
        self.max_mu1[k].get_or_init(|| MaxMu1 {
            by_mach: mu1_machs()
                .par_iter()
                .map(|&m| (m, max_mu1_one_cycle(&self.study.case(WINGS[k], m))))
                .collect(),
        })
    }

    /// Whether the 45° delta's margin Δm_θ̇ (eq 41) is larger with the c.g.
    /// forward than aft (Fig 26's c.g. positions, `standard::CGS`), by Mach
    /// number.
    pub fn forward_cg_better(&self) -> &[(f64, bool)] {
        self.forward_cg_better.get_or_init(|| {
            let ms = &self.study.ms;
            let [fwd, aft] = CGS.map(|h| self.study.across(WINGS[0], ms, |c| Case { h, ..c }));
            ms.iter()
                .zip(fwd.iter().zip(&aft))
                .filter_map(|(&m, (a, b))| Some((m, margin(a.as_ref()?)? > margin(b.as_ref()?)?)))
                .collect()
        })
    }

    /// m_θ̇ of theory (36) for the 45° delta at M = 1.2 across §7's
    /// practical c.g. range: (x₀/c₀, m_θ̇). (The derivatives do not depend
    /// on the unstated inputs.)
    pub fn m_thetadot_36(&self) -> &[(f64, f64)] {
        self.m_thetadot_36.get_or_init(|| {
            let case = report_wing(WINGS[0], NOTE_SUPERSONIC);
            let wing = WingInput::from(&case.planform);
            practical_cg_range()
                .iter()
                .filter_map(|&xo| {
                    let h = case.planform.h_from_xo_over_root_chord(xo);
                    let d = damping_derivatives(Theory::Supersonic, &wing, h, case.mach, None);
                    Some((xo, d.ok()?.derivatives.m_thetadot()))
                })
                .collect()
        })
    }

    /// Both wings cropped to taper 1/7 at M = 1.2, the c.g. in place, with
    /// the study's damping model (as Fig 36); `None` where a case fails.
    pub fn cropping(&self) -> Option<&[Cropping; 2]> {
        self.cropping
            .get_or_init(|| Some([self.crop(WINGS[0])?, self.crop(WINGS[1])?]))
            .as_ref()
    }

    fn crop(&self, deg: f64) -> Option<Cropping> {
        let sweep = deg.to_radians();
        let case = self.study.case(deg, NOTE_SUPERSONIC);
        let h = cropped_h(case.h, sweep, CROPPED_TAPER).ok()?;
        let planform = Planform::new(
            sweep,
            CROPPED_TAPER,
            Size::RootChord(case.planform.root_chord),
        )
        .ok()?;
        let m_thetadot = |c: &Case| -> Option<f64> {
            let r = super::study::eval(c)?;
            Some(-r.damping.derivatives.m_thetadot())
        };
        Some(Cropping {
            sweep_deg: deg,
            true_delta: m_thetadot(&case)?,
            cropped: m_thetadot(&Case {
                planform,
                h,
                ..case
            })?,
        })
    }

    /// The margin Δm_θ̇ (eq 41) of the wings of [`SWEEPS_ABOUT_60`] by Mach number
    /// (where all three have one), as Fig 25.
    pub fn sweep_margins(&self) -> &[(f64, [f64; 3])] {
        self.sweep_margins.get_or_init(|| {
            let s = &self.study;
            let extra = s.across(SWEEPS_ABOUT_60[2], &s.ms, |c| c);
            let at = |rs: &[Option<CaseResult>], i: usize| rs[i].as_ref().and_then(margin);
            (0..s.ms.len())
                .filter_map(|i| {
                    let m = [at(&s.results[0], i)?, at(&s.results[1], i)?, at(&extra, i)?];
                    Some((s.ms[i], m))
                })
                .collect()
        })
    }
}

/// The worst case of the largest μ₁ in `summary.json`: its value (`null`
/// where no μ₁ meets the standard) and the Mach intervals where it is
/// found.
#[derive(Serialize)]
pub struct WorstJson {
    mu1: Option<f64>,
    mach: Vec<[f64; 2]>,
}

impl From<&Worst> for WorstJson {
    fn from(w: &Worst) -> Self {
        match w {
            Worst::NoneMeets(at) => WorstJson {
                mu1: None,
                mach: at.clone(),
            },
            Worst::Least { mach, mu1 } => WorstJson {
                mu1: Some(*mu1),
                mach: vec![[*mach, *mach]],
            },
        }
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
    worst_max_mu1: Option<WorstJson>,
}

/// The values taken for the unstated inputs, in `summary.json`.
#[derive(Serialize)]
pub struct AssumedJson {
    i_b: f64,
    cl_m2: f64,
}

/// `summary.json`: the unstated inputs' values; the note's conclusions,
/// each with ours and whether it is reproduced; and for each wing
/// (`delta_45`, `delta_60`) its sweep, c.g., μ₁, the Mach intervals where it
/// diverges and fails the standard, the largest μ₁ meeting it by Mach
/// number, and the worst case of that.
#[derive(Serialize)]
pub struct SummaryJson<'a> {
    assumptions: AssumedJson,
    conclusions: Vec<ConclusionJson>,
    delta_45: WingJson<'a>,
    delta_60: WingJson<'a>,
}

fn wing_json(f: &Findings, k: usize) -> WingJson<'_> {
    let w = &f.wings[k];
    let case = f.study.case(w.sweep_deg, 1.0);
    let max_mu1 = f.max_mu1(k);
    WingJson {
        cg: case.h,
        fails_one_cycle_mach: &w.fails,
        max_mu1_one_cycle: &max_mu1.by_mach,
        mu1: case.mu1,
        sweep_deg: w.sweep_deg,
        unstable_mach: &w.unstable,
        worst_max_mu1: max_mu1.worst().as_ref().map(WorstJson::from),
    }
}

pub fn summary_json<'a>(f: &'a Findings, judged: &[Judged]) -> SummaryJson<'a> {
    let a = f.assumed();
    SummaryJson {
        assumptions: AssumedJson {
            i_b: a.i_b,
            cl_m2: a.cl_m2,
        },
        conclusions: conclusions_json(judged),
        delta_45: wing_json(f, 0),
        delta_60: wing_json(f, 1),
    }
}

/// `summary.json` whole: the findings and conclusions ([`SummaryJson`]),
/// then the section "how sure" under `how_sure` ([`CertaintyJson`]) and
/// §10 (ours), the smallest tailplane and foreplane meeting the standard
/// ([`crate::tail`]), under `tail_needed`.
#[derive(Serialize)]
pub struct SummaryWithHowSure<'a> {
    #[serde(flatten)]
    summary: SummaryJson<'a>,
    how_sure: CertaintyJson,
    tail_needed: TailJson,
}

/// `summary.json`'s text (pretty JSON), every number checked finite
/// ([`stability_io::finite::guard`]: the error names the file).
pub fn summary_file(
    f: &Findings,
    judged: &[Judged],
    sure: &Certainty,
    tail: &TailNeeded,
) -> Result<String, InputError> {
    let s = SummaryWithHowSure {
        summary: summary_json(f, judged),
        how_sure: sure.json(),
        tail_needed: tail.json(),
    };
    stability_io::finite::guard("summary.json", &s)?;
    Ok(serde_json::to_string_pretty(&s).unwrap_or_default())
}

/// Mach intervals in words: `1.16–2.00, 2.10` or `none`.
pub fn show_intervals(v: &[[f64; 2]]) -> String {
    if v.is_empty() {
        return "none".into();
    }
    v.iter()
        .map(|[a, b]| {
            if stability_core::numerics::grid::on(*a, *b) {
                format!("{a:.2}")
            } else {
                format!("{a:.2}–{b:.2}")
            }
        })
        .collect::<Vec<_>>()
        .join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn worst(by_mach: &[(f64, Option<f64>)]) -> Option<Worst> {
        MaxMu1 {
            by_mach: by_mach.to_vec(),
        }
        .worst()
    }

    /// A Mach number where no μ₁ meets the standard is the worst case, not
    /// a gap: a smaller finite limit elsewhere does not hide it.
    #[test]
    fn no_mu1_at_some_mach_is_the_worst_case() {
        let w = worst(&[
            (1.1, Some(600.0)),
            (1.2, None),
            (1.25, None),
            (1.3, Some(12.8)),
            (2.0, None),
        ]);
        assert_eq!(w, Some(Worst::NoneMeets(vec![[1.2, 1.25], [2.0, 2.0]])));
        assert_eq!(w.unwrap().describe(), "no μ₁ meets it at M 1.20–1.25, 2.00");
        let w = worst(&[(1.1, Some(600.0)), (1.3, Some(12.8)), (2.0, Some(99.6))]);
        assert_eq!(
            w,
            Some(Worst::Least {
                mach: 1.3,
                mu1: 12.8
            })
        );
        assert_eq!(w.unwrap().describe(), "12.8 at M = 1.30");
        assert_eq!(worst(&[]), None);
        let json = serde_json::to_string(&WorstJson::from(&Worst::NoneMeets(vec![[1.2, 1.3]])));
        assert_eq!(json.unwrap(), r#"{"mu1":null,"mach":[[1.2,1.3]]}"#);
    }
}
