//! The numerical layer: what the engineering modules above compute with
//! and write their numbers by, knowing nothing of aircraft — the roots of
//! a real quartic ([`roots`]), a root of an analytic function
//! ([`complex_root`]), K₀ and K₁ of complex argument ([`bessel`]),
//! interpolation with exact slopes
//! ([`interpolation`]), a process-wide table of solutions each computed
//! once ([`memo`]), grids of values ([`grid`]), checks of inputs
//! ([`invalid`]) and numbers in messages ([`display`]).

pub mod bessel;
pub mod complex_root;
pub mod display;
pub mod elliptic;
pub mod grid;
pub mod interpolation;
pub mod invalid;
pub mod memo;
pub mod roots;
