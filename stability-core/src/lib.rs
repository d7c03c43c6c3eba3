//! Longitudinal (pitch-plane) dynamic stability of aircraft, after
//! W.B. McCarter, *Note on the longitudinal stability characteristics and
//! damping in pitch of delta wings at subsonic, transonic and supersonic
//! speeds*, College of Aeronautics, Cranfield, 1953 ("the report").
//!
//! Equation numbers in this crate's documentation are the report's.
//!
//! The crate is in layers, each folder naming only those below it (no
//! module imports one that imports it back: `cargo xtask modules` checks
//! it), from the numbers up to the study:
//!
//! | layer | the report | modules |
//! | --- | --- | --- |
//! | [`numerics`] | — | roots of the quartic, interpolation, the solve-once table, grids, input checks, numbers in messages |
//! | [`units`], [`geometry`], [`derivatives`] | §2.2, §3 | units and constants; the planform and a configuration's surfaces; the derivative set |
//! | [`aerodynamics`] | §5–7, §10 | the lifting surface (lattice, near-sonic, Mach box) and its store of solutions; the closed-form theories; the damping models; the aerodynamic model |
//! | [`dynamics`] | §3–4, §11 | the quartic (eqs 4–6), modes (eqs 7–8), responses, state space |
//! | [`criteria`] | §4, §8, §9 | Routh, the damping standard, margins, MIL-F-8785C, verdicts |
//! | [`analysis`] | — | a derivative set's analysis, whole, and the engineer's outputs |
//! | [`design`] | §9–10 | design points, flight conditions, configurations' shares and tail sizing, sweeps, the study's grids |
//! | [`uncertainty`] | — | uncertainty propagation and Sobol indices |
//! | [`data`] | appendix | notations, handbook dimensional derivatives, DATCOM, the results as JSON |

pub mod aerodynamics;
pub mod analysis;
pub mod criteria;
pub mod data;
pub mod derivatives;
pub mod design;
pub mod dynamics;
pub mod geometry;
pub mod numerics;
pub mod uncertainty;
pub mod units;

pub use derivatives::Derivatives;
pub use dynamics::quartic::{Quartic, QuarticGradient};

/// The README's example, compiled and run as a doctest.
#[cfg(doctest)]
#[doc = include_str!("../../README.md")]
pub struct ReadmeDoctests;
