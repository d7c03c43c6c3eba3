//! The failures fuzzing found in the program (issue 10), each as a user
//! meets it: every one failed on the program before its fix (run with
//! `DELTA_STABILITY_BIN=path/to/old/delta-stability` to see it fail there).

use crate::common;

use common::{
    Scratch, bin, example, json, path, run_err, run_ok, stderr, stdout, wait_while_running,
};
use std::time::{Duration, Instant};

/// Exit status for bad input and for a file that cannot be read or written.
const INPUT: i32 = 2;
const IO: i32 = 3;

/// No message quotes more than this much of what it is about.
const SHORT: usize = 2_000;

fn assert_short(err: &str) {
    assert!(
        err.len() < SHORT,
        "{} bytes of message:\n{}",
        err.len(),
        &err[..SHORT.min(err.len())]
    );
    let longest_digits = err
        .split(|c: char| !c.is_ascii_digit())
        .map(str::len)
        .max()
        .unwrap_or(0);
    assert!(
        longest_digits < 20,
        "a {longest_digits}-digit number in:\n{err}"
    );
}

/// The 45° example with `z_w`'s value at column 70,007 of its line, and
/// the value not a finite number.
fn error_past_column_65535() -> String {
    example("tailless-delta-45.toml")
        .replace("z_w = -3.2", &format!("{}z_w = nan", " ".repeat(70_000)))
}

#[test]
fn an_error_past_column_65535_is_reported_not_a_panic() {
    let dir = Scratch::new();
    let f = dir.write("wide.toml", error_past_column_65535());
    let cfg = dir.write(
        "wide-config.toml",
        example("delta-45.toml").replace("mu1 = 50.0", &format!("{}mu1 = inf", " ".repeat(70_000))),
    );
    let (f, cfg) = (path(&f), path(&cfg));
    let out_csv = dir.path().join("o.csv");
    for args in [
        vec!["quartic", f],
        vec!["response", f, "--until", "1"],
        vec!["convert", "--from", "report", "--to", "garner", f],
        vec!["analyze", cfg],
        vec!["sweep", cfg, "--mach", "1", "-o", path(&out_csv)],
    ] {
        let err = stderr(&run_err(&args, INPUT));
        assert!(
            err.contains(":13:70007: [derivatives] z_w") || err.contains(":17:70007: [flight] mu1"),
            "{args:?}:\n{err}"
        );
        assert_short(&err);
    }
}

