//! The doublet lattice near M = 1: chordwise convergence at M = 0.95 and
//! 0.98 (the tables of `docs/lattice-near-sonic.md`), and the approach to
//! the sonic point at fixed ω̄ (`lifting_surface::near_sonic`).
//!
//! For the note's 45° and 60° deltas at ω̄ = 0, 0.3, 0.6: z_θ̇, m_θ̇ (about
//! h = 0.25), C_Lα and H₀ of single lattices of N = 12, 24, 48, 96 boxes per
//! strip on the default 16 strips, the observed order of convergence
//! p = log₂(|X₂₄ − X₁₂|/|X₄₈ − X₂₄|) and log₂(|X₄₈ − X₂₄|/|X₉₆ − X₄₈|), the
//! Richardson estimates (8X_N − 6X_{N/2} + X_{N/4})/3 for N = 48 and 96, and
//! the default lattice at that Mach number (`LatticeSpec::for_mach`, its
//! own extrapolation) against the N = 96 estimate.
//!
//! `cargo run --release -p stability-core --example lifting_surface_near_sonic [convergence|approach|spanwise|crossover]`

use stability_core::aerodynamics::lifting_surface::{
    Lattice, LatticeSpec, Solution, Spacing, near_sonic,
};
use stability_core::geometry::Trapezoid;

fn note(deg: f64) -> Trapezoid {
    let t = deg.to_radians().tan();
    Trapezoid::new(1.0, 0.0, 1.0 / t, deg.to_radians()).unwrap()
}

/// z_θ̇, m_θ̇ (h = 0.25), C_Lα, H₀.
fn four(s: &Solution) -> [f64; 4] {
    let d = s.derivatives(0.25, 0.0).unwrap();
    [
        d.z_thetadot,
        d.m_thetadot,
        d.lift_slope,
        d.aerodynamic_centre,
    ]
}

fn convergence() {
    let names = ["z_θ̇", "m_θ̇", "C_Lα", "H₀"];
    for deg in [45.0, 60.0] {
        let wing = note(deg);
        for mach in [0.95, 0.98] {
            for w in [0.0, 0.3, 0.6] {
                let x: Vec<[f64; 4]> = [12, 24, 48, 96]
                    .iter()
                    .map(|&n| {
                        let l = Lattice::new(&wing, LatticeSpec::new(n, 16, Spacing::RootCosine));
                        four(&l.unwrap().solve(mach, w).unwrap())
                    })
                    .collect();
                let spec = LatticeSpec::for_mach(&wing, mach);
                let solve = |spec: LatticeSpec| {
                    four(&Lattice::new(&wing, spec).unwrap().solve(mach, w).unwrap())
                };
                let d = solve(spec);
                let dense_c = solve(LatticeSpec {
                    chordwise: 96,
                    ..spec
                });
                let dense_s = solve(LatticeSpec {
                    spanwise: 32,
                    ..spec
                });
                let (nc, ns) = (spec.chordwise, spec.spanwise);
                println!(
                    "\n**{deg}° delta, M = {mach}, ω̄ = {w}** (default here: {nc} × {ns}, extrapolated both ways)\n"
                );
                println!(
                    "| | N = 12 | 24 | 48 | 96 | p (12–48) | p (24–96) | R 48 | R 96 | default {nc}×{ns} | 96×{ns} − default | {nc}×32 − default |"
                );
                println!("|---|---|---|---|---|---|---|---|---|---|---|---|");
                for (k, name) in names.iter().enumerate() {
                    let v = |i: usize| x[i][k];
                    let p =
                        |a: usize| ((v(a + 1) - v(a)).abs() / (v(a + 2) - v(a + 1)).abs()).log2();
                    let r = |a: usize| (8.0 * v(a + 2) - 6.0 * v(a + 1) + v(a)) / 3.0;
                    println!(
                        "| {name} | {:.5} | {:.5} | {:.5} | {:.5} | {:.2} | {:.2} | {:.5} | {:.5} | {:.5} | {:+.1e} | {:+.1e} |",
                        v(0),
                        v(1),
                        v(2),
                        v(3),
                        p(0),
                        p(1),
                        r(0),
                        r(1),
                        d[k],
                        dense_c[k] - d[k],
                        dense_s[k] - d[k]
                    );
                }
            }
        }
    }
}

