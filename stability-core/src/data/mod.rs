//! Derivatives in and results out: the appendix's notations and AVL's
//! ([`notation`]), handbook dimensional derivatives ([`dimensional`]),
//! DATCOM's derivatives ([`datcom`]) and the results as the command line
//! prints them ([`json`]).

pub mod datcom;
pub mod dimensional;
pub mod json;
pub mod notation;
