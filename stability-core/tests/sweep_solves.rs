//! A sweep solves the lifting surface once per (planform, Mach, ω̄), not
//! per c.g., μ₁ or i_B: counted by the cache (`lifting_surface::store::
//! solves`). One test, alone in its binary (not a module of `tests/it/`):
//! the count is the process's, so no other test's solves may be counted
//! with it, and its `store::clear()` would empty the store under the other
//! tests (the allocation tests' warmed store among them).

use stability_core::aerodynamics::damping::Theory;
use stability_core::aerodynamics::lifting_surface::store;
use stability_core::aerodynamics::models::aero::{AeroModel, AeroModelName};
use stability_core::design::case::{Case, DampingModel};
use stability_core::design::study::report_wing;
use stability_core::design::sweep::{Axes, Sweep};

#[test]
fn the_lattice_is_solved_once_per_planform_and_mach_number() {
    let axes = Axes {
        mach: vec![0.5, 0.7, 0.9],
        sweep_deg: vec![50.0, 60.0],
        cg: vec![0.1, 0.2, 0.3, 0.4],
        mu1: vec![20.0, 60.0, 180.0],
        i_b: vec![0.05, 0.1],
        ..Axes::default()
    };
    for (aero, damping) in [
        (AeroModelName::Default, Theory::LiftingSurface),
        (AeroModelName::LiftingSurface, Theory::LiftingSurface),
        (AeroModelName::LiftingSurface, Theory::Slender),
    ] {
        store::clear();
        let base = Case {
            aero: AeroModel::default().with_name(aero),
            damping: DampingModel::Theory(damping),
            ..report_wing(60.0, 0.5)
        };
        let sweep = Sweep::new(base, axes.clone()).unwrap();
        let points = sweep.run(false);
        assert_eq!(points.len(), 144);
        assert!(points.errors.is_empty());
        // 3 Mach numbers × 2 planforms; the lattice's quasi-steady solution
        // serves the damping and, with its Mach derivatives, the lift slope
        // and aerodynamic centre
        assert_eq!(store::solves(), 6, "{} {}", aero.name(), damping.name());
        // a second run solves nothing
        sweep.run(false);
        assert_eq!(store::solves(), 6);
    }
}
