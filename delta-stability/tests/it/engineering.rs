//! The engineer's outputs as a user runs them: physical flight conditions
//! in `analyze` and `sweep`, the `damp()` table, the mode shapes, the
//! state-space export, the short-period frequency requirement and the
//! `sensitivity` command — each against an independent route: numbers by
//! hand, the non-dimensional route, python-control and numpy (fixtures
//! written by `scripts/state_space_fixtures.py`), Etkin & Reid's printed
//! state matrix, finite differences.

use crate::common;

use common::{Scratch, json, path, root, run_err, run_ok, stderr, stdout};
use nalgebra::Matrix4;
use num_complex::Complex64;
use serde_json::Value;
use stability_core::Derivatives;
use stability_core::analysis::Analysis;
use stability_core::dynamics::mode_shape::eigenvector;
use stability_core::dynamics::response::{Simplifications, StateSpace};

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("a number, not {v}"))
}

fn fixture(name: &str) -> Value {
    let p = root().join(format!(
        "delta-stability/tests/data/state_space/{name}.json"
    ));
    serde_json::from_str(&std::fs::read_to_string(p).expect("fixture")).expect("JSON")
}

fn derivatives(example: &str) -> Derivatives {
    let p = root().join("examples").join(example);
    stability_io::input::read(path(&p))
        .expect("the example reads")
        .derivatives
}

// ------------------------------------------------------------ flight

#[test]
fn analyze_computes_and_prints_the_physical_flight_condition() {
    let v = json(&run_ok(&[
        "analyze",
        "examples/delta-60-physical.toml",
        "--json",
    ]));
    let fl = &v["flight"];
    // the planform by hand: c₀ = 12 m, Λ = 60°: b = 24/√3, S = 6b, c̄ = 8
    let s = 6.0 * 24.0 / 3f64.sqrt();
    let (rho, a) = (f(&fl["density_kg_m3"]), f(&fl["speed_of_sound_m_s"]));
    // the 1976 standard at 11 km′
    assert!((rho - 0.36392).abs() < 5e-6 && (a - 295.07).abs() < 5e-3);
    assert!((f(&fl["area_m2"]) - s).abs() < 1e-12 && f(&fl["chord_m"]) == 8.0);
    let mu1 = 12_000.0 / (0.5 * rho * s * 8.0);
    let v_ms = 0.9 * a;
    let tau = 12_000.0 / (0.5 * rho * s * v_ms);
    assert!((f(&fl["mu1"]) - mu1).abs() < 1e-9 * mu1);
    assert!((f(&fl["i_b"]) - 70_000.0 / (12_000.0 * 64.0)).abs() < 1e-15);
    assert!((f(&fl["tau_s"]) - tau).abs() < 1e-12 * tau);
    assert!((f(&fl["c_l"]) - 117_679.8 / (0.5 * rho * v_ms * v_ms * s)).abs() < 1e-6);
    // the case carries them, and the modes come in seconds too
    assert!((f(&v["case"]["mu1"]) - mu1).abs() < 1e-9 * mu1);
    assert_eq!(f(&v["tau_s"]), f(&fl["tau_s"]));
    let sp = &v["modes"][0];
    assert!((f(&sp["re_s"]) - f(&sp["re"]) / tau).abs() < 1e-12);
    assert!((f(&v["damp"][0]["im_s"]) - f(&sp["im"]) / tau).abs() < 1e-12);
    let page = stdout(&run_ok(&["analyze", "examples/delta-60-physical.toml"]));
    for needle in [
        "pressure altitude 11000",
        "τ = m/(½ρSV) = 2.9870 s",
        "damp(): the modes in seconds",
        "rad/s",
    ] {
        assert!(page.contains(needle), "{needle}:\n{page}");
    }
}

#[test]
fn a_physical_condition_is_the_nondimensional_one_it_gives() {
    let phys = json(&run_ok(&[
        "analyze",
        "examples/delta-60-physical.toml",
        "--json",
    ]));
    let fl = &phys["flight"];
    let text = common::example("delta-60-physical.toml");
    let nondim = text
        .replace("units = \"si\"", &format!("mu1 = {}", fl["mu1"]))
        .replace("altitude = 11000.0", &format!("i_b = {}", fl["i_b"]))
        .replace("mass = 12000.0", &format!("cl_m2 = {}", fl["cl_m2"]))
        .replace("I_y = 70000.0", "");
    let dir = Scratch::new();
    let p = dir.write("nondim.toml", nondim);
    let v = json(&run_ok(&["analyze", path(&p), "--json"]));
    assert!(v.get("flight").is_none() && v.get("damp").is_none());
    for k in 0..4 {
        for part in ["re", "im"] {
            let (a, b) = (f(&v["roots"][k][part]), f(&phys["roots"][k][part]));
            assert!(
                (a - b).abs() < 1e-12 * (1.0 + b.abs()),
                "root {k} {part}: {a} vs {b}"
            );
        }
    }
}

