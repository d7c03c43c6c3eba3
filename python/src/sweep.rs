//! `sweep()`: design points over a Cartesian grid of Mach number, sweep,
//! c.g., μ₁ and i_B, in parallel with the GIL released, into columns (one
//! numpy array each) — the columns of `delta-stability sweep`'s CSV, with
//! no text in between.
//!
//! The grid is the command line's: its axes in the order mach, sweep_deg,
//! cg, mu1, i_b, the last varying fastest; each point takes the lean path
//! (`case::evaluate_point`, no eq 7 check); consecutive points that differ
//! in μ₁ and i_B only share their aerodynamics
//! (`DampingModel::depends_on_mass`).

use crate::errors::argument;
use crate::guard;
use crate::quartic::overridden;
use delta_stability::cmd::sweep::parse_range;
use delta_stability::config::limits::{self, Limit};
use numpy::IntoPyArray;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};
use rayon::prelude::*;
use stability_core::Derivatives;
use stability_core::analysis::Analysis;
use stability_core::case::{Case, CaseResult, evaluate_point};
use stability_core::criteria::Verdict;
use stability_core::geometry::{Planform, Size};

/// The most points one call evaluates (each holds 11 to 26 numbers).
pub const MAX_POINTS: usize = 50_000_000;

/// The float columns of every point, in order.
const FLOATS: [&str; 9] = [
    "sp_re",
    "sp_im",
    "sp_cycles_to_half",
    "sp_damping_ratio",
    "sp_omega_bar",
    "ph_re",
    "ph_im",
    "m_thetadot",
    "delta_m_thetadot",
];

/// The grid's axes, in output order; the last varies fastest.
struct Grid {
    axes: [Vec<f64>; 5],
    planforms: Vec<Planform>,
    base: Case,
}

impl Grid {
    fn dims(&self) -> [usize; 5] {
        std::array::from_fn(|k| self.axes[k].len())
    }

    fn points(&self) -> Option<usize> {
        self.dims()
            .iter()
            .try_fold(1usize, |a, &d| a.checked_mul(d))
    }

    /// The grid index of point `i`.
    fn index(&self, mut i: usize) -> [usize; 5] {
        let dims = self.dims();
        let mut idx = [0; 5];
        for d in (0..5).rev() {
            idx[d] = i % dims[d];
            i /= dims[d];
        }
        idx
    }

    /// Makes `case` point `idx`.
    fn set(&self, idx: [usize; 5], case: &mut Case) {
        case.mach = self.axes[0][idx[0]];
        case.planform = self.planforms[idx[1]];
        case.h = self.axes[2][idx[2]];
        case.mu1 = self.axes[3][idx[3]];
        case.i_b = self.axes[4][idx[4]];
    }
}

