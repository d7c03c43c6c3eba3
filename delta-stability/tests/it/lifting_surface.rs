//! The lifting surface from the command line: `--damping lifting-surface`,
//! `lifting-surface-frequency`, `--aero lifting-surface`, `--omega-bar`, on
//! `analyze`, in `[model]`, and on `sweep` — each value against the library
//! computing the same design point, and the sweep's rows against `analyze`.

use crate::common;

use common::{Scratch, json, path, run_err, run_ok, stderr, stdout};
use stability_core::aerodynamics::damping::Theory;
use stability_core::aerodynamics::models::aero::{AeroModel, AeroModelName};
use stability_core::design::case::{Case, DampingModel, evaluate};
use stability_core::design::study::report_wing;

/// examples/delta-45.toml's design point at `mach`, as the library sees it.
fn delta_45(mach: f64, damping: Theory, aero: AeroModelName) -> Case {
    // the note's Mach box solutions, as the command line has them
    let _ = stability_study::study::preload();
    Case {
        planform: stability_core::geometry::Planform::new(
            45f64.to_radians(),
            0.0,
            stability_core::geometry::Size::RootChord(10.0),
        )
        .unwrap(),
        damping: DampingModel::Theory(damping),
        aero: AeroModel::default().with_name(aero),
        ..report_wing(45.0, mach)
    }
}

/// `a` within `tol` of `b`, relative, and never closer than serde_json
/// reads numbers (its default float parser may be one unit in the last
/// place off): the same number, printed by the program and read back.
fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol.max(1e-15) * b.abs()
}

fn short_period(v: &serde_json::Value) -> Option<&serde_json::Value> {
    v["modes"]
        .as_array()
        .unwrap()
        .iter()
        .find(|m| m["name"] == "short_period")
}

#[test]
fn analyze_json_carries_the_lattices_derivatives_under_the_same_keys() {
    let out = run_ok(&[
        "analyze",
        "examples/delta-45.toml",
        "--mach",
        "0.5",
        "--damping",
        "lifting-surface",
        "--aero",
        "lifting-surface",
        "--json",
    ]);
    let v = json(&out);
    let r = evaluate(&delta_45(
        0.5,
        Theory::LiftingSurface,
        AeroModelName::LiftingSurface,
    ))
    .unwrap();
    let d = &v["derivatives"];
    let want = [
        ("z_q", r.derivatives.z_q),
        ("m_q", r.derivatives.m_q),
        ("z_wdot", r.derivatives.z_wdot),
        ("m_wdot", r.derivatives.m_wdot),
        ("z_w", r.derivatives.z_w),
        ("m_w", r.derivatives.m_w),
        ("x_u", r.derivatives.x_u),
        ("m_u", r.derivatives.m_u),
    ];
    for (key, value) in want {
        assert!(close(d[key].as_f64().unwrap(), value, 0.0), "{key}");
    }
    let a = &v["aerodynamics"];
    let c = &r.coefficients;
    assert!(close(
        a["lift_slope"]["d_mach"].as_f64().unwrap(),
        c.lift_slope.d_mach,
        0.0
    ));
    assert!(close(
        a["aerodynamic_centre"]["value"].as_f64().unwrap(),
        c.aerodynamic_centre.value,
        0.0
    ));
    assert_eq!(v["damping"]["theory"], "lifting-surface");
    assert_eq!(v["damping"]["equations"], "§7, doublet lattice, Mach box");
    assert_eq!(v["case"]["damping"], "lifting-surface");
    // the headline: slender-wing theory's two real roots there,
    // the lattice's oscillation
    let sp = short_period(&v).expect("an oscillatory short period");
    assert!(sp["re"].as_f64().unwrap() < 0.0);
    let slender = json(&run_ok(&[
        "analyze",
        "examples/delta-45.toml",
        "--mach",
        "0.5",
        "--damping",
        "faired-slender",
        "--json",
    ]));
    assert!(short_period(&slender).is_none());
}

