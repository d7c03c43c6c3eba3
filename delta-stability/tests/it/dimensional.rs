//! `notation = "dimensional"` and American notation's C_L/C_D form through
//! the program (issue 12, items 1, 2 and 5): the published aircraft of
//! examples/aircraft/ against their sources' modes
//! (stability-core/tests/data/aircraft/*.json), the body-axis trap, the
//! errors, and the conversions' round trips.

use crate::common;

use common::{Scratch, json, path, root, run_err, run_ok, stderr};
use serde_json::Value;
use stability_core::data::dimensional::{
    Axes, DimensionalAnalysis, DimensionalDerivatives, DimensionalModel, Trim, Units,
};
use stability_core::data::notation::{N_ROWS, Notation, row};

fn published(name: &str) -> Value {
    let p = root().join(format!("stability-core/tests/data/aircraft/{name}.json"));
    serde_json::from_str(&std::fs::read_to_string(p).expect("data")).expect("JSON")
}

fn names() -> Vec<String> {
    let dir = root().join("stability-core/tests/data/aircraft");
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .expect("data")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .map(|p| p.file_stem().unwrap().to_string_lossy().into_owned())
        .collect();
    v.sort();
    assert!(v.len() >= 5, "the published aircraft are missing");
    v
}

/// `quartic --json` of a file.
fn quartic(file: &str) -> Value {
    json(&run_ok(&["quartic", file, "--json"]))
}

/// The program's mode `name` (`short_period`, `phugoid`) as (re, im) in 1/s.
fn mode(v: &Value, name: &str) -> (f64, f64) {
    common::mode_s(v, name)
}

/// ω_n, ζ, Re λ or Im λ of a root.
fn quantity((re, im): (f64, f64), which: &str) -> f64 {
    let wn = re.hypot(im);
    match which {
        "omega_n" => wn,
        "zeta" => -re / wn,
        "re" => re,
        "im" => im,
        _ => unreachable!("{which}"),
    }
}

/// Half a unit in the last printed digit of `text` (0 for a printed zero).
fn half_unit(text: &str) -> f64 {
    if text.parse::<f64>().unwrap() == 0.0 {
        return 0.0;
    }
    let decimals = text.split_once('.').map_or(0, |(_, f)| f.len()) as i32;
    0.5 * 10f64.powi(-decimals)
}

/// The model of a published case from its JSON, with one printed input
/// moved by `step` (the tolerance's route: the library, not the program).
fn model_of(js: &Value, moved: Option<(&str, f64)>) -> DimensionalModel {
    let step = |name: &str| match moved {
        Some((n, s)) if n == name => s,
        _ => 0.0,
    };
    let mut v = [0.0; 15];
    for (i, n) in DimensionalDerivatives::NAMES.iter().enumerate() {
        v[i] = js["derivatives"][n].as_f64().unwrap_or(0.0) + step(n);
    }
    let fp = &js["flight_printed"];
    let speed =
        fp["V"].as_str().unwrap().parse::<f64>().unwrap() * fp["V_factor"].as_f64().unwrap();
    let alpha: f64 =
        fp["alpha0_deg"].as_str().unwrap().parse::<f64>().unwrap() + step("alpha0_deg");
    let gamma: f64 = fp["gamma0_deg"].as_str().unwrap().parse().unwrap();
    let (speed, a) = (speed + step("V"), alpha.to_radians());
    let axes = if js["axes"] == "body" {
        Axes::Body
    } else {
        Axes::Stability
    };
    DimensionalModel {
        axes,
        units: if js["units"] == "ft" {
            Units::Ft
        } else {
            Units::Si
        },
        derivatives: DimensionalDerivatives::from_values(v),
        trim: Trim {
            u0: speed * a.cos(),
            w0: if axes == Axes::Body {
                speed * a.sin()
            } else {
                0.0
            },
            theta0: (alpha + gamma).to_radians(),
            g: js["flight"]["g"].as_f64().unwrap(),
        },
    }
}

