//! The complete elliptic integral of the second kind with its slope, for
//! linear supersonic theory's lift slope (πA/(2E), eq 36).

use std::f64::consts::PI;

/// E(m) and dE/dm = (E − K)/(2m) (the `ellip` crate takes the parameter
/// m = k²); at m = 0 the limit −π/8.
pub fn ellip_e_and_slope(m: f64) -> (f64, f64) {
    let e = ellip::ellipe(m).unwrap_or(f64::NAN);
    if m.abs() < 1e-12 {
        return (e, -PI / 8.0);
    }
    let k = ellip::ellipk(m).unwrap_or(f64::NAN);
    (e, (e - k) / (2.0 * m))
}
