//! The AVL `.st` reader: values against the fixture's text, conversion into
//! the report's notation by hand, errors with line numbers, no panic on any
//! input.

use proptest::prelude::*;
use stability_core::data::notation::avl::{AvlError, parse_st, to_report};

const ST: &str = include_str!("../data/avl/tailless-delta.st");

#[test]
fn reads_the_fixture() {
    let st = parse_st(ST).unwrap();
    assert_eq!(
        (st.sref, st.cref, st.bref, st.xref),
        (60.0, 7.0, 11.547, 4.6667)
    );
    assert_eq!((st.alpha_deg, st.mach), (3.21460, 0.3));
    assert_eq!((st.cl, st.cd, st.cm), (0.15021, 0.00963, -0.0));
    assert_eq!((st.cd_ind, st.e), (Some(0.00363), Some(0.7610)));
    assert_eq!(
        (st.cl_a, st.cm_a, st.cl_q, st.cm_q),
        (2.694221, -0.672913, 4.108260, -2.401193)
    );
    assert_eq!(st.xnp, Some(5.21482));
}

#[test]
fn converts_into_the_report_notation_by_hand() {
    let r = to_report(&parse_st(ST).unwrap());
    assert_eq!(r.z_w, -2.694221 - 0.00963); // eq (12)
    assert_eq!(r.m_w, -0.672913); // eq (14)
    assert_eq!(r.z_q, -4.108260 / 2.0); // q̂ = qc/2V
    assert_eq!(r.m_q, -2.401193 / 2.0);
    assert_eq!(r.x_u, -2.0 * 0.00963);
    assert_eq!(r.z_u, -2.0 * 0.15021);
    // x_w = C_L − 2C_Di·C_Lα/C_L
    assert!((r.x_w - (0.15021 - 2.0 * 0.00363 * 2.694221 / 0.15021)).abs() < 1e-15);
    assert!(r.notes.iter().any(|n| n.contains("quasi-steady")));
}

#[test]
fn truncated_and_foreign_files_are_errors_with_line_numbers() {
    let lines: Vec<&str> = ST.lines().collect();
    // cut before Cmq (the "y  mom.  Cm |    Cmp" line)
    let cut = lines.iter().position(|l| l.contains("Cmq")).unwrap();
    let text = lines[..cut].join("\n");
    match parse_st(&text) {
        Err(AvlError::Missing {
            name: "Cmq",
            last_line,
        }) => assert_eq!(last_line, cut),
        other => panic!("{other:?}"),
    }
    // another program's output
    let e = parse_st("XFOIL output\n alpha = 3.0  CL = 0.4\n").unwrap_err();
    assert!(matches!(e, AvlError::NotStFile { line: 2, .. }), "{e:?}");
    // a garbled number in one of ours
    let bad = ST.replace("CLa =   2.694221", "CLa =   2.69x221");
    let e = parse_st(&bad).unwrap_err();
    let line = ST.lines().position(|l| l.contains("CLa =")).unwrap() + 1;
    assert_eq!(
        e,
        AvlError::BadNumber {
            name: "CLa".into(),
            line,
            text: "2.69x221".into()
        }
    );
    assert_eq!(parse_st("   \n"), Err(AvlError::Empty));
    // body axes only (no stability-axis block)
    let geo = ST.replace(
        "Stability-axis derivatives...",
        "Geometry-axis derivatives...",
    );
    assert!(matches!(
        parse_st(&geo),
        Err(AvlError::NoStabilityAxes { .. })
    ));
}

/// Fuzzing found `Sref = 0` reported as an overflow (μ₁ = m/(½ρSc̄)
/// divided by zero downstream): the reader names the real cause, with its
/// line.
#[test]
fn a_zero_or_negative_reference_quantity_is_named() {
    let line = ST.lines().position(|l| l.contains("Sref")).unwrap() + 1;
    for (name, what, printed) in [
        ("Sref", "area", "Sref =  60.000"),
        ("Cref", "chord", "Cref =  7.0000"),
        ("Bref", "span", "Bref =  11.547"),
    ] {
        for bad in ["0.0", "-7.0"] {
            let text = ST.replace(printed, &format!("{name} = {bad}"));
            let e = parse_st(&text).unwrap_err();
            assert!(
                matches!(e, AvlError::NotPositive { name: n, .. } if n == name),
                "{name} = {bad}: {e}"
            );
            assert_eq!(e.line(), line, "{e}");
            let m = e.to_string();
            assert!(
                m.contains(name) && m.contains(what) && m.contains("positive"),
                "{m}"
            );
            assert!(!m.contains("overflow"), "{m}");
        }
    }
}

#[test]
fn glued_negative_numbers_are_read() {
    let text = ST.replace("Cmq =  -2.401193", "Cmq =-12.401193");
    assert_eq!(parse_st(&text).unwrap().cm_q, -12.401193);
}

proptest! {
    #[test]
    fn no_input_panics(s in "\\PC{0,300}") {
        let _ = parse_st(&s);
    }

    #[test]
    fn no_truncation_panics(cut in 0usize..3000, junk in "\\PC{0,20}") {
        let cut = cut.min(ST.len());
        let mut t = ST.chars().take(cut).collect::<String>();
        t.push_str(&junk);
        if let Ok(st) = parse_st(&t) {
            prop_assert!(st.cl_a.is_finite() && st.cm_q.is_finite());
        }
    }
}
