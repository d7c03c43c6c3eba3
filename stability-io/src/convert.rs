//! A derivative set from one notation into another (`convert`), by the
//! factors derived in `stability-core/specs/notation.toml` (see
//! docs/notations.md): the values, and the file or JSON object they are
//! written as. No value that is not finite is written: a conversion that
//! overflows is an error at the value that caused it.

use crate::diag::InputError;
use crate::input::dimensional_notation::DIMENSIONAL;
use crate::input::rows::{DERIVATIVES, FLIGHT, QUARTIC};
use crate::input::tabled::uses_parameter;
use crate::input::{AnyFile, DerivativeFile};
use serde::Serialize;
use stability_core::dimensional::{DimensionalDerivatives, DimensionalModel, Reference};
use stability_core::display::Num;
use stability_core::notation::{Notation, NotationError, Values, tables};
use std::collections::BTreeMap;
use std::fmt::Write;

/// A notation a set can be written in: one of
/// `stability-core/specs/notation.toml`'s, or the dimensional one (AVL's is
/// read only).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Target {
    Table(Notation),
    Dimensional,
}

impl Target {
    pub fn name(self) -> &'static str {
        match self {
            Target::Table(n) => n.name(),
            Target::Dimensional => DIMENSIONAL,
        }
    }
}

/// The notation a file is written in (`notation`), and the form its values
/// were read in (`american_cl` for an `american` file in the C_L/C_D form).
pub fn written_in(any: &AnyFile) -> (&str, &'static str) {
    match any {
        AnyFile::Report(f) => (f.notation.as_str(), f.form),
        AnyFile::Dimensional(_) => (DIMENSIONAL, DIMENSIONAL),
    }
}

/// A conversion done: what it writes. (One per conversion: its size does
/// not matter.)
#[allow(clippy::large_enum_variant)]
pub enum Conversion<'a> {
    /// Into one of the notations of `stability-core/specs/notation.toml`.
    Table {
        input: std::borrow::Cow<'a, DerivativeFile>,
        from: &'a str,
        to: Notation,
        values: Values,
    },
    /// Into `notation = "dimensional"`.
    Dimensional(Dimensional<'a>),
}

/// Converts `any`, written in notation `from`, into `to`.
pub fn convert<'a>(
    any: &'a AnyFile,
    from: &'a str,
    to: Target,
) -> Result<Conversion<'a>, InputError> {
    use std::borrow::Cow;
    match (any, to) {
        (AnyFile::Dimensional(d), Target::Dimensional) => {
            Ok(Conversion::Dimensional(Dimensional {
                path: &d.path,
                from,
                model: d.model.in_stability_axes(),
                reference: d.reference,
                warnings: &d.warnings,
            }))
        }
        (AnyFile::Dimensional(d), Target::Table(to)) => {
            let input = d.to_derivative_file()?;
            let values = converted(&input, to)?;
            Ok(Conversion::Table {
                input: Cow::Owned(input),
                from,
                to,
                values,
            })
        }
        (AnyFile::Report(input), Target::Table(to)) => {
            let values = converted(input, to)?;
            Ok(Conversion::Table {
                input: Cow::Borrowed(input),
                from,
                to,
                values,
            })
        }
        (AnyFile::Report(input), Target::Dimensional) => {
            let Some(dim) = &input.dimensional else {
                return Err(InputError::file(
                    &input.path,
                    "--to dimensional needs the flight condition in seconds: a [dimensional] table with V, rho, S, chord and mass (SI)",
                ));
            };
            let (model, reference) = DimensionalModel::from_report_with(&input.derivatives, dim);
            Ok(Conversion::Dimensional(Dimensional {
                path: &input.path,
                from,
                model,
                reference: Some(reference),
                warnings: &input.warnings,
            }))
        }
    }
}

