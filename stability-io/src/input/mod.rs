//! Derivative files: a derivative set in any notation of
//! `stability-core/specs/notation.toml` (or AVL's `.st` output) and its
//! flight condition, as TOML.
//!
//! ```toml
//! notation = "report"
//! [derivatives]      # all twelve, report notation (§3, eqs 9–20)
//! x_u = -0.05
//! # x_w x_wdot x_q z_u z_w z_wdot z_q m_u m_w m_wdot m_q
//! [flight]
//! c_l = 0.3          # lift coefficient, eq (24)
//! mu1 = 50.0         # relative density m/(½ρSc̄) > 0
//! i_b = 0.08         # pitching inertia B/(mc̄²) > 0
//! [dimensional]      # optional: times in seconds
//! V = 250.0          # true airspeed, m/s
//! rho = 0.41         # air density, kg/m³
//! S = 93.0           # wing area, m²
//! chord = 6.6        # the chord of the derivatives and of μ₁, m
//! mass = 12000.0     # kg
//! ```
//!
//! In another notation the names are that notation's (`delta-stability
//! convert --help` lists them). Quantities a notation does not define come
//! in a `[report]` table in the report's names; μ₁ and i_B may instead come
//! from `[dimensional]` (`mass`, `rho`, `S`, `chord`, and `I_y` in kg·m²).
//! Duncan's notation needs `[parameters] lt = l_t/c̄`. For AVL, `st_file`
//! names the `.st` output and `[dimensional]` gives `mass`, `I_y`, `rho`, `V`.
//!
//! Each notation has its reader: [`tabled`] for the notations of the specs,
//! [`avl`] for AVL's output; [`check`] then checks what either read. Every
//! value read is finite and every error names the file, line and field.

pub mod analysis;
pub mod avl;
pub mod check;
pub mod datcom;
pub mod dimensional;
pub mod dimensional_notation;
pub mod raw;
pub mod rows;
pub mod suggest;
pub mod tabled;

use crate::Failure;
use crate::diag::InputError;
use stability_core::Derivatives;
use stability_core::analysis::Dimensional;
use stability_core::data::notation::{N_ROWS, Parameters, Values, tables};
use std::ops::Range;
use std::path::Path;

pub use avl::AVL;
pub use raw::toml_error;
pub use rows::{DERIVATIVE_ROWS, FLIGHT_ROWS};

/// The notations a derivative file may be written in.
pub fn notations() -> Vec<&'static str> {
    let mut v: Vec<&str> = tables::NOTATIONS.to_vec();
    v.push(AVL);
    v.push(dimensional_notation::DIMENSIONAL);
    v
}

/// A derivative file, read and checked.
#[derive(Debug, Clone, PartialEq)]
pub struct DerivativeFile {
    pub path: String,
    pub notation: String,
    /// The notation the values were read in: `notation`, or `american_cl`
    /// for a `notation = "american"` file in the C_L/C_D form.
    pub form: &'static str,
    /// The derivative set in the report's notation.
    pub derivatives: Derivatives,
    /// All report-notation values known (by row), every one finite.
    pub report: Values,
    /// Dimensionless parameters (l_t/c̄).
    pub parameters: Parameters,
    /// The dimensional flight condition, when given.
    pub dimensional: Option<Dimensional>,
    /// Where each row's value was given (an error with an empty message,
    /// to be filled in by whoever finds fault with the value).
    pub origins: Vec<Option<InputError>>,
    /// Inconsistencies worth a user's attention (not errors).
    pub warnings: Vec<String>,
}

impl DerivativeFile {
    /// An error about the value of `row`, where it was given (the file as
    /// a whole when it was not given in it).
    pub fn error_at(&self, row: usize, message: impl Into<String>) -> InputError {
        match self.origins.get(row).and_then(Option::as_ref) {
            Some(at) => InputError {
                message: message.into(),
                ..at.clone()
            },
            None => InputError::file(&self.path, message),
        }
    }
}

/// Where a value was written: its span and field.
#[derive(Debug, Clone)]
pub struct Origin {
    pub span: Range<usize>,
    pub field: String,
}

/// What a notation's reader makes of a file, before the checks.
pub struct Reading {
    /// The report-notation values by row.
    pub report: Values,
    pub origins: [Option<Origin>; N_ROWS],
    pub parameters: Parameters,
    pub dimensional: Option<Dimensional>,
    pub warnings: Vec<String>,
    /// The notation of `stability-core/specs/notation.toml` the values were
    /// read in (a `notation = "american"` file may be in its C_L/C_D form).
    pub form: &'static str,
}

/// Read a derivative file from disk (a regular file of at most
/// [`crate::files::MAX_INPUT_BYTES`]).
pub fn read(path: &str) -> Result<DerivativeFile, Failure> {
    let text = crate::files::read_input(Path::new(path))?;
    parse(path, &text)
}

/// A derivative file in any notation: `notation = "dimensional"` as it is
/// (the general model, [`dimensional_notation`]), any other in the
/// report's notation.
#[derive(Debug, Clone)]
pub enum AnyFile {
    Report(Box<DerivativeFile>),
    Dimensional(Box<dimensional_notation::DimensionalFile>),
}

/// Read a derivative file of any notation from disk, keeping a dimensional
/// set dimensional.
pub fn read_any(path: &str) -> Result<AnyFile, Failure> {
    let text = crate::files::read_input(Path::new(path))?;
    if dimensional_notation::is_dimensional(&text) {
        let file = dimensional_notation::parse(path, &text)?;
        return Ok(AnyFile::Dimensional(Box::new(file)));
    }
    Ok(AnyFile::Report(Box::new(parse(path, &text)?)))
}

/// Parse a derivative file's text (an AVL file's `.st` output is read from
/// disk, relative to `path`); a `notation = "dimensional"` set in the
/// report's notation (it needs `[reference]`).
pub fn parse(path: &str, text: &str) -> Result<DerivativeFile, Failure> {
    if crate::config::is_config(text) {
        return Err(InputError::file(path, crate::config::NOT_A_DERIVATIVE_FILE).into());
    }
    if dimensional_notation::is_dimensional(text) {
        return Ok(dimensional_notation::parse(path, text)?.to_derivative_file()?);
    }
    let raw: raw::RawFile = toml::from_str(text).map_err(|e| toml_error(path, text, &e))?;
    let cx = raw::Ctx { path, text };
    let dims = dimensional::Dims::read(&cx, &raw.dimensional)?;
    let reading = if raw.notation.get_ref() == AVL {
        avl::read(&cx, &raw, &dims)?
    } else {
        tabled::read(&cx, &raw, &dims)?
    };
    Ok(check::finish(&cx, &raw, &dims, reading)?)
}
