//! `delta-stability convert --from X --to Y FILE [--json]`: a derivative set
//! from one notation into another, by the factors derived in
//! `specs/notation.toml` (see docs/notations.md). No value that is not
//! finite is written: a conversion that overflows is an error at the value
//! that caused it.

use crate::Failure;
use crate::args::{NotationArg, TargetNotation};
use crate::diag::{InputError, num};
use crate::input::AnyFile;
use crate::input::dimensional_notation::DIMENSIONAL;
use crate::input::rows::{DERIVATIVES, FLIGHT, QUARTIC};
use crate::input::tabled::uses_parameter;
use crate::input::{self, DerivativeFile};
use crate::output::print;
use serde::Serialize;
use stability_core::dimensional::{DimensionalDerivatives, DimensionalModel, Reference};
use stability_core::notation::{Notation, NotationError, Values, tables};
use std::collections::BTreeMap;
use std::fmt::Write;

pub fn run(
    from: NotationArg,
    to: TargetNotation,
    file: &str,
    json_out: bool,
) -> Result<(), Failure> {
    let any = input::read_any(file)?;
    let (written, form) = match &any {
        AnyFile::Report(f) => (f.notation.as_str(), f.form),
        AnyFile::Dimensional(_) => (DIMENSIONAL, DIMENSIONAL),
    };
    if written != from.name() && form != from.name() {
        return Err(InputError::file(
            file,
            format!(
                "--from {}: the file is in notation `{written}` (its `notation` key)",
                from.name()
            ),
        )
        .into());
    }
    match (any, to) {
        (AnyFile::Dimensional(d), TargetNotation::Dimensional) => {
            warn_all(&d.warnings);
            let out = Dimensional {
                path: &d.path,
                from: from.name(),
                model: d.model.in_stability_axes(),
                reference: d.reference,
            };
            out.print(json_out)
        }
        (AnyFile::Dimensional(d), TargetNotation::Table(to)) => {
            table(&d.to_derivative_file()?, from.name(), to, json_out)
        }
        (AnyFile::Report(input), TargetNotation::Table(to)) => {
            table(&input, from.name(), to, json_out)
        }
        (AnyFile::Report(input), TargetNotation::Dimensional) => {
            warn_all(&input.warnings);
            let Some(dim) = &input.dimensional else {
                return Err(InputError::file(
                    file,
                    "--to dimensional needs the flight condition in seconds: a [dimensional] table with V, rho, S, chord and mass (SI)",
                )
                .into());
            };
            let (model, reference) = DimensionalModel::from_report_with(&input.derivatives, dim);
            let out = Dimensional {
                path: &input.path,
                from: from.name(),
                model,
                reference: Some(reference),
            };
            out.print(json_out)
        }
    }
}

fn warn_all(warnings: &[String]) {
    for w in warnings {
        crate::output::warn(&format!("warning: {w}"));
    }
}

/// A conversion into one of the notations of `specs/notation.toml`.
fn table(input: &DerivativeFile, from: &str, to: Notation, json_out: bool) -> Result<(), Failure> {
    warn_all(&input.warnings);
    let values = converted(input, to)?;
    if json_out {
        let out = to_json(input, from, to, &values);
        print(&format!(
            "{}\n",
            serde_json::to_string_pretty(&out).unwrap_or_default()
        ))?;
    } else {
        print(&to_toml(input, from, to, &values))?;
    }
    Ok(())
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
                        num(v)
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

pub fn to_json<'a>(
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
        "# ({}); factors derived in specs/notation.toml, see docs/notations.md",
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
struct Dimensional<'a> {
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
    fn print(&self, json_out: bool) -> Result<(), Failure> {
        if json_out {
            let out = DimensionalJson {
                from: self.from,
                to: DIMENSIONAL,
                model: &self.model,
                reference: &self.reference,
            };
            print(&format!(
                "{}\n",
                serde_json::to_string_pretty(&out).unwrap_or_default()
            ))?;
        } else {
            print(&self.toml())?;
        }
        Ok(())
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
