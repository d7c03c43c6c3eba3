//! The reviewable documents of a characteristic-polynomial spec: its
//! formulas (`docs/formulas.md`), its errata (a part of `docs/errata.md`),
//! its expansion as plain text and the Rust the derive emits, formatted.
//! `cargo xtask regen` writes them, with its preamble.

use super::expand;
use super::model::{Coefficient, QuarticModel};
use crate::codegen;
use crate::render::{ordered_terms, poly_latex, poly_text};
use std::fmt::Write;

fn matrix_latex(model: &QuarticModel) -> String {
    let rows: Vec<String> = (model.determinant.entries.iter())
        .map(|row| {
            (row.iter().map(|e| poly_latex(&e.poly, &model.table)))
                .collect::<Vec<_>>()
                .join(" & ")
        })
        .collect();
    format!(
        "\\begin{{vmatrix}} {} \\end{{vmatrix}} = 0",
        rows.join(" \\\\ ")
    )
}

fn printed_text(c: &Coefficient) -> String {
    (c.printed.iter().map(|t| format!("({})", t.text)))
        .collect::<Vec<_>>()
        .join(" + ")
}

/// `docs/formulas.md`: the determinant and each coefficient as a sum of
/// terms, in text and LaTeX; `generated` is where the generated Rust is
/// written for review.
pub fn formulas_markdown(model: &QuarticModel, generated: &str) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "# {}: the formulas, expanded\n", model.title);
    let _ = writeln!(
        s,
        "Source: {}. Spec: `{}`. Every formula below is computed from the spec by the symbolic engine \
         (`derive-quartic/engine`) and is exactly what `stability-core` evaluates.\n",
        model.source, model.file
    );
    symbols_section(&mut s, model);
    determinant_section(&mut s, model);
    for c in &model.coefficients {
        coefficient_section(&mut s, model, c);
    }
    generated_code_section(&mut s, model, generated);
    s
}

fn symbols_section(s: &mut String, model: &QuarticModel) {
    let _ = writeln!(s, "## The symbols\n");
    let _ = writeln!(s, "| name | symbol | meaning |\n| --- | --- | --- |");
    for sym in &model.table.symbols {
        let _ = writeln!(s, "| `{}` | ${}$ | {} |", sym.name, sym.latex, sym.doc);
    }
}

fn determinant_section(s: &mut String, model: &QuarticModel) {
    let det = &model.determinant;
    let _ = writeln!(s, "\n## Eq ({}): the determinant\n", det.equation);
    let _ = writeln!(s, "$$\n{}\n$$\n", matrix_latex(model));
    let _ = writeln!(s, "Entry by entry (spec syntax):\n\n```text");
    for (r, row) in det.entries.iter().enumerate() {
        for (c, e) in row.iter().enumerate() {
            let text = poly_text(&e.poly, &model.table);
            let _ = writeln!(s, "({}, {})  {text}", r + 1, c + 1);
        }
    }
    let _ = writeln!(s, "```\n");
    let _ = writeln!(
        s,
        "Its expansion is the polynomial `{} = 0`, with {} monomials in all.\n",
        model.polynomial(" ").join(" + "),
        det.expansion.len()
    );
}

fn coefficient_section(s: &mut String, model: &QuarticModel, c: &Coefficient) {
    let t = &model.table;
    let var = &model.variable_symbol().name;
    let _ = writeln!(
        s,
        "## {} (eq ({}), the coefficient of {var}^{})\n",
        c.name, c.equation, c.power
    );
    let before = if c.errata.is_empty() {
        ""
    } else {
        " (before the errata)"
    };
    let _ = writeln!(s, "As the spec writes it (its source's form){before}:\n");
    let _ = writeln!(s, "```text\n{} = {}\n```\n", c.name, printed_text(c));
    if !c.errata.is_empty() {
        let _ = writeln!(
            s,
            "Errata applied: {} (see [errata.md](errata.md)).\n",
            c.errata.len()
        );
    }
    let _ = writeln!(s, "Expanded ({} terms):\n", c.expansion.len());
    let text = poly_text(&c.expansion, t);
    let _ = writeln!(s, "```text\n{} = {text}\n```\n", c.name);
    let _ = writeln!(s, "$$\n{} = {}\n$$\n", c.name, poly_latex(&c.expansion, t));
}

fn generated_code_section(s: &mut String, model: &QuarticModel, generated: &str) {
    let coefs = expand::coefficient_program(model);
    let grad = expand::gradient_program(model);
    let (ca, cm, cd) = codegen::op_count(&coefs);
    let (ga, gm, gd) = codegen::op_count(&grad);
    let _ = writeln!(s, "## The generated code\n");
    let _ = writeln!(
        s,
        "`quartic_coefficients` evaluates the {} coefficients with {} shared products, {cm} multiplications, \
         {ca} additions and {cd} divisions; `quartic_gradient` evaluates the {} partial derivatives with \
         {gm} multiplications, {ga} additions and {gd} divisions. See `{generated}`.",
        model.coefficients.len(),
        coefs.lets.len(),
        model.coefficients.len() * model.inputs().len()
    );
}

