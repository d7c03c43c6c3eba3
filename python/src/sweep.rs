//! `sweep()`: the library's sweep ([`stability_core::sweep::Sweep`], the
//! grid `delta-stability sweep` evaluates) with the GIL released, into
//! columns — one numpy array each, named and ordered as the command
//! line's CSV ([`stability_core::sweep::columns`]), with no text in
//! between. The axes are the library's ([`stability_io::sweep::axes`]:
//! ranges, lists or one value, each within its range).
//!
//! The grid, its order (mach, sweep_deg, cg, mu1, i_b, the last varying
//! fastest), the reuse of each point's aerodynamics across μ₁ and i_B, the
//! lifting surface solved once per planform and Mach number
//! ([`Sweep::prepare`]) and a frequency iteration's interpolation in its
//! frequency table (`Harmonic::Interpolated`) are the library's; so are a
//! physical flight condition's μ₁, i_B and C_L·M² per planform
//! ([`Sweep::with_flight`]). The modes in seconds at such a condition are
//! the library's columns ([`Points::seconds`]).

use crate::errors::{argument, input_error};
use crate::guard;
use crate::overrides::{Model, overridden};
use numpy::IntoPyArray;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};
use stability_core::Derivatives;
use stability_core::criteria::Verdict;
use stability_core::sweep::{
    Cell, Points, RESULT_COLUMNS, SECONDS_COLUMNS, Sweep, SweepError, columns,
};
use stability_io::config::Config;
use stability_io::diag;
use stability_io::sweep::{Given, axes, parse_values};
use std::collections::HashMap;

/// The most points one call evaluates: every column is held in memory
/// (the command line streams its rows; its limit is the library's).
pub const MAX_POINTS: usize = 50_000_000;

/// The verdicts the `verdict` codes index (the code 3: no result).
const VERDICTS: [Verdict; 3] = [Verdict::Meets, Verdict::Fails, Verdict::Divergent];

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
        ..Given::default()
    };
    let axes = axes(given, &cfg.case, cfg.physical.is_some())
        .map_err(|e| argument(NAMES[e.axis], e.message))?;
    let n = [&axes.mach, &axes.sweep_deg, &axes.cg, &axes.mu1, &axes.i_b]
        .iter()
        .try_fold(1usize, |n, v| n.checked_mul(v.len()));
    if n.is_none_or(|n| n > MAX_POINTS) {
        // the count bounded in length, however large the grid
        let points = stability_core::sweep::count(n, "points");
        let m = format!("the grid has {points}; the limit of one call is {MAX_POINTS:e}");
        return Err(argument("grid", m));
    }
    match &cfg.physical {
        Some(p) => Sweep::physical(cfg.case.clone(), axes, &p.condition),
        None => Sweep::new(cfg.case.clone(), axes),
    }
    .map_err(|e| sweep_error(cfg, e))
}

/// A column of results, as numpy takes it.
enum Column {
    Bool(Vec<bool>),
    /// An index into [`VERDICTS`], or 3 (no result).
    Code(Vec<u8>),
    /// NaN where the command line leaves the cell empty.
    Float(Vec<f64>),
}

impl Column {
    fn push(&mut self, cell: Cell) {
        match (self, cell) {
            (Column::Bool(v), Cell::Bool(b)) => v.push(b),
            (Column::Code(v), Cell::Word(w)) => v.push(verdict_code(w)),
            (Column::Float(v), Cell::Number(x)) => v.push(x.unwrap_or(f64::NAN)),
            _ => unreachable!("a column's cells are of one kind"),
        }
    }

    fn of(cell: Cell, n: usize) -> Column {
        match cell {
            Cell::Bool(_) => Column::Bool(Vec::with_capacity(n)),
            Cell::Word(_) => Column::Code(Vec::with_capacity(n)),
            Cell::Number(_) => Column::Float(Vec::with_capacity(n)),
        }
    }

    fn into_py<'py>(self, py: Python<'py>) -> Bound<'py, PyAny> {
        match self {
            Column::Bool(v) => v.into_pyarray(py).into_any(),
            Column::Code(v) => v.into_pyarray(py).into_any(),
            Column::Float(v) => v.into_pyarray(py).into_any(),
        }
    }
}

