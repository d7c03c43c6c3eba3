//! `delta-stability report [--out DIR]`: the note's whole study
//! ([`stability_study`]) written into DIR — figNN.svg and figNN.csv,
//! `summary.json`, `index.html` and the documents it links to.
//!
//! The files are written into a temporary directory beside DIR, which
//! replaces DIR only when complete: a killed run leaves the previous report
//! whole (and its temporary directory, which a later run removes). DIR, if
//! it exists, must be a report (or empty): everything in it a file the
//! report's manifest lists, unchanged ([`manifest`]), checked when the run
//! starts and again when DIR is replaced; nothing else is replaced.

use crate::Failure;
use crate::output::{AtomicDir, Refused};
use crate::report::html;
use crate::report::manifest::{self, MANIFEST, Manifest};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use stability_io::diag::IoError;
use stability_io::files::write_error;
use stability_io::plot::Plate;
use stability_study::conclusions::Judged;
use stability_study::report::{Report, STEPS, Step, Stopped};
use stability_study::summary::{self, Findings};
use std::path::Path;

/// DIR may be replaced: it does not exist, or it is a directory holding
/// only what a report wrote there, unchanged ([`manifest::foreign`]).
fn check_target(out: &Path) -> Result<(), Failure> {
    let Ok(meta) = out.symlink_metadata() else {
        return Ok(());
    };
    let refuse = |why: String| Failure::Io(IoError::new("will not replace", out, why));
    if meta.file_type().is_symlink() {
        return Err(refuse(
            "it is a symbolic link; give the directory it points to".into(),
        ));
    }
    if !meta.is_dir() {
        return Err(refuse("it is not a directory".into()));
    }
    may_replace(out).map_err(refuse)
}

/// Whether the directory `dir` holds only what a report wrote: else what
/// replacing it would lose, in words.
fn may_replace(dir: &Path) -> Result<(), String> {
    let foreign = manifest::foreign(dir).map_err(|e| stability_io::files::reason(&e))?;
    if foreign.is_empty() {
        return Ok(());
    }
    Err(format!(
        "a report replaces the whole directory, and it holds what a report did not write, which would be lost: {}; choose another --out, or move those away (nothing was removed)",
        manifest::describe(&foreign)
    ))
}

pub(super) fn progress_bar(steps: usize) -> ProgressBar {
    let bar = ProgressBar::with_draw_target(Some(steps as u64), ProgressDrawTarget::stderr());
    bar.set_style(
        ProgressStyle::with_template("{spinner} [{bar:30}] {pos}/{len} {msg}")
            .unwrap_or_else(|_| ProgressStyle::default_bar())
            .progress_chars("=> "),
    );
    bar
}

/// The command's options.
#[derive(Debug, Clone, clap::Args)]
pub struct Args {
    /// A design-point config (TOML, as for `analyze`): report that design
    /// across Mach number instead of the note's study.
    pub config: Option<String>,
    /// The output directory.
    #[arg(long, default_value = "report")]
    pub out: String,
    /// With CONFIG: the Mach numbers, A:B:STEP (inclusive) or a list
    /// A,B,…; default 0.5:2:0.05, widened in steps of 0.05 to take in the
    /// config's own Mach number.
    #[arg(long, value_name = "A:B:STEP|LIST", allow_hyphen_values = true)]
    pub mach: Option<String>,
    /// With CONFIG: the MIL-F-8785C airplane class (§1.3) whose Category C
    /// floors the short-period frequency requirement applies (default IV).
    #[arg(long = "class", value_enum)]
    pub class: Option<crate::args::ClassArg>,
    #[command(flatten)]
    pub model: crate::args::ModelArgs,
}

/// A file of the report: its name in DIR and its bytes.
pub(super) type Write<'a> = dyn Fn(&str, &[u8]) -> Result<(), Failure> + 'a;

