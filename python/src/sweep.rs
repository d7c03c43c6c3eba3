//! `sweep()`: the library's sweep ([`stability_core::design::sweep::Sweep`], the
//! grid `delta-stability sweep` evaluates) with the GIL released, into
//! columns — one numpy array each, named, ordered and computed as the
//! command line's CSV (from one table, [`columns::COLUMNS`]), with no text
//! in between. The axes are the library's ([`stability_io::sweep::axes`]:
//! ranges, lists or one value, each within its range).
//!
//! The grid, its order (mach, sweep_deg, cg, mu1, i_b, the last varying
//! fastest), the reuse of each point's aerodynamics across μ₁ and i_B, the
//! lifting surface solved once per planform and Mach number
//! ([`Sweep::prepare`]) and a frequency iteration's interpolation in its
//! frequency table (`Harmonic::Interpolated`) are the library's; so are a
//! physical flight condition's μ₁, i_B and C_L·M² per planform
//! ([`Sweep::with_flight`]).

use crate::errors::{argument, input_error};
use crate::guard;
use crate::overrides::{Model, overridden};
use numpy::IntoPyArray;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};
use stability_core::design::sweep::{Points, Sweep, SweepError};
use stability_io::config::Config;
use stability_io::diag;
use stability_io::sweep::columns::{self, Point, Value};
use stability_io::sweep::{Given, axes, parse_values};
use std::collections::HashMap;

/// The most points one call evaluates: every column is held in memory
/// (the command line streams its rows; its limit is the library's).
pub const MAX_POINTS: usize = 50_000_000;

/// An axis as given: a number, a sequence or array of numbers, or the
/// command line's "A:B:STEP".
fn axis(name: &str, v: &Bound<'_, PyAny>) -> PyResult<Vec<f64>> {
    if let Ok(s) = v.cast::<PyString>() {
        return parse_values(&s.extract::<String>()?).map_err(|e| argument(name, e));
    }
    if let Ok(x) = v.extract::<f64>() {
        return Ok(vec![x]);
    }
    let listed = if v.hasattr("tolist")? {
        v.call_method0("tolist")?
    } else {
        v.clone()
    };
    let values: Vec<f64> = listed.extract().map_err(|_| {
        argument(
            name,
            "expected a number, a sequence or 1-D array of numbers, or \"A:B:STEP\"",
        )
    })?;
    if values.is_empty() {
        return Err(argument(name, "the axis has no values"));
    }
    Ok(values)
}

/// The axes as given to `sweep()`.
pub struct AxisArgs<'a, 'py> {
    pub mach: Option<&'a Bound<'py, PyAny>>,
    pub sweep: Option<&'a Bound<'py, PyAny>>,
    pub cg: Option<&'a Bound<'py, PyAny>>,
    pub mu1: Option<&'a Bound<'py, PyAny>>,
    pub i_b: Option<&'a Bound<'py, PyAny>>,
    /// A physical flight condition's axes ([`NAMES`]' last three).
    pub altitude: Option<&'a Bound<'py, PyAny>>,
    pub mass: Option<&'a Bound<'py, PyAny>>,
    pub i_y: Option<&'a Bound<'py, PyAny>>,
}

/// The arguments' names, in the order of the library's axes (those of a
/// physical flight condition last: `altitude`, `mass`, `I_y`).
const NAMES: [&str; 8] = [
    "mach", "sweep", "cg", "mu1", "i_b", "altitude", "mass", "I_y",
];

/// Why the library cannot sweep the grid, as an InputError.
fn sweep_error(cfg: &Config, e: SweepError) -> PyErr {
    match e {
        SweepError::Empty { axis } => argument(axis, "the axis has no values"),
        SweepError::Planform { sweep_deg, error } => {
            argument("sweep", format!("{sweep_deg}: {error}"))
        }
        e => input_error(&diag::InputError::file(&cfg.path, e.to_string())),
    }
}

