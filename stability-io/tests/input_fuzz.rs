//! A fuzz target for the input parser: valid derivative files in every
//! notation (and design-point configs), damaged field by field — huge,
//! tiny and non-finite numbers, long strings, long lines, misspelt keys,
//! stray tables, lines deleted or repeated — and arbitrary text. Every
//! input gives either a result whose every value is finite, or an error
//! whose message starts with `file:line:column` and is short. The inputs
//! fuzzing once found wrong are kept in `tests/fuzz-corpus/` and checked
//! the same way.

use proptest::prelude::*;
use stability_core::data::notation::{Notation, report_values};
use stability_io::Failure;
use std::path::{Path, PathBuf};

/// The longest message an error may have.
const SHORT: usize = 2_000;

fn examples() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples")
}

/// The file name the fuzzed text is parsed under (in `examples/`, so that
/// an AVL file's `st_file` finds `tailless-delta.st`).
fn fuzz_path() -> String {
    examples().join("fuzz.toml").display().to_string()
}

/// The 45° example's derivative set in the report's notation.
fn report_set() -> stability_core::Derivatives {
    stability_core::design::examples::tailless_delta_45()
}

/// A valid derivative file in `notation`, written from the library's
/// tables (its names and its conversion from the report's notation).
fn valid_file(notation: Notation) -> String {
    let params = [2.5];
    let values = notation
        .from_report(&report_values(&report_set()), &params)
        .expect("the example converts into every notation");
    let names = notation.names();
    let mut s = format!("notation = \"{}\"\n", notation.name());
    let derivative_rows = &stability_io::input::rows::DERIVATIVES;
    let flight_rows = &stability_io::input::rows::FLIGHT;
    for (table, rows) in [
        ("derivatives", &derivative_rows[..]),
        ("flight", &flight_rows[..]),
    ] {
        s.push_str(&format!("[{table}]\n"));
        for &i in rows {
            if let (Some(n), Some(v)) = (names[i], values[i]) {
                s.push_str(&format!("{n} = {v:?}\n"));
            }
        }
    }
    let report_names = Notation::REPORT.names();
    let lacking: Vec<String> = stability_io::input::rows::QUARTIC
        .iter()
        .filter(|&&i| names[i].is_none())
        .filter_map(|&i| {
            Some(format!(
                "{} = {:?}\n",
                report_names[i]?,
                report_values(&report_set())[i]?
            ))
        })
        .collect();
    if !lacking.is_empty() {
        s.push_str("[report]\n");
        s.push_str(&lacking.concat());
    }
    if notation.name() == "duncan" {
        s.push_str("[parameters]\nlt = 2.5\n");
    }
    s.push_str("[dimensional]\nV = 250.0\nrho = 0.41\nS = 93.0\nchord = 6.6\nmass = 12000.0\n");
    s
}

/// Every file the fuzzer starts from: each notation's, and AVL's.
fn bases() -> Vec<String> {
    let mut v: Vec<String> = Notation::all().map(valid_file).collect();
    v.push(
        "notation = \"avl\"\nst_file = \"tailless-delta.st\"\n[dimensional]\nmass = 9000.0\nI_y = 60000.0\nrho = 1.225\nV = 102.0\n"
            .to_string(),
    );
    v.push(std::fs::read_to_string(examples().join("tailless-delta-45.toml")).unwrap());
    v.push(std::fs::read_to_string(examples().join("boeing-747-american-cl.toml")).unwrap());
    v.extend(dimensional_bases());
    v
}

