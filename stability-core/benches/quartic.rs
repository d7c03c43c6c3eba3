//! Coefficient evaluation of the stability quartic, side by side in one run:
//!
//! - `generated`: `Derivatives::quartic_coefficients`, emitted by
//!   derive-quartic from specs/quartic.toml;
//! - `hand_written`: eq (6) typed by hand, corrected (`reference::eq6_by_hand`);
//! - `interpolated_determinant`: eq (4) evaluated at five complex points and
//!   interpolated (`reference::coefficients_by_interpolation`);
//! - the gradient: generated, against fifteen dual-number passes through the
//!   hand-written eq (6).
//!
//! Each iteration evaluates a batch of 256 derivative sets; divan reports
//! the time per batch, and (AllocProfiler) the allocations, which must be 0.

use divan::{AllocProfiler, Bencher, black_box};
use stability_core::Derivatives;
use stability_core::dynamics::quartic::reference::{
    coefficients_by_interpolation, eq6_by_hand, gradient_by_dual_numbers, natural_radius,
};

#[global_allocator]
static ALLOC: AllocProfiler = AllocProfiler::system();

const N: usize = 256;

/// Deterministic, varied derivative sets of realistic size and sign.
fn sets() -> Vec<Derivatives> {
    (0..N)
        .map(|i| {
            let t = i as f64;
            let w = |k: f64, scale: f64| scale * (0.3 + (t * 0.37 + k * 1.91).sin().abs());
            Derivatives {
                x_u: -w(1.0, 0.05),
                x_w: w(2.0, 0.3),
                x_wdot: -w(3.0, 0.01),
                x_q: -w(4.0, 0.02),
                z_u: -w(5.0, 0.6),
                z_w: -w(6.0, 3.0),
                z_wdot: -w(7.0, 0.8),
                z_q: -w(8.0, 1.5),
                m_u: -w(9.0, 0.01),
                m_w: -w(10.0, 0.5),
                m_wdot: -w(11.0, 0.3),
                m_q: -w(12.0, 0.7),
                c_l: w(13.0, 0.3),
                mu1: 20.0 + 400.0 * w(14.0, 1.0),
                i_b: 0.05 + w(15.0, 0.1),
            }
        })
        .collect()
}

fn main() {
    divan::main();
}

#[divan::bench]
fn generated(b: Bencher) {
    let sets = sets();
    b.bench_local(|| {
        let mut acc = 0.0;
        for d in black_box(&sets) {
            let c = d.quartic_coefficients();
            acc += c[0] + c[1] + c[2] + c[3] + c[4];
        }
        acc
    });
}

#[divan::bench]
fn hand_written(b: Bencher) {
    let sets: Vec<[f64; 15]> = sets()
        .iter()
        .map(Derivatives::quartic_input_values)
        .collect();
    b.bench_local(|| {
        let mut acc = 0.0;
        for v in black_box(&sets) {
            let c = eq6_by_hand(v);
            acc += c[0] + c[1] + c[2] + c[3] + c[4];
        }
        acc
    });
}

#[divan::bench]
fn interpolated_determinant(b: Bencher) {
    let sets: Vec<([f64; 15], f64)> = sets()
        .iter()
        .map(|d| {
            let v = d.quartic_input_values();
            (v, natural_radius(&v))
        })
        .collect();
    b.bench_local(|| {
        let mut acc = 0.0;
        for (v, r) in black_box(&sets) {
            let (c, _) = coefficients_by_interpolation(v, *r);
            acc += c[0] + c[1] + c[2] + c[3] + c[4];
        }
        acc
    });
}

#[divan::bench]
fn gradient_generated(b: Bencher) {
    let sets = sets();
    b.bench_local(|| {
        let mut acc = 0.0;
        for d in black_box(&sets) {
            let g = d.quartic_gradient();
            acc += g.iter().flatten().sum::<f64>();
        }
        acc
    });
}

#[divan::bench]
fn gradient_dual_numbers(b: Bencher) {
    let sets: Vec<[f64; 15]> = sets()
        .iter()
        .map(Derivatives::quartic_input_values)
        .collect();
    b.bench_local(|| {
        let mut acc = 0.0;
        for v in black_box(&sets) {
            let g = gradient_by_dual_numbers(v);
            acc += g.iter().flatten().sum::<f64>();
        }
        acc
    });
}
