//! The user's aerodynamic tables (`[model.tables]`): inline
//! (`mach = [...]`, `value = [...]`) or a two-column CSV file (Mach,
//! value). A CSV file's first line is a header when it is not two numbers;
//! a file without a header is used whole.

use super::raw::RawTable;
use crate::Failure;
use crate::diag::{InputError, quote};
use stability_core::aero::{AeroError, Table};
use std::path::Path;
use toml::Spanned;

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
            Ok(Table::new(m.clone(), v.clone()).map_err(|e| at(e.to_string()))?)
        }
        (None, None, Some(f)) => {
            let file = Path::new(path)
                .parent()
                .unwrap_or(Path::new("."))
                .join(f.get_ref());
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

/// A line's two columns, or `None` when it has not two.
fn columns(line: &str) -> Option<[&str; 2]> {
    let cols: Vec<&str> = line.split(',').map(str::trim).collect();
    <[&str; 2]>::try_from(cols).ok()
}

fn both_numbers(cols: [&str; 2]) -> bool {
    cols.iter().all(|c| c.parse::<f64>().is_ok())
}

/// A two-column CSV table (Mach, value), with a header line or without;
/// errors name the file and line.
pub fn read_csv_table(path: &str, csv: &str) -> Result<Table, InputError> {
    let mut mach = Vec::new();
    let mut value = Vec::new();
    let mut lines_of_rows = Vec::new();
    let mut seen_first = false;
    for (i, line) in csv.lines().enumerate() {
        let line_no = i + 1;
        let l = line.trim();
        if l.is_empty() || l.starts_with('#') {
            continue;
        }
        let bad = |m: String| InputError::at_line(path, csv, line_no, m);
        let cols = columns(l).ok_or_else(|| {
            bad(format!(
                "expected two columns (Mach, value), found {}",
                l.split(',').count()
            ))
        })?;
        let header = !seen_first && !both_numbers(cols);
        seen_first = true;
        if header {
            continue;
        }
        let number = |c: &str| {
            c.parse::<f64>()
                .map_err(|_| bad(format!("`{}` is not a number", quote(c))))
        };
        mach.push(number(cols[0])?);
        value.push(number(cols[1])?);
        lines_of_rows.push(line_no);
    }
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
            e.to_string().starts_with("t.csv:3:1: `x` is not a number"),
            "{e}"
        );
        let e = read_csv_table("t.csv", "mach,cd0,extra\n0.5,0.01\n").unwrap_err();
        assert!(
            e.to_string().starts_with("t.csv:1:1: expected two columns"),
            "{e}"
        );
    }
}
