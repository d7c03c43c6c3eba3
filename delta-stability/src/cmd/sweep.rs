//! `delta-stability sweep CONFIG --mach A:B:STEP … -o OUT.csv|OUT.json`:
//! design points over a Cartesian grid, evaluated in parallel (rayon),
//! written atomically.
//!
//! The grid is evaluated in chunks; within a chunk, blocks of points are
//! formatted in parallel into their own buffers, and a chunk is written while
//! the next is computed. Each point takes the lean path
//! ([`stability_core::case::evaluate_point`]: no eq (7) check).

use crate::Failure;
use crate::config::{self, limits};
use crate::diag::InputError;
use crate::files::write_error;
use crate::output::AtomicFile;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rayon::prelude::*;
use stability_core::Derivatives;
use stability_core::analysis::Analysis;
use stability_core::case::{Case, CaseResult, evaluate_point};
use stability_core::geometry::{Planform, Size};
use stability_core::study::grid as values;
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
}

/// The grid's axes, in output order; the last varies fastest.
pub struct Grid {
    pub mach: Vec<f64>,
    pub sweep_deg: Vec<f64>,
    pub cg: Vec<f64>,
    pub mu1: Vec<f64>,
    pub i_b: Vec<f64>,
    planforms: Vec<Planform>,
    /// Each axis's values as written (formatted once, not once per row).
    text: [Vec<Box<str>>; 5],
    base: Case,
    /// The physical flight condition of each planform, when the config's
    /// is physical.
    physical: Option<super::sweep_physical::PhysicalAxis>,
}

impl Grid {
    fn dims(&self) -> [usize; 5] {
        [
            self.mach.len(),
            self.sweep_deg.len(),
            self.cg.len(),
            self.mu1.len(),
            self.i_b.len(),
        ]
    }

    /// The number of design points, if it fits in a `usize`.
    pub fn points(&self) -> Option<usize> {
        self.dims()
            .iter()
            .try_fold(1usize, |acc, &d| acc.checked_mul(d))
    }

