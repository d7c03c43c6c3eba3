//! A sweep as the front ends ask for it: the axes from ranges
//! (`A:B:STEP`, a list `A,B,…`, or one value) or the base design point's
//! values, each within its range ([`crate::limits`]); the grid; and its
//! rows as CSV or JSON ([`crate::format::Table`]), in the columns of one
//! table ([`columns::COLUMNS`]), numbers in their shortest round-trip
//! form.
//!
//! The computation is the library's ([`stability_core::design::sweep`]).

use crate::config::physical::Physical;
use crate::limits::{self, Limit};
use stability_core::aerodynamics::models::aero::{Source, TableOrigin};
use stability_core::design::case::Case;
use stability_core::design::sweep::{Axes, PointError, Sweep, SweepError};
use stability_core::numerics::display::{Num, sig};
use stability_core::numerics::grid;

pub mod columns;

use crate::format::{Record, Repeated, Table};
pub use columns::{Column, Point, Value};

/// The most values one range may have.
pub const MAX_RANGE_VALUES: usize = 10_000_000;

/// Values from their text: a range `A:B:STEP` (inclusive; the values
/// `A + k·STEP` rounded to the decimals they stand for, [`grid::grid`]), a
/// list `A,B,…`, or a single value `A`. The message names nothing: the
/// caller says which option or argument it was.
pub fn parse_values(text: &str) -> Result<Vec<f64>, String> {
    let num = |s: &str| {
        s.trim()
            .parse::<f64>()
            .ok()
            .filter(|x| x.is_finite())
            .ok_or_else(|| format!("`{}` is not a finite number", crate::diag::quote(s)))
    };
    if text.contains(',') {
        return text.split(',').map(num).collect();
    }
    let parts: Vec<&str> = text.split(':').collect();
    match parts.as_slice() {
        [a] => Ok(vec![num(a)?]),
        [a, b, step] => {
            let (a, b, step) = (num(a)?, num(b)?, num(step)?);
            if step <= 0.0 {
                return Err(format!("the step must be positive, not {}", Num(step)));
            }
            if b < a {
                return Err(format!(
                    "the range {}:{} runs backwards (write the smaller value first)",
                    Num(a),
                    Num(b)
                ));
            }
            let n = ((b - a) / step).floor() + 1.0;
            if n.is_nan() || n > MAX_RANGE_VALUES as f64 {
                // never the count's 301 digits, nor `inf`
                let many = if n.is_finite() {
                    format!("about {} values", sig(n, 3))
                } else {
                    "more values than can be counted".to_string()
                };
                return Err(format!(
                    "too many values: {}:{}:{} gives {many}, and a range has at most 1e7; take a larger step",
                    Num(a),
                    Num(b),
                    Num(step)
                ));
            }
            Ok(grid::grid(a, b, step))
        }
        _ => Err(format!(
            "expected A:B:STEP, a list A,B,… or a single value, not `{}`",
            crate::diag::quote(text)
        )),
    }
}

/// `--flag: message`, the command line's form of a range's error.
pub fn parse_range(flag: &str, text: &str) -> Result<Vec<f64>, String> {
    parse_values(text).map_err(|e| format!("--{flag}: {e}"))
}

/// The Mach numbers of `--mach TEXT` ([`parse_values`]), each within
/// [`limits::MACH`]: what every command that takes a list of them reads.
pub fn parse_machs(text: &str) -> Result<Vec<f64>, String> {
    let ms = parse_range("mach", text)?;
    limits::machs(&ms).map_err(|e| format!("--mach: {e}"))?;
    Ok(ms)
}

/// The axes as given (`None`: the base design point's value).
#[derive(Debug, Clone, Default)]
pub struct Given {
    pub mach: Option<Vec<f64>>,
    pub sweep_deg: Option<Vec<f64>>,
    pub cg: Option<Vec<f64>>,
    pub mu1: Option<Vec<f64>>,
    pub i_b: Option<Vec<f64>>,
    /// At a physical flight condition only: pressure altitudes, masses and
    /// I_y, in the config's units ([`Axes::FLIGHT_NAMES`]).
    pub altitude: Option<Vec<f64>>,
    pub mass: Option<Vec<f64>>,
    pub i_y: Option<Vec<f64>>,
}

/// An axis's error: which axis (its index in [`Axes::NAMES`], then
/// [`Axes::FLIGHT_NAMES`]) and why.
#[derive(Debug, Clone, PartialEq)]
pub struct AxisError {
    pub axis: usize,
    pub message: String,
}

/// Each axis's range of values, in the order of [`Axes::NAMES`] (sweep
/// angles are any the planform allows).
const LIMITS: [Option<&Limit>; 5] = [
    Some(&limits::MACH),
    None,
    Some(&limits::CG),
    Some(&limits::MU1),
    Some(&limits::I_B),
];

