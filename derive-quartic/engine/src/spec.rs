//! What every kind of spec shares: the file and its positions (TOML spans →
//! line and column), the reading of the TOML into a kind's typed input, the
//! parsing of its expressions, and the [`Context`] that carries the file and
//! the [`Diagnostics`] through a validation.

use crate::diag::{Diagnostic, Diagnostics, SpecErrors};
use crate::expr::{Site, SymbolTable, parse_poly};
use crate::poly::Poly;
use serde::de::DeserializeOwned;
use std::ops::Range;
use toml::Spanned;

/// A spec file's text and the name it is shown by.
#[derive(Clone, Debug)]
pub struct SourceFile {
    /// The path as the user wrote it (shown in messages).
    pub name: String,
    pub text: String,
}

impl SourceFile {
    pub fn new(name: impl Into<String>, text: impl Into<String>) -> Self {
        SourceFile {
            name: name.into(),
            text: text.into(),
        }
    }

    /// 1-based line and column (in characters) of a byte offset.
    pub fn position(&self, offset: usize) -> (usize, usize) {
        let offset = offset.min(self.text.len());
        let before = &self.text[..floor_char_boundary(&self.text, offset)];
        let line = before.matches('\n').count() + 1;
        let line_start = before.rfind('\n').map_or(0, |i| i + 1);
        let column = before[line_start..].chars().count() + 1;
        (line, column)
    }

    /// The text of a 1-based line, without its newline.
    pub fn line_text(&self, line: usize) -> &str {
        self.text.lines().nth(line.saturating_sub(1)).unwrap_or("")
    }

    /// A diagnostic at a byte offset.
    pub fn at(
        &self,
        offset: usize,
        entry: impl Into<String>,
        message: impl Into<String>,
    ) -> Diagnostic {
        let (line, column) = self.position(offset);
        Diagnostic {
            file: self.name.clone(),
            line,
            column,
            entry: entry.into(),
            message: message.into(),
            help: None,
        }
    }

    /// Byte offset of the first character inside a TOML string whose span
    /// (quotes included) is `span`.
    pub fn string_content_start(&self, span: &Range<usize>) -> usize {
        let rest = self.text.get(span.start..).unwrap_or("");
        if rest.starts_with("\"\"\"") || rest.starts_with("'''") {
            span.start + 3
        } else if rest.starts_with('"') || rest.starts_with('\'') {
            span.start + 1
        } else {
            span.start
        }
    }
}

fn floor_char_boundary(s: &str, mut i: usize) -> usize {
    while i > 0 && !s.is_char_boundary(i) {
        i -= 1;
    }
    i
}

/// An expression of a spec, with its text, its line and its expansion.
#[derive(Clone, Debug)]
pub struct Expression {
    pub text: String,
    pub line: usize,
    pub poly: Poly,
}

/// A spec being validated: its file and the problems found so far.
pub struct Context<'a> {
    file: &'a SourceFile,
    diags: Diagnostics,
}

impl<'a> Context<'a> {
    pub fn new(file: &'a SourceFile) -> Self {
        Context {
            file,
            diags: Diagnostics::new(),
        }
    }

    pub fn file(&self) -> &'a SourceFile {
        self.file
    }

    pub fn diagnostics(&self) -> &Diagnostics {
        &self.diags
    }

    /// The spec's typed input; a TOML or shape error is reported at its line.
    pub fn read<T: DeserializeOwned>(&self) -> Option<T> {
        match toml::from_str(&self.file.text) {
            Ok(v) => Some(v),
            Err(e) => {
                self.push(toml_error(self.file, &e));
                None
            }
        }
    }

    /// A diagnostic at the start of `span` (not yet reported).
    pub fn at(
        &self,
        span: &Range<usize>,
        entry: impl Into<String>,
        message: impl Into<String>,
    ) -> Diagnostic {
        self.file.at(span.start, entry, message)
    }

    /// Report a problem at the start of `span`.
    pub fn error(&self, span: &Range<usize>, entry: impl Into<String>, message: impl Into<String>) {
        self.push(self.at(span, entry, message));
    }

    /// Report a problem.
    pub fn push(&self, d: Diagnostic) {
        self.diags.push(d);
    }

    pub fn has_errors(&self) -> bool {
        self.diags.has_errors()
    }

    /// The 1-based line of a span's start.
    pub fn line(&self, span: &Range<usize>) -> usize {
        self.file.position(span.start).0
    }

    /// Parse the TOML string `s` as an expression over `table`; a problem is
    /// reported at its character, under `entry`.
    pub fn expression(
        &self,
        s: &Spanned<String>,
        entry: impl Into<String>,
        table: &SymbolTable,
    ) -> Option<Expression> {
        let site = Site {
            file: self.file,
            offset: self.file.string_content_start(&s.span()),
            entry: entry.into(),
        };
        let poly = parse_poly(s.get_ref(), &site, table, &self.diags)?;
        Some(Expression {
            text: s.get_ref().clone(),
            line: self.line(&s.span()),
            poly,
        })
    }

    /// The validated model, or every problem found.
    pub fn finish<T>(self, value: Option<T>) -> Result<T, SpecErrors> {
        self.diags.finish(value, &self.file.name)
    }
}

/// Whitespace-insensitive form of an expression's text (to match a printed
/// term or cell with its erratum).
pub fn squash(s: &str) -> String {
    s.chars().filter(|c| !c.is_whitespace()).collect()
}

/// Whether `name` can become a Rust identifier of the generated code.
pub fn is_identifier(name: &str) -> bool {
    syn::parse_str::<syn::Ident>(name).is_ok()
}

/// A TOML error as a diagnostic at its line.
pub fn toml_error(file: &SourceFile, e: &toml::de::Error) -> Diagnostic {
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
    Diagnostic {
        help,
        ..file.at(offset, "", message)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn positions_are_one_based_lines_and_character_columns() {
        let f = SourceFile::new("s.toml", "a = 1\nλ = \"x_u\"\n");
        assert_eq!(f.position(0), (1, 1));
        assert_eq!(f.position(6), (2, 1));
        // byte 11 is the opening quote after "λ = " (λ is two bytes)
        assert_eq!(f.position(11), (2, 5));
        assert_eq!(f.line_text(2), "λ = \"x_u\"");
    }

    #[test]
    fn a_toml_error_names_its_line_and_key() {
        let f = SourceFile::new("s.toml", "a = 1\na = 2\n");
        let cx = Context::new(&f);
        let read: Option<toml::Table> = cx.read();
        assert!(read.is_none());
        let e = cx.finish(read).unwrap_err();
        let d = &e.0[0];
        assert_eq!((d.file.as_str(), d.line), ("s.toml", 2));
        assert!(d.message.contains("duplicate key"), "{d}");
        assert!(
            d.help
                .as_deref()
                .is_some_and(|h| h.contains("duplicate entry"))
        );
    }
}
