//! The lifting surface at every Mach number from 0 to 3
//! (`lifting_surface::mach_range`, issue 22 item 3): above M = 1 the damping
//! theory is the Mach box's solution by axis transfer, at ω̄ → 0 it meets the
//! first-order supersonic theory, the aero model's lift slope, aerodynamic
//! centre and their Mach derivatives meet the exact 4/β of a delta with
//! supersonic leading edges; the sonic band refuses small ω̄ with what to
//! give; the bridge between M = 1 and the Mach box is the line between them;
//! the steady coefficients' join through the sonic point; the
//! subsonic-leading-edge warning; and the approach to M = 1 from both
//! sides (`docs/lattice-near-sonic.md`, "Across M = 1").

use stability_core::aerodynamics::damping::{DampingError, Theory, WingInput, damping_derivatives};
use stability_core::aerodynamics::lifting_surface::mach_box::{self as mach_box, MachBoxSpec};
use stability_core::aerodynamics::lifting_surface::mach_range::{
    MACH_BOX_STEP, MACH_BOX_VERIFIED_BETA_COT, Method, coefficients, first_mach_box_mach, solution,
    sonic_steady, steady,
};
use stability_core::aerodynamics::lifting_surface::{
    Harmonic, LiftingSurfaceError, Solution, store,
};
use stability_core::aerodynamics::models::aero::lifting_surface_steady;
use stability_core::aerodynamics::warnings::Warning;
use stability_core::geometry::{Planform, Size, Trapezoid};
use std::f64::consts::PI;

fn planform(deg: f64) -> Planform {
    Planform::new(deg.to_radians(), 0.0, Size::RootChord(1.0)).unwrap()
}