/// Why μ₁ or i_B cannot be an axis at a physical flight condition.
pub const FIXED_BY_FLIGHT: &str = "the config's flight condition is physical (mass, I_y, altitude…), which fixes μ₁ and i_B; sweep its altitude, mass or I_y instead (the axes altitude, mass, I_y: --altitude, --mass, --iy), or give mu1, i_b and cl_m2 in [flight]";

/// Why altitude, mass or I_y cannot be an axis without a physical flight
/// condition.
pub const NEEDS_PHYSICAL: &str = "the config's flight condition is non-dimensional (mu1, i_b, cl_m2), so there is no altitude, mass or I_y to vary; vary μ₁ and i_B instead (--mu1, --ib), or give a physical flight condition in [flight] (units, altitude, mass, I_y; see `analyze --help`)";

/// Whether a case's lift slope comes from a DATCOM output's table.
fn from_datcom(case: &Case) -> bool {
    matches!(&case.aero.lift_slope, Source::Table(t) if t.origin() == TableOrigin::Datcom)
}

/// The axes of a sweep about `base`: each given one within its range, the
/// others the base's values (its sweep angle rounded to the decimals it
/// stands for; the library then uses the base's own planform for it). At
/// a physical flight condition μ₁ and i_B may not be given; without one,
/// altitude, mass and I_y may not; with a DATCOM output's tables, the
/// sweep angle may not change.
pub fn axes(given: Given, base: &Case, physical: bool) -> Result<Axes, AxisError> {
    let fixed = [(3, &given.mu1), (4, &given.i_b)];
    let flight = [(5, &given.altitude), (6, &given.mass), (7, &given.i_y)];
    let (refused, message) = match physical {
        true => (&fixed[..], FIXED_BY_FLIGHT),
        false => (&flight[..], NEEDS_PHYSICAL),
    };
    if let Some((axis, _)) = refused.iter().find(|(_, g)| g.is_some()) {
        let message = message.to_string();
        return Err(AxisError {
            axis: *axis,
            message,
        });
    }
    for (axis, g) in flight {
        if g.as_ref().is_some_and(Vec::is_empty) {
            let message = "the axis has no values".to_string();
            return Err(AxisError { axis, message });
        }
    }
    let (altitude, mass, i_y) = (
        given.altitude.clone().unwrap_or_default(),
        given.mass.clone().unwrap_or_default(),
        given.i_y.clone().unwrap_or_default(),
    );
    let defaults = [
        base.mach,
        grid::round(base.planform.sweep_le.to_degrees()),
        base.h,
        base.mu1,
        base.i_b,
    ];
    if from_datcom(base)
        && given
            .sweep_deg
            .as_ref()
            .is_some_and(|v| v.iter().any(|x| *x != defaults[1]))
    {
        let message = "the model's tables come from a DATCOM output, which is of one planform (its reference area, M.A.C. and moment centre): sweep the planform with one DATCOM run per sweep".to_string();
        return Err(AxisError { axis: 1, message });
    }
    let given = [given.mach, given.sweep_deg, given.cg, given.mu1, given.i_b];
    let mut out: [Vec<f64>; 5] = Default::default();
    for (axis, v) in given.into_iter().enumerate() {
        let values = v.unwrap_or_else(|| vec![defaults[axis]]);
        if values.is_empty() {
            let message = "the axis has no values".to_string();
            return Err(AxisError { axis, message });
        }
        if let Some(limit) = LIMITS[axis] {
            for &x in &values {
                limit
                    .check(x)
                    .map_err(|message| AxisError { axis, message })?;
            }
        }
        out[axis] = values;
    }
    let [mach, sweep_deg, cg, mu1, i_b] = out;
    Ok(Axes {
        mach,
        sweep_deg,
        cg,
        mu1,
        i_b,
        altitude,
        mass,
        i_y,
    })
}

