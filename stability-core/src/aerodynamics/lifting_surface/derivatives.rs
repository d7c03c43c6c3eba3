//! From one [`Solution`] to the report's derivatives about any c.g., by
//! axis transfer (no new solve).
//!
//! Pitch about h (flight path fixed) is incidence plus rate:
//! θ[1 + iω̄(x − x_a)/c̄] = θ[(1 − iω̄h) + iω̄(x − x̄)/c̄], and a moment about
//! h is the moment about h = 0 plus h·C_L. Taking in-phase parts, and
//! quadrature parts divided by ω̄:
//! - C_Lα = ℓ_α, H₀ = −μ_α/ℓ_α (C_mα(h) = μ_α + hℓ_α = (h − H₀)C_Lα);
//! - z_w = −(C_Lα + C_D), m_w = (h − H₀)(C_Lα + C_D) (eqs 12, 14, 25);
//! - z_ẇ = −ℓ_α̇, m_ẇ = μ_α̇ + hℓ_α̇;
//! - z_q = −(ℓ_q − hℓ_α), m_q = μ_q − hμ_α − h²ℓ_α + hℓ_q;
//! - z_θ̇ = z_q + z_ẇ, m_θ̇ = m_q + m_ẇ (the quadrature parts of the pitch
//!   response over ω̄; the note's z_δ, m_φ̇ …).
//!
//! The ω̄² terms of the pitch response's in-phase part (the q̇ derivatives)
//! are not in the report's set and are not returned.

use super::{LiftingSurfaceError, Solution, Steady};
use crate::derivatives::DampingDerivatives;
use serde::Serialize;

/// The derivatives of one solve at one c.g., in the report's notation.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LiftingSurfaceDerivatives {
    /// C_Lα(ω̄), per radian: the in-phase lift of the plunge.
    pub lift_slope: f64,
    /// H₀, fraction of the M.A.C. aft of its leading edge.
    pub aerodynamic_centre: f64,
    pub z_w: f64,
    pub m_w: f64,
    pub z_wdot: f64,
    pub m_wdot: f64,
    pub z_q: f64,
    pub m_q: f64,
    pub z_thetadot: f64,
    pub m_thetadot: f64,
}

impl LiftingSurfaceDerivatives {
    /// The damping four, as `damping` gives them for the other theories.
    pub fn damping(&self) -> DampingDerivatives {
        DampingDerivatives {
            z_q: self.z_q,
            z_wdot: self.z_wdot,
            m_q: self.m_q,
            m_wdot: self.m_wdot,
        }
    }
}

/// What the lattice's extrapolation combines number by number
/// ([`super::Extrapolation`]).
pub(crate) trait Extrapolate: Sized {
    /// a·self + b·other, number by number.
    fn combine(&self, other: &Self, a: f64, b: f64) -> Self;

    /// Itself if every number is finite, or the error.
    fn checked(self) -> Result<Self, LiftingSurfaceError>;

    /// Richardson's extrapolation (8X_N − 6X_{N/2} + X_{N/4})/3 of each
    /// number, from the solutions of N, N/2 and N/4 boxes per strip.
    fn richardson(&self, half: &Self, quarter: &Self) -> Self {
        self.combine(half, 8.0 / 3.0, -2.0)
            .combine(quarter, 1.0, 1.0 / 3.0)
    }
}

impl Extrapolate for Solution {
    fn checked(self) -> Result<Solution, LiftingSurfaceError> {
        Solution::checked(self)
    }

    fn combine(&self, other: &Solution, a: f64, b: f64) -> Solution {
        let c = |x: f64, y: f64| a * x + b * y;
        Solution {
            mach: self.mach,
            omega_bar: self.omega_bar,
            lift_alpha: c(self.lift_alpha, other.lift_alpha),
            moment_alpha: c(self.moment_alpha, other.moment_alpha),
            lift_alphadot: c(self.lift_alphadot, other.lift_alphadot),
            moment_alphadot: c(self.moment_alphadot, other.moment_alphadot),
            lift_q: c(self.lift_q, other.lift_q),
            moment_q: c(self.moment_q, other.moment_q),
        }
    }
}

