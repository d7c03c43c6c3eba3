//! Symbols, and expressions parsed with syn into exact Laurent polynomials.
//!
//! An expression in a spec is Rust syntax restricted to `+ - * / ( )`, decimal
//! numbers, the spec's symbols and `.powi(n)`. Division is allowed by a single
//! term whose symbols are declared positive (so `x/mu1` is exact, `x/(1 + y)`
//! is not a polynomial and is refused).

use crate::diag::{Diagnostic, Diagnostics};
use crate::poly::{Poly, rational_from_decimal};
use crate::spec::SourceFile;
use num_traits::Zero;
use quote::ToTokens;
use syn::{BinOp, Expr, Lit, UnOp};

/// A symbol of a spec: an input of the generated functions, or the
/// polynomial variable (λ).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Symbol {
    pub name: String,
    /// LaTeX for the rendered formulas.
    pub latex: String,
    /// What it is, with the report's equation number.
    pub doc: String,
    /// Declared positive: one may divide by it.
    pub positive: bool,
}

/// The symbols of a spec, in spec order.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct SymbolTable {
    pub symbols: Vec<Symbol>,
}

impl SymbolTable {
    pub fn len(&self) -> usize {
        self.symbols.len()
    }

    pub fn is_empty(&self) -> bool {
        self.symbols.is_empty()
    }

    pub fn id(&self, name: &str) -> Option<usize> {
        self.symbols.iter().position(|s| s.name == name)
    }

    pub fn get(&self, id: usize) -> &Symbol {
        &self.symbols[id]
    }

    pub fn names(&self) -> Vec<&str> {
        self.symbols.iter().map(|s| s.name.as_str()).collect()
    }
}

/// Where an expression sits in its spec, for diagnostics.
pub struct Site<'a> {
    pub file: &'a SourceFile,
    /// Byte offset of the expression's first character in the file.
    pub offset: usize,
    /// The spec entry, e.g. "eq (6), coefficient `B`, printed term 2".
    pub entry: String,
}

impl Site<'_> {
    fn error(&self, at: usize, message: impl Into<String>) -> Diagnostic {
        self.file.at(self.offset + at, self.entry.clone(), message)
    }
}

const ALLOWED: &str = "characters allowed in an expression: letters, digits, `_`, `.`, `+ - * /`, parentheses and spaces";

/// Parse `text` (found at `site`) into a polynomial over `table`'s symbols;
/// every problem is reported to `diags` (and the result is `None`).
pub fn parse_poly(
    text: &str,
    site: &Site<'_>,
    table: &SymbolTable,
    diags: &Diagnostics,
) -> Option<Poly> {
    let expr = match syntax(text, site, table) {
        Ok(expr) => expr,
        Err(d) => {
            diags.push(d);
            return None;
        }
    };
    let before = diags.count();
    let poly = Lower {
        text,
        site,
        table,
        diags,
    }
    .lower(&expr);
    poly.filter(|_| diags.count() == before)
}

/// The expression's syntax tree, or the first problem with its characters,
/// its parentheses or its syntax.
fn syntax(text: &str, site: &Site<'_>, table: &SymbolTable) -> Result<Expr, Diagnostic> {
    if let Some((i, c)) = text
        .char_indices()
        .find(|(_, c)| !(c.is_ascii_alphanumeric() || "_.+-*/() \t".contains(*c)))
    {
        let help = if c == '^' {
            "write a power as `x.powi(n)` (`^` is not a power in Rust)".to_string()
        } else {
            format!(
                "{ALLOWED}; write symbols by their spec names ({})",
                table.names().join(", ")
            )
        };
        return Err(site
            .error(i, format!("unexpected character `{c}` in `{text}`"))
            .with_help(help));
    }
    if text.trim().is_empty() {
        return Err(site.error(0, "empty expression"));
    }
    if let Some((at, message)) = unbalanced(text) {
        return Err(site
            .error(at, format!("{message} in `{text}`"))
            .with_help("close every `(` with a `)`"));
    }
    syn::parse_str(text).map_err(|e| {
        site.error(0, format!("cannot parse `{text}` as an expression: {e}"))
            .with_help("write it as Rust: `a*b`, `a/mu1`, `(a + b)*c`, `lam.powi(2)`")
    })
}

/// The first unbalanced parenthesis, as (byte offset, message).
fn unbalanced(text: &str) -> Option<(usize, String)> {
    let mut open = Vec::new();
    for (i, c) in text.char_indices() {
        match c {
            '(' => open.push(i),
            ')' if open.pop().is_none() => return Some((i, "unmatched `)`".into())),
            _ => {}
        }
    }
    open.first().map(|&i| (i, "unclosed `(`".into()))
}

