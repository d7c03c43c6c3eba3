//! What README.md shows of the report, computed as the report computes it:
//! Fig 33 (`docs/figures/fig33.svg` and `.csv`) and the text under it —
//! the figure's numbers, then the note's conclusions judged on our
//! findings, each with its claim, whether it is reproduced and our numbers
//! (`summary.json`'s `claim`, `reproduced` and the numbers of `ours`; the
//! sweeps over the unstated inputs are the report's). `cargo xtask regen`
//! writes the figure's files and puts the text between README.md's
//! `conclusions` markers, so that the README cannot drift from what the
//! program computes: `regen --check` fails when it does.

use super::conclusions::{
    ABOUT, Assessment, CONCLUSIONS, Conclusion, MU1_LIMIT, TRANSONIC, about_limit,
};
use super::quartic;
use super::study::{Study, WINGS};
use super::summary::{Findings, Wing, Worst, show_intervals};
use stability_core::criteria::Verdict;
use stability_core::design::case::Case;
use stability_core::design::study::intervals;
use stability_core::numerics::display::sig;

/// The name of README.md's markers around [`Readme::conclusions`]:
/// `<!-- conclusions:begin … -->` and `<!-- conclusions:end -->`.
pub const MARKER: &str = "conclusions";

/// The name of README.md's markers around [`Readme::python`], under the
/// Python example that sweeps the note's two wings.
pub const PYTHON_MARKER: &str = "python-fig33";

/// The μ₁ of Fig 33's third curve of the 60° delta, whose failures the
/// text names.
const HEAVY_MU1: f64 = 400.0;

/// The width README.md's text is wrapped to.
const WIDTH: usize = 76;

/// README.md's figure files and text.
pub struct Readme {
    /// `docs/figures/fig33.svg` and `docs/figures/fig33.csv`, by their path
    /// in the repository, as the report draws them.
    pub figures: Vec<(String, String)>,
    /// The text between the markers: the figure's paragraph and the note's
    /// conclusions (Markdown, wrapped, ending with a newline).
    pub conclusions: String,
    /// What the Python section's sweep of the two wings prints, in words:
    /// each wing's short period against the standard at μ₁ = 50 (Fig 33's
    /// curves).
    pub python: String,
}

/// One conclusion judged at our values of the unstated inputs.
struct Judgement {
    conclusion: &'static Conclusion,
    assessment: Assessment,
}

impl Judgement {
    fn reproduced(&self) -> bool {
        self.assessment.agreement.reproduced()
    }
}

/// The study, Fig 33 and the findings the text is written from.
pub fn compute() -> Result<Readme, String> {
    of(&Findings::new(Study::new()))
}

/// README.md's figure and text from `findings` (ours: a [`Study::new`]'s,
/// as the report's).
pub fn of(findings: &Findings) -> Result<Readme, String> {
    let plate = quartic::fig33(&findings.study);
    let figures = vec![
        ("docs/figures/fig33.svg".to_string(), plate.figure.to_svg()?),
        ("docs/figures/fig33.csv".to_string(), plate.figure.to_csv()),
    ];
    let judged: Vec<Judgement> = CONCLUSIONS
        .iter()
        .map(|c| Judgement {
            conclusion: c,
            assessment: (c.assess)(findings),
        })
        .collect();
    let heavy = heavy_60(&findings.study);
    let conclusions = [
        wrap(&figure_paragraph(findings, &heavy), ""),
        wrap(&verdicts_paragraph(&judged), ""),
        format!(
            "<details>\n<summary>The {} conclusions: the note's claim and our numbers</summary>\n",
            number(judged.len())
        ),
        conclusion_list(&judged),
        "</details>\n".into(),
    ]
    .join("\n");
    Ok(Readme {
        figures,
        conclusions,
        python: wrap(&python_paragraph(findings), ""),
    })
}

/// Mach intervals where a short period diverges, and where it takes more
/// than one cycle to halve.
type Inadequate = (Vec<[f64; 2]>, Vec<[f64; 2]>);

/// The 60° delta at μ₁ = [`HEAVY_MU1`] across the study's Mach numbers (Fig
/// 33's curve): where it diverges and where it fails the standard.
fn heavy_60(study: &Study) -> Inadequate {
    let rs = study.across(WINGS[1], &study.ms, |c| Case {
        mu1: HEAVY_MU1,
        ..c
    });
    let is = |v: Verdict| -> Vec<bool> {
        rs.iter()
            .map(|r| r.as_ref().map(|r| r.analysis.verdict) == Some(v))
            .collect()
    };
    (
        intervals(&study.ms, &is(Verdict::Divergent)),
        intervals(&study.ms, &is(Verdict::Fails)),
    )
}

