//! The frequency table's accuracy (`lifting_surface::FrequencyTable`, what
//! `sweep --damping lifting-surface-frequency` interpolates in): for each
//! wing and Mach number, the table against direct solves at 50 ω̄ between
//! its nodes (geometric from 0.002 to 4), at the default lattice. "worst" is
//! each number's largest |interpolated − direct| over max(|direct|, a tenth
//! of its largest |direct| on the range) — a relative error, floored where
//! the number passes through zero — for the six numbers of the solution and
//! the damping derivatives about h = 0.25 they make.
//!
//! `cargo run --release -p stability-core --example lifting_surface_interpolation`
//! prints the table of `docs/damping-theories.md`.

use stability_core::aerodynamics::lifting_surface::{
    FrequencyTable, Lattice, LatticeSpec, Solution,
};
use stability_core::geometry::Trapezoid;

const NAMES: [&str; 10] = [
    "ℓ_α",
    "μ_α",
    "ℓ_α̇",
    "μ_α̇",
    "ℓ_q",
    "μ_q",
    "z_ẇ(¼)",
    "m_ẇ(¼)",
    "z_q(¼)",
    "m_q(¼)",
];

fn numbers(s: &Solution) -> [f64; 10] {
    let d = s.derivatives(0.25, 0.0).unwrap();
    [
        s.lift_alpha,
        s.moment_alpha,
        s.lift_alphadot,
        s.moment_alphadot,
        s.lift_q,
        s.moment_q,
        d.z_wdot,
        d.m_wdot,
        d.z_q,
        d.m_q,
    ]
}

fn wings() -> Vec<(&'static str, Trapezoid, f64)> {
    let note = |deg: f64, taper: f64| {
        let t = deg.to_radians().tan();
        Trapezoid::new(1.0, taper, (1.0 - taper) / t, deg.to_radians()).unwrap()
    };
    vec![
        ("delta 45°", note(45.0, 0.0), 0.5),
        ("delta 45°", note(45.0, 0.0), 0.8),
        ("delta 45°", note(45.0, 0.0), 0.9),
        ("delta 60°", note(60.0, 0.0), 0.5),
        ("delta 60°", note(60.0, 0.0), 0.8),
        ("cropped 45°, λ = 1/7", note(45.0, 1.0 / 7.0), 0.8),
        (
            "delta A = 0.5",
            Trapezoid::from_aspect_ratio(0.5, 0.0, 8f64.atan(), 1.0).unwrap(),
            0.9,
        ),
        (
            "trapezoid A = 8, λ = 0.4, Λ = 30°",
            Trapezoid::from_aspect_ratio(8.0, 0.4, 30f64.to_radians(), 1.0).unwrap(),
            0.6,
        ),
    ]
}

fn main() {
    let tests: Vec<f64> = (0..50)
        .map(|i| 0.002 * 2000f64.powf(i as f64 / 49.0))
        .collect();
    println!("| wing | M | {} | nodes solved |", NAMES.join(" | "));
    println!("|{}", " --- |".repeat(NAMES.len() + 3));
    for (name, wing, mach) in wings() {
        let lattice = Lattice::new(&wing, LatticeSpec::for_wing(&wing)).unwrap();
        let table = FrequencyTable::new(lattice.clone(), mach).unwrap();
        let direct: Vec<[f64; 10]> = tests
            .iter()
            .map(|&w| numbers(&lattice.solve(mach, w).unwrap()))
            .collect();
        let table_values: Vec<[f64; 10]> = tests
            .iter()
            .map(|&w| numbers(&table.at(w).unwrap()))
            .collect();
        let worst: Vec<String> = (0..NAMES.len())
            .map(|k| {
                let scale = direct.iter().map(|v| v[k].abs()).fold(0.0, f64::max);
                let e = direct
                    .iter()
                    .zip(&table_values)
                    .map(|(d, t)| (t[k] - d[k]).abs() / d[k].abs().max(0.1 * scale))
                    .fold(0.0, f64::max);
                format!("{e:.1e}")
            })
            .collect();
        println!(
            "| {name} | {mach} | {} | {} |",
            worst.join(" | "),
            table.solved()
        );
    }
}
