//! Lifting-surface theory for a flat wing in harmonic pitching and plunging
//! motion at subsonic speeds: the doublet-lattice method, giving the
//! stiffness pair (lift slope, aerodynamic centre) and the damping
//! derivatives of §7 in the report's notation, for any straight-tapered
//! wing ([`Trapezoid`], which a [`crate::geometry::Planform`] converts to).
//!
//! The note bases its subsonic damping on lifting-surface theory
//! (Multhopp–Garner, Lehrian's vortex lattice, §7); this module is that
//! theory in its modern form:
//!
//! - E. Albano and W.P. Rodden, "A doublet-lattice method for calculating
//!   lift distributions on oscillating surfaces in subsonic flows",
//!   AIAA J. 7(2), 1969, pp. 279–285: boxes with a pressure doublet line at
//!   the quarter chord and a collocation point at three-quarters;
//! - the steady part from horseshoe vortices (a vortex lattice) with the
//!   Prandtl–Glauert factor, plus the oscillatory increment of the kernel
//!   (M.T. Landahl, AIAA J. 5(5), 1967) integrated across each line by the
//!   quartic approximation of W.P. Rodden, P.F. Taylor and S.C. McIntosh,
//!   "Further refinement of the subsonic doublet-lattice method",
//!   J. Aircraft 35(5), 1998, pp. 720–727;
//! - the kernel's integral I₁ by R.N. Desmarais' approximation (AIAA Paper
//!   82-0687, 1982; default) or I.E. Laschka's (1963).
//!
//! Symmetric motions only: the half wing and the mirror image of each box.
//!
//! # Use
//! ```
//! use stability_core::geometry::{Planform, Size, Trapezoid};
//! use stability_core::aerodynamics::lifting_surface::{Lattice, LatticeSpec};
//! let delta = Planform::new(60f64.to_radians(), 0.0, Size::RootChord(1.0)).unwrap();
//! let wing = Trapezoid::from(&delta);
//! let lattice = Lattice::new(&wing, LatticeSpec::for_wing(&wing)).unwrap();
//! let solution = lattice.solve(0.5, 0.0).unwrap(); // M = 0.5, quasi-steady
//! for h in [0.0, 0.25, 0.5] {
//!     let d = solution.derivatives(h, 0.01).unwrap(); // C_D = 0.01
//!     assert!(d.m_q < 0.0 && d.z_w < 0.0);
//! }
//! ```
//! A sweep over c.g., μ₁ and i_B solves once per (planform, Mach, ω̄) and
//! calls [`Solution::derivatives`] for each point (allocation-free, a few
//! dozen flops); a frequency iteration calls [`Lattice::solve`] with each
//! new ω̄ on the same lattice.
//!
//! # In the program
//! The damping theories `lifting-surface` and `lifting-surface-frequency`
//! and the aerodynamic model `lifting-surface` (`crate::aerodynamics::damping`,
//! `crate::aerodynamics::models::aero`) take their solutions from [`store`], which solves each
//! (solver, wing shape, M, p̄) once per process; the aerodynamic model's lift slope
//! and aerodynamic centre, with the exact Mach derivatives eqs (27)–(29)
//! need, from [`Lattice::solve_steady`]; a sweep's frequency iterations
//! interpolate between the frequency nodes ([`Harmonic::Interpolated`]).
//!
//! # Layers
//! [`solution`] (what every solver gives, and the one [`solution::Key`]) ←
//! the solvers: the doublet lattice ([`kernel`], [`doublet_line`],
//! [`Lattice`]), the near-sonic extrapolation ([`near_sonic()`]), the Mach box
//! ([`mach_box`]) and the multi-surface lattice ([`configuration`]) ←
//! [`frequency`] (interpolation in ω̄) and [`precomputed`] (solutions
//! solved ahead of time, as a file) ← [`store`] (each solve once) ←
//! [`mach_table`] (the Mach box tabulated in M) ← [`mach_range`] (which
//! solver at which Mach number).
//!
//! # Notation
//! The report's (§3): forces on ½ρSV, moments with a further c̄ (the
//! M.A.C.), rates per qc̄/V and α̇c̄/V, ω̄ = ωc̄/V, h the c.g. aft of the
//! M.A.C.'s leading edge in M.A.C.; z = −lift, m nose-up.
//!
//! # Limits
//! Linear, inviscid, thin, flat wing: no thickness, camber, separation or
//! leading-edge vortex (the lift of a slender delta at incidence is
//! underestimated once its vortices form). Subsonic, 0 ≤ M < 1; towards
//! M = 1 the Prandtl–Glauert stretching needs ever more chordwise boxes
//! and linear theory itself fails (the note: "invalid near M₁ = 1.0").
//! [`LatticeSpec::for_mach`] refines the lattice chordwise above M = 0.9,
//! and [`near_sonic()`] (stored: [`store::near_sonic`]) gives the solution
//! from 0.9 to the sonic point M = 1 at ω̄ > 0, with its accuracy
//! (`docs/lattice-near-sonic.md`).
//! At frequency the lattice needs boxes short against the wavelength,
//! Δx·ω/V ≲ 0.5, and strips narrower than V/ω: the default lattice meets
//! both for ω̄ ≲ 2 on the note's wings. Below ω̄ ≈ 0.1 the harmonic α̇
//! derivatives carry Desmarais' approximation error (up to 1 %): ask for
//! ω̄ = 0 for quasi-steady values, which are exact.

