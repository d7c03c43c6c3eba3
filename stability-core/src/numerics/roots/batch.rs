//! Many quartics at once: steps 1–4 of the module documentation on four
//! quartics per SIMD vector (`wide::f64x4`, one quartic per lane), with
//! the acceptance test of the scalar path; a quartic that the vector path
//! does not settle is solved by [`solve_quartic`] instead.
//!
//! Every lane performs the scalar path's operations in the scalar path's
//! order (IEEE arithmetic, no fused multiply-add, sqrt and division
//! correctly rounded in both), with its branches turned into masks:
//! the largest root of Ferrari's resolvent by Halley's iteration where it
//! has three real roots and by Cardano's formula where it has one (the
//! cube root per lane, by the scalar `f64::cbrt`), the factorization from
//! it and its refinement by Newton's method on the Vieta equations
//! (Orellana & De Michele, Algorithm 1010, ACM TOMS 46(2), 2020, as in
//! `factor`). The iterations stop per lane exactly where the scalar loops
//! break, and end when no lane is left moving. A lane is accepted only when
//! both quadratics' roots are *settled* — residual within 8ε of rounding
//! and condition number κ ≤ 16 — which is where the scalar path accepts
//! the same roots from its first candidate. So an accepted lane carries
//! the scalar path's roots bit for bit, and every other lane (a repair, a
//! second resolvent root or the polish needed, a quartic outside the
//! scaled range, an error) is [`solve_quartic`]'s answer itself:
//! [`solve_quartics`] returns exactly what [`solve_quartic`] returns, at a
//! lower cost per quartic (`tests/it/roots_batch.rs` holds it to that).

use super::binary::{exponent, pow2};
use super::{Complex64, RootsError, scale_back, scale_exponent, solve_quartic, sort_roots};
use wide::f64x4;

type V = f64x4;
const LANES: usize = 4;

/// The roots of many quartics: `roots[i]` = [`solve_quartic`]`(coeffs[i])`,
/// bit for bit, for `i` below the shorter slice's length, which is returned
/// (the rest of `roots` is left as it was). Pass slices of equal length.
///
/// Quartics are solved four at a time on SIMD vectors where the
/// factorization settles at once (the usual stability quartic: two complex
/// pairs), which costs less per quartic than one call each; no allocation.
pub fn solve_quartics(
    coeffs: &[[f64; 5]],
    roots: &mut [Result<[Complex64; 4], RootsError>],
) -> usize {
    let n = coeffs.len().min(roots.len());
    for (c, r) in coeffs[..n].chunks(LANES).zip(roots[..n].chunks_mut(LANES)) {
        solve_chunk(c, r);
    }
    n
}

/// The scaled quartic of a lane without one of its own (a short chunk, or
/// a quartic that `Scaled::of` declines): (x² + 1)(x² + 4), harmless.
const FILLER: [f64; 5] = [1.0, 0.0, 5.0, 0.0, 4.0];

/// Up to four quartics, one per lane.
fn solve_chunk(c: &[[f64; 5]], out: &mut [Result<[Complex64; 4], RootsError>]) {
    let scaled = Scaled::of(c);
    let (accepted, lanes) = factored_lanes(&scaled);
    for (l, (q, o)) in c.iter().zip(out.iter_mut()).enumerate() {
        let fast = (accepted >> l & 1 == 1)
            .then(|| scale_back(scaled.sigma[l], lanes[l]))
            .flatten();
        *o = match fast {
            Some(mut r) => {
                sort_roots(&mut r);
                Ok(r)
            }
            None => solve_quartic(*q),
        };
    }
}

/// Step 1 (`Scaling::of`) on four lanes: the quartics scaled by λ = 2^σ·x
/// and divided by 2^(e₀ + 4σ), where that is a single exact multiplication
/// by a power of two in range (else the lane is absent and the scalar path
/// takes it, as it takes a short chunk's empty lanes).
struct Scaled {
    /// The lanes that hold a scaled quartic.
    present: V,
    sigma: [i32; LANES],
    /// x⁴ + ax³ + bx² + cx + d.
    monic: [V; 4],
    /// The given coefficients scaled.
    exact: [V; 5],
}