/// A sweep's results as columns, ready for numpy.
pub struct Columns {
    points: Points,
    /// The sweep axis's values as given (the library's `sweep_deg` is the
    /// planform's, converted back from radians).
    sweep_deg: Vec<f64>,
    /// [`RESULT_COLUMNS`], then at a physical flight condition
    /// [`SECONDS_COLUMNS`], by name.
    results: Vec<(&'static str, Column)>,
    /// An index into `messages`, or −1.
    error: Vec<i32>,
    messages: Vec<String>,
    physical: bool,
}

/// Evaluates every point (in parallel: [`Sweep::run`]) into columns.
pub fn evaluate(sweep: &Sweep, derivatives: bool) -> Columns {
    let points = sweep.run(derivatives);
    let n = points.len();
    let axis = &sweep.axes().sweep_deg;
    let sweep_deg = sweep.indices(0..n).map(|idx| axis[idx[1]]).collect();
    let mut error = vec![-1; n];
    let mut messages: Vec<String> = Vec::new();
    let mut seen: HashMap<String, i32> = HashMap::new();
    for (k, e) in &points.errors {
        let m = e.to_string();
        error[*k] = *seen.entry(m).or_insert_with_key(|m| {
            messages.push(m.clone());
            messages.len() as i32 - 1
        });
    }
    let physical = sweep.flights().is_some();
    let results = results(sweep, &points, &error);
    Columns {
        points,
        sweep_deg,
        results,
        error,
        messages,
        physical,
    }
}

/// Every point's [`Points::results`] (and at a physical flight condition
/// its [`Points::seconds`]), as the command line writes them, by column.
fn results(sweep: &Sweep, points: &Points, error: &[i32]) -> Vec<(&'static str, Column)> {
    let n = points.len();
    let mut columns: Vec<(&'static str, Column)> = Vec::new();
    for (k, e) in error.iter().enumerate() {
        let point = (*e < 0).then(|| sweep.flight_point(k)).flatten();
        let cells = points.results(k, point.map(|p| p.tau));
        let seconds = sweep
            .flights()
            .map(|_| points.seconds(k, point).map(Cell::Number));
        let names = RESULT_COLUMNS.iter().chain(SECONDS_COLUMNS.iter());
        let row = cells.into_iter().chain(seconds.into_iter().flatten());
        for (j, (name, cell)) in names.zip(row).enumerate() {
            if k == 0 {
                columns.push((name, Column::of(cell, n)));
            }
            columns[j].1.push(cell);
        }
    }
    columns
}

/// The index of the verdict `word` in [`VERDICTS`]; 3 for none.
fn verdict_code(word: &str) -> u8 {
    let at = VERDICTS.iter().position(|v| v.as_str() == word);
    at.map_or(3, |k| k as u8)
}

/// The grid's float column `name` of the library's points (moved out), if
/// it is one of them.
fn grid_column(p: &mut Points, name: &str) -> Option<Vec<f64>> {
    let c = match name {
        "mach" => &mut p.mach,
        "cg" => &mut p.cg,
        "mu1" => &mut p.mu1,
        "i_b" => &mut p.i_b,
        "altitude" => &mut p.altitude,
        "mass" => &mut p.mass,
        "I_y" => &mut p.i_y,
        _ => return None,
    };
    Some(std::mem::take(c))
}

/// The fifteen quartic inputs as columns (in the order of
/// `Derivatives::QUARTIC_INPUTS`).
fn derivative_columns(p: &Points) -> Vec<Vec<f64>> {
    let Some(ds) = &p.derivatives else {
        return Vec::new();
    };
    let mut out: Vec<Vec<f64>> = (0..15).map(|_| Vec::with_capacity(ds.len())).collect();
    for d in ds {
        for (c, v) in out.iter_mut().zip(d.quartic_input_values()) {
            c.push(v);
        }
    }
    out
}

/// The columns as a dict: each of `columns` (the CSV's names, in its
/// order) as an array, `verdict`, `standard` and `error` as codes into
/// `verdicts` and `messages`; and the grid's `shape`.
fn to_dict<'py>(py: Python<'py>, c: Columns, shape: Vec<usize>) -> PyResult<Bound<'py, PyDict>> {
    let Columns {
        mut points,
        sweep_deg,
        results,
        error,
        messages,
        physical,
    } = c;
    let names = columns(points.derivatives.is_some(), physical);
    let mut arrays: HashMap<&str, Bound<'py, PyAny>> = HashMap::new();
    let mut put = |name: &'static str, a: Bound<'py, PyAny>| {
        arrays.entry(name).or_insert(a);
    };
    put("sweep_deg", sweep_deg.into_pyarray(py).into_any());
    put("error", error.into_pyarray(py).into_any());
    for name in &names {
        if let Some(v) = grid_column(&mut points, name) {
            put(name, v.into_pyarray(py).into_any());
        }
    }
    for (name, column) in results {
        put(name, column.into_py(py));
    }
    let inputs = Derivatives::QUARTIC_INPUTS;
    for (name, v) in inputs.into_iter().zip(derivative_columns(&points)) {
        put(name, v.into_pyarray(py).into_any());
    }
    let out = PyDict::new(py);
    let mut columns = Vec::with_capacity(names.len());
    for name in names {
        if let Some(a) = arrays.remove(name) {
            out.set_item(name, a)?;
            columns.push(name);
        }
    }
    out.set_item("columns", columns)?;
    out.set_item("verdicts", VERDICTS.map(Verdict::as_str))?;
    out.set_item("messages", messages)?;
    out.set_item("shape", shape)?;
    Ok(out)
}

/// The sweep's columns as a dict of numpy arrays (see [`to_dict`]);
/// `delta_stability.sweep` decodes the verdicts and errors.
#[pyfunction]
#[pyo3(signature = (config, *, mach=None, sweep=None, cg=None, mu1=None, i_b=None, damping=None, aero=None, omega_bar=None, derivatives=false, datcom=None))]
#[allow(clippy::too_many_arguments)]
pub fn sweep_columns<'py>(
    py: Python<'py>,
    config: &Bound<'py, PyAny>,
    mach: Option<&Bound<'py, PyAny>>,
    sweep: Option<&Bound<'py, PyAny>>,
    cg: Option<&Bound<'py, PyAny>>,
    mu1: Option<&Bound<'py, PyAny>>,
    i_b: Option<&Bound<'py, PyAny>>,
    damping: Option<&str>,
    aero: Option<&str>,
    omega_bar: Option<f64>,
    derivatives: bool,
    datcom: Option<&str>,
) -> PyResult<Bound<'py, PyDict>> {
    guard(|| {
        let model = Model {
            damping,
            aero,
            omega_bar,
            datcom,
        };
        let cfg = overridden(config, None, None, model)?;
        let axes = AxisArgs {
            mach,
            sweep,
            cg,
            mu1,
            i_b,
        };
        let s = sweep_of(&axes, &cfg)?;
        let a = s.axes();
        let shape = vec![
            a.mach.len(),
            a.sweep_deg.len(),
            a.cg.len(),
            a.mu1.len(),
            a.i_b.len(),
        ];
        // a panic in here unwinds through `detach`, which takes the GIL
        // back, to `guard`
        let columns = py.detach(|| evaluate(&s, derivatives));
        to_dict(py, columns, shape)
    })
}
