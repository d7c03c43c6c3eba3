//! The overall verdict of a derivative set, defined once: every root is
//! judged, so that no output can say "meets" of an aircraft with a mode
//! that grows. The report's §8 standard (half amplitude within one cycle,
//! eq 41) is a verdict on the short period alone ([`Verdict::of`]); the
//! overall verdict adds the rest of the motion:
//!
//! - a mode that grows (r > 0) is **divergent**, whatever else holds: an
//!   oscillation by its time to double and cycles to double, an aperiodic
//!   root by its time to double, each with the MIL-F-8785C level it would
//!   have (§3.2.1.2: a phugoid, or a root it split into, may diverge at
//!   Level 3 if it takes at least 55 s to double; a growing short period
//!   is worse than Level 3 — but divergent all the same);
//! - a neutral mode (r = 0) **fails**: it never halves;
//! - otherwise the §8 standard on the short period decides: **meets** when
//!   it halves within one cycle (or is aperiodic and decays), **fails**
//!   when it takes longer.
//!
//! Routh's test (§4) agrees with the roots except on the stability
//! boundary ([`crate::analysis::ON_AXIS`]); a marginal Routh verdict there
//! is a reason too, and never "meets".

use crate::analysis::{Characteristic, Timebase};
use crate::criteria::{Level, Verdict, phugoid_level};
use crate::dynamics::modes::{Mode, ModeName, Origin};
use crate::numerics::display::sig;
use serde::Serialize;

/// The overall verdict and why: `{"overall": "divergent", "reasons":
/// ["…"]}` in JSON.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Overall {
    /// The worst of the reasons' verdicts.
    pub overall: Verdict,
    /// One sentence per mode that decides it, worst first.
    pub reasons: Vec<String>,
}

impl Overall {
    /// The overall verdict of `c`, its times in the unit of `time` (and in
    /// seconds where τ is known, which the MIL-F-8785C phugoid rule needs).
    pub fn of(c: &Characteristic, time: Timebase) -> Overall {
        let mut found: Vec<(Verdict, String)> = c
            .modes
            .iter()
            .filter(|m| m.re >= 0.0)
            .map(|m| growing_or_neutral(m, time))
            .collect();
        let settled = found.is_empty();
        // the short period's own growth is a reason already
        if c.verdict != Verdict::Divergent {
            found.push(standard(c));
        }
        if settled && !c.routh.stable && c.verdict.is_met() {
            let r = sig(c.routh.discriminant, 3);
            found.push((
                Verdict::Fails,
                format!("Routh's test (§4) is marginal: R = {r}, on the stability boundary"),
            ));
        }
        found.sort_by_key(|f| std::cmp::Reverse(f.0));
        Overall {
            overall: overall(c),
            reasons: found.into_iter().map(|f| f.1).collect(),
        }
    }

    /// Whether the aircraft meets the standard and no mode grows.
    pub fn is_met(&self) -> bool {
        self.overall.is_met()
    }
}

/// The overall verdict's word alone, without the reasons (allocation-free:
/// a sweep's): divergent if any root grows, fails if one is neutral, the
/// standard on the short period otherwise, and never meets where Routh's
/// test is marginal.
pub fn overall(c: &Characteristic) -> Verdict {
    let mut v = c.verdict;
    for m in c.modes.iter() {
        if m.re > 0.0 {
            return Verdict::Divergent;
        }
        if m.re == 0.0 {
            v = v.max(Verdict::Fails);
        }
    }
    if !c.routh.stable {
        v = v.max(Verdict::Fails);
    }
    v
}

/// A time in the unit of `time` in words: `48.9 s`, or `12.3 τ` (with the
/// seconds where τ is known).
fn duration(t: f64, time: Timebase) -> String {
    match time {
        Timebase::Seconds(_) => format!("{} s", sig(t, 3)),
        Timebase::Tau(Some(tau)) => format!("{} s", sig(t * tau, 3)),
        Timebase::Tau(None) => format!("{} τ", sig(t, 3)),
    }
}

/// A time in the unit of `time` in seconds, where known.
fn seconds(t: f64, time: Timebase) -> Option<f64> {
    time.to_per_second().map(|f| t / f)
}

/// A mode that grows or is neutral: its verdict and why.
fn growing_or_neutral(m: &Mode, time: Timebase) -> (Verdict, String) {
    let what = match (m.name, m.origin) {
        (ModeName::Aperiodic, Some(Origin::Unknown) | None) => "an aperiodic root".to_string(),
        (ModeName::Aperiodic, Some(o)) => format!(
            "an aperiodic root (the {} split)",
            ModeName::from(o).as_str().replace('_', " ")
        ),
        (name, _) => format!("the {}", name.as_str().replace('_', " ")),
    };
    let Some(t2) = m.time_to_double else {
        return (
            Verdict::Fails,
            format!("{what} is neutral: it never halves"),
        );
    };
    let cycles = m
        .cycles_to_double
        .map(|c| format!(", {} cycles", sig(c, 3)))
        .unwrap_or_default();
    let text = format!(
        "{what} grows, doubling in {}{cycles}{}",
        duration(t2, time),
        level(m, seconds(t2, time))
    );
    (Verdict::Divergent, text)
}

