//! Exact Laurent polynomials with rational coefficients.
//!
//! A [`Poly`] is a finite sum of terms `c · ∏ sᵢ^eᵢ` where `c` is an exact
//! rational and the exponents `eᵢ` are integers. Negative exponents are
//! allowed only for symbols declared positive (μ₁ and i_B in the quartic), so
//! that `1/mu1` is represented exactly rather than as a rational function.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::collections::BTreeMap;

/// Exponents of a monomial, indexed by symbol id.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Monomial(pub Vec<i32>);

impl Monomial {
    /// The monomial `1` over `n` symbols.
    pub fn one(n: usize) -> Self {
        Monomial(vec![0; n])
    }

    /// The monomial `s` (symbol `id`) over `n` symbols.
    pub fn symbol(n: usize, id: usize) -> Self {
        let mut e = vec![0; n];
        e[id] = 1;
        Monomial(e)
    }

    pub fn mul(&self, other: &Monomial) -> Monomial {
        Monomial(self.0.iter().zip(&other.0).map(|(a, b)| a + b).collect())
    }

    pub fn inverse(&self) -> Monomial {
        Monomial(self.0.iter().map(|a| -a).collect())
    }

    pub fn is_one(&self) -> bool {
        self.0.iter().all(|&e| e == 0)
    }

    /// The exponent of symbol `id`.
    pub fn exponent(&self, id: usize) -> i32 {
        self.0[id]
    }

    /// This monomial with symbol `id` removed (its exponent set to zero).
    pub fn without(&self, id: usize) -> Monomial {
        let mut e = self.0.clone();
        e[id] = 0;
        Monomial(e)
    }

    /// The symbols with a non-zero exponent, as `(id, exponent)`.
    pub fn factors(&self) -> impl Iterator<Item = (usize, i32)> + '_ {
        self.0
            .iter()
            .enumerate()
            .filter(|(_, e)| **e != 0)
            .map(|(i, e)| (i, *e))
    }
}

/// An exact Laurent polynomial over a fixed list of symbols.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Poly {
    n: usize,
    terms: BTreeMap<Monomial, BigRational>,
}

impl Poly {
    pub fn zero(n: usize) -> Self {
        Poly {
            n,
            terms: BTreeMap::new(),
        }
    }

    pub fn constant(n: usize, c: BigRational) -> Self {
        let mut p = Poly::zero(n);
        p.add_term(Monomial::one(n), c);
        p
    }

    pub fn symbol(n: usize, id: usize) -> Self {
        let mut p = Poly::zero(n);
        p.add_term(Monomial::symbol(n, id), BigRational::one());
        p
    }

    /// Number of symbols this polynomial is written over.
    pub fn arity(&self) -> usize {
        self.n
    }

    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    pub fn len(&self) -> usize {
        self.terms.len()
    }

    pub fn is_empty(&self) -> bool {
        self.terms.is_empty()
    }

    /// The terms, in the order of their monomials.
    pub fn terms(&self) -> impl Iterator<Item = (&Monomial, &BigRational)> {
        self.terms.iter()
    }

    /// The coefficient of monomial `m` (zero if absent).
    pub fn coefficient(&self, m: &Monomial) -> BigRational {
        self.terms.get(m).cloned().unwrap_or_else(BigRational::zero)
    }

    pub fn add_term(&mut self, m: Monomial, c: BigRational) {
        if c.is_zero() {
            return;
        }
        let entry = self.terms.entry(m);
        match entry {
            std::collections::btree_map::Entry::Vacant(v) => {
                v.insert(c);
            }
            std::collections::btree_map::Entry::Occupied(mut o) => {
                let sum = o.get() + c;
                if sum.is_zero() {
                    o.remove();
                } else {
                    *o.get_mut() = sum;
                }
            }
        }
    }

    pub fn add(&self, other: &Poly) -> Poly {
        let mut p = self.clone();
        for (m, c) in &other.terms {
            p.add_term(m.clone(), c.clone());
        }
        p
    }

    pub fn sub(&self, other: &Poly) -> Poly {
        self.add(&other.neg())
    }

    pub fn neg(&self) -> Poly {
        Poly {
            n: self.n,
            terms: self.terms.iter().map(|(m, c)| (m.clone(), -c)).collect(),
        }
    }

