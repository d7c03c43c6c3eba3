//! Steps 2–4 of the module documentation: the factorization of a scaled
//! monic quartic into two real quadratics from a root of Ferrari's
//! resolvent cubic, repaired and refined by Newton's method on the Vieta
//! equations (after Orellana & De Michele's Algorithm 1010).

use super::horner::{abs_sum, derivative, horner, l1};
use super::quadratic;
use num_complex::Complex64;

/// The roots of the factorization from each real root of the resolvent,
/// raw and repaired, each refined by Newton's method; the set with the
/// smallest residual wins. The first candidate (the largest resolvent root,
/// raw then repaired) usually settles it.
#[inline]
pub(super) fn factored_roots(
    a: f64,
    b: f64,
    c: f64,
    d: f64,
    exact: &[f64; 5],
) -> ([Complex64; 4], bool) {
    let m = Monic::new(a, b, c, d);
    // Ferrari's resolvent: y³ − b y² + (ac − 4d) y + (4bd − a²d − c²) = 0.
    let (e2, e1, e0) = (-b, a * c - 4.0 * d, 4.0 * b * d - a * a * d - c * c);
    let mut best = ([Complex64::new(0.0, 0.0); 4], f64::INFINITY);
    let try_root = |y: f64, best: &mut ([Complex64; 4], f64)| {
        let raw = from_resolvent(y, &m);
        for pass in 0..2 {
            let f = if pass == 0 { raw } else { repair(raw, &m) };
            let (al, be, ga, de) = newton_factor(f, &m);
            let q1 = quadratic(al, be);
            let q2 = quadratic(ga, de);
            let (c1, c2) = (check_pair(exact, q1), check_pair(exact, q2));
            let res = c1.residual().max(c2.residual());
            if res < best.1 {
                *best = ([q1.0, q1.1, q2.0, q2.1], res);
                if c1.settled() && c2.settled() {
                    return true;
                }
            }
        }
        false
    };
    // The largest root first: it usually settles everything.
    if try_root(largest_cubic_root(e2, e1, e0), &mut best) {
        return (best.0, true);
    }
    let (ys, n) = real_cubic_roots(e2, e1, e0);
    for &y in &ys[..n] {
        if try_root(y, &mut best) {
            return (best.0, true);
        }
    }
    (best.0, false)
}

/// The residual of a quadratic's roots, |P(z)| against its rounding scale
/// Σ|cₖ||z|^(4−k), and their condition number κ = Σ|cₖ||z|^(4−k)/(|z||P′(z)|)
/// as a ratio, divided only when asked for (the usual case is settled by
/// comparisons alone).
#[derive(Clone, Copy)]
pub(super) struct PairCheck {
    /// The larger |P(z)| / Σ|cₖ||z|^(4−k) of the two roots, as (|P|, Σ).
    residual: (f64, f64),
    /// Whether κ ≤ 16 for both.
    well_conditioned: bool,
}

impl PairCheck {
    #[inline]
    fn residual(&self) -> f64 {
        self.residual.0 / self.residual.1
    }

    /// Residual within 8ε of rounding and κ ≤ 16: nothing to polish.
    #[inline]
    fn settled(&self) -> bool {
        self.residual.0 <= 8.0 * f64::EPSILON * self.residual.1 && self.well_conditioned
    }
}

