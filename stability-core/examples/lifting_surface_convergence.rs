//! The doublet lattice's convergence: every output of
//! `lifting_surface::Solution::derivatives` at the default lattice, at a
//! lattice twice as dense in each direction, and their difference against
//! the tolerance max(0.5 %, 0.005) — for the note's wings, cropped deltas and
//! aspect ratios from 0.5 to 8, quasi-steady at M = 0 and 0.8 and harmonic
//! at M = 0.5, ω̄ = 0.5. "default" is `LatticeSpec::for_wing` (chordwise ×
//! strips of the finest of its extrapolated lattices); "worst" is the
//! largest difference over the tolerance (≤ 1 passes).
//!
//! `cargo run --release -p stability-core --example lifting_surface_convergence`
//! prints the table (docs/damping-theories.md); with `--write` it also
//! writes the dense lattice's values to
//! `stability-core/tests/data/lifting_surface/convergence.json`, which
//! `tests/it/lifting_surface_convergence.rs` holds the default lattice to;
//! with `--check` it compares the dense values it computed with the
//! committed fixture instead (to 1e-9, relative) and fails if they differ.

use stability_core::aerodynamics::lifting_surface::{Lattice, LatticeSpec};
use stability_core::geometry::Trapezoid;

/// The wings: (name, wing).
pub fn wings() -> Vec<(&'static str, Trapezoid)> {
    let delta = |a: f64| Trapezoid::from_aspect_ratio(a, 0.0, (4.0 / a).atan(), 1.0).unwrap();
    let note = |deg: f64, taper: f64| {
        let t = deg.to_radians().tan();
        Trapezoid::new(1.0, taper, (1.0 - taper) / t, deg.to_radians()).unwrap()
    };
    vec![
        ("delta A = 0.5", delta(0.5)),
        ("delta A = 1", delta(1.0)),
        ("delta 60° (A = 2.31)", note(60.0, 0.0)),
        ("delta 45° (A = 4)", note(45.0, 0.0)),
        ("delta A = 8", delta(8.0)),
        ("cropped 60°, λ = 1/7", note(60.0, 1.0 / 7.0)),
        ("cropped 45°, λ = 1/7", note(45.0, 1.0 / 7.0)),
        (
            "trapezoid A = 4, λ = 0.5, Λ = 40°",
            Trapezoid::from_aspect_ratio(4.0, 0.5, 40f64.to_radians(), 1.0).unwrap(),
        ),
        (
            "trapezoid A = 8, λ = 0.4, Λ = 30°",
            Trapezoid::from_aspect_ratio(8.0, 0.4, 30f64.to_radians(), 1.0).unwrap(),
        ),
    ]
}

/// The flight conditions: (M, ω̄).
pub const CONDITIONS: [(f64, f64); 3] = [(0.0, 0.0), (0.8, 0.0), (0.5, 0.5)];

/// The outputs' names.
pub const NAMES: [&str; 12] = [
    "C_Lα",
    "H₀",
    "m_w(¼)",
    "z_ẇ",
    "m_ẇ(0)",
    "m_ẇ(¼)",
    "z_q(0)",
    "z_q(¼)",
    "m_q(0)",
    "m_q(¼)",
    "z_θ̇(¼)",
    "m_θ̇(¼)",
];

pub fn outputs(wing: &Trapezoid, spec: LatticeSpec, mach: f64, omega_bar: f64) -> [f64; 12] {
    let s = Lattice::new(wing, spec)
        .unwrap()
        .solve(mach, omega_bar)
        .unwrap();
    let (d0, d) = (
        s.derivatives(0.0, 0.0).unwrap(),
        s.derivatives(0.25, 0.0).unwrap(),
    );
    [
        d.lift_slope,
        d.aerodynamic_centre,
        d.m_w,
        d.z_wdot,
        d0.m_wdot,
        d.m_wdot,
        d0.z_q,
        d.z_q,
        d0.m_q,
        d.m_q,
        d.z_thetadot,
        d.m_thetadot,
    ]
}

/// The fixture's path.
const FIXTURE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/tests/data/lifting_surface/convergence.json"
);