/// Runs the program on `args`; it must end within 300 s (a FIFO read
/// blocks forever, /dev/zero never ends: a hang's only sign is that it
/// does not end, so this one check has a limit, far beyond the
/// milliseconds a refusal takes on any machine).
fn run_with_deadline(args: &[&str]) -> std::process::Output {
    let mut child = bin()
        .args(args)
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("run");
    let start = Instant::now();
    while child.try_wait().expect("wait").is_none() {
        if start.elapsed() > Duration::from_secs(300) {
            child.kill().ok();
            panic!("{args:?} did not finish in 300 s");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    child.wait_with_output().expect("output")
}

#[cfg(unix)]
#[test]
fn a_fifo_or_a_device_is_refused_not_read() {
    let dir = Scratch::new();
    let fifo = dir.path().join("pipe.toml");
    let made = std::process::Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .expect("mkfifo");
    assert!(made.success());
    let cfg = dir.write(
        "c.toml",
        example("delta-45.toml").replace(
            "damping = \"faired\"",
            "damping = \"faired\"\n[model.tables]\nzero_lift_drag = { file = \"pipe.toml\" }",
        ),
    );
    for (args, what) in [
        (vec!["quartic", path(&fifo)], "FIFO"),
        (vec!["quartic", "/dev/zero"], "character device"),
        (vec!["analyze", path(&cfg)], "FIFO"),
    ] {
        let out = run_with_deadline(&args);
        let err = stderr(&out);
        assert_eq!(out.status.code(), Some(IO), "{args:?}: {err}");
        assert!(
            err.contains(what) && err.contains("regular file"),
            "{args:?}: {err}"
        );
    }
    // the table's error is located where the config names it
    let err = stderr(&run_with_deadline(&["analyze", path(&cfg)]));
    assert!(
        err.contains("c.toml:") && err.contains("[model.tables] zero_lift_drag"),
        "{err}"
    );
}

#[test]
fn an_input_larger_than_the_limit_is_refused() {
    let dir = Scratch::new();
    let big = dir.write("big.toml", " ".repeat(17 << 20));
    let err = stderr(&run_err(&["quartic", path(&big)], INPUT));
    assert!(err.contains("16 MiB"), "{err}");
}

#[test]
fn response_rejects_values_that_are_not_finite() {
    for (flag, value) in [
        ("--m0", "NaN"),
        ("--w0", "inf"),
        ("--until", "-1"),
        ("--until", "nan"),
    ] {
        let args = [
            "response",
            "examples/tailless-delta-45.toml",
            "--until",
            "2",
            flag,
            value,
        ];
        let err = stderr(&run_err(&args, INPUT));
        assert!(err.contains(flag), "{flag} {value}: {err}");
    }
}

#[test]
fn a_response_that_cannot_reach_until_is_an_error_that_says_why() {
    let dir = Scratch::new();
    let csv = dir.path().join("r.csv");
    // a step far too long for the matrix exponential: refused, with advice
    let args = [
        "response",
        "examples/tailless-delta-45.toml",
        "--until",
        "1e308",
        "--csv",
        path(&csv),
    ];
    let err = stderr(&run_err(&args, INPUT));
    assert!(
        err.contains("--until 1e308") && err.contains("too long"),
        "{err}"
    );
    assert_short(&err);
    assert!(!csv.exists(), "a one-sample file was written");
    // a divergent motion that overflows f64 before --until: where it stopped
    let divergent = dir.write(
        "div.toml",
        example("tailless-delta-45.toml").replace("m_w = -0.55", "m_w = 5.0"),
    );
    let args = [
        "response",
        path(&divergent),
        "--until",
        "1000",
        "--steps",
        "100000",
        "--csv",
        path(&csv),
    ];
    let err = stderr(&run_err(&args, INPUT));
    assert!(
        err.contains("stops at t̂ = ") && err.contains("diverged"),
        "{err}"
    );
    assert!(!csv.exists(), "a short file was written");
}

#[test]
fn convert_never_writes_a_value_that_is_not_finite() {
    let dir = Scratch::new();
    let f = dir.write(
        "big.toml",
        example("tailless-delta-45.toml").replace("z_q = -1.5 ", "z_q = -1.5e308"),
    );
    for extra in [None, Some("--json")] {
        let mut args = vec!["convert", "--from", "report", "--to", "ribner", path(&f)];
        args.extend(extra);
        let out = run_err(&args, INPUT);
        let err = stderr(&out);
        assert!(
            err.contains(":15:7: [derivatives] z_q") && err.contains("C_Lq"),
            "{err}"
        );
        assert!(stdout(&out).is_empty(), "{}", stdout(&out));
        assert_short(&err);
    }
}

#[test]
fn stray_tables_beside_avl_output_are_errors() {
    let dir = Scratch::new();
    std::fs::copy(
        common::root().join("examples/tailless-delta.st"),
        dir.path().join("tailless-delta.st"),
    )
    .unwrap();
    let avl = example("avl-tailless-delta.toml");
    for (table, key) in [
        ("report", "mu1 = 1e6"),
        ("flight", "c_l = 0.3"),
        ("derivatives", "m_q = -1.0"),
        ("parameters", "lt = 3.0"),
    ] {
        let f = dir.write("a.toml", format!("{avl}\n[{table}]\n{key}\n"));
        let err = stderr(&run_err(&["quartic", path(&f)], INPUT));
        let name = key.split(' ').next().unwrap();
        assert!(
            err.contains(&format!("a.toml:20:1: [{table}] {name}")) && err.contains("ignored"),
            "{err}"
        );
    }
}

#[test]
fn a_csv_table_without_a_header_is_used_whole() {
    let dir = Scratch::new();
    let rows = "0.5,0.02\n0.7,0.03\n2.0,0.04\n";
    dir.write("headed.csv", format!("mach,cd0\n{rows}"));
    dir.write("bare.csv", rows);
    let result = |table: &str| {
        let cfg = dir.write(
            "c.toml",
            example("delta-45.toml").replace(
                "damping = \"faired\"",
                &format!("damping = \"faired\"\n[model.tables]\nzero_lift_drag = {table}"),
            ),
        );
        json(&run_ok(&["analyze", path(&cfg), "--mach", "0.6", "--json"]))
    };
    // the same three rows inline: the independent route
    let inline = result("{ mach = [0.5, 0.7, 2.0], value = [0.02, 0.03, 0.04] }");
    let headed = result("{ file = \"headed.csv\" }");
    let bare = result("{ file = \"bare.csv\" }");
    let cd0 = |v: &serde_json::Value| {
        v["aerodynamics"]["zero_lift_drag"]["value"]
            .as_f64()
            .unwrap()
    };
    assert!((0.02..0.03).contains(&cd0(&inline)), "{}", cd0(&inline));
    assert_eq!(cd0(&headed), cd0(&inline));
    assert_eq!(cd0(&bare), cd0(&inline));
}

#[test]
fn a_first_row_with_one_bad_cell_is_an_error_not_a_header() {
    let dir = Scratch::new();
    let cfg = dir.write(
        "c.toml",
        example("delta-45.toml").replace(
            "damping = \"faired\"",
            "damping = \"faired\"\n[model.tables]\nzero_lift_drag = { file = \"t.csv\" }",
        ),
    );
    for (first, at) in [
        (
            "0.5,2.6x",
            "t.csv:1:5: column 2 (value): `2.6x` is not a number",
        ),
        (
            "O.5,2.6",
            "t.csv:1:1: column 1 (Mach): `O.5` is not a number",
        ),
    ] {
        dir.write("t.csv", format!("{first}\n0.7,0.03\n2.0,0.04\n"));
        let err = stderr(&run_err(&["analyze", path(&cfg), "--mach", "0.8"], INPUT));
        assert!(err.contains(at), "{first}: {err}");
    }
    // a header is a first line with no number in it
    dir.write("t.csv", "mach,cd0\n0.5,0.02\n2.0,0.04\n");
    run_ok(&["analyze", path(&cfg), "--mach", "0.8"]);
}

#[test]
fn a_huge_string_gives_a_short_message() {
    let dir = Scratch::new();
    let huge = "a".repeat(10 << 20);
    let f = dir.write(
        "s.toml",
        example("tailless-delta-45.toml").replace("\"report\"", &format!("\"{huge}\"")),
    );
    let err = stderr(&run_err(&["quartic", path(&f)], INPUT));
    assert!(
        err.contains("s.toml:5:12: notation: unknown notation"),
        "{}",
        &err[..err.len().min(300)]
    );
    assert_short(&err);
    // a string where a number belongs
    let f = dir.write(
        "n.toml",
        example("tailless-delta-45.toml").replace("-3.2", &format!("\"{huge}\"")),
    );
    let err = stderr(&run_err(&["quartic", path(&f)], INPUT));
    assert!(err.contains("n.toml:13:"), "{}", &err[..err.len().min(300)]);
    assert_short(&err);
}

#[test]
fn messages_name_the_line_and_field_and_print_short_numbers() {
    let dir = Scratch::new();
    // a c.g. at h = 1e308: the config's own line, not "a derivative is not finite"
    let cfg = dir.write(
        "cg-1e308.toml",
        example("delta-45.toml").replace("cg = 0.25", "cg = 1e308"),
    );
    let err = stderr(&run_err(&["analyze", path(&cfg)], INPUT));
    assert!(
        err.contains("cg-1e308.toml:16:6: [flight] cg:") && err.contains("1e308"),
        "{err}"
    );
    assert_short(&err);
    // a value whose conversion overflows: named at the value
    // (Garner's x_u is half the report's)
    let garner = stdout(&run_ok(&[
        "convert",
        "--from",
        "report",
        "--to",
        "garner",
        "examples/tailless-delta-45.toml",
    ]));
    let line = garner
        .lines()
        .position(|l| l.starts_with("x_u = "))
        .unwrap()
        + 1;
    let big = dir.write(
        "g.toml",
        garner
            .lines()
            .map(|l| {
                if l.starts_with("x_u = ") {
                    "x_u = -1.7e308"
                } else {
                    l
                }
            })
            .collect::<Vec<_>>()
            .join("\n"),
    );
    let err = stderr(&run_err(&["quartic", path(&big)], INPUT));
    assert!(
        err.contains(&format!("g.toml:{line}:7: [derivatives] x_u")) && err.contains("-inf"),
        "{err}"
    );
    assert!(err.contains("overflows"), "{err}");
    assert_short(&err);
    // an AVL file with Sref = 0: the .st line, not an overflow
    let st = example("tailless-delta.st");
    let line = st.lines().position(|l| l.contains("Sref")).unwrap() + 1;
    let sref = st.lines().nth(line - 1).unwrap();
    let value = sref
        .split('=')
        .nth(1)
        .unwrap()
        .split_whitespace()
        .next()
        .unwrap();
    let zeroed = sref.replacen(value, "0.0", 1);
    dir.write("tailless-delta.st", st.replacen(sref, &zeroed, 1));
    let avl = dir.write("a.toml", example("avl-tailless-delta.toml"));
    let err = stderr(&run_err(&["quartic", path(&avl)], INPUT));
    assert!(
        err.contains(&format!("tailless-delta.st:{line}:"))
            && err.contains("Sref")
            && err.contains("positive"),
        "{err}"
    );
    assert!(!err.contains("overflow"), "{err}");
}

#[test]
fn a_misspelt_name_is_an_error_with_the_nearest_valid_one() {
    let dir = Scratch::new();
    let ex = example("boeing-747-american.toml");
    let line = ex.lines().position(|l| l.starts_with("C_mq = ")).unwrap() + 1;
    let misspelt =
        format!(":{line}:1: [derivatives] C_mqq: unknown field `C_mqq`; did you mean `C_mq`?");
    for (from, to, expect) in [
        ("C_mq = -23.92", "C_mqq = -23.92", misspelt.as_str()),
        (
            "notation = \"american\"",
            "notaton = \"american\"",
            "did you mean `notation`?",
        ),
        (
            "mass = 288660.55",
            "mas = 288660.55",
            "[dimensional] mas: unknown field `mas`",
        ),
        (
            "notation = \"american\"",
            "notation = \"amercan\"",
            "did you mean `american`?",
        ),
    ] {
        let f = dir.write("m.toml", ex.replace(from, to));
        let err = stderr(&run_err(&["quartic", path(&f)], INPUT));
        assert!(err.contains(expect), "{expect}\n{err}");
    }
    let f = dir.write("m.toml", ex.replace("mass = 288660.55", "mas = 288660.55"));
    assert!(stderr(&run_err(&["quartic", path(&f)], INPUT)).contains("did you mean `mass`?"));
}

#[test]
fn a_write_failure_names_the_output_not_the_config() {
    let dir = Scratch::new();
    let plain = dir.write("plain", "a regular file");
    let under = plain.join("out.csv");
    let args = [
        "sweep",
        "examples/delta-60.toml",
        "--mach",
        "1",
        "-o",
        path(&under),
    ];
    let err = stderr(&run_err(&args, IO));
    assert!(
        err.contains("plain/out.csv") && err.contains("is a file, not a directory"),
        "{err}"
    );
    assert!(
        !err.contains("delta-60.toml") && !err.contains("File exists"),
        "{err}"
    );
    let svg = plain.join("r.svg");
    let args = [
        "response",
        "examples/tailless-delta-45.toml",
        "--until",
        "1",
        "--svg",
        path(&svg),
    ];
    assert!(stderr(&run_err(&args, IO)).contains("is a file, not a directory"));
    let report = plain.join("report");
    let args = ["report", "--out", path(&report)];
    assert!(stderr(&run_err(&args, IO)).contains("is a file, not a directory"));
}

#[test]
fn a_missing_input_is_an_io_failure_naming_its_path() {
    let err = stderr(&run_err(&["quartic", "no/such/file.toml"], IO));
    assert!(
        err.contains("`no/such/file.toml`") && err.contains("No such file"),
        "{err}"
    );
}

#[test]
fn exit_statuses_and_input_limits_are_documented_in_help() {
    let help = stdout(&run_ok(&["--help"]));
    for text in [
        "Exit status",
        "2  bad input",
        "3  a file could not be read or written",
        "16 MiB",
    ] {
        assert!(help.contains(text), "{text}:\n{help}");
    }
}

#[test]
fn a_reader_that_stops_early_is_not_a_panic_and_a_full_disk_is_an_io_failure() {
    use std::io::{BufRead, BufReader};
    let mut child = bin()
        .args([
            "response",
            "examples/tailless-delta-45.toml",
            "--until",
            "100",
            "--steps",
            "200000",
        ])
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("run");
    let mut first = String::new();
    BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut first)
        .unwrap();
    assert!(first.starts_with("t_hat"), "{first}");
    // the pipe is closed here, with most of the output unread
    let out = child.wait_with_output().unwrap();
    let err = stderr(&out);
    assert!(!err.contains("panicked"), "{err}");
    assert_eq!(out.status.code(), Some(0), "{err}");
    #[cfg(target_os = "linux")]
    {
        let full = std::fs::File::create("/dev/full").unwrap();
        let out = bin()
            .args(["quartic", "examples/tailless-delta-45.toml"])
            .stdout(full)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(IO));
        assert!(
            stderr(&out).contains("cannot write `standard output`"),
            "{}",
            stderr(&out)
        );
    }
}