/// The check of a quadratic's roots: once for a conjugate pair (both share
/// it), in real arithmetic for reals.
#[inline]
pub(super) fn check_pair(c: &[f64; 5], (z1, z2): (Complex64, Complex64)) -> PairCheck {
    let real = |x: f64| {
        let p = (((c[0] * x + c[1]) * x + c[2]) * x + c[3]) * x + c[4];
        let ax = x.abs();
        let s = (((c[0].abs() * ax + c[1].abs()) * ax + c[2].abs()) * ax + c[3].abs()) * ax
            + c[4].abs();
        let dp = ((4.0 * c[0] * x + 3.0 * c[1]) * x + 2.0 * c[2]) * x + c[3];
        let s = s.max(f64::MIN_POSITIVE);
        ((p.abs(), s), ax == 0.0 || s <= 16.0 * ax * dp.abs())
    };
    if z1.im == 0.0 {
        let (r1, k1) = real(z1.re);
        let (r2, k2) = real(z2.re);
        // the larger ratio (by division: the cross products of two small
        // roots' terms can underflow)
        let residual = if r1.0 / r1.1 >= r2.0 / r2.1 { r1 } else { r2 };
        PairCheck {
            residual,
            well_conditioned: k1 && k2,
        }
    } else {
        let s = abs_sum(c, z1).max(f64::MIN_POSITIVE);
        let n = l1(z1);
        PairCheck {
            residual: (l1(horner(c, z1)), s),
            well_conditioned: n == 0.0 || s <= 16.0 * n * l1(derivative(c, z1)),
        }
    }
}

/// The largest real root of y³ + e2·y² + e1·y + e0, cheaply: Cardano for a
/// single real root; for three, Halley's iteration on the depressed cubic
/// t³ + pt + q from t₀ = 2√(−p/3) — the largest root lies in [√(−p/3),
/// 2√(−p/3)], where the cubic is increasing and convex, so the iteration
/// falls monotonically onto it — instead of acos and cos. Not polished
/// further: Newton on the factorization follows.
#[inline]
pub(super) fn largest_cubic_root(e2: f64, e1: f64, e0: f64) -> f64 {
    let sh = e2 / 3.0;
    let p = e1 - e2 * sh;
    let q = e0 - sh * e1 + 2.0 * sh * sh * sh;
    let disc = (q / 2.0) * (q / 2.0) + (p / 3.0) * (p / 3.0) * (p / 3.0);
    let t = if disc >= 0.0 {
        let sq = disc.sqrt();
        let u = (-q / 2.0 + if q <= 0.0 { sq } else { -sq }).cbrt();
        if u != 0.0 {
            u - p / (3.0 * u)
        } else {
            (-q).cbrt()
        }
    } else {
        let mut t = 2.0 * (-p / 3.0).sqrt();
        // y = b (t = −2e₂/3) lies just above the root when a factor's
        // linear coefficient is small (b − y = αγ, e.g. a lightly damped
        // mode): a closer start, if it is right of the local minimum and
        // f > 0 there.
        let tb = -2.0 * sh;
        if tb < t && 3.0 * tb * tb >= -p && tb > 0.0 && (tb * tb + p) * tb + q > 0.0 {
            t = tb;
        }
        for _ in 0..8 {
            let f = (t * t + p) * t + q;
            let df = 3.0 * t * t + p;
            let den = 2.0 * df * df - f * 6.0 * t;
            if f <= 0.0 || den <= 0.0 {
                break;
            }
            let next = t - 2.0 * f * df / den;
            if next >= t || next.is_nan() {
                break;
            }
            // cubic convergence: after a step this small, ~ε is left
            let settled = t - next <= 1e-6 * next.abs();
            t = next;
            if settled {
                break;
            }
        }
        t
    };
    t - sh
}

