//! The note's conclusions, each set beside what we computed, with the
//! numbers and a verdict. A conclusion is one entry of [`CONCLUSIONS`]: where
//! the note says it, its words, a function that measures it on the
//! [`Findings`] and judges it, and the unstated inputs it depends on;
//! adding one is adding an entry (and, if it needs a number not yet found, a
//! method of `Findings`).
//!
//! # What "reproduced" means
//! Each judgement is [`Agreement::Agrees`], `Partly` or `Differs` by a
//! tolerance of its own — a constant here, documented with the function that
//! uses it and stated, with its numbers, in the report beside the verdict
//! ([`Assessment::tolerance`]). A claim is *reproduced* when it `Agrees`:
//! our numbers bear it out within that tolerance. `Partly` is not
//! reproduced; the text says which part holds.
//!
//! # The unstated inputs
//! Where a verdict rests on the quartic it depends on the pitching inertia
//! i_B and on C_L·M², which the note does not state ([`Assumption`]). Each
//! such conclusion is judged again on the study redone with other values
//! (`Study::assuming`): from ours toward each end of the input's range in
//! [`SWEEP_STEPS`] steps, and where the verdict first reverses, bisection of
//! that step [`SWEEP_HALVINGS`] times ([`nearest_reversal`]). The report
//! states the nearest reversal on each side ("reversed above i_B ≈ 0.14"),
//! or that the verdict holds over the whole range; a reversal and its undoing
//! within one step would not be seen.

use super::standard::CGS;
use super::study::{Assumed, Assumption, Study, WINGS};
use super::summary::{CROPPED_TAPER, Findings, SWEEPS_ABOUT_60, Worst, show_intervals};
use crate::certainty::percent;
use crate::study::{NOTE_SUPERSONIC, SUBCRITICAL};
use serde::Serialize;
use stability_core::design::study::intervals;
use stability_core::numerics::display::sig;
use std::cell::RefCell;
use std::rc::Rc;

/// How what we computed stands to the note's claim.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Agreement {
    Agrees,
    Partly,
    Differs,
}

impl Agreement {
    pub fn as_str(self) -> &'static str {
        match self {
            Agreement::Agrees => "agrees",
            Agreement::Partly => "agrees in part",
            Agreement::Differs => "differs",
        }
    }

    /// Whether the claim is reproduced: it agrees within its tolerance.
    pub fn reproduced(self) -> bool {
        self == Agreement::Agrees
    }

    /// `Agrees` when `value` ≥ `agrees`, `Partly` when ≥ `partly`, else
    /// `Differs`.
    fn at_least(value: f64, agrees: f64, partly: f64) -> Agreement {
        if value >= agrees {
            Agreement::Agrees
        } else if value >= partly {
            Agreement::Partly
        } else {
            Agreement::Differs
        }
    }
}

/// What we computed about a claim.
#[derive(Debug, Clone, PartialEq)]
pub struct Assessment {
    pub agreement: Agreement,
    /// Our result, in words with its numbers.
    pub computed: String,
    /// What "reproduced" means for this claim, with the numbers used.
    pub tolerance: String,
}

/// One of the note's conclusions.
pub struct Conclusion {
    /// A stable name: "45-transonic".
    pub id: &'static str,
    /// A short name for lists, lower case: "the 45° delta's transonic
    /// instability" (README.md's paragraph, `readme`).
    pub title: &'static str,
    /// What it is about: "45° delta".
    pub subject: &'static str,
    /// Where the note says it: "Summary; §9, Fig 33".
    pub section: &'static str,
    /// The note's claim, in its words.
    pub claim: &'static str,
    /// Measures the claim on the findings and judges it.
    pub assess: fn(&Findings) -> Assessment,
    /// The unstated inputs its verdict depends on (swept).
    pub depends_on: &'static [Assumption],
    /// Why our models may part from the note here, shown when they do.
    pub when_they_part: &'static str,
}

/// Both unstated inputs.
const BOTH: &[Assumption] = &Assumption::ALL;