/// The library's sweep of the axes about the config's design point, at
/// its physical flight condition when it has one (which fixes μ₁ and
/// i_B: those axes may not be given, as on the command line); each axis
/// not given is the config's value.
pub fn sweep_of(a: &AxisArgs<'_, '_>, cfg: &Config) -> PyResult<Sweep> {
    let read = |k: usize, v: Option<&Bound<'_, PyAny>>| v.map(|v| axis(NAMES[k], v)).transpose();
    let given = Given {
        mach: read(0, a.mach)?,
        sweep_deg: read(1, a.sweep)?,
        cg: read(2, a.cg)?,
        mu1: read(3, a.mu1)?,
        i_b: read(4, a.i_b)?,
        altitude: read(5, a.altitude)?,
        mass: read(6, a.mass)?,
        i_y: read(7, a.i_y)?,
    };
    let axes = axes(given, &cfg.case, cfg.physical.is_some())
        .map_err(|e| argument(NAMES[e.axis], e.message))?;
    let n = shape(&axes)
        .iter()
        .try_fold(1usize, |n, len| n.checked_mul(*len));
    if n.is_none_or(|n| n > MAX_POINTS) {
        // the count bounded in length, however large the grid
        let points = stability_core::design::sweep::count(n, "points");
        let m = format!("the grid has {points}; the limit of one call is {MAX_POINTS:e}");
        return Err(argument("grid", m));
    }
    match &cfg.physical {
        Some(p) => Sweep::physical(cfg.case.clone(), axes, &p.condition),
        None => Sweep::new(cfg.case.clone(), axes),
    }
    .map_err(|e| sweep_error(cfg, e))
}

/// The grid's shape: the five axes of [`NAMES`], then the physical
/// flight condition's three where any of them is given (each the
/// condition's one value where it is not), the last varying fastest.
pub fn shape(a: &stability_core::design::sweep::Axes) -> Vec<usize> {
    let mut shape = vec![
        a.mach.len(),
        a.sweep_deg.len(),
        a.cg.len(),
        a.mu1.len(),
        a.i_b.len(),
    ];
    if a.has_flight_axes() {
        shape.extend([&a.altitude, &a.mass, &a.i_y].map(|v| v.len().max(1)));
    }
    shape
}

/// A column, as numpy takes it.
enum Array {
    Bool(Vec<bool>),
    /// An index into the column's words.
    Code(Vec<u16>),
    /// NaN where the command line leaves the cell empty.
    Float(Vec<f64>),
    /// An index into the messages, or −1 (no error).
    Message(Vec<i32>),
}

impl Array {
    fn into_py<'py>(self, py: Python<'py>) -> Bound<'py, PyAny> {
        match self {
            Array::Bool(v) => v.into_pyarray(py).into_any(),
            Array::Code(v) => v.into_pyarray(py).into_any(),
            Array::Float(v) => v.into_pyarray(py).into_any(),
            Array::Message(v) => v.into_pyarray(py).into_any(),
        }
    }
}

