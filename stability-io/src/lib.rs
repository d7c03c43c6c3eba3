//! The file formats of `delta-stability`: what every front end (the
//! command line, the Python package, a Rust program) reads and writes.
//!
//! | what | module |
//! | --- | --- |
//! | derivative files in every notation of the appendix, AVL's `.st` output, handbook (dimensional) sets | [`input`] |
//! | design-point configs: planform, flight condition (non-dimensional or physical), model, tables | [`config`] |
//! | the range each value may take | [`limits`] |
//! | errors that name the file, line, column and field; file-system errors | [`diag`] |
//! | reading input files safely (regular files, bounded size, UTF-8) | [`files`] |
//! | the `[control]` table (control derivatives) | [`control`] |
//! | the state-space export: JSON, python-control and MATLAB scripts | [`state_space`] |
//! | the guard every writer of results passes: no value that is not finite | [`finite`] |
//! | the form a result is written in (text, JSON, CSV), chosen once, and the writers of whole results and of records | [`format`](mod@format) |
//! | a sweep's axes, grid and rows, in the columns of one table | [`sweep`] |
//! | figures (curves, bands, lines, labels) as SVG and their data as CSV | [`plot`] |
//!
//! Every reader checks what it reads: each value finite and within its
//! range, every name known (a misspelt one gets the nearest valid name),
//! every error located at the value at fault. The computations are
//! [`stability_core`]'s.

pub mod class;
pub mod config;
pub mod control;
pub mod convert;
pub mod csv;
pub mod design_point;
pub mod diag;
pub mod files;
pub mod finite;
pub mod format;
pub mod input;
pub mod limits;
pub mod plot;
pub mod response;
pub mod state_space;
pub mod sweep;
pub mod uncertainty;
pub mod views;

/// The version the files this crate writes are stamped with (the
/// program's: the crates of the workspace share one version).
pub const VERSION: &str = env!("CARGO_PKG_VERSION");

/// Why reading (or writing) failed; each kind has its own exit status on
/// the command line and its own exception in Python.
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
