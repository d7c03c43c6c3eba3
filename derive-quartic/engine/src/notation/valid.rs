//! From the typed input ([`super::ast`]) to the verified model
//! ([`super::model`]), one node at a time: the declarations (dimensional
//! quantities, parameters, rows, the reference notation), the errata by cell,
//! the report's definitions, then each notation — its symbols, each entry's
//! derived factor checked against its printed cell (and erratum), the
//! inverse relations — and finally the errata that matched no cell. Every
//! problem is reported with its file, line and entry.

use super::ast;
use super::derive::{self, Inversion, Linear, NotLinear};
use super::model::{Entry, Notation, NotationErratum, NotationModel, Row, SymbolKind};
use crate::expr::{Symbol, SymbolTable};
use crate::poly::Poly;
use crate::render::poly_text;
use crate::spec::{Context, is_identifier, squash};
use std::cell::RefCell;
use std::collections::BTreeMap;
use toml::Spanned;

/// The errata by (notation, row).
type Errata<'s> = BTreeMap<(String, String), &'s Spanned<ast::Erratum>>;

/// What every notation is read against.
struct Declarations {
    /// The dimensional quantities (ids 0…) and their dimensions.
    dims: Vec<(Symbol, [i32; 3])>,
    parameters: Vec<Symbol>,
    rows: Vec<Row>,
    /// The symbol id of each row's primary quantity.
    primary: Vec<usize>,
    /// The index of the reference notation.
    reference: usize,
}

/// Validate a spec into its model (`None` when a problem was reported).
pub fn model(cx: &Context<'_>, spec: ast::Spec) -> Option<NotationModel> {
    let decl = declarations(cx, &spec)?;
    let errata = errata_index(cx, &spec);
    let base = base_table(&decl);
    let reference = spec.notation[decl.reference].get_ref();
    let report = report_definitions(cx, reference, &decl, &base);
    let reader = Reader {
        cx,
        decl: &decl,
        base: &base,
        reference,
        report: &report,
        errata: &errata,
        used: RefCell::new(Vec::new()),
    };
    let notations: Vec<Notation> = (spec.notation.iter())
        .enumerate()
        .map(|(k, n)| reader.notation(n.get_ref(), k == decl.reference))
        .collect();
    stale_errata(cx, &errata, &reader.used.borrow());
    if cx.has_errors() {
        return None;
    }
    Some(NotationModel {
        file: cx.file().name.clone(),
        title: spec.title,
        source: spec.source,
        rows: decl.rows,
        parameters: decl.parameters,
        notations,
        reference: decl.reference,
    })
}

/// The declarations, each checked; `None` if any is wrong.
fn declarations(cx: &Context<'_>, spec: &ast::Spec) -> Option<Declarations> {
    let dims = dimensional(cx, spec);
    let parameters = parameters(cx, spec);
    let (rows, primary) = rows(cx, spec, &dims);
    let reference = reference(cx, spec);
    define_keys(cx, spec, &rows);
    notation_names(cx, spec);
    if cx.has_errors() {
        return None;
    }
    Some(Declarations {
        dims,
        parameters,
        rows,
        primary: primary.into_iter().collect::<Option<Vec<_>>>()?,
        reference: reference?,
    })
}

fn dimensional(cx: &Context<'_>, spec: &ast::Spec) -> Vec<(Symbol, [i32; 3])> {
    let mut dims: Vec<(Symbol, [i32; 3])> = Vec::new();
    for d in &spec.dimensional {
        let r = d.get_ref();
        let name = r.name.get_ref().clone();
        if dims.iter().any(|(s, _)| s.name == name) {
            let message = format!("duplicate entry: `{name}` is declared twice");
            cx.error(&r.name.span(), "dimensional", message);
        }
        let symbol = Symbol {
            latex: name.clone(),
            name,
            doc: r.doc.clone(),
            positive: true,
        };
        dims.push((symbol, r.dims));
    }
    dims
}

