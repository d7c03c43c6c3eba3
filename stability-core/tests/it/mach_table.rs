//! The Mach box's table in Mach number (`lifting_surface::mach_table`:
//! nodes equally spaced in β on either side of the sonic leading edge,
//! each interpolated in ω̄) against direct Mach box solves between its
//! nodes; its slope against the exact Mach derivative of the supersonic-
//! edged delta's lift slope, 4/β (Puckett & Stewart 1947); and the
//! quasi-steady Mach derivatives `mach_range::steady` takes from it.

use stability_core::aerodynamics::lifting_surface::mach_range::steady;
use stability_core::aerodynamics::lifting_surface::store::mach_box as solution;
use stability_core::aerodynamics::lifting_surface::{Solution, mach_table};
use stability_core::geometry::{Planform, Size, Trapezoid};

fn wing(deg: f64, taper: f64) -> Trapezoid {
    let p = Planform::new(deg.to_radians(), taper, Size::RootChord(1.0)).unwrap();
    Trapezoid::from(&p)
}

/// The largest difference of the six numbers, on the scale of C_Lα.
fn apart(a: &Solution, b: &Solution) -> f64 {
    let d = [
        a.lift_alpha - b.lift_alpha,
        a.moment_alpha - b.moment_alpha,
        a.lift_alphadot - b.lift_alphadot,
        a.moment_alphadot - b.moment_alphadot,
        a.lift_q - b.lift_q,
        a.moment_q - b.moment_q,
    ];
    d.iter().fold(0.0f64, |m, x| m.max(x.abs())) / b.lift_alpha.abs()
}

/// Between the nodes, off-centre, on the note's deltas (the 45° next to
/// its sonic edge at M = √2 too) and a cropped delta, at the short
/// period's ω̄ and off the frequency nodes: within 2.5·10⁻³ of C_Lα
/// (measured worst 2.1·10⁻³, the 45° delta at M = 1.033, ω̄ = 0.13, most
/// of it the frequency interpolation below β = 0.3; 1.7·10⁻³ at M = 1.405,
/// beside the sonic edge; elsewhere the Mach box's own scatter from Mach
/// number to Mach number, ~10⁻³).
#[test]
fn the_table_is_within_2_5e_3_of_the_direct_solves_between_its_nodes() {
    let cases = [
        (45.0, 0.0, 1.07, 0.45),
        (45.0, 0.0, 1.405, 0.13),
        (45.0, 0.0, 1.97, 0.45),
        (60.0, 0.0, 1.24, 0.45),
        (60.0, 0.0, 2.3, 0.8),
        (45.0, 1.0 / 7.0, 1.3, 0.45),
    ];
    for (deg, taper, mach, ob) in cases {
        let w = wing(deg, taper);
        let nodes = mach_table::nodes(&w);
        assert!(!nodes.iter().any(|&m| (m - mach).abs() < 1e-3), "{mach}");
        let (t, _) = mach_table::solution(&w, mach, ob).unwrap();
        let d = solution(&w, mach, ob).unwrap();
        let e = apart(&t, &d);
        assert!(e < 2.5e-3, "{deg}° taper {taper} M {mach} ω̄ {ob}: {e:.2e}");
        assert_eq!((t.mach, t.omega_bar), (mach, ob));
    }
}

/// At a node the table is the node's solve (to rounding, ω̄ on a frequency
/// node).
#[test]
fn at_a_node_the_table_is_the_solve() {
    let w = wing(60.0, 0.0);
    let m = mach_table::nodes(&w)[12];
    let (t, _) = mach_table::solution(&w, m, 0.5).unwrap();
    let d = solution(&w, m, 0.5).unwrap();
    assert!(apart(&t, &d) < 1e-13, "{:e}", apart(&t, &d));
}

/// The 45° delta's leading edge is supersonic past M = √2, where C_Lα =
/// 4/β exactly: its Mach derivative −4M/β³ from the table's slope within
/// 2 % at M = 1.6, 2 and 2.5 (quasi-steady), through `mach_range::steady`
/// (measured: 1.4 % at M = 2.5, the Mach box's own scatter of ≈ 10⁻³ of
/// C_Lα from node to node; the central difference over ±0.05 it replaces
/// was 1.1 % off there).
#[test]
fn the_slope_is_the_exact_mach_derivative_of_4_over_beta() {
    let w = wing(45.0, 0.0);
    for mach in [1.6, 2.0, 2.5] {
        let beta: f64 = (mach * mach - 1.0_f64).sqrt();
        let exact = -4.0 * mach / beta.powi(3);
        let (s, _) = steady(&w, mach).unwrap();
        let (a, da) = s.lift_slope();
        assert!((a / (4.0 / beta) - 1.0).abs() < 5e-3, "M {mach}: {a}");
        assert!((da / exact - 1.0).abs() < 2e-2, "M {mach}: {da} vs {exact}");
    }
}
