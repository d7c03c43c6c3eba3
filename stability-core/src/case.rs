//! A design point of the report's study, whole: a planform at a flight
//! condition, with its aerodynamic model and a damping theory → the
//! derivative set (§5–7) → the quartic, its modes and criteria (§4, §8).
//!
//! Where the damping theory depends on the frequency parameter ω̄ (Mangler's
//! (39)–(40)), ω̄ is iterated to the short-period frequency it produces,
//! ω̄ = s/μ₁ — the consistency the report could not afford ("quasi-static
//! derivatives are used in cases where frequency effects should properly be
//! included", Summary); the result records the starting and converged ω̄
//! and what the iteration changed.

use crate::Derivatives;
use crate::aero::{AeroError, AeroModel, Coefficients, TheoryCoefficients, level_flight_lift};
use crate::analysis::{Analysis, AnalysisError};
use crate::damping::{
    Damping, DampingDerivatives, DampingError, Theory, UnknownTheory, WingInput,
    damping_derivatives, theory_coefficients, x_q, x_wdot,
};
use crate::display::Num;
use crate::geometry::Planform;
use crate::stiffness::{Stiffness, stiffness};
use crate::warnings::{Warning, Warnings};
use serde::Serialize;

/// Which damping derivatives a case uses; serializes as its name.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DampingModel {
    /// One theory, wherever it is asked for (errors outside its domain).
    Theory(Theory),
    /// The theories faired through Mach number, as the report faired its
    /// Figs 19–24: slender-wing theory (37) — identical with Garrick's and
    /// with Mangler's steady sonic theory (38) — up to M = 1; blended into
    /// the supersonic linear theory over 1 ≤ M ≤ 1.2 by the weight
    /// w = 3x² − 2x³, x = (M − 1)/0.2 (w·(36)'s logarithmic singularity at
    /// M = 1 vanishes with w); that theory beyond — (36) while the leading
    /// edge is subsonic, the supersonic-edge theory past the Mach number
    /// where it turns sonic (`supersonic::edge_theory`, continuous there).
    Faired,
    /// The previous slender-wing fairing, `faired-slender`: as
    /// [`DampingModel::Faired`] up to the Mach number where the leading
    /// edge turns sonic, and past it (36)'s values at the sonic leading
    /// edge, held, with a warning.
    FairedSlender,
}

impl Serialize for DampingModel {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.name())
    }
}

impl DampingModel {
    /// Whether the derivatives depend on μ₁ and i_B. They do not, except
    /// through the frequency parameter ω̄ = s/μ₁ of a frequency-dependent
    /// theory: μ₁ and i_B enter the equations of motion (eqs 2, 4), not the
    /// derivatives of §5–7. So a sweep over them need evaluate the
    /// aerodynamics once per planform, Mach number and c.g. (The warnings
    /// may depend on them: `supersonic`'s low-frequency rule is checked at
    /// the short period's ω̄.)
    pub fn depends_on_mass(self) -> bool {
        self.uses_frequency()
    }

    /// Whether the model's derivatives depend on the frequency parameter ω̄
    /// (Mangler's (39)–(40)).
    pub fn uses_frequency(self) -> bool {
        matches!(self, DampingModel::Theory(t) if t.uses_frequency())
    }

    /// Every model: the two fairings, then the theories.
    pub const ALL: [DampingModel; 8] = [
        DampingModel::Faired,
        DampingModel::FairedSlender,
        DampingModel::Theory(Theory::Garrick),
        DampingModel::Theory(Theory::GarnerTaper),
        DampingModel::Theory(Theory::Slender),
        DampingModel::Theory(Theory::Supersonic),
        DampingModel::Theory(Theory::Transonic),
        DampingModel::Theory(Theory::TransonicFrequency),
    ];