/// At a physical flight condition with axes of its own (altitude, mass,
/// I_y), μ₁, i_B and C_L·M² within the ranges a config may give them
/// ([`crate::limits`], as `analyze` checks a config's): each is monotone in
/// each axis (μ₁ = m/(½ρSc̄) and C_L·M² = W/(½ρa²S) grow with the mass
/// and, ρ and ρa² falling, with the altitude; i_B = I_y/(mc̄²)), so the
/// corners of the axes' ranges bound them, planform by planform. The
/// message names the corner and what to do.
pub fn check_flight_limits(sweep: &Sweep) -> Result<(), String> {
    use stability_core::design::sweep::set_flight_value;
    let Some(base) = sweep.condition() else {
        return Ok(());
    };
    let axes = sweep.axes();
    let ends = |v: &[f64]| match v {
        [] => vec![None],
        v => {
            let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            vec![Some(lo), Some(hi)]
        }
    };
    let flags = ["--altitude", "--mass", "--iy"];
    let (alt, mass, iy) = (ends(&axes.altitude), ends(&axes.mass), ends(&axes.i_y));
    let mut corners = Vec::new();
    for a in &alt {
        for m in &mass {
            for i in &iy {
                corners.push([*a, *m, *i]);
            }
        }
    }
    for (p, sweep_deg) in sweep.planforms().iter().zip(&axes.sweep_deg) {
        for corner in &corners {
            let mut c = *base;
            for (k, v) in corner.iter().enumerate() {
                if let Some(v) = v {
                    set_flight_value(&mut c, Axes::FLIGHT_NAMES[k], *v);
                }
            }
            let Ok(f) = c.for_planform(p) else { continue };
            let derived = [
                (&limits::MU1, "μ₁ = m/(½ρSc̄)", f.mu1()),
                (&limits::I_B, "i_B = I_y/(mc̄²)", f.i_b()),
                (&limits::CL_M2, "C_L·M² = W/(½ρa²S)", f.cl_m2()),
            ];
            for (limit, what, v) in derived {
                if let Err(m) = limit.check(v) {
                    let at: Vec<String> = corner
                        .iter()
                        .zip(flags)
                        .filter_map(|(v, f)| v.map(|v| format!("{f} {}", Num(v))))
                        .collect();
                    return Err(format!(
                        "{}: {what} = {} at a sweep of {}°: {m}; narrow the range",
                        at.join(", "),
                        Num(v),
                        Num(*sweep_deg)
                    ));
                }
            }
        }
    }
    Ok(())
}

/// The library's grid, whose rows are written in the columns of
/// [`columns::COLUMNS`].
pub struct Grid {
    pub sweep: Sweep,
    /// Whether the flight condition is physical: each point's μ₁ and i_B
    /// are then its planform's and condition's, written beside its
    /// altitude, mass and I_y.
    physical: bool,
}

impl Grid {
    /// The grid of `axes` about `base`, at its physical flight condition
    /// when it has one.
    pub fn new(base: Case, axes: Axes, physical: Option<&Physical>) -> Result<Grid, SweepError> {
        // the library checks the grid's size before the values are written
        let sweep = match physical {
            Some(p) => Sweep::physical(base, axes, &p.condition)?,
            None => Sweep::new(base, axes)?,
        };
        Ok(Grid {
            physical: physical.is_some(),
            sweep,
        })
    }

    /// The number of design points.
    pub fn points(&self) -> usize {
        self.sweep.len()
    }

    /// Whether the rows carry the modes in seconds.
    pub fn is_physical(&self) -> bool {
        self.physical
    }

    /// The columns of the rows.
    pub fn columns(&self, derivatives: bool) -> impl Iterator<Item = &'static Column> {
        columns::columns(derivatives, self.physical)
    }

    /// Evaluates points `range` of the grid (the library's lean path,
    /// reusing the aerodynamics across μ₁ and i_B where the model allows)
    /// and writes them as records of `table` into one buffer, in the
    /// columns of [`Grid::columns`] (the first record preceded by the
    /// separator from the one before unless it is the grid's first point).
    pub fn rows(&self, range: std::ops::Range<usize>, table: Table, derivatives: bool) -> Vec<u8> {
        let mut out = Vec::with_capacity(range.len() * 280);
        let points = self.sweep.evaluate(range.clone(), derivatives);
        let columns: Vec<&Column> = self.columns(derivatives).collect();
        let mut errors = points.errors.iter().peekable();
        let sweeps = &self.sweep.axes().sweep_deg;
        // the grid's values, formatted once per change
        let mut last = vec![Repeated::default(); columns.len()];
        let indices = self.sweep.indices(range.clone());
        for (k, (i, idx)) in range.zip(indices).enumerate() {
            let error = errors.next_if(|(at, _)| *at == k).map(|(_, e)| e);
            let flight = match (self.physical, error) {
                (true, None) => self.sweep.flight_point(i),
                _ => None,
            };
            let point = Point::new(&points, k, sweeps[idx[1]], flight);
            let mut record = table.record(&mut out, i == 0);
            write_point(&mut record, &columns, &point, error, &mut last);
            record.end();
        }
        out
    }
}

/// A point's record in `columns`: its grid values, then its results or,
/// where it has none, why.
fn write_point(
    r: &mut Record<'_>,
    columns: &[&Column],
    p: &Point<'_>,
    error: Option<&PointError>,
    last: &mut [Repeated],
) {
    for (c, last) in columns.iter().zip(last) {
        match (c.value, error) {
            (Value::Grid(v), _) => r.repeated(c.name, v(p), last),
            (Value::Error, Some(e)) => r.text(c.name, &e.to_string()),
            (_, Some(_)) | (Value::Error, None) => r.absent(),
            (Value::Number(v), None) => r.number(c.name, v(p)),
            (Value::Bool(v), None) => r.boolean(c.name, v(p)),
            (Value::Word(v), None) => r.word(c.name, v(p)),
        }
    }
}
