//! The stiffness derivatives against an independent route: C_L, C_D, C_m as
//! functions of (α, M) built from the same coefficient model, differentiated
//! by central differences in the test, then eqs (9)–(14) applied directly —
//! i.e. the definitions, not the report's chain of eqs (21)–(29).

use stability_core::aero::{AeroModel, level_flight_lift};
use stability_core::geometry::{Planform, Size};
use stability_core::stiffness::stiffness;

#[test]
fn eqs_9_to_14_against_finite_differences_of_the_coefficients() {
    let model = AeroModel::default();
    for deg in [45.0f64, 60.0] {
        let p = Planform::new(deg.to_radians(), 0.0, Size::RootChord(10.0)).unwrap();
        for mach in [0.5, 0.85, 0.95, 1.1, 1.3, 1.8] {
            let h = 0.25;
            let cl = level_flight_lift(0.05, mach).value;
            let c = model.at(&p, mach).unwrap();
            let s = stiffness(&c, cl, h);
            // Coefficients at incidence α (C_L = aα) and Mach M:
            let coefs = |alpha: f64, m: f64| {
                let c = model.at(&p, m).unwrap();
                let cl = c.lift_slope.value * alpha;
                let cd = c.zero_lift_drag.value + c.drag_due_to_lift.value * cl * cl;
                let cm = cl * (h - c.aerodynamic_centre.value);
                (cl, cd, cm)
            };
            let alpha = cl / c.lift_slope.value;
            let (dm, da) = (1e-6, 1e-7);
            let (clp, cdp, cmp) = coefs(alpha, mach + dm);
            let (clm, cdm, cmm) = coefs(alpha, mach - dm);
            let (_, cdap, _) = coefs(alpha + da, mach);
            let (_, cdam, _) = coefs(alpha - da, mach);
            let (cl0, cd0, _) = coefs(alpha, mach);
            let dcl_dm = (clp - clm) / (2.0 * dm);
            let dcd_dm = (cdp - cdm) / (2.0 * dm);
            let dcm_dm = (cmp - cmm) / (2.0 * dm);
            let dcd_da = (cdap - cdam) / (2.0 * da);
            let tol = 1e-6;
            let near = |a: f64, b: f64, what: &str| {
                assert!(
                    (a - b).abs() <= tol * (1.0 + b.abs()),
                    "{deg}° M {mach} {what}: {a} vs {b}"
                )
            };
            near(s.x_u, -mach * dcd_dm - 2.0 * cd0, "x_u (eq 9)");
            near(s.z_u, -mach * dcl_dm - 2.0 * cl0, "z_u (eq 10)");
            near(s.x_w, cl0 - dcd_da, "x_w (eq 11)");
            near(s.z_w, -cd0 - c.lift_slope.value, "z_w (eq 12)");
            near(s.m_u, mach * dcm_dm, "m_u (eq 13, trimmed)");
            near(
                s.m_w,
                (h - c.aerodynamic_centre.value) * (c.lift_slope.value + cd0),
                "m_w (eq 25)",
            );
        }
    }
}

#[test]
fn level_flight_keeps_cl_m_squared() {
    for m in [0.5, 1.0, 2.0] {
        let v = level_flight_lift(0.08, m);
        assert!((v.value * m * m - 0.08).abs() < 1e-15);
        assert!((v.d_mach + 2.0 * v.value / m).abs() < 1e-15);
    }
}
