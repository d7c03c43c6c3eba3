//! `report CONFIG`: a design's own report across Mach number, checked by
//! routes other than its own — `analyze --mach M --json` and `sweep` at
//! the same Mach numbers (other commands, run as a user runs them), the
//! 1976 standard atmosphere's published values for τ, and the relations
//! the note states (eq 8's cycles, t½ = ln 2/|r|, CAP = ωₙ²/(n/α),
//! eq 42's K_n from E).

use crate::common;

use common::*;
use serde_json::Value;
use std::path::Path;

/// The figures every design report draws, and those only a physical
/// flight condition (times in seconds, g) adds.
const FIGURES: [&str; 16] = [
    "cycles-to-half",
    "roots-re",
    "roots-im",
    "damping-ratio",
    "short-period-frequency",
    "short-period-times",
    "phugoid-frequency",
    "phugoid-times",
    "standard",
    "levels-damping",
    "margins",
    "positions",
    "lift-slope",
    "drag",
    "stiffness",
    "damping-derivatives",
];
const PHYSICAL_FIGURES: [&str; 2] = ["cap", "levels-cap"];

fn read_json(p: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(p).expect("file")).expect("JSON")
}

/// Runs the report of `config` at `mach` into a scratch directory and
/// returns it with summary.json.
fn report(config: &str, mach: &str) -> (Scratch, Value) {
    let dir = Scratch::new();
    let out = dir.path().join("design");
    run_ok(&["report", config, "--mach", mach, "--out", path(&out)]);
    let summary = read_json(&out.join("summary.json"));
    (dir, summary)
}

/// Every figure named on the page exists as SVG (with its title) and CSV,
/// and the page links only to files the report wrote.
fn check_files(out: &Path, physical: bool) {
    let html = std::fs::read_to_string(out.join("index.html")).unwrap();
    let mut figures = FIGURES.to_vec();
    if physical {
        figures.extend(PHYSICAL_FIGURES);
    }
    for f in &figures {
        let svg = std::fs::read_to_string(out.join(format!("{f}.svg"))).unwrap();
        assert!(svg.starts_with("<svg") || svg.contains("<svg"), "{f}");
        assert!(out.join(format!("{f}.csv")).is_file(), "{f}.csv");
        assert!(
            html.contains(&format!("src=\"{f}.svg\"")),
            "{f} not on the page"
        );
    }
    for f in PHYSICAL_FIGURES {
        assert_eq!(out.join(format!("{f}.svg")).exists(), physical, "{f}");
    }
    for link in html
        .split("href=\"")
        .skip(1)
        .chain(html.split("src=\"").skip(1))
    {
        let target = link.split('"').next().unwrap();
        if let Some(file) = target.split('#').next().filter(|f| !f.is_empty()) {
            assert!(out.join(file).is_file(), "index.html links to {file}");
        }
    }
    assert!(out.join(".report-manifest.json").is_file());
    assert!(out.join("sources.csv").is_file());
}

/// `a` and `b` equal to 12 significant figures (both written by serde
/// from the same f64 in principle; a bit's difference is allowed).
fn close(a: &Value, b: &Value, what: &str) {
    match (a.as_f64(), b.as_f64()) {
        (Some(x), Some(y)) => assert!(
            (x - y).abs() <= 1e-12 * x.abs().max(y.abs()).max(1e-300),
            "{what}: {x} vs {y}"
        ),
        _ => assert_eq!(a, b, "{what}"),
    }
}

