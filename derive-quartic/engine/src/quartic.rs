//! The stability-quartic spec: a determinant whose expansion in the variable
//! gives the coefficients, and the coefficients as a report printed them,
//! term by term, with declared errata.
//!
//! Loading a spec parses it, expands the determinant exactly, and compares
//! each printed coefficient (after its errata) with the expansion, term by
//! term. Every disagreement that no erratum declares, and every erratum that
//! no longer corrects anything, is a [`Diagnostic`] naming the file, line and
//! entry.

use crate::diag::{Diagnostic, Diagnostics, SourceFile};
use crate::expr::{Site, Symbol, SymbolTable, parse_poly};
use crate::poly::Poly;
use crate::render;
use num_traits::Zero;
use serde::Deserialize;
use std::collections::BTreeMap;
use std::ops::Range;
use toml::Spanned;

// ---------------------------------------------------------------- raw form

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSpec {
    title: String,
    source: String,
    symbols: Vec<Spanned<RawSymbol>>,
    variable: Spanned<RawSymbol>,
    determinant: Spanned<RawDeterminant>,
    coefficients: Spanned<BTreeMap<String, Spanned<RawCoefficient>>>,
    #[serde(default)]
    errata: Vec<Spanned<RawErratum>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSymbol {
    name: Spanned<String>,
    latex: String,
    doc: String,
    #[serde(default)]
    positive: bool,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawDeterminant {
    equation: String,
    rows: Vec<Spanned<Vec<Spanned<String>>>>,
    #[serde(default)]
    notes: Vec<Spanned<RawNote>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawNote {
    entry: [usize; 2],
    printed: String,
    reason: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawCoefficient {
    power: Spanned<i64>,
    equation: String,
    printed: Vec<Spanned<String>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawErratum {
    coefficient: Spanned<String>,
    printed: Spanned<String>,
    corrected: Spanned<String>,
    reason: String,
}

// ------------------------------------------------------------ validated form

/// An expression of the spec, with its text, its line and its expansion.
#[derive(Clone, Debug)]
pub struct Expression {
    pub text: String,
    pub line: usize,
    pub poly: Poly,
}

/// A note on how a determinant entry was read from the printed report.
#[derive(Clone, Debug)]
pub struct Reading {
    /// 1-based row and column.
    pub entry: [usize; 2],
    pub printed: String,
    pub reason: String,
    pub line: usize,
}

/// The determinant whose vanishing is the characteristic equation.
#[derive(Clone, Debug)]
pub struct Determinant {
    pub equation: String,
    pub entries: Vec<Vec<Expression>>,
    pub readings: Vec<Reading>,
    /// The determinant, expanded exactly.
    pub expansion: Poly,
}

/// An erratum: a printed term of a coefficient, and what it should be.
#[derive(Clone, Debug)]
pub struct Erratum {
    pub coefficient: String,
    /// Index of the corrected term in the coefficient's printed terms.
    pub term: usize,
    pub printed: Expression,
    pub corrected: Expression,
    pub reason: String,
}

impl Erratum {
    /// printed − corrected: what the misprint adds to the coefficient.
    pub fn difference(&self) -> Poly {
        self.printed.poly.sub(&self.corrected.poly)
    }
}

/// A coefficient of the characteristic polynomial.
#[derive(Clone, Debug)]
pub struct Coefficient {
    /// The report's name, e.g. `B`.
    pub name: String,
    /// The power of the variable it multiplies.
    pub power: usize,
    pub equation: String,
    /// The terms as printed.
    pub printed: Vec<Expression>,
    /// The errata declared against this coefficient.
    pub errata: Vec<Erratum>,
    /// The coefficient from the determinant's expansion (= the printed terms
    /// after the errata, verified).
    pub expansion: Poly,
}

impl Coefficient {
    /// The printed terms with the errata applied.
    pub fn corrected_terms(&self) -> Vec<&Expression> {
        self.printed
            .iter()
            .enumerate()
            .map(|(i, t)| {
                self.errata
                    .iter()
                    .find(|e| e.term == i)
                    .map_or(t, |e| &e.corrected)
            })
            .collect()
    }

    /// The sum of the terms exactly as printed (errata not applied).
    pub fn printed_sum(&self, n: usize) -> Poly {
        self.printed
            .iter()
            .fold(Poly::zero(n), |acc, t| acc.add(&t.poly))
    }
}

/// A verified quartic (or any-degree characteristic polynomial) spec.
#[derive(Clone, Debug)]
pub struct QuarticModel {
    pub file: String,
    pub title: String,
    pub source: String,
    /// Inputs in spec order, then the variable last.
    pub table: SymbolTable,
    pub determinant: Determinant,
    /// Ordered by descending power.
    pub coefficients: Vec<Coefficient>,
}

impl QuarticModel {
    /// Id of the polynomial variable (λ).
    pub fn variable(&self) -> usize {
        self.table.len() - 1
    }

    /// The inputs of the generated functions (all symbols but the variable).
    pub fn inputs(&self) -> &[Symbol] {
        &self.table.symbols[..self.table.len() - 1]
    }

    /// Load, expand and verify a spec. All problems are reported together.
    pub fn load(file: &SourceFile) -> Result<QuarticModel, Diagnostics> {
        let raw: RawSpec = toml::from_str(&file.text).map_err(|e| toml_error(file, &e))?;
        let mut diags = Diagnostics::default();

        let table = symbol_table(file, &raw, &mut diags);
        if !diags.is_empty() {
            return Err(diags);
        }
        let n = table.len();
        let var = n - 1;
        let parse = |s: &Spanned<String>, entry: String, diags: &mut Diagnostics| {
            let site = Site {
                file,
                offset: file.string_content_start(&s.span()),
                entry,
            };
            match parse_poly(s.get_ref(), &site, &table) {
                Ok(poly) => Some(Expression {
                    text: s.get_ref().clone(),
                    line: file.position(s.span().start).0,
                    poly,
                }),
                Err(d) => {
                    diags.0.extend(d.0);
                    None
                }
            }
        };

        // The determinant.
        let det_raw = raw.determinant.get_ref();
        let eq_det = det_raw.equation.clone();
        let size = det_raw.rows.len();
        let mut entries = Vec::new();
        if size == 0 {
            diags.push(file.at_span(
                &raw.determinant.span(),
                format!("eq ({eq_det}), determinant"),
                "the determinant has no rows",
            ));
        }
        for (r, row) in det_raw.rows.iter().enumerate() {
            if row.get_ref().len() != size {
                diags.push(file.at_span(
                    &row.span(),
                    format!("eq ({eq_det}), determinant row {}", r + 1),
                    format!(
                        "row {} has {} entries; a determinant of {size} rows needs {size}",
                        r + 1,
                        row.get_ref().len()
                    ),
                ));
                continue;
            }
            let mut parsed = Vec::new();
            for (c, cell) in row.get_ref().iter().enumerate() {
                let entry = format!("eq ({eq_det}), determinant entry ({}, {})", r + 1, c + 1);
                if let Some(e) = parse(cell, entry, &mut diags) {
                    parsed.push(e);
                }
            }
            entries.push(parsed);
        }
        let mut readings = Vec::new();
        for note in &det_raw.notes {
            let [r, c] = note.get_ref().entry;
            if r == 0 || c == 0 || r > size || c > size {
                diags.push(file.at_span(
                    &note.span(),
                    format!("eq ({eq_det}), determinant note"),
                    format!("entry [{r}, {c}] is outside the {size}×{size} determinant (rows and columns count from 1)"),
                ));
            }
            readings.push(Reading {
                entry: [r, c],
                printed: note.get_ref().printed.clone(),
                reason: note.get_ref().reason.clone(),
                line: file.position(note.span().start).0,
            });
        }

        // The printed coefficients.
        let mut coefficients: Vec<(Coefficient, Range<usize>, Range<usize>)> = Vec::new();
        for (name, c) in raw.coefficients.get_ref() {
            let cr = c.get_ref();
            let mut printed = Vec::new();
            if cr.printed.is_empty() {
                diags.push(file.at_span(
                    &c.span(),
                    format!("eq ({}), coefficient `{name}`", cr.equation),
                    "no printed terms; transcribe the coefficient as printed (a zero coefficient is `printed = [\"0\"]`)",
                ));
            }
            for (i, t) in cr.printed.iter().enumerate() {
                let entry = format!(
                    "eq ({}), coefficient `{name}`, printed term {}",
                    cr.equation,
                    i + 1
                );
                if let Some(e) = parse(t, entry, &mut diags) {
                    if e.poly.mentions(var) {
                        diags.push(file.at_span(
                            &t.span(),
                            format!(
                                "eq ({}), coefficient `{name}`, printed term {}",
                                cr.equation,
                                i + 1
                            ),
                            format!(
                                "a coefficient may not contain the variable `{}`",
                                table.get(var).name
                            ),
                        ));
                    }
                    printed.push(e);
                }
            }
            let power = *cr.power.get_ref();
            coefficients.push((
                Coefficient {
                    name: name.clone(),
                    power: usize::try_from(power).unwrap_or(usize::MAX),
                    equation: cr.equation.clone(),
                    printed,
                    errata: Vec::new(),
                    expansion: Poly::zero(n),
                },
                c.span(),
                cr.power.span(),
            ));
        }

        // The errata, parsed.
        let mut errata = Vec::new();
        for e in &raw.errata {
            let er = e.get_ref();
            let coef = er.coefficient.get_ref();
            let entry = format!("erratum to coefficient `{coef}`");
            let printed = parse(&er.printed, format!("{entry}, printed form"), &mut diags);
            let corrected = parse(
                &er.corrected,
                format!("{entry}, corrected form"),
                &mut diags,
            );
            if let (Some(p), Some(c)) = (printed, corrected) {
                errata.push((er, p, c));
            }
        }
        if !diags.is_empty() {
            return Err(diags);
        }

        // Expand the determinant.
        let expansion = determinant(&entries);
        let degree = expansion.degree_in(var).unwrap_or(0);
        let low = expansion.low_degree_in(var).unwrap_or(0);
        let det_entry = format!("eq ({eq_det}), determinant");
        if low < 0 {
            diags.push(file.at_span(
                &raw.determinant.span(),
                det_entry.clone(),
                format!(
                    "the expansion has negative powers of `{}`",
                    table.get(var).name
                ),
            ));
            return Err(diags);
        }
        if degree < 1 {
            diags.push(file.at_span(
                &raw.determinant.span(),
                det_entry,
                format!(
                    "the expansion does not contain `{}`: it is not a characteristic polynomial",
                    table.get(var).name
                ),
            ));
            return Err(diags);
        }
        let degree = degree as usize;

        // Each power of the variable claimed exactly once.
        let var_name = table.get(var).name.clone();
        let mut by_power: BTreeMap<usize, String> = BTreeMap::new();
        for (c, span, power_span) in &coefficients {
            let entry = format!("eq ({}), coefficient `{}`", c.equation, c.name);
            if c.power > degree {
                diags.push(file.at_span(
                    power_span,
                    entry,
                    format!(
                        "power {} exceeds the degree {degree} of the determinant's expansion in `{var_name}`",
                        if c.power == usize::MAX { "(negative)".to_string() } else { c.power.to_string() }
                    ),
                ));
            } else if let Some(other) = by_power.get(&c.power) {
                diags.push(file.at_span(
                    span,
                    entry,
                    format!(
                        "duplicate entry: coefficients `{other}` and `{}` both claim the power {var_name}^{}",
                        c.name, c.power
                    ),
                ).with_help("each power of the variable has exactly one coefficient; remove or renumber one"));
            } else {
                by_power.insert(c.power, c.name.clone());
            }
        }
        for p in (0..=degree).rev() {
            if !by_power.contains_key(&p) {
                diags.push(file.at_span(
                    &raw.coefficients.span(),
                    "coefficients",
                    format!(
                        "missing coefficient: the determinant expands to degree {degree} in `{var_name}`, and no coefficient has `power = {p}`"
                    ),
                ).with_help(format!("add a `[coefficients.X]` table with `power = {p}` and its printed terms")));
            }
        }
        if !diags.is_empty() {
            return Err(diags);
        }

        // Attach errata to their terms; reject the stale ones.
        for (er, printed, corrected) in errata {
            let coef_name = er.coefficient.get_ref();
            let line = file.position(er.printed.span().start).0;
            let entry = format!("erratum to coefficient `{coef_name}` (line {line})");
            let Some((coef, _, _)) = coefficients
                .iter_mut()
                .find(|(c, _, _)| &c.name == coef_name)
            else {
                diags.push(file.at_span(
                    &er.coefficient.span(),
                    entry,
                    format!(
                        "there is no coefficient `{coef_name}`; the coefficients are {}",
                        by_power.values().cloned().collect::<Vec<_>>().join(", ")
                    ),
                ));
                continue;
            };
            let key = squash(&printed.text);
            let Some(term) = coef.printed.iter().position(|t| squash(&t.text) == key) else {
                diags.push(file.at_span(
                    &er.printed.span(),
                    entry,
                    format!(
                        "stale erratum: coefficient `{coef_name}` has no printed term `{}` (its terms are {})",
                        printed.text,
                        coef.printed.iter().map(|t| format!("`{}`", t.text)).collect::<Vec<_>>().join(", ")
                    ),
                ).with_help("if the transcription was corrected in place, restore the printed form or remove this erratum"));
                continue;
            };
            if coef.errata.iter().any(|e| e.term == term) {
                diags.push(file.at_span(
                    &er.printed.span(),
                    entry,
                    format!(
                        "duplicate entry: printed term {} `{}` already has an erratum",
                        term + 1,
                        printed.text
                    ),
                ));
                continue;
            }
            if printed.poly == corrected.poly {
                diags.push(file.at_span(
                    &er.corrected.span(),
                    entry,
                    format!(
                        "stale erratum: the printed form `{}` and the corrected form `{}` are equal, so it corrects nothing",
                        printed.text, corrected.text
                    ),
                ).with_help("remove this erratum"));
                continue;
            }
            coef.errata.push(Erratum {
                coefficient: coef_name.clone(),
                term,
                printed,
                corrected,
                reason: er.reason.clone(),
            });
        }

        // Compare each coefficient, after its errata, with the expansion.
        for (coef, span, _) in &mut coefficients {
            let expected = expansion.coefficient_of_power(var, coef.power as i32);
            let corrected = coef
                .corrected_terms()
                .iter()
                .fold(Poly::zero(n), |acc, t| acc.add(&t.poly));
            let diff = corrected.sub(&expected);
            if !diff.is_zero() {
                diags.push(disagreement(file, coef, &diff, &table, span));
            }
            coef.expansion = expected;
        }
        if !diags.is_empty() {
            return Err(diags);
        }

        let mut coefficients: Vec<Coefficient> =
            coefficients.into_iter().map(|(c, _, _)| c).collect();
        coefficients.sort_by_key(|c| std::cmp::Reverse(c.power));
        Ok(QuarticModel {
            file: file.name.clone(),
            title: raw.title,
            source: raw.source,
            table,
            determinant: Determinant {
                equation: eq_det,
                entries,
                readings,
                expansion,
            },
            coefficients,
        })
    }
}

/// The symbol table: the inputs in spec order, the variable last.
fn symbol_table(file: &SourceFile, raw: &RawSpec, diags: &mut Diagnostics) -> SymbolTable {
    let mut table = SymbolTable::default();
    let all = raw
        .symbols
        .iter()
        .map(|s| (s, "symbols"))
        .chain(std::iter::once((&raw.variable, "variable")));
    for (s, what) in all {
        let r = s.get_ref();
        let name = r.name.get_ref();
        let entry = format!("{what} `{name}`");
        if syn::parse_str::<syn::Ident>(name).is_err() {
            diags.push(file.at_span(
                &r.name.span(),
                entry,
                format!("`{name}` is not a valid Rust identifier; symbols become field and variable names"),
            ));
            continue;
        }
        if table.id(name).is_some() {
            diags.push(file.at_span(
                &r.name.span(),
                entry,
                format!("duplicate entry: the symbol `{name}` is declared twice"),
            ));
            continue;
        }
        table.symbols.push(Symbol {
            name: name.clone(),
            latex: r.latex.clone(),
            doc: r.doc.clone(),
            positive: r.positive,
        });
    }
    table
}

/// The error for a coefficient that disagrees with the expansion, naming the
/// printed terms that carry the offending monomials.
fn disagreement(
    file: &SourceFile,
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
    let named: Vec<String> = culprits
        .iter()
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
    let line_of = culprits.first().map(|&i| corrected[i].line);
    let mut d = match line_of {
        Some(line) => Diagnostic {
            file: file.name.clone(),
            line,
            column: 1,
            entry,
            message,
            help: None,
        },
        None => file.at_span(span, entry, message),
    };
    d.help = Some(format!(
        "if the transcription is faithful, the report is wrong here: declare it as an [[errata]] entry with coefficient = \"{}\", printed = the term as printed, corrected = the right term, and a one-line reason",
        coef.name
    ));
    d
}

/// Whitespace-insensitive form of an expression's text.
fn squash(s: &str) -> String {
    s.chars().filter(|c| !c.is_whitespace()).collect()
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

/// Turn a TOML error into a diagnostic at its line.
pub fn toml_error(file: &SourceFile, e: &toml::de::Error) -> Diagnostics {
    let offset = e.span().map_or(0, |s| s.start);
    let mut message = e.message().trim().to_string();
    // Name the key that a terse message like "duplicate key" refers to.
    if let Some(key) = e.span().and_then(|s| file.text.get(s))
        && !key.is_empty()
        && key.len() <= 40
        && !key.contains('\n')
        && !message.contains(key)
    {
        message = format!("{message} `{key}`");
    }
    let help = if message.contains("duplicate key") {
        Some("duplicate entry: each key may appear once; remove or rename one".to_string())
    } else if message.contains("missing field") {
        Some("every entry of the spec is required unless documented as optional".to_string())
    } else {
        None
    };
    let mut d = file.at(offset, "", message);
    d.help = help;
    d.into()
}