pub const CONCLUSIONS: &[Conclusion] = &[
    Conclusion {
        id: "45-transonic",
        title: "the 45° delta's transonic instability",
        subject: "45° delta",
        section: "Summary; §9, Fig 33",
        claim: "Inadequately damped at transonic speeds (μ₁ = 50): a tailplane is needed “to correct the serious instability in the range 0.97 < M < 1.5”.",
        assess: transonic_45,
        depends_on: BOTH,
        when_they_part: "The transonic short period rests on the damping derivatives between M = 0.9 and 1.2, where the note's Figs 19–24 were “plausible guides” faired through data we do not have. Ours come from one linear lifting-surface theory through M = 1 (the lattice, its sonic point, the Mach box; stability_core::aerodynamics::models::faired), each root solved with the air forces at its own complex frequency (docs/exact-root.md), which the note could not afford; the note's own fairing of its theories (`faired-theories`) reproduces its verdict. The note's edges 0.97 and 1.5 are read off its lost Fig 33.",
    },
    Conclusion {
        id: "60-mu1-limit",
        title: "the 60° delta's limit of μ₁ ≈ 200",
        subject: "60° delta",
        section: "Summary; §9, Fig 33",
        claim: "Adequately damped “for values of the relative density parameter μ₁ … less than about 200”.",
        assess: mu1_limit_60,
        depends_on: BOTH,
        when_they_part: "The largest μ₁ is found on the exact roots (not §8's approximation), and it depends on i_B, which the note does not state: see the sweep.",
    },
    Conclusion {
        id: "subcritical-trend",
        title: "the subcritical rise of damping and frequency",
        subject: "45° delta",
        section: "§11, Fig 37",
        claim: "“The increase in damping and frequency with Mach number at subcritical speeds will be apparent” in the response to an elevon step.",
        assess: subcritical_trend,
        depends_on: BOTH,
        when_they_part: "The note's Fig 37 is lost; we measure the trend on eq (45)'s b and k at every Mach number up to 0.9, per unit t̂ as Fig 37 is drawn (in seconds every rate grows further with V).",
    },
    Conclusion {
        id: "mwdot-negligible",
        title: "m_ẇ negligible at subcritical speeds",
        subject: "both wings",
        section: "§7 (a)",
        claim: "“The moment-acceleration derivative m_ẇ can be safely neglected at sub-critical speeds.”",
        assess: mwdot_negligible,
        depends_on: BOTH,
        when_they_part: "The note judged m_ẇ on its faired Fig 23; we judge its share of the short period's damping, with the subsonic derivatives of our default model (the doublet lattice below M = 1; stability_core::aerodynamics::models::faired).",
    },
    Conclusion {
        id: "45-m-thetadot-positive",
        title: "(36)'s negative damping at M = 1.2",
        subject: "45° delta",
        section: "§7, eq (36), Fig 17",
        claim: "Supersonic theory (36) indicates “negative damping [m_θ̇ > 0] for the specified practical C.G. range of 0.4 < x₀/c₀ < 0.6 at M = 1.2”.",
        assess: m_thetadot_positive_45,
        depends_on: &[],
        when_they_part: "Eq (36) is printed garbled; our recovery of it (docs/damping-theories.md) is checked against its limits, not against the note's lost Fig 17.",
    },
    Conclusion {
        id: "cropping",
        title: "cropping",
        subject: "both wings",
        section: "§10, Fig 36",
        claim: "Cropping the tips (taper 1/7) gives “a substantial increase in −m_θ̇ at M = 1.2” for the 45° delta, “but this is not the case for the 60° delta”.",
        assess: cropping,
        // the default model's damping at M = 1.2 is at the short period's
        // ω̄, which i_B and C_L·M² set
        depends_on: BOTH,
        when_they_part: "The note reasoned from Fig 17 with cropping as a shift of axis: the true delta's (36) about another c.g. We evaluate the cropped wing itself, the c.g. in place, as Fig 36 draws it, with its own linear theory (the true delta's potentials less the tips' Mach-cone corrections), which keeps more lift and moves the aerodynamic centre forward.",
    },
    Conclusion {
        id: "sweep-diminishing",
        title: "diminishing returns beyond 60° of sweep",
        subject: "deltas of 45°–75°",
        section: "§8, Figs 25–26",
        claim: "“There are diminishing returns in damping for increased sweep. In fact, little advantage is to be gained for sweep angles greater than about 60°.”",
        assess: diminishing_returns,
        depends_on: BOTH,
        when_they_part: "Eq (41)'s margin weighs the damping against the stiffness, both of which change with sweep; where the returns do not diminish, the 75° wing's margin rises with its lower stiffness.",
    },
    Conclusion {
        id: "omega-approximation",
        title: "§9's ω̄ approximation",
        subject: "both wings",
        section: "§9, Fig 32",
        claim: "√(−m_w/(μ₁i_B)) is “a good first approximation to the short period frequency parameter” ω̄.",
        assess: omega_approximation,
        depends_on: BOTH,
        when_they_part: "The approximation is the undamped frequency of the short-period approximation; the exact ω̄ is the damped frequency of the exact roots, far below it where the short period is heavily damped.",
    },
    Conclusion {
        id: "omega-maximum",
        title: "ω̄'s maximum of 0.6",
        subject: "both wings",
        section: "§7",
        claim: "“The frequency parameter for the short period oscillation has in fact a maximum value of 0.6.”",
        assess: omega_maximum,
        depends_on: BOTH,
        when_they_part: "Our ω̄ comes from the exact short-period roots at μ₁ = 50, and it depends on i_B, which the note does not state: see the sweep.",
    },
    Conclusion {
        id: "45-forward-cg",
        title: "a forward c.g. improving the damping",
        subject: "45° delta",
        section: "§8, Figs 25–26",
        claim: "“Forward movement of the C.G. improves the damping.”",
        assess: forward_cg,
        depends_on: BOTH,
        when_they_part: "Eq (41)'s margin weighs the damping against the stiffness, which a forward c.g. increases; the note finds the stiffness outweighing the gain only above 60° of sweep.",
    },
];

