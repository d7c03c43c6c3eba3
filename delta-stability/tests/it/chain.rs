//! Commands that chain (issue 20, item 4): a config → `analyze
//! --write-derivatives` → a derivative file every command reads →
//! `response` in seconds to an elevon step in degrees → `--state-space`
//! with n_z at the c.g. → the generated python-control script.

use crate::common;

use common::{Scratch, json, path, run_err, run_ok, stderr, stdout};
use serde_json::Value;
use std::path::Path;

const CONFIG: &str = "examples/delta-60-physical.toml";
const INPUT: i32 = 2;

/// FNV-1a 64 written out here from its definition (offset basis
/// 0xcbf29ce484222325, prime 0x100000001b3), for the header's hash.
fn fnv1a64(bytes: &[u8]) -> u64 {
    bytes.iter().fold(14_695_981_039_346_656_037, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(1_099_511_628_211)
    })
}

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * a.abs().max(b.abs())
}

/// The four roots of a `--json` page, (re, im) in 1/τ and in 1/s.
fn roots(v: &Value) -> Vec<[f64; 4]> {
    let f = |z: &Value, k: &str| z[k].as_f64().unwrap_or(f64::NAN);
    v["roots"]
        .as_array()
        .expect("roots")
        .iter()
        .map(|z| [f(z, "re"), f(z, "im"), f(z, "re_s"), f(z, "im_s")])
        .collect()
}

fn assert_same_roots(a: &Value, b: &Value) {
    let (ra, rb) = (roots(a), roots(b));
    assert_eq!(ra.len(), 4);
    for (x, y) in ra.iter().zip(&rb) {
        let scale = x[0].hypot(x[1]);
        for k in 0..4 {
            if x[k].is_nan() {
                assert!(y[k].is_nan(), "{x:?} vs {y:?}");
                continue;
            }
            let s = if k < 2 { scale } else { x[2].hypot(x[3]) };
            assert!((x[k] - y[k]).abs() <= 1e-12 * s, "{x:?} vs {y:?}");
        }
    }
}

/// A CSV's columns by name.
fn columns(text: &str) -> std::collections::BTreeMap<String, Vec<f64>> {
    let mut lines = text.lines();
    let names: Vec<&str> = lines.next().expect("a header").split(',').collect();
    let mut out: std::collections::BTreeMap<String, Vec<f64>> = Default::default();
    for line in lines {
        for (name, cell) in names.iter().zip(line.split(',')) {
            let v = if cell.is_empty() {
                f64::NAN
            } else {
                cell.parse().expect("a number")
            };
            out.entry(name.to_string()).or_default().push(v);
        }
    }
    out
}

fn read(p: &Path) -> String {
    std::fs::read_to_string(p).expect("the file was written")
}

#[test]
fn a_config_and_its_derivative_file_give_the_same_roots() {
    let dir = Scratch::new();
    for (config, extra) in [
        (CONFIG, vec![]),
        (
            "examples/delta-60.toml",
            vec!["--mach", "1.2", "--cg", "0.3"],
        ),
    ] {
        let out = dir.path().join("dp.toml");
        // by default each root is at its own complex frequency (the
        // p-method), which constant derivatives cannot give: the file says
        // so, and its quartic's roots are the k-method's
        let mut default = vec!["analyze", config, "--write-derivatives", path(&out)];
        default.extend(&extra);
        run_ok(&default);
        let said = read(&out);
        assert!(
            said.contains("their quartic's roots are the k-method's"),
            "{said}"
        );
        let mut args = vec![
            "analyze",
            config,
            "--json",
            "--frequency-method",
            "k",
            "--write-derivatives",
            path(&out),
        ];
        args.extend(&extra);
        let analysed = json(&run_ok(&args));
        let text = read(&out);
        // the provenance: the config by path, size and hash, and the command
        let cfg = std::fs::read(common::root().join(config)).unwrap();
        let hash = format!("{} bytes, FNV-1a {:016x}", cfg.len(), fnv1a64(&cfg));
        assert!(
            text.starts_with(&format!("# The design point of {config}")),
            "{text}"
        );
        assert!(text.contains(&hash), "{text}");
        assert!(text.contains(&format!("Written by `delta-stability analyze {config}")));
        assert!(!text.contains("k-method's"), "{text}");
        for flag in &extra {
            assert!(text.lines().take(4).any(|l| l.contains(flag)), "{text}");
        }
        // read back by quartic: the same fifteen inputs, so the same roots
        let read_back = json(&run_ok(&["quartic", path(&out), "--json"]));
        assert_same_roots(&analysed, &read_back);
        assert_eq!(analysed["tau_s"].is_null(), read_back["tau_s"].is_null());
        if let Some(t) = analysed["tau_s"].as_f64() {
            assert!(close(t, read_back["tau_s"].as_f64().unwrap(), 1e-14));
        }
        assert_eq!(text.contains("[dimensional]"), config == CONFIG);
        assert_eq!(text.contains("[control]"), config == CONFIG);
    }
}