/// How a wing's short period stands to the one-cycle standard, in words:
/// "meets the one-cycle standard at every Mach number", or where it
/// diverges and where it takes more than one cycle to halve.
fn against_standard((unstable, fails): &Inadequate) -> String {
    let mut parts = Vec::new();
    if !unstable.is_empty() {
        parts.push(format!("diverges at M {}", show_intervals(unstable)));
    }
    if !fails.is_empty() {
        parts.push(format!(
            "takes more than one cycle to halve at M {}",
            show_intervals(fails)
        ));
    }
    if parts.is_empty() {
        "meets the one-cycle standard at every Mach number".into()
    } else {
        parts.join(" and ")
    }
}

fn inadequate(w: &Wing) -> Inadequate {
    (w.unstable.clone(), w.fails.clone())
}

/// The paragraph on Fig 33: the model, then each wing's short period.
fn figure_paragraph(f: &Findings, heavy: &Inadequate) -> String {
    let (w45, w60) = (&f.wings[0], &f.wings[1]);
    let (lo, hi) = TRANSONIC;
    let least = w45.most_cycles.map_or(String::new(), |(m, c)| {
        format!(
            ", least damped at M = {m:.2} ({} cycles to half amplitude)",
            sig(c, 3)
        )
    });
    let diverges = if w45.unstable.is_empty() {
        "its short period never diverges".to_string()
    } else {
        format!(
            "its short period diverges at M {}",
            show_intervals(&w45.unstable)
        )
    };
    // the join's widest reach from M = 1 on the two wings, rounded up to
    // hundredths
    let reach = super::regimes::damping_joins(&WINGS)
        .iter()
        .map(|&(a, b)| (1.0 - a).max(b - 1.0))
        .fold(0.0, f64::max);
    let within = (reach * 100.0).ceil() / 100.0;
    format!(
        "Fig. 33 of the note, recomputed by one linear lifting-surface theory, each root solved with the air forces at its own complex frequency (the p-method, docs/exact-root.md; the default `faired` model: the doublet lattice below M = 1, its sonic extrapolation at M = 1, the Mach box above; joined only across the shaded band, within {within} of M = 1). At μ₁ = 50 the 45° tailless delta (blue) {}{least} — the note finds “serious instability in the range {lo} < M < {hi}” — and {diverges}. At μ₁ = 50 the 60° delta {}; at μ₁ = {HEAVY_MU1} it {}. {}",
        against_standard(&inadequate(w45)),
        against_standard(&inadequate(w60)),
        against_standard(heavy),
        mu1_limit_sentence(f),
    )
}

/// The paragraph under the Python section's sweep: each wing's short
/// period at μ₁ = 50 against the standard, and its most cycles to half
/// amplitude.
fn python_paragraph(f: &Findings) -> String {
    let (w45, w60) = (&f.wings[0], &f.wings[1]);
    let (lo, hi) = TRANSONIC;
    let worst = |w: &Wing| {
        w.most_cycles.map_or(String::new(), |(m, c)| {
            format!(
                ", {} cycles to half amplitude at its worst (M = {m:.2})",
                sig(c, 3)
            )
        })
    };
    format!(
        "The 45° delta's short period {}{} — the note: “serious instability in the range {lo} < M < {hi}”; the 60° delta's {}{}.",
        against_standard(&inadequate(w45)),
        worst(w45),
        against_standard(&inadequate(w60)),
        worst(w60),
    )
}

/// The 60° delta's largest μ₁ meeting the standard against the note's
/// "about 200".
fn mu1_limit_sentence(f: &Findings) -> String {
    let by_mach = &f.max_mu1(1).by_mach;
    let (ms, near): (Vec<f64>, Vec<bool>) = by_mach
        .iter()
        .map(|&(m, v)| (m, v.is_some_and(about_limit)))
        .unzip();
    let near = intervals(&ms, &near);
    let at = if near.is_empty() {
        "at no Mach number".to_string()
    } else {
        format!("at M {}", show_intervals(&near))
    };
    let worst = match f.max_mu1(1).worst() {
        Some(Worst::Least { mach, mu1 }) => {
            format!("its least is {} at M = {mach:.2}", sig(mu1, 3))
        }
        Some(w @ Worst::NoneMeets(_)) => w.describe(),
        None => "it has no value".into(),
    };
    format!(
        "The note puts the 60° delta's limit at about μ₁ = {MU1_LIMIT}; ours, the largest μ₁ meeting the standard, is within a factor {ABOUT} of it ({}–{}) {at}, and {worst}.",
        sig(MU1_LIMIT / ABOUT, 3),
        sig(MU1_LIMIT * ABOUT, 3),
    )
}

