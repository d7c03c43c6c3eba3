//! The algebra of the conversion factors, with no diagnostics of its own:
//! the report's quantity from another notation's definition of the same row,
//! and the inverse relations.
//!
//! For a row whose dimensional "primary" quantity is p, each definition is
//! linear in p, q = a·p + b. Solving the other notation's definition for p
//! and substituting it into the report's, Q_R = a_R·p + b_R, gives
//! Q_R = (a_R/a)(q − b) + b_R: the report's quantity in the other notation's
//! terms. Solving that for q, and substituting the inverses of the other
//! quantities it uses, gives the other notation's quantity in the report's.

use super::model::SymbolKind;
use crate::expr::SymbolTable;
use crate::poly::{Monomial, Poly};
use num_rational::BigRational;
use num_traits::{One, Zero};

/// A definition `a·p + b` of a row's quantity, linear in its primary p, with
/// `a` a single term (a product of positive quantities) `c·m`.
pub struct Linear {
    pub m: Monomial,
    pub c: BigRational,
    pub b: Poly,
}

/// Why a definition is not of the form [`Linear`] needs.
pub enum NotLinear {
    /// p occurs squared, or divided by.
    NotLinear,
    /// The factor of p is a sum.
    FactorNotATerm,
    /// The factor of p is zero or has a factor not declared positive.
    FactorNotPositive,
}

/// `def` as `a·p + b` for the primary `p`.
pub fn linear(def: &Poly, p: usize, table: &SymbolTable) -> Result<Linear, NotLinear> {
    let (a, b) = def.linear_in(p).ok_or(NotLinear::NotLinear)?;
    let (m, c) = a.as_single_term().ok_or(NotLinear::FactorNotATerm)?;
    if c.is_zero() || m.factors().any(|(id, _)| !table.get(id).positive) {
        return Err(NotLinear::FactorNotPositive);
    }
    Ok(Linear {
        m: m.clone(),
        c: c.clone(),
        b,
    })
}

/// The report's quantity in the notation's terms: with the notation's
/// definition `own` (of its quantity, symbol `q`) and the report's `report`
/// (both linear in the same primary), Q_R = (a_R/a)(q − b) + b_R.
pub fn report_in_own_terms(own: &Linear, report: &Poly, p: usize, q: usize) -> Option<Poly> {
    let (ar, br) = report.linear_in(p)?;
    let n = report.arity();
    let q = Poly::symbol(n, q);
    Some(ar.div_term(&own.m, &own.c).mul(&q.sub(&own.b)).add(&br))
}

/// The symbols of `p` that are dimensional quantities, and the dimensions
/// (mass, length, time) of its first term.
pub fn leftover_dimensions<'t>(
    p: &Poly,
    table: &'t SymbolTable,
    kinds: &[SymbolKind],
    dims: &[[i32; 3]],
) -> (Vec<&'t str>, [i32; 3]) {
    let is_dim = |id: usize| kinds[id] == SymbolKind::Dimensional;
    let names: Vec<&str> = (p.terms())
        .flat_map(|(m, _)| m.factors().map(|(id, _)| id).collect::<Vec<_>>())
        .filter(|&id| is_dim(id))
        .map(|id| table.get(id).name.as_str())
        .collect();
    let mut acc = [0; 3];
    if let Some((m, _)) = p.terms().next() {
        for (id, e) in m.factors().filter(|(id, _)| is_dim(*id)) {
            for (a, d) in acc.iter_mut().zip(dims[id]) {
                *a += d * e;
            }
        }
    }
    (names, acc)
}

/// The inversion of one notation's relations Q_R = α·q + β: each of its
/// quantities q in the report's names.
pub struct Inversion<'a> {
    /// (row, symbol id) of the notation's own quantities.
    own: &'a [(usize, usize)],
    /// The report's quantity of each row in the notation's terms.
    to_report: &'a [Option<Poly>],
    /// The symbol id of the report's quantity of row 0 (the rows follow).
    report_start: usize,
    table: &'a SymbolTable,
    inverse: Vec<Option<Poly>>,
    visiting: Vec<bool>,
}

impl<'a> Inversion<'a> {
    pub fn new(
        own: &'a [(usize, usize)],
        to_report: &'a [Option<Poly>],
        report_start: usize,
        table: &'a SymbolTable,
    ) -> Self {
        Inversion {
            own,
            to_report,
            report_start,
            table,
            inverse: vec![None; to_report.len()],
            visiting: vec![false; to_report.len()],
        }
    }

    /// Row `ri`'s quantity in the report's names, or why it cannot be had.
    pub fn of(&mut self, ri: usize) -> Result<Poly, String> {
        self.visiting.iter_mut().for_each(|v| *v = false);
        self.solve(ri)
    }

    /// The inverses found, by row.
    pub fn into_inverses(self) -> Vec<Option<Poly>> {
        self.inverse
    }

    fn solve(&mut self, ri: usize) -> Result<Poly, String> {
        if let Some(p) = &self.inverse[ri] {
            return Ok(p.clone());
        }
        if self.visiting[ri] {
            return Err("the definitions refer to each other in a cycle".into());
        }
        self.visiting[ri] = true;
        let Some(rel) = &self.to_report[ri] else {
            return Err("the report does not define this row".into());
        };
        let sym = (self.own.iter())
            .find(|(r, _)| *r == ri)
            .map(|(_, s)| *s)
            .ok_or("the notation has no quantity of this row")?;
        let (alpha, beta) = rel
            .linear_in(sym)
            .ok_or("the relation is not linear in this notation's quantity")?;
        let (ma, ca) = alpha
            .as_single_term()
            .ok_or("the factor of this notation's quantity is not a single term")?;
        let report = Poly::symbol(rel.arity(), self.report_start + ri);
        let mut q = report.sub(&beta).div_term(ma, ca);
        // Replace the other quantities of this notation by their inverses.
        for &(rj, sj) in self.own {
            if rj != ri && q.mentions(sj) {
                let v = self.solve(rj)?;
                q = substitute_any(&q, sj, &v).ok_or_else(|| {
                    format!(
                        "cannot invert: `{}` occurs with a negative power and its inverse is not a single term",
                        self.table.get(sj).name
                    )
                })?;
            }
        }
        self.visiting[ri] = false;
        self.inverse[ri] = Some(q.clone());
        Ok(q)
    }
}

/// Substitute `value` for symbol `id`, negative powers included when
/// `value` is a single term.
fn substitute_any(p: &Poly, id: usize, value: &Poly) -> Option<Poly> {
    if let Some(s) = p.substitute(id, value) {
        return Some(s);
    }
    let (m, c) = value.as_single_term()?;
    let mut out = Poly::zero(p.arity());
    for (mm, cc) in p.terms() {
        let e = mm.exponent(id);
        let scaled = Monomial(m.0.iter().map(|x| x * e).collect());
        out.add_term(mm.without(id).mul(&scaled), cc * power(c, e));
    }
    Some(out)
}

/// `r^k` for any integer k (r non-zero when k < 0).
fn power(r: &BigRational, k: i32) -> BigRational {
    let mut acc = BigRational::one();
    for _ in 0..k.unsigned_abs() {
        acc *= r;
    }
    if k < 0 { BigRational::one() / acc } else { acc }
}
