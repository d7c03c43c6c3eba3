//! The neutral point h_n and the static margin h_n − h
//! (`criteria::NeutralPoint`, the sweep's `neutral_point` and
//! `static_margin_pct` columns) against independent values: the doublet
//! lattice's own aerodynamic centre −μ_α/ℓ_α; linear theory's centre of
//! pressure of a delta at supersonic speed (two-thirds of the root chord,
//! h = ½ on the M.A.C., at every Mach number); and eq (42)'s K_n, whose
//! zero the Mach-number term m_u moves from h_n by −(M/2)·dH₀/dM (from
//! E = (μ₁/i_B)C_L(m_w z_u − z_w m_u) with eqs 10, 13, 14: E = 0 where
//! (h − H₀)(z_u + M C_L a′/a) = M C_L H₀′, and z_u + M C_L a′/a = −2C_L).

use stability_core::aerodynamics::damping::Theory;
use stability_core::aerodynamics::models::aero::{
    AeroModel, AeroModelName, lifting_surface_steady,
};
use stability_core::design::case::{Case, DampingModel, evaluate_point};
use stability_core::design::study::report_wing;
use stability_core::design::sweep::{Axes, Sweep};

fn case(deg: f64, mach: f64, damping: DampingModel, aero: AeroModelName) -> Case {
    Case {
        damping,
        aero: AeroModel::default().with_name(aero),
        ..report_wing(deg, mach)
    }
}

/// A steady model (the lattice for the lift slope, the aerodynamic centre
/// and the damping, quasi-steady): h_n is the lattice's aerodynamic centre
/// at every c.g., and the margin is h_n − h in per cent.
#[test]
fn the_neutral_point_of_a_steady_model_is_the_lattices_aerodynamic_centre() {
    let damping = DampingModel::Theory(Theory::LiftingSurface);
    let base = case(60.0, 0.6, damping, AeroModelName::LiftingSurface);
    let axes = Axes {
        mach: vec![0.4, 0.7],
        cg: vec![0.1, 0.25, 0.45],
        ..Axes::around(&base)
    };
    let sweep = Sweep::new(base.clone(), axes).unwrap();
    let points = sweep.run(false);
    assert!(points.errors.is_empty(), "{:?}", points.errors);
    for i in 0..points.len() {
        let steady = lifting_surface_steady(&base.planform, points.mach[i]).unwrap();
        let (h0, _) = steady.aerodynamic_centre();
        let (h_n, h) = (points.neutral_point[i], points.cg[i]);
        assert!(
            (h_n - h0).abs() < 1e-12,
            "M {}: {h_n} vs {h0}",
            points.mach[i]
        );
        assert!((points.static_margin_pct[i] - 100.0 * (h0 - h)).abs() < 1e-10);
        // the c.g. ahead of the neutral point is stable in incidence: m_w < 0
        let r = evaluate_point(&sweep.case(i)).unwrap();
        assert_eq!(r.derivatives.m_w < 0.0, points.static_margin_pct[i] > 0.0);
    }
}

/// At M = 1.5 a true delta's centre of pressure is at two-thirds of its
/// root chord in linear theory (conical flow), whatever the Mach number:
/// h = ½ on the M.A.C. (which runs from c₀/3 to c₀). There m_u = 0, so
/// eq (42)'s K_n changes sign exactly at h_n.
#[test]
fn k_n_changes_sign_at_the_neutral_point_where_the_centre_does_not_move() {
    let base = case(
        60.0,
        1.5,
        DampingModel::Theory(Theory::Supersonic),
        AeroModelName::Default,
    );
    let axes = Axes {
        cg: vec![0.4, 0.45, 0.5, 0.55, 0.6],
        ..Axes::around(&base)
    };
    let points = Sweep::new(base, axes).unwrap().run(false);
    assert!(points.errors.is_empty(), "{:?}", points.errors);
    for i in 0..points.len() {
        let (h, k_n) = (points.cg[i], points.k_n[i]);
        assert!((points.neutral_point[i] - 0.5).abs() < 1e-9, "{h}");
        assert!((points.static_margin_pct[i] - 100.0 * (0.5 - h)).abs() < 1e-7);
        match h {
            h if h < 0.5 => assert!(k_n > 0.0, "h {h}: K_n {k_n}"),
            h if h > 0.5 => assert!(k_n < 0.0, "h {h}: K_n {k_n}"),
            _ => assert!(k_n.abs() < 1e-9, "K_n {k_n} at h_n"),
        }
    }
}

/// Where the aerodynamic centre moves with Mach number, K_n (constant
/// C_L·M²) vanishes at H₀ − (M/2)·dH₀/dM, not at h_n = H₀: the difference
/// the page and the columns name.
#[test]
fn mach_tuck_moves_the_zero_of_k_n_from_the_neutral_point() {
    for mach in [0.9, 0.95] {
        let base = case(
            60.0,
            mach,
            DampingModel::FairedSlender,
            AeroModelName::Default,
        );
        let (h1, h2) = (0.2, 0.6);
        let axes = Axes {
            cg: vec![h1, h2],
            ..Axes::around(&base)
        };
        let points = Sweep::new(base.clone(), axes).unwrap().run(false);
        assert!(points.errors.is_empty(), "{:?}", points.errors);
        let h0 = evaluate_point(&base)
            .unwrap()
            .coefficients
            .aerodynamic_centre;
        let tuck = mach / 2.0 * h0.d_mach;
        assert!(tuck.abs() > 1e-3, "M {mach}: the centre hardly moves");
        // K_n is linear in h (m_w and m_u are; z_u, z_w and C_L are not h's)
        let (k1, k2) = (points.k_n[0], points.k_n[1]);
        let zero = h1 - k1 * (h2 - h1) / (k2 - k1);
        assert!((zero - (h0.value - tuck)).abs() < 1e-9, "M {mach}: {zero}");
        for k in 0..2 {
            assert!((points.neutral_point[k] - h0.value).abs() < 1e-12);
        }
    }
}
