//! The symbolic engine behind `derive-quartic`.
//!
//! A formula lives once, in a spec file, in the report's own form. This crate
//! reads such a spec ([`quartic`]), parses every expression with syn into an
//! exact Laurent polynomial ([`expr`], [`poly`]), expands the determinant,
//! checks the printed coefficients against it term by term, differentiates
//! them, and emits flat, allocation-free Rust ([`codegen`], [`expand`]).
//! [`render`] writes the same polynomials for people (text and LaTeX).
//!
//! The proc-macro crate `derive-quartic` and `cargo xtask regen` both call
//! it, so the generated code and the reviewed snapshots cannot drift apart.

pub mod codegen;
pub mod diag;
pub mod docs;
pub mod expand;
pub mod expr;
pub mod notation;
pub mod poly;
pub mod quartic;
pub mod render;

pub use diag::{Diagnostic, Diagnostics, SourceFile};
pub use quartic::QuarticModel;
