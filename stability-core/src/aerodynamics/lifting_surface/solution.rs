//! The solution of a wing or a configuration at one Mach number and
//! reduced frequency: the in-phase and quadrature responses to incidence
//! and to pitch rate, moments about the wing M.A.C.'s leading edge, from
//! which every derivative follows about any c.g. by axis transfer
//! ([`Solution::derivatives`]).

use crate::geometry::configuration::Part;
use serde::Serialize;

/// One solve of the lattice: the wing's response to incidence and to pitch
/// rate at one Mach number and ω̄, with moments about the M.A.C.'s leading
/// edge (h = 0). Everything else follows by axis transfer
/// ([`Solution::derivatives`]).
///
/// With the incidence response C_L = α₀(ℓ_α + iω̄ℓ_α̇), C_m = α₀(μ_α + iω̄μ_α̇)
/// and the unit-rate response (normalwash (x − x̄)/c̄) C_L = ℓ_q + i…,
/// C_m = μ_q + i…:
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Solution {
    pub mach: f64,
    /// ω̄ (0: the quasi-steady limit).
    pub omega_bar: f64,
    /// ℓ_α: in-phase lift per unit incidence, C_Lα(ω̄).
    pub lift_alpha: f64,
    /// μ_α: in-phase moment about h = 0 per unit incidence.
    pub moment_alpha: f64,
    /// ℓ_α̇: quadrature lift per unit incidence, divided by ω̄ (per α̇c̄/V).
    pub lift_alphadot: f64,
    /// μ_α̇: quadrature moment (h = 0) per unit incidence, divided by ω̄.
    pub moment_alphadot: f64,
    /// ℓ_q: in-phase lift per unit rate (per qc̄/V, axis at h = 0).
    pub lift_q: f64,
    /// μ_q: in-phase moment (h = 0) per unit rate.
    pub moment_q: f64,
}

/// The quasi-steady [`Solution`] at one Mach number with the exact Mach
/// derivatives of its in-phase numbers ([`Lattice::solve_steady`]): what the
/// aerodynamic model's lift slope and aerodynamic centre, and their d/dM in
/// eqs (27)–(29), come from.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Steady {
    pub solution: Solution,
    /// dℓ_α/dM, dμ_α/dM, dℓ_q/dM, dμ_q/dM.
    pub d_lift_alpha: f64,
    pub d_moment_alpha: f64,
    pub d_lift_q: f64,
    pub d_moment_q: f64,
}

/// One part's share of a configuration's response, in the lattice's
/// [`Solution`] form (on the wing's S and c̄, moments about the wing
/// M.A.C.'s leading edge): the force on that part's boxes (or by that
/// part's theory), interference included. The parts sum to the total.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Contribution {
    pub part: Part,
    pub solution: Solution,
}

/// A configuration's response at one (M, ω̄): the total and each part's.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ConfigurationSolution {
    pub total: Solution,
    pub parts: Vec<Contribution>,
}
