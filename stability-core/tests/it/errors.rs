//! Error messages name the quantity, its value and the limit it breaks,
//! and never print a number the way `{}` prints 1e308 (309 digits): every
//! number goes through `display::Num`.

use stability_core::Derivatives;
use stability_core::aerodynamics::damping::{DampingError, Theory, WingInput, damping_derivatives};
use stability_core::aerodynamics::models::aero::{AeroError, Table};
use stability_core::analysis::{Analysis, AnalysisError};
use stability_core::design::case::{CaseError, CaseInput, DampingModel, evaluate};
use stability_core::design::examples::tailless_delta_45;
use stability_core::design::study::report_wing;
use stability_core::geometry::{GeometryError, Planform, Size};
use stability_core::numerics::invalid::Invalid;

/// No run of more than 20 digits: a number written in full.
fn assert_short(m: &str) {
    let mut run = 0;
    for c in m.chars() {
        run = if c.is_ascii_digit() { run + 1 } else { 0 };
        assert!(run <= 20, "a long number in: {m}");
    }
}

type Edit = fn(&mut stability_core::design::case::Case);

#[test]
fn case_errors_name_the_input() {
    let cases: [(Edit, CaseInput, &str); 6] = [
        (|c| c.mach = f64::NAN, CaseInput::Mach, "NaN"),
        (|c| c.mach = -1e308, CaseInput::Mach, "-1e308"),
        (|c| c.h = f64::INFINITY, CaseInput::Cg, "inf"),
        (|c| c.mu1 = 0.0, CaseInput::Mu1, "0"),
        (|c| c.i_b = -1e-310, CaseInput::IB, "-1e-310"),
        (|c| c.cl_m2 = -2.0, CaseInput::ClM2, "-2"),
    ];
    for (set, input, value) in cases {
        let mut c = report_wing(45.0, 0.9);
        set(&mut c);
        let e = evaluate(&c).unwrap_err();
        let q = match &e {
            CaseError::Invalid(invalid) => invalid.quantity(),
            other => panic!("{other}"),
        };
        assert_eq!(q, input);
        let m = e.to_string();
        assert!(m.contains(&input.to_string()) && m.contains(value), "{m}");
        assert_short(&m);
    }
}

#[test]
fn analysis_errors_name_the_derivative() {
    let d = Derivatives {
        m_q: f64::NEG_INFINITY,
        ..tailless_delta_45()
    };
    let e = Analysis::of(&d).unwrap_err();
    assert_eq!(
        e,
        AnalysisError::Invalid(Invalid::NonFinite {
            quantity: "m_q",
            value: f64::NEG_INFINITY
        })
    );
    assert_eq!(e.to_string(), "m_q must be a finite number, not -inf");
    let d = Derivatives {
        i_b: -1e308,
        ..tailless_delta_45()
    };
    let m = Analysis::of(&d).unwrap_err().to_string();
    assert_eq!(m, "i_b must be positive, not -1e308");
    // coefficients that overflow name the coefficient
    let d = Derivatives {
        m_w: -1e300,
        mu1: 1e300,
        ..tailless_delta_45()
    };
    let e = Analysis::of(&d).unwrap_err();
    assert!(matches!(e, AnalysisError::Overflow { .. }), "{e}");
    assert_short(&e.to_string());
}

#[test]
fn damping_aero_and_geometry_errors_write_numbers_short() {
    let wing = WingInput {
        aspect_ratio: 4.0,
        sweep_le: 45f64.to_radians(),
        taper: 0.0,
    };
    let e = damping_derivatives(Theory::Slender, &wing, f64::NAN, 0.9, None).unwrap_err();
    assert!(matches!(e, DampingError::Invalid { .. }));
    assert_eq!(
        e.to_string(),
        "slender: the c.g. position h must be a finite number, not NaN"
    );
    let tapered = WingInput {
        taper: 1e-300,
        ..wing
    };
    let e = damping_derivatives(Theory::GarnerTaper, &tapered, 0.25, 0.5, None).unwrap_err();
    assert!(e.to_string().ends_with("taper 1e-300"), "{e}");
    let e = damping_derivatives(Theory::Supersonic, &wing, 0.25, 1e-200, None).unwrap_err();
    assert_eq!(
        e.to_string(),
        "supersonic theory (36) needs M > 1, not M = 1e-200"
    );
    let e = damping_derivatives(Theory::TransonicFrequency, &wing, 0.25, 1.0, Some(-1e300))
        .unwrap_err();
    assert!(e.to_string().ends_with("ω̄ > 0, not -1e300"), "{e}");
    let e = Table::new(vec![1e308, 1e300], vec![1.0, 2.0]).unwrap_err();
    assert!(matches!(e, AeroError::NotIncreasing { row: 2, .. }));
    assert_eq!(
        e.to_string(),
        "row 2: Mach 1e300 does not increase on the row before (1e308); the Mach column must increase strictly"
    );
    let e = Planform::new(1.0, 0.0, Size::Area(-1e-320)).unwrap_err();
    assert_eq!(e, GeometryError::Size("area", -1e-320));
    assert_short(&e.to_string());
    let e = Planform::new(1e300, 0.0, Size::Area(1.0)).unwrap_err();
    assert_short(&e.to_string());
}

#[test]
fn unknown_names_are_quoted_as_excerpts() {
    let long = "x".repeat(100_000_000 / 1000);
    let e = long.parse::<Theory>().unwrap_err().to_string();
    assert!(e.len() < 300, "{} bytes", e.len());
    assert!(e.contains("`transonic-frequency`"));
    let e = DampingModel::parse("mangler").unwrap_err().to_string();
    assert!(e.starts_with("unknown damping theory `mangler`; the theories are `garrick`"));
    assert!(
        e.ends_with(
            "; or the fairings `faired` (the default), `faired-theories` and `faired-slender`"
        ),
        "{e}"
    );
}