#[test]
fn an_analysis_that_overflows_is_an_error_at_the_value_behind_it() {
    let dir = Scratch::new();
    let ex = example("tailless-delta-45.toml");
    for (from, to, at) in [
        ("mu1 = 50.0", "mu1 = 1e300", "[flight] mu1"),
        ("mu1 = 50.0", "mu1 = 1e-300", "[flight] mu1"),
        ("i_b = 0.08", "i_b = 1e-300", "[flight] i_b"),
    ] {
        let f = dir.write("x.toml", ex.replace(from, to));
        let out = run_err(&["quartic", path(&f), "--json"], INPUT);
        let err = stderr(&out);
        assert!(
            err.contains(&format!(
                "x.toml:{}:7: {at}",
                if at.contains("i_b") { 24 } else { 23 }
            )),
            "{to}: {err}"
        );
        assert!(stdout(&out).is_empty(), "{to}: printed {}", stdout(&out));
        assert_short(&err);
    }
}

/// A `[dimensional]` table for the 45° example: τ known, the modes in
/// seconds and the short-period frequency requirement assessed.
const SECONDS: &str =
    "\n[dimensional]\nV = 250.0\nrho = 0.41\nS = 93.0\nchord = 6.6\nmass = 12000.0\n";

#[test]
fn an_undefined_cap_is_not_assessed_not_graded_on_infinity() {
    let dir = Scratch::new();
    let report = format!("{}{SECONDS}", example("tailless-delta-45.toml"));
    let dimensional = example("aircraft/boeing-747-etkin-reid.toml");
    for (text, why) in [
        (report.replace("c_l = 0.3 ", "c_l = 0.0 "), "C_L = 0"),
        (report.replace("z_w = -3.2", "z_w = 0.0 "), "Z_w = 0"),
        (dimensional.replace("g = 9.81 ", "g = 5e-324 "), "g → 0"),
    ] {
        let f = dir.write("x.toml", &text);
        let page = stdout(&run_ok(&["quartic", path(&f)]));
        let line = page
            .lines()
            .find(|l| l.contains("short-period frequency"))
            .unwrap_or_else(|| panic!("{why}: no requirement line:\n{page}"));
        assert!(
            line.contains("not assessed") && line.contains(why),
            "{line}"
        );
        // no level graded on an infinite or undefined CAP, no `inf` printed
        assert!(!line.contains("Level") && !line.contains("inf "), "{line}");
        let j = json(&run_ok(&["quartic", path(&f), "--json"]));
        assert!(j.get("short_period_frequency").is_none(), "{why}: {j}");
        let reason = j["short_period_frequency_not_assessed"].as_str().unwrap();
        assert!(reason.contains(why), "{reason}");
    }
}

