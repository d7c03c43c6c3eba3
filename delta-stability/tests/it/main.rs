//! The program's integration tests, one test binary: each module was a
//! test file of its own (each linking the crates, 12 binaries). They run the
//! program as a user runs it ([`common`]), and share the note's study: the
//! library computes it once for the binary ([`common::report`]) and the
//! command writes the whole report once ([`common::note_report`]), for every
//! module that checks them.

mod common;

mod chain;
mod cli;
mod configurations;
mod datcom;
mod design_report;
mod dimensional;
mod engineering;
mod handbook;
mod how_sure;
mod lifting_surface;
mod regressions;
mod report_conclusions;
