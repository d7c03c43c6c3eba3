//! The command line's failures as Python exceptions: bad input (exit
//! status 2) is [`InputError`], a `ValueError` whose message is the one the
//! command line prints after `error: `, with the file, line, column and
//! field as attributes; a file that cannot be read (exit status 3) is an
//! `OSError` (`FileNotFoundError` when it does not exist).

use pyo3::exceptions::{PyFileNotFoundError, PyOSError, PyValueError};
use pyo3::prelude::*;
use stability_io::Failure;
use stability_io::diag;

pyo3::create_exception!(
    delta_stability,
    InputError,
    PyValueError,
    "Bad input: a file's or a dict's content, or an argument's value.\n\n\
     The message is the command line's (`file:line:column: field: message`, \
     the offending line and a caret). Attributes: `file`, `line` and \
     `column` (0 when the error is about the whole input), `field` (e.g. \
     `[derivatives] m_q`, or empty) and `message` (the message alone)."
);

/// An input error of the command line's readers as an [`InputError`].
pub fn input_error(e: &diag::InputError) -> PyErr {
    Python::attach(|py| {
        let err = InputError::new_err(e.to_string());
        let v = err.value(py);
        let set = |k: &str, x: Bound<'_, PyAny>| v.setattr(k, x);
        let attrs = (|| -> PyResult<()> {
            set("file", e.file.clone().into_pyobject(py)?.into_any())?;
            set("line", e.line.into_pyobject(py)?.into_any())?;
            set("column", e.column.into_pyobject(py)?.into_any())?;
            set("field", e.field.clone().into_pyobject(py)?.into_any())?;
            set("message", e.message.clone().into_pyobject(py)?.into_any())
        })();
        match attrs {
            Ok(()) => err,
            Err(other) => other,
        }
    })
}

/// A failure of the command line's library as a Python exception.
pub fn failure(f: Failure) -> PyErr {
    match f {
        Failure::Input(e) => input_error(&e),
        Failure::Io(e) => {
            if std::path::Path::new(&e.path).exists() {
                PyOSError::new_err(e.to_string())
            } else {
                PyFileNotFoundError::new_err(e.to_string())
            }
        }
    }
}

/// An input error about an argument (no file): `name: message`.
pub fn argument(name: &str, message: impl std::fmt::Display) -> PyErr {
    input_error(&diag::InputError {
        field: name.to_string(),
        ..diag::InputError::file("<arguments>", message.to_string())
    })
}