/// The published aircraft (`notation = "dimensional"`, body and stability
/// axes, ft and SI, with and without `[reference]`).
fn dimensional_bases() -> Vec<String> {
    let mut paths: Vec<PathBuf> = std::fs::read_dir(examples().join("aircraft"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    paths.sort();
    paths
        .iter()
        .map(|p| std::fs::read_to_string(p).unwrap())
        .collect()
}

/// The property for a dimensional set as `quartic` reads it: an analysis
/// whose roots, modes and coefficients are finite, or a short located
/// error.
fn check_dimensional(text: &str) -> Result<(), String> {
    use stability_io::input::dimensional_notation as dn;
    let analysis = dn::parse(&fuzz_path(), text).and_then(|f| f.analysis());
    match analysis {
        Ok(a) => {
            let finite = a.quartic.is_finite()
                && a.roots.iter().all(|z| z.re.is_finite() && z.im.is_finite())
                && a.modes
                    .iter()
                    .all(|m| m.re.is_finite() && m.natural_frequency.is_finite());
            if finite {
                Ok(())
            } else {
                Err(format!("not finite: {:?}", a.roots))
            }
        }
        Err(e) => located_and_short(&e.to_string()),
    }
}

/// What a field's value may be replaced by.
fn values() -> impl Strategy<Value = String> {
    prop_oneof![
        Just("1e308".to_string()),
        Just("-1.7e308".to_string()),
        Just("1.7976931348623157e308".to_string()),
        Just("5e-324".to_string()),
        Just("1e-320".to_string()),
        Just("0.0".to_string()),
        Just("-0.0".to_string()),
        Just("nan".to_string()),
        Just("inf".to_string()),
        Just("-inf".to_string()),
        Just("-1".to_string()),
        Just("\"text\"".to_string()),
        Just("true".to_string()),
        Just("[1, 2]".to_string()),
        Just(format!("\"{}\"", "a".repeat(100_000))),
        Just(format!("{}1.0", " ".repeat(70_000))),
        Just(String::new()),
        (-1e6f64..1e6).prop_map(|x| format!("{x:e}")),
        (-300i32..300).prop_map(|e| format!("1e{e}")),
    ]
}

/// A damage to a file.
#[derive(Debug, Clone)]
enum Damage {
    Value(usize, String),
    Key(usize, String),
    Delete(usize),
    Repeat(usize),
    Prefix(usize, usize),
    Append(String),
}

fn damages() -> impl Strategy<Value = Damage> {
    prop_oneof![
        (0usize..40, values()).prop_map(|(l, v)| Damage::Value(l, v)),
        (0usize..40, "[a-zA-Z_]{1,12}").prop_map(|(l, k)| Damage::Key(l, k)),
        (0usize..40).prop_map(Damage::Delete),
        (0usize..40).prop_map(Damage::Repeat),
        (0usize..40, prop_oneof![Just(1usize), Just(70_000usize)])
            .prop_map(|(l, n)| Damage::Prefix(l, n)),
        prop_oneof![
            Just("[report]\nmu1 = 1e6".to_string()),
            Just("[flight]\nc_l = 0.3".to_string()),
            Just("[derivatives]\nm_q = -1.0".to_string()),
            Just("[parameters]\nlt = 3.0".to_string()),
            Just("st_file = \"tailless-delta.st\"".to_string()),
            Just("[dimensional]\nI_y = 1e308".to_string()),
            Just(format!("[{}]", "x".repeat(100_000))),
        ]
        .prop_map(Damage::Append),
    ]
}

fn damage(text: &str, d: &Damage) -> String {
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    let n = lines.len();
    match d {
        Damage::Value(l, v) => {
            let l = &mut lines[l % n];
            if let Some((k, _)) = l.split_once('=') {
                *l = format!("{k}= {v}");
            }
        }
        Damage::Key(l, k) => {
            let l = &mut lines[l % n];
            if let Some((_, v)) = l.split_once('=') {
                *l = format!("{k} ={v}");
            }
        }
        Damage::Delete(l) => {
            lines.remove(l % n);
        }
        Damage::Repeat(l) => {
            let copy = lines[l % n].clone();
            lines.insert(l % n, copy);
        }
        Damage::Prefix(l, k) => {
            let l = &mut lines[l % n];
            *l = format!("{}{l}", " ".repeat(*k));
        }
        Damage::Append(t) => lines.push(t.clone()),
    }
    lines.join("\n")
}

/// The property: a result whose every value is finite, or a short error
/// located at `file:line:column`.
fn check(outcome: Result<stability_io::input::DerivativeFile, Failure>) -> Result<(), String> {
    match outcome {
        Ok(f) => {
            let d = f.derivatives;
            if !d.quartic_input_values().iter().all(|v| v.is_finite()) {
                return Err(format!("a non-finite derivative: {d:?}"));
            }
            if !(d.mu1 > 0.0 && d.i_b > 0.0) {
                return Err(format!("μ₁ = {}, i_B = {}", d.mu1, d.i_b));
            }
            if let Some(v) = f.report.iter().flatten().find(|v| !v.is_finite()) {
                return Err(format!("a non-finite report value {v}"));
            }
            if let Some(dim) = f.dimensional {
                let all = [dim.v, dim.rho, dim.s, dim.chord, dim.mass];
                if !all.iter().all(|v| v.is_finite() && *v > 0.0) {
                    return Err(format!("{dim:?}"));
                }
            }
            Ok(())
        }
        Err(e) => located_and_short(&e.to_string()),
    }
}

/// The property for a config: a design point whose every value (and its
/// planform's derived sizes) is finite, or a short located error.
fn check_config(outcome: Result<stability_io::config::Config, Failure>) -> Result<(), String> {
    match outcome {
        Ok(c) => {
            let (case, p) = (&c.case, &c.case.planform);
            let all = [
                case.mach,
                case.h,
                case.mu1,
                case.i_b,
                case.cl_m2,
                p.area(),
                p.span(),
                p.mac(),
                p.aspect_ratio(),
            ];
            if all.iter().all(|v| v.is_finite()) {
                Ok(())
            } else {
                Err(format!("a value that is not finite: {all:?}"))
            }
        }
        Err(e) => located_and_short(&e.to_string()),
    }
}

fn located_and_short(message: &str) -> Result<(), String> {
    if message.len() > SHORT {
        return Err(format!("{} bytes of message", message.len()));
    }
    let first = message.lines().next().unwrap_or("");
    let mut parts = first.splitn(4, ':');
    let (file, line, column) = (parts.next(), parts.next(), parts.next());
    let number =
        |s: Option<&str>| s.is_some_and(|s| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit()));
    if file.is_some_and(|f| !f.is_empty()) && number(line) && number(column) {
        Ok(())
    } else {
        Err(format!("not located at file:line:column: {first}"))
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    #[test]
    fn damaged_files_of_every_notation_give_finite_values_or_a_located_error(
        base in 0usize..24,
        first in damages(),
        second in proptest::option::of(damages()),
    ) {
        let bases = bases();
        let mut text = damage(&bases[base % bases.len()], &first);
        if let Some(d) = &second {
            text = damage(&text, d);
        }
        let outcome = stability_io::input::parse(&fuzz_path(), &text);
        prop_assert!(check(outcome).is_ok(), "{:?}", check(stability_io::input::parse(&fuzz_path(), &text)));
    }

    #[test]
    fn damaged_dimensional_sets_give_finite_modes_or_a_located_error(
        base in 0usize..16,
        first in damages(),
        second in proptest::option::of(damages()),
    ) {
        let bases = dimensional_bases();
        let mut text = damage(&bases[base % bases.len()], &first);
        if let Some(d) = &second {
            text = damage(&text, d);
        }
        let verdict = check_dimensional(&text);
        prop_assert!(verdict.is_ok(), "{:?}\n{}", verdict, text);
    }

    #[test]
    fn damaged_configs_give_a_design_point_or_a_located_error(
        first in damages(),
        second in proptest::option::of(damages()),
    ) {
        let base = std::fs::read_to_string(examples().join("delta-45.toml")).unwrap();
        let mut text = damage(&base, &first);
        if let Some(d) = &second {
            text = damage(&text, d);
        }
        let verdict = check_config(stability_io::config::parse(&fuzz_path(), &text));
        prop_assert!(verdict.is_ok(), "{:?}", verdict);
    }

    #[test]
    fn arbitrary_text_never_panics_and_errors_are_located(text in "\\PC{0,400}") {
        if let Err(e) = stability_io::input::parse("fuzz.toml", &text) {
            let m = e.to_string();
            prop_assert!(located_and_short(&m).is_ok(), "{:?}", located_and_short(&m));
        }
    }
}

/// The inputs fuzzing found wrong (issue 10), kept as files: each must
/// satisfy the same property (`*.config.toml` as design-point configs).
#[test]
fn the_corpus_of_past_failures_satisfies_the_property() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fuzz-corpus");
    let mut n = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        let name = path.display().to_string();
        if !name.ends_with(".toml") {
            continue;
        }
        let text = expand(&std::fs::read_to_string(&path).unwrap());
        let verdict = if name.ends_with(".config.toml") {
            check_config(stability_io::config::parse(&name, &text))
        } else {
            check(stability_io::input::parse(&name, &text))
        };
        if let Err(e) = verdict {
            panic!("{name}: {e}");
        }
        n += 1;
    }
    assert!(n >= 10, "{n} corpus files");
}

