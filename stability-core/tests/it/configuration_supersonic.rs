//! The supersonic configuration theory (issue 21 item 3) against
//! independent routes: the limit of a vanishing tail, the hand-worked
//! tail-volume formulas for a small distant tail, and the theories' own
//! axis transfer for a surface moved against the wing.

use stability_core::aerodynamics::supersonic::configuration::{Placement, moved, own_solution};
use stability_core::aerodynamics::supersonic::{Wing, edge_theory};
use stability_core::geometry::configuration::Configuration;
use stability_core::geometry::configuration::Part;
use stability_core::geometry::configuration::Surface;
use stability_core::geometry::configuration::SurfaceKind;
use stability_core::geometry::{Planform, Size, Trapezoid};
use std::f64::consts::PI;

fn delta(deg: f64, taper: f64, root: f64) -> Trapezoid {
    Trapezoid::from(&Planform::new(deg.to_radians(), taper, Size::RootChord(root)).unwrap())
}

fn tailed(wing: Trapezoid, shape: Trapezoid, x: f64, z: f64) -> Configuration {
    Configuration {
        tailplane: Some(Surface {
            kind: SurfaceKind::Tailplane,
            shape,
            x,
            z,
            incidence: 0.0,
        }),
        ..Configuration::wing_alone(wing)
    }
}

#[test]
fn a_vanishing_tail_leaves_the_wing_alone() {
    let wing = delta(45.0, 0.0, 1.0);
    let alone = note_bands(&Configuration::wing_alone(wing), 1.6);
    assert_eq!(alone.solution.lift_alpha, 0.0);
    assert_eq!(alone.solution.moment_q, 0.0);
    assert!(alone.parts.is_empty());
    // the increment scales with the tail's area: ∝ root chord² for a
    // delta of fixed sweep; at c₀ = 1e-6 it is 1e-12 of the wing's
    let wing_sol = Configuration::wing_alone(wing)
        .solve_supersonic(1.6, 0.0)
        .unwrap()
        .total;
    let tiny = tailed(wing, delta(45.0, 0.0, 1e-6), 3.0, 0.0);
    let inc = note_bands(&tiny, 1.6).solution;
    let total = tiny.solve_supersonic(1.6, 0.0).unwrap().total;
    assert!(inc.lift_alpha.abs() < 1e-11 * wing_sol.lift_alpha);
    assert!((total.lift_alpha - wing_sol.lift_alpha).abs() < 1e-11 * wing_sol.lift_alpha);
    assert!((total.moment_q - wing_sol.moment_q).abs() < 1e-9 * wing_sol.moment_q.abs());
}

/// The small distant tail at M = 2: a 45° true delta (supersonic leading
/// edge, a_T = 4/β, centre of pressure at ⅔ of its root chord) of 1/20 the
/// wing's root chord, 40 wing root chords aft, in the wing's plane, behind
/// the 45° true-delta wing (a_w = 4/β, A = 4, its aerodynamic centre at ⅔
/// of its root chord). Hand formulas in the report's normalisation, with
/// the tail's own rate terms (of relative order c_T/l_T) neglected:
/// dε/dα = 2a_w/(πA) (Trefftz plane, in the plane), κ = (dε/dα)/a_w,
/// Δa = a_T(S_T/S)(1 − dε/dα),
/// Δz_q = −a_T(S_T/S)[l_T/c̄ − κℓ_q,w(h)], Δm_q = (l_T/c̄)Δz_q
///   (= −a_T V̄_T l_T/c̄ without the downwash of the wing's pitch-rate lift),
/// Δz_ẇ = −a_T(S_T/S)[dε/dα·l_ε/c̄ − κℓ_α̇,w], Δm_ẇ = (l_T/c̄)Δz_ẇ,
/// with the true delta's ℓ_q,w(h) = (4/β)(½ − h) and ℓ_α̇,w = −2/β³
/// (`supersonic::strip::true_delta`), l_T from the c.g. and l_ε from the
/// wing's aerodynamic centre to the tail's.
#[test]
fn a_small_distant_tail_follows_the_tail_volume_formulas() {
    let (mach, h, c0) = (2.0, 0.3, 1.0);
    let beta = (mach * mach - 1.0f64).sqrt();
    let wing = delta(45.0, 0.0, c0);
    let (ct, x) = (c0 / 20.0, 40.0 * c0);
    let config = tailed(wing, delta(45.0, 0.0, ct), x, 0.0);
    let inc = note_bands(&config, mach);
    let d = inc.solution.derivatives(h, 0.0).unwrap();
    let (s, cbar) = (wing.area(), wing.mac());
    let (a_w, a_t, r) = (4.0 / beta, 4.0 / beta, (ct * ct) / (c0 * c0));
    assert!((s - c0 * c0).abs() < 1e-12);
    let de = 2.0 * a_w / (PI * 4.0);
    let kappa = de / a_w;
    let x_cg = wing.x_mac() + h * cbar;
    let tail_ac = x + 2.0 / 3.0 * ct;
    let l_t = (tail_ac - x_cg) / cbar;
    let l_e = (tail_ac - 2.0 / 3.0 * c0) / cbar;
    let lq_w = 4.0 / beta * (0.5 - h);
    let lad_w = -2.0 / (beta * beta * beta);
    let expect_a = a_t * r * (1.0 - de);
    let z_q = -a_t * r * (l_t - kappa * lq_w);
    let z_wdot = -a_t * r * (de * l_e - kappa * lad_w);
    let cases = [
        ("Δa", d.lift_slope, expect_a, 1e-12),
        ("Δz_q", d.z_q, z_q, 1e-3),
        ("Δm_q", d.m_q, l_t * z_q, 1e-3),
        ("Δz_ẇ", d.z_wdot, z_wdot, 1e-3),
        ("Δm_ẇ", d.m_wdot, l_t * z_wdot, 1e-3),
    ];
    for (name, got, want, tol) in cases {
        let rel = (got - want).abs() / want.abs();
        eprintln!("{name}: {got:.6e} against {want:.6e}, relative {rel:.2e}");
        assert!(
            rel < tol,
            "{name}: {got} against the hand formula {want} ({rel:.2e})"
        );
    }
    assert_eq!(inc.parts.len(), 1);
    assert_eq!(inc.parts[0].part, Part::Tailplane);
}

