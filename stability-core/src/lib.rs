//! Longitudinal (pitch-plane) dynamic stability of aircraft, after
//! W.B. McCarter, *Note on the longitudinal stability characteristics and
//! damping in pitch of delta wings at subsonic, transonic and supersonic
//! speeds*, College of Aeronautics, Cranfield, 1953 ("the report").
//!
//! Equation numbers in this crate's documentation are the report's.

pub mod aero;
pub mod analysis;
pub mod atmosphere;
pub mod case;
pub mod classical;
pub mod criteria;
pub mod damping;
pub mod derivatives;
pub mod examples;
pub mod geometry;
pub mod json;
pub mod modes;
pub mod notation;
pub mod quartic;
pub mod response;
pub mod roots;
pub mod sensitivity;
pub mod stiffness;
pub mod study;
pub mod supersonic;
pub mod warnings;

pub use derivatives::Derivatives;
pub use quartic::{Quartic, QuarticGradient};

/// The README's example, compiled and run as a doctest.
#[cfg(doctest)]
#[doc = include_str!("../../README.md")]
pub struct ReadmeDoctests;
