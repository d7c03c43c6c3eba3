//! A dimensional set in the report's notation (§3, eqs 9–20), and back.
//!
//! The report non-dimensionalises forces on ½ρSV (speed derivatives), ½ρSc̄
//! (acceleration) and ½ρSVc̄ (rate), moments with a further c̄, and time on
//! τ = m/(½ρSV); μ₁ = m/(½ρSc̄), i_B = B/(mc̄²). Per unit mass and inertia,
//! with c̄ = Vτ/μ₁:
//!
//! ```text
//! x_u = X_u τ     x_w = X_w τ     x_ẇ = X_ẇ μ₁      x_q = X_q μ₁/V      (z alike)
//! m_u = M_u τ i_B c̄   m_w = M_w τ i_B c̄   m_ẇ = M_ẇ μ₁ i_B c̄   m_q = M_q τ i_B
//! C_L = g τ/V (level flight: W = mg = C_L ½ρV²S)
//! ```
//!
//! These need what the derivatives per unit mass do not carry: c̄, μ₁ and
//! i_B ([`Reference`]; from ρ, S, c̄, m, I_y or given directly). The report's
//! eq (4) is level flight in stability axes without u̇ derivatives, so a set
//! is first turned into stability axes
//! ([`DimensionalModel::in_stability_axes`]); what eq (4) cannot hold — the
//! u̇ derivatives the rotation brings in, a flight-path angle — is
//! [`Dropped`] and reported, never silently lost.

use super::{Axes, DimensionalDerivatives, DimensionalModel, Trim, Units};
use crate::Derivatives;
use crate::analysis::Dimensional;
use serde::Serialize;

/// The reference quantities of the conversion to the report's notation:
/// the chord c̄ (ft or m) and the report's μ₁ = m/(½ρSc̄) and i_B =
/// I_y/(mc̄²), which with V give τ = μ₁c̄/V.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Reference {
    pub chord: f64,
    pub mu1: f64,
    pub i_b: f64,
    /// ρ, S, m and I_y when they were given (in the set's units).
    pub physical: Option<Physical>,
}

/// The physical reference quantities, in the set's units.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Physical {
    /// Air density ρ (slug/ft³ or kg/m³).
    pub rho: f64,
    /// Wing area S (ft² or m²).
    pub s: f64,
    /// Mass m (slug or kg).
    pub mass: f64,
    /// Pitching inertia I_y (slug·ft² or kg·m²).
    pub i_y: f64,
}

impl Reference {
    /// From ρ, S, c̄, m and I_y: μ₁ = m/(½ρSc̄), i_B = I_y/(mc̄²).
    pub fn physical(rho: f64, s: f64, chord: f64, mass: f64, i_y: f64) -> Reference {
        Reference {
            chord,
            mu1: mass / (0.5 * rho * s * chord),
            i_b: i_y / (mass * chord * chord),
            physical: Some(Physical { rho, s, mass, i_y }),
        }
    }

    /// From c̄ and the report's μ₁ and i_B directly.
    pub fn nondimensional(chord: f64, mu1: f64, i_b: f64) -> Reference {
        Reference {
            chord,
            mu1,
            i_b,
            physical: None,
        }
    }

    /// The report's unit of time τ = m/(½ρSV) = μ₁c̄/V (s) at speed `v`.
    pub fn tau(&self, v: f64) -> f64 {
        self.mu1 * self.chord / v
    }

    /// The report's `[dimensional]` flight condition (SI) at speed `v` in
    /// `units`, when the physical quantities are known.
    pub fn dimensional(&self, v: f64, units: Units) -> Option<Dimensional> {
        let p = self.physical?;
        let (l, kg) = (units.length(), units.mass());
        Some(Dimensional {
            v: v * l,
            rho: p.rho * kg / (l * l * l),
            s: p.s * l * l,
            chord: self.chord * l,
            mass: p.mass * kg,
        })
    }

    /// I_y in kg·m² when the physical quantities are known.
    pub fn i_y_si(&self, units: Units) -> Option<f64> {
        let p = self.physical?;
        Some(p.i_y * units.mass() * units.length().powi(2))
    }
}

/// What the report's eq (4) cannot hold of a stability-axis set, and the
/// conversion therefore leaves out: the u̇ derivatives and the flight-path
/// angle γ₀ (eq 4 is level flight; C_L is taken as gτ cos γ₀/V and the
/// g sin γ₀ term is lost).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct Dropped {
    pub x_udot: f64,
    pub z_udot: f64,
    pub m_udot: f64,
    /// γ₀ (rad).
    pub gamma0: f64,
}

/// A flight-path angle |γ₀| at or below this (rad, 0.0057°) is level
/// flight to the rounding of printed data (θ₀ and α₀ = atan(W₀/U₀) from
/// rounded numbers): g sin γ₀ is then below 1e-4 g.
pub const GAMMA0_NEGLIGIBLE: f64 = 1e-4;

