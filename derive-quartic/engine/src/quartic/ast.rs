//! The typed input of a characteristic-polynomial spec, as the TOML file
//! states it (every position kept, for the diagnostics of [`super::valid`]).

use serde::Deserialize;
use std::collections::BTreeMap;
use toml::Spanned;

/// A whole spec: its symbols, the polynomial variable, the determinant and
/// the coefficients as printed, and the errata to them.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Spec {
    pub title: String,
    pub source: String,
    pub symbols: Vec<Spanned<Symbol>>,
    pub variable: Spanned<Symbol>,
    pub determinant: Spanned<Determinant>,
    pub coefficients: Spanned<BTreeMap<String, Spanned<Coefficient>>>,
    #[serde(default)]
    pub errata: Vec<Spanned<Erratum>>,
}

/// A symbol: an input of the generated functions, or the variable.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Symbol {
    pub name: Spanned<String>,
    pub latex: String,
    pub doc: String,
    #[serde(default)]
    pub positive: bool,
}

/// The determinant whose vanishing is the characteristic equation.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Determinant {
    pub equation: String,
    pub rows: Vec<Spanned<Vec<Spanned<String>>>>,
    #[serde(default)]
    pub notes: Vec<Spanned<Note>>,
}

/// How an entry of the determinant was read from the printed report.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Note {
    pub entry: [usize; 2],
    pub printed: String,
    pub reason: String,
}

/// A coefficient as printed, term by term.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Coefficient {
    pub power: Spanned<i64>,
    pub equation: String,
    pub printed: Vec<Spanned<String>>,
}

/// A printed term that the report got wrong, and its correction.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Erratum {
    pub coefficient: Spanned<String>,
    pub printed: Spanned<String>,
    pub corrected: Spanned<String>,
    pub reason: String,
}