impl Scaled {
    /// `Scaling::of`'s operations and conditions lane by lane, with the
    /// scalar `scale_exponent` and `exponent` for σ and e₀.
    #[inline]
    fn of(q: &[[f64; 5]]) -> Scaled {
        let s = V::splat;
        let c: [V; 5] = std::array::from_fn(|k| {
            V::new(std::array::from_fn(|l| {
                q.get(l).map_or(FILLER[k], |q| q[k])
            }))
        });
        let m: [V; 4] = std::array::from_fn(|k| c[k + 1] / c[0]);
        let (ma, ca) = (m.map(V::to_array), c.map(V::to_array));
        let mut sigma = [0; LANES];
        let mut ok = [0.0; LANES];
        let mut to_monic = [[1.0; LANES]; 4];
        let mut to_exact = [[1.0; LANES]; 5];
        for l in 0..q.len().min(LANES) {
            let lane_m = [ma[0][l], ma[1][l], ma[2][l], ma[3][l]];
            let valid = ca[4][l] != 0.0
                && (0..4).all(|k| {
                    lane_m[k].is_finite()
                        && (lane_m[k].abs() >= f64::MIN_POSITIVE || ca[k + 1][l] == 0.0)
                });
            if !valid {
                continue;
            }
            let sg = scale_exponent(&lane_m);
            let e0 = exponent(ca[0][l]);
            let n_monic: [i32; 4] = std::array::from_fn(|k| -(k as i32 + 1) * sg);
            let n_exact: [i32; 5] = std::array::from_fn(|k| -(k as i32) * sg - e0);
            let in_range = |n: &i32| (-1022..=1023).contains(n);
            if !(n_monic.iter().all(in_range) && n_exact.iter().all(in_range)) {
                continue;
            }
            (0..4).for_each(|k| to_monic[k][l] = pow2(n_monic[k]));
            (0..5).for_each(|k| to_exact[k][l] = pow2(n_exact[k]));
            sigma[l] = sg;
            ok[l] = 1.0;
        }
        let monic: [V; 4] = std::array::from_fn(|k| m[k] * V::new(to_monic[k]));
        let exact: [V; 5] = std::array::from_fn(|k| c[k] * V::new(to_exact[k]));
        let mut present = V::new(ok).simd_ne(s(0.0));
        let smallest = s(pow2(-969));
        for k in 0..4 {
            present = present
                & (monic[k].abs().simd_ge(smallest) | m[k].simd_eq(s(0.0)))
                & (exact[k + 1].abs().simd_ge(smallest) | c[k + 1].simd_eq(s(0.0)));
        }
        // an absent lane holds the harmless filler, not what it computed
        Scaled {
            present,
            sigma,
            monic: std::array::from_fn(|k| present.select(monic[k], s(FILLER[k + 1]))),
            exact: std::array::from_fn(|k| present.select(exact[k], s(FILLER[k]))),
        }
    }
}

/// Steps 2–4 on the scaled quartics of four lanes: the roots of each
/// lane's two quadratic factors (of the scaled quartic) and the bit mask
/// of the lanes whose roots are settled (bit l for lane l).
fn factored_lanes(scaled: &Scaled) -> (u32, [[Complex64; 4]; LANES]) {
    let [a, b, c, d] = scaled.monic;
    let m = Monic::new(a, b, c, d);
    let (y, resolved) = largest_resolvent_root(&m);
    let candidates = scaled.present & resolved;
    if !candidates.any() {
        return (0, [[Complex64::new(0.0, 0.0); 4]; LANES]);
    }
    let exact = &scaled.exact;
    let (al, be, ga, de) = newton_factor(from_resolvent(y, &m), &m);
    let (z1, z2, s1) = settled_quadratic(al, be, exact);
    let (z3, z4, s2) = settled_quadratic(ga, de, exact);
    let accepted = (candidates & s1 & s2).to_bitmask();
    let parts = [z1, z2, z3, z4].map(|(re, im)| (re.to_array(), im.to_array()));
    let roots = std::array::from_fn(|l| parts.map(|(re, im)| Complex64::new(re[l], im[l])));
    (accepted, roots)
}

