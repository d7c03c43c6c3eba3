//! The `delta-stability` program's library: the subcommands, their pages
//! on the terminal, plots and the report. The files are read and written
//! by [`stability_io`], the computations are [`stability_core`]'s; the
//! binary (`src/main.rs`) is a thin clap front end.

pub mod args;
pub mod cmd;
pub mod configuration;
pub mod engineering;
pub mod output;
pub mod overwrite;
pub mod page;
pub mod plot;
pub mod report;
pub mod state_space;

pub use stability_io::Failure;
