//! `--state-space FILE.json` (`quartic`, `analyze`): the export of
//! [`stability_io::state_space`] written, its three files as a set.

use crate::Failure;
use stability_io::diag::InputError;
use stability_io::files::write_error;
pub use stability_io::state_space::{Export, matlab_snippet, paths, python_snippet, to_json};

/// Writes the export as a set: the JSON and the two scripts written to
/// their temporary files first, then all renamed into place, so that a
/// failure leaves the three as they were. Every number is finite.
pub fn write(out: &str, e: &Export<'_>) -> Result<(), Failure> {
    let [json, py, m] = paths(out)?;
    if !e.model.is_finite() {
        return Err(InputError::file(
            e.source,
            "the state matrix overflows f64: no state space can be written",
        )
        .into());
    }
    stability_io::state_space::guard(e)?;
    let files = [
        (json.clone(), to_json(e).into_bytes()),
        (py.clone(), python_snippet(e).into_bytes()),
        (m.clone(), matlab_snippet(e).into_bytes()),
    ];
    crate::output::write_set(&files)
        .map_err(|(path, err)| Failure::Io(write_error(&path, &err)))?;
    crate::output::warn(&format!(
        "wrote the state space to {} (and {}, {})",
        json.display(),
        py.display(),
        m.display()
    ));
    Ok(())
}
