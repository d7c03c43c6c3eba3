//! The form a command writes its result in, chosen once from its options
//! ([`Format`]), and the writers every command hands its results to: a
//! whole result ([`Format::document`]: JSON from its view, else the
//! command's own text), or records one after another ([`Table`] and
//! [`Record`]: CSV lines under a header, or a JSON array of objects).
//!
//! Nothing else branches on the format: a command asks for a [`Format`]
//! (`--json`: [`Format::printed`]; `-o OUT.csv|OUT.json`:
//! [`Format::of_file`]) and hands its view and its text, or its records,
//! to these writers.

use crate::Failure;
use crate::diag::InputError;
use serde::Serialize;
use std::path::Path;

/// How a result is written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// The command's own text: its page, its TOML, its CSV table.
    Text,
    /// JSON: the result's view ([`crate::views`]), or an array of records.
    Json,
    /// CSV: a header, then one line a record.
    Csv,
}

impl Format {
    /// What `--json` asks for: JSON, else the command's text.
    pub fn printed(json: bool) -> Format {
        match json {
            true => Format::Json,
            false => Format::Text,
        }
    }

    /// An output file's format, from its extension: `.csv` or `.json`.
    /// The message names no option (the caller's option is named beside
    /// it).
    pub fn of_file(path: &str) -> Result<Format, &'static str> {
        match Path::new(path).extension().and_then(|e| e.to_str()) {
            Some("csv") => Ok(Format::Csv),
            Some("json") => Ok(Format::Json),
            _ => Err("the output must end in .csv or .json"),
        }
    }

    /// A result as written: in JSON its view, pretty-printed with a line
    /// break after it, every number in it finite ([`crate::finite::guard`];
    /// the error names `source`, the input the result is of); in the other
    /// formats `text()`, the command's own rendering (a page, TOML, CSV).
    pub fn document(
        self,
        source: &str,
        view: &impl Serialize,
        text: impl FnOnce() -> Result<String, Failure>,
    ) -> Result<String, Failure> {
        match self {
            Format::Json => {
                crate::finite::guard(source, view)?;
                let json = serde_json::to_string_pretty(view).map_err(|e| {
                    let m = format!("the result cannot be written as JSON: {e}");
                    InputError::file(source, m)
                })?;
                Ok(json + "\n")
            }
            Format::Text | Format::Csv => text(),
        }
    }
}

/// Records written one after another: CSV lines under a header of the
/// fields' names, or a JSON array of objects (a table's text is its CSV).
/// The records may be written into separate buffers (in parallel) and
/// joined in order: [`Table::record`] writes what separates a record from
/// the one before it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Table {
    json: bool,
}

impl Table {
    /// The records of a result written as `format` says.
    pub fn new(format: Format) -> Table {
        Table {
            json: format == Format::Json,
        }
    }

    /// What comes before the records: the CSV's header (the fields'
    /// names), or the JSON array's opening.
    pub fn head<'a>(self, names: impl IntoIterator<Item = &'a str>) -> String {
        match self.json {
            true => "[\n".to_string(),
            false => names.into_iter().collect::<Vec<_>>().join(",") + "\n",
        }
    }

    /// What comes after the last record.
    pub fn foot(self) -> &'static str {
        match self.json {
            true => "\n]\n",
            false => "",
        }
    }

    /// A record written into `out`, after the separator from the one
    /// before it unless it is the table's `first`; [`Record::end`] closes
    /// it.
    pub fn record(self, out: &mut Vec<u8>, first: bool) -> Record<'_> {
        if self.json {
            if !first {
                out.extend_from_slice(b",\n");
            }
            out.push(b'{');
        }
        Record {
            out,
            num: zmij::Buffer::new(),
            json: self.json,
            first: true,
        }
    }
}

/// A column's last number and its text ([`Record::repeated`]).
#[derive(Debug, Clone, Default)]
pub struct Repeated {
    bits: Option<u64>,
    text: String,
}

/// One record: its fields in order, as a CSV line or a JSON object,
/// numbers in their shortest round-trip form.
pub struct Record<'a> {
    out: &'a mut Vec<u8>,
    num: zmij::Buffer,
    json: bool,
    first: bool,
}