/// `factor::Monic` on four lanes: the scaled monic quartic and the
/// reciprocals of its coefficients (0 for a zero coefficient).
struct Monic {
    a: V,
    b: V,
    c: V,
    d: V,
    inv: [V; 4],
}

impl Monic {
    #[inline]
    fn new(a: V, b: V, c: V, d: V) -> Monic {
        let zero = V::splat(0.0);
        let r = |x: V| x.simd_ne(zero).select(V::splat(1.0) / x, zero);
        Monic {
            a,
            b,
            c,
            d,
            inv: [r(a), r(b), r(c), r(d)],
        }
    }

    /// `factor::Monic::backward_error`: Σ|residualₖ/coefₖ|.
    #[inline]
    fn backward_error(&self, (al, be, ga, de): (V, V, V, V)) -> V {
        let zero = V::splat(0.0);
        let rel = |got: V, want: V, inv: V| {
            let r = got - want;
            inv.simd_ne(zero).select((r * inv).abs(), r.abs())
        };
        rel(al + ga, self.a, self.inv[0])
            + rel(be + de + al * ga, self.b, self.inv[1])
            + rel(al * de + be * ga, self.c, self.inv[2])
            + rel(be * de, self.d, self.inv[3])
    }
}

/// `factor::largest_cubic_root` of Ferrari's resolvent
/// y³ − by² + (ac − 4d)y + (4bd − a²d − c²): Halley's iteration from above
/// where it has three real roots, Cardano's formula where it has one; the
/// mask is the lanes that have either (not those with a NaN).
#[inline]
fn largest_resolvent_root(m: &Monic) -> (V, V) {
    let (a, b, c, d) = (m.a, m.b, m.c, m.d);
    let s = V::splat;
    let (e2, e1, e0) = (-b, a * c - s(4.0) * d, s(4.0) * b * d - a * a * d - c * c);
    let sh = e2 / s(3.0);
    let p = e1 - e2 * sh;
    let q = e0 - sh * e1 + s(2.0) * sh * sh * sh;
    let (h, k) = (q / s(2.0), p / s(3.0));
    let disc = h * h + k * k * k;
    let three_real = disc.simd_lt(s(0.0));
    let one_real = disc.simd_ge(s(0.0));
    let mut t = s(2.0) * (-p / s(3.0)).sqrt();
    let tb = s(-2.0) * sh;
    let from_b = tb.simd_lt(t)
        & (s(3.0) * tb * tb).simd_ge(-p)
        & tb.simd_gt(s(0.0))
        & ((tb * tb + p) * tb + q).simd_gt(s(0.0));
    t = from_b.select(tb, t);
    let mut moving = three_real;
    for _ in 0..8 {
        let f = (t * t + p) * t + q;
        let df = s(3.0) * t * t + p;
        let den = s(2.0) * df * df - f * s(6.0) * t;
        let next = t - s(2.0) * f * df / den;
        // the scalar loop's breaks: f ≤ 0, den ≤ 0, no descent, NaN
        let step = moving & f.simd_gt(s(0.0)) & den.simd_gt(s(0.0)) & next.simd_lt(t);
        let settled = (t - next).simd_le(s(1e-6) * next.abs());
        t = step.select(next, t);
        moving = step & !settled;
        if !moving.any() {
            break;
        }
    }
    let t = if one_real.any() {
        one_real.select(cardano(p, q, disc, one_real), t)
    } else {
        t
    };
    (t - sh, three_real | one_real)
}