/// The parameters; their names become variables of the generated code.
fn parameters(cx: &Context<'_>, spec: &ast::Spec) -> Vec<Symbol> {
    let mut parameters: Vec<Symbol> = Vec::new();
    for p in &spec.parameters {
        let name = p.get_ref().name.get_ref();
        if !is_identifier(name) {
            let message = format!(
                "`{name}` is not a valid Rust identifier; parameters become variable names"
            );
            cx.error(&p.get_ref().name.span(), "parameters", message);
        }
        parameters.push(Symbol {
            name: name.clone(),
            latex: name.clone(),
            doc: p.get_ref().doc.clone(),
            positive: true,
        });
    }
    parameters
}

/// The rows, each with the id of its primary (a declared dimensional
/// quantity); a row's name becomes part of a generated function's name.
fn rows(
    cx: &Context<'_>,
    spec: &ast::Spec,
    dims: &[(Symbol, [i32; 3])],
) -> (Vec<Row>, Vec<Option<usize>>) {
    let mut rows: Vec<Row> = Vec::new();
    let mut primary_ids = Vec::new();
    for r in &spec.rows {
        let (name, primary) = (r.get_ref().name.get_ref(), r.get_ref().primary.get_ref());
        let id = dims.iter().position(|(s, _)| &s.name == primary);
        if id.is_none() {
            let message = format!("the primary `{primary}` is not a declared dimensional quantity");
            cx.error(
                &r.get_ref().primary.span(),
                format!("row `{name}`"),
                message,
            );
        }
        if rows.iter().any(|x| &x.name == name) {
            let message = format!("duplicate entry: row `{name}` is declared twice");
            cx.error(&r.get_ref().name.span(), "rows", message);
        } else if !is_identifier(name) {
            let message = format!(
                "`{name}` is not a valid Rust identifier; rows name the generated functions"
            );
            cx.error(&r.get_ref().name.span(), "rows", message);
        }
        rows.push(Row {
            name: name.clone(),
            primary: primary.clone(),
            doc: r.get_ref().doc.clone(),
        });
        primary_ids.push(id);
    }
    (rows, primary_ids)
}

/// The index of the one notation with `reference = true`.
fn reference(cx: &Context<'_>, spec: &ast::Spec) -> Option<usize> {
    let refs: Vec<usize> = (spec.notation.iter().enumerate())
        .filter(|(_, n)| n.get_ref().reference)
        .map(|(k, _)| k)
        .collect();
    if refs.len() != 1 {
        let message = format!(
            "exactly one notation must have `reference = true` (found {})",
            refs.len()
        );
        cx.error(&(0..0), "notation", message);
    }
    refs.first().copied()
}

/// Every key of a notation's `define` must be a row.
fn define_keys(cx: &Context<'_>, spec: &ast::Spec, rows: &[Row]) {
    let names: Vec<&str> = rows.iter().map(|r| r.name.as_str()).collect();
    for n in &spec.notation {
        for (key, e) in &n.get_ref().define {
            if !names.contains(&key.as_str()) {
                let entry = format!("notation `{}`", n.get_ref().name.get_ref());
                let message = format!("`{key}` is not a row; the rows are {}", names.join(", "));
                cx.error(&e.span(), entry, message);
            }
        }
    }
}

/// The notations' names: distinct, and Rust identifiers (they name the
/// generated modules).
fn notation_names(cx: &Context<'_>, spec: &ast::Spec) {
    for (k, n) in spec.notation.iter().enumerate() {
        let name = n.get_ref().name.get_ref();
        let span = n.get_ref().name.span();
        if spec.notation[..k]
            .iter()
            .any(|m| m.get_ref().name.get_ref() == name)
        {
            let message = format!("duplicate entry: notation `{name}` is declared twice");
            cx.error(&span, "notation", message);
        } else if !is_identifier(name) {
            let message = format!(
                "`{name}` is not a valid Rust identifier; notations name the generated modules"
            );
            cx.error(&span, "notation", message);
        }
    }
}

/// The errata by (notation, row); two for one cell are an error.
fn errata_index<'s>(cx: &Context<'_>, spec: &'s ast::Spec) -> Errata<'s> {
    let mut errata = Errata::new();
    for e in &spec.errata {
        let key = (
            e.get_ref().notation.get_ref().clone(),
            e.get_ref().row.get_ref().clone(),
        );
        if errata.insert(key.clone(), e).is_some() {
            let message = format!(
                "duplicate entry: two errata for `{}` row `{}`",
                key.0, key.1
            );
            cx.error(&e.span(), "errata", message);
        }
    }
    errata
}

