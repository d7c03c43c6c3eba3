//! From the typed input ([`super::ast`]) to the verified model
//! ([`super::model`]), one node at a time: the symbols, the determinant, the
//! printed coefficients, the errata; then the determinant's expansion, the
//! powers it needs, the errata attached to their terms, and each coefficient
//! compared with the expansion. Every problem is reported with its file, line
//! and entry; a stage that needs the previous one whole stops when it is not.

use super::ast;
use super::model::{Coefficient, Determinant, Erratum, Expression, QuarticModel, Reading};
use crate::diag::Diagnostic;
use crate::expr::{Symbol, SymbolTable};
use crate::poly::Poly;
use crate::render;
use crate::spec::{Context, is_identifier, squash};
use num_traits::Zero;
use std::collections::BTreeMap;
use std::ops::Range;
use toml::Spanned;

/// A coefficient being verified, with the spans its diagnostics point at.
struct Draft {
    coef: Coefficient,
    span: Range<usize>,
    power_span: Range<usize>,
}

/// An erratum whose two forms parsed.
struct ParsedErratum<'s> {
    raw: &'s ast::Erratum,
    printed: Expression,
    corrected: Expression,
}

/// Validate a spec into its model (`None` when a problem was reported).
pub fn model(cx: &Context<'_>, spec: ast::Spec) -> Option<QuarticModel> {
    let table = symbol_table(cx, &spec)?;
    let det = spec.determinant.get_ref();
    let entries = determinant_entries(cx, &spec.determinant, &table);
    let readings = readings(cx, det);
    let mut drafts: Vec<Draft> = (spec.coefficients.get_ref().iter())
        .filter_map(|(name, c)| printed_coefficient(cx, name, c, &table))
        .collect();
    let errata: Vec<ParsedErratum<'_>> = (spec.errata.iter())
        .filter_map(|e| parsed_erratum(cx, e.get_ref(), &table))
        .collect();
    if cx.has_errors() {
        return None;
    }
    let (expansion, degree) = expand_determinant(cx, &spec.determinant, &entries, &table)?;
    let by_power = claim_powers(cx, &drafts, degree, &table, &spec.coefficients.span());
    if cx.has_errors() {
        return None;
    }
    for e in errata {
        attach_erratum(cx, &mut drafts, e, &by_power);
    }
    let var = table.len() - 1;
    for d in &mut drafts {
        d.coef.expansion = expansion.coefficient_of_power(var, d.coef.power as i32);
        verify(cx, d, &table);
    }
    if cx.has_errors() {
        return None;
    }
    let mut coefficients: Vec<Coefficient> = drafts.into_iter().map(|d| d.coef).collect();
    coefficients.sort_by_key(|c| std::cmp::Reverse(c.power));
    Some(QuarticModel {
        file: cx.file().name.clone(),
        title: spec.title,
        source: spec.source,
        table,
        determinant: Determinant {
            equation: det.equation.clone(),
            entries,
            readings,
            expansion,
        },
        coefficients,
    })
}

/// The symbol table: the inputs in spec order, the variable last.
fn symbol_table(cx: &Context<'_>, spec: &ast::Spec) -> Option<SymbolTable> {
    let mut table = SymbolTable::default();
    let all = (spec.symbols.iter().map(|s| (s, "symbols")))
        .chain(std::iter::once((&spec.variable, "variable")));
    for (s, what) in all {
        let r = s.get_ref();
        let name = r.name.get_ref();
        let entry = format!("{what} `{name}`");
        if !is_identifier(name) {
            cx.error(
                &r.name.span(),
                entry,
                format!("`{name}` is not a valid Rust identifier; symbols become field and variable names"),
            );
        } else if table.id(name).is_some() {
            cx.error(
                &r.name.span(),
                entry,
                format!("duplicate entry: the symbol `{name}` is declared twice"),
            );
        } else {
            table.symbols.push(Symbol {
                name: name.clone(),
                latex: r.latex.clone(),
                doc: r.doc.clone(),
                positive: r.positive,
            });
        }
    }
    (!cx.has_errors()).then_some(table)
}

/// The determinant's entries, parsed; it must be square.
fn determinant_entries(
    cx: &Context<'_>,
    det: &Spanned<ast::Determinant>,
    table: &SymbolTable,
) -> Vec<Vec<Expression>> {
    let eq = &det.get_ref().equation;
    let rows = &det.get_ref().rows;
    let size = rows.len();
    if size == 0 {
        cx.error(
            &det.span(),
            format!("eq ({eq}), determinant"),
            "the determinant has no rows",
        );
    }
    let mut entries = Vec::new();
    for (r, row) in rows.iter().enumerate() {
        if row.get_ref().len() != size {
            cx.error(
                &row.span(),
                format!("eq ({eq}), determinant row {}", r + 1),
                format!(
                    "row {} has {} entries; a determinant of {size} rows needs {size}",
                    r + 1,
                    row.get_ref().len()
                ),
            );
            continue;
        }
        let parsed = (row.get_ref().iter().enumerate())
            .filter_map(|(c, cell)| {
                let entry = format!("eq ({eq}), determinant entry ({}, {})", r + 1, c + 1);
                cx.expression(cell, entry, table)
            })
            .collect();
        entries.push(parsed);
    }
    entries
}

