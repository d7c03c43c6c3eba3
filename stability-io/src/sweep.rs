//! A sweep as the front ends ask for it: the axes from ranges
//! (`A:B:STEP`, a list `A,B,…`, or one value) or the base design point's
//! values, each within its range ([`crate::limits`]); the grid with each
//! value's text; and the rows as CSV or JSON, in the columns of
//! [`stability_core::sweep::columns`], numbers in their shortest
//! round-trip form.
//!
//! The computation is the library's ([`stability_core::sweep`]).

use crate::config::physical::Physical;
use crate::limits::{self, Limit};
use stability_core::aero::{Source, TableOrigin};
use stability_core::case::Case;
use stability_core::display::{Num, sig};
use stability_core::grid;
use stability_core::sweep::{
    Axes, Cell, DIMS, ERROR_COLUMN, PointError, Points, RESULT_COLUMNS, SECONDS_COLUMNS, Seconds,
    Sweep, SweepError, columns, derivative_columns,
};

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
    use stability_core::sweep::set_flight_value;
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

/// The library's grid, and each axis's values as written (formatted once,
/// not once per row).
pub struct Grid {
    pub sweep: Sweep,
    text: [Vec<Box<str>>; 5],
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
        let axes = sweep.axes();
        let mut num = zmij::Buffer::new();
        let mut text =
            |v: &[f64]| -> Vec<Box<str>> { v.iter().map(|&x| num.format(x).into()).collect() };
        let text = [
            text(&axes.mach),
            text(&axes.sweep_deg),
            text(&axes.cg),
            text(&axes.mu1),
            text(&axes.i_b),
        ];
        Ok(Grid {
            physical: physical.is_some(),
            sweep,
            text,
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
    pub fn columns(&self, derivatives: bool) -> Vec<&'static str> {
        columns(derivatives, self.is_physical())
    }

    /// The grid values as written of the point of indices `idx`.
    fn head(&self, idx: [usize; DIMS]) -> [&str; 5] {
        std::array::from_fn(|k| &*self.text[k][idx[k]])
    }

    /// Evaluates points `range` of the grid (the library's lean path,
    /// reusing the aerodynamics across μ₁ and i_B where the model allows)
    /// and writes them as rows into one buffer: CSV lines, or JSON objects
    /// separated by `,\n` (the first preceded by it too unless it is the
    /// grid's first point).
    pub fn rows(&self, range: std::ops::Range<usize>, format: Format) -> Vec<u8> {
        let mut out = Vec::with_capacity(range.len() * 280);
        let points = self.sweep.evaluate(range.clone(), format.derivatives);
        let mut errors = points.errors.iter().peekable();
        let indices = self.sweep.indices(range.clone());
        for (k, (i, idx)) in range.zip(indices).enumerate() {
            if format.json && i > 0 {
                out.extend_from_slice(b",\n");
            }
            let r = match errors.peek() {
                Some((at, e)) if *at == k => {
                    errors.next();
                    Err(e)
                }
                _ => Ok((&points, k)),
            };
            let seconds = self.physical.then(|| {
                let point = r.is_ok().then(|| self.sweep.flight_point(i)).flatten();
                points.seconds(k, point)
            });
            // at a physical condition μ₁ and i_B are the point's own, with
            // its altitude, mass and I_y
            let flight = self.physical.then(|| {
                let p = &points;
                [p.mu1[k], p.i_b[k], p.altitude[k], p.mass[k], p.i_y[k]]
            });
            let head = Head {
                text: self.head(idx),
                flight,
            };
            write_point(&mut out, head, r, format, seconds);
            if !format.json {
                out.push(b'\n');
            }
        }
        out
    }
}

/// How rows are written.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Format {
    /// JSON objects (else CSV lines).
    pub json: bool,
    /// With the quartic inputs ([`derivative_columns`]).
    pub derivatives: bool,
}

/// Formats one row (CSV) or object (JSON) into a byte buffer, numbers in
/// their shortest round-trip form.
struct Row<'a> {
    out: &'a mut Vec<u8>,
    num: zmij::Buffer,
    json: bool,
    first: bool,
}

