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
use crate::Derivatives;
use crate::data::json::{CharacteristicJson, CriteriaJson};
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
    #[serde(flatten)]
    characteristic: CharacteristicJson<'a>,
    criteria: CriteriaJson<'a>,
    report: Option<ReportJson<'a>>,
}

/// The polynomial the coefficients are of, in words.
pub const POLYNOMIAL: &str = "det(λE − A) = A λ⁴ + B λ³ + C λ² + D λ + E, λ in 1/s (eq D2)";

impl Serialize for DimensionalAnalysis {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let time = self.timebase();
        let report = self.report.as_ref();
        AnalysisJson {
            model: &self.model,
            stability_axes: (self.model.axes == Axes::Body).then_some(&self.stability),
            polynomial: POLYNOMIAL,
            characteristic: CharacteristicJson::new(self, time),
            criteria: CriteriaJson::new(self, time).with_report(
                report.map(|r| &r.short_period_approximation),
                report.map(|r| &r.damping_standard),
            ),
            report: report.map(ReportJson::new),
        }
        .serialize(s)
    }
}
