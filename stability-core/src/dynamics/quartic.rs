//! The stability quartic Aλ⁴ + Bλ³ + Cλ² + Dλ + E = 0 (eq 5) and its
//! coefficients' gradient.
//!
//! The coefficients are the exact expansion of the determinant of eq (4),
//! generated at compile time by `derive-quartic` from `specs/quartic.toml`
//! (see `docs/formulas.md`). Eq (6) as printed has three misprints, which
//! the build found and `docs/errata.md` records; the generated functions are
//! the corrected ones.

use crate::Derivatives;
use num_complex::Complex64;
use serde::Serialize;

pub mod reference;

/// The coefficients of the stability quartic, eq (5); λ in units of 1/τ.
/// Serializes as `{"A": …, "B": …, "C": …, "D": …, "E": …}`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Quartic {
    #[serde(rename = "A")]
    pub a: f64,
    #[serde(rename = "B")]
    pub b: f64,
    #[serde(rename = "C")]
    pub c: f64,
    #[serde(rename = "D")]
    pub d: f64,
    #[serde(rename = "E")]
    pub e: f64,
}

impl Quartic {
    /// The quartic of a derivative set (eqs 4–6, corrected).
    #[inline]
    #[must_use]
    pub fn from_derivatives(d: &Derivatives) -> Self {
        Self::from_array(d.quartic_coefficients())
    }

    /// From `[A, B, C, D, E]`.
    #[inline]
    #[must_use]
    pub fn from_array([a, b, c, d, e]: [f64; 5]) -> Self {
        Quartic { a, b, c, d, e }
    }

    /// `[A, B, C, D, E]`.
    #[inline]
    #[must_use]
    pub fn to_array(&self) -> [f64; 5] {
        [self.a, self.b, self.c, self.d, self.e]
    }

    /// P(λ), by Horner's rule.
    #[inline]
    #[must_use]
    pub fn eval(&self, lam: Complex64) -> Complex64 {
        (((lam * self.a + self.b) * lam + self.c) * lam + self.d) * lam + self.e
    }

    /// P′(λ), by Horner's rule.
    #[inline]
    #[must_use]
    pub fn eval_derivative(&self, lam: Complex64) -> Complex64 {
        ((lam * (4.0 * self.a) + 3.0 * self.b) * lam + 2.0 * self.c) * lam + self.d
    }

    /// Whether every coefficient is finite.
    #[must_use]
    pub fn is_finite(&self) -> bool {
        self.to_array().iter().all(|c| c.is_finite())
    }
}

/// ∂[A, B, C, D, E]/∂(each input of [`Derivatives`]), exact (symbolic
/// differentiation of the expansion of eq (4)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QuarticGradient {
    /// Row `i`: the partial derivatives with respect to input `i` of
    /// [`Derivatives::QUARTIC_INPUTS`].
    pub rows: [[f64; 5]; 15],
}

impl QuarticGradient {
    #[inline]
    #[must_use]
    pub fn of(d: &Derivatives) -> Self {
        QuarticGradient {
            rows: d.quartic_gradient(),
        }
    }

    /// The partial derivatives of [A..E] with respect to the input `name`
    /// (`"x_u"`, …, `"i_b"`), if there is such an input.
    #[must_use]
    pub fn by_name(&self, name: &str) -> Option<Quartic> {
        Derivatives::QUARTIC_INPUTS
            .iter()
            .position(|n| *n == name)
            .map(|i| Quartic::from_array(self.rows[i]))
    }
}

/// |A| at or below this is a degenerate quartic (A = 1 − z_ẇ/μ₁, eq 5:
/// the equations of motion have no solution for ẇ).
pub const LEADING_COEFFICIENT_MIN: f64 = 1e-12;
