//! A design point of the report's study, whole: a planform at a flight
//! condition, with its aerodynamic model and a damping theory → the
//! derivative set (§5–7) → the quartic, its modes and criteria (§4, §8).
//!
//! Where the damping theory depends on the frequency parameter ω̄ (Mangler's
//! (39)–(40), the lifting surface's `lifting-surface-frequency`, the
//! default `faired` model below M = 1.2), ω̄ is
//! iterated to the short-period frequency it produces, ω̄ = s/μ₁ — the
//! consistency the report could not afford ("quasi-static derivatives are
//! used in cases where frequency effects should properly be included",
//! Summary); the result records the starting and converged ω̄ and what the
//! iteration changed ([`FrequencyIteration`]). One iteration, the secant
//! method on the residual s(ω̄)/μ₁ − ω̄, serves every such theory.

use crate::Derivatives;
use crate::aerodynamics::damping::{
    Damping, DampingDerivatives, DampingError, WingInput, x_q, x_wdot,
};
use crate::aerodynamics::lifting_surface::Harmonic;
use crate::aerodynamics::lifting_surface::configuration::ConfigurationError;
use crate::aerodynamics::models::aero::{
    AeroError, AeroModel, Coefficients, Configured, level_flight_lift,
};
use crate::aerodynamics::models::derivative_tables::TableUse;
use crate::aerodynamics::models::stiffness::{Stiffness, stiffness};
use crate::aerodynamics::warnings::{Warning, Warnings};
use crate::analysis::{Analysis, AnalysisError};
use crate::design::shares::Shares;
use crate::dynamics::p_method::{self, AtFrequency};
use crate::geometry::Planform;
use crate::numerics::invalid::{self, Invalid};
use serde::Serialize;

pub use crate::aerodynamics::models::damping_model::{DampingModel, UnknownDampingModel};
pub use crate::dynamics::p_method::FrequencyMethod;

/// A design point.
#[derive(Debug, Clone, PartialEq)]
pub struct Case {
    pub planform: Planform,
    pub mach: f64,
    /// c.g. position h (fraction of the M.A.C. aft of its leading edge).
    pub h: f64,
    /// Relative density μ₁ = m/(½ρSc̄).
    pub mu1: f64,
    /// Pitching inertia i_B = B/(mc̄²).
    pub i_b: f64,
    /// C_L·M² = W/(½ρa²S), constant in level flight (eq 24).
    pub cl_m2: f64,
    pub aero: AeroModel,
    pub damping: DampingModel,
    /// A starting (or fixed) frequency parameter for frequency-dependent
    /// theories, and the short period's ω̄ at which `supersonic` checks its
    /// low-frequency rule; `None`: §9's √(−m_w/(μ₁i_B)). For
    /// `lifting-surface` the ω̄ it is evaluated at; `None`: quasi-steady.
    pub omega_bar: Option<f64>,
    /// Iterate ω̄ to consistency (frequency-dependent theories only).
    pub iterate_frequency: bool,
    /// How the air forces' frequency enters the roots
    /// ([`FrequencyMethod`]: the exact p-method by default; frequency-dependent
    /// theories only, with `iterate_frequency`).
    pub frequency_method: FrequencyMethod,
}

/// The frequency iteration of a frequency-dependent theory.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FrequencyIteration {
    /// ω̄ the derivatives were first evaluated at.
    pub initial: f64,
    /// The consistent ω̄ = s/μ₁ (or the last iterate).
    pub converged: f64,
    pub iterations: usize,
    pub converged_ok: bool,
    /// Short-period cycles to half amplitude at the initial and converged ω̄.
    pub cycles_to_half_initial: Option<f64>,
    pub cycles_to_half_converged: Option<f64>,
    /// m_θ̇ at the initial and converged ω̄.
    pub m_thetadot_initial: f64,
    pub m_thetadot_converged: f64,
    /// How the roots take the frequency: with `p` or `p-k` the analysis's
    /// roots are each at its own frequency, and `cycles_to_half_converged`
    /// above stays the k-method's.
    pub method: FrequencyMethod,
    /// Short-period cycles to half amplitude by `method`.
    pub cycles_to_half: Option<f64>,
}