struct Lower<'a, 'b> {
    text: &'a str,
    site: &'a Site<'b>,
    table: &'a SymbolTable,
    diags: &'a Diagnostics,
}

impl Lower<'_, '_> {
    fn n(&self) -> usize {
        self.table.len()
    }

    /// Byte offset, within the expression text, of the first occurrence of
    /// `needle` as a whole word (0 if not found).
    fn locate(&self, needle: &str) -> usize {
        let bytes = self.text.as_bytes();
        let is_word = |b: u8| b.is_ascii_alphanumeric() || b == b'_';
        let mut from = 0;
        while let Some(i) = self.text[from..].find(needle) {
            let start = from + i;
            let end = start + needle.len();
            let before_ok = start == 0 || !is_word(bytes[start - 1]);
            let after_ok = end >= bytes.len() || !is_word(bytes[end]);
            if before_ok && after_ok {
                return start;
            }
            from = start + needle.len().max(1);
        }
        0
    }

    fn fail(&mut self, needle: &str, message: String, help: Option<String>) -> Option<Poly> {
        let at = self.locate(needle);
        let mut d = self.site.error(at, message);
        d.help = help;
        self.diags.push(d);
        None
    }

    fn lower(&mut self, e: &Expr) -> Option<Poly> {
        match e {
            Expr::Paren(p) => self.lower(&p.expr),
            Expr::Group(g) => self.lower(&g.expr),
            Expr::Lit(l) => self.literal(&l.lit),
            Expr::Path(p) => {
                let name = match p.path.get_ident() {
                    Some(i) => i.to_string(),
                    None => {
                        let s = p.to_token_stream().to_string();
                        return self.fail(&s, format!("`{s}` is not a symbol"), None);
                    }
                };
                match self.table.id(&name) {
                    Some(id) => Some(Poly::symbol(self.n(), id)),
                    None => {
                        let help = format!(
                            "the symbols are: {}; declare a new one in `symbols`",
                            self.table.names().join(", ")
                        );
                        self.fail(&name, format!("unknown symbol `{name}`"), Some(help))
                    }
                }
            }
            Expr::Unary(u) => match u.op {
                UnOp::Neg(_) => self.lower(&u.expr).map(|p| p.neg()),
                _ => self.unsupported(e),
            },
            Expr::Binary(b) => {
                let lhs = self.lower(&b.left);
                let rhs = self.lower(&b.right);
                let (lhs, rhs) = (lhs?, rhs?);
                match b.op {
                    BinOp::Add(_) => Some(lhs.add(&rhs)),
                    BinOp::Sub(_) => Some(lhs.sub(&rhs)),
                    BinOp::Mul(_) => Some(lhs.mul(&rhs)),
                    BinOp::Div(_) => self.divide(&lhs, &rhs, &b.right),
                    _ => self.unsupported(e),
                }
            }
            Expr::MethodCall(m) if m.method == "powi" && m.args.len() == 1 => {
                let base = self.lower(&m.receiver)?;
                let k = match &m.args[0] {
                    Expr::Lit(syn::ExprLit {
                        lit: Lit::Int(i), ..
                    }) => i.base10_parse::<u32>().ok(),
                    _ => None,
                };
                match k {
                    Some(k) if k <= 16 => Some(base.pow(k)),
                    _ => {
                        let s = m.to_token_stream().to_string();
                        self.fail(
                            "powi",
                            format!("`{s}`: the power must be an integer literal from 0 to 16"),
                            None,
                        )
                    }
                }
            }
            _ => self.unsupported(e),
        }
    }

    fn literal(&mut self, lit: &Lit) -> Option<Poly> {
        let digits = match lit {
            Lit::Int(i) if i.suffix().is_empty() => i.base10_digits().to_string(),
            Lit::Float(f) if f.suffix().is_empty() => f.base10_digits().to_string(),
            _ => {
                let s = lit.to_token_stream().to_string();
                return self.fail(
                    &s,
                    format!("`{s}` is not a plain decimal number"),
                    Some("write numbers without suffixes: `2`, `0.5`, `1e-3`".into()),
                );
            }
        };
        match rational_from_decimal(&digits) {
            Some(r) => Some(Poly::constant(self.n(), r)),
            None => self.fail(&digits, format!("`{digits}` is not a decimal number"), None),
        }
    }