/// Each mode's damping ratio, by mode name, from `quartic --json`.
fn damping_ratios(j: &serde_json::Value) -> Vec<(String, f64)> {
    let mut v: Vec<(String, f64)> = j["modes"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|m| {
            Some((
                m["name"].as_str()?.to_string(),
                m["damping_ratio"].as_f64()?,
            ))
        })
        .collect();
    v.sort_by(|a, b| a.partial_cmp(b).unwrap());
    v
}

/// Converts `input` (in notation `from`) to `to` and reads the file back
/// with the program's reader: the same aircraft (each mode's ζ within
/// 0.02), or a refusal (exit status 2) that writes nothing. Whether it was
/// written.
fn round_trip(dir: &Scratch, ex: &std::path::Path, from: &str, to: &str) -> bool {
    let input = dir.write("in.toml", std::fs::read(ex).unwrap());
    let original = json(&run_ok(&["quartic", path(&input), "--json"]));
    let args = ["convert", "--from", from, "--to", to, path(&input)];
    let out = bin().args(args).output().unwrap();
    let (err, ex) = (stderr(&out), ex.display());
    match out.status.code() {
        Some(0) => {}
        Some(2) => {
            assert!(stdout(&out).is_empty() && err.contains("in.toml"), "{err}");
            return false;
        }
        code => panic!("{ex} --to {to}: {code:?}\n{err}"),
    }
    let back = dir.write("back.toml", &out.stdout);
    let read = bin()
        .args(["quartic", path(&back), "--json"])
        .output()
        .unwrap();
    assert!(
        read.status.success(),
        "{ex} --to {to}: written, then refused by the reader:\n{}\n{}",
        stdout(&out),
        stderr(&read)
    );
    let (a, b) = (damping_ratios(&original), damping_ratios(&json(&read)));
    assert_eq!(a.len(), b.len(), "{ex} --to {to}");
    for ((n, x), (_, y)) in a.iter().zip(&b) {
        assert!((x - y).abs() < 0.02, "{ex} --to {to}: {n} ζ {x} → {y}");
    }
    true
}

#[test]
fn convert_writes_files_its_own_reader_accepts_or_says_what_is_missing() {
    let dir = Scratch::new();
    let root = common::root();
    std::fs::copy(
        root.join("examples/tailless-delta.st"),
        dir.path().join("tailless-delta.st"),
    )
    .unwrap();
    let mut examples: Vec<std::path::PathBuf> = ["examples", "examples/aircraft"]
        .iter()
        .flat_map(|d| std::fs::read_dir(root.join(d)).unwrap())
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    examples.sort();
    let targets: Vec<&str> = stability_core::data::notation::Notation::all()
        .map(|n| n.name())
        .chain(["dimensional"])
        .collect();
    let (mut written, mut refused) = (0, 0);
    for ex in &examples {
        let text = std::fs::read_to_string(ex).unwrap();
        let Some(line) = text.lines().find(|l| l.starts_with("notation = ")) else {
            continue; // a design-point config, not a derivative file
        };
        let from = line.split('"').nth(1).unwrap();
        for to in &targets {
            match round_trip(&dir, ex, from, to) {
                true => written += 1,
                false => refused += 1,
            }
        }
    }
    assert!(
        written > 40 && refused > 0,
        "{written} written, {refused} refused"
    );
    // the shipped example has no C_D: Ribner's C_Lα holds it with z_w
    let ex = "examples/tailless-delta-45.toml";
    for to in ["ribner", "lehrian", "perkins", "american_cl"] {
        let err = stderr(&run_err(
            &["convert", "--from", "report", "--to", to, ex],
            INPUT,
        ));
        assert!(
            err.contains(&format!("--to {to} needs C_D")) && err.contains("give c_d in [flight]"),
            "{err}"
        );
        // the JSON still says which values the input determines (null: not)
        let j = json(&run_ok(&[
            "convert", "--from", "report", "--to", to, ex, "--json",
        ]));
        assert!(
            j["values"]
                .as_object()
                .unwrap()
                .values()
                .any(|v| v.is_null())
        );
    }
}

#[test]
fn convert_to_dimensional_writes_only_what_a_dimensional_file_holds() {
    let dir = Scratch::new();
    let ex = example("tailless-delta-60-dimensional.toml");
    for (from, to, expect) in [
        (
            "c_l = 0.121",
            "c_l = 0.0  ",
            ":24:7: [flight] c_l: --to dimensional: C_L = 0",
        ),
        (
            "c_l = 0.121",
            "c_l = -0.2 ",
            ":24:7: [flight] c_l: --to dimensional: C_L = -0.2",
        ),
        (
            "i_b = 0.06",
            "i_b = 1e-310",
            "the result's `model.derivatives.M_w` = -inf is not finite",
        ),
        ("mu1 = 138.2", "mu1 = 1e-310", "is not finite"),
    ] {
        let f = dir.write("x.toml", ex.replace(from, to));
        for json in [None, Some("--json")] {
            let mut args = vec![
                "convert",
                "--from",
                "report",
                "--to",
                "dimensional",
                path(&f),
            ];
            args.extend(json);
            let out = run_err(&args, INPUT);
            assert!(stderr(&out).contains(expect), "{to}: {}", stderr(&out));
            assert!(stdout(&out).is_empty(), "{to}: wrote {}", stdout(&out));
        }
    }
    // a body-axis set whose stability-axis attitude is beyond ±89°
    let steep = dir.write(
        "steep.toml",
        example("aircraft/boeing-747-cr2144-fc9.toml")
            .replace("W0 = 62.0740 ", "W0 = -300.0 ")
            .replace("theta0 = 4.6 ", "theta0 = 88.9 "),
    );
    let args = [
        "convert",
        "--from",
        "dimensional",
        "--to",
        "dimensional",
        path(&steep),
    ];
    let err = stderr(&run_err(&args, INPUT));
    assert!(
        err.contains("[flight] theta0") && err.contains("110.1°"),
        "{err}"
    );
}

#[test]
fn the_warning_of_what_eq4_leaves_out_never_says_inf_percent() {
    let dir = Scratch::new();
    // Z_u = M_u = 0: a root at 0, which a relative move divided by
    let f = dir.write(
        "zero-root.toml",
        example("aircraft/boeing-747-etkin-reid.toml")
            .replace("Z_u = -0.08989797864 ", "Z_u = 0.0 ")
            .replace("M_u = 0.0003547884187 ", "M_u = 0.0 ")
            .replace("X_q = 0.0", "X_q = 0.0\nX_udot = 0.01"),
    );
    let out = run_ok(&[
        "convert",
        "--from",
        "dimensional",
        "--to",
        "report",
        path(&f),
    ]);
    let err = stderr(&out);
    assert!(err.contains("cannot hold X_u̇ = 0.0100"), "{err}");
    assert!(
        err.contains("the modes move by up to 1.00 % of |λ|"),
        "{err}"
    );
    assert!(!err.contains("inf") && !err.contains("NaN"), "{err}");
}

