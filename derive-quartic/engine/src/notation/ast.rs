//! The typed input of a notation spec, as the TOML file states it (every
//! position kept, for the diagnostics of [`super::valid`]).

use serde::Deserialize;
use std::collections::BTreeMap;
use toml::Spanned;

/// A whole spec: the dimensional quantities, the parameters, the rows (the
/// concepts every notation may define), the notations and the errata to the
/// printed table.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Spec {
    pub title: String,
    pub source: String,
    pub dimensional: Vec<Spanned<Dimensional>>,
    #[serde(default)]
    pub parameters: Vec<Spanned<Parameter>>,
    pub rows: Vec<Spanned<Row>>,
    pub notation: Vec<Spanned<Notation>>,
    #[serde(default)]
    pub errata: Vec<Spanned<Erratum>>,
}

/// A dimensional quantity (X_u, ρ, S, V, …).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Dimensional {
    pub name: Spanned<String>,
    /// Exponents of mass, length and time.
    pub dims: [i32; 3],
    pub doc: String,
}

/// A dimensionless parameter a conversion may need (l_t/c̄).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Parameter {
    pub name: Spanned<String>,
    pub doc: String,
}

/// A row of the table: a concept, and the dimensional quantity it
/// normalises.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Row {
    pub name: Spanned<String>,
    pub primary: Spanned<String>,
    pub doc: String,
}

/// One author's notation: a definition per row it has.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Notation {
    pub name: Spanned<String>,
    pub title: String,
    pub source: String,
    #[serde(default)]
    pub reference: bool,
    pub define: BTreeMap<String, Spanned<Entry>>,
}

/// A notation's quantity of one row: its name, its definition and the
/// printed cell of the table.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Entry {
    pub name: Spanned<String>,
    pub expr: Spanned<String>,
    #[serde(default)]
    pub printed: Option<Spanned<String>>,
    #[serde(default)]
    pub positive: bool,
}

/// A printed cell that the report got wrong, and its correction.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Erratum {
    pub notation: Spanned<String>,
    pub row: Spanned<String>,
    pub printed: Spanned<String>,
    pub corrected: Spanned<String>,
    pub reason: String,
}