/// The real roots of y³ + e2·y² + e1·y + e0 (Cardano or the trigonometric
/// form, each polished by Newton's method): up to three, and their count.
///
/// With one real root t and a complex pair of real part −t/2 (Cardano's
/// discriminant ≥ 0), the pair may in fact be a (near-)double real root:
/// −t/2 is returned too when it is a root to within rounding.
#[inline]
pub(super) fn real_cubic_roots(e2: f64, e1: f64, e0: f64) -> ([f64; 3], usize) {
    // Depressed: y = t − e2/3, t³ + P t + Q = 0.
    let sh = e2 / 3.0;
    let p = e1 - e2 * sh;
    let q = e0 - sh * e1 + 2.0 * sh * sh * sh;
    let f = |y: f64| ((y + e2) * y + e1) * y + e0;
    let scale = |y: f64| ((y.abs() + e2.abs()) * y.abs() + e1.abs()) * y.abs() + e0.abs();
    let polish = |mut y: f64| {
        for _ in 0..4 {
            let fy = f(y);
            let df = (3.0 * y + 2.0 * e2) * y + e1;
            if df == 0.0 || !fy.is_finite() {
                break;
            }
            let next = y - fy / df;
            if !next.is_finite() || f(next).abs() >= fy.abs() {
                break;
            }
            y = next;
        }
        y
    };
    if p == 0.0 && q == 0.0 {
        return ([-sh, 0.0, 0.0], 1);
    }
    let disc = (q / 2.0) * (q / 2.0) + (p / 3.0) * (p / 3.0) * (p / 3.0);
    if disc >= 0.0 {
        let sq = disc.sqrt();
        let u = (-q / 2.0 + if q <= 0.0 { sq } else { -sq }).cbrt();
        let t = if u != 0.0 {
            u - p / (3.0 * u)
        } else {
            (-q).cbrt()
        };
        let y = polish(t - sh);
        let y2 = polish(-t / 2.0 - sh);
        if f(y2).abs() <= 1e-8 * scale(y2) {
            ([y, y2, 0.0], 2)
        } else {
            ([y, 0.0, 0.0], 1)
        }
    } else {
        let r = (-p / 3.0).sqrt();
        let phi = (-q / 2.0 / (r * r * r)).clamp(-1.0, 1.0).acos() / 3.0;
        let third = 2.0 * std::f64::consts::PI / 3.0;
        (
            [
                polish(2.0 * r * phi.cos() - sh),
                polish(2.0 * r * (phi + third).cos() - sh),
                polish(2.0 * r * (phi - third).cos() - sh),
            ],
            3,
        )
    }
}

/// The scaled monic quartic x⁴ + ax³ + bx² + cx + d, with the reciprocals
/// of its coefficients (0 for a zero coefficient) for the backward error.
#[derive(Clone, Copy)]
pub(super) struct Monic {
    a: f64,
    b: f64,
    c: f64,
    d: f64,
    inv: [f64; 4],
}

impl Monic {
    #[inline]
    fn new(a: f64, b: f64, c: f64, d: f64) -> Monic {
        let r = |x: f64| if x != 0.0 { 1.0 / x } else { 0.0 };
        Monic {
            a,
            b,
            c,
            d,
            inv: [r(a), r(b), r(c), r(d)],
        }
    }

    /// Relative backward error of a factorization: Σ|residualₖ/coefₖ|
    /// (absolute for a zero coefficient).
    #[inline]
    fn backward_error(&self, f: (f64, f64, f64, f64)) -> f64 {
        let (al, be, ga, de) = f;
        let rel = |got: f64, want: f64, inv: f64| {
            let r = got - want;
            if inv != 0.0 { (r * inv).abs() } else { r.abs() }
        };
        rel(al + ga, self.a, self.inv[0])
            + rel(be + de + al * ga, self.b, self.inv[1])
            + rel(al * de + be * ga, self.c, self.inv[2])
            + rel(be * de, self.d, self.inv[3])
    }
}

/// The factorization (x² + ax/2 + y/2)² − (px + q)² for a resolvent root y.
#[inline]
pub(super) fn from_resolvent(y: f64, m: &Monic) -> (f64, f64, f64, f64) {
    let (a, b, c, d) = (m.a, m.b, m.c, m.d);
    let p = (a * a / 4.0 + y - b).max(0.0).sqrt();
    let mut q = (y * y / 4.0 - d).max(0.0).sqrt();
    // sign(pq) = sign(ay/4 − c/2)
    if a * y / 4.0 - c / 2.0 < 0.0 {
        q = -q;
    }
    (a / 2.0 + p, y / 2.0 + q, a / 2.0 - p, y / 2.0 - q)
}

