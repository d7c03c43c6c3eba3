//! The program as a user runs it: output, exit status and messages.

use crate::common;

use common::{Scratch, bin, json, path, root, run_err, run_ok, stderr, wait_while_running};
use stability_core::dynamics::quartic::reference::eq6_by_hand;

#[test]
fn quartic_json_has_the_coefficients_of_eq6() {
    let v = json(&run_ok(&[
        "quartic",
        "examples/tailless-delta-45.toml",
        "--json",
    ]));
    // The example's values (the file is the library's example aircraft,
    // tested in stability-core/tests/it/examples.rs), through eq (6) typed by
    // hand (corrected).
    let inputs = stability_core::design::examples::tailless_delta_45().quartic_input_values();
    let expect = eq6_by_hand(&inputs);
    for (k, name) in ["A", "B", "C", "D", "E"].iter().enumerate() {
        let got = v["coefficients"][name].as_f64().expect("a number");
        assert!(
            (got - expect[k]).abs() <= 1e-12 * expect[k].abs().max(1.0),
            "{name}: {got} vs {}",
            expect[k]
        );
    }
    // A = 1 − z_ẇ/μ₁ = 1 + 0.6/50, by hand.
    assert_eq!(v["coefficients"]["A"].as_f64(), Some(1.012));
}

#[test]
fn quartic_table_is_readable() {
    let out = run_ok(&["quartic", "examples/tailless-delta-45.toml"]);
    let text = common::stdout(&out);
    assert!(text.contains("A =       1.012000"), "{text}");
}

/// `quartic` on a file with `contents`: its exit status and standard error.
fn run_on(contents: &str) -> (i32, String) {
    let dir = Scratch::new();
    let path = dir.write("case.toml", contents);
    let out = bin().arg("quartic").arg(&path).output().expect("run");
    (out.status.code().unwrap_or(-1), stderr(&out))
}

fn example() -> String {
    common::example("tailless-delta-45.toml")
}

#[test]
fn bad_input_is_exit_status_2_with_file_line_and_field() {
    let ex = example();
    let cases = [
        (
            ex.replace("m_q = -0.6", ""),
            ":7:1: [derivatives] m_q: missing field `m_q`",
        ),
        (
            ex.replace("m_q = -0.6", "m_qq = -0.6"),
            ":19:1: [derivatives] m_qq: unknown field `m_qq`",
        ),
        (
            ex.replace("z_w = -3.2", "z_w = nan"),
            ":13:7: [derivatives] z_w: NaN is not a finite number",
        ),
        (
            ex.replace("mu1 = 50.0", "mu1 = 0.0"),
            ":23:7: [flight] mu1: the relative density",
        ),
        (
            ex.replace("i_b = 0.08", "i_b = -1"),
            ":24:7: [flight] i_b: the pitching inertia",
        ),
        (
            ex.replace("\"report\"", "\"navy\""),
            ":5:12: notation: unknown notation `navy`",
        ),
        (
            ex.replace("\"report\"", "\"avl\""),
            ":5:12: st_file: the avl notation needs `st_file",
        ),
    ];
    for (text, expected) in cases {
        let (code, err) = run_on(&text);
        assert_eq!(code, 2, "{err}");
        assert!(err.contains(expected), "expected {expected:?} in:\n{err}");
        assert!(err.contains("case.toml"), "{err}");
    }
}

#[test]
fn help_teaches_the_file_format() {
    let text = common::stdout(&run_ok(&["quartic", "--help"]));
    assert!(text.contains("notation = \"report\""), "{text}");
    assert!(text.contains("docs/errata.md"), "{text}");
}

#[test]
fn quartic_json_has_roots_modes_and_routh() {
    let out = run_ok(&[
        "quartic",
        "examples/tailless-delta-60-dimensional.toml",
        "--json",
    ]);
    let text = common::stdout(&out);
    assert!(!text.contains("NaN"));
    let v: serde_json::Value = serde_json::from_str(&text).expect("JSON");
    let q: Vec<f64> = ["A", "B", "C", "D", "E"]
        .iter()
        .map(|k| v["coefficients"][k].as_f64().unwrap())
        .collect();
    // Routh's discriminant from the printed coefficients, by hand: BCD − AD² − B²E
    let r = q[1] * q[2] * q[3] - q[0] * q[3] * q[3] - q[1] * q[1] * q[4];
    assert!((v["routh_discriminant"].as_f64().unwrap() - r).abs() <= 1e-9 * r.abs());
    assert_eq!(v["stable"], serde_json::Value::Bool(true));
    let roots = v["roots"].as_array().unwrap();
    assert_eq!(roots.len(), 4);
    for z in roots {
        let (re, im) = (z["re"].as_f64().unwrap(), z["im"].as_f64().unwrap());
        // P(λ) ≈ 0 relative to its terms
        let l = num_complex::Complex64::new(re, im);
        let p = (((l * q[0] + q[1]) * l + q[2]) * l + q[3]) * l + q[4];
        let scale: f64 = q
            .iter()
            .enumerate()
            .map(|(k, c)| c.abs() * l.norm().powi(4 - k as i32))
            .sum();
        assert!(p.norm() <= 1e-12 * scale);
        assert!(z["re_s"].is_number() && z["im_s"].is_number());
    }
    let modes = v["modes"].as_array().unwrap();
    let names: Vec<&str> = modes.iter().map(|m| m["name"].as_str().unwrap()).collect();
    assert_eq!(names, ["short_period", "phugoid"]);
    for m in modes {
        for key in [
            "re",
            "im",
            "period",
            "time_to_half",
            "cycles_to_half",
            "damping_ratio",
            "natural_frequency",
            "period_s",
            "time_to_half_s",
        ] {
            assert!(m[key].is_number(), "{key} in {m}");
        }
        // eq (8): cycles = (ln 2/2π)·s/(−r), and seconds = τ units × τ
        let (re, im) = (m["re"].as_f64().unwrap(), m["im"].as_f64().unwrap());
        let cycles = std::f64::consts::LN_2 / (2.0 * std::f64::consts::PI) * im / -re;
        assert!((m["cycles_to_half"].as_f64().unwrap() - cycles).abs() <= 1e-12 * cycles);
        let tau = 12000.0 / (0.5 * 0.4135 * 60.0 * 280.0);
        let p = m["period"].as_f64().unwrap();
        assert!((m["period_s"].as_f64().unwrap() - p * tau).abs() <= 1e-12 * p * tau);
    }
}

#[test]
fn a_degenerate_quartic_is_a_clear_error() {
    // z_wdot = mu1 makes A = 0.
    let ex = example().replace("z_wdot = -0.6", "z_wdot = 50.0");
    let (code, err) = run_on(&ex);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("A = 1 − z_ẇ/μ₁ = 0"), "{err}");
}

#[test]
fn response_writes_csv_and_svg() {
    let dir = Scratch::new();
    let csv = dir.path().join("r.csv");
    let svg = dir.path().join("r.svg");
    run_ok(&[
        "response",
        "examples/tailless-delta-45.toml",
        "--input",
        "step",
        "--until",
        "2",
        "--steps",
        "100",
        "--csv",
        path(&csv),
        "--svg",
        path(&svg),
    ]);
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("t_hat,u_hat,w_hat,q_hat,theta,w_hat_eq45,gamma,n_z")
    );
    assert_eq!(lines.count(), 101);
    let svg = std::fs::read_to_string(&svg).unwrap();
    assert!(svg.contains("<svg") && svg.contains("t̂ = t/τ"));
}

#[test]
fn response_rejects_a_bad_input_kind() {
    let out = run_err(
        &[
            "response",
            "examples/tailless-delta-45.toml",
            "--input",
            "ramp",
            "--until",
            "1",
        ],
        2,
    );
    // a closed choice: the message lists the kinds there are
    let err = stderr(&out);
    assert!(
        err.contains("'ramp'") && err.contains("step") && err.contains("initial"),
        "{err}"
    );
}

