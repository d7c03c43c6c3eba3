//! The documents shared by the spec kinds: `docs/errata.md`, which gathers
//! the errata of every spec, and the formatting of generated Rust for
//! review. Each kind writes its own documents (`quartic::docs`,
//! `notation::docs`); `cargo xtask regen` adds its preamble and writes them.

use crate::notation::NotationModel;
use crate::quartic::QuarticModel;
use std::fmt::Write;

/// `docs/errata.md`: every erratum found against the report, one section
/// per equation, for every characteristic-polynomial spec and the notation
/// spec.
pub fn errata_markdown(quartics: &[&QuarticModel], notation: Option<&NotationModel>) -> String {
    let mut s = String::new();
    let files: Vec<String> = quartics.iter().map(|m| format!("`{}`", m.file)).collect();
    let sources: Vec<&str> = quartics.iter().map(|m| m.source.as_str()).collect();
    let _ = writeln!(s, "# Errata to the report\n");
    let _ = writeln!(
        s,
        "Found by the build: the coefficients each spec ({}) writes in its source's form — the \
         report's eq (6) as printed, or a hand expansion — are compared term by term with the \
         exact expansion of the determinant they come from, and the build fails unless every \
         disagreement is declared here with its evidence. Sources: {}.\n",
        files.join(", "),
        sources.join("; ")
    );
    for model in quartics {
        s.push_str(&crate::quartic::docs::errata_sections(model));
    }
    if let Some(n) = notation {
        s.push_str(&crate::notation::docs::errata_section(n));
    }
    s
}

/// Generated tokens as a formatted Rust file.
#[cfg(feature = "docs")]
pub fn format_rust(tokens: proc_macro2::TokenStream) -> Result<String, String> {
    let file: syn::File =
        syn::parse2(tokens).map_err(|e| format!("the generated code does not parse: {e}"))?;
    Ok(prettyplease::unparse(&file))
}
