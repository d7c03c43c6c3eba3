//! `cargo xtask bench`: the sweep's throughput in design points per second,
//! side by side in one run with (a) the same design points through
//! python-control point by point (and numpy's `eigvals` point by point) and
//! (b) numpy's batched eigenvalues (benches/sweep_baseline.py).
//!
//! Ours is the whole command as a user runs it — process start, planform →
//! coefficients → derivatives → quartic → roots → modes → criteria for each
//! point, and the CSV written. The baselines are handed our derivatives and
//! do only the roots and the short period's cycles to half amplitude. A
//! Python virtual environment with numpy and python-control is made under
//! target/bench/ on first use.
//!
//! The grid is defined once, in benches/sweep-grid.json, which the baseline
//! script reads too; the number of points is counted from the CSV the sweep
//! writes, not restated.

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

const GRID_FILE: &str = "benches/sweep-grid.json";

fn run(cmd: &mut Command) -> Result<std::process::Output, String> {
    let out = cmd
        .output()
        .map_err(|e| format!("cannot run {cmd:?}: {e}"))?;
    if !out.status.success() {
        return Err(format!(
            "{cmd:?} failed:\n{}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        ));
    }
    Ok(out)
}

/// The `delta-stability sweep` arguments of benches/sweep-grid.json: the
/// base file, then `--name value` for each of `options` (optional) and
/// `--axis range` for each axis.
fn grid_args(grid: &Value) -> Result<Vec<String>, String> {
    let bad = || {
        format!(
            "{GRID_FILE}: expected `base`, `axes` = [[name, range], …] and optionally `options` = [[name, value], …]"
        )
    };
    let mut args = vec![grid["base"].as_str().ok_or_else(bad)?.to_string()];
    let options = grid["options"].as_array().map(Vec::as_slice).unwrap_or(&[]);
    let axes = grid["axes"].as_array().ok_or_else(bad)?;
    for axis in options.iter().chain(axes) {
        match axis.as_array().map(Vec::as_slice) {
            Some([Value::String(name), Value::String(range)]) => {
                args.push(format!("--{name}"));
                args.push(range.clone());
            }
            _ => return Err(bad()),
        }
    }
    Ok(args)
}

fn read_grid(root: &Path) -> Result<Value, String> {
    let text = std::fs::read_to_string(root.join(GRID_FILE))
        .map_err(|e| format!("cannot read {GRID_FILE}: {e}"))?;
    serde_json::from_str(&text).map_err(|e| format!("{GRID_FILE}: {e}"))
}

/// The release binary, and the Python of target/bench/venv (made on first
/// use, with numpy and python-control).
fn setup(root: &Path, dir: &Path) -> Result<(PathBuf, PathBuf), String> {
    let bin = build_release(root, dir)?;
    let python = dir.join("venv/bin/python");
    if !python.exists() {
        eprintln!("making target/bench/venv with numpy and python-control…");
        run(Command::new("python3")
            .args(["-m", "venv"])
            .arg(dir.join("venv")))?;
        run(Command::new(&python).args(["-m", "pip", "install", "-q", "numpy", "control"]))?;
    }
    Ok((bin, python))
}

/// Makes `dir` and builds the release binary, returning its path.
fn build_release(root: &Path, dir: &Path) -> Result<PathBuf, String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    eprintln!("building delta-stability (release)…");
    run(Command::new(env!("CARGO")).current_dir(root).args([
        "build",
        "--release",
        "-q",
        "-p",
        "delta-stability",
    ]))?;
    Ok(root.join("target/release/delta-stability"))
}

/// One timed `sweep` over the grid into `dir/out`, in seconds.
fn timed_sweep(
    root: &Path,
    bin: &Path,
    args: &[String],
    extra: &[&str],
    out: &Path,
) -> Result<f64, String> {
    // each run starts with no dirty pages of the last one to flush
    let _ = std::fs::remove_file(out);
    let _ = Command::new("sync").status();
    let t = Instant::now();
    run(Command::new(bin)
        .current_dir(root)
        .arg("sweep")
        .args(args)
        .args(extra)
        .arg("-o")
        .arg(out))?;
    Ok(t.elapsed().as_secs_f64())
}

/// The design points a sweep wrote: its CSV's rows after the header.
fn points_in(csv: &Path) -> Result<usize, String> {
    let text = std::fs::read_to_string(csv).map_err(|e| format!("{}: {e}", csv.display()))?;
    Ok(text.lines().count().saturating_sub(1))
}

/// Our runs: the median of three plain sweeps, and one with derivatives
/// (the baselines' input). Seconds, and the number of points.
struct Ours {
    seconds: Vec<f64>,
    with_derivatives: f64,
    points: usize,
}

fn measure_ours(root: &Path, bin: &Path, args: &[String], dir: &Path) -> Result<Ours, String> {
    eprintln!("delta-stability sweep over {GRID_FILE}, 3 runs…");
    let mut seconds: Vec<f64> = (0..3)
        .map(|_| timed_sweep(root, bin, args, &[], &dir.join("sweep.csv")))
        .collect::<Result<_, _>>()?;
    seconds.sort_by(f64::total_cmp);
    let with_derivatives = timed_sweep(
        root,
        bin,
        args,
        &["--derivatives"],
        &dir.join("sweep-derivatives.csv"),
    )?;
    Ok(Ours {
        seconds,
        with_derivatives,
        points: points_in(&dir.join("sweep.csv"))?,
    })
}

/// The table's rows: (route, design points per second, points, worst
/// relative difference of the short-period root from ours).
fn rows(ours: &Ours, base: &Value) -> Vec<(&'static str, f64, usize, f64)> {
    let rate = |k: &str| base[k]["points_per_second"].as_f64().unwrap_or(f64::NAN);
    let worst = |k: &str| {
        base[k]["worst_relative_difference"]
            .as_f64()
            .unwrap_or(f64::NAN)
    };
    let count = |k: &str| base[k]["points"].as_u64().unwrap_or(0) as usize;
    let n = ours.points;
    vec![
        (
            "delta-stability sweep → CSV (median of 3)",
            n as f64 / ours.seconds[1],
            n,
            f64::NAN,
        ),
        (
            "delta-stability sweep --derivatives → CSV",
            n as f64 / ours.with_derivatives,
            n,
            f64::NAN,
        ),
        (
            "(a) python-control ss + damp, point by point",
            rate("python_control"),
            count("python_control"),
            worst("python_control"),
        ),
        (
            "(a') numpy eigvals, point by point",
            rate("numpy_pointwise"),
            count("numpy_pointwise"),
            worst("numpy_pointwise"),
        ),
        (
            "(b) numpy batched eigvals",
            rate("numpy_batched"),
            count("numpy_batched"),
            worst("numpy_batched"),
        ),
    ]
}

fn table(ours: &Ours, base: &Value, threads: usize) -> String {
    let ours_rate = ours.points as f64 / ours.seconds[1];
    let mut table = format!(
        "Sweep throughput, {threads} cores; versions {}\n\n\
         | route | points | design points/s | ours ÷ route | short-period root vs ours (worst rel.) |\n\
         |---|---:|---:|---:|---:|\n",
        base["versions"]
    );
    for (name, r, n, diff) in rows(ours, base) {
        let d = if diff.is_nan() {
            "—".to_string()
        } else {
            format!("{diff:.1e}")
        };
        table.push_str(&format!(
            "| {name} | {n} | {r:.0} | {:.1}× | {d} |\n",
            ours_rate / r
        ));
    }
    table
}

pub fn bench(root: &Path) -> Result<(), String> {
    let dir = root.join("target/bench");
    let grid = read_grid(root)?;
    let args = grid_args(&grid)?;
    let (bin, python) = setup(root, &dir)?;
    let ours = measure_ours(root, &bin, &args, &dir)?;

    eprintln!("python-control and numpy on the same points…");
    let out = run(Command::new(&python)
        .arg(root.join("benches/sweep_baseline.py"))
        .arg(root.join(GRID_FILE))
        .arg(dir.join("sweep-derivatives.csv")))?;
    let base: Value = serde_json::from_slice(&out.stdout)
        .map_err(|e| format!("sweep_baseline.py printed no JSON: {e}"))?;
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let table = table(&ours, &base, threads);
    println!("{table}");
    let json = serde_json::json!({
        "threads": threads,
        "grid": grid,
        "sweep_arguments": args,
        "points": ours.points,
        "ours_seconds": ours.seconds,
        "ours_points_per_second": ours.points as f64 / ours.seconds[1],
        "ours_with_derivatives_seconds": ours.with_derivatives,
        "baselines": base,
    });
    let write = |name: &str, text: String| {
        std::fs::write(dir.join(name), text).map_err(|e| format!("target/bench/{name}: {e}"))
    };
    write(
        "sweep-throughput.json",
        serde_json::to_string_pretty(&json).unwrap_or_default(),
    )?;
    write("sweep-throughput.md", table)?;
    eprintln!("wrote target/bench/sweep-throughput.{{md,json}}");
    Ok(())
}

/// The report's budget on 2 cores (issue 11: "within 10 s on 2 cores once
/// built").
const REPORT_BUDGET_S: f64 = 10.0;

/// The median wall time of three `report` runs, `threads` rayon threads
/// (`None`: every core).
fn timed_reports(root: &Path, bin: &Path, threads: Option<usize>) -> Result<f64, String> {
    let out = root.join("target/bench/report");
    let mut seconds = Vec::new();
    for _ in 0..3 {
        let _ = std::fs::remove_dir_all(&out);
        let mut cmd = Command::new(bin);
        cmd.current_dir(root).arg("report").arg("--out").arg(&out);
        if let Some(n) = threads {
            cmd.env("RAYON_NUM_THREADS", n.to_string());
        }
        let t = Instant::now();
        run(&mut cmd)?;
        seconds.push(t.elapsed().as_secs_f64());
    }
    seconds.sort_by(f64::total_cmp);
    Ok(seconds[1])
}

/// `cargo xtask bench-report`: the main job's time on every core against
/// one core, in the same run, and against the budget.
pub fn bench_report(root: &Path) -> Result<(), String> {
    let dir = root.join("target/bench");
    let bin = build_release(root, &dir)?;
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    eprintln!("delta-stability report, 3 runs on {threads} cores and 3 on one…");
    let all = timed_reports(root, &bin, None)?;
    let one = timed_reports(root, &bin, Some(1))?;
    let table = format!(
        "| `delta-stability report` (median of 3) | wall (s) | ratio |\n| --- | --- | --- |\n| {threads} cores | {all:.2} | 1 |\n| 1 core (RAYON_NUM_THREADS=1) | {one:.2} | {:.2}× |\n| budget on 2 cores | {REPORT_BUDGET_S:.0} | {:.2}× |\n",
        one / all,
        REPORT_BUDGET_S / all
    );
    println!("{table}");
    std::fs::write(dir.join("report-time.md"), &table)
        .map_err(|e| format!("target/bench/report-time.md: {e}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_grid_file_gives_the_sweep_its_arguments() {
        let grid = read_grid(&crate::root()).unwrap_or_else(|e| panic!("{e}"));
        let args = grid_args(&grid).unwrap_or_else(|e| panic!("{e}"));
        assert!(crate::root().join(&args[0]).is_file(), "{}", args[0]);
        let flags: Vec<&str> = args[1..].iter().step_by(2).map(String::as_str).collect();
        assert_eq!(flags, ["--damping", "--mach", "--cg", "--mu1", "--sweep"]);
        assert_eq!(args[2], "faired-slender");
        assert!(grid["pointwise"].as_u64().is_some_and(|n| n > 0));
    }
}