fn library_mode(m: &DimensionalModel, name: &str) -> (f64, f64) {
    let a = DimensionalAnalysis::of(m, None).expect("analysis");
    let md = a
        .modes
        .iter()
        .find(|x| x.name.as_str() == name)
        .expect("mode");
    (md.re, md.im)
}

/// The source's rounding: each printed input moved by half a unit in its
/// last digit (one at a time, first order, summed), as
/// stability-core/tests/it/aircraft_published.rs establishes it.
fn rounding_band(js: &Value, name: &str, which: &str) -> f64 {
    let nominal = quantity(library_mode(&model_of(js, None), name), which);
    let mut inputs: Vec<(String, f64)> = Vec::new();
    for (n, p) in js["printed"].as_object().unwrap() {
        let h = half_unit(p["text"].as_str().unwrap()) * p["factor"].as_f64().unwrap().abs();
        inputs.push((n.clone(), h));
    }
    let fp = &js["flight_printed"];
    inputs.push((
        "V".into(),
        half_unit(fp["V"].as_str().unwrap()) * fp["V_factor"].as_f64().unwrap(),
    ));
    inputs.push((
        "alpha0_deg".into(),
        half_unit(fp["alpha0_deg"].as_str().unwrap()),
    ));
    inputs
        .iter()
        .filter(|(_, h)| *h > 0.0)
        .map(|(n, h)| {
            [1.0, -1.0]
                .iter()
                .map(|s| {
                    let moved = model_of(js, Some((n, s * h)));
                    (quantity(library_mode(&moved, name), which) - nominal).abs()
                })
                .fold(0.0, f64::max)
        })
        .sum()
}

fn mode_key(published_name: &str) -> &'static str {
    match published_name {
        "phugoid" => "phugoid",
        "short period" => "short_period",
        other => panic!("unknown mode {other}"),
    }
}

/// Every published aircraft, as its TOML is typed in from the source,
/// through `quartic --json`: each published quantity within the source's
/// rounding, or within the bound of its recorded discrepancy (and at the
/// recorded value, to 5e-4).
#[test]
fn every_published_aircraft_gives_its_published_modes_through_the_program() {
    let mut within = 0;
    for name in names() {
        let js = published(&name);
        let out = quartic(js["toml"].as_str().unwrap());
        assert_eq!(out["notation"], "dimensional");
        for pm in js["published_modes"].as_array().unwrap() {
            let key = mode_key(pm["mode"].as_str().unwrap());
            let ours = mode(&out, key);
            let keys = if pm["form"] == "omega_zeta" {
                ["omega_n", "zeta"]
            } else {
                ["re", "im"]
            };
            for k in keys {
                let text = pm[k].as_str().unwrap();
                let p: f64 = text.parse().unwrap();
                let q = quantity(ours, k);
                let band = rounding_band(&js, key, k) + half_unit(text);
                let rel = (q - p) / p.abs();
                if (q - p).abs() <= band {
                    within += 1;
                    continue;
                }
                let known = pm["known_discrepancies"]
                    .as_array()
                    .and_then(|l| l.iter().find(|x| x["quantity"] == k))
                    .unwrap_or_else(|| {
                        panic!(
                            "{name} {key} {k}: {q} against {text} ({rel:+.2e}), outside ±{band:.2e}"
                        )
                    });
                assert!(
                    rel.abs() <= known["bound"].as_f64().unwrap(),
                    "{name} {key} {k}: {rel}"
                );
                assert!(
                    (rel - known["relative"].as_f64().unwrap()).abs() < 5e-4,
                    "{name} {key} {k}: {rel}"
                );
            }
        }
    }
    assert!(within >= 17, "{within} of 22 within the rounding");
}

