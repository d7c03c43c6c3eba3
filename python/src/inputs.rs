//! What a function is given, read by the command line's own readers: a
//! derivative set (a path to a TOML file, a dict of the same shape or a
//! flat one, keyword arguments, a `Derivatives`) and a design-point config
//! (a path or a dict). A dict is written as TOML and read as if it were the
//! file `<dict>`, so that every check, message and field name is the
//! command line's.

use crate::errors::failure;
use crate::json::{table, toml_text};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};
use stability_core::data::notation::{Notation, tables};
use stability_io::config::{self, Config};
use stability_io::input::{self, DerivativeFile, rows};

/// The name a dict is read under, in messages.
pub const DICT: &str = "<dict>";

/// The tables of a derivative file.
const TABLES: [&str; 5] = [
    "derivatives",
    "flight",
    "report",
    "parameters",
    "dimensional",
];
/// The keys of its `[dimensional]` table.
const DIMENSIONAL: [&str; 6] = ["V", "rho", "S", "chord", "mass", "I_y"];
/// Its top-level keys that are not tables.
const TOP: [&str; 2] = ["notation", "st_file"];

/// The table a flat key belongs in, in `notation`: its own derivative or
/// flight quantity, a report quantity it lacks (`[report]`), a parameter,
/// a dimensional quantity; else `[derivatives]`, where the reader names
/// it with the nearest valid name.
fn table_of(notation: Option<Notation>, key: &str) -> &'static str {
    if let Some(row) = notation.and_then(|n| n.row_of(key)) {
        return if rows::FLIGHT.contains(&row) {
            "flight"
        } else {
            "derivatives"
        };
    }
    if Notation::REPORT.row_of(key).is_some() {
        "report"
    } else if tables::PARAMETERS.contains(&key) {
        "parameters"
    } else if DIMENSIONAL.contains(&key) {
        "dimensional"
    } else {
        "derivatives"
    }
}

/// A derivative file's table from a dict that may be flat (`{"x_u": …,
/// "notation": "report"}`), nested as the TOML file is, or both.
fn nest(mut flat: toml::Table, notation: Option<&str>) -> toml::Table {
    if let Some(n) = notation {
        flat.entry("notation")
            .or_insert_with(|| toml::Value::String(n.to_string()));
    }
    flat.entry("notation")
        .or_insert_with(|| toml::Value::String("report".into()));
    let named = flat
        .get("notation")
        .and_then(|v| v.as_str())
        .and_then(Notation::named);
    let mut out = toml::Table::new();
    for (k, v) in flat {
        let nested = TOP.contains(&k.as_str()) || (TABLES.contains(&k.as_str()) && v.is_table());
        if nested {
            match (out.get_mut(&k), v) {
                (Some(toml::Value::Table(have)), toml::Value::Table(more)) => have.extend(more),
                (_, v) => {
                    out.insert(k, v);
                }
            }
        } else {
            let t = out
                .entry(table_of(named, &k))
                .or_insert_with(|| toml::Value::Table(toml::Table::new()));
            if let toml::Value::Table(t) = t {
                t.insert(k, v);
            }
        }
    }
    out
}

/// A path (str or os.PathLike), if `v` is one.
fn path_of(v: &Bound<'_, PyAny>) -> PyResult<Option<String>> {
    if let Ok(s) = v.cast::<PyString>() {
        return Ok(Some(s.extract::<String>()?));
    }
    if v.hasattr("__fspath__")? {
        let p = v.call_method0("__fspath__")?;
        return Ok(Some(p.extract::<String>()?));
    }
    Ok(None)
}

/// A derivative set from what a function was given: `source` (a path, a
/// dict or a `Derivatives`) and keyword arguments (quantities in the
/// notation `notation`, default the file's or the report's).
pub fn derivative_file(
    source: Option<&Bound<'_, PyAny>>,
    notation: Option<&str>,
    kwargs: Option<&Bound<'_, PyDict>>,
) -> PyResult<DerivativeFile> {
    let extra = match kwargs {
        Some(k) if !k.is_empty() => Some(table(k, "")?),
        _ => None,
    };
    let from_table = |t: toml::Table| -> PyResult<DerivativeFile> {
        let text = toml_text(&nest(t, notation))?;
        input::parse(DICT, &text).map_err(failure)
    };
    let Some(src) = source else {
        return match extra {
            Some(t) => from_table(t),
            None => Err(PyTypeError::new_err(
                "give a derivative set: a path to a TOML file, a dict, a Derivatives, or the quantities as keyword arguments",
            )),
        };
    };
    if let Ok(d) = src.cast::<crate::quartic::Derivatives>() {
        let mut t = d.get().report_table();
        if let Some(e) = extra {
            t.extend(e);
        }
        return from_table(t);
    }
    if let Ok(d) = src.cast::<PyDict>() {
        let mut t = table(d, "")?;
        if let Some(e) = extra {
            t.extend(e);
        }
        return from_table(t);
    }
    if let Some(path) = path_of(src)? {
        if extra.is_some() || notation.is_some() {
            return Err(PyTypeError::new_err(
                "a derivative file is read as it is: give either a path or the quantities, not both",
            ));
        }
        return input::read(&path).map_err(failure);
    }
    Err(PyTypeError::new_err(format!(
        "a derivative set is a path, a dict or a Derivatives, not {}",
        src.get_type().name()?
    )))
}

/// A design-point config: a path to a TOML file, or a dict of the same
/// shape (`{"planform": {…}, "flight": {…}, "model": {…}}`).
pub fn config(source: &Bound<'_, PyAny>) -> PyResult<Config> {
    if let Ok(d) = source.cast::<PyDict>() {
        let text = toml_text(&table(d, "")?)?;
        return config::parse(DICT, &text).map_err(failure);
    }
    if let Some(path) = path_of(source)? {
        return config::read(&path).map_err(failure);
    }
    Err(PyTypeError::new_err(format!(
        "a config is a path to a TOML file or a dict, not {}",
        source.get_type().name()?
    )))
}
