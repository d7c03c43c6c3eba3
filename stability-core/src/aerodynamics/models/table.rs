//! A coefficient against Mach number from a table (the user's, or one
//! made from a DATCOM output).

use super::error::AeroError;
use crate::numerics::interpolation::{Value, hermite, monotone_slopes};
use serde::Serialize;

/// A table of a coefficient against Mach number, interpolated by the
/// monotone piecewise cubic Hermite scheme of F.N. Fritsch and R.E. Carlson,
/// "Monotone piecewise cubic interpolation", SIAM J. Numer. Anal. 17(2),
/// 1980: C¹, exact at the nodes, and without overshoot — where the data are
/// monotone on an interval, so is the interpolant.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    mach: Vec<f64>,
    value: Vec<f64>,
    slope: Vec<f64>,
    origin: TableOrigin,
}

/// Whose table it is: the user's, or one made from a DATCOM output
/// ([`crate::data::datcom`]). Serializes as `"table"` or `"datcom"`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum TableOrigin {
    #[default]
    User,
    Datcom,
}

impl TableOrigin {
    /// In words (a page's).
    pub fn describe(self) -> &'static str {
        match self {
            TableOrigin::User => "your table",
            TableOrigin::Datcom => "DATCOM's output",
        }
    }
}

impl Serialize for TableOrigin {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(match self {
            TableOrigin::User => "table",
            TableOrigin::Datcom => "datcom",
        })
    }
}

impl Table {
    /// A table from its columns; rows count from 1 in errors.
    pub fn new(mach: Vec<f64>, value: Vec<f64>) -> Result<Table, AeroError> {
        if mach.len() != value.len() {
            return Err(AeroError::Lengths(mach.len(), value.len()));
        }
        let n = mach.len();
        if n < 2 {
            return Err(AeroError::TooShort(n));
        }
        for i in 0..n {
            if !mach[i].is_finite() {
                return Err(AeroError::NonFinite {
                    row: i + 1,
                    what: "Mach",
                    value: mach[i],
                });
            }
            if !value[i].is_finite() {
                return Err(AeroError::NonFinite {
                    row: i + 1,
                    what: "value",
                    value: value[i],
                });
            }
            if i > 0 && mach[i] <= mach[i - 1] {
                return Err(AeroError::NotIncreasing {
                    row: i + 1,
                    mach: mach[i],
                    previous: mach[i - 1],
                });
            }
        }
        // Secants, then Fritsch–Carlson slopes.
        let delta: Vec<f64> = (0..n - 1)
            .map(|i| (value[i + 1] - value[i]) / (mach[i + 1] - mach[i]))
            .collect();
        let mut slope = vec![0.0; n];
        slope[0] = delta[0];
        slope[n - 1] = delta[n - 2];
        for i in 1..n - 1 {
            slope[i] = if delta[i - 1] * delta[i] <= 0.0 {
                0.0
            } else {
                (delta[i - 1] + delta[i]) / 2.0
            };
        }
        for i in 0..n - 1 {
            (slope[i], slope[i + 1]) = monotone_slopes(delta[i], slope[i], slope[i + 1]);
        }
        Ok(Table {
            mach,
            value,
            slope,
            origin: TableOrigin::User,
        })
    }

    /// The table marked as coming from `origin`.
    pub fn with_origin(self, origin: TableOrigin) -> Table {
        Table { origin, ..self }
    }

    /// Whose table it is.
    pub fn origin(&self) -> TableOrigin {
        self.origin
    }

    /// The Mach numbers and values, as given.
    pub fn points(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        self.mach.iter().copied().zip(self.value.iter().copied())
    }

    /// The Mach range covered.
    pub fn range(&self) -> (f64, f64) {
        (self.mach[0], self.mach[self.mach.len() - 1])
    }

    /// The interpolated value and its derivative at `m`.
    pub fn at(&self, m: f64) -> Result<Value, AeroError> {
        let (lo, hi) = self.range();
        if !(m >= lo && m <= hi) {
            return Err(AeroError::OutsideTable { mach: m, lo, hi });
        }
        let i = match self.mach.partition_point(|&x| x <= m) {
            0 => 0,
            k => (k - 1).min(self.mach.len() - 2),
        };
        Ok(hermite(
            (self.mach[i], self.value[i], self.slope[i]),
            (self.mach[i + 1], self.value[i + 1], self.slope[i + 1]),
            m,
        ))
    }
}
