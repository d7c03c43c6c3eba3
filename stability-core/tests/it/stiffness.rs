//! The stiffness derivatives against an independent route: the forces and
//! moment on the aircraft built from the coefficient model and resolved
//! into the stability axes of the undisturbed flight, then differentiated
//! numerically with respect to the disturbance velocities û = u/V and
//! ŵ = w/V — the definitions of §3, not the report's chain of eqs (9)–(29).
//!
//! With the disturbed velocity V(1 + û, ŵ): the dynamic pressure grows by
//! q̂ = (1 + û)² + ŵ², the incidence by Δα = atan(ŵ/(1 + û)) and the Mach
//! number to M₀√q̂; lift and drag act normal and along the disturbed
//! velocity, so in the fixed axes (X forward, Z down)
//! X/(½ρV²S) = q̂(C_L sin Δα − C_D cos Δα) and
//! Z/(½ρV²S) = −q̂(C_L cos Δα + C_D sin Δα), with C_L = a(M)·α,
//! C_D = C_D0(M) + K(M)C_L²; the pitching moment is that of the normal
//! force C_N = C_L cos Δα + C_D sin Δα about the c.g., (h − H₀(M))·C_N,
//! plus the elevon's trim moment, which cancels it in the undisturbed
//! flight (the report's trimmed aircraft, eq 13). Then x_u = ∂(X/½ρV²S)/∂û,
//! x_w = ∂(X/½ρV²S)/∂ŵ, and so on (the report's ½ρSV normalisation).

use stability_core::aerodynamics::models::aero::{AeroModel, Coefficients, level_flight_lift};
use stability_core::aerodynamics::models::stiffness::stiffness;
use stability_core::geometry::{Planform, Size};

/// (X, Z, M) on ½ρV²S (M also on c̄) at the disturbance (û, ŵ).
fn forces(
    model: &AeroModel,
    p: &Planform,
    (mach, alpha, h): (f64, f64, f64),
    trim: f64,
    (u, w): (f64, f64),
) -> [f64; 3] {
    let q = (1.0 + u).powi(2) + w * w;
    let d_alpha = (w / (1.0 + u)).atan();
    let c: Coefficients = model.at(p, mach * q.sqrt()).unwrap();
    let cl = c.lift_slope.value * (alpha + d_alpha);
    let cd = c.zero_lift_drag.value + c.drag_due_to_lift.value * cl * cl;
    let (s, co) = d_alpha.sin_cos();
    let cn = cl * co + cd * s;
    [
        q * (cl * s - cd * co),
        -q * (cl * co + cd * s),
        q * ((h - c.aerodynamic_centre.value) * cn + trim),
    ]
}

#[test]
fn the_six_stiffness_derivatives_from_the_forces_on_the_aircraft() {
    let model = AeroModel::default();
    for deg in [45.0f64, 60.0] {
        let p = Planform::new(deg.to_radians(), 0.0, Size::RootChord(10.0)).unwrap();
        for mach in [0.5, 0.85, 0.95, 1.1, 1.3, 1.8] {
            let h = 0.25;
            let cl = level_flight_lift(0.05, mach).value;
            let c = model.at(&p, mach).unwrap();
            let s = stiffness(&c, cl, h);
            let alpha = cl / c.lift_slope.value;
            let trim = -(h - c.aerodynamic_centre.value) * cl;
            let at = |u: f64, w: f64| forces(&model, &p, (mach, alpha, h), trim, (u, w));
            let d = 1e-6;
            let (up, um) = (at(d, 0.0), at(-d, 0.0));
            let (wp, wm) = (at(0.0, d), at(0.0, -d));
            let by_u: [f64; 3] = std::array::from_fn(|k| (up[k] - um[k]) / (2.0 * d));
            let by_w: [f64; 3] = std::array::from_fn(|k| (wp[k] - wm[k]) / (2.0 * d));
            let near = |got: f64, want: f64, what: &str| {
                assert!(
                    (got - want).abs() <= 1e-6 * (1.0 + want.abs()),
                    "{deg}° M {mach} {what}: {got} vs {want} from the forces"
                )
            };
            near(s.x_u, by_u[0], "x_u (eq 9)");
            near(s.z_u, by_u[1], "z_u (eq 10)");
            near(s.m_u, by_u[2], "m_u (eq 13, trimmed)");
            near(s.x_w, by_w[0], "x_w (eq 11)");
            near(s.z_w, by_w[1], "z_w (eq 12)");
            near(s.m_w, by_w[2], "m_w (eqs 14, 25)");
        }
    }
}

/// A hand value: the 45° delta at M = 0.5 with the default models,
/// a = 2πA/(2 + √(A²(β² + tan²Λ½) + 4)) = 8π/(2 + √20) = 3.8832 (A = 4,
/// tan Λ½ = ½, β² = 0.75), C_L = 0.05/0.25 = 0.2, K = 1/a,
/// C_D = 0.01 + 0.04/a: z_w = −C_D − a = −3.9035.
#[test]
fn z_w_by_hand() {
    let p = Planform::new(45f64.to_radians(), 0.0, Size::RootChord(10.0)).unwrap();
    let c = AeroModel::default().at(&p, 0.5).unwrap();
    let a = 2.0 * std::f64::consts::PI * 4.0 / (2.0 + (16.0 * (0.75 + 0.25) + 4.0f64).sqrt());
    assert!((a - 3.883_2).abs() < 1e-4, "{a}");
    let s = stiffness(&c, level_flight_lift(0.05, 0.5).value, 0.25);
    assert!((s.z_w - (-0.01 - 0.04 / a - a)).abs() < 1e-12, "{}", s.z_w);
    assert!((s.z_w + 3.903_5).abs() < 1e-4, "{}", s.z_w);
}

#[test]
fn level_flight_keeps_cl_m_squared() {
    for m in [0.5, 1.0, 2.0] {
        let v = level_flight_lift(0.08, m);
        assert!((v.value * m * m - 0.08).abs() < 1e-15);
        assert!((v.d_mach + 2.0 * v.value / m).abs() < 1e-15);
    }
}