/// A cropped 60° surface 3 wing M.A.C.s aft and half the wing's size,
/// moved to the wing's S, c̄ and axis, has about the wing's c.g. h the
/// derivatives its own theory gives about the same point, h_T =
/// (x_cg − x̄_T)/c̄_T, scaled by r = S_T/S and k = c̄_T/c̄:
/// a′ = r a_T, z_q′ = rk z_q,T, m_q′ = rk² m_q,T, z_ẇ′ = rk z_ẇ,T,
/// m_ẇ′ = rk² m_ẇ,T, m_w′ = rk m_w,T.
#[test]
fn a_moved_surface_matches_its_own_theory_about_the_same_axis() {
    let mach = 1.8;
    let wing = delta(45.0, 0.0, 2.0);
    let shape = delta(60.0, 0.2, 1.0);
    let x = 3.0 * wing.mac();
    let own = own_solution(&shape, "surface", mach, 0.0).unwrap();
    let p = Placement::of(&shape, x, &wing);
    let (r, k) = (p.area_ratio, p.chord_ratio);
    let pf = Planform::new(60f64.to_radians(), 0.2, Size::RootChord(1.0)).unwrap();
    for h in [-0.2, 0.25, 0.6] {
        let x_cg = wing.x_mac() + h * wing.mac();
        let h_t = (x_cg - (x + shape.x_mac())) / shape.mac();
        let t = edge_theory(&Wing::from(&pf), mach, h_t)
            .unwrap()
            .derivatives;
        let m = moved(&own, &p).derivatives(h, 0.0).unwrap();
        let m_w_t = (h_t - t.aerodynamic_centre) * t.lift_slope;
        let pairs = [
            (m.lift_slope, r * t.lift_slope),
            (m.z_q, r * k * t.damping.z_q),
            (m.m_q, r * k * k * t.damping.m_q),
            (m.z_wdot, r * k * t.damping.z_wdot),
            (m.m_wdot, r * k * k * t.damping.m_wdot),
            (m.m_w, r * k * m_w_t),
        ];
        for (i, (got, want)) in pairs.into_iter().enumerate() {
            assert!(
                (got - want).abs() < 1e-10 * (1.0 + want.abs()),
                "h = {h}, #{i}: {got} vs {want}"
            );
        }
    }
}

#[test]
fn a_swept_trailing_edge_is_refused_with_advice() {
    let wing = delta(45.0, 0.0, 1.0);
    let swept = Trapezoid::new(1.0, 0.4, 1.0, 50f64.to_radians()).unwrap();
    let e = tailed(wing, swept, 3.0, 0.0)
        .solve_supersonic(2.0, 0.0)
        .unwrap_err();
    assert!(e.to_string().contains("unswept trailing edge"), "{e}");
    assert!(
        Configuration::wing_alone(wing)
            .solve_supersonic(0.9, 0.0)
            .is_err()
    );
}

/// The increment by linear supersonic theory: the note's bands above
/// M = 1.2 (`faired-theories`).
fn note_bands(
    config: &Configuration,
    mach: f64,
) -> stability_core::aerodynamics::models::increment::Increment {
    stability_core::design::case::DampingModel::FairedTheories
        .increment(
            config,
            mach,
            0.0,
            stability_core::aerodynamics::lifting_surface::Harmonic::Direct,
            true,
        )
        .unwrap()
}