/// `analyze` on the example with `from` replaced by `to`: exit 2, and the
/// message contains each of `expect`.
fn refused(from: &str, to: &str, expect: &[&str]) {
    let text = common::example("delta-60-physical.toml");
    assert!(text.contains(from), "{from}");
    let dir = Scratch::new();
    let p = dir.write("case.toml", text.replace(from, to));
    let err = stderr(&run_err(&["analyze", path(&p)], 2));
    for e in expect {
        assert!(err.contains(e), "{to}: expected {e}:\n{err}");
    }
}

#[test]
fn both_forms_and_bad_physical_inputs_are_errors_naming_the_fields() {
    refused(
        "cg = 0.25",
        "cg = 0.25\nmu1 = 50.0",
        &["[flight] mu1 and [flight] mass both give", "case.toml:"],
    );
    refused(
        "cg = 0.25",
        "cg = 0.25\ni_b = 0.08",
        &["[flight] i_b and [flight] I_y"],
    );
    refused(
        "units = \"si\"",
        "units = \"sii\"",
        &[
            "unknown units `sii`",
            "did you mean `si`?",
            "[flight] units",
        ],
    );
    refused("units = \"si\"", "", &["[flight] units", "missing"]);
    refused(
        "altitude = 11000.0",
        "altitude = 11000.0\nrho = 0.4",
        &["[flight] altitude and [flight] rho both give"],
    );
    refused(
        "altitude = 11000.0",
        "rho = 0.4",
        &["[flight] rho", "needs speed_of_sound"],
    );
    refused(
        "altitude = 11000.0",
        "altitude = 90000.0",
        &["[flight] altitude", "above 86 km"],
    );
    refused(
        "altitude = 11000.0",
        "altitude = 11000.0\ngeometric_altitude = 11000.0",
        &["both give the air's density"],
    );
    refused(
        "mass = 12000.0",
        "mass = 12000.0\nweight = 1.0",
        &["[flight] weight", "both give the mass"],
    );
    refused("I_y = 70000.0", "", &["[flight] I_y", "missing"]);
    refused(
        "mass = 12000.0",
        "mass = -1.0",
        &["[flight] mass", "positive"],
    );
    refused(
        "mass = 12000.0",
        "mass = 1e30",
        &["[flight] mass", "μ₁ = m/(½ρSc̄)"],
    );
    // the non-dimensional form still needs all three
    let dir = Scratch::new();
    let p = dir.write(
        "nondim.toml",
        "[planform]\nsweep = 60.0\nroot_chord = 1.0\n[flight]\nmach = 0.9\ncg = 0.25\nmu1 = 50.0\ni_b = 0.08\n",
    );
    let err = stderr(&run_err(&["analyze", path(&p)], 2));
    assert!(
        err.contains("[flight] cl_m2") && err.contains("missing"),
        "{err}"
    );
}

