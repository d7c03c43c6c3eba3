//! Issue 21 items 4 and 5 as a user meets them: a Digital DATCOM output
//! driving `analyze` and `sweep` (`--datcom FILE`, `[model] datcom`), and
//! the user's own tables of derivatives, value or increment, in the output.

use crate::common;

use common::{Scratch, json, path, run_err, run_ok, stderr};
use std::f64::consts::PI;

/// The real output: a 60° delta, moment centre at the M.A.C.'s leading edge.
const DATCOM: &str = "stability-io/tests/fixtures/datcom/delta60_h0.0.out";

/// The same wing in a config (root chord 10: S = 57.735, c̄ = 6.6667).
const CONFIG: &str = "[planform]\nsweep = 60.0\nroot_chord = 10.0\n\n[flight]\nmach = 0.9\ncg = 0.25\nmu1 = 50.0\ni_b = 0.08\ncl_m2 = 0.05\n";

fn config(dir: &Scratch, model: &str) -> String {
    path(&dir.write("case.toml", format!("{CONFIG}{model}"))).to_string()
}

fn number(v: &serde_json::Value, keys: &[&str]) -> f64 {
    let mut x = v;
    for k in keys {
        x = &x[*k];
    }
    x.as_f64().unwrap_or_else(|| panic!("{keys:?}: {x}"))
}