/// The errata that matched no printed cell.
fn stale_errata(cx: &Context<'_>, errata: &Errata<'_>, used: &[(String, String)]) {
    for (key, e) in errata.iter().filter(|(key, _)| !used.contains(key)) {
        let message = format!(
            "stale erratum: notation `{}` has no printed cell for row `{}`",
            key.0, key.1
        );
        cx.error(&e.span(), "errata", message);
    }
}

/// The symbols every notation's table starts with: the dimensional
/// quantities, then the parameters.
fn base_table(decl: &Declarations) -> SymbolTable {
    let symbols = (decl.dims.iter().map(|(s, _)| s.clone()))
        .chain(decl.parameters.iter().cloned())
        .collect();
    SymbolTable { symbols }
}

/// The report's definition of each row, over the dimensional quantities and
/// the parameters only (the report's quantities are what the others are
/// converted to, so they are defined from first principles).
fn report_definitions(
    cx: &Context<'_>,
    reference: &ast::Notation,
    decl: &Declarations,
    base: &SymbolTable,
) -> Vec<Option<Poly>> {
    let rname = reference.name.get_ref();
    (decl.rows.iter())
        .map(|row| {
            let e = reference.define.get(&row.name)?;
            let entry = format!("notation `{rname}`, row `{}`, definition", row.name);
            cx.expression(&e.get_ref().expr, entry, base)
                .map(|x| x.poly)
        })
        .collect()
}

/// One notation's symbols: the base, its own quantities, the report's.
struct Universe {
    table: SymbolTable,
    kinds: Vec<SymbolKind>,
    /// (row, symbol id) of the notation's own quantities.
    own: Vec<(usize, usize)>,
    /// The symbol id of the report's quantity of row 0 (the rows follow).
    report_start: usize,
}

/// A notation's reading: everything it is checked against.
struct Reader<'a, 's> {
    cx: &'a Context<'a>,
    decl: &'a Declarations,
    base: &'a SymbolTable,
    reference: &'s ast::Notation,
    /// The report's definitions over `base`.
    report: &'a [Option<Poly>],
    errata: &'a Errata<'s>,
    /// The errata that matched their cell.
    used: RefCell<Vec<(String, String)>>,
}

impl Reader<'_, '_> {
    /// One notation: its entries derived and checked, then inverted.
    fn notation(&self, n: &ast::Notation, is_reference: bool) -> Notation {
        let u = self.universe(n);
        let rows = &self.decl.rows;
        let mut entries: Vec<Option<Entry>> = vec![None; rows.len()];
        let mut derived: Vec<Option<Poly>> = vec![None; rows.len()];
        for &(ri, sym) in &u.own {
            let raw = &n.define[&rows[ri].name];
            let Some(mut entry) = self.entry(&u, n, ri, sym, is_reference) else {
                continue;
            };
            derived[ri] = entry.to_report.clone();
            if self.printed_cell(&u, n, ri, raw.get_ref(), &mut entry) {
                entries[ri] = Some(entry);
            }
        }
        self.invert(&u, n, &derived, &mut entries);
        Notation {
            name: n.name.get_ref().clone(),
            title: n.title.clone(),
            source: n.source.clone(),
            reference: n.reference,
            entries,
            table: u.table,
            kinds: u.kinds,
        }
    }

    /// The notation's symbols: the base, its own quantities (their names new
    /// and identifiers), then the report's.
    fn universe(&self, n: &ast::Notation) -> Universe {
        let nd = self.decl.dims.len();
        let kinds = (0..self.base.len())
            .map(|id| {
                id.checked_sub(nd)
                    .map_or(SymbolKind::Dimensional, SymbolKind::Parameter)
            })
            .collect();
        let mut u = Universe {
            table: self.base.clone(),
            kinds,
            own: Vec::new(),
            report_start: 0,
        };
        for (ri, row) in self.decl.rows.iter().enumerate() {
            if let Some(e) = n.define.get(&row.name) {
                self.add_own(&mut u, n, ri, e);
            }
        }
        u.report_start = u.table.len();
        for (ri, row) in self.decl.rows.iter().enumerate() {
            let (name, positive) = match self.reference.define.get(&row.name) {
                Some(e) => (e.get_ref().name.get_ref().clone(), e.get_ref().positive),
                None => (row.name.clone(), false),
            };
            u.table.symbols.push(Symbol {
                name: format!("report_{name}"),
                latex: name,
                doc: row.doc.clone(),
                positive,
            });
            u.kinds.push(SymbolKind::Report(ri));
        }
        u
    }

