//! Eq (36), the theory of Mangler and of Ribner & Malvestuto (NACA Rep.
//! 908, 1948) for subsonic leading edges, β cot Λ < 1, and the functions
//! of Fig 18 it needs. It lives in `supersonic`, which continues it past
//! the sonic edge, so that `damping` (which uses `supersonic` for
//! `--damping supersonic`) is not imported back; `damping` re-exports it.
//! `docs/damping-theories.md` gives (36) as printed and as recovered.

use crate::derivatives::DampingDerivatives;
use serde::Serialize;
use std::f64::consts::PI;

/// The functions of Fig 18 (supersonic theory): k² = 1 − β² cot²Λ,
/// E = E(k), K = K(k), G = k²/((2k² − 1)E + (1 − k²)K), H = E·G.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Fig18 {
    pub k2: f64,
    pub e: f64,
    pub k: f64,
    pub g: f64,
    pub h: f64,
}

impl Fig18 {
    /// At β cot Λ (< 1); the `ellip` crate takes the parameter m = k².
    pub fn at(beta_cot: f64) -> Fig18 {
        let k2 = 1.0 - beta_cot * beta_cot;
        let e = ellip::ellipe(k2).unwrap_or(f64::NAN);
        let k = ellip::ellipk(k2).unwrap_or(f64::INFINITY);
        // (1 − k²)K → 0 as k → 1
        let tail = if k2 >= 1.0 { 0.0 } else { (1.0 - k2) * k };
        // As k → 0 (the leading edge turning sonic) numerator and
        // denominator vanish together: with E, K's series to k⁶ the
        // denominator is (3π/4)k²(1 − 3k²/8 − 5k⁴/64 + O(k⁶)), so
        // G → 4/(3π) and H → 2/3. Below k² = 1e-4 the series (its error
        // 3.4e-5·k⁶, against mpmath) is better than the difference (which
        // loses the digits of k²): continuous to 1e-13 at the switch.
        let g = if k2 < 1e-4 {
            4.0 / (3.0 * PI) / (1.0 - k2 * (3.0 / 8.0 + 5.0 / 64.0 * k2))
        } else {
            k2 / ((2.0 * k2 - 1.0) * e + tail)
        };
        Fig18 {
            k2,
            e,
            k,
            g,
            h: e * g,
        }
    }
}

/// Eq (36), recovered (Mangler; Ribner & Malvestuto, NACA Rep. 908), in
/// the report's notation, for given E and H (Fig 18):
/// z_q = −(πA/4E)(3H − 2h − 1),
/// z_ẇ = −(πA/4E)[1 − 3M²(1 − H)/(M² − 1)],
/// m_q = −(πA/4E)(2h² − 3hH + (15/8)H − ½),
/// m_ẇ = z_ẇ(5/8 − h)
/// (with z_w = −πA/(2E), m_w = z_w(½ − h)). With H = E = 1 these are (37).
pub fn eq36(a: f64, h: f64, mach: f64, e: f64, hh: f64) -> DampingDerivatives {
    let c = PI * a / (4.0 * e);
    let z_wdot = -c * (1.0 - 3.0 * mach * mach * (1.0 - hh) / (mach * mach - 1.0));
    DampingDerivatives {
        z_q: -c * (3.0 * hh - 2.0 * h - 1.0),
        z_wdot,
        m_q: -c * (2.0 * h * h - 3.0 * h * hh + 15.0 / 8.0 * hh - 0.5),
        m_wdot: z_wdot * (5.0 / 8.0 - h),
    }
}
