//! `delta-stability report CONFIG [--mach A:B:STEP|LIST] [--out DIR]`: a
//! design's own report ([`crate::report::design`]) — its figures (SVG and
//! CSV), `summary.json`, `sources.csv` and `index.html` — written as the
//! note's study is (`cmd::report`'s `write_report`: atomically, with the
//! manifest, replacing only an earlier report).

use super::report::{Args, progress_bar, write_plate, write_report};
use crate::Failure;
use crate::report::design::{Design, MAX_MACHS, default_machs, figures, page};
use crate::report::html::DOCS;
use stability_io::config::overridden;
use stability_io::diag::InputError;
use stability_io::sweep::parse_machs;
use stability_io::views::DesignReportJson;
use std::path::Path;

/// The options that need CONFIG, refused without one (the note's study
/// has its own cases).
pub fn refuse_design_options(args: &Args) -> Result<(), Failure> {
    let m = &args.model;
    let given = [
        ("--mach", args.mach.is_some()),
        ("--class", args.class.is_some()),
        ("--damping", m.damping.is_some()),
        ("--aero", m.aero.is_some()),
        ("--omega-bar", m.omega_bar.is_some()),
    ];
    match given.iter().find(|g| g.1) {
        Some((flag, _)) => Err(Failure::Input(InputError::file(
            "report",
            format!(
                "{flag} applies to a design's report: give its CONFIG (report CONFIG {flag} …); without one, report writes the note's own study"
            ),
        ))),
        None => Ok(()),
    }
}

/// The Mach numbers of `--mach`, or the default about `own`, each within
/// the Mach number's range and at most [`MAX_MACHS`] of them.
fn machs(text: Option<&str>, own: f64) -> Result<Vec<f64>, String> {
    let ms = match text {
        Some(t) => parse_machs(t)?,
        None => return Ok(default_machs(own)),
    };
    if ms.len() > MAX_MACHS {
        return Err(format!(
            "--mach: {} Mach numbers; a report takes at most {MAX_MACHS} (take a larger step)",
            ms.len()
        ));
    }
    Ok(ms)
}

pub fn run(args: &Args, config: &str) -> Result<(), Failure> {
    let (cfg, read) =
        stability_io::files::recording(|| overridden(config, &args.model.overrides()));
    let cfg = cfg?;
    let out = Path::new(&args.out);
    let outputs = [crate::overwrite::Named::directory("--out", &args.out)];
    crate::overwrite::refuse("CONFIG", config, &read, &outputs)?;
    let bad = |m: String| Failure::Input(InputError::file(config, m));
    let ms = machs(args.mach.as_deref(), cfg.case.mach).map_err(bad)?;
    let class = stability_io::class::ClassChoice::of(args.class.map(|c| c.0), cfg.class);
    let bar = progress_bar(3);
    bar.set_message(format!("{} Mach numbers", ms.len()));
    let design = Design::new(cfg, &ms, class);
    bar.inc(1);
    let failed: Vec<String> = design
        .points
        .iter()
        .filter_map(|(m, r)| {
            r.as_ref()
                .err()
                .map(|e| format!("M = {}: {e}", stability_io::plot::short(*m)))
        })
        .collect();
    if failed.len() == design.points.len() {
        bar.finish_and_clear();
        return Err(Failure::Input(InputError::file(
            config,
            format!(
                "no Mach number has a result, so there is nothing to report; the first: {}",
                failed[0]
            ),
        )));
    }
    let mut figures_written = 0;
    write_report(out, |write| {
        bar.set_message("figures");
        let sections = figures::sections(&design);
        for (_, plates) in &sections {
            for p in plates {
                write_plate(write, out, p)?;
                figures_written += 1;
            }
        }
        bar.inc(1);
        let summary = DesignReportJson::new(&design.cfg, class.class, &design.points);
        crate::output::finite("summary.json", &summary)?;
        let json = serde_json::to_string_pretty(&summary).unwrap_or_default();
        write("summary.json", json.as_bytes())?;
        write("sources.csv", page::sources_csv(&design).as_bytes())?;
        write(
            "index.html",
            page::index_html(&design, &sections).as_bytes(),
        )?;
        for (name, text) in DOCS {
            write(name, text.as_bytes())?;
        }
        Ok(())
    })?;
    bar.finish_and_clear();
    for f in &failed {
        crate::output::warn(&format!("warning: no result at {f}"));
    }
    crate::output::print(&format!(
        "wrote {figures_written} figures (SVG and CSV), summary.json, sources.csv and index.html to {}\n{}",
        out.display(),
        page::verdict_lines(&design)
    ))
}
