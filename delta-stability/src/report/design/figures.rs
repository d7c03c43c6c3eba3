//! A design's figures against Mach number, each as SVG and CSV: the modes
//! (eq 8's cycles to half amplitude with the one-cycle line of §8, the
//! roots, ζ, ωₙ, period and time to half or double), §8's margin Δm_θ̇
//! (eq 41), the MIL-F-8785C levels and CAP, §9's margins (eq 42) and the
//! aerodynamic centre beside the c.g., and every coefficient and
//! derivative with its source. The boundaries drawn are read from the
//! library's own definitions ([`stability_core::criteria`],
//! [`stability_core::criteria::cap::regions`]), not restated.

use super::{Design, phugoid, short_period, times};
use stability_core::criteria::cap::regions;
use stability_core::criteria::{Category, Level, phugoid_level, short_period_level};
use stability_core::dynamics::modes::Mode;
use stability_io::design_point::Results;
use stability_io::plot::Plate;
use stability_io::plot::short;

/// The page's sections of figures, in order: each a title and its plates.
pub fn sections(d: &Design) -> Vec<(&'static str, Vec<Plate>)> {
    vec![
        ("The modes across Mach number (eqs 4–8)", modes(d)),
        (
            "§8: the one-cycle standard and its margin (eq 41)",
            vec![standard(d)],
        ),
        ("MIL-F-8785C: damping levels and CAP", mil(d)),
        ("§9: margins and the aerodynamic centre (eq 42)", margins(d)),
        (
            "The coefficients and derivatives, with their sources (§6–7)",
            derivatives(d),
        ),
    ]
}

/// Cycles to half amplitude, negative where the mode grows (cycles to
/// double): Fig 33's convention.
fn cycles(m: &Mode) -> Option<f64> {
    m.cycles_to_half.or(m.cycles_to_double.map(|c| -c))
}

fn modes(d: &Design) -> Vec<Plate> {
    let (t, w) = (d.time_unit(), d.rate_unit());
    let mut cyc = d
        .figure(
            "Cycles to half amplitude of the short period and the phugoid",
            "cycles to half amplitude (negative: to double)",
        )
        .with(d.curve("short period", |r| short_period(r).and_then(cycles)))
        .with(d.curve("phugoid", |r| phugoid(r).and_then(cycles)));
    cyc.reference_lines
        .push((1.0, "one cycle: §8's standard met below".into()));
    let mut out = vec![Plate::named(
        "cycles-to-half",
        cyc,
        "Eq (8): cycles = (ln 2/2π)·|s/r|. The standard (§8) asks that the short period halve within one cycle; a negative value is the cycles to double of a mode that grows. A gap: the mode does not oscillate there (its roots are real) or the point has no result.",
    )];
    out.push(roots(d, "re", "Real parts of the four roots", |z| z.re));
    out.push(roots(d, "im", "Imaginary parts of the four roots", |z| {
        z.im
    }));
    let zeta = damping_ratio(d);
    out.push(zeta);
    for (file, name, pick) in [
        (
            "short-period",
            "short period",
            short_period as fn(&Results) -> Option<&Mode>,
        ),
        ("phugoid", "phugoid", phugoid),
    ] {
        let wn = d
            .figure(
                &format!("Undamped natural frequency ωₙ of the {name}"),
                &format!("ωₙ ({w})"),
            )
            .with(d.curve(name, |r| pick(r).map(|m| times(r, m).natural_frequency)));
        out.push(Plate::named(
            &format!("{file}-frequency"),
            wn,
            format!("ωₙ = |λ| of the {name}'s roots, in {w}."),
        ));
        let tf = d
            .figure(
                &format!("Period and time to half or double: the {name}"),
                &format!("time ({t})"),
            )
            .with(d.curve("period", |r| pick(r).and_then(|m| times(r, m).period)))
            .with(d.curve("time to half amplitude", |r| {
                pick(r).and_then(|m| times(r, m).time_to_half)
            }))
            .with(d.curve("time to double amplitude", |r| {
                pick(r).and_then(|m| times(r, m).time_to_double)
            }));
        out.push(Plate::named(
            &format!("{file}-times"),
            tf,
            format!(
                "Period 2π/s and time to half (or double) amplitude ln 2/|r| of the {name}, in {}.",
                if d.physical() {
                    "seconds"
                } else {
                    "units of τ = m/(½ρSV)"
                }
            ),
        ));
    }
    out
}

