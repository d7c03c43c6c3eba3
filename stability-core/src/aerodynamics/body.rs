//! The forebody of eq (43): Munk's slender-body theory (M.M. Munk, "The
//! aerodynamic forces on airship hulls", NACA Rep. 184, 1924), as §10 of
//! the note applies it.
//!
//! A slender body whose cross-section grows to its base area B_v = πd²/4
//! carries the normal force 2B_v·α_b (on ½ρV²), α_b the local incidence,
//! concentrated at its base, here at the wing's apex (x = 0); its length
//! does not enter. With x̄ the wing M.A.C.'s leading edge and e = x̄/c̄,
//! L = 2B_v/S = πd²/(2S):
//!
//! ℓ_α = L, μ_α = L·e, ℓ_q = −L·e, μ_q = −L·e², no α̇ terms;
//!
//! so that about the c.g. h ([`Solution::derivatives`]) m_q = −L(e + h)² =
//! −½πd²(l − x)²/(Sc̄²) — eq (43), l − x being minus the c.g.'s distance
//! aft of the apex — and m_ẇ = 0. The same theory's lift, a force ahead
//! of the wing, moves the aerodynamic centre forward (it is kept: the
//! note's eq (43) states only the damping). No interference between body
//! and wing is modelled. Slender-body theory does not depend on Mach
//! number.

use crate::aerodynamics::lifting_surface::Solution;
use crate::geometry::Trapezoid;
use crate::geometry::configuration::Body;
use std::f64::consts::PI;

impl Body {
    /// The body's response on the wing's S and c̄, moments about the wing
    /// M.A.C.'s leading edge, at Mach `mach` and ω̄ `omega_bar` (recorded;
    /// the values depend on neither).
    pub fn solution(&self, wing: &Trapezoid, mach: f64, omega_bar: f64) -> Solution {
        let l = PI * self.diameter * self.diameter / (2.0 * wing.area());
        let e = wing.x_mac() / wing.mac();
        Solution {
            mach,
            omega_bar,
            lift_alpha: l,
            moment_alpha: l * e,
            lift_alphadot: 0.0,
            moment_alphadot: 0.0,
            lift_q: -l * e,
            moment_q: -l * e * e,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::aerodynamics::damping::fuselage_increment;
    use crate::geometry::{Planform, Size};

    #[test]
    fn the_body_adds_eq_43_to_m_thetadot_at_every_cg() {
        // the 45° delta of 30 ft M.A.C. (c₀ = 45 ft, S = 2025 ft²), a 10 ft
        // body 20 ft ahead of the apex
        let p = Planform::new(45f64.to_radians(), 0.0, Size::RootChord(45.0)).unwrap();
        let wing = Trapezoid::from(&p);
        let body = Body {
            length_ahead: 20.0,
            diameter: 10.0,
        };
        let s = body.solution(&wing, 2.0, 0.0);
        for h in [0.0, 0.25, 0.5] {
            let d = s.derivatives(h, 0.0).unwrap();
            // x: c.g. to nose = l + (x̄ + h c̄)
            let x = 20.0 + wing.x_mac() + h * wing.mac();
            let eq43 = fuselage_increment(10.0, 20.0, x, wing.area(), wing.mac());
            assert!((d.m_thetadot - eq43).abs() < 1e-14, "h = {h}");
            assert_eq!(d.m_wdot, 0.0);
        }
        // the note's own case, c.g. 15 ft aft of the apex, S = 1000 ft²,
        // c̄ = 30 ft: −(π/2)·100·225/(1000·900) = −0.039270
        let note = fuselage_increment(10.0, 20.0, 35.0, 1000.0, 30.0);
        assert!((note + 0.039_27).abs() < 1e-5);
    }
}
