//! The validated form of a characteristic-polynomial spec: every expression
//! parsed and expanded, the determinant expanded, every printed coefficient
//! verified against it (after its declared errata).

use crate::expr::{Symbol, SymbolTable};
use crate::poly::Poly;
pub use crate::spec::Expression;

/// A note on how a determinant entry was read from the printed report.
#[derive(Clone, Debug)]
pub struct Reading {
    /// 1-based row and column.
    pub entry: [usize; 2],
    pub printed: String,
    pub reason: String,
    pub line: usize,
}

/// The determinant whose vanishing is the characteristic equation.
#[derive(Clone, Debug)]
pub struct Determinant {
    pub equation: String,
    pub entries: Vec<Vec<Expression>>,
    pub readings: Vec<Reading>,
    /// The determinant, expanded exactly.
    pub expansion: Poly,
}

/// An erratum: a printed term of a coefficient, and what it should be.
#[derive(Clone, Debug)]
pub struct Erratum {
    pub coefficient: String,
    /// Index of the corrected term in the coefficient's printed terms.
    pub term: usize,
    pub printed: Expression,
    pub corrected: Expression,
    pub reason: String,
}

impl Erratum {
    /// printed − corrected: what the misprint adds to the coefficient.
    pub fn difference(&self) -> Poly {
        self.printed.poly.sub(&self.corrected.poly)
    }
}

/// A coefficient of the characteristic polynomial.
#[derive(Clone, Debug)]
pub struct Coefficient {
    /// The report's name, e.g. `B`.
    pub name: String,
    /// The power of the variable it multiplies.
    pub power: usize,
    pub equation: String,
    /// The terms as printed.
    pub printed: Vec<Expression>,
    /// The errata declared against this coefficient.
    pub errata: Vec<Erratum>,
    /// The coefficient from the determinant's expansion (= the printed terms
    /// after the errata, verified).
    pub expansion: Poly,
}

impl Coefficient {
    /// The printed terms with the errata applied.
    pub fn corrected_terms(&self) -> Vec<&Expression> {
        self.printed
            .iter()
            .enumerate()
            .map(|(i, t)| {
                self.errata
                    .iter()
                    .find(|e| e.term == i)
                    .map_or(t, |e| &e.corrected)
            })
            .collect()
    }

    /// The sum of the terms exactly as printed (errata not applied).
    pub fn printed_sum(&self, n: usize) -> Poly {
        self.printed
            .iter()
            .fold(Poly::zero(n), |acc, t| acc.add(&t.poly))
    }
}

/// A verified characteristic-polynomial spec (the quartic of eq (4), or
/// any other determinant of any degree).
#[derive(Clone, Debug)]
pub struct QuarticModel {
    pub file: String,
    pub title: String,
    pub source: String,
    /// Inputs in spec order, then the variable last.
    pub table: SymbolTable,
    pub determinant: Determinant,
    /// Ordered by descending power.
    pub coefficients: Vec<Coefficient>,
}

impl QuarticModel {
    /// Id of the polynomial variable (λ).
    pub fn variable(&self) -> usize {
        self.table.len() - 1
    }

    /// The variable's symbol.
    pub fn variable_symbol(&self) -> &Symbol {
        self.table.get(self.variable())
    }

    /// The inputs of the generated functions (all symbols but the variable).
    pub fn inputs(&self) -> &[Symbol] {
        &self.table.symbols[..self.table.len() - 1]
    }

    /// `A·λ^4 + B·λ^3 + …` with the spec's names, `·` and `^` written by
    /// `times` and `power`.
    pub fn polynomial(&self, times: &str) -> Vec<String> {
        let var = &self.variable_symbol().name;
        self.coefficients
            .iter()
            .map(|c| match c.power {
                0 => c.name.clone(),
                1 => format!("{}{times}{var}", c.name),
                p => format!("{}{times}{var}^{p}", c.name),
            })
            .collect()
    }

    /// The coefficients' names, highest power first, comma-separated.
    pub fn coefficient_names(&self) -> String {
        self.coefficients
            .iter()
            .map(|c| c.name.as_str())
            .collect::<Vec<_>>()
            .join(", ")
    }
}
