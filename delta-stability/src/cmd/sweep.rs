//! `delta-stability sweep CONFIG --mach A:B:STEP … -o OUT.csv|OUT.json`:
//! design points over a Cartesian grid, evaluated in parallel (rayon),
//! written atomically with a progress bar.
//!
//! The grid and its rows are [`stability_io::sweep`]'s, the computation
//! [`stability_core::design::sweep`]'s; this command parses the options and writes
//! the rows: the grid is evaluated in chunks, within a chunk blocks of
//! points are evaluated and formatted in parallel into their own buffers,
//! and a chunk is written while the next is computed.

use crate::Failure;
use crate::args::ModelArgs;
use crate::output::AtomicFile;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rayon::prelude::*;
use stability_core::design::sweep::{Axes, SweepError};
use stability_core::numerics::display::sig;
use stability_io::config::{Config, overridden};
use stability_io::diag::{InputError, IoError};
use stability_io::files::write_error;
use stability_io::format::{Format, Table};
use stability_io::sweep::{Given, Grid, axes, check_flight_limits, parse_range};
use std::io::Write as _;
use std::path::Path;

/// The command's options.
#[derive(Debug, Clone, clap::Args)]
pub struct Args {
    /// The base design point (TOML).
    pub config: String,
    /// Mach numbers: A:B:STEP (inclusive), a list A,B,… or one value.
    #[arg(long, allow_hyphen_values = true)]
    pub mach: String,
    /// Leading-edge sweeps in degrees, A:B:STEP, A,B,… or one value.
    #[arg(long, allow_hyphen_values = true)]
    pub sweep: Option<String>,
    /// c.g. positions h, A:B:STEP, A,B,… or one value.
    #[arg(long, allow_hyphen_values = true)]
    pub cg: Option<String>,
    /// Relative densities μ₁, A:B:STEP, A,B,… or one value.
    #[arg(long, allow_hyphen_values = true)]
    pub mu1: Option<String>,
    /// Pitching inertias i_B, A:B:STEP, A,B,… or one value.
    #[arg(long, allow_hyphen_values = true)]
    pub ib: Option<String>,
    /// Pressure altitudes (1976 standard atmosphere) in the config's units
    /// (m or ft), A:B:STEP, A,B,… or one value: a physical flight
    /// condition's `altitude` (the config must give one), each point's μ₁,
    /// i_B, C_L·M² and speed of sound from it.
    #[arg(long, allow_hyphen_values = true)]
    pub altitude: Option<String>,
    /// Masses in the config's units (kg or slug; in place of its mass or
    /// weight), A:B:STEP, A,B,… or one value: a physical flight condition
    /// only.
    #[arg(long, allow_hyphen_values = true)]
    pub mass: Option<String>,
    /// Pitching moments of inertia I_y in the config's units (kg·m² or
    /// slug·ft²), A:B:STEP, A,B,… or one value: a physical flight
    /// condition only.
    #[arg(long = "iy", alias = "I_y", allow_hyphen_values = true)]
    pub i_y: Option<String>,
    /// The output file, .csv or .json.
    #[arg(short = 'o', long = "output")]
    pub output: String,
    /// Add the quartic inputs (the twelve derivatives x_u … m_q and c_l,
    /// report notation) to each row, e.g. to feed another tool.
    #[arg(long)]
    pub derivatives: bool,
    #[command(flatten)]
    pub model: ModelArgs,
}

/// The list of the columns after `sweep --help`: every column of the
/// rows, from their table ([`stability_io::sweep::columns`]).
pub fn columns_help() -> String {
    let list = stability_io::sweep::columns::listing("--derivatives");
    format!("Columns (name [unit]: meaning):\n{list}")
}

/// The options' flags, in the order of [`Axes::NAMES`] and
/// [`Axes::FLIGHT_NAMES`].
const FLAGS: [&str; 8] = ["mach", "sweep", "cg", "mu1", "ib", "altitude", "mass", "iy"];