impl Extrapolate for Steady {
    /// The solution checked; the rates by [`super::Lattice::solve_steady`].
    fn checked(self) -> Result<Steady, LiftingSurfaceError> {
        Ok(self)
    }

    fn combine(&self, other: &Steady, a: f64, b: f64) -> Steady {
        let c = |x: f64, y: f64| a * x + b * y;
        Steady {
            solution: self.solution.combine(&other.solution, a, b),
            d_lift_alpha: c(self.d_lift_alpha, other.d_lift_alpha),
            d_moment_alpha: c(self.d_moment_alpha, other.d_moment_alpha),
            d_lift_q: c(self.d_lift_q, other.d_lift_q),
            d_moment_q: c(self.d_moment_q, other.d_moment_q),
        }
    }
}

impl Steady {
    /// C_Lα and dC_Lα/dM (steady).
    pub fn lift_slope(&self) -> (f64, f64) {
        (self.solution.lift_alpha, self.d_lift_alpha)
    }

    /// H₀ = −μ_α/ℓ_α and dH₀/dM = −(μ_α′ℓ_α − μ_αℓ_α′)/ℓ_α² (steady).
    pub fn aerodynamic_centre(&self) -> (f64, f64) {
        let (l, m) = (self.solution.lift_alpha, self.solution.moment_alpha);
        let d = -(self.d_moment_alpha * l - m * self.d_lift_alpha) / (l * l);
        (-m / l, d)
    }
}

impl Solution {
    /// A solution whose every number is finite, or the error.
    pub(super) fn checked(s: Solution) -> Result<Solution, LiftingSurfaceError> {
        let all = [
            s.lift_alpha,
            s.moment_alpha,
            s.lift_alphadot,
            s.moment_alphadot,
            s.lift_q,
            s.moment_q,
        ];
        if all.iter().all(|v| v.is_finite()) && s.lift_alpha != 0.0 {
            Ok(s)
        } else {
            Err(LiftingSurfaceError::NotFinite {
                mach: s.mach,
                omega_bar: s.omega_bar,
            })
        }
    }

    /// C_Lα(ω̄), the in-phase lift slope.
    pub fn lift_slope(&self) -> f64 {
        self.lift_alpha
    }

    /// H₀, the aerodynamic centre of the in-phase lift (fraction of the
    /// M.A.C. aft of its leading edge).
    pub fn aerodynamic_centre(&self) -> f64 {
        -self.moment_alpha / self.lift_alpha
    }

    /// The derivatives about c.g. `h` with drag coefficient `c_d` (eq 25's
    /// C_D in z_w and m_w). Allocation-free; errors only for non-finite
    /// input.
    pub fn derivatives(
        &self,
        h: f64,
        c_d: f64,
    ) -> Result<LiftingSurfaceDerivatives, LiftingSurfaceError> {
        crate::numerics::invalid::finite("the c.g. position h", h)?;
        crate::numerics::invalid::finite("the drag coefficient C_D", c_d)?;
        let a = self.lift_alpha;
        let h0 = self.aerodynamic_centre();
        let z_wdot = -self.lift_alphadot;
        let m_wdot = self.moment_alphadot + h * self.lift_alphadot;
        let z_q = -(self.lift_q - h * a);
        let m_q = self.moment_q - h * self.moment_alpha - h * h * a + h * self.lift_q;
        Ok(LiftingSurfaceDerivatives {
            lift_slope: a,
            aerodynamic_centre: h0,
            z_w: -(a + c_d),
            m_w: (h - h0) * (a + c_d),
            z_wdot,
            m_wdot,
            z_q,
            m_q,
            z_thetadot: z_q + z_wdot,
            m_thetadot: m_q + m_wdot,
        })
    }
}
