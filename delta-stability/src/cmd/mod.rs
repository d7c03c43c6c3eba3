//! The subcommands.

pub mod quartic;
pub mod response;
