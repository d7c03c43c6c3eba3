//! Errors that point into an input file: file, line, column and field.

use std::fmt;
use std::ops::Range;

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
    /// An error about the file as a whole (it cannot be read, …).
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
        InputError {
            file: file.to_string(),
            line,
            column,
            field: field.into(),
            message: message.into(),
            source_line: text.lines().nth(line - 1).map(str::to_string),
        }
    }
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line > 0 {
            write!(f, "{}:{}:{}: ", self.file, self.line, self.column)?;
        } else {
            write!(f, "{}: ", self.file)?;
        }
        if !self.field.is_empty() {
            write!(f, "{}: ", self.field)?;
        }
        write!(f, "{}", self.message)?;
        if let Some(src) = &self.source_line {
            let gutter = self.line.to_string().len();
            write!(
                f,
                "\n{:gutter$} |\n{} | {}\n{:gutter$} | {:>col$}",
                "",
                self.line,
                src,
                "",
                "^",
                col = self.column
            )?;
        }
        Ok(())
    }
}

impl std::error::Error for InputError {}
