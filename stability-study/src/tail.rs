//! §10 (ours), "The tail the 45° delta needs": the note's question
//! answered. §9 finds the tailless 45° delta seriously unstable in
//! 0.97 < M₁ < 1.5 (Fig 33) and §10 names "the addition of a forebody,
//! foreplane, or tailplane" as the remedy; this section finds how large.
//!
//! The wing and design point are the report's 45° delta at μ₁ = 50,
//! h = 0.25 and the report's i_B and C_L·M² ([`Assumed`]). Two
//! families, each with its shape (sweep, taper, aspect ratio) and apex
//! fixed and its area varied
//! ([`stability_core::design::sizing`], unchanged):
//! - the tailplane of examples/delta-45-tailed.toml (a cropped 45° delta,
//!   λ = 0.2, apex 12 aft of the wing's, in its plane);
//! - the foreplane of examples/delta-60-canard.toml (a 60° delta, apex 5
//!   ahead of the wing's and 1 above), placed ahead of the 45° wing, with
//!   no forebody.
//!
//! Each is sized by [`size_surface`] over [`machs`]: the smallest area
//! meeting §8's one-cycle standard at every one of them, up to the wing's
//! area.

use super::Plate;
use super::study::{Assumed, mach_fig};
use rayon::prelude::*;
use serde::Serialize;
use stability_core::criteria::Verdict;
use stability_core::design::case::Case;
use stability_core::design::sizing::{MachOutcome, Sizing, outcomes_at, size_surface};
use stability_core::design::study::report_wing;
use stability_core::geometry::configuration::Configuration;
use stability_core::geometry::configuration::SurfaceKind;
use stability_core::numerics::display::sig;
use stability_io::plot::{Series, short};
use std::sync::Arc;

/// The tailed config whose tailplane is the family.
pub const TAILED: &str = include_str!("../data/delta-45-tailed.toml");
/// The canard config whose foreplane is the family.
pub const CANARD: &str = include_str!("../data/delta-60-canard.toml");

/// The Mach numbers the standard must hold at: 0.5 to 2.0, dense where
/// the tailless wing fails (Fig 33's 0.97 < M₁ < 1.5), sparse elsewhere —
/// each point costs a sizing's ~35 evaluations, the subsonic and faired
/// ones each a doublet-lattice solve (`size-tail` over 0.5:2.0:0.1 takes
/// ~100 s on release against the report's ~10 s).
pub fn machs() -> Vec<f64> {
    vec![0.5, 0.9, 0.97, 1.02, 1.1, 1.2, 1.3, 1.4, 1.5, 1.75, 2.0]
}

/// The configuration of the example `text` (named `path`).
fn configuration(path: &str, text: &str) -> Result<Configuration, String> {
    let cfg = stability_io::config::parse(path, text).map_err(|e| format!("{e:?}"))?;
    cfg.case
        .aero
        .configuration_for(&cfg.case.planform)
        .ok_or_else(|| format!("{path} has no surfaces"))
}

/// The report's 45° delta with one surface of a family: the tailplane
/// (`kind` Tailplane) or the foreplane ahead of it.
pub fn case(assumed: Assumed, kind: SurfaceKind) -> Result<Case, String> {
    let mut config = configuration("examples/delta-45-tailed.toml", TAILED)?;
    config.body = None;
    if kind == SurfaceKind::Foreplane {
        let canard = configuration("examples/delta-60-canard.toml", CANARD)?;
        config.tailplane = None;
        config.foreplane = canard.foreplane;
    }
    let mut case = assumed.apply(report_wing(45.0, 1.0));
    case.aero.configuration = Some(Arc::new(config));
    Ok(case)
}

/// The answer: both families sized, and the tailplane's members drawn.
pub struct TailNeeded {
    pub machs: Vec<f64>,
    pub tailplane: Sizing,
    pub foreplane: Sizing,
    /// (S_T/S, cycles to half amplitude at each Mach number; NaN where
    /// none) for no tail, half the found area, the found area and 1.5×.
    pub members: Vec<(f64, Vec<f64>)>,
    /// The wing alone at each Mach number, every root judged: what the
    /// tail cures.
    pub tailless: Vec<MachOutcome>,
}

impl TailNeeded {
    /// The report's: sized over [`machs`] with the study's assumptions
    /// ([`Assumed::ours`], as [`super::Study::new`] takes), so that it can run beside
    /// the study.
    pub fn ours() -> Result<TailNeeded, String> {
        TailNeeded::over(Assumed::ours(), machs())
    }

