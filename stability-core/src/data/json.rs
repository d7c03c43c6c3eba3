//! The JSON of the results, from the types: what `delta-stability quartic
//! --json` and `analyze --json` print, key for key.
//!
//! [`Analysis`] serializes itself in units of τ; times in seconds need τ,
//! which only the caller knows (`[dimensional]`, eq: τ = m/(½ρSV)), so
//! [`Analysis::timed`] wraps an analysis with it and adds the `_s` keys
//! (`re_s`, `im_s`, `period_s`, `time_to_half_s`, `time_to_double_s`,
//! `natural_frequency_s`) and `tau_s`. [`CaseResult::view`] does the same
//! for a design point, with its case, aerodynamics, derivatives, damping
//! and margins. Non-finite numbers serialize as `null` (serde_json's rule
//! for f64), as do absent quantities.
//!
//! The key names are an interface (scripts depend on them): `tests/it/json.rs`
//! pins them, and the values, against the command line's output as it was
//! assembled by hand.

use crate::analysis::verdict::Overall;
use crate::analysis::{Analysis, Characteristic, ClassicalCheck, Timebase};
use crate::criteria::{
    DampingStandard, FlyingQualities, Margins, ShortPeriodApproximation, Verdict,
};
use crate::design::case::{Case, CaseResult};
use crate::dynamics::modes::{Mode, ModeName, ModeTimes, Origin};
use crate::{Derivatives, Quartic};
use num_complex::Complex64;
use serde::{Serialize, Serializer};

/// An analysis with the time unit τ (s) its roots and modes are to be read
/// in, when it is known; serializes as the `quartic --json` object (less
/// the command's own `file`, `notation` and `warnings`).
#[derive(Debug, Clone, Copy)]
pub struct Timed<'a> {
    pub analysis: &'a Analysis,
    /// τ = m/(½ρSV) in seconds.
    pub tau: Option<f64>,
}

impl Analysis {
    /// This analysis with τ (s), for JSON with times in seconds too.
    pub fn timed(&self, tau: Option<f64>) -> Timed<'_> {
        Timed {
            analysis: self,
            tau,
        }
    }
}

impl Serialize for Analysis {
    /// As [`Analysis::timed`] with τ unknown.
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.timed(None).serialize(s)
    }
}

impl Serialize for Timed<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        AnalysisJson::new(self.analysis, self.tau, None).serialize(s)
    }
}

/// A report-notation analysis: its characteristic, the criteria with the
/// report's quantities, and eq (7); shared by [`Timed`] and [`CaseView`]
/// (which adds the margins to `criteria`).
#[derive(Serialize)]
struct AnalysisJson<'a> {
    #[serde(flatten)]
    characteristic: CharacteristicJson<'a>,
    criteria: CriteriaJson<'a>,
    classical_eq7: &'a Option<ClassicalCheck>,
}

impl<'a> AnalysisJson<'a> {
    fn new(a: &'a Analysis, tau: Option<f64>, margins: Option<Margins>) -> Self {
        let time = Timebase::Tau(tau);
        AnalysisJson {
            characteristic: CharacteristicJson::new(a, time),
            criteria: CriteriaJson {
                margins,
                ..CriteriaJson::new(a, time).with_report(
                    Some(&a.short_period_approximation),
                    Some(&a.damping_standard),
                )
            },
            classical_eq7: &a.classical,
        }
    }
}

/// A characteristic's keys, whatever the notation: the coefficients,
/// Routh's discriminant and verdict, the roots and modes in their unit and
/// in the other where τ converts them, τ, and the overall verdict.
#[derive(Serialize)]
pub(crate) struct CharacteristicJson<'a> {
    coefficients: &'a Quartic,
    routh_discriminant: f64,
    stable: bool,
    roots: [RootJson; 4],
    modes: Vec<TimedMode>,
    tau_s: Option<f64>,
    /// Every root judged ([`Overall`]): never "meets" with a mode that
    /// grows.
    verdict: Overall,
}

impl<'a> CharacteristicJson<'a> {
    pub(crate) fn new(c: &'a Characteristic, time: Timebase) -> Self {
        CharacteristicJson {
            coefficients: &c.quartic,
            routh_discriminant: c.routh.discriminant,
            stable: c.routh.stable,
            roots: c.roots.map(|z| RootJson::new(z, time)),
            modes: c.modes.iter().map(|m| m.in_timebase(time)).collect(),
            tau_s: time.tau(),
            verdict: Overall::of(c, time),
        }
    }
}