    /// Makes `case` the `i`-th design point (from the base point, whose other
    /// fields it keeps; no clone per point) and returns its grid values as
    /// written, and the index of its planform.
    fn set_point(&self, i: usize, case: &mut Case) -> ([&str; 5], usize) {
        let dims = self.dims();
        let mut k = i;
        let mut idx = [0usize; 5];
        for d in (0..5).rev() {
            idx[d] = k % dims[d];
            k /= dims[d];
        }
        let head = [
            self.mach[idx[0]],
            self.sweep_deg[idx[1]],
            self.cg[idx[2]],
            self.mu1[idx[3]],
            self.i_b[idx[4]],
        ];
        case.planform = self.planforms[idx[1]];
        [case.mach, _, case.h, case.mu1, case.i_b] = head;
        let mut text: [&str; 5] = std::array::from_fn(|k| &*self.text[k][idx[k]]);
        if let Some(p) = &self.physical {
            p.apply(idx[1], case);
            [text[3], text[4]] = p.text(idx[1]);
        }
        (text, idx[1])
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

/// Whether every number a point's row would carry is finite (a point
/// whose numbers overflow is written as an error, not as blanks).
fn finite(d: &Derivatives, a: &Analysis) -> bool {
    d.quartic_input_values().iter().all(|v| v.is_finite())
        && a.quartic.to_array().iter().all(|v| v.is_finite())
        && a.roots.iter().all(|z| z.re.is_finite() && z.im.is_finite())
        && a.routh.discriminant.is_finite()
        && a.damping_standard.m_thetadot.is_finite()
}

/// The error of a point whose numbers overflow.
const OVERFLOW: &str = "the design point's numbers overflow f64";

/// The modes in seconds of a physical flight condition's point (`None`
/// without one).
type Seconds = Option<[Option<f64>; super::sweep_physical::COLUMNS.len()]>;

fn write_point(
    out: &mut Vec<u8>,
    head: [&str; 5],
    r: Result<(&Derivatives, &Analysis), &dyn std::fmt::Display>,
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
    let r = match r {
        Ok((d, a)) if !finite(d, a) => Err(&OVERFLOW as &dyn std::fmt::Display),
        other => other,
    };
    match r {
        Ok((d, a)) => {
            results(&mut row, d, a, with_derivatives, seconds);
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

/// A point's results: Routh, the verdict, the modes, eq (41), and the
/// derivatives when asked for.
fn results(
    row: &mut Row<'_>,
    d: &Derivatives,
    a: &Analysis,
    with_derivatives: bool,
    seconds: Seconds,
) {
    let sp = a.modes.short_period();
    let ph = a.modes.phugoid();
    row.boolean("stable", a.routh.stable);
    row.word("verdict", a.verdict.as_str());
    row.number("sp_re", sp.map(|m| m.re));
    row.number("sp_im", sp.map(|m| m.im));
    row.number("sp_cycles_to_half", sp.and_then(|m| m.cycles_to_half));
    row.number("sp_damping_ratio", sp.and_then(|m| m.damping_ratio));
    row.number("sp_omega_bar", sp.and_then(|m| m.frequency_parameter));
    row.number("ph_re", ph.map(|m| m.re));
    row.number("ph_im", ph.map(|m| m.im));
    row.number("m_thetadot", Some(a.damping_standard.m_thetadot));
    row.number("delta_m_thetadot", a.damping_standard.margin);
    if let Some(values) = seconds {
        for (name, v) in super::sweep_physical::COLUMNS.iter().zip(values) {
            row.number(name, v);
        }
    }
    if with_derivatives {
        let values = d.quartic_input_values();
        for (name, v) in Derivatives::QUARTIC_INPUTS.iter().zip(values) {
            row.number(name, Some(v));
        }
    }
}

/// Evaluates points `range` of the grid into one buffer. Consecutive points
/// that differ in μ₁ and i_B only share their derivatives
/// ([`stability_core::case::DampingModel::depends_on_mass`]): the
/// aerodynamics are evaluated once and the quartic again.
fn block(grid: &Grid, range: std::ops::Range<usize>, options: (bool, bool)) -> Vec<u8> {
    let mut out = Vec::with_capacity(range.len() * 280);
    let per_aero = grid.mu1.len() * grid.i_b.len();
    let reuse = !grid.base.damping.depends_on_mass();
    let mut last: Option<(usize, CaseResult)> = None;
    let mut case = grid.base.clone();
    for i in range {
        if options.0 && i > 0 {
            out.extend_from_slice(b",\n");
        }
        let (head, k) = grid.set_point(i, &mut case);
        let key = i / per_aero;
        let seconds = |a: Option<&Analysis>| {
            grid.physical.as_ref().map(|p| match a {
                Some(a) => p.seconds(k, case.mach, a),
                None => [None; super::sweep_physical::COLUMNS.len()],
            })
        };
        match &last {
            Some((k, r)) if reuse && *k == key => {
                let d = Derivatives {
                    mu1: case.mu1,
                    i_b: case.i_b,
                    ..r.derivatives
                };
                match Analysis::without_classical(&d) {
                    Ok(a) => write_point(&mut out, head, Ok((&d, &a)), options, seconds(Some(&a))),
                    Err(e) => write_point(&mut out, head, Err(&e), options, seconds(None)),
                }
            }
            _ => match evaluate_point(&case) {
                Ok(r) => {
                    let sec = seconds(Some(&r.analysis));
                    write_point(
                        &mut out,
                        head,
                        Ok((&r.derivatives, &r.analysis)),
                        options,
                        sec,
                    );
                    last = Some((key, r));
                }
                Err(e) => write_point(&mut out, head, Err(&e), options, seconds(None)),
            },
        }
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
    let mach = within("mach", parse_range("mach", &o.mach)?, &limits::MACH)?;
    let sweep_deg = or_base("sweep", &o.sweep, base.planform.sweep_le.to_degrees())?;
    let cg = within("cg", or_base("cg", &o.cg, base.h)?, &limits::CG)?;
    let mu1 = within("mu1", or_base("mu1", &o.mu1, base.mu1)?, &limits::MU1)?;
    let i_b = within("ib", or_base("ib", &o.ib, base.i_b)?, &limits::I_B)?;
    let mut planforms = Vec::with_capacity(sweep_deg.len());
    for &s in &sweep_deg {
        let p = Planform::new(s.to_radians(), base.planform.taper, Size::RootChord(1.0))
            .map_err(|e| format!("--sweep {s}: {e}"))?;
        planforms.push(Planform {
            sweep_le: p.sweep_le,
            ..base.planform
        });
    }
    let physical = match physical {
        Some(p) => Some(super::sweep_physical::PhysicalAxis::new(
            p,
            &planforms,
            [("mu1", o.mu1.is_some()), ("ib", o.ib.is_some())],
        )?),
        None => None,
    };
    let mut num = zmij::Buffer::new();
    let mut text =
        |v: &[f64]| -> Vec<Box<str>> { v.iter().map(|&x| num.format(x).into()).collect() };
    let text = [
        text(&mach),
        text(&sweep_deg),
        text(&cg),
        text(&mu1),
        text(&i_b),
    ];
    let g = Grid {
        mach,
        sweep_deg,
        cg,
        mu1,
        i_b,
        planforms,
        text,
        base,
        physical,
    };
    match g.points() {
        Some(n) if n <= 200_000_000 => Ok(g),
        Some(n) => Err(format!("the grid has {n} points; the limit is 2e8")),
        None => Err("the grid is too large".into()),
    }
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
    let cfg = config::read(&o.config)?;
    let bad = |m: String| Failure::Input(InputError::file(&o.config, m));
    let json = is_json(o).map_err(&bad)?;
    let grid = grid(o, cfg.case, cfg.physical.as_ref()).map_err(&bad)?;
    let out = Path::new(&o.output);
    let write_err = |e: std::io::Error| Failure::Io(write_error(out, &e));
    let mut file = AtomicFile::create(out).map_err(write_err)?;
    let total = grid.points().unwrap_or(0);
    let bar = progress_bar(total);
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
    let total = grid.points().unwrap_or(0);
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