/// The intervals of `points` (x, flag) where the flag holds, in words.
fn where_true(points: &[(f64, bool)]) -> String {
    let (x, flags): (Vec<f64>, Vec<bool>) = points.iter().copied().unzip();
    show_intervals(&intervals(&x, &flags))
}

/// Mach intervals in words: "at M 1.16–1.50" or "nowhere".
fn at_mach(v: &[[f64; 2]]) -> String {
    if v.is_empty() {
        "nowhere".into()
    } else {
        format!("at M {}", show_intervals(v))
    }
}

/// The share of `points` whose flag holds (0 with none).
fn share(points: &[(f64, bool)]) -> f64 {
    if points.is_empty() {
        return 0.0;
    }
    points.iter().filter(|(_, f)| *f).count() as f64 / points.len() as f64
}

/// The note's range of "serious instability" of the 45° delta (Fig 33).
pub const TRANSONIC: (f64, f64) = (0.97, 1.5);
/// Reproduced when the short period diverges or fails the standard at this
/// share of the study's Mach numbers in [`TRANSONIC`] (its edges are read
/// off a lost figure, and the study's are 0.01 apart); in part at
/// [`TRANSONIC_PARTLY`].
const TRANSONIC_AGREES: f64 = 0.8;
const TRANSONIC_PARTLY: f64 = 0.25;

/// §9: the 45° delta diverges or fails one cycle over 0.97 < M < 1.5 at
/// μ₁ = 50. Tolerance: [`TRANSONIC_AGREES`] of the Mach numbers there.
fn transonic_45(f: &Findings) -> Assessment {
    let w = &f.wings[0];
    let (a, b) = TRANSONIC;
    let within: Vec<(f64, bool)> = w
        .inadequate
        .iter()
        .copied()
        .filter(|(m, _)| stability_core::numerics::grid::within(*m, a, b))
        .collect();
    let covered = share(&within);
    let most = w.most_cycles.map_or("—".into(), |(m, c)| {
        format!("{} cycles to half amplitude at M = {m:.2}", sig(c, 3))
    });
    Assessment {
        agreement: Agreement::at_least(covered, TRANSONIC_AGREES, TRANSONIC_PARTLY),
        computed: format!(
            "Divergent {}; fails one cycle {}: covers {} of {a}–{b}. Least damped: {most}.",
            at_mach(&w.unstable),
            at_mach(&w.fails),
            percent(covered),
        ),
        tolerance: format!(
            "divergent or failing at ≥ {} of the Mach numbers in {a}–{b} (in part ≥ {})",
            percent(TRANSONIC_AGREES),
            percent(TRANSONIC_PARTLY)
        ),
    }
}

/// The note's limit of μ₁ for the 60° delta …
pub const MU1_LIMIT: f64 = 200.0;
/// … "about" it: within this factor.
pub const ABOUT: f64 = 1.25;

/// Whether `mu1` is "about" [`MU1_LIMIT`].
pub fn about_limit(mu1: f64) -> bool {
    (mu1 / MU1_LIMIT).ln().abs() <= ABOUT.ln()
}

/// §9: the 60° delta meets the standard while μ₁ < about 200. Tolerance:
/// the worst largest μ₁ over Mach number within a factor [`ABOUT`] of 200;
/// in part where it is so at some Mach numbers only.
fn mu1_limit_60(f: &Findings) -> Assessment {
    let by_mach = &f.max_mu1(1).by_mach;
    let near: Vec<(f64, bool)> = by_mach
        .iter()
        .map(|&(m, v)| (m, v.is_some_and(about_limit)))
        .collect();
    let (ms_lo, ms_hi) = (
        by_mach.first().map_or(0.0, |p| p.0),
        by_mach.last().map_or(0.0, |p| p.0),
    );
    let worst = f.max_mu1(1).worst();
    let agreement = match &worst {
        Some(Worst::Least { mu1, .. }) if about_limit(*mu1) => Agreement::Agrees,
        _ if share(&near) > 0.0 => Agreement::Partly,
        _ => Agreement::Differs,
    };
    let w = &f.wings[1];
    let at_50 = if w.fails.is_empty() && w.unstable.is_empty() {
        "At μ₁ = 50 it meets the standard at every Mach number.".to_string()
    } else {
        format!(
            "At μ₁ = 50 it diverges {} and fails {}.",
            at_mach(&w.unstable),
            at_mach(&w.fails)
        )
    };
    Assessment {
        agreement,
        computed: format!(
            "The largest μ₁ meeting the standard is within a factor {ABOUT} of 200 at M {}; the worst over {ms_lo:.2}–{ms_hi:.2}: {}. {at_50}",
            where_true(&near),
            worst.map_or("—".into(), |w| w.describe()),
        ),
        tolerance: format!(
            "the worst largest μ₁ over Mach number within a factor {ABOUT} of {MU1_LIMIT} (in part: at some Mach numbers)"
        ),
    }
}

