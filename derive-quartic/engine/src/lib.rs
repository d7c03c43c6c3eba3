//! The symbolic engine behind `derive-quartic`.
//!
//! A formula lives once, in a spec file, in the report's own form. Each kind
//! of spec is its own module, after thiserror's macro crate: typed input
//! (`ast`) → validated model with spanned errors (`valid`, `model`) →
//! emitted Rust (`expand`) and reviewable documents (`docs`):
//! - [`quartic`]: a determinant and the characteristic polynomial's
//!   coefficients as printed (eq (4) and eq (6));
//! - [`notation`]: the notations' definitions and the appendix's table.
//!
//! What the kinds share: [`spec`] (the file, its positions, the TOML
//! reading and the expression parsing), [`diag`] (the diagnostics, collected
//! as serde_derive's `Ctxt` does), [`expr`] and [`poly`] (expressions parsed
//! with syn into exact Laurent polynomials), [`codegen`] (polynomials into
//! flat, allocation-free Rust) and [`render`] (polynomials for people, as
//! text and LaTeX).
//!
//! The proc-macro crate `derive-quartic` and `cargo xtask regen` both call
//! it, so the generated code and the reviewed files cannot drift apart.

pub mod codegen;
pub mod diag;
pub mod docs;
pub mod expr;
pub mod notation;
pub mod poly;
pub mod quartic;
pub mod render;
pub mod spec;

pub use diag::{Diagnostic, Diagnostics, SpecErrors};
pub use notation::NotationModel;
pub use quartic::QuarticModel;
pub use spec::SourceFile;
