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
use serde_json::{Value, json};
use stability_core::notation::{Notation, Values, tables};
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

/// The values in notation `to`, every one finite.
fn converted(input: &DerivativeFile, to: Notation) -> Result<Values, InputError> {
    let values = to.from_report(&input.report, &input.parameters);
    for (i, v) in values.iter().enumerate() {
        let Some(v) = v.filter(|v| !v.is_finite()) else {
            continue;
        };
        let theirs = to.names()[i].unwrap_or(tables::ROWS[i]);
        let ours = Notation::REPORT.names()[i].unwrap_or(tables::ROWS[i]);
        let message = format!(
            "in notation `{}`, {theirs} would be {}: the conversion overflows ({ours} = {} in the report's notation); nothing written",
            to.name(),
            num(v),
            input.report[i].map_or("—".into(), num)
        );
        return Err(input.error_at(i, message));
    }
    Ok(values)
}

fn to_json(input: &DerivativeFile, from: &str, to: Notation, values: &Values) -> Value {
    let mut theirs = serde_json::Map::new();
    for (i, n) in to.names().iter().enumerate() {
        if let Some(n) = n {
            theirs.insert(
                (*n).to_string(),
                values[i].map_or(Value::Null, |v| json!(v)),
            );
        }
    }
    let mut report = serde_json::Map::new();
    for (i, n) in Notation::REPORT.names().iter().enumerate() {
        if let (Some(n), Some(v)) = (n, input.report[i]) {
            report.insert((*n).to_string(), json!(v));
        }
    }
    json!({
        "from": from,
        "to": to.name(),
        "values": theirs,
        "report": report,
        "parameters": { "lt": input.parameters[0] },
    })
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