    /// Sized over `ms`.
    pub fn over(assumed: Assumed, ms: Vec<f64>) -> Result<TailNeeded, String> {
        let size = |kind| -> Result<(Case, Sizing), String> {
            let c = case(assumed, kind)?;
            let s = size_surface(&c, kind, &ms, None).map_err(|e| e.to_string())?;
            Ok((c, s))
        };
        let (tail, fore) = rayon::join(
            || size(SurfaceKind::Tailplane),
            || size(SurfaceKind::Foreplane),
        );
        let ((tc, tailplane), (_, foreplane)) = (tail?, fore?);
        let wing = tailplane.limit;
        let found = tailplane.area.unwrap_or(tailplane.limit);
        let outcomes = [0.0, 0.5, 1.0, 1.5]
            .par_iter()
            .map(|&k| {
                let o = outcomes_at(&tc, SurfaceKind::Tailplane, &ms, k * found)
                    .map_err(|e| e.to_string())?;
                Ok((k * found / wing, o))
            })
            .collect::<Result<Vec<_>, String>>()?;
        let members = outcomes
            .iter()
            .map(|(ratio, o)| {
                let c = o.iter().map(|o| o.cycles_to_half.unwrap_or(f64::NAN));
                (*ratio, c.collect())
            })
            .collect();
        let tailless = outcomes
            .into_iter()
            .next()
            .map(|(_, o)| o)
            .unwrap_or_default();
        Ok(TailNeeded {
            machs: ms,
            tailplane,
            foreplane,
            members,
            tailless,
        })
    }
}

/// One family's answer in summary.json.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SurfaceJson {
    /// S_T/S, or null where no area up to the wing's meets the standard.
    pub area_ratio: Option<f64>,
    /// V̄ = S_T·l/(S·c̄) (negative: ahead of the c.g.).
    pub volume: Option<f64>,
}

/// summary.json's `tail_needed`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TailJson {
    pub mach: Vec<f64>,
    pub tailplane: SurfaceJson,
    pub foreplane: SurfaceJson,
}

fn surface_json(s: &Sizing) -> SurfaceJson {
    SurfaceJson {
        area_ratio: s.area.map(|a| a / s.limit),
        volume: s.volume,
    }
}

/// One family's answer in words.
fn answer(s: &Sizing) -> String {
    let name = s.surface.name();
    match (s.area, s.volume) {
        (Some(0.0), _) => format!("no {name} is needed"),
        (Some(a), Some(v)) => format!(
            "a {name} of V̄ = {} (S/S_w = {}) is needed",
            sig(v, 3),
            sig(a / s.limit, 3)
        ),
        _ => format!("no {name} up to the wing's area is enough"),
    }
}

impl TailNeeded {
    pub fn json(&self) -> TailJson {
        TailJson {
            mach: self.machs.clone(),
            tailplane: surface_json(&self.tailplane),
            foreplane: surface_json(&self.foreplane),
        }
    }

    /// The conclusion: "a tailplane of V̄ = … (S_T/S = …) is needed …",
    /// with what it cures.
    pub fn sentence(&self) -> String {
        format!(
            "{} for the 45° delta (μ₁ = 50, h = 0.25) to meet the one-cycle standard at every Mach number from {} to {}, every root judged ({}; examples/delta-45-tailed.toml's tail shape; V̄ from the c.g. to the tail's M.A.C. quarter chord); of examples/delta-60-canard.toml's foreplane shape ahead of the wing, {}",
            answer(&self.tailplane),
            sig(self.machs[0], 2),
            sig(self.machs[self.machs.len() - 1], 2),
            self.cures(),
            answer(&self.foreplane),
        )
    }

    /// What the tail cures, from the wing alone's every-root verdict:
    /// "the wing alone diverges (a root grows) at M = 0.97 and meets it
    /// elsewhere".
    pub fn cures(&self) -> String {
        let at = |v: Verdict| -> Vec<String> {
            self.tailless
                .iter()
                .filter(|o| o.verdict == Some(v))
                .map(|o| short(o.mach))
                .collect()
        };
        let (diverges, fails) = (at(Verdict::Divergent), at(Verdict::Fails));
        let mut parts = Vec::new();
        if !diverges.is_empty() {
            parts.push(format!(
                "diverges (a root grows) at M = {}",
                diverges.join(", ")
            ));
        }
        if !fails.is_empty() {
            parts.push(format!(
                "takes more than one cycle to halve, or has a neutral root, at M = {}",
                fails.join(", ")
            ));
        }
        let judged = self.tailless.iter().filter(|o| o.verdict.is_some());
        let elsewhere = match judged.count() > diverges.len() + fails.len() {
            true => " and meets it elsewhere",
            false => "",
        };
        match parts.is_empty() {
            true => "the wing alone meets it at each of them".into(),
            false => format!("the wing alone {}{elsewhere}", parts.join("; ")),
        }
    }