impl Conversion<'_> {
    /// The reader's warnings about the set converted (for a dimensional
    /// set into a table, those of its turn into the report's notation).
    pub fn warnings(&self) -> &[String] {
        match self {
            Conversion::Table { input, .. } => &input.warnings,
            Conversion::Dimensional(d) => d.warnings,
        }
    }

    /// The converted set as a derivative file of the target notation.
    pub fn toml(&self) -> String {
        match self {
            Conversion::Table {
                input,
                from,
                to,
                values,
            } => to_toml(input, from, *to, values),
            Conversion::Dimensional(d) => d.toml(),
        }
    }

    /// The `convert --json` object.
    pub fn json(&self) -> serde_json::Value {
        let v = match self {
            Conversion::Table {
                input,
                from,
                to,
                values,
            } => serde_json::to_value(ConvertJson::new(input, from, *to, values)),
            Conversion::Dimensional(d) => serde_json::to_value(d.view()),
        };
        v.unwrap_or_default()
    }
}

/// The values in notation `to`, every one finite (the library refuses a
/// conversion that overflows; the error is placed at the value it came
/// from).
pub fn converted(input: &DerivativeFile, to: Notation) -> Result<Values, InputError> {
    to.from_report(&input.report, &input.parameters)
        .map_err(|e| {
            let (notation, quantity) = match &e {
                NotationError::Overflow { quantity, .. } => (to, *quantity),
                NotationError::NonFiniteInput { quantity, .. } => (Notation::REPORT, *quantity),
            };
            let row = notation
                .row_of(quantity)
                .or_else(|| tables::ROWS.iter().position(|r| *r == quantity));
            let source = row
                .and_then(|i| input.report[i].map(|v| (i, v)))
                .map(|(i, v)| {
                    format!(
                        " ({} = {} in the report's notation)",
                        Notation::REPORT.name_of(i),
                        Num(v)
                    )
                })
                .unwrap_or_default();
            let message = format!("{e}{source}; nothing written");
            match row {
                Some(i) => input.error_at(i, message),
                None => InputError::file(&input.path, message),
            }
        })
}

/// The `convert --json` object: the notations, the values in the target
/// notation by its names (null where the input does not determine one),
/// the report's values, and the parameters.
#[derive(Serialize)]
pub struct ConvertJson<'a> {
    from: &'a str,
    to: &'a str,
    values: BTreeMap<&'static str, Option<f64>>,
    report: BTreeMap<&'static str, f64>,
    parameters: BTreeMap<&'static str, f64>,
}

impl<'a> ConvertJson<'a> {
    pub fn new(
        input: &DerivativeFile,
        from: &'a str,
        to: Notation,
        values: &Values,
    ) -> ConvertJson<'a> {
        let theirs = to.names().iter().zip(values);
        let ours = Notation::REPORT.names().iter().zip(&input.report);
        ConvertJson {
            from,
            to: to.name(),
            values: theirs.filter_map(|(n, v)| n.map(|n| (n, *v))).collect(),
            report: ours.filter_map(|(n, v)| Some(((*n)?, (*v)?))).collect(),
            parameters: tables::PARAMETERS
                .iter()
                .copied()
                .zip(input.parameters)
                .collect(),
        }
    }
}

/// One table of the TOML output: the notation's names for `rows`.
fn section(s: &mut String, title: &str, rows: &[usize], to: Notation, values: &Values) {
    let entries: Vec<(usize, &str)> = rows
        .iter()
        .filter_map(|&i| to.names()[i].map(|n| (i, n)))
        .collect();
    if entries.is_empty() {
        return;
    }
    let _ = writeln!(s, "\n[{title}]");
    for (i, n) in entries {
        match values[i] {
            Some(v) => {
                let _ = writeln!(s, "{n} = {v:?}");
            }
            None => {
                let _ = writeln!(
                    s,
                    "# {n}: not determined by the input (a quantity it depends on is missing)"
                );
            }
        }
    }
}