#[test]
fn analyze_gives_the_derivatives_coefficients_modes_and_criteria() {
    let out = run_ok(&[
        "analyze",
        "examples/delta-45.toml",
        "--json",
        "--mach",
        "0.6",
    ]);
    let text = common::stdout(&out);
    assert!(!text.contains("NaN"));
    let v: serde_json::Value = serde_json::from_str(&text).expect("JSON");
    for key in ["derivatives", "coefficients", "modes", "criteria"] {
        assert!(!v[key].is_null(), "{key}");
    }
    let d = &v["derivatives"];
    for name in [
        "x_u", "x_w", "x_wdot", "x_q", "z_u", "z_w", "z_wdot", "z_q", "m_u", "m_w", "m_wdot",
        "m_q", "c_l", "mu1", "i_b",
    ] {
        assert!(d[name].is_number(), "{name}");
    }
    // level flight, eq (24): C_L = 0.05/0.36
    assert!((d["c_l"].as_f64().unwrap() - 0.05 / 0.36).abs() < 1e-15);
    // the default (faired) model subsonic is the lattice at the short
    // period's own ω̄: the lifting surface asked for at that ω̄ by name, with
    // its own lift slope and aerodynamic centre, gives the same derivatives
    let w = v["damping"]["frequency"]["converged"]
        .as_f64()
        .expect("iterated");
    // (the roots are the p-method's, each at its own complex frequency: the
    // short period's ω̄ near the k-method's fixed point, not at it)
    let own = v["modes"][0]["frequency_parameter"].as_f64().unwrap();
    assert!(
        (w - own).abs() < 0.1 * w && (w - own).abs() > 1e-6,
        "{w} vs {own}"
    );
    assert_eq!(v["damping"]["frequency"]["method"], "p");
    let by_name = run_ok(&[
        "analyze",
        "examples/delta-45.toml",
        "--json",
        "--mach",
        "0.6",
        "--damping",
        "lifting-surface",
        "--aero",
        "lifting-surface",
        "--omega-bar",
        &format!("{w:?}"),
    ]);
    let l: serde_json::Value = serde_json::from_str(&common::stdout(&by_name)).unwrap();
    for name in ["z_q", "z_wdot", "m_q", "m_wdot", "z_w", "m_w", "z_u", "m_u"] {
        let (a, b) = (
            d[name].as_f64().unwrap(),
            l["derivatives"][name].as_f64().unwrap(),
        );
        assert!(
            (a - b).abs() < 1e-12 * b.abs().max(1.0),
            "{name}: {a} vs {b}"
        );
    }
    // the slender fairing's damping subsonic at h = 0.25, A = 4, by hand (eq 37)
    let slender = run_ok(&[
        "analyze",
        "examples/delta-45.toml",
        "--json",
        "--mach",
        "0.6",
        "--damping",
        "faired-slender",
    ]);
    let s: serde_json::Value = serde_json::from_str(&common::stdout(&slender)).unwrap();
    let pi = std::f64::consts::PI;
    assert!((s["derivatives"]["z_q"].as_f64().unwrap() + 1.5 * pi).abs() < 1e-12);
    assert!((s["derivatives"]["m_q"].as_f64().unwrap() + 0.75 * pi).abs() < 1e-12);
}

#[test]
fn analyze_rejects_theories_outside_their_validity_and_bad_configs() {
    let out = run_err(
        &[
            "analyze",
            "examples/delta-45.toml",
            "--damping",
            "supersonic",
            "--mach",
            "0.9",
        ],
        2,
    );
    assert!(stderr(&out).contains("needs M > 1"));
    let out = run_err(
        &["analyze", "examples/delta-45.toml", "--damping", "mangler"],
        2,
    );
    assert!(
        stderr(&out).contains("transonic-frequency"),
        "{}",
        stderr(&out)
    );

    let cfg = common::example("delta-45.toml");
    let dir = Scratch::new();
    let cases = [
        (cfg.replace("sweep = 45.0", "sweep = 95.0"), "[planform] sweep: the leading-edge sweep must lie strictly between 0° and 90°"),
        (cfg.replace("mu1 = 50.0", "mu1 = -3.0"), "[flight] mu1: the relative density μ₁ must be positive"),
        (
            cfg.replace("damping = \"faired\"", "damping = \"faired\"\n[model.tables]\nlift_slope = { mach = [0.5, 0.4], value = [3.0, 3.1] }"),
            "row 2: Mach 0.4 does not increase",
        ),
        (cfg.replace("root_chord = 10.0", "root_chord = 10.0\nspan = 3.0"), "give only one size"),
    ];
    for (text, expected) in cases {
        let p = dir.write("c.toml", text);
        let out = run_err(&["analyze", path(&p)], 2);
        let err = stderr(&out);
        assert!(
            err.contains(expected) && err.contains("c.toml:"),
            "{expected}\n{err}"
        );
    }
}

fn quartic_json(file: &std::path::Path) -> serde_json::Value {
    json(&run_ok(&["quartic", path(file), "--json"]))
}

#[test]
fn the_747_in_american_notation_gives_etkin_and_reids_roots_in_seconds() {
    let v = quartic_json(&root().join("examples/boeing-747-american.toml"));
    let roots = v["roots"].as_array().unwrap();
    let get = |i: usize, k: &str| roots[i][k].as_f64().unwrap();
    // Etkin & Reid (1996): −0.3719 ± 0.8875i, −0.003289 ± 0.06723i (1/s)
    assert!((get(0, "re_s") + 0.3719).abs() < 0.001 && (get(0, "im_s") - 0.8875).abs() < 0.002);
    assert!(
        (get(2, "re_s") + 0.003289).abs() < 0.00001 && (get(2, "im_s") - 0.06723).abs() < 0.0001
    );
}

#[test]
fn converted_files_describe_the_same_aircraft() {
    let dir = Scratch::new();
    let base = quartic_json(&root().join("examples/boeing-747-american.toml"));
    for to in ["report", "garner", "duncan", "american"] {
        let out = run_ok(&[
            "convert",
            "--from",
            "american",
            "--to",
            to,
            "examples/boeing-747-american.toml",
        ]);
        let p = dir.write(&format!("{to}.toml"), &out.stdout);
        let v = quartic_json(&p);
        for k in ["A", "B", "C", "D", "E"] {
            let (a, b) = (
                base["coefficients"][k].as_f64().unwrap(),
                v["coefficients"][k].as_f64().unwrap(),
            );
            assert!((a - b).abs() <= 1e-12 * a.abs(), "{to}: {k} {a} vs {b}");
        }
    }
}

#[test]
fn avl_output_is_read_with_its_assumptions_stated() {
    let out = run_ok(&["quartic", "examples/avl-tailless-delta.toml", "--json"]);
    let err = stderr(&out);
    assert!(err.contains("quasi-steady") && err.contains("apparent mass"));
    let v = json(&out);
    // μ₁ = m/(½ρ Sref Cref) = 9000/(0.5·1.225·60·7) and A = 1 (z_ẇ = 0)
    assert_eq!(v["coefficients"]["A"].as_f64(), Some(1.0));
    assert!(v["modes"][0]["name"] == "short_period");
}

#[test]
fn notations_missing_what_they_need_are_named() {
    let dir = Scratch::new();
    // American without mass: μ₁ cannot be formed
    let text = common::example("boeing-747-american.toml").replace("mass = 288660.55", "");
    let p = dir.write("d.toml", text);
    let args = ["quartic", path(&p)];
    let err = stderr(&run_err(&args, 2));
    assert!(
        err.contains("lacks `mu1`, `i_b`") && err.contains("[dimensional]"),
        "{err}"
    );
    // Duncan without the tail arm
    dir.write(
        "d.toml",
        "notation = \"duncan\"\n[derivatives]\nx_u = 1.0\n",
    );
    assert!(stderr(&run_err(&args, 2)).contains("[parameters] lt"));
    // a truncated AVL file: the .st's own line
    let st = common::example("tailless-delta.st");
    let cut: String = st.lines().take(30).collect::<Vec<_>>().join("\n");
    dir.write("cut.st", cut);
    dir.write("d.toml", "notation = \"avl\"\nst_file = \"cut.st\"\n[dimensional]\nmass = 1.0\nI_y = 1.0\nrho = 1.0\nV = 1.0\n");
    let err = stderr(&run_err(&args, 2));
    assert!(
        err.contains("cut.st:30:") && err.contains("ends without"),
        "{err}"
    );
}

