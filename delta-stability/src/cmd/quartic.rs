//! `delta-stability quartic FILE [--json]`: the stability quartic of a
//! derivative set (eqs 4–6), its roots and modes (§4, eqs 7–8), Routh's
//! test, the §8 damping standard and the MIL-F-8785C levels.

use crate::Failure;
use crate::diag::InputError;
use crate::input::dimensional_notation::DIMENSIONAL;
use crate::input::dimensional_notation::DimensionalFile;
use crate::input::{self, AnyFile, DerivativeFile, rows};
use crate::output::print;
use crate::page::analysis_page;
use serde::Serialize;
use stability_core::Derivatives;
use stability_core::analysis::{Analysis, AnalysisError};
use stability_core::dimensional::DimensionalAnalysis;
use stability_core::json::Timed;

pub fn run(file: &str, json: bool) -> Result<(), Failure> {
    let input = match input::read_any(file)? {
        AnyFile::Report(input) => *input,
        AnyFile::Dimensional(input) => return run_dimensional(&input, json),
    };
    for w in &input.warnings {
        crate::output::warn(&format!("warning: {w}"));
    }
    let analysis = analysis_of(&input)?;
    if json {
        print(&format!(
            "{}\n",
            serde_json::to_string_pretty(&to_json(&input, &analysis)).unwrap_or_default()
        ))?;
    } else {
        print(&table(&input, &analysis))?;
    }
    Ok(())
}

/// The analysis of a derivative file, every number of it finite, or the
/// error at the input it arises from (what `quartic` prints; the Python
/// package raises the same).
pub fn analysis_of(input: &DerivativeFile) -> Result<Analysis, InputError> {
    let analysis = Analysis::of(&input.derivatives)
        .map_err(|e| input.error_at(blame(input, &e), e.to_string()))?;
    if !is_finite(&analysis) {
        let largest = most_extreme_input(input);
        return Err(input.error_at(
            largest,
            "the analysis overflows f64: no result can be written",
        ));
    }
    Ok(analysis)
}

/// Whether every number the analysis would print is finite (absent ones,
/// such as an aperiodic mode's period, are `None`, not infinite).
pub fn is_finite(a: &Analysis) -> bool {
    a.quartic.to_array().iter().all(|v| v.is_finite())
        && a.roots.iter().all(|z| z.re.is_finite() && z.im.is_finite())
        && a.routh.discriminant.is_finite()
        && a.modes.iter().all(|m| m.re.is_finite() && m.im.is_finite())
}

/// The quartic input most extreme in magnitude, largest or smallest (the
/// likeliest cause of an overflow: μ₁ = 1e-300 as much as 1e300).
fn most_extreme_input(input: &DerivativeFile) -> usize {
    let mut best = (0.0, rows::QUARTIC[0]);
    for i in rows::QUARTIC {
        let v = input.report[i].map_or(0.0, f64::abs);
        let extreme = if v > 0.0 { v.log10().abs() } else { 0.0 };
        if extreme > best.0 {
            best = (extreme, i);
        }
    }
    best.1
}

/// The row an analysis error is about.
fn blame(input: &DerivativeFile, e: &AnalysisError) -> usize {
    let named = |name: &str| {
        Derivatives::QUARTIC_INPUTS
            .iter()
            .position(|n| *n == name)
            .map(|k| rows::QUARTIC[k])
    };
    match e {
        AnalysisError::LeadingCoefficientZero { .. } => rows::Z_WDOT,
        AnalysisError::NonFinite { input: name, .. }
        | AnalysisError::NotPositive { input: name, .. } => {
            named(name).unwrap_or_else(|| most_extreme_input(input))
        }
        _ => most_extreme_input(input),
    }
}

/// The `quartic --json` object: the file and its notation, the analysis as
/// the library serializes it (with times in seconds where τ is known), and
/// the reader's warnings.
#[derive(Serialize)]
pub struct QuarticJson<'a> {
    file: &'a str,
    notation: &'a str,
    #[serde(flatten)]
    analysis: Timed<'a>,
    warnings: &'a [String],
}

pub fn to_json<'a>(input: &'a DerivativeFile, a: &'a Analysis) -> QuarticJson<'a> {
    QuarticJson {
        file: &input.path,
        notation: &input.notation,
        analysis: a.timed(input.dimensional.map(|d| d.tau())),
        warnings: &input.warnings,
    }
}

pub fn table(input: &DerivativeFile, a: &Analysis) -> String {
    analysis_page(
        &format!(
            "Stability quartic of {} (eqs 4–6; the errata of docs/errata.md applied)",
            input.path
        ),
        a,
        input.dimensional.map(|d| d.tau()),
    )
}

/// `quartic` of a `notation = "dimensional"` set: the general model
/// (eq D2), roots in 1/s, modes in seconds.
fn run_dimensional(input: &DimensionalFile, json: bool) -> Result<(), Failure> {
    for w in &input.warnings {
        crate::output::warn(&format!("warning: {w}"));
    }
    let a = input.analysis()?;
    let finite = a.quartic.is_finite()
        && a.routh.discriminant.is_finite()
        && a.roots.iter().all(|z| z.re.is_finite() && z.im.is_finite());
    if !finite {
        return Err(input
            .error_at(
                input.most_extreme(),
                "the analysis overflows f64: no result can be written",
            )
            .into());
    }
    if json {
        let out = DimensionalJson {
            file: &input.path,
            notation: DIMENSIONAL,
            analysis: &a,
            warnings: &input.warnings,
        };
        print(&format!(
            "{}\n",
            serde_json::to_string_pretty(&out).unwrap_or_default()
        ))?;
    } else {
        let title = format!(
            "Stability quartic of {} (notation \"dimensional\": the general longitudinal model, eqs D1–D2)",
            input.path
        );
        print(&crate::page_dimensional::page(&title, &a))?;
    }
    Ok(())
}

/// The `quartic --json` object of a dimensional set.
#[derive(Serialize)]
struct DimensionalJson<'a> {
    file: &'a str,
    notation: &'a str,
    #[serde(flatten)]
    analysis: &'a DimensionalAnalysis,
    warnings: &'a [String],
}