/// "Apparent" (Fig 37): a rise by at least this share from the first
/// subcritical Mach number to 0.9 …
const APPARENT_RISE: f64 = 0.05;
/// … never falling by more than this share between neighbouring Mach
/// numbers (0.01 apart).
const STEP_SLACK: f64 = 1e-3;

/// The rise of `v` from first to last, relative to the first (infinite
/// from zero to a positive value), and whether it never falls by more
/// than [`STEP_SLACK`] between neighbours.
fn rise(v: &[f64]) -> (f64, bool) {
    let (Some(&first), Some(&last)) = (v.first(), v.last()) else {
        return (0.0, false);
    };
    let overall = if first.abs() > 1e-12 {
        (last - first) / first.abs()
    } else if last > first {
        f64::INFINITY
    } else {
        0.0
    };
    let steady = v.windows(2).all(|p| p[1] >= p[0] - STEP_SLACK * p[0].abs());
    (overall, steady)
}

/// §11: damping and frequency of the 45° delta's short period (eq 45, per
/// unit t̂) increase with Mach number at subcritical speeds. Tolerance: each
/// rises by [`APPARENT_RISE`] over M ≤ 0.9, at no step falling by more than
/// [`STEP_SLACK`]; in part when one of them does.
fn subcritical_trend(f: &Findings) -> Assessment {
    let pts = &f.subcritical;
    let damping: Vec<f64> = pts.iter().map(|p| p.damping).collect();
    let frequency: Vec<f64> = pts.iter().map(|p| p.frequency).collect();
    let describe = |name: &str, v: &[f64]| -> (bool, String) {
        let (r, steady) = rise(v);
        let first_last = match (v.first(), v.last()) {
            (Some(a), Some(b)) => format!("from {} to {}", sig(*a, 3), sig(*b, 3)),
            _ => "none".into(),
        };
        let by = if r.is_finite() {
            format!("{}{}", if r >= 0.0 { "+" } else { "" }, percent(r))
        } else {
            "up from zero".into()
        };
        let steps = if steady {
            "never falling"
        } else {
            "falling at some step"
        };
        (
            r >= APPARENT_RISE && steady,
            format!("{name} {first_last} ({by}, {steps})"),
        )
    };
    let (d_ok, d) = describe("damping b/2", &damping);
    let (w_ok, w) = describe("frequency √(k − b²/4)", &frequency);
    let agreement = match (d_ok, w_ok) {
        (true, true) => Agreement::Agrees,
        _ if rise(&damping).0 > 0.0 || rise(&frequency).0 > 0.0 => Agreement::Partly,
        _ => Agreement::Differs,
    };
    let span = match (pts.first(), pts.last()) {
        (Some(a), Some(b)) => format!("M {:.2}–{:.2}", a.mach, b.mach),
        _ => "no subcritical Mach number".into(),
    };
    Assessment {
        agreement,
        computed: format!("Eq (45) per unit t̂ over {span}: {d}; {w}."),
        tolerance: format!(
            "both rise by ≥ {} over M ≤ {SUBCRITICAL}, never falling by more than {} a step (in part: one rises)",
            percent(APPARENT_RISE),
            percent(STEP_SLACK)
        ),
    }
}

/// "Can be neglected": m_ẇ carries at most this share of the short period's
/// damping b (eq 45) at every subcritical Mach number; in part at most
/// [`MWDOT_PARTLY`].
const MWDOT_AGREES: f64 = 0.10;
const MWDOT_PARTLY: f64 = 0.25;

/// §7 (a): m_ẇ can be neglected at subcritical speeds. Tolerance: its share
/// of eq (45)'s damping b at most [`MWDOT_AGREES`] for both wings at every
/// M ≤ 0.9.
fn mwdot_negligible(f: &Findings) -> Assessment {
    let mut worst = 0.0f64;
    let mut parts = Vec::new();
    for (deg, shares) in WINGS.iter().zip(&f.mwdot_share) {
        let abs: Vec<f64> = shares.iter().map(|(_, s)| s.abs()).collect();
        let lo = abs.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = abs.iter().copied().fold(0.0, f64::max);
        worst = worst.max(if abs.is_empty() { f64::INFINITY } else { hi });
        let range = if hi - lo < 0.005 {
            percent(hi)
        } else {
            format!("{}–{}", percent(lo), percent(hi))
        };
        parts.push(format!("{deg}° delta {range}"));
    }
    Assessment {
        agreement: Agreement::at_least(-worst, -MWDOT_AGREES, -MWDOT_PARTLY),
        computed: format!(
            "m_ẇ's share of the short period's damping b (eq 45) at M ≤ {SUBCRITICAL}: {}.",
            parts.join("; ")
        ),
        tolerance: format!(
            "a share ≤ {} at every subcritical Mach number, both wings (in part ≤ {})",
            percent(MWDOT_AGREES),
            percent(MWDOT_PARTLY)
        ),
    }
}

