//! `index.html`: the study's page — its assumptions, a table of contents,
//! the note's conclusions beside ours (generated from the computed results,
//! with their verdicts), and the figures by section. Every link is relative to the page: the documents it cites are
//! written beside it ([`DOCS`]), so the page works wherever `--out` puts
//! it.

use stability_core::design::study::report_wing;
use stability_core::numerics::display::sig;
use stability_io::plot::Plate;
use stability_study::certainty::Certainty;
use stability_study::conclusions::{Agreement, Judged};
use std::fmt::Write;

/// The documents the page links to, written into the report's `docs/`.
pub const DOCS: [(&str, &str); 3] = [
    ("docs/models.md", include_str!("../../../docs/models.md")),
    (
        "docs/damping-theories.md",
        include_str!("../../../docs/damping-theories.md"),
    ),
    ("docs/errata.md", include_str!("../../../docs/errata.md")),
];

fn esc(t: &str) -> String {
    t.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

const HEAD: &str = "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>delta-stability: McCarter (1953) reproduced</title>\n<style>body{font-family:sans-serif;max-width:60em;margin:2em auto;line-height:1.45}figure{margin:2em 0}img{max-width:100%;border:1px solid #ddd}td,th{padding:.2em .6em;border-bottom:1px solid #eee;text-align:left;vertical-align:top}.agrees{color:#060}.partly{color:#850}.differs{color:#a00}</style></head><body>\n<h1>Longitudinal stability of delta wings — McCarter (1953), recomputed</h1>";

/// The built-in cases and what we assume, from the cases themselves.
fn introduction() -> String {
    let (w45, w60) = (report_wing(45.0, 1.0), report_wing(60.0, 1.0));
    format!(
        "<p>W.B. McCarter's note studies tailless true deltas of 45° and 60° leading-edge sweep (aspect ratios {} and {}), 6&nbsp;% thick, c.g. at h&nbsp;=&nbsp;{}, relative density μ₁&nbsp;=&nbsp;{}, against a standard: the short period must damp to half amplitude within one cycle (§8). His aerodynamic curves (Figs 1–6, 19–24) were faired through data we do not have; here every coefficient comes from a named method (<a href=\"docs/models.md\">docs/models.md</a>), the damping derivatives from his own theories (<a href=\"docs/damping-theories.md\">docs/damping-theories.md</a>) faired through Mach number, the quartic from his eq (4) with the three misprints of eq (6) corrected (<a href=\"docs/errata.md\">docs/errata.md</a>), and the roots exactly. The pitching inertia i_B&nbsp;=&nbsp;{} and the level-flight C_L·M²&nbsp;=&nbsp;{}, which the note does not state, are our assumptions: each conclusion that rests on them is judged again across a range of each. Numbers: <a href=\"summary.json\">summary.json</a>.</p>",
        sig(w45.planform.aspect_ratio(), 3),
        sig(w60.planform.aspect_ratio(), 3),
        w45.h,
        w45.mu1,
        w45.i_b,
        w45.cl_m2,
    )
}

fn class(a: Agreement) -> &'static str {
    match a {
        Agreement::Agrees => "agrees",
        Agreement::Partly => "partly",
        Agreement::Differs => "differs",
    }
}

/// "reproduced" or "not reproduced".
fn verdict(j: &Judged) -> &'static str {
    if j.reproduced() {
        "reproduced"
    } else {
        "not reproduced"
    }
}

/// The anchor of the `k`th section of figures.
fn section_id(k: usize) -> String {
    format!("section-{}", k + 1)
}

/// The anchor of a conclusion's row.
fn conclusion_id(j: &Judged) -> String {
    format!("conclusion-{}", j.conclusion.id)
}

/// The table of contents: the conclusions (each, with its verdict), then
/// each section of figures; every link an anchor of this page or a file
/// beside it.
fn contents(sections: &[(&str, Vec<Plate>)], judged: &[Judged]) -> String {
    let n = judged.iter().filter(|j| j.reproduced()).count();
    let mut s = format!(
        "<nav id=\"contents\"><h2>Contents</h2><ol>\n<li><a href=\"#conclusions\">His conclusions and ours</a> ({n} of {} reproduced)<ol>",
        judged.len()
    );
    for j in judged {
        let c = j.conclusion;
        let _ = write!(
            s,
            "<li><a href=\"#{}\">{} ({})</a>: <span class=\"{}\">{}</span></li>",
            conclusion_id(j),
            esc(c.subject),
            esc(c.section),
            class(j.assessment.agreement),
            verdict(j)
        );
    }
    s.push_str("</ol></li>\n");
    for (k, (title, plates)) in sections.iter().enumerate() {
        let figs: Vec<String> = plates
            .iter()
            .map(|p| format!("<a href=\"#{}\">{}</a>", p.name(), esc(&p.figure.id)))
            .collect();
        let _ = writeln!(
            s,
            "<li><a href=\"#{}\">{}</a>: Figs {}</li>",
            section_id(k),
            esc(title),
            figs.join(", ")
        );
    }
    s.push_str("<li><a href=\"summary.json\">summary.json</a>: the numbers</li></ol></nav>\n");
    s
}

