//! `response()`: the longitudinal response of §11, as
//! `delta-stability response` computes it, into numpy arrays.

use crate::errors::{argument, input_error};
use crate::guard;
use crate::inputs::derivative_file;
use numpy::IntoPyArray;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use stability_core::dynamics::response::{Computed, MAX_STEPS};
use stability_io::input::DerivativeFile;
use stability_io::input::suggest::did_you_mean;
use stability_io::response::{Asked, Disturbance, Style, respond};

/// The longitudinal response (§11) of a derivative set to an elevon step
/// (`input="step"`, the moment m₀ from rest) or to an initial disturbance
/// (`input="initial"`, ŵ = w0), solved exactly from the state-space form of
/// eqs (2): the matrix exponential of the augmented system sampled at
/// `steps + 1` times from 0 to `until` (units of τ) or `until_s` (seconds,
/// where τ is known: a set with `[dimensional]`, or a physical flight
/// condition). For a step it also gives the report's two-degree-of-freedom
/// closed form, eqs (44)–(45); `elevator_deg` makes the step a deflection
/// of the file's `[control]` in degrees (its force and moment derivatives)
/// instead of m0 (default 1); `w0` defaults to 0.01. The options are the
/// command line's (`--until-s`, `--elevator-deg`), checked by the same
/// code.
///
/// `neglect_zq_zwdot` sets z_q = z_ẇ = 0 (Fig 38); `neglect_u` holds
/// û = 0 (two degrees of freedom). The derivative set is given as to
/// `quartic()`. Returns a dict of numpy arrays named as the command line's
/// CSV columns: t_hat, t_s (when τ is known), u_hat, w_hat (= the incidence
/// change, rad), q_hat, theta (rad), w_hat_eq45 (step only), gamma
/// (= θ − ŵ, rad) and n_z (the normal load factor at the c.g.,
/// (q̂ − dŵ/dt̂)/C_L; where C_L > 0). Raises
/// InputError with the command line's message (e.g. a response that
/// overflows before `until`).
#[pyfunction]
#[pyo3(signature = (source=None, /, *, until=None, input="step", steps=400, m0=None, w0=None, neglect_zq_zwdot=false, neglect_u=false, notation=None, until_s=None, elevator_deg=None, **kwargs))]
#[allow(clippy::too_many_arguments)]
pub fn response<'py>(
    py: Python<'py>,
    source: Option<&Bound<'py, PyAny>>,
    until: Option<f64>,
    input: &str,
    steps: usize,
    m0: Option<f64>,
    w0: Option<f64>,
    neglect_zq_zwdot: bool,
    neglect_u: bool,
    notation: Option<&str>,
    until_s: Option<f64>,
    elevator_deg: Option<f64>,
    kwargs: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    guard(|| {
        let file = derivative_file(source, notation, kwargs)?;
        let control = crate::engineering::control(&file.path)?;
        let asked = Asked {
            input: disturbance(input)?,
            until: checked("until", until, true)?,
            until_s: checked("until_s", until_s, true)?,
            steps: checked_steps(steps)?,
            m0: checked("m0", m0, false)?,
            w0: checked("w0", w0, false)?,
            elevator_deg: checked("elevator_deg", elevator_deg, false)?,
            neglect_zq_zwdot,
            neglect_u,
            style: Style::Keywords,
        };
        if asked.until.is_some() && asked.until_s.is_some() {
            return Err(argument(
                "until_s",
                "give until (units of τ) or until_s (seconds), not both",
            ));
        }
        if asked.m0.is_some() && asked.elevator_deg.is_some() {
            return Err(argument(
                "elevator_deg",
                "give m0 or elevator_deg, not both",
            ));
        }
        let spec = asked
            .spec(&file, control.as_ref())
            .map_err(|e| input_error(&e))?;
        let r = py
            .detach(|| respond(&file, &spec))
            .map_err(|e| input_error(&e))?;
        columns(py, &file, r)
    })
}

/// The input named `input`.
fn disturbance(input: &str) -> PyResult<Disturbance> {
    Disturbance::parse(input).ok_or_else(|| {
        let hint = did_you_mean(input, ["step", "initial"]);
        argument(
            "input",
            format!("`{input}` is neither `step` nor `initial`{hint}"),
        )
    })
}

/// `value`, finite (and positive for a span), as the command line's
/// parser checks its options.
fn checked(name: &str, value: Option<f64>, positive: bool) -> PyResult<Option<f64>> {
    match value {
        Some(v) if !v.is_finite() => {
            Err(argument(name, format!("must be a finite number, not {v}")))
        }
        Some(v) if positive && v <= 0.0 => Err(argument(
            name,
            format!("must be positive and finite, not {v}"),
        )),
        v => Ok(v),
    }
}

fn checked_steps(steps: usize) -> PyResult<usize> {
    if steps == 0 || steps > MAX_STEPS {
        return Err(argument(
            "steps",
            format!("must lie between 1 and {MAX_STEPS}, not {steps}"),
        ));
    }
    Ok(steps)
}

/// The response's samples as columns of numpy arrays (the CSV's names).
fn columns<'py>(
    py: Python<'py>,
    file: &DerivativeFile,
    r: Computed,
) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    let column = |f: fn(&stability_core::dynamics::response::Sample) -> f64| -> Vec<f64> {
        r.samples.iter().map(f).collect()
    };
    out.set_item("t_hat", column(|s| s.t).into_pyarray(py))?;
    if let Some(tau) = file.tau() {
        let t: Vec<f64> = r.samples.iter().map(|s| s.t * tau).collect();
        out.set_item("t_s", t.into_pyarray(py))?;
    }
    out.set_item("u_hat", column(|s| s.u).into_pyarray(py))?;
    out.set_item("w_hat", column(|s| s.w).into_pyarray(py))?;
    out.set_item("q_hat", column(|s| s.q).into_pyarray(py))?;
    out.set_item("theta", column(|s| s.theta).into_pyarray(py))?;
    if let Some(w) = r.eq45 {
        out.set_item("w_hat_eq45", w.into_pyarray(py))?;
    }
    out.set_item("gamma", column(|s| s.theta - s.w).into_pyarray(py))?;
    if let Some(n) = r.n_z {
        out.set_item("n_z", n.into_pyarray(py))?;
    }
    Ok(out)
}
