//! The `delta-stability` program's library: input files, diagnostics and
//! the subcommands. The binary (`src/main.rs`) is a thin clap front end.

pub mod args;
pub mod cmd;
pub mod config;
pub mod diag;
pub mod files;
pub mod fmt;
pub mod input;
pub mod output;
pub mod page;
pub mod page_dimensional;
pub mod plot;
pub mod report;

/// Why a command failed; each kind has its own exit status.
#[derive(Debug, thiserror::Error)]
pub enum Failure {
    /// The input is at fault (a file's content, or a command-line value):
    /// exit status 2. The message names the file, line and field.
    #[error("{0}")]
    Input(#[from] diag::InputError),
    /// A file could not be read or written (missing, not a regular file,
    /// no permission, a full disk, a path through a file): exit status 3.
    /// The message names the path.
    #[error("{0}")]
    Io(#[from] diag::IoError),
}

impl Failure {
    /// Exit status for bad input (also clap's, for a bad command line).
    pub const INPUT_STATUS: u8 = 2;
    /// Exit status for a file that could not be read or written.
    pub const IO_STATUS: u8 = 3;

    /// The exit status of this failure.
    pub fn status(&self) -> u8 {
        match self {
            Failure::Input(_) => Self::INPUT_STATUS,
            Failure::Io(_) => Self::IO_STATUS,
        }
    }
}