/// `factor::largest_cubic_root`'s single real root t of t³ + pt + q by
/// Cardano's formula, in the lanes of `one_real` (disc ≥ 0), with the
/// scalar `f64::cbrt` on each of those lanes (as the scalar path takes it).
#[inline(never)]
fn cardano(p: V, q: V, disc: V, one_real: V) -> V {
    let s = V::splat;
    let sq = disc.sqrt();
    let arg = -q / s(2.0) + q.simd_le(s(0.0)).select(sq, -sq);
    let (arg, p, q) = (arg.to_array(), p.to_array(), q.to_array());
    let lanes = one_real.to_bitmask();
    V::new(std::array::from_fn(|l| {
        if lanes >> l & 1 == 0 {
            return 0.0;
        }
        let u = arg[l].cbrt();
        if u != 0.0 {
            u - p[l] / (3.0 * u)
        } else {
            (-q[l]).cbrt()
        }
    }))
}

/// `factor::from_resolvent`: (x² + ax/2 + y/2)² − (px + q)².
#[inline]
fn from_resolvent(y: V, m: &Monic) -> (V, V, V, V) {
    let (a, b, c, d) = (m.a, m.b, m.c, m.d);
    let s = V::splat;
    let p = (a * a / s(4.0) + y - b).max(s(0.0)).sqrt();
    let q = (y * y / s(4.0) - d).max(s(0.0)).sqrt();
    let q = (a * y / s(4.0) - c / s(2.0)).simd_lt(s(0.0)).select(-q, q);
    (
        a / s(2.0) + p,
        y / s(2.0) + q,
        a / s(2.0) - p,
        y / s(2.0) - q,
    )
}

/// a₁(b₂c₃ − b₃c₂) − a₂(b₁c₃ − b₃c₁) + a₃(b₁c₂ − b₂c₁).
#[inline]
#[allow(clippy::too_many_arguments)]
fn det3(a1: V, a2: V, a3: V, b1: V, b2: V, b3: V, c1: V, c2: V, c3: V) -> V {
    a1 * (b2 * c3 - b3 * c2) - a2 * (b1 * c3 - b3 * c1) + a3 * (b1 * c2 - b2 * c1)
}

/// `factor::newton_factor` per lane: Newton's method on the four Vieta
/// equations, each lane stopping where the scalar loop breaks.
#[inline]
fn newton_factor(mut f: (V, V, V, V), m: &Monic) -> (V, V, V, V) {
    let (a, b, c, d) = (m.a, m.b, m.c, m.d);
    let zero = V::splat(0.0);
    let mut err = m.backward_error(f);
    let mut moving = V::splat(0.0).simd_eq(zero);
    for _ in 0..16 {
        moving &= !err.simd_le(V::splat(2.0 * f64::EPSILON));
        if !moving.any() {
            break;
        }
        let (al, be, ga, de) = f;
        let r = [
            al + ga - a,
            be + de + al * ga - b,
            al * de + be * ga - c,
            be * de - d,
        ];
        let (m11, m12, m13, k1) = (ga - al, V::splat(1.0), V::splat(1.0), r[1] - al * r[0]);
        let (m21, m22, m23, k2) = (de - be, ga, al, r[2] - be * r[0]);
        let (m31, m32, m33, k3) = (zero, de, be, r[3]);
        let det = det3(m11, m12, m13, m21, m22, m23, m31, m32, m33);
        let inv = V::splat(1.0) / det;
        let x1 = det3(k1, m12, m13, k2, m22, m23, k3, m32, m33) * inv;
        let x2 = det3(m11, k1, m13, m21, k2, m23, m31, k3, m33) * inv;
        let x4 = det3(m11, m12, k1, m21, m22, k2, m31, m32, k3) * inv;
        let next = (al - x1, be - x2, ga - (r[0] - x1), de - x4);
        let next_err = m.backward_error(next);
        // the scalar loop's breaks: det = 0 or not finite, no decrease, NaN
        let step = moving
            & det.simd_ne(zero)
            & det.is_finite()
            & !next_err.simd_ge(err)
            & !next_err.is_nan();
        f = (
            step.select(next.0, f.0),
            step.select(next.1, f.1),
            step.select(next.2, f.2),
            step.select(next.3, f.3),
        );
        err = step.select(next_err, err);
        moving = step;
    }
    f
}

