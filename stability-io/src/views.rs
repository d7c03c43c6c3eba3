//! The JSON objects the program prints (`--json`) and the Python package's
//! `to_dict()` returns, key for key: each a view over the library's
//! results and the file they came from. The key names are an interface
//! (scripts depend on them).

use crate::config::Config;
use crate::design_point::Results;
use crate::input::DerivativeFile;
use crate::input::dimensional_notation::{DIMENSIONAL, DimensionalFile};
use serde::Serialize;
use stability_core::Derivatives;
use stability_core::aerodynamics::models::aero::Coefficients;
use stability_core::analysis::engineering::Engineering;
use stability_core::analysis::verdict::Overall;
use stability_core::analysis::{Analysis, Timebase};
use stability_core::criteria::cap::ShortPeriodFrequency;
use stability_core::criteria::{DampingStandard, FlyingQualities, Margins};
use stability_core::data::dimensional::DimensionalAnalysis;
use stability_core::data::json::TimedMode;
use stability_core::data::json::{CaseView, Timed};
use stability_core::design::flight::FlightJson;
use stability_core::dynamics::modes::{ModeName, Origin};
use stability_core::dynamics::sensitivity::{ModeSensitivity, mode_sensitivities};

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
    /// The form the `[derivatives]` table was printed in.
    form: &'static str,
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
            form: input.form.as_str(),
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

/// One Mach number of a design's report (`report CONFIG`'s
/// `summary.json`, `points`): the design point as `analyze --mach M`
/// evaluates it, under `analyze --json`'s key names — the flight
/// condition, the overall verdict with its reasons, the modes (in τ, and
/// in seconds where the flight condition is physical), §8's standard
/// (eq 41), the MIL-F-8785C levels and CAP, §9's margins (eq 42), the
/// aerodynamic centre beside the c.g., the coefficients with their
/// origins, the damping theory and the derivatives — or why there is none
/// (`error`).
#[derive(Serialize)]
pub struct DesignPointJson<'a> {
    mach: f64,
    #[serde(flatten)]
    point: Option<DesignPointKeys<'a>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    error: Option<&'a str>,
}

#[derive(Serialize)]
struct DesignPointKeys<'a> {
    #[serde(skip_serializing_if = "Option::is_none")]
    flight: Option<FlightJson>,
    c_l: f64,
    tau_s: Option<f64>,
    verdict: Overall,
    stable: bool,
    modes: Vec<TimedMode>,
    damping_standard: &'a DampingStandard,
    mil_f_8785c: FlyingQualities,
    short_period_frequency: Option<&'a ShortPeriodFrequency>,
    #[serde(skip_serializing_if = "Option::is_none")]
    short_period_frequency_not_assessed: Option<&'a str>,
    margins: Margins,
    cg: f64,
    aerodynamic_centre: f64,
    aerodynamics: &'a Coefficients,
    damping: DesignDamping,
    derivatives: &'a Derivatives,
    warnings: Vec<String>,
}

/// The damping theory of a point and its two damping derivatives (§7).
#[derive(Serialize)]
struct DesignDamping {
    theory: &'static str,
    equations: &'static str,
    z_thetadot: f64,
    m_thetadot: f64,
}

impl<'a> DesignPointJson<'a> {
    /// Mach number `mach`'s point of `cfg`, or its error.
    pub fn new(cfg: &'a Config, mach: f64, res: Result<&'a Results, &'a str>) -> Self {
        match res {
            Ok(res) => DesignPointJson {
                mach,
                point: Some(DesignPointKeys::new(cfg, res)),
                error: None,
            },
            Err(e) => DesignPointJson {
                mach,
                point: None,
                error: Some(e),
            },
        }
    }
}

impl<'a> DesignPointKeys<'a> {
    fn new(cfg: &'a Config, res: &'a Results) -> Self {
        let r = &res.result;
        let a = &r.analysis;
        let tau = res.tau();
        let time = Timebase::Tau(tau);
        let e = &res.engineering;
        DesignPointKeys {
            flight: res.flight.map(|(f, p)| f.json(&p)),
            c_l: r.c_l,
            tau_s: tau,
            verdict: Overall::of(a, time),
            stable: a.routh.stable,
            modes: a.modes.iter().map(|m| m.timed(tau)).collect(),
            damping_standard: &a.damping_standard,
            mil_f_8785c: a.flying_qualities(time),
            short_period_frequency: e.short_period_frequency.as_ref(),
            short_period_frequency_not_assessed: e.short_period_frequency_not_assessed.as_deref(),
            margins: Margins::at_cg(
                &a.quartic,
                &r.derivatives,
                r.coefficients.lift_slope.value,
                cfg.case.h,
            ),
            cg: cfg.case.h,
            aerodynamic_centre: r.coefficients.aerodynamic_centre.value,
            aerodynamics: &r.coefficients,
            damping: DesignDamping {
                theory: r.damping.theory.name(),
                equations: r.damping.theory.equations(),
                z_thetadot: r.damping.derivatives.z_thetadot(),
                m_thetadot: r.damping.derivatives.m_thetadot(),
            },
            derivatives: &r.derivatives,
            warnings: r.warnings.iter().map(ToString::to_string).collect(),
        }
    }
}

