//! The Mach box method (supersonic, M = 2.5) against the subsonic doublet
//! lattice (M = 0.5) on the same wing, the note's 60° delta, at ω̄ = 0.5,
//! with about the same number of boxes on the half wing: the Mach box's
//! 23 strips (183 wing boxes, no extrapolation) and the lattice's 12 × 16
//! (192 boxes, no extrapolation); and the Mach box's default grid (128
//! strips extrapolated with 64: 6 100 + 1 500 wing boxes), also at M = 1.6
//! (subsonic leading edge: the diaphragm).
//!
//! The march alone by each method (`mach_box::upstream`): the earlier
//! rows' sum term by term (today's reference) and by relaxed FFT
//! convolution, on the same one-grid solves of the 45° delta (near sonic,
//! subsonic and supersonic leading edge).
//!
//! `cargo bench -p stability-core --bench supersonic_oscillatory`

use divan::{Bencher, black_box};
use stability_core::aerodynamics::lifting_surface::mach_box::direct::Flow;
use stability_core::aerodynamics::lifting_surface::mach_box::grid::Grid;
use stability_core::aerodynamics::lifting_surface::mach_box::influence::Influence;
use stability_core::aerodynamics::lifting_surface::mach_box::march::march;
use stability_core::aerodynamics::lifting_surface::mach_box::{MachBoxSpec, Method, solve};
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

/// The march on the finer grid `MachBoxSpec::for_wing` takes for the 45°
/// delta at `mach`, ω̄ = 0.5, by `method`.
fn bench_march(bencher: Bencher, mach: f64, method: Method) {
    let p = Planform::new(45f64.to_radians(), 0.0, Size::RootChord(1.0)).unwrap();
    let w = Trapezoid::from(&p);
    let beta = (mach * mach - 1.0).sqrt();
    let grid = Grid::new(&w, beta, MachBoxSpec::for_wing(&w, mach).strips);
    let kappa = 0.5 / w.mac();
    let (sigma, nu) = (
        kappa * mach * mach / (beta * beta),
        kappa * mach / (beta * beta),
    );
    let table = Influence::new(grid.rows, sigma * grid.dx, nu * grid.dx);
    let flow = Flow {
        beta,
        sigma,
        nu,
        x_mac: w.x_mac(),
        mac: w.mac(),
    };
    bencher.bench_local(|| march(black_box(&w), &grid, &table, &flow, method));
}

const METHODS: [Method; 2] = [Method::Direct, Method::Relaxed];

/// Near sonic, M = 1.05 (β cot Λ = 0.32; 96 strips, 298 rows).
#[divan::bench(sample_count = 3, args = METHODS)]
fn march_near_sonic(bencher: Bencher, method: Method) {
    bench_march(bencher, 1.05, method);
}

/// Subsonic leading edge, M = 1.2 (β cot Λ = 0.66).
#[divan::bench(sample_count = 3, args = METHODS)]
fn march_subsonic_edge(bencher: Bencher, method: Method) {
    bench_march(bencher, 1.2, method);
}

/// Supersonic leading edge, M = 2 (β cot Λ = 1.73): no diaphragm ahead of
/// the wing, none beside its pointed tip.
#[divan::bench(sample_count = 5, args = METHODS)]
fn march_supersonic_edge(bencher: Bencher, method: Method) {
    bench_march(bencher, 2.0, method);
}
