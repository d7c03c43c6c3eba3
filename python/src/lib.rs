//! `delta_stability._native`: the Python extension module of the
//! `delta_stability` package (PyO3). The package's `__init__.py` re-exports
//! it and adds the pure-Python conveniences (the sweep's `to_pandas`, the
//! array shapes of `batch_roots`).
//!
//! Every function called from Python runs inside [`guard`]: a Rust panic
//! becomes a Python `RuntimeError`, never an abort or a `PanicException`
//! (which `except Exception` would not catch). Bad input raises
//! [`InputError`] (a `ValueError`) with the command line's message: file,
//! line, column and field. Long computations release the GIL
//! ([`Python::detach`]).

use pyo3::prelude::*;

mod convert;
mod engineering;
mod errors;
mod inputs;
mod json;
mod overrides;
mod quartic;
mod report;
mod response;
mod roots;
mod sensitivity;
mod size_tail;
mod sweep;
mod theories;
mod uncertainty;
mod views;

pub use errors::InputError;

/// The module.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    // as the command line does: the note's wings' Mach box and near-sonic
    // solutions, solved ahead of time, into the store (a cache checked by
    // the solvers' fingerprints; a stale file is refused whole)
    let _ = stability_study::study::preload();
    m.add("InputError", py.get_type::<InputError>())?;
    m.add_class::<quartic::Derivatives>()?;
    m.add_class::<quartic::Mode>()?;
    m.add_class::<quartic::Quartic>()?;
    m.add_class::<quartic::Analysis>()?;
    m.add_function(wrap_pyfunction!(quartic::quartic, m)?)?;
    m.add_function(wrap_pyfunction!(quartic::analyze, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep_columns, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep_columns_doc, m)?)?;
    m.add_function(wrap_pyfunction!(roots::batch_roots, m)?)?;
    m.add_function(wrap_pyfunction!(response::response, m)?)?;
    m.add_function(wrap_pyfunction!(convert::convert, m)?)?;
    m.add_function(wrap_pyfunction!(convert::notations, m)?)?;
    m.add_function(wrap_pyfunction!(sensitivity::sensitivity, m)?)?;
    m.add_function(wrap_pyfunction!(size_tail::size_tail, m)?)?;
    m.add_function(wrap_pyfunction!(theories::damping_derivatives, m)?)?;
    m.add_function(wrap_pyfunction!(theories::theories, m)?)?;
    m.add_function(wrap_pyfunction!(theories::damping_models, m)?)?;
    m.add_function(wrap_pyfunction!(theories::aero_models, m)?)?;
    m.add_function(wrap_pyfunction!(theories::lifting_surface, m)?)?;
    m.add_function(wrap_pyfunction!(uncertainty::uncertainty_run, m)?)?;
    m.add_function(wrap_pyfunction!(report::report_run, m)?)?;
    m.add_function(wrap_pyfunction!(panic_for_tests, m)?)?;
    m.add_function(wrap_pyfunction!(views::json_attributes, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}

/// Runs `f`, turning a Rust panic into a Python `RuntimeError` that says
/// it is a bug (no panic crosses the FFI boundary).
pub fn guard<T>(f: impl FnOnce() -> PyResult<T>) -> PyResult<T> {
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)) {
        Ok(r) => r,
        Err(payload) => {
            let what = payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "a panic".into());
            Err(pyo3::exceptions::PyRuntimeError::new_err(format!(
                "internal error in delta_stability (please report it, with the input): {what}"
            )))
        }
    }
}

/// Panics inside [`guard`], for the test that no panic crosses the FFI
/// boundary (tests/test_errors.py); not part of the API.
#[pyfunction]
#[pyo3(name = "_panic_for_tests")]
fn panic_for_tests(py: Python<'_>) -> PyResult<()> {
    guard(|| {
        let fail = std::hint::black_box(true);
        py.detach(|| {
            if fail {
                panic!("a deliberate panic, for the tests")
            }
        });
        Ok(())
    })
}