    pub fn mul(&self, other: &Poly) -> Poly {
        let mut p = Poly::zero(self.n);
        for (ma, ca) in &self.terms {
            for (mb, cb) in &other.terms {
                p.add_term(ma.mul(mb), ca * cb);
            }
        }
        p
    }

    /// `self^k` for `k ≥ 0`.
    pub fn pow(&self, k: u32) -> Poly {
        let mut p = Poly::constant(self.n, BigRational::one());
        for _ in 0..k {
            p = p.mul(self);
        }
        p
    }

    /// If this polynomial is a single term `c·m`, that term.
    pub fn as_single_term(&self) -> Option<(&Monomial, &BigRational)> {
        if self.terms.len() == 1 {
            self.terms.iter().next()
        } else {
            None
        }
    }

    /// If this polynomial is a constant, its value.
    pub fn as_constant(&self) -> Option<BigRational> {
        if self.is_zero() {
            return Some(BigRational::zero());
        }
        match self.as_single_term() {
            Some((m, c)) if m.is_one() => Some(c.clone()),
            _ => None,
        }
    }

    /// Divide by a single term `c·m` (`c ≠ 0`).
    pub fn div_term(&self, m: &Monomial, c: &BigRational) -> Poly {
        let inv = m.inverse();
        Poly {
            n: self.n,
            terms: self
                .terms
                .iter()
                .map(|(mm, cc)| (mm.mul(&inv), cc / c))
                .collect(),
        }
    }

    /// The coefficient of `s^k` where `s` is symbol `id`: the terms whose
    /// exponent of `s` is `k`, with `s` removed.
    pub fn coefficient_of_power(&self, id: usize, k: i32) -> Poly {
        let mut p = Poly::zero(self.n);
        for (m, c) in &self.terms {
            if m.exponent(id) == k {
                p.add_term(m.without(id), c.clone());
            }
        }
        p
    }

    /// The largest exponent of symbol `id` (None for the zero polynomial).
    pub fn degree_in(&self, id: usize) -> Option<i32> {
        self.terms.keys().map(|m| m.exponent(id)).max()
    }

    /// The smallest exponent of symbol `id` (None for the zero polynomial).
    pub fn low_degree_in(&self, id: usize) -> Option<i32> {
        self.terms.keys().map(|m| m.exponent(id)).min()
    }

    /// ∂/∂s for symbol `id`, exact (Laurent exponents included).
    pub fn derivative(&self, id: usize) -> Poly {
        let mut p = Poly::zero(self.n);
        for (m, c) in &self.terms {
            let e = m.exponent(id);
            if e != 0 {
                let mut mm = m.clone();
                mm.0[id] -= 1;
                p.add_term(mm, c * BigRational::from_integer(BigInt::from(e)));
            }
        }
        p
    }

    /// Substitute the polynomial `value` for symbol `id` (which must occur
    /// with non-negative exponents only; `None` otherwise).
    pub fn substitute(&self, id: usize, value: &Poly) -> Option<Poly> {
        let mut out = Poly::zero(self.n);
        for (m, c) in &self.terms {
            let e = m.exponent(id);
            if e < 0 {
                return None;
            }
            let rest = Poly {
                n: self.n,
                terms: std::iter::once((m.without(id), c.clone())).collect(),
            };
            out = out.add(&rest.mul(&value.pow(e as u32)));
        }
        Some(out)
    }

    /// Split as `a·s + b` for symbol `id`: `(a, b)` when s occurs only to
    /// the first power (a, b free of s), `None` otherwise.
    pub fn linear_in(&self, id: usize) -> Option<(Poly, Poly)> {
        if self.terms.keys().any(|m| !matches!(m.exponent(id), 0 | 1)) {
            return None;
        }
        Some((
            self.coefficient_of_power(id, 1),
            self.coefficient_of_power(id, 0),
        ))
    }

    /// The same polynomial over `n` symbols (`n` at least its arity): the
    /// symbols it has keep their ids, the new ones do not occur.
    pub fn widen(&self, n: usize) -> Poly {
        assert!(n >= self.n, "widen: {n} symbols are fewer than {}", self.n);
        let terms = (self.terms.iter())
            .map(|(m, c)| {
                let mut e = m.0.clone();
                e.resize(n, 0);
                (Monomial(e), c.clone())
            })
            .collect();
        Poly { n, terms }
    }

