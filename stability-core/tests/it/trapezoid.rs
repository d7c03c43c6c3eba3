//! `geometry::Trapezoid` against a numerical integration over the planform
//! (composite Simpson's rule on the chord distribution), and against
//! `Planform`'s §2.2 formulas for the wings both describe.

use stability_core::geometry::{Planform, Size, Trapezoid, TrapezoidError};
use std::f64::consts::PI;

fn simpson(f: impl Fn(f64) -> f64, s: f64, n: usize) -> f64 {
    let h = s / n as f64;
    let mut acc = f(0.0) + f(s);
    for i in 1..n {
        acc += f(i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
    }
    acc * h / 3.0
}

#[test]
fn the_formulas_are_the_integrals() {
    for (cr, ct, s, sweep) in [
        (2.0, 0.5, 3.0, 0.6),
        (1.0, 1.0, 5.0, 0.0),
        (1.0, 0.0, 0.6, 1.2),
        (1.5, 2.0, 1.0, -0.3),
        (1.0, 0.3, 4.0, 0.5),
    ] {
        let w = Trapezoid::new(cr, ct, s, sweep).unwrap();
        let chord = |y: f64| cr + (ct - cr) * y / s;
        let le = |y: f64| y * sweep.tan();
        let n = 2000;
        let area = 2.0 * simpson(chord, s, n);
        let mac = 2.0 / area * simpson(|y| chord(y).powi(2), s, n);
        let y_bar = 2.0 / area * simpson(|y| y * chord(y), s, n);
        let x_bar = 2.0 / area * simpson(|y| le(y) * chord(y), s, n);
        assert!((area - w.area()).abs() < 1e-12, "{w:?}");
        assert!((mac - w.mac()).abs() < 1e-12, "{w:?}");
        assert!((y_bar - w.y_mac()).abs() < 1e-12, "{w:?}");
        assert!((x_bar - w.x_mac()).abs() < 1e-12, "{w:?}");
        assert!((w.aspect_ratio() - 4.0 * s * s / area).abs() < 1e-12);
        // the trailing edge: x_le + c at the tip
        let te_tip = le(s) + ct;
        assert!((w.sweep_te().tan() - (te_tip - cr) / s).abs() < 1e-12);
        // from_aspect_ratio round-trips
        let again = Trapezoid::from_aspect_ratio(w.aspect_ratio(), w.taper(), sweep, cr).unwrap();
        assert!((again.semi_span - s).abs() < 1e-12);
    }
}

#[test]
fn a_planform_is_a_trapezoid_with_an_unswept_trailing_edge() {
    for sweep in [30.0f64, 45.0, 60.0, 75.0] {
        for taper in [0.0, 1.0 / 7.0, 0.5] {
            let p = Planform::new(sweep.to_radians(), taper, Size::RootChord(2.0)).unwrap();
            let t = Trapezoid::from(&p);
            assert!(t.sweep_te().abs() < 1e-12);
            for (a, b) in [
                (t.area(), p.area()),
                (t.span(), p.span()),
                (t.aspect_ratio(), p.aspect_ratio()),
                (t.mac(), p.mac()),
                (t.reference_chord(), p.reference_chord()),
                (t.x_mac(), p.x_mac()),
                (t.y_mac(), p.y_mac()),
                (t.taper(), p.taper),
                (t.sweep_at(0.25), p.quarter_chord_sweep()),
            ] {
                assert!(
                    (a - b).abs() < 1e-12 * (1.0 + b.abs()),
                    "{sweep} {taper}: {a} {b}"
                );
            }
        }
    }
}

#[test]
fn the_affine_wing_keeps_the_chords() {
    let w = Trapezoid::new(1.0, 0.2, 2.0, 0.8).unwrap();
    let a = w.affine(0.6).unwrap();
    assert!((a.aspect_ratio() - 0.6 * w.aspect_ratio()).abs() < 1e-12);
    assert!((a.sweep_le.tan() - w.sweep_le.tan() / 0.6).abs() < 1e-12);
    assert!((a.mac() - w.mac()).abs() < 1e-15 && (a.x_mac() - w.x_mac()).abs() < 1e-12);
}

#[test]
fn bad_trapezoids_name_the_field() {
    assert_eq!(
        Trapezoid::new(0.0, 0.1, 1.0, 0.0),
        Err(TrapezoidError::Length("root chord", 0.0))
    );
    assert_eq!(
        Trapezoid::new(1.0, -0.1, 1.0, 0.0),
        Err(TrapezoidError::TipChord(-0.1))
    );
    assert!(matches!(
        Trapezoid::new(1.0, 0.1, f64::NAN, 0.0),
        Err(TrapezoidError::Length("semi-span", _))
    ));
    assert!(matches!(
        Trapezoid::new(1.0, 0.1, 1.0, PI / 2.0),
        Err(TrapezoidError::Sweep(_))
    ));
    assert!(matches!(
        Trapezoid::new(1.0, 0.1, 1.0, f64::NAN),
        Err(TrapezoidError::Sweep(_))
    ));
    assert!(Trapezoid::from_aspect_ratio(-1.0, 0.5, 0.0, 1.0).is_err());
    // a pointed tip is a wing
    assert!(Trapezoid::new(1.0, 0.0, 1.0, 0.0).unwrap().area() > 0.0);
}