    /// Cycles to half amplitude against Mach number for the tailplane's
    /// members, with the one-cycle line.
    pub fn plate(&self) -> Plate {
        let mut fig = mach_fig(
            "tail",
            "The tail the 45° delta needs: short period, cycles to half amplitude",
            "cycles to half amplitude",
        );
        for (ratio, cycles) in &self.members {
            let pts = self.machs.iter().copied().zip(cycles.iter().copied());
            fig = fig.with(Series::new(
                format!("S_T/S = {}", sig(*ratio, 3)),
                pts.collect(),
            ));
        }
        let (lo, hi) = (self.machs[0], self.machs[self.machs.len() - 1]);
        fig = fig.with(Series::new("one cycle (§8)", vec![(lo, 1.0), (hi, 1.0)]));
        Plate::named(
            "tail-needed",
            fig,
            format!(
                "§10 (ours): the tail the 45° delta needs. {}. Curves: no tail, half the found area, the found area, 1.5×; a point is missing where the short period does not oscillate or does not decay.",
                self.sentence()
            ),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use stability_core::analysis::verdict::overall;
    use stability_core::criteria::Verdict;
    use stability_core::design::case::evaluate;

    /// Two of the report's Mach numbers ([`machs`]): 0.97, where the
    /// tailless wing diverges, and 1.4, where the tail's increment is the
    /// Mach box's (the whole range would make the test a report's length).
    const MS: [f64; 2] = [0.97, 1.4];

    /// The verdict at each of `ms` with the tailplane of the example
    /// scaled (every length, about its apex) to area `area`, built here
    /// from the Trapezoid, not by the sizing code.
    fn verdicts(c: &Case, area: f64) -> Vec<Option<Verdict>> {
        let mut config = (**c.aero.configuration.as_ref().unwrap()).clone();
        let mut t = config.tailplane.unwrap();
        let f = (area / t.shape.area()).sqrt();
        t.shape.root_chord *= f;
        t.shape.tip_chord *= f;
        t.shape.semi_span *= f;
        config.tailplane = Some(t);
        let config = Arc::new(config);
        MS.par_iter()
            .map(|&m| {
                let mut k = c.clone();
                k.mach = m;
                k.aero.configuration = Some(config.clone());
                evaluate(&k).ok().map(|r| overall(&r.analysis))
            })
            .collect()
    }

    #[test]
    fn the_reports_tail_is_size_tails_and_is_the_smallest() {
        // the report's solutions, as the report has them (MS is in its
        // grid, [`machs`])
        let _ = crate::study::preload();
        let t = TailNeeded::over(Assumed::ours(), MS.to_vec()).unwrap();
        // size-tail's route: the example file as the CLI reads it.
        let cfg = stability_io::config::overridden(
            "../examples/delta-45-tailed.toml",
            &Default::default(),
        )
        .unwrap();
        let cli = size_surface(&cfg.case, SurfaceKind::Tailplane, &MS, None).unwrap();
        let area = t.tailplane.area.expect("a tail up to the wing's area");
        assert_eq!(Some(area), cli.area);
        assert!(area > 0.0, "the tailless wing diverges at M = 0.97");
        let c = case(Assumed::ours(), SurfaceKind::Tailplane).unwrap();
        let (at, below) = rayon::join(|| verdicts(&c, area), || verdicts(&c, 0.99 * area));
        assert!(at.iter().all(|v| *v == Some(Verdict::Meets)), "{at:?}");
        assert!(
            below.iter().any(|v| *v != Some(Verdict::Meets)),
            "{below:?}"
        );
        // The members drawn: the found one's cycles are all ≤ 1.
        let found = &t.members[2];
        assert!((found.0 - area / 100.0).abs() < 1e-12);
        assert!(found.1.iter().all(|&c| c.is_nan() || c <= 1.0));
        assert!(t.sentence().contains("tailplane of V̄ ="));
        // what it cures is the wing alone's every-root verdict, evaluated
        // here with the tailplane taken out of the configuration
        let mut alone = (**c.aero.configuration.as_ref().unwrap()).clone();
        alone.tailplane = None;
        let alone = Arc::new(alone);
        assert_eq!(t.tailless.len(), MS.len());
        let judged: Vec<_> = t
            .tailless
            .par_iter()
            .map(|o| {
                let mut k = c.clone();
                k.mach = o.mach;
                k.aero.configuration = Some(alone.clone());
                evaluate(&k).ok().map(|r| overall(&r.analysis))
            })
            .collect();
        for (o, v) in t.tailless.iter().zip(judged) {
            assert_eq!(o.verdict, v, "the wing alone at M = {}", o.mach);
            if v != Some(Verdict::Meets) {
                assert!(t.cures().contains(&short(o.mach)), "{}", t.cures());
            }
        }
        assert!(
            t.tailless.iter().any(|o| o.verdict != Some(Verdict::Meets)),
            "the tail cures nothing"
        );
        assert!(t.sentence().contains(&t.cures()));
    }
}