/// A root, `{re, im}` in 1/τ and `{re_s, im_s}` in 1/s, each pair where
/// it is known.
#[derive(Serialize)]
struct RootJson {
    #[serde(skip_serializing_if = "Option::is_none")]
    re: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    im: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    re_s: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    im_s: Option<f64>,
}

impl RootJson {
    fn new(z: Complex64, time: Timebase) -> Self {
        let (tau, seconds) = match time {
            Timebase::Tau(t) => (Some(z), t.map(|t| z / t)),
            Timebase::Seconds(t) => (t.map(|t| z * t), Some(z)),
        };
        RootJson {
            re: tau.map(|z| z.re),
            im: tau.map(|z| z.im),
            re_s: seconds.map(|z| z.re),
            im_s: seconds.map(|z| z.im),
        }
    }
}

/// A mode with its rates and times in 1/τ and τ, and in 1/s and s, each
/// set where it is known (the dimensionless quantities in both).
#[derive(Debug, Clone, Copy, Serialize)]
pub struct TimedMode {
    name: ModeName,
    origin: Option<Origin>,
    #[serde(flatten)]
    tau: Option<ModeTimes>,
    cycles_to_half: Option<f64>,
    cycles_to_double: Option<f64>,
    damping_ratio: Option<f64>,
    frequency_parameter: Option<f64>,
    #[serde(flatten)]
    seconds: Option<InSeconds>,
}

/// A mode's rates in 1/s and times in s: [`ModeTimes`] under the `_s`
/// names of the JSON (`period_s`, `time_to_half_s`, `time_to_double_s`,
/// `re_s`, `im_s`, `natural_frequency_s`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InSeconds(pub ModeTimes);

impl Serialize for InSeconds {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let t = &self.0;
        let mut map = s.serialize_map(Some(6))?;
        map.serialize_entry("period_s", &t.period)?;
        map.serialize_entry("time_to_half_s", &t.time_to_half)?;
        map.serialize_entry("time_to_double_s", &t.time_to_double)?;
        map.serialize_entry("re_s", &t.re)?;
        map.serialize_entry("im_s", &t.im)?;
        map.serialize_entry("natural_frequency_s", &t.natural_frequency)?;
        map.end()
    }
}

impl Mode {
    /// This mode (in 1/τ) with τ (s), for JSON.
    pub fn timed(&self, tau: Option<f64>) -> TimedMode {
        self.in_timebase(Timebase::Tau(tau))
    }

    /// This mode, in the unit of `time`, for JSON: its keys in τ and in
    /// seconds where they are known.
    pub fn in_timebase(&self, time: Timebase) -> TimedMode {
        let own = self.times();
        let (tau, seconds) = match time {
            Timebase::Tau(t) => (Some(own), t.map(|t| own.in_units_of(t))),
            Timebase::Seconds(t) => (t.map(|t| own.in_units_of(1.0 / t)), Some(own)),
        };
        TimedMode {
            name: self.name,
            origin: self.origin,
            tau,
            cycles_to_half: self.cycles_to_half,
            cycles_to_double: self.cycles_to_double,
            damping_ratio: self.damping_ratio,
            frequency_parameter: self.frequency_parameter,
            seconds: seconds.map(InSeconds),
        }
    }
}

/// The criteria: the §8 standard, the MIL-F-8785C levels, and the
/// report's own quantities where the set is in (or has) its notation.
#[derive(Serialize)]
pub(crate) struct CriteriaJson<'a> {
    one_cycle_standard_met: bool,
    verdict: Verdict,
    short_period_approximation: Option<&'a ShortPeriodApproximation>,
    damping_standard: Option<&'a DampingStandard>,
    mil_f_8785c: FlyingQualities,
    #[serde(skip_serializing_if = "Option::is_none")]
    margins: Option<Margins>,
}

impl<'a> CriteriaJson<'a> {
    /// The criteria of `c` in `time`, without the report's quantities.
    pub(crate) fn new(c: &Characteristic, time: Timebase) -> Self {
        // the standard is met only where no mode grows: the overall
        // verdict, not the short period's alone
        let verdict = crate::analysis::verdict::overall(c);
        CriteriaJson {
            one_cycle_standard_met: verdict.is_met(),
            verdict,
            short_period_approximation: None,
            damping_standard: None,
            mil_f_8785c: c.flying_qualities(time),
            margins: None,
        }
    }

