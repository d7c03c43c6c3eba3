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

use std::path::Path;
use std::process::Command;
use std::time::Instant;

/// The grid: the 60° delta's base point, Mach 0.5–2.0 × c.g. 0.20–0.30 ×
/// μ₁ 50–500 × sweep 45°–75°.
const GRID: [&str; 9] = [
    "examples/delta-60.toml",
    "--mach",
    "0.5:2:0.0015",
    "--cg",
    "0.2:0.3:0.005",
    "--mu1",
    "50:500:50",
    "--sweep",
    "45:75:7.5",
];
const POINTS: usize = 1001 * 21 * 10 * 5;
/// Points the point-by-point baselines take (they are slow).
const POINTWISE: usize = 20_000;

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

pub fn bench(root: &Path) -> Result<(), String> {
    let dir = root.join("target/bench");
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    eprintln!("building delta-stability (release)…");
    run(Command::new(env!("CARGO")).current_dir(root).args([
        "build",
        "--release",
        "-q",
        "-p",
        "delta-stability",
    ]))?;
    let bin = root.join("target/release/delta-stability");
    let python = dir.join("venv/bin/python");
    if !python.exists() {
        eprintln!("making target/bench/venv with numpy and python-control…");
        run(Command::new("python3")
            .args(["-m", "venv"])
            .arg(dir.join("venv")))?;
        run(Command::new(&python).args(["-m", "pip", "install", "-q", "numpy", "control"]))?;
    }

    let sweep = |extra: &[&str], out: &str| -> Result<f64, String> {
        // each run starts with no dirty pages of the last one to flush
        let _ = std::fs::remove_file(dir.join(out));
        let _ = Command::new("sync").status();
        let t = Instant::now();
        run(Command::new(&bin)
            .current_dir(root)
            .arg("sweep")
            .args(GRID)
            .args(extra)
            .arg("-o")
            .arg(dir.join(out)))?;
        Ok(t.elapsed().as_secs_f64())
    };
    eprintln!("delta-stability sweep, {POINTS} design points, 3 runs…");
    let mut ours: Vec<f64> = (0..3)
        .map(|_| sweep(&[], "sweep.csv"))
        .collect::<Result<_, _>>()?;
    ours.sort_by(f64::total_cmp);
    let with_derivatives = sweep(&["--derivatives"], "sweep-derivatives.csv")?;

    eprintln!("python-control and numpy on the same points…");
    let out = run(Command::new(&python)
        .arg(root.join("benches/sweep_baseline.py"))
        .arg(dir.join("sweep-derivatives.csv"))
        .arg(POINTWISE.to_string()))?;
    let base: serde_json::Value = serde_json::from_slice(&out.stdout)
        .map_err(|e| format!("sweep_baseline.py printed no JSON: {e}"))?;
    let rate = |k: &str| base[k]["points_per_second"].as_f64().unwrap_or(f64::NAN);
    let ours_rate = POINTS as f64 / ours[1];
    let rows = [
        (
            "delta-stability sweep → CSV (median of 3)",
            ours_rate,
            POINTS,
            f64::NAN,
        ),
        (
            "delta-stability sweep --derivatives → CSV",
            POINTS as f64 / with_derivatives,
            POINTS,
            f64::NAN,
        ),
        (
            "(a) python-control ss + damp, point by point",
            rate("python_control"),
            POINTWISE,
            base["python_control"]["worst_relative_difference"]
                .as_f64()
                .unwrap_or(f64::NAN),
        ),
        (
            "(a') numpy eigvals, point by point",
            rate("numpy_pointwise"),
            POINTWISE,
            base["numpy_pointwise"]["worst_relative_difference"]
                .as_f64()
                .unwrap_or(f64::NAN),
        ),
        (
            "(b) numpy batched eigvals",
            rate("numpy_batched"),
            base["points"].as_u64().unwrap_or(0) as usize,
            base["numpy_batched"]["worst_relative_difference"]
                .as_f64()
                .unwrap_or(f64::NAN),
        ),
    ];
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let mut table = format!(
        "Sweep throughput, {threads} cores; versions {}\n\n\
         | route | points | design points/s | ours ÷ route | short-period root vs ours (worst rel.) |\n\
         |---|---:|---:|---:|---:|\n",
        base["versions"]
    );
    for (name, r, n, diff) in rows {
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
    println!("{table}");
    let json = serde_json::json!({
        "threads": threads,
        "grid": GRID,
        "points": POINTS,
        "ours_seconds": ours,
        "ours_points_per_second": ours_rate,
        "ours_with_derivatives_seconds": with_derivatives,
        "baselines": base,
    });
    std::fs::write(
        dir.join("sweep-throughput.json"),
        serde_json::to_string_pretty(&json).unwrap_or_default(),
    )
    .map_err(|e| format!("target/bench/sweep-throughput.json: {e}"))?;
    std::fs::write(dir.join("sweep-throughput.md"), table)
        .map_err(|e| format!("target/bench/sweep-throughput.md: {e}"))?;
    eprintln!("wrote target/bench/sweep-throughput.{{md,json}}");
    Ok(())
}
