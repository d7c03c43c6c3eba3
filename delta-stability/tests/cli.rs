//! The program as a user runs it: output, exit status and messages.

use stability_core::quartic::reference::eq6_by_hand;
use std::process::Command;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_delta-stability"))
}

fn root() -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

#[test]
fn quartic_json_has_the_coefficients_of_eq6() {
    let out = bin()
        .current_dir(root())
        .args(["quartic", "examples/tailless-delta-45.toml", "--json"])
        .output()
        .expect("run");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("one JSON object");
    // The example's values, through eq (6) typed by hand (corrected).
    let inputs = [
        -0.03, 0.25, 0.0, 0.0, -0.62, -3.2, -0.6, -1.5, 0.0, -0.55, -0.25, -0.6, 0.3, 50.0, 0.08,
    ];
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
    let out = bin()
        .current_dir(root())
        .args(["quartic", "examples/tailless-delta-45.toml"])
        .output()
        .expect("run");
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success());
    assert!(text.contains("A =       1.012000"), "{text}");
}

fn run_on(contents: &str) -> (i32, String) {
    let dir = tempfile::tempdir().expect("temp dir");
    let path = dir.path().join("case.toml");
    std::fs::write(&path, contents).expect("write");
    let out = bin().arg("quartic").arg(&path).output().expect("run");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn example() -> String {
    std::fs::read_to_string(root().join("examples/tailless-delta-45.toml")).expect("example")
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
            ex.replace("\"report\"", "\"avl\""),
            ":5:12: notation: unknown notation `avl`",
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
    let out = bin().args(["quartic", "--help"]).output().expect("run");
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("notation = \"report\""), "{text}");
    assert!(text.contains("docs/errata.md"), "{text}");
}
