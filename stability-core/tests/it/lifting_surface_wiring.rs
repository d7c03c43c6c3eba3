//! The lifting surface as the program uses it: the steady solve's Mach
//! derivative (what eqs 27–29 need of `aero = "lifting-surface"`), the
//! frequency table a sweep interpolates in, and the cache that solves each
//! (wing, M, ω̄) once. Each against an independent route: central
//! differences of the solves themselves, and direct solves between the
//! table's nodes.

use stability_core::aerodynamics::lifting_surface::frequency::NODES;
use stability_core::aerodynamics::lifting_surface::{
    Extrapolation, FrequencyTable, Harmonic, Lattice, LatticeSpec, OMEGA_BAR_QUASI_STEADY,
    Solution, Spacing, store,
};
use stability_core::geometry::Trapezoid;

fn note_delta(deg: f64, taper: f64) -> Trapezoid {
    let t = deg.to_radians().tan();
    Trapezoid::new(1.0, taper, (1.0 - taper) / t, deg.to_radians()).unwrap()
}

fn six(s: &Solution) -> [f64; 6] {
    [
        s.lift_alpha,
        s.moment_alpha,
        s.lift_alphadot,
        s.moment_alphadot,
        s.lift_q,
        s.moment_q,
    ]
}

/// A small lattice (debug-mode tests), extrapolated as the default is.
fn small(wing: &Trapezoid) -> Lattice {
    let spec = LatticeSpec::new(4, 6, Spacing::Auto).with_extrapolation(Extrapolation::Richardson);
    Lattice::new(wing, spec).unwrap()
}

#[test]
fn the_steady_mach_derivative_is_that_of_the_solves() {
    let wings = [
        ("45°", note_delta(45.0, 0.0)),
        ("60°, λ = 1/7", note_delta(60.0, 1.0 / 7.0)),
        (
            "A = 8",
            Trapezoid::from_aspect_ratio(8.0, 0.4, 30f64.to_radians(), 1.0).unwrap(),
        ),
    ];
    let d = 1e-4;
    for (name, wing) in wings {
        let l = small(&wing);
        for m in [0.0, 0.5, 0.85] {
            let s = l.solve_steady(m).unwrap();
            // the solution is the quasi-steady solve's, bit for bit
            assert_eq!(s.solution, l.solve(m, 0.0).unwrap());
            // at M = 0 every number is even in M: its derivative vanishes
            let rates = [s.d_lift_alpha, s.d_moment_alpha, s.d_lift_q, s.d_moment_q];
            if m == 0.0 {
                assert_eq!(rates, [0.0; 4], "{name}");
                continue;
            }
            // elsewhere, central differences of the solves
            let at = |m: f64| l.solve(m, 0.0).unwrap();
            let (lo, hi) = (at(m - d), at(m + d));
            let fd = |f: fn(&Solution) -> f64| (f(&hi) - f(&lo)) / (2.0 * d);
            let diffs = [
                fd(|s| s.lift_alpha),
                fd(|s| s.moment_alpha),
                fd(|s| s.lift_q),
                fd(|s| s.moment_q),
            ];
            for (k, (exact, diff)) in rates.into_iter().zip(diffs).enumerate() {
                assert!(
                    (exact - diff).abs() <= 1e-6 * (1.0 + diff.abs()),
                    "{name} M = {m}, number {k}: {exact} against {diff}"
                );
            }
            // H₀'s derivative is the quotient rule's
            let (h0, dh0) = s.aerodynamic_centre();
            let h = |s: &Solution| -s.moment_alpha / s.lift_alpha;
            assert_eq!(h0, h(&s.solution));
            let fd_h = (h(&hi) - h(&lo)) / (2.0 * d);
            assert!(
                (dh0 - fd_h).abs() <= 1e-6 * (1.0 + fd_h.abs()),
                "{name} {m}: {dh0} {fd_h}"
            );
        }
    }
}

#[test]
fn the_default_lattices_mach_derivative_too() {
    let wing = note_delta(45.0, 0.0);
    let l = Lattice::new(&wing, LatticeSpec::for_wing(&wing)).unwrap();
    let s = l.solve_steady(0.5).unwrap();
    let d = 1e-4;
    let (lo, hi) = (
        l.solve(0.5 - d, 0.0).unwrap(),
        l.solve(0.5 + d, 0.0).unwrap(),
    );
    let fd = (hi.lift_alpha - lo.lift_alpha) / (2.0 * d);
    assert!(
        (s.d_lift_alpha - fd).abs() < 1e-6 * fd,
        "{} {fd}",
        s.d_lift_alpha
    );
    // and by Prandtl–Glauert's similarity, another route: β·C_Lα(M) is the
    // M = 0 lift slope of the affine wing (spans × β), so d(βC_Lα)/dM is
    // the difference of two incompressible solves of two affine wings
    let affine = |m: f64| {
        let w = wing.affine((1.0 - m * m).sqrt()).unwrap();
        let l = Lattice::new(&w, LatticeSpec::for_wing(&wing)).unwrap();
        l.solve(0.0, 0.0).unwrap().lift_alpha
    };
    let fd_affine = (affine(0.5 + d) - affine(0.5 - d)) / (2.0 * d);
    let beta = 0.75f64.sqrt();
    let exact = beta * s.d_lift_alpha - s.solution.lift_alpha * 0.5 / beta;
    assert!((exact - fd_affine).abs() < 1e-6, "{exact} {fd_affine}");
    assert!(
        exact < 0.0,
        "the affine wing's slope falls with its aspect ratio"
    );
}