    fn divide(&mut self, lhs: &Poly, rhs: &Poly, rhs_expr: &Expr) -> Option<Poly> {
        let shown = rhs_expr.to_token_stream().to_string();
        let Some((m, c)) = rhs.as_single_term() else {
            let help =
                "divide only by a number or by a product of symbols declared `positive = true`";
            let msg = if rhs.is_zero() {
                format!("division by zero (`{shown}`)")
            } else {
                format!("division by `{shown}`, which is a sum: the result is not a polynomial")
            };
            return self.fail(&first_word(&shown), msg, Some(help.into()));
        };
        if c.is_zero() {
            return self.fail(&shown, format!("division by zero (`{shown}`)"), None);
        }
        let not_positive: Vec<&str> = m
            .factors()
            .map(|(id, _)| self.table.get(id))
            .filter(|s| !s.positive)
            .map(|s| s.name.as_str())
            .collect();
        if let Some(first) = not_positive.first() {
            let name = first.to_string();
            return self.fail(
                &name,
                format!("division by `{name}`, which is not declared positive and may be zero"),
                Some(format!(
                    "declare `positive = true` on `{name}` in `symbols` if it can never be zero"
                )),
            );
        }
        Some(lhs.div_term(m, c))
    }

    fn unsupported(&mut self, e: &Expr) -> Option<Poly> {
        let s = e.to_token_stream().to_string();
        self.fail(
            &first_word(&s),
            format!("unsupported expression `{s}`"),
            Some(format!("{ALLOWED}; powers are written `x.powi(n)`")),
        )
    }
}

fn first_word(s: &str) -> String {
    s.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .find(|w| !w.is_empty())
        .unwrap_or("")
        .to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table(names: &[(&str, bool)]) -> SymbolTable {
        SymbolTable {
            symbols: names
                .iter()
                .map(|(n, p)| Symbol {
                    name: n.to_string(),
                    latex: n.to_string(),
                    doc: String::new(),
                    positive: *p,
                })
                .collect(),
        }
    }

    fn parse(text: &str, t: &SymbolTable) -> Result<Poly, crate::diag::SpecErrors> {
        let file = SourceFile::new("t.toml", format!("e = \"{text}\"\n"));
        let site = Site {
            file: &file,
            offset: 5,
            entry: "test".into(),
        };
        let diags = Diagnostics::new();
        let poly = parse_poly(text, &site, t, &diags);
        diags.finish(poly, "t.toml")
    }

    #[test]
    fn expressions_expand_exactly() {
        let t = table(&[("x", false), ("mu", true), ("lam", false)]);
        let p = parse("(x/mu - 1)*(lam + 0.5) + lam.powi(2)", &t).unwrap();
        // x·lam/mu + x/(2 mu) − lam − 1/2 + lam²
        assert_eq!(p.len(), 5);
        let v = [3.0, 4.0, 2.0];
        assert!((p.eval(&v) - ((0.75 - 1.0) * 2.5 + 4.0)).abs() < 1e-15);
    }

    #[test]
    fn unknown_symbols_are_located() {
        let t = table(&[("x", false)]);
        let e = parse("x + yy*2", &t).unwrap_err();
        let d = &e.0[0];
        assert_eq!((d.line, d.column), (1, 10));
        assert!(d.message.contains("unknown symbol `yy`"), "{d}");
    }

    #[test]
    fn division_needs_a_positive_monomial() {
        let t = table(&[("x", false), ("y", false), ("mu", true)]);
        assert!(parse("x/mu", &t).is_ok());
        let e = parse("x/y", &t).unwrap_err();
        assert!(e.0[0].message.contains("not declared positive"), "{e}");
        let e = parse("x/(mu + 1)", &t).unwrap_err();
        assert!(e.0[0].message.contains("is a sum"), "{e}");
    }

    #[test]
    fn foreign_characters_and_bad_syntax_are_reported() {
        let t = table(&[("x", false)]);
        let e = parse("x θ", &t).unwrap_err();
        assert!(e.0[0].message.contains("unexpected character `θ`"), "{e}");
        let e = parse("(x + 1", &t).unwrap_err();
        assert!(e.0[0].message.contains("unclosed `(`"), "{e}");
        let e = parse("x + x x", &t).unwrap_err();
        assert!(e.0[0].message.contains("cannot parse"), "{e}");
        let e = parse("x + * x", &t).unwrap_err();
        assert!(
            e.0[0].message.contains("unsupported expression `* x`"),
            "{e}"
        );
        let e = parse("x ^ 2", &t).unwrap_err();
        assert!(e.0[0].message.contains("unexpected character `^`"), "{e}");
    }
}
