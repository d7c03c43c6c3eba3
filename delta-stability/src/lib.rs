//! The `delta-stability` program's library: input files, diagnostics and
//! the subcommands. The binary (`src/main.rs`) is a thin clap front end.

pub mod cmd;
pub mod config;
pub mod diag;
pub mod fmt;
pub mod input;
pub mod output;
pub mod plot;

/// Why a command failed.
#[derive(Debug)]
pub enum Failure {
    /// The input is at fault: exit status 2.
    Input(diag::InputError),
}

impl From<diag::InputError> for Failure {
    fn from(e: diag::InputError) -> Self {
        Failure::Input(e)
    }
}