#[test]
fn the_table_interpolates_the_direct_solves() {
    let wings = [
        ("45° at M = 0.8", note_delta(45.0, 0.0), 0.8),
        (
            "A = 8 at M = 0.6",
            Trapezoid::from_aspect_ratio(8.0, 0.4, 30f64.to_radians(), 1.0).unwrap(),
            0.6,
        ),
    ];
    // between nodes, from the geometric part to the coarse end
    let tests = [0.003, 0.02, 0.05, 0.12, 0.27, 0.45, 0.75, 1.25, 1.85, 3.1];
    for (name, wing, mach) in wings {
        let l = small(&wing);
        let table = FrequencyTable::new(l.clone(), mach).unwrap();
        let direct: Vec<[f64; 6]> = tests
            .iter()
            .map(|&w| six(&l.solve(mach, w).unwrap()))
            .collect();
        for (k, (&w, d)) in tests.iter().zip(&direct).enumerate() {
            let t = table.at(w).unwrap();
            assert_eq!(t.omega_bar, w);
            for n in 0..6 {
                let scale = direct.iter().map(|v| v[n].abs()).fold(0.0, f64::max);
                let e = (six(&t)[n] - d[n]).abs() / d[n].abs().max(0.1 * scale);
                assert!(e < 4e-3, "{name}, ω̄ = {w} (test {k}), number {n}: {e:.1e}");
            }
        }
        // at a node, the node's solve exactly
        let at_node = table.at(NODES[20]).unwrap();
        assert_eq!(six(&at_node), six(&l.solve(mach, NODES[20]).unwrap()));
        // outside the nodes: quasi-steady below 1e-6, a direct solve beyond
        assert_eq!(table.at(0.0).unwrap(), l.solve(mach, 0.0).unwrap());
        assert_eq!(
            table.at(OMEGA_BAR_QUASI_STEADY / 2.0).unwrap(),
            l.solve(mach, 0.0).unwrap()
        );
        assert_eq!(table.at(5.0).unwrap(), l.solve(mach, 5.0).unwrap());
        let below = table.at(0.0005).unwrap();
        assert_eq!(six(&below), six(&table.node(0).unwrap()));
    }
}

#[test]
fn a_table_solves_only_the_nodes_it_is_asked_for() {
    let wing = note_delta(60.0, 0.0);
    let table = FrequencyTable::new(small(&wing), 0.5).unwrap();
    assert_eq!(table.solved(), 0);
    table.at(0.22).unwrap();
    // the four around 0.2 < ω̄ ≤ 0.25: 0.15, 0.2, 0.25, 0.3
    assert_eq!(table.solved(), 4);
    table.at(0.24).unwrap();
    assert_eq!(table.solved(), 4);
    assert!(FrequencyTable::new(small(&wing), 1.0).is_err());
    assert!(table.at(f64::NAN).is_err() && table.at(-1.0).is_err());
}

#[test]
fn the_store_gives_the_lattices_own_solutions() {
    let wing = store::unit_wing(2.5, 0.2, 55f64.to_radians()).unwrap();
    let lattice = Lattice::new(&wing, LatticeSpec::for_wing(&wing)).unwrap();
    let direct = store::lattice(&wing, 0.6, 0.4, Harmonic::Direct).unwrap();
    assert_eq!(direct, lattice.solve(0.6, 0.4).unwrap());
    // again: the same numbers (from the cache)
    assert_eq!(
        store::lattice(&wing, 0.6, 0.4, Harmonic::Direct).unwrap(),
        direct
    );
    // the steady solve's solution is the quasi-steady one, whichever came first
    let steady = store::lattice_steady(&wing, 0.7).unwrap();
    assert_eq!(steady.solution, lattice.solve(0.7, 0.0).unwrap());
    assert_eq!(
        store::lattice(&wing, 0.7, 0.0, Harmonic::Direct).unwrap(),
        steady.solution
    );
    // interpolated: a frequency table's of the default lattice, to the bit
    let table = FrequencyTable::new(lattice.clone(), 0.6).unwrap();
    let interpolated = store::lattice(&wing, 0.6, 0.37, Harmonic::Interpolated).unwrap();
    assert_eq!(interpolated, table.at(0.37).unwrap());
    // and quasi-steady either way
    assert_eq!(
        store::lattice(&wing, 0.6, 0.0, Harmonic::Interpolated).unwrap(),
        store::lattice(&wing, 0.6, 0.0, Harmonic::Direct).unwrap()
    );
    // bad conditions are errors, not entries
    assert!(store::lattice(&wing, 1.0, 0.0, Harmonic::Direct).is_err());
    assert!(store::lattice(&wing, 0.5, -0.1, Harmonic::Direct).is_err());
    assert!(store::lattice_steady(&wing, f64::NAN).is_err());
}