/// A point of summary.json against `analyze --mach M --json` of the same
/// config: the verdict, every mode's quantities, the criteria, CAP, the
/// derivatives and their sources.
fn agrees_with_analyze(config: &str, point: &Value) {
    let m = point["mach"].as_f64().unwrap();
    let a = json(&run_ok(&[
        "analyze",
        config,
        "--mach",
        &m.to_string(),
        "--json",
    ]));
    let at = |w: &str| format!("M = {m}: {w}");
    assert_eq!(point["verdict"], a["verdict"], "{}", at("verdict"));
    assert_eq!(point["stable"], a["stable"]);
    let (pm, am) = (
        point["modes"].as_array().unwrap(),
        a["modes"].as_array().unwrap(),
    );
    assert_eq!(pm.len(), am.len());
    for (p, q) in pm.iter().zip(am) {
        for (k, v) in q.as_object().unwrap() {
            close(&p[k], v, &at(&format!("{} {k}", q["name"])));
        }
    }
    let c = &a["criteria"];
    for k in ["m_thetadot", "m_thetadot_max", "margin", "margin_exact"] {
        close(
            &point["damping_standard"][k],
            &c["damping_standard"][k],
            &at(k),
        );
    }
    assert_eq!(point["mil_f_8785c"], c["mil_f_8785c"], "{}", at("levels"));
    for k in ["static_margin", "manoeuvre_margin"] {
        close(&point["margins"][k], &c["margins"][k], &at(k));
    }
    assert_eq!(
        point["short_period_frequency"].is_null(),
        a["short_period_frequency"].is_null()
    );
    if let Some(s) = a["short_period_frequency"].as_object() {
        for (k, v) in s {
            close(&point["short_period_frequency"][k], v, &at(k));
        }
    }
    for (k, v) in a["derivatives"].as_object().unwrap() {
        close(&point["derivatives"][k], v, &at(k));
    }
    assert_eq!(point["aerodynamics"]["origin"], a["aerodynamics"]["origin"]);
    close(
        &point["aerodynamic_centre"],
        &a["aerodynamics"]["aerodynamic_centre"]["value"],
        &at("H0"),
    );
    assert_eq!(point["damping"]["theory"], a["damping"]["theory"]);
    close(&point["tau_s"], &a["tau_s"], &at("tau"));
}

/// The relations the note states, on a point's own numbers: eq (8)'s
/// cycles to half amplitude (ln 2/2π)|s/r|, t½ = ln 2/|r|, ζ = −r/|λ|,
/// and eq (42)'s K_n = E/(2(μ₁/i_B)C_L²a).
fn obeys_the_notes_relations(point: &Value) {
    let ln2 = std::f64::consts::LN_2;
    for mode in point["modes"].as_array().unwrap() {
        let (r, s) = (mode["re"].as_f64().unwrap(), mode["im"].as_f64().unwrap());
        if s == 0.0 || r >= 0.0 {
            continue;
        }
        let cycles = ln2 / (2.0 * std::f64::consts::PI) * (s / r).abs();
        let rel = |a: f64, b: f64| (a - b).abs() / b.abs();
        assert!(rel(mode["cycles_to_half"].as_f64().unwrap(), cycles) < 1e-12);
        assert!(rel(mode["time_to_half"].as_f64().unwrap(), ln2 / r.abs()) < 1e-12);
        assert!(rel(mode["damping_ratio"].as_f64().unwrap(), -r / r.hypot(s)) < 1e-12);
        if let Some(t) = point["tau_s"].as_f64() {
            assert!(rel(mode["time_to_half_s"].as_f64().unwrap(), ln2 / r.abs() * t) < 1e-12);
        }
    }
}