/// The committed fixture's dense values, case by case, against `computed`
/// (in the same order): the cases that differ by more than 1e-9, relative.
fn stale(computed: &[[f64; 12]]) -> Result<Vec<String>, String> {
    let text = std::fs::read_to_string(FIXTURE).map_err(|e| format!("{FIXTURE}: {e}"))?;
    let f: serde_json::Value =
        serde_json::from_str(&text).map_err(|e| format!("{FIXTURE}: {e}"))?;
    let cases = f["cases"].as_array().ok_or("no cases")?;
    if cases.len() != computed.len() {
        return Ok(vec![format!(
            "{} cases, not {}",
            cases.len(),
            computed.len()
        )]);
    }
    let mut out = Vec::new();
    for (c, fine) in cases.iter().zip(computed) {
        let dense: Vec<f64> = c["dense"]
            .as_array()
            .ok_or("no dense")?
            .iter()
            .filter_map(|v| v.as_f64())
            .collect();
        let same = dense.len() == 12
            && dense
                .iter()
                .zip(fine)
                .all(|(y, x)| (x - y).abs() <= 1e-9 * (1.0 + y.abs()));
        if !same {
            out.push(format!(
                "{} at M = {}, ω̄ = {}",
                c["wing"], c["mach"], c["omega_bar"]
            ));
        }
    }
    Ok(out)
}

fn main() {
    let write = std::env::args().any(|a| a == "--write");
    let check = std::env::args().any(|a| a == "--check");
    let mut computed = Vec::new();
    let mut fixture = Vec::new();
    println!("| wing | M | ω̄ | lattice | {} | worst |", NAMES.join(" | "));
    println!("|{}", " --- |".repeat(NAMES.len() + 5));
    for (name, wing) in wings() {
        let spec = LatticeSpec::for_wing(&wing);
        for (mach, omega_bar) in CONDITIONS {
            let coarse = outputs(&wing, spec.scaled(1), mach, omega_bar);
            let fine = outputs(&wing, spec.scaled(2), mach, omega_bar);
            let ratio = |k: usize| (coarse[k] - fine[k]).abs() / (0.005 * fine[k].abs()).max(0.005);
            let worst = (0..NAMES.len()).map(ratio).fold(0.0, f64::max);
            let row = |v: &[f64; 12]| {
                v.iter()
                    .map(|x| format!("{x:.4}"))
                    .collect::<Vec<_>>()
                    .join(" | ")
            };
            let lattice = format!("{}×{}", spec.chordwise, spec.spanwise);
            println!(
                "| {name} | {mach} | {omega_bar} | {lattice} | {} | {worst:.2} |",
                row(&coarse)
            );
            println!("| | | | ×2 | {} | |", row(&fine));
            computed.push(fine);
            fixture.push(format!(
                "  {{\"wing\": \"{name}\", \"root_chord\": {}, \"tip_chord\": {}, \"semi_span\": {}, \"sweep_le\": {}, \"mach\": {mach}, \"omega_bar\": {omega_bar}, \"dense\": [{}]}}",
                wing.root_chord, wing.tip_chord, wing.semi_span, wing.sweep_le,
                fine.iter().map(|x| format!("{x:e}")).collect::<Vec<_>>().join(", ")
            ));
        }
    }
    if check {
        match stale(&computed) {
            Ok(bad) if bad.is_empty() => eprintln!("{FIXTURE} is the dense lattice's"),
            Ok(bad) => {
                eprintln!(
                    "{FIXTURE} differs from the dense lattice for:\n  {}",
                    bad.join("\n  ")
                );
                std::process::exit(1);
            }
            Err(e) => {
                eprintln!("{e}");
                std::process::exit(1);
            }
        }
    }
    if write {
        let path = FIXTURE;
        let text = format!(
            "{{\"source\": \"cargo run --release -p stability-core --example lifting_surface_convergence -- --write: the default lattice scaled 2x\",\n \"names\": [{}],\n \"cases\": [\n{}\n ]}}\n",
            NAMES.map(|n| format!("\"{n}\"")).join(", "),
            fixture.join(",\n")
        );
        std::fs::write(path, text).unwrap();
        eprintln!("wrote {path}");
    }
}