    /// The notation's quantity of row `ri`, unless its name is taken or
    /// cannot be a variable.
    fn add_own(&self, u: &mut Universe, n: &ast::Notation, ri: usize, e: &Spanned<ast::Entry>) {
        let ename = e.get_ref().name.get_ref();
        let problem = if u.table.id(ename).is_some() {
            format!("the name `{ename}` is already used (by another row or a dimensional quantity)")
        } else if !is_identifier(ename) {
            format!(
                "`{ename}` is not a valid Rust identifier; names become variables of the generated code"
            )
        } else {
            u.own.push((ri, u.table.len()));
            u.kinds.push(SymbolKind::Own(ri));
            u.table.symbols.push(Symbol {
                name: ename.clone(),
                latex: ename.clone(),
                doc: self.decl.rows[ri].doc.clone(),
                positive: e.get_ref().positive,
            });
            return;
        };
        let entry = format!(
            "notation `{}`, row `{}`",
            n.name.get_ref(),
            self.decl.rows[ri].name
        );
        self.cx.error(&e.get_ref().name.span(), entry, problem);
    }

    /// The entry of row `ri` (own quantity `sym`) with the report's quantity
    /// derived from its definition; `None` when a problem was reported.
    fn entry(
        &self,
        u: &Universe,
        n: &ast::Notation,
        ri: usize,
        sym: usize,
        is_reference: bool,
    ) -> Option<Entry> {
        let row = &self.decl.rows[ri];
        let raw = n.define[&row.name].get_ref();
        let entry_name = format!("notation `{}`, row `{}`", n.name.get_ref(), row.name);
        let n_sym = u.table.len();
        let def = if is_reference {
            // Parsed (and any problem reported) once, by `report_definitions`.
            self.report[ri].as_ref()?.widen(n_sym)
        } else {
            let entry = format!("{entry_name}, definition");
            self.cx.expression(&raw.expr, entry, &u.table)?.poly
        };
        let p = self.decl.primary[ri];
        let own = self.linear(&def, p, u, raw, &entry_name)?;
        let to_report = match &self.report[ri] {
            // The report has no such quantity: nothing to convert to.
            None => None,
            // `None` when the report's definition is not linear: its own
            // entry reports that.
            Some(report) => {
                let derived = derive::report_in_own_terms(&own, &report.widen(n_sym), p, sym)?;
                self.dimensions_cancel(&derived, u, raw, &entry_name)?;
                Some(derived)
            }
        };
        Some(Entry {
            name: raw.name.get_ref().clone(),
            define: raw.expr.get_ref().clone(),
            line: self.cx.line(&raw.expr.span()),
            printed: raw.printed.as_ref().map(|s| s.get_ref().clone()),
            erratum: None,
            to_report,
            from_report: None,
        })
    }

    /// The definition as `a·p + b` for the row's primary `p`.
    fn linear(
        &self,
        def: &Poly,
        p: usize,
        u: &Universe,
        raw: &ast::Entry,
        entry_name: &str,
    ) -> Option<Linear> {
        let primary = &u.table.get(p).name;
        let message = match derive::linear(def, p, &u.table) {
            Ok(l) => return Some(l),
            Err(NotLinear::NotLinear) => {
                format!("the definition must be linear in the row's primary quantity `{primary}`")
            }
            Err(NotLinear::FactorNotATerm) => format!(
                "the factor of `{primary}` must be a single term (a product of positive quantities)"
            ),
            Err(NotLinear::FactorNotPositive) => {
                format!("`{primary}` must be multiplied by positive quantities only")
            }
        };
        self.cx.error(&raw.expr.span(), entry_name, message);
        None
    }

