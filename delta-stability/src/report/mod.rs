//! The reports' pages: the note's study's ([`html`]; the study itself is
//! [`stability_study`]'s, its figures drawn by [`stability_io::plot`]), a
//! design's own report ([`design`]), and the manifest of what a report
//! wrote ([`manifest`]).
//!
//! Everything here computes; writing the files is `cmd::report`'s.

pub mod design;
pub mod html;
pub mod manifest;
