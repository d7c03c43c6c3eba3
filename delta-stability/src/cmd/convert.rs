//! `delta-stability convert --from X --to Y FILE [--json]`: a derivative set
//! from one notation into another, by the factors derived in
//! `specs/notation.toml` (see docs/notations.md). No value that is not
//! finite is written: a conversion that overflows is an error at the value
//! that caused it.

use crate::Failure;
use crate::args::NotationArg;
use crate::diag::{InputError, num};
use crate::input::rows::{DERIVATIVES, FLIGHT, QUARTIC};
use crate::input::tabled::uses_parameter;
use crate::input::{self, DerivativeFile};
use crate::output::print;
use serde::Serialize;
use stability_core::notation::{Notation, NotationError, Values, tables};
use std::collections::BTreeMap;
use std::fmt::Write;

pub fn run(from: NotationArg, to: Notation, file: &str, json_out: bool) -> Result<(), Failure> {
    let input = input::read(file)?;
    for w in &input.warnings {
        crate::output::warn(&format!("warning: {w}"));
    }
    if input.notation != from.name() {
        return Err(InputError::file(
            file,
            format!(
                "--from {}: the file is in notation `{}` (its `notation` key)",
                from.name(),
                input.notation
            ),
        )
        .into());
    }
    let values = converted(&input, to)?;
    if json_out {
        let out = to_json(&input, from.name(), to, &values);
        print(&format!(
            "{}\n",
            serde_json::to_string_pretty(&out).unwrap_or_default()
        ))?;
    } else {
        print(&to_toml(&input, from.name(), to, &values))?;
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
