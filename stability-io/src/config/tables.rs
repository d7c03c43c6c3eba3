//! The user's aerodynamic tables (`[model.tables]`): inline
//! (`mach = [...]`, `value = [...]` or `values = [...]`) or a two-column
//! CSV file (Mach, value). A CSV file's first line is a header when none
//! of its cells is a number; a file without a header is used whole, and a
//! cell of a row that is not a number is an error at its line and column.
//!
//! A table is of a coefficient of §6 ([`COEFFICIENTS`]) or of a derivative
//! of the report's notation ([`stability_core::aerodynamics::models::derivative_tables::NAMES`],
//! `z_ẇ` and `m_ẇ` also so spelt), the latter with `mode = "value"` (the
//! default) or `"increment"` and, optionally, `cg = h`, the c.g. its values
//! are about.

use super::raw::{RawTable, RawTables};
use crate::Failure;
use crate::diag::{InputError, quote};
use crate::input::suggest::did_you_mean;
use crate::limits;
use stability_core::aerodynamics::models::aero::{AeroError, AeroModel, Source, Table};
use stability_core::aerodynamics::models::derivative_tables::{
    self, DerivativeTable, Mode, Outside,
};
use toml::Spanned;

/// The coefficients of §6 a table may give.
pub const COEFFICIENTS: [&str; 4] = [
    "lift_slope",
    "zero_lift_drag",
    "drag_due_to_lift",
    "aerodynamic_centre",
];

/// The model's sources from the user's tables: each coefficient's table,
/// and the derivative tables (in the order of their names).
pub fn user_tables(path: &str, text: &str, tables: &RawTables) -> Result<AeroModel, Failure> {
    let mut aero = AeroModel::default();
    for (name, t) in tables {
        let raw = t.get_ref();
        let field = format!("[model.tables] {name}");
        let at = |span: std::ops::Range<usize>, m: String| {
            Failure::from(InputError::at(path, text, span, field.clone(), m))
        };
        if let Some(k) = COEFFICIENTS.iter().position(|c| c == name) {
            if let Some(s) = raw
                .mode
                .as_ref()
                .map(|m| m.span())
                .or(raw.cg.as_ref().map(|c| c.span()))
            {
                return Err(at(s, "`mode` and `cg` belong to a derivative's table; a coefficient's table gives its value".into()));
            }
            let source = Source::Table(table_from(path, text, name, t)?);
            match k {
                0 => aero.lift_slope = source,
                1 => aero.zero_lift_drag = source,
                2 => aero.drag_due_to_lift = source,
                _ => aero.aerodynamic_centre = source,
            }
            continue;
        }
        let Some(derivative) = derivative_tables::named(name) else {
            let names = COEFFICIENTS.iter().chain(&derivative_tables::NAMES);
            return Err(at(
                t.span(),
                format!(
                    "unknown table `{}`{}; the tables are: {}",
                    quote(name),
                    did_you_mean(name, names.clone().copied()),
                    names.copied().collect::<Vec<_>>().join(", ")
                ),
            ));
        };
        if aero.derivatives.0.iter().any(|d| d.name == derivative) {
            return Err(at(
                t.span(),
                format!("{derivative} has two tables (one spelt otherwise); give one"),
            ));
        }
        let mode = match &raw.mode {
            None => Mode::Value,
            Some(m) => Mode::parse(m.get_ref()).ok_or_else(|| {
                at(
                    m.span(),
                    format!(
                        "mode is `value` or `increment`, not `{}`",
                        quote(m.get_ref())
                    ),
                )
            })?,
        };
        let reference_cg = match &raw.cg {
            None => None,
            Some(c) => Some(
                limits::CG
                    .check(*c.get_ref())
                    .map_err(|m| at(c.span(), m))?,
            ),
        };
        aero.derivatives.0.push(DerivativeTable {
            name: derivative,
            table: table_from(path, text, name, t)?,
            mode,
            reference_cg,
            outside: Outside::Refuse,
            missing: Vec::new(),
        });
    }
    Ok(aero)
}

pub fn table_from(
    path: &str,
    text: &str,
    name: &str,
    t: &Spanned<RawTable>,
) -> Result<Table, Failure> {
    let field = format!("[model.tables] {name}");
    let raw = t.get_ref();
    let at = |m: String| InputError::at(path, text, t.span(), field.clone(), m);
    match (&raw.mach, &raw.value, &raw.file) {
        (Some(m), Some(v), None) => {
            let column = |xs: &[Spanned<f64>], key: &str| -> Result<Vec<f64>, InputError> {
                let limit = column_limit(key);
                xs.iter()
                    .enumerate()
                    .map(|(k, x)| {
                        limit.check(*x.get_ref()).map_err(|m| {
                            let f = format!("{field} {key}[{k}]");
                            InputError::at(path, text, x.span(), f, m)
                        })
                    })
                    .collect()
            };
            let (m, v) = (column(m, "mach")?, column(v, "value")?);
            Ok(Table::new(m, v).map_err(|e| at(e.to_string()))?)
        }
        (None, None, Some(f)) => {
            let file = super::relative(path, f.get_ref());
            let named_at = InputError::at(path, text, f.span(), field.clone(), "");
            let csv = crate::files::read_input(&file).map_err(|e| match e {
                Failure::Io(e) => Failure::Io(e.named_at(&named_at)),
                other => other,
            })?;
            Ok(read_csv_table(&file.display().to_string(), &csv)?)
        }
        _ => Err(at(
            "a table is either `mach = [...]` with `value = [...]`, or `file = \"name.csv\"`"
                .into(),
        )
        .into()),
    }
}

