//! The lifting surface across M = 1 (`lifting_surface::mach_range`): the
//! near-sonic lattice up to M = 1 and the Mach box from its first Mach
//! number, at ω̄ = 0.6, on the wings given (h = 0.25). Numbers for
//! `docs/lattice-near-sonic.md`, "Across M = 1".
//!
//! `cargo run --release -p stability-core --example lifting_surface_mach_range`

use stability_core::aerodynamics::lifting_surface::mach_range::{first_mach_box_mach, solution};
use stability_core::aerodynamics::lifting_surface::{Harmonic, Trapezoid, store};

fn main() {
    let wings = [
        ("rectangle A = 2", store::unit_wing(2.0, 1.0, 0.0)),
        (
            "A = 3, λ = 0.5, Λ = 10°",
            store::unit_wing(3.0, 0.5, 10f64.to_radians()),
        ),
        // the note's deltas: A = 4 cot Λ (45°: 4, 60°: 2.309)
        ("delta 45°", store::unit_wing(4.0, 0.0, 45f64.to_radians())),
        (
            "delta 60°",
            store::unit_wing(4.0 / 3f64.sqrt(), 0.0, 60f64.to_radians()),
        ),
    ];
    for (name, wing) in wings {
        let wing: Trapezoid = wing.expect("a valid wing");
        let first = first_mach_box_mach(&wing);
        println!("{name}: Mach box from M = {first:.5}");
        println!("| M | method | C_Lα | H₀ | z_θ̇ | m_θ̇ | z_ẇ | m_ẇ |");
        println!("|---|---|---|---|---|---|---|---|");
        for m in [0.98, 0.99, 1.0, first, 1.02, 1.03, 1.05, 1.1, 1.2, 1.3] {
            match solution(&wing, m, 0.6, Harmonic::Direct) {
                Ok(at) => {
                    let s = at.solution;
                    let d = s.derivatives(0.25, 0.0).expect("finite");
                    println!(
                        "| {m:.4} | {:?} | {:.4} | {:.4} | {:.4} | {:.4} | {:.4} | {:.4} |",
                        at.method,
                        s.lift_slope(),
                        s.aerodynamic_centre(),
                        d.z_thetadot,
                        d.m_thetadot,
                        d.z_wdot,
                        d.m_wdot
                    );
                }
                Err(e) => println!("| {m:.4} | error: {e} |"),
            }
        }
    }
}
