//! One design point, whole and in parts, side by side in one run:
//! `evaluate` (planform → coefficients → derivatives → quartic → roots →
//! modes → criteria), `evaluate_point` (the sweep's lean path), and its
//! stages alone. Each iteration evaluates 64 Mach numbers from 0.5 to 2.0
//! on the report's 60° delta, with the quasi-steady `faired-slender`
//! damping model (the default `faired` model's lifting surface and frequency
//! iteration are benchmarked in `lifting_surface.rs` and `sweep.rs`).

use divan::{AllocProfiler, black_box};
use stability_core::analysis::Analysis;
use stability_core::design::case::{Case, DampingModel, evaluate, evaluate_point};
use stability_core::design::study::report_wing;

#[global_allocator]
static ALLOC: AllocProfiler = AllocProfiler::system();

fn cases() -> Vec<Case> {
    (0..64)
        .map(|i| {
            let mut c = report_wing(60.0, 0.5 + 1.5 * i as f64 / 63.0);
            c.damping = DampingModel::FairedSlender;
            c.iterate_frequency = false;
            c
        })
        .collect()
}

fn main() {
    divan::main();
}

#[divan::bench]
fn evaluate_full(b: divan::Bencher) {
    let cs = cases();
    b.bench_local(|| {
        for c in &cs {
            let _ = black_box(evaluate(black_box(c)));
        }
    });
}

#[divan::bench]
fn evaluate_point_lean(b: divan::Bencher) {
    let cs = cases();
    b.bench_local(|| {
        for c in &cs {
            let _ = black_box(evaluate_point(black_box(c)));
        }
    });
}

#[divan::bench]
fn aero_coefficients(b: divan::Bencher) {
    let cs = cases();
    b.bench_local(|| {
        for c in &cs {
            let _ = black_box(c.aero.at(&c.planform, black_box(c.mach)));
        }
    });
}

#[divan::bench]
fn analysis_of(b: divan::Bencher) {
    let ds: Vec<_> = cases()
        .iter()
        .map(|c| evaluate(c).unwrap().derivatives)
        .collect();
    b.bench_local(|| {
        for d in &ds {
            let _ = black_box(Analysis::of(black_box(d)));
        }
    });
}

#[divan::bench]
fn analysis_without_classical(b: divan::Bencher) {
    let ds: Vec<_> = cases()
        .iter()
        .map(|c| evaluate(c).unwrap().derivatives)
        .collect();
    b.bench_local(|| {
        for d in &ds {
            let _ = black_box(Analysis::without_classical(black_box(d)));
        }
    });
}

#[divan::bench]
fn damping_faired(b: divan::Bencher) {
    use stability_core::aerodynamics::damping::{Theory, WingInput, damping_derivatives};
    let cs = cases();
    let wing = WingInput::from(&cs[0].planform);
    b.bench_local(|| {
        for c in &cs {
            let _ = black_box(damping_derivatives(
                Theory::Slender,
                &wing,
                0.25,
                black_box(c.mach),
                None,
            ));
            let _ = black_box(damping_derivatives(
                Theory::Supersonic,
                &wing,
                0.25,
                black_box(c.mach.max(1.01)),
                None,
            ));
        }
    });
}

/// `--damping supersonic` on 64 Mach numbers from 1.05 to 2.5: the 45°
/// true delta (closed forms) and the same delta cropped to λ = 1/7 (past
/// the sonic edge, Evvard's integrals at five Mach numbers for the lift
/// slope and aerodynamic centre with their numerical Mach derivatives, and
/// once more for the damping derivatives).
fn supersonic_cases(taper: f64) -> Vec<Case> {
    use stability_core::aerodynamics::damping::Theory;
    use stability_core::design::case::DampingModel;
    use stability_core::geometry::{Planform, Size};
    (0..64)
        .map(|i| {
            let mut c = report_wing(45.0, 1.05 + 1.45 * i as f64 / 63.0);
            c.planform = Planform::new(45f64.to_radians(), taper, Size::RootChord(10.0)).unwrap();
            c.damping = DampingModel::Theory(Theory::Supersonic);
            c
        })
        .collect()
}

#[divan::bench(args = [0.0, 1.0 / 7.0])]
fn evaluate_supersonic(b: divan::Bencher, taper: f64) {
    let cs = supersonic_cases(taper);
    b.bench_local(|| {
        for c in &cs {
            let _ = black_box(evaluate_point(black_box(c)));
        }
    });
}