/// `super::quadratic`'s roots of x² + px + q per lane, and whether both
/// are settled as `factor::check_pair` judges (residual within 8ε of its
/// rounding scale, κ ≤ 16) on the scaled quartic `c`.
#[inline]
fn settled_quadratic(p: V, q: V, c: &[V; 5]) -> ((V, V), (V, V), V) {
    let zero = V::splat(0.0);
    let h = -p / V::splat(2.0);
    let disc = h * h - q;
    let real = disc.simd_ge(zero);
    // √|disc|: √disc in the real lanes, √(−disc) in the complex ones
    let sd = disc.abs().sqrt();
    let big = h.simd_eq(zero).select(sd, h + sd.copysign(h));
    let small = big.simd_ne(zero).select(q / big, zero);
    let w = sd;
    let z1 = (real.select(big, h), real.select(zero, w));
    let z2 = (real.select(small, h), real.select(zero, -w));
    // the first root in complex arithmetic (exact for a real one); the
    // second in real arithmetic, needed only when real
    let first = settled_at(c, z1.0, z1.1);
    if !real.any() {
        // two complex pairs (the usual stability quartic): the conjugate
        // shares the first root's check
        return (z1, z2, first);
    }
    let second = settled_at(c, z2.0, zero);
    (z1, z2, first & (second | !real))
}

/// `factor::check_pair` at one root z = x + iy: |P(z)|₁ ≤ 8ε Σ|cₖ||z|₁^(4−k)
/// (the sum at least the smallest normal) and κ ≤ 16, i.e.
/// Σ|cₖ||z|₁^(4−k) ≤ 16|z|₁|P′(z)|₁ or z = 0; with |·|₁ = |re| + |im|.
#[inline]
fn settled_at(c: &[V; 5], x: V, y: V) -> V {
    let s = V::splat;
    let n = x.abs() + y.abs();
    // P(z) = (((z c₀ + c₁) z + c₂) z + c₃) z + c₄, as num-complex does it
    let (mut pr, mut pi) = (x * c[0] + c[1], y * c[0]);
    for &ck in &c[2..] {
        (pr, pi) = (pr * x - pi * y + ck, pr * y + pi * x);
    }
    // P′(z) = ((z·4c₀ + 3c₁) z + 2c₂) z + c₃
    let (mut dr, mut di) = (x * (s(4.0) * c[0]) + s(3.0) * c[1], y * (s(4.0) * c[0]));
    for ck in [s(2.0) * c[2], c[3]] {
        (dr, di) = (dr * x - di * y + ck, dr * y + di * x);
    }
    let mut sum = s(0.0);
    for &ck in c {
        sum = sum * n + ck.abs();
    }
    let sum = sum.max(s(f64::MIN_POSITIVE));
    let residual = (pr.abs() + pi.abs()).simd_le(s(8.0 * f64::EPSILON) * sum);
    let conditioned = n.simd_eq(s(0.0)) | sum.simd_le(s(16.0) * n * (dr.abs() + di.abs()));
    residual & conditioned
}

#[cfg(test)]
mod tests {
    use super::super::Scaling;
    use super::*;

    /// The stability quartics of `benches/roots.rs`: short period and
    /// phugoid pairs of a tailless delta, A = 1 + small.
    fn stability_quartics() -> Vec<[f64; 5]> {
        (0..256)
            .map(|i| {
                let t = i as f64;
                let w = |k: f64| 0.3 + (t * 0.37 + k * 1.91).sin().abs();
                let (p1, q1) = (4.0 * w(1.0), 40.0 + 400.0 * w(2.0));
                let (p2, q2) = (0.02 * w(3.0), 0.004 + 0.05 * w(4.0));
                let a = 1.0 + 0.01 * w(5.0);
                [
                    a,
                    a * (p1 + p2),
                    a * (q1 + q2 + p1 * p2),
                    a * (p1 * q2 + p2 * q1),
                    a * q1 * q2,
                ]
            })
            .collect()
    }