/// The names and contents of the files in `dir`, sorted.
fn contents(dir: &std::path::Path) -> Vec<(String, Vec<u8>)> {
    let mut v: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.is_file())
        .map(|p| {
            let name = p.file_name().unwrap().to_string_lossy().into_owned();
            (name, std::fs::read(&p).unwrap())
        })
        .collect();
    v.sort();
    v
}

#[test]
fn no_output_overwrites_an_input_or_another_output() {
    let dir = Scratch::new();
    let set = example("tailless-delta-45.toml");
    for name in ["X.toml", "X.json", "X.py", "X.m"] {
        dir.write(name, &set);
    }
    let config = example("delta-45.toml").replace(
        "damping = \"faired\"",
        "damping = \"faired\"\n[model.tables]\nzero_lift_drag = { file = \"t.csv\" }",
    );
    dir.write("W.json", &config);
    dir.write("t.csv", "mach,cd0\n0.5,0.02\n2.0,0.03\n");
    let st = common::root().join("examples/tailless-delta.st");
    std::fs::copy(st, dir.path().join("tailless-delta.st")).unwrap();
    dir.write("avl.toml", example("avl-tailless-delta.toml"));
    std::fs::create_dir(dir.path().join("sub")).unwrap();
    let mut cases = vec![
        (
            "response X.toml --until 1 --csv X.toml",
            "--csv would overwrite FILE",
        ),
        (
            "quartic X.json --state-space X.json",
            "--state-space would overwrite FILE",
        ),
        (
            "quartic X.py --state-space X.json",
            "the script X.py that --state-space writes",
        ),
        (
            "quartic X.m --state-space X.json",
            "the script X.m that --state-space writes",
        ),
        (
            "sweep W.json --mach 1 -o W.json",
            "-o would overwrite CONFIG",
        ),
        (
            "analyze W.json --state-space W.json",
            "--state-space would overwrite CONFIG",
        ),
        (
            "sweep W.json --mach 1 -o sub/../t.csv",
            "`t.csv` (named in CONFIG)",
        ),
        (
            "response X.toml --until 1 --csv o.csv --svg ./o.csv",
            "--csv and --svg name the same file",
        ),
        (
            "response avl.toml --until 1 --svg tailless-delta.st",
            "(named in FILE)",
        ),
    ];
    #[cfg(unix)]
    {
        std::fs::hard_link(dir.path().join("X.toml"), dir.path().join("hard.csv")).unwrap();
        cases.push((
            "response X.toml --until 1 --csv hard.csv",
            "--csv would overwrite FILE",
        ));
    }
    let before = contents(dir.path());
    for (args, expect) in cases {
        let err = refused_in(dir.path(), args);
        assert!(err.contains(expect), "{args}:\n{err}");
        assert_eq!(contents(dir.path()), before, "{args} changed a file");
    }
}

/// The message of `args` (split at spaces) run in `dir`, which must be
/// refused as bad input.
fn refused_in(dir: &std::path::Path, args: &str) -> String {
    let out = bin()
        .current_dir(dir)
        .args(args.split(' '))
        .output()
        .unwrap();
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(INPUT), "{args}:\n{err}");
    err
}

#[test]
fn the_state_space_files_are_written_as_a_set() {
    let dir = Scratch::new();
    let out = dir.path().join("ss.json");
    // a directory where the MATLAB script goes: nothing of the set written
    std::fs::create_dir(dir.path().join("ss.m")).unwrap();
    let args = [
        "quartic",
        "examples/tailless-delta-45.toml",
        "--state-space",
        path(&out),
    ];
    let err = stderr(&run_err(&args, IO));
    assert!(
        err.contains("ss.m") && err.contains("it is a directory"),
        "{err}"
    );
    assert!(!out.exists() && !dir.path().join("ss.py").exists());
    std::fs::remove_dir(dir.path().join("ss.m")).unwrap();
    run_ok(&args);
    for ext in ["json", "py", "m"] {
        assert!(out.with_extension(ext).is_file(), "{ext}");
    }
}

/// Runs `report --out out`, which must refuse (exit status 3) naming each
/// of `lost`, and leave every file in `out` as it was.
fn report_refuses(out: &std::path::Path, lost: &[&str]) {
    let before = contents(out);
    let err = stderr(&run_err(&["report", "--out", path(out)], IO));
    assert!(err.contains("will not replace"), "{err}");
    for name in lost {
        assert!(err.contains(&format!("`{name}`")), "{name}: {err}");
    }
    assert_eq!(contents(out), before);
}

/// The report written is a design's (`report CONFIG`), written as the
/// note's is (`write_report`, its manifest); the note's report refuses it
/// at the start. A file saved into the report during a run is refused at
/// the swap: `cmd::report`'s unit test.
#[test]
fn the_report_replaces_only_what_a_report_wrote() {
    let dir = Scratch::new();
    let out = dir.path().join("report");
    let design = ["report", "examples/delta-60.toml", "--mach", "1.2", "--out"];
    run_ok(&[&design[..], &[path(&out)]].concat());
    let page = std::fs::read(out.join("index.html")).unwrap();
    // a file of the user's under docs/, a name the report writes
    std::fs::write(out.join("docs/mine.md"), "my notes").unwrap();
    report_refuses(&out, &["docs/mine.md"]);
    assert!(out.join("docs/mine.md").is_file());
    std::fs::remove_file(out.join("docs/mine.md")).unwrap();
    // the report's page edited by its user
    std::fs::write(out.join("index.html"), "<p>my own page</p>").unwrap();
    report_refuses(&out, &["index.html"]);
    std::fs::write(out.join("index.html"), &page).unwrap();
    // a user's own index.html and summary.json, never written by a report
    let own = dir.path().join("own");
    std::fs::create_dir(&own).unwrap();
    std::fs::write(own.join("index.html"), "<p>mine</p>").unwrap();
    std::fs::write(own.join("summary.json"), "{}").unwrap();
    report_refuses(&own, &["index.html", "summary.json"]);
    // the report, as it was, is replaced
    run_ok(&[&design[..], &[path(&out)]].concat());
    assert!(temporaries(dir.path()).is_empty());
}

/// The program's temporary files and directories in `dir`.
fn temporaries(dir: &std::path::Path) -> Vec<std::path::PathBuf> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| {
            p.file_name()
                .is_some_and(|n| n.to_string_lossy().starts_with(".delta-stability-"))
        })
        .collect()
}

/// Sends `signal` (`TERM`, `INT`) to process `pid`.
#[cfg(unix)]
fn send(signal: &str, pid: u32) {
    let sent = std::process::Command::new("kill")
        .args(["-s", signal, &pid.to_string()])
        .status()
        .expect("kill");
    assert!(sent.success());
}

