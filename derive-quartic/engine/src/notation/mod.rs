//! The notation spec kind: how each author normalises each quantity, and the
//! report's appendix table as printed.
//!
//! Every notation defines its quantity of each row (x_u, …, τ, μ, i_B, …)
//! from dimensional quantities (X_u, ρ, S, V, c̄, m, …). The conversion
//! factor between two notations is derived from their definitions
//! ([`mod@derive`]): every dimensional quantity must cancel (else the
//! definitions are inconsistent), and the result is compared with the
//! appendix's printed cell; a disagreement must be declared as an erratum,
//! as for eq (6). Inverting the relations gives the conversions from the
//! report's notation back.
//!
//! Loading a spec reads its typed input ([`ast`]) and validates it into a
//! verified model ([`valid`] → [`model`]); [`expand`] writes one plain
//! function per notation and conversion, and [`docs`] the reviewable
//! documents.

pub mod ast;
pub mod derive;
pub mod docs;
pub mod expand;
pub mod model;
pub mod valid;

pub use model::{Entry, Notation, NotationErratum, NotationModel, Row, SymbolKind};

use crate::diag::SpecErrors;
use crate::spec::{Context, SourceFile};

impl NotationModel {
    /// Load, derive and verify a notation spec. All problems are reported
    /// together.
    pub fn load(file: &SourceFile) -> Result<NotationModel, SpecErrors> {
        let cx = Context::new(file);
        let model = cx
            .read::<ast::Spec>()
            .and_then(|spec| valid::model(&cx, spec));
        cx.finish(model)
    }
}
