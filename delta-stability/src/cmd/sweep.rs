//! `delta-stability sweep CONFIG --mach A:B:STEP … -o OUT.csv|OUT.json`:
//! design points over a Cartesian grid, evaluated in parallel (rayon),
//! written atomically.
//!
//! The computation is the library's ([`stability_core::sweep`]); this
//! command parses the ranges and writes the rows. The grid is evaluated in
//! chunks; within a chunk, blocks of points are evaluated and formatted in
//! parallel into their own buffers, and a chunk is written while the next
//! is computed.

use crate::Failure;
use crate::args::{AeroArg, DampingArg};
use crate::cmd::analyze::{Overrides, overridden};
use crate::config::limits;
use crate::diag::InputError;
use crate::files::write_error;
use crate::output::AtomicFile;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rayon::prelude::*;
use stability_core::Derivatives;
use stability_core::case::Case;
use stability_core::study::grid as values;
use stability_core::sweep::{Axes, PointError, Points, Sweep, SweepError};
use std::io::Write as _;
use std::path::Path;

/// A range `A:B:STEP` (inclusive) or a single value `A`. The values are
/// `A + k·STEP`, cleaned of rounding noise (0.2:0.3:0.01 gives 0.21, not
/// 0.21000000000000002).
pub fn parse_range(flag: &str, text: &str) -> Result<Vec<f64>, String> {
    let parts: Vec<&str> = text.split(':').collect();
    let num = |s: &str| {
        s.trim()
            .parse::<f64>()
            .ok()
            .filter(|x| x.is_finite())
            .ok_or_else(|| format!("--{flag}: `{s}` is not a finite number"))
    };
    match parts.as_slice() {
        [a] => Ok(vec![num(a)?]),
        [a, b, step] => {
            let (a, b, step) = (num(a)?, num(b)?, num(step)?);
            if step <= 0.0 {
                return Err(format!("--{flag}: the step must be positive, not {step}"));
            }
            if b < a {
                return Err(format!(
                    "--{flag}: the range {a}:{b} runs backwards (write the smaller value first)"
                ));
            }
            let n = ((b - a) / step).floor() + 1.0;
            if n > 1e7 {
                return Err(format!("--{flag}: {n} values is too many (at most 1e7)"));
            }
            Ok(values(a, b, step).into_iter().map(clean).collect())
        }
        _ => Err(format!(
            "--{flag}: expected A:B:STEP or a single value, not `{text}`"
        )),
    }
}

/// `v` rounded to 13 significant digits: grid values without the noise of
/// `A + k·STEP` or of a conversion to degrees.
fn clean(v: f64) -> f64 {
    format!("{v:.12e}").parse::<f64>().unwrap_or(v)
}

/// The command's options.
#[derive(Debug, Clone, clap::Args)]
pub struct Options {
    /// The base design point (TOML).
    pub config: String,
    /// Mach numbers, A:B:STEP.
    #[arg(long)]
    pub mach: String,
    /// Leading-edge sweeps in degrees, A:B:STEP.
    #[arg(long)]
    pub sweep: Option<String>,
    /// c.g. positions h, A:B:STEP.
    #[arg(long)]
    pub cg: Option<String>,
    /// Relative densities μ₁, A:B:STEP.
    #[arg(long)]
    pub mu1: Option<String>,
    /// Pitching inertias i_B, A:B:STEP.
    #[arg(long)]
    pub ib: Option<String>,
    /// The output file, .csv or .json.
    #[arg(short = 'o', long = "output")]
    pub output: String,
    /// Add the fifteen quartic inputs (x_u … m_q, c_l, mu1, i_b, report
    /// notation) to each row, e.g. to feed another tool.
    #[arg(long)]
    pub derivatives: bool,
    /// Override the config's damping model (see `analyze --help`). With
    /// lifting-surface the lattice is solved once per sweep and Mach number;
    /// with lifting-surface-frequency each point's ω̄ is interpolated between
    /// solved frequencies.
    #[arg(long, value_enum)]
    pub damping: Option<DampingArg>,
    /// Override the config's aerodynamic model (see `analyze --help`).
    #[arg(long, value_enum)]
    pub aero: Option<AeroArg>,
    /// Evaluate a frequency-dependent damping theory at ω̄ = W at every
    /// point, not iterated (as `analyze --omega-bar`).
    #[arg(long = "omega-bar", value_name = "W", value_parser = crate::args::positive)]
    pub omega_bar: Option<f64>,
}