#[cfg(unix)]
#[test]
fn sigint_and_sigterm_remove_the_runs_temporaries() {
    for (signal, status) in [("TERM", 143), ("INT", 130)] {
        let dir = Scratch::new();
        let out = dir.path().join("big.csv");
        let mut child = bin()
            // 1.5 million points: seconds of writing to be killed in, and
            // about 0.7 GB if it ran to the end (a sweep the disk cannot
            // hold is refused before it starts)
            .args(["sweep", "examples/delta-60.toml", "--mach", "0.5:2:0.0001"])
            .args(["--damping", "faired-slender", "--cg", "0.2:0.3:0.001", "-o"])
            .arg(&out)
            .stderr(std::process::Stdio::null())
            .spawn()
            .expect("run");
        // once rows (not only the header) are in the temporary file
        let writing = wait_while_running(&mut child, || {
            temporaries(dir.path())
                .iter()
                .any(|p| std::fs::metadata(p).is_ok_and(|m| m.len() > 200))
        });
        send(signal, child.id());
        let done = child.wait_with_output().unwrap();
        assert!(writing, "the sweep never wrote into a temporary file");
        assert_eq!(done.status.code(), Some(status), "SIG{signal}");
        assert!(
            temporaries(dir.path()).is_empty(),
            "SIG{signal}: a temporary left"
        );
        assert!(!out.exists());
    }
    // a report's temporary directory too
    let dir = Scratch::new();
    let out = dir.path().join("report");
    let mut child = bin()
        .args(["report", "--out", path(&out)])
        .stderr(std::process::Stdio::null())
        .spawn()
        .expect("run");
    let writing = wait_while_running(&mut child, || {
        temporaries(dir.path())
            .iter()
            .any(|d| std::fs::read_dir(d).is_ok_and(|mut e| e.next().is_some()))
    });
    send("INT", child.id());
    let done = child.wait_with_output().unwrap();
    assert!(
        writing && done.status.code() == Some(130),
        "{:?}",
        done.status
    );
    assert!(temporaries(dir.path()).is_empty() && !out.exists());
}

#[test]
fn sweep_counts_in_messages_are_short() {
    let dir = Scratch::new();
    let o = dir.path().join("o.csv");
    for (range, expect) in [
        (
            vec!["--mach", "0.5:2:1e-300"],
            "0.5:2:1e-300 gives about 1.50e300 values",
        ),
        (
            vec!["--mach", "1", "--sweep", "0:1e308:1e-308"],
            "gives more values than can be counted",
        ),
        (
            vec![
                "--mach",
                "0.5:1.4999999:1e-7",
                "--cg",
                "0.1:0.19999999:1e-8",
                "--mu1",
                "10:10.00099:1e-8",
            ],
            "the grid has about 9.90e18 points",
        ),
    ] {
        let mut args = vec!["sweep", "examples/delta-60.toml", "-o", path(&o)];
        args.extend(range);
        let err = stderr(&run_err(&args, INPUT));
        assert!(err.contains(expect), "{args:?}: {err}");
        assert!(!err.contains("inf"), "{err}");
        let digits = err.split(|c: char| !c.is_ascii_digit()).map(str::len).max();
        assert!(digits < Some(10), "{err}");
    }
}

#[cfg(unix)]
#[test]
fn a_sweep_that_would_not_fit_is_refused_with_its_estimate() {
    let dir = Scratch::new();
    let out = dir.path().join("out.csv");
    // a file-size limit of 100 blocks (51.2 kB in sh's 512-byte blocks, or
    // 102.4 kB): about 320 kB of rows would not fit
    let done = std::process::Command::new("sh")
        .arg("-c")
        .arg("ulimit -f 100; exec \"$0\" \"$@\"")
        .arg(bin().get_program())
        .args(["sweep", "examples/delta-60.toml", "--mach", "0.5:2:0.001"])
        // quasi-steady: this is about the file, not the lattice's solves
        .args(["--damping", "faired-slender", "-o"])
        .arg(&out)
        .current_dir(common::root())
        .output()
        .unwrap();
    let err = stderr(&done);
    assert_eq!(done.status.code(), Some(IO), "{err}");
    assert!(
        err.contains("the grid's 1501 rows need about") && err.contains("bytes a row"),
        "{err}"
    );
    assert!(err.contains("file-size limit (ulimit -f)"), "{err}");
    assert!(!out.exists() && temporaries(dir.path()).is_empty());
}

#[test]
fn a_response_over_a_tiny_span_is_written_in_short_numbers() {
    let args = [
        "response",
        "examples/tailless-delta-45.toml",
        "--until",
        "1e-300",
        "--steps",
        "10",
    ];
    let csv = stdout(&run_ok(&args));
    assert_eq!(csv.lines().count(), 12, "{csv}");
    for line in csv.lines().skip(1) {
        for field in line.split(',') {
            assert!(field.len() <= 20, "{field} in {line}");
            assert!(field.is_empty() || field.parse::<f64>().is_ok_and(f64::is_finite));
        }
    }
    assert!(csv.lines().nth(10).unwrap().starts_with("9e-301,"), "{csv}");
}

// The third campaign (issue 31): each test failed on the program before
// its fix.

/// The 60° delta at a supersonic Mach number, by the supersonic theory
/// (no lattice: quick), with `more` appended.
fn supersonic_config(more: &str) -> String {
    format!(
        "[planform]\nsweep = 60.0\ntaper = 0.0\nroot_chord = 10.0\n\n[flight]\nmach = 1.5\ncg = 0.25\nmu1 = 50.0\ni_b = 0.08\ncl_m2 = 0.05\n\n[model]\ndamping = \"supersonic\"\n{more}"
    )
}

/// The message of `args` — `CFG` standing for a config of `text` written
/// in a scratch directory — which must be refused as bad input.
fn refused_with(text: &str, args: &[&str]) -> String {
    let dir = Scratch::new();
    let cfg = dir.write("c.toml", text);
    let args: Vec<&str> = args
        .iter()
        .map(|a| if *a == "CFG" { path(&cfg) } else { a })
        .collect();
    stderr(&run_err(&args, INPUT))
}

/// Issue 31, 1: A samples file `[uncertainty]` names is an input of every command
/// that reads the config, whether it runs the study or not: no output
/// overwrites it.
#[test]
fn a_samples_file_the_config_names_is_never_overwritten() {
    let dir = Scratch::new();
    let samples = "i_b\n0.07\n0.08\n0.09\n";
    dir.write(
        "u.toml",
        supersonic_config("[uncertainty.i_b]\ndist = \"samples\"\nfile = \"s.csv\"\n"),
    );
    dir.write("s.csv", samples);
    for args in [
        "uncertainty u.toml --mach 1.5 --samples 10 -o s.csv",
        "sweep u.toml --mach 1.5 -o s.csv",
        "analyze u.toml --write-derivatives ./s.csv",
    ] {
        let err = refused_in(dir.path(), args);
        assert!(
            err.contains("would overwrite `s.csv` (named in CONFIG)"),
            "{args}:\n{err}"
        );
        let now = std::fs::read_to_string(dir.path().join("s.csv")).unwrap();
        assert_eq!(now, samples, "{args} changed the samples");
    }
}

