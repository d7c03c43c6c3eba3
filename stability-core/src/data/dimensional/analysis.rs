//! The stability of a dimensional set: the general quartic (eq D2) and its
//! roots in 1/s, the modes with their times in seconds (eq 8's cycles to
//! half amplitude are dimensionless), Routh's test (§4), the §8 verdict and
//! the MIL-F-8785C levels; with a [`Reference`], the set in the report's
//! notation and its §8–9 quantities (m_θ̇, eq 41).

use super::{Axes, DimensionalModel, Reference, ReportEquivalent, THETA0_MAX};
use crate::analysis::{AnalysisError, Characteristic, LEADING_COEFFICIENT_MIN, Timebase};
use crate::criteria::{DampingStandard, FlyingQualities, ShortPeriodApproximation};
use crate::numerics::display::Num;
use crate::numerics::invalid::{self, Invalid};

/// Why a dimensional set has no analysis. `input` is the file's name of
/// the value at fault (`X_u`, `U0`, `theta0`, `chord`, …).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DimensionalError {
    #[error(transparent)]
    Invalid(#[from] Invalid<&'static str>),
    #[error(
        "the trim attitude θ₀ = {}° is not within ±89°: the x axis would be (nearly) vertical",
        Num(theta0.to_degrees())
    )]
    Attitude { theta0: f64 },
    #[error(
        "W0 = {} in stability axes, where the x axis is along the trim velocity and W₀ = 0 by definition; body-axis data need axes = \"body\"",
        Num(*w0)
    )]
    StabilityW0 { w0: f64 },
    #[error(
        "det E = (1 − X_u̇)(1 − Z_ẇ) − X_ẇ·Z_u̇ = {} is within {} of zero: the equations have no solution for u̇ and ẇ",
        Num(*a), Num(LEADING_COEFFICIENT_MIN)
    )]
    Singular { a: f64 },
    #[error(
        "A = det E = (1 − X_u̇)(1 − Z_ẇ) − X_ẇ·Z_u̇ = {} is negative (Z_ẇ = {}): A is the mass the heave and surge motion carries in units of the aircraft's ((m − ∂Z/∂ẇ)/m with X_u̇ = X_ẇ = Z_u̇ = 0), so A ≤ 0 says the aerodynamic added mass cancels or exceeds the aircraft's own, which no aircraft has; a table per force (Z_ẇ in kg or slug) typed as per unit mass gives this: divide X and Z by m and M by I_y, or check the sign of Z_ẇ",
        Num(*a), Num(*z_wdot)
    )]
    MassNotPositive { a: f64, z_wdot: f64 },
    #[error(transparent)]
    Analysis(#[from] AnalysisError),
}

impl DimensionalModel {
    /// Every value finite, U₀ and g positive, |θ₀| < 89°, W₀ = 0 in
    /// stability axes.
    pub fn check(&self) -> Result<(), DimensionalError> {
        let names = super::DimensionalDerivatives::NAMES;
        let t = &self.trim;
        let values = self.derivatives.values().into_iter().zip(names);
        let trim = [(t.u0, "U0"), (t.w0, "W0"), (t.theta0, "theta0"), (t.g, "g")];
        for (value, input) in values.chain(trim) {
            invalid::finite(input, value)?;
        }
        invalid::positive("U0", t.u0)?;
        invalid::positive("g", t.g)?;
        if t.theta0.abs() > THETA0_MAX {
            return Err(DimensionalError::Attitude { theta0: t.theta0 });
        }
        if self.axes == Axes::Stability && t.w0 != 0.0 {
            return Err(DimensionalError::StabilityW0 { w0: t.w0 });
        }
        Ok(())
    }
}

impl Reference {
    /// c̄, μ₁ and i_B positive and finite.
    pub fn check(&self) -> Result<(), DimensionalError> {
        for (value, input) in [(self.chord, "chord"), (self.mu1, "mu1"), (self.i_b, "i_b")] {
            invalid::positive(input, value)?;
        }
        Ok(())
    }
}

/// The set in the report's notation and the report's §8–9 quantities of it
/// (eq 41's m_θ̇ and its limit, the short-period approximation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InReportNotation {
    pub equivalent: ReportEquivalent,
    pub reference: Reference,
    pub short_period_approximation: ShortPeriodApproximation,
    pub damping_standard: DampingStandard,
}

/// The stability of a dimensional set: its [`Characteristic`] with roots
/// in 1/s and times in s (the modes' `frequency_parameter` ω̄ = s·c̄/V when
/// a [`Reference`] gives c̄), and the set's own quantities.
#[derive(Debug, Clone, PartialEq)]
pub struct DimensionalAnalysis {
    /// The set as given.
    pub model: DimensionalModel,
    /// The same set in stability axes (the model itself if it is in them).
    pub stability: DimensionalModel,
    /// det(λE − A) = Aλ⁴ + Bλ³ + Cλ² + Dλ + E (eq D2), λ in 1/s, and what
    /// follows from it.
    pub characteristic: Characteristic,
    /// The MIL-F-8785C levels (times in s).
    pub flying_qualities: FlyingQualities,
    /// With a [`Reference`]: the set in the report's notation.
    pub report: Option<InReportNotation>,
}

impl std::ops::Deref for DimensionalAnalysis {
    type Target = Characteristic;
    fn deref(&self) -> &Characteristic {
        &self.characteristic
    }
}

impl DimensionalAnalysis {
    /// Analyse a set, with the reference quantities of the report's
    /// notation when known.
    pub fn of(
        model: &DimensionalModel,
        reference: Option<&Reference>,
    ) -> Result<DimensionalAnalysis, DimensionalError> {
        model.check()?;
        if let Some(r) = reference {
            r.check()?;
        }
        let quartic = model.quartic();
        if quartic.a.abs() <= LEADING_COEFFICIENT_MIN {
            return Err(DimensionalError::Singular { a: quartic.a });
        }
        if quartic.a < 0.0 {
            let z_wdot = model.derivatives.z_wdot;
            return Err(DimensionalError::MassNotPositive {
                a: quartic.a,
                z_wdot,
            });
        }
        let stability = model.in_stability_axes();
        // ω̄ = s·c̄/V: Modes divides s by its "μ₁", here V/c̄.
        let per_chord = reference.map_or(0.0, |r| stability.trim.u0 / r.chord);
        let names = &super::DescriptorSystem::QUARTIC_COEFFICIENTS;
        let characteristic = Characteristic::of(quartic, names, per_chord)?;
        let time = Timebase::Seconds(None);
        Ok(DimensionalAnalysis {
            model: *model,
            stability,
            flying_qualities: characteristic.flying_qualities(time),
            characteristic,
            report: reference.map(|r| in_report_notation(model, r)),
        })
    }

    /// τ (s) of the report's notation, when a reference gives it.
    pub fn tau(&self) -> Option<f64> {
        self.report.map(|r| r.equivalent.tau)
    }

    /// The roots' unit (1/s) and τ when known.
    pub fn timebase(&self) -> Timebase {
        Timebase::Seconds(self.tau())
    }
}

fn in_report_notation(model: &DimensionalModel, r: &Reference) -> InReportNotation {
    let equivalent = model.to_report(r);
    InReportNotation {
        equivalent,
        reference: *r,
        short_period_approximation: ShortPeriodApproximation::of(&equivalent.derivatives),
        damping_standard: DampingStandard::of(&equivalent.derivatives),
    }
}
