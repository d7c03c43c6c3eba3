//! Why a coefficient of the aerodynamic model cannot be given.

use super::defaults;
use crate::aerodynamics::lifting_surface::LiftingSurfaceError;
use crate::numerics::display::Num;

/// Why a coefficient cannot be given.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum AeroError {
    #[error("a table needs at least two points, not {0}")]
    TooShort(usize),
    #[error("the table's Mach and value columns have different lengths ({0} and {1})")]
    Lengths(usize, usize),
    #[error(
        "row {row}: Mach {} does not increase on the row before ({}); the Mach column must increase strictly",
        Num(*mach), Num(*previous)
    )]
    NotIncreasing {
        row: usize,
        mach: f64,
        previous: f64,
    },
    #[error("row {row}: {what} {} is not a finite number", Num(*value))]
    NonFinite {
        row: usize,
        what: &'static str,
        value: f64,
    },
    #[error(
        "Mach {} is outside the table's range [{}, {}] (tables are not extrapolated)",
        Num(*mach), Num(*lo), Num(*hi)
    )]
    OutsideTable { mach: f64, lo: f64, hi: f64 },
    #[error(
        "Mach {} is outside the range [{}, {}] of the table of {derivative} (tables are not extrapolated: extend the table, or drop it to use the computed value)",
        Num(*mach), Num(*lo), Num(*hi)
    )]
    OutsideDerivativeTable {
        derivative: &'static str,
        mach: f64,
        lo: f64,
        hi: f64,
    },
    #[error(
        "Mach {} is outside the default models' range [0, {}]",
        Num(*.0), defaults::MACH_MAX
    )]
    OutsideDefaults(f64),
    #[error(
        "the lifting-surface model's lift slope and aerodynamic centre come from a subsonic theory: they need 0 ≤ M < 1, not M = {}; at and above M = 1 use the default model",
        Num(*.0)
    )]
    LatticeMach(f64),
    #[error("the lifting-surface lift slope and aerodynamic centre: {0}")]
    LiftingSurface(LiftingSurfaceError),
    #[error("the configuration's surfaces and body: {0}")]
    Configuration(crate::aerodynamics::lifting_surface::configuration::ConfigurationError),
}