#[test]
fn omega_bar_fixes_the_frequency_of_every_frequency_dependent_theory() {
    for theory in [
        Theory::LiftingSurface,
        Theory::LiftingSurfaceFrequency,
        Theory::TransonicFrequency,
    ] {
        let v = json(&run_ok(&[
            "analyze",
            "examples/delta-45.toml",
            "--mach",
            "0.8",
            "--damping",
            theory.name(),
            "--omega-bar",
            "0.3",
            "--json",
        ]));
        let mut c = delta_45(0.8, theory, AeroModelName::Default);
        c.omega_bar = Some(0.3);
        c.iterate_frequency = false;
        let r = evaluate(&c).unwrap();
        assert_eq!(
            v["derivatives"]["m_wdot"].as_f64(),
            Some(r.derivatives.m_wdot),
            "{theory}"
        );
        if theory.uses_frequency() {
            assert_eq!(v["damping"]["frequency"]["iterations"], 0);
            assert_eq!(v["damping"]["frequency"]["converged"].as_f64(), Some(0.3));
        } else {
            assert!(v["damping"]["frequency"].is_null());
        }
    }
    // the quasi-steady lattice differs from the one at ω̄ = 0.3
    let page = stdout(&run_ok(&[
        "analyze",
        "examples/delta-45.toml",
        "--mach",
        "0.8",
        "--damping",
        "lifting-surface",
    ]));
    assert!(page.contains("frequency parameter: quasi-steady"), "{page}");
    // and iterated, ω̄ ends at the short period's own
    let v = json(&run_ok(&[
        "analyze",
        "examples/delta-45.toml",
        "--mach",
        "0.8",
        "--damping",
        "lifting-surface-frequency",
        "--frequency-method",
        "k",
        "--json",
    ]));
    // (the k-method's roots are the quartic's at the converged ω̄)
    let f = &v["damping"]["frequency"];
    let sp = short_period(&v).unwrap();
    let own = sp["frequency_parameter"].as_f64().unwrap();
    assert_eq!(f["converged_ok"], true);
    assert!((f["converged"].as_f64().unwrap() - own).abs() < 1e-11 * own);
}

#[test]
fn what_does_not_apply_is_an_error_naming_the_flag_or_field() {
    let out = run_err(
        &[
            "analyze",
            "examples/delta-45.toml",
            "--damping",
            "faired-slender",
            "--omega-bar",
            "0.3",
        ],
        2,
    );
    let err = stderr(&out);
    assert!(
        err.contains("--omega-bar: the damping model `faired-slender` takes no frequency parameter")
            && err.contains(
                "the models that do: faired, faired-theories, transonic-frequency, lifting-surface, lifting-surface-frequency"
            ),
        "{err}"
    );
    // at M = 1 the sonic extrapolation needs ω̄ ≥ 0.3: the error says so
    let out = run_err(
        &[
            "analyze",
            "examples/delta-45.toml",
            "--damping",
            "lifting-surface",
            "--mach",
            "1.0",
        ],
        2,
    );
    let err = stderr(&out);
    assert!(err.contains("give --omega-bar 0.3 or more"), "{err}");
    // in a config: the field, with a suggestion for a misspelt model
    let cfg = common::example("delta-45.toml");
    let dir = Scratch::new();
    let p = dir.write(
        "c.toml",
        cfg.replace(
            "damping = \"faired\"",
            "damping = \"faired\"\naero = \"lifting-surfce\"",
        ),
    );
    let err = stderr(&run_err(&["analyze", path(&p)], 2));
    assert!(
        err.contains("[model] aero")
            && err.contains("did you mean `lifting-surface`")
            && err.contains("default, lifting-surface"),
        "{err}"
    );
    let p = dir.write(
        "d.toml",
        cfg.replace(
            "damping = \"faired\"",
            "damping = \"lifting-surface\"\naero = \"lifting-surface\"",
        )
        .replace("mach = 0.9", "mach = 3.5"),
    );
    let err = stderr(&run_err(&["analyze", path(&p)], 2));
    assert!(
        err.contains("d.toml:")
            && err.contains("[model] aero")
            && err.contains("cover 0 ≤ M ≤ 3, not M = 3.5"),
        "{err}"
    );
}