/// The notes on how entries were read; each must name an entry.
fn readings(cx: &Context<'_>, det: &ast::Determinant) -> Vec<Reading> {
    let size = det.rows.len();
    let mut readings = Vec::new();
    for note in &det.notes {
        let [r, c] = note.get_ref().entry;
        if r == 0 || c == 0 || r > size || c > size {
            cx.error(
                &note.span(),
                format!("eq ({}), determinant note", det.equation),
                format!("entry [{r}, {c}] is outside the {size}×{size} determinant (rows and columns count from 1)"),
            );
        }
        readings.push(Reading {
            entry: [r, c],
            printed: note.get_ref().printed.clone(),
            reason: note.get_ref().reason.clone(),
            line: cx.line(&note.span()),
        });
    }
    readings
}

/// A coefficient's printed terms, parsed; none may contain the variable.
fn printed_coefficient(
    cx: &Context<'_>,
    name: &str,
    c: &Spanned<ast::Coefficient>,
    table: &SymbolTable,
) -> Option<Draft> {
    let raw = c.get_ref();
    let var = table.len() - 1;
    let entry = format!("eq ({}), coefficient `{name}`", raw.equation);
    if !is_identifier(&format!("coef_{}", name.to_lowercase())) {
        let message = format!(
            "`{name}` cannot name a coefficient: coefficients become variable names (letters, digits, `_`)"
        );
        cx.error(&c.span(), &entry, message);
    }
    if raw.printed.is_empty() {
        cx.error(
            &c.span(),
            &entry,
            "no printed terms; transcribe the coefficient as printed (a zero coefficient is `printed = [\"0\"]`)",
        );
    }
    let mut printed = Vec::new();
    for (i, t) in raw.printed.iter().enumerate() {
        let term = format!("{entry}, printed term {}", i + 1);
        let Some(e) = cx.expression(t, &term, table) else {
            continue;
        };
        if e.poly.mentions(var) {
            let var_name = &table.get(var).name;
            cx.error(
                &t.span(),
                term,
                format!("a coefficient may not contain the variable `{var_name}`"),
            );
        }
        printed.push(e);
    }
    let Ok(power) = usize::try_from(*raw.power.get_ref()) else {
        let message = format!(
            "power {} is negative: a coefficient multiplies a power 0, 1, 2, … of the variable",
            raw.power.get_ref()
        );
        cx.error(&raw.power.span(), entry, message);
        return None;
    };
    let coef = Coefficient {
        name: name.to_string(),
        power,
        equation: raw.equation.clone(),
        printed,
        errata: Vec::new(),
        expansion: Poly::zero(table.len()),
    };
    Some(Draft {
        coef,
        span: c.span(),
        power_span: raw.power.span(),
    })
}

/// An erratum's printed and corrected forms, parsed.
fn parsed_erratum<'s>(
    cx: &Context<'_>,
    raw: &'s ast::Erratum,
    table: &SymbolTable,
) -> Option<ParsedErratum<'s>> {
    let entry = format!("erratum to coefficient `{}`", raw.coefficient.get_ref());
    let printed = cx.expression(&raw.printed, format!("{entry}, printed form"), table);
    let corrected = cx.expression(&raw.corrected, format!("{entry}, corrected form"), table);
    Some(ParsedErratum {
        raw,
        printed: printed?,
        corrected: corrected?,
    })
}

/// The determinant, expanded exactly, and its degree in the variable: a
/// polynomial (no negative power) of degree one at least.
fn expand_determinant(
    cx: &Context<'_>,
    det: &Spanned<ast::Determinant>,
    entries: &[Vec<Expression>],
    table: &SymbolTable,
) -> Option<(Poly, usize)> {
    let var = table.len() - 1;
    let var_name = &table.get(var).name;
    let expansion = determinant(entries);
    let entry = format!("eq ({}), determinant", det.get_ref().equation);
    if expansion.low_degree_in(var).is_some_and(|low| low < 0) {
        let message = format!("the expansion has negative powers of `{var_name}`");
        cx.error(&det.span(), entry, message);
        return None;
    }
    match expansion
        .degree_in(var)
        .and_then(|d| usize::try_from(d).ok())
    {
        Some(degree) if degree >= 1 => Some((expansion, degree)),
        _ => {
            let message = format!(
                "the expansion does not contain `{var_name}`: it is not a characteristic polynomial"
            );
            cx.error(&det.span(), entry, message);
            None
        }
    }
}

