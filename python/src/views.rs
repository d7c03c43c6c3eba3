//! Python attributes read from the library's serde views: a class keeps
//! its result's JSON (the command line's `--json`, key for key) and
//! answers an attribute from a table of names and JSON paths, so that no
//! field is mirrored by hand and a key added to the library's view is one
//! line here. `None` where the path is absent (a quantity undefined, or in
//! seconds when τ is unknown).

use crate::json::to_py;
use pyo3::exceptions::PyAttributeError;
use pyo3::prelude::*;
use serde_json::Value;

/// An attribute: its Python name and the path of keys to its value in the
/// JSON.
pub type Attr = (&'static str, &'static [&'static str]);

/// The value at `path` in `json`, or `Null`.
fn at<'j>(json: &'j Value, path: &[&str]) -> &'j Value {
    path.iter()
        .try_fold(json, |v, k| v.get(k))
        .unwrap_or(&Value::Null)
}

/// The attribute `name` of a class whose attributes are `attrs` over
/// `json`; an AttributeError naming the class when it has none.
pub fn getattr<'py>(
    py: Python<'py>,
    class: &str,
    json: &Value,
    attrs: &[Attr],
    name: &str,
) -> PyResult<Bound<'py, PyAny>> {
    match attrs.iter().find(|(n, _)| *n == name) {
        Some((_, path)) => to_py(py, at(json, path)),
        None => Err(PyAttributeError::new_err(format!(
            "'{class}' object has no attribute '{name}'"
        ))),
    }
}

/// The names of `attrs` with the class's own methods and attributes, for
/// `dir()`.
pub fn dir(attrs: &[Attr], own: &[&'static str]) -> Vec<&'static str> {
    let mut v: Vec<&str> = attrs.iter().map(|(n, _)| *n).collect();
    v.extend(own);
    v.sort_unstable();
    v
}

/// Attributes named as their key at the top level.
macro_rules! keys {
    ($($k:literal),* $(,)?) => { &[$(($k, &[$k])),*] };
}
pub(crate) use keys;