/// DATCOM's M = 0.9 (output lines 447 and 463, per degree) moved by hand
/// to h = 0.25 with the NACA forms of the transfer (Etkin & Reid §5.6;
/// DATCOM §7.1.1): C_mα' = C_mα + (C_Lα + C_D)Δ, C_Lq' = C_Lq − 2(C_Lα +
/// C_D)Δ, C_mq' = C_mq − 2Δ(C_mα − ½C_Lq) − 2Δ²(C_Lα + C_D), C_mα̇' =
/// C_mα̇ + ½C_Lα̇·2Δ; then the appendix's z_w = −C_Lα − C_D, m_w = C_mα,
/// z_q = −½C_Lq, m_q = ½C_mq, z_ẇ = −½C_Lα̇, m_ẇ = ½C_mα̇.
fn by_hand_at_m09() -> [(&'static str, f64); 6] {
    let r = 180.0 / PI;
    let (cd, cla, cma) = (0.006, 5.067e-2 * r, -2.374e-2 * r);
    let (clq, cmq, clad, cmad) = (7.281e-2 * r, -3.461e-2 * r, 9.249e-3 * r, -1.153e-2 * r);
    // h_r = (XCG − x̄)/c̄ = (3.333333 − 10/3)/(20/3)
    let delta = 0.25 - (3.333333 - 10.0 / 3.0) / (20.0 / 3.0);
    let n = cla + cd;
    [
        ("z_w", -cla - cd),
        ("m_w", cma + n * delta),
        ("z_q", -0.5 * (clq - 2.0 * n * delta)),
        (
            "m_q",
            0.5 * (cmq - 2.0 * delta * (cma - 0.5 * clq) - 2.0 * delta * delta * n),
        ),
        ("z_wdot", -0.5 * clad),
        ("m_wdot", 0.5 * (cmad + clad * delta)),
    ]
}

#[test]
fn a_datcom_output_drives_analyze_with_the_values_it_prints() {
    let dir = Scratch::new();
    let cfg = config(&dir, "");
    let v = json(&run_ok(&["analyze", &cfg, "--datcom", DATCOM, "--json"]));
    for (name, want) in by_hand_at_m09() {
        let got = number(&v, &["derivatives", name]);
        assert!(
            (got - want).abs() < 1e-9 * (1.0 + want.abs()),
            "{name}: {got} vs {want}"
        );
    }
    // the coefficients: a = CLA per radian, H₀ = h_r − CMA/CLA, C_D0 = CD
    let o = &v["aerodynamics"]["origin"];
    for k in ["lift_slope", "aerodynamic_centre", "zero_lift_drag"] {
        assert_eq!(o[k], "datcom", "{k}");
    }
    assert_eq!(o["drag_due_to_lift"], "method");
    let a = number(&v, &["aerodynamics", "lift_slope", "value"]);
    assert!((a - 5.067e-2 * 180.0 / PI).abs() < 1e-12);
    let h0 = number(&v, &["aerodynamics", "aerodynamic_centre", "value"]);
    assert!((h0 - 2.374 / 5.067).abs() < 1e-6, "{h0}");
    // every derivative table's use is in the output, DATCOM's
    let tables = v["derivative_tables"].as_array().expect("an array");
    assert_eq!(tables.len(), 6);
    assert!(tables.iter().all(|t| t["origin"] == "datcom"));
    assert_eq!(v["datcom"]["configuration"], "WING ALONE CONFIGURATION");
    assert_eq!(v["datcom"]["mach"].as_array().map(Vec::len), Some(21));
    // the key in [model] does what the option does
    let keyed = config(
        &dir,
        &format!(
            "[model]\ndatcom = \"{}\"\n",
            common::root().join(DATCOM).display()
        ),
    );
    let w = json(&run_ok(&["analyze", &keyed, "--json"]));
    assert_eq!(w["derivatives"], v["derivatives"]);
    // the page says where each came from
    let page = common::stdout(&run_ok(&["analyze", &cfg, "--datcom", DATCOM]));
    assert!(
        page.contains("DATCOM output") && page.contains("m_q = "),
        "{page}"
    );
}

#[test]
fn where_datcom_prints_ndm_the_computed_value_is_kept_and_said() {
    let dir = Scratch::new();
    let cfg = config(&dir, "");
    // CLAD, CMAD are NDM at M 1.05–1.3 (lines 700–1058)
    let v = json(&run_ok(&[
        "analyze", &cfg, "--datcom", DATCOM, "--json", "--mach", "1.2",
    ]));
    let t = v["derivative_tables"].as_array().unwrap();
    let z_wdot = t.iter().find(|t| t["derivative"] == "z_wdot").unwrap();
    assert!(z_wdot["table"].is_null());
    assert_eq!(z_wdot["computed"], z_wdot["used"]);
    // CLQ is printed there (line 979): z_q about h_r = −½·6.735E-02·57.2958
    let z_q = t.iter().find(|t| t["derivative"] == "z_q").unwrap();
    let want = -0.5 * 6.735e-2 * 180.0 / PI;
    assert!((number(z_q, &["table"]) - want).abs() < 1e-12);
}

#[test]
fn sweep_takes_the_datcom_output_and_says_so() {
    let dir = Scratch::new();
    let cfg = config(&dir, "");
    let out = dir.path().join("s.json");
    let run = run_ok(&[
        "sweep",
        &cfg,
        "--datcom",
        DATCOM,
        "--mach",
        "0.9,1.5",
        "--derivatives",
        "-o",
        path(&out),
    ]);
    assert!(common::stdout(&run).contains("tables: DATCOM output"));
    // a DATCOM output is of one planform: --sweep may not change it
    let err = stderr(&run_err(
        &[
            "sweep",
            &cfg,
            "--datcom",
            DATCOM,
            "--mach",
            "0.9",
            "--sweep",
            "55,60",
            "-o",
            path(&out),
        ],
        2,
    ));
    assert!(err.contains("--sweep") && err.contains("DATCOM"), "{err}");
    let rows: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    let first = &rows[0];
    assert_eq!(first["mach"], 0.9);
    for (name, want) in by_hand_at_m09() {
        let got = number(first, &[name]);
        assert!(
            (got - want).abs() < 1e-9 * (1.0 + want.abs()),
            "{name}: {got} vs {want}"
        );
    }
}

#[test]
fn user_tables_of_damping_derivatives_value_and_increment() {
    let dir = Scratch::new();
    let plain = json(&run_ok(&[
        "analyze",
        &config(&dir, "[model]\ndamping = \"faired-slender\"\n"),
        "--json",
    ]));
    let tables = "[model]\ndamping = \"faired-slender\"\n[model.tables]\n\
        m_q = { mach = [0.5, 1.5], values = [-0.9, -1.1] }\n\
        \"z_ẇ\" = { mach = [0.5, 1.5], value = [-0.2, -0.2], mode = \"increment\" }\n\
        m_w = { file = \"m_w.csv\", cg = 0.0 }\n";
    dir.write("m_w.csv", "mach,m_w\n0.5,-1.0\n1.5,-1.0\n");
    let v = json(&run_ok(&["analyze", &config(&dir, tables), "--json"]));
    let d = |v: &serde_json::Value, n: &str| number(v, &["derivatives", n]);
    // m_q: linear data, M 0.9 → −0.9 − 0.2·0.4 = −0.98 (the Hermite is exact on a line)
    assert!((d(&v, "m_q") + 0.98).abs() < 1e-12);
    // z_ẇ: the computed one plus −0.2
    assert!((d(&v, "z_wdot") - (d(&plain, "z_wdot") - 0.2)).abs() < 1e-12);
    // m_w about h = 0 moved to h = 0.25: m_w − 0.25 z_w
    assert!((d(&v, "m_w") - (-1.0 - 0.25 * d(&v, "z_w"))).abs() < 1e-12);
    let t = v["derivative_tables"].as_array().unwrap();
    assert_eq!(t.len(), 3);
    assert!(t.iter().all(|t| t["origin"] == "table"));
    // outside its range a user's table is refused, naming it and the range
    let err = stderr(&run_err(
        &["analyze", &config(&dir, tables), "--mach", "1.8"],
        2,
    ));
    assert!(
        err.contains("table of m_w") && err.contains("[0.5, 1.5]"),
        "{err}"
    );
    // a name that is no table is named, with the nearest
    let bad = "[model.tables]\nm_qq = { mach = [0.5, 1.5], value = [1.0, 1.0] }\n";
    let err = stderr(&run_err(&["analyze", &config(&dir, bad)], 2));
    assert!(err.contains("m_qq") && err.contains("m_q"), "{err}");
}
