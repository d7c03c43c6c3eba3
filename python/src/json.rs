//! Between Python objects and the library's serde views: a JSON value as
//! Python objects (what `to_dict()` returns, key for key the command
//! line's `--json`), and a Python dict as TOML (what the readers parse).

use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyList, PyString};
use serde_json::Value;

/// A JSON value as Python objects: null → None, numbers → float (int for
/// integers), objects → dict, arrays → list.
pub fn to_py<'py>(py: Python<'py>, v: &Value) -> PyResult<Bound<'py, PyAny>> {
    Ok(match v {
        Value::Null => py.None().into_bound(py),
        Value::Bool(b) => PyBool::new(py, *b).to_owned().into_any(),
        Value::Number(n) => match (n.as_i64(), n.as_u64()) {
            (Some(i), _) => i.into_pyobject(py)?.into_any(),
            (None, Some(u)) => u.into_pyobject(py)?.into_any(),
            _ => n.as_f64().unwrap_or(f64::NAN).into_pyobject(py)?.into_any(),
        },
        Value::String(s) => PyString::new(py, s).into_any(),
        Value::Array(a) => {
            let items = a
                .iter()
                .map(|x| to_py(py, x))
                .collect::<PyResult<Vec<_>>>()?;
            PyList::new(py, items)?.into_any()
        }
        Value::Object(o) => {
            let d = PyDict::new(py);
            for (k, x) in o {
                d.set_item(k, to_py(py, x)?)?;
            }
            d.into_any()
        }
    })
}

/// A serializable view as Python objects.
pub fn view_to_py<'py>(
    py: Python<'py>,
    view: &impl serde::Serialize,
) -> PyResult<Bound<'py, PyAny>> {
    let v = serde_json::to_value(view).map_err(|e| {
        pyo3::exceptions::PyRuntimeError::new_err(format!("cannot serialize a result: {e}"))
    })?;
    to_py(py, &v)
}

/// A Python value as TOML: bool, int and float (ints become floats: every
/// number the readers take is one), str, dict (a table), and list, tuple
/// or numpy array (an array). `at` names the key, for errors.
pub fn to_toml(v: &Bound<'_, PyAny>, at: &str) -> PyResult<toml::Value> {
    if let Ok(b) = v.cast::<PyBool>() {
        return Ok(toml::Value::Boolean(b.is_true()));
    }
    if let Ok(s) = v.cast::<PyString>() {
        return Ok(toml::Value::String(s.extract::<String>()?));
    }
    if let Ok(d) = v.cast::<PyDict>() {
        return Ok(toml::Value::Table(table(d, at)?));
    }
    if let Ok(x) = v.extract::<f64>() {
        return Ok(toml::Value::Float(x));
    }
    let listed = if v.hasattr("tolist")? {
        v.call_method0("tolist")?
    } else {
        v.clone()
    };
    if let Ok(items) = listed.extract::<Vec<Bound<'_, PyAny>>>() {
        let values = items
            .iter()
            .enumerate()
            .map(|(i, x)| to_toml(x, &format!("{at}[{i}]")))
            .collect::<PyResult<Vec<_>>>()?;
        return Ok(toml::Value::Array(values));
    }
    Err(PyTypeError::new_err(format!(
        "{at}: expected a number, a string, a bool, a list or a dict, not {}",
        v.get_type().name()?
    )))
}

/// A Python dict as a TOML table (keys must be strings).
pub fn table(d: &Bound<'_, PyDict>, at: &str) -> PyResult<toml::Table> {
    let mut t = toml::Table::new();
    for (k, v) in d.iter() {
        let key: String = k.extract().map_err(|_| {
            PyTypeError::new_err(format!(
                "{at}: keys must be strings, not {}",
                k.get_type()
                    .name()
                    .map(|n| n.to_string())
                    .unwrap_or_default()
            ))
        })?;
        let here = if at.is_empty() {
            key.clone()
        } else {
            format!("{at}.{key}")
        };
        t.insert(key, to_toml(&v, &here)?);
    }
    Ok(t)
}

/// A table as TOML text.
pub fn toml_text(t: &toml::Table) -> PyResult<String> {
    toml::to_string(t)
        .map_err(|e| PyTypeError::new_err(format!("cannot write the dict as TOML: {e}")))
}