    /// Whether symbol `id` occurs.
    pub fn mentions(&self, id: usize) -> bool {
        self.terms.keys().any(|m| m.exponent(id) != 0)
    }

    /// Evaluate in floating point (for tests and numeric cross-checks).
    pub fn eval(&self, values: &[f64]) -> f64 {
        self.terms
            .iter()
            .map(|(m, c)| {
                let mut v = c.to_f64().unwrap_or(f64::NAN);
                for (id, e) in m.factors() {
                    v *= values[id].powi(e);
                }
                v
            })
            .sum()
    }

    /// Σ|terms| in floating point: the scale against which a rounding error of
    /// [`Poly::eval`] is measured.
    pub fn eval_abs(&self, values: &[f64]) -> f64 {
        self.terms
            .iter()
            .map(|(m, c)| {
                let mut v = c.abs().to_f64().unwrap_or(f64::NAN);
                for (id, e) in m.factors() {
                    v *= values[id].abs().powi(e);
                }
                v
            })
            .sum()
    }
}

/// Parse a decimal literal (`12`, `0.5`, `1e-3`, `2.5E+2`) exactly.
pub fn rational_from_decimal(text: &str) -> Option<BigRational> {
    let text = text.replace('_', "");
    let (mantissa, exponent) = match text.find(['e', 'E']) {
        Some(i) => (&text[..i], text[i + 1..].parse::<i32>().ok()?),
        None => (text.as_str(), 0),
    };
    let (int_part, frac_part) = match mantissa.find('.') {
        Some(i) => (&mantissa[..i], &mantissa[i + 1..]),
        None => (mantissa, ""),
    };
    if int_part.is_empty() && frac_part.is_empty() {
        return None;
    }
    let digits = format!("{int_part}{frac_part}");
    if !digits.chars().all(|c| c.is_ascii_digit()) {
        return None;
    }
    let num: BigInt = digits.parse().ok()?;
    let scale = exponent - frac_part.len() as i32;
    let ten = BigInt::from(10);
    let r = if scale >= 0 {
        BigRational::from_integer(num * num_traits::pow(ten, scale as usize))
    } else {
        BigRational::new(num, num_traits::pow(ten, (-scale) as usize))
    };
    Some(r)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn r(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    #[test]
    fn decimal_literals_are_exact() {
        assert_eq!(rational_from_decimal("0.5"), Some(r(1, 2)));
        assert_eq!(rational_from_decimal("1e-3"), Some(r(1, 1000)));
        assert_eq!(rational_from_decimal("2.5E+2"), Some(r(250, 1)));
        assert_eq!(rational_from_decimal("0.1"), Some(r(1, 10)));
        assert_eq!(rational_from_decimal("1_000"), Some(r(1000, 1)));
        assert_eq!(rational_from_decimal("abc"), None);
    }

    #[test]
    fn laurent_arithmetic_and_derivative() {
        // (x + 1/y)² = x² + 2x/y + 1/y²; ∂/∂y = -2x/y² - 2/y³
        let n = 2;
        let x = Poly::symbol(n, 0);
        let y = Poly::symbol(n, 1);
        let inv_y = Poly::constant(n, r(1, 1)).div_term(&Monomial::symbol(n, 1), &r(1, 1));
        let p = x.add(&inv_y).pow(2);
        assert_eq!(p.len(), 3);
        let d = p.derivative(1);
        let vals = [3.0, 2.0];
        let expect = -2.0 * 3.0 / 4.0 - 2.0 / 8.0;
        assert!((d.eval(&vals) - expect).abs() < 1e-15);
        // y · (1/y) = 1 exactly
        assert_eq!(y.mul(&inv_y).as_constant(), Some(r(1, 1)));
    }

    #[test]
    fn coefficient_of_power_splits_a_polynomial() {
        // (l - a)(l + b) = l² + (b - a) l - ab
        let n = 3;
        let l = Poly::symbol(n, 0);
        let a = Poly::symbol(n, 1);
        let b = Poly::symbol(n, 2);
        let p = l.sub(&a).mul(&l.add(&b));
        assert_eq!(p.degree_in(0), Some(2));
        assert_eq!(p.coefficient_of_power(0, 1), b.sub(&a));
        assert_eq!(p.coefficient_of_power(0, 0), a.mul(&b).neg());
    }
}