/// Issue 31, 2: `report --out DIR` replaces DIR whole: a DIR that holds an input of
/// the run (here the lift-slope table an earlier report wrote there) is
/// refused, however DIR is spelt, and nothing in it changes.
#[test]
fn a_report_directory_that_holds_an_input_is_refused() {
    let dir = Scratch::new();
    dir.write("a.toml", supersonic_config(""));
    let run = |args: &str| {
        bin()
            .current_dir(dir.path())
            .args(args.split(' '))
            .output()
            .unwrap()
    };
    let first = run("report a.toml --mach 1.5,1.6 --out rep");
    assert!(first.status.success(), "{}", stderr(&first));
    dir.write(
        "b.toml",
        supersonic_config("[model.tables]\nlift_slope = { file = \"rep/lift-slope.csv\" }\n"),
    );
    let before = contents(&dir.path().join("rep"));
    assert!(before.iter().any(|(n, _)| n == "lift-slope.csv"));
    for out in ["rep", "rep/", "rep/.", "./rep"] {
        let done = run(&format!("report b.toml --mach 1.5,1.6 --out {out}"));
        let err = stderr(&done);
        assert_eq!(done.status.code(), Some(INPUT), "{out}:\n{err}");
        assert!(
            err.contains("--out holds `rep/lift-slope.csv` (named in CONFIG)"),
            "{out}:\n{err}"
        );
        assert_eq!(contents(&dir.path().join("rep")), before, "{out}");
    }
}

/// The DATCOM fixture's text, and the config of its 60° delta taking it.
fn datcom_config(dir: &Scratch, name: &str, text: &str) -> std::path::PathBuf {
    dir.write(name, text);
    dir.write(
        &format!("{name}.toml"),
        supersonic_config(&format!("datcom = \"{name}\"\n"))
            .replace("\"supersonic\"", "\"faired\""),
    )
}

/// Issue 31, 3: A DATCOM table headed `(PER RADIAN)` (DATCOM's `DERIV RAD`) is read
/// per radian: its dynamic derivatives, printed the same, are 180/π times
/// smaller than under a `(PER DEGREE)` header.
#[test]
fn a_datcom_table_headed_per_radian_is_read_per_radian() {
    let dir = Scratch::new();
    let degree = include_str!("../../../stability-io/tests/fixtures/datcom/delta60_h0.0.out");
    let radian = degree.replace(
        "DYNAMIC DERIVATIVES (PER DEGREE)",
        "DYNAMIC DERIVATIVES (PER RADIAN)",
    );
    let z_q = |name: &str, text: &str| {
        let cfg = datcom_config(&dir, name, text);
        // the c.g. at DATCOM's moment centre (h = −5e-8): no transfer
        let j = json(&run_ok(&[
            "analyze",
            path(&cfg),
            "--mach",
            "2.0",
            "--cg",
            "0",
            "--json",
        ]));
        ["z_q", "m_q", "z_wdot", "m_wdot"].map(|k| j["derivatives"][k].as_f64().unwrap())
    };
    let (d, r) = (z_q("deg.out", degree), z_q("rad.out", &radian));
    for k in 0..4 {
        let ratio = r[k] / d[k];
        assert!(
            (ratio * 180.0 / std::f64::consts::PI - 1.0).abs() < 1e-4,
            "{k}: {} per degree, {} per radian",
            d[k],
            r[k]
        );
    }
    // the static table's lift slope is the per-degree header's still
    let a = |name: &str| {
        let cfg = dir.path().join(format!("{name}.toml"));
        let j = json(&run_ok(&["analyze", path(&cfg), "--mach", "2.0", "--json"]));
        j["aerodynamics"]["lift_slope"]["value"].as_f64().unwrap()
    };
    assert_eq!(a("deg.out"), a("rad.out"));
}

/// Issue 31, 4: An option the config already fixes is refused, not ignored:
/// `--damping` beside `[uncertainty.model]`, `--aero` where tables give
/// both the lift slope and the aerodynamic centre.
#[test]
fn an_option_the_config_fixes_is_refused_not_ignored() {
    let err = stderr(&run_err(
        &[
            "uncertainty",
            "examples/delta-60-uncertain.toml",
            "--mach",
            "1.5",
            "--samples",
            "10",
            "--damping",
            "faired-slender",
        ],
        INPUT,
    ));
    assert!(
        err.contains("[uncertainty.model]") && err.contains("--damping faired-slender: "),
        "{err}"
    );
    let both = supersonic_config(
        "[model.tables]\nlift_slope = { mach = [1.0, 2.0], value = [3.0, 2.5] }\naerodynamic_centre = { mach = [1.0, 2.0], value = [0.5, 0.5] }\n",
    );
    let err = refused_with(&both, &["analyze", "CFG", "--aero", "lifting-surface"]);
    assert!(
        err.contains("--aero lifting-surface: ") && err.contains("[model.tables]"),
        "{err}"
    );
    // one table of the two: --aero gives the other, and is taken
    let dir = Scratch::new();
    let one = dir.write(
        "one.toml",
        supersonic_config(
            "[model.tables]\nlift_slope = { mach = [1.0, 2.0], value = [3.0, 2.5] }\n",
        ),
    );
    run_ok(&["analyze", path(&one), "--aero", "lifting-surface"]);
}

/// Issue 31, 5: A limit far above the wing's area is refused where no config could
/// give such a surface; up to it, the search finds the tail the wing's
/// own limit finds (the scan starts at the wing's scale).
#[test]
fn size_tail_finds_the_same_tail_whatever_the_limit() {
    let base = [
        "size-tail",
        "examples/delta-45-tailed.toml",
        "--mach",
        "1.2:1.5:0.1",
        "--damping",
        "faired-theories",
        "--json",
    ];
    let area = |extra: &[&str]| {
        let args: Vec<&str> = base.iter().chain(extra).copied().collect();
        json(&run_ok(&args))["area"].as_f64().unwrap()
    };
    let own = area(&[]);
    assert!(own > 0.0 && own < 100.0, "{own}");
    assert_eq!(area(&["--max-area", "1e9"]), own);
    let args: Vec<&str> = base
        .iter()
        .chain(&["--max-area", "1e100"])
        .copied()
        .collect();
    let err = stderr(&run_err(&args, INPUT));
    assert!(err.contains("--max-area: the size must lie in"), "{err}");
}