#[test]
fn a_sweep_over_mach_keeps_cl_m2_and_scales_tau() {
    let dir = Scratch::new();
    let out = dir.path().join("s.json");
    run_ok(&[
        "sweep",
        "examples/delta-60-physical.toml",
        "--mach",
        "0.5:2:0.5",
        "-o",
        path(&out),
    ]);
    let rows: Value = serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    let rows = rows.as_array().unwrap();
    assert_eq!(rows.len(), 4);
    let (m0, t0, cl0) = (
        f(&rows[0]["mach"]),
        f(&rows[0]["tau_s"]),
        f(&rows[0]["c_l"]),
    );
    for r in rows {
        let m = f(&r["mach"]);
        // C_L·M² constant (eq 24), τ ∝ 1/M, V = M·a, μ₁ the config's
        assert!((f(&r["c_l"]) * m * m - cl0 * m0 * m0).abs() < 1e-12);
        assert!((f(&r["tau_s"]) * m - t0 * m0).abs() < 1e-12);
        assert!((f(&r["v_m_s"]) / m - 295.0696).abs() < 1e-3);
        assert!((f(&r["mu1"]) - 99.155).abs() < 5e-3);
        if r["sp_re"].is_number() {
            let tau = f(&r["tau_s"]);
            assert!((f(&r["sp_re_s"]) - f(&r["sp_re"]) / tau).abs() < 1e-12);
        }
    }
    // the sweep angle changes the wing, and so μ₁ (the root chord is held)
    let csv = dir.path().join("s.csv");
    run_ok(&[
        "sweep",
        "examples/delta-60-physical.toml",
        "--mach",
        "0.9",
        "--sweep",
        "45:60:15",
        "-o",
        path(&csv),
    ]);
    let text = std::fs::read_to_string(&csv).unwrap();
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    assert!(header.contains(&"tau_s") && header.last() == Some(&"error"));
    let mu1: Vec<f64> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').nth(3).unwrap().parse().unwrap())
        .collect();
    // S ∝ 1/tan Λ at a fixed root chord: μ₁(45°)/μ₁(60°) = tan 45°/tan 60°
    assert!((mu1[0] / mu1[1] - 1.0 / 3f64.sqrt()).abs() < 1e-12);
    let err = stderr(&run_err(
        &[
            "sweep",
            "examples/delta-60-physical.toml",
            "--mach",
            "0.9",
            "--ib",
            "0.1",
            "-o",
            path(&csv),
        ],
        2,
    ));
    assert!(err.contains("--ib") && err.contains("physical"), "{err}");
}

// ------------------------------------------------------------ damp

#[test]
fn quartic_with_dimensional_gives_rad_per_s_and_the_damp_table() {
    let page = stdout(&run_ok(&[
        "quartic",
        "examples/tailless-delta-60-dimensional.toml",
    ]));
    assert!(page.contains(" rad/s)"), "ωₙ in rad/s:\n{page}");
    assert!(
        page.contains("damp(): the modes in seconds") && page.contains("ωₙ (rad/s)"),
        "{page}"
    );
    assert!(
        page.contains("MIL-F-8785C short-period frequency"),
        "{page}"
    );
    // without dimensions: neither
    let page = stdout(&run_ok(&["quartic", "examples/tailless-delta-45.toml"]));
    assert!(
        !page.contains("damp()") && !page.contains("rad/s") && page.contains("Mode shapes"),
        "{page}"
    );
}

#[test]
fn damp_and_mode_shapes_agree_with_python_control_and_numpy() {
    for (name, args) in [
        (
            "boeing-747-american",
            vec!["quartic", "examples/boeing-747-american.toml"],
        ),
        (
            "tailless-delta-60-dimensional",
            vec!["quartic", "examples/tailless-delta-60-dimensional.toml"],
        ),
        (
            "delta-60-physical",
            // the exported state space is the derivatives' (the k-method's
            // roots; by default analyze's are each at its own frequency)
            vec![
                "analyze",
                "examples/delta-60-physical.toml",
                "--frequency-method",
                "k",
            ],
        ),
    ] {
        let fx = fixture(name);
        let mut a = args.clone();
        a.push("--json");
        let v = json(&run_ok(&a));
        let damp = v["damp"].as_array().unwrap();
        // python-control lists each pole; ours lists each mode (s ≥ 0)
        for row in damp {
            let p = fx["damp"]
                .as_array()
                .unwrap()
                .iter()
                .find(|p| {
                    (f(&p["im"]) - f(&row["im_s"])).abs() < 1e-9
                        && (f(&p["re"]) - f(&row["re_s"])).abs() < 1e-9
                })
                .unwrap_or_else(|| panic!("{name}: no python-control pole for {row}"));
            let rel = |a: f64, b: f64| (a - b).abs() / b.abs();
            assert!(
                rel(
                    f(&row["natural_frequency_rad_s"]),
                    f(&p["natural_frequency"])
                ) < 1e-10,
                "{name}"
            );
            assert!(
                rel(f(&row["damping_ratio"]), f(&p["damping_ratio"])) < 1e-9,
                "{name}"
            );
        }
        for shape in v["mode_shapes"].as_array().unwrap() {
            let n = fx["mode_shapes"]
                .as_array()
                .unwrap()
                .iter()
                .find(|s| {
                    (f(&s["re"]) - f(&shape["re"])).abs() < 1e-9 * (1.0 + f(&s["re"]).abs())
                        && (f(&s["im"]) - f(&shape["im"])).abs() < 1e-9
                })
                .unwrap_or_else(|| panic!("{name}: no numpy eigenvector for {shape}"));
            for (k, key) in ["u_over_v", "alpha", "q", "theta"].iter().enumerate() {
                let (m, p) = (f(&shape[key]["magnitude"]), f(&shape[key]["phase_deg"]));
                let (nm, np_) = (f(&n["magnitude"][k]), f(&n["phase_deg"][k]));
                assert!(
                    (m - nm).abs() < 1e-8 * (1.0 + nm),
                    "{name} {key}: {m} vs {nm}"
                );
                let dp = (p - np_ + 540.0).rem_euclid(360.0) - 180.0;
                assert!(dp.abs() < 1e-6, "{name} {key}: {p}° vs {np_}°");
            }
        }
    }
}