#[test]
fn a_physical_designs_report_agrees_with_analyze_sweep_and_the_atmosphere() {
    let config = "examples/delta-60-physical.toml";
    let (dir, s) = report(config, "0.6,0.9,1.5");
    let out = dir.path().join("design");
    check_files(&out, true);
    assert_eq!(s["design"]["flight_condition"], "physical");
    let points = s["points"].as_array().unwrap();
    assert_eq!(points.len(), 3);
    // the 1976 standard atmosphere at 11 000 m (NOAA-S/T 76-1562, Table I):
    // ρ = 0.36392 kg/m³, a = 295.07 m/s; S = ½·12·(2·12·tan 30°) m²
    let area = 0.5 * 12.0 * (24.0 * 30f64.to_radians().tan());
    for p in points {
        agrees_with_analyze(config, p);
        obeys_the_notes_relations(p);
        let m = p["mach"].as_f64().unwrap();
        let tau = 12000.0 / (0.5 * 0.36392 * area * m * 295.07);
        let got = p["tau_s"].as_f64().unwrap();
        assert!(
            (got - tau).abs() < 1e-4 * tau,
            "M = {m}: τ {got} s, by hand {tau} s"
        );
        // CAP = ωₙ²/(n/α), n/α = −z_w/C_L, from the point's own numbers
        let wn = p["modes"][0]["natural_frequency_s"].as_f64().unwrap();
        let n_alpha = -p["derivatives"]["z_w"].as_f64().unwrap() / p["c_l"].as_f64().unwrap();
        let cap = p["short_period_frequency"]["cap"].as_f64().unwrap();
        assert!(
            (cap - wn * wn / n_alpha).abs() < 1e-12 * cap,
            "M = {m}: CAP {cap}"
        );
    }
    // a third route: the sweep's lean path (the lifting surface
    // interpolated in frequency, and the Mach box in Mach number, within
    // 2.5·10⁻³ of C_Lα: so within 3·10⁻³) at the same Mach numbers
    let csv = dir.path().join("sweep.csv");
    run_ok(&["sweep", config, "--mach", "0.6,0.9,1.5", "-o", path(&csv)]);
    let text = std::fs::read_to_string(&csv).unwrap();
    let head: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    let col = |name: &str| head.iter().position(|h| *h == name).unwrap();
    for (line, p) in text.lines().skip(1).zip(points) {
        let cells: Vec<&str> = line.split(',').collect();
        let v = |name: &str| cells[col(name)].parse::<f64>().unwrap();
        let sp = &p["modes"][0];
        for (c, k) in [
            ("sp_damping_ratio", "damping_ratio"),
            ("sp_cycles_to_half", "cycles_to_half"),
            ("sp_period_s", "period_s"),
        ] {
            let (a, b) = (v(c), sp[k].as_f64().unwrap());
            assert!(
                (a - b).abs() < 3e-3 * b.abs(),
                "M = {}: {c} {a} vs {b}",
                p["mach"]
            );
        }
        assert_eq!(
            cells[col("verdict")],
            p["verdict"]["overall"].as_str().unwrap()
        );
    }
    // the figure's CSV holds the summary's numbers
    let cyc = std::fs::read_to_string(out.join("cycles-to-half.csv")).unwrap();
    let row: Vec<f64> = cyc
        .lines()
        .nth(2)
        .unwrap()
        .split(',')
        .map(|c| c.parse().unwrap())
        .collect();
    assert_eq!(row[0], 0.9);
    let sp = points[1]["modes"][0]["cycles_to_half"].as_f64().unwrap();
    assert!((row[1] - sp).abs() < 1e-11 * sp, "{row:?} vs {sp}");
}

#[test]
fn a_non_dimensional_designs_report_agrees_with_analyze() {
    let config = "examples/delta-60.toml";
    let (dir, s) = report(config, "0.8:1.6:0.4");
    let out = dir.path().join("design");
    check_files(&out, false);
    assert_eq!(s["design"]["flight_condition"], "non-dimensional");
    assert_eq!(s["design"]["mu1"], 50.0);
    let points = s["points"].as_array().unwrap();
    let machs: Vec<f64> = points.iter().map(|p| p["mach"].as_f64().unwrap()).collect();
    assert_eq!(machs, [0.8, 1.2, 1.6]);
    for p in points {
        agrees_with_analyze(config, p);
        obeys_the_notes_relations(p);
        assert!(p["tau_s"].is_null() && p["modes"][0].get("period_s").is_none());
    }
    // the verdict's intervals are the points' verdicts
    let v = &s["verdict"];
    let all: Vec<&Value> = ["meets", "fails", "divergent"]
        .iter()
        .flat_map(|k| v[*k].as_array().unwrap())
        .collect();
    let covered: usize = all
        .iter()
        .map(|r| {
            machs
                .iter()
                .filter(|m| **m >= r[0].as_f64().unwrap() && **m <= r[1].as_f64().unwrap())
                .count()
        })
        .sum();
    assert_eq!(covered, 3);
    let html = std::fs::read_to_string(out.join("index.html")).unwrap();
    assert!(
        html.contains("units of τ") && html.contains("μ₁ = 50"),
        "the page says the condition"
    );
}

