//! The doublet lattice from M = 0.9 to the sonic point M = 1 at a frequency
//! parameter ω̄ > 0: what the faired damping model can use to narrow its
//! join around M = 1.
//!
//! # Below M = 0.99: the lattice, refined
//! [`near_sonic`] solves the lattice of [`LatticeSpec::for_mach`], whose
//! chordwise boxes shrink with β = √(1 − M²) (the Prandtl–Glauert stretched
//! box length Δx/β held at its M = 0.9 value), extrapolated as the default
//! lattice is. Its convergence at M = 0.95 and 0.98 is tabled in
//! `docs/lattice-near-sonic.md`.
//!
//! # At M = 1: the limit from below, by extrapolation in β²
//! Linearised unsteady transonic theory is finite at M = 1 when the motion
//! oscillates (M.T. Landahl, *Unsteady transonic flow*, Pergamon, 1961):
//! the frequency, not β, then cuts off the far field. In the
//! subsonic kernel (Landahl, AIAA J. 5(5), 1967; [`super::kernel`]) every
//! term has a finite limit as β → 0 at fixed κ = ω/V downstream of the
//! sending element — u₁ → (r² − x₀²)/2rx₀ and the phase κM(R − Mx₀)/β² →
//! κ(x₀/2 + r²/2x₀) — and vanishes upstream (u₁ → ∞): the sonic kernel, which
//! has no upstream influence, and whose steady part is the two-dimensional
//! cross-flow kernel of slender-wing theory (hence (37)–(38) at M = 1 for
//! any aspect ratio, within linear theory). Away from the Mach plane x₀ = 0
//! the subsonic kernel differs from it by terms in β² (relative order
//! β²r²/x₀² and β²κx₀), so at fixed ω̄ > 0 the loads approach their sonic
//! values as X(β) = X(0) + aβ² + bβ⁴ + … once β² is past the crossover
//! where the frequency takes over from β as the far field's cut-off (the
//! matching of (36) with Mangler's (40) puts its middle at β² = ω̄/2.4,
//! [`crate::aerodynamics::supersonic::transonic::MATCHING_RATIO`]; measured, it ends near
//! β² ≈ ω̄/10, later still for slender wings — `docs/lattice-near-sonic.md`).
//!
//! Evaluating the lattice *at* M = 1 with the sonic kernel was not done:
//! near the Mach plane its phase κr²/2x₀ oscillates without bound, which the
//! quartic line rule across each box does not resolve. Instead, above
//! [`SONIC_ANCHORS`]`[0]` the solution is the quadratic in β² through the
//! lattice's solutions at the three [`SONIC_ANCHORS`] (M = 0.99, 0.995,
//! 0.998), interpolated for M < 0.998 and extrapolated beyond, to M = 1.
//!
//! # Accuracy
//! Measured (`tests/it/lifting_surface_near_sonic.rs`,
//! `docs/lattice-near-sonic.md`): on the note's 45° and 60° deltas at
//! ω̄ = 0.3 and 0.6 the quadratic at M = 0.999 is within 0.9 % of C_Lα (each
//! number of the [`Solution`]) of a direct solve there, which it does not
//! use, and M = 0.995–1 continue the trend of the direct solves at
//! 0.97–0.99 without a jump; on a slender 80° delta at ω̄ = 0.6 and 1 the
//! sonic C_Lα, z_ẇ, z_θ̇, m_θ̇ and z_q are within 3 % of Mangler's
//! low-aspect-ratio theory (38)–(40). Stated accuracy at M = 1: 1 % of C_Lα
//! on each derivative for the note's wings at 0.3 ≤ ω̄ ≤ 0.6, on top of the
//! refined lattice's own, 3·10⁻² absolute (chordwise, [`LatticeSpec::for_mach`];
//! spanwise: the anchors on 32 strips move the sonic values by at most
//! 2.7·10⁻²). Not reliable: ω̄ < [`SONIC_OMEGA_BAR_MIN`] (the anchors are
//! still in the ln(1/β) regime of the α̇ derivatives), slender wings at
//! larger ω̄ too (80° at ω̄ = 0.3), and ω̄ ≳ 1 on the 45° delta (the
//! upstream wave, of length 2πβ²V/(ωM(1 + M)), shorter than two boxes at
//! the anchors). At ω̄ = 0 the α̇ derivatives are infinite at M = 1 (an
//! error here). Linear theory itself ignores the shock waves and
//! nonlinearity of real transonic flow.