/// Writes a report into `out`: `fill` writes its files through the
/// function it is given (each recorded in the manifest), into a temporary
/// directory that then replaces `out` — only if `out` holds nothing but an
/// earlier report's files, unchanged, when the run starts and at the swap.
pub(super) fn write_report(
    out: &Path,
    fill: impl FnOnce(&Write<'_>) -> Result<(), Failure>,
) -> Result<(), Failure> {
    let out = &crate::output::directory_target(out);
    check_target(out)?;
    let dir = AtomicDir::create(out).map_err(|e| write_error(out, &e))?;
    let written = std::cell::RefCell::new(Manifest::default());
    let write = |name: &str, bytes: &[u8]| -> Result<(), Failure> {
        written.borrow_mut().add(name, bytes);
        dir.write(name, bytes)
            .map_err(|e| Failure::Io(write_error(&dir.path().join(name), &e)))
    };
    fill(&write)?;
    let list = written.borrow().to_json();
    dir.write(MANIFEST, list.as_bytes())
        .map_err(|e| write_error(&dir.path().join(MANIFEST), &e))?;
    dir.commit_if(may_replace).map_err(|e| match e {
        Refused::Not(why) => Failure::Io(IoError::new("will not replace", out, why)),
        Refused::Io(e) => Failure::Io(write_error(out, &e)),
    })
}

/// A plate's two files, written.
pub(super) fn write_plate(write: &Write<'_>, out: &Path, p: &Plate) -> Result<(), Failure> {
    for (name, bytes) in p
        .files()
        .map_err(|m| IoError::new("cannot draw", &out.join(p.name()), m))?
    {
        write(&name, &bytes)?;
    }
    Ok(())
}

pub fn run(args: &Args) -> Result<(), Failure> {
    if let Some(config) = &args.config {
        return super::report_design::run(args, config);
    }
    super::report_design::refuse_design_options(args)?;
    let out = Path::new(&args.out);
    let bar = progress_bar(STEPS);
    let mut done = None;
    write_report(out, |write| {
        done = Some(contents(write, out, &bar)?);
        Ok(())
    })?;
    bar.finish_and_clear();
    let (figures, summary) = done.unwrap_or_default();
    let text = format!(
        "wrote {figures} figures (SVG and CSV), summary.json and index.html to {}\n{summary}",
        out.display(),
    );
    crate::output::print(&text)
}

/// The note's report ([`Report::compute`]) written through `write`, each
/// figure as soon as it is drawn, the bar showing each step: its figures'
/// count and the terminal's summary.
fn contents(write: &Write<'_>, out: &Path, bar: &ProgressBar) -> Result<(usize, String), Failure> {
    let on = |step: Step<'_>| -> Result<(), Failure> {
        match step {
            Step::Begins(what) => bar.set_message(what.to_string()),
            Step::Drew(plates) => {
                for p in plates {
                    write_plate(write, out, p)?;
                }
            }
            Step::Done => bar.inc(1),
        }
        Ok(())
    };
    let report = Report::compute(on).map_err(|e| match e {
        Stopped::Caller(f) => f,
        Stopped::Study { what, why } => Failure::Io(IoError::new(what, out, why)),
    })?;
    if let Some(Err(stale)) = &report.precomputed {
        bar.suspend(|| eprintln!("warning: {stale} (the study solved them)"));
    }
    write("summary.json", report.summary_json()?.as_bytes())?;
    write(
        "index.html",
        html::index_html(
            &report.sections,
            &report.judged,
            Some((&report.sure, &report.sure_plate)),
        )
        .as_bytes(),
    )?;
    for (name, text) in html::DOCS {
        write(name, text.as_bytes())?;
    }
    let mut text = terminal_summary(&report.findings, &report.judged);
    text.push_str(&format!(
        "  the note's question: {}\n",
        report.tail.sentence()
    ));
    for a in &report.sure.answers {
        text.push_str(&format!("  how sure: {}\n", a.sentence()));
    }
    Ok((report.plates().count(), text))
}

/// Where in Mach number: "for M in 0.92–0.99, 1.2", or "at no Mach
/// number" (never "for M in none").
fn where_in_mach(v: &[[f64; 2]]) -> String {
    match v.is_empty() {
        true => "at no Mach number".into(),
        false => format!("for M in {}", summary::show_intervals(v)),
    }
}

/// What the terminal shows of the findings: each wing's intervals and the
/// worst case of its largest μ₁ (a Mach number where none meets the
/// standard is the worst), then each conclusion's verdict.
pub fn terminal_summary(f: &Findings, judged: &[Judged]) -> String {
    let mut text = String::new();
    for (k, w) in f.wings.iter().enumerate() {
        text.push_str(&format!(
            "  {}° delta: short period divergent {}; more than one cycle to halve {}; largest μ₁ meeting the standard, at worst: {}\n",
            w.sweep_deg,
            where_in_mach(&w.unstable),
            where_in_mach(&w.fails),
            f.max_mu1(k).worst().map_or("—".into(), |w| w.describe())
        ));
    }
    let n = judged.iter().filter(|j| j.reproduced()).count();
    text.push_str(&format!(
        "  the note's conclusions: {n} of {} reproduced (index.html)\n",
        judged.len()
    ));
    for j in judged {
        let c = j.conclusion;
        text.push_str(&format!(
            "    {:<15} {} ({})\n",
            if j.reproduced() {
                "reproduced"
            } else {
                "not reproduced"
            },
            c.subject,
            c.section
        ));
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_empty_set_of_mach_numbers_is_said_in_words() {
        assert_eq!(where_in_mach(&[]), "at no Mach number");
        assert_eq!(
            where_in_mach(&[[0.92, 0.99], [1.2, 1.2]]),
            "for M in 0.92–0.99, 1.20"
        );
    }

    /// The temporary directories of runs beside `out`.
    fn temporaries(out: &Path) -> Vec<std::path::PathBuf> {
        let dir = out.parent().unwrap();
        std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.as_path() != out)
            .collect()
    }

    /// A file saved into the report while a run writes the new one: the
    /// run refuses at the swap, naming it, and removes nothing — the
    /// previous report and the file stay, no temporary is left; with the
    /// file moved away the report is replaced.
    #[test]
    fn a_file_saved_during_a_run_is_refused_at_the_swap() {
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("report");
        write_report(&out, |write| write("index.html", b"the first")).unwrap();
        let saved = out.join("notes.txt");
        let err = write_report(&out, |write| {
            write("index.html", b"the second")?;
            std::fs::write(&saved, "saved during the run").unwrap();
            Ok(())
        })
        .unwrap_err()
        .to_string();
        assert!(
            err.contains("will not replace") && err.contains("`notes.txt`"),
            "{err}"
        );
        assert_eq!(
            std::fs::read_to_string(&saved).unwrap(),
            "saved during the run"
        );
        let page = std::fs::read_to_string(out.join("index.html")).unwrap();
        assert_eq!(page, "the first");
        assert!(temporaries(&out).is_empty(), "{:?}", temporaries(&out));
        std::fs::remove_file(&saved).unwrap();
        write_report(&out, |write| write("index.html", b"the third")).unwrap();
        let page = std::fs::read_to_string(out.join("index.html")).unwrap();
        assert_eq!(page, "the third");
    }
}