/// Everything a design point yields.
#[derive(Debug, Clone, PartialEq)]
pub struct CaseResult {
    pub coefficients: Coefficients,
    /// C_L of the level flight at this Mach number (eq 24).
    pub c_l: f64,
    pub stiffness: Stiffness,
    pub damping: Damping,
    pub derivatives: Derivatives,
    pub analysis: Analysis,
    pub frequency: Option<FrequencyIteration>,
    pub warnings: Warnings,
    /// What each derivative table of the aerodynamic model did
    /// ([`crate::aerodynamics::models::derivative_tables`]): the derivatives above are with them.
    pub tables: Vec<TableUse>,
    /// Each part's share when the model has a configuration
    /// ([`AeroModel::configuration`]).
    pub configuration: Option<Shares>,
}

impl CaseResult {
    /// The §9 margins of the design point `case` (whose result this is):
    /// K_n (eq 42) and H_m, the neutral point h_n and the static margin
    /// h_n − h ([`crate::criteria::NeutralPoint`]).
    pub fn margins(&self, case: &Case) -> crate::criteria::Margins {
        crate::criteria::Margins::at_cg(
            &self.analysis.quartic,
            &self.derivatives,
            self.coefficients.lift_slope.value,
            case.h,
        )
    }
}

/// The inputs of a design point that [`evaluate`] checks before use.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CaseInput {
    Mach,
    Cg,
    Mu1,
    IB,
    ClM2,
}

impl CaseInput {
    /// The name of the field in [`Case`] and in configs.
    pub fn name(self) -> &'static str {
        match self {
            CaseInput::Mach => "mach",
            CaseInput::Cg => "cg",
            CaseInput::Mu1 => "mu1",
            CaseInput::IB => "i_b",
            CaseInput::ClM2 => "cl_m2",
        }
    }
}

impl std::fmt::Display for CaseInput {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            CaseInput::Mach => "the Mach number",
            CaseInput::Cg => "the c.g. position h",
            CaseInput::Mu1 => "the relative density μ₁ (mu1)",
            CaseInput::IB => "the pitching inertia i_B (i_b)",
            CaseInput::ClM2 => "C_L·M² (cl_m2, eq 24)",
        })
    }
}