/// The one run of the whole report end to end in the tests
/// ([`common::note_report`]; the library's report is checked in
/// report_conclusions.rs).
#[test]
fn report_writes_the_figures_summary_and_page() {
    // nested: the page's links must work wherever --out points
    let out = common::note_report();
    assert_links_stay_in(out);
    assert_figures_are_whole(out);
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_summary_findings(&summary);
    assert_how_sure_reruns(&summary);
    let html = std::fs::read_to_string(out.join("index.html")).unwrap();
    assert!(
        html.contains("fig33.svg")
            && html.contains("0.97 &lt; M &lt; 1.5")
            && html.contains("about 200")
    );
    // README.md shows docs/figures/fig33.* and the text under it, which
    // `cargo xtask regen` writes (its check-mode test keeps them as the
    // library computes them now): they are exactly the report's files, and
    // the text says what summary.json says
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    for name in ["fig33.svg", "fig33.csv"] {
        let shown = std::fs::read_to_string(root.join("docs/figures").join(name)).unwrap();
        let (preamble, shown) = shown.split_once('\n').unwrap();
        assert!(preamble.contains("generated by `cargo xtask regen`"));
        let written = std::fs::read_to_string(out.join(name)).unwrap();
        assert!(
            written == shown.trim_start_matches('\n'),
            "{name} differs from the report's"
        );
    }
    let readme = std::fs::read_to_string(root.join("README.md")).unwrap();
    let (_, text) = readme.split_once("<!-- conclusions:begin").unwrap();
    let (text, _) = text.split_once("<!-- conclusions:end -->").unwrap();
    assert_readme_says_what_the_summary_says(text, &summary);
    assert_conclusions_are_computed(&html, &summary);
}

/// README.md's list of the note's conclusions is summary.json's: one
/// bullet per conclusion, with its claim, its verdict and, as "Ours", the
/// numbers its `ours` begins with (before the sweeps).
fn assert_readme_says_what_the_summary_says(text: &str, summary: &serde_json::Value) {
    let words = |s: &str| s.split_whitespace().collect::<Vec<_>>().join(" ");
    let conclusions = summary["conclusions"].as_array().unwrap();
    let bullets: Vec<String> = text.split("\n- ").skip(1).map(words).collect();
    assert_eq!(bullets.len(), conclusions.len(), "{text}");
    for (bullet, c) in bullets.iter().zip(conclusions) {
        let claim = words(c["claim"].as_str().unwrap());
        let verdict = if c["reproduced"].as_bool().unwrap() {
            "Reproduced:"
        } else {
            "Not reproduced:"
        };
        let (head, ours) = bullet.split_once(" Ours: ").unwrap();
        let ours = ours.trim_end_matches(" </details>");
        assert!(
            head.starts_with(verdict) && head.ends_with(&claim),
            "{bullet}"
        );
        assert!(
            words(c["ours"].as_str().unwrap()).starts_with(ours),
            "{bullet}"
        );
    }
}

/// Every figure the report draws, as SVG with its title and as CSV, with no
/// NaN or infinity in either.
fn assert_figures_are_whole(dir: &std::path::Path) {
    for n in [
        "02", "04", "05", "06", "07", "12", "13", "14", "15", "16", "17", "18", "19", "24", "25",
        "26", "27", "31", "32", "33", "34", "35", "36", "37", "38",
    ] {
        let svg = std::fs::read_to_string(dir.join(format!("fig{n}.svg")))
            .unwrap_or_else(|e| panic!("fig{n}.svg: {e}"));
        assert!(
            svg.contains(&format!("Fig. {}", n.trim_start_matches('0'))) && !svg.contains("NaN"),
            "fig{n}"
        );
        let csv = std::fs::read_to_string(dir.join(format!("fig{n}.csv"))).unwrap();
        assert!(
            csv.lines().count() > 10 && !csv.contains("NaN") && !csv.contains("inf"),
            "fig{n}.csv"
        );
    }
}

/// summary.json's section "how sure" (`report::certainty`): each headline's
/// counts by Mach number are those its stated command gives, run as
/// written.
fn assert_how_sure_reruns(summary: &serde_json::Value) {
    let headlines = summary["how_sure"]["headlines"].as_array().unwrap();
    assert_eq!(headlines.len(), 2);
    for h in headlines {
        let command = h["command"].as_str().unwrap();
        let mut args: Vec<&str> = command.split_whitespace().skip(1).collect();
        args.push("--json");
        let v = json(&run_ok(&args));
        let (ours, theirs) = (
            h["by_mach"].as_array().unwrap(),
            v["results"].as_array().unwrap(),
        );
        assert_eq!(ours.len(), theirs.len(), "{command}");
        let fails = h["conclusion"] == "45-transonic";
        for (a, b) in ours.iter().zip(theirs) {
            let met = &b["standard_met"];
            let (count, n) = (met["count"].as_u64().unwrap(), met["n"].as_u64().unwrap());
            let claimed = if fails { n - count } else { count };
            assert_eq!(a["mach"], b["mach"], "{command}");
            assert_eq!(
                a["count"].as_u64(),
                Some(claimed),
                "{command} at {}",
                a["mach"]
            );
            assert_eq!(a["n"].as_u64(), Some(n));
        }
    }
}

/// summary.json's keys, and the note's findings about the 60° and 45° deltas.
fn assert_summary_findings(summary: &serde_json::Value) {
    for wing in ["delta_45", "delta_60"] {
        for key in ["unstable_mach", "fails_one_cycle_mach", "max_mu1_one_cycle"] {
            assert!(summary[wing][key].is_array(), "{wing} {key}");
        }
    }
    // The 60° delta meets the standard at μ₁ = 50 everywhere (as the note
    // says); its largest μ₁ at M = 1.3 is of the note's size (~200).
    let fails_60 = summary["delta_60"]["fails_one_cycle_mach"]
        .as_array()
        .unwrap();
    assert_eq!(fails_60.len(), 0);
    let at = summary["delta_60"]["max_mu1_one_cycle"]
        .as_array()
        .unwrap()
        .iter()
        .find(|p| (p[0].as_f64().unwrap() - 1.3).abs() < 1e-9)
        .unwrap()[1]
        .as_f64()
        .unwrap();
    assert!((100.0..400.0).contains(&at), "{at}");
    // by one lifting surface at the short period's frequency the 45° delta
    // meets it everywhere (the note's fairing failed it at M 0.98–1.50:
    // docs/lattice-near-sonic.md, "The headline, recomputed")
    let fails_45 = summary["delta_45"]["fails_one_cycle_mach"]
        .as_array()
        .unwrap();
    assert!(fails_45.is_empty(), "{fails_45:?}");
}

/// The conclusions are generated from what was computed: the 45° delta's
/// intervals in summary.json appear, as numbers, in its row.
fn assert_conclusions_are_computed(html: &str, summary: &serde_json::Value) {
    let interval = match summary["delta_45"]["fails_one_cycle_mach"].get(0) {
        Some(fails) => format!(
            "{:.2}–{:.2}",
            fails[0].as_f64().unwrap(),
            fails[1].as_f64().unwrap()
        ),
        None => "fails one cycle nowhere".to_string(),
    };
    let row = html
        .split("<tr>")
        .find(|r| r.contains("0.97 &lt; M &lt; 1.5"))
        .unwrap();
    assert!(
        row.contains(&interval) && row.contains("class=\""),
        "{interval}: {row}"
    );
}

/// The relative links (`href`, `src`) of an HTML page.
fn links(html: &str) -> Vec<String> {
    let mut out = Vec::new();
    for attr in ["href=\"", "src=\""] {
        for part in html.split(attr).skip(1) {
            let target = part.split('"').next().unwrap_or("");
            if !target.starts_with('#') && !target.contains("://") {
                out.push(target.to_string());
            }
        }
    }
    out
}

