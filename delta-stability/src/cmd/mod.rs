//! The subcommands.

pub mod analyze;
pub mod convert;
pub mod quartic;
pub mod report;
pub mod report_design;
pub mod response;
pub mod sensitivity;
pub mod size_tail;
pub mod sweep;
pub mod uncertainty;
