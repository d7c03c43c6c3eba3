//! The reviewable documents of a notation spec: `docs/notations.md`, its
//! part of `docs/errata.md`, and the Rust `notations!` emits, formatted.
//! `cargo xtask regen` writes them, with its preamble.

use super::model::{Entry, Notation, NotationErratum, NotationModel, Row};
use crate::render::poly_text;
use std::fmt::Write;

/// `docs/notations.md`: every notation's definitions, and the derived
/// conversion factors beside the printed appendix.
pub fn notations_markdown(n: &NotationModel) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "# {}\n", n.title);
    let _ = writeln!(
        s,
        "Source: {}. Spec: `{}`. Each notation defines its quantities from dimensional ones; the engine derives the \
         report's quantity of each row in the notation's terms (all dimensional quantities cancel) and the inverse, and \
         compares the first with the appendix's printed cell. ✓: the printed cell agrees; ✗: an erratum (see \
         [errata.md](errata.md)); –: not printed.\n",
        n.source, n.file
    );
    for nt in &n.notations {
        notation_section(&mut s, n, nt);
    }
    s
}

fn notation_section(s: &mut String, n: &NotationModel, nt: &Notation) {
    let _ = writeln!(s, "## `{}` — {}\n", nt.name, nt.title);
    let _ = writeln!(s, "{}\n", nt.source);
    let _ = writeln!(
        s,
        "| row | quantity | definition | report's quantity = | printed | | theirs = |"
    );
    let _ = writeln!(s, "| --- | --- | --- | --- | --- | --- | --- |");
    let text = |p: &Option<crate::poly::Poly>| match p {
        Some(p) => poly_text(p, &nt.table).replace("report_", ""),
        None => "–".to_string(),
    };
    for (row, e) in n.rows.iter().zip(&nt.entries) {
        let Some(e) = e else { continue };
        let mark = match (&e.printed, &e.erratum) {
            (None, _) => "–",
            (Some(_), None) => "✓",
            (Some(_), Some(_)) => "✗",
        };
        let printed = (e.printed.as_ref()).map_or("–".to_string(), |p| format!("`{p}`"));
        let _ = writeln!(
            s,
            "| {} | `{}` | `{}` | `{}` | {printed} | {mark} | `{}` |",
            row.name,
            e.name,
            e.define,
            text(&e.to_report),
            text(&e.from_report),
        );
    }
    let _ = writeln!(s);
}

/// The section of `docs/errata.md` for the appendix's conversion table.
pub fn errata_section(n: &NotationModel) -> String {
    let mut s = String::new();
    let list: Vec<(&Notation, &Row, &Entry, &NotationErratum)> = (n.notations.iter())
        .flat_map(|nt| {
            n.rows.iter().zip(&nt.entries).filter_map(move |(row, e)| {
                let e = e.as_ref()?;
                e.erratum.as_ref().map(|er| (nt, row, e, er))
            })
        })
        .collect();
    if list.is_empty() {
        return s;
    }
    let _ = writeln!(s, "## Appendix: the conversion table\n");
    let _ = writeln!(
        s,
        "Each factor is derived from the notations' definitions in `{}` (see [notations.md](notations.md)) and compared with the printed cell. {} cells disagree.\n",
        n.file,
        list.len()
    );
    for (nt, row, e, er) in list {
        let _ = writeln!(s, "### {} — row {}\n", nt.title, row.doc);
        let _ = writeln!(s, "- Printed: `{}`", er.printed);
        let _ = writeln!(s, "- Corrected: `{}`", er.corrected);
        let _ = writeln!(s, "- Reason: {}", er.reason);
        let derived = (e.to_report.as_ref()).map_or("–".to_string(), |p| poly_text(p, &nt.table));
        let _ = writeln!(
            s,
            "- Evidence (computed): from `{}` = `{}` and the report's definition, the report's quantity is `{derived}`.",
            e.name, e.define,
        );
        let _ = writeln!(s, "- Spec: `{}` line {}\n", n.file, er.line);
    }
    s
}

/// The Rust that `notations!` emits, formatted.
#[cfg(feature = "docs")]
pub fn generated_rust(model: &NotationModel) -> Result<String, String> {
    let code = crate::docs::format_rust(super::expand::notation_items(model))?;
    Ok(format!(
        "// What `notations!` emits from `{}`.\n\n{code}",
        model.file
    ))
}