/// A line `# repeat N` makes `⟨c⟩` in the next line N copies of `c` (the
/// corpus keeps its long lines and long strings small on disk; the
/// directive's line stays, empty, so that line numbers hold).
fn expand(text: &str) -> String {
    let mut out = Vec::new();
    let mut repeat = None;
    for line in text.lines() {
        if let Some(n) = line.strip_prefix("# repeat ") {
            repeat = n.trim().parse::<usize>().ok();
            out.push(String::new());
            continue;
        }
        let expanded = match (repeat.take(), line.find('⟨')) {
            (Some(n), Some(i)) => {
                let rest = &line[i + '⟨'.len_utf8()..];
                let c = rest.chars().next().unwrap_or(' ');
                let after = rest[c.len_utf8()..].trim_start_matches('⟩');
                format!("{}{}{after}", &line[..i], c.to_string().repeat(n))
            }
            _ => line.to_string(),
        };
        out.push(expanded);
    }
    out.join("\n")
}

#[test]
fn the_corpus_expands_as_documented() {
    assert_eq!(expand("# repeat 3\nx = \"⟨a⟩\"\ny"), "\nx = \"aaa\"\ny");
}

/// The DATCOM fixture with line `l` damaged: a token replaced by `v`,
/// the line deleted, repeated or shifted right by `k` columns.
fn damage_datcom(text: &str, l: usize, how: u8, v: &str, k: usize) -> String {
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    let n = lines.len();
    let i = l % n;
    match how % 4 {
        0 => {
            let words: Vec<&str> = lines[i].split_whitespace().collect();
            if let Some(w) = words.get(k % words.len().max(1)) {
                lines[i] = lines[i].replacen(w, v, 1);
            }
        }
        1 => {
            lines.remove(i);
        }
        2 => {
            let copy = lines[i].clone();
            lines.insert(i, copy);
        }
        _ => lines[i] = format!("{}{}", " ".repeat(k % 12), lines[i]),
    }
    lines.join("\n")
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    /// A damaged DATCOM output gives finite points whose tables are made
    /// or refused, or an error at its line and column (or, with no table
    /// left, one naming the file): never a panic.
    #[test]
    fn damaged_datcom_outputs_give_finite_points_or_a_located_error(
        l in 0usize..1400, how in 0u8..4, v in values(), k in 0usize..14,
        l2 in 0usize..1400, how2 in 0u8..4,
    ) {
        let base = include_str!("fixtures/datcom/delta60_h0.0.out");
        let text = damage_datcom(&damage_datcom(base, l, how, &v, k), l2, how2, &v, k + 1);
        match stability_io::input::datcom::parse("d.out", &text) {
            Ok(o) => {
                for p in &o.points {
                    let all = [p.mach, p.reference.area, p.reference.length, p.reference.moment_x];
                    prop_assert!(all.iter().all(|x| x.is_finite()), "{p:?}");
                    let given = [p.cd, p.cla, p.cma, p.clq, p.cmq, p.clad, p.cmad];
                    prop_assert!(given.iter().flatten().all(|x| x.is_finite()), "{p:?}");
                }
                let wing = stability_core::geometry::Planform::new(
                    60f64.to_radians(), 0.0, stability_core::geometry::Size::RootChord(10.0),
                ).unwrap();
                let _ = stability_core::data::datcom::tables(&o.points, &wing, o.apex_x);
            }
            Err(e) => {
                let m = e.to_string();
                prop_assert!(
                    located_and_short(&m).is_ok() || m.starts_with("d.out: no static or dynamic"),
                    "{m}"
                );
            }
        }
    }
}