    pub fn name(self) -> &'static str {
        match self {
            DampingModel::Theory(t) => t.name(),
            DampingModel::Faired => "faired",
            DampingModel::FairedSlender => "faired-slender",
        }
    }

    /// `faired`, `faired-slender` or a theory's name.
    pub fn parse(s: &str) -> Result<Self, UnknownDampingModel> {
        match s {
            "faired" => Ok(DampingModel::Faired),
            "faired-slender" => Ok(DampingModel::FairedSlender),
            _ => Ok(DampingModel::Theory(s.parse::<Theory>()?)),
        }
    }

    /// The lift slope and aerodynamic centre the model's own theory gives
    /// at `mach`, with their Mach derivatives — taken by
    /// [`aero::Source::Default`](crate::aero::Source::Default) in place of
    /// the default methods (`damping::theory_coefficients`: the supersonic
    /// theory at M > 1). The fairings give none.
    pub fn own_coefficients(
        self,
        planform: &Planform,
        mach: f64,
    ) -> Result<Option<TheoryCoefficients>, DampingError> {
        match self {
            DampingModel::Theory(t) => theory_coefficients(t, planform, mach),
            DampingModel::Faired | DampingModel::FairedSlender => Ok(None),
        }
    }
}

/// A damping model's name that is neither a fairing's nor a theory's.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{0}; or the fairings `faired` (the default) and `faired-slender`")]
pub struct UnknownDampingModel(#[from] pub UnknownTheory);

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
    /// low-frequency rule; `None`: §9's √(−m_w/(μ₁i_B)).
    pub omega_bar: Option<f64>,
    /// Iterate ω̄ to consistency (frequency-dependent theories only).
    pub iterate_frequency: bool,
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
    #[error("{quantity} must be a finite number, not {}", Num(*value))]
    NonFinite { quantity: CaseInput, value: f64 },
    #[error("{quantity} must be positive, not {}", Num(*value))]
    NotPositive { quantity: CaseInput, value: f64 },
    #[error("aerodynamic model: {0}")]
    Aero(#[from] AeroError),
    #[error("damping theory: {0}")]
    Damping(#[from] DampingError),
    #[error("{0}")]
    Analysis(#[from] AnalysisError),
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
            if !value.is_finite() {
                return Err(CaseError::NonFinite { quantity, value });
            }
        }
        for (quantity, value) in inputs {
            if quantity != CaseInput::Cg && value <= 0.0 {
                return Err(CaseError::NotPositive { quantity, value });
            }
        }
        Ok(())
    }
}

/// The faired model's blend of slender-wing theory (37) into supersonic
/// theory (36): w = 3x² − 2x³, x = (M − 1)/[`FAIRING_WIDTH`].
pub const FAIRING_WIDTH: f64 = 0.2;

/// The damping derivatives of the case's model at ω̄ (used by the
/// frequency-dependent theory, and by `supersonic` for its low-frequency
/// warning).
fn damping_at(case: &Case, wing: &WingInput, omega_bar: Option<f64>) -> Result<Damping, CaseError> {
    match case.damping {
        DampingModel::Theory(t) => Ok(damping_derivatives(t, wing, case.h, case.mach, omega_bar)?),
        DampingModel::Faired => faired(wing, case.h, case.mach),
        DampingModel::FairedSlender => faired_slender(wing, case.h, case.mach),
    }
}

/// [`DampingModel::Faired`]: (37) to M = 1, blended into the supersonic
/// linear theory over 1 ≤ M ≤ 1 + [`FAIRING_WIDTH`], that theory beyond.
fn faired(wing: &WingInput, h: f64, m: f64) -> Result<Damping, CaseError> {
    let slender = damping_derivatives(Theory::Slender, wing, h, m, None)?;
    if m <= 1.0 {
        return Ok(slender);
    }
    let sup = damping_derivatives(Theory::Supersonic, wing, h, m, None)?;
    Ok(fair(&slender, &sup, m, Warnings::default()))
}

/// [`DampingModel::FairedSlender`], the previous fairing: (37) to M = 1,
/// blended into (36) over 1 ≤ M ≤ 1 + [`FAIRING_WIDTH`], (36) beyond —
/// held at its values at the sonic leading edge past it.
fn faired_slender(wing: &WingInput, h: f64, m: f64) -> Result<Damping, CaseError> {
    let slender = damping_derivatives(Theory::Slender, wing, h, m, None)?;
    if m <= 1.0 {
        return Ok(slender);
    }
    let sonic = crate::geometry::sonic_leading_edge_mach(wing.sweep_le);
    let mut warnings = Warnings::default();
    let m_sup = if m >= sonic {
        warnings.push(Warning::FairedHeldAtSonicEdge { sonic });
        sonic * (1.0 - 1e-9)
    } else {
        m
    };
    let sup = damping_derivatives(Theory::Supersonic, wing, h, m_sup, None)?;
    Ok(fair(&slender, &sup, m, warnings))
}

/// (37)'s derivatives blended into the supersonic theory's by the weight
/// w = 3x² − 2x³, x = (M − 1)/[`FAIRING_WIDTH`] clamped to [0, 1]; the
/// warnings are the fairing's own (the theories' are not carried).
fn fair(slender: &Damping, sup: &Damping, m: f64, warnings: Warnings) -> Damping {
    let x = ((m - 1.0) / FAIRING_WIDTH).clamp(0.0, 1.0);
    let w = x * x * (3.0 - 2.0 * x);
    let blend = |a: f64, b: f64| (1.0 - w) * a + w * b;
    let (a, b) = (slender.derivatives, sup.derivatives);
    Damping {
        theory: Theory::Supersonic,
        derivatives: DampingDerivatives {
            z_q: blend(a.z_q, b.z_q),
            z_wdot: blend(a.z_wdot, b.z_wdot),
            m_q: blend(a.m_q, b.m_q),
            m_wdot: blend(a.m_wdot, b.m_wdot),
        },
        fig18: sup.fig18,
        warnings,
    }
}

/// Evaluate a design point.
pub fn evaluate(case: &Case) -> Result<CaseResult, CaseError> {
    evaluate_with(case, true)
}

/// As [`evaluate`], without the eq (7) check (`analysis.classical` is
/// `None`): the lean path of `delta-stability sweep`.
pub fn evaluate_point(case: &Case) -> Result<CaseResult, CaseError> {
    evaluate_with(case, false)
}

fn evaluate_with(case: &Case, classical: bool) -> Result<CaseResult, CaseError> {
    case.check()?;
    let point = Point::new(case, classical)?;
    let (run, frequency) = if case.damping.uses_frequency() {
        let (run, f) = point.iterate_frequency()?;
        (run, Some(f))
    } else {
        (point.run(point.omega_bar_estimate())?, None)
    };
    let mut warnings = run.damping.warnings.clone();
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
}

/// The damping derivatives at one ω̄, the derivative set they complete and
/// its analysis.
#[derive(Clone)]
struct Run {
    damping: Damping,
    derivatives: Derivatives,
    analysis: Analysis,
}

impl<'a> Point<'a> {
    fn new(case: &'a Case, classical: bool) -> Result<Self, CaseError> {
        let own = case.damping.own_coefficients(&case.planform, case.mach)?;
        let coefficients = case.aero.at_with(&case.planform, case.mach, own.as_ref())?;
        let c_l = level_flight_lift(case.cl_m2, case.mach).value;
        Ok(Point {
            case,
            coefficients,
            c_l,
            stiffness: stiffness(&coefficients, c_l, case.h),
            wing: WingInput::from(&case.planform),
            classical,
        })
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

    fn run(&self, omega_bar: Option<f64>) -> Result<Run, CaseError> {
        let damping = damping_at(self.case, &self.wing, omega_bar)?;
        let derivatives = self.derivatives(&damping.derivatives);
        let analysis = if self.classical {
            Analysis::of(&derivatives)?
        } else {
            Analysis::without_classical(&derivatives)?
        };
        Ok(Run {
            damping,
            derivatives,
            analysis,
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

    /// ω̄ iterated to the short period it produces, ω̄ = s/μ₁, by an
    /// under-relaxed fixed point (the map can overshoot), from the case's
    /// ω̄ or §9's √(−m_w/(μ₁i_B)).
    fn iterate_frequency(&self) -> Result<(Run, FrequencyIteration), CaseError> {
        let case = self.case;
        let start = self.omega_bar_estimate().unwrap_or(0.1);
        let first = self.run(Some(start))?;
        let (mut w, mut current, mut iterations) = (start, first.clone(), 0);
        let mut ok = !case.iterate_frequency;
        while case.iterate_frequency && iterations < 200 {
            let Some(sp) = current.analysis.modes.short_period() else {
                break;
            };
            let target = sp.im / case.mu1;
            if !(target > 0.0 && target.is_finite()) {
                break;
            }
            iterations += 1;
            let next = 0.5 * (w + target);
            if (next - w).abs() <= 1e-12 * w {
                ok = true;
                break;
            }
            match self.run(Some(next)) {
                Ok(r) => (w, current) = (next, r),
                Err(_) => break,
            }
        }
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
        };
        Ok((current, f))
    }
}