/// The library's grid, and each axis's values as written (formatted once,
/// not once per row).
pub struct Grid {
    pub sweep: Sweep,
    text: [Vec<Box<str>>; 5],
    /// With a physical flight condition, each planform's μ₁ and i_B as
    /// written.
    physical: Option<super::sweep_physical::PhysicalAxis>,
}

impl Grid {
    /// The number of design points.
    pub fn points(&self) -> usize {
        self.sweep.len()
    }

    /// The grid values as written of the point of indices `idx` (μ₁ and
    /// i_B the planform's, with a physical flight condition).
    fn head(&self, idx: [usize; 5]) -> [&str; 5] {
        let mut text: [&str; 5] = std::array::from_fn(|k| &*self.text[k][idx[k]]);
        if let Some(p) = &self.physical {
            [text[3], text[4]] = p.text(idx[1]);
        }
        text
    }
}

const HEAD: [&str; 5] = ["mach", "sweep_deg", "cg", "mu1", "i_b"];
const RESULTS: [&str; 12] = [
    "stable",
    "verdict",
    "sp_re",
    "sp_im",
    "sp_cycles_to_half",
    "sp_damping_ratio",
    "sp_omega_bar",
    "ph_re",
    "ph_im",
    "m_thetadot",
    "delta_m_thetadot",
    "error",
];

/// The column names, in order (with a physical flight condition, the
/// modes in seconds after the results).
pub fn columns(derivatives: bool, physical: bool) -> Vec<&'static str> {
    let mut c: Vec<&str> = HEAD.to_vec();
    c.extend(&RESULTS[..11]);
    if physical {
        c.extend(super::sweep_physical::COLUMNS);
    }
    if derivatives {
        c.extend(stability_core::Derivatives::QUARTIC_INPUTS);
    }
    c.push(RESULTS[11]);
    c
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
            self.out.push(b'"');
            self.out
                .extend_from_slice(t.replace('"', "\"\"").as_bytes());
            self.out.push(b'"');
        }
    }
}

/// The modes in seconds of a physical flight condition's point (`None`
/// without one).
type Seconds = Option<super::sweep_physical::Seconds>;

fn write_point(
    out: &mut Vec<u8>,
    head: [&str; 5],
    r: Result<(&Points, usize), &PointError>,
    options: (bool, bool),
    seconds: Seconds,
) {
    let (json, with_derivatives) = options;
    if json {
        out.push(b'{');
    }
    let mut row = Row {
        out,
        num: zmij::Buffer::new(),
        json,
        first: true,
    };
    for (name, v) in HEAD.iter().zip(head) {
        row.key(name);
        row.out.extend_from_slice(v.as_bytes());
    }
    match r {
        Ok((p, k)) => {
            results(&mut row, p, k, with_derivatives, seconds);
            if !json {
                row.key("error");
            }
        }
        Err(e) => {
            if !json {
                let n = RESULTS.len() - 1
                    + if with_derivatives { 15 } else { 0 }
                    + seconds.map_or(0, |s| s.len());
                for _ in 0..n {
                    row.key("");
                }
            }
            row.text("error", &e.to_string());
        }
    }
    if json {
        row.out.push(b'}');
    }
}