/// How many reproduced, and which, in one paragraph.
fn verdicts_paragraph(judged: &[Judgement]) -> String {
    let titles = |reproduced: bool| -> Vec<&str> {
        judged
            .iter()
            .filter(|j| j.reproduced() == reproduced)
            .map(|j| j.conclusion.title)
            .collect()
    };
    let list = |v: &[&str], what: &str| -> String {
        if v.is_empty() {
            format!("none {what}")
        } else {
            format!("{} {what} ({})", number(v.len()), v.join(", "))
        }
    };
    format!(
        "`report/index.html` and `summary.json` set each of the note's {} conclusions beside ours with the numbers: {}, {}. The report gives the tolerance each is judged by, why ours may part from the note where it does, and the values of the unstated i_B or C_L·M² that would reverse a verdict.",
        number(judged.len()),
        list(&titles(true), "reproduced"),
        list(&titles(false), "not"),
    )
}

/// One bullet a conclusion: the verdict, its title and where the note
/// says it, the note's claim, and our numbers.
fn conclusion_list(judged: &[Judgement]) -> String {
    judged
        .iter()
        .map(|j| {
            let c = j.conclusion;
            let verdict = if j.reproduced() {
                "Reproduced"
            } else {
                "Not reproduced"
            };
            let text = format!(
                "{verdict}: **{}** ({}). The note: {} Ours: {}",
                c.title, c.section, c.claim, j.assessment.computed
            );
            wrap(&text, "- ")
        })
        .collect()
}

/// A count in words up to twelve, else in digits.
fn number(n: usize) -> String {
    const WORDS: [&str; 13] = [
        "no", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten",
        "eleven", "twelve",
    ];
    WORDS.get(n).map_or(n.to_string(), |w| w.to_string())
}

/// Words a line does not end with: each stays with the next ("M = 1.17",
/// "Fig 33").
const KEEP_WITH_NEXT: [&str; 9] = ["=", "<", ">", "≤", "≥", "M", "Fig", "Figs", "eq"];

/// `text` wrapped to [`WIDTH`] columns, the first line after `bullet` and
/// the rest indented as far, ending with a newline. A word that Markdown
/// would read as the start of a list, a heading or a quote at the start of
/// a line is kept on the line before, as is one after a word of
/// [`KEEP_WITH_NEXT`].
fn wrap(text: &str, bullet: &str) -> String {
    let indent = " ".repeat(bullet.chars().count());
    let mut out = String::new();
    let mut line = bullet.to_string();
    let mut empty = true;
    let mut previous = "";
    for word in text.split_whitespace() {
        let fits = line.chars().count() + 1 + word.chars().count() <= WIDTH;
        let may_break = !starts_a_block(word) && !KEEP_WITH_NEXT.contains(&previous);
        previous = word;
        if !empty && !fits && may_break {
            out.push_str(line.trim_end());
            out.push('\n');
            line = indent.clone();
            empty = true;
        }
        if !empty {
            line.push(' ');
        }
        line.push_str(word);
        empty = false;
    }
    out.push_str(line.trim_end());
    out.push('\n');
    out
}

/// Whether `word` at the start of a line would begin a Markdown block
/// (a list item, a heading, a quote, a rule or a setext underline).
fn starts_a_block(word: &str) -> bool {
    let digits = word.trim_start_matches(|c: char| c.is_ascii_digit());
    word.starts_with(['-', '+', '*', '>', '<', '#', '=', '|'])
        || (digits.len() < word.len() && (digits == "." || digits == ")"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrapping_keeps_words_whole_and_starts_no_block() {
        let text = "a ".repeat(37) + "- b 1. c";
        let wrapped = wrap(&text, "- ");
        for line in wrapped.lines().skip(1) {
            assert!(
                line.starts_with("  ") && !starts_a_block(line.trim_start()),
                "{line}"
            );
        }
        assert_eq!(
            wrapped.split_whitespace().collect::<Vec<_>>().join(" "),
            format!("- {}", text.trim_end())
        );
        assert!(wrapped.lines().all(|l| l.chars().count() <= WIDTH + 3));
        assert!(starts_a_block("12.") && starts_a_block("3)") && !starts_a_block("−0.4"));
        assert_eq!(number(6), "six");
        assert_eq!(number(13), "13");
    }
}
