//! The wing's downwash at a tailplane, supersonic.
//!
//! The stated method: the downwash of the wing's trailing vortex sheet in
//! the Trefftz plane (far downstream), the sheet flat and in the wing's
//! plane, the wing's span loading elliptic. In linear theory the far wake
//! is the two-dimensional cross flow of the sheet at any Mach number, so
//! Mach number enters only through the wing's lift slope. An elliptically
//! loaded sheet of semi-span s moves down as a flat plate of width 2s
//! (L. Prandtl; H. Glauert, *The Elements of Aerofoil and Airscrew
//! Theory*, 1926, ch. XI) with the downwash ε₀ = 2C_L/(πA); the plate's
//! cross-flow potential F(σ) = iw₀(σ − √(σ² − s²)) gives on the centre
//! line at height z above the sheet
//!
//! ε(z) = (2C_L/(πA))·(1 − |z|/√(z² + s²)),  so  dε/dα = (2a/(πA))(1 − |z|/√(z² + s²)).
//!
//! The span loading of a slender delta is elliptic (R.T. Jones, NACA Rep.
//! 835, 1946); a flat delta with subsonic leading edges carries the
//! conical-flow loading, whose span loading is close to it.
//!
//! Limits: the Trefftz-plane value holds once the tail lies behind the
//! Mach cones from the wing's tips (about β·s behind the trailing edge);
//! nearer, linear theory's downwash is smaller on the centre line; the
//! sheet's roll-up and the wing's leading-edge vortices are not modelled;
//! the tail is taken as sampling the centre-line value over its span
//! (a tail of span small against the wing's).

/// dε/dα at a tailplane `z` above the plane of a wing of lift slope `a`
/// (per radian), aspect ratio `aspect_ratio` and semi-span `semi_span` (z
/// and s in one unit): (2a/(πA))(1 − |z|/√(z² + s²)).
pub fn gradient(a: f64, aspect_ratio: f64, semi_span: f64, z: f64) -> f64 {
    let far = 2.0 * a / (std::f64::consts::PI * aspect_ratio);
    far * (1.0 - z.abs() / z.hypot(semi_span))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// The centre-line downwash w/V at height z of the sheet shed by the
    /// elliptic circulation Γ(y) = Γ₀√(1 − y²/s²), by Biot–Savart summed
    /// over its two-dimensional (Trefftz-plane) filaments: each of strength
    /// −Γ′(y)dy = Γ₀ sin θ dθ (y = s sin θ) at (y, 0) induces at (0, z) the
    /// vertical velocity −Γ₀ sin θ·y/(2π(y² + z²)). Midpoint rule in θ.
    fn biot_savart(gamma0: f64, s: f64, z: f64) -> f64 {
        let n = 200_000;
        let dt = PI / n as f64;
        (0..n)
            .map(|i| {
                let t = -PI / 2.0 + (i as f64 + 0.5) * dt;
                let y = s * t.sin();
                -gamma0 * t.sin() * y / (2.0 * PI * (y * y + z * z)) * dt
            })
            .sum()
    }

    #[test]
    fn the_closed_form_is_the_elliptic_sheets_biot_savart_sum() {
        // S = 1, A = 4 (s = 1), C_L = 1: Γ₀/V = S·C_L/(πs); the downwash
        // is ε = −w/V = C_L·dε/dα / a at any a.
        let (s, area, c_l) = (1.0, 1.0, 1.0);
        let aspect_ratio = (2.0 * s) * (2.0 * s) / area;
        let gamma0 = area * c_l / (PI * s);
        for z in [0.0, 0.1, 0.3, 0.7, 1.5] {
            let numeric = -biot_savart(gamma0, s, z);
            let closed = c_l * gradient(1.0, aspect_ratio, s, z);
            assert!(
                (numeric - closed).abs() < 1e-6 * closed.max(1e-3),
                "z = {z}: Biot–Savart {numeric}, closed form {closed}"
            );
        }
        // in the plane: Prandtl's 2C_L/(πA)
        assert!((gradient(1.0, aspect_ratio, s, 0.0) - 2.0 / (PI * 4.0)).abs() < 1e-15);
    }
}
