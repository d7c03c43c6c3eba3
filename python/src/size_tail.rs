//! `size_tail(config, …)`: `delta-stability size-tail` — the smallest
//! tailplane (or foreplane) of the config's shape meeting the §8 standard
//! at every Mach number ([`stability_core::design::sizing`]).

use crate::errors::{argument, failure};
use crate::guard;
use crate::overrides::{Model, overridden};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use stability_core::design::sizing::size_surface;
use stability_core::geometry::configuration::SurfaceKind;
use stability_io::diag::InputError;

/// The smallest area of the config's `[tailplane]` (or, with
/// `surface="foreplane"`, its `[foreplane]`) — sweep, taper, aspect ratio
/// and apex held, every length scaled by √(area ratio) — at which the
/// design point meets the §8 one-cycle standard (every root judged) at
/// every Mach number of `mach` (a list; default 0.5 to 2.0 in steps of
/// 0.05), searched up to `max_area` (default: the wing's area) by a scan
/// then bisection. Returns a dict with the command's `--json` keys:
/// `surface`, `area` (None: no area up to the limit meets; 0: the wing
/// alone does), `given_area`, `limit`, `volume` (V̄ = S_T·l/(S·c̄), l from
/// the c.g. to the surface's M.A.C. quarter chord) and `outcomes`
/// ([{mach, verdict, cycles_to_half, error}] at the area found, or at the
/// limit). `damping`, `aero`, `omega_bar`, `datcom` override the config as
/// in `analyze`.
#[pyfunction]
#[pyo3(signature = (config, /, *, mach=None, surface="tailplane", max_area=None, damping=None, aero=None, omega_bar=None, datcom=None, frequency_method=None))]
#[allow(clippy::too_many_arguments)]
pub fn size_tail<'py>(
    py: Python<'py>,
    config: &Bound<'py, PyAny>,
    mach: Option<Vec<f64>>,
    surface: &str,
    max_area: Option<f64>,
    damping: Option<&str>,
    aero: Option<&str>,
    omega_bar: Option<f64>,
    datcom: Option<&str>,
    frequency_method: Option<&str>,
) -> PyResult<Bound<'py, PyAny>> {
    guard(|| {
        let model = Model {
            damping,
            aero,
            omega_bar,
            datcom,
            frequency_method,
        };
        let cfg = overridden(config, None, None, model)?;
        let kind = match surface {
            "tailplane" => SurfaceKind::Tailplane,
            "foreplane" => SurfaceKind::Foreplane,
            other => {
                return Err(argument(
                    "surface",
                    format!("`{other}` is not a surface: give \"tailplane\" or \"foreplane\""),
                ));
            }
        };
        let machs = mach.unwrap_or_else(|| (0..=30).map(|i| 0.5 + 0.05 * i as f64).collect());
        stability_io::limits::machs(&machs).map_err(|e| argument("mach", e))?;
        if let Some(a) = max_area {
            stability_io::limits::SIZE
                .check(a)
                .map_err(|e| argument("max_area", e))?;
        }
        let sizing = py
            .detach(|| size_surface(&cfg.case, kind, &machs, max_area))
            .map_err(|e| failure(InputError::file(&cfg.path, e.to_string()).into()))?;
        let json =
            serde_json::to_value(&sizing).map_err(|e| PyTypeError::new_err(e.to_string()))?;
        crate::json::to_py(py, &json)
    })
}