/// Every link of the report's page at `out` is a file of the report, and
/// none leaves it (one report run serves this and the test above).
fn assert_links_stay_in(out: &std::path::Path) {
    let html = std::fs::read_to_string(out.join("index.html")).unwrap();
    let targets = links(&html);
    assert!(targets.len() > 70, "{targets:?}");
    for t in targets {
        assert!(
            out.join(&t).is_file(),
            "index.html links to {t}, which is not in the report"
        );
        assert!(!t.starts_with(".."), "{t} leaves the report");
    }
}

/// The previous report is a copy of the tests' one run of the note's
/// report ([`common::note_report`]); the runs killed are the note's
/// report's (its Fig 1 is written at once), the later run a design's
/// report, written as the note's is (`write_report`).
#[test]
fn a_killed_report_leaves_the_previous_report_whole() {
    let dir = Scratch::new();
    let out = dir.path().join("report");
    common::copy_dir(common::note_report(), &out);
    // the previous report's page, told from a new one by its time
    let page = out.join("index.html");
    let modified = |p: &std::path::Path| std::fs::metadata(p).unwrap().modified().unwrap();
    age(&page, 3600);
    let mut previous = modified(&page);
    let listing = |p: &std::path::Path| -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(p)
            .unwrap()
            .map(|e| e.unwrap().file_name().into_string().unwrap())
            .collect();
        v.sort();
        v
    };
    let before = listing(&out);
    // kill a run once its temporary directory holds some of its figures
    let mut killed = false;
    for _ in 0..5 {
        let mut child = bin()
            .args(["report", "--out", path(&out)])
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .expect("run");
        let started = wait_while_running(&mut child, || {
            entries_named(dir.path(), ".delta-stability-")
                .iter()
                .any(|d| std::fs::read_dir(d).is_ok_and(|mut e| e.next().is_some()))
        });
        child.kill().unwrap();
        let status = child.wait().unwrap();
        if started && !status.success() {
            killed = true;
            break;
        }
        age(&page, 3600);
        previous = modified(&page);
    }
    assert!(killed, "no run was killed while writing");
    assert_eq!(modified(&page), previous, "the page was replaced");
    assert_eq!(listing(&out), before, "a mix of old and new");
    let stray = entries_named(dir.path(), ".delta-stability-");
    assert_eq!(stray.len(), 1, "{stray:?}");
    // a later run removes the dead run's directory and replaces the report
    age(&stray[0], 3600);
    let design = ["report", "examples/delta-60.toml", "--mach", "1.2"];
    run_ok(&[&design[..], &["--out", path(&out)]].concat());
    assert_ne!(modified(&page), previous, "the page was not replaced");
    assert!(entries_named(dir.path(), ".delta-stability-").is_empty());
}

#[test]
fn the_report_replaces_only_a_report() {
    let dir = Scratch::new();
    let notes = dir.write("notes.txt", "mine");
    let err = stderr(&run_err(&["report", "--out", path(dir.path())], 3));
    assert!(
        err.contains("will not replace") && err.contains("notes.txt"),
        "{err}"
    );
    assert_eq!(std::fs::read_to_string(notes).unwrap(), "mine");
}

/// The eigenvalues of the state matrix of eqs (2) (independent of the
/// quartic and of its solver), from a row's fifteen inputs.
fn eigenvalues_of_eqs_2(d: &[f64; 15]) -> Vec<num_complex::Complex64> {
    let [
        x_u,
        x_w,
        x_wdot,
        x_q,
        z_u,
        z_w,
        z_wdot,
        z_q,
        m_u,
        m_w,
        m_wdot,
        m_q,
        c_l,
        mu1,
        i_b,
    ] = *d;
    // (1 − z_ẇ/μ₁) ŵ' = z_u û + z_w ŵ + (μ₁ + z_q)/μ₁ q̂, and the rows
    // for û' and q̂' with the ŵ' terms substituted
    let a = 1.0 - z_wdot / mu1;
    let w = [z_u / a, z_w / a, (1.0 + z_q / mu1) / a, 0.0];
    let m = nalgebra::Matrix4::new(
        x_u + x_wdot / mu1 * w[0],
        x_w + x_wdot / mu1 * w[1],
        x_q / mu1 + x_wdot / mu1 * w[2],
        -c_l,
        w[0],
        w[1],
        w[2],
        0.0,
        mu1 / i_b * m_u + m_wdot / i_b * w[0],
        mu1 / i_b * m_w + m_wdot / i_b * w[1],
        m_q / i_b + m_wdot / i_b * w[2],
        0.0,
        0.0,
        0.0,
        1.0,
        0.0,
    );
    m.complex_eigenvalues().iter().copied().collect()
}

/// One sweep row against the eigenvalues of eqs (2) from its own
/// derivative columns: the short period's root, eq (8)'s cycles and the
/// overall verdict; the row's cycles to half amplitude.
fn row_agrees_with_eqs_2(r: &[&str], col: &dyn Fn(&str) -> usize) -> f64 {
    // the twelve derivatives and c_l, then μ₁ and i_B from the grid's
    // columns (each column once: issue 19)
    let d: [f64; 15] = std::array::from_fn(|k| {
        let c = match k {
            13 => col("mu1"),
            14 => col("i_b"),
            _ => col("x_u") + k,
        };
        r[c].parse().unwrap()
    });
    let eig = eigenvalues_of_eqs_2(&d);
    let sp = num_complex::Complex64::new(
        r[col("sp_re")].parse().unwrap(),
        r[col("sp_im")].parse().unwrap(),
    );
    let nearest = eig
        .iter()
        .map(|z| (z - sp).norm())
        .fold(f64::INFINITY, f64::min);
    assert!(nearest <= 1e-9 * sp.norm(), "{nearest} {r:?}");
    // eq (8): cycles to half = 0.11032 s/(−r)
    let cycles: f64 = r[col("sp_cycles_to_half")].parse().unwrap();
    assert!((cycles - 0.11032 * sp.im / -sp.re).abs() < 1e-4 * cycles);
    // the overall verdict from the eigenvalues of eqs (2): divergent
    // where any root grows, else the §8 standard on the short period
    let verdict = r[col("verdict")];
    let grows = eig.iter().any(|z| z.re > 0.0);
    let expected = match (grows, cycles <= 1.0) {
        (true, _) => "divergent",
        (false, true) => "meets",
        (false, false) => "fails",
    };
    assert_eq!(verdict, expected, "{r:?}");
    cycles
}

#[test]
fn sweep_csv_covers_the_grid_and_agrees_with_the_state_matrix() {
    let dir = Scratch::new();
    let out_path = dir.path().join("grid.csv");
    // the k-method: its roots are the derivative columns' eqs (2)
    run_ok(&[
        "sweep",
        "examples/delta-60.toml",
        "--frequency-method",
        "k",
        "--mach",
        "0.6:2.0:0.2",
        "--cg",
        "0.2:0.3:0.05",
        "--mu1",
        "50:450:200",
        "--derivatives",
        "-o",
        path(&out_path),
    ]);
    let text = std::fs::read_to_string(&out_path).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |n: &str| {
        header
            .iter()
            .position(|h| *h == n)
            .unwrap_or_else(|| panic!("{n}"))
    };
    // each column once, `--derivatives` included (issue 19: mu1, i_b, c_l
    // were repeated)
    let mut names = header.clone();
    names.sort_unstable();
    names.dedup();
    assert_eq!(names.len(), header.len(), "{header:?}");
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    // 8 Mach numbers × 3 c.g. × 3 μ₁, in order, the last axis fastest
    assert_eq!(rows.len(), 8 * 3 * 3);
    assert_eq!(rows[1][col("mu1")], "250.0");
    assert_eq!(rows[3][col("cg")], "0.25");
    assert_eq!(rows[9][col("mach")], "0.8");
    let mut meets_at_50 = 0;
    for r in &rows {
        assert_eq!(r.len(), header.len());
        assert_eq!(r[col("error")], "", "{r:?}");
        let cycles = row_agrees_with_eqs_2(r, &col);
        if r[col("mu1")] == "50.0" && cycles <= 1.0 {
            meets_at_50 += 1;
        }
    }
    // the note: the 60° delta's short period meets the standard at μ₁ = 50
    // at every Mach number (a phugoid may still grow: the verdict says so)
    assert_eq!(meets_at_50, 8 * 3);
}