pub mod configuration;
pub(crate) mod derivatives;
pub mod doublet_line;
pub mod frequency;
pub mod kernel;
pub(crate) mod lattice;
pub mod mach_box;
pub mod mach_range;
pub mod mach_table;
pub mod near_sonic;
pub mod precomputed;
pub mod solution;
pub(crate) mod solve;
pub mod store;

pub use crate::geometry::Trapezoid;
pub use derivatives::LiftingSurfaceDerivatives;
pub use doublet_line::LineRule;
pub use frequency::FrequencyTable;
pub use kernel::I1Approximation;
pub use lattice::{Box, Extrapolation, Lattice, LatticeSpec, Spacing};
pub use near_sonic::{near_sonic, sonic_limit};
pub use solution::{ConfigurationSolution, Contribution, ReducedFrequency, Solution, Steady};
pub use store::Harmonic;

/// Below this ω̄ [`Lattice::solve`] returns the quasi-steady limit.
pub const OMEGA_BAR_QUASI_STEADY: f64 = 1e-6;

/// Why the lattice cannot be built or solved.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum LiftingSurfaceError {
    #[error(
        "the doublet lattice is a subsonic theory: it needs 0 ≤ M < 1, not M = {0} (use the supersonic or transonic theories above)"
    )]
    Mach(f64),
    #[error("the frequency parameter ω̄ = ωc̄/V must be finite and ≥ 0 (0: quasi-steady), not {0}")]
    Frequency(f64),
    #[error(
        "a lattice needs at least one strip and a number of chordwise boxes that is a positive multiple of {multiple} (4 for Richardson's extrapolation), not {chordwise} × {spanwise}"
    )]
    Lattice {
        chordwise: usize,
        spanwise: usize,
        multiple: usize,
    },
    #[error("a lattice of {boxes} boxes on the half wing is more than the {max} this solver takes")]
    TooManyBoxes { boxes: usize, max: usize },
    #[error("the lattice's normalwash matrix is singular at M = {mach}, ω̄ = {omega_bar}")]
    Singular { mach: f64, omega_bar: f64 },
    #[error("the lattice's solution at M = {mach}, ω̄ = {omega_bar} is not finite")]
    NotFinite { mach: f64, omega_bar: f64 },
    #[error(transparent)]
    Invalid(#[from] crate::numerics::invalid::Invalid<&'static str>),
    #[error("{0}")]
    Planform(String),
    #[error(
        "near_sonic covers 0.9 ≤ M ≤ 1, not M = {0} (below 0.9 use Lattice::solve with LatticeSpec::for_wing; above 1 the supersonic theories)"
    )]
    NearSonicMach(f64),
    #[error(
        "at M = 1 the quasi-steady α̇ derivatives are infinite (they grow like ln(1/β) as M → 1): give the motion's frequency parameter ω̄ > 0, or a Mach number below 1"
    )]
    SonicQuasiSteady,
    #[error(
        "the lifting-surface methods cover 0 ≤ M ≤ {max}, not M = {0}",
        max = mach_range::MACH_RANGE_MAX
    )]
    MachRange(f64),
    #[error(
        "at M = {mach} the lifting-surface solution comes from the sonic extrapolation (M > 0.99) or the bridge to the Mach box (which starts at M = {first_mach_box:.4}), verified only for ω̄ ≥ {min}, not ω̄ = {omega_bar}: give --omega-bar {min} or more (or use lifting-surface-frequency), a Mach number ≤ 0.99 or ≥ {first_mach_box:.4}, or the faired damping / default aero model",
        min = near_sonic::SONIC_OMEGA_BAR_MIN
    )]
    SonicFrequency {
        mach: f64,
        omega_bar: f64,
        first_mach_box: f64,
    },
    #[error(
        "the steady lifting-surface solution (the aerodynamic model's lift slope and aerodynamic centre) is not available at M = {mach}, between 0.99 and the Mach box's first Mach number {first_mach_box:.4}: its α̇ derivatives are infinite at M = 1 and the sonic extrapolation needs a frequency; use a Mach number ≤ 0.99 or ≥ {first_mach_box:.4}, or the default aero model there"
    )]
    SonicSteady { mach: f64, first_mach_box: f64 },
    #[error(transparent)]
    MachBox(#[from] crate::aerodynamics::lifting_surface::mach_box::MachBoxError),
}
