//! Errors that point into an input file (file, line, column and field), and
//! errors of the file system (the path, what was being done, why).
//!
//! Every message quotes at most a short excerpt of what the user wrote
//! ([`quote`], [`excerpt_line`]) and prints numbers in their shortest form
//! ([`stability_core::numerics::display::Num`]: `1e308`, not 309 digits), however
//! large the input.

use std::fmt;
use std::ops::Range;
use std::path::Path;

/// The most characters of the user's text a message quotes.
pub const QUOTE_CHARS: usize = 48;
/// The most characters of an input line shown under a message.
pub const LINE_CHARS: usize = 80;
/// The most characters of a message or field (a safety net: messages are
/// built from [`quote`]d text).
const MESSAGE_CHARS: usize = 600;

/// `s`, or its beginning and end around "…" when longer than
/// [`QUOTE_CHARS`].
pub fn quote(s: &str) -> String {
    shorten(s, QUOTE_CHARS)
}

fn shorten(s: &str, max: usize) -> String {
    let n = s.chars().count();
    if n <= max {
        return s.to_string();
    }
    let head: String = s.chars().take(max * 2 / 3).collect();
    let tail: String = s.chars().skip(n - max / 3).collect();
    format!("{head}…({} characters)…{tail}", n)
}

/// A window of at most [`LINE_CHARS`] characters of `line` around the
/// 1-based character `column`, and the caret's column within it.
pub fn excerpt_line(line: &str, column: usize) -> (String, usize) {
    let n = line.chars().count();
    if n <= LINE_CHARS {
        return (line.to_string(), column);
    }
    let half = LINE_CHARS / 2;
    let start = column
        .saturating_sub(half + 1)
        .min(n.saturating_sub(LINE_CHARS));
    let body: String = line.chars().skip(start).take(LINE_CHARS).collect();
    let (lead, lead_len) = if start > 0 { ("…", 1) } else { ("", 0) };
    let tail = if start + LINE_CHARS < n { "…" } else { "" };
    (
        format!("{lead}{body}{tail}"),
        column.saturating_sub(start) + lead_len,
    )
}

/// A problem with the user's input: exit status 2.
#[derive(Debug, Clone, PartialEq)]
pub struct InputError {
    pub file: String,
    pub line: usize,
    pub column: usize,
    /// The field, e.g. `[derivatives] m_q` (empty when the file as a whole).
    pub field: String,
    pub message: String,
    /// The offending line of the file, for context.
    pub source_line: Option<String>,
}

impl InputError {
    /// An error about the file as a whole.
    pub fn file(file: &str, message: impl Into<String>) -> Self {
        InputError {
            file: file.to_string(),
            line: 0,
            column: 0,
            field: String::new(),
            message: message.into(),
            source_line: None,
        }
    }

    /// An error at a 1-based line of `text` (column 1).
    pub fn at_line(file: &str, text: &str, line: usize, message: impl Into<String>) -> Self {
        InputError {
            file: file.to_string(),
            line,
            column: 1,
            field: String::new(),
            message: message.into(),
            source_line: (line > 0)
                .then(|| text.lines().nth(line - 1).map(str::to_string))
                .flatten(),
        }
    }

    /// An error at a byte span of `text`.
    pub fn at(
        file: &str,
        text: &str,
        span: Range<usize>,
        field: impl Into<String>,
        message: impl Into<String>,
    ) -> Self {
        let start = span.start.min(text.len());
        let mut cut = start;
        while cut > 0 && !text.is_char_boundary(cut) {
            cut -= 1;
        }
        let before = &text[..cut];
        let line = before.matches('\n').count() + 1;
        let line_start = before.rfind('\n').map_or(0, |i| i + 1);
        let column = before[line_start..].chars().count() + 1;
        let line_end = text[line_start..]
            .find('\n')
            .map_or(text.len(), |i| line_start + i);
        InputError {
            file: file.to_string(),
            line,
            column,
            field: field.into(),
            message: message.into(),
            source_line: Some(
                text[line_start..line_end]
                    .trim_end_matches('\r')
                    .to_string(),
            ),
        }
    }

    /// `file:line:column: field: ` (or `file: `), the message's location.
    pub fn location(&self) -> String {
        let mut s = if self.line > 0 {
            format!("{}:{}:{}: ", self.file, self.line, self.column)
        } else {
            format!("{}: ", self.file)
        };
        if !self.field.is_empty() {
            s.push_str(&shorten(&self.field, QUOTE_CHARS + 16));
            s.push_str(": ");
        }
        s
    }
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}{}",
            self.location(),
            shorten(&self.message, MESSAGE_CHARS)
        )?;
        if let Some(src) = &self.source_line {
            let (shown, col) = excerpt_line(src, self.column.max(1));
            let gutter = " ".repeat(self.line.to_string().len());
            // the caret's padding is written out: a width of more than
            // 65,535 is out of range for `{:>w$}`
            let pad = " ".repeat(col.saturating_sub(1));
            write!(
                f,
                "\n{gutter} |\n{} | {shown}\n{gutter} | {pad}^",
                self.line
            )?;
        }
        Ok(())
    }
}

impl std::error::Error for InputError {}

/// A file that could not be read or written: exit status 3.
#[derive(Debug, Clone, PartialEq)]
pub struct IoError {
    /// The path the program failed on.
    pub path: String,
    /// What it was doing: "cannot read", "cannot write", …
    pub doing: &'static str,
    /// Why, in words.
    pub reason: String,
    /// Where the path was named, when another file named it
    /// (`case.toml:12:18: [model.tables] zero_lift_drag: `).
    pub named_at: Option<String>,
}

impl IoError {
    pub fn new(doing: &'static str, path: &Path, reason: impl Into<String>) -> IoError {
        IoError {
            path: path.display().to_string(),
            doing,
            reason: reason.into(),
            named_at: None,
        }
    }

    /// The same error, located where another file named the path.
    pub fn named_at(mut self, at: &InputError) -> IoError {
        self.named_at = Some(at.location());
        self
    }
}

impl fmt::Display for IoError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let Some(at) = &self.named_at {
            write!(f, "{at}")?;
        }
        write!(
            f,
            "{} `{}`: {}",
            self.doing,
            shorten(&self.path, 2 * QUOTE_CHARS),
            shorten(&self.reason, MESSAGE_CHARS)
        )
    }
}

impl std::error::Error for IoError {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quotes_are_short_and_keep_both_ends() {
        let long = format!("a{}z", "m".repeat(10_000));
        let q = quote(&long);
        assert!(q.chars().count() < 80, "{q}");
        assert!(q.starts_with('a') && q.ends_with('z') && q.contains("10002 characters"));
        assert_eq!(quote("m_q"), "m_q");
    }

    #[test]
    fn a_caret_far_along_a_line_is_under_its_character() {
        // the value `nan` at column 70,007, after 70,000 spaces and `z_w = `
        let line = format!("{}z_w = nan", " ".repeat(70_000));
        let e = InputError::at("f.toml", &line, 70_006..70_009, "[derivatives] z_w", "bad");
        assert_eq!(e.column, 70_007);
        let text = e.to_string();
        assert!(text.len() < 400, "{text}");
        let lines: Vec<&str> = text.lines().collect();
        let (src, caret) = (lines[2], lines[3]);
        let at = caret.chars().position(|c| c == '^').unwrap();
        let under: String = src.chars().skip(at).take(3).collect();
        assert_eq!(under, "nan", "{src}\n{caret}");
    }
}