#[test]
fn sweep_json_is_an_array_of_objects() {
    let dir = Scratch::new();
    let out_path = dir.path().join("sub/grid.json");
    run_ok(&[
        "sweep",
        "examples/delta-45.toml",
        "--mach",
        "0.5:2:0.5",
        "--sweep",
        "30:75:15",
        "-o",
        path(&out_path),
    ]);
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&out_path).unwrap()).unwrap();
    let a = v.as_array().unwrap();
    assert_eq!(a.len(), 4 * 4);
    assert_eq!(a[1]["sweep_deg"].as_f64(), Some(45.0));
    for p in a {
        assert!(p["stable"].is_boolean() || p["error"].is_string(), "{p}");
        // a divergent short period is an unstable aircraft (Routh, §4); an
        // unstable one may be its phugoid alone, with the short period
        // judged on its own (§8)
        if p["verdict"] == "divergent" {
            assert_eq!(p["stable"], false, "{p}");
        }
    }
    // the file is the user's to read
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let mode = std::fs::metadata(&out_path).unwrap().permissions().mode();
        assert_eq!(mode & 0o044, 0o044, "{mode:o}");
    }
}

#[test]
fn sweep_rejects_bad_ranges_with_status_2_and_writes_nothing() {
    let dir = Scratch::new();
    let out_path = dir.write("grid.csv", "an earlier result\n");
    for (args, expect) in [
        (vec!["--mach", "2:1:0.1"], "runs backwards"),
        (vec!["--mach", "1:2:0"], "step must be positive"),
        (vec!["--mach", "1:2"], "A:B:STEP"),
        (
            vec!["--mach", "1", "--cg", "x"],
            "--cg: `x` is not a finite number",
        ),
        (vec!["--mach", "1", "--sweep", "95"], "--sweep 95"),
        (vec!["--mach", "0:1e9:1"], "too many"),
    ] {
        let mut a = vec!["sweep", "examples/delta-60.toml"];
        a.extend(args);
        a.extend(["-o", path(&out_path)]);
        let err = stderr(&run_err(&a, 2));
        assert!(err.contains(expect), "{a:?}: {err}");
    }
    let a = [
        "sweep",
        "examples/delta-60.toml",
        "--mach",
        "1",
        "-o",
        "grid.txt",
    ];
    assert!(stderr(&run_err(&a, 2)).contains(".csv or .json"));
    assert_eq!(
        std::fs::read_to_string(&out_path).unwrap(),
        "an earlier result\n"
    );
}

/// The entries of `dir` whose names begin with `prefix`.
fn entries_named(dir: &std::path::Path, prefix: &str) -> Vec<std::path::PathBuf> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| {
            p.file_name()
                .and_then(|n| n.to_str())
                .is_some_and(|n| n.starts_with(prefix))
        })
        .collect()
}

/// Makes `path` look `secs` seconds old.
fn age(path: &std::path::Path, secs: u64) {
    let then = std::time::SystemTime::now() - std::time::Duration::from_secs(secs);
    std::fs::File::open(path)
        .unwrap()
        .set_modified(then)
        .unwrap();
}

#[test]
fn a_killed_sweep_leaves_no_half_written_file() {
    let dir = Scratch::new();
    let out_path = dir.path().join("big.csv");
    let mut child = bin()
        // 1.5 million points: seconds of writing to be killed in, and
        // about 0.7 GB if it ran to the end (a sweep the disk cannot
        // hold is refused before it starts)
        .args(["sweep", "examples/delta-60.toml", "--mach", "0.5:2:0.0001"])
        // the quasi-steady fairing: the default iterates every point through
        // the lattice, and this is about the file, not the model
        .args(["--damping", "faired-slender"])
        .args(["--cg", "0.2:0.3:0.001", "-o"])
        .arg(&out_path)
        .stderr(std::process::Stdio::null())
        .spawn()
        .expect("run");
    // wait until the sweep has written rows (not only the header) into its
    // temporary file, then kill it
    let header = 200;
    let writing = wait_while_running(&mut child, || {
        entries_named(dir.path(), ".delta-stability-")
            .iter()
            .any(|p| std::fs::metadata(p).is_ok_and(|m| m.len() > header))
    });
    child.kill().unwrap();
    let status = child.wait().unwrap();
    assert!(writing, "the sweep never wrote into a temporary file");
    assert!(
        !status.success(),
        "a 1.5-million-point sweep finished early?"
    );
    assert!(!out_path.exists(), "a half-written file at the target");
    let stale = entries_named(dir.path(), ".delta-stability-");
    assert_eq!(stale.len(), 1, "{stale:?}");

    // A later sweep into the same directory removes the dead run's stale
    // file, and nothing else: not a live process's, not the user's files.
    age(&stale[0], 3600);
    let live = dir.write(
        &format!(".delta-stability-{}-abcdef", std::process::id()),
        "live",
    );
    age(&live, 3600);
    let users = dir.write(".delta-stability-notes", "mine");
    age(&users, 3600);
    let small = dir.path().join("small.csv");
    run_ok(&[
        "sweep",
        "examples/delta-60.toml",
        "--mach",
        "1",
        "-o",
        path(&small),
    ]);
    assert!(small.exists());
    assert!(
        !stale[0].exists(),
        "the stale temporary file is still there"
    );
    assert!(live.exists() && users.exists());
}

/// A sweep reuses the derivatives across μ₁; each point must still be the
/// design point `analyze` computes on its own.
#[test]
fn sweep_points_are_those_analyze_computes_alone() {
    let dir = Scratch::new();
    let base = common::example("delta-60.toml");
    let heavy = base.replace("mu1 = 50.0", "mu1 = 450.0");
    assert_ne!(heavy, base);
    let cfg = dir.write("heavy.toml", heavy);
    let csv = dir.path().join("grid.csv");
    run_ok(&[
        "sweep",
        "examples/delta-60.toml",
        "--mach",
        "0.9:1.5:0.3",
        "--mu1",
        "50:450:400",
        "-o",
        path(&csv),
    ]);
    let text = std::fs::read_to_string(&csv).unwrap();
    let rows: Vec<Vec<String>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(String::from).collect())
        .collect();
    assert_eq!(rows.len(), 3 * 2);
    for (k, mach) in ["0.9", "1.2", "1.5"].iter().enumerate() {
        let row = &rows[2 * k + 1];
        assert_eq!((row[0].as_str(), row[3].as_str()), (*mach, "450.0"));
        let v = json(&run_ok(&["analyze", path(&cfg), "--mach", mach, "--json"]));
        let sp = v["modes"]
            .as_array()
            .unwrap()
            .iter()
            .find(|m| m["name"] == "short_period")
            .unwrap();
        // the default faired model iterates ω̄ through the lifting surface
        // at every Mach number: a sweep interpolates the lattice in its
        // frequency table and the Mach box in ω̄ and in Mach number
        // (`lifting_surface::mach_table`, within 2.5·10⁻³ of C_Lα of the
        // direct solves), `analyze` solves at each iterate
        let tol = if *mach == "0.9" { 1e-5 } else { 2e-3 };
        for (col, key) in [(7, "re"), (8, "im")] {
            let ours: f64 = row[col].parse().unwrap();
            let alone = sp[key].as_f64().unwrap();
            assert!(
                (ours - alone).abs() <= tol * alone.abs(),
                "M {mach} {key}: {ours} vs {alone}"
            );
        }
    }
}

#[test]
fn closed_choices_are_listed_in_help_from_the_library() {
    let help = common::stdout(&run_ok(&["analyze", "--help"]));
    for t in stability_core::aerodynamics::damping::Theory::ALL {
        assert!(
            help.contains(&format!("- {}:", t.name())),
            "{}\n{help}",
            t.name()
        );
        assert!(help.contains(t.equations()), "{}", t.equations());
    }
    assert!(help.contains("- faired:"), "{help}");
    let help = common::stdout(&run_ok(&["convert", "--help"]));
    for n in stability_core::data::notation::Notation::all() {
        assert!(help.contains(&format!("- {}:", n.name())), "{}", n.name());
    }
    assert!(
        help.contains("- avl:") && help.contains("read only"),
        "{help}"
    );
    let help = common::stdout(&run_ok(&["response", "--help"]));
    assert!(
        help.contains("- step:") && help.contains("- initial:"),
        "{help}"
    );
    // avl is read, never written
    let out = run_err(
        &[
            "convert",
            "--from",
            "avl",
            "--to",
            "avl",
            "examples/avl-tailless-delta.toml",
        ],
        2,
    );
    assert!(stderr(&out).contains("'avl'"), "{}", stderr(&out));
}

