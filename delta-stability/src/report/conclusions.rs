//! The note's conclusions, each set beside what we computed, with the
//! numbers. A conclusion is one entry of [`CONCLUSIONS`]: where the note
//! says it, its words, and a function that judges it against the
//! [`Findings`]; adding one is adding an entry (and, if it needs a number
//! not yet found, a field of `Findings`).

use super::study::WINGS;
use super::summary::{Findings, show_intervals};
use crate::fmt::sig;
use stability_core::study::intervals;

/// The intervals of `points` (x, flag) where the flag holds, in words.
fn where_true(points: &[(f64, bool)]) -> String {
    let (x, flags): (Vec<f64>, Vec<bool>) = points.iter().copied().unzip();
    show_intervals(&intervals(&x, &flags))
}

/// The share of `points` whose flag holds.
fn share(points: &[(f64, bool)]) -> f64 {
    if points.is_empty() {
        return 0.0;
    }
    points.iter().filter(|(_, f)| *f).count() as f64 / points.len() as f64
}

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

    /// `Agrees` within `close`, `Partly` within `near`, else `Differs`.
    fn by(deviation: f64, close: f64, near: f64) -> Agreement {
        if deviation <= close {
            Agreement::Agrees
        } else if deviation <= near {
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
}

/// One of the note's conclusions.
pub struct Conclusion {
    /// What it is about: "45° delta".
    pub subject: &'static str,
    /// Where the note says it: "§9, Fig 33".
    pub source: &'static str,
    /// The note's claim, in its words.
    pub claim: &'static str,
    /// Judges the claim against what was computed.
    pub assess: fn(&Findings) -> Assessment,
    /// Why our models may part from the note here, shown when they do.
    pub when_they_part: &'static str,
}

pub const CONCLUSIONS: &[Conclusion] = &[
    Conclusion {
        subject: "45° delta",
        source: "Summary; §9, Fig 33",
        claim: "Inadequately damped at transonic speeds: a tailplane is needed “to correct the serious instability in the range 0.97 < M < 1.5”.",
        assess: tailplane_45,
        when_they_part: "Our faired damping derivatives keep the 45° delta's short period damped through M = 1: linear supersonic theory (36), the source of the adverse m_ẇ, takes over only above M = 1 (Figs 19–24), where the note's faired curves were steeper.",
    },
    Conclusion {
        subject: "60° delta",
        source: "Summary; §9, Fig 33",
        claim: "Adequately damped “for values of the relative density parameter μ₁ … less than about 200”.",
        assess: mu1_limit_60,
        when_they_part: "The largest μ₁ here is found on the exact roots (not §8's approximation), at i_B = 0.08, which the note does not state.",
    },
    Conclusion {
        subject: "both wings",
        source: "§9, Fig 32",
        claim: "√(−m_w/(μ₁i_B)) is “a good first approximation to the short period frequency parameter” ω̄.",
        assess: omega_approximation,
        when_they_part: "The approximation is the undamped frequency of the short-period approximation; the exact ω̄ is the damped frequency of the exact roots, far below it where the short period is heavily damped.",
    },
    Conclusion {
        subject: "both wings",
        source: "§9",
        claim: "“The frequency parameter for the short period oscillation has in fact a maximum value of 0.6.”",
        assess: omega_maximum,
        when_they_part: "Our ω̄ comes from the exact short-period roots at μ₁ = 50 and our i_B = 0.08.",
    },
    Conclusion {
        subject: "45° delta",
        source: "§7, Fig 17",
        claim: "Supersonic theory (36) gives “negative damping for the specified practical C.G. range of 0.4 < x₀/c₀ < 0.6 at M = 1.2”.",
        assess: negative_damping_45,
        when_they_part: "",
    },
    Conclusion {
        subject: "45° delta",
        source: "§8, Figs 25–26",
        claim: "“Forward movement of the C.G. improves the damping.”",
        assess: forward_cg,
        when_they_part: "Eq (41)'s margin weighs the damping against the stiffness, which a forward c.g. increases; the note finds the stiffness outweighing the gain only above 60° of sweep.",
    },
];

/// Every conclusion with its assessment.
pub fn assess_all(f: &Findings) -> Vec<(&'static Conclusion, Assessment)> {
    CONCLUSIONS.iter().map(|c| (c, (c.assess)(f))).collect()
}

/// The length of `[a, b]` covered by `intervals`.
fn covered(intervals: &[[f64; 2]], a: f64, b: f64) -> f64 {
    intervals
        .iter()
        .map(|[lo, hi]| (hi.min(b) - lo.max(a)).max(0.0))
        .sum()
}

fn tailplane_45(f: &Findings) -> Assessment {
    let w = &f.wings[0];
    let (a, b) = (0.97, 1.5);
    let diverges = covered(&w.unstable, a, b) / (b - a);
    let fails = covered(&w.fails, a, b) / (b - a) + diverges;
    let agreement = if diverges >= 0.5 {
        Agreement::Agrees
    } else if fails >= 0.25 {
        Agreement::Partly
    } else {
        Agreement::Differs
    };
    let most = w.most_cycles.map_or("—".into(), |(m, c)| {
        format!(
            "{} cycles to half amplitude at M = {}",
            sig(c, 3),
            sig(m, 3)
        )
    });
    Assessment {
        agreement,
        computed: format!(
            "Divergent short period for M in {}; more than one cycle to halve for M in {} — together {}% of 0.97–1.5. Least damped: {most}.",
            show_intervals(&w.unstable),
            show_intervals(&w.fails),
            sig(100.0 * fails.min(1.0), 2),
        ),
    }
}

fn mu1_limit_60(f: &Findings) -> Assessment {
    let w = &f.wings[1];
    let Some((m, v)) = w.least_max_mu1 else {
        return Assessment {
            agreement: Agreement::Differs,
            computed: "No μ₁ meets the standard at some Mach number.".into(),
        };
    };
    // "about 200": within 25 %
    let near: Vec<(f64, bool)> = w
        .max_mu1
        .iter()
        .map(|&(m, v)| (m, v.is_some_and(|v| (v / 200.0).ln().abs() <= 1.25f64.ln())))
        .collect();
    let agreement = if (v / 200.0).ln().abs() <= 1.25f64.ln() {
        Agreement::Agrees
    } else if share(&near) > 0.0 {
        Agreement::Partly
    } else {
        Agreement::Differs
    };
    let at_50 = if w.fails.is_empty() && w.unstable.is_empty() {
        "At μ₁ = 50 it meets the standard at every Mach number.".to_string()
    } else {
        format!(
            "At μ₁ = 50 it fails the standard for M in {}.",
            show_intervals(&w.fails)
        )
    };
    Assessment {
        agreement,
        computed: format!(
            "The largest μ₁ meeting the standard is within 25% of 200 for M in {}, and falls to {} at M = {} (0.5 ≤ M ≤ 2). {at_50}",
            where_true(&near),
            sig(v, 3),
            sig(m, 3)
        ),
    }
}

fn omega_approximation(f: &Findings) -> Assessment {
    let mut parts = Vec::new();
    let mut close = Vec::new();
    for (deg, errors) in WINGS.iter().zip(&f.omega_approx_error) {
        let within: Vec<(f64, bool)> = errors.iter().map(|&(m, e)| (m, e <= 0.10)).collect();
        let worst = errors
            .iter()
            .copied()
            .fold(None::<(f64, f64)>, |acc, p| match acc {
                Some(b) if b.1 >= p.1 => Some(b),
                _ => Some(p),
            });
        parts.push(format!(
            "{deg}° delta: within 10% for M in {}{}",
            where_true(&within),
            worst.map_or(String::new(), |(m, e)| format!(
                ", at worst {}% off (M = {})",
                sig(100.0 * e, 2),
                sig(m, 3)
            ))
        ));
        close.extend(within);
    }
    let s = share(&close);
    Assessment {
        agreement: Agreement::by(1.0 - s, 0.1, 0.5),
        computed: format!("{}.", parts.join("; ")),
    }
}

fn omega_maximum(f: &Findings) -> Assessment {
    let Some((w, deg, m)) = f.omega_max else {
        return Assessment {
            agreement: Agreement::Differs,
            computed: "No oscillatory short period.".into(),
        };
    };
    let mangler = f.omega_mangler_max.map_or(String::new(), |wm| {
        format!(
            " With Mangler's frequency-dependent theory iterated to consistency near M = 1 (45° delta), ω̄ converges to at most {}.",
            sig(wm, 3)
        )
    });
    Assessment {
        agreement: Agreement::by((w / 0.6 - 1.0).abs(), 0.15, 0.35),
        computed: format!(
            "The largest ω̄ is {} ({deg}° delta, M = {}).{mangler}",
            sig(w, 3),
            sig(m, 3)
        ),
    }
}

fn negative_damping_45(f: &Findings) -> Assessment {
    let v = &f.supersonic_damping_45;
    let negative = v.iter().filter(|(_, d)| *d < 0.0).count();
    let agreement = match negative {
        n if n == v.len() && n > 0 => Agreement::Agrees,
        0 => Agreement::Differs,
        _ => Agreement::Partly,
    };
    let values: Vec<String> = v
        .iter()
        .map(|(xo, d)| format!("{} at x₀/c₀ = {xo}", sig(*d, 3)))
        .collect();
    Assessment {
        agreement,
        computed: format!("−m_θ̇ of theory (36) at M = 1.2: {}.", values.join(", ")),
    }
}

fn forward_cg(f: &Findings) -> Assessment {
    let better = &f.forward_cg_better;
    Assessment {
        agreement: Agreement::by(1.0 - share(better), 0.0, 0.5),
        computed: format!(
            "The margin Δm_θ̇ (eq 41) is larger with h = 0.15 than with h = 0.35 for M in {} ({} of {} Mach numbers from 0.5 to 2).",
            where_true(better),
            better.iter().filter(|(_, b)| *b).count(),
            better.len()
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::summary::Wing;

    fn findings(unstable: Vec<[f64; 2]>, fails: Vec<[f64; 2]>, least_mu1: f64) -> Findings {
        let wing = |deg| Wing {
            sweep_deg: deg,
            unstable: unstable.clone(),
            fails: fails.clone(),
            max_mu1: vec![],
            least_max_mu1: Some((2.0, least_mu1)),
            most_cycles: Some((1.2, 1.5)),
        };
        Findings {
            wings: [wing(45.0), wing(60.0)],
            omega_approx_error: [vec![(1.0, 0.05)], vec![(1.0, 0.05), (1.1, 0.3)]],
            omega_max: Some((0.75, 45.0, 1.1)),
            omega_mangler_max: None,
            supersonic_damping_45: vec![(0.4, -0.1), (0.5, 0.2)],
            forward_cg_better: vec![(1.0, true), (1.1, true)],
        }
    }

    #[test]
    fn a_claim_is_judged_by_the_numbers_not_fixed_text() {
        // the note's instability over 0.97–1.5, computed divergent there
        let a = tailplane_45(&findings(vec![[0.95, 1.6]], vec![], 200.0));
        assert_eq!(a.agreement, Agreement::Agrees);
        assert!(a.computed.contains("0.95–1.60"), "{}", a.computed);
        // computed only as more than a cycle over part of it
        let a = tailplane_45(&findings(vec![], vec![[1.16, 2.0]], 200.0));
        assert_eq!(a.agreement, Agreement::Partly);
        assert!(a.computed.contains("64%"), "{}", a.computed);
        // computed nowhere
        let a = tailplane_45(&findings(vec![], vec![], 200.0));
        assert_eq!(a.agreement, Agreement::Differs);
        // the 60° delta's limit: 210 agrees with "about 200"; 100 at the
        // least but 200 at some Mach number, in part; never near 200, not
        for (least, at_some, want) in [
            (210.0, 210.0, Agreement::Agrees),
            (100.0, 190.0, Agreement::Partly),
            (20.0, 30.0, Agreement::Differs),
        ] {
            let mut f = findings(vec![], vec![], least);
            f.wings[1].max_mu1 = vec![(1.2, Some(at_some)), (2.0, Some(least))];
            let a = mu1_limit_60(&f);
            assert_eq!(a.agreement, want, "{least}: {}", a.computed);
        }
        // two of three points within 10 %
        assert_eq!(
            omega_approximation(&findings(vec![], vec![], 200.0)).agreement,
            Agreement::Partly
        );
        let f = findings(vec![], vec![], 200.0);
        assert_eq!(omega_maximum(&f).agreement, Agreement::Partly);
        assert_eq!(negative_damping_45(&f).agreement, Agreement::Partly);
        assert_eq!(forward_cg(&f).agreement, Agreement::Agrees);
    }
}
