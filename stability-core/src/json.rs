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
//! The key names are an interface (scripts depend on them): `tests/json.rs`
//! pins them, and the values, against the command line's output as it was
//! assembled by hand.

use crate::analysis::{Analysis, ClassicalCheck};
use crate::case::{Case, CaseResult};
use crate::criteria::{
    DampingStandard, FlyingQualities, Margins, ShortPeriodApproximation, Verdict,
};
use crate::modes::Mode;
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

/// The analysis object, shared by [`Timed`] and [`CaseView`] (which adds
/// the margins to `criteria`).
#[derive(Serialize)]
struct AnalysisJson<'a> {
    coefficients: &'a Quartic,
    routh_discriminant: f64,
    stable: bool,
    roots: [RootJson; 4],
    modes: ModesJson<'a>,
    tau_s: Option<f64>,
    criteria: CriteriaJson<'a>,
    classical_eq7: &'a Option<ClassicalCheck>,
}

impl<'a> AnalysisJson<'a> {
    fn new(a: &'a Analysis, tau: Option<f64>, margins: Option<Margins>) -> Self {
        AnalysisJson {
            coefficients: &a.quartic,
            routh_discriminant: a.routh.discriminant,
            stable: a.routh.stable,
            roots: a.roots.map(|z| RootJson::new(z, tau)),
            modes: ModesJson {
                modes: &a.modes,
                tau,
            },
            tau_s: tau,
            criteria: CriteriaJson {
                one_cycle_standard_met: a.verdict.is_met(),
                verdict: a.verdict,
                short_period_approximation: &a.short_period_approximation,
                damping_standard: &a.damping_standard,
                mil_f_8785c: a.flying_qualities(tau),
                margins,
            },
            classical_eq7: &a.classical,
        }
    }
}

/// A root, `{re, im}` in 1/τ, and `{re_s, im_s}` in 1/s when τ is known.
#[derive(Serialize)]
struct RootJson {
    re: f64,
    im: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    re_s: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    im_s: Option<f64>,
}

impl RootJson {
    fn new(z: Complex64, tau: Option<f64>) -> Self {
        RootJson {
            re: z.re,
            im: z.im,
            re_s: tau.map(|t| z.re / t),
            im_s: tau.map(|t| z.im / t),
        }
    }
}

struct ModesJson<'a> {
    modes: &'a [Mode],
    tau: Option<f64>,
}

impl Serialize for ModesJson<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(self.modes.iter().map(|m| m.timed(self.tau)))
    }
}

/// A mode with τ (s): its own keys (τ units) and, when τ is known, the
/// same times in seconds under `_s` names.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct TimedMode<'a> {
    #[serde(flatten)]
    pub mode: &'a Mode,
    #[serde(flatten)]
    pub seconds: Option<ModeSecondsJson>,
}

/// A mode's times in seconds and rates in 1/s, named as in the JSON.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ModeSecondsJson {
    pub period_s: Option<f64>,
    pub time_to_half_s: Option<f64>,
    pub time_to_double_s: Option<f64>,
    pub re_s: f64,
    pub im_s: f64,
    pub natural_frequency_s: f64,
}

impl Mode {
    /// This mode with τ (s), for JSON.
    pub fn timed(&self, tau: Option<f64>) -> TimedMode<'_> {
        TimedMode {
            mode: self,
            seconds: tau.map(|t| {
                let s = self.in_seconds(t);
                ModeSecondsJson {
                    period_s: s.period,
                    time_to_half_s: s.time_to_half,
                    time_to_double_s: s.time_to_double,
                    re_s: s.re,
                    im_s: s.im,
                    natural_frequency_s: s.natural_frequency,
                }
            }),
        }
    }
}

#[derive(Serialize)]
struct CriteriaJson<'a> {
    one_cycle_standard_met: bool,
    verdict: Verdict,
    short_period_approximation: &'a ShortPeriodApproximation,
    damping_standard: &'a DampingStandard,
    mil_f_8785c: FlyingQualities,
    #[serde(skip_serializing_if = "Option::is_none")]
    margins: Option<Margins>,
}

/// A design point's result with its case: serializes as the
/// `analyze --json` object (less the command's own `file`).
#[derive(Debug, Clone, Copy)]
pub struct CaseView<'a> {
    pub case: &'a Case,
    pub result: &'a CaseResult,
    /// τ = m/(½ρSV) in seconds, when the flight condition is physical
    /// ([`crate::flight`]): the modes then carry their `_s` keys too.
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
        let margins = Margins::of(
            &r.analysis.quartic,
            &r.derivatives,
            r.coefficients.lift_slope.value,
        );
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
            analysis: AnalysisJson::new(&r.analysis, self.tau, Some(margins)),
            warnings: &r.warnings,
        }
        .serialize(s)
    }
}

#[derive(Serialize)]
struct CaseJson<'a> {
    case: CaseKeys,
    aerodynamics: &'a crate::aero::Coefficients,
    derivatives: &'a Derivatives,
    damping: DampingJson<'a>,
    #[serde(flatten)]
    analysis: AnalysisJson<'a>,
    warnings: &'a crate::warnings::Warnings,
}

#[derive(Serialize)]
struct DampingJson<'a> {
    theory: &'static str,
    equations: &'static str,
    z_thetadot: f64,
    m_thetadot: f64,
    fig18: &'a Option<crate::damping::Fig18>,
    frequency: &'a Option<crate::case::FrequencyIteration>,
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