fn to_toml(input: &DerivativeFile, from: &str, to: Notation, values: &Values) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "# {}, converted from notation `{from}` to `{}` by delta-stability",
        input.path,
        to.name()
    );
    let _ = writeln!(
        s,
        "# ({}); factors derived in stability-core/specs/notation.toml, see docs/notations.md",
        to.title()
    );
    let _ = writeln!(s, "notation = \"{}\"", to.name());
    section(&mut s, "derivatives", &DERIVATIVES, to, values);
    section(&mut s, "flight", &FLIGHT, to, values);
    let report_names = Notation::REPORT.names();
    let lacking: Vec<usize> = QUARTIC
        .into_iter()
        .filter(|&i| to.names()[i].is_none() && input.report[i].is_some())
        .collect();
    if !lacking.is_empty() {
        let _ = writeln!(
            s,
            "\n# quantities notation `{}` does not define, in the report's names",
            to.name()
        );
        let _ = writeln!(s, "[report]");
        for i in lacking {
            if let (Some(n), Some(v)) = (report_names[i], input.report[i]) {
                let _ = writeln!(s, "{n} = {v:?}");
            }
        }
    }
    for (k, p) in tables::PARAMETERS.iter().enumerate() {
        if uses_parameter(to, k) {
            let _ = writeln!(s, "\n[parameters]\n{p} = {:?}", input.parameters[k]);
        }
    }
    if let Some(d) = &input.dimensional {
        let _ = writeln!(
            s,
            "\n[dimensional]\nV = {:?}\nrho = {:?}\nS = {:?}\nchord = {:?}\nmass = {:?}",
            d.v, d.rho, d.s, d.chord, d.mass
        );
    }
    s
}

/// A conversion into `notation = "dimensional"`: the set in stability
/// axes, with its reference quantities.
pub struct Dimensional<'a> {
    /// The reader's warnings about the set converted.
    warnings: &'a [String],
    path: &'a str,
    from: &'a str,
    model: DimensionalModel,
    reference: Option<Reference>,
}

/// The `convert --to dimensional --json` object.
#[derive(Serialize)]
struct DimensionalJson<'a> {
    from: &'a str,
    to: &'a str,
    model: &'a DimensionalModel,
    reference: &'a Option<Reference>,
}

impl Dimensional<'_> {
    /// The `convert --to dimensional --json` object.
    fn view(&self) -> DimensionalJson<'_> {
        DimensionalJson {
            from: self.from,
            to: DIMENSIONAL,
            model: &self.model,
            reference: &self.reference,
        }
    }

    /// The set as a `notation = "dimensional"` file.
    fn toml(&self) -> String {
        let m = &self.model;
        let mut s = String::new();
        let _ = writeln!(
            s,
            "# {}, converted from notation `{}` to `dimensional` by delta-stability\n# (derivatives per unit mass and inertia in stability axes; see docs/dimensional.md)",
            self.path, self.from
        );
        let _ = writeln!(
            s,
            "notation = \"dimensional\"\naxes = \"{}\"\nunits = \"{}\"\n\n[derivatives]",
            m.axes.as_str(),
            m.units.name()
        );
        for (n, v) in DimensionalDerivatives::NAMES
            .iter()
            .zip(m.derivatives.values())
        {
            let _ = writeln!(s, "{n} = {v:?}");
        }
        let t = &m.trim;
        let _ = writeln!(
            s,
            "\n[flight]\nU0 = {:?}\nW0 = {:?}\ntheta0 = {:?}  # degrees\ng = {:?}",
            t.u0,
            t.w0,
            t.theta0.to_degrees(),
            t.g
        );
        if let Some(r) = &self.reference {
            let _ = writeln!(s, "\n[reference]\nchord = {:?}", r.chord);
            match &r.physical {
                Some(p) => {
                    let _ = writeln!(
                        s,
                        "rho = {:?}\nS = {:?}\nmass = {:?}\nI_y = {:?}",
                        p.rho, p.s, p.mass, p.i_y
                    );
                }
                None => {
                    let _ = writeln!(s, "mu1 = {:?}\ni_b = {:?}", r.mu1, r.i_b);
                }
            }
        }
        s
    }
}