/// Etkin & Reid's 747 at 40 000 ft, M 0.8: the system matrix they print in
/// §6.2 (states Δu, w in ft/s, q, Δθ; as quoted in course problems of
/// their example), whose eigenvalues they give as −0.3719 ± 0.8875i and
/// −0.003289 ± 0.06723i.
fn etkin_reid_a() -> Matrix4<f64> {
    Matrix4::new(
        -0.006868, 0.01395, 0.0, -32.2, //
        -0.09055, -0.3151, 773.98, 0.0, //
        0.0001187, -0.001026, -0.4285, 0.0, //
        0.0, 0.0, 1.0, 0.0,
    )
}

#[test]
fn the_747s_state_matrix_is_etkin_and_reids() {
    let dir = Scratch::new();
    let out = dir.path().join("ss.json");
    run_ok(&[
        "quartic",
        "examples/boeing-747-american.toml",
        "--state-space",
        path(&out),
    ]);
    let ss: Value = serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    assert_eq!(ss["time_unit"], "s");
    // theirs in (u/V, α, q, θ): S⁻¹ A S, S = diag(V, V, 1, 1), V = 774 ft/s
    let v = 235.9 / 0.3048;
    let s = [v, v, 1.0, 1.0];
    let er = etkin_reid_a();
    let theirs = Matrix4::from_fn(|i, j| er[(i, j)] * s[j] / s[i]);
    // their printed eigenvalues are those of their matrix (to its digits)
    for z in [
        Complex64::new(-0.3719, 0.8875),
        Complex64::new(-0.003289, 0.06723),
    ] {
        let near = theirs
            .complex_eigenvalues()
            .iter()
            .map(|w| (w - z).norm() / z.norm())
            .fold(f64::INFINITY, f64::min);
        assert!(near < 1e-3, "{z}: {near}");
    }
    // ours, from their non-dimensional table through the notation and eqs
    // (2): each entry within 0.2 % of theirs (their 4 figures; g = 32.2)
    let a = &ss["A"];
    for i in 0..4 {
        for j in 0..4 {
            let (o, t) = (f(&a[i][j]), theirs[(i, j)]);
            assert!(
                (o - t).abs() <= 2e-3 * t.abs() + 1e-12,
                "A[{i}][{j}]: {o} vs {t}"
            );
        }
    }
}

