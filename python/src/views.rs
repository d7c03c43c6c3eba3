//! Python attributes read from the library's serde views: a class keeps
//! its result's JSON (the command line's `--json`, key for key) and
//! answers an attribute from a table of names and JSON paths, so that no
//! field is mirrored by hand and a key added to the library's view is one
//! line here.
//!
//! Each path says whether the JSON always has it ([`always`]) or leaves it
//! out where it does not apply ([`optional`]: a quantity in seconds when
//! τ is unknown, the flight condition of a non-dimensional one): only an
//! optional key that is absent gives `None`. A key that should be there
//! and is not — a key renamed in the library without its attribute — is a
//! `RuntimeError` naming the attribute and the key, never a silent `None`;
//! and tests/test_cli_agreement.py finds every path ([`json_attributes`])
//! in results that have all of them.

use crate::json::to_py;
use pyo3::exceptions::{PyAttributeError, PyRuntimeError};
use pyo3::prelude::*;
use serde_json::Value;

/// An attribute: its Python name, the path of keys to its value in the
/// JSON, and where the JSON may leave the path out (`None`: always there).
#[derive(Debug, Clone, Copy)]
pub struct Attr {
    pub name: &'static str,
    pub path: &'static [&'static str],
    pub optional: Option<&'static str>,
}

/// An attribute whose path the JSON always has (its value may be `null`).
pub const fn always(name: &'static str, path: &'static [&'static str]) -> Attr {
    Attr {
        name,
        path,
        optional: None,
    }
}

/// An attribute whose path the JSON leaves out where it does not apply:
/// present `when` (in words), `None` where absent.
pub const fn optional(
    name: &'static str,
    path: &'static [&'static str],
    when: &'static str,
) -> Attr {
    Attr {
        name,
        path,
        optional: Some(when),
    }
}

/// The value at `path` in `json`, if it has the path.
fn at<'j>(json: &'j Value, path: &[&str]) -> Option<&'j Value> {
    path.iter().try_fold(json, |v, k| v.get(k))
}

/// The attribute `name` of a class whose attributes are `attrs` over
/// `json`; an AttributeError naming the class when it has none, a
/// RuntimeError when the JSON lacks a path it always has.
pub fn getattr<'py>(
    py: Python<'py>,
    class: &str,
    json: &Value,
    attrs: &[Attr],
    name: &str,
) -> PyResult<Bound<'py, PyAny>> {
    let Some(attr) = attrs.iter().find(|a| a.name == name) else {
        return Err(PyAttributeError::new_err(format!(
            "'{class}' object has no attribute '{name}'"
        )));
    };
    match (at(json, attr.path), attr.optional) {
        (Some(v), _) => to_py(py, v),
        (None, Some(_)) => Ok(py.None().into_bound(py)),
        (None, None) => Err(PyRuntimeError::new_err(format!(
            "internal error in delta_stability (please report it): {class}.{name} reads the key `{}`, which the result does not have",
            attr.path.join(".")
        ))),
    }
}

/// The names of `attrs` with the class's own methods and attributes, for
/// `dir()`.
pub fn dir(attrs: &[Attr], own: &[&'static str]) -> Vec<&'static str> {
    let mut v: Vec<&str> = attrs.iter().map(|a| a.name).collect();
    v.extend(own);
    v.sort_unstable();
    v
}

/// Every class's attributes read from its JSON: (class, name, path, when
/// the path may be absent or `None`), for the test that each path is in
/// the results that have them all; not part of the API.
#[pyfunction]
#[pyo3(name = "_json_attributes")]
pub fn json_attributes() -> Vec<(
    &'static str,
    &'static str,
    Vec<&'static str>,
    Option<&'static str>,
)> {
    crate::quartic::ATTRIBUTES
        .iter()
        .flat_map(|(class, attrs)| {
            attrs
                .iter()
                .map(move |a| (*class, a.name, a.path.to_vec(), a.optional))
        })
        .collect()
}