#[test]
fn the_config_names_the_models_too() {
    let cfg = common::example("delta-60.toml");
    let dir = Scratch::new();
    let p = dir.write(
        "c.toml",
        cfg.replace("[model]", "[model]\naero = \"lifting-surface\"")
            .replace("damping = \"faired\"", "damping = \"lifting-surface\"")
            .replace("mach = 1.2", "mach = 0.7"),
    );
    let from_config = json(&run_ok(&["analyze", path(&p), "--json"]));
    let from_flags = json(&run_ok(&[
        "analyze",
        "examples/delta-60.toml",
        "--mach",
        "0.7",
        "--damping",
        "lifting-surface",
        "--aero",
        "lifting-surface",
        "--json",
    ]));
    assert_eq!(from_config["derivatives"], from_flags["derivatives"]);
    assert_eq!(from_config["aerodynamics"], from_flags["aerodynamics"]);
}

/// (mach, sweep, cg, mu1, i_b, sp_re, sp_im) of each row of a sweep's CSV.
fn rows(csv: &std::path::Path) -> Vec<Vec<String>> {
    std::fs::read_to_string(csv)
        .unwrap()
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(String::from).collect())
        .collect()
}

#[test]
fn sweep_rows_are_what_analyze_gives_each_point() {
    let dir = Scratch::new();
    for (damping, tol) in [
        ("lifting-surface", 0.0),
        ("lifting-surface-frequency", 2e-4),
    ] {
        let csv = dir.path().join(format!("{damping}.csv"));
        run_ok(&[
            "sweep",
            "examples/delta-45.toml",
            "--mach",
            "0.5:0.8:0.3",
            "--mu1",
            "50:250:200",
            "--damping",
            damping,
            "--aero",
            "lifting-surface",
            "-o",
            path(&csv),
        ]);
        let rows = rows(&csv);
        assert_eq!(rows.len(), 4);
        for row in &rows {
            let cfg = common::example("delta-45.toml")
                .replace("mu1 = 50.0", &format!("mu1 = {}", row[3]));
            let p = dir.write("point.toml", cfg);
            let v = json(&run_ok(&[
                "analyze",
                path(&p),
                "--mach",
                &row[0],
                "--cg",
                &row[2],
                "--damping",
                damping,
                "--aero",
                "lifting-surface",
                "--json",
            ]));
            let sp = short_period(&v).unwrap();
            for (col, key) in [(7, "re"), (8, "im")] {
                let ours: f64 = row[col].parse().unwrap();
                let alone = sp[key].as_f64().unwrap();
                assert!(
                    close(ours, alone, tol),
                    "{damping} M {} h {} μ₁ {} {key}: {ours} vs {alone}",
                    row[0],
                    row[2],
                    row[3]
                );
            }
        }
    }
}

#[test]
fn a_sweep_at_a_fixed_frequency_is_analyze_at_it() {
    let dir = Scratch::new();
    let csv = dir.path().join("fixed.csv");
    run_ok(&[
        "sweep",
        "examples/delta-45.toml",
        "--mach",
        "0.6",
        "--damping",
        "lifting-surface-frequency",
        "--omega-bar",
        "0.3",
        "--derivatives",
        "-o",
        path(&csv),
    ]);
    let row = &rows(&csv)[0];
    let v = json(&run_ok(&[
        "analyze",
        "examples/delta-45.toml",
        "--mach",
        "0.6",
        "--damping",
        "lifting-surface-frequency",
        "--omega-bar",
        "0.3",
        "--json",
    ]));
    // m_wdot, found by its column's name
    let header = std::fs::read_to_string(&csv).unwrap();
    let at = header
        .lines()
        .next()
        .unwrap()
        .split(',')
        .position(|c| c == "m_wdot")
        .expect("an m_wdot column");
    let m_wdot: f64 = row[at].parse().unwrap();
    assert!(close(
        m_wdot,
        v["derivatives"]["m_wdot"].as_f64().unwrap(),
        0.0
    ));
    let out = run_err(
        &[
            "sweep",
            "examples/delta-45.toml",
            "--mach",
            "0.6",
            "--damping",
            "slender",
            "--omega-bar",
            "0.3",
            "-o",
            path(&csv),
        ],
        2,
    );
    assert!(stderr(&out).contains("--omega-bar: the damping model `slender`"));
}

