//! The characteristic-polynomial spec kind: a determinant whose expansion in
//! the variable gives the coefficients, and the coefficients as a report
//! printed them, term by term, with declared errata.
//! `stability-core/specs/quartic.toml` (eq (4) and eq (6) of the report) is
//! one such spec; another determinant over other symbols is another spec
//! file of the same kind — nothing here knows eq (4)'s symbols.
//!
//! Loading a spec reads its typed input ([`ast`]), validates it into a
//! verified model ([`valid`] → [`model`]): the determinant expanded exactly,
//! each printed coefficient (after its errata) compared with the expansion
//! term by term. Every disagreement that no erratum declares, and every
//! erratum that no longer corrects anything, is a diagnostic naming the
//! file, line and entry. [`expand`] writes the Rust of the verified model
//! and [`docs`] its reviewable documents.

pub mod ast;
pub mod docs;
pub mod expand;
pub mod model;
pub mod valid;

pub use model::{Coefficient, Determinant, Erratum, Expression, QuarticModel, Reading};

use crate::diag::SpecErrors;
use crate::spec::{Context, SourceFile};

impl QuarticModel {
    /// Load, expand and verify a spec. All problems are reported together.
    pub fn load(file: &SourceFile) -> Result<QuarticModel, SpecErrors> {
        let cx = Context::new(file);
        let model = cx
            .read::<ast::Spec>()
            .and_then(|spec| valid::model(&cx, spec));
        cx.finish(model)
    }
}