/// The four roots' `part` (re or im) across Mach number.
fn roots(d: &Design, part: &str, title: &str, f: fn(num_complex::Complex64) -> f64) -> Plate {
    let w = d.rate_unit();
    let mut fig = d.figure(title, &format!("{part} λ ({w})"));
    for k in 0..4 {
        fig = fig.with(d.curve(&format!("λ{}", k + 1), |r| {
            let z = r.result.analysis.roots[k];
            Some(f(r.tau().map_or(z, |t| z / t)))
        }));
    }
    if part == "re" {
        fig.reference_lines
            .push((0.0, "r = 0: a root to the right grows".into()));
    }
    Plate::named(
        &format!("roots-{part}"),
        fig,
        format!(
            "The quartic's four roots (eqs 4–6 corrected, docs/errata.md), conjugates adjacent, fastest first, in {w}. A root with a positive real part grows."
        ),
    )
}

/// Where `level` of ζ changes, as ζ rises from −1 to 2: each boundary
/// found by bisection on the library's own rule.
fn boundaries(level: impl Fn(f64) -> Level) -> Vec<(f64, Level)> {
    let mut out = Vec::new();
    for k in -1000..2000 {
        let (mut a, mut b) = (k as f64 / 1000.0, (k + 1) as f64 / 1000.0);
        let (la, lb) = (level(a), level(b));
        if la == lb {
            continue;
        }
        for _ in 0..60 {
            let mid = 0.5 * (a + b);
            if level(mid) == la { a = mid } else { b = mid }
        }
        out.push((b, la.min(lb)));
    }
    out
}

fn damping_ratio(d: &Design) -> Plate {
    let mut fig = d
        .figure(
            "Damping ratio ζ of the short period and the phugoid",
            "damping ratio ζ",
        )
        .with(d.curve("short period", |r| {
            short_period(r).and_then(|m| m.damping_ratio)
        }))
        .with(d.curve("phugoid", |r| phugoid(r).and_then(|m| m.damping_ratio)));
    // the lower bounds up to ζ = 0.6 (the upper ones lie above 1.3), as
    // curves of their own (told apart in the legend, and in the CSV)
    for (z, l) in boundaries(|z| short_period_level(z, Category::A)) {
        if z < 0.6 {
            let label = format!(
                "short period {} from ζ = {} (Cat. A, C)",
                l.as_str(),
                short(z)
            );
            fig = fig.with(d.curve(&label, |_| Some(z)));
        }
    }
    for (z, l) in boundaries(|z| phugoid_level(z, None)) {
        let label = format!("phugoid {} from ζ = {}", l.as_str(), short(z));
        fig = fig.with(d.curve(&label, |_| Some(z)));
    }
    fig.y_range = Some((-0.2, 1.2));
    Plate::named(
        "damping-ratio",
        fig,
        "ζ = −r/|λ|. The flat lines are MIL-F-8785C's lower bounds (§3.2.2.1.2, Table IV, Categories A and C; Category B's are 0.30 and 0.20; §3.2.1.2 for the phugoid), read from the library's rule.",
    )
}

fn standard(d: &Design) -> Plate {
    let ds = |r: &Results| r.result.analysis.damping_standard;
    let mut fig = d
        .figure(
            "Ability to damp the short period to half amplitude in one cycle",
            "Δm_θ̇ = m_θ̇max − m_θ̇ (eq 41)",
        )
        .with(d.curve("Δm_θ̇ (eq 41)", |r| ds(r).margin))
        .with(d.curve("Δm_θ̇, exact m_θ̇max", |r| ds(r).margin_exact));
    fig.reference_lines.push((0.0, "standard met above".into()));
    Plate::named(
        "standard",
        fig,
        "Δm_θ̇ > 0: §8's approximation says the short period halves within one cycle; beside it the margin over the m_θ̇ at which the exact quartic takes one cycle.",
    )
}