#[test]
fn the_747s_mode_shapes_are_those_of_etkin_and_reids_matrix() {
    let s = [235.9 / 0.3048, 235.9 / 0.3048, 1.0, 1.0];
    let er = etkin_reid_a();
    let theirs = Matrix4::from_fn(|i, j| er[(i, j)] * s[j] / s[i]);
    // the mode shapes of their matrix against ours: within 1 % and 1°
    let v = json(&run_ok(&[
        "quartic",
        "examples/boeing-747-american.toml",
        "--json",
    ]));
    for shape in v["mode_shapes"].as_array().unwrap() {
        let lam = Complex64::new(f(&shape["re"]), f(&shape["im"]));
        let ev = theirs.complex_eigenvalues();
        let mine = *ev
            .iter()
            .min_by(|x, y| (*x - lam).norm().total_cmp(&(*y - lam).norm()))
            .unwrap();
        let vec = eigenvector(&theirs, mine).expect("an eigenvector");
        for (k, key) in ["u_over_v", "alpha", "q", "theta"].iter().enumerate() {
            let z = vec[k] / vec[3];
            let (m, p) = (f(&shape[key]["magnitude"]), f(&shape[key]["phase_deg"]));
            assert!(
                (m - z.norm()).abs() < 1e-2 * z.norm() + 1e-4,
                "{key}: {m} vs {}",
                z.norm()
            );
            let dp = (p - z.arg().to_degrees() + 540.0).rem_euclid(360.0) - 180.0;
            assert!(dp.abs() < 1.0, "{key}: {p}° vs {}°", z.arg().to_degrees());
        }
    }
    // Etkin & Reid: in the phugoid "the speed leads the pitch angle by about
    // 90°"; Lanchester's phugoid (α = 0, u̇ = −gθ) gives |û/θ| = g/(V|λ|).
    let ph = &v["mode_shapes"][1];
    assert_eq!(ph["mode"], "phugoid");
    assert!((f(&ph["u_over_v"]["phase_deg"]) - 90.0).abs() < 5.0);
    let lanchester = 9.81 / (235.9 * 0.06729);
    assert!((f(&ph["u_over_v"]["magnitude"]) / lanchester - 1.0).abs() < 0.02);
    // in the short period u barely moves and α ≈ θ in size
    let sp = &v["mode_shapes"][0];
    assert!(
        f(&sp["u_over_v"]["magnitude"]) < 0.05 && (f(&sp["alpha"]["magnitude"]) - 1.0).abs() < 0.15
    );
}

// ------------------------------------------------------------ state space

#[test]
fn the_state_space_file_is_the_librarys_state_matrix() {
    let dir = Scratch::new();
    // quartic with [dimensional]: A in seconds, no control
    let out = dir.path().join("delta.json");
    run_ok(&[
        "quartic",
        "examples/tailless-delta-60-dimensional.toml",
        "--state-space",
        path(&out),
    ]);
    let ss: Value = serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    let d = derivatives("tailless-delta-60-dimensional.toml");
    let lib = StateSpace::new(&d, Simplifications::default()).unwrap();
    let tau = stability_core::design::examples::tailless_delta_60_flight().tau();
    // by hand: dû/dt = Dû/τ; q = q̂/τ, so A_s[i][j] = A_τ[i][j]·(row i is q ? 1/τ : 1)·(col j is q ? τ : 1)/τ
    for i in 0..4 {
        for j in 0..4 {
            let row = if i == 2 { 1.0 / tau } else { 1.0 };
            let col = if j == 2 { tau } else { 1.0 };
            let expect = lib.a[(i, j)] * row * col / tau;
            let got = f(&ss["A"][i][j]);
            assert!(
                (got - expect).abs() <= 1e-14 * (1.0 + expect.abs()),
                "A[{i}][{j}]"
            );
        }
    }
    assert!(ss["B"].is_null() && ss["states"][1] == "alpha" && ss["time_unit"] == "s");
    for ext in ["py", "m"] {
        let script = std::fs::read_to_string(out.with_extension(ext)).unwrap();
        assert!(
            script.contains(&format!("{:?}", f(&ss["A"][1][1]))),
            "{ext}:\n{script}"
        );
    }
}

#[test]
fn without_dimensions_the_state_space_is_in_tau() {
    let dir = Scratch::new();
    // without dimensions: in τ, the library's matrix itself
    let out = dir.path().join("tau.json");
    run_ok(&[
        "quartic",
        "examples/tailless-delta-45.toml",
        "--state-space",
        path(&out),
    ]);
    let ss: Value = serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    let lib = StateSpace::new(
        &derivatives("tailless-delta-45.toml"),
        Simplifications::default(),
    )
    .unwrap();
    assert_eq!(ss["time_unit"], "tau");
    for i in 0..4 {
        for j in 0..4 {
            assert_eq!(f(&ss["A"][i][j]), lib.a[(i, j)]);
        }
    }
}