    /// With the report's §8–9 quantities of the set.
    pub(crate) fn with_report(
        self,
        approximation: Option<&'a ShortPeriodApproximation>,
        standard: Option<&'a DampingStandard>,
    ) -> Self {
        CriteriaJson {
            short_period_approximation: approximation,
            damping_standard: standard,
            ..self
        }
    }
}

/// A design point's result with its case: serializes as the
/// `analyze --json` object (less the command's own `file`).
#[derive(Debug, Clone, Copy)]
pub struct CaseView<'a> {
    pub case: &'a Case,
    pub result: &'a CaseResult,
    /// τ = m/(½ρSV) in seconds, when the flight condition is physical
    /// ([`crate::design::flight`]): the modes then carry their `_s` keys too.
    pub tau: Option<f64>,
}

impl CaseResult {
    /// This result with the case it came from, for JSON.
    pub fn view<'a>(&'a self, case: &'a Case) -> CaseView<'a> {
        self.view_timed(case, None)
    }

    /// As [`CaseResult::view`], with τ (s) when it is known.
    pub fn view_timed<'a>(&'a self, case: &'a Case, tau: Option<f64>) -> CaseView<'a> {
        CaseView {
            case,
            result: self,
            tau,
        }
    }
}

impl Serialize for CaseView<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let r = self.result;
        let margins = r.margins(self.case);
        CaseJson {
            case: CaseKeys::new(self.case, r),
            aerodynamics: &r.coefficients,
            derivatives: &r.derivatives,
            damping: DampingJson {
                theory: r.damping.theory.name(),
                equations: r.damping.theory.equations(),
                z_thetadot: r.damping.derivatives.z_thetadot(),
                m_thetadot: r.damping.derivatives.m_thetadot(),
                fig18: &r.damping.fig18,
                frequency: &r.frequency,
            },
            derivative_tables: &r.tables,
            analysis: AnalysisJson::new(&r.analysis, self.tau, Some(margins)),
            warnings: &r.warnings,
            configuration: &r.configuration,
        }
        .serialize(s)
    }
}

#[derive(Serialize)]
struct CaseJson<'a> {
    case: CaseKeys,
    aerodynamics: &'a crate::aerodynamics::models::aero::Coefficients,
    derivatives: &'a Derivatives,
    /// What each derivative table did (`[model.tables]`, DATCOM's).
    derivative_tables: &'a [crate::aerodynamics::models::derivative_tables::TableUse],
    damping: DampingJson<'a>,
    #[serde(flatten)]
    analysis: AnalysisJson<'a>,
    warnings: &'a crate::aerodynamics::warnings::Warnings,
    /// Each part's share, with a tailplane, foreplane or body.
    #[serde(skip_serializing_if = "Option::is_none")]
    configuration: &'a Option<crate::design::shares::Shares>,
}

#[derive(Serialize)]
struct DampingJson<'a> {
    theory: &'static str,
    equations: &'static str,
    z_thetadot: f64,
    m_thetadot: f64,
    fig18: &'a Option<crate::aerodynamics::damping::Fig18>,
    frequency: &'a Option<crate::design::case::FrequencyIteration>,
}

/// The `case` object: the planform's derived sizes and the flight
/// condition.
#[derive(Serialize)]
struct CaseKeys {
    sweep_deg: f64,
    taper: f64,
    aspect_ratio: f64,
    mac: f64,
    smc: f64,
    area: f64,
    span: f64,
    mach: f64,
    cg: f64,
    mu1: f64,
    i_b: f64,
    cl_m2: f64,
    c_l: f64,
    damping: &'static str,
}

impl CaseKeys {
    fn new(c: &Case, r: &CaseResult) -> Self {
        let p = &c.planform;
        CaseKeys {
            sweep_deg: p.sweep_le.to_degrees(),
            taper: p.taper,
            aspect_ratio: p.aspect_ratio(),
            mac: p.mac(),
            smc: p.smc(),
            area: p.area(),
            span: p.span(),
            mach: c.mach,
            cg: c.h,
            mu1: c.mu1,
            i_b: c.i_b,
            cl_m2: c.cl_m2,
            c_l: r.c_l,
            damping: c.damping.name(),
        }
    }
}
