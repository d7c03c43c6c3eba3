//! Uncertainty propagation (issue 23): samples per second on one thread,
//! side by side with one design point's evaluation, so the figures compare
//! as ratios in one run:
//!
//! - `design_point`: one `evaluate_point` of the 60° delta at M = 1.5 with
//!   the quasi-steady `faired-slender` model (what a sample would cost if
//!   each were a design point);
//! - `quartic_only`: 4096 samples of i_B and m_q uncertain, the same
//!   model — the aerodynamics evaluated once, a sample a quartic and its
//!   analysis;
//! - `quartic_only_per_sample`: `quartic_only` with each sample's quartic
//!   solved alone (`run_per_sample`, the path before `solve_quartics`);
//! - `quartic_only_sobol`: the same with the Sobol design (k + 2 = 4
//!   evaluations a row: 1024 rows);
//! - `quartic_only_quasi`: `quartic_only` from Owen-scrambled Sobol′
//!   points (`--sampling sobol`);
//! - `design_point_per_sample`: 1024 samples with the c.g. uncertain too,
//!   each a design point;
//! - `faired_lattice`: 256 samples of the default `faired` model at
//!   M = 0.9 with the c.g. uncertain: each sample's frequency iteration
//!   interpolates in the lattice's frequency table, solved once.
//!
//! `cargo bench -p stability-core --bench uncertainty`

use divan::counter::ItemsCount;
use divan::{Bencher, black_box};
use stability_core::design::case::{Case, DampingModel, evaluate_point};
use stability_core::design::study::report_wing;
use stability_core::uncertainty::{Dist, ErrorKind, Input, Options, Quantity, Sampling, Study};

fn main() {
    divan::main();
}

fn base(mach: f64, damping: DampingModel) -> Case {
    Case {
        damping,
        ..report_wing(60.0, mach)
    }
}

fn inputs(cg: bool) -> Vec<Input> {
    let mut v = vec![
        Input {
            quantity: Quantity::IB,
            error: ErrorKind::Value,
            dist: Dist::Normal {
                mean: 0.08,
                sd: 0.008,
            },
        },
        Input {
            quantity: Quantity::parse("m_q").unwrap(),
            error: ErrorKind::Multiplicative,
            dist: Dist::Uniform {
                low: 0.8,
                high: 1.2,
            },
        },
    ];
    if cg {
        v.push(Input {
            quantity: Quantity::Cg,
            error: ErrorKind::Value,
            dist: Dist::Triangular {
                low: 0.22,
                mode: 0.25,
                high: 0.3,
            },
        });
    }
    v
}

/// `samples` of `study` at `mach` on one thread.
fn run(b: Bencher, study: &Study, mach: f64, samples: u64, sobol: bool) {
    run_with(b, study, mach, samples, sobol, Sampling::Random);
}

/// `samples` of `study` at `mach` on one thread, drawn by `sampling`.
fn run_with(b: Bencher, study: &Study, mach: f64, samples: u64, sobol: bool, sampling: Sampling) {
    run_by(b, study, mach, samples, sobol, sampling, false);
}

/// `samples` of `study` at `mach` on one thread, drawn by `sampling`;
/// each sample's quartic solved alone if `per_sample`.
fn run_by(
    b: Bencher,
    study: &Study,
    mach: f64,
    samples: u64,
    sobol: bool,
    sampling: Sampling,
    per_sample: bool,
) {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    let at = study.at_mach(mach);
    let options = Options {
        samples,
        seed: 1,
        sobol,
        sampling,
    };
    b.counter(ItemsCount::new(samples)).bench_local(|| {
        pool.install(|| match per_sample {
            true => black_box(at.run_per_sample(&options, &|_| {})),
            false => black_box(at.run(&options, &|_| {})),
        })
    });
}

#[divan::bench]
fn design_point(b: Bencher) {
    let c = base(1.5, DampingModel::FairedSlender);
    b.counter(ItemsCount::new(1u64))
        .bench_local(|| black_box(evaluate_point(black_box(&c))));
}

#[divan::bench]
fn quartic_only(b: Bencher) {
    let s = Study::new(
        base(1.5, DampingModel::FairedSlender),
        None,
        inputs(false),
        &[],
        &[],
    )
    .unwrap();
    run(b, &s, 1.5, 4096, false);
}

/// `quartic_only` before the batched roots: one `solve_quartic` a sample.
#[divan::bench]
fn quartic_only_per_sample(b: Bencher) {
    let s = Study::new(
        base(1.5, DampingModel::FairedSlender),
        None,
        inputs(false),
        &[],
        &[],
    )
    .unwrap();
    run_by(b, &s, 1.5, 4096, false, Sampling::Random, true);
}

#[divan::bench]
fn quartic_only_sobol(b: Bencher) {
    let s = Study::new(
        base(1.5, DampingModel::FairedSlender),
        None,
        inputs(false),
        &[],
        &[],
    )
    .unwrap();
    run(b, &s, 1.5, 1024, true);
}

/// `quartic_only` drawn from the scrambled Sobol′ sequence: what its
/// points and Φ⁻¹ cost beside ChaCha8's normals.
#[divan::bench]
fn quartic_only_quasi(b: Bencher) {
    let s = Study::new(
        base(1.5, DampingModel::FairedSlender),
        None,
        inputs(false),
        &[],
        &[],
    )
    .unwrap();
    run_with(b, &s, 1.5, 4096, false, Sampling::Sobol);
}

#[divan::bench]
fn design_point_per_sample(b: Bencher) {
    let s = Study::new(
        base(1.5, DampingModel::FairedSlender),
        None,
        inputs(true),
        &[],
        &[],
    )
    .unwrap();
    run(b, &s, 1.5, 1024, false);
}

#[divan::bench(sample_count = 10)]
fn faired_lattice(b: Bencher) {
    let s = Study::new(
        base(0.9, DampingModel::Faired),
        None,
        inputs(true),
        &[],
        &[],
    )
    .unwrap();
    run(b, &s, 0.9, 256, false);
}
