//! A derivative file as TOML gives it: tables of spanned values, before
//! any notation is applied; and the TOML parser's errors, located.

use super::suggest::did_you_mean;
use crate::diag::{InputError, quote};
use serde::Deserialize;
use stability_core::numerics::display::Num;
use std::collections::BTreeMap;
use std::ops::Range;
use toml::Spanned;

/// A table of numbers, keys and values with their spans.
pub type Table = Spanned<BTreeMap<Spanned<String>, Spanned<f64>>>;

/// A table's entries: key and value, with their spans.
pub type Entries<'t> = Vec<(&'t Spanned<String>, &'t Spanned<f64>)>;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawFile {
    pub notation: Spanned<String>,
    pub derivatives: Option<Table>,
    pub flight: Option<Table>,
    pub report: Option<Table>,
    pub parameters: Option<Table>,
    pub dimensional: Option<Spanned<RawDimensional>>,
    pub st_file: Option<Spanned<String>>,
    /// The control derivatives, read by [`crate::control`].
    pub control: Option<toml::Value>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawDimensional {
    #[serde(rename = "V")]
    pub v: Option<Spanned<f64>>,
    pub rho: Option<Spanned<f64>>,
    #[serde(rename = "S")]
    pub s: Option<Spanned<f64>>,
    pub chord: Option<Spanned<f64>>,
    pub mass: Option<Spanned<f64>>,
    #[serde(rename = "I_y")]
    pub i_y: Option<Spanned<f64>>,
}

/// The names the parser expected where it found an unknown one:
/// ``unknown field `x`, expected one of `a`, `b` `` → (`x`, [a, b]).
fn unknown_and_expected(message: &str) -> Option<(&str, Vec<&str>)> {
    let rest = message.strip_prefix("unknown field `")?;
    let (name, rest) = rest.split_once('`')?;
    let expected = rest.split('`').skip(1).step_by(2).collect();
    Some((name, expected))
}

/// The table header (`[flight]`) a line is, if it is one.
fn header(line: &str) -> Option<String> {
    let l = line.trim();
    let end = l.find(']')?;
    l.starts_with('[').then(|| l[..=end].to_string())
}

/// The TOML parser's error, at its line, naming the table and key it arose
/// in (`[derivatives] m_q`), with the nearest valid name for a misspelt one.
pub fn toml_error(path: &str, text: &str, e: &toml::de::Error) -> InputError {
    let span = e.span().unwrap_or(0..0);
    let mut message = e.message().trim().to_string();
    let start = span.start.min(text.len());
    let start = (0..=start)
        .rev()
        .find(|&i| text.is_char_boundary(i))
        .unwrap_or(0);
    let line_start = text[..start].rfind('\n').map_or(0, |i| i + 1);
    let line = text[line_start..].lines().next().unwrap_or("");
    let table = header(line)
        .or_else(|| text[..line_start].lines().rev().find_map(header))
        .unwrap_or_default();
    let named = message
        .split('`')
        .nth(1)
        .filter(|_| message.starts_with("missing field") || message.starts_with("unknown field"))
        .map(str::to_string);
    if let Some((name, expected)) = unknown_and_expected(&message) {
        let hint = did_you_mean(name, expected);
        message.push_str(&hint);
    }
    let key = named.or_else(|| {
        (header(line).is_none())
            .then(|| line.split('=').next().unwrap_or("").trim().to_string())
            .filter(|k| !k.is_empty())
    });
    let field = match key {
        Some(k) => format!("{table} {}", quote(&k)).trim().to_string(),
        None => table,
    };
    InputError::at(path, text, span, field, message)
}

/// The file being read, for errors located in it.
pub struct Ctx<'a> {
    pub path: &'a str,
    pub text: &'a str,
}

impl Ctx<'_> {
    pub fn err(
        &self,
        span: Range<usize>,
        field: impl Into<String>,
        message: impl Into<String>,
    ) -> InputError {
        InputError::at(self.path, self.text, span, field, message)
    }

    /// A table's values by key, every value finite.
    pub fn entries<'t>(&self, name: &str, t: &'t Option<Table>) -> Result<Entries<'t>, InputError> {
        let Some(t) = t else { return Ok(Vec::new()) };
        let mut out = Vec::new();
        for (k, v) in t.get_ref() {
            let x = *v.get_ref();
            if !x.is_finite() {
                return Err(self.err(
                    v.span(),
                    format!("[{name}] {}", quote(k.get_ref())),
                    format!("{} is not a finite number", Num(x)),
                ));
            }
            out.push((k, v));
        }
        Ok(out)
    }
}