/// An axis as given: None (the config's value), a number, a sequence or
/// array of numbers, or the command line's "A:B:STEP".
fn axis(name: &str, v: Option<&Bound<'_, PyAny>>, base: f64) -> PyResult<Vec<f64>> {
    let Some(v) = v else { return Ok(vec![base]) };
    if let Ok(s) = v.cast::<PyString>() {
        return parse_range(name, &s.extract::<String>()?)
            .map_err(|e| argument(name, e.replacen("--", "", 1)));
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

fn within(name: &str, v: Vec<f64>, limit: &Limit) -> PyResult<Vec<f64>> {
    for &x in &v {
        limit.check(x).map_err(|e| argument(name, e))?;
    }
    Ok(v)
}

struct Axes<'a, 'py> {
    mach: Option<&'a Bound<'py, PyAny>>,
    sweep: Option<&'a Bound<'py, PyAny>>,
    cg: Option<&'a Bound<'py, PyAny>>,
    mu1: Option<&'a Bound<'py, PyAny>>,
    i_b: Option<&'a Bound<'py, PyAny>>,
}

fn grid(a: &Axes<'_, '_>, base: Case) -> PyResult<Grid> {
    let mach = within("mach", axis("mach", a.mach, base.mach)?, &limits::MACH)?;
    let sweep_deg = axis("sweep", a.sweep, base.planform.sweep_le.to_degrees())?;
    let cg = within("cg", axis("cg", a.cg, base.h)?, &limits::CG)?;
    let mu1 = within("mu1", axis("mu1", a.mu1, base.mu1)?, &limits::MU1)?;
    let i_b = within("i_b", axis("i_b", a.i_b, base.i_b)?, &limits::I_B)?;
    let mut planforms = Vec::with_capacity(sweep_deg.len());
    for &s in &sweep_deg {
        let p = Planform::new(s.to_radians(), base.planform.taper, Size::RootChord(1.0))
            .map_err(|e| argument("sweep", format!("{s}: {e}")))?;
        planforms.push(Planform {
            sweep_le: p.sweep_le,
            ..base.planform
        });
    }
    let g = Grid {
        axes: [mach, sweep_deg, cg, mu1, i_b],
        planforms,
        base,
    };
    match g.points() {
        Some(n) if n <= MAX_POINTS => Ok(g),
        Some(n) => Err(argument(
            "grid",
            format!("the grid has {n} points; the limit of one call is {MAX_POINTS:e}"),
        )),
        None => Err(argument("grid", "the grid is too large")),
    }
}

/// The columns, preallocated; each block of points writes its own slices.
struct Columns {
    floats: Vec<Vec<f64>>,
    stable: Vec<bool>,
    /// 0 meets, 1 fails, 2 divergent, 3 no result.
    verdict: Vec<u8>,
    /// An index into `messages`, or −1.
    error: Vec<i32>,
}

/// One block's slices of every column.
struct Block<'a> {
    start: usize,
    floats: Vec<&'a mut [f64]>,
    stable: &'a mut [bool],
    verdict: &'a mut [u8],
    error: &'a mut [i32],
    messages: Vec<String>,
}

/// Whether every number a point's row would carry is finite (the command
/// line writes a point whose numbers overflow as an error).
fn finite(d: &Derivatives, a: &Analysis) -> bool {
    d.quartic_input_values().iter().all(|v| v.is_finite())
        && a.quartic.to_array().iter().all(|v| v.is_finite())
        && a.roots.iter().all(|z| z.re.is_finite() && z.im.is_finite())
        && a.routh.discriminant.is_finite()
        && a.damping_standard.m_thetadot.is_finite()
}

const OVERFLOW: &str = "the design point's numbers overflow f64";

impl Block<'_> {
    fn error_at(&mut self, k: usize, message: String) {
        let at = match self.messages.iter().position(|m| *m == message) {
            Some(i) => i,
            None => {
                self.messages.push(message);
                self.messages.len() - 1
            }
        };
        self.error[k] = at as i32;
        self.verdict[k] = 3;
        for c in self.floats.iter_mut() {
            c[k] = f64::NAN;
        }
    }

    fn write(&mut self, k: usize, d: &Derivatives, a: &Analysis) {
        if !finite(d, a) {
            return self.error_at(k, OVERFLOW.into());
        }
        let sp = a.modes.short_period();
        let ph = a.modes.phugoid();
        let nan = f64::NAN;
        let values = [
            sp.map_or(nan, |m| m.re),
            sp.map_or(nan, |m| m.im),
            sp.and_then(|m| m.cycles_to_half).unwrap_or(nan),
            sp.and_then(|m| m.damping_ratio).unwrap_or(nan),
            sp.and_then(|m| m.frequency_parameter).unwrap_or(nan),
            ph.map_or(nan, |m| m.re),
            ph.map_or(nan, |m| m.im),
            a.damping_standard.m_thetadot,
            a.damping_standard.margin.unwrap_or(nan),
        ];
        let inputs = d.quartic_input_values();
        for (c, v) in self.floats.iter_mut().zip(values.iter().chain(&inputs)) {
            c[k] = *v;
        }
        self.stable[k] = a.routh.stable;
        // the index into `verdicts` (see `sweep_columns`)
        self.verdict[k] = match a.verdict {
            Verdict::Meets => 0,
            Verdict::Fails => 1,
            Verdict::Divergent => 2,
        };
        self.error[k] = -1;
    }

    /// Evaluates the block's points.
    fn run(&mut self, grid: &Grid) {
        let per_aero = grid.axes[3].len() * grid.axes[4].len();
        let reuse = !grid.base.damping.depends_on_mass();
        let mut last: Option<(usize, CaseResult)> = None;
        let mut case = grid.base.clone();
        for k in 0..self.stable.len() {
            let i = self.start + k;
            grid.set(grid.index(i), &mut case);
            let key = i / per_aero;
            match &last {
                Some((at, r)) if reuse && *at == key => {
                    let d = Derivatives {
                        mu1: case.mu1,
                        i_b: case.i_b,
                        ..r.derivatives
                    };
                    match Analysis::without_classical(&d) {
                        Ok(a) => self.write(k, &d, &a),
                        Err(e) => self.error_at(k, e.to_string()),
                    }
                }
                _ => match evaluate_point(&case) {
                    Ok(r) => {
                        self.write(k, &r.derivatives, &r.analysis);
                        last = Some((key, r));
                    }
                    Err(e) => self.error_at(k, e.to_string()),
                },
            }
        }
    }
}