/// A design's report across Mach number (`report CONFIG`'s
/// `summary.json`): the config and its design (planform, c.g., damping
/// model, flight condition), the airplane class of the CAP levels, the
/// Mach numbers where the overall verdict is each of meets, fails and
/// divergent (runs of consecutive grid values, `[first, last]`), and with
/// no result, the worst verdict, and each Mach number's point
/// ([`DesignPointJson`]).
#[derive(Serialize)]
pub struct DesignReportJson<'a> {
    config: &'a str,
    design: DesignKeys,
    class: &'static str,
    verdict: DesignVerdicts,
    points: Vec<DesignPointJson<'a>>,
}

#[derive(Serialize)]
struct DesignKeys {
    sweep_deg: f64,
    taper: f64,
    aspect_ratio: f64,
    cg: f64,
    damping: &'static str,
    flight_condition: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    mu1: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    i_b: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    cl_m2: Option<f64>,
}

/// The overall verdict across the Mach numbers.
#[derive(Serialize)]
struct DesignVerdicts {
    /// The worst over the points with a result (`null` if none has one).
    worst: Option<stability_core::criteria::Verdict>,
    meets: Vec<[f64; 2]>,
    fails: Vec<[f64; 2]>,
    divergent: Vec<[f64; 2]>,
    no_result: Vec<[f64; 2]>,
}

/// Runs of consecutive grid values `machs` where `pick` holds, as
/// `[first, last]`.
fn runs(machs: &[f64], pick: impl Fn(usize) -> bool) -> Vec<[f64; 2]> {
    let mut out: Vec<[f64; 2]> = Vec::new();
    let mut open = false;
    for (k, &m) in machs.iter().enumerate() {
        match (pick(k), open, out.last_mut()) {
            (true, true, Some(last)) => last[1] = m,
            (true, _, _) => out.push([m, m]),
            (false, _, _) => {}
        }
        open = pick(k);
    }
    out
}

impl<'a> DesignReportJson<'a> {
    /// The report of `cfg` at the Mach numbers `points` (each with its
    /// results or its error), with the CAP levels of `class`.
    pub fn new(
        cfg: &'a Config,
        class: Option<stability_core::criteria::cap::AirplaneClass>,
        points: &'a [(f64, Result<Results, String>)],
    ) -> Self {
        use stability_core::criteria::Verdict;
        let verdicts: Vec<Option<Verdict>> = points
            .iter()
            .map(|(_, r)| {
                r.as_ref()
                    .ok()
                    .map(|r| stability_core::analysis::verdict::overall(&r.result.analysis))
            })
            .collect();
        let machs: Vec<f64> = points.iter().map(|p| p.0).collect();
        let on = |v: Verdict| runs(&machs, |k| verdicts[k] == Some(v));
        let c = &cfg.case;
        let dimensionless = cfg.physical.is_none();
        DesignReportJson {
            config: &cfg.path,
            design: DesignKeys {
                sweep_deg: c.planform.sweep_le.to_degrees(),
                taper: c.planform.taper,
                aspect_ratio: c.planform.aspect_ratio(),
                cg: c.h,
                damping: c.damping.name(),
                flight_condition: if dimensionless {
                    "non-dimensional"
                } else {
                    "physical"
                },
                mu1: dimensionless.then_some(c.mu1),
                i_b: dimensionless.then_some(c.i_b),
                cl_m2: dimensionless.then_some(c.cl_m2),
            },
            class: class.map_or("not given", |c| c.name()),
            verdict: DesignVerdicts {
                worst: verdicts.iter().flatten().max().copied(),
                meets: on(Verdict::Meets),
                fails: on(Verdict::Fails),
                divergent: on(Verdict::Divergent),
                no_result: runs(&machs, |k| verdicts[k].is_none()),
            },
            points: points
                .iter()
                .map(|(m, r)| DesignPointJson::new(cfg, *m, r.as_ref().map_err(String::as_str)))
                .collect(),
        }
    }
}

#[cfg(test)]
mod design_tests {
    use super::runs;

    #[test]
    fn runs_join_consecutive_grid_values() {
        let ms = [0.5, 0.6, 0.7, 0.8, 0.9];
        let pick = [true, true, false, true, true];
        assert_eq!(runs(&ms, |k| pick[k]), vec![[0.5, 0.6], [0.8, 0.9]]);
        assert_eq!(runs(&ms, |_| false), Vec::<[f64; 2]>::new());
        assert_eq!(runs(&ms, |k| k == 2), vec![[0.7, 0.7]]);
    }
}
