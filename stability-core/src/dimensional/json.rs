//! The JSON of a dimensional set's analysis: what `delta-stability quartic
//! --json` prints for `notation = "dimensional"`.
//!
//! Rates are in 1/s and times in s under the `_s` keys of the report
//! notation's JSON (`re_s`, `im_s`, `period_s`, `time_to_half_s`,
//! `time_to_double_s`, `natural_frequency_s`); when a reference gives τ, the
//! τ-unit keys (`re`, `im`, `period`, …) and `tau_s` are there too, as for a
//! report-notation set with `[dimensional]`. The polynomial's coefficients
//! are those of det(λE − A) with λ in 1/s (eq D2).

use super::analysis::{DimensionalAnalysis, InReportNotation};
use super::{Axes, DimensionalDerivatives, DimensionalModel, Dropped, Reference, Units};
use crate::criteria::{DampingStandard, FlyingQualities, ShortPeriodApproximation, Verdict};
use crate::modes::{Mode, ModeName, Origin};
use crate::{Derivatives, Quartic};
use num_complex::Complex64;
use serde::ser::SerializeMap;
use serde::{Serialize, Serializer};

impl Serialize for DimensionalDerivatives {
    /// As an object by the file's names (`X_u`, …, `M_q`), in their order.
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut map = s.serialize_map(Some(Self::NAMES.len()))?;
        for (name, value) in Self::NAMES.iter().zip(self.values()) {
            map.serialize_entry(name, &value)?;
        }
        map.end()
    }
}

/// A model as its file gives it: axes, units, the trim (θ₀, α₀, γ₀ in
/// degrees) and the derivatives.
#[derive(Serialize)]
struct ModelJson<'a> {
    axes: Axes,
    units: Units,
    #[serde(rename = "U0")]
    u0: f64,
    #[serde(rename = "W0")]
    w0: f64,
    #[serde(rename = "V")]
    v: f64,
    theta0_deg: f64,
    alpha0_deg: f64,
    gamma0_deg: f64,
    g: f64,
    derivatives: &'a DimensionalDerivatives,
}

impl Serialize for DimensionalModel {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let t = &self.trim;
        ModelJson {
            axes: self.axes,
            units: self.units,
            u0: t.u0,
            w0: t.w0,
            v: t.speed(),
            theta0_deg: t.theta0.to_degrees(),
            alpha0_deg: t.alpha0().to_degrees(),
            gamma0_deg: t.gamma0().to_degrees(),
            g: t.g,
            derivatives: &self.derivatives,
        }
        .serialize(s)
    }
}

/// A root in 1/s, and in 1/τ when τ is known.
#[derive(Serialize)]
struct RootJson {
    re_s: f64,
    im_s: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    re: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    im: Option<f64>,
}

impl RootJson {
    fn new(z: Complex64, tau: Option<f64>) -> Self {
        RootJson {
            re_s: z.re,
            im_s: z.im,
            re: tau.map(|t| z.re * t),
            im: tau.map(|t| z.im * t),
        }
    }
}

/// A mode (computed in seconds) with the keys of the report notation's
/// JSON: the `_s` ones always, the τ-unit ones when τ is known.
#[derive(Serialize)]
struct ModeJson {
    name: ModeName,
    origin: Option<Origin>,
    re_s: f64,
    im_s: f64,
    period_s: Option<f64>,
    time_to_half_s: Option<f64>,
    time_to_double_s: Option<f64>,
    cycles_to_half: Option<f64>,
    cycles_to_double: Option<f64>,
    damping_ratio: Option<f64>,
    natural_frequency_s: f64,
    frequency_parameter: Option<f64>,
    #[serde(flatten)]
    in_tau: Option<ModeTauJson>,
}

/// A mode's rates in 1/τ and times in τ.
#[derive(Serialize)]
struct ModeTauJson {
    re: f64,
    im: f64,
    period: Option<f64>,
    time_to_half: Option<f64>,
    time_to_double: Option<f64>,
    natural_frequency: f64,
}