/// Issue 20: no output says the standard is met for a design point with a
/// root that grows. The Mirage-class 60° delta at its physical flight
/// condition, swept over M 0.9–1.1 and the c.g. range: wherever the
/// eigenvalues of eqs (2) (independent of the quartic and its solver) have
/// a positive real part, the sweep's verdict is `divergent`, and `analyze`
/// says DIVERGENT on its page, `divergent` in its JSON (top-level
/// `verdict.overall` and `criteria.verdict`), and never "met".
#[test]
fn no_output_says_met_where_a_root_grows() {
    let dir = Scratch::new();
    let out_path = dir.path().join("mirage.csv");
    let config = "examples/delta-60-physical.toml";
    // the k-method: the roots are those of the derivative columns (by
    // default, the p-method's, each at its own frequency)
    run_ok(&[
        "sweep",
        config,
        "--frequency-method",
        "k",
        "--mach",
        "0.9:1.1:0.05",
        "--cg",
        "0.15:0.45:0.05",
        "--derivatives",
        "-o",
        path(&out_path),
    ]);
    let text = std::fs::read_to_string(&out_path).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |n: &str| header.iter().position(|h| *h == n).unwrap();
    let mut divergent = Vec::new();
    for line in lines {
        let r: Vec<&str> = line.split(',').collect();
        let d: [f64; 15] = std::array::from_fn(|k| {
            let name = stability_core::Derivatives::QUARTIC_INPUTS[k];
            r[col(name)].parse().unwrap()
        });
        let grows = eigenvalues_of_eqs_2(&d).iter().any(|z| z.re > 0.0);
        let verdict = r[col("verdict")];
        assert_eq!(verdict == "divergent", grows, "{line}");
        if grows {
            divergent.push((r[col("mach")].to_string(), r[col("cg")].to_string()));
        }
    }
    assert!(
        divergent.len() >= 5,
        "the c.g. range reaches divergence: {divergent:?}"
    );
    for (mach, cg) in divergent.iter().step_by(3) {
        let args = [
            "analyze",
            config,
            "--frequency-method",
            "k",
            "--mach",
            mach,
            "--cg",
            cg,
        ];
        let page = common::stdout(&run_ok(&args));
        assert!(page.contains("Verdict (every root): DIVERGENT"), "{page}");
        assert!(
            !page.contains("met:") && !page.contains("meets the standard"),
            "{page}"
        );
        let mut a = args.to_vec();
        a.push("--json");
        let v = json(&run_ok(&a));
        assert_eq!(v["verdict"]["overall"], "divergent", "M {mach}, h {cg}");
        assert_eq!(v["criteria"]["verdict"], "divergent");
        assert_eq!(v["criteria"]["one_cycle_standard_met"], false);
        assert!(
            v["verdict"]["reasons"][0]
                .as_str()
                .unwrap()
                .contains("grows")
        );
    }
}

/// The 60° delta at M = 0.9 (slender fairing) with m_q + e, e uniform on
/// [0, 2.2], and `extra` appended.
fn uncertain_config(extra: &str) -> String {
    format!(
        "[planform]\nsweep = 60.0\nroot_chord = 10.0\n\n[flight]\nmach = 0.9\ncg = 0.25\nmu1 = 50.0\ni_b = 0.08\ncl_m2 = 0.05\n\n\
         [model]\ndamping = \"faired-slender\"\n\n[uncertainty.m_q]\nerror = \"additive\"\ndist = \"uniform\"\nlow = 0.0\nhigh = 2.2\n{extra}"
    )
}

/// The additive error on m_q at which the §8 verdict changes, by bisection
/// on the library's analysis of the config's design point.
fn m_q_flip() -> f64 {
    use stability_core::analysis::Analysis;
    let case = stability_core::design::case::Case {
        damping: stability_core::design::case::DampingModel::FairedSlender,
        ..stability_core::design::study::report_wing(60.0, 0.9)
    };
    let d = stability_core::design::case::evaluate(&case)
        .unwrap()
        .derivatives;
    let met = |e: f64| {
        let d = stability_core::Derivatives {
            m_q: d.m_q + e,
            ..d
        };
        Analysis::of(&d).unwrap().verdict.is_met()
    };
    let (mut lo, mut hi) = (0.0, 2.2);
    assert!(met(lo) && !met(hi));
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if met(mid) { lo = mid } else { hi = mid }
    }
    lo
}

#[test]
fn uncertainty_gives_the_probability_of_a_known_flip_and_writes_csv_and_json() {
    let dir = Scratch::new();
    let cfg = dir.write("u.toml", uncertain_config(""));
    let csv = dir.path().join("u.csv");
    let args = [
        "uncertainty",
        path(&cfg),
        "--mach",
        "0.9",
        "--samples",
        "8000",
        "--sobol",
        "--seed",
        "4",
    ];
    let v = json(&run_ok(
        &[&args[..], &["--json", "-o", path(&csv)]].concat(),
    ));
    let r = &v["results"][0];
    let p = r["standard_met"]["p"].as_f64().unwrap();
    let expected = m_q_flip() / 2.2;
    let se = (expected * (1.0 - expected) / 8000.0).sqrt();
    assert!((p - expected).abs() < 3.0 * se, "{p} vs {expected}");
    let (lo, hi) = (
        r["standard_met"]["low"].as_f64().unwrap(),
        r["standard_met"]["high"].as_f64().unwrap(),
    );
    assert!(lo < p && p < hi && hi - lo < 0.03, "{lo} {hi}");
    assert_eq!(r["sobol"]["factors"][0], "m_q");
    let s1 = r["sobol"]["margin"][0]["first"].as_f64().unwrap();
    let se1 = r["sobol"]["margin"][0]["first_se"].as_f64().unwrap();
    assert!((s1 - 1.0).abs() < 3.0 * se1, "S1 = {s1} ± {se1}");
    // the CSV has the same numbers, and the same seed the same bits
    let text = std::fs::read_to_string(&csv).unwrap();
    assert!(text.starts_with("mach,quantity,value,low,high\n"), "{text}");
    let row = text
        .lines()
        .find(|l| l.starts_with("0.9,p_standard_met,"))
        .unwrap();
    let got: f64 = row.split(',').nth(2).unwrap().parse().unwrap();
    assert!((got - p).abs() < 1e-11, "{row}");
    let again = json(&run_ok(&[&args[..], &["--json"]].concat()));
    assert_eq!(again["results"], v["results"]);
    // the page says the same
    let page = common::stdout(&run_ok(&args));
    assert!(
        page.contains("P(§8 met)") && page.contains("Sobol indices"),
        "{page}"
    );
}

