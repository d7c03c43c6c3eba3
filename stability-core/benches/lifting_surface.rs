//! The doublet lattice, one planform (the note's 60° delta) at one Mach
//! number: the harmonic solve (M = 0.5, ω̄ = 0.5) and the quasi-steady one
//! (M = 0.5, ω̄ = 0), every derivative included, at the default lattice and
//! at the next coarser and denser ones (all extrapolated as the default is:
//! 8×12, 12×16 (default), 16×24 boxes per strip × strips); the steady
//! solve with its exact Mach derivatives (`Lattice::solve_steady`, what
//! `aero = "lifting-surface"` takes); and, per design point of a sweep,
//! `Solution::derivatives` and one interpolation in a solved
//! `FrequencyTable` (a frequency iteration's cost per iterate).
//!
//! Near M = 1: the refined lattice of `LatticeSpec::for_mach` at M = 0.98
//! against the default at 0.5, and the sonic point (`sonic_limit`).
//!
//! And the configuration lattice: a wing with a tailplane against the wing
//! alone at the same density.
//!
//! `cargo bench -p stability-core --bench lifting_surface`

use divan::{AllocProfiler, Bencher, black_box};
use stability_core::aerodynamics::lifting_surface::configuration::ConfigurationLattice;
use stability_core::aerodynamics::lifting_surface::{
    FrequencyTable, Lattice, LatticeSpec, Solution,
};
use stability_core::geometry::configuration::Configuration;
use stability_core::geometry::configuration::Surface;
use stability_core::geometry::configuration::SurfaceKind;
use stability_core::geometry::{Planform, Size, Trapezoid};

#[global_allocator]
static ALLOC: AllocProfiler = AllocProfiler::system();

fn main() {
    divan::main();
}

const LATTICES: [&str; 3] = ["coarser 8x12", "default 12x16", "denser 16x24"];

fn lattice(name: &str) -> Lattice {
    let p = Planform::new(60f64.to_radians(), 0.0, Size::RootChord(1.0)).unwrap();
    let wing = Trapezoid::from(&p);
    let (chordwise, spanwise) = match name {
        "coarser 8x12" => (8, 12),
        "default 12x16" => (12, 16),
        _ => (16, 24),
    };
    let spec = LatticeSpec {
        chordwise,
        spanwise,
        ..LatticeSpec::for_wing(&wing)
    };
    assert!(name != "default 12x16" || spec == LatticeSpec::for_wing(&wing));
    Lattice::new(&wing, spec).unwrap()
}

fn all_derivatives(s: &Solution) -> f64 {
    let d = s.derivatives(0.25, 0.01).unwrap();
    d.lift_slope + d.aerodynamic_centre + d.z_w + d.m_w + d.z_wdot + d.m_wdot + d.z_q + d.m_q
}

#[divan::bench(args = LATTICES, sample_count = 20)]
fn harmonic(bencher: Bencher, name: &str) {
    let l = lattice(name);
    bencher.bench_local(|| all_derivatives(&black_box(&l).solve(0.5, black_box(0.5)).unwrap()));
}

#[divan::bench(args = LATTICES, sample_count = 20)]
fn quasi_steady(bencher: Bencher, name: &str) {
    let l = lattice(name);
    bencher.bench_local(|| all_derivatives(&black_box(&l).solve(0.5, black_box(0.0)).unwrap()));
}

/// One solution's derivatives about one c.g.: a sweep's cost per point.
#[divan::bench]
fn derivatives_per_point(bencher: Bencher) {
    let s = lattice("coarser 8x12").solve(0.5, 0.5).unwrap();
    let mut h = 0.0;
    bencher.bench_local(|| {
        h += 1e-6;
        black_box(&s).derivatives(black_box(h), 0.01).unwrap()
    });
}

#[divan::bench(args = LATTICES, sample_count = 20)]
fn steady_with_mach_derivative(bencher: Bencher, name: &str) {
    let l = lattice(name);
    bencher.bench_local(|| {
        let s = black_box(&l).solve_steady(black_box(0.5)).unwrap();
        s.lift_slope().1 + s.aerodynamic_centre().1 + all_derivatives(&s.solution)
    });
}