/// §7: (36) gives the 45° delta m_θ̇ > 0 at M = 1.2 over 0.4 < x₀/c₀ < 0.6.
/// Tolerance: m_θ̇ > 0 at every sampled c.g. (0.02 apart); in part at some.
fn m_thetadot_positive_45(f: &Findings) -> Assessment {
    let v = f.m_thetadot_36();
    let positive: Vec<(f64, bool)> = v.iter().map(|&(xo, m)| (xo, m > 0.0)).collect();
    let n = positive.iter().filter(|p| p.1).count();
    let agreement = match n {
        n if n == v.len() && n > 0 => Agreement::Agrees,
        0 => Agreement::Differs,
        _ => Agreement::Partly,
    };
    let show = |k: usize| {
        v.get(k).map_or(String::new(), |(xo, m)| {
            format!("{} at x₀/c₀ = {xo:.2}", sig(*m, 3))
        })
    };
    Assessment {
        agreement,
        computed: format!(
            "m_θ̇ of (36) at M = {NOTE_SUPERSONIC}: {}, {}, {}; positive at x₀/c₀ {} ({n} of {} points).",
            show(0),
            show(v.len() / 2),
            show(v.len().saturating_sub(1)),
            where_true(&positive),
            v.len()
        ),
        tolerance: "m_θ̇ > 0 at every c.g. sampled in 0.4–0.6 (in part: at some)".into(),
    }
}

/// §10: a fuselage's Δm_θ̇ ≈ −0.05 (eq 43) is "a small, but significant
/// value at transonic speeds": a substantial gain in −m_θ̇ is more than it.
const SIGNIFICANT: f64 = 0.05;

/// §10: cropping the tips gives the 45° delta a substantial gain in −m_θ̇ at
/// M = 1.2, not the 60°. Tolerance: the 45°'s gain above [`SIGNIFICANT`],
/// the 60°'s not; in part when one of the two holds.
fn cropping(f: &Findings) -> Assessment {
    let tolerance = format!(
        "the 45° delta gains more than {SIGNIFICANT} in −m_θ̇ (§10's “small, but significant” fuselage increment, eq 43), the 60° delta not (in part: one of the two)"
    );
    let Some(c) = f.cropping() else {
        return Assessment {
            agreement: Agreement::Differs,
            computed: "A cropped or true wing has no result at M = 1.2.".into(),
            tolerance,
        };
    };
    let (big45, big60) = (c[0].gain() > SIGNIFICANT, c[1].gain() > SIGNIFICANT);
    let agreement = match (big45, big60) {
        (true, false) => Agreement::Agrees,
        (false, true) => Agreement::Differs,
        _ => Agreement::Partly,
    };
    let parts: Vec<String> = c
        .iter()
        .map(|x| {
            format!(
                "{}° delta {} → {} (gain {}{})",
                x.sweep_deg,
                sig(x.true_delta, 3),
                sig(x.cropped, 3),
                if x.gain() >= 0.0 { "+" } else { "" },
                sig(x.gain(), 2)
            )
        })
        .collect();
    Assessment {
        agreement,
        computed: format!(
            "−m_θ̇ at M = {NOTE_SUPERSONIC}, tips cropped to taper 1/{} with the c.g. in place: {}.",
            (1.0 / CROPPED_TAPER).round(),
            parts.join("; ")
        ),
        tolerance,
    }
}

/// "Little advantage beyond 60°": the margin gained from 60° to 75° is at
/// most this share of that gained from 45° to 60° (none where that is
/// none) …
const DIMINISHING: f64 = 0.5;
/// … at this share of the Mach numbers (in part: [`DIMINISHING_PARTLY`]).
const DIMINISHING_AGREES: f64 = 0.9;
const DIMINISHING_PARTLY: f64 = 0.5;

/// Whether the margins of 45°, 60°, 75° (eq 41) show returns diminishing
/// beyond 60° ([`DIMINISHING`]).
fn diminishes([m45, m60, m75]: [f64; 3]) -> bool {
    m75 - m60 <= DIMINISHING * (m60 - m45).max(0.0)
}

