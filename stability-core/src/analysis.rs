//! A derivative set's stability, whole: the quartic (eqs 4–6), Routh's test
//! (§4), the roots and modes (eqs 7–8), the short-period approximations and
//! the damping standard (§8).

use crate::criteria::{DampingStandard, Routh, ShortPeriodApproximation};
use crate::modes::Modes;
use crate::roots::{RootsError, solve_quartic};
use crate::{Derivatives, Quartic};
use num_complex::Complex64;
use serde::Serialize;

/// Why a derivative set has no analysis.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum AnalysisError {
    #[error("a derivative or parameter is not a finite number")]
    NonFiniteInput,
    #[error("μ₁ and i_B must be positive (μ₁ = {mu1}, i_B = {i_b})")]
    NonPositiveParameter { mu1: f64, i_b: f64 },
    #[error(
        "A = 1 − z_ẇ/μ₁ = 0 (z_ẇ = μ₁ = {0}): the quartic degenerates to a cubic and the equations of motion have no solution for ẇ"
    )]
    LeadingCoefficientZero(f64),
    #[error("the quartic's coefficients overflow: the derivatives are too large")]
    Overflow,
    #[error("the roots could not be computed: {0}")]
    Roots(#[from] RootsError),
}

/// The flight condition in dimensional form, for times in seconds.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Dimensional {
    /// True airspeed V (m/s).
    pub v: f64,
    /// Air density ρ (kg/m³).
    pub rho: f64,
    /// Wing area S (m²).
    pub s: f64,
    /// The reference chord c̄ of the derivatives and of μ₁ (m).
    pub chord: f64,
    /// Mass m (kg).
    pub mass: f64,
}

impl Dimensional {
    /// The unit of time τ = m/(½ρSV) (s), §3.
    pub fn tau(&self) -> f64 {
        self.mass / (0.5 * self.rho * self.s * self.v)
    }

    /// The relative density these values imply, μ₁ = m/(½ρSc̄), §3.
    pub fn mu1(&self) -> f64 {
        self.mass / (0.5 * self.rho * self.s * self.chord)
    }

    /// The lift coefficient of level flight, W/(½ρV²S), eq (24), with g =
    /// 9.80665 m/s².
    pub fn c_l(&self) -> f64 {
        self.mass * 9.806_65 / (0.5 * self.rho * self.v * self.v * self.s)
    }
}

/// The stability of a derivative set.
#[derive(Debug, Clone, PartialEq)]
pub struct Analysis {
    pub quartic: Quartic,
    pub routh: Routh,
    /// The four roots (units of 1/τ), conjugates adjacent, fastest first.
    pub roots: [Complex64; 4],
    pub modes: Modes,
    pub short_period_approximation: ShortPeriodApproximation,
    pub damping_standard: DampingStandard,
}

impl Analysis {
    /// Analyse a derivative set. A zero root (E = 0) is a neutral mode and
    /// is reported as such; A = 0 is an error.
    pub fn of(d: &Derivatives) -> Result<Analysis, AnalysisError> {
        if !d.quartic_input_values().iter().all(|v| v.is_finite()) {
            return Err(AnalysisError::NonFiniteInput);
        }
        if !(d.mu1 > 0.0 && d.i_b > 0.0) {
            return Err(AnalysisError::NonPositiveParameter {
                mu1: d.mu1,
                i_b: d.i_b,
            });
        }
        let quartic = Quartic::from_derivatives(d);
        if !quartic.is_finite() {
            return Err(AnalysisError::Overflow);
        }
        if quartic.a.abs() <= 1e-12 {
            return Err(AnalysisError::LeadingCoefficientZero(d.mu1));
        }
        let roots = solve_quartic(quartic.to_array())?;
        Ok(Analysis {
            quartic,
            routh: Routh::of(&quartic),
            roots,
            modes: Modes::identify(&roots, d.mu1),
            short_period_approximation: ShortPeriodApproximation::of(d),
            damping_standard: DampingStandard::of(d),
        })
    }
}