fn approach() {
    for deg in [45.0, 60.0, 80.0] {
        let wing = note(deg);
        for w in [0.3, 0.6, 1.0] {
            println!("\n**{deg}° delta, ω̄ = {w}**\n");
            println!("| M | z_θ̇ | m_θ̇ | z_ẇ | m_ẇ | C_Lα | H₀ |");
            println!("|---|---|---|---|---|---|---|");
            for mach in [0.9, 0.95, 0.97, 0.98, 0.99, 0.995, 0.998, 1.0] {
                let s = near_sonic(&wing, mach, w).unwrap();
                let d = s.derivatives(0.25, 0.0).unwrap();
                println!(
                    "| {mach} | {:.4} | {:.4} | {:.4} | {:.4} | {:.4} | {:.4} |",
                    d.z_thetadot,
                    d.m_thetadot,
                    d.z_wdot,
                    d.m_wdot,
                    d.lift_slope,
                    d.aerodynamic_centre
                );
            }
        }
    }
}

/// The sonic point with the anchors on 16 strips (the default) and on 32:
/// the spanwise uncertainty of `sonic_limit`.
fn spanwise() {
    let anchors = stability_core::aerodynamics::lifting_surface::near_sonic::SONIC_ANCHORS;
    let b2 = anchors.map(|m| 1.0 - m * m);
    // Lagrange's weights at β² = 0
    let w: [f64; 3] = std::array::from_fn(|m| {
        (0..3)
            .filter(|&k| k != m)
            .map(|k| (0.0 - b2[k]) / (b2[m] - b2[k]))
            .product()
    });
    println!("| wing | ω̄ | strips | z_θ̇ | m_θ̇ | z_ẇ | m_ẇ | C_Lα | H₀ |");
    println!("|---|---|---|---|---|---|---|---|---|");
    for deg in [45.0, 60.0] {
        let wing = note(deg);
        for om in [0.3, 0.6] {
            for strips in [16, 32] {
                let mut sum = [0.0; 6];
                for (m, wm) in anchors.iter().zip(w) {
                    let spec = LatticeSpec {
                        spanwise: strips,
                        ..LatticeSpec::for_mach(&wing, *m)
                    };
                    let s = Lattice::new(&wing, spec).unwrap().solve(*m, om).unwrap();
                    let d = s.derivatives(0.25, 0.0).unwrap();
                    let v = [
                        d.z_thetadot,
                        d.m_thetadot,
                        d.z_wdot,
                        d.m_wdot,
                        d.lift_slope,
                        d.aerodynamic_centre,
                    ];
                    for k in 0..6 {
                        sum[k] += wm * v[k];
                    }
                }
                println!(
                    "| {deg}° | {om} | {strips} | {:.4} | {:.4} | {:.4} | {:.4} | {:.4} | {:.4} |",
                    sum[0], sum[1], sum[2], sum[3], sum[4], sum[5]
                );
            }
        }
    }
}

/// z_ẇ of the 45° and 60° deltas against M at small ω̄: the ln(1/β)
/// growth of the quasi-steady limit, cut off where β² falls below about
/// ω̄/2.4.
fn crossover() {
    let machs = [0.9, 0.95, 0.97, 0.98, 0.99, 0.995, 0.998];
    for deg in [45.0, 60.0] {
        let wing = note(deg);
        println!("\n**{deg}° delta, z_ẇ**\n");
        println!("| ω̄ | M = 0.9 | 0.95 | 0.97 | 0.98 | 0.99 | 0.995 | 0.998 |");
        println!("|---|---|---|---|---|---|---|---|");
        for om in [0.0, 0.05, 0.1, 0.3] {
            let z: Vec<String> = machs
                .iter()
                .map(|&m| {
                    let d = near_sonic(&wing, m, om)
                        .unwrap()
                        .derivatives(0.25, 0.0)
                        .unwrap();
                    format!("{:.3}", d.z_wdot)
                })
                .collect();
            println!("| {om} | {} |", z.join(" | "));
        }
    }
}

fn main() {
    match std::env::args().nth(1).as_deref() {
        Some("crossover") => crossover(),
        Some("approach") => approach(),
        Some("spanwise") => spanwise(),
        _ => convergence(),
    }
}