/// Algorithm 1010's repair: βδ = d exactly from the larger of β, δ, and α,
/// γ re-solved from α + γ = a, αδ + βγ = c when that lowers the backward
/// error.
#[inline]
pub(super) fn repair(f: (f64, f64, f64, f64), m: &Monic) -> (f64, f64, f64, f64) {
    let (al, be, ga, de) = f;
    let (be2, de2) = if be.abs() >= de.abs() {
        (be, if be != 0.0 { m.d / be } else { de })
    } else {
        (if de != 0.0 { m.d / de } else { be }, de)
    };
    let mut best = f;
    let mut best_err = m.backward_error(f);
    let mut consider = |g: (f64, f64, f64, f64)| {
        let e = m.backward_error(g);
        if e < best_err {
            best = g;
            best_err = e;
        }
    };
    consider((al, be2, ga, de2));
    if (de2 - be2).abs() > 1e-8 * (de2.abs() + be2.abs()) {
        let al2 = (m.c - be2 * m.a) / (de2 - be2);
        consider((al2, be2, m.a - al2, de2));
    }
    best
}

/// Newton's method on the four Vieta equations of the factorization,
/// stopping when the backward error no longer decreases.
#[inline]
pub(super) fn newton_factor(mut f: (f64, f64, f64, f64), m: &Monic) -> (f64, f64, f64, f64) {
    let (a, b, c, d) = (m.a, m.b, m.c, m.d);
    let mut err = m.backward_error(f);
    for _ in 0..16 {
        if err <= 2.0 * f64::EPSILON {
            break;
        }
        let (al, be, ga, de) = f;
        let r = [
            al + ga - a,
            be + de + al * ga - b,
            al * de + be * ga - c,
            be * de - d,
        ];
        // J·Δ = r with J's columns ∂/∂α = (1, γ, δ, 0), ∂/∂β = (0, 1, γ, δ),
        // ∂/∂γ = (1, α, β, 0), ∂/∂δ = (0, 1, α, β). With Δγ = r₀ − Δα the
        // rest is a 3×3 system in (Δα, Δβ, Δδ), solved by Cramer's rule:
        //   (γ−α)Δα + Δβ + Δδ = r₁ − αr₀
        //   (δ−β)Δα + γΔβ + αΔδ = r₂ − βr₀
        //              δΔβ + βΔδ = r₃
        let (m11, m12, m13, k1) = (ga - al, 1.0, 1.0, r[1] - al * r[0]);
        let (m21, m22, m23, k2) = (de - be, ga, al, r[2] - be * r[0]);
        let (m31, m32, m33, k3) = (0.0, de, be, r[3]);
        let det3 =
            |a1: f64, a2: f64, a3: f64, b1: f64, b2: f64, b3: f64, c1: f64, c2: f64, c3: f64| {
                a1 * (b2 * c3 - b3 * c2) - a2 * (b1 * c3 - b3 * c1) + a3 * (b1 * c2 - b2 * c1)
            };
        let det = det3(m11, m12, m13, m21, m22, m23, m31, m32, m33);
        if det == 0.0 || !det.is_finite() {
            break;
        }
        let inv = 1.0 / det;
        let x1 = det3(k1, m12, m13, k2, m22, m23, k3, m32, m33) * inv;
        let x2 = det3(m11, k1, m13, m21, k2, m23, m31, k3, m33) * inv;
        let x4 = det3(m11, m12, k1, m21, m22, k2, m31, m32, k3) * inv;
        let step = [x1, x2, r[0] - x1, x4];
        let next = (al - step[0], be - step[1], ga - step[2], de - step[3]);
        let next_err = m.backward_error(next);
        if next_err >= err || next_err.is_nan() {
            break;
        }
        f = next;
        err = next_err;
    }
    f
}
