//! The validated form of a notation spec: each notation's quantities, the
//! conversion of each to the report's quantity (derived from the
//! definitions, checked against the printed cell) and back.

use crate::expr::{Symbol, SymbolTable};
use crate::poly::Poly;

/// A row of the appendix: a concept every notation may define.
#[derive(Clone, Debug)]
pub struct Row {
    pub name: String,
    /// The dimensional quantity the row normalises.
    pub primary: String,
    pub doc: String,
}

/// A notation's quantity of one row.
#[derive(Clone, Debug)]
pub struct Entry {
    /// The notation's own name for it.
    pub name: String,
    pub define: String,
    pub line: usize,
    /// The appendix's cell: the report's quantity in this notation's terms,
    /// as printed (None where the table has "-").
    pub printed: Option<String>,
    /// An erratum to the printed cell.
    pub erratum: Option<NotationErratum>,
    /// The report's quantity in this notation's names (derived; None where
    /// the report has no such quantity).
    pub to_report: Option<Poly>,
    /// This notation's quantity in the report's names (derived; None where
    /// the report has no such quantity).
    pub from_report: Option<Poly>,
}

/// A printed cell of the appendix that the derivation contradicts.
#[derive(Clone, Debug)]
pub struct NotationErratum {
    pub printed: String,
    pub corrected: String,
    pub reason: String,
    pub line: usize,
}

/// What a symbol of a notation's derived polynomials stands for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SymbolKind {
    /// A dimensional quantity (cancelled from every derived polynomial).
    Dimensional,
    /// The dimensionless parameter of this index.
    Parameter(usize),
    /// This notation's quantity of this row.
    Own(usize),
    /// The report's quantity of this row.
    Report(usize),
}

/// One notation, with everything derived against the report's.
#[derive(Clone, Debug)]
pub struct Notation {
    pub name: String,
    pub title: String,
    pub source: String,
    pub reference: bool,
    /// One entry per row (None: the notation has no such quantity).
    pub entries: Vec<Option<Entry>>,
    /// The symbols of the derived polynomials: the dimensional quantities,
    /// the parameters, this notation's names, then the report's names (as
    /// `report_<name>`).
    pub table: SymbolTable,
    /// What each symbol of `table` stands for.
    pub kinds: Vec<SymbolKind>,
}

/// A verified notation spec.
#[derive(Clone, Debug)]
pub struct NotationModel {
    pub file: String,
    pub title: String,
    pub source: String,
    pub rows: Vec<Row>,
    /// The dimensionless parameters conversions may need (e.g. l_t/c̄).
    pub parameters: Vec<Symbol>,
    pub notations: Vec<Notation>,
    /// The index of the reference notation (the report's).
    pub reference: usize,
}

impl NotationModel {
    /// The reference notation (the report's).
    pub fn reference(&self) -> &Notation {
        &self.notations[self.reference]
    }
}