    /// The lanes' scaled quartics and roots, each accepted lane checked
    /// against the scalar path (`Scaling::of`, `factor::factored_roots`)
    /// bit for bit; returns the number accepted.
    fn accepted_as_the_scalar_path(quartics: &[[f64; 5]]) -> u32 {
        let mut count = 0;
        for chunk in quartics.chunks(LANES) {
            let scaled = Scaled::of(chunk);
            let (accepted, lanes) = factored_lanes(&scaled);
            for (l, q) in chunk.iter().enumerate() {
                if accepted >> l & 1 == 0 {
                    continue;
                }
                let s = Scaling::of(q).unwrap();
                assert_eq!(scaled.sigma[l], s.sigma);
                let monic = scaled.monic.map(|v| v.to_array()[l]);
                let exact = scaled.exact.map(|v| v.to_array()[l]);
                assert_eq!((monic, exact), (s.monic, s.exact), "{q:?}");
                let [a, b, c, d] = s.monic;
                let (scalar, settled) = super::super::factor::factored_roots(a, b, c, d, &s.exact);
                assert!(settled);
                assert_eq!(lanes[l], scalar, "{q:?}");
                count += 1;
            }
        }
        count
    }

    #[test]
    fn the_vector_path_settles_every_stability_quartic_as_the_scalar_path_does() {
        assert_eq!(accepted_as_the_scalar_path(&stability_quartics()), 256);
    }

    /// The mixed quartics of `benches/roots.rs`: every root structure.
    fn mixed_quartics() -> Vec<[f64; 5]> {
        (0..256)
            .map(|i| {
                let t = i as f64;
                let w = |k: f64| (t * 0.731 + k * 2.17).sin();
                [
                    1.0 + w(0.0).abs(),
                    3.0 * w(1.0),
                    5.0 * w(2.0),
                    2.0 * w(3.0),
                    4.0 * w(4.0),
                ]
            })
            .collect()
    }

    #[test]
    fn mixed_quartics_settle_in_lanes_with_either_resolvent_formula() {
        // 255 of the 256 settle on the scalar path's first candidate; 181
        // of them from Cardano's formula (one real resolvent root)
        assert_eq!(accepted_as_the_scalar_path(&mixed_quartics()), 255);
    }

    #[test]
    fn scaled_quartics_far_from_one_are_scaled_as_the_scalar_path_does() {
        // the stability quartics with λ scaled by 2^±200 and A by 2^±100:
        // σ, the monic and the exact coefficients bit for bit
        let mut quartics = Vec::new();
        for q in stability_quartics().iter().take(16) {
            for (rho, alpha) in [(200, 100), (-200, -100), (200, -100), (-200, 100)] {
                let f = |k: usize| pow2(alpha) * pow2(rho * k as i32);
                quartics.push(std::array::from_fn(|k| q[k] * f(k)));
            }
        }
        assert_eq!(accepted_as_the_scalar_path(&quartics), 64);
    }

    #[test]
    fn empty_and_invalid_lanes_are_never_accepted() {
        assert_eq!(factored_lanes(&Scaled::of(&[])).0, 0);
        let invalid = [
            [0.0, 1.0, 2.0, 3.0, 4.0],
            [1.0, f64::NAN, 2.0, 3.0, 4.0],
            [1.0, 1.0, 2.0, 3.0, 0.0],
            [1e-300, 1e300, 1.0, 1.0, 1.0],
        ];
        let scaled = Scaled::of(&invalid);
        assert!(!scaled.present.any());
        assert_eq!(factored_lanes(&scaled).0, 0);
    }
}
