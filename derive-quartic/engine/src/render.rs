//! Rendering polynomials for people: as spec-syntax text (which parses back
//! to the same polynomial) and as LaTeX.

use crate::expr::SymbolTable;
use crate::poly::{Monomial, Poly};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed};

/// The display order of monomials: fewer "ordinary" (not positive-declared)
/// factors first, then by the ordinary symbols in spec order, then by the
/// positive ones.
/// (ordinary degree, ordinary factors, positive factors), exponents negated
/// so that higher powers sort first.
type DisplayKey = (i32, Vec<(usize, i32)>, Vec<(usize, i32)>);

fn display_key(m: &Monomial, table: &SymbolTable) -> DisplayKey {
    let mut degree = 0;
    let mut ordinary = Vec::new();
    let mut positive = Vec::new();
    for (id, e) in m.factors() {
        if table.get(id).positive {
            positive.push((id, -e));
        } else {
            degree += e.abs();
            ordinary.push((id, -e));
        }
    }
    (degree, ordinary, positive)
}

/// The terms of `p` in display order.
pub fn ordered_terms<'a>(p: &'a Poly, table: &SymbolTable) -> Vec<(&'a Monomial, &'a BigRational)> {
    let mut terms: Vec<_> = p.terms().collect();
    terms.sort_by_key(|(m, _)| display_key(m, table));
    terms
}

fn factor_text(name: &str, e: i32) -> String {
    if e == 1 {
        name.to_string()
    } else {
        format!("{name}.powi({e})")
    }
}

/// One term's magnitude (sign dropped) in spec syntax.
fn term_text(m: &Monomial, c: &BigRational, table: &SymbolTable) -> String {
    let c = c.abs();
    let mut num: Vec<String> = Vec::new();
    let mut den: Vec<String> = Vec::new();
    if !c.numer().is_one() || m.is_one() {
        num.push(c.numer().to_string());
    }
    if !c.denom().is_one() {
        den.push(c.denom().to_string());
    }
    for (id, e) in m.factors() {
        let name = &table.get(id).name;
        if e > 0 {
            num.push(factor_text(name, e));
        } else {
            den.push(factor_text(name, -e));
        }
    }
    if num.is_empty() {
        num.push("1".into());
    }
    let mut s = num.join("*");
    match den.len() {
        0 => {}
        1 => s = format!("{s}/{}", den[0]),
        _ => s = format!("{s}/({})", den.join("*")),
    }
    s
}

/// A polynomial as spec-syntax text, e.g. `-x_u - z_w + x_u*z_wdot/mu1`.
pub fn poly_text(p: &Poly, table: &SymbolTable) -> String {
    if p.is_zero() {
        return "0".into();
    }
    let mut s = String::new();
    for (i, (m, c)) in ordered_terms(p, table).into_iter().enumerate() {
        let neg = c.is_negative();
        match (i, neg) {
            (0, true) => s.push('-'),
            (0, false) => {}
            (_, true) => s.push_str(" - "),
            (_, false) => s.push_str(" + "),
        }
        s.push_str(&term_text(m, c, table));
    }
    s
}

fn latex_factor(latex: &str, e: i32) -> String {
    if e == 1 {
        latex.to_string()
    } else {
        format!("{latex}^{{{e}}}")
    }
}

fn latex_int(i: &BigInt) -> String {
    i.to_string()
}

/// One term's magnitude in LaTeX.
fn term_latex(m: &Monomial, c: &BigRational, table: &SymbolTable) -> String {
    let c = c.abs();
    let mut num: Vec<String> = Vec::new();
    let mut den: Vec<String> = Vec::new();
    if !c.numer().is_one() {
        num.push(latex_int(c.numer()));
    }
    if !c.denom().is_one() {
        den.push(latex_int(c.denom()));
    }
    for (id, e) in m.factors() {
        let latex = &table.get(id).latex;
        if e > 0 {
            num.push(latex_factor(latex, e));
        } else {
            den.push(latex_factor(latex, -e));
        }
    }
    let num = if num.is_empty() {
        "1".to_string()
    } else {
        num.join(" ")
    };
    if den.is_empty() {
        num
    } else {
        format!("\\frac{{{num}}}{{{}}}", den.join(" "))
    }
}

/// A polynomial in LaTeX.
pub fn poly_latex(p: &Poly, table: &SymbolTable) -> String {
    if p.is_zero() {
        return "0".into();
    }
    let mut s = String::new();
    for (i, (m, c)) in ordered_terms(p, table).into_iter().enumerate() {
        let neg = c.is_negative();
        match (i, neg) {
            (0, true) => s.push('-'),
            (0, false) => {}
            (_, true) => s.push_str(" - "),
            (_, false) => s.push_str(" + "),
        }
        s.push_str(&term_latex(m, c, table));
    }
    s
}

/// A rational as text: `3`, `-1/2`.
pub fn rational_text(r: &BigRational) -> String {
    if r.denom().is_one() {
        r.numer().to_string()
    } else {
        format!("{}/{}", r.numer(), r.denom())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diag::Diagnostics;
    use crate::expr::{Site, Symbol, parse_poly};
    use crate::spec::SourceFile;

    fn table() -> SymbolTable {
        let s = |n: &str, l: &str, p: bool| Symbol {
            name: n.into(),
            latex: l.into(),
            doc: String::new(),
            positive: p,
        };
        SymbolTable {
            symbols: vec![
                s("x_u", "x_u", false),
                s("z_w", "z_w", false),
                s("mu1", "\\mu_1", true),
            ],
        }
    }

    fn parse(text: &str, t: &SymbolTable) -> Poly {
        let file = SourceFile::new("t", text);
        let site = Site {
            file: &file,
            offset: 0,
            entry: String::new(),
        };
        let diags = Diagnostics::new();
        let poly = parse_poly(text, &site, t, &diags);
        diags.finish(poly, "t").unwrap()
    }

    #[test]
    fn text_round_trips_through_the_parser() {
        let t = table();
        for src in [
            "-x_u - z_w + x_u*z_w/mu1",
            "3/2*x_u.powi(2)/mu1.powi(2) - 1",
            "(x_u - 2*z_w)*(x_u + z_w/mu1)/3",
        ] {
            let p = parse(src, &t);
            let text = poly_text(&p, &t);
            assert_eq!(parse(&text, &t), p, "{src} → {text}");
        }
    }

    #[test]
    fn latex_uses_fractions_for_negative_powers() {
        let t = table();
        let p = parse("-x_u*z_w/mu1 + 2*x_u", &t);
        assert_eq!(poly_latex(&p, &t), "2 x_u - \\frac{x_u z_w}{\\mu_1}");
    }
}
