//! All four roots of the stability quartic, side by side in one run:
//!
//! - `solve_quartic_roots`: this crate's solver (`roots::solve_quartic`), one
//!   call per quartic;
//! - `solve_quartics_batch`: the same answers from `roots::solve_quartics`,
//!   four quartics per SIMD vector;
//! - `companion_eigenvalues`: nalgebra's eigenvalues of the companion matrix
//!   (the route of numpy.roots, MATLAB's roots and most tools);
//! - `classical_eq7`: the report's eq (7) and its successive approximation
//!   (`classical`), to 1e-12.
//!
//! Each iteration solves 256 quartics: stability quartics of tailless deltas
//! (two complex pairs, short period |λ| ~ 5–25 and phugoid ~ 0.05–0.3 in τ
//! units) and, in `mixed`, random quartics of every root structure.
//! AllocProfiler shows that the solver allocates nothing.

use divan::{AllocProfiler, Bencher, black_box};
use nalgebra::Matrix4;
use stability_core::dynamics::classical::{first_approximation, refine};
use stability_core::numerics::roots::{Complex64, RootsError, solve_quartic, solve_quartics};

#[global_allocator]
static ALLOC: AllocProfiler = AllocProfiler::system();

const N: usize = 256;

fn stability_quartics() -> Vec<[f64; 5]> {
    (0..N)
        .map(|i| {
            let t = i as f64;
            let w = |k: f64| 0.3 + (t * 0.37 + k * 1.91).sin().abs();
            // (λ² + p₁λ + q₁)(λ² + p₂λ + q₂), A = 1 + small
            let (p1, q1) = (4.0 * w(1.0), 40.0 + 400.0 * w(2.0));
            let (p2, q2) = (0.02 * w(3.0), 0.004 + 0.05 * w(4.0));
            let a = 1.0 + 0.01 * w(5.0);
            [
                a,
                a * (p1 + p2),
                a * (q1 + q2 + p1 * p2),
                a * (p1 * q2 + p2 * q1),
                a * q1 * q2,
            ]
        })
        .collect()
}

fn mixed_quartics() -> Vec<[f64; 5]> {
    (0..N)
        .map(|i| {
            let t = i as f64;
            let w = |k: f64| (t * 0.731 + k * 2.17).sin();
            [
                1.0 + w(0.0).abs(),
                3.0 * w(1.0),
                5.0 * w(2.0),
                2.0 * w(3.0),
                4.0 * w(4.0),
            ]
        })
        .collect()
}

fn companion(c: &[f64; 5]) -> Matrix4<f64> {
    let [a, b, cc, d, e] = *c;
    Matrix4::new(
        -b / a,
        -cc / a,
        -d / a,
        -e / a, //
        1.0,
        0.0,
        0.0,
        0.0, //
        0.0,
        1.0,
        0.0,
        0.0, //
        0.0,
        0.0,
        1.0,
        0.0,
    )
}

fn main() {
    divan::main();
}

#[divan::bench(args = ["stability", "mixed"])]
fn solve_quartic_roots(b: Bencher, set: &str) {
    let qs = if set == "stability" {
        stability_quartics()
    } else {
        mixed_quartics()
    };
    b.bench_local(|| {
        let mut acc = 0.0;
        for q in black_box(&qs) {
            if let Ok(r) = solve_quartic(*q) {
                acc += r[0].re + r[3].im;
            }
        }
        acc
    });
}

#[divan::bench(args = ["stability", "mixed"])]
fn solve_quartics_batch(b: Bencher, set: &str) {
    let qs = if set == "stability" {
        stability_quartics()
    } else {
        mixed_quartics()
    };
    let mut out: Vec<Result<[Complex64; 4], RootsError>> = vec![Err(RootsError::LeadingZero); N];
    b.bench_local(|| {
        solve_quartics(black_box(&qs), &mut out);
        let mut acc = 0.0;
        for r in out.iter().flatten() {
            acc += r[0].re + r[3].im;
        }
        acc
    });
}

#[divan::bench(args = ["stability", "mixed"])]
fn companion_eigenvalues(b: Bencher, set: &str) {
    let qs = if set == "stability" {
        stability_quartics()
    } else {
        mixed_quartics()
    };
    b.bench_local(|| {
        let mut acc = 0.0;
        for q in black_box(&qs) {
            let ev = companion(q).complex_eigenvalues();
            acc += ev[0].re + ev[3].im;
        }
        acc
    });
}

#[divan::bench]
fn classical_eq7(b: Bencher) {
    let qs = stability_quartics();
    b.bench_local(|| {
        let mut acc = 0.0;
        for q in black_box(&qs) {
            if let Ok(start) = first_approximation(*q)
                && let Ok(r) = refine(*q, &start, 200, 1e-12)
            {
                acc += r.roots.short_period.re + r.roots.phugoid.im;
            }
        }
        acc
    });
}