/// A sweep's results as columns, ready for numpy: those of the command
/// line's rows ([`columns::columns`]), in their order.
pub struct Columns {
    arrays: Vec<(&'static str, Array)>,
    /// The words each word column's codes index.
    words: Vec<(&'static str, Vec<&'static str>)>,
    messages: Vec<String>,
}

/// Evaluates every point (in parallel: [`Sweep::run`]) into columns.
pub fn evaluate(sweep: &Sweep, derivatives: bool) -> Columns {
    let points = sweep.run(derivatives);
    let n = points.len();
    let axis = &sweep.axes().sweep_deg;
    let sweep_deg: Vec<f64> = sweep.indices(0..n).map(|idx| axis[idx[1]]).collect();
    let (error, messages) = errors(&points);
    let flights: Vec<_> = (0..n)
        .map(|k| (error[k] < 0).then(|| sweep.flight_point(k)).flatten())
        .collect();
    let point = |k: usize| Point::new(&points, k, sweep_deg[k], flights[k]);
    let floats =
        |v: &dyn Fn(&Point<'_>) -> f64| Array::Float((0..n).map(|k| v(&point(k))).collect());
    let mut words = Vec::new();
    let physical = sweep.flights().is_some();
    let arrays = columns::columns(derivatives, physical)
        .map(|c| {
            let array = match c.value {
                Value::Grid(v) => floats(&v),
                Value::Number(v) => floats(&|p| v(p).unwrap_or(f64::NAN)),
                Value::Bool(v) => Array::Bool((0..n).map(|k| v(&point(k))).collect()),
                Value::Word(v) => {
                    let (codes, vocabulary) = encode((0..n).map(|k| v(&point(k))));
                    words.push((c.name, vocabulary));
                    Array::Code(codes)
                }
                Value::Error => Array::Message(error.clone()),
            };
            (c.name, array)
        })
        .collect();
    Columns {
        arrays,
        words,
        messages,
    }
}

/// Each point's error as an index into the distinct messages (−1: none).
fn errors(points: &Points) -> (Vec<i32>, Vec<String>) {
    let mut error = vec![-1; points.len()];
    let mut messages: Vec<String> = Vec::new();
    let mut seen: HashMap<String, i32> = HashMap::new();
    for (k, e) in &points.errors {
        let m = e.to_string();
        error[*k] = *seen.entry(m).or_insert_with_key(|m| {
            messages.push(m.clone());
            messages.len() as i32 - 1
        });
    }
    (error, messages)
}

/// Words as codes into their distinct values, in the order first seen.
fn encode(words: impl Iterator<Item = &'static str>) -> (Vec<u16>, Vec<&'static str>) {
    let mut vocabulary: Vec<&'static str> = Vec::new();
    let codes = words
        .map(|w| match vocabulary.iter().position(|v| *v == w) {
            Some(i) => i as u16,
            None => {
                vocabulary.push(w);
                vocabulary.len() as u16 - 1
            }
        })
        .collect();
    (codes, vocabulary)
}

/// The columns as a dict: each of `columns` (the CSV's names, in its
/// order) as an array, a word column (`verdict`) as codes into its list in
/// `words` (`verdict`'s also as `verdicts`, the older key), `error` as
/// codes into `messages` (−1: none); and the grid's `shape`.
fn to_dict<'py>(py: Python<'py>, c: Columns, shape: Vec<usize>) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    let mut names = Vec::with_capacity(c.arrays.len());
    for (name, array) in c.arrays {
        out.set_item(name, array.into_py(py))?;
        names.push(name);
    }
    out.set_item("columns", names)?;
    let words = PyDict::new(py);
    for (name, vocabulary) in c.words {
        if name == "verdict" {
            // the key before `words`: still decodes `verdict`'s codes
            out.set_item("verdicts", &vocabulary)?;
        }
        words.set_item(name, vocabulary)?;
    }
    out.set_item("words", words)?;
    out.set_item("messages", c.messages)?;
    out.set_item("shape", shape)?;
    Ok(out)
}

/// The sweep's columns, one line each (name, unit, meaning, the rows that
/// carry it): the table of the command line's columns
/// ([`columns::listing`]), for `SweepResult`'s docs.
#[pyfunction]
pub fn sweep_columns_doc() -> String {
    columns::listing("derivatives=True")
}

/// The sweep's columns as a dict of numpy arrays (see [`to_dict`]);
/// `delta_stability.sweep` decodes the verdicts and errors.
#[pyfunction]
#[pyo3(signature = (config, *, mach=None, sweep=None, cg=None, mu1=None, i_b=None, altitude=None, mass=None, i_y=None, damping=None, aero=None, omega_bar=None, derivatives=false, datcom=None, frequency_method=None))]
#[allow(clippy::too_many_arguments)]
pub fn sweep_columns<'py>(
    py: Python<'py>,
    config: &Bound<'py, PyAny>,
    mach: Option<&Bound<'py, PyAny>>,
    sweep: Option<&Bound<'py, PyAny>>,
    cg: Option<&Bound<'py, PyAny>>,
    mu1: Option<&Bound<'py, PyAny>>,
    i_b: Option<&Bound<'py, PyAny>>,
    altitude: Option<&Bound<'py, PyAny>>,
    mass: Option<&Bound<'py, PyAny>>,
    i_y: Option<&Bound<'py, PyAny>>,
    damping: Option<&str>,
    aero: Option<&str>,
    omega_bar: Option<f64>,
    derivatives: bool,
    datcom: Option<&str>,
    frequency_method: Option<&str>,
) -> PyResult<Bound<'py, PyDict>> {
    guard(|| {
        let model = Model {
            damping,
            aero,
            omega_bar,
            datcom,
            frequency_method,
        };
        let cfg = overridden(config, None, None, model)?;
        let axes = AxisArgs {
            mach,
            sweep,
            cg,
            mu1,
            i_b,
            altitude,
            mass,
            i_y,
        };
        let s = sweep_of(&axes, &cfg)?;
        let shape = shape(s.axes());
        // a panic in here unwinds through `detach`, which takes the GIL
        // back, to `guard`
        let columns = py.detach(|| evaluate(&s, derivatives));
        to_dict(py, columns, shape)
    })
}