/// One interpolation in a table whose nodes around ω̄ = 0.3 are solved
/// (allocation-free).
#[divan::bench]
fn interpolated_per_iterate(bencher: Bencher) {
    let table = FrequencyTable::new(lattice("coarser 8x12"), 0.5).unwrap();
    // the nodes of both stencils the iterates use (0.2 … 0.4)
    table.at(0.3).unwrap();
    table.at(0.32).unwrap();
    let mut w = 0.3;
    bencher.bench_local(|| {
        w = if w > 0.34 { 0.3 } else { w + 1e-4 };
        black_box(&table).at(black_box(w)).unwrap()
    });
}

/// Near M = 1 (`LatticeSpec::for_mach`): the harmonic solve (ω̄ = 0.5) at
/// M = 0.98 on the refined lattice (28 × 16 boxes, extrapolated) against
/// the same solve at M = 0.5 on the default one (12 × 16), the note's 60°
/// delta; the ratio of the two is in `docs/lattice-near-sonic.md`.
#[divan::bench(args = [0.5, 0.98], sample_count = 10)]
fn harmonic_near_sonic(bencher: Bencher, mach: f64) {
    let p = Planform::new(60f64.to_radians(), 0.0, Size::RootChord(1.0)).unwrap();
    let wing = Trapezoid::from(&p);
    let l = Lattice::new(&wing, LatticeSpec::for_mach(&wing, mach)).unwrap();
    bencher.bench_local(|| all_derivatives(&black_box(&l).solve(mach, black_box(0.5)).unwrap()));
}

/// The sonic point (`lifting_surface::sonic_limit`: three refined solves at
/// M = 0.99, 0.995 and 0.998 and the quadratic in β²), the 60° delta at
/// ω̄ = 0.5.
#[divan::bench(sample_count = 3)]
fn sonic_point(bencher: Bencher) {
    let p = Planform::new(60f64.to_radians(), 0.0, Size::RootChord(1.0)).unwrap();
    let wing = Trapezoid::from(&p);
    bencher.bench_local(|| {
        all_derivatives(
            &stability_core::aerodynamics::lifting_surface::sonic_limit(&wing, black_box(0.5))
                .unwrap(),
        )
    });
}

/// The configuration lattice (issue 21): the note's 60° delta with a
/// tailplane 0.3c_r above its plane (root 0.3, tip 0.15, semi-span 0.35,
/// 30° sweep; 12 × 16 boxes per surface, extrapolated) against the wing
/// alone at the same box density (`ConfigurationLattice` of the wing alone,
/// which is `Lattice::solve`): the cost ratio of the whole configuration,
/// harmonic (M = 0.5, ω̄ = 0.5) and quasi-steady (M = 0.5). Measured (two
/// runs on a shared two-core machine, medians): harmonic 206 / 24 ms and
/// 263 / 51 ms (5–9 times the wing alone, for twice its boxes: the dense
/// LU's n³ and the non-planar cross blocks), quasi-steady 30 / 7.9 ms and
/// 39 / 8.1 ms (4–5 times).
const CONFIGURATIONS: [&str; 2] = ["wing alone", "wing + tailplane"];

fn configuration(name: &str) -> ConfigurationLattice {
    let p = Planform::new(60f64.to_radians(), 0.0, Size::RootChord(1.0)).unwrap();
    let wing = Trapezoid::from(&p);
    let tail = Surface {
        kind: SurfaceKind::Tailplane,
        shape: Trapezoid::new(0.3, 0.15, 0.35, 30f64.to_radians()).unwrap(),
        x: 1.3,
        z: 0.3,
        incidence: 0.0,
    };
    let cfg = Configuration {
        tailplane: (name != "wing alone").then_some(tail),
        ..Configuration::wing_alone(wing)
    };
    ConfigurationLattice::new(&cfg).unwrap()
}

#[divan::bench(args = CONFIGURATIONS, sample_count = 10)]
fn configuration_harmonic(bencher: Bencher, name: &str) {
    let l = configuration(name);
    bencher.bench_local(|| {
        black_box(&l)
            .solve(0.5, black_box(0.5))
            .unwrap()
            .total
            .lift_alpha
    });
}

#[divan::bench(args = CONFIGURATIONS, sample_count = 10)]
fn configuration_quasi_steady(bencher: Bencher, name: &str) {
    let l = configuration(name);
    bencher.bench_local(|| {
        black_box(&l)
            .solve(0.5, black_box(0.0))
            .unwrap()
            .total
            .lift_alpha
    });
}
