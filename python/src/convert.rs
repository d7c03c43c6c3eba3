//! `convert()`: a derivative set from one notation into another (the
//! appendix), as `delta-stability convert --json`.

use crate::errors::{argument, input_error};
use crate::guard;
use crate::inputs::derivative_file;
use crate::json::view_to_py;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use stability_core::data::notation::Notation;
use stability_io::convert::{ConvertJson, converted};
use stability_io::input::suggest::did_you_mean;

/// A derivative set converted into the notation `to` by the factors
/// derived from each author's definitions
/// (stability-core/specs/notation.toml; the report's appendix with its
/// misprints corrected, docs/errata.md): the
/// dict `delta-stability convert --from F --to T FILE --json` prints, with
/// `from`, `to`, `values` (T's names; None where the input does not
/// determine one), `report` (the report's values) and `parameters`.
///
/// The source is given as to `quartic()`, in its own notation (the file's
/// `notation`, or `notation=…`). Raises InputError with the command line's
/// message (a conversion that would overflow names the value it came from).
#[pyfunction]
#[pyo3(signature = (source=None, /, *, to, notation=None, **kwargs))]
pub fn convert<'py>(
    py: Python<'py>,
    source: Option<&Bound<'py, PyAny>>,
    to: &str,
    notation: Option<&str>,
    kwargs: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    guard(|| {
        let target = Notation::named(to).ok_or_else(|| {
            let names: Vec<&str> = Notation::all().map(Notation::name).collect();
            argument(
                "to",
                format!(
                    "unknown notation `{to}`{}; the notations are: {}",
                    did_you_mean(to, names.iter().copied()),
                    names.join(", ")
                ),
            )
        })?;
        let file = derivative_file(source, notation, kwargs)?;
        let values = converted(&file, target).map_err(|e| input_error(&e))?;
        view_to_py(
            py,
            &ConvertJson::new(&file, &file.notation, target, &values),
        )
    })
}

/// The notations a derivative set may be written in (`avl` is read only,
/// from AVL's .st output).
#[pyfunction]
pub fn notations() -> Vec<&'static str> {
    stability_io::input::notations()
}