/// A level as a number: 1, 2, 3, or 4 for worse than Level 3.
fn number(l: Level) -> f64 {
    f64::from(l.number())
}

fn mil(d: &Design) -> Vec<Plate> {
    let fq = |r: &Results| {
        r.result
            .analysis
            .flying_qualities(stability_core::analysis::Timebase::Tau(r.tau()))
    };
    let mut lv = d.figure(
        "MIL-F-8785C levels: damping",
        "level (4: worse than Level 3)",
    );
    for (name, cat) in [("A", Category::A), ("B", Category::B), ("C", Category::C)] {
        lv = lv.with(d.curve(&format!("short period, Category {name}"), |r| {
            fq(r).short_period.map(|s| {
                number(match cat {
                    Category::A => s.a,
                    Category::B => s.b,
                    Category::C => s.c,
                })
            })
        }));
    }
    lv = lv.with(d.curve("phugoid", |r| fq(r).phugoid.map(|p| number(p.level))));
    lv.y_range = Some((0.5, 4.5));
    let mut out = vec![Plate::named(
        "levels-damping",
        lv,
        "The short period's damping ratio against §3.2.2.1.2 in each flight-phase category, the phugoid's against §3.2.1.2.",
    )];
    if d.physical() {
        out.extend(cap(d));
    }
    out
}

fn cap(d: &Design) -> Vec<Plate> {
    let spf = |r: &Results| r.engineering.short_period_frequency;
    let mut fig = d
        .figure(
            "Control anticipation parameter CAP = ωₙ²/(n/α)",
            "CAP (1/(g·s²))",
        )
        .with(d.curve("CAP", |r| spf(r).map(|s| s.cap)));
    // Category A's regions are the same for every class (§3.2.2.1.1)
    let rs = regions(
        Category::A,
        d.class
            .class
            .unwrap_or(stability_core::criteria::cap::AirplaneClass::IV),
    );
    for (k, r) in rs.iter().take(2).enumerate() {
        let l = k + 1;
        let (lo, hi) = (r.cap_min, r.cap_max);
        let span = hi.map_or(format!("above {}", short(lo)), |h| {
            format!("{}–{}", short(lo), short(h))
        });
        fig = fig.with(
            d.curve(&format!("Category A, Level {l}: {span} (lower)"), |_| {
                Some(lo)
            }),
        );
        if let Some(h) = hi {
            fig = fig.with(
                d.curve(&format!("Category A, Level {l}: {span} (upper)"), |_| {
                    Some(h)
                }),
            );
        }
    }
    let mut lv = d.figure(
        "MIL-F-8785C levels: short-period frequency (CAP)",
        "level (4: worse than Level 3)",
    );
    for name in ["A", "B", "C"] {
        lv = lv.with(d.curve(&format!("Category {name}"), |r| {
            spf(r).and_then(|s| match name {
                "A" => Some(number(s.a)),
                "B" => Some(number(s.b)),
                _ => s.c.map(number),
            })
        }));
    }
    lv.y_range = Some((0.5, 4.5));
    vec![
        Plate::named(
            "cap",
            fig,
            format!(
                "§3.2.2.1.1: n/α = −z_w/C_L (g/rad). The lines bound Category A's Levels 1 and 2 (the ωₙ floors and the other categories are in the levels beside; {} for Category C).",
                d.class.describe("--class")
            ),
        ),
        Plate::named(
            "levels-cap",
            lv,
            "The short period's frequency against §3.2.2.1.1 (Figure 1–3), in each category.",
        ),
    ]
}

