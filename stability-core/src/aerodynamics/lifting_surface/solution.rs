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

impl Solution {
    /// Its six numbers: ℓ_α, μ_α, ℓ_α̇, μ_α̇, ℓ_q, μ_q.
    pub fn numbers(&self) -> [f64; 6] {
        [
            self.lift_alpha,
            self.moment_alpha,
            self.lift_alphadot,
            self.moment_alphadot,
            self.lift_q,
            self.moment_q,
        ]
    }
}

/// The quasi-steady [`Solution`] at one Mach number with the exact Mach
/// derivatives of its in-phase numbers (`Lattice::solve_steady`): what the
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

/// The reduced frequency p̄ = pc̄/V of a motion e^{pt}, p = σ + iω: its
/// imaginary part is ω̄ = ωc̄/V, its real part σ̄ = σc̄/V the motion's rate
/// of growth (negative: decay). A steady oscillation has σ̄ = 0 — all the
/// solvers take today ([`ReducedFrequency::harmonic`]); the store of
/// solutions is keyed by the whole p̄ ([`Key`]), so that air forces at a
/// decaying oscillation's own p̄ land beside them.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ReducedFrequency {
    /// σ̄ = σc̄/V.
    pub sigma_bar: f64,
    /// ω̄ = ωc̄/V.
    pub omega_bar: f64,
}

impl ReducedFrequency {
    /// A steady oscillation at ω̄ (σ̄ = 0; ω̄ = 0 is the quasi-steady limit).
    pub fn harmonic(omega_bar: f64) -> ReducedFrequency {
        ReducedFrequency {
            sigma_bar: 0.0,
            omega_bar,
        }
    }

    /// The bits of σ̄ and ω̄, as a key holds them.
    pub fn bits(self) -> [u64; 2] {
        [self.sigma_bar.to_bits(), self.omega_bar.to_bits()]
    }
}

/// Which solver a solution comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Solver {
    /// The doublet lattice on its default boxes ([`super::LatticeSpec::for_wing`]).
    Lattice,
    /// The doublet lattice refined near M = 1 ([`super::LatticeSpec::for_mach`]).
    NearSonicLattice,
    /// The Mach box on its default grid ([`super::mach_box::MachBoxSpec::for_wing`]).
    MachBox,
    /// The multi-surface lattice of a configuration
    /// ([`super::configuration::ConfigurationLattice`]).
    ConfigurationLattice,
}

impl Solver {
    /// Its name in the precomputed solutions' file.
    pub fn name(self) -> &'static str {
        match self {
            Solver::Lattice => "lattice",
            Solver::NearSonicLattice => "near-sonic-lattice",
            Solver::MachBox => "mach-box",
            Solver::ConfigurationLattice => "configuration-lattice",
        }
    }

    /// The solver of this name.
    pub fn parse(s: &str) -> Option<Solver> {
        [
            Solver::Lattice,
            Solver::NearSonicLattice,
            Solver::MachBox,
            Solver::ConfigurationLattice,
        ]
        .into_iter()
        .find(|k| k.name() == s)
    }
}

/// A wing's shape as a key holds it: the bits of the root chord, tip chord,
/// semi-span and leading-edge sweep of its unit wing (root chord 1: the
/// derivatives do not depend on scale).
pub type Shape = [u64; 4];

/// The shape of `wing` ([`Shape`]).
pub fn shape(wing: &crate::geometry::Trapezoid) -> Shape {
    [
        wing.root_chord,
        wing.tip_chord,
        wing.semi_span,
        wing.sweep_le,
    ]
    .map(f64::to_bits)
}

/// The one key of a solution: the solver, the geometry (a wing's
/// [`Shape`], or every number a configuration's lattice depends on), the
/// Mach number and the reduced frequency p̄, as bits.
#[derive(Debug, Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Key<G> {
    pub solver: Solver,
    pub geometry: G,
    pub mach: u64,
    pub frequency: [u64; 2],
}

impl<G> Key<G> {
    /// The key of `geometry`'s solution by `solver` at (`mach`, p̄).
    pub fn new(solver: Solver, geometry: G, mach: f64, p: ReducedFrequency) -> Key<G> {
        Key {
            solver,
            geometry,
            mach: mach.to_bits(),
            frequency: p.bits(),
        }
    }

    pub fn mach(&self) -> f64 {
        f64::from_bits(self.mach)
    }

    pub fn frequency(&self) -> ReducedFrequency {
        ReducedFrequency {
            sigma_bar: f64::from_bits(self.frequency[0]),
            omega_bar: f64::from_bits(self.frequency[1]),
        }
    }
}
