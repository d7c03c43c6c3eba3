//! The lifting-surface solutions solved ahead of time
//! (`stability-core/data/lifting-surface-solutions.csv`, `frozen`) are what
//! the solvers give now: a sample of the file's entries solved again —
//! the Mach box's and the near-sonic lattice's, the cheap ones and a few
//! near-sonic ones — every number within 10⁻¹⁰ of C_Lα (the same code:
//! they could differ in the last bits of another machine's libm). A change
//! to either solver without `cargo xtask tables` fails here.

use stability_core::frozen::{self, Kind};
use stability_core::geometry::Trapezoid;
use stability_core::lifting_surface::mach_box::{MachBoxSpec, solve};
use stability_core::lifting_surface::{Lattice, LatticeSpec, Solution};

fn fresh(kind: Kind, wing: &Trapezoid, mach: f64, omega_bar: f64) -> Solution {
    match kind {
        Kind::MachBox => solve(wing, mach, omega_bar, MachBoxSpec::for_wing(wing, mach)).unwrap(),
        Kind::NearSonicLattice => Lattice::new(wing, LatticeSpec::for_mach(wing, mach))
            .unwrap()
            .solve(mach, omega_bar)
            .unwrap(),
    }
}

#[test]
fn a_sample_of_the_frozen_solutions_is_solved_again_to_the_same_numbers() {
    let entries = frozen::entries();
    for kind in [Kind::MachBox, Kind::NearSonicLattice] {
        let n = entries.iter().filter(|(k, _)| k.0 == kind).count();
        assert!(n > 100, "{kind:?}: {n} solutions: run `cargo xtask tables`");
    }
    // every 97th entry where a solve is cheap (the Mach box above M = 1.2,
    // the lattice below 0.95), and some of the near-sonic ones
    let sample = entries.iter().enumerate().filter(|(i, (k, _))| {
        let mach = f64::from_bits(k.2);
        let cheap = match k.0 {
            Kind::MachBox => mach > 1.2,
            Kind::NearSonicLattice => mach < 0.95,
        };
        (cheap && i % 97 == 0) || (!cheap && i % 211 == 0)
    });
    let mut checked = 0;
    for (_, (key, stored)) in sample {
        let [root_chord, tip_chord, semi_span, sweep_le] = key.1.map(f64::from_bits);
        let wing = Trapezoid {
            root_chord,
            tip_chord,
            semi_span,
            sweep_le,
        };
        let (mach, omega_bar) = (f64::from_bits(key.2), f64::from_bits(key.3));
        let now = fresh(key.0, &wing, mach, omega_bar);
        let d = [
            now.lift_alpha - stored.lift_alpha,
            now.moment_alpha - stored.moment_alpha,
            now.lift_alphadot - stored.lift_alphadot,
            now.moment_alphadot - stored.moment_alphadot,
            now.lift_q - stored.lift_q,
            now.moment_q - stored.moment_q,
        ];
        let worst = d.iter().fold(0.0f64, |m, x| m.max(x.abs())) / now.lift_alpha.abs();
        assert!(
            worst < 1e-10,
            "{:?}: {:.1}° wing (tip {tip_chord}), M = {mach}, ω̄ = {omega_bar}: the file differs by {worst:e}: run `cargo xtask tables`",
            key.0,
            sweep_le.to_degrees()
        );
        checked += 1;
    }
    assert!(checked >= 10, "{checked}");
}
