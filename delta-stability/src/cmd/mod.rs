//! The subcommands.

pub mod quartic;