#[test]
fn at_mach_one_the_lattices_aerodynamic_model_is_the_sonic_point() {
    // between M = 0.99 and the Mach box's first Mach number the lift slope
    // and aerodynamic centre are joined through linear theory's sonic
    // point, slender-wing theory: at M = 1 on the 45° delta (A = 4)
    // C_Lα = πA/2 = 2π and H₀ = ½ exactly; the sweep's rows have no error
    let out = stdout(&run_ok(&[
        "analyze",
        "examples/delta-45.toml",
        "--mach",
        "1.0",
        "--aero",
        "lifting-surface",
        "--json",
    ]));
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let aero = &v["aerodynamics"];
    let a = aero["lift_slope"]["value"].as_f64().unwrap();
    let h0 = aero["aerodynamic_centre"]["value"].as_f64().unwrap();
    assert!(
        (a / (2.0 * std::f64::consts::PI) - 1.0).abs() < 1e-12,
        "{a}"
    );
    assert!((h0 - 0.5).abs() < 1e-12, "{h0}");
    assert_eq!(aero["origin"]["lift_slope"], "lifting-surface");
    let dir = Scratch::new();
    let csv = dir.path().join("transonic.csv");
    run_ok(&[
        "sweep",
        "examples/delta-45.toml",
        "--mach",
        "0.9:1.1:0.1",
        "--aero",
        "lifting-surface",
        "-o",
        path(&csv),
    ]);
    let text = std::fs::read_to_string(&csv).unwrap();
    let lines: Vec<&str> = text.lines().skip(1).collect();
    assert_eq!(lines.len(), 3);
    for line in lines {
        assert!(line.ends_with(','), "{line}");
    }
}

#[test]
fn help_lists_the_models_from_the_library() {
    let help = stdout(&run_ok(&["analyze", "--help"]));
    for m in AeroModelName::ALL {
        assert!(
            help.contains(&format!("- {}:", m.name())),
            "{}\n{help}",
            m.name()
        );
    }
    assert!(help.contains("--omega-bar") && help.contains("lifting-surface-frequency"));
    let help = stdout(&run_ok(&["sweep", "--help"]));
    assert!(help.contains("--damping") && help.contains("--aero") && help.contains("--omega-bar"));
}

#[test]
fn above_mach_one_analyze_takes_the_mach_box() {
    // the command: the 45° delta at M = 1.5 (β cot Λ = 1.12, a
    // supersonic leading edge), ω̄ = 0.5; and --aero lifting-surface at
    // M = 2, whose lift slope is 4/β exactly
    let out = run_ok(&[
        "analyze",
        "examples/delta-45.toml",
        "--mach",
        "1.5",
        "--damping",
        "lifting-surface",
        "--omega-bar",
        "0.5",
        "--json",
    ]);
    let v = json(&out);
    let c = Case {
        omega_bar: Some(0.5),
        ..delta_45(1.5, Theory::LiftingSurface, AeroModelName::Default)
    };
    let r = evaluate(&c).unwrap();
    let d = &v["derivatives"];
    for (key, value) in [
        ("z_q", r.derivatives.z_q),
        ("m_q", r.derivatives.m_q),
        ("z_wdot", r.derivatives.z_wdot),
        ("m_wdot", r.derivatives.m_wdot),
    ] {
        assert!(close(d[key].as_f64().unwrap(), value, 0.0), "{key}");
    }
    let out = run_ok(&[
        "analyze",
        "examples/delta-45.toml",
        "--mach",
        "2",
        "--aero",
        "lifting-surface",
        "--json",
    ]);
    let v = json(&out);
    let cla = v["aerodynamics"]["lift_slope"]["value"].as_f64().unwrap();
    assert!((cla * 3f64.sqrt() / 4.0 - 1.0).abs() < 2e-3, "{cla}");
}
