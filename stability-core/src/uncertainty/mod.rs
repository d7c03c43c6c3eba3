//! Uncertainty propagation: distributions on a design point's
//! inputs — i_B, μ₁, C_L·M², the c.g., the physical flight condition
//! (altitude, mass, I_y), any of the twelve aerodynamic derivatives as a
//! multiplicative or additive error — and on the damping theory itself
//! (model-form uncertainty: theories with weights), sampled by Monte Carlo;
//! for each Mach number the probability of meeting the §8 one-cycle
//! standard (eq 41), of each MIL-F-8785C level and of a divergence, with
//! 95 % intervals; the distributions of cycles to half amplitude and ζ;
//! and first-order and total Sobol indices of every input for the margin
//! Δm_θ̇ (eq 41) and for ζ ([`sobol`]).
//!
//! # Reproducibility
//! Samples are drawn in chunks of [`CHUNK`] rows; chunk k draws from a
//! ChaCha8 generator seeded from the seed, on stream k (Bernstein's ChaCha
//! with a 64-bit stream id: independent streams). Chunks are evaluated in
//! parallel in batches of [`BATCH`] and their sums added in chunk order, so
//! a seed gives the same bits on any number of threads. Every Mach number
//! draws the same samples (common random numbers: the curves through Mach
//! are smooth, their differences sharper than their values). Memory does
//! not grow with the sample count ([`stats::Reservoir`] for quantiles).
//! With [`Sampling::Sobol`] row i is point i of one Owen-scrambled Sobol′
//! sequence seeded from the seed ([`quasi`]), whichever chunk and thread
//! it falls to: the same bits again, with an error nearer 1/N than 1/√N.
//!
//! # Cost
//! Where the model is quasi-steady at the Mach number and only μ₁, i_B
//! (or I_y) and the derivatives are uncertain, the aerodynamics are
//! evaluated once per Mach number and damping theory and a sample costs a
//! quartic and its analysis (as [`crate::design::sweep`] reuses them). Otherwise
//! each sample is a design point ([`crate::design::case::evaluate_point_with`]),
//! the lifting surface's solves interpolated in its cached
//! [`crate::aerodynamics::lifting_surface::FrequencyTable`] (shared by every sample).

pub mod dist;
pub mod quasi;
mod run;
pub mod sobol;
pub mod stats;
mod study;

pub use dist::Dist;
pub use quasi::Sampling;
pub use study::*;
