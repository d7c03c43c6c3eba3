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
use crate::aero::{AeroError, AeroModel, Coefficients, level_flight_lift};
use crate::analysis::{Analysis, AnalysisError};
use crate::damping::{Damping, DampingError, Theory, WingInput, damping_derivatives, x_q, x_wdot};
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
    /// the supersonic theory (36) over 1 ≤ M ≤ 1.2 by the weight
    /// w = 3x² − 2x³, x = (M − 1)/0.2 (w·(36)'s logarithmic singularity at
    /// M = 1 vanishes with w); (36) beyond; and, past the Mach number where
    /// the leading edge turns sonic (where (36) no longer applies), (36)'s
    /// values at the sonic leading edge, with a warning.
    Faired,
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
    /// aerodynamics once per planform, Mach number and c.g.
    pub fn depends_on_mass(self) -> bool {
        matches!(self, DampingModel::Theory(t) if t.uses_frequency())
    }

    pub fn name(self) -> &'static str {
        match self {
            DampingModel::Theory(t) => t.name(),
            DampingModel::Faired => "faired",
        }
    }

    /// `faired` or a theory's name.
    pub fn parse(s: &str) -> Result<Self, String> {
        if s == "faired" {
            Ok(DampingModel::Faired)
        } else {
            s.parse::<Theory>()
                .map(DampingModel::Theory)
                .map_err(|e| format!("{e}, or `faired` (the default)"))
        }
    }
}

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
    /// theories; `None`: start from §9's √(−m_w/(μ₁i_B)).
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