fn margins(d: &Design) -> Vec<Plate> {
    use stability_core::criteria::Margins;
    let m = |r: &Results| {
        let r = &r.result;
        Margins::at_cg(
            &r.analysis.quartic,
            &r.derivatives,
            r.coefficients.lift_slope.value,
            d.cfg.case.h,
        )
    };
    let mut fig = d
        .figure(
            "Static and manoeuvre margins",
            "margin (fraction of M.A.C.)",
        )
        .with(d.curve("static margin K_n (eq 42)", |r| m(r).static_margin))
        .with(d.curve("manoeuvre margin H_m (§9)", |r| m(r).manoeuvre_margin));
    fig.reference_lines.push((0.0, "neutral".into()));
    let pos = d
        .figure(
            "The aerodynamic centre and the c.g.",
            "position (fraction of M.A.C. aft of its leading edge)",
        )
        .with(d.curve("aerodynamic centre H₀", |r| {
            Some(r.result.coefficients.aerodynamic_centre.value)
        }))
        .with(d.curve("neutral point h_n (m_w = 0)", |r| m(r).neutral_point))
        .with(d.curve("c.g. h", |_| Some(d.cfg.case.h)));
    vec![
        Plate::named(
            "margins",
            fig,
            "K_n from the quartic's E (eq 42: E = 2(μ₁/i_B)C_L²aK_n), H_m from its C (§9), both stick fixed; positive is stable.",
        ),
        Plate::named(
            "positions",
            pos,
            format!(
                "H₀ from {}. The neutral point h_n = h + m_w/z_w is the c.g. at which m_w = 0 at constant speed (the wing alone: h_n = H₀); the static margin is h_n − h; K_n (eq 42) differs from it by the Mach-number term of E.",
                d.sources(|r| r.result.coefficients.origin.aerodynamic_centre.describe())
            ),
        ),
    ]
}

fn derivatives(d: &Design) -> Vec<Plate> {
    let co = |r: &Results| r.result.coefficients;
    let lift = d
        .figure("Lift slope ∂C_L/∂α", "∂C_L/∂α (per radian)")
        .with(d.curve("∂C_L/∂α", |r| Some(co(r).lift_slope.value)));
    let drag = d
        .figure(
            "Drag: zero-lift C_D0 and the factor K of C_D = C_D0 + KC_L²",
            "C_D0, K",
        )
        .with(d.curve("C_D0", |r| Some(co(r).zero_lift_drag.value)))
        .with(d.curve("K", |r| Some(co(r).drag_due_to_lift.value)));
    let from = |f: fn(&Results) -> String| d.sources(f);
    let mut out = vec![
        Plate::named(
            "lift-slope",
            lift,
            format!(
                "∂C_L/∂α from {}.",
                from(|r| r.result.coefficients.origin.lift_slope.describe())
            ),
        ),
        Plate::named(
            "drag",
            drag,
            format!(
                "C_D0 from {}; K from {}.",
                from(|r| r.result.coefficients.origin.zero_lift_drag.describe()),
                from(|r| r.result.coefficients.origin.drag_due_to_lift.describe())
            ),
        ),
    ];
    let names = stability_core::Derivatives::QUARTIC_INPUTS;
    let theory = from(|r| {
        format!(
            "{} {}",
            r.result.damping.theory.name(),
            r.result.damping.theory.equations()
        )
    });
    for (file, title, idx, caption) in [
        (
            "stiffness",
            "Stiffness derivatives (report notation, §3)",
            [0usize, 1, 4, 5, 8, 9],
            "From the coefficients (eqs 9–14, 25–29): ∂C_L/∂α and H₀ as above.".to_string(),
        ),
        (
            "damping-derivatives",
            "Damping derivatives (report notation, §3)",
            [3, 7, 11, 2, 6, 10],
            format!("From the damping theory: {theory}."),
        ),
    ] {
        let mut fig = d.figure(title, "derivative (report notation)");
        for k in idx {
            fig = fig.with(d.curve(names[k], |r| {
                Some(r.result.derivatives.quartic_input_values()[k])
            }));
        }
        out.push(Plate::named(file, fig, caption));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The boundaries found are MIL-F-8785C's (Table IV; §3.2.1.2).
    #[test]
    fn the_level_boundaries_are_the_specifications() {
        let at = |b: Vec<(f64, Level)>| {
            b.iter()
                .map(|p| (p.0 * 1e9).round() / 1e9)
                .collect::<Vec<_>>()
        };
        assert_eq!(
            at(boundaries(|z| short_period_level(z, Category::A))),
            vec![0.15, 0.25, 0.35, 1.3]
        );
        assert_eq!(
            at(boundaries(|z| short_period_level(z, Category::B))),
            vec![0.15, 0.2, 0.3]
        );
        assert_eq!(at(boundaries(|z| phugoid_level(z, None))), vec![0.0, 0.04]);
    }
}
