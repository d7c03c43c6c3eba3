//! The notation spec: how each author normalises each quantity, and the
//! report's appendix table as printed.
//!
//! Every notation defines its quantity of each row (x_u, …, τ, μ, i_B, …)
//! from dimensional quantities (X_u, ρ, S, V, c̄, m, …). For a row whose
//! dimensional "primary" quantity is p, a definition must be linear in p,
//! q = a·p + b; solving the other notation's definition for p and
//! substituting it into the report's gives the report's quantity in the
//! other notation's terms — the conversion factor, derived. Every dimensional
//! quantity must cancel (else the definitions are inconsistent), and the
//! result is compared with the appendix's printed cell; a disagreement must
//! be declared as an erratum, as for eq (6). Inverting the relations gives
//! the conversions from the report's notation back.

use crate::diag::{Diagnostics, SourceFile};
use crate::expr::{Site, Symbol, SymbolTable, parse_poly};
use crate::poly::{Monomial, Poly};
use crate::quartic::toml_error;
use crate::render::poly_text;
use num_rational::BigRational;
use num_traits::{One, Zero};
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
    dimensional: Vec<Spanned<RawDimensional>>,
    #[serde(default)]
    parameters: Vec<Spanned<RawParameter>>,
    rows: Vec<Spanned<RawRow>>,
    notation: Vec<Spanned<RawNotation>>,
    #[serde(default)]
    errata: Vec<Spanned<RawErratum>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawDimensional {
    name: Spanned<String>,
    /// Exponents of mass, length and time.
    dims: [i32; 3],
    doc: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawParameter {
    name: Spanned<String>,
    doc: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawRow {
    name: Spanned<String>,
    primary: Spanned<String>,
    doc: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawNotation {
    name: Spanned<String>,
    title: String,
    source: String,
    #[serde(default)]
    reference: bool,
    define: BTreeMap<String, Spanned<RawEntry>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawEntry {
    name: Spanned<String>,
    expr: Spanned<String>,
    #[serde(default)]
    printed: Option<Spanned<String>>,
    #[serde(default)]
    positive: bool,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawErratum {
    notation: Spanned<String>,
    row: Spanned<String>,
    printed: Spanned<String>,
    corrected: Spanned<String>,
    reason: String,
}

// ------------------------------------------------------------ validated form

/// A row of the appendix: a concept every notation may define.
#[derive(Clone, Debug)]
pub struct Row {
    pub name: String,
    /// The dimensional quantity the row normalises.
    pub primary: String,
    pub doc: String,
}

/// A notation's quantity of one row.
#[derive(Clone, Debug)]
pub struct Entry {
    /// The notation's own name for it.
    pub name: String,
    pub define: String,
    pub line: usize,
    /// The appendix's cell: the report's quantity in this notation's terms,
    /// as printed (None where the table has "-").
    pub printed: Option<String>,
    /// An erratum to the printed cell.
    pub erratum: Option<NotationErratum>,
    /// The report's quantity in this notation's names (derived).
    pub to_report: Poly,
    /// This notation's quantity in the report's names (derived).
    pub from_report: Poly,
}

/// A printed cell of the appendix that the derivation contradicts.
#[derive(Clone, Debug)]
pub struct NotationErratum {
    pub printed: String,
    pub corrected: String,
    pub reason: String,
    pub line: usize,
}

/// One notation, with everything derived against the report's.
#[derive(Clone, Debug)]
pub struct Notation {
    pub name: String,
    pub title: String,
    pub source: String,
    pub reference: bool,
    /// One entry per row (None: the notation has no such quantity).
    pub entries: Vec<Option<Entry>>,
    /// The symbols of the derived polynomials: the parameters, this
    /// notation's names, then the report's names (as `report_<name>`).
    pub table: SymbolTable,
}

/// A verified notation spec.
#[derive(Clone, Debug)]
pub struct NotationModel {
    pub file: String,
    pub title: String,
    pub source: String,
    pub rows: Vec<Row>,
    /// The dimensionless parameters conversions may need (e.g. l_t/c̄).
    pub parameters: Vec<Symbol>,
    pub notations: Vec<Notation>,
}

impl NotationModel {
    /// The reference notation (the report's).
    pub fn reference(&self) -> &Notation {
        self.notations
            .iter()
            .find(|n| n.reference)
            .unwrap_or(&self.notations[0])
    }

    /// Load, derive and verify a notation spec.
    pub fn load(file: &SourceFile) -> Result<NotationModel, Diagnostics> {
        let raw: RawSpec = toml::from_str(&file.text).map_err(|e| toml_error(file, &e))?;
        let mut diags = Diagnostics::default();
        let at = |span: &Range<usize>, entry: &str, msg: String| {
            file.at_span(span, entry.to_string(), msg)
        };

        // Dimensional symbols and parameters.
        let mut dims: Vec<(Symbol, [i32; 3])> = Vec::new();
        for d in &raw.dimensional {
            let r = d.get_ref();
            let name = r.name.get_ref().clone();
            if dims.iter().any(|(s, _)| s.name == name) {
                diags.push(at(
                    &r.name.span(),
                    "dimensional",
                    format!("duplicate entry: `{name}` is declared twice"),
                ));
            }
            dims.push((
                Symbol {
                    name,
                    latex: r.name.get_ref().clone(),
                    doc: r.doc.clone(),
                    positive: true,
                },
                r.dims,
            ));
        }
        let parameters: Vec<Symbol> = raw
            .parameters
            .iter()
            .map(|p| Symbol {
                name: p.get_ref().name.get_ref().clone(),
                latex: p.get_ref().name.get_ref().clone(),
                doc: p.get_ref().doc.clone(),
                positive: true,
            })
            .collect();
        let mut rows = Vec::new();
        for r in &raw.rows {
            let rr = r.get_ref();
            let primary = rr.primary.get_ref();
            if !dims.iter().any(|(s, _)| &s.name == primary) {
                diags.push(at(
                    &rr.primary.span(),
                    &format!("row `{}`", rr.name.get_ref()),
                    format!("the primary `{primary}` is not a declared dimensional quantity"),
                ));
            }
            if rows.iter().any(|x: &Row| &x.name == rr.name.get_ref()) {
                diags.push(at(
                    &rr.name.span(),
                    "rows",
                    format!(
                        "duplicate entry: row `{}` is declared twice",
                        rr.name.get_ref()
                    ),
                ));
            }
            rows.push(Row {
                name: rr.name.get_ref().clone(),
                primary: primary.clone(),
                doc: rr.doc.clone(),
            });
        }
        let refs: Vec<&Spanned<RawNotation>> = raw
            .notation
            .iter()
            .filter(|n| n.get_ref().reference)
            .collect();
        if refs.len() != 1 {
            diags.push(at(
                &(0..0),
                "notation",
                format!(
                    "exactly one notation must have `reference = true` (found {})",
                    refs.len()
                ),
            ));
        }
        for n in &raw.notation {
            for key in n.get_ref().define.keys() {
                if !rows.iter().any(|r| &r.name == key) {
                    let span = n.get_ref().define[key].span();
                    diags.push(at(
                        &span,
                        &format!("notation `{}`", n.get_ref().name.get_ref()),
                        format!(
                            "`{key}` is not a row; the rows are {}",
                            rows.iter()
                                .map(|r| r.name.as_str())
                                .collect::<Vec<_>>()
                                .join(", ")
                        ),
                    ));
                }
            }
        }
        if !diags.is_empty() {
            return Err(diags);
        }
        let reference = refs[0].get_ref();

        // Errata by (notation, row).
        let mut errata: BTreeMap<(String, String), &Spanned<RawErratum>> = BTreeMap::new();
        for e in &raw.errata {
            let key = (
                e.get_ref().notation.get_ref().clone(),
                e.get_ref().row.get_ref().clone(),
            );
            if errata.insert(key.clone(), e).is_some() {
                diags.push(at(
                    &e.span(),
                    "errata",
                    format!(
                        "duplicate entry: two errata for `{}` row `{}`",
                        key.0, key.1
                    ),
                ));
            }
        }
        let mut used_errata: Vec<(String, String)> = Vec::new();

        let mut notations = Vec::new();
        for n in &raw.notation {
            let nr = n.get_ref();
            let nname = nr.name.get_ref().clone();
            // Universe: dimensional, parameters, this notation's names, the report's names.
            let mut table = SymbolTable::default();
            for (s, _) in &dims {
                table.symbols.push(s.clone());
            }
            table.symbols.extend(parameters.iter().cloned());
            let mut own: Vec<(usize, usize)> = Vec::new(); // (row, symbol id)
            for (ri, row) in rows.iter().enumerate() {
                if let Some(e) = nr.define.get(&row.name) {
                    let ename = e.get_ref().name.get_ref();
                    if table.id(ename).is_some() {
                        diags.push(at(&e.get_ref().name.span(), &format!("notation `{nname}`, row `{}`", row.name), format!("the name `{ename}` is already used (by another row or a dimensional quantity)")));
                        continue;
                    }
                    own.push((ri, table.len()));
                    table.symbols.push(Symbol {
                        name: ename.clone(),
                        latex: ename.clone(),
                        doc: row.doc.clone(),
                        positive: e.get_ref().positive,
                    });
                }
            }
            let report_start = table.len();
            for row in &rows {
                let (name, positive) = match reference.define.get(&row.name) {
                    Some(e) => (e.get_ref().name.get_ref().clone(), e.get_ref().positive),
                    None => (row.name.clone(), false),
                };
                table.symbols.push(Symbol {
                    name: format!("report_{name}"),
                    latex: name,
                    doc: row.doc.clone(),
                    positive,
                });
            }
            let n_sym = table.len();
            let parse = |s: &Spanned<String>,
                         entry: String,
                         diags: &mut Diagnostics,
                         table: &SymbolTable| {
                let site = Site {
                    file,
                    offset: file.string_content_start(&s.span()),
                    entry,
                };
                match parse_poly(s.get_ref(), &site, table) {
                    Ok(p) => Some(p),
                    Err(d) => {
                        diags.0.extend(d.0);
                        None
                    }
                }
            };
            // The report's definitions in this universe (they may only use
            // dimensional symbols and parameters).
            let report_defs: Vec<Option<Poly>> = rows
                .iter()
                .map(|row| {
                    reference.define.get(&row.name).and_then(|e| {
                        parse(
                            &e.get_ref().expr,
                            format!(
                                "notation `{}`, row `{}`",
                                reference.name.get_ref(),
                                row.name
                            ),
                            &mut Diagnostics::default(),
                            &table,
                        )
                    })
                })
                .collect();
            let mut entries: Vec<Option<Entry>> = vec![None; rows.len()];
            let mut to_report: Vec<Option<Poly>> = vec![None; rows.len()];
            for &(ri, sym) in &own {
                let row = &rows[ri];
                let e = &nr.define[&row.name];
                let er = e.get_ref();
                let entry_name = format!("notation `{nname}`, row `{}`", row.name);
                let Some(def) = parse(
                    &er.expr,
                    format!("{entry_name}, definition"),
                    &mut diags,
                    &table,
                ) else {
                    continue;
                };
                let p = match table.id(&row.primary) {
                    Some(p) => p,
                    None => continue,
                };
                let Some((a, b)) = def.linear_in(p) else {
                    diags.push(at(
                        &er.expr.span(),
                        &entry_name,
                        format!(
                            "the definition must be linear in the row's primary quantity `{}`",
                            row.primary
                        ),
                    ));
                    continue;
                };
                let Some((ma, ca)) = a.as_single_term().map(|(m, c)| (m.clone(), c.clone())) else {
                    diags.push(at(&er.expr.span(), &entry_name, format!("the factor of `{}` must be a single term (a product of positive quantities)", row.primary)));
                    continue;
                };
                if ca.is_zero() || ma.factors().any(|(id, _)| !table.get(id).positive) {
                    diags.push(at(
                        &er.expr.span(),
                        &entry_name,
                        format!(
                            "`{}` must be multiplied by positive quantities only",
                            row.primary
                        ),
                    ));
                    continue;
                }
                let Some(Some(rdef)) = report_defs.get(ri) else {
                    // the report does not define this row: nothing to derive
                    to_report[ri] = None;
                    entries[ri] = Some(Entry {
                        name: er.name.get_ref().clone(),
                        define: er.expr.get_ref().clone(),
                        line: file.position(er.expr.span().start).0,
                        printed: er.printed.as_ref().map(|s| s.get_ref().clone()),
                        erratum: None,
                        to_report: Poly::zero(n_sym),
                        from_report: Poly::zero(n_sym),
                    });
                    continue;
                };
                let Some((ar, br)) = rdef.linear_in(p) else {
                    continue;
                };
                // Q_R = (a_R/a)(q − b) + b_R
                let q = Poly::symbol(n_sym, sym);
                let derived = ar.div_term(&ma, &ca).mul(&q.sub(&b)).add(&br);
                // every dimensional quantity must cancel
                let leftover: Vec<&str> = derived
                    .terms()
                    .flat_map(|(m, _)| m.factors().map(|(id, _)| id).collect::<Vec<_>>())
                    .filter(|&id| id < dims.len())
                    .map(|id| table.get(id).name.as_str())
                    .collect();
                if !leftover.is_empty() {
                    let dimsum: [i32; 3] = derived
                        .terms()
                        .next()
                        .map(|(m, _)| {
                            let mut acc = [0; 3];
                            for (id, e) in m.factors() {
                                if id < dims.len() {
                                    for (a, d) in acc.iter_mut().zip(dims[id].1) {
                                        *a += d * e;
                                    }
                                }
                            }
                            acc
                        })
                        .unwrap_or([0; 3]);
                    diags.push(at(
                        &er.expr.span(),
                        &entry_name,
                        format!(
                            "the definitions do not match: {} does not cancel (left with mass^{} length^{} time^{}); derived {}",
                            leftover.join(", "),
                            dimsum[0],
                            dimsum[1],
                            dimsum[2],
                            poly_text(&derived, &table)
                        ),
                    ));
                    continue;
                }
                to_report[ri] = Some(derived.clone());
                // The printed cell, with its erratum.
                let key = (nname.clone(), row.name.clone());
                let erratum = errata.get(&key).copied();
                let mut entry = Entry {
                    name: er.name.get_ref().clone(),
                    define: er.expr.get_ref().clone(),
                    line: file.position(er.expr.span().start).0,
                    printed: er.printed.as_ref().map(|s| s.get_ref().clone()),
                    erratum: None,
                    to_report: derived.clone(),
                    from_report: Poly::zero(n_sym),
                };
                if let Some(printed) = &er.printed {
                    let Some(pp) = parse(
                        printed,
                        format!("{entry_name}, printed cell"),
                        &mut diags,
                        &table,
                    ) else {
                        continue;
                    };
                    match erratum {
                        Some(raw_e) => {
                            used_errata.push(key.clone());
                            let re = raw_e.get_ref();
                            let squash = |s: &str| {
                                s.chars().filter(|c| !c.is_whitespace()).collect::<String>()
                            };
                            if squash(re.printed.get_ref()) != squash(printed.get_ref()) {
                                diags.push(at(
                                    &re.printed.span(),
                                    &format!("erratum to {entry_name}"),
                                    format!(
                                        "stale erratum: the transcribed cell is `{}`, not `{}`",
                                        printed.get_ref(),
                                        re.printed.get_ref()
                                    ),
                                ));
                                continue;
                            }
                            let Some(corr) = parse(
                                &re.corrected,
                                format!("erratum to {entry_name}, corrected form"),
                                &mut diags,
                                &table,
                            ) else {
                                continue;
                            };
                            if corr == pp {
                                diags.push(at(
                                    &re.corrected.span(),
                                    &format!("erratum to {entry_name}"),
                                    "stale erratum: the printed and corrected forms are equal"
                                        .into(),
                                ));
                                continue;
                            }
                            if corr != derived {
                                diags.push(at(
                                    &re.corrected.span(),
                                    &format!("erratum to {entry_name}"),
                                    format!(
                                        "the corrected form `{}` disagrees with the derivation, {}",
                                        re.corrected.get_ref(),
                                        poly_text(&derived, &table)
                                    ),
                                ));
                                continue;
                            }
                            entry.erratum = Some(NotationErratum {
                                printed: re.printed.get_ref().clone(),
                                corrected: re.corrected.get_ref().clone(),
                                reason: re.reason.clone(),
                                line: file.position(re.printed.span().start).0,
                            });
                        }
                        None => {
                            if pp != derived {
                                diags.push(
                                    at(
                                        &printed.span(),
                                        &entry_name,
                                        format!(
                                            "the printed cell `{}` disagrees with the factor derived from the definitions, {}, and no erratum declares it",
                                            printed.get_ref(),
                                            poly_text(&derived, &table)
                                        ),
                                    )
                                    .with_help(format!("if the transcription is faithful, declare an [[errata]] entry with notation = \"{nname}\", row = \"{}\"", row.name)),
                                );
                                continue;
                            }
                        }
                    }
                }
                entries[ri] = Some(entry);
            }
            // Invert: this notation's quantity of each row in the report's names.
            let mut inverse: Vec<Option<Poly>> = vec![None; rows.len()];
            for ri in 0..rows.len() {
                if to_report[ri].is_some() {
                    let mut visiting = vec![false; rows.len()];
                    if let Err(msg) = invert(
                        ri,
                        &own,
                        &to_report,
                        &mut inverse,
                        &mut visiting,
                        report_start,
                        n_sym,
                        &table,
                    ) {
                        let span = nr.define[&rows[ri].name].span();
                        diags.push(at(
                            &span,
                            &format!("notation `{nname}`, row `{}`", rows[ri].name),
                            msg,
                        ));
                    }
                }
            }
            for (ri, inv) in inverse.into_iter().enumerate() {
                if let (Some(e), Some(p)) = (entries[ri].as_mut(), inv) {
                    e.from_report = p;
                }
            }
            notations.push(Notation {
                name: nname,
                title: nr.title.clone(),
                source: nr.source.clone(),
                reference: nr.reference,
                entries,
                table,
            });
        }
        for (key, e) in &errata {
            if !used_errata.contains(key) {
                diags.push(at(
                    &e.span(),
                    "errata",
                    format!(
                        "stale erratum: notation `{}` has no printed cell for row `{}`",
                        key.0, key.1
                    ),
                ));
            }
        }
        diags.into_result(NotationModel {
            file: file.name.clone(),
            title: raw.title,
            source: raw.source,
            rows,
            parameters,
            notations,
        })
    }
}

/// Solve row `ri`'s relation Q_R = α·q + β for q (this notation's quantity)
/// in the report's names, substituting the other quantities β and α use.
#[allow(clippy::too_many_arguments)]
fn invert(
    ri: usize,
    own: &[(usize, usize)],
    to_report: &[Option<Poly>],
    inverse: &mut Vec<Option<Poly>>,
    visiting: &mut Vec<bool>,
    report_start: usize,
    n_sym: usize,
    table: &SymbolTable,
) -> Result<Poly, String> {
    if let Some(p) = &inverse[ri] {
        return Ok(p.clone());
    }
    if visiting[ri] {
        return Err("the definitions refer to each other in a cycle".into());
    }
    visiting[ri] = true;
    let Some(rel) = &to_report[ri] else {
        return Err("the report does not define this row".into());
    };
    let sym = own
        .iter()
        .find(|(r, _)| *r == ri)
        .map(|(_, s)| *s)
        .ok_or("no symbol")?;
    let (alpha, beta) = rel
        .linear_in(sym)
        .ok_or("the relation is not linear in this notation's quantity")?;
    let (ma, ca) = alpha
        .as_single_term()
        .map(|(m, c)| (m.clone(), c.clone()))
        .ok_or("the factor of this notation's quantity is not a single term")?;
    let report = Poly::symbol(n_sym, report_start + ri);
    let mut q = report.sub(&beta).div_term(&ma, &ca);
    // Replace the other quantities of this notation by their inverses.
    for &(rj, sj) in own {
        if rj != ri && q.mentions(sj) {
            let v = invert(
                rj,
                own,
                to_report,
                inverse,
                visiting,
                report_start,
                n_sym,
                table,
            )?;
            q = substitute_any(&q, sj, &v).ok_or_else(|| {
                format!(
                    "cannot invert: `{}` occurs with a negative power and its inverse is not a single term",
                    table.get(sj).name
                )
            })?;
        }
    }
    visiting[ri] = false;
    inverse[ri] = Some(q.clone());
    Ok(q)
}

/// Substitute `value` for symbol `id`, negative powers included when
/// `value` is a single term.
fn substitute_any(p: &Poly, id: usize, value: &Poly) -> Option<Poly> {
    if let Some(s) = p.substitute(id, value) {
        return Some(s);
    }
    let (m, c) = value.as_single_term()?;
    let n = p.arity();
    let mut out = Poly::zero(n);
    for (mm, cc) in p.terms() {
        let e = mm.exponent(id);
        let mut coef = cc.clone();
        let mut mono = mm.without(id);
        let power = |r: &BigRational, k: i32| {
            let mut acc = BigRational::one();
            for _ in 0..k.unsigned_abs() {
                acc *= r;
            }
            if k < 0 { BigRational::one() / acc } else { acc }
        };
        coef *= power(c, e);
        let scaled = Monomial(m.0.iter().map(|x| x * e).collect());
        mono = mono.mul(&scaled);
        out.add_term(mono, coef);
    }
    Some(out)
}