/// Why a design point has no result.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CaseError {
    #[error("{0}")]
    Input(String),
    #[error("aerodynamic model: {0}")]
    Aero(#[from] AeroError),
    #[error("damping theory: {0}")]
    Damping(#[from] DampingError),
    #[error("{0}")]
    Analysis(#[from] AnalysisError),
}

fn damping_at(case: &Case, wing: &WingInput, omega_bar: Option<f64>) -> Result<Damping, CaseError> {
    let (h, m) = (case.h, case.mach);
    match case.damping {
        DampingModel::Theory(t) => Ok(damping_derivatives(t, wing, h, m, omega_bar)?),
        DampingModel::Faired => {
            let slender = damping_derivatives(Theory::Slender, wing, h, m, None)?;
            if m <= 1.0 {
                return Ok(Damping {
                    theory: Theory::Slender,
                    ..slender
                });
            }
            let cot = 1.0 / wing.sweep_le.tan();
            let sonic = (1.0 + 1.0 / (cot * cot)).sqrt();
            let mut warnings = Warnings::default();
            let m_sup = if m >= sonic {
                warnings.push(Warning::FairedHeldAtSonicEdge { sonic });
                sonic * (1.0 - 1e-9)
            } else {
                m
            };
            let sup = damping_derivatives(Theory::Supersonic, wing, h, m_sup, None)?;
            let x = ((m - 1.0) / 0.2).clamp(0.0, 1.0);
            let w = x * x * (3.0 - 2.0 * x);
            let blend = |a: f64, b: f64| (1.0 - w) * a + w * b;
            let (a, b) = (slender.derivatives, sup.derivatives);
            Ok(Damping {
                theory: Theory::Supersonic,
                derivatives: crate::damping::DampingDerivatives {
                    z_q: blend(a.z_q, b.z_q),
                    z_wdot: blend(a.z_wdot, b.z_wdot),
                    m_q: blend(a.m_q, b.m_q),
                    m_wdot: blend(a.m_wdot, b.m_wdot),
                },
                fig18: sup.fig18,
                warnings,
            })
        }
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
    let analyse = if classical {
        Analysis::of
    } else {
        Analysis::without_classical
    };
    for (name, v) in [
        ("Mach number", case.mach),
        ("c.g. h", case.h),
        ("mu1", case.mu1),
        ("i_b", case.i_b),
        ("C_L·M²", case.cl_m2),
    ] {
        if !v.is_finite() {
            return Err(CaseError::Input(format!(
                "{name} must be a finite number, not {v}"
            )));
        }
    }
    if case.mach <= 0.0 {
        return Err(CaseError::Input(format!(
            "the Mach number must be positive, not {}",
            case.mach
        )));
    }
    if !(case.mu1 > 0.0 && case.i_b > 0.0 && case.cl_m2 > 0.0) {
        return Err(CaseError::Input(
            "mu1, i_b and C_L·M² must be positive".into(),
        ));
    }
    let p = &case.planform;
    let coefficients = case.aero.at(p, case.mach)?;
    let c_l = level_flight_lift(case.cl_m2, case.mach).value;
    let st = stiffness(&coefficients, c_l, case.h);
    let wing = WingInput::from(p);
    let h0 = coefficients.aerodynamic_centre.value;
    let assemble = |d: &Damping| Derivatives {
        x_u: st.x_u,
        x_w: st.x_w,
        x_wdot: x_wdot(h0, case.h, st.dcd_dalpha),
        x_q: x_q(h0, case.h, st.x_w),
        z_u: st.z_u,
        z_w: st.z_w,
        z_wdot: d.derivatives.z_wdot,
        z_q: d.derivatives.z_q,
        m_u: st.m_u,
        m_w: st.m_w,
        m_wdot: d.derivatives.m_wdot,
        m_q: d.derivatives.m_q,
        c_l,
        mu1: case.mu1,
        i_b: case.i_b,
    };
    let uses_frequency = matches!(case.damping, DampingModel::Theory(t) if t.uses_frequency());
    let mut frequency = None;
    let (damping, derivatives, analysis) = if uses_frequency {
        let start = case.omega_bar.unwrap_or_else(|| {
            if st.m_w < 0.0 {
                (-st.m_w / (case.mu1 * case.i_b)).sqrt()
            } else {
                0.1
            }
        });
        let run = |w: f64| -> Result<(Damping, Derivatives, Analysis), CaseError> {
            let d = damping_at(case, &wing, Some(w))?;
            let der = assemble(&d);
            let a = analyse(&der)?;
            Ok((d, der, a))
        };
        let first = run(start)?;
        let cycles = |a: &Analysis| a.modes.short_period().and_then(|m| m.cycles_to_half);
        let mut w = start;
        let mut current = first.clone();
        let mut iterations = 0;
        let mut ok = !case.iterate_frequency;
        if case.iterate_frequency {
            for _ in 0..200 {
                let Some(sp) = current.2.modes.short_period() else {
                    break;
                };
                let target = sp.im / case.mu1;
                if !(target > 0.0 && target.is_finite()) {
                    break;
                }
                iterations += 1;
                // under-relaxed fixed point (the map can overshoot)
                let next = 0.5 * (w + target);
                if (next - w).abs() <= 1e-12 * w {
                    ok = true;
                    break;
                }
                match run(next) {
                    Ok(r) => {
                        w = next;
                        current = r;
                    }
                    Err(_) => break,
                }
            }
        }
        frequency = Some(FrequencyIteration {
            initial: start,
            converged: w,
            iterations,
            converged_ok: ok,
            cycles_to_half_initial: cycles(&first.2),
            cycles_to_half_converged: cycles(&current.2),
            m_thetadot_initial: first.0.derivatives.m_thetadot(),
            m_thetadot_converged: current.0.derivatives.m_thetadot(),
        });
        current
    } else {
        let d = damping_at(case, &wing, case.omega_bar)?;
        let der = assemble(&d);
        let a = analyse(&der)?;
        (d, der, a)
    };
    let mut warnings = damping.warnings;
    if let Some(f) = &frequency
        && !f.converged_ok
    {
        warnings.push(Warning::FrequencyNotConverged {
            iterations: f.iterations,
            last: f.converged,
        });
    }
    Ok(CaseResult {
        coefficients,
        c_l,
        stiffness: st,
        damping,
        derivatives,
        analysis,
        frequency,
        warnings,
    })
}
