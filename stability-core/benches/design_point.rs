//! One design point from an empty store of solutions, as `analyze` computes
//! it (the default `faired` model: the lifting surface at the short
//! period's own ω̄, iterated; its steady Mach derivatives from the Mach
//! box's table in M): on the note's 45° delta and on a 60.5° delta of the
//! Mirage class, at M = 0.6 (doublet lattice), 1.05 (near sonic: the Mach
//! box's long grid), 1.2 and 1.6 (subsonic leading edges: the diaphragm)
//! and 2 (the 45° delta's leading edge supersonic). Every iteration clears
//! the store first, so each solve is paid.
//!
//! `cargo bench -p stability-core --bench design_point`

use divan::{Bencher, black_box};
use stability_core::aerodynamics::lifting_surface::store;
use stability_core::design::case::evaluate;
use stability_core::design::study::report_wing;

fn main() {
    divan::main();
}

const MACH: [f64; 5] = [0.6, 1.05, 1.2, 1.6, 2.0];

fn bench_wing(bencher: Bencher, sweep_deg: f64, mach: f64) {
    let case = report_wing(sweep_deg, mach);
    bencher.bench_local(|| {
        store::clear();
        black_box(evaluate(black_box(&case)).expect("a design point"))
    });
}

/// The note's 45° delta (aspect ratio 4).
#[divan::bench(sample_count = 3, args = MACH)]
fn delta_45(bencher: Bencher, mach: f64) {
    bench_wing(bencher, 45.0, mach);
}

/// A 60.5° delta (aspect ratio 2.26), the Mirage III's planform.
#[divan::bench(sample_count = 3, args = MACH)]
fn delta_60_5(bencher: Bencher, mach: f64) {
    bench_wing(bencher, 60.5, mach);
}
