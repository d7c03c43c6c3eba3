//! The Mach box method (supersonic, M = 2.5) against the subsonic doublet
//! lattice (M = 0.5) on the same wing, the note's 60° delta, at ω̄ = 0.5,
//! with about the same number of boxes on the half wing: the Mach box's
//! 23 strips (183 wing boxes, no extrapolation) and the lattice's 12 × 16
//! (192 boxes, no extrapolation); and the Mach box's default grid (128
//! strips extrapolated with 64: 6 100 + 1 500 wing boxes), also at M = 1.6
//! (subsonic leading edge: the diaphragm).
//!
//! `cargo bench -p stability-core --bench supersonic_oscillatory`

use divan::{Bencher, black_box};
use stability_core::aerodynamics::lifting_surface::mach_box::{MachBoxSpec, solve};
use stability_core::aerodynamics::lifting_surface::{Extrapolation, Lattice, LatticeSpec};
use stability_core::geometry::{Planform, Size, Trapezoid};

fn main() {
    divan::main();
}

fn wing() -> Trapezoid {
    let p = Planform::new(60f64.to_radians(), 0.0, Size::RootChord(1.0)).unwrap();
    Trapezoid::from(&p)
}

#[divan::bench(sample_count = 20)]
fn mach_box_183_boxes(bencher: Bencher) {
    let w = wing();
    let spec = MachBoxSpec {
        strips: 23,
        richardson: false,
    };
    bencher.bench_local(|| solve(black_box(&w), 2.5, black_box(0.5), spec).unwrap());
}

#[divan::bench(sample_count = 20)]
fn lattice_192_boxes(bencher: Bencher) {
    let w = wing();
    let spec = LatticeSpec {
        chordwise: 12,
        spanwise: 16,
        extrapolation: Extrapolation::None,
        ..LatticeSpec::for_wing(&w)
    };
    let l = Lattice::new(&w, spec).unwrap();
    bencher.bench_local(|| black_box(&l).solve(0.5, black_box(0.5)).unwrap());
}

#[divan::bench(sample_count = 10)]
fn mach_box_default(bencher: Bencher) {
    let w = wing();
    bencher
        .bench_local(|| solve(black_box(&w), 2.5, black_box(0.5), MachBoxSpec::default()).unwrap());
}

/// The default grid with a subsonic leading edge (M = 1.6, β cot Λ =
/// 0.72): the diaphragm's march, with the edge's weights and near-field
/// coefficients (`lifting_surface::mach_box::edge`).
#[divan::bench(sample_count = 10)]
fn mach_box_default_subsonic_edge(bencher: Bencher) {
    let w = wing();
    bencher
        .bench_local(|| solve(black_box(&w), 1.6, black_box(0.5), MachBoxSpec::default()).unwrap());
}

/// Near M = 1 with a subsonic leading edge: the 45° delta at M = 1.05
/// (β cot Λ = 0.32) on `MachBoxSpec::for_wing`'s grid (96 strips with 48,
/// 298 rows: the diaphragm out to the apex's Mach cone, four times the
/// wing's width), the grid the frequency iteration of
/// `--damping lifting-surface-frequency` solves there.
#[divan::bench(sample_count = 5)]
fn mach_box_near_sonic_subsonic_edge(bencher: Bencher) {
    let p = Planform::new(45f64.to_radians(), 0.0, Size::RootChord(1.0)).unwrap();
    let w = Trapezoid::from(&p);
    let spec = MachBoxSpec::for_wing(&w, 1.05);
    bencher.bench_local(|| solve(black_box(&w), 1.05, black_box(0.5), spec).unwrap());
}
