//! Longitudinal (pitch-plane) dynamic stability of aircraft, after
//! W.B. McCarter, *Note on the longitudinal stability characteristics and
//! damping in pitch of delta wings at subsonic, transonic and supersonic
//! speeds*, College of Aeronautics, Cranfield, 1953 ("the report").
//!
//! Equation numbers in this crate's documentation are the report's.
//!
//! The modules follow the report's method, planform to response:
//!
//! | the report | module |
//! | --- | --- |
//! | §2.2 the planform | [`geometry`] |
//! | §5–6 aerodynamic coefficients, stiffness derivatives | [`aero`], [`stiffness`] |
//! | §7 the damping derivatives and their theories; the faired model of Figs 19–24 | [`theory`], [`damping`], [`faired`], [`supersonic`] (supersonic leading edges), [`lifting_surface`] (subsonic lifting surface) |
//! | §3 the derivative set; the user's tables of derivatives; DATCOM's derivatives in the report's notation | [`derivatives`], [`derivative_tables`], [`datcom`] |
//! | §3–4, eqs (4)–(6) the stability quartic; its roots | [`quartic`], [`roots`] |
//! | §4, eqs (7)–(8) the modes; the report's own method | [`modes`], [`classical`] |
//! | §4 Routh, §8 the damping standard, §9 margins | [`criteria`] |
//! | the overall verdict: every root judged, never "meets" with a growing mode | [`verdict`] |
//! | a derivative set's analysis; a design point; a grid of them; the study | [`analysis`], [`case`], [`sweep`], [`study`] |
//! | §10 which derivative drives the damping | [`sensitivity`] |
//! | §11 responses | [`response`] |
//! | the appendix's notations | [`notation`] |
//! | the flight condition | [`atmosphere`] (U.S. Standard Atmosphere, 1976), [`flight`] (physical → μ₁, i_B, C_L·M², τ) |
//! | the engineer's outputs | [`linear`] (state space), [`mode_shape`], [`damp`] (modes in seconds), [`cap`] (MIL-F-8785C short-period frequency), [`engineering`] (all of them) |
//! | handbook data: dimensional derivatives, body or stability axes (issue 12) | [`dimensional`] |
//!
//! The data of the note's figures that set one theory beside another
//! (Fig 4, Figs 14–15): [`figures`]; grids of values and their one
//! tolerance: [`grid`].
//!
//! Around them: [`warnings`] (validity limits approached), [`invalid`]
//! (an input that is not finite or not positive), [`json`] (the
//! results as the command line prints them), [`display`] (numbers and
//! quotes in messages), [`examples`] (the example aircraft).

pub mod aero;
pub mod analysis;
pub mod atmosphere;
pub mod cap;
pub mod case;
pub mod classical;
pub mod configuration;
pub mod criteria;
pub mod damp;
pub mod damping;
pub mod datcom;
pub mod derivative_tables;
pub mod derivatives;
pub mod dimensional;
pub mod display;
pub mod engineering;
pub mod examples;
pub mod faired;
pub mod figures;
pub mod flight;
pub mod frozen;
pub mod geometry;
pub mod grid;
pub mod invalid;
pub mod json;
pub mod lifting_surface;
pub mod linear;
pub mod memo;
pub mod mode_shape;
pub mod modes;
pub mod notation;
pub mod quartic;
pub mod response;
pub mod roots;
pub mod sensitivity;
pub mod stiffness;
pub mod study;
pub mod supersonic;
pub mod sweep;
pub mod theory;
pub mod uncertainty;
pub mod units;
pub mod verdict;
pub mod warnings;

pub use derivatives::Derivatives;
pub use quartic::{Quartic, QuarticGradient};

/// The README's example, compiled and run as a doctest.
#[cfg(doctest)]
#[doc = include_str!("../../README.md")]
pub struct ReadmeDoctests;