/// The grid of the options about the config's design point.
pub fn grid(o: &Args, cfg: &Config) -> Result<Grid, String> {
    let range = |k: usize, t: &Option<String>| t.as_deref().map(|t| parse_range(FLAGS[k], t));
    let given = Given {
        mach: Some(parse_range(FLAGS[0], &o.mach)?),
        sweep_deg: range(1, &o.sweep).transpose()?,
        cg: range(2, &o.cg).transpose()?,
        mu1: range(3, &o.mu1).transpose()?,
        i_b: range(4, &o.ib).transpose()?,
        altitude: range(5, &o.altitude).transpose()?,
        mass: range(6, &o.mass).transpose()?,
        i_y: range(7, &o.i_y).transpose()?,
    };
    let axes: Axes = axes(given, &cfg.case, cfg.physical.is_some())
        .map_err(|e| format!("--{}: {}", FLAGS[e.axis], e.message))?;
    let grid = Grid::new(cfg.case.clone(), axes, cfg.physical.as_ref()).map_err(|e| match e {
        SweepError::Planform { sweep_deg, error } => format!("--sweep {sweep_deg}: {error}"),
        SweepError::FlightAxis { axis, value, error } => {
            let k = Axes::FLIGHT_NAMES
                .iter()
                .position(|n| *n == axis)
                .unwrap_or(0);
            format!("--{} {value}: {error}", FLAGS[5 + k])
        }
        e @ SweepError::NotPressureAltitude { .. } => format!("--altitude: {e}"),
        e => e.to_string(),
    })?;
    check_flight_limits(&grid.sweep)?;
    Ok(grid)
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

pub fn run(o: &Args) -> Result<(), Failure> {
    let (cfg, read) =
        stability_io::files::recording(|| overridden(&o.config, &o.model.overrides()));
    let cfg = cfg?;
    let bad = |m: String| Failure::Input(InputError::file(&o.config, m));
    let format = Format::of_file(&o.output).map_err(|e| bad(format!("-o {}: {e}", o.output)))?;
    let outputs = [crate::overwrite::Named::new("-o", &o.output)];
    crate::overwrite::refuse("CONFIG", &o.config, &read, &outputs)?;
    let grid = grid(o, &cfg).map_err(&bad)?;
    let out = Path::new(&o.output);
    let write_err = |e: std::io::Error| Failure::Io(write_error(out, &e));
    let mut file = AtomicFile::create(out).map_err(write_err)?;
    let total = grid.points();
    let bar = progress_bar(total);
    // the lifting surface's solves, once per (planform, Mach), in parallel
    grid.sweep.prepare();
    let rows = Rows {
        table: Table::new(format),
        derivatives: o.derivatives,
    };
    let head = rows.table.head(grid.columns(o.derivatives).map(|c| c.name));
    let first = chunk(&grid, rows, 0);
    fits(out, head.len(), &first, total)?;
    file.write_all(head.as_bytes()).map_err(write_err)?;
    write_points(&mut file, &grid, rows, &bar, first).map_err(write_err)?;
    file.write_all(rows.table.foot().as_bytes())
        .map_err(write_err)?;
    file.commit().map_err(write_err)?;
    bar.finish_and_clear();
    let mut message = format!("wrote {total} design points to {}\n", o.output);
    for line in cfg.tables_summary() {
        message.push_str(&format!("  tables: {line}\n"));
    }
    crate::output::print(&message)
}

/// How the rows are written: as CSV or JSON, with the derivatives or not.
#[derive(Clone, Copy)]
struct Rows {
    table: Table,
    derivatives: bool,
}

/// The points of a chunk.
const CHUNK: usize = 1 << 16;

/// The rows of the chunk from point `start`: blocks of points evaluated
/// and formatted in parallel, each into its own buffer.
fn chunk(grid: &Grid, rows: Rows, start: usize) -> Vec<Vec<u8>> {
    const BLOCK: usize = 1 << 10;
    let end = (start + CHUNK).min(grid.points());
    (start..end)
        .step_by(BLOCK)
        .collect::<Vec<_>>()
        .into_par_iter()
        .map(|b| grid.rows(b..(b + BLOCK).min(end), rows.table, rows.derivatives))
        .collect()
}

/// Refuses a grid whose file would not fit where it is written: its size
/// estimated from the first chunk's rows (bytes per row × rows), against
/// the room the file system (and the file-size limit) leaves this process.
fn fits(out: &Path, head: usize, first: &[Vec<u8>], total: usize) -> Result<(), Failure> {
    let rows = total.min(CHUNK);
    let bytes: usize = first.iter().map(Vec::len).sum();
    let per_row = bytes as f64 / rows.max(1) as f64;
    let estimate = head as f64 + per_row * total as f64 + 3.0;
    let dir = match out.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let Some(room) = crate::output::room(dir) else {
        return Ok(());
    };
    if estimate <= room.bytes as f64 {
        return Ok(());
    }
    Err(Failure::Io(IoError::new(
        "cannot write",
        out,
        format!(
            "the grid's {total} rows need about {} ({} bytes a row, measured on the first {rows}), more than the {} {}; sweep a smaller grid, or write where there is room",
            crate::output::bytes(estimate),
            sig(per_row, 3),
            crate::output::bytes(room.bytes as f64),
            room.limited_by
        ),
    )))
}

/// Writes the grid's rows, chunk by chunk from `first` (the first chunk's),
/// writing chunk k while chunk k + 1 is computed.
fn write_points(
    file: &mut AtomicFile,
    grid: &Grid,
    rows: Rows,
    bar: &ProgressBar,
    first: Vec<Vec<u8>>,
) -> std::io::Result<()> {
    let total = grid.points();
    let mut pending = first;
    let mut start = CHUNK;
    loop {
        let (written, next) = rayon::join(
            || -> std::io::Result<()> {
                for b in &pending {
                    file.write_all(b)?;
                }
                Ok(())
            },
            || (start < total).then(|| chunk(grid, rows, start)),
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
