//! `uncertainty()`: the config's `[uncertainty]` study
//! ([`stability_io::config::uncertainty`]) run by the library
//! ([`stability_core::uncertainty`]) at each Mach number, with the GIL
//! released — what `delta-stability uncertainty` computes, as its JSON
//! and its long CSV (which the package's `uncertainty()` turns into a
//! pandas DataFrame).

use crate::errors::{argument, failure, input_error};
use crate::guard;
use crate::overrides::{Model, overridden};
use pyo3::prelude::*;
use stability_core::uncertainty::{Options, Sampling};
use stability_io::diag::InputError;
use stability_io::sweep::parse_values;
use stability_io::uncertainty::{CSV_HEADER, UncertaintyJson, csv_rows};

/// The study of `config` (a path or a dict with an `uncertainty` table) at
/// the Mach numbers `mach` ("A:B:STEP", a list or one value): `samples`
/// a Mach number, `seed`, with `sobol` the Sobol indices, and `sampling`
/// "random" or "sobol" (Owen-scrambled Sobol′ points; default: the
/// config's `sampling`, else random). Returns the
/// JSON (a str, `delta-stability uncertainty --json`'s) and the long CSV
/// (mach, quantity, value, low, high).
#[pyfunction]
#[pyo3(signature = (config, /, *, mach, samples=10_000, seed=1, sobol=false, damping=None, aero=None, omega_bar=None, sampling=None, datcom=None, frequency_method=None))]
#[allow(clippy::too_many_arguments)] // the keywords of the Python function
pub fn uncertainty_run(
    py: Python<'_>,
    config: &Bound<'_, PyAny>,
    mach: &Bound<'_, PyAny>,
    samples: u64,
    seed: u64,
    sobol: bool,
    damping: Option<&str>,
    aero: Option<&str>,
    omega_bar: Option<f64>,
    sampling: Option<&str>,
    datcom: Option<&str>,
    frequency_method: Option<&str>,
) -> PyResult<(String, String)> {
    guard(|| {
        let machs: Vec<f64> = match mach.extract::<String>() {
            Ok(s) => parse_values(&s).map_err(|e| argument("mach", e))?,
            Err(_) => match mach.extract::<f64>() {
                Ok(m) => vec![m],
                Err(_) => mach
                    .extract()
                    .map_err(|_| argument("mach", "a number, a list of numbers or \"A:B:STEP\""))?,
            },
        };
        stability_io::limits::machs(&machs).map_err(|e| argument("mach", e))?;
        if samples == 0 {
            return Err(argument("samples", "at least one sample"));
        }
        let model = Model {
            damping,
            aero,
            omega_bar,
            datcom,
            frequency_method,
        };
        let cfg = overridden(config, None, None, model)?;
        let study = stability_io::config::uncertainty::read(&cfg)
            .map_err(failure)?
            .ok_or_else(|| {
                input_error(&InputError::file(
                    &cfg.path,
                    "the config has no [uncertainty] table: give a distribution for an input, e.g. {\"uncertainty\": {\"i_b\": {\"dist\": \"normal\", \"relative_sd\": 0.1}}}",
                ))
            })?;
        let sampling = match sampling {
            Some(name) => Sampling::parse(name)
                .ok_or_else(|| argument("sampling", "\"random\" or \"sobol\""))?,
            None => stability_io::config::uncertainty::sampling(&cfg)
                .map_err(failure)?
                .unwrap_or_default(),
        };
        let options = Options {
            samples,
            seed,
            sobol,
            sampling,
        };
        let results = py.detach(|| study.run(&machs, &options, &|_| {}));
        let view = UncertaintyJson::new(&cfg.path, &study, &options, &results)
            .checked()
            .map_err(|e| input_error(&e))?;
        let json = serde_json::to_string(&view)
            .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))?;
        let mut csv = format!("{CSV_HEADER}\n");
        results.iter().for_each(|r| csv.push_str(&csv_rows(r)));
        Ok((json, csv))
    })
}