/// A line's cells: each one's text (trimmed) and the byte offset in the
/// line where that text begins.
fn cells(line: &str) -> Vec<(&str, usize)> {
    let mut out = Vec::new();
    let mut start = 0;
    for raw in line.split(',') {
        let lead = raw.len() - raw.trim_start().len();
        out.push((raw.trim(), start + lead));
        start += raw.len() + 1;
    }
    out
}

/// The range of a table's column: its Mach numbers ([`limits::TABLE_MACH`])
/// or its values ([`limits::TABLE_VALUE`]).
fn column_limit(key: &str) -> &'static limits::Limit {
    match key {
        "mach" | "Mach" => &limits::TABLE_MACH,
        _ => &limits::TABLE_VALUE,
    }
}

fn is_number(cell: &str) -> bool {
    cell.parse::<f64>().is_ok()
}

/// A two-column CSV table (Mach, value). The first line that is not blank
/// or a comment is a header when none of its cells is a number; any other
/// line is a row, and each cell of it that is not a number is an error at
/// its file, line and column (a row is never taken for a header).
pub fn read_csv_table(path: &str, csv: &str) -> Result<Table, InputError> {
    const NAMES: [&str; 2] = ["Mach", "value"];
    let mut columns: [Vec<f64>; 2] = Default::default();
    let mut lines_of_rows = Vec::new();
    let mut seen_first = false;
    let mut offset = 0;
    for (i, line) in csv.split_inclusive('\n').enumerate() {
        let (line_no, line_start) = (i + 1, offset);
        offset += line.len();
        let line = line.trim_end_matches(['\n', '\r']);
        let l = line.trim();
        if l.is_empty() || l.starts_with('#') {
            continue;
        }
        let cells = cells(line);
        if cells.len() != 2 {
            return Err(InputError::at_line(
                path,
                csv,
                line_no,
                format!("expected two columns (Mach, value), found {}", cells.len()),
            ));
        }
        let header = !seen_first && !cells.iter().any(|(c, _)| is_number(c));
        seen_first = true;
        if header {
            continue;
        }
        for (k, (cell, at)) in cells.into_iter().enumerate() {
            let start = line_start + at;
            let located = |m: String| {
                InputError::at(
                    path,
                    csv,
                    start..start + cell.len(),
                    format!("column {} ({})", k + 1, NAMES[k]),
                    m,
                )
            };
            let x = cell.parse::<f64>().map_err(|_| {
                let what = if cell.is_empty() {
                    "is empty".to_string()
                } else {
                    format!("`{}` is not a number", quote(cell))
                };
                located(format!(
                    "{what}; every row is two numbers, Mach and value (only a first line with no number in it is a header)"
                ))
            })?;
            columns[k].push(column_limit(NAMES[k]).check(x).map_err(located)?);
        }
        lines_of_rows.push(line_no);
    }
    let [mach, value] = columns;
    Table::new(mach, value).map_err(|e| {
        let line = match &e {
            AeroError::NotIncreasing { row, .. } | AeroError::NonFinite { row, .. } => {
                lines_of_rows.get(row - 1).copied().unwrap_or(0)
            }
            _ => 0,
        };
        InputError::at_line(path, csv, line, e.to_string())
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_header_is_skipped_and_a_table_without_one_is_used_whole() {
        let with = read_csv_table("t.csv", "mach,cd0\n0.5,0.01\n1.2,0.02\n").unwrap();
        let without = read_csv_table("t.csv", "0.5,0.01\n1.2,0.02\n").unwrap();
        assert_eq!(with, without);
        assert_eq!(with.range(), (0.5, 1.2));
    }

    #[test]
    fn a_bad_row_is_located() {
        let e = read_csv_table("t.csv", "mach,cd0\n0.5,0.01\n1.2,x\n").unwrap_err();
        assert!(
            e.to_string()
                .starts_with("t.csv:3:5: column 2 (value): `x` is not a number"),
            "{e}"
        );
        let e = read_csv_table("t.csv", "mach,cd0,extra\n0.5,0.01\n").unwrap_err();
        assert!(
            e.to_string().starts_with("t.csv:1:1: expected two columns"),
            "{e}"
        );
    }

    #[test]
    fn a_value_out_of_range_is_located_at_its_cell() {
        let e = read_csv_table("t.csv", "mach,cd0\n0.5,0.01\n1.2,-1e308\n").unwrap_err();
        assert!(
            e.to_string()
                .starts_with("t.csv:3:5: column 2 (value): a table's value must lie in [-1000000, 1000000], not -1e308"),
            "{e}"
        );
        let e = read_csv_table("t.csv", "-0.5,0.01\n1.2,0.02\n").unwrap_err();
        assert!(
            e.to_string().starts_with("t.csv:1:1: column 1 (Mach)"),
            "{e}"
        );
    }

    #[test]
    fn a_first_line_with_a_number_in_it_is_a_row_not_a_header() {
        for (text, at) in [
            (
                "0.5,2.6x\n1.2,0.02\n",
                "t.csv:1:5: column 2 (value): `2.6x`",
            ),
            ("O.5,2.6\n1.2,0.02\n", "t.csv:1:1: column 1 (Mach): `O.5`"),
            (
                "# c\r\n 0.5 , \r\n1.2,0.02\r\n",
                "t.csv:2:8: column 2 (value): is empty",
            ),
        ] {
            let e = read_csv_table("t.csv", text).unwrap_err();
            assert!(e.to_string().starts_with(at), "{text:?}: {e}");
        }
    }
}

#[cfg(test)]
mod derivative_table_tests {
    const BASE: &str = "[planform]\nsweep = 60.0\nroot_chord = 10.0\n[flight]\nmach = 0.9\ncg = 0.25\nmu1 = 50.0\ni_b = 0.08\ncl_m2 = 0.05\n[model.tables]\n";

    fn error(tables: &str) -> String {
        crate::config::parse("c.toml", &format!("{BASE}{tables}"))
            .unwrap_err()
            .to_string()
    }

    #[test]
    fn mode_and_cg_are_checked_and_located() {
        let e = error("m_q = { mach = [0.5, 1.0], value = [1.0, 1.0], mode = \"add\" }\n");
        assert!(
            e.starts_with("c.toml:11:") && e.contains("`value` or `increment`, not `add`"),
            "{e}"
        );
        let e = error("lift_slope = { mach = [0.5, 1.0], value = [3.0, 3.0], cg = 0.1 }\n");
        assert!(e.contains("belong to a derivative's table"), "{e}");
        let e = error("m_q = { mach = [0.5, 1.0], value = [1.0, 1.0], cg = 900.0 }\n");
        assert!(e.contains("[model.tables] m_q"), "{e}");
        let e = error(
            "z_wdot = { mach = [0.5, 1.0], value = [1.0, 1.0] }\n\"z_ẇ\" = { mach = [0.5, 1.0], value = [1.0, 1.0] }\n",
        );
        assert!(e.contains("two tables"), "{e}");
    }

    /// A value no coefficient or derivative reaches is refused at the
    /// table and its line, not where the design point overflows later.
    #[test]
    fn a_table_value_out_of_range_is_located_at_the_table() {
        for (table, field) in [
            (
                "m_q = { mach = [0.5, 2.0], values = [-1e308, -0.5] }",
                "[model.tables] m_q value[0]",
            ),
            (
                "lift_slope = { mach = [0.5, 2.0], value = [3.0, 1e7] }",
                "[model.tables] lift_slope value[1]",
            ),
            (
                "z_u = { mach = [0.5, 1e300], values = [0.1, 0.1], mode = \"increment\" }",
                "[model.tables] z_u mach[1]",
            ),
        ] {
            let e = error(&format!("{table}\n"));
            assert!(e.starts_with("c.toml:11:") && e.contains(field), "{e}");
            assert!(e.contains("must lie in"), "{e}");
        }
    }

    #[test]
    fn the_old_tables_and_the_new_are_read() {
        let c = crate::config::parse(
            "c.toml",
            &format!(
                "{BASE}lift_slope = {{ mach = [0.5, 1.0], value = [3.0, 3.2] }}\n\"m_ẇ\" = {{ mach = [0.5, 1.0], values = [-0.1, -0.1], mode = \"increment\", cg = 0.0 }}\n"
            ),
        )
        .unwrap();
        let d = &c.case.aero.derivatives.0;
        assert_eq!(d.len(), 1);
        assert_eq!(d[0].name, "m_wdot");
        assert_eq!(
            d[0].mode,
            stability_core::aerodynamics::models::derivative_tables::Mode::Increment
        );
        assert_eq!(d[0].reference_cg, Some(0.0));
        assert!(matches!(
            c.case.aero.lift_slope,
            stability_core::aerodynamics::models::aero::Source::Table(_)
        ));
    }
}
