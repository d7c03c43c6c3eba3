//! `delta-stability report [--out DIR]`: the note's whole study on its
//! built-in cases — the figures it draws (as SVG, with their data as CSV),
//! `summary.json`, and `index.html` setting its conclusions beside ours.

use crate::Failure;
use crate::diag::InputError;
use crate::fmt::sig;
use crate::output::atomic_write;
use crate::plot::{Figure, Series};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rayon::prelude::*;
use serde_json::json;
use stability_core::case::{Case, CaseResult, DampingModel, evaluate};
use stability_core::criteria::Margins;
use stability_core::criteria::Verdict;
use stability_core::damping::{Fig18, Theory, WingInput, damping_derivatives};
use stability_core::geometry::{Planform, Size, cropped_h};
use stability_core::response::{Input, Simplifications, StateSpace, TwoDof};
use stability_core::study::{grid, intervals, max_mu1_one_cycle, report_wing};
use std::fmt::Write;
use std::path::Path;

/// One figure of the note, with its place in the page.
struct Plate {
    figure: Figure,
    caption: String,
}

fn machs() -> Vec<f64> {
    grid(0.5, 2.0, 0.01)
}

fn eval_all(cases: Vec<Case>) -> Vec<Option<CaseResult>> {
    cases.par_iter().map(|c| evaluate(c).ok()).collect()
}