/// The note's conclusions beside ours, with the verdict and its tolerance,
/// and where they part, why.
fn conclusions(judged: &[Judged]) -> String {
    let mut s = String::from(
        "<h2 id=\"conclusions\">His conclusions and ours</h2><p>Each claim of the note beside what our models compute, with the numbers; “reproduced” means our numbers bear the claim out within the tolerance stated under the verdict. Where the verdict rests on the unstated i_B or C_L·M², the study is redone across a range of each, and the value that would reverse the verdict is given.</p><table><tr><th>the note</th><th>our models</th><th>verdict</th></tr>\n",
    );
    for j in judged {
        let c = j.conclusion;
        let a = &j.assessment;
        let _ = writeln!(
            s,
            "<tr id=\"{}\"><td><b>{}</b>: {} ({})</td><td>{}</td><td class=\"{}\">{} ({})<br><small>Reproduced if: {}.</small></td></tr>",
            conclusion_id(j),
            esc(c.subject),
            esc(c.claim),
            esc(c.section),
            esc(&j.ours()),
            class(a.agreement),
            verdict(j),
            a.agreement.as_str(),
            esc(&a.tolerance)
        );
    }
    s.push_str("</table>\n");
    let parting: Vec<String> = judged
        .iter()
        .filter(|j| !j.reproduced() && !j.conclusion.when_they_part.is_empty())
        .map(|j| {
            let c = j.conclusion;
            format!(
                "<li><a href=\"#{}\">{} ({})</a>: {}</li>",
                conclusion_id(j),
                esc(c.subject),
                esc(c.section),
                esc(c.when_they_part)
            )
        })
        .collect();
    if !parting.is_empty() {
        let _ = writeln!(s, "<p>Where they part:</p><ul>{}</ul>", parting.join(""));
    }
    s
}

fn figure(p: &Plate) -> String {
    let name = p.name();
    format!(
        "<figure id=\"{name}\"><img src=\"{name}.svg\" alt=\"Fig. {id}\"><figcaption><b>Fig. {id}</b> — {title}. {caption} <a href=\"{name}.csv\">data (CSV)</a></figcaption></figure>",
        id = p.figure.id,
        title = esc(&p.figure.title),
        caption = esc(&p.caption)
    )
}

/// The section "How sure are the headline conclusions?": the inputs'
/// distributions and their sources, each headline's probabilities by Mach
/// number with the bounds on "throughout" and the deciding inputs, the
/// command that reruns it, and the figure ([`stability_study::certainty`]).
fn how_sure(c: &Certainty, plate: &Plate) -> String {
    let mut s = format!(
        "<section id=\"{HOW_SURE}\"><h2>How sure are the headline conclusions?</h2><p>The note answers yes or no; its inputs are not known that well. Here each headline conclusion is a probability under stated distributions of i_B and C_L·M² (which the note does not state), of the c.g., and of the damping theory itself (model-form uncertainty), by {} Owen-scrambled Sobol′ points at each Mach number (seed {}; each 95 % Wilson interval at most ±{}); the deciding inputs by their total Sobol indices for the short period's ζ ({} rows of Saltelli's design), averaged over Mach number.</p>\n",
        c.samples,
        stability_study::certainty::SEED,
        stability_study::certainty::percent(
            stability_core::uncertainty::stats::Z95 * (0.25 / c.samples as f64).sqrt()
        ),
        c.sobol_samples,
    );
    for (a, j) in c.answers.iter().zip(c.json().headlines) {
        let _ = write!(
            s,
            "<h3>{}</h3><p>{}</p><table><tr><th>input</th><th>distribution</th><th>from</th></tr>",
            esc(&stability_study::certainty::capitalised(
                a.headline.question
            )),
            esc(&a.sentence())
        );
        for i in &j.inputs {
            let _ = write!(
                s,
                "<tr><td>{}</td><td>{}</td><td>{}</td></tr>",
                esc(i.name),
                esc(&i.distribution),
                esc(i.source)
            );
        }
        let _ = writeln!(
            s,
            "</table><p><small>Rerun: <code>{}</code> (add <code>--sobol</code> for the indices); the file states each spread.</small></p>",
            esc(&j.command)
        );
    }
    s.push_str(&figure(plate));
    s.push_str("</section>\n");
    s
}

/// The anchor of the section "How sure are the headline conclusions?".
const HOW_SURE: &str = "how-sure-section";

/// The page: the introduction, the contents, the conclusions (with how
/// sure the headline ones are, when `sure` is given), then each section
/// (its title, from `stability_study::SECTIONS`) with its figures, and the section
/// on how sure.
pub fn index_html(
    sections: &[(&str, Vec<Plate>)],
    judged: &[Judged],
    sure: Option<(&Certainty, &Plate)>,
) -> String {
    let mut s = String::from(HEAD);
    s.push('\n');
    s.push_str(&introduction());
    s.push('\n');
    let mut nav = contents(sections, judged);
    if sure.is_some() {
        nav = nav.replace(
            "<li><a href=\"summary.json\">",
            &format!("<li><a href=\"#{HOW_SURE}\">How sure are the headline conclusions?</a>: Fig U1</li>\n<li><a href=\"summary.json\">"),
        );
    }
    s.push_str(&nav);
    s.push_str(&conclusions(judged));
    if let Some((c, _)) = sure {
        let _ = writeln!(
            s,
            "<p><a href=\"#{HOW_SURE}\">{}</a></p>",
            esc(&c.conclusion_line())
        );
    }
    for (k, (title, plates)) in sections.iter().enumerate() {
        let _ = writeln!(
            s,
            "<section id=\"{}\"><h2>{}</h2>",
            section_id(k),
            esc(title)
        );
        for p in plates {
            s.push_str(&figure(p));
            s.push('\n');
        }
        s.push_str("</section>\n");
    }
    if let Some((c, p)) = sure {
        s.push_str(&how_sure(c, p));
    }
    s.push_str("</body></html>\n");
    s
}
