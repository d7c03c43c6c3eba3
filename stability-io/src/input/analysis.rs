//! A derivative file's analysis, checked: every number it would write
//! finite, and each of the library's errors placed at the value at fault
//! (the input most extreme in magnitude, where an overflow has no single
//! cause). What `quartic`, `sensitivity` and the Python package's
//! `quartic()` compute from a file.

use super::dimensional_notation::DimensionalFile;
use super::{DerivativeFile, rows};
use crate::diag::InputError;
use stability_core::Derivatives;
use stability_core::analysis::engineering::Engineering;
use stability_core::analysis::{Analysis, AnalysisError};
use stability_core::criteria::cap::{AirplaneClass, n_alpha_dimensional};
use stability_core::data::dimensional::DimensionalAnalysis;
use stability_core::dynamics::linear::{Control, LinearModel};

/// The message of an analysis whose numbers overflow.
pub const OVERFLOW: &str = "the analysis overflows f64: no result can be written";

impl DerivativeFile {
    /// τ = m/(½ρSV) in seconds, when `[dimensional]` gives it.
    pub fn tau(&self) -> Option<f64> {
        self.dimensional.map(|d| d.tau())
    }

    /// The analysis of the set, every number of it finite, or the error at
    /// the input it arises from.
    pub fn analysis(&self) -> Result<Analysis, InputError> {
        let analysis = Analysis::of(&self.derivatives)
            .map_err(|e| self.error_at(self.blame(&e), e.to_string()))?;
        if !analysis.is_finite() {
            return Err(self.error_at(self.most_extreme_input(), OVERFLOW));
        }
        Ok(analysis)
    }

    /// The analysis and the engineer's outputs from it (damp(), mode
    /// shapes, the short-period frequency requirement of `class`), every
    /// number finite.
    pub fn evaluated(
        &self,
        control: Option<&Control>,
        class: Option<AirplaneClass>,
    ) -> Result<(Analysis, Engineering), InputError> {
        let analysis = self.analysis()?;
        Engineering::of_report(&self.derivatives, &analysis, self.tau(), control, class)
            .map(|engineering| (analysis, engineering))
            .map_err(|_| self.error_at(self.most_extreme_input(), OVERFLOW))
    }

    /// The quartic input most extreme in magnitude, largest or smallest
    /// (the likeliest cause of an overflow: μ₁ = 1e-300 as much as 1e300).
    pub fn most_extreme_input(&self) -> usize {
        let mut best = (0.0, rows::QUARTIC[0]);
        for i in rows::QUARTIC {
            let v = self.report[i].map_or(0.0, f64::abs);
            let extreme = if v > 0.0 { v.log10().abs() } else { 0.0 };
            if extreme > best.0 {
                best = (extreme, i);
            }
        }
        best.1
    }

    /// The row an analysis error is about.
    pub fn blame(&self, e: &AnalysisError) -> usize {
        let named = |name: &str| {
            Derivatives::QUARTIC_INPUTS
                .iter()
                .position(|n| *n == name)
                .map(|k| rows::QUARTIC[k])
        };
        match e {
            AnalysisError::LeadingCoefficientZero { .. } => rows::Z_WDOT,
            AnalysisError::Invalid(e) => {
                named(e.quantity()).unwrap_or_else(|| self.most_extreme_input())
            }
            _ => self.most_extreme_input(),
        }
    }
}

impl DimensionalFile {
    /// The analysis of the set (eq D2: roots in 1/s, modes in seconds) and
    /// the engineer's outputs from its stability-axis form (where the mode
    /// shapes are the ones Etkin & Reid and AVL print): the state matrix
    /// E⁻¹A in seconds, n/α = −Z_w U₀/g. Every number finite.
    pub fn evaluated(
        &self,
        class: Option<AirplaneClass>,
    ) -> Result<(DimensionalAnalysis, Engineering), InputError> {
        let a = self.analysis()?;
        let overflow = || self.error_at(self.most_extreme(), OVERFLOW);
        let finite = a.quartic.is_finite()
            && a.routh.discriminant.is_finite()
            && a.roots.iter().all(|z| z.re.is_finite() && z.im.is_finite());
        if !finite {
            return Err(overflow());
        }
        let st = &a.stability;
        let matrix = st
            .state_matrix()
            .filter(|m| m.iter().all(|v| v.is_finite()))
            .ok_or_else(overflow)?;
        let model = LinearModel::of_dimensional(matrix, None, None, st.trim.speed())
            .with_gravity(st.trim.speed(), st.trim.g);
        let n_alpha = n_alpha_dimensional(st.derivatives.z_w, st.trim.u0, st.trim.g);
        let engineering = Engineering::of_model(model, &a.roots, Some(n_alpha), class);
        Ok((a, engineering))
    }
}