impl Dropped {
    /// Whether nothing was left out: no u̇ derivative, and level flight to
    /// within [`GAMMA0_NEGLIGIBLE`].
    pub fn is_empty(&self) -> bool {
        [self.x_udot, self.z_udot, self.m_udot]
            .iter()
            .all(|&v| v == 0.0)
            && self.gamma0.abs() <= GAMMA0_NEGLIGIBLE
    }
}

/// A dimensional set in the report's notation.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ReportEquivalent {
    pub derivatives: Derivatives,
    /// τ = μ₁c̄/V (s).
    pub tau: f64,
    /// V (ft/s or m/s).
    pub v: f64,
    /// What eq (4) could not hold (all zero: the conversion is exact).
    pub dropped: Dropped,
}

impl ReportEquivalent {
    /// Whether the report's set has exactly the dimensional set's motion.
    pub fn is_exact(&self) -> bool {
        self.dropped.is_empty()
    }
}

impl DimensionalModel {
    /// This set in the report's notation, after turning it into stability
    /// axes (see the module's documentation for the factors).
    #[must_use]
    pub fn to_report(&self, r: &Reference) -> ReportEquivalent {
        let st = self.in_stability_axes();
        let d = &st.derivatives;
        let v = st.trim.u0;
        let tau = r.tau(v);
        let (mu1, i_b, c) = (r.mu1, r.i_b, r.chord);
        let gamma0 = st.trim.theta0;
        let derivatives = Derivatives {
            x_u: d.x_u * tau,
            x_w: d.x_w * tau,
            x_wdot: d.x_wdot * mu1,
            x_q: d.x_q * mu1 / v,
            z_u: d.z_u * tau,
            z_w: d.z_w * tau,
            z_wdot: d.z_wdot * mu1,
            z_q: d.z_q * mu1 / v,
            m_u: d.m_u * tau * i_b * c,
            m_w: d.m_w * tau * i_b * c,
            m_wdot: d.m_wdot * mu1 * i_b * c,
            m_q: d.m_q * tau * i_b,
            c_l: st.trim.g * tau * gamma0.cos() / v,
            mu1,
            i_b,
        };
        ReportEquivalent {
            derivatives,
            tau,
            v,
            dropped: Dropped {
                x_udot: d.x_udot,
                z_udot: d.z_udot,
                m_udot: d.m_udot,
                gamma0,
            },
        }
    }

    /// A report-notation set at speed `v` (in `units`) with time unit τ (s)
    /// as a dimensional model: stability axes, level flight (θ₀ = W₀ = 0,
    /// U₀ = V), g = C_L V/τ; and the reference (c̄ = Vτ/μ₁, μ₁, i_B) that
    /// converts it back. The inverse of [`DimensionalModel::to_report`].
    pub fn from_report(
        d: &Derivatives,
        v: f64,
        tau: f64,
        units: Units,
    ) -> (DimensionalModel, Reference) {
        let (mu1, i_b) = (d.mu1, d.i_b);
        let c = v * tau / mu1;
        let derivatives = DimensionalDerivatives {
            x_u: d.x_u / tau,
            x_w: d.x_w / tau,
            x_wdot: d.x_wdot / mu1,
            x_udot: 0.0,
            x_q: d.x_q * v / mu1,
            z_u: d.z_u / tau,
            z_w: d.z_w / tau,
            z_wdot: d.z_wdot / mu1,
            z_udot: 0.0,
            z_q: d.z_q * v / mu1,
            m_u: d.m_u / (tau * i_b * c),
            m_w: d.m_w / (tau * i_b * c),
            m_wdot: d.m_wdot / (mu1 * i_b * c),
            m_udot: 0.0,
            m_q: d.m_q / (tau * i_b),
        };
        let model = DimensionalModel {
            axes: Axes::Stability,
            units,
            derivatives,
            trim: Trim {
                u0: v,
                w0: 0.0,
                theta0: 0.0,
                g: d.c_l * v / tau,
            },
        };
        (model, Reference::nondimensional(c, mu1, i_b))
    }

    /// A report-notation set with its `[dimensional]` flight condition (SI)
    /// as a dimensional model, with the physical reference (ρ, S, m, and
    /// I_y = i_B·mc̄²). τ and V are the flight condition's; c̄ = Vτ/μ₁ is
    /// the set's own chord (the flight condition's when they agree).
    pub fn from_report_with(d: &Derivatives, dim: &Dimensional) -> (DimensionalModel, Reference) {
        let (model, r) = DimensionalModel::from_report(d, dim.v, dim.tau(), Units::Si);
        let physical = Physical {
            rho: dim.rho,
            s: dim.s,
            mass: dim.mass,
            i_y: d.i_b * dim.mass * r.chord * r.chord,
        };
        (
            model,
            Reference {
                physical: Some(physical),
                ..r
            },
        )
    }
}
