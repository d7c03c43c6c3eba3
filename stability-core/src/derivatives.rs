//! The derivative set of the report's notation (§3): the twelve
//! non-dimensional derivatives of eqs (2)–(4) and the three flight
//! parameters that enter the stability quartic.

use crate::numerics::invalid::{self, Invalid};

/// A longitudinal derivative set in the report's notation (§3, eqs 2–4).
///
/// Forces are made non-dimensional on ½ρSV (velocity derivatives), ½ρSc̄
/// (acceleration derivatives) and ½ρSVc̄ (rate derivatives); moments carry a
/// further c̄. Time is measured in the unit τ = m/(½ρSV).
/// Serializes as an object of the fifteen inputs by their names
/// ([`Derivatives::QUARTIC_INPUTS`]).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, derive_quartic::Quartic)]
#[quartic(spec = "specs/quartic.toml")]
pub struct Derivatives {
    /// x_u = X_u/(½ρSV), eq (9).
    pub x_u: f64,
    /// x_w = X_w/(½ρSV), eq (11).
    pub x_w: f64,
    /// x_ẇ = X_ẇ/(½ρSc̄), eq (18).
    pub x_wdot: f64,
    /// x_q = X_q/(½ρSVc̄), eq (15).
    pub x_q: f64,
    /// z_u = Z_u/(½ρSV), eq (10).
    pub z_u: f64,
    /// z_w = Z_w/(½ρSV), eq (12).
    pub z_w: f64,
    /// z_ẇ = Z_ẇ/(½ρSc̄), eq (19).
    pub z_wdot: f64,
    /// z_q = Z_q/(½ρSVc̄), eq (16).
    pub z_q: f64,
    /// m_u = M_u/(½ρSVc̄), eq (13).
    pub m_u: f64,
    /// m_w = M_w/(½ρSVc̄), eq (14).
    pub m_w: f64,
    /// m_ẇ = M_ẇ/(½ρSc̄²), eq (20).
    pub m_wdot: f64,
    /// m_q = M_q/(½ρSVc̄²), eq (17).
    pub m_q: f64,
    /// Lift coefficient of the undisturbed flight, C_L = W/(½ρV²S) (eq 24).
    pub c_l: f64,
    /// Relative density μ₁ = m/(½ρSc̄) (§3).
    pub mu1: f64,
    /// Non-dimensional pitching inertia i_B = B/(mc̄²) (§3).
    pub i_b: f64,
}

/// z_q, z_ẇ, m_q, m_ẇ in the report's notation.
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize)]
pub struct DampingDerivatives {
    pub z_q: f64,
    pub z_wdot: f64,
    pub m_q: f64,
    pub m_wdot: f64,
}

impl DampingDerivatives {
    /// z_θ̇ = z_q + z_ẇ (damping in pitch, force).
    pub fn z_thetadot(&self) -> f64 {
        self.z_q + self.z_wdot
    }

    /// m_θ̇ = m_q + m_ẇ (damping in pitch, moment).
    pub fn m_thetadot(&self) -> f64 {
        self.m_q + self.m_wdot
    }
}

impl Derivatives {
    /// The set's inputs checked: every one finite, μ₁ and i_B positive.
    pub fn check(&self) -> Result<(), Invalid<&'static str>> {
        let values = self.quartic_input_values();
        for (input, value) in Derivatives::QUARTIC_INPUTS.into_iter().zip(values) {
            invalid::finite(input, value)?;
        }
        invalid::positive("mu1", self.mu1)?;
        invalid::positive("i_b", self.i_b)?;
        Ok(())
    }
}
