//! The lattice's α̇ derivatives against ω̄ as ω̄ → 0, beside the exact
//! quasi-steady solve (ω̄ = 0: the kernel's first-order term): with the
//! exact kernel (I₁ by quadrature) the harmonic values tend to it as
//! O(ω̄ ln ω̄); with Desmarais' and Laschka's approximations they stop at
//! the approximation's error. A small lattice (6 × 8, not extrapolated), the
//! note's 60° delta at M = 0.5 and the 45° delta at M = 0.8.
//!
//! `cargo run --release -p stability-core --example lifting_surface_frequency`

use stability_core::aerodynamics::lifting_surface::{
    I1Approximation, Lattice, LatticeSpec, Spacing,
};
use stability_core::geometry::Trapezoid;

fn main() {
    println!(
        "| wing | M | ω̄ | z_ẇ exact | z_ẇ Desmarais | z_ẇ Laschka | m_ẇ(0) exact | m_ẇ(0) Desmarais | m_ẇ(0) Laschka |"
    );
    println!("| --- | --- | --- | --- | --- | --- | --- | --- | --- |");
    for (name, deg, mach) in [("delta 60°", 60.0f64, 0.5), ("delta 45°", 45.0, 0.8)] {
        let t = deg.to_radians().tan();
        let wing = Trapezoid::new(1.0, 0.0, 1.0 / t, deg.to_radians()).unwrap();
        let spec = LatticeSpec::new(6, 8, Spacing::Auto);
        let lattices = [
            I1Approximation::Quadrature,
            I1Approximation::Desmarais,
            I1Approximation::Laschka,
        ]
        .map(|k| Lattice::new(&wing, spec.with_kernel(k)).unwrap());
        for w in [0.1, 0.03, 0.01, 0.003, 0.001, 0.0] {
            let d: Vec<_> = lattices
                .iter()
                .map(|l| l.solve(mach, w).unwrap().derivatives(0.0, 0.0).unwrap())
                .collect();
            let label = if w == 0.0 {
                "0 (quasi-steady)".to_string()
            } else {
                w.to_string()
            };
            println!(
                "| {name} | {mach} | {label} | {:.4} | {:.4} | {:.4} | {:.4} | {:.4} | {:.4} |",
                d[0].z_wdot, d[1].z_wdot, d[2].z_wdot, d[0].m_wdot, d[1].m_wdot, d[2].m_wdot
            );
        }
    }
}
