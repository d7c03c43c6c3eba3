//! Derivative notations (the report's appendix, and today's): conversions
//! derived from each author's definitions in `specs/notation.toml` and
//! generated at compile time (see `docs/notations.md`; the appendix's
//! misprints are in `docs/errata.md`).
//!
//! Values travel as arrays indexed by [`tables::ROWS`] (`None` where a
//! quantity is absent). Every conversion goes through the report's
//! notation: `to_report` then `from_report`.

use crate::Derivatives;
use crate::numerics::display::Num;

pub mod avl;

/// The generated tables and conversion functions.
pub mod tables {
    derive_quartic::notations!("specs/notation.toml");
}

/// Number of rows.
pub const N_ROWS: usize = tables::ROWS.len();

/// Values of one notation, by row.
pub type Values = [Option<f64>; N_ROWS];

/// Dimensionless parameters (in the order of [`tables::PARAMETERS`]).
pub type Parameters = [f64; tables::PARAMETERS.len()];

/// A notation of [`tables::NOTATIONS`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Notation(usize);

impl Notation {
    /// The report's own notation.
    pub const REPORT: Notation = Notation(0);

    /// The notation called `name`.
    pub fn named(name: &str) -> Option<Notation> {
        tables::NOTATIONS
            .iter()
            .position(|n| *n == name)
            .map(Notation)
    }

    pub fn name(self) -> &'static str {
        tables::NOTATIONS[self.0]
    }

    pub fn title(self) -> &'static str {
        tables::TITLES[self.0]
    }

    /// This notation's name for each row (None where it has no such quantity).
    pub fn names(self) -> &'static [Option<&'static str>; N_ROWS] {
        &tables::NAMES[self.0]
    }

    /// The row of the quantity this notation calls `name`.
    pub fn row_of(self, name: &str) -> Option<usize> {
        self.names().iter().position(|n| *n == Some(name))
    }

    /// All notations.
    pub fn all() -> impl Iterator<Item = Notation> {
        (0..tables::NOTATIONS.len()).map(Notation)
    }

    /// The report's values from this notation's.
    pub fn to_report(
        self,
        values: &Values,
        parameters: &Parameters,
    ) -> Result<Values, NotationError> {
        self.check_inputs(values, parameters)?;
        Notation::REPORT.finite(tables::to_report(self.0, values, parameters))
    }

    /// This notation's values from the report's.
    pub fn from_report(
        self,
        report: &Values,
        parameters: &Parameters,
    ) -> Result<Values, NotationError> {
        Notation::REPORT.check_inputs(report, parameters)?;
        self.finite(tables::from_report(self.0, report, parameters))
    }

    /// Convert values from this notation to `to`.
    pub fn convert(
        self,
        to: Notation,
        values: &Values,
        parameters: &Parameters,
    ) -> Result<Values, NotationError> {
        to.from_report(&self.to_report(values, parameters)?, parameters)
    }

    /// The name of `row` in this notation (its report name where it has
    /// none).
    pub fn name_of(self, row: usize) -> &'static str {
        self.names()[row].unwrap_or(tables::ROWS[row])
    }

    fn check_inputs(self, values: &Values, parameters: &Parameters) -> Result<(), NotationError> {
        for (row, v) in values.iter().enumerate() {
            if let Some(value) = *v
                && !value.is_finite()
            {
                return Err(NotationError::NonFiniteInput {
                    notation: self.name(),
                    quantity: self.name_of(row),
                    value,
                });
            }
        }
        for (k, &value) in parameters.iter().enumerate() {
            if !value.is_finite() {
                return Err(NotationError::NonFiniteInput {
                    notation: self.name(),
                    quantity: tables::PARAMETERS[k],
                    value,
                });
            }
        }
        Ok(())
    }

    /// `values` (of this notation) if every one is finite.
    fn finite(self, values: Values) -> Result<Values, NotationError> {
        match values
            .iter()
            .enumerate()
            .find_map(|(row, v)| v.filter(|x| !x.is_finite()).map(|x| (row, x)))
        {
            None => Ok(values),
            Some((row, value)) => Err(NotationError::Overflow {
                notation: self.name(),
                quantity: self.name_of(row),
                value,
            }),
        }
    }
}

/// Why values cannot be converted: a conversion never returns a value that
/// is not a finite number.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum NotationError {
    #[error("{quantity} = {} (notation `{notation}`) is not a finite number", Num(*value))]
    NonFiniteInput {
        notation: &'static str,
        quantity: &'static str,
        value: f64,
    },
    #[error(
        "{quantity} in notation `{notation}` comes out as {}: the conversion overflows f64 (the values are too large for its factors)",
        Num(*value)
    )]
    Overflow {
        notation: &'static str,
        quantity: &'static str,
        value: f64,
    },
}

/// The row index of a report quantity by its row name.
pub fn row(name: &str) -> Option<usize> {
    tables::ROWS.iter().position(|r| *r == name)
}

/// The report's derivative set from report-notation values; the names of
/// the rows missing otherwise.
pub fn derivatives_from_report(values: &Values) -> Result<Derivatives, Vec<&'static str>> {
    let mut missing = Vec::new();
    let mut get = |name: &'static str| match row(name).and_then(|r| values[r]) {
        Some(v) => v,
        None => {
            missing.push(name);
            0.0
        }
    };
    let d = Derivatives {
        x_u: get("x_u"),
        x_w: get("x_w"),
        x_wdot: get("x_wdot"),
        x_q: get("x_q"),
        z_u: get("z_u"),
        z_w: get("z_w"),
        z_wdot: get("z_wdot"),
        z_q: get("z_q"),
        m_u: get("m_u"),
        m_w: get("m_w"),
        m_wdot: get("m_wdot"),
        m_q: get("m_q"),
        c_l: get("c_l"),
        mu1: get("mu"),
        i_b: get("i_b"),
    };
    if missing.is_empty() {
        Ok(d)
    } else {
        Err(missing)
    }
}

/// Report-notation values of a derivative set.
pub fn report_values(d: &Derivatives) -> Values {
    let mut v = [None; N_ROWS];
    let mut set = |name: &str, x: f64| {
        if let Some(r) = row(name) {
            v[r] = Some(x);
        }
    };
    set("x_u", d.x_u);
    set("x_w", d.x_w);
    set("x_wdot", d.x_wdot);
    set("x_q", d.x_q);
    set("z_u", d.z_u);
    set("z_w", d.z_w);
    set("z_wdot", d.z_wdot);
    set("z_q", d.z_q);
    set("m_u", d.m_u);
    set("m_w", d.m_w);
    set("m_wdot", d.m_wdot);
    set("m_q", d.m_q);
    set("c_l", d.c_l);
    set("mu", d.mu1);
    set("i_b", d.i_b);
    v
}
