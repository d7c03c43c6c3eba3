//! The modified Bessel functions of the second kind K₀(z) and K₁(z) at
//! complex z, by their ascending series (Abramowitz & Stegun 9.6.13 and
//! 9.6.11), principal branch (cut along the negative real axis): what
//! Theodorsen's function at a complex reduced frequency needs
//! ([`crate::aerodynamics::theodorsen`]).
//!
//! K₀(z) = −(ln(z/2) + γ) I₀(z) + Σₖ Hₖ (z²/4)ᵏ/(k!)²,
//! K₁(z) = 1/z + ln(z/2) I₁(z) − (z/4) Σₖ (ψ(k+1) + ψ(k+2)) (z²/4)ᵏ/(k!(k+1)!),
//! Hₖ = 1 + ½ + … + 1/k, ψ(k+1) = Hₖ − γ.
//!
//! Limits: the series subtract terms that grow like I₀(|z|) from a result
//! that falls like e^{−z}: at |z| = [`SERIES_UP_TO`] about three of the
//! sixteen digits are lost (measured against mpmath: within 1e-12
//! relative up to there; 1.3e-12 at |z| = 5). Beyond it, an error; the asymptotic expansion
//! or a continued fraction would serve there (not written: the reduced
//! frequencies of aircraft modes stay well below).

use num_complex::Complex64;

/// The largest |z| the series are used to.
pub const SERIES_UP_TO: f64 = 4.0;

/// Euler's constant γ.
const EULER_GAMMA: f64 = 0.577_215_664_901_532_9;

/// (K₀(z), K₁(z)), z ≠ 0, |z| ≤ [`SERIES_UP_TO`]; None outside.
pub fn k0_k1(z: Complex64) -> Option<(Complex64, Complex64)> {
    let r = z.norm();
    // NaN and ∞ fail too
    if !(r > 0.0 && r <= SERIES_UP_TO) {
        return None;
    }
    let q = z * z * 0.25;
    let log = (z * 0.5).ln();
    // running (z²/4)ᵏ/(k!)² and (z²/4)ᵏ/(k!(k+1)!), Hₖ
    let (mut t0, mut t1, mut h) = (Complex64::new(1.0, 0.0), Complex64::new(1.0, 0.0), 0.0);
    let (mut i0, mut i1) = (t0, t1);
    let (mut s0, mut s1) = (Complex64::default(), t1 * (2.0 * (-EULER_GAMMA) + 1.0));
    for k in 1..200 {
        let kf = k as f64;
        t0 = t0 * q / (kf * kf);
        t1 = t1 * q / (kf * (kf + 1.0));
        h += 1.0 / kf;
        i0 += t0;
        i1 += t1;
        s0 += t0 * h;
        // ψ(k+1) + ψ(k+2) = 2Hₖ + 1/(k+1) − 2γ
        s1 += t1 * (2.0 * h + 1.0 / (kf + 1.0) - 2.0 * EULER_GAMMA);
        if t0.norm() * (h + 1.0) <= 1e-17 * s0.norm().max(i0.norm())
            && t1.norm() * (2.0 * h + 2.0) <= 1e-17 * s1.norm().max(i1.norm())
        {
            break;
        }
    }
    let i1 = i1 * z * 0.5;
    let k0 = -(log + EULER_GAMMA) * i0 + s0;
    let k1 = z.inv() + log * i1 - z * 0.25 * s1;
    Some((k0, k1))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Against mpmath's besselk (25 digits, as it printed them), real and
    /// complex, either side of the imaginary axis.
    #[test]
    #[allow(clippy::excessive_precision)]
    fn the_series_are_mpmaths_values() {
        let cases = [
            (
                (1.0, 0.0),
                (0.421_024_438_240_708_3, 0.0),
                (0.601_907_230_197_234_6, 0.0),
            ),
            (
                (0.3, 1.7),
                (-0.478_633_754_387_122_07, -0.496_322_308_811_993_5),
                (-0.645_025_983_324_559_6, -0.407_690_207_041_461_77),
            ),
            (
                (-0.05, 0.8),
                (0.105_144_202_436_754_95, -1.406_860_567_101_436_2),
                (-0.668_842_159_702_471, -1.562_881_160_435_127_4),
            ),
            (
                (0.01, 0.2),
                (1.698_540_445_870_441_8, -1.502_996_912_884_297_8),
                (0.087_147_812_851_445_04, -5.200_979_579_254_271),
            ),
            (
                (2.0, 3.0),
                (-0.082_968_526_567_625_51, 0.027_949_603_635_183_42),
                (-0.086_499_976_481_281_73, 0.039_061_434_005_214_47),
            ),
        ];
        // at |z| = SERIES_UP_TO the stated 1e-12
        let edge = [
            (
                (4.0, 0.0),
                (0.011_159_676_085_853_024, 0.0),
                (0.012_483_498_887_268_431, 0.0),
            ),
            (
                (2.4, 3.2),
                (-0.048_932_677_986_622_09, 0.026_755_119_661_163_489),
                (-0.050_148_964_303_644_91, 0.033_353_474_730_260_81),
            ),
            (
                (-0.8, 3.9),
                (0.060_001_975_089_001_94, 1.400_087_918_088_985_6),
                (0.232_944_754_351_065_8, 1.368_067_231_515_254_9),
            ),
        ];
        let within = |tol: f64| {
            move |((x, y), (a, b), (c, d)): ((f64, f64), (f64, f64), (f64, f64))| {
                let (k0, k1) = k0_k1(Complex64::new(x, y)).unwrap();
                let (w0, w1) = (Complex64::new(a, b), Complex64::new(c, d));
                assert!(
                    (k0 - w0).norm() <= tol * w0.norm(),
                    "K0({x}+{y}i) {k0} {w0}"
                );
                assert!(
                    (k1 - w1).norm() <= tol * w1.norm(),
                    "K1({x}+{y}i) {k1} {w1}"
                );
            }
        };
        cases.into_iter().for_each(within(1e-13));
        edge.into_iter().for_each(within(1e-12));
        assert!(k0_k1(Complex64::new(4.5, 0.0)).is_none());
        assert!(k0_k1(Complex64::default()).is_none());
    }
}
