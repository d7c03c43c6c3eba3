//! The library sweep (`stability_core::design::sweep`) over 10 Mach numbers ×
//! 10⁵ c.g. × μ₁ × i_B points (10⁶ design points; the 60° delta), evaluated
//! as `delta-stability sweep` evaluates it — the lattice's solves first,
//! in parallel (`Sweep::prepare`), then blocks of 1024 points in parallel —
//! with the damping of slender-wing theory, of the lifting surface, and of
//! the lifting surface with its lift slope and aerodynamic centre too. The
//! cache is emptied before each sample, so the lifting surface pays its ten
//! solves (one per Mach number) every time. Side by side in one run, so the
//! figures compare as ratios.
//!
//! `cargo bench -p stability-core --bench sweep`

use divan::Bencher;
use rayon::prelude::*;
use stability_core::aerodynamics::damping::Theory;
use stability_core::aerodynamics::lifting_surface::store;
use stability_core::aerodynamics::models::aero::{AeroModel, AeroModelName};
use stability_core::design::case::{Case, DampingModel};
use stability_core::design::study::{grid, report_wing};
use stability_core::design::sweep::{Axes, Sweep};

fn main() {
    divan::main();
}

const MODELS: [&str; 3] = ["slender", "lifting-surface", "lifting-surface + aero"];

fn sweep(model: &str) -> Sweep {
    let (damping, aero) = match model {
        "slender" => (Theory::Slender, AeroModelName::Default),
        "lifting-surface" => (Theory::LiftingSurface, AeroModelName::Default),
        _ => (Theory::LiftingSurface, AeroModelName::LiftingSurface),
    };
    let base = Case {
        damping: DampingModel::Theory(damping),
        aero: AeroModel::default().with_name(aero),
        ..report_wing(60.0, 0.5)
    };
    let axes = Axes {
        mach: grid(0.3, 0.75, 0.05),
        cg: grid(0.0, 0.495, 0.005),
        mu1: grid(10.0, 1000.0, 10.0),
        i_b: grid(0.04, 0.13, 0.01),
        ..Axes::around(&base)
    };
    let s = Sweep::new(base, axes).unwrap();
    assert_eq!(s.len(), 1_000_000);
    s
}

/// The whole grid as the command evaluates it; the points with a result.
fn run(s: &Sweep) -> usize {
    const BLOCK: usize = 1 << 10;
    s.prepare();
    let n = s.len();
    (0..n)
        .step_by(BLOCK)
        .collect::<Vec<_>>()
        .into_par_iter()
        .map(|b| {
            let p = s.evaluate(b..(b + BLOCK).min(n), false);
            p.len() - p.errors.len()
        })
        .sum()
}

#[divan::bench(args = MODELS, sample_count = 15, sample_size = 1)]
fn million_points(bencher: Bencher, model: &str) {
    let s = sweep(model);
    bencher
        .with_inputs(store::clear)
        .bench_local_values(|()| run(&s));
}