/// Point `k`'s results: Routh, the verdict, the modes, eq (41), and the
/// derivatives when asked for.
fn results(row: &mut Row<'_>, p: &Points, k: usize, with_derivatives: bool, seconds: Seconds) {
    let some = |v: f64| Some(v);
    row.boolean("stable", p.stable[k] == Some(true));
    row.word("verdict", p.verdict[k].map_or("", |v| v.as_str()));
    row.number("sp_re", some(p.sp_re[k]));
    row.number("sp_im", some(p.sp_im[k]));
    row.number("sp_cycles_to_half", some(p.sp_cycles_to_half[k]));
    row.number("sp_damping_ratio", some(p.sp_damping_ratio[k]));
    row.number("sp_omega_bar", some(p.sp_omega_bar[k]));
    row.number("ph_re", some(p.ph_re[k]));
    row.number("ph_im", some(p.ph_im[k]));
    row.number("m_thetadot", some(p.m_thetadot[k]));
    row.number("delta_m_thetadot", some(p.delta_m_thetadot[k]));
    if let Some(values) = seconds {
        for (name, v) in super::sweep_physical::COLUMNS.iter().zip(values) {
            row.number(name, v);
        }
    }
    if let (true, Some(ds)) = (with_derivatives, &p.derivatives) {
        let values = ds[k].quartic_input_values();
        for (name, v) in Derivatives::QUARTIC_INPUTS.iter().zip(values) {
            row.number(name, Some(v));
        }
    }
}

/// Evaluates points `range` of the grid (the library's lean path, reusing
/// the aerodynamics across μ₁ and i_B where the model allows) and formats
/// them into one buffer.
fn block(grid: &Grid, range: std::ops::Range<usize>, options: (bool, bool)) -> Vec<u8> {
    let mut out = Vec::with_capacity(range.len() * 280);
    let points = grid.sweep.evaluate(range.clone(), options.1);
    let mut errors = points.errors.iter().peekable();
    let indices = grid.sweep.indices(range.clone());
    for (k, (i, idx)) in range.zip(indices).enumerate() {
        if options.0 && i > 0 {
            out.extend_from_slice(b",\n");
        }
        let r = match errors.peek() {
            Some((at, e)) if *at == k => {
                errors.next();
                Err(e)
            }
            _ => Ok((&points, k)),
        };
        let seconds = grid.physical.as_ref().map(|_| {
            let point = r.is_ok().then(|| grid.sweep.flight_point(i)).flatten();
            super::sweep_physical::seconds(point, &points, k)
        });
        write_point(&mut out, grid.head(idx), r, options, seconds);
        if !options.0 {
            out.push(b'\n');
        }
    }
    out
}

/// Builds the grid from the options and the base design point (with its
/// physical flight condition, when it has one).
pub fn grid(
    o: &Options,
    base: Case,
    physical: Option<&crate::config::physical::Physical>,
) -> Result<Grid, String> {
    if physical.is_some() {
        super::sweep_physical::refuse_ranges([("mu1", o.mu1.is_some()), ("ib", o.ib.is_some())])?;
    }
    let or_base = |flag: &str, v: &Option<String>, base: f64| match v {
        Some(t) => parse_range(flag, t),
        None => Ok(vec![clean(base)]),
    };
    let within = |flag: &str, v: Vec<f64>, limit: &limits::Limit| -> Result<Vec<f64>, String> {
        for &x in &v {
            limit.check(x).map_err(|e| format!("--{flag}: {e}"))?;
        }
        Ok(v)
    };
    let axes = Axes {
        mach: within("mach", parse_range("mach", &o.mach)?, &limits::MACH)?,
        sweep_deg: or_base("sweep", &o.sweep, base.planform.sweep_le.to_degrees())?,
        cg: within("cg", or_base("cg", &o.cg, base.h)?, &limits::CG)?,
        mu1: within("mu1", or_base("mu1", &o.mu1, base.mu1)?, &limits::MU1)?,
        i_b: within("ib", or_base("ib", &o.ib, base.i_b)?, &limits::I_B)?,
    };
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
    let sweep = Sweep::new(base, axes).map_err(|e| match e {
        SweepError::Planform { sweep_deg, error } => format!("--sweep {sweep_deg}: {error}"),
        SweepError::TooLarge { points: Some(n) } => {
            format!("the grid has {n} points; the limit is 2e8")
        }
        SweepError::TooLarge { points: None } => "the grid is too large".into(),
        e => e.to_string(),
    })?;
    let sweep = match physical {
        Some(p) => sweep.with_flight(&p.condition).map_err(|e| e.to_string())?,
        None => sweep,
    };
    let physical = super::sweep_physical::PhysicalAxis::of(&sweep);
    Ok(Grid {
        sweep,
        text,
        physical,
    })
}