/// A curve of `f` over a Mach grid of results (non-finite where no result).
fn curve(
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

fn mach_fig(id: &str, title: &str, y: &str) -> Figure {
    Figure::new(id, title, "Mach number M", y)
}

pub fn run(out: &Path) -> Result<(), Failure> {
    let bad = |m: String| Failure::Input(InputError::file(&out.display().to_string(), m));
    std::fs::create_dir_all(out).map_err(|e| bad(format!("cannot create the directory: {e}")))?;
    let steps = 12u64;
    let bar = ProgressBar::with_draw_target(Some(steps), ProgressDrawTarget::stderr());
    bar.set_style(
        ProgressStyle::with_template("{spinner} [{bar:30}] {pos}/{len} {msg}")
            .unwrap_or_else(|_| ProgressStyle::default_bar())
            .progress_chars("=> "),
    );
    let ms = machs();
    let mut plates: Vec<Plate> = Vec::new();
    let mut push = |figure: Figure, caption: &str| {
        plates.push(Plate {
            figure,
            caption: caption.to_string(),
        })
    };

    // The two wings across Mach number.
    bar.set_message("the 45° and 60° deltas across Mach number");
    let wings = [45.0, 60.0];
    let results: Vec<Vec<Option<CaseResult>>> = wings
        .iter()
        .map(|&deg| eval_all(ms.iter().map(|&m| report_wing(deg, m)).collect()))
        .collect();
    let label = |deg: f64| format!("{deg}° delta");
    let pair = |id: &str, title: &str, y: &str, f: &dyn Fn(&CaseResult) -> Option<f64>| {
        let mut fig = mach_fig(id, title, y);
        for (k, &deg) in wings.iter().enumerate() {
            fig = fig.with(curve(&label(deg), &ms, &results[k], f));
        }
        fig
    };
    bar.inc(1);

    // §6: coefficients and stiffness derivatives (Figs 2–3, 5–12).
    bar.set_message("aerodynamic coefficients and stiffness derivatives");
    push(
        pair("2", "Drag coefficient at zero lift", "C_D0", &|r| {
            Some(r.coefficients.zero_lift_drag.value)
        }),
        "C_D0: 0.01 subsonic; 0.005 friction + thin-wing wave drag supersonic; faired (docs/models.md).",
    );
    push(
        pair("3", "Drag due to lift", "K = ∂C_D/∂C_L²", &|r| {
            Some(r.coefficients.drag_due_to_lift.value)
        }),
        "K = 1/(∂C_L/∂α): no leading-edge suction; §6's transonic rule.",
    );
    push(
        pair(
            "5",
            "Slope of the lift curve",
            "∂C_L/∂α (per radian)",
            &|r| Some(r.coefficients.lift_slope.value),
        ),
        "DATCOM subsonic, linear conical-flow theory supersonic, faired between.",
    );
    push(
        pair(
            "6",
            "Aerodynamic centre",
            "H₀ (fraction of M.A.C.)",
            &|r| Some(r.coefficients.aerodynamic_centre.value),
        ),
        "Slender-wing to two-dimensional blend subsonic; ½ supersonic.",
    );
    push(
        pair("7", "Force-linear velocity derivative x_w", "x_w", &|r| {
            Some(r.derivatives.x_w)
        }),
        "Eq (11).",
    );
    push(
        pair("8", "Force-linear velocity derivative z_w", "z_w", &|r| {
            Some(r.derivatives.z_w)
        }),
        "Eq (12).",
    );
    push(
        pair(
            "9",
            "Moment-linear velocity derivative m_w",
            "−m_w",
            &|r| Some(-r.derivatives.m_w),
        ),
        "Eqs (14), (25), c.g. at h = 0.25.",
    );
    push(
        pair(
            "10",
            "Force-linear velocity derivative x_u",
            "−x_u",
            &|r| Some(-r.derivatives.x_u),
        ),
        "Eqs (9), (28), level flight C_L·M² = 0.05 (eq 24).",
    );
    push(
        pair(
            "11",
            "Force-linear velocity derivative z_u",
            "−z_u",
            &|r| Some(-r.derivatives.z_u),
        ),
        "Eqs (10), (27).",
    );
    push(
        pair(
            "12",
            "Moment-linear velocity derivative m_u",
            "−m_u",
            &|r| Some(-r.derivatives.m_u),
        ),
        "Eqs (13), (29), trimmed.",
    );
    bar.inc(1);

    // §7: the damping theories (Figs 13, 16–18).
    bar.set_message("damping theories");
    let hs = grid(0.0, 1.0, 0.01);
    let unit = WingInput {
        aspect_ratio: 1.0,
        sweep_le: 1.0,
        taper: 0.0,
    };
    let garrick = |f: fn(&stability_core::damping::DampingDerivatives) -> f64| -> Vec<(f64, f64)> {
        hs.iter()
            .map(|&h| {
                (
                    h,
                    damping_derivatives(Theory::Garrick, &unit, h, 0.0, None)
                        .map(|d| -f(&d.derivatives))
                        .unwrap_or(f64::NAN),
                )
            })
            .collect()
    };
    push(
        Figure::new(
            "13",
            "Low aspect ratio theory (Garrick, incompressible)",
            "c.g. position h (fraction of M.A.C.)",
            "per unit aspect ratio",
        )
        .with(Series::new("−z_θ̇/A, eq (32)", garrick(|d| d.z_thetadot())))
        .with(Series::new("−m_θ̇/A, eq (33)", garrick(|d| d.m_thetadot()))),
        "Eqs (32)–(33): −z_θ̇ = (πA/4)(3 − 2h), −m_θ̇ = (πA/2)(h − 1)²; m_θ̇ vanishes with the axis at the trailing edge.",
    );
    let sup = |deg: f64, f: fn(&stability_core::damping::DampingDerivatives) -> f64| -> Series {
        let sweep = f64::to_radians(deg);
        let w = WingInput {
            aspect_ratio: 4.0 / sweep.tan(),
            sweep_le: sweep,
            taper: 0.0,
        };
        Series::new(
            label(deg),
            ms.iter()
                .map(|&m| {
                    (
                        m,
                        damping_derivatives(Theory::Supersonic, &w, 0.25, m, None)
                            .map(|d| -f(&d.derivatives))
                            .unwrap_or(f64::NAN),
                    )
                })
                .collect(),
        )
    };
    push(
        mach_fig(
            "16",
            "Supersonic damping in pitch (Mangler, Ribner & Malvestuto)",
            "−z_θ̇",
        )
        .with(sup(45.0, |d| d.z_thetadot()))
        .with(sup(60.0, |d| d.z_thetadot())),
        "Eq (36) recovered (docs/damping-theories.md), h = 0.25; defined only for supersonic Mach numbers and subsonic leading edges.",
    );
    push(
        mach_fig(
            "17",
            "Supersonic damping in pitch derivative (Mangler, Ribner & Malvestuto)",
            "−m_θ̇",
        )
        .with(sup(45.0, |d| d.m_thetadot()))
        .with(sup(60.0, |d| d.m_thetadot())),
        "Eq (36), h = 0.25: the 45° delta's −m_θ̇ is negative at M = 1.2, as §7 says.",
    );
    let bcs = grid(0.0, 0.999, 0.003);
    push(
        Figure::new(
            "18",
            "Functions H, E in the theory of Mangler, Ribner & Malvestuto",
            "β cot Λ = cot Λ/cot μ",
            "value",
        )
        .with(Series::new(
            "H = E·G",
            bcs.iter().map(|&b| (b, Fig18::at(b).h)).collect(),
        ))
        .with(Series::new(
            "1/E",
            bcs.iter().map(|&b| (b, 1.0 / Fig18::at(b).e)).collect(),
        )),
        "Complete elliptic integrals (the ellip crate); H → 1 and 1/E → 1 at M = 1, H → 2/3 and 1/E → 2/π as the leading edge turns sonic.",
    );
    bar.inc(1);

    // The faired damping derivatives (Figs 19–24), with Mangler's
    // frequency-consistent theory near M = 1 for comparison.
    bar.set_message("damping derivatives (faired) and the frequency iteration");
    let near_sonic = grid(0.9, 1.1, 0.01);
    let mangler: Vec<Option<CaseResult>> = eval_all(
        near_sonic
            .iter()
            .map(|&m| Case {
                damping: DampingModel::Theory(Theory::TransonicFrequency),
                ..report_wing(45.0, m)
            })
            .collect(),
    );
    let damping_fig = |id: &str, title: &str, y: &str, f: &dyn Fn(&CaseResult) -> f64| {
        pair(id, title, y, &|r| Some(f(r))).with(curve(
            "45°, Mangler (39)–(40), consistent ω̄",
            &near_sonic,
            &mangler,
            |r| Some(f(r)),
        ))
    };
    push(
        damping_fig("19", "Force-angular velocity derivative z_q", "z_q", &|r| {
            r.derivatives.z_q
        }),
        "Faired theories: slender wing (37) to M = 1, blended into (36) by M = 1.2.",
    );
    push(
        damping_fig("20", "Force-acceleration derivative z_ẇ", "z_ẇ", &|r| {
            r.derivatives.z_wdot
        }),
        "As Fig 19; (36)'s z_ẇ is positive at low supersonic speeds.",
    );
    push(
        damping_fig(
            "21",
            "Damping in pitch derivative z_θ̇",
            "z_θ̇ = z_q + z_ẇ",
            &|r| r.damping.derivatives.z_thetadot(),
        ),
        "As Fig 19.",
    );
    push(
        damping_fig(
            "22",
            "Moment-angular velocity derivative m_q",
            "m_q",
            &|r| r.derivatives.m_q,
        ),
        "As Fig 19.",
    );
    push(
        damping_fig(
            "23",
            "Moment-acceleration derivative m_ẇ",
            "m_ẇ",
            &|r| r.derivatives.m_wdot,
        ),
        "As Fig 19.",
    );
    push(
        damping_fig(
            "24",
            "Damping in pitch derivative m_θ̇",
            "m_θ̇ = m_q + m_ẇ",
            &|r| r.damping.derivatives.m_thetadot(),
        ),
        "As Fig 19; Mangler's theory with ω̄ iterated to the short period's own frequency.",
    );
    bar.inc(1);

    // §8: the damping standard across sweep, c.g. and μ₁ (Figs 25–26).
    bar.set_message("the damping standard (Figs 25–26)");
    let margin = |r: &CaseResult| r.analysis.damping_standard.margin;
    let mut f25 = mach_fig(
        "25",
        "Ability to damp the short period to half amplitude in one cycle: sweep",
        "Δm_θ̇ = m_θ̇max − m_θ̇ (eq 41)",
    );
    for deg in [30.0, 45.0, 60.0, 75.0] {
        let rs = eval_all(ms.iter().map(|&m| report_wing(deg, m)).collect());
        f25 = f25.with(curve(&label(deg), &ms, &rs, margin));
    }
    f25.reference_lines.push((0.0, "standard met above".into()));
    push(
        f25,
        "Δm_θ̇ > 0: the §8 approximation says the short period halves within one cycle. h = 0.25, μ₁ = 50.",
    );
    let mut f26 = mach_fig(
        "26",
        "Ability to damp to half amplitude in one cycle: μ₁ and c.g. position",
        "Δm_θ̇ (eq 41)",
    );
    for mu1 in [50.0, 100.0, 200.0, 400.0] {
        let rs = eval_all(
            ms.iter()
                .map(|&m| Case {
                    mu1,
                    ..report_wing(60.0, m)
                })
                .collect(),
        );
        f26 = f26.with(curve(&format!("60°, μ₁ = {mu1}"), &ms, &rs, margin));
    }
    for h in [0.15, 0.35] {
        let rs = eval_all(
            ms.iter()
                .map(|&m| Case {
                    h,
                    ..report_wing(45.0, m)
                })
                .collect(),
        );
        f26 = f26.with(curve(&format!("45°, h = {h}"), &ms, &rs, margin));
    }
    f26.reference_lines.push((0.0, "standard met above".into()));
    push(
        f26,
        "Forward c.g. and low μ₁ help; for the 60° delta the margin shrinks as μ₁ grows.",
    );
    bar.inc(1);

    // §9: the quartic's coefficients, ω̄, cycles to half, margins (Figs 27–35).
    bar.set_message("the quartic and its modes (Figs 27–35)");
    for (id, name, k) in [
        ("27", "A", 0usize),
        ("28", "B", 1),
        ("29", "C", 2),
        ("30", "D", 3),
        ("31", "E", 4),
    ] {
        push(
            pair(
                id,
                &format!("The coefficient {name} of the stability quartic"),
                name,
                &|r| Some(r.analysis.quartic.to_array()[k]),
            ),
            "Eq (6) corrected (docs/errata.md); μ₁ = 50.",
        );
    }
    let mut f32 = pair(
        "32",
        "The frequency parameter ω̄ of the short period",
        "ω̄ = 2πfc̄/V",
        &|r| {
            r.analysis
                .modes
                .short_period()
                .and_then(|m| m.frequency_parameter)
        },
    );
    for (k, &deg) in wings.iter().enumerate() {
        f32 = f32.with(curve(
            &format!("{deg}°, √(−m_w/(μ₁i_B)) (§9)"),
            &ms,
            &results[k],
            |r| r.analysis.short_period_approximation.frequency_parameter,
        ));
    }
    push(
        f32,
        "§9: √(−m_w/(μ₁i_B)) is a good first approximation to ω̄ = s/μ₁.",
    );
    let cycles = |r: &CaseResult| match r.analysis.modes.short_period() {
        Some(m) => m.cycles_to_half.or(m.cycles_to_double.map(|c| -c)),
        None => Some(0.0),
    };
    let mut f33 = pair(
        "33",
        "Cycles to damp to half amplitude",
        "cycles to half amplitude (negative: cycles to double)",
        &|r| cycles(r),
    );
    for mu1 in [200.0, 400.0] {
        let rs = eval_all(
            ms.iter()
                .map(|&m| Case {
                    mu1,
                    ..report_wing(60.0, m)
                })
                .collect(),
        );
        f33 = f33.with(curve(&format!("60° delta, μ₁ = {mu1}"), &ms, &rs, cycles));
    }
    f33.reference_lines.push((1.0, "one cycle (§8)".into()));
    // cycles to double (negative) only when some point diverges
    let diverges = f33
        .series
        .iter()
        .any(|s| s.points.iter().any(|p| p.1 < 0.0));
    f33.y_range = Some((if diverges { -2.0 } else { 0.0 }, 6.0));
    push(
        f33,
        "Exact roots; 0 where the short period is not oscillatory. The report's Fig 33: serious instability of the 45° delta for 0.97 < M < 1.5; the 60° delta adequate for μ₁ below about 200.",
    );
    push(
        pair(
            "34",
            "Contribution of the wing to the static margin",
            "K_n (eq 42)",
            &|r| {
                Margins::of(
                    &r.analysis.quartic,
                    &r.derivatives,
                    r.coefficients.lift_slope.value,
                )
                .static_margin
            },
        ),
        "From E by eq (42).",
    );
    push(
        pair(
            "35",
            "Contribution of the wing to the manoeuvre margin",
            "H_m (§9)",
            &|r| {
                Margins::of(
                    &r.analysis.quartic,
                    &r.derivatives,
                    r.coefficients.lift_slope.value,
                )
                .manoeuvre_margin
            },
        ),
        "From C by §9's relation C ≈ (μ₁/i_B)(∂C_L/∂α)H_m (sign corrected, see criteria.rs).",
    );
    bar.inc(1);

    // §10: taper (Fig 36).
    bar.set_message("taper (Fig 36)");
    let h_crop = cropped_h(0.25, 45f64.to_radians(), 1.0 / 7.0).unwrap_or(0.25);
    let cropped: Vec<Option<CaseResult>> = eval_all(
        ms.iter()
            .map(|&m| Case {
                planform: Planform::new(45f64.to_radians(), 1.0 / 7.0, Size::RootChord(10.0))
                    .expect("valid"),
                h: h_crop,
                ..report_wing(45.0, m)
            })
            .collect(),
    );
    push(
        mach_fig(
            "36",
            "Effect of taper on the damping in pitch derivative m_θ̇",
            "−m_θ̇",
        )
        .with(curve("45° true delta, h = 0.25", &ms, &results[0], |r| {
            Some(-r.damping.derivatives.m_thetadot())
        }))
        .with(curve(
            &format!(
                "tips cropped to taper 1/7, same c.g. (h = {})",
                sig(h_crop, 3)
            ),
            &ms,
            &cropped,
            |r| Some(-r.damping.derivatives.m_thetadot()),
        )),
        "§10: cropping the tips acts like a shift of axis; the cropped wing's theories are the true delta's at its own aspect ratio.",
    );
    bar.inc(1);

    // §11: responses (Figs 37–38).
    bar.set_message("responses (Figs 37–38)");
    let ts = grid(0.0, 2.0, 0.005);
    let mut f37 = Figure::new(
        "37",
        "Effect of Mach number on response (45° delta, two degrees of freedom)",
        "t̂ = t/τ",
        "ŵ/m₀ (eqs 44–45)",
    );
    for m in [0.8, 1.0, 1.2, 1.6] {
        if let Ok(r) = evaluate(&report_wing(45.0, m)) {
            let two = TwoDof::of(&r.derivatives);
            f37 = f37.with(Series::new(
                format!("M = {m}"),
                ts.iter().map(|&t| (t, two.w(t, 1.0))).collect(),
            ));
        }
    }
    push(
        f37,
        "The report's two-degree-of-freedom solution of eq (44) (eq 45 as recovered) after an elevon step m₀.",
    );
    let mut f38 = Figure::new(
        "38",
        "Effect of neglecting the damping in lift derivatives z_q, z_ẇ (45° delta, M = 1.2)",
        "t̂ = t/τ",
        "ŵ/m₀",
    );
    if let Ok(r) = evaluate(&report_wing(45.0, 1.2)) {
        for (name, neglect) in [("with z_q, z_ẇ", false), ("z_q = z_ẇ = 0", true)] {
            if let Ok(ss) = StateSpace::new(
                &r.derivatives,
                Simplifications {
                    neglect_zq_zwdot: neglect,
                    neglect_u: true,
                },
            ) && let Ok(s) = ss.simulate(
                Input::Step {
                    x0: 0.0,
                    z0: 0.0,
                    m0: 1.0,
                },
                2.0,
                400,
            ) {
                f38 = f38.with(Series::new(
                    name,
                    s.samples.iter().map(|x| (x.t, x.w)).collect(),
                ));
            }
        }
    }
    push(
        f38,
        "Exact solution of the state-space form (matrix exponential), û held at zero.",
    );
    bar.inc(1);

    // Write the figures.
    bar.set_message("writing figures");
    for p in &plates {
        let svg = p.figure.to_svg().map_err(&bad)?;
        let name = format!("fig{:0>2}", p.figure.id);
        atomic_write(&out.join(format!("{name}.svg")), svg.as_bytes())
            .map_err(|e| bad(format!("cannot write {name}.svg: {e}")))?;
        atomic_write(
            &out.join(format!("{name}.csv")),
            p.figure.to_csv().as_bytes(),
        )
        .map_err(|e| bad(format!("cannot write {name}.csv: {e}")))?;
    }
    bar.inc(1);

    // The summary: where each wing fails the standard, and the largest μ₁.
    bar.set_message("summary: intervals and the largest μ₁ (bisection)");
    let coarse = grid(0.5, 2.0, 0.05);
    let mut summary = serde_json::Map::new();
    let mut findings = Vec::new();
    for (k, &deg) in wings.iter().enumerate() {
        let verdicts: Vec<Option<Verdict>> = results[k]
            .iter()
            .map(|r| r.as_ref().map(|r| r.analysis.verdict))
            .collect();
        let unstable = intervals(
            &ms,
            &verdicts
                .iter()
                .map(|v| *v == Some(Verdict::Divergent))
                .collect::<Vec<_>>(),
        );
        let fails = intervals(
            &ms,
            &verdicts
                .iter()
                .map(|v| *v == Some(Verdict::Fails))
                .collect::<Vec<_>>(),
        );
        let maxmu: Vec<(f64, Option<f64>)> = coarse
            .par_iter()
            .map(|&m| (m, max_mu1_one_cycle(&report_wing(deg, m))))
            .collect();
        let worst = maxmu.iter().filter_map(|(m, v)| v.map(|v| (*m, v))).fold(
            None::<(f64, f64)>,
            |acc, (m, v)| match acc {
                Some((_, best)) if best <= v => acc,
                _ => Some((m, v)),
            },
        );
        findings.push((deg, unstable.clone(), fails.clone(), worst));
        summary.insert(
            format!("delta_{deg}"),
            json!({
                "sweep_deg": deg,
                "cg": 0.25,
                "mu1": 50.0,
                "unstable_mach": unstable,
                "fails_one_cycle_mach": fails,
                "max_mu1_one_cycle": maxmu.iter().map(|(m, v)| json!([m, v])).collect::<Vec<_>>(),
            }),
        );
    }
    let summary = serde_json::Value::Object(summary);
    atomic_write(
        &out.join("summary.json"),
        serde_json::to_string_pretty(&summary)
            .unwrap_or_default()
            .as_bytes(),
    )
    .map_err(|e| bad(format!("cannot write summary.json: {e}")))?;
    bar.inc(1);

    bar.set_message("index.html");
    let html = index_html(&plates, &findings);
    atomic_write(&out.join("index.html"), html.as_bytes())
        .map_err(|e| bad(format!("cannot write index.html: {e}")))?;
    bar.inc(1);
    bar.finish_and_clear();
    println!(
        "wrote {} figures (SVG and CSV), summary.json and index.html to {}",
        plates.len(),
        out.display()
    );
    for (deg, unstable, fails, worst) in &findings {
        println!(
            "  {deg}° delta: short period divergent for M in {}; more than one cycle to halve for M in {}; smallest largest-μ₁ {}",
            show_intervals(unstable),
            show_intervals(fails),
            worst.map_or("—".into(), |(m, v)| format!(
                "{} at M = {}",
                sig(v, 3),
                sig(m, 3)
            ))
        );
    }
    Ok(())
}

fn show_intervals(v: &[[f64; 2]]) -> String {
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

type Finding = (f64, Vec<[f64; 2]>, Vec<[f64; 2]>, Option<(f64, f64)>);

fn index_html(plates: &[Plate], findings: &[Finding]) -> String {
    let mut s = String::new();
    let esc = |t: &str| {
        t.replace('&', "&amp;")
            .replace('<', "&lt;")
            .replace('>', "&gt;")
    };
    let _ = writeln!(
        s,
        "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>delta-stability: McCarter (1953) reproduced</title>\n<style>body{{font-family:sans-serif;max-width:60em;margin:2em auto;line-height:1.45}}figure{{margin:2em 0}}img{{max-width:100%;border:1px solid #ddd}}td,th{{padding:.2em .6em;border-bottom:1px solid #eee;text-align:left}}</style></head><body>"
    );
    let _ = writeln!(
        s,
        "<h1>Longitudinal stability of delta wings — McCarter (1953), recomputed</h1>"
    );
    let _ = writeln!(
        s,
        "<p>W.B. McCarter's note studies tailless true deltas of 45° and 60° leading-edge sweep (aspect ratios 4 and 2.31), 6&nbsp;% thick, c.g. at h&nbsp;=&nbsp;0.25, relative density μ₁&nbsp;=&nbsp;50, against a standard: the short period must damp to half amplitude within one cycle (§8). His aerodynamic curves (Figs 1–6, 19–24) were faired through data we do not have; here every coefficient comes from a named method (<a href=\"../docs/models.md\">docs/models.md</a>), the damping derivatives from his own theories (<a href=\"../docs/damping-theories.md\">docs/damping-theories.md</a>) faired through Mach number, the quartic from his eq (4) with the three misprints of eq (6) corrected (<a href=\"../docs/errata.md\">docs/errata.md</a>), and the roots exactly. The pitching inertia i_B&nbsp;=&nbsp;0.08 and the level-flight C_L·M²&nbsp;=&nbsp;0.05, which the note does not state, are our assumptions.</p>"
    );
    let _ = writeln!(
        s,
        "<h2>His conclusions and ours</h2><table><tr><th>wing</th><th>the note</th><th>our models</th></tr>"
    );
    for (deg, unstable, fails, worst) in findings {
        let note = if *deg == 45.0 {
            "Inadequately damped at transonic speeds: a tailplane is needed “to correct the serious instability in the range 0.97 &lt; M &lt; 1.5” (§9, Fig 33)."
        } else {
            "Adequately damped “for values of the relative density parameter μ₁ … less than about 200” (Summary; §9, Fig 33)."
        };
        let ours = format!(
            "Divergent short period for M in {}; more than one cycle to halve for M in {}. The largest μ₁ meeting the standard falls to {} at M&nbsp;=&nbsp;{}.",
            show_intervals(unstable),
            show_intervals(fails),
            worst.map_or("—".into(), |(_, v)| sig(v, 3)),
            worst.map_or("—".into(), |(m, _)| sig(m, 3)),
        );
        let _ = writeln!(s, "<tr><td>{deg}°</td><td>{note}</td><td>{ours}</td></tr>");
    }
    let _ = writeln!(s, "</table>");
    let _ = writeln!(
        s,
        "<p>Where they differ: our models make the 45° delta's worst case a lightly damped (not a divergent) short period just above M&nbsp;=&nbsp;1.1, because linear supersonic theory (36) — the source of the adverse m_ẇ — only takes over above M&nbsp;=&nbsp;1 and our faired z_w keeps the motion damped; the note's faired curves were steeper through M&nbsp;=&nbsp;1. For the 60° delta the limiting μ₁ we find is of the size the note gives. With Mangler's frequency-dependent theory iterated to the short period's own frequency (Figs 19–24), the frequency parameter near M&nbsp;=&nbsp;1 converges to about 0.6 — the note's own “maximum value of 0.6” — and the damping it implies differs visibly from the quasi-steady value: the correction the note could not make. Numbers: <a href=\"summary.json\">summary.json</a>.</p>"
    );
    for p in plates {
        let name = format!("fig{:0>2}", p.figure.id);
        let _ = writeln!(
            s,
            "<figure id=\"{name}\"><img src=\"{name}.svg\" alt=\"Fig. {id}\"><figcaption><b>Fig. {id}</b> — {title}. {caption} <a href=\"{name}.csv\">data (CSV)</a></figcaption></figure>",
            id = p.figure.id,
            title = esc(&p.figure.title),
            caption = esc(&p.caption)
        );
    }
    let _ = writeln!(s, "</body></html>");
    s
}