/// The default Mach numbers: 0.5 to 2.0 in steps of 0.05 about the
/// config's M = 1.2; a point without a result is reported, not fatal.
#[test]
fn the_default_range_and_a_point_without_a_result() {
    let dir = Scratch::new();
    let out = dir.path().join("d");
    let o = run_ok(&[
        "report",
        "examples/delta-60.toml",
        "--out",
        path(&out),
        "--damping",
        "supersonic",
        "--mach",
        "0.6,1.5",
    ]);
    let s = read_json(&out.join("summary.json"));
    let p = &s["points"];
    assert!(
        p[0]["error"].as_str().unwrap().contains("needs M > 1"),
        "{}",
        p[0]
    );
    assert!(p[1]["error"].is_null() && p[1]["verdict"]["overall"].is_string());
    assert_eq!(s["verdict"]["no_result"], serde_json::json!([[0.6, 0.6]]));
    assert!(
        stderr(&o).contains("no result at M = 0.6"),
        "{}",
        stderr(&o)
    );
    // every Mach number without a result: nothing to report, exit 2
    let err = stderr(&run_err(
        &[
            "report",
            "examples/delta-60.toml",
            "--out",
            path(&dir.path().join("e")),
            "--damping",
            "supersonic",
            "--mach",
            "0.6,0.8",
        ],
        2,
    ));
    assert!(
        err.contains("no Mach number has a result") && err.contains("delta-60.toml"),
        "{err}"
    );
    assert!(!dir.path().join("e").exists());
    // the default range, over the earlier report (which it may replace);
    // the range is the question, so a quasi-steady model (no lifting
    // surface solved at each point's frequency)
    run_ok(&[
        "report",
        "examples/delta-60.toml",
        "--damping",
        "faired-slender",
        "--out",
        path(&out),
    ]);
    let s = read_json(&out.join("summary.json"));
    let machs: Vec<f64> = s["points"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["mach"].as_f64().unwrap())
        .collect();
    assert_eq!((machs.len(), machs[0], machs[30]), (31, 0.5, 2.0));
}

#[test]
fn the_design_report_refuses_what_it_must() {
    let dir = Scratch::new();
    let notes = dir.write("notes.txt", "mine");
    let err = stderr(&run_err(
        &[
            "report",
            "examples/delta-60.toml",
            "--mach",
            "1.2",
            "--out",
            path(dir.path()),
        ],
        3,
    ));
    assert!(
        err.contains("will not replace") && err.contains("notes.txt"),
        "{err}"
    );
    assert_eq!(std::fs::read_to_string(notes).unwrap(), "mine");
    let out = path(&dir.path().join("x")).to_string();
    for (mach, says) in [
        ("0:1:0.5", "--mach"),
        ("1:0.5:0.1", "backwards"),
        ("0.5:2:0.0001", "at most"),
    ] {
        let err = stderr(&run_err(
            &[
                "report",
                "examples/delta-60.toml",
                "--mach",
                mach,
                "--out",
                &out,
            ],
            2,
        ));
        assert!(
            err.contains(says) && err.contains("delta-60.toml"),
            "{mach}: {err}"
        );
    }
    // the note's study takes no design options
    let err = stderr(&run_err(&["report", "--mach", "1.2", "--out", &out], 2));
    assert!(err.contains("--mach") && err.contains("CONFIG"), "{err}");
}
