//! The numerical layer: what the engineering modules above compute with
//! and write their numbers by, knowing nothing of aircraft — the roots of
//! a real quartic ([`roots`]), interpolation with exact slopes
//! ([`interpolation`]), a process-wide table of solutions each computed
//! once ([`memo`]), grids of values ([`grid`]), checks of inputs
//! ([`invalid`]) and numbers in messages ([`display`]).

pub mod display;
pub mod elliptic;
pub mod grid;
pub mod interpolation;
pub mod invalid;
pub mod memo;
pub mod roots;
