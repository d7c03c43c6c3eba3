//! `report()`: the note's whole study ([`stability_study::Report`]), what
//! `delta-stability report` computes, with the GIL released: its
//! `summary.json`, byte for byte the command line's, and each figure's SVG
//! and CSV, written into a folder (the command line's page, `index.html`,
//! and its atomic replacement of the folder are the command line's).

use crate::errors::{failure, input_error};
use crate::guard;
use pyo3::prelude::*;
use stability_io::Failure;
use stability_io::diag::IoError;
use stability_io::files::write_error;
use stability_io::plot::Plate;
use stability_study::Report;
use stability_study::report::{Step, Stopped};
use std::path::{Path, PathBuf};

/// The study, computed whole: with `out`, its `summary.json` and (with
/// `figures`) each figure's `figNN.svg` and `figNN.csv` written into the
/// folder `out` (made if missing; files of the same names replaced, the
/// figures as soon as each is drawn). Returns `summary.json`'s text.
#[pyfunction]
#[pyo3(signature = (out, /, *, figures=true))]
pub fn report_run(py: Python<'_>, out: Option<PathBuf>, figures: bool) -> PyResult<String> {
    guard(|| {
        let written = py.detach(|| run(out.as_deref(), figures));
        let report = written.map_err(failure)?;
        let json = report.summary_json().map_err(|e| input_error(&e))?;
        if let Some(dir) = &out {
            write(&dir.join("summary.json"), json.as_bytes()).map_err(failure)?;
        }
        Ok(json)
    })
}

/// The report, its figures written into `out` as they are drawn.
fn run(out: Option<&Path>, figures: bool) -> Result<Report, Failure> {
    if let Some(dir) = out {
        std::fs::create_dir_all(dir).map_err(|e| Failure::Io(write_error(dir, &e)))?;
    }
    Report::compute(|step| match (step, out) {
        (Step::Drew(plates), Some(dir)) if figures => write_plates(dir, plates),
        _ => Ok(()),
    })
    .map_err(|e| match e {
        Stopped::Caller(f) => f,
        Stopped::Study { what, why } => {
            Failure::Io(IoError::new(what, out.unwrap_or(Path::new(".")), why))
        }
    })
}

/// Each plate's two files, written into `dir`.
fn write_plates(dir: &Path, plates: &[Plate]) -> Result<(), Failure> {
    for p in plates {
        let files = p
            .files()
            .map_err(|m| IoError::new("cannot draw", &dir.join(p.name()), m))?;
        for (name, bytes) in files {
            write(&dir.join(name), &bytes)?;
        }
    }
    Ok(())
}

fn write(path: &Path, bytes: &[u8]) -> Result<(), Failure> {
    std::fs::write(path, bytes).map_err(|e| Failure::Io(write_error(path, &e)))
}