/// §8: diminishing returns in damping for sweep beyond about 60° (Fig 25).
/// Tolerance: [`diminishes`] at [`DIMINISHING_AGREES`] of the Mach numbers.
fn diminishing_returns(f: &Findings) -> Assessment {
    let m = f.sweep_margins();
    let holds: Vec<(f64, bool)> = m.iter().map(|&(mach, x)| (mach, diminishes(x))).collect();
    let mean =
        |k: usize| m.iter().map(|(_, x)| x[k + 1] - x[k]).sum::<f64>() / m.len().max(1) as f64;
    let s = share(&holds);
    Assessment {
        agreement: Agreement::at_least(s, DIMINISHING_AGREES, DIMINISHING_PARTLY),
        computed: format!(
            "The margin Δm_θ̇ (eq 41) gained from {}° to {}° and from {}° to {}°: on average over Mach number {} then {}; the second at most half the first (or none where the first is none) at M {} ({} of the Mach numbers).",
            SWEEPS_ABOUT_60[0],
            SWEEPS_ABOUT_60[1],
            SWEEPS_ABOUT_60[1],
            SWEEPS_ABOUT_60[2],
            sig(mean(0), 2),
            sig(mean(1), 2),
            where_true(&holds),
            percent(s)
        ),
        tolerance: format!(
            "from 60° to 75° at most {} of the gain from 45° to 60°, at ≥ {} of the Mach numbers (in part ≥ {})",
            percent(DIMINISHING),
            percent(DIMINISHING_AGREES),
            percent(DIMINISHING_PARTLY)
        ),
    }
}

/// §9's approximation is "good": within this relative error …
const OMEGA_CLOSE: f64 = 0.10;
/// … at this share of the Mach numbers (in part: [`OMEGA_CLOSE_PARTLY`]).
const OMEGA_CLOSE_AGREES: f64 = 0.9;
const OMEGA_CLOSE_PARTLY: f64 = 0.5;

/// §9, Fig 32: √(−m_w/(μ₁i_B)) approximates ω̄. Tolerance: within
/// [`OMEGA_CLOSE`] at [`OMEGA_CLOSE_AGREES`] of the Mach numbers, both wings.
fn omega_approximation(f: &Findings) -> Assessment {
    let mut parts = Vec::new();
    let mut close = Vec::new();
    for (deg, errors) in WINGS.iter().zip(&f.omega_approx_error) {
        let within: Vec<(f64, bool)> = errors.iter().map(|&(m, e)| (m, e <= OMEGA_CLOSE)).collect();
        let worst = errors
            .iter()
            .copied()
            .fold(None::<(f64, f64)>, |acc, p| match acc {
                Some(b) if b.1 >= p.1 => Some(b),
                _ => Some(p),
            });
        parts.push(format!(
            "{deg}° delta: within {} at M {}{}",
            percent(OMEGA_CLOSE),
            where_true(&within),
            worst.map_or(String::new(), |(m, e)| format!(
                ", at worst {} off (M = {m:.2})",
                percent(e)
            ))
        ));
        close.extend(within);
    }
    Assessment {
        agreement: Agreement::at_least(share(&close), OMEGA_CLOSE_AGREES, OMEGA_CLOSE_PARTLY),
        computed: format!("{}.", parts.join("; ")),
        tolerance: format!(
            "within {} of the exact ω̄ at ≥ {} of the Mach numbers where the short period oscillates (in part ≥ {})",
            percent(OMEGA_CLOSE),
            percent(OMEGA_CLOSE_AGREES),
            percent(OMEGA_CLOSE_PARTLY)
        ),
    }
}

/// The note's largest ω̄ …
const OMEGA_MAX: f64 = 0.6;
/// … reproduced within this relative error (in part: [`OMEGA_MAX_PARTLY`]).
const OMEGA_MAX_AGREES: f64 = 0.15;
const OMEGA_MAX_PARTLY: f64 = 0.35;

/// §7: the short period's ω̄ reaches at most 0.6. Tolerance: our largest
/// within [`OMEGA_MAX_AGREES`] of it.
fn omega_maximum(f: &Findings) -> Assessment {
    let tolerance = format!(
        "our largest ω̄ within {} of {OMEGA_MAX} (in part {})",
        percent(OMEGA_MAX_AGREES),
        percent(OMEGA_MAX_PARTLY)
    );
    let Some((w, deg, m)) = f.omega_max else {
        return Assessment {
            agreement: Agreement::Differs,
            computed: "No oscillatory short period.".into(),
            tolerance,
        };
    };
    let mangler = f.omega_mangler_max.map_or(String::new(), |wm| {
        format!(
            " With Mangler's frequency-dependent theory iterated to consistency near M = 1 (45° delta), ω̄ converges to at most {}.",
            sig(wm, 3)
        )
    });
    let off = (w / OMEGA_MAX - 1.0).abs();
    Assessment {
        agreement: Agreement::at_least(-off, -OMEGA_MAX_AGREES, -OMEGA_MAX_PARTLY),
        computed: format!(
            "The largest ω̄ is {} ({deg}° delta, M = {m:.2}).{mangler}",
            sig(w, 3)
        ),
        tolerance,
    }
}

/// §8: a forward c.g. improves the 45° delta's damping. Tolerance: eq (41)'s
/// margin larger with the c.g. forward at every Mach number (in part: at
/// half of them).
fn forward_cg(f: &Findings) -> Assessment {
    let better = f.forward_cg_better();
    let [fwd, aft] = CGS;
    Assessment {
        agreement: Agreement::at_least(share(better), 1.0, 0.5),
        computed: format!(
            "The margin Δm_θ̇ (eq 41) is larger with h = {fwd} than with h = {aft} at M {} ({} of {} Mach numbers).",
            where_true(better),
            better.iter().filter(|(_, b)| *b).count(),
            better.len()
        ),
        tolerance: "a larger margin with the c.g. forward at every Mach number (in part: at half)"
            .into(),
    }
}

