//! A design report's `index.html`: the design and its flight condition,
//! the overall verdict across Mach number, a table of every Mach number
//! (the modes, §8's margin, the MIL-F-8785C levels, CAP and §9's margins),
//! the figures by section, and where each coefficient and damping
//! derivative came from at each Mach number (also `sources.csv`). Every
//! link is relative to the page.

use super::{Design, phugoid, short_period, times};
use stability_core::analysis::Timebase;
use stability_core::analysis::verdict::Overall;
use stability_core::dynamics::modes::Mode;
use stability_core::numerics::display::sig;
use stability_io::design_point::Results;
use stability_io::plot::Plate;
use stability_io::plot::{csv_field, num, short};
use std::fmt::Write;

fn esc(t: &str) -> String {
    t.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

const STYLE: &str = "<style>body{font-family:sans-serif;max-width:72em;margin:2em auto;line-height:1.45}figure{margin:2em 0}img{max-width:100%;border:1px solid #ddd}table{border-collapse:collapse;font-size:.8em}td,th{padding:.15em .4em;white-space:nowrap;border-bottom:1px solid #eee;text-align:right;vertical-align:top}th{background:#f4f4f4}td:first-child,th:first-child{text-align:left}.meets{color:#060}.fails{color:#850}.divergent{color:#a00}.scroll{overflow-x:auto}th{white-space:normal}</style>";

/// A number to three significant figures, or a dash.
fn n(v: Option<f64>) -> String {
    v.filter(|x| x.is_finite())
        .map_or("—".into(), |x| sig(x, 3))
}

/// A number in prose: `digits` significant figures, shortest form.
fn g(x: f64, digits: usize) -> String {
    stability_core::numerics::display::round_to(x, digits).to_string()
}

/// The design, in words: planform, c.g., models, flight condition.
fn design(d: &Design) -> String {
    let c = &d.cfg.case;
    let p = &c.planform;
    let flight = match d.results().next().and_then(|(_, r)| r.flight) {
        Some((f, _)) => format!(
            "a physical flight condition: ρ = {} kg/m³, a = {} m/s, m = {} kg, I_y = {} kg·m², giving μ₁ = {}, i_B = {}, C_L·M² = {} (eq 24) at every Mach number, and V, C_L and τ = m/(½ρSV) at each; times are in seconds",
            g(f.density, 4),
            g(f.speed_of_sound, 4),
            g(f.mass, 5),
            g(f.pitch_inertia, 5),
            g(f.mu1(), 4),
            g(f.i_b(), 3),
            g(f.cl_m2(), 3)
        ),
        None => format!(
            "a non-dimensional flight condition: μ₁ = {}, i_B = {}, C_L·M² = {} (eq 24); times are in units of τ = m/(½ρSV)",
            g(c.mu1, 4),
            g(c.i_b, 3),
            g(c.cl_m2, 3)
        ),
    };
    format!(
        "<p>The design of <code>{}</code>: leading-edge sweep Λ = {}°, taper {}, aspect ratio {}, c.g. at h = {} of the M.A.C., damping model <code>{}</code> (<a href=\"docs/models.md\">docs/models.md</a>, <a href=\"docs/damping-theories.md\">docs/damping-theories.md</a>), {flight}. Each Mach number is evaluated as <code>delta-stability analyze {} --mach M</code> evaluates it. MIL-F-8785C: {} for Category C. Numbers: <a href=\"summary.json\">summary.json</a>; sources: <a href=\"sources.csv\">sources.csv</a>.</p>",
        esc(&d.cfg.path),
        g(p.sweep_le.to_degrees(), 4),
        g(p.taper, 3),
        g(p.aspect_ratio(), 3),
        g(c.h, 3),
        c.damping.name(),
        esc(&d.cfg.path),
        d.class.describe("--class")
    )
}

/// The overall verdict (every root judged) across Mach number.
fn verdicts(d: &Design) -> String {
    let runs = d.runs(|r| {
        stability_core::analysis::verdict::overall(&r.result.analysis)
            .as_str()
            .to_string()
    });
    let mut s = String::from(
        "<h2 id=\"verdict\">Verdict across Mach number</h2><p>Every root judged (<code>stability_core::analysis::verdict</code>): <b>divergent</b> where any mode grows, <b>fails</b> where one is neutral or the short period takes more than one cycle to halve (§8), else <b>meets</b>.</p><ul>",
    );
    for (what, a, b) in runs {
        let range = mach_range(a, b);
        let _ = write!(s, "<li>{range}: <span class=\"{what}\">{what}</span></li>");
    }
    let failed: Vec<String> = d
        .points
        .iter()
        .filter_map(|(m, r)| {
            r.as_ref()
                .err()
                .map(|e| format!("<li>M = {}: {}</li>", short(*m), esc(e)))
        })
        .collect();
    if !failed.is_empty() {
        let _ = write!(s, "<li>no result:<ul>{}</ul></li>", failed.join(""));
    }
    s.push_str("</ul>\n");
    s
}

/// The verdict's runs of Mach number, a line each, for the terminal.
pub fn verdict_lines(d: &Design) -> String {
    let runs = d.runs(|r| {
        stability_core::analysis::verdict::overall(&r.result.analysis)
            .as_str()
            .to_string()
    });
    let mut s = String::new();
    for (what, a, b) in runs {
        let _ = writeln!(s, "  {}: {what}", mach_range(a, b));
    }
    s
}

/// A run of Mach numbers from `a` to `b`: "M = a to b", or "M = a" when
/// the run is one point (never "M = 1 to 1").
fn mach_range(a: f64, b: f64) -> String {
    match short(a) == short(b) {
        true => format!("M = {}", short(a)),
        false => format!("M = {} to {}", short(a), short(b)),
    }
}

/// A mode's cells: ζ, ωₙ, period, time to half (or double, marked ×2),
/// cycles to half (or double).
fn mode_cells(r: &Results, m: Option<&Mode>) -> String {
    let Some(m) = m else {
        return "<td>—</td>".repeat(5);
    };
    let t = times(r, m);
    let half = match (t.time_to_half, t.time_to_double) {
        (Some(h), _) => sig(h, 3),
        (None, Some(x)) => format!("×2 in {}", sig(x, 3)),
        _ => "—".into(),
    };
    let cycles = match (m.cycles_to_half, m.cycles_to_double) {
        (Some(h), _) => sig(h, 3),
        (None, Some(x)) => format!("×2 in {}", sig(x, 3)),
        _ => "—".into(),
    };
    format!(
        "<td>{}</td><td>{}</td><td>{}</td><td>{half}</td><td>{cycles}</td>",
        n(m.damping_ratio),
        n(Some(t.natural_frequency)),
        n(t.period)
    )
}

/// The aperiodic roots (a pair split): each one's time to half or to
/// double (×2).
fn aperiodic(r: &Results) -> String {
    use stability_core::dynamics::modes::ModeName;
    let cells: Vec<String> = r
        .result
        .analysis
        .modes
        .iter()
        .filter(|m| m.name == ModeName::Aperiodic)
        .map(|m| {
            let t = times(r, m);
            match (t.time_to_half, t.time_to_double) {
                (Some(h), _) => format!("½ in {}", sig(h, 3)),
                (None, Some(x)) => format!("×2 in {}", sig(x, 3)),
                _ => "neutral".into(),
            }
        })
        .collect();
    if cells.is_empty() {
        "—".into()
    } else {
        cells.join(", ")
    }
}

/// One Mach number's row of the table.
fn row(m: f64, r: &Results, h: f64) -> String {
    let a = &r.result.analysis;
    let tau = r.tau();
    let v = Overall::of(a, Timebase::Tau(tau));
    let fq = a.flying_qualities(Timebase::Tau(tau));
    let lv = |l: stability_core::criteria::Level| l.number().to_string();
    let sp_levels = fq.short_period.map_or("—".into(), |s| {
        format!("{}/{}/{}", lv(s.a), lv(s.b), lv(s.c))
    });
    let ph_level = fq.phugoid.map_or("—".into(), |p| lv(p.level));
    let spf = r.engineering.short_period_frequency;
    let cap = spf.map_or("—".into(), |s| {
        format!(
            "{} ({}/{}/{})",
            sig(s.cap, 3),
            lv(s.a),
            lv(s.b),
            s.c.map_or("—".into(), lv)
        )
    });
    let res = &r.result;
    let mg = stability_core::criteria::Margins::at_cg(
        &a.quartic,
        &res.derivatives,
        res.coefficients.lift_slope.value,
        h,
    );
    let word = v.overall.as_str();
    format!(
        "<tr><td>{}</td><td class=\"{word}\" title=\"{}\">{word}</td>{}{}<td>{}</td><td>{}</td><td>{sp_levels}</td><td>{ph_level}</td><td>{cap}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>",
        short(m),
        esc(&v.reasons.join("; ")),
        mode_cells(r, short_period(r)),
        mode_cells(r, phugoid(r)),
        aperiodic(r),
        n(a.damping_standard.margin),
        n(mg.static_margin),
        n(mg.manoeuvre_margin),
        n(Some(res.coefficients.aerodynamic_centre.value)),
        n(mg.neutral_point),
        n(mg.static_margin_pct),
    )
}

/// The table of every Mach number.
fn table(d: &Design) -> String {
    let (t, w) = (d.time_unit(), d.rate_unit());
    let mode = |name: &str| {
        format!("<th colspan=\"5\">{name}: ζ, ωₙ ({w}), period ({t}), t½ ({t}), cycles to ½</th>")
    };
    let mut s = format!(
        "<h2 id=\"table\">Every Mach number</h2><p>×2: the mode grows, and doubles in that time or those cycles. Levels: MIL-F-8785C, Categories A/B/C (4: worse than Level 3). CAP with its levels A/B/C (physical flight conditions only). Hover over a verdict for its reasons.</p><div class=\"scroll\"><table><tr><th>M</th><th>verdict</th>{}{}<th>aperiodic roots ({t})</th><th>Δm_θ̇ (eq 41)</th><th>short-period ζ levels</th><th>phugoid level</th><th>CAP (levels)</th><th>K_n (eq 42)</th><th>H_m</th><th>H₀</th><th>h_n</th><th>h_n − h (% M.A.C.)</th></tr>\n",
        mode("short period"),
        mode("phugoid")
    );
    for (m, r) in &d.points {
        match r {
            Ok(r) => s.push_str(&row(*m, r, d.cfg.case.h)),
            Err(e) => {
                let _ = write!(
                    s,
                    "<tr><td>{}</td><td colspan=\"20\">no result: {}</td></tr>",
                    short(*m),
                    esc(e)
                );
            }
        }
        s.push('\n');
    }
    s.push_str("</table></div>\n");
    s
}

/// Each Mach number's sources: the damping theory, each coefficient's
/// origin, and the warnings (a theory outside its validity).
fn sources(d: &Design) -> String {
    let mut s = String::from(
        "<h2 id=\"sources\">Sources and regimes</h2><p>Where each coefficient (§6) and the damping derivatives (§7) came from at each Mach number, and the warnings of theories used near or beyond their validity. The same as CSV: <a href=\"sources.csv\">sources.csv</a>.</p><div class=\"scroll\"><table><tr><th>M</th><th>damping theory</th><th>∂C_L/∂α</th><th>H₀</th><th>C_D0</th><th>K</th><th>warnings</th></tr>\n",
    );
    for (m, r) in d.results() {
        let [theory, a, h0, cd0, k, warn] = source_cells(r);
        let _ = writeln!(
            s,
            "<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td style=\"text-align:left;white-space:normal;min-width:30em\">{}</td></tr>",
            short(m),
            esc(&theory),
            esc(&a),
            esc(&h0),
            esc(&cd0),
            esc(&k),
            esc(&warn)
        );
    }
    s.push_str("</table></div>\n");
    s
}

/// A point's sources: the damping theory, the origins of ∂C_L/∂α, H₀,
/// C_D0 and K, and its warnings.
fn source_cells(r: &Results) -> [String; 6] {
    let o = r.result.coefficients.origin;
    let th = r.result.damping.theory;
    let warn: Vec<String> = r.result.warnings.iter().map(ToString::to_string).collect();
    [
        format!("{} {}", th.name(), th.equations()),
        o.lift_slope.describe(),
        o.aerodynamic_centre.describe(),
        o.zero_lift_drag.describe(),
        o.drag_due_to_lift.describe(),
        warn.join(" | "),
    ]
}

/// `sources.csv`: each Mach number's sources (the page's table).
pub fn sources_csv(d: &Design) -> String {
    let mut s = String::from(
        "mach,damping_theory,lift_slope,aerodynamic_centre,zero_lift_drag,drag_due_to_lift,warnings,error\n",
    );
    for (m, r) in &d.points {
        let cells = match r {
            Ok(r) => {
                let mut c = source_cells(r).to_vec();
                c.push(String::new());
                c
            }
            Err(e) => {
                let mut c = vec![String::new(); 6];
                c.push(e.clone());
                c
            }
        };
        let cells: Vec<String> = cells.iter().map(|c| csv_field(c)).collect();
        let _ = writeln!(s, "{},{}", num(*m), cells.join(","));
    }
    s
}

fn figure(p: &Plate) -> String {
    let name = p.name();
    format!(
        "<figure id=\"{name}\"><img src=\"{name}.svg\" alt=\"{title}\"><figcaption><b>{title}</b>. {caption} <a href=\"{name}.csv\">data (CSV)</a></figcaption></figure>",
        title = esc(&p.figure.title),
        caption = esc(&p.caption)
    )
}

/// The page.
pub fn index_html(d: &Design, sections: &[(&str, Vec<Plate>)]) -> String {
    let mut s = format!(
        "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>delta-stability: {} across Mach number</title>\n{STYLE}</head><body>\n<h1>Longitudinal stability of {} across Mach number</h1>\n",
        esc(&d.cfg.path),
        esc(&d.cfg.path)
    );
    s.push_str(&design(d));
    s.push_str("<nav><h2>Contents</h2><ol><li><a href=\"#verdict\">Verdict across Mach number</a></li><li><a href=\"#table\">Every Mach number</a></li>");
    for (k, (title, plates)) in sections.iter().enumerate() {
        let figs: Vec<String> = plates
            .iter()
            .map(|p| format!("<a href=\"#{}\">{}</a>", p.name(), p.name()))
            .collect();
        let _ = write!(
            s,
            "<li><a href=\"#section-{}\">{}</a>: {}</li>",
            k + 1,
            esc(title),
            figs.join(", ")
        );
    }
    if d.cfg.configuration.is_some() {
        s.push_str("<li><a href=\"#configuration\">§10 The surfaces and body</a></li>");
    }
    s.push_str("<li><a href=\"#sources\">Sources and regimes</a></li></ol></nav>\n");
    s.push_str(&verdicts(d));
    s.push_str(&table(d));
    for (k, (title, plates)) in sections.iter().enumerate() {
        let _ = writeln!(
            s,
            "<section id=\"section-{}\"><h2>{}</h2>",
            k + 1,
            esc(title)
        );
        for p in plates {
            s.push_str(&figure(p));
            s.push('\n');
        }
        s.push_str("</section>\n");
    }
    s.push_str(&super::configuration::section(d));
    s.push_str(&sources(d));
    s.push_str("</body></html>\n");
    s
}

#[cfg(test)]
mod tests {
    use super::mach_range;

    #[test]
    fn a_run_of_one_mach_number_is_one_point() {
        assert_eq!(mach_range(1.0, 1.0), "M = 1");
        assert_eq!(mach_range(0.95, 0.95), "M = 0.95");
        assert_eq!(mach_range(0.5, 0.9), "M = 0.5 to 0.9");
    }
}
