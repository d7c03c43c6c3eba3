//! Scaling by powers of two, which is exact: a coefficient times 2ⁿ loses
//! nothing unless the result leaves f64's normal range. The quartic is
//! solved at any finite scale by moving it into range this way
//! (λ = 2^σ·x), and Routh's discriminant is signed the same way.

use num_complex::Complex64;

/// ⌊log₂|x|⌋ of a finite, non-zero x (subnormals included).
#[inline]
pub(crate) fn exponent(x: f64) -> i32 {
    let bits = x.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i32;
    if biased == 0 {
        let mantissa = bits & ((1u64 << 52) - 1);
        -1011 - mantissa.leading_zeros() as i32
    } else {
        biased - 1023
    }
}

/// 2ⁿ for −1022 ≤ n ≤ 1023.
#[inline]
pub(crate) const fn pow2(n: i32) -> f64 {
    f64::from_bits(((n + 1023) as u64) << 52)
}

/// x·2ⁿ for any n, exact unless the result is subnormal, zero or infinite
/// (it is applied in steps of at most 2¹⁰⁰⁰, each of which moves x towards
/// the result, so no intermediate leaves the range the result is in).
#[inline]
pub(crate) fn ldexp(x: f64, n: i32) -> f64 {
    if (-1022..=1023).contains(&n) {
        x * pow2(n)
    } else {
        ldexp_far(x, n)
    }
}

fn ldexp_far(mut x: f64, mut n: i32) -> f64 {
    while n > 1000 {
        x *= pow2(1000);
        n -= 1000;
    }
    while n < -1000 {
        x *= pow2(-1000);
        n += 1000;
    }
    x * pow2(n)
}

/// z·2ⁿ.
#[inline]
pub(crate) fn ldexp_c(z: Complex64, n: i32) -> Complex64 {
    Complex64::new(ldexp(z.re, n), ldexp(z.im, n))
}

/// log₂|x| of a finite non-zero x, from its exponent and mantissa (no
/// overflow for any x).
pub(crate) fn log2_abs(x: f64) -> f64 {
    let e = exponent(x);
    e as f64 + ldexp(x.abs(), -e).log2()
}

/// a/b for any finite a, b ≠ 0 whose quotient is representable: b is
/// brought to modulus ~1 by a power of two first (Smith's concern: |b|²
/// overflows for |b| > 1e154 and underflows for |b| < 1e-154).
pub(crate) fn cdiv(a: Complex64, b: Complex64) -> Complex64 {
    let m = b.re.abs().max(b.im.abs());
    if m == 0.0 {
        return Complex64::new(f64::INFINITY, f64::INFINITY);
    }
    let k = exponent(m);
    let bs = ldexp_c(b, -k);
    let q = a * bs.conj() / bs.norm_sqr();
    ldexp_c(q, -k)
}

/// A real number as m·2^e with 1 ≤ |m| < 2 (or m = 0): products of any
/// finite numbers without overflow or underflow, for the sign of Routh's
/// discriminant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Wide {
    m: f64,
    e: i32,
}

impl Wide {
    pub(crate) fn new(x: f64) -> Wide {
        if x == 0.0 {
            Wide { m: 0.0, e: 0 }
        } else {
            let e = exponent(x);
            Wide { m: ldexp(x, -e), e }
        }
    }

    pub(crate) fn mul(self, o: Wide) -> Wide {
        let p = self.m * o.m;
        if p == 0.0 {
            return Wide { m: 0.0, e: 0 };
        }
        let k = exponent(p);
        Wide {
            m: ldexp(p, -k),
            e: self.e + o.e + k,
        }
    }

    /// The sum of `terms` as (the sum, Σ|terms|), both on the scale 2^e of
    /// the largest term, and that e.
    pub(crate) fn sum(terms: &[Wide]) -> (f64, f64, i32) {
        let e = terms
            .iter()
            .filter(|t| t.m != 0.0)
            .map(|t| t.e)
            .max()
            .unwrap_or(0);
        let (mut s, mut a) = (0.0, 0.0);
        for t in terms {
            let v = ldexp(t.m, t.e.saturating_sub(e).max(-2000));
            s += v;
            a += v.abs();
        }
        (s, a, e)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exponents_and_exact_scaling() {
        for x in [
            1.0,
            1.5,
            3.0,
            1e308,
            f64::MAX,
            1e-308,
            5e-324,
            1e-320,
            -7.25,
        ] {
            let e = exponent(x);
            let m = ldexp(x, -e).abs();
            assert!((1.0..2.0).contains(&m), "{x}: {e} {m}");
            assert_eq!(ldexp(ldexp(x, -e), e), x, "{x}");
        }
        assert_eq!(exponent(5e-324), -1074);
        assert_eq!(ldexp(1.0, 2000), f64::INFINITY);
        assert_eq!(ldexp(f64::MAX, -2046), ldexp(f64::MAX / 2.0, -2045));
        assert!((log2_abs(1e300) - 1e300f64.log2()).abs() < 1e-12);
        assert!((log2_abs(5e-324) + 1074.0).abs() < 1e-12);
    }

    #[test]
    fn division_at_any_scale() {
        let c = Complex64::new;
        for s in [1e-300, 1e-160, 1.0, 1e160, 1e300] {
            let q = cdiv(c(3.0 * s, 4.0 * s), c(1.0 * s, 2.0 * s));
            assert!((q - c(2.2, -0.4)).norm() < 1e-15, "{s}: {q}");
        }
    }

    #[test]
    fn wide_products_keep_their_sign_past_f64() {
        let big = Wide::new(1e300).mul(Wide::new(1e300));
        let small = Wide::new(-1e-300).mul(Wide::new(1e-300));
        let (s, a, e) = Wide::sum(&[big, small]);
        assert!(s > 0.0 && a >= s && e > 1900);
        let (s, _, _) = Wide::sum(&[small, Wide::new(0.0)]);
        assert!(s < 0.0);
    }
}