#[test]
fn uncertainty_rejects_bad_tables_at_their_line_and_field() {
    let dir = Scratch::new();
    let cases = [
        (
            "[uncertainty.m_qq]\ndist = \"normal\"\nsd = 0.1\n",
            ":20:1: [uncertainty.m_qq]: `m_qq` cannot be uncertain; did you mean `m_q`?",
        ),
        (
            "[uncertainty.i_b]\ndist = \"normal\"\nsd = -0.1\n",
            ":20:1: [uncertainty.i_b] sd: sd must not be negative",
        ),
        (
            "[uncertainty.i_b]\ndist = \"gauss\"\nsd = 0.1\n",
            "[uncertainty.i_b] dist: `gauss` is not a distribution",
        ),
        (
            "[uncertainty.mass]\ndist = \"normal\"\nsd = 0.1\n",
            "[uncertainty.mass]: `mass` is a quantity of the physical flight condition",
        ),
        (
            "[uncertainty]\ncorrelation = [{ between = [\"m_q\", \"cg\"], rho = 0.5 }]\n",
            "[uncertainty] correlation: the correlation names `cg`, which is not uncertain",
        ),
        (
            "[uncertainty.model]\ndamping = [\"faired\", \"slendr\"]\n",
            "[uncertainty.model]: unknown damping model `slendr`; did you mean `slender`?",
        ),
        (
            "[uncertainty.model]\ndamping = [\"faired\"]\nweights = [1.0, 2.0]\n",
            "give one weight per damping model",
        ),
    ];
    for (extra, message) in cases {
        let cfg = dir.write("bad.toml", uncertain_config(extra));
        let out = run_err(
            &[
                "uncertainty",
                path(&cfg),
                "--mach",
                "0.9",
                "--samples",
                "10",
            ],
            2,
        );
        let err = stderr(&out);
        assert!(err.contains(message), "{extra}: {err}");
    }
    let plain = common::example("delta-60.toml");
    let cfg = dir.write("plain.toml", plain);
    let err = stderr(&run_err(&["uncertainty", path(&cfg), "--mach", "0.9"], 2));
    assert!(err.contains("no [uncertainty] table"), "{err}");
}

#[test]
fn uncertainty_of_a_physical_condition_without_spread_is_analyzes_verdict() {
    // altitude, mass and I_y uncertain with no spread: every sample is the
    // design point, so the probabilities are 0 or 1 as analyze says, and
    // every quantile its ζ
    let dir = Scratch::new();
    let text = common::example("delta-60-physical.toml")
        + "\n[uncertainty.altitude]\ndist = \"normal\"\nsd = 0.0\n\
           [uncertainty.mass]\nerror = \"multiplicative\"\ndist = \"uniform\"\nlow = 1.0\nhigh = 1.0000000001\n\
           [uncertainty.I_y]\ndist = \"triangular\"\nlow = 69999.99999\nmode = 70000.0\nhigh = 70000.00001\n";
    let cfg = dir.write("p.toml", text);
    // uncertainty judges each sample by its quartic (the k-method)
    let a = json(&run_ok(&[
        "analyze",
        path(&cfg),
        "--json",
        "--frequency-method",
        "k",
    ]));
    let u = json(&run_ok(&[
        "uncertainty",
        path(&cfg),
        "--mach",
        "0.9",
        "--samples",
        "300",
        "--json",
    ]));
    let r = &u["results"][0];
    let met = a["verdict"]["overall"] == "meets";
    assert_eq!(r["meets"]["p"].as_f64(), Some(if met { 1.0 } else { 0.0 }));
    let zeta = a["modes"][0]["damping_ratio"].as_f64().unwrap();
    for q in r["damping_ratio"]["values"].as_array().unwrap() {
        assert!(
            (q.as_f64().unwrap() - zeta).abs() < 1e-6 * zeta,
            "{q} vs {zeta}"
        );
    }
    // the phugoid's level is judged (τ in seconds is known)
    assert_eq!(
        r["phugoid_level"]["not_assessed"]["count"].as_u64(),
        Some(0)
    );
}

/// The neutral point and static margin (issue 20, item 6): `analyze`'s
/// page and JSON give h_n = the aerodynamic centre H₀ its aerodynamics
/// report (m_w = (h − H₀)(a + C_D), eq 14) and the margin h_n − h in % of
/// the M.A.C.; the sweep's columns are the same numbers, beside K_n.
#[test]
fn the_neutral_point_and_static_margin_are_on_the_page_the_json_and_the_sweep() {
    let dir = Scratch::new();
    let csv = dir.path().join("cg.csv");
    run_ok(&[
        "sweep",
        "examples/delta-60.toml",
        "--mach",
        "0.8",
        "--cg",
        "0.2,0.6",
        "-o",
        path(&csv),
    ]);
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |n: &str| header.iter().position(|h| *h == n).expect(n);
    for line in lines {
        let r: Vec<&str> = line.split(',').collect();
        let cell = |n: &str| r[col(n)].parse::<f64>().unwrap();
        let cg = r[col("cg")];
        let v = json(&run_ok(&[
            "analyze",
            "examples/delta-60.toml",
            "--mach",
            "0.8",
            "--cg",
            cg,
            "--json",
        ]));
        let h0 = v["aerodynamics"]["aerodynamic_centre"]["value"]
            .as_f64()
            .unwrap();
        let m = &v["criteria"]["margins"];
        let h_n = m["neutral_point"].as_f64().unwrap();
        let h: f64 = cg.parse().unwrap();
        assert!((h_n - h0).abs() < 1e-12, "{h_n} vs H₀ {h0}");
        let pct = m["static_margin_pct"].as_f64().unwrap();
        assert!((pct - 100.0 * (h0 - h)).abs() < 1e-10, "{pct}");
        assert!((cell("neutral_point") - h_n).abs() < 1e-12);
        assert!((cell("static_margin_pct") - pct).abs() < 1e-10);
        let k_n = m["static_margin"].as_f64().unwrap();
        assert!((cell("k_n") - k_n).abs() <= 1e-6 * k_n.abs(), "{k_n}");
        // a c.g. behind the neutral point is statically unstable: K_n < 0
        // there as well (the Mach-number term is small at M = 0.8)
        assert_eq!(pct > 0.0, k_n > 0.0, "h {h}");
    }
    // the note's fairing at M = 1.2: linear theory's exact aerodynamic
    // centre of a true delta, two thirds of the root chord (H₀ = ½)
    let page = common::stdout(&run_ok(&[
        "analyze",
        "examples/delta-60.toml",
        "--cg",
        "0.3",
        "--damping",
        "faired-theories",
    ]));
    assert!(
        page.contains("neutral point h_n = 0.5000")
            && page.contains("static margin h_n − h = 20.00 % M.A.C."),
        "{page}"
    );
}

/// The physical flight condition's axes (issue 20, item 6): each point of
/// a sweep over altitude, mass and I_y is the design point `analyze`
/// computes from the config edited by hand to that altitude, mass and I_y
/// (μ₁, i_B, C_L, τ, V and the short period); at sea level μ₁ is
/// m/(½ρ₀Sc̄) with the standard atmosphere's ρ₀ = 1.2250 kg/m³.
#[test]
fn sweeps_over_altitude_mass_and_inertia_are_analyze_on_edited_configs() {
    let dir = Scratch::new();
    let base = common::example("delta-60-physical.toml");
    let csv = dir.path().join("physical.csv");
    run_ok(&[
        "sweep",
        "examples/delta-60-physical.toml",
        "--mach",
        "0.9,1.5",
        "--altitude",
        "0:6000:6000",
        "--mass",
        "10000,14000",
        "--iy",
        "50000,70000",
        "--damping",
        "faired-slender",
        "-o",
        path(&csv),
    ]);
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |n: &str| header.iter().position(|h| *h == n).expect(n);
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 2 * 2 * 2 * 2);
    // S = 83.138 m², c̄ = 8 m (12 m root chord, 60°): the file's comment
    let (s, c) = (0.5 * 12.0 * 24.0 * 30f64.to_radians().tan(), 8.0);
    for r in &rows {
        let cell = |n: &str| r[col(n)].parse::<f64>().unwrap();
        assert_eq!(r[col("error")], "", "{r:?}");
        let (alt, mass, i_y) = (r[col("altitude")], r[col("mass")], r[col("I_y")]);
        let edited = base
            .replace("altitude = 11000.0", &format!("altitude = {alt}"))
            .replace("mass = 12000.0", &format!("mass = {mass}"))
            .replace("I_y = 70000.0", &format!("I_y = {i_y}"));
        let cfg = dir.write("edited.toml", edited);
        let v = json(&run_ok(&[
            "analyze",
            path(&cfg),
            "--mach",
            r[col("mach")],
            "--damping",
            "faired-slender",
            "--json",
        ]));
        let f = &v["flight"];
        assert_eq!(
            f["pressure_altitude_m"].as_f64(),
            Some(alt.parse().unwrap())
        );
        let close = |a: f64, b: &serde_json::Value, what: &str| {
            let b = b.as_f64().unwrap();
            assert!((a - b).abs() <= 1e-12 * b.abs(), "{what}: {a} vs {b} {r:?}");
        };
        close(cell("mu1"), &f["mu1"], "mu1");
        close(cell("i_b"), &f["i_b"], "i_b");
        close(cell("c_l"), &f["c_l"], "c_l");
        close(cell("tau_s"), &f["tau_s"], "tau_s");
        close(cell("v_m_s"), &f["speed_m_s"], "V");
        let sp = v["modes"]
            .as_array()
            .unwrap()
            .iter()
            .find(|m| m["name"] == "short_period")
            .unwrap();
        close(cell("sp_re"), &sp["re"], "sp re");
        close(cell("sp_im"), &sp["im"], "sp im");
        if alt == "0.0" {
            // ρ₀ = 1.2250 kg/m³ as the standard tables print it (5 figures)
            let mu1 = cell("mass") / (0.5 * 1.225 * s * c);
            assert!((cell("mu1") - mu1).abs() < 1e-5 * mu1, "{mu1}");
            assert!((cell("i_b") - cell("I_y") / (cell("mass") * c * c)).abs() < 1e-15);
        }
    }
}

