//! `--state-space FILE.json` (`quartic`, `analyze`): the export of
//! [`stability_io::state_space`] written, its three files as a set.

use crate::Failure;
use crate::output::atomic_write;
use stability_io::diag::InputError;
use stability_io::files::write_error;
pub use stability_io::state_space::{Export, matlab_snippet, paths, python_snippet, to_json};

/// Writes the export: the JSON, then the two scripts, each atomically.
pub fn write(out: &str, e: &Export<'_>) -> Result<(), Failure> {
    let [json, py, m] = paths(out)?;
    if !e.model.is_finite() {
        return Err(InputError::file(
            e.source,
            "the state matrix overflows f64: no state space can be written",
        )
        .into());
    }
    for (path, text) in [
        (&json, to_json(e)),
        (&py, python_snippet(e)),
        (&m, matlab_snippet(e)),
    ] {
        atomic_write(path, text.as_bytes()).map_err(|err| Failure::Io(write_error(path, &err)))?;
    }
    crate::output::warn(&format!(
        "wrote the state space to {} (and {}, {})",
        json.display(),
        py.display(),
        m.display()
    ));
    Ok(())
}