#[test]
fn response_and_sensitivity_read_a_config_as_its_derivative_file() {
    let dir = Scratch::new();
    let dp = dir.path().join("dp.toml");
    run_ok(&["analyze", CONFIG, "--write-derivatives", path(&dp)]);
    let args = ["--until-s", "2", "--steps", "50", "--elevator-deg", "-2"];
    let of = |file: &str| stdout(&run_ok(&[&["response", file][..], &args[..]].concat()));
    assert_eq!(of(CONFIG), of(path(&dp)));
    let sens = |file: &str| {
        let mut v = json(&run_ok(&["sensitivity", file, "--json"]));
        v["file"] = Value::Null;
        v
    };
    assert_eq!(sens(CONFIG), sens(path(&dp)));
}

#[test]
fn the_wrong_kind_of_file_or_a_missing_table_is_said_plainly() {
    let err = stderr(&run_err(&["quartic", CONFIG], INPUT));
    assert!(
        err.contains("design-point config") && err.contains("analyze"),
        "{err}"
    );
    let dp = "examples/tailless-delta-45.toml";
    let err = stderr(&run_err(&["analyze", dp], INPUT));
    assert!(
        err.contains("derivative file") && err.contains("quartic"),
        "{err}"
    );
    // seconds need τ; a deflection needs [control]
    let err = stderr(&run_err(&["response", dp, "--until-s", "1"], INPUT));
    assert!(err.contains("--until-s") && err.contains("τ"), "{err}");
    let err = stderr(&run_err(
        &["response", dp, "--until", "1", "--elevator-deg", "1"],
        INPUT,
    ));
    assert!(err.contains("[control]"), "{err}");
    let err = stderr(&run_err(
        &[
            "response",
            CONFIG,
            "--until",
            "1",
            "--elevator-deg",
            "1",
            "--input",
            "initial",
        ],
        INPUT,
    ));
    assert!(err.contains("--input step"), "{err}");
}

/// The derivative set's value `name` (the `[derivatives]` or `[flight]`
/// line of a file written by `--write-derivatives`).
fn value(text: &str, name: &str) -> f64 {
    let line = text
        .lines()
        .find(|l| l.starts_with(&format!("{name} = ")))
        .unwrap_or_else(|| panic!("{name} in {text}"));
    line.split('=').nth(1).unwrap().trim().parse().unwrap()
}