/// Evaluates the grid into columns, in parallel; the messages the error
/// column indexes.
fn evaluate(grid: &Grid, with_derivatives: bool) -> (Columns, Vec<String>) {
    const BLOCK: usize = 1 << 10;
    let n = grid.points().unwrap_or(0);
    let n_floats = FLOATS.len() + if with_derivatives { 15 } else { 0 };
    let mut cols = Columns {
        floats: (0..n_floats).map(|_| vec![0.0; n]).collect(),
        stable: vec![false; n],
        verdict: vec![3; n],
        error: vec![-1; n],
    };
    let n_blocks = n.div_ceil(BLOCK);
    let mut floats: Vec<Vec<&mut [f64]>> = (0..n_blocks).map(|_| Vec::new()).collect();
    for c in cols.floats.iter_mut() {
        for (b, chunk) in c.chunks_mut(BLOCK).enumerate() {
            floats[b].push(chunk);
        }
    }
    let blocks: Vec<Block<'_>> = floats
        .into_iter()
        .zip(cols.stable.chunks_mut(BLOCK))
        .zip(cols.verdict.chunks_mut(BLOCK))
        .zip(cols.error.chunks_mut(BLOCK))
        .enumerate()
        .map(|(b, (((floats, stable), verdict), error))| Block {
            start: b * BLOCK,
            floats,
            stable,
            verdict,
            error,
            messages: Vec::new(),
        })
        .collect();
    let block_messages: Vec<Vec<String>> = blocks
        .into_par_iter()
        .map(|mut b| {
            b.run(grid);
            b.messages
        })
        .collect();
    // one list of messages: renumber each block's indices into it
    let mut messages: Vec<String> = Vec::new();
    for (b, local) in block_messages.into_iter().enumerate() {
        if local.is_empty() {
            continue;
        }
        let map: Vec<i32> = local
            .into_iter()
            .map(|m| match messages.iter().position(|x| *x == m) {
                Some(i) => i as i32,
                None => {
                    messages.push(m);
                    messages.len() as i32 - 1
                }
            })
            .collect();
        let end = ((b + 1) * BLOCK).min(n);
        for e in cols.error[b * BLOCK..end].iter_mut() {
            if *e >= 0 {
                *e = map[*e as usize];
            }
        }
    }
    (cols, messages)
}

/// The grid's values of each point (the head columns).
fn head(grid: &Grid) -> Vec<Vec<f64>> {
    let n = grid.points().unwrap_or(0);
    let mut out: Vec<Vec<f64>> = (0..5).map(|_| Vec::with_capacity(n)).collect();
    for i in 0..n {
        let idx = grid.index(i);
        for k in 0..5 {
            out[k].push(grid.axes[k][idx[k]]);
        }
    }
    out
}

/// The sweep's columns as a dict of numpy arrays: the grid values, the
/// float columns, `stable`, `verdict_code` (0 meets, 1 fails, 2
/// divergent, 3 no result), `error_code` (−1 or an index into
/// `messages`) and `messages`. `delta_stability.sweep` wraps it.
#[pyfunction]
#[pyo3(signature = (config, *, mach=None, sweep=None, cg=None, mu1=None, i_b=None, damping=None, derivatives=false))]
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
    derivatives: bool,
) -> PyResult<Bound<'py, PyDict>> {
    guard(|| {
        let cfg = overridden(config, None, None, damping)?;
        let axes = Axes {
            mach,
            sweep,
            cg,
            mu1,
            i_b,
        };
        let grid = grid(&axes, cfg.case)?;
        let shape = grid.dims().to_vec();
        // a panic in here unwinds through `detach`, which takes the GIL
        // back, to `guard`
        let (head, (cols, messages)) =
            py.detach(|| rayon::join(|| head(&grid), || evaluate(&grid, derivatives)));
        let out = PyDict::new(py);
        for (name, v) in ["mach", "sweep_deg", "cg", "mu1", "i_b"].iter().zip(head) {
            out.set_item(name, v.into_pyarray(py))?;
        }
        let names = FLOATS.iter().chain(if derivatives {
            Derivatives::QUARTIC_INPUTS.as_slice()
        } else {
            &[]
        });
        for (name, v) in names.zip(cols.floats) {
            out.set_item(name, v.into_pyarray(py))?;
        }
        out.set_item("stable", cols.stable.into_pyarray(py))?;
        out.set_item("verdict_code", cols.verdict.into_pyarray(py))?;
        out.set_item("error_code", cols.error.into_pyarray(py))?;
        out.set_item("messages", messages)?;
        out.set_item("shape", shape)?;
        let verdicts = [Verdict::Meets, Verdict::Fails, Verdict::Divergent];
        out.set_item("verdicts", verdicts.map(Verdict::as_str))?;
        Ok(out)
    })
}