impl Row<'_> {
    fn key(&mut self, name: &str) {
        if !self.first {
            self.out.push(b',');
        }
        self.first = false;
        if self.json {
            self.out.push(b'"');
            self.out.extend_from_slice(name.as_bytes());
            self.out.extend_from_slice(b"\":");
        }
    }

    fn number(&mut self, name: &str, v: Option<f64>) {
        self.key(name);
        match v.filter(|x| x.is_finite()) {
            Some(x) => self
                .out
                .extend_from_slice(self.num.format_finite(x).as_bytes()),
            None if self.json => self.out.extend_from_slice(b"null"),
            None => {}
        }
    }

    fn word(&mut self, name: &str, w: &str) {
        self.key(name);
        if self.json {
            self.out.push(b'"');
        }
        self.out.extend_from_slice(w.as_bytes());
        if self.json {
            self.out.push(b'"');
        }
    }

    fn boolean(&mut self, name: &str, b: bool) {
        self.key(name);
        self.out
            .extend_from_slice(if b { b"true" as &[u8] } else { b"false" });
    }

    fn text(&mut self, name: &str, t: &str) {
        self.key(name);
        if self.json {
            let quoted = serde_json::to_string(t).unwrap_or_else(|_| "\"?\"".into());
            self.out.extend_from_slice(quoted.as_bytes());
        } else {
            self.out.extend_from_slice(crate::csv::field(t).as_bytes());
        }
    }
}

/// A row's grid values: the axes as written, and at a physical flight
/// condition the point's μ₁, i_B, altitude, mass and I_y (in place of the
/// μ₁ and i_B axes).
struct Head<'a> {
    text: [&'a str; 5],
    flight: Option<[f64; 5]>,
}

fn write_point(
    out: &mut Vec<u8>,
    head: Head<'_>,
    r: Result<(&Points, usize), &PointError>,
    format: Format,
    seconds: Option<Seconds>,
) {
    if format.json {
        out.push(b'{');
    }
    let mut row = Row {
        out,
        num: zmij::Buffer::new(),
        json: format.json,
        first: true,
    };
    let given = if head.flight.is_some() { 3 } else { 5 };
    for (name, v) in Axes::NAMES.iter().zip(head.text).take(given) {
        row.key(name);
        row.out.extend_from_slice(v.as_bytes());
    }
    if let Some(values) = head.flight {
        let names = ["mu1", "i_b"].iter().chain(&Axes::FLIGHT_NAMES);
        for (name, v) in names.zip(values) {
            row.number(name, Some(v));
        }
    }
    match r {
        Ok((p, k)) => {
            results(&mut row, p, k, format.derivatives, seconds);
            if !format.json {
                row.key(ERROR_COLUMN);
            }
        }
        Err(e) => {
            if !format.json {
                let physical = seconds.is_some();
                let n = RESULT_COLUMNS.len()
                    + seconds.map_or(0, |s| s.len())
                    + if format.derivatives {
                        derivative_columns(physical).len()
                    } else {
                        0
                    };
                for _ in 0..n {
                    row.key("");
                }
            }
            row.text(ERROR_COLUMN, &e.to_string());
        }
    }
    if format.json {
        row.out.push(b'}');
    }
}

/// Point `k`'s results ([`Points::results`]), the modes in seconds and the
/// derivatives when asked for.
fn results(
    row: &mut Row<'_>,
    p: &Points,
    k: usize,
    with_derivatives: bool,
    seconds: Option<Seconds>,
) {
    let tau = seconds.and_then(|s| s[2]);
    for (name, cell) in RESULT_COLUMNS.iter().zip(p.results(k, tau)) {
        match cell {
            Cell::Bool(b) => row.boolean(name, b),
            Cell::Word(w) => row.word(name, w),
            Cell::Number(v) => row.number(name, v),
        }
    }
    if let Some(values) = seconds {
        for (name, v) in SECONDS_COLUMNS.iter().zip(values) {
            row.number(name, v);
        }
    }
    if let (true, Some(ds)) = (with_derivatives, &p.derivatives) {
        let names = derivative_columns(seconds.is_some());
        let values = ds[k].quartic_input_values();
        for (name, v) in names.iter().zip(values) {
            row.number(name, Some(v));
        }
    }
}
