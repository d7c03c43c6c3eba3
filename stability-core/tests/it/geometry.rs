//! §2.2's formulas against each other and against a numerical integration
//! over the planform (composite Simpson's rule on the chord distribution).

use stability_core::geometry::{Planform, Size, cropped_h};
use std::f64::consts::PI;

/// Simpson's rule on [0, s] with n (even) panels.
fn simpson(f: impl Fn(f64) -> f64, s: f64, n: usize) -> f64 {
    let h = s / n as f64;
    let mut acc = f(0.0) + f(s);
    for i in 1..n {
        acc += f(i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
    }
    acc * h / 3.0
}

fn cases() -> Vec<Planform> {
    let mut v = Vec::new();
    for sweep in [30.0f64, 45.0, 60.0, 75.0] {
        for taper in [0.0, 1.0 / 7.0, 0.3, 0.6] {
            v.push(Planform::new(sweep.to_radians(), taper, Size::RootChord(3.0)).unwrap());
        }
    }
    v
}

#[test]
fn printed_formulas_match_the_integrals() {
    for p in cases() {
        let s = p.semi_span();
        let tan = p.sweep_le.tan();
        let chord = |y: f64| p.root_chord - y * tan; // unswept trailing edge
        let le = |y: f64| y * tan;
        let n = 2000;
        let area = 2.0 * simpson(chord, s, n);
        let mac = 2.0 / area * simpson(|y| chord(y).powi(2), s, n);
        let x_bar = 2.0 / area * simpson(|y| le(y) * chord(y), s, n);
        let y_bar = 2.0 / area * simpson(|y| y * chord(y), s, n);
        let tol = 1e-12 * p.root_chord.powi(2);
        assert!((area - p.area()).abs() < tol, "{p:?}: S");
        assert!((mac - p.mac()).abs() < 1e-12, "{p:?}: M.A.C.");
        assert!((x_bar - p.x_mac()).abs() < 1e-12, "{p:?}: x̄");
        assert!((y_bar - p.y_mac()).abs() < 1e-12, "{p:?}: ȳ");
        // the printed forms against each other
        let l = p.taper;
        let smc = area / p.span();
        assert!((p.smc() - smc).abs() < 1e-12);
        assert!((p.mac() - 4.0 / 3.0 * smc * (1.0 - l / (1.0 + l).powi(2))).abs() < 1e-12);
        assert!((p.mac() - 2.0 / 3.0 * p.root_chord * (1.0 + l - l / (1.0 + l))).abs() < 1e-12);
        assert!((p.x_mac() - p.y_mac() * tan).abs() < 1e-12);
        let a1 = 2.0 * p.span() / (p.root_chord * (1.0 + l));
        let a2 = p.span().powi(2) / area;
        let a3 = 3.0 / p.quarter_chord_sweep().tan() * (1.0 - l) / (1.0 + l);
        for a in [a1, a2, a3] {
            assert!(
                (a - p.aspect_ratio()).abs() < 1e-12,
                "{p:?}: A {a} vs {}",
                p.aspect_ratio()
            );
        }
        // h = x₀/c̄ − (1 + λ − 2λ²)/(2(1 + λ + λ²))
        let h = 0.3;
        let xo = p.xo_over_root_chord(h) * p.root_chord;
        let printed = xo / p.mac() - (1.0 + l - 2.0 * l * l) / (2.0 * (1.0 + l + l * l));
        assert!((printed - h).abs() < 1e-12);
        // §7's x₀/c̄ₛ form
        let sec7 = 4.0 / 3.0 * h * (1.0 + l + l * l) / (1.0 + l).powi(2)
            + 2.0 / 3.0 * (1.0 - l) * (1.0 + 2.0 * l) / (1.0 + l).powi(2);
        assert!((p.xo_over_smc(h) - sec7).abs() < 1e-12);
        // the quarter-chord line through the integrated quarter-chord points
        let qc = |y: f64| le(y) + 0.25 * chord(y);
        assert!(((qc(s) - qc(0.0)) / s - p.quarter_chord_sweep().tan()).abs() < 1e-12);
    }
}

#[test]
fn section_7_numbers_for_taper_one_seventh() {
    // §7: x₀/c̄ = 1.190h + 0.560 for λ = 1/7 (the printed values are rounded
    // to three figures: 4/3·57/64 = 1.1875, 2/3·(6/7)(9/7)/(64/49) = 0.5625).
    let p = Planform::new(PI / 4.0, 1.0 / 7.0, Size::RootChord(1.0)).unwrap();
    let slope = p.xo_over_smc(1.0) - p.xo_over_smc(0.0);
    let intercept = p.xo_over_smc(0.0);
    assert!((slope - 1.1875).abs() < 1e-12 && (slope - 1.190).abs() < 0.005);
    assert!((intercept - 0.5625).abs() < 1e-12 && (intercept - 0.560).abs() < 0.005);
}

#[test]
fn tip_cropping_keeps_the_cg_fixed_in_space() {
    // A true delta's c.g. at h = 0.25 (x₀/c₀ = 0.5); cropped to λ = 1/7 with
    // the same apex and root chord: M.A.C. = (2/3)(57/56) = 0.67857c₀,
    // x̄ = (1/3)(54/56) = 0.32143c₀, so h = (0.5 − 0.32143)/0.67857 = 0.26316.
    let h = cropped_h(0.25, PI / 4.0, 1.0 / 7.0).unwrap();
    assert!((h - (0.5 - 54.0 / 168.0) / (114.0 / 168.0)).abs() < 1e-12);
    assert!((h - 0.26316).abs() < 1e-5);
}
