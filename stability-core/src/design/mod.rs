//! Design points and their studies: a planform (or configuration) at a
//! flight condition with its models ([`case`]), the physical flight
//! condition ([`flight`], [`atmosphere`]), a configuration's parts' shares
//! ([`shares`]) and the tail it needs ([`sizing`]), grids of design points
//! ([`sweep`], [`study`]) and the example aircraft ([`examples`]).

pub mod atmosphere;
pub mod case;
pub mod examples;
pub mod flight;
pub mod shares;
pub mod sizing;
pub mod study;
pub mod sweep;
