//! `#[derive(Quartic)]`: the stability quartic's coefficients and their
//! gradient, generated at compile time from a declarative spec and verified
//! against the determinant it came from.
//!
//! ```text
//! #[derive(Quartic)]
//! #[quartic(spec = "specs/quartic.toml")]
//! pub struct Derivatives { pub x_u: f64, /* … one f64 field per spec input … */ }
//! ```
//!
//! The spec path is relative to the invoking crate's manifest directory. The
//! macro reads the spec, expands its determinant exactly, compares every
//! printed coefficient with the expansion (after the spec's declared
//! errata), and emits:
//! - `QUARTIC_INPUTS` and `QUARTIC_COEFFICIENTS`, the names in order;
//! - `quartic_coefficients(&self) -> [f64; N]`, highest power first;
//! - `quartic_gradient(&self) -> [[f64; N]; INPUTS]`, exact partial
//!   derivatives, one row per input.
//!
//! Both are `#[inline]`, flat, allocation-free and branch-free, and use
//! nothing from `std`. Any problem in the spec (an unknown symbol, an
//! unparsable expression, a disagreement that no erratum declares, a stale
//! erratum, a missing or duplicate entry) is a compile error naming the spec
//! file, line and entry. The build re-runs when the spec changes.
//!
//! The work is split as in serde_derive: the private module `attr` parses
//! the derive input,
//! `formula_engine::quartic` validates the spec into a model, and
//! `formula_engine::quartic::expand` writes the code.

use proc_macro::TokenStream;
use syn::{DeriveInput, parse_macro_input};

mod attr;

/// See the crate documentation.
#[proc_macro_derive(Quartic, attributes(quartic))]
pub fn derive_quartic(input: TokenStream) -> TokenStream {
    let input = parse_macro_input!(input as DeriveInput);
    expand_quartic(&input)
        .unwrap_or_else(syn::Error::into_compile_error)
        .into()
}

fn expand_quartic(input: &DeriveInput) -> syn::Result<proc_macro2::TokenStream> {
    let target = attr::Target::parse(input)?;
    let spec = attr::read_spec(&target.spec)?;
    let model = formula_engine::QuarticModel::load(&spec.file)
        .map_err(|errors| errors.to_syn_error(&target.spec))?;
    target.check_fields(&model)?;
    let body = formula_engine::quartic::expand::quartic_impl(&model, &input.ident);
    Ok(spec.rerun_when_changed(body))
}

/// `notations!("path/to/notation.toml")`: the conversion tables and
/// functions of a notation spec (see `formula_engine::notation`), verified
/// at compile time: a printed cell of the appendix that disagrees with the
/// factor derived from the definitions, undeclared, is a compile error.
#[proc_macro]
pub fn notations(input: TokenStream) -> TokenStream {
    let lit = parse_macro_input!(input as syn::LitStr);
    expand_notations(&lit)
        .unwrap_or_else(syn::Error::into_compile_error)
        .into()
}

fn expand_notations(lit: &syn::LitStr) -> syn::Result<proc_macro2::TokenStream> {
    let spec = attr::read_spec(lit)?;
    let model = formula_engine::NotationModel::load(&spec.file)
        .map_err(|errors| errors.to_syn_error(lit))?;
    let body = formula_engine::notation::expand::notation_items(&model);
    Ok(spec.rerun_when_changed(body))
}