// ------------------------------------------------- sweeps of the assumptions

/// Steps from ours to each end of an input's range, …
pub const SWEEP_STEPS: usize = 4;
/// … and the halvings of the step where the verdict first reverses.
pub const SWEEP_HALVINGS: usize = 5;

/// Where a conclusion's verdict reverses as an unstated input moves from
/// ours toward each end of its range.
#[derive(Debug, Clone, PartialEq)]
pub struct Reversal {
    pub assumption: Assumption,
    /// Our value, and the range swept.
    pub ours: f64,
    pub range: (f64, f64),
    /// Whether the claim is reproduced at ours.
    pub reproduced: bool,
    /// The nearest value below ours, and above, where it reverses.
    pub below: Option<f64>,
    pub above: Option<f64>,
}

impl Reversal {
    /// In words: "Holds for every i_B in 0.04–0.2 (ours 0.08)." or
    /// "Reversed above i_B ≈ 0.14 (ours 0.08; swept 0.04–0.2)."
    pub fn describe(&self) -> String {
        let s = self.assumption.symbol();
        let (lo, hi) = self.range;
        let ours = self.ours;
        let sides: Vec<String> = [("below", self.below), ("above", self.above)]
            .iter()
            .filter_map(|(side, v)| v.map(|v| format!("{side} {s} ≈ {}", sig(v, 2))))
            .collect();
        match (self.reproduced, sides.is_empty()) {
            (true, true) => format!("Holds for every {s} in {lo}–{hi} (ours {ours})."),
            (false, true) => format!("Not reproduced for any {s} in {lo}–{hi} (ours {ours})."),
            (true, false) => format!(
                "Reversed {} (ours {ours}; swept {lo}–{hi}).",
                sides.join(" and ")
            ),
            (false, false) => format!(
                "Would be reproduced {} (ours {ours}; swept {lo}–{hi}).",
                sides.join(" and ")
            ),
        }
    }
}

/// The nearest value from `from` toward `to` where `reproduced` differs
/// from `at_from`: [`SWEEP_STEPS`] steps, then [`SWEEP_HALVINGS`] halvings
/// of the step where it first differs; the middle of the last bracket.
pub fn nearest_reversal(
    reproduced: &dyn Fn(f64) -> bool,
    at_from: bool,
    from: f64,
    to: f64,
) -> Option<f64> {
    let step = (to - from) / SWEEP_STEPS as f64;
    let value = |i: usize| {
        if i == SWEEP_STEPS {
            to
        } else {
            from + step * i as f64
        }
    };
    let i = (1..=SWEEP_STEPS).find(|&i| reproduced(value(i)) != at_from)?;
    let (mut same, mut other) = (value(i - 1), value(i));
    for _ in 0..SWEEP_HALVINGS {
        let mid = 0.5 * (same + other);
        if reproduced(mid) == at_from {
            same = mid;
        } else {
            other = mid;
        }
    }
    Some(0.5 * (same + other))
}

/// The study redone under other values of the unstated inputs, each once
/// (their findings are shared by the conclusions).
struct Trials {
    ours: Assumed,
    made: RefCell<Vec<(Assumed, Rc<Findings>)>>,
}

impl Trials {
    fn at(&self, a: Assumed) -> Rc<Findings> {
        if let Some((_, f)) = self.made.borrow().iter().find(|(b, _)| *b == a) {
            return f.clone();
        }
        let f = Rc::new(Findings::new(Study::assuming(a)));
        self.made.borrow_mut().push((a, f.clone()));
        f
    }
}

/// Where `c`'s verdict (reproduced at ours or not) reverses over `a`'s range.
fn sweep(c: &Conclusion, a: Assumption, reproduced: bool, trials: &Trials) -> Reversal {
    let ours = a.of(trials.ours);
    let range = a.range();
    let at = |v: f64| {
        let f = trials.at(a.set(trials.ours, v));
        (c.assess)(&f).agreement.reproduced()
    };
    Reversal {
        assumption: a,
        ours,
        range,
        reproduced,
        below: nearest_reversal(&at, reproduced, ours, range.0),
        above: nearest_reversal(&at, reproduced, ours, range.1),
    }
}

/// A conclusion judged on our findings, with the sweeps over the unstated
/// inputs its verdict depends on.
pub struct Judged {
    pub conclusion: &'static Conclusion,
    pub assessment: Assessment,
    pub sweeps: Vec<Reversal>,
}

impl Judged {
    pub fn reproduced(&self) -> bool {
        self.assessment.agreement.reproduced()
    }

    /// Ours, in words: the computed numbers, then each sweep.
    pub fn ours(&self) -> String {
        let mut s = self.assessment.computed.clone();
        for r in &self.sweeps {
            s.push(' ');
            s.push_str(&r.describe());
        }
        s
    }
}

