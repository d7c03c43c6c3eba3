//! The integral across the forward Mach cone that both of the Mach box's
//! quadratures need at each station ξ: with η = y − r sin θ,
//! ∫cos(z cos θ) dθ over the part [lo, hi] of [−π/2, π/2] the wing's
//! section (or a box's strip) takes of the cone's chord, z = ν(x − ξ)
//! (`direct.rs`) or ν̂X (`influence.rs`). Over the whole range it is
//! πJ₀(z) (Abramowitz & Stegun 9.1.18); over a part, no closed form, but
//! a power series whose terms need no cosine.

/// Up to this z the inner integral ∫cos(z cos θ)dθ is summed as a power
/// series ([`by_series`]), beyond by Gauss–Legendre rules (`direct.rs`,
/// `influence.rs`): at z = 4 the largest term is z⁴/4! ≈ 11 times the integral, so the sum
/// keeps all but one of the sixteen digits (the rule's error is 3·10⁻¹¹).
pub const SERIES_UP_TO: f64 = 4.0;

/// ∫_{lo}^{hi} cos(z cos θ) dθ = Σₖ (−1)ᵏ z²ᵏ/(2k)! I₂ₖ, −π/2 ≤ lo ≤ hi ≤
/// π/2, with Iₙ = ∫cosⁿθ dθ over [lo, hi] by the reduction formula
/// Iₙ = [cosⁿ⁻¹θ sin θ]/n + (n − 1)/n Iₙ₋₂ (Gradshteyn & Ryzhik 2.513.1;
/// forward it is stable: the factor (n − 1)/n < 1), cos θ = √(1 − sin²θ)
/// at either end (cos θ ≥ 0 there). The terms fall below 10⁻¹⁷ of I₀
/// within 19 of them at z ≤ [`SERIES_UP_TO`]. Each (angle, sine) pair is
/// one end.
pub fn by_series(z: f64, (lo, sin_lo): (f64, f64), (hi, sin_hi): (f64, f64)) -> f64 {
    let (cos_lo, cos_hi) = (
        (1.0 - sin_lo * sin_lo).sqrt(),
        (1.0 - sin_hi * sin_hi).sqrt(),
    );
    let (c2_lo, c2_hi) = (cos_lo * cos_lo, cos_hi * cos_hi);
    let z2 = z * z;
    // cos^{n−1}θ sin θ at each end, n = 2k, stepping by cos²θ
    let (mut end_lo, mut end_hi) = (cos_lo * sin_lo, cos_hi * sin_hi);
    let mut integral = hi - lo; // I₀
    let mut sum = integral;
    let mut coefficient = 1.0; // (−1)ᵏ z²ᵏ/(2k)!
    for k in 1..=SERIES_TERMS {
        let n = (2 * k) as f64;
        integral = (end_hi - end_lo) / n + (n - 1.0) / n * integral;
        coefficient *= -z2 / (n * (n - 1.0));
        let term = coefficient * integral;
        sum += term;
        if term.abs() <= 1e-17 * sum.abs() {
            break;
        }
        end_lo *= c2_lo;
        end_hi *= c2_hi;
    }
    sum
}

/// The most terms [`by_series`] sums (z = [`SERIES_UP_TO`] needs 19).
const SERIES_TERMS: usize = 30;

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::{FRAC_PI_2, PI};

    /// Jₙ(z) by its power series Σ (−1)ᵐ(z/2)²ᵐ⁺ⁿ/(m!(m + n)!) (A&S 9.1.10).
    fn bessel_j(n: usize, z: f64) -> f64 {
        let mut term = (0.5 * z).powi(n as i32) / (1..=n).map(|k| k as f64).product::<f64>();
        let mut sum = term;
        for m in 1..60 {
            term *= -(0.25 * z * z) / (m as f64 * (m + n) as f64);
            sum += term;
        }
        sum
    }

    /// The same integral by another expansion, Jacobi–Anger's
    /// cos(z cos θ) = J₀(z) + 2Σₖ(−1)ᵏJ₂ₖ(z)cos 2kθ (A&S 9.1.44), integrated
    /// term by term.
    fn by_jacobi_anger(z: f64, lo: f64, hi: f64) -> f64 {
        let mut sum = bessel_j(0, z) * (hi - lo);
        for k in 1..30 {
            let n = 2.0 * k as f64;
            let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
            sum += 2.0 * sign * bessel_j(2 * k, z) * ((n * hi).sin() - (n * lo).sin()) / n;
        }
        sum
    }

    /// The series against Jacobi–Anger's expansion over the range it
    /// serves, ends anywhere in [−π/2, π/2], within a few roundings of
    /// hi − lo; over the whole range πJ₀(z): J₀(1) =
    /// 0.765197686557966551449717526103 (A&S table 9.1).
    #[test]
    fn the_series_is_the_integral() {
        for z in [0.0, 1e-4, 0.3, 1.0, 2.5, SERIES_UP_TO] {
            for (a, b) in [
                (-1.0, 1.0),
                (-0.3, 0.9),
                (0.2, 0.25),
                (-1.0, -0.99),
                (0.5, 1.0),
            ] {
                let (lo, hi) = (f64::asin(a), f64::asin(b));
                let s = by_series(z, (lo, a), (hi, b));
                let e = by_jacobi_anger(z, lo, hi);
                assert!(
                    (s - e).abs() <= 1e-14 * (hi - lo),
                    "z {z} [{a}, {b}]: {s} {e}"
                );
            }
        }
        let j0 = by_series(1.0, (-FRAC_PI_2, -1.0), (FRAC_PI_2, 1.0)) / PI;
        assert!((j0 - 0.765_197_686_557_966_6).abs() < 1e-15, "{j0}");
    }
}
