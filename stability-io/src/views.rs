//! The JSON objects the program prints (`--json`) and the Python package's
//! `to_dict()` returns, key for key: each a view over the library's
//! results and the file they came from. The key names are an interface
//! (scripts depend on them).

use crate::config::Config;
use crate::design_point::Results;
use crate::input::DerivativeFile;
use crate::input::dimensional_notation::{DIMENSIONAL, DimensionalFile};
use serde::Serialize;
use stability_core::analysis::Analysis;
use stability_core::dimensional::DimensionalAnalysis;
use stability_core::engineering::Engineering;
use stability_core::flight::FlightJson;
use stability_core::json::{CaseView, Timed};
use stability_core::modes::{ModeName, Origin};
use stability_core::sensitivity::{ModeSensitivity, mode_sensitivities};

/// The `quartic --json` object of a report-notation file: the file and
/// its notation, the analysis as the library serializes it (with times in
/// seconds where τ is known), the reader's warnings and the engineer's
/// outputs (`damp`, `mode_shapes`, `short_period_frequency`).
#[derive(Serialize)]
pub struct QuarticJson<'a> {
    file: &'a str,
    notation: &'a str,
    #[serde(flatten)]
    analysis: Timed<'a>,
    warnings: &'a [String],
    #[serde(flatten)]
    engineering: &'a Engineering,
}

impl<'a> QuarticJson<'a> {
    pub fn new(input: &'a DerivativeFile, a: &'a Analysis, engineering: &'a Engineering) -> Self {
        QuarticJson {
            file: &input.path,
            notation: &input.notation,
            analysis: a.timed(input.tau()),
            warnings: &input.warnings,
            engineering,
        }
    }
}

/// The `quartic --json` object of a `notation = "dimensional"` file.
#[derive(Serialize)]
pub struct DimensionalJson<'a> {
    file: &'a str,
    notation: &'a str,
    #[serde(flatten)]
    analysis: &'a DimensionalAnalysis,
    warnings: &'a [String],
    #[serde(flatten)]
    engineering: &'a Engineering,
}

impl<'a> DimensionalJson<'a> {
    pub fn new(
        input: &'a DimensionalFile,
        analysis: &'a DimensionalAnalysis,
        engineering: &'a Engineering,
    ) -> Self {
        DimensionalJson {
            file: &input.path,
            notation: DIMENSIONAL,
            analysis,
            warnings: &input.warnings,
            engineering,
        }
    }
}

/// The `analyze --json` object: the config's path, the physical flight
/// condition when there is one, the design point as the library
/// serializes it and the engineer's outputs.
#[derive(Serialize)]
pub struct AnalyzeJson<'a> {
    file: &'a str,
    #[serde(skip_serializing_if = "Option::is_none")]
    flight: Option<FlightJson>,
    /// The DATCOM output the tables come from, when one does.
    #[serde(skip_serializing_if = "Option::is_none")]
    datcom: Option<DatcomJson<'a>>,
    /// Where the model's tables come from, in words.
    tables: Vec<String>,
    #[serde(flatten)]
    point: CaseView<'a>,
    #[serde(flatten)]
    engineering: &'a Engineering,
}

impl<'a> AnalyzeJson<'a> {
    pub fn new(cfg: &'a Config, res: &'a Results) -> Self {
        AnalyzeJson {
            file: &cfg.path,
            flight: res.flight.map(|(f, p)| f.json(&p)),
            datcom: cfg.datcom.as_ref().map(|d| DatcomJson {
                file: &d.output.path,
                configuration: &d.output.configuration,
                reference_cg: d.tables.reference_cg,
                mach: d.output.points.iter().map(|p| p.mach).collect(),
            }),
            tables: cfg.tables_summary(),
            point: res.result.view_timed(&cfg.case, res.tau()),
            engineering: &res.engineering,
        }
    }
}

/// A DATCOM output's particulars (`analyze --json`'s `datcom`).
#[derive(Serialize)]
pub struct DatcomJson<'a> {
    pub file: &'a str,
    pub configuration: &'a str,
    /// DATCOM's moment centre h (fraction of the M.A.C.).
    pub reference_cg: f64,
    /// Its Mach numbers.
    pub mach: Vec<f64>,
}

/// One input's sensitivities, with the rates also in 1/s when τ is known.
#[derive(Serialize)]
pub struct InputSensitivity {
    #[serde(flatten)]
    pub s: ModeSensitivity,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub d_re_s: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub d_im_s: Option<f64>,
}

/// One mode's root and its sensitivities.
#[derive(Serialize)]
pub struct ModeSensitivities {
    pub mode: ModeName,
    pub origin: Option<Origin>,
    pub re: f64,
    pub im: f64,
    /// `None` at a multiple root, where λ is not differentiable.
    pub sensitivities: Option<Vec<InputSensitivity>>,
}

/// The `sensitivity --json` object.
#[derive(Serialize)]
pub struct SensitivityJson<'a> {
    pub file: &'a str,
    pub notation: &'a str,
    pub tau_s: Option<f64>,
    pub modes: Vec<ModeSensitivities>,
}

impl<'a> SensitivityJson<'a> {
    /// Every mode's sensitivities to the fifteen quartic inputs.
    pub fn new(input: &'a DerivativeFile, analysis: &Analysis) -> Self {
        let tau = input.tau();
        let d = &input.derivatives;
        let modes = analysis
            .modes
            .iter()
            .map(|m| ModeSensitivities {
                mode: m.name,
                origin: m.origin,
                re: m.re,
                im: m.im,
                sensitivities: mode_sensitivities(d, m).map(|v| {
                    v.into_iter()
                        .map(|s| InputSensitivity {
                            d_re_s: tau.map(|t| s.d_re / t),
                            d_im_s: tau.map(|t| s.d_im / t),
                            s,
                        })
                        .collect()
                }),
            })
            .collect();
        SensitivityJson {
            file: &input.path,
            notation: &input.notation,
            tau_s: tau,
            modes,
        }
    }

    /// Whether every sensitivity is finite.
    pub fn is_finite(&self) -> bool {
        self.modes
            .iter()
            .flat_map(|m| m.sensitivities.iter().flatten())
            .all(|i| {
                [i.s.d_re, i.s.d_im, i.s.d_damping_ratio, i.s.damping_drive]
                    .iter()
                    .all(|v| v.is_finite())
            })
    }
}
