//! `delta-stability quartic FILE [--json] [--state-space OUT.json]`: the
//! stability quartic of a derivative set (eqs 4–6), its roots and modes
//! (§4, eqs 7–8), Routh's test, the §8 damping standard and the
//! MIL-F-8785C levels; with `[dimensional]`, the modes in seconds
//! (`damp()`) and the short-period frequency requirement; the mode shapes;
//! and the state-space model, written on request.

use crate::Failure;
use crate::diag::InputError;
use crate::input::dimensional_notation::{self, DIMENSIONAL, DimensionalFile, is_dimensional};
use crate::input::{self, DerivativeFile, rows};
use crate::output::print;
use crate::page::analysis_page;
use serde::Serialize;
use stability_core::Derivatives;
use stability_core::analysis::{Analysis, AnalysisError};
use stability_core::cap::{AirplaneClass, n_alpha_dimensional};
use stability_core::dimensional::DimensionalAnalysis;
use stability_core::engineering::Engineering;
use stability_core::json::Timed;
use stability_core::linear::{Control, LinearModel};
use std::path::Path;

/// The command's options beside the file.
#[derive(Debug, Clone)]
pub struct Options {
    pub json: bool,
    /// Where to write the state space (`OUT.json`, with `OUT.py` and `OUT.m`).
    pub state_space: Option<String>,
    /// The airplane class of the Category C frequency floors.
    pub class: AirplaneClass,
}

pub fn run(file: &str, o: &Options) -> Result<(), Failure> {
    let text = crate::files::read_input(Path::new(file))?;
    if is_dimensional(&text) {
        return run_dimensional(&dimensional_notation::parse(file, &text)?, o);
    }
    let input = input::parse(file, &text)?;
    let control = crate::state_space::read_control(file, &text)?;
    for w in &input.warnings {
        crate::output::warn(&format!("warning: {w}"));
    }
    let (analysis, engineering) = evaluated(&input, control.as_ref(), o.class)?;
    let tau = input.dimensional.map(|d| d.tau());
    if let Some(out) = &o.state_space {
        let roots = tau.map_or(analysis.roots, |t| analysis.roots.map(|z| z / t));
        crate::state_space::write(
            out,
            &crate::state_space::Export {
                source: file,
                command: "quartic",
                model: &engineering.model,
                tau,
                eigenvalues: roots,
            },
        )?;
    }
    if o.json {
        print(&format!(
            "{}\n",
            serde_json::to_string_pretty(&to_json(&input, &analysis, &engineering))
                .unwrap_or_default()
        ))?;
    } else {
        print(&table(&input, &analysis, &engineering))?;
    }
    Ok(())
}

/// The analysis of a derivative file and the engineer's outputs from it
/// (damp(), mode shapes, the short-period frequency requirement), every
/// number finite, or the error at the input it arises from: what `quartic`
/// prints, and what the Python package's `quartic()` returns.
pub fn evaluated(
    input: &DerivativeFile,
    control: Option<&Control>,
    class: AirplaneClass,
) -> Result<(Analysis, Engineering), InputError> {
    let analysis = analysis_of(input)?;
    let tau = input.dimensional.map(|d| d.tau());
    match Engineering::of_report(&input.derivatives, &analysis, tau, control, class) {
        Ok(engineering) => Ok((analysis, engineering)),
        Err(_) => Err(input.error_at(
            most_extreme_input(input),
            "the analysis overflows f64: no result can be written",
        )),
    }
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
pub(crate) fn most_extreme_input(input: &DerivativeFile) -> usize {
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
pub(crate) fn blame(input: &DerivativeFile, e: &AnalysisError) -> usize {
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
    /// `damp`, `mode_shapes`, `short_period_frequency`.
    #[serde(flatten)]
    engineering: &'a Engineering,
}

pub fn to_json<'a>(
    input: &'a DerivativeFile,
    a: &'a Analysis,
    engineering: &'a Engineering,
) -> QuarticJson<'a> {
    QuarticJson {
        file: &input.path,
        notation: &input.notation,
        analysis: a.timed(input.dimensional.map(|d| d.tau())),
        warnings: &input.warnings,
        engineering,
    }
}

pub fn table(input: &DerivativeFile, a: &Analysis, engineering: &Engineering) -> String {
    let mut s = analysis_page(
        &format!(
            "Stability quartic of {} (eqs 4–6; the errata of docs/errata.md applied)",
            input.path
        ),
        a,
        input.dimensional.map(|d| d.tau()),
    );
    if let Some(f) = &engineering.short_period_frequency {
        s.push_str(&crate::engineering::frequency_line(f));
        s.push('\n');
    }
    s.push_str(&crate::engineering::tables(engineering));
    s
}

/// `quartic` of a `notation = "dimensional"` set: the general model
/// (eq D2), roots in 1/s, modes in seconds; the engineer's outputs (damp(),
/// mode shapes, the short-period frequency requirement, the state space)
/// from the set in stability axes.
fn run_dimensional(input: &DimensionalFile, o: &Options) -> Result<(), Failure> {
    for w in &input.warnings {
        crate::output::warn(&format!("warning: {w}"));
    }
    let a = input.analysis()?;
    let engineering = dimensional_engineering(&a, o.class);
    let finite = a.quartic.is_finite()
        && a.routh.discriminant.is_finite()
        && a.roots.iter().all(|z| z.re.is_finite() && z.im.is_finite());
    let (true, Some(engineering)) = (finite, engineering) else {
        return Err(input
            .error_at(
                input.most_extreme(),
                "the analysis overflows f64: no result can be written",
            )
            .into());
    };
    if let Some(out) = &o.state_space {
        crate::state_space::write(
            out,
            &crate::state_space::Export {
                source: &input.path,
                command: "quartic",
                model: &engineering.model,
                tau: None,
                eigenvalues: a.roots,
            },
        )?;
    }
    if o.json {
        let out = DimensionalJson {
            file: &input.path,
            notation: DIMENSIONAL,
            analysis: &a,
            warnings: &input.warnings,
            engineering: &engineering,
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
        let mut page = crate::page_dimensional::page(&title, &a);
        if let Some(f) = &engineering.short_period_frequency {
            page.push_str(&crate::engineering::frequency_line(f));
            page.push('\n');
        }
        page.push_str(&crate::engineering::tables(&engineering));
        print(&page)?;
    }
    Ok(())
}

/// The engineer's outputs of a dimensional set, from its stability-axis
/// form (where the mode shapes are the ones Etkin & Reid and AVL print):
/// the state matrix E⁻¹A in seconds, n/α = −Z_w U₀/g. `None` when E is
/// singular or the matrix is not finite.
fn dimensional_engineering(a: &DimensionalAnalysis, class: AirplaneClass) -> Option<Engineering> {
    let st = &a.stability;
    let matrix = st
        .state_matrix()
        .filter(|m| m.iter().all(|v| v.is_finite()))?;
    let model = LinearModel::of_dimensional(matrix, None, None, st.trim.speed());
    let n_alpha = n_alpha_dimensional(st.derivatives.z_w, st.trim.u0, st.trim.g);
    Some(Engineering::of_model(model, &a.roots, Some(n_alpha), class))
}

/// The `quartic --json` object of a dimensional set.
#[derive(Serialize)]
struct DimensionalJson<'a> {
    file: &'a str,
    notation: &'a str,
    #[serde(flatten)]
    analysis: &'a DimensionalAnalysis,
    warnings: &'a [String],
    /// `damp`, `mode_shapes`, `short_period_frequency`.
    #[serde(flatten)]
    engineering: &'a Engineering,
}