/// The cache's shape of the planform (as the damping theory makes it).
fn shape(p: &Planform) -> Trapezoid {
    store::unit_wing(p.aspect_ratio(), p.taper, p.sweep_le).unwrap()
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

#[test]
fn above_mach_one_the_damping_theory_is_the_mach_box_by_axis_transfer() {
    // 45° delta at M = 2: β cot Λ = 1.73, a supersonic leading edge
    let p = planform(45.0);
    let wing = WingInput::from(&p);
    for (theory, h) in [
        (Theory::LiftingSurface, 0.25),
        (Theory::LiftingSurfaceFrequency, 0.4),
    ] {
        let d = damping_derivatives(theory, &wing, h, 2.0, Some(0.5)).unwrap();
        let w = shape(&p);
        let s = mach_box::solve(&w, 2.0, 0.5, MachBoxSpec::for_wing(&w, 2.0)).unwrap();
        assert_eq!(d.derivatives, s.derivatives(h, 0.0).unwrap().damping());
        assert!(
            !d.warnings
                .iter()
                .any(|w| matches!(w, Warning::MachBoxSubsonicEdge { .. })),
            "{:?}",
            d.warnings
        );
    }
}

#[test]
fn at_low_frequency_it_meets_the_first_order_supersonic_theory() {
    // no ω̄: the quasi-steady Mach box; (36)'s supersonic-edge form
    let p = planform(45.0);
    let wing = WingInput::from(&p);
    for mach in [2.0, 2.5] {
        let ls = damping_derivatives(Theory::LiftingSurface, &wing, 0.25, mach, None)
            .unwrap()
            .derivatives;
        let first = damping_derivatives(Theory::Supersonic, &wing, 0.25, mach, None)
            .unwrap()
            .derivatives;
        let scale = first.m_q.abs();
        for (a, b, what) in [
            (ls.z_q, first.z_q, "z_q"),
            (ls.z_wdot, first.z_wdot, "z_ẇ"),
            (ls.m_q, first.m_q, "m_q"),
            (ls.m_wdot, first.m_wdot, "m_ẇ"),
        ] {
            let e = (a - b) / scale;
            println!("M {mach} {what}: lifting surface {a:.5}, (36) {b:.5}, {e:+.1e} of m_q");
            assert!(e.abs() < 0.01, "M {mach} {what}: {a} vs {b}");
        }
    }
}

#[test]
fn the_aero_model_meets_four_over_beta_above_the_sonic_leading_edge() {
    // a delta with supersonic leading edges: C_Lα = 4/β exactly (the
    // two-dimensional plate inside the Mach cones), centre of pressure at
    // 2/3 of the root chord, i.e. H₀ = ½ of the M.A.C., at every M
    let p = planform(45.0);
    for mach in [2.0, 2.5] {
        let s = lifting_surface_steady(&p, mach).unwrap();
        let beta = (mach * mach - 1.0_f64).sqrt();
        let (cla, dcla) = s.lift_slope();
        let (h0, dh0) = s.aerodynamic_centre();
        // the exact derivative −4M/β³, and the exact 4/β's own central
        // difference over the dispatch's step (its truncation error apart)
        let exact_d = -4.0 * mach / beta.powi(3);
        let f = |m: f64| 4.0 / (m * m - 1.0).sqrt();
        let h = MACH_BOX_STEP;
        let differenced = (f(mach + h) - f(mach - h)) / (2.0 * h);
        println!(
            "M {mach}: C_Lα {cla:.5} (4/β {:.5}), dC_Lα/dM {dcla:.5} ({exact_d:.5}), H₀ {h0:.5}, dH₀/dM {dh0:.2e}",
            4.0 / beta
        );
        assert!((cla * beta / 4.0 - 1.0).abs() < 2e-3);
        println!(
            "  dC_Lα/dM vs exact {:+.1e}, vs the exact central difference {:+.1e}",
            dcla / exact_d - 1.0,
            dcla / differenced - 1.0
        );
        // measured: −3.4e-3 (M 2), +9.9e-3 (M 2.5): the grid noise ≈ 10⁻⁴ of
        // C_Lα over the step 2 × 0.05
        assert!((dcla / differenced - 1.0).abs() < 1.5e-2);
        assert!((dcla / exact_d - 1.0).abs() < 1.5e-2);
        assert!((h0 - 0.5).abs() < 2e-3 && dh0.abs() < 1e-2);
    }
    // below 0.9: the lattice's exact Mach derivatives, unchanged
    let w = shape(&p);
    let (s, warning) = steady(&w, 0.5).unwrap();
    assert_eq!(s, store::lattice_steady(&w, 0.5).unwrap());
    assert!(warning.is_none());
}

#[test]
fn in_the_sonic_band_a_small_frequency_is_an_error_that_says_what_to_give() {
    let p = planform(45.0);
    let wing = WingInput::from(&p);
    for (mach, omega_bar) in [(1.0, None), (0.995, Some(0.2)), (1.003, None)] {
        let e =
            damping_derivatives(Theory::LiftingSurface, &wing, 0.25, mach, omega_bar).unwrap_err();
        assert!(
            matches!(
                e,
                DampingError::LiftingSurface(LiftingSurfaceError::SonicFrequency { .. })
            ),
            "{e:?}"
        );
        let msg = e.to_string();
        assert!(msg.contains("give --omega-bar 0.3 or more"), "{msg}");
    }
    // the aero model's steady solve there: an error naming the range
    let w = shape(&p);
    for m in [0.995, 1.0, 1.003] {
        assert!(matches!(
            steady(&w, m),
            Err(LiftingSurfaceError::SonicSteady { first_mach_box, .. })
                if first_mach_box == first_mach_box_mach(&w)
        ));
    }
    // out of range is an error
    for m in [-0.1, 3.01, f64::NAN] {
        assert!(matches!(
            solution(&w, m, 0.5, Harmonic::Direct),
            Err(LiftingSurfaceError::MachRange(_))
        ));
    }
}

#[test]
fn the_bridge_is_the_line_from_the_sonic_point_to_the_mach_box() {
    let w = shape(&planform(45.0));
    let first = first_mach_box_mach(&w);
    // 32 strips in 300 rows: β = 31.5/300 on the 45° delta (x_end = s = 1)
    let beta = (first * first - 1.0).sqrt();
    assert!((beta / (31.5 / 300.0) - 1.0).abs() < 1e-6, "{first}");
    let sonic = store::near_sonic(&w, 1.0, 0.6, Harmonic::Direct).unwrap();
    let boxed = store::mach_box(&w, first, 0.6).unwrap();
    let at = |m: f64| solution(&w, m, 0.6, Harmonic::Direct).unwrap();
    assert_eq!(six(&at(1.0).solution), six(&sonic));
    assert_eq!(at(1.0).method, Method::NearSonic);
    let end = at(first);
    assert_eq!(
        (six(&end.solution), end.method),
        (six(&boxed), Method::MachBox)
    );
    let mid = at(0.5 * (1.0 + first));
    assert_eq!(mid.method, Method::SonicBridge);
    assert!(matches!(mid.warning, Some(Warning::SonicBridge { .. })));
    for ((m, a), b) in six(&mid.solution).iter().zip(six(&sonic)).zip(six(&boxed)) {
        assert!((m - 0.5 * (a + b)).abs() < 1e-9 * (1.0 + a.abs() + b.abs()));
    }
}

#[test]
fn a_subsonic_leading_edge_outside_the_verified_range_is_warned() {
    let p = planform(45.0);
    let wing = WingInput::from(&p);
    let warned = |mach: f64| {
        let d = damping_derivatives(Theory::LiftingSurface, &wing, 0.25, mach, Some(0.5)).unwrap();
        let found = d.warnings.iter().find_map(|w| match *w {
            Warning::MachBoxSubsonicEdge { beta_cot, .. } => Some((beta_cot, w.to_string())),
            _ => None,
        });
        let beta_cot = (mach * mach - 1.0).sqrt(); // cot 45° = 1
        if let Some((b, _)) = &found {
            assert!((b - beta_cot).abs() < 1e-9);
        }
        found.map(|(_, text)| text)
    };
    // β cot Λ = 0.244, below the 0.3 down to which it was verified
    assert!((1.03f64 * 1.03 - 1.0).sqrt() < MACH_BOX_VERIFIED_BETA_COT);
    assert!(warned(1.03).unwrap().contains("verified"));
    // 0.663 and 0.831: verified (within 1 % of eq (36) at 1.2 and 1.3)
    assert_eq!(warned(1.2), None);
    assert_eq!(warned(1.3), None);
    // 0.980: just below the sonic edge, the diaphragm narrower than a box
    assert!(warned(1.4).unwrap().contains("4 %"));
    // 1.25: a supersonic edge
    assert_eq!(warned(1.6), None);
}

#[test]
fn across_mach_one_the_mach_box_starts_at_the_slender_limit() {
    // rectangle A = 2 (supersonic leading edge at any M > 1): as M → 1⁺ the
    // steady supersonic loads tend to slender-wing theory's, C_Lα = πA/2
    // with all the lift at the leading edge (the span grows only there):
    // H₀ → 0. The Mach box at its first Mach number, 1.0055:
    let w = store::unit_wing(2.0, 1.0, 0.0).unwrap();
    let first = first_mach_box_mach(&w);
    let s = solution(&w, first, 0.0, Harmonic::Direct).unwrap().solution;
    println!(
        "rectangle A = 2 at M = {first:.4}, steady: C_Lα {:.4} (πA/2 = {:.4}), H₀ {:.4}",
        s.lift_slope(),
        PI,
        s.aerodynamic_centre()
    );
    assert!((s.lift_slope() / PI - 1.0).abs() < 0.02);
    assert!(s.aerodynamic_centre().abs() < 0.01);
    // the jump at ω̄ = 0.6 between the near-sonic lattice at M = 1 and the
    // Mach box at its first Mach number (reported, docs/lattice-near-sonic.md)
    let a = solution(&w, 1.0, 0.6, Harmonic::Direct).unwrap().solution;
    let b = solution(&w, first, 0.6, Harmonic::Direct).unwrap().solution;
    let (da, db) = (
        a.derivatives(0.25, 0.0).unwrap(),
        b.derivatives(0.25, 0.0).unwrap(),
    );
    let cla = a.lift_slope();
    println!(
        "jump at ω̄ 0.6 (of C_Lα at M = 1): C_Lα {:+.3}, H₀ {:+.3} (abs), z_θ̇ {:+.3}, m_θ̇ {:+.3}, z_ẇ {:+.3}, m_ẇ {:+.3}",
        (b.lift_slope() - cla) / cla,
        b.aerodynamic_centre() - a.aerodynamic_centre(),
        (db.z_thetadot - da.z_thetadot) / cla,
        (db.m_thetadot - da.m_thetadot) / cla,
        (db.z_wdot - da.z_wdot) / cla,
        (db.m_wdot - da.m_wdot) / cla,
    );
    for v in six(&a).into_iter().chain(six(&b)) {
        assert!(v.is_finite());
    }
}

/// The quasi-steady lift slope and aerodynamic centre across M = 1
/// (`mach_range::coefficients`): at M = 1 linear theory's sonic point,
/// slender-wing theory (C_Lα = πA/2, the centre at ⅔ of the tip's
/// leading-edge station — the deltas' ⅔ root chord, H₀ = ½), which the
/// Mach box at its first Mach number approaches from above M = 1 (within
/// 1.7 % in C_Lα and 4·10⁻⁴ in H₀ on the note's deltas: an independent
/// route to the anchor); equal to `steady` at both ends of the join, and
/// monotone on each side (no overshoot of its ends).
#[test]
fn the_steady_coefficients_are_joined_through_the_sonic_point() {
    for deg in [45.0, 60.0] {
        let p = planform(deg);
        let w = shape(&p);
        let (a1, h1) = sonic_steady(&w).unwrap();
        assert!((a1 / (PI * p.aspect_ratio() / 2.0) - 1.0).abs() < 1e-12);
        assert!((h1 - 0.5).abs() < 1e-12, "{h1}");
        let at = |m: f64| coefficients(&w, m).unwrap();
        let sonic = at(1.0);
        assert!(sonic.joined);
        assert_eq!((sonic.lift_slope.0, sonic.aerodynamic_centre.0), (a1, h1));
        // the Mach box just above M = 1 approaches the same limit
        let first = first_mach_box_mach(&w);
        let above = at(first);
        assert!(!above.joined);
        println!(
            "{deg}°: sonic C_Lα {a1:.4}, H₀ {h1:.4}; Mach box at M = {first:.4}: {:.4}, {:.4}",
            above.lift_slope.0, above.aerodynamic_centre.0
        );
        assert!((above.lift_slope.0 / a1 - 1.0).abs() < 0.02);
        assert!((above.aerodynamic_centre.0 - h1).abs() < 1e-3);
        // the ends: steady's values
        let below = steady(&w, 0.99).unwrap().0;
        let inside = at(0.99 + 1e-9);
        assert!(inside.joined);
        assert!((inside.lift_slope.0 - below.lift_slope().0).abs() < 1e-6);
        let just = at(first - 1e-9);
        assert!((just.lift_slope.0 - above.lift_slope.0).abs() < 1e-6);
        // monotone: rising to the sonic point, falling after (the deltas)
        let ms: Vec<f64> = (0..=20).map(|k| 0.99 + 0.0005 * k as f64).collect();
        let rise: Vec<f64> = ms.iter().map(|&m| at(m).lift_slope.0).collect();
        assert!(rise.windows(2).all(|p| p[1] >= p[0]), "{rise:?}");
        let fall: Vec<f64> = (0..=10)
            .map(|k| at(1.0 + (first - 1.0) * k as f64 / 10.0).lift_slope.0)
            .collect();
        assert!(fall.windows(2).all(|p| p[1] <= p[0]), "{fall:?}");
        assert!(fall.iter().all(|&v| v <= a1 && v >= above.lift_slope.0));
    }
    // a forward-swept leading edge has no sonic point (sections not convex)
    let w = store::unit_wing(4.0, 0.5, (-20f64).to_radians()).unwrap();
    assert_eq!(sonic_steady(&w), None);
}