impl Record<'_> {
    #[inline]
    fn key(&mut self, name: &str) {
        if !self.first {
            self.out.push(b',');
        }
        self.first = false;
        if self.json {
            self.out.push(b'"');
            self.out.extend_from_slice(name.as_bytes());
            self.out.extend_from_slice(b"\":");
        }
    }

    /// A number; empty (CSV) or `null` (JSON) where it is undefined or not
    /// finite.
    #[inline]
    pub fn number(&mut self, name: &str, v: Option<f64>) {
        self.key(name);
        match v.filter(|x| x.is_finite()) {
            Some(x) => self
                .out
                .extend_from_slice(self.num.format_finite(x).as_bytes()),
            None if self.json => self.out.extend_from_slice(b"null"),
            None => {}
        }
    }

    /// A number that repeats from record to record (a grid's value),
    /// written as [`Record::number`] writes it but formatted only when it
    /// changes: `last` holds the column's last value and its text.
    pub fn repeated(&mut self, name: &str, v: f64, last: &mut Repeated) {
        if last.bits != Some(v.to_bits()) {
            last.text.clear();
            match v.is_finite() {
                true => last.text.push_str(self.num.format_finite(v)),
                false if self.json => last.text.push_str("null"),
                false => {}
            }
            last.bits = Some(v.to_bits());
        }
        self.key(name);
        self.out.extend_from_slice(last.text.as_bytes());
    }

    /// A word of the program's own (a verdict: no character to escape).
    pub fn word(&mut self, name: &str, w: &str) {
        self.key(name);
        if self.json {
            self.out.push(b'"');
        }
        self.out.extend_from_slice(w.as_bytes());
        if self.json {
            self.out.push(b'"');
        }
    }

    pub fn boolean(&mut self, name: &str, b: bool) {
        self.key(name);
        self.out
            .extend_from_slice(if b { b"true" as &[u8] } else { b"false" });
    }

    /// Any text (a message), quoted as CSV or JSON needs.
    pub fn text(&mut self, name: &str, t: &str) {
        self.key(name);
        if self.json {
            let quoted = serde_json::to_string(t).unwrap_or_else(|_| "\"?\"".into());
            self.out.extend_from_slice(quoted.as_bytes());
        } else {
            self.out.extend_from_slice(crate::csv::field(t).as_bytes());
        }
    }

    /// A field this record does not have: an empty CSV field, no JSON key.
    pub fn absent(&mut self) {
        if !self.json {
            self.key("");
        }
    }

    /// The record closed: the CSV line's end, or the JSON object's.
    pub fn end(self) {
        self.out.push(if self.json { b'}' } else { b'\n' });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two records with a number, an undefined number, a word, a boolean,
    /// a message with a comma and a quote, and a field the second lacks:
    /// the CSV and the JSON written out by hand.
    fn two(format: Format) -> String {
        let table = Table::new(format);
        let mut out = table.head(["x", "y", "v", "ok", "error"]).into_bytes();
        let mut last = Repeated::default();
        for (k, error) in [None, Some("a, \"b\"")].into_iter().enumerate() {
            let mut r = table.record(&mut out, k == 0);
            r.repeated("x", 0.1 + 0.2, &mut last);
            r.number("y", [None, Some(f64::NAN)][k]);
            r.word("v", "meets");
            r.boolean("ok", k == 0);
            match error {
                Some(e) => r.text("error", e),
                None => r.absent(),
            }
            r.end();
        }
        out.extend_from_slice(table.foot().as_bytes());
        String::from_utf8(out).unwrap()
    }

    #[test]
    fn records_as_csv_and_as_json() {
        assert_eq!(
            two(Format::Csv),
            "x,y,v,ok,error\n0.30000000000000004,,meets,true,\n0.30000000000000004,,meets,false,\"a, \"\"b\"\"\"\n"
        );
        assert_eq!(
            two(Format::Json),
            "[\n{\"x\":0.30000000000000004,\"y\":null,\"v\":\"meets\",\"ok\":true},\n{\"x\":0.30000000000000004,\"y\":null,\"v\":\"meets\",\"ok\":false,\"error\":\"a, \\\"b\\\"\"}\n]\n"
        );
        let parsed: serde_json::Value = serde_json::from_str(&two(Format::Json)).unwrap();
        assert_eq!(parsed[1]["error"], "a, \"b\"");
    }

    #[test]
    fn a_format_is_chosen_from_the_option_or_the_file() {
        assert_eq!(Format::printed(true), Format::Json);
        assert_eq!(Format::printed(false), Format::Text);
        assert_eq!(Format::of_file("a/b.csv"), Ok(Format::Csv));
        assert_eq!(Format::of_file("b.json"), Ok(Format::Json));
        assert!(Format::of_file("b.txt").is_err() && Format::of_file("json").is_err());
    }

    #[test]
    fn a_document_is_the_view_in_json_else_the_text() {
        let view = serde_json::json!({"a": 1.5, "b": [1, 2]});
        let text = || Ok("page\n".to_string());
        let json = Format::Json.document("f.toml", &view, text).unwrap();
        assert_eq!(
            json,
            "{\n  \"a\": 1.5,\n  \"b\": [\n    1,\n    2\n  ]\n}\n"
        );
        assert_eq!(
            Format::Text.document("f.toml", &view, text).unwrap(),
            "page\n"
        );
        // a number that is not finite is refused, naming the input
        #[derive(Serialize)]
        struct V {
            x: f64,
        }
        let e = Format::Json
            .document("f.toml", &V { x: f64::INFINITY }, text)
            .unwrap_err();
        assert!(e.to_string().starts_with("f.toml"), "{e}");
        // the text is not guarded here: the command guards its own page
        assert_eq!(
            Format::Text
                .document("f", &V { x: f64::NAN }, text)
                .unwrap(),
            "page\n"
        );
    }
}