use super::derivatives::Extrapolate;
use super::{
    Lattice, LatticeSpec, LiftingSurfaceError, OMEGA_BAR_QUASI_STEADY, Solution, Trapezoid,
};

/// The lowest Mach number [`near_sonic`] takes.
pub const NEAR_SONIC_FROM: f64 = 0.9;

/// The Mach numbers whose lattice solutions the sonic extrapolation
/// passes through (quadratic in β²).
pub const SONIC_ANCHORS: [f64; 3] = [0.99, 0.995, 0.998];

/// The smallest ω̄ at which the sonic values (M > 0.99) were verified on
/// the note's wings: at smaller ω̄ the α̇ derivatives at the anchors still
/// follow the quasi-steady ln(1/β), which they leave only once β² < ω̄/10
/// (measured, `docs/lattice-near-sonic.md`), and the extrapolation to M = 1
/// is not their sonic limit. Not enforced: a caller below it should fall
/// back to a fairing (Mangler's theory at M = 1, say).
pub const SONIC_OMEGA_BAR_MIN: f64 = 0.3;

/// The wing's [`Solution`] at 0.9 ≤ M ≤ 1 and ω̄ = ωc̄/V: the refined
/// lattice ([`LatticeSpec::for_mach`]) up to M = 0.99, the quadratic in β²
/// through its solutions at [`SONIC_ANCHORS`] beyond (see the module's
/// documentation for the method and its accuracy). ω̄ = 0 is accepted
/// below M = 1 (a direct quasi-steady solve, whose α̇ derivatives grow like
/// ln(1/β)); at M = 1 it needs ω̄ > 0.
pub fn near_sonic(
    wing: &Trapezoid,
    mach: f64,
    omega_bar: f64,
) -> Result<Solution, LiftingSurfaceError> {
    near_sonic_by(mach, omega_bar, |m| {
        Lattice::new(wing, LatticeSpec::for_mach(wing, m))?.solve(m, omega_bar)
    })
}

/// [`near_sonic`] with the refined lattice's solution at each Mach number
/// it needs (M itself up to 0.99, else the anchors) from `solve` — a direct
/// solve, or the cache's ([`super::cache::near_sonic`]).
pub(super) fn near_sonic_by(
    mach: f64,
    omega_bar: f64,
    solve: impl Fn(f64) -> Result<Solution, LiftingSurfaceError> + Sync,
) -> Result<Solution, LiftingSurfaceError> {
    if !(mach.is_finite() && (NEAR_SONIC_FROM..=1.0).contains(&mach)) {
        return Err(LiftingSurfaceError::NearSonicMach(mach));
    }
    if !(omega_bar.is_finite() && omega_bar >= 0.0) {
        return Err(LiftingSurfaceError::Frequency(omega_bar));
    }
    if mach <= SONIC_ANCHORS[0] || (omega_bar < OMEGA_BAR_QUASI_STEADY && mach < 1.0) {
        return solve(mach);
    }
    if omega_bar < OMEGA_BAR_QUASI_STEADY {
        return Err(LiftingSurfaceError::SonicQuasiSteady);
    }
    let [m0, m1, m2] = SONIC_ANCHORS;
    // the anchors in parallel
    let (a, (b, c)) = rayon::join(|| solve(m0), || rayon::join(|| solve(m1), || solve(m2)));
    let (a, b, c) = (a?, b?, c?);
    let w = quadratic_weights(SONIC_ANCHORS.map(beta2), beta2(mach));
    let s = a.combine(&b, w[0], w[1]).combine(&c, 1.0, w[2]);
    Solution::checked(Solution {
        mach,
        omega_bar,
        ..s
    })
}

/// The sonic point: [`near_sonic`] at M = 1 (ω̄ > 0).
pub fn sonic_limit(wing: &Trapezoid, omega_bar: f64) -> Result<Solution, LiftingSurfaceError> {
    near_sonic(wing, 1.0, omega_bar)
}