/// Why a design point has no result.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CaseError {
    #[error(transparent)]
    Invalid(#[from] Invalid<CaseInput>),
    #[error("aerodynamic model: {0}")]
    Aero(#[from] AeroError),
    #[error("damping theory: {0}")]
    Damping(#[from] DampingError),
    #[error("{0}")]
    Analysis(#[from] AnalysisError),
    #[error("the configuration's surfaces and body: {0}")]
    Configuration(#[from] ConfigurationError),
}

impl Case {
    /// Check the flight condition: every input finite, and M, μ₁, i_B,
    /// C_L·M² positive.
    pub fn check(&self) -> Result<(), CaseError> {
        let inputs = [
            (CaseInput::Mach, self.mach),
            (CaseInput::Cg, self.h),
            (CaseInput::Mu1, self.mu1),
            (CaseInput::IB, self.i_b),
            (CaseInput::ClM2, self.cl_m2),
        ];
        for (quantity, value) in inputs {
            invalid::finite(quantity, value)?;
        }
        for (quantity, value) in inputs {
            if quantity != CaseInput::Cg {
                invalid::positive(quantity, value)?;
            }
        }
        Ok(())
    }
}

/// The damping derivatives of the case's model at ω̄ (the short period's:
/// the frequency-dependent theories take it, `supersonic` checks its
/// low-frequency warning at it; [`DampingModel::damping`]), the lifting
/// surface's harmonic solutions had as `harmonic` says.
fn damping_at(
    case: &Case,
    wing: &WingInput,
    omega_bar: Option<f64>,
    harmonic: Harmonic,
) -> Result<Damping, CaseError> {
    Ok(case
        .damping
        .damping(wing, case.h, case.mach, omega_bar, case.omega_bar, harmonic)?)
}

/// Evaluate a design point.
pub fn evaluate(case: &Case) -> Result<CaseResult, CaseError> {
    evaluate_with(case, true, Harmonic::Direct)
}

/// As [`evaluate`], the lifting surface's harmonic solutions had as
/// `harmonic` says ([`Harmonic::Interpolated`]: the report's, which
/// evaluates the frequency-dependent models at many design points).
pub fn evaluate_harmonic(case: &Case, harmonic: Harmonic) -> Result<CaseResult, CaseError> {
    evaluate_with(case, true, harmonic)
}

/// As [`evaluate`], without the eq (7) check (`analysis.classical` is
/// `None`): the lean path of `delta-stability sweep`.
pub fn evaluate_point(case: &Case) -> Result<CaseResult, CaseError> {
    evaluate_with(case, false, Harmonic::Direct)
}

/// As [`evaluate_point`], the lifting surface's harmonic solutions had as
/// `harmonic` says: [`Harmonic::Interpolated`] is the library sweep's, whose
/// frequency iterations would otherwise solve the lattice at every iterate
/// of every point.
pub fn evaluate_point_with(case: &Case, harmonic: Harmonic) -> Result<CaseResult, CaseError> {
    evaluate_with(case, false, harmonic)
}

fn evaluate_with(
    case: &Case,
    classical: bool,
    harmonic: Harmonic,
) -> Result<CaseResult, CaseError> {
    case.check()?;
    let point = Point::new(case, classical, harmonic)?;
    let (mut run, frequency) = if case.damping.uses_frequency_at(case.mach) {
        let (run, f) = point.iterate_frequency()?;
        (run, Some(f))
    } else {
        (point.run(point.omega_bar_estimate())?, None)
    };
    let mut frequency = frequency;
    let mut warnings = run.damping.warnings.clone();
    if let Some(f) = frequency.as_mut()
        && f.converged_ok
        && case.iterate_frequency
        && f.method != FrequencyMethod::K
    {
        let (analysis, kept) = point.exact_roots(&run, f.method);
        run.analysis = analysis;
        if kept > 0 {
            warnings.push(Warning::ExactRootNotConverged { kept });
        }
        f.cycles_to_half = run
            .analysis
            .modes
            .short_period()
            .and_then(|m| m.cycles_to_half);
    }
    if let Some(f) = &frequency
        && !f.converged_ok
    {
        warnings.push(Warning::FrequencyNotConverged {
            iterations: f.iterations,
            last: f.converged,
        });
    }
    Ok(CaseResult {
        coefficients: point.coefficients,
        c_l: point.c_l,
        stiffness: point.stiffness,
        damping: run.damping,
        derivatives: run.derivatives,
        analysis: run.analysis,
        frequency,
        warnings,
        tables: run.tables,
        configuration: run.configuration,
    })
}

/// A design point's aerodynamics (§5–6), which do not depend on the
/// damping theory or on ω̄.
struct Point<'a> {
    case: &'a Case,
    coefficients: Coefficients,
    c_l: f64,
    stiffness: Stiffness,
    wing: WingInput,
    classical: bool,
    harmonic: Harmonic,
    /// The wing's own coefficients and the configuration's steady
    /// increment, when the model has a configuration.
    configured: Option<Configured>,
}

/// The damping derivatives at one ω̄, the derivative set they complete and
/// its analysis.
#[derive(Clone)]
struct Run {
    damping: Damping,
    derivatives: Derivatives,
    analysis: Analysis,
    tables: Vec<TableUse>,
    configuration: Option<Shares>,
}

impl<'a> Point<'a> {
    fn new(case: &'a Case, classical: bool, harmonic: Harmonic) -> Result<Self, CaseError> {
        let own = case.damping.own_coefficients(&case.planform, case.mach)?;
        let (coefficients, configured) =
            case.aero
                .at_configured(&case.planform, case.mach, own.as_ref(), case.damping)?;
        let c_l = level_flight_lift(case.cl_m2, case.mach).value;
        Ok(Point {
            case,
            coefficients,
            c_l,
            stiffness: stiffness(&coefficients, c_l, case.h),
            wing: WingInput::from(&case.planform),
            classical,
            harmonic,
            configured,
        })
    }

    /// The configuration's damping increment at ω̄ added to the wing's
    /// `damping`, and the parts' shares; nothing without a configuration.
    fn add_configuration(
        &self,
        damping: &mut Damping,
        omega_bar: Option<f64>,
    ) -> Result<Option<Shares>, CaseError> {
        let Some(configured) = &self.configured else {
            return Ok(None);
        };
        let case = self.case;
        // at the wing's own ω̄, as the model takes it (quasi-steady: 0)
        let model = case.damping;
        let w = model.increment_omega_bar(case.mach, omega_bar, case.omega_bar);
        let at_omega = match case.aero.configuration_for(&case.planform) {
            Some(c) if w > 0.0 => model.increment(&c, case.mach, w, self.harmonic, false)?,
            _ => configured.increment.clone(),
        };
        let d = at_omega
            .solution
            .derivatives(case.h, 0.0)
            .map_err(ConfigurationError::from)?;
        let shares = Shares::new(
            &configured.wing,
            &damping.derivatives,
            &configured.increment,
            &at_omega,
            case.h,
        )
        .map_err(ConfigurationError::from)?;
        if let Some(c) = case.aero.configuration_for(&case.planform)
            && case.mach >= model.supersonic_increment_from(&c)
            && let Some(w) =
                crate::aerodynamics::supersonic::configuration::downwash_warning(&c, case.mach)
        {
            damping.warnings.push(w);
        }
        let own = &mut damping.derivatives;
        own.z_q += d.z_q;
        own.m_q += d.m_q;
        own.z_wdot += d.z_wdot;
        own.m_wdot += d.m_wdot;
        Ok(Some(shares))
    }

    /// The derivative set of eqs (9)–(31) with these damping derivatives.
    fn derivatives(&self, d: &DampingDerivatives) -> Derivatives {
        let (st, h) = (&self.stiffness, self.case.h);
        let h0 = self.coefficients.aerodynamic_centre.value;
        Derivatives {
            x_u: st.x_u,
            x_w: st.x_w,
            x_wdot: x_wdot(h0, h, st.dcd_dalpha),
            x_q: x_q(h0, h, st.x_w),
            z_u: st.z_u,
            z_w: st.z_w,
            z_wdot: d.z_wdot,
            z_q: d.z_q,
            m_u: st.m_u,
            m_w: st.m_w,
            m_wdot: d.m_wdot,
            m_q: d.m_q,
            c_l: self.c_l,
            mu1: self.case.mu1,
            i_b: self.case.i_b,
        }
    }

    /// The aerodynamics at a real ω̄ as the p-method samples them
    /// ([`crate::dynamics::p_method::AtFrequency`]).
    fn at_frequency(&self, omega_bar: f64) -> Result<AtFrequency, CaseError> {
        let (damping, derivatives, _, _) = self.aerodynamics(Some(omega_bar))?;
        Ok(AtFrequency {
            derivatives,
            dz_w: damping.in_phase.dz_w,
            dm_w: damping.in_phase.dm_w,
        })
    }

    /// The analysis of `run` (the k-method's, at the short period's ω̄)
    /// with its roots each solved at its own frequency by `method`
    /// ([`p_method::roots`]), and how many kept the quartic's.
    fn exact_roots(&self, run: &Run, method: FrequencyMethod) -> (Analysis, usize) {
        let mut sample = |w: f64| self.at_frequency(w);
        let mu1 = self.case.mu1;
        let (roots, kept) = p_method::roots(&mut sample, run.analysis.roots, mu1, method);
        (run.analysis.clone().with_roots(roots, mu1), kept)
    }

    /// The damping, the derivative set and the tables' and configuration's
    /// doings at ω̄.
    #[allow(clippy::type_complexity)]
    fn aerodynamics(
        &self,
        omega_bar: Option<f64>,
    ) -> Result<(Damping, Derivatives, Vec<TableUse>, Option<Shares>), CaseError> {
        let mut damping = damping_at(self.case, &self.wing, omega_bar, self.harmonic)?;
        let configuration = self.add_configuration(&mut damping, omega_bar)?;
        let computed = self.derivatives(&damping.derivatives);
        let (derivatives, tables) =
            self.case
                .aero
                .derivatives
                .apply(&computed, self.case.h, self.case.mach)?;
        // the damping four as used, tables included
        damping.derivatives = DampingDerivatives {
            z_q: derivatives.z_q,
            z_wdot: derivatives.z_wdot,
            m_q: derivatives.m_q,
            m_wdot: derivatives.m_wdot,
        };
        Ok((damping, derivatives, tables, configuration))
    }

    fn run(&self, omega_bar: Option<f64>) -> Result<Run, CaseError> {
        let (damping, derivatives, tables, configuration) = self.aerodynamics(omega_bar)?;
        let analysis = if self.classical {
            Analysis::of(&derivatives)?
        } else {
            Analysis::without_classical(&derivatives)?
        };
        Ok(Run {
            damping,
            derivatives,
            analysis,
            tables,
            configuration,
        })
    }

    /// The short period's ω̄ before any iteration: the case's own, else
    /// §9's √(−m_w/(μ₁i_B)) (Fig 32) where m_w < 0.
    fn omega_bar_estimate(&self) -> Option<f64> {
        let case = self.case;
        let m_w = self.stiffness.m_w;
        case.omega_bar
            .or_else(|| (m_w < 0.0).then(|| (-m_w / (case.mu1 * case.i_b)).sqrt()))
    }

    /// ω̄ iterated to the short period it produces, ω̄ = s/μ₁, from the
    /// case's ω̄ or §9's √(−m_w/(μ₁i_B)) ([`Point::converge`]); with
    /// `iterate_frequency` off, the derivatives at the starting ω̄.
    fn iterate_frequency(&self) -> Result<(Run, FrequencyIteration), CaseError> {
        let case = self.case;
        let start = self.omega_bar_estimate().unwrap_or(0.1);
        let first = self.run(Some(start))?;
        let (w, current, iterations, ok) = if case.iterate_frequency {
            self.converge(start, first.clone())
        } else {
            (start, first.clone(), 0, true)
        };
        let cycles = |r: &Run| {
            r.analysis
                .modes
                .short_period()
                .and_then(|m| m.cycles_to_half)
        };
        let f = FrequencyIteration {
            initial: start,
            converged: w,
            iterations,
            converged_ok: ok,
            cycles_to_half_initial: cycles(&first),
            cycles_to_half_converged: cycles(&current),
            m_thetadot_initial: first.damping.derivatives.m_thetadot(),
            m_thetadot_converged: current.damping.derivatives.m_thetadot(),
            method: case.frequency_method,
            cycles_to_half: cycles(&current),
        };
        Ok((current, f))
    }

    /// The fixed point of g(ω̄) = s(ω̄)/μ₁, s the short period's frequency
    /// with the derivatives at ω̄: the residual r = g(ω̄) − ω̄ driven below
    /// 2·10⁻¹²ω̄ by the secant method ([`next_iterate`]), from `start`
    /// (whose run is `first`). Returns the last ω̄ and its run, the
    /// iterations (residuals evaluated) and whether it converged; it stops
    /// unconverged where the short period does not oscillate, where a run
    /// fails, or after [`MAX_FREQUENCY_ITERATIONS`].
    fn converge(&self, start: f64, first: Run) -> (f64, Run, usize, bool) {
        let mu1 = self.case.mu1;
        let (mut w, mut current) = (start, first);
        let mut previous = None;
        for iterations in 1..=MAX_FREQUENCY_ITERATIONS {
            let target = current.analysis.modes.short_period().map(|sp| sp.im / mu1);
            let Some(target) = target.filter(|t| *t > 0.0 && t.is_finite()) else {
                return (w, current, iterations - 1, false);
            };
            let r = target - w;
            if r.abs() <= 2e-12 * w {
                return (w, current, iterations, true);
            }
            let next = next_iterate(w, r, previous);
            previous = Some((w, r));
            match self.run(Some(next)) {
                Ok(run) => (w, current) = (next, run),
                Err(_) => return (w, current, iterations, false),
            }
        }
        (w, current, MAX_FREQUENCY_ITERATIONS, false)
    }
}

/// The frequency iteration gives up after this many residuals.
pub const MAX_FREQUENCY_ITERATIONS: usize = 200;

/// The next ω̄ from the residual r = g(ω̄) − ω̄ at ω̄ = `w` and the previous
/// (ω̄, r): the secant step ω̄ − r/r′, r′ from the two, where r′ is that of
/// a contraction (g′ = r′ + 1 within (−9, 0.75): a step between 0.1|r| and
/// 4|r|) and the step stays positive; else — the first step, or a slope the
/// secant cannot trust — the under-relaxed fixed point ω̄ + r/2, which
/// converges for −3 < g′ < 1 (the map can overshoot). The secant converges
/// superlinearly near the fixed point: the lattice's frequency iteration
/// then needs a handful of solves, not the relaxation's forty.
fn next_iterate(w: f64, r: f64, previous: Option<(f64, f64)>) -> f64 {
    let relaxed = w + 0.5 * r;
    let Some((wp, rp)) = previous else {
        return relaxed;
    };
    let slope = (r - rp) / (w - wp);
    let secant = w - r / slope;
    if slope.is_finite() && slope > -10.0 && slope < -0.25 && secant > 0.0 {
        secant
    } else {
        relaxed
    }
}
