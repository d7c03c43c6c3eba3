//! `delta-stability convert --from X --to Y FILE [--json]`: a derivative set
//! from one notation into another, by the factors derived in
//! `specs/notation.toml` (see docs/notations.md).

use crate::Failure;
use crate::diag::InputError;
use crate::input::{self, DERIVATIVE_ROWS, FLIGHT_ROWS};
use serde_json::{Value, json};
use stability_core::notation::{Notation, row, tables};
use std::fmt::Write;

pub fn run(from: &str, to: &str, file: &str, json_out: bool) -> Result<(), Failure> {
    let bad = |m: String| Failure::Input(InputError::file(file, m));
    let input = input::read(file)?;
    for w in &input.warnings {
        eprintln!("warning: {w}");
    }
    if input.notation != from {
        return Err(bad(format!(
            "the file is in notation `{}` (its `notation` key), not `{from}`",
            input.notation
        )));
    }
    let Some(target) = Notation::named(to) else {
        return Err(bad(format!(
            "--to: unknown or read-only notation `{to}`; the notations one can write are: {}",
            tables::NOTATIONS.join(", ")
        )));
    };
    let values = target
        .from_report(&input.report, &input.parameters)
        .map_err(|e| bad(e.to_string()))?;
    let names = target.names();
    let report_names = Notation::REPORT.names();
    let quartic_rows: Vec<&str> = DERIVATIVE_ROWS
        .iter()
        .chain(["c_l", "mu", "i_b"].iter())
        .copied()
        .collect();
    if json_out {
        let mut theirs = serde_json::Map::new();
        for (i, n) in names.iter().enumerate() {
            if let Some(n) = n {
                theirs.insert(
                    (*n).to_string(),
                    values[i].map_or(Value::Null, |v| json!(v)),
                );
            }
        }
        let mut report = serde_json::Map::new();
        for (i, n) in report_names.iter().enumerate() {
            if let (Some(n), Some(v)) = (n, input.report[i]) {
                report.insert((*n).to_string(), json!(v));
            }
        }
        let out = json!({
            "from": from,
            "to": to,
            "values": theirs,
            "report": report,
            "parameters": { "lt": input.parameters[0] },
        });
        println!("{}", serde_json::to_string_pretty(&out).unwrap_or_default());
        return Ok(());
    }
    let mut s = String::new();
    let _ = writeln!(
        s,
        "# {file}, converted from notation `{from}` to `{to}` by delta-stability"
    );
    let _ = writeln!(
        s,
        "# ({}); factors derived in specs/notation.toml, see docs/notations.md",
        target.title()
    );
    let _ = writeln!(s, "notation = \"{to}\"");
    let section = |title: &str, rows: &[&str], s: &mut String| {
        let entries: Vec<(usize, &str)> = rows
            .iter()
            .filter_map(|r| row(r))
            .filter_map(|i| names[i].map(|n| (i, n)))
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
    };
    section("derivatives", &DERIVATIVE_ROWS, &mut s);
    section("flight", &FLIGHT_ROWS, &mut s);
    let lacking: Vec<usize> = quartic_rows
        .iter()
        .filter_map(|r| row(r))
        .filter(|&i| names[i].is_none() && input.report[i].is_some())
        .collect();
    if !lacking.is_empty() {
        let _ = writeln!(
            s,
            "\n# quantities notation `{to}` does not define, in the report's names"
        );
        let _ = writeln!(s, "[report]");
        for i in lacking {
            if let (Some(n), Some(v)) = (report_names[i], input.report[i]) {
                let _ = writeln!(s, "{n} = {v:?}");
            }
        }
    }
    if to == "duncan" {
        let _ = writeln!(s, "\n[parameters]\nlt = {:?}  # l_t/c̄", input.parameters[0]);
    }
    if let Some(d) = &input.dimensional {
        let _ = writeln!(
            s,
            "\n[dimensional]\nV = {:?}\nrho = {:?}\nS = {:?}\nchord = {:?}\nmass = {:?}",
            d.v, d.rho, d.s, d.chord, d.mass
        );
    }
    print!("{s}");
    Ok(())
}