    /// Every dimensional quantity must cancel from a derived factor.
    fn dimensions_cancel(
        &self,
        derived: &Poly,
        u: &Universe,
        raw: &ast::Entry,
        entry_name: &str,
    ) -> Option<()> {
        let dims: Vec<[i32; 3]> = self.decl.dims.iter().map(|(_, d)| *d).collect();
        let (leftover, [m, l, t]) = derive::leftover_dimensions(derived, &u.table, &u.kinds, &dims);
        if leftover.is_empty() {
            return Some(());
        }
        let message = format!(
            "the definitions do not match: {} does not cancel (left with mass^{m} length^{l} time^{t}); derived {}",
            leftover.join(", "),
            poly_text(derived, &u.table)
        );
        self.cx.error(&raw.expr.span(), entry_name, message);
        None
    }

    /// The printed cell must equal the derived factor, or its declared
    /// erratum must correct it to that; false when a problem was reported.
    fn printed_cell(
        &self,
        u: &Universe,
        n: &ast::Notation,
        ri: usize,
        raw: &ast::Entry,
        entry: &mut Entry,
    ) -> bool {
        let Some(printed) = &raw.printed else {
            return true;
        };
        let (nname, row) = (n.name.get_ref(), &self.decl.rows[ri].name);
        let entry_name = format!("notation `{nname}`, row `{row}`");
        let Some(derived) = &entry.to_report else {
            let message = "the report has no quantity of this row, so a printed cell cannot be checked; remove `printed`";
            self.cx.error(&printed.span(), entry_name, message);
            return false;
        };
        let cell = format!("{entry_name}, printed cell");
        let Some(pp) = self.cx.expression(printed, cell, &u.table) else {
            return false;
        };
        let key = (nname.clone(), row.clone());
        if let Some(raw_e) = self.errata.get(&key) {
            self.used.borrow_mut().push(key);
            let erratum = self.erratum(u, &entry_name, printed, &pp.poly, derived, raw_e.get_ref());
            entry.erratum = erratum;
            return entry.erratum.is_some();
        }
        if &pp.poly != derived {
            let message = format!(
                "the printed cell `{}` disagrees with the factor derived from the definitions, {}, and no erratum declares it",
                printed.get_ref(),
                poly_text(derived, &u.table)
            );
            let help = format!(
                "if the transcription is faithful, declare an [[errata]] entry with notation = \"{nname}\", row = \"{row}\""
            );
            self.cx.push(
                self.cx
                    .at(&printed.span(), entry_name, message)
                    .with_help(help),
            );
            return false;
        }
        true
    }

    /// An erratum to a printed cell `pp`: it must quote the cell, correct it
    /// and agree with the derived factor.
    fn erratum(
        &self,
        u: &Universe,
        entry_name: &str,
        printed: &Spanned<String>,
        pp: &Poly,
        derived: &Poly,
        re: &ast::Erratum,
    ) -> Option<NotationErratum> {
        let entry = format!("erratum to {entry_name}");
        if squash(re.printed.get_ref()) != squash(printed.get_ref()) {
            let message = format!(
                "stale erratum: the transcribed cell is `{}`, not `{}`",
                printed.get_ref(),
                re.printed.get_ref()
            );
            self.cx.error(&re.printed.span(), entry, message);
            return None;
        }
        let corrected = format!("{entry}, corrected form");
        let corr = self.cx.expression(&re.corrected, corrected, &u.table)?.poly;
        if &corr == pp {
            let message = "stale erratum: the printed and corrected forms are equal";
            self.cx.error(&re.corrected.span(), entry, message);
            return None;
        }
        if &corr != derived {
            let message = format!(
                "the corrected form `{}` disagrees with the derivation, {}",
                re.corrected.get_ref(),
                poly_text(derived, &u.table)
            );
            self.cx.error(&re.corrected.span(), entry, message);
            return None;
        }
        Some(NotationErratum {
            printed: re.printed.get_ref().clone(),
            corrected: re.corrected.get_ref().clone(),
            reason: re.reason.clone(),
            line: self.cx.line(&re.printed.span()),
        })
    }

