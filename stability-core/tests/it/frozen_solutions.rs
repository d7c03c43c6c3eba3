//! The lifting-surface solutions solved ahead of time
//! (`stability-study/data/lifting-surface-solutions.csv`,
//! `lifting_surface::precomputed`): the file is not stale (its
//! fingerprints are the solvers' own), and a sample of its entries solved
//! again gives the same numbers — the Mach box's and the near-sonic
//! lattice's, the cheap ones and a few near-sonic ones — every number within
//! 10⁻¹⁰ of C_Lα (the same code: they could differ in the last bits of
//! another machine's libm). And a file made by another solver is refused
//! whole: the store then solves, and never returns its stale values.

use stability_core::aerodynamics::lifting_surface::mach_box::{MachBoxSpec, solve};
use stability_core::aerodynamics::lifting_surface::precomputed::{
    Precomputed, PrecomputedError, fingerprint,
};
use stability_core::aerodynamics::lifting_surface::solution::{
    Key, ReducedFrequency, Solver, shape,
};
use stability_core::aerodynamics::lifting_surface::{Lattice, LatticeSpec, Solution, store};
use stability_core::geometry::Trapezoid;

const FILE: &str = include_str!("../../../stability-study/data/lifting-surface-solutions.csv");

fn fresh(solver: Solver, wing: &Trapezoid, mach: f64, omega_bar: f64) -> Solution {
    match solver {
        Solver::MachBox => solve(wing, mach, omega_bar, MachBoxSpec::for_wing(wing, mach)).unwrap(),
        _ => Lattice::new(wing, LatticeSpec::for_mach(wing, mach))
            .unwrap()
            .solve(mach, omega_bar)
            .unwrap(),
    }
}

fn worst(now: &Solution, stored: &Solution) -> f64 {
    let d = [
        now.lift_alpha - stored.lift_alpha,
        now.moment_alpha - stored.moment_alpha,
        now.lift_alphadot - stored.lift_alphadot,
        now.moment_alphadot - stored.moment_alphadot,
        now.lift_q - stored.lift_q,
        now.moment_q - stored.moment_q,
    ];
    d.iter().fold(0.0f64, |m, x| m.max(x.abs())) / now.lift_alpha.abs()
}

#[test]
fn a_sample_of_the_precomputed_solutions_is_solved_again_to_the_same_numbers() {
    let file = Precomputed::parse(FILE).expect("the precomputed solutions");
    let entries = file.entries();
    for solver in [Solver::MachBox, Solver::NearSonicLattice] {
        let n = entries.iter().filter(|(k, _)| k.solver == solver).count();
        assert!(
            n > 100,
            "{solver:?}: {n} solutions: run `cargo xtask tables`"
        );
    }
    // every 97th entry where a solve is cheap (the Mach box above M = 1.2,
    // the lattice below 0.95), and some of the near-sonic ones
    let sample = entries.iter().enumerate().filter(|(i, (k, _))| {
        let cheap = match k.solver {
            Solver::MachBox => k.mach() > 1.2,
            _ => k.mach() < 0.95,
        };
        (cheap && i % 97 == 0) || (!cheap && i % 211 == 0)
    });
    let mut checked = 0;
    for (_, (key, stored)) in sample {
        let [root_chord, tip_chord, semi_span, sweep_le] = key.geometry.map(f64::from_bits);
        let wing = Trapezoid {
            root_chord,
            tip_chord,
            semi_span,
            sweep_le,
        };
        let (mach, omega_bar) = (key.mach(), key.frequency().omega_bar);
        let w = worst(&fresh(key.solver, &wing, mach, omega_bar), stored);
        assert!(
            w < 1e-10,
            "{:?}: {:.1}° wing (tip {tip_chord}), M = {mach}, ω̄ = {omega_bar}: the file differs by {w:e}: run `cargo xtask tables`",
            key.solver,
            sweep_le.to_degrees()
        );
        checked += 1;
    }
    assert!(checked >= 10, "{checked}");
}

/// A wing no other test solves (so that what this test puts in the
/// process-wide store reaches no other).
fn odd_wing(sweep_deg: f64) -> Trapezoid {
    store::unit_wing(1.234_567, 0.0, sweep_deg.to_radians()).unwrap()
}

/// A file holding, for `wing` at M = 2.5, ω̄ = 0.3, the value `bogus`.
fn file_with(wing: &Trapezoid, bogus: Solution) -> String {
    let key = Key::new(
        Solver::MachBox,
        shape(wing),
        2.5,
        ReducedFrequency::harmonic(0.3),
    );
    Precomputed::write([(key, bogus)])
}

fn bogus(mach: f64) -> Solution {
    Solution {
        mach,
        omega_bar: 0.3,
        lift_alpha: 99.0,
        moment_alpha: -99.0,
        lift_alphadot: 9.0,
        moment_alphadot: -9.0,
        lift_q: 1.0,
        moment_q: -1.0,
    }
}

#[test]
fn a_preloaded_solution_is_answered_without_solving() {
    let wing = odd_wing(63.0);
    let file = Precomputed::parse(&file_with(&wing, bogus(2.5))).unwrap();
    assert_eq!(store::preload(&file), 1);
    // the file's value, not a solve's: the store answers what it holds
    assert_eq!(store::mach_box(&wing, 2.5, 0.3).unwrap(), bogus(2.5));
}

#[test]
fn a_changed_solver_fingerprint_makes_the_whole_file_stale_and_the_store_solves_afresh() {
    let wing = odd_wing(64.0);
    let text = file_with(&wing, bogus(2.5));
    let current = fingerprint(Solver::MachBox).unwrap();
    let changed = text.replace(&format!("{current:016x}"), &format!("{:016x}", !current));
    let err = Precomputed::parse(&changed).unwrap_err();
    assert_eq!(
        err,
        PrecomputedError::Stale {
            solver: Solver::MachBox,
            file: !current,
            current
        }
    );
    assert!(err.to_string().contains("cargo xtask tables"), "{err}");
    // nothing was preloaded: the store solves, and gives the solver's value
    let got = store::mach_box(&wing, 2.5, 0.3).unwrap();
    assert!(worst(&fresh(Solver::MachBox, &wing, 2.5, 0.3), &got) == 0.0);
    assert_ne!(got, bogus(2.5));
}