/// Every conclusion judged on `f` (ours), each swept over the unstated
/// inputs it depends on.
pub fn judge_all(f: &Findings) -> Vec<Judged> {
    let trials = Trials {
        ours: f.assumed(),
        made: RefCell::new(Vec::new()),
    };
    CONCLUSIONS
        .iter()
        .map(|c| {
            let assessment = (c.assess)(f);
            let reproduced = assessment.agreement.reproduced();
            let sweeps = c
                .depends_on
                .iter()
                .map(|&a| sweep(c, a, reproduced, &trials))
                .collect();
            Judged {
                conclusion: c,
                assessment,
                sweeps,
            }
        })
        .collect()
}

/// A sweep in `summary.json`.
#[derive(Serialize)]
pub struct ReversalJson {
    assumption: &'static str,
    ours: f64,
    range: [f64; 2],
    reversed_below: Option<f64>,
    reversed_above: Option<f64>,
}

/// A conclusion in `summary.json`: the note's claim, where it says it, ours
/// (numbers and sweeps, in words), whether it is reproduced; then its id,
/// subject, agreement, tolerance, why ours parts from it (when it does) and
/// the sweeps.
#[derive(Serialize)]
pub struct ConclusionJson {
    claim: &'static str,
    section: &'static str,
    ours: String,
    reproduced: bool,
    id: &'static str,
    subject: &'static str,
    agreement: &'static str,
    tolerance: String,
    why: Option<&'static str>,
    assumptions: Vec<ReversalJson>,
}

pub fn conclusions_json(judged: &[Judged]) -> Vec<ConclusionJson> {
    judged
        .iter()
        .map(|j| {
            let c = j.conclusion;
            ConclusionJson {
                claim: c.claim,
                section: c.section,
                ours: j.ours(),
                reproduced: j.reproduced(),
                id: c.id,
                subject: c.subject,
                agreement: j.assessment.agreement.as_str(),
                tolerance: j.assessment.tolerance.clone(),
                why: (!j.reproduced()).then_some(c.when_they_part),
                assumptions: j
                    .sweeps
                    .iter()
                    .map(|r| ReversalJson {
                        assumption: r.assumption.symbol(),
                        ours: r.ours,
                        range: [r.range.0, r.range.1],
                        reversed_below: r.below,
                        reversed_above: r.above,
                    })
                    .collect(),
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tolerances_are_applied_as_stated() {
        assert_eq!(Agreement::at_least(0.8, 0.8, 0.25), Agreement::Agrees);
        assert_eq!(Agreement::at_least(0.64, 0.8, 0.25), Agreement::Partly);
        assert_eq!(Agreement::at_least(0.1, 0.8, 0.25), Agreement::Differs);
        assert!(Agreement::Agrees.reproduced() && !Agreement::Partly.reproduced());
        // "about 200": 160–250
        assert!(about_limit(161.0) && about_limit(249.0));
        assert!(!about_limit(150.0) && !about_limit(99.6));
        // a rise from 22.8 to 23.2 is steady but not apparent; a dip fails
        assert!(rise(&[22.8, 23.0, 23.2]).1);
        assert!(rise(&[22.8, 23.0, 23.2]).0 < APPARENT_RISE);
        assert!(!rise(&[1.0, 1.2, 1.1, 1.3]).1);
        assert_eq!(rise(&[0.0, 0.0, 2.4]), (f64::INFINITY, true));
        // beyond 60°: a third of the gain diminishes, more than half does
        // not; where 45°→60° loses, 75° must not gain
        assert!(diminishes([-0.4, 0.4, 0.5]));
        assert!(!diminishes([-0.4, 0.4, 0.9]));
        assert!(diminishes([3.4, 1.9, 0.8]));
        assert!(!diminishes([0.13, 0.13, 0.28]));
    }

    /// The sweep finds a reversal to within a 32nd of its step, on the side
    /// it is, and says so; none where the verdict holds.
    #[test]
    fn the_sweep_finds_the_nearest_reversal() {
        let holds_below = |v: f64| v < 0.137;
        let above = nearest_reversal(&holds_below, true, 0.08, 0.2).unwrap();
        assert!((above - 0.137).abs() <= 0.03 / 32.0, "{above}");
        assert_eq!(nearest_reversal(&holds_below, true, 0.08, 0.04), None);
        let r = Reversal {
            assumption: Assumption::IB,
            ours: 0.08,
            range: (0.04, 0.2),
            reproduced: true,
            below: None,
            above: Some(above),
        };
        assert_eq!(
            r.describe(),
            "Reversed above i_B ≈ 0.14 (ours 0.08; swept 0.04–0.2)."
        );
        let r = Reversal {
            reproduced: false,
            above: None,
            ..r
        };
        assert_eq!(
            r.describe(),
            "Not reproduced for any i_B in 0.04–0.2 (ours 0.08)."
        );
    }
}
