//! The oscillatory solution against panelaero's (DLR's public
//! doublet-lattice implementation, an independent code:
//! `scripts/panelaero_fixtures.py` writes the fixture) on the same lattice
//! — same boxes, collocation points and loads — so that the two differ only
//! in how each integrates the kernel across a doublet line: panelaero fits
//! Rodden, Taylor & McIntosh's quartic across every line, with Desmarais'
//! I₁; ours is the same except that a line far from the receiving point
//! (|ȳ| > 6e) is integrated by two-point Gauss and a line on the receiving
//! point's own strip by graded pieces (doublet_line.rs). The fixture also
//! fixes panelaero's conventions (k = ω/V per unit length, e^{iωt}, w
//! positive as an incidence), which its script checks.

use serde_json::Value;
use stability_core::aerodynamics::lifting_surface::{Lattice, LatticeSpec, LineRule, Spacing};
use stability_core::geometry::Trapezoid;

#[test]
fn the_quartic_rule_is_panelaeros_method() {
    assert!(
        worst_difference(LineRule::Quartic)
            .iter()
            .all(|w| *w < 2e-5)
    );
}

#[test]
fn the_graded_rule_differs_from_it_by_the_quartics_error() {
    let worst = worst_difference(LineRule::Graded);
    assert!(worst.iter().all(|w| *w < 0.015), "{worst:?}");
    // the steady parts do not depend on the rule
    assert!(worst[0] < 1e-3 && worst[4] < 1e-3, "{worst:?}");
}

fn worst_difference(rule: LineRule) -> [f64; 6] {
    let fixture: Value =
        serde_json::from_str(include_str!("../data/lifting_surface/panelaero.json")).unwrap();
    let keys = [
        "lift_alpha",
        "moment_alpha",
        "lift_alphadot",
        "moment_alphadot",
        "lift_q",
        "moment_q",
    ];
    let mut worst = [0.0f64; 6];
    for c in fixture["cases"].as_array().unwrap() {
        let get = |k: &str| c[k].as_f64().unwrap();
        let wing = Trapezoid::new(
            1.0,
            get("taper"),
            get("semi_span"),
            get("sweep_deg").to_radians(),
        );
        let spacing = match c["spacing"].as_str().unwrap() {
            "Cosine" => Spacing::Cosine,
            "RootCosine" => Spacing::RootCosine,
            _ => Spacing::Uniform,
        };
        let n = |k: &str| c[k].as_u64().unwrap() as usize;
        let spec = LatticeSpec::new(n("chordwise"), n("spanwise"), spacing).with_line_rule(rule);
        let lattice = Lattice::new(&wing.unwrap(), spec).unwrap();
        let first = lattice.boxes()[0];
        let fc = c["first_collocation"].as_array().unwrap();
        assert!((first.x_c - fc[0].as_f64().unwrap()).abs() < 1e-12);
        assert!((first.y_c - fc[1].as_f64().unwrap()).abs() < 1e-12);
        let s = lattice.solve(get("mach"), get("omega_bar")).unwrap();
        let ours = [
            s.lift_alpha,
            s.moment_alpha,
            s.lift_alphadot,
            s.moment_alphadot,
            s.lift_q,
            s.moment_q,
        ];
        for (k, key) in keys.iter().enumerate() {
            let theirs = get(key);
            let err = (ours[k] - theirs).abs() / theirs.abs().max(0.1);
            println!(
                "{rule:?} {} {key}: ours {:.6} panelaero {theirs:.6} ({err:.2e})",
                c["name"], ours[k]
            );
            worst[k] = worst[k].max(err);
        }
    }
    println!("{rule:?}: largest relative differences {worst:?}");
    worst
}