/// The physical axes need a physical flight condition, and values it can
/// have: each refusal names the option and says why, and nothing is
/// written.
#[test]
fn physical_axes_are_refused_where_they_mean_nothing() {
    let dir = Scratch::new();
    let out = dir.path().join("x.csv");
    let geometric = dir.write(
        "geometric.toml",
        common::example("delta-60-physical.toml").replace("altitude = ", "geometric_altitude = "),
    );
    for (cfg, args, expect) in [
        (
            "examples/delta-60.toml",
            vec!["--mass", "1000"],
            "--mass: the config's flight condition is non-dimensional",
        ),
        (
            "examples/delta-60.toml",
            vec!["--altitude", "0"],
            "vary μ₁ and i_B instead",
        ),
        (
            "examples/delta-60-physical.toml",
            vec!["--mu1", "50"],
            "--mu1: the config's flight condition is physical",
        ),
        (
            "examples/delta-60-physical.toml",
            vec!["--altitude", "90000"],
            "--altitude 90000: the altitude",
        ),
        (
            "examples/delta-60-physical.toml",
            vec!["--mass", "0,1000"],
            "--mass 0: the mass must be positive",
        ),
        (
            "examples/delta-60-physical.toml",
            vec!["--iy", "-1"],
            "--iy -1:",
        ),
        // 10⁶ t at 11 km: C_L·M² = W/(½ρa²S) ≈ 7.5e3, beyond the 1e3 a
        // config may give
        (
            "examples/delta-60-physical.toml",
            vec!["--mass", "1e4,1e9"],
            "C_L·M² = W/(½ρa²S) =",
        ),
        (
            path(&geometric),
            vec!["--altitude", "1000"],
            "--altitude: the `altitude` axis varies the pressure altitude",
        ),
    ] {
        let mut a = vec!["sweep", cfg, "--mach", "0.9"];
        a.extend(args);
        a.extend(["-o", path(&out)]);
        let err = stderr(&run_err(&a, 2));
        assert!(err.contains(expect), "{a:?}: {err}");
        assert!(!out.exists());
    }
}

/// The MIL-F-8785C class (issue 20, item 7): `--class`, else the config's
/// `[aircraft] class`, else none — and then Category C of the short-period
/// frequency requirement (the only limits that depend on the class, Fig 3)
/// is not assessed while A and B are, as with any class. Each choice is
/// printed; a class that is not one is refused at its line.
#[test]
fn the_class_is_given_or_the_configs_or_category_c_is_not_assessed() {
    let dir = Scratch::new();
    let stated = "examples/delta-60-physical.toml";
    let text = common::example("delta-60-physical.toml");
    assert!(text.contains("class = \"IV\""));
    let none = dir.write("none.toml", text.replace("class = \"IV\"", ""));
    let freq = |args: &[&str]| {
        let mut a = vec!["analyze"];
        a.extend(args);
        let page = common::stdout(&run_ok(&a));
        a.push("--json");
        let v = json(&run_ok(&a))["short_period_frequency"].clone();
        let line = page
            .lines()
            .find(|l| l.contains("short-period frequency (§3.2.2.1.1)"))
            .expect("the requirement's line")
            .to_string();
        (v, line)
    };
    let (config, line) = freq(&[stated]);
    assert_eq!(config["class"], "IV");
    assert!(
        line.contains(
            "Class IV (high manoeuvrability (fighters, attack)), from the config's [aircraft] class"
        ),
        "{line}"
    );
    let (given, line) = freq(&[stated, "--class", "III"]);
    assert_eq!(given["class"], "III");
    assert!(
        line.contains("Class III") && line.contains("given by --class"),
        "{line}"
    );
    let (absent, line) = freq(&[path(&none)]);
    assert!(
        absent["class"].is_null() && absent["C"].is_null(),
        "{absent}"
    );
    assert!(
        line.contains("C not assessed (class not given")
            && line.contains("give --class or [aircraft] class"),
        "{line}"
    );
    // Categories A and B are the class's own whatever it is
    for v in [&given, &absent] {
        assert_eq!((&v["A"], &v["B"]), (&config["A"], &config["B"]));
        assert_eq!(v["cap"], config["cap"]);
    }
    // ω_sp = 8.14 rad/s at n/α = 27.2 g/rad: CAP 2.44 lies in Category C's
    // Level 1 band (0.16–3.6) above every class's floors
    assert_eq!(
        (&config["C"], &given["C"]),
        (&"Level 1".into(), &"Level 1".into())
    );
    let bad = dir.write("bad.toml", text.replace("class = \"IV\"", "class = \"iv\""));
    let err = stderr(&run_err(&["analyze", path(&bad)], 2));
    assert!(
        err.contains("[aircraft] class") && err.contains("did you mean `IV`"),
        "{err}"
    );
}

/// The sweep's columns come from one table (issue 30, item 5): the CSV's
/// header, the JSON objects' keys and the list after `sweep --help` name
/// the same columns in the same order, at a physical flight condition
/// with the derivatives (every column but the one `c_l` it gives once) and
/// without either.
#[test]
fn the_sweeps_header_json_keys_and_help_list_the_same_columns() {
    let dir = Scratch::new();
    let help = common::stdout(&run_ok(&["sweep", "--help"]));
    let listed: Vec<&str> = help
        .split_once("Columns (name [unit]: meaning):\n")
        .expect("the column list")
        .1
        .lines()
        .filter_map(|l| l.strip_prefix("  "))
        .filter_map(|l| l.split([' ', ':']).next())
        .collect();
    let runs: [&[&str]; 2] = [
        &["examples/delta-60-physical.toml", "--derivatives"],
        &["examples/delta-60.toml"],
    ];
    for args in runs {
        let mut header = Vec::new();
        for ext in ["csv", "json"] {
            let out = dir.path().join(format!("columns.{ext}"));
            let mut a = vec!["sweep", args[0], "--mach", "0.8,1.2"];
            a.extend(&args[1..]);
            a.extend(["--damping", "faired-slender", "-o", path(&out)]);
            run_ok(&a);
            let text = std::fs::read_to_string(&out).unwrap();
            if ext == "csv" {
                header = text
                    .lines()
                    .next()
                    .unwrap()
                    .split(',')
                    .map(String::from)
                    .collect();
                continue;
            }
            // the first object's keys in the file's order (a point with a
            // result has every column but `error`; no value has a comma)
            let v: serde_json::Value = serde_json::from_str(&text).unwrap();
            assert!(v[0].get("error").is_none() && v[0]["verdict"].is_string());
            let first = text.lines().nth(1).unwrap();
            let keys: Vec<&str> = first
                .split(',')
                .filter_map(|kv| kv.split('"').nth(1))
                .collect();
            assert_eq!(keys, header[..header.len() - 1]);
        }
        assert_eq!(header.last().map(String::as_str), Some("error"));
        // the help's list in its order, with the columns of other rows
        let mut at = listed.iter();
        for name in &header {
            assert!(at.any(|l| l == name), "{name} out of order in {listed:?}");
        }
    }
}