/// Whether the output is JSON (`.json`) or CSV (`.csv`).
fn is_json(o: &Options) -> Result<bool, String> {
    match Path::new(&o.output).extension().and_then(|e| e.to_str()) {
        Some("csv") => Ok(false),
        Some("json") => Ok(true),
        _ => Err(format!(
            "-o {}: the output must end in .csv or .json",
            o.output
        )),
    }
}

fn progress_bar(total: usize) -> ProgressBar {
    let bar = ProgressBar::with_draw_target(Some(total as u64), ProgressDrawTarget::stderr());
    bar.set_style(
        ProgressStyle::with_template(
            "{spinner} [{bar:30}] {pos}/{len} design points ({per_sec}, eta {eta})",
        )
        .unwrap_or_else(|_| ProgressStyle::default_bar())
        .progress_chars("=> "),
    );
    bar
}

pub fn run(o: &Options) -> Result<(), Failure> {
    let overrides = Overrides {
        damping: o.damping.map(|d| d.0),
        aero: o.aero.map(|a| a.0),
        omega_bar: o.omega_bar,
        ..Overrides::default()
    };
    let cfg = overridden(&o.config, &overrides)?;
    let bad = |m: String| Failure::Input(InputError::file(&o.config, m));
    let json = is_json(o).map_err(&bad)?;
    let grid = grid(o, cfg.case, cfg.physical.as_ref()).map_err(&bad)?;
    let out = Path::new(&o.output);
    let write_err = |e: std::io::Error| Failure::Io(write_error(out, &e));
    let mut file = AtomicFile::create(out).map_err(write_err)?;
    let total = grid.points();
    let bar = progress_bar(total);
    // the lifting surface's solves, once per (planform, Mach), in parallel
    grid.sweep.prepare();
    if json {
        file.write_all(b"[\n").map_err(write_err)?;
    } else {
        file.write_all(
            columns(o.derivatives, grid.physical.is_some())
                .join(",")
                .as_bytes(),
        )
        .and_then(|_| file.write_all(b"\n"))
        .map_err(write_err)?;
    }
    write_points(&mut file, &grid, (json, o.derivatives), &bar).map_err(write_err)?;
    if json {
        file.write_all(b"\n]\n").map_err(write_err)?;
    }
    file.commit().map_err(write_err)?;
    bar.finish_and_clear();
    crate::output::print(&format!("wrote {total} design points to {}\n", o.output))
}

/// Evaluates the grid in chunks, writing chunk k while chunk k + 1 is
/// computed.
fn write_points(
    file: &mut AtomicFile,
    grid: &Grid,
    options: (bool, bool),
    bar: &ProgressBar,
) -> std::io::Result<()> {
    const CHUNK: usize = 1 << 16;
    const BLOCK: usize = 1 << 10;
    let total = grid.points();
    let compute = |start: usize| -> Vec<Vec<u8>> {
        let end = (start + CHUNK).min(total);
        (start..end)
            .step_by(BLOCK)
            .collect::<Vec<_>>()
            .into_par_iter()
            .map(|b| block(grid, b..(b + BLOCK).min(end), options))
            .collect()
    };
    let mut pending = compute(0);
    let mut start = CHUNK;
    loop {
        let (written, next) = rayon::join(
            || -> std::io::Result<()> {
                for b in &pending {
                    file.write_all(b)?;
                }
                Ok(())
            },
            || (start < total).then(|| compute(start)),
        );
        written?;
        bar.set_position(start.min(total) as u64);
        match next {
            Some(n) => {
                pending = n;
                start += CHUNK;
            }
            None => return Ok(()),
        }
    }
}
