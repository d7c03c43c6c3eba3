//! The `delta-stability` program's library: the subcommands, their pages
//! on the terminal, and the reports' pages and folders. The files are read
//! and written by [`stability_io`] (figures drawn by [`stability_io::plot`]),
//! the computations are [`stability_core`]'s and, for the note's study,
//! [`stability_study`]'s; the binary (`src/main.rs`) is a thin clap front
//! end.

pub mod args;
pub mod cmd;
pub mod configuration;
pub mod engineering;
pub mod output;
pub mod overwrite;
pub mod page;
pub mod report;
pub mod state_space;

pub use stability_io::Failure;