/// The sections of `docs/errata.md` for this spec: how the determinant's
/// entries were read, and the errata of each equation's coefficients.
pub fn errata_sections(model: &QuarticModel) -> String {
    let mut s = String::new();
    let det = &model.determinant;
    if !det.readings.is_empty() {
        let _ = writeln!(s, "## Eq ({})\n", det.equation);
        for r in &det.readings {
            let [row, col] = r.entry;
            let entry = &det.entries[row - 1][col - 1];
            let _ = writeln!(s, "### Entry ({row}, {col})\n");
            let _ = writeln!(s, "- Printed: `{}`", r.printed);
            let latex = poly_latex(&entry.poly, &model.table);
            let _ = writeln!(s, "- Read as: `{}`  ($ {latex} $)", entry.text);
            let _ = writeln!(s, "- Evidence: {}", r.reason);
            let _ = writeln!(s, "- Spec: `{}` line {}\n", model.file, r.line);
        }
    }
    for eq in unique(model.coefficients.iter().map(|c| c.equation.clone())) {
        equation_errata(&mut s, model, &eq);
    }
    s
}

fn equation_errata(s: &mut String, model: &QuarticModel, eq: &str) {
    let errata: Vec<_> = (model.coefficients.iter())
        .filter(|c| c.equation == eq)
        .flat_map(|c| c.errata.iter().map(move |e| (c, e)))
        .collect();
    if errata.is_empty() {
        return;
    }
    let _ = writeln!(s, "## Eq ({eq})\n");
    let count = if errata.len() == 1 {
        "1 erratum".to_string()
    } else {
        format!("{} errata", errata.len())
    };
    let names = unique(errata.iter().map(|(c, _)| format!("`{}`", c.name)));
    let _ = writeln!(s, "{count} in the coefficients {}.\n", names.join(", "));
    let t = &model.table;
    for (c, e) in errata {
        let _ = writeln!(
            s,
            "### Coefficient {}, printed term {}\n",
            c.name,
            e.term + 1
        );
        let printed = poly_latex(&e.printed.poly, t);
        let _ = writeln!(s, "- Printed: `{}`  ($ {printed} $)", e.printed.text);
        let corrected = poly_latex(&e.corrected.poly, t);
        let _ = writeln!(s, "- Corrected: `{}`  ($ {corrected} $)", e.corrected.text);
        let _ = writeln!(s, "- Reason: {}", e.reason);
        let _ = writeln!(
            s,
            "- Evidence (computed): printed − corrected = `{}`. With the term as printed, {} would be \
             `{}`; the expansion of eq ({}) gives `{}`.",
            poly_text(&e.difference(), t),
            c.name,
            poly_text(&c.expansion.add(&e.difference()), t),
            model.determinant.equation,
            poly_text(&c.expansion, t),
        );
        let _ = writeln!(s, "- Spec: `{}` line {}\n", model.file, e.printed.line);
    }
}

/// The distinct items, in first-seen order.
pub(crate) fn unique(it: impl Iterator<Item = String>) -> Vec<String> {
    let mut v: Vec<String> = Vec::new();
    for x in it {
        if !v.contains(&x) {
            v.push(x);
        }
    }
    v
}

/// The expansion as plain text, one coefficient per block, one term a line.
pub fn expansion_text(model: &QuarticModel) -> String {
    let mut s = String::new();
    for c in &model.coefficients {
        let _ = writeln!(
            s,
            "{} (power {}, {} terms):",
            c.name,
            c.power,
            c.expansion.len()
        );
        for (m, k) in ordered_terms(&c.expansion, &model.table) {
            let mut single = crate::poly::Poly::zero(c.expansion.arity());
            single.add_term(m.clone(), k.clone());
            let _ = writeln!(s, "    {}", poly_text(&single, &model.table));
        }
    }
    s
}

/// The Rust that the derive emits for a struct named `ty`, formatted.
#[cfg(feature = "docs")]
pub fn generated_rust(model: &QuarticModel, ty: &str) -> Result<String, String> {
    let ident = proc_macro2::Ident::new(ty, proc_macro2::Span::call_site());
    let code = crate::docs::format_rust(expand::quartic_impl(model, &ident))?;
    Ok(format!(
        "// What `#[derive(Quartic)]` emits for `{ty}` from `{}`.\n\n{code}",
        model.file
    ))
}
