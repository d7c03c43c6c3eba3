//! Theodorsen's function at a complex reduced frequency: the lift deficiency
//! of the two-dimensional incompressible aerofoil in any exponential motion
//! e^{st}, not only a steady oscillation.
//!
//! T. Theodorsen, "General theory of aerodynamic instability and the
//! mechanism of flutter", NACA Rep. 496, 1935, gave C(k) =
//! H₁⁽²⁾(k)/(H₁⁽²⁾(k) + iH₀⁽²⁾(k)) for harmonic motion at reduced frequency
//! k = ωb/V; its analytic continuation to p̄ = sb/V (R.T. Jones; W.W.
//! Edwards, H. Ashley & J.V. Breakwell, "Unsteady aerodynamic modeling for
//! arbitrary motions", AIAA J. 17(4), 1979) is
//!
//! C(p̄) = K₁(p̄)/(K₀(p̄) + K₁(p̄)),
//!
//! equal to C(k) at p̄ = ik (K₀(ik) = −(iπ/2)H₀⁽²⁾(k), K₁(ik) =
//! −(π/2)H₁⁽²⁾(k)). The p-method solves the equations of motion with the
//! air forces at the root's own p̄; this is the closed-form case it is
//! checked on (`tests/it/typical_section.rs`).
//!
//! Limits: |p̄| ≤ [`crate::numerics::bessel::SERIES_UP_TO`] (the series of
//! K₀ and K₁), principal branch (p̄ not on the negative real axis).

use crate::numerics::bessel::k0_k1;
use num_complex::Complex64;

/// C(p̄), or None where K₀ and K₁ are not evaluated (p̄ = 0, |p̄| beyond
/// the series' range).
pub fn theodorsen(p: Complex64) -> Option<Complex64> {
    let (k0, k1) = k0_k1(p)?;
    Some(k1 / (k0 + k1))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// At p̄ = ik, Theodorsen's C(k): at k = 0.5, F = 0.5979, G = −0.1507
    /// (Bisplinghoff, Ashley & Halfman, Table 5-1, 4 digits); and C → 1 as
    /// the motion slows (k → 0), C → ½ as it quickens (mpmath at p̄ = 1:
    /// K₁/(K₀ + K₁) = 0.588413917340510835).
    #[test]
    fn on_the_imaginary_axis_it_is_theodorsens_function() {
        let c = theodorsen(Complex64::new(0.0, 0.5)).unwrap();
        assert!(
            (c.re - 0.5979).abs() < 1e-4 && (c.im + 0.1507).abs() < 1e-4,
            "{c}"
        );
        let slow = theodorsen(Complex64::new(0.0, 1e-4)).unwrap();
        assert!((slow - 1.0).norm() < 2e-3, "{slow}");
        let real = theodorsen(Complex64::new(1.0, 0.0)).unwrap();
        assert!((real.re - 0.588_413_917_340_510_8).abs() < 1e-14 && real.im.abs() < 1e-15);
    }
}