/// Issue 31, 6: A Mach number where no sample has a result says so ("—", null, an
/// empty cell), never NaN; none with a result anywhere is an error; and
/// the Mach numbers are checked as every other command checks them.
#[test]
fn uncertainty_writes_no_nan_and_checks_its_mach_numbers() {
    let dir = Scratch::new();
    let cfg = dir.write(
        "u.toml",
        supersonic_config("[uncertainty.i_b]\ndist = \"normal\"\nrelative_sd = 0.1\n"),
    );
    let csv = dir.path().join("u.csv");
    let args = [
        "uncertainty",
        path(&cfg),
        "--mach",
        "0.9,1.5",
        "--samples",
        "16",
        "-o",
        path(&csv),
    ];
    let page = stdout(&run_ok(&args));
    assert!(!page.contains("NaN"), "{page}");
    assert!(page.contains("M = 0.9000: no result"), "{page}");
    let written = std::fs::read_to_string(&csv).unwrap();
    assert!(!written.to_lowercase().contains("nan"), "{written}");
    assert!(written.contains("0.9,p_meets,,,"), "{written}");
    let mut with_json = args[..6].to_vec();
    with_json.push("--json");
    let j = json(&run_ok(&with_json));
    assert!(j["results"][0]["meets"]["p"].is_null());
    assert!(j["results"][1]["meets"]["p"].as_f64().is_some());
    let err = stderr(&run_err(
        &[
            "uncertainty",
            path(&cfg),
            "--mach",
            "0.9",
            "--samples",
            "16",
        ],
        INPUT,
    ));
    assert!(err.contains("no sample has a result"), "{err}");
    for m in ["0", "1e-320", "-1"] {
        let err = stderr(&run_err(
            &["uncertainty", path(&cfg), "--mach", m, "--samples", "16"],
            INPUT,
        ));
        assert!(
            err.contains("--mach: the Mach number must lie in"),
            "{m}: {err}"
        );
    }
}

/// Issue 31, 7: A FIFO in the place of a report's manifest is refused at once (it
/// is not what a report wrote), never waited on.
#[cfg(unix)]
#[test]
fn a_fifo_in_the_report_directory_is_refused_not_read() {
    let dir = Scratch::new();
    let cfg = dir.write("a.toml", supersonic_config(""));
    let out = dir.path().join("rep");
    std::fs::create_dir(&out).unwrap();
    let fifo = out.join(".report-manifest.json");
    let made = std::process::Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .expect("mkfifo");
    assert!(made.success());
    let done = run_with_deadline(&[
        "report",
        path(&cfg),
        "--mach",
        "1.5,1.6",
        "--out",
        path(&out),
    ]);
    let err = stderr(&done);
    assert_eq!(done.status.code(), Some(IO), "{err}");
    assert!(
        err.contains("`.report-manifest.json` (not a regular file)"),
        "{err}"
    );
}

/// Issue 31, 8: A configuration whose lattice would cost more than the solver takes
/// is refused before anything is solved, saying what to change.
#[test]
fn a_configuration_too_costly_to_solve_is_refused_saying_what_to_change() {
    let text = example("delta-45-tailed.toml")
        .replace(
            "sweep = 45.0          # leading-edge",
            "sweep = 1.0 # leading-edge",
        )
        .replace("mach = 1.5", "mach = 0.5");
    let err = refused_with(&text, &["analyze", "CFG"]);
    assert!(
        err.contains("[tailplane]") && err.contains("3960 boxes") && err.contains("MB at once"),
        "{err}"
    );
    assert!(
        err.contains("more leading-edge sweep (it has 1.0°)"),
        "{err}"
    );
}

/// Issue 31, 9: An error of a distribution names the key the user wrote or must
/// write, never one computed from it.
#[test]
fn a_lognormal_error_names_the_key_to_give() {
    let text = supersonic_config(
        "[uncertainty.m_q]\nerror = \"additive\"\ndist = \"lognormal\"\nsigma = 0.2\n",
    );
    let err = refused_with(
        &text,
        &["uncertainty", "CFG", "--mach", "1.5", "--samples", "8"],
    );
    assert!(
        err.contains("[uncertainty.m_q] median: give `median`"),
        "{err}"
    );
    assert!(!err.contains("mu:") && !err.contains("mu is"), "{err}");
}

/// Issue 31, 10: `--out rep/.` is the directory `rep`: an earlier report there is
/// replaced as by `--out rep`.
#[test]
fn a_report_directory_spelt_with_a_trailing_dot_is_replaced() {
    let dir = Scratch::new();
    let cfg = dir.write("a.toml", supersonic_config(""));
    let out = dir.path().join("rep");
    let args = |o: &str| {
        vec![
            "report".to_string(),
            path(&cfg).to_string(),
            "--mach".into(),
            "1.5,1.6".into(),
            "--out".into(),
            o.to_string(),
        ]
    };
    run_ok(&args(path(&out)));
    run_ok(&args(&format!("{}/.", path(&out))));
    assert!(out.join("index.html").is_file());
    assert_eq!(temporaries(dir.path()), Vec::<std::path::PathBuf>::new());
}

/// Issue 31, 11: A table value no coefficient or derivative reaches is refused at
/// the table and its line, inline or in a CSV file.
#[test]
fn a_table_value_out_of_range_is_named_at_the_table() {
    let text = supersonic_config(
        "[model.tables]\nm_q = { mach = [1.0, 2.0], values = [-1e308, -0.5], mode = \"value\" }\n",
    );
    let err = refused_with(&text, &["analyze", "CFG"]);
    assert!(
        err.contains("c.toml:16:") && err.contains("[model.tables] m_q value[0]"),
        "{err}"
    );
    assert!(!err.contains("[flight]"), "{err}");
    let dir = Scratch::new();
    dir.write("mq.csv", "mach,m_q\n1.0,-0.5\n2.0,-1e308\n");
    let cfg = dir.write(
        "f.toml",
        supersonic_config("[model.tables]\nm_q = { file = \"mq.csv\" }\n"),
    );
    let err = stderr(&run_err(&["analyze", path(&cfg)], INPUT));
    assert!(err.contains("mq.csv:3:5: column 2 (value)"), "{err}");
}

/// Issue 31, 12: A response's error names the options the user gave.
#[test]
fn a_response_error_names_the_options_given() {
    let err = stderr(&run_err(
        &[
            "response",
            "examples/delta-60-physical.toml",
            "--elevator-deg",
            "1e308",
            "--until-s",
            "5",
        ],
        INPUT,
    ));
    assert!(err.contains("--elevator-deg 1e308: "), "{err}");
    assert!(!err.contains("--until ") && !err.contains("m0"), "{err}");
    // an option of the other input is refused, not ignored
    for (input, flag) in [("step", "--w0"), ("initial", "--m0")] {
        let args = [
            "response",
            "examples/tailless-delta-45.toml",
            "--until",
            "2",
            "--input",
            input,
            flag,
            "0.05",
        ];
        let err = stderr(&run_err(&args, INPUT));
        assert!(
            err.contains(&format!("{flag} is")) && err.contains("does nothing"),
            "{err}"
        );
    }
}