/// β² = 1 − M².
fn beta2(mach: f64) -> f64 {
    1.0 - mach * mach
}

/// Lagrange's weights of the quadratic through x₀, x₁, x₂ at x.
fn quadratic_weights(x: [f64; 3], at: f64) -> [f64; 3] {
    std::array::from_fn(|m| {
        (0..3)
            .filter(|&k| k != m)
            .map(|k| (at - x[k]) / (x[m] - x[k]))
            .product()
    })
}

#[cfg(test)]
mod tests {
    use super::super::kernel::{self, I1Approximation, KernelFlow, i1_by_quadrature};
    use super::*;
    use num_complex::Complex64;

    #[test]
    fn the_weights_reproduce_quadratics() {
        let x = SONIC_ANCHORS.map(beta2);
        for at in [0.0, 0.004, 0.012, 0.03] {
            for p in 0..3 {
                let s: f64 = (0..3)
                    .map(|m| quadratic_weights(x, at)[m] * x[m].powi(p))
                    .sum();
                assert!((s - at.powi(p)).abs() < 1e-12, "{at} {p}: {s}");
            }
        }
    }

    /// The sonic numerator in closed form (x₀ > 0): with
    /// u_s = (r² − x₀²)/2rx₀, √(1 + u_s²) = (r² + x₀²)/2rx₀, so
    /// N_s = −[e^{−iκx₀} I₁(u_s, κr) + e^{−iκ(x₀/2 + r²/2x₀)}·2r²/(r² + x₀²)];
    /// zero upstream. I₁ by quadrature.
    fn sonic_numerator(x0: f64, r: f64, kappa: f64) -> Complex64 {
        if x0 <= 0.0 {
            return Complex64::new(0.0, 0.0);
        }
        let u = (r * r - x0 * x0) / (2.0 * r * x0);
        let lag = Complex64::from_polar(1.0, -kappa * x0);
        let both = Complex64::from_polar(1.0, -kappa * (0.5 * x0 + r * r / (2.0 * x0)));
        -(lag * i1_by_quadrature(u, kappa * r) + both * (2.0 * r * r / (r * r + x0 * x0)))
    }

    #[test]
    fn the_subsonic_kernel_tends_to_the_sonic_one() {
        // the module's claim: finite downstream, zero upstream, and the
        // difference O(β²) away from the Mach plane
        for (x0, r, kappa) in [
            (0.5, 0.3, 0.9),
            (1.2, 0.1, 0.45),
            (0.2, 0.6, 1.5),
            (-0.4, 0.3, 0.9),
        ] {
            let at = |beta2: f64| {
                let flow =
                    KernelFlow::new((1.0 - beta2).sqrt(), kappa, I1Approximation::Quadrature);
                kernel::numerator(x0, r, &flow)
            };
            let exact = sonic_numerator(x0, r, kappa);
            let (e1, e2) = ((at(1e-3) - exact).norm(), (at(1e-4) - exact).norm());
            assert!(
                e2 < 2e-3,
                "{x0} {r} {kappa}: {} against {exact}: {e2}",
                at(1e-4)
            );
            // ten times closer for β² ten times smaller
            assert!(e2 < 0.2 * e1, "{x0} {r} {kappa}: {e1} {e2}");
            // and the steady part is the cross-flow kernel, −2 behind
            let n0 = kernel::steady_numerator(x0, r, 1e-8);
            let cross = if x0 > 0.0 { -2.0 } else { 0.0 };
            assert!((n0 - cross).abs() < 1e-6, "{n0}");
        }
    }

    #[test]
    fn outside_the_range_is_an_error() {
        let w = Trapezoid::new(1.0, 0.0, 1.0, 45f64.to_radians()).unwrap();
        for m in [0.5, 1.01, f64::NAN] {
            assert!(matches!(
                near_sonic(&w, m, 0.3),
                Err(LiftingSurfaceError::NearSonicMach(_))
            ));
        }
        assert!(matches!(
            near_sonic(&w, 1.0, 0.0),
            Err(LiftingSurfaceError::SonicQuasiSteady)
        ));
        assert!(matches!(
            near_sonic(&w, 0.95, -1.0),
            Err(LiftingSurfaceError::Frequency(_))
        ));
    }
}