impl ModeJson {
    fn new(m: &Mode, tau: Option<f64>) -> Self {
        ModeJson {
            name: m.name,
            origin: m.origin,
            re_s: m.re,
            im_s: m.im,
            period_s: m.period,
            time_to_half_s: m.time_to_half,
            time_to_double_s: m.time_to_double,
            cycles_to_half: m.cycles_to_half,
            cycles_to_double: m.cycles_to_double,
            damping_ratio: m.damping_ratio,
            natural_frequency_s: m.natural_frequency,
            frequency_parameter: m.frequency_parameter,
            in_tau: tau.map(|t| ModeTauJson {
                re: m.re * t,
                im: m.im * t,
                period: m.period.map(|p| p / t),
                time_to_half: m.time_to_half.map(|p| p / t),
                time_to_double: m.time_to_double.map(|p| p / t),
                natural_frequency: m.natural_frequency * t,
            }),
        }
    }
}

#[derive(Serialize)]
struct CriteriaJson<'a> {
    one_cycle_standard_met: bool,
    verdict: Verdict,
    mil_f_8785c: &'a FlyingQualities,
    /// From the set in the report's notation (with a reference).
    short_period_approximation: Option<&'a ShortPeriodApproximation>,
    damping_standard: Option<&'a DampingStandard>,
}

/// The set in the report's notation, and what eq (4) could not hold.
#[derive(Serialize)]
struct ReportJson<'a> {
    derivatives: &'a Derivatives,
    tau_s: f64,
    reference: &'a Reference,
    exact: bool,
    dropped: &'a Dropped,
}

impl<'a> ReportJson<'a> {
    fn new(r: &'a InReportNotation) -> Self {
        ReportJson {
            derivatives: &r.equivalent.derivatives,
            tau_s: r.equivalent.tau,
            reference: &r.reference,
            exact: r.equivalent.is_exact(),
            dropped: &r.equivalent.dropped,
        }
    }
}

#[derive(Serialize)]
struct AnalysisJson<'a> {
    model: &'a DimensionalModel,
    /// The same set in stability axes (body-axis sets only).
    #[serde(skip_serializing_if = "Option::is_none")]
    stability_axes: Option<&'a DimensionalModel>,
    polynomial: &'static str,
    coefficients: &'a Quartic,
    routh_discriminant: f64,
    stable: bool,
    roots: [RootJson; 4],
    modes: Vec<ModeJson>,
    tau_s: Option<f64>,
    criteria: CriteriaJson<'a>,
    report: Option<ReportJson<'a>>,
}

/// The polynomial the coefficients are of, in words.
pub const POLYNOMIAL: &str = "det(λE − A) = A λ⁴ + B λ³ + C λ² + D λ + E, λ in 1/s (eq D2)";

impl Serialize for DimensionalAnalysis {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let tau = self.tau();
        let report = self.report.as_ref();
        AnalysisJson {
            model: &self.model,
            stability_axes: (self.model.axes == Axes::Body).then_some(&self.stability),
            polynomial: POLYNOMIAL,
            coefficients: &self.quartic,
            routh_discriminant: self.routh.discriminant,
            stable: self.routh.stable,
            roots: self.roots.map(|z| RootJson::new(z, tau)),
            modes: self.modes.iter().map(|m| ModeJson::new(m, tau)).collect(),
            tau_s: tau,
            criteria: CriteriaJson {
                one_cycle_standard_met: self.verdict.is_met(),
                verdict: self.verdict,
                mil_f_8785c: &self.flying_qualities,
                short_period_approximation: report.map(|r| &r.short_period_approximation),
                damping_standard: report.map(|r| &r.damping_standard),
            },
            report: report.map(ReportJson::new),
        }
        .serialize(s)
    }
}