/// Each power of the variable, 0 to the degree, claimed by exactly one
/// coefficient: the names by power.
fn claim_powers(
    cx: &Context<'_>,
    drafts: &[Draft],
    degree: usize,
    table: &SymbolTable,
    coefficients_span: &Range<usize>,
) -> BTreeMap<usize, String> {
    let var_name = &table.get(table.len() - 1).name;
    let mut by_power: BTreeMap<usize, String> = BTreeMap::new();
    for Draft {
        coef: c,
        span,
        power_span,
    } in drafts
    {
        let entry = format!("eq ({}), coefficient `{}`", c.equation, c.name);
        if c.power > degree {
            cx.error(
                power_span,
                entry,
                format!(
                    "power {} exceeds the degree {degree} of the determinant's expansion in `{var_name}`",
                    c.power
                ),
            );
        } else if let Some(other) = by_power.get(&c.power) {
            let message = format!(
                "duplicate entry: coefficients `{other}` and `{}` both claim the power {var_name}^{}",
                c.name, c.power
            );
            let help =
                "each power of the variable has exactly one coefficient; remove or renumber one";
            cx.push(cx.at(span, entry, message).with_help(help));
        } else {
            by_power.insert(c.power, c.name.clone());
        }
    }
    for p in (0..=degree).rev().filter(|p| !by_power.contains_key(p)) {
        let message = format!(
            "missing coefficient: the determinant expands to degree {degree} in `{var_name}`, and no coefficient has `power = {p}`"
        );
        let help =
            format!("add a `[coefficients.X]` table with `power = {p}` and its printed terms");
        cx.push(
            cx.at(coefficients_span, "coefficients", message)
                .with_help(help),
        );
    }
    by_power
}

/// Attach an erratum to the printed term it corrects; reject it when it
/// names no coefficient or term, duplicates another, or corrects nothing.
fn attach_erratum(
    cx: &Context<'_>,
    drafts: &mut [Draft],
    e: ParsedErratum<'_>,
    by_power: &BTreeMap<usize, String>,
) {
    let raw = e.raw;
    let coef_name = raw.coefficient.get_ref();
    let entry = format!(
        "erratum to coefficient `{coef_name}` (line {})",
        cx.line(&raw.printed.span())
    );
    let Some(coef) = drafts
        .iter_mut()
        .map(|d| &mut d.coef)
        .find(|c| &c.name == coef_name)
    else {
        let names: Vec<&str> = by_power.values().map(String::as_str).collect();
        let message = format!(
            "there is no coefficient `{coef_name}`; the coefficients are {}",
            names.join(", ")
        );
        cx.error(&raw.coefficient.span(), entry, message);
        return;
    };
    let key = squash(&e.printed.text);
    let Some(term) = coef.printed.iter().position(|t| squash(&t.text) == key) else {
        let terms: Vec<String> = coef
            .printed
            .iter()
            .map(|t| format!("`{}`", t.text))
            .collect();
        let message = format!(
            "stale erratum: coefficient `{coef_name}` has no printed term `{}` (its terms are {})",
            e.printed.text,
            terms.join(", ")
        );
        let help = "if the transcription was corrected in place, restore the printed form or remove this erratum";
        cx.push(cx.at(&raw.printed.span(), entry, message).with_help(help));
        return;
    };
    if coef.errata.iter().any(|x| x.term == term) {
        let message = format!(
            "duplicate entry: printed term {} `{}` already has an erratum",
            term + 1,
            e.printed.text
        );
        cx.error(&raw.printed.span(), entry, message);
    } else if e.printed.poly == e.corrected.poly {
        let message = format!(
            "stale erratum: the printed form `{}` and the corrected form `{}` are equal, so it corrects nothing",
            e.printed.text, e.corrected.text
        );
        cx.push(
            cx.at(&raw.corrected.span(), entry, message)
                .with_help("remove this erratum"),
        );
    } else {
        coef.errata.push(Erratum {
            coefficient: coef_name.clone(),
            term,
            printed: e.printed,
            corrected: e.corrected,
            reason: raw.reason.clone(),
        });
    }
}

/// The coefficient, after its errata, must equal its part of the expansion.
fn verify(cx: &Context<'_>, d: &Draft, table: &SymbolTable) {
    let corrected =
        (d.coef.corrected_terms().iter()).fold(Poly::zero(table.len()), |acc, t| acc.add(&t.poly));
    let diff = corrected.sub(&d.coef.expansion);
    if !diff.is_zero() {
        cx.push(disagreement(cx, &d.coef, &diff, table, &d.span));
    }
}

