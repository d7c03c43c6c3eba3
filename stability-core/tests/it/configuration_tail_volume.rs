//! The configuration lattice's tail shares against the classical
//! tail-volume formulas, for a small tailplane far behind the note's 60°
//! delta (l_T/c̄ ≈ 4, S_T/S ≈ 0.27).
//!
//! In the lattice's normalisation (lifting_surface/derivatives.rs: forces
//! on ½ρSV, moments on ½ρSVc̄, rates per qc̄/V and α̇c̄/V, so z_w = −(a + C_D)
//! and m_q = ∂C_m/∂(qc̄/V)), a tail of lift slope a_T on its own area S_T, its
//! aerodynamic centre l_T behind the axis, V̄_T = S_T l_T/(S c̄):
//! - pitch rate: the tail's incidence grows by q l_T/V, so
//!   m_q,T = −a_T V̄_T l_T/c̄ (the factor 1 of this normalisation; ½ in the
//!   ρSV normalisation of R&M 1801-era texts);
//! - downwash lag: the downwash at the tail, ε = (dε/dα)α(t − l_T/V), lags
//!   the wing's incidence by l_T/V, so the tail's lift gains
//!   a_T(S_T/S)(dε/dα)α̇ l_T/V and m_ẇ,T = −a_T V̄_T (l_T/c̄)(dε/dα);
//! - with dε/dα from the lattice's own tail load:
//!   ℓ_α,T = a_T(S_T/S)(1 − dε/dα).
//!
//! The formulas neglect the tail's own damping (its load's spread over its
//! chord: ∝ (c̄_T/l_T)² of the above) and the downwash's change along the
//! tail's chord and span; expected accuracy some 10 % at l_T/c̄ ≳ 3.
//! Found (l_T/c̄ = 3.97, V̄_T = 1.08): m_q,T within 3.5 % of the formula
//! (the lattice's smaller: the tail's own chord and the rate's downwash),
//! m_ẇ,T within 0.4 % in the wing's plane (dε/dα = 0.73 at M = 0, 0.76 at
//! M = 0.6) and 5 % at z = 0.3c_r (dε/dα = 0.35).

use stability_core::geometry::configuration::Configuration;

use stability_core::geometry::configuration::Part;

use stability_core::geometry::configuration::Surface;

use stability_core::aerodynamics::lifting_surface::{Lattice, LatticeSpec};
use stability_core::geometry::Trapezoid;
use stability_core::geometry::configuration::SurfaceKind;

#[test]
fn a_distant_tail_follows_the_tail_volume_formulas() {
    let wing = Trapezoid::new(1.0, 0.0, 1.0 / 3f64.sqrt(), 60f64.to_radians()).unwrap();
    let shape = Trapezoid::new(0.3, 0.15, 0.35, 30f64.to_radians()).unwrap();
    let h = 0.25;
    for (mach, z) in [(0.0, 0.0), (0.0, 0.3), (0.6, 0.0)] {
        let tail = Surface {
            kind: SurfaceKind::Tailplane,
            shape,
            x: 3.0,
            z,
            incidence: 0.0,
        };
        let cfg = Configuration {
            tailplane: Some(tail),
            ..Configuration::wing_alone(wing)
        };
        let s = cfg.solve_subsonic(mach, 0.0).unwrap();
        let t = s
            .parts
            .iter()
            .find(|p| p.part == Part::Tailplane)
            .unwrap()
            .solution;
        let d = t.derivatives(h, 0.0).unwrap();
        // the isolated tail's lift slope on its own area
        let a_t = Lattice::new(&shape, LatticeSpec::for_wing(&shape))
            .unwrap()
            .solve(mach, 0.0)
            .unwrap()
            .lift_alpha;
        let (area, c) = (wing.area(), wing.mac());
        let x_axis = wing.x_mac() + h * c;
        let x_tail = tail.x + shape.x_mac() + 0.25 * shape.mac();
        let l = (x_tail - x_axis) / c;
        let volume = shape.area() / area * l;
        let deps = 1.0 - t.lift_alpha / (a_t * shape.area() / area);
        let m_q = -a_t * volume * l;
        let m_wdot = -a_t * volume * l * deps;
        println!(
            "M {mach} z {z}: l_T/c̄ {l:.3}, V̄_T {volume:.3}, dε/dα {deps:.3}; m_q,T {:.4} / {m_q:.4}, m_ẇ,T {:.4} / {m_wdot:.4}",
            d.m_q, d.m_wdot
        );
        assert!(l > 3.0 && deps > 0.1 && deps < 0.9);
        assert!((d.m_q / m_q - 1.0).abs() < 0.10, "m_q: {} {m_q}", d.m_q);
        assert!(
            (d.m_wdot / m_wdot - 1.0).abs() < 0.10,
            "m_ẇ: {} {m_wdot}",
            d.m_wdot
        );
    }
}
