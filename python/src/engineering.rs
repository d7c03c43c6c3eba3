//! What the command line's `--state-space` and `--write-derivatives` give,
//! for `Quartic` and `Analysis`: the linear model ẋ = A x + B δ,
//! y = C x + D δ of eqs (2)–(3) as numpy arrays (the same export, key for
//! key, as the JSON file `--state-space` writes: [`stability_io::state_space`]),
//! the roots in 1/s where τ is known, and the design point as a derivative
//! file (`analyze --write-derivatives`: [`stability_io::design_point::derivative_text`]).

use crate::errors::{argument, input_error};
use numpy::{Complex64, IntoPyArray, PyArray1, PyArray2};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use serde_json::Value;
use stability_core::criteria::cap::AirplaneClass;
use stability_core::dynamics::linear::Control;
use stability_core::dynamics::linear::LinearModel;
use stability_io::diag::InputError;
use stability_io::state_space::{Export, to_json};
use std::path::Path;

/// `--state-space`'s JSON of a model whose roots are `roots` (1/τ): the
/// state space in seconds where τ is known, else in τ.
pub fn export(
    source: &str,
    command: &str,
    model: &LinearModel,
    tau: Option<f64>,
    roots: [Complex64; 4],
) -> PyResult<Value> {
    let e = Export {
        source,
        command,
        model,
        tau,
        eigenvalues: tau.map_or(roots, |t| roots.map(|z| z / t)),
    };
    serde_json::from_str(&to_json(&e)).map_err(|e| PyTypeError::new_err(e.to_string()))
}

/// The roots in 1/s (the roots in 1/τ over τ), where τ is known.
pub fn roots_s<'py>(
    py: Python<'py>,
    roots: &[Complex64; 4],
    tau: Option<f64>,
) -> Option<Bound<'py, PyArray1<Complex64>>> {
    tau.map(|t| roots.map(|z| z / t).to_vec().into_pyarray(py))
}

/// The export as a dict, its matrices (`A`, `B`, `C`, `D`) as 2-D numpy
/// arrays (`B` and `D` None without a control) and `eigenvalues` a
/// complex array; the other keys as the JSON has them.
pub fn state_space<'py>(py: Python<'py>, json: &Value) -> PyResult<Bound<'py, PyDict>> {
    let out = crate::json::to_py(py, json)?.cast_into::<PyDict>()?;
    for key in ["A", "B", "C", "D"] {
        let rows: Option<Vec<Vec<f64>>> = serde_json::from_value(json[key].clone()).ok();
        match rows {
            Some(rows) if !rows.is_empty() => {
                let array = PyArray2::from_vec2(py, &rows)
                    .map_err(|e| PyTypeError::new_err(e.to_string()))?;
                out.set_item(key, array)?;
            }
            _ => out.set_item(key, py.None())?,
        }
    }
    let eigenvalues: Vec<Complex64> = json["eigenvalues"]
        .as_array()
        .map(|v| {
            v.iter()
                .map(|z| {
                    let part = |k: &str| z[k].as_f64().unwrap_or(f64::NAN);
                    Complex64::new(part("re"), part("im"))
                })
                .collect()
        })
        .unwrap_or_default();
    out.set_item("eigenvalues", eigenvalues.into_pyarray(py))?;
    Ok(out)
}

/// Writes `text`, a derivative file, to `out` — as `analyze
/// --write-derivatives` does: read back first (what is written is what
/// the reader takes), never over the config it came from, and into place
/// whole (a temporary file beside it, then renamed).
pub fn write_derivatives(
    out: &Path,
    text: &str,
    back: &stability_core::Derivatives,
    config: Option<&Path>,
) -> PyResult<()> {
    let name = out.display().to_string();
    let same = |a: &Path, b: &Path| matches!((a.canonicalize(), b.canonicalize()), (Ok(a), Ok(b)) if a == b);
    if config.is_some_and(|c| same(c, out)) {
        let m = "write_derivatives: this is the config the design point was read from; give another path";
        return Err(input_error(&InputError::file(&name, m)));
    }
    let read = stability_io::input::parse(&name, text).map_err(crate::errors::failure)?;
    if read.derivatives != *back {
        let m = "write_derivatives: the derivative file does not read back to the design point's set (a bug: please report it)";
        return Err(input_error(&InputError::file(&name, m)));
    }
    let file = out.file_name().map(|f| f.to_string_lossy().into_owned());
    let tmp = out.with_file_name(format!(
        ".{}.{}.tmp",
        file.unwrap_or_default(),
        std::process::id()
    ));
    let written = std::fs::write(&tmp, text).and_then(|()| std::fs::rename(&tmp, out));
    written.map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        let e = stability_io::files::write_error(out, &e);
        crate::errors::failure(stability_io::Failure::Io(e))
    })
}

/// The MIL-F-8785C airplane class given as `class_` (the command line's
/// `--class`: I, II-C, II-L, III or IV), if one was.
pub fn class(given: Option<&str>) -> PyResult<Option<AirplaneClass>> {
    given
        .map(|c| {
            AirplaneClass::parse(c).ok_or_else(|| {
                let names: Vec<&str> = AirplaneClass::ALL.iter().map(|c| c.name()).collect();
                argument(
                    "class_",
                    format!("`{c}` is not a class; one of {}", names.join(", ")),
                )
            })
        })
        .transpose()
}

/// The `[control]` table of the derivative file at `path`, as `quartic`
/// reads it (none for a set given as a dict or as quantities).
pub fn control(path: &str) -> PyResult<Option<Control>> {
    let file = Path::new(path);
    if !file.is_file() {
        return Ok(None);
    }
    let text = stability_io::files::read_input(file).map_err(crate::errors::failure)?;
    stability_io::control::read_control(path, &text).map_err(|e| input_error(&e))
}
