//! Interpolation with exact slopes: a value with its derivative
//! ([`Value`]), the cubic Hermite interpolant ([`hermite`]) and the
//! Fritsch–Carlson slopes that keep it monotone ([`monotone_slopes`]).

use serde::Serialize;

/// A coefficient's value and its Mach derivative at one Mach number.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Value {
    pub value: f64,
    /// d(value)/dM, exact (analytic, or the interpolant's own derivative).
    pub d_mach: f64,
}

impl Value {
    pub fn new(value: f64, d_mach: f64) -> Value {
        Value { value, d_mach }
    }
}

/// The end slopes d₀, d₁ of one interval whose secant is δ, made such that
/// the cubic Hermite interpolant on it is monotone where the data are (F.N.
/// Fritsch and R.E. Carlson, SIAM J. Numer. Anal. 17(2), 1980, §4): with
/// α = d₀/δ, β = d₁/δ, a slope against the secant's sign becomes 0, and
/// (α, β) is pulled radially into the circle α² + β² ≤ 9; δ = 0 gives flat
/// ends.
pub fn monotone_slopes(delta: f64, d0: f64, d1: f64) -> (f64, f64) {
    if delta == 0.0 {
        return (0.0, 0.0);
    }
    let (mut a, mut b) = ((d0 / delta).max(0.0), (d1 / delta).max(0.0));
    let s = a * a + b * b;
    if s > 9.0 {
        let t = 3.0 / s.sqrt();
        (a, b) = (t * a, t * b);
    }
    (a * delta, b * delta)
}

/// The cubic Hermite interpolant through (x₀, y₀, y₀′) and (x₁, y₁, y₁′), and
/// its derivative, at x.
pub fn hermite((x0, y0, d0): (f64, f64, f64), (x1, y1, d1): (f64, f64, f64), x: f64) -> Value {
    let h = x1 - x0;
    let t = (x - x0) / h;
    let (t2, t3) = (t * t, t * t * t);
    let h00 = 2.0 * t3 - 3.0 * t2 + 1.0;
    let h10 = t3 - 2.0 * t2 + t;
    let h01 = -2.0 * t3 + 3.0 * t2;
    let h11 = t3 - t2;
    let value = h00 * y0 + h10 * h * d0 + h01 * y1 + h11 * h * d1;
    let dh00 = (6.0 * t2 - 6.0 * t) / h;
    let dh10 = 3.0 * t2 - 4.0 * t + 1.0;
    let dh01 = (-6.0 * t2 + 6.0 * t) / h;
    let dh11 = 3.0 * t2 - 2.0 * t;
    Value::new(value, dh00 * y0 + dh10 * d0 + dh01 * y1 + dh11 * d1)
}