#[test]
fn the_control_column_is_the_librarys_input_matrix() {
    let dir = Scratch::new();
    // analyze with [control]: B = the library's B·(C_Xδ, C_Zδ, (μ₁/i_B)C_mδ), in seconds
    let out = dir.path().join("phys.json");
    run_ok(&[
        "analyze",
        "examples/delta-60-physical.toml",
        "--state-space",
        path(&out),
    ]);
    let ss: Value = serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    let v = json(&run_ok(&[
        "analyze",
        "examples/delta-60-physical.toml",
        "--json",
    ]));
    let d = Derivatives::from_quartic_input_values(std::array::from_fn(|k| {
        f(&v["derivatives"][Derivatives::QUARTIC_INPUTS[k]])
    }));
    let lib = StateSpace::new(&d, Simplifications::default()).unwrap();
    let tau = f(&v["tau_s"]);
    let forcing = [0.0, -0.6, d.mu1 / d.i_b * -0.25];
    assert_eq!(ss["inputs"][0], "elevon");
    for i in 0..4 {
        let b_tau: f64 = (0..3).map(|k| lib.b[(i, k)] * forcing[k]).sum();
        let expect = b_tau * if i == 2 { 1.0 / tau } else { 1.0 } / tau;
        let got = f(&ss["B"][i][0]);
        assert!(
            (got - expect).abs() <= 1e-12 * (1.0 + expect.abs()),
            "B[{i}]: {got} vs {expect}"
        );
    }
}

#[test]
fn state_space_and_control_errors_are_located() {
    let dir = Scratch::new();
    let err = stderr(&run_err(
        &[
            "quartic",
            "examples/tailless-delta-45.toml",
            "--state-space",
            path(&dir.path().join("x.txt")),
        ],
        2,
    ));
    assert!(err.contains("must end in .json"), "{err}");
    let ex = common::example("tailless-delta-45.toml");
    for (control, expect) in [
        ("[control]\nC_zdelta = -0.3\n", "[control] C_mdelta"),
        (
            "[control]\nC_mdelta = -1.0\nC_Lalpha = 3.0\n",
            "unknown field `C_Lalpha`",
        ),
        (
            "[control]\nC_mdelta = -1.0\nC_zdelta = -0.3\nC_Ldelta = 0.3\n",
            "both give the control's normal force",
        ),
        (
            "[control]\nname = \"x'y\"\nC_mdelta = -1.0\n",
            "[control] name",
        ),
    ] {
        let p = dir.write("c.toml", format!("{ex}\n{control}"));
        let err = stderr(&run_err(&["quartic", path(&p)], 2));
        assert!(err.contains(expect), "{control}: {err}");
    }
}

// ------------------------------------------------------------ sensitivity

#[test]
fn sensitivities_are_the_finite_differences_of_the_roots() {
    for example in ["tailless-delta-45.toml", "boeing-747-american.toml"] {
        let v = json(&run_ok(&[
            "sensitivity",
            &format!("examples/{example}"),
            "--json",
        ]));
        let d = derivatives(example);
        let base = Analysis::of(&d).unwrap();
        let values = d.quartic_input_values();
        for (m, mode) in v["modes"].as_array().unwrap().iter().zip(base.modes.iter()) {
            assert_eq!(m["mode"], mode.name.as_str());
            for s in m["sensitivities"].as_array().unwrap() {
                let k = Derivatives::QUARTIC_INPUTS
                    .iter()
                    .position(|n| *n == s["input"])
                    .unwrap();
                let h = 1e-6 * values[k].abs().max(1e-3);
                let root = |x: f64| {
                    let mut p = values;
                    p[k] = x;
                    let a = Analysis::of(&Derivatives::from_quartic_input_values(p)).unwrap();
                    let r = a.modes.iter().find(|r| r.name == mode.name).unwrap();
                    Complex64::new(r.re, r.im)
                };
                let fd = (root(values[k] + h) - root(values[k] - h)) / (2.0 * h);
                let (dr, di) = (f(&s["d_re"]), f(&s["d_im"]));
                let scale = 1e-5 * (1.0 + fd.norm());
                assert!(
                    (dr - fd.re).abs() < scale && (di - fd.im).abs() < scale,
                    "{example} {} {}: {dr} {di} vs {fd}",
                    mode.name.as_str(),
                    s["input"]
                );
                assert!(
                    (f(&s["damping_drive"]) - values[k] * dr).abs()
                        < 1e-12 * (1.0 + (values[k] * dr).abs())
                );
            }
        }
        if example.starts_with("boeing") {
            let tau = f(&v["tau_s"]);
            let s = &v["modes"][0]["sensitivities"][0];
            assert!((f(&s["d_re_s"]) - f(&s["d_re"]) / tau).abs() < 1e-12);
        }
    }
    let page = stdout(&run_ok(&["sensitivity", "examples/tailless-delta-45.toml"]));
    assert!(
        page.contains("short period") && page.contains("p·∂r/∂p") && page.contains("m_q"),
        "{page}"
    );
}
