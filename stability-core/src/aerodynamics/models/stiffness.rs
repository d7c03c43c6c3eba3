//! The stiffness derivatives x_u, z_u, m_u, x_w, z_w, m_w (§5–6) from the
//! aerodynamic coefficients at one Mach number, in the report's notation:
//!
//! - C_D = C_D0 + K C_L² (eq 21);
//! - ∂C_D/∂α = 2K C_L a (eq 26 — the OCR prints "C_D = C_D(o) + K C_L", but
//!   the relation it differentiates is eq 21, with C_L²);
//! - (∂C_L/∂M)_α = (C_L/a) da/dM (eq 27);
//! - (∂C_D/∂M)_α = dC_D0/dM + (2K C_L²/a) da/dM + C_L² dK/dM (eq 28);
//! - (∂C_m/∂M)_α = −C_L dH₀/dM + (h − H₀)(C_L/a) da/dM (eq 29);
//! - x_u = −M(∂C_D/∂M)_α − 2C_D (eq 9); z_u = −M(∂C_L/∂M)_α − 2C_L (10);
//!   x_w = C_L − ∂C_D/∂α (11); z_w = −C_D − a (12);
//!   m_u = M(∂C_m/∂M)_α for the trimmed aircraft (13);
//!   m_w = (h − H₀)(a + C_D) (14, 25).
//!
//! The Mach derivatives are the model's exact ones (`aero::Value::d_mach`).

use crate::aerodynamics::models::aero::Coefficients;
use serde::Serialize;

/// The stiffness derivatives of one flight condition.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Stiffness {
    pub x_u: f64,
    pub z_u: f64,
    pub m_u: f64,
    pub x_w: f64,
    pub z_w: f64,
    pub m_w: f64,
    /// C_D of the flight condition (eq 21).
    pub c_d: f64,
    /// ∂C_D/∂α (eq 26).
    pub dcd_dalpha: f64,
}

/// Eqs (9)–(14), (21), (25)–(29) at lift coefficient `c_l` and c.g. `h`.
pub fn stiffness(coef: &Coefficients, c_l: f64, h: f64) -> Stiffness {
    let m = coef.mach;
    let a = coef.lift_slope;
    let k = coef.drag_due_to_lift;
    let cd0 = coef.zero_lift_drag;
    let h0 = coef.aerodynamic_centre;
    let c_d = cd0.value + k.value * c_l * c_l;
    let dcd_dalpha = 2.0 * k.value * c_l * a.value;
    let dcl_dm = c_l / a.value * a.d_mach;
    let dcd_dm = cd0.d_mach + 2.0 * k.value * c_l * c_l / a.value * a.d_mach + c_l * c_l * k.d_mach;
    let dcm_dm = -c_l * h0.d_mach + (h - h0.value) * c_l / a.value * a.d_mach;
    Stiffness {
        x_u: -m * dcd_dm - 2.0 * c_d,
        z_u: -m * dcl_dm - 2.0 * c_l,
        m_u: m * dcm_dm,
        x_w: c_l - dcd_dalpha,
        z_w: -c_d - a.value,
        m_w: (h - h0.value) * (a.value + c_d),
        c_d,
        dcd_dalpha,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::aerodynamics::models::aero::{Origin, Origins, Value};

    #[test]
    fn by_hand_at_constant_coefficients() {
        // With no Mach dependence: x_u = −2C_D, z_u = −2C_L, m_u = 0.
        let c = Coefficients {
            mach: 0.6,
            lift_slope: Value::new(3.0, 0.0),
            zero_lift_drag: Value::new(0.01, 0.0),
            drag_due_to_lift: Value::new(0.3, 0.0),
            aerodynamic_centre: Value::new(0.4, 0.0),
            origin: Origins::all(Origin::Method),
        };
        let s = stiffness(&c, 0.2, 0.25);
        let cd = 0.01 + 0.3 * 0.04;
        assert!((s.c_d - cd).abs() < 1e-15);
        assert!((s.x_u + 2.0 * cd).abs() < 1e-15);
        assert!((s.z_u + 0.4).abs() < 1e-15);
        assert_eq!(s.m_u, 0.0);
        assert!((s.x_w - (0.2 - 2.0 * 0.3 * 0.2 * 3.0)).abs() < 1e-15);
        assert!((s.z_w + cd + 3.0).abs() < 1e-15);
        assert!((s.m_w - (0.25 - 0.4) * (3.0 + cd)).abs() < 1e-15);
    }
}