/// The text of a published case's TOML with `edit` applied line by line
/// (a line starting with the key is replaced).
fn edited(toml: &str, edits: &[(&str, &str)]) -> String {
    let text = std::fs::read_to_string(root().join(toml)).expect("example");
    text.lines()
        .map(|l| {
            edits
                .iter()
                .find(|(k, _)| l.starts_with(&format!("{k} =")))
                .map_or(l.to_string(), |(_, new)| new.to_string())
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// The 1-based line of `key = …` in an example file.
fn line_of(toml: &str, key: &str) -> usize {
    let text = std::fs::read_to_string(root().join(toml)).expect("example");
    1 + text
        .lines()
        .position(|l| l.starts_with(&format!("{key} =")))
        .unwrap_or_else(|| panic!("{key} in {toml}"))
}

/// CR-2144's Z_q, Z_ẇ, M_ẇ are flight-path effects of q and α̇; in body
/// axes they carry X_q = −Z_q tan α₀, X_ẇ = −Z_ẇ tan α₀ and the u̇ terms
/// X_u̇ = Z_ẇ tan²α₀, Z_u̇ = −Z_ẇ tan α₀, M_u̇ = −M_ẇ tan α₀, which the
/// tables do not print. Typed in through the optional u̇ fields, the
/// published phugoid damping comes out (the records' explanation).
#[test]
fn the_udot_fields_reproduce_cr_2144s_phugoid_damping() {
    for name in ["nt33a-fc1", "boeing-747-cr2144-fc9"] {
        let js = published(name);
        let d = &js["derivatives"];
        let t = js["flight"]["W0"].as_f64().unwrap() / js["flight"]["U0"].as_f64().unwrap();
        let (zq, zwd, mwd) = (
            d["Z_q"].as_f64().unwrap(),
            d["Z_wdot"].as_f64().unwrap(),
            d["M_wdot"].as_f64().unwrap(),
        );
        let text = edited(
            js["toml"].as_str().unwrap(),
            &[
                ("X_q", &format!("X_q = {}", -zq * t)),
                (
                    "X_wdot",
                    &format!(
                        "X_wdot = {}\nX_udot = {}\nZ_udot = {}\nM_udot = {}",
                        -zwd * t,
                        zwd * t * t,
                        -zwd * t,
                        -mwd * t
                    ),
                ),
            ],
        );
        let dir = Scratch::new();
        let f = dir.write("completed.toml", text);
        let out = quartic(path(&f));
        let pm = &js["published_modes"][0];
        assert_eq!(pm["mode"], "phugoid");
        let zeta = quantity(mode(&out, "phugoid"), "zeta");
        let p: f64 = pm["zeta"].as_str().unwrap().parse().unwrap();
        let band = rounding_band(&js, "phugoid", "zeta") + half_unit(pm["zeta"].as_str().unwrap());
        assert!(
            (zeta - p).abs() <= band,
            "{name}: ζ {zeta} against {p} ± {band}"
        );
        let as_printed = quantity(
            mode(&quartic(js["toml"].as_str().unwrap()), "phugoid"),
            "zeta",
        );
        assert!(
            (as_printed - p).abs() > band,
            "{name}: nothing left to explain"
        );
    }
}

/// The trap of issue 12: the 747's body-axis set read as stability axes
/// (θ₀ = W₀ = 0, U₀ = V) keeps its short period and loses its phugoid
/// damping (ζ 0.0485 → 0.0051); the reader refuses the file that would do
/// it unasked.
#[test]
fn a_body_axis_set_read_as_stability_axes_gives_other_modes_and_is_refused() {
    let toml = "examples/aircraft/boeing-747-cr2144-fc9.toml";
    let right = quartic(toml);
    let misread = edited(
        toml,
        &[
            ("axes", "axes = \"stability\""),
            ("U0", "U0 = 774.0"),
            ("W0", "W0 = 0.0"),
            ("theta0", "theta0 = 0.0"),
        ],
    );
    let dir = Scratch::new();
    let f = dir.write("misread.toml", &misread);
    let wrong = quartic(path(&f));
    let (zr, zw) = (
        quantity(mode(&right, "phugoid"), "zeta"),
        quantity(mode(&wrong, "phugoid"), "zeta"),
    );
    assert!(
        (zr - 0.0485).abs() < 5e-5 && (zw - 0.0051).abs() < 5e-5,
        "ζ {zr} against misread {zw}"
    );
    let (sr, sw) = (mode(&right, "short_period"), mode(&wrong, "short_period"));
    assert!(((sr.0 - sw.0).hypot(sr.1 - sw.1)) / sr.0.hypot(sr.1) < 0.02);
    // The ambiguous files: stability axes with the body-axis W0, no axes,
    // body axes without θ₀.
    for (edits, expect) in [
        (
            vec![("axes", "axes = \"stability\"")],
            format!(
                ":{}:6: [flight] W0: W0 = 62.074 in stability axes",
                line_of(toml, "W0")
            ),
        ),
        (
            vec![("axes", "")],
            ": axes: missing field `axes`".to_string(),
        ),
        (
            vec![("theta0", "")],
            ": [flight] theta0: missing field `theta0`: a body-axis set needs".to_string(),
        ),
    ] {
        let f = dir.write("ambiguous.toml", edited(toml, &edits));
        let err = stderr(&run_err(&["quartic", path(&f)], 2));
        assert!(err.contains(&expect), "{expect}:\n{err}");
        assert!(err.contains("ambiguous.toml:"), "{err}");
    }
}

/// Item 5's errors: exit status 2, the file, line and field, and what to
/// write instead.
#[test]
fn dimensional_input_errors_name_file_line_field_and_the_fix() {
    let toml = "examples/aircraft/nt33a-fc1.toml";
    let dir = Scratch::new();
    for (edits, expect) in [
        (
            vec![("units", "units = \"feet\"")],
            format!(
                ":{}:9: units: unknown units `feet`; did you mean `ft`?",
                line_of(toml, "units")
            ),
        ),
        (
            vec![("units", "units = \"SI\"")],
            "did you mean `si`?".to_string(),
        ),
        (
            vec![("axes", "axes = \"bdy\"")],
            format!(
                ":{}:8: axes: unknown axes `bdy`; did you mean `body`?",
                line_of(toml, "axes")
            ),
        ),
        (
            vec![("X_u", "C_Lalpha = 4.5")],
            format!(
                ":{}:1: [derivatives] C_Lalpha: `C_Lalpha` is a quantity of notation = \"american\" in its C_L/C_D form, not of this file's notation = \"dimensional\"",
                line_of(toml, "X_u")
            ),
        ),
        (
            vec![("X_u", "x_u = -0.1")],
            "[derivatives] x_u: `x_u` is a quantity of notation `report`".to_string(),
        ),
        (
            vec![("M_q", "M_qq = -0.694")],
            "[derivatives] M_qq: unknown field `M_qq` in [derivatives]; did you mean `M_q`?"
                .to_string(),
        ),
        (
            vec![("M_q", "")],
            "[derivatives] M_q: missing field `M_q`".to_string(),
        ),
        (
            vec![("g", "g = 9.81")],
            "[flight] g: g = 9.81 is the standard gravity in units = \"si\"".to_string(),
        ),
        (
            vec![("U0", "U0 = -227.8")],
            "[flight] U0: U0 must be positive".to_string(),
        ),
        (
            vec![("theta0", "theta0 = 95.0")],
            "[flight] theta0: the trim attitude θ₀ = 95° is not within ±89°".to_string(),
        ),
        (
            vec![("W0", "mu1 = 50.0")],
            "[flight] mu1: unknown field `mu1` in [flight]: it belongs in [reference]".to_string(),
        ),
    ] {
        let f = dir.write("bad.toml", edited(toml, &edits));
        let err = stderr(&run_err(&["quartic", path(&f)], 2));
        assert!(err.contains(&expect), "{expect}:\n{err}");
        assert!(err.contains("bad.toml:"), "{err}");
    }
    // A dimensional name in a report-notation file is named as such.
    let f = dir.write(
        "report.toml",
        common::example("tailless-delta-45.toml").replace("x_u = -0.03", "X_u = -0.03"),
    );
    let err = stderr(&run_err(&["quartic", path(&f)], 2));
    assert!(
        err.contains("`X_u` is a quantity of notation = \"dimensional\""),
        "{err}"
    );
}

/// The text page: seconds and rad/s, the set in stability axes with its u̇
/// terms, and with [reference] the report's notation and eq (41).
#[test]
fn the_quartic_page_of_a_dimensional_set_is_in_seconds() {
    let text = common::stdout(&run_ok(&[
        "quartic",
        "examples/aircraft/boeing-747-cr2144-fc9.toml",
    ]));
    for s in [
        "λ in 1/s",
        "ωₙ (rad/s)",
        "short period     -0.37170 ± 0.88682i       7.085",
        "In stability axes",
        "M_udot = -9.303e-6",
        "In the report's notation",
        "eq (41): m_θ̇ =",
        "MIL-F-8785C phugoid, ζ = 0.0485: Level 1",
    ] {
        assert!(text.contains(s), "{s}:\n{text}");
    }
    // The README's quotation of this output is the output.
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let section = &readme[readme.find("## Real aircraft data").expect("the section")..];
    let block = section
        .split("```text\n")
        .nth(1)
        .and_then(|b| b.split("```").next())
        .unwrap();
    for line in block.lines().filter(|l| !l.trim().is_empty()) {
        assert!(text.contains(line), "README line not in the output: {line}");
    }
    let v = quartic("examples/aircraft/boeing-747-cr2144-fc9.toml");
    // with [reference]: τ, and the roots in 1/τ beside 1/s
    let tau = v["tau_s"].as_f64().expect("τ");
    let r = &v["roots"][0];
    assert!((r["re"].as_f64().unwrap() - r["re_s"].as_f64().unwrap() * tau).abs() < 1e-12);
    assert_eq!(v["report"]["exact"], false);
    assert!(v["criteria"]["damping_standard"]["m_thetadot"].is_number());
}

/// The values of a `convert --json` object by name.
fn values(v: &Value) -> Vec<(String, f64)> {
    v["values"]
        .as_object()
        .unwrap()
        .iter()
        .filter_map(|(k, x)| x.as_f64().map(|x| (k.clone(), x)))
        .collect()
}

fn convert(
    from: &str,
    to: &str,
    file: &std::path::Path,
    dir: &Scratch,
    out: &str,
) -> std::path::PathBuf {
    let o = run_ok(&["convert", "--from", from, "--to", to, path(file)]);
    dir.write(out, &o.stdout)
}

/// dimensional → report → american → report → dimensional: the derivatives
/// per unit mass and inertia come back to 1e-12 (Etkin & Reid's 747, SI).
#[test]
fn dimensional_report_american_round_trip_to_1e_12() {
    let dir = Scratch::new();
    let start = root().join("examples/aircraft/boeing-747-etkin-reid.toml");
    let r = convert("dimensional", "report", &start, &dir, "r.toml");
    let a = convert("report", "american", &r, &dir, "a.toml");
    let r2 = convert("american", "report", &a, &dir, "r2.toml");
    let d = convert("report", "dimensional", &r2, &dir, "d.toml");
    let before = json(&run_ok(&["quartic", path(&start), "--json"]));
    let after = json(&run_ok(&["quartic", path(&d), "--json"]));
    for n in DimensionalDerivatives::NAMES {
        let (x, y) = (
            before["model"]["derivatives"][n].as_f64().unwrap(),
            after["model"]["derivatives"][n].as_f64().unwrap(),
        );
        assert!((x - y).abs() <= 1e-12 * x.abs(), "{n}: {x} → {y}");
    }
    for k in ["U0", "g"] {
        let (x, y) = (
            before["model"][k].as_f64().unwrap(),
            after["model"][k].as_f64().unwrap(),
        );
        assert!((x - y).abs() <= 1e-12 * x, "{k}: {x} → {y}");
    }
    // the American values are Etkin & Reid's Table 6.1 (to its 4 figures)
    let am = json(&run_ok(&[
        "convert",
        "--from",
        "report",
        "--to",
        "american",
        path(&r),
        "--json",
    ]));
    for (name, table) in [
        ("C_xu", -0.1080),
        ("C_zalpha", -4.920),
        ("C_mq", -23.92),
        ("C_zalphadot", 5.896),
    ] {
        let got = am["values"][name].as_f64().unwrap();
        assert!(
            (got - table).abs() <= 0.0015 * table.abs(),
            "{name}: {got} against {table}"
        );
    }
    // --to report of a body-axis set says what eq (4) leaves out
    let body = root().join("examples/aircraft/boeing-747-cr2144-fc9.toml");
    let err = stderr(&run_ok(&[
        "convert",
        "--from",
        "dimensional",
        "--to",
        "report",
        path(&body),
    ]));
    assert!(
        err.contains("cannot hold X_u̇ = 3.58e-5, Z_u̇ = 4.44e-4, M_u̇ = -9.30e-6"),
        "{err}"
    );
    assert!(
        err.contains("the modes move by up to 0.09 % of |λ|"),
        "{err}"
    );
}

/// `convert --from dimensional --to dimensional` turns a body-axis set into
/// stability axes; the modes stay.
#[test]
fn a_body_axis_set_converts_into_stability_axes() {
    let dir = Scratch::new();
    let body = root().join("examples/aircraft/nt33a-fc1.toml");
    let s = convert("dimensional", "dimensional", &body, &dir, "s.toml");
    let text = std::fs::read_to_string(&s).unwrap();
    assert!(
        text.contains("axes = \"stability\"") && text.contains("M_udot = -5.83"),
        "{text}"
    );
    let (a, b) = (quartic(path(&body)), quartic(path(&s)));
    for m in ["short_period", "phugoid"] {
        let (x, y) = (mode(&a, m), mode(&b, m));
        assert!(
            (x.0 - y.0).hypot(x.1 - y.1) < 1e-9 * x.0.hypot(x.1),
            "{m}: {x:?} {y:?}"
        );
    }
    // and without [reference] the report's notation is refused, saying why
    let err = stderr(&run_err(
        &[
            "convert",
            "--from",
            "dimensional",
            "--to",
            "report",
            path(&body),
        ],
        2,
    ));
    assert!(err.contains("add a [reference] table"), "{err}");
}

/// The 747 in American notation's two forms: the same roots (to rounding),
/// Etkin & Reid's published ones (within their recorded 6.5e-4), and the
/// C_L/C_D file is the C_x/C_z one converted.
#[test]
fn the_747_in_both_american_forms_has_etkin_and_reids_roots() {
    let cx = quartic("examples/boeing-747-american.toml");
    let cl = quartic("examples/boeing-747-american-cl.toml");
    let published = [
        ("short_period", (-0.3719, 0.8875)),
        ("phugoid", (-0.003289, 0.06723)),
    ];
    for (m, (re, im)) in published {
        let (a, b) = (mode(&cx, m), mode(&cl, m));
        assert!(
            (a.0 - b.0).hypot(a.1 - b.1) < 1e-12 * a.0.hypot(a.1),
            "{m}: {a:?} {b:?}"
        );
        for (ours, theirs) in [(b.0, re), (b.1, im)] {
            assert!(
                (ours - theirs).abs() <= 6.5e-4 * re.hypot(im),
                "{m}: {ours} against {theirs}"
            );
        }
    }
    // C_L/C_D → C_x/C_z: Table 6.1's values back (the C_L/C_D file was
    // written from them by the relations, with C_D = 0.043).
    let v = json(&run_ok(&[
        "convert",
        "--from",
        "american",
        "--to",
        "american",
        "examples/boeing-747-american-cl.toml",
        "--json",
    ]));
    let table = [
        ("C_xu", -0.1080),
        ("C_xalpha", 0.2193),
        ("C_zu", -0.1060),
        ("C_zalpha", -4.920),
        ("C_zq", -5.921),
        ("C_zalphadot", 5.896),
    ];
    for (name, t) in table {
        let got = v["values"][name].as_f64().unwrap();
        assert!((got - t).abs() < 1e-12, "{name}: {got} against {t}");
    }
    assert_eq!(values(&v).len(), 13);
}

/// The relations of the C_L/C_D form, derivative by derivative, written by
/// hand (stability axes at trim: X = −D cos α + L sin α, Z = −L cos α −
/// D sin α, thrust independent of speed), against the conversions the
/// engine derived from stability-core/specs/notation.toml.
#[test]
fn the_lift_drag_form_relations_derivative_by_derivative() {
    let american = Notation::named("american").unwrap();
    let cl = Notation::named("american_cl").unwrap();
    let mut v = [None; N_ROWS];
    let set = |v: &mut [Option<f64>; N_ROWS], n: Notation, name: &str, x: f64| {
        v[n.row_of(name).unwrap_or_else(|| panic!("{name}"))] = Some(x);
    };
    for (name, x) in [
        ("C_xu", -0.1080),
        ("C_xalpha", 0.2193),
        ("C_xalphadot", 0.0),
        ("C_xq", 0.0),
        ("C_zu", -0.1060),
        ("C_zalpha", -4.920),
        ("C_zq", -5.921),
        ("C_zalphadot", 5.896),
        ("C_mu", 0.1043),
        ("C_malpha", -1.023),
        ("C_mq", -23.92),
        ("C_malphadot", -6.314),
        ("C_W0", 0.6540672),
    ] {
        set(&mut v, american, name, x);
    }
    let p = [1.0; stability_core::data::notation::tables::PARAMETERS.len()];
    let mut report = american.to_report(&v, &p).unwrap();
    let c_d = 0.043;
    report[row("c_d").unwrap()] = Some(c_d);
    let w = cl.from_report(&report, &p).unwrap();
    let get = |n: Notation, vals: &[Option<f64>; N_ROWS], name: &str| {
        vals[n.row_of(name).unwrap()].unwrap()
    };
    let (a, c) = (|name| get(american, &v, name), |name| get(cl, &w, name));
    let c_l = c("C_L");
    let close = |x: f64, y: f64| (x - y).abs() < 1e-12;
    assert!(close(c_l, a("C_W0")));
    assert!(
        close(a("C_xu"), -c("C_Du") - 2.0 * c_d),
        "C_xu = −C_Du − 2C_D"
    );
    assert!(
        close(a("C_xalpha"), c_l - c("C_Dalpha")),
        "C_xα = C_L − C_Dα"
    );
    assert!(
        close(a("C_zu"), -c("C_Lu")),
        "C_zu = −C_Lu: the −2C_W0 is not in C_zu"
    );
    assert!(
        close(a("C_zalpha"), -c("C_Lalpha") - c_d),
        "C_zα = −C_Lα − C_D"
    );
    assert!(close(a("C_zq"), -c("C_Lq")), "C_zq = −C_Lq");
    assert!(close(a("C_zalphadot"), -c("C_Lalphadot")), "C_zα̇ = −C_Lα̇");
    assert!(c("C_Lalphadot") < 0.0, "the 747's C_Lα̇ is negative");
    for m in ["C_mu", "C_malpha", "C_mq", "C_malphadot"] {
        assert!(close(a(m), c(m)), "{m}");
    }
    // and the report's z_u holds the −2C_L: z_u = C_zu − 2C_W0 = −C_Lu − 2C_L
    let z_u = report[row("z_u").unwrap()].unwrap();
    assert!(close(z_u, a("C_zu") - 2.0 * a("C_W0")));
}

/// A file mixing the two American forms is refused, naming both names.
#[test]
fn the_american_forms_are_not_mixed() {
    let dir = Scratch::new();
    let text =
        common::example("boeing-747-american-cl.toml").replace("C_Lu = 0.1060", "C_zu = -0.1060");
    let f = dir.write("mixed.toml", text);
    let err = stderr(&run_err(&["quartic", path(&f)], 2));
    assert!(
        err.contains("of the C_L/C_D form and `C_zu` of the C_x/C_z form"),
        "{err}"
    );
    let text = common::example("boeing-747-american-cl.toml").replace("C_D = 0.043", "");
    let f = dir.write("nodrag.toml", text);
    let err = stderr(&run_err(&["quartic", path(&f)], 2));
    assert!(
        err.contains("[flight] C_D: missing field `C_D`: the C_L/C_D form needs"),
        "{err}"
    );
}

/// The trim as V and α₀ (as CR-2144 prints it) is the same set as U₀ and
/// W₀; the reference as μ₁ and i_B the same as ρ, S, m and I_y; W₀ left
/// out in body axes is announced.
#[test]
fn the_alternative_forms_of_the_trim_and_the_reference_are_the_same_set() {
    let toml = "examples/aircraft/boeing-747-cr2144-fc9.toml";
    let base = quartic(toml);
    let dir = Scratch::new();
    let va = edited(toml, &[("U0", "V = 774.0"), ("W0", "alpha0 = 4.6")]);
    let f = dir.write("va.toml", va);
    let v = quartic(path(&f));
    for m in ["short_period", "phugoid"] {
        let (a, b) = (mode(&base, m), mode(&v, m));
        // U0 and W0 are printed to 1e-4 ft/s
        assert!(
            (a.0 - b.0).hypot(a.1 - b.1) < 1e-6 * a.0.hypot(a.1),
            "{m}: {a:?} {b:?}"
        );
    }
    let r = &base["report"]["reference"];
    let (mu1, i_b) = (r["mu1"].as_f64().unwrap(), r["i_b"].as_f64().unwrap());
    let direct = edited(
        toml,
        &[
            ("S", &format!("mu1 = {mu1:?}")),
            ("rho", &format!("i_b = {i_b:?}")),
            ("weight", ""),
            ("I_y", ""),
        ],
    );
    let f = dir.write("direct.toml", direct);
    let d = quartic(path(&f));
    for k in ["m_thetadot", "m_thetadot_max"] {
        let (x, y) = (
            base["criteria"]["damping_standard"][k].as_f64().unwrap(),
            d["criteria"]["damping_standard"][k].as_f64().unwrap(),
        );
        assert!((x - y).abs() <= 1e-12 * x.abs(), "{k}: {x} {y}");
    }
    let no_w0 = edited("examples/aircraft/nt33a-fc1.toml", &[("W0", "")]);
    let f = dir.write("no_w0.toml", no_w0);
    let err = stderr(&run_ok(&["quartic", path(&f)]));
    assert!(err.contains("[flight] W0 not given: taken as 0"), "{err}");
}

/// The engineer's outputs of a dimensional set (damp(), mode shapes, the
/// short-period frequency requirement) are those of the same aircraft typed
/// in another notation: Etkin & Reid's 747 as dimensional derivatives (SI,
/// stability axes) and as American coefficients give the same mode shapes
/// to the rounding of their printed data (the American route's shapes are
/// tested against Etkin & Reid's printed matrix in tests/it/engineering.rs).
#[test]
fn a_dimensional_set_has_the_mode_shapes_of_the_same_aircraft_in_american_notation() {
    let dim = quartic("examples/aircraft/boeing-747-etkin-reid.toml");
    let american = quartic("examples/boeing-747-american.toml");
    for key in ["damp", "mode_shapes", "short_period_frequency"] {
        assert!(!dim[key].is_null(), "no {key} for a dimensional set");
    }
    let shape = |v: &Value, mode: &str, state: &str| {
        let m = v["mode_shapes"]
            .as_array()
            .unwrap()
            .iter()
            .find(|m| m["mode"] == mode)
            .unwrap_or_else(|| panic!("no {mode}"));
        let c = &m[state];
        (
            c["magnitude"].as_f64().unwrap(),
            c["phase_deg"].as_f64().unwrap(),
        )
    };
    for mode in ["short_period", "phugoid"] {
        for state in ["u_over_v", "alpha", "q", "theta"] {
            let (a, pa) = shape(&dim, mode, state);
            let (b, pb) = shape(&american, mode, state);
            assert!(
                (a - b).abs() <= 5e-3 * b.abs().max(1e-3) && (pa - pb).abs() < 0.5,
                "{mode} {state}: {a} ∠{pa}° vs {b} ∠{pb}°"
            );
        }
    }
    let cap = |v: &Value| v["short_period_frequency"]["cap"].as_f64();
    let (c1, c2) = (cap(&dim), cap(&american));
    assert!(c1.is_some() && c2.is_some(), "{dim:#?}");
    assert!((c1.unwrap() - c2.unwrap()).abs() < 2e-3 * c2.unwrap());
}