    /// This notation's quantity of each row in the report's names.
    fn invert(
        &self,
        u: &Universe,
        n: &ast::Notation,
        derived: &[Option<Poly>],
        entries: &mut [Option<Entry>],
    ) {
        let mut inversion = Inversion::new(&u.own, derived, u.report_start, &u.table);
        for (ri, row) in self.decl.rows.iter().enumerate() {
            if derived[ri].is_none() {
                continue;
            }
            if let Err(message) = inversion.of(ri) {
                let entry = format!("notation `{}`, row `{}`", n.name.get_ref(), row.name);
                self.cx.error(&n.define[&row.name].span(), entry, message);
            }
        }
        for (entry, inverse) in entries.iter_mut().zip(inversion.into_inverses()) {
            if let Some(e) = entry.as_mut() {
                e.from_report = inverse;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::NotationModel;
    use crate::spec::SourceFile;

    /// A toy table: the report's ½ρ notation and a classical ρ one.
    fn spec(report_tau: &str, classical_name: &str) -> String {
        format!(
            r#"title = "toy"
source = "tests"
dimensional = [
  {{ name = "Z_w", dims = [1, 0, -1], doc = "force per speed" }},
  {{ name = "rho", dims = [1, -3, 0], doc = "density" }},
  {{ name = "S",   dims = [0, 2, 0],  doc = "area" }},
  {{ name = "V",   dims = [0, 1, -1], doc = "speed" }},
  {{ name = "m",   dims = [1, 0, 0],  doc = "mass" }},
]
rows = [
  {{ name = "z_w", primary = "Z_w", doc = "z_w" }},
  {{ name = "tau", primary = "m",   doc = "unit of time" }},
]
[[notation]]
name = "report"
title = "half rho"
source = "toy"
reference = true
[notation.define]
z_w = {{ name = "z_w", expr = "Z_w/(rho/2*S*V)" }}
tau = {{ name = "tau", expr = "{report_tau}", positive = true }}
[[notation]]
name = "{classical_name}"
title = "rho"
source = "toy"
[notation.define]
z_w = {{ name = "Z", expr = "Z_w/(rho*S*V)", printed = "2*Z" }}
tau = {{ name = "T", expr = "m/(rho*S*V)", positive = true }}
"#
        )
    }

    fn load(text: String) -> Result<NotationModel, crate::SpecErrors> {
        NotationModel::load(&SourceFile::new("toy.toml", text))
    }

    #[test]
    fn the_factors_are_derived_both_ways() {
        let m = load(spec("m/(rho/2*S*V)", "classical")).unwrap_or_else(|e| panic!("{e}"));
        let c = &m.notations[1];
        // Z_w = ρSV·Z = ½ρSV·z_w, so z_w = 2Z and Z = z_w/2; likewise τ.
        let z = c.entries[0].as_ref().unwrap();
        let (own, report) = (c.table.id("Z").unwrap(), c.table.id("report_z_w").unwrap());
        let mut v = vec![0.0; c.table.len()];
        v[own] = 3.0;
        v[report] = 5.0;
        assert_eq!(z.to_report.as_ref().unwrap().eval(&v), 6.0);
        assert_eq!(z.from_report.as_ref().unwrap().eval(&v), 2.5);
        let t = c.entries[1].as_ref().unwrap();
        assert!(t.printed.is_none() && t.to_report.is_some());
    }

    #[test]
    fn a_report_definition_may_not_use_the_reports_own_names() {
        // Before, this definition parsed only in the report's own table and
        // was dropped without a word for every other notation, whose τ then
        // had no conversion.
        let e = load(spec("m/(rho/2*S*V*z_w)", "classical")).unwrap_err();
        let d = &e.0[0];
        assert_eq!((d.file.as_str(), d.line), ("toy.toml", 21));
        assert_eq!(d.entry, "notation `report`, row `tau`, definition");
        assert!(d.message.contains("unknown symbol `z_w`"), "{e}");
    }

    #[test]
    fn a_notation_name_must_be_an_identifier() {
        let e = load(spec("m/(rho/2*S*V)", "class ical")).unwrap_err();
        let d = &e.0[0];
        assert_eq!((d.line, d.entry.as_str()), (23, "notation"));
        assert!(d.message.contains("not a valid Rust identifier"), "{e}");
    }
}