/// The error for a coefficient that disagrees with the expansion, naming the
/// printed terms that carry the offending monomials.
fn disagreement(
    cx: &Context<'_>,
    coef: &Coefficient,
    diff: &Poly,
    table: &SymbolTable,
    span: &Range<usize>,
) -> Diagnostic {
    let corrected = coef.corrected_terms();
    let mut culprits: Vec<usize> = Vec::new();
    for (m, _) in diff.terms() {
        for (i, t) in corrected.iter().enumerate() {
            if !t.poly.coefficient(m).is_zero() && !culprits.contains(&i) {
                culprits.push(i);
            }
        }
    }
    culprits.sort_unstable();
    let entry = format!("eq ({}), coefficient `{}`", coef.equation, coef.name);
    let named: Vec<String> = (culprits.iter())
        .map(|&i| {
            format!(
                "term {} `{}` (line {})",
                i + 1,
                corrected[i].text,
                corrected[i].line
            )
        })
        .collect();
    let mut message = format!(
        "the printed coefficient disagrees with the expansion of the determinant, and no erratum declares it: printed − expansion = {}",
        render::poly_text(diff, table)
    );
    if !named.is_empty() {
        message.push_str(&format!(
            "; the differing monomials occur in {}",
            named.join(", ")
        ));
    }
    let d = match culprits.first() {
        // At the line of the first offending term.
        Some(&i) => Diagnostic {
            file: cx.file().name.clone(),
            line: corrected[i].line,
            column: 1,
            entry,
            message,
            help: None,
        },
        None => cx.at(span, entry, message),
    };
    d.with_help(format!(
        "if the transcription is faithful, the report is wrong here: declare it as an [[errata]] entry with coefficient = \"{}\", printed = the term as printed, corrected = the right term, and a one-line reason",
        coef.name
    ))
}

/// The determinant of a square matrix of polynomials, by expansion along
/// the first row (exact).
pub fn determinant(m: &[Vec<Expression>]) -> Poly {
    let polys: Vec<Vec<Poly>> = m
        .iter()
        .map(|r| r.iter().map(|e| e.poly.clone()).collect())
        .collect();
    det_of(&polys)
}

fn det_of(m: &[Vec<Poly>]) -> Poly {
    match m.len() {
        0 => Poly::zero(0),
        1 => m[0][0].clone(),
        size => {
            let n = m[0][0].arity();
            let mut acc = Poly::zero(n);
            for j in 0..size {
                let minor: Vec<Vec<Poly>> = m[1..]
                    .iter()
                    .map(|row| {
                        row.iter()
                            .enumerate()
                            .filter(|(k, _)| *k != j)
                            .map(|(_, p)| p.clone())
                            .collect()
                    })
                    .collect();
                let term = m[0][j].mul(&det_of(&minor));
                acc = if j % 2 == 0 {
                    acc.add(&term)
                } else {
                    acc.sub(&term)
                };
            }
            acc
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::QuarticModel;
    use crate::spec::SourceFile;

    const TOY: &str = r#"
title = "toy"
source = "tests"
symbols = [
  { name = "c", latex = "c", doc = "damping" },
  { name = "k", latex = "k", doc = "stiffness", positive = true },
]
[variable]
name = "s"
latex = "s"
doc = "Laplace variable"
[determinant]
equation = "1"
rows = [["s + c", "k"], ["-1", "s"]]
[coefficients.A]
power = 2
equation = "2"
printed = ["1"]
[coefficients.B]
power = POWER_B
equation = "2"
printed = ["c"]
[coefficients.C]
power = 0
equation = "2"
printed = ["k"]
"#;

    fn load(power_b: &str) -> Result<QuarticModel, crate::SpecErrors> {
        let text = TOY.replace("POWER_B", power_b);
        QuarticModel::load(&SourceFile::new("toy.toml", text))
    }

    #[test]
    fn a_determinant_by_hand_is_verified_and_ordered() {
        // |s + c, k; −1, s| = s² + c·s + k.
        let m = load("1").unwrap_or_else(|e| panic!("{e}"));
        let powers: Vec<usize> = m.coefficients.iter().map(|c| c.power).collect();
        assert_eq!(powers, [2, 1, 0]);
        let v = [0.3, 2.0, 0.0];
        let values: Vec<f64> = m
            .coefficients
            .iter()
            .map(|c| c.expansion.eval(&v))
            .collect();
        assert_eq!(values, [1.0, 0.3, 2.0]);
    }

    #[test]
    fn a_negative_power_is_named_at_its_line() {
        let e = load("-1").unwrap_err();
        assert_eq!(e.0.len(), 1, "{e}");
        let d = &e.0[0];
        assert_eq!((d.file.as_str(), d.line), ("toy.toml", 20));
        assert_eq!(d.entry, "eq (2), coefficient `B`");
        assert!(d.message.contains("power -1 is negative"), "{d}");
    }
}
