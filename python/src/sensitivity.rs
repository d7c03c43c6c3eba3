//! `sensitivity()`: how a mode's root moves with each derivative (§10).

use crate::errors::argument;
use crate::guard;
use crate::inputs::derivative_file;
use numpy::IntoPyArray;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use stability_core::dynamics::modes::ModeName;
use stability_core::dynamics::sensitivity::mode_sensitivities;
use stability_io::input::suggest::did_you_mean;

/// The sensitivity of a mode's root λ = r + is to each of the fifteen
/// quartic inputs p (Derivatives.NAMES): the question of §10, which
/// derivative drives the damping. By implicit differentiation of
/// P(λ(p); p) = 0, dλ/dp = −(Σₖ ∂cₖ/∂p·λ^(4−k))/P′(λ), with the exact
/// gradient ∂cₖ/∂p of the generated expansion of eq (4).
///
/// `mode` is `short_period` or `phugoid`. Returns a dict of numpy arrays,
/// ranked by |p·∂r/∂p| (largest first): `input` (names), `value` (p),
/// `d_re`, `d_im` (∂r/∂p, ∂s/∂p, 1/τ per unit p), `d_damping_ratio`,
/// `d_cycles_to_half` (NaN unless the mode is a decaying oscillation) and
/// `damping_drive` (p·∂r/∂p). The derivative set is given as to
/// `quartic()`. Raises InputError when the mode does not oscillate or its
/// root is multiple.
#[pyfunction]
#[pyo3(signature = (source=None, /, *, mode="short_period", notation=None, **kwargs))]
pub fn sensitivity<'py>(
    py: Python<'py>,
    source: Option<&Bound<'py, PyAny>>,
    mode: &str,
    notation: Option<&str>,
    kwargs: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    guard(|| {
        let file = derivative_file(source, notation, kwargs)?;
        let a = file
            .analysis()
            .map_err(|e| crate::errors::input_error(&e))?;
        let name = match mode {
            "short_period" => ModeName::ShortPeriod,
            "phugoid" => ModeName::Phugoid,
            other => {
                let hint = did_you_mean(other, ["short_period", "phugoid"]);
                return Err(argument(
                    "mode",
                    format!("`{other}` is neither `short_period` nor `phugoid`{hint}"),
                ));
            }
        };
        let m = a.modes.iter().find(|m| m.name == name).ok_or_else(|| {
            argument(
                "mode",
                format!("this derivative set has no oscillatory {mode} mode"),
            )
        })?;
        let s = mode_sensitivities(&file.derivatives, m).ok_or_else(|| {
            argument(
                "mode",
                format!("the {mode} root is multiple: λ is not differentiable"),
            )
        })?;
        let out = PyDict::new(py);
        let col =
            |f: fn(&stability_core::dynamics::sensitivity::ModeSensitivity) -> f64| -> Vec<f64> {
                s.iter().map(f).collect()
            };
        out.set_item("input", s.iter().map(|x| x.input).collect::<Vec<_>>())?;
        out.set_item("value", col(|x| x.value).into_pyarray(py))?;
        out.set_item("d_re", col(|x| x.d_re).into_pyarray(py))?;
        out.set_item("d_im", col(|x| x.d_im).into_pyarray(py))?;
        out.set_item(
            "d_damping_ratio",
            col(|x| x.d_damping_ratio).into_pyarray(py),
        )?;
        out.set_item(
            "d_cycles_to_half",
            col(|x| x.d_cycles_to_half.unwrap_or(f64::NAN)).into_pyarray(py),
        )?;
        out.set_item("damping_drive", col(|x| x.damping_drive).into_pyarray(py))?;
        Ok(out)
    })
}