#[test]
fn the_chained_workflow_runs_end_to_end() {
    let dir = Scratch::new();
    let (dp, csv, ss) = (
        dir.path().join("dp.toml"),
        dir.path().join("r.csv"),
        dir.path().join("ss.json"),
    );
    run_ok(&["analyze", CONFIG, "--write-derivatives", path(&dp)]);
    let text = read(&dp);
    let deg: f64 = 1.0;
    run_ok(&[
        "response",
        path(&dp),
        "--until-s",
        "6",
        "--steps",
        "600",
        "--elevator-deg",
        "1",
        "--csv",
        path(&csv),
    ]);
    let r = columns(&read(&csv));
    // τ = m/(½ρSV) from the 1976 standard atmosphere's published values at
    // 11 000 m (ρ = 0.36392 kg/m³, a = 295.07 m/s), the planform by hand
    // (S = ½·12·2·12·tan 30° m²) and M = 0.9: seconds are t̂·τ
    let s = 12.0 * 12.0 * (30.0_f64).to_radians().tan();
    let tau = 12000.0 / (0.5 * 0.36392 * s * 0.9 * 295.07);
    let (t_hat, t_s) = (&r["t_hat"], &r["t_s"]);
    assert!(close(*t_s.last().unwrap(), 6.0, 1e-12));
    assert!(
        close(t_s[300] / t_hat[300], tau, 2e-5),
        "{} vs {tau}",
        t_s[300] / t_hat[300]
    );
    // n_z at 0⁺: the elevon's lift alone, −C_Zδ·δ/(A·C_L) with
    // A = 1 − z_ẇ/μ₁ and the config's C_Ldelta = 0.6 per radian
    let (c_l, z_wdot, mu1) = (
        value(&text, "c_l"),
        value(&text, "z_wdot"),
        value(&text, "mu1"),
    );
    let n0 = 0.6 * deg.to_radians() / ((1.0 - z_wdot / mu1) * c_l);
    let n_z = &r["n_z"];
    assert!(close(n_z[0], n0, 1e-10), "{} vs {n0}", n_z[0]);
    // the state space of the same file: y = C x + D δ's n_z row on the
    // response's states (q in rad/s = q̂/τ) is the response's n_z
    run_ok(&["quartic", path(&dp), "--state-space", path(&ss)]);
    let e: Value = serde_json::from_str(&read(&ss)).unwrap();
    assert_eq!(e["outputs"][4], "gamma");
    assert_eq!(e["outputs"][5], "n_z");
    let row = |m: &str, i: usize| -> Vec<f64> {
        e[m][i]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect()
    };
    let (c, d) = (row("C", 5), row("D", 5)[0]);
    let tau_s = e["tau_s"].as_f64().unwrap();
    let peak = n_z.iter().fold(0.0_f64, |a, n| a.max(n.abs()));
    for k in (1..=600).step_by(23) {
        let x = [
            r["u_hat"][k],
            r["w_hat"][k],
            r["q_hat"][k] / tau_s,
            r["theta"][k],
        ];
        let y: f64 = (0..4).map(|j| c[j] * x[j]).sum::<f64>() + d * deg.to_radians();
        assert!(
            (y - n_z[k]).abs() < 1e-9 * peak,
            "t = {}: {y} vs {}",
            t_s[k],
            n_z[k]
        );
        assert!((r["gamma"][k] - (r["theta"][k] - r["w_hat"][k])).abs() < 1e-11);
    }
    python_control_agrees(&ss, e["t_final"].as_f64().unwrap(), &dp);
}

/// The generated python-control script, run where `python3` (or
/// `$PYTHON`) imports `control`: its step response (python-control's own
/// integration) against `response`'s exact one at the same times.
fn python_control_agrees(ss: &Path, t_final: f64, dp: &Path) {
    let python = std::env::var("PYTHON").unwrap_or_else(|_| "python3".into());
    let probe = std::process::Command::new(&python)
        .args(["-c", "import control"])
        .output();
    if !probe.as_ref().is_ok_and(|o| o.status.success()) {
        eprintln!(
            "skipped running the python-control script: `{python}` cannot import control (set PYTHON to one that can)"
        );
        return;
    }
    let out = std::process::Command::new(&python)
        .arg(ss.with_extension("py"))
        .output()
        .expect("python runs");
    let text = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(
        out.status.success(),
        "{text}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let header = text
        .lines()
        .position(|l| l.trim_start().starts_with("t "))
        .expect(&text);
    let rows: Vec<Vec<f64>> = text
        .lines()
        .skip(header + 1)
        .map(|l| l.split_whitespace().map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 11, "{text}");
    let t = format!("{t_final:?}");
    let ours = stdout(&run_ok(&[
        "response",
        path(dp),
        "--until-s",
        &t,
        "--steps",
        "400",
        "--elevator-deg",
        "1",
    ]));
    let r = columns(&ours);
    let peak = r["n_z"].iter().fold(0.0_f64, |a, n| a.max(n.abs()));
    for (i, row) in rows.iter().enumerate() {
        let k = 40 * i;
        assert!(close(row[0], r["t_s"][k], 1e-6), "{row:?}");
        // outputs u/V, alpha, q, theta, gamma, n_z; printed to 7 digits
        assert!(
            (row[6] - r["n_z"][k]).abs() < 2e-6 * peak,
            "{row:?} vs {}",
            r["n_z"][k]
        );
        assert!((row[5] - r["gamma"][k]).abs() < 1e-6 * r["gamma"][k].abs().max(1e-3));
        assert!((row[2] - r["w_hat"][k]).abs() < 1e-6 * r["w_hat"][k].abs().max(1e-3));
    }
    eprintln!("ran the python-control script with {python}: its step response agrees");
}
