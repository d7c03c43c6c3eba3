//! The subcommands.

pub mod analyze;
pub mod quartic;
pub mod response;