/// The MIL-F-8785C level a growing mode would have, in words (the phugoid
/// and what it splits into by §3.2.1.2's time to double; a growing short
/// period is worse than Level 3).
fn level(m: &Mode, t2_s: Option<f64>) -> String {
    let phugoid = m.name == ModeName::Phugoid || m.origin == Some(Origin::Phugoid);
    if !phugoid {
        return " (MIL-F-8785C: worse than Level 3)".to_string();
    }
    match t2_s {
        None => " (MIL-F-8785C §3.2.1.2 needs the time in seconds)".to_string(),
        Some(t) => match phugoid_level(m.damping_ratio.unwrap_or(-1.0), Some(t)) {
            Level::Three => " (MIL-F-8785C §3.2.1.2: Level 3, time to double ≥ 55 s)".to_string(),
            _ => " (MIL-F-8785C §3.2.1.2: worse than Level 3, time to double < 55 s)".to_string(),
        },
    }
}

/// The §8 standard on the short period, in words.
fn standard(c: &Characteristic) -> (Verdict, String) {
    let sp = c.modes.short_period();
    let text = match (c.verdict, sp.and_then(|m| m.cycles_to_half)) {
        (Verdict::Meets, Some(n)) => format!(
            "the short period halves in {} cycles (§8: within one)",
            sig(n, 3)
        ),
        (Verdict::Meets, None) => "the short period is aperiodic and decays (§8)".to_string(),
        (_, Some(n)) => format!(
            "the short period takes {} cycles to halve (§8: more than one)",
            sig(n, 3)
        ),
        (_, None) => "the short period never halves (§8)".to_string(),
    };
    (c.verdict, text)
}

impl From<Origin> for ModeName {
    /// The pair an aperiodic root came from (`Unknown`: aperiodic).
    fn from(o: Origin) -> ModeName {
        match o {
            Origin::ShortPeriod => ModeName::ShortPeriod,
            Origin::Phugoid => ModeName::Phugoid,
            Origin::Unknown => ModeName::Aperiodic,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Quartic;
    use num_complex::Complex64;

    /// The characteristic of the quartic with roots `roots` (conjugates
    /// given both), μ₁ = 50.
    fn of_roots(roots: [Complex64; 4]) -> Characteristic {
        let mut coefficients = vec![Complex64::new(1.0, 0.0)];
        for r in roots {
            let mut next = vec![Complex64::new(0.0, 0.0); coefficients.len() + 1];
            for (k, c) in coefficients.iter().enumerate() {
                next[k] += c;
                next[k + 1] -= c * r;
            }
            coefficients = next;
        }
        let q: [f64; 5] = std::array::from_fn(|k| coefficients[k].re);
        let names = ["A", "B", "C", "D", "E"];
        Characteristic::of(Quartic::from_array(q), &names, 50.0).unwrap()
    }

    fn c(re: f64, im: f64) -> Complex64 {
        Complex64::new(re, im)
    }

    #[test]
    fn a_growing_aperiodic_root_is_divergent_though_the_short_period_meets_the_standard() {
        // the 60° delta at M = 0.95: a good short period and a
        // phugoid split into a decaying and a growing real root
        let ch = of_roots([c(-3.0, 6.0), c(-3.0, -6.0), c(0.02, 0.0), c(-0.05, 0.0)]);
        assert_eq!(ch.verdict, Verdict::Meets, "the §8 standard alone");
        let o = Overall::of(&ch, Timebase::Tau(Some(48.9 / (2f64.ln() / 0.02))));
        assert_eq!(o.overall, Verdict::Divergent);
        assert!(
            o.reasons[0]
                .starts_with("an aperiodic root (the phugoid split) grows, doubling in 48.9 s"),
            "{o:?}"
        );
        assert!(o.reasons[0].contains("time to double < 55 s"), "{o:?}");
    }

    #[test]
    fn a_slowly_divergent_phugoid_is_level_3_but_still_divergent() {
        let ch = of_roots([c(-3.0, 6.0), c(-3.0, -6.0), c(0.001, 0.1), c(0.001, -0.1)]);
        let o = Overall::of(&ch, Timebase::Seconds(None));
        assert_eq!(o.overall, Verdict::Divergent);
        assert!(o.reasons[0].contains("Level 3"), "{o:?}");
        // without seconds the level cannot be judged, the divergence can
        let o = Overall::of(&ch, Timebase::Tau(None));
        assert_eq!(o.overall, Verdict::Divergent);
        assert!(o.reasons[0].contains("τ") && o.reasons[0].contains("needs the time in seconds"));
    }

    #[test]
    fn a_stable_aircraft_is_judged_by_the_standard() {
        let good = of_roots([c(-3.0, 6.0), c(-3.0, -6.0), c(-0.01, 0.1), c(-0.01, -0.1)]);
        let o = Overall::of(&good, Timebase::Tau(None));
        assert_eq!(o.overall, Verdict::Meets);
        assert!(o.reasons[0].contains("within one"), "{o:?}");
        let slow = of_roots([c(-0.3, 6.0), c(-0.3, -6.0), c(-0.01, 0.1), c(-0.01, -0.1)]);
        let o = Overall::of(&slow, Timebase::Tau(None));
        assert_eq!(o.overall, Verdict::Fails);
        assert!(o.reasons[0].contains("more than one"), "{o:?}");
    }

    #[test]
    fn a_neutral_root_fails() {
        let ch = of_roots([c(-3.0, 6.0), c(-3.0, -6.0), c(0.0, 0.0), c(-0.05, 0.0)]);
        let o = Overall::of(&ch, Timebase::Tau(None));
        assert_eq!(o.overall, Verdict::Fails);
        assert!(o.reasons.iter().any(|r| r.contains("neutral")), "{o:?}");
    }
}
