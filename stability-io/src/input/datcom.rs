//! A reader for USAF Digital DATCOM's printed output (`for006.dat`, issue
//! 21 item 5): per Mach number, the static table (`CHARACTERISTICS AT
//! ANGLE OF ATTACK AND IN SIDESLIP`: CD, CLA, CMA, … per degree) and the
//! dynamic one (`DYNAMIC DERIVATIVES`: CLQ, CMQ, CLAD, CMAD, … per degree)
//! at α = 0, with the reference area, length and moment centre printed
//! above each — the points of [`stability_core::data::datcom`], which makes them
//! the tables of `[model.tables]` in the report's notation.
//!
//! The printout is FORTRAN's: a page starts with carriage control `1`,
//! its title names the table, its flight-condition row gives the Mach
//! number first and the reference dimensions last (SREF, CBARR, BLREF,
//! XCG, ZCG); a table's column header begins `ALPHA`, and each value of a
//! row is taken under the header whose name ends nearest the value's end
//! (so that a blank entry shifts nothing). `NDM` (no DATCOM method),
//! `NaN`, `******` (overflow) and blanks are "not given". Pages may repeat;
//! several cases (`NEXT CASE`) add their Mach numbers. Each table's unit
//! is read from its header — `DERIVATIVE (PER DEGREE)` or `(PER RADIAN)`
//! (DATCOM's `DERIV RAD` option), `DYNAMIC DERIVATIVES (PER …)` — and the
//! values made per degree, as [`Point`] holds them; a table whose header
//! states neither is an error at its column header. When the output
//! holds several configurations (`BUILD`), the last one printed is taken.
//! The wing's apex x (XW) is read from the echoed `$SYNTHS` cards (0 when
//! absent, DATCOM's default), and the moment centre XCG too where it
//! agrees with the tables' rounded one.

use crate::Failure;
use crate::diag::{InputError, quote};
use stability_core::data::datcom::{DatcomError, Point, Reference, Tables};
use stability_core::geometry::Planform;
use stability_core::numerics::display::{Num, sig};
use std::ops::Range;
use std::path::Path;

/// A DATCOM output, read.
#[derive(Debug, Clone, PartialEq)]
pub struct Output {
    pub path: String,
    /// The configuration whose tables were taken (`WING ALONE
    /// CONFIGURATION`).
    pub configuration: String,
    /// The Mach numbers, increasing.
    pub points: Vec<Point>,
    /// XW, the wing apex's x (DATCOM's axes), from the `$SYNTHS` cards.
    pub apex_x: f64,
}

/// Which table a page holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Page {
    Static,
    Dynamic,
    Other,
}

/// The unit a table's derivatives are printed in, from its header.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Unit {
    PerDegree,
    PerRadian,
}

impl Unit {
    /// The unit a header line states, if it states one.
    fn stated(line: &str) -> Option<Unit> {
        if line.contains("(PER DEGREE)") {
            Some(Unit::PerDegree)
        } else if line.contains("(PER RADIAN)") {
            Some(Unit::PerRadian)
        } else {
            None
        }
    }

    /// A derivative printed in this unit, per degree.
    fn per_degree(self, v: f64) -> f64 {
        match self {
            Unit::PerDegree => v,
            Unit::PerRadian => v / stability_core::data::datcom::PER_RADIAN,
        }
    }
}

/// One table row at α = 0 of one page.
struct Row {
    page: Page,
    /// The unit of its derivatives (its table's header).
    unit: Unit,
    configuration: String,
    mach: f64,
    reference: Reference,
    /// (column name, value) pairs.
    cells: Vec<(String, Option<f64>)>,
}

/// Read a DATCOM output (a regular file of at most
/// [`crate::files::MAX_INPUT_BYTES`]).
pub fn read(path: &Path) -> Result<Output, Failure> {
    let text = crate::files::read_input(path)?;
    Ok(parse(&path.display().to_string(), &text)?)
}

/// A DATCOM output read and made the tables of a planform.
#[derive(Debug, Clone, PartialEq)]
pub struct Datcom {
    pub output: Output,
    pub tables: Tables,
}

impl Datcom {
    /// The output at `path` made the tables of `planform`; an error names
    /// the DATCOM file (its line and column where the printout is at
    /// fault).
    pub fn load(path: &Path, planform: &Planform) -> Result<Datcom, Failure> {
        let text = crate::files::read_input(path)?;
        let output = parse(&path.display().to_string(), &text)?;
        let tables = stability_core::data::datcom::tables(&output.points, planform, output.apex_x)
            .map_err(|e| located(&output.path, &text, &e))?;
        Ok(Datcom { output, tables })
    }

    /// What the output gives, in words (a page's).
    pub fn describe(&self) -> String {
        let o = &self.output;
        let (lo, hi) = self.tables.lift_slope.range();
        format!(
            "DATCOM output {} ({}, {} Mach numbers, M {}–{}; moment centre h = {})",
            o.path,
            o.configuration,
            o.points.len(),
            Num(lo),
            Num(hi),
            sig(self.tables.reference_cg, 3)
        )
    }
}

/// A line's whitespace-separated tokens with their byte ranges in it.
fn tokens(line: &str) -> Vec<(&str, Range<usize>)> {
    let mut out = Vec::new();
    let mut start = None;
    for (i, c) in line.char_indices().chain([(line.len(), ' ')]) {
        match (c.is_whitespace(), start) {
            (true, Some(s)) => {
                out.push((&line[s..i], s..i));
                start = None;
            }
            (false, None) => start = Some(i),
            _ => {}
        }
    }
    out
}

/// A printed value: a number, or `None` for `NDM`, `NaN`, `******`.
fn value(cell: &str) -> Result<Option<f64>, ()> {
    if cell == "NDM" || cell.eq_ignore_ascii_case("nan") || cell.chars().all(|c| c == '*') {
        return Ok(None);
    }
    match cell.parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(Some(x)),
        _ => Err(()),
    }
}

/// The reader's state through the lines.
struct Reader<'a> {
    path: &'a str,
    text: &'a str,
    page: Page,
    /// Lines since the page's first (the title is the next non-blank one).
    title_pending: bool,
    configuration_pending: bool,
    configuration: String,
    flight_pending: bool,
    flight: Option<(f64, Reference)>,
    /// The unit the page's header states, once read.
    unit: Option<Unit>,
    header: Option<Vec<(String, usize)>>,
    rows: Vec<Row>,
}

impl Reader<'_> {
    fn err(&self, start: usize, range: Range<usize>, field: &str, m: String) -> InputError {
        InputError::at(
            self.path,
            self.text,
            start + range.start..start + range.end,
            field,
            m,
        )
    }

    fn line(&mut self, line: &str, start: usize) -> Result<(), InputError> {
        let body = line.get(1..).unwrap_or("");
        let trimmed = body.trim();
        if line.starts_with('1') {
            self.page = Page::Other;
            self.title_pending = trimmed.contains("AUTOMATED STABILITY AND CONTROL");
            (self.flight, self.header, self.flight_pending) = (None, None, false);
            self.unit = None;
            return Ok(());
        }
        if trimmed.is_empty() {
            return Ok(());
        }
        if self.title_pending {
            self.title_pending = false;
            self.configuration_pending = true;
            self.page = if trimmed.starts_with("CHARACTERISTICS AT ANGLE OF ATTACK") {
                Page::Static
            } else if trimmed.starts_with("DYNAMIC DERIVATIVES") {
                Page::Dynamic
            } else {
                Page::Other
            };
            return Ok(());
        }
        if self.page == Page::Other {
            return Ok(());
        }
        if self.configuration_pending {
            self.configuration_pending = false;
            self.configuration = trimmed.to_string();
            return Ok(());
        }
        if trimmed.contains("MOMENT REF. CENTER") {
            self.flight_pending = true;
            return Ok(());
        }
        if let Some(unit) = Unit::stated(trimmed) {
            self.unit = Some(unit);
            return Ok(());
        }
        let toks = tokens(body);
        let first_number = toks.first().is_some_and(|(t, _)| t.parse::<f64>().is_ok());
        if self.flight_pending && first_number {
            self.flight_pending = false;
            self.flight = Some(self.flight_row(&toks, start + 1)?);
            return Ok(());
        }
        if toks.first().is_some_and(|(t, _)| *t == "ALPHA") {
            if self.unit.is_none() {
                let r = toks[0].1.clone();
                return Err(self.err(
                    start + 1,
                    r,
                    "ALPHA",
                    "the table's header states no unit: DATCOM prints DERIVATIVE (PER DEGREE) or (PER RADIAN) above the columns (DYNAMIC DERIVATIVES (PER …) above the dynamic table); without it the values' unit is unknown".into(),
                ));
            }
            self.header = Some(toks.iter().map(|(t, r)| (t.to_string(), r.end)).collect());
            return Ok(());
        }
        if let (Some(header), Some((mach, reference)), Some(unit), true) =
            (&self.header, self.flight, self.unit, first_number)
        {
            let cells = self.cells(header, &toks, start + 1)?;
            if cells.first().and_then(|(_, v)| *v) == Some(0.0) {
                self.rows.push(Row {
                    page: self.page,
                    unit,
                    configuration: self.configuration.clone(),
                    mach,
                    reference,
                    cells,
                });
            }
        } else if !trimmed.starts_with("***") {
            // a line that ends the table (a note, a new block)
            self.header = None;
        }
        Ok(())
    }

    /// The flight-condition row: the Mach number first, the reference
    /// dimensions SREF, CBARR, BLREF, XCG, ZCG last.
    fn flight_row(
        &self,
        toks: &[(&str, Range<usize>)],
        start: usize,
    ) -> Result<(f64, Reference), InputError> {
        const NAMES: [&str; 5] = ["REF. AREA", "LONG. LENGTH", "LAT. LENGTH", "XCG", "ZCG"];
        if toks.len() < 6 {
            let r = toks.first().map_or(0..0, |(_, r)| r.clone());
            return Err(self.err(
                start,
                r,
                "flight conditions",
                format!(
                    "expected the Mach number and the five reference dimensions ({}), found {} values",
                    NAMES.join(", "),
                    toks.len()
                ),
            ));
        }
        let number = |k: usize, field: &str| -> Result<f64, InputError> {
            let (t, r) = &toks[k];
            value(t).ok().flatten().ok_or_else(|| {
                self.err(
                    start,
                    r.clone(),
                    field,
                    format!("`{}` is not a number", quote(t)),
                )
            })
        };
        let n = toks.len();
        let mach = number(0, "MACH")?;
        Ok((
            mach,
            Reference {
                area: number(n - 5, NAMES[0])?,
                length: number(n - 4, NAMES[1])?,
                moment_x: number(n - 2, NAMES[3])?,
            },
        ))
    }

    /// A table row's values, each under the header ending nearest it.
    fn cells(
        &self,
        header: &[(String, usize)],
        toks: &[(&str, Range<usize>)],
        start: usize,
    ) -> Result<Vec<(String, Option<f64>)>, InputError> {
        let mut out: Vec<(String, Option<f64>)> =
            header.iter().map(|(n, _)| (n.clone(), None)).collect();
        let mut taken = vec![false; header.len()];
        for (t, r) in toks {
            let k = (0..header.len())
                .min_by_key(|&k| header[k].1.abs_diff(r.end))
                .unwrap_or(0);
            let name = &header[k].0;
            if taken[k] {
                return Err(self.err(
                    start,
                    r.clone(),
                    name,
                    format!(
                        "two values fall under the column {name}; the row does not line up with its header"
                    ),
                ));
            }
            taken[k] = true;
            let at = |m: String| self.err(start, r.clone(), name, m);
            out[k].1 = value(t).map_err(|_| {
                at(format!(
                    "`{}` is not a number (nor NDM, NaN or ******)",
                    quote(t)
                ))
            })?;
            // a value the tables take lies in a table's range, as the
            // config's own tables' do
            if let Some(v) = out[k].1
                && TAKEN.contains(&name.as_str())
            {
                crate::limits::TABLE_VALUE.check(v).map_err(at)?;
            }
        }
        Ok(out)
    }
}

/// An error of the tables at the flight-condition row of the Mach number
/// it concerns (the file's, when it concerns none).
fn located(path: &str, text: &str, e: &DatcomError) -> InputError {
    let (mach, field) = match e {
        DatcomError::Reference { mach, what, .. } => (*mach, format!("reference {what}")),
        DatcomError::MomentCentres { mach, .. } => (*mach, "XCG".to_string()),
        DatcomError::Notation { mach, .. } => (*mach, "MACH".to_string()),
        _ => return InputError::file(path, e.to_string()),
    };
    let line = text
        .lines()
        .position(|l| {
            let t: Vec<&str> = l.get(1..).unwrap_or("").split_whitespace().collect();
            l.starts_with('0') && t.len() >= 6 && t[0].parse::<f64>() == Ok(mach)
        })
        .map_or(0, |i| i + 1);
    InputError {
        field,
        ..InputError::at_line(path, text, line, e.to_string())
    }
}

/// The value of `name` in the first `$SYNTHS` card echoed, if any.
fn synths(text: &str, name: &str) -> Option<f64> {
    let at = text.find("$SYNTHS")?;
    let rest = &text[at + "$SYNTHS".len()..];
    let card = &rest[..rest.find('$').unwrap_or(rest.len())];
    card.split(',')
        .filter_map(|kv| kv.split_once('='))
        .find(|(k, _)| k.trim() == name)
        .and_then(|(_, v)| v.trim().parse::<f64>().ok())
}

/// The moment centre as the `$SYNTHS` card gives it (XCG = 3.333333),
/// where the tables print it rounded (3.333): the tables' value otherwise.
fn exact_moment_centre(points: &mut [Point], text: &str) {
    if let Some(xcg) = synths(text, "XCG") {
        for p in points {
            if (p.reference.moment_x - xcg).abs() <= 5e-4 * (1.0 + xcg.abs()) {
                p.reference.moment_x = xcg;
            }
        }
    }
}

/// The columns whose values become tables.
const TAKEN: [&str; 7] = ["CD", "CLA", "CMA", "CLQ", "CMQ", "CLAD", "CMAD"];

/// The value of column `name` in a row (`None` where not given).
fn column(row: &Row, name: &str) -> Option<f64> {
    row.cells.iter().find(|(n, _)| n == name).and_then(|c| c.1)
}

/// Parse a DATCOM output's text.
pub fn parse(path: &str, text: &str) -> Result<Output, InputError> {
    let mut r = Reader {
        path,
        text,
        page: Page::Other,
        title_pending: false,
        configuration_pending: false,
        configuration: String::new(),
        flight_pending: false,
        flight: None,
        unit: None,
        header: None,
        rows: Vec::new(),
    };
    let mut offset = 0;
    for line in text.split_inclusive('\n') {
        let start = offset;
        offset += line.len();
        r.line(line.trim_end_matches(['\n', '\r']), start)?;
    }
    let Some(configuration) = r.rows.last().map(|row| row.configuration.clone()) else {
        return Err(InputError::file(
            path,
            "no static or dynamic derivative table at ALPHA = 0 found: is this DATCOM's printed output (for006.dat), run with ALSCHD including 0.0?",
        ));
    };
    let mut points: Vec<Point> = Vec::new();
    for row in r
        .rows
        .iter()
        .filter(|row| row.configuration == configuration)
    {
        let k = match points.iter().position(|p| p.mach == row.mach) {
            Some(k) => k,
            None => {
                points.push(empty(row.mach, row.reference));
                points.len() - 1
            }
        };
        let p = &mut points[k];
        // a coefficient as printed; a derivative per degree
        let set = |slot: &mut Option<f64>, name: &str, derivative: bool| {
            if let Some(v) = column(row, name) {
                *slot = Some(if derivative {
                    row.unit.per_degree(v)
                } else {
                    v
                });
            }
        };
        match row.page {
            Page::Static => {
                set(&mut p.cd, "CD", false);
                set(&mut p.cla, "CLA", true);
                set(&mut p.cma, "CMA", true);
            }
            _ => {
                set(&mut p.clq, "CLQ", true);
                set(&mut p.cmq, "CMQ", true);
                set(&mut p.clad, "CLAD", true);
                set(&mut p.cmad, "CMAD", true);
            }
        }
    }
    points.sort_by(|a, b| a.mach.total_cmp(&b.mach));
    exact_moment_centre(&mut points, text);
    Ok(Output {
        path: path.to_string(),
        configuration,
        points,
        apex_x: synths(text, "XW").unwrap_or(0.0),
    })
}

fn empty(mach: f64, reference: Reference) -> Point {
    Point {
        mach,
        reference,
        cd: None,
        cla: None,
        cma: None,
        clq: None,
        cmq: None,
        clad: None,
        cmad: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const FILE: &str = include_str!("../../tests/fixtures/datcom/delta60_h0.0.out");

    fn output() -> Output {
        parse("delta60_h0.0.out", FILE).unwrap()
    }

    fn at(o: &Output, mach: f64) -> Point {
        *o.points.iter().find(|p| p.mach == mach).unwrap()
    }

    #[test]
    fn every_mach_number_of_both_cases_is_read() {
        let o = output();
        let machs: Vec<f64> = o.points.iter().map(|p| p.mach).collect();
        assert_eq!(
            machs,
            [
                0.2, 0.4, 0.6, 0.7, 0.8, 0.85, 0.9, 0.95, 1.0, 1.05, 1.1, 1.15, 1.2, 1.3, 1.4, 1.5,
                1.6, 1.8, 2.0, 2.5, 3.0
            ]
        );
        assert_eq!(o.configuration, "WING ALONE CONFIGURATION");
        assert_eq!(o.apex_x, 0.0);
    }

    #[test]
    fn the_values_are_the_printed_ones() {
        let o = output();
        // line 119: M 0.200, SREF 57.735, CBARR 6.667, XCG 3.333 (3.333333
        // on the $SYNTHS card, line 4)
        let p = at(&o, 0.2);
        assert_eq!(
            p.reference,
            Reference {
                area: 57.735,
                length: 6.667,
                moment_x: 3.333333
            }
        );
        // line 123: CD 0.006, CLA 4.505E-02, CMA -1.684E-02
        assert_eq!(
            (p.cd, p.cla, p.cma),
            (Some(0.006), Some(4.505e-2), Some(-1.684e-2))
        );
        // line 138: CLQ 5.621E-02, CMQ -2.687E-02, CLAD 2.049E-02, CMAD -1.148E-02
        assert_eq!(
            (p.clq, p.cmq, p.clad, p.cmad),
            (
                Some(5.621e-2),
                Some(-2.687e-2),
                Some(2.049e-2),
                Some(-1.148e-2)
            )
        );
        // line 447: M 0.9, CL..CA NDM, CLA 5.067E-02, CMA -2.374E-02
        let p = at(&o, 0.9);
        assert_eq!(
            (p.cd, p.cla, p.cma),
            (Some(0.006), Some(5.067e-2), Some(-2.374e-2))
        );
        // line 463: CLQ 7.281E-02, CMQ -3.461E-02, CLAD 9.249E-03, CMAD -1.153E-02
        assert_eq!((p.clad, p.cmad), (Some(9.249e-3), Some(-1.153e-2)));
        // line 700: M 1.05, CLQ 8.253E-02, CMQ -3.350E-02, CLAD and CMAD NDM
        let p = at(&o, 1.05);
        assert_eq!(
            (p.clq, p.cmq, p.clad, p.cmad),
            (Some(8.253e-2), Some(-3.350e-2), None, None)
        );
        // line 963: M 1.2, CD 0.008, CLA 4.479E-02, CMA -2.248E-02
        let p = at(&o, 1.2);
        assert_eq!(
            (p.cd, p.cla, p.cma),
            (Some(0.008), Some(4.479e-2), Some(-2.248e-2))
        );
    }

    #[test]
    fn a_bad_cell_and_a_file_without_tables_are_named() {
        let bad = FILE.replacen("4.505E-02", "4.505X-02", 1);
        let e = parse("d.out", &bad).unwrap_err().to_string();
        assert!(
            e.starts_with("d.out:123:") && e.contains("CLA") && e.contains("4.505X-02"),
            "{e}"
        );
        let e = parse("d.out", "hello\n").unwrap_err().to_string();
        assert!(e.contains("no static or dynamic derivative table"), "{e}");
        // a row whose values do not line up with the header
        let shifted = FILE.replacen(
            "    0.0    0.006    0.000    0.0000   0.000    0.006   ******    4.505E-02",
            "    0.0    0.006    0.000    0.0000   0.000    0.006   ******4.505E-02 1.0",
            1,
        );
        assert!(parse("d.out", &shifted).is_err());
        // a value no derivative reaches, at its cell
        let huge = FILE.replacen("4.505E-02", "4.505E+99", 1);
        let e = parse("d.out", &huge).unwrap_err().to_string();
        assert!(
            e.starts_with("d.out:123:") && e.contains("CLA") && e.contains("must lie in"),
            "{e}"
        );
    }

    /// The fixture as DATCOM prints it with `DERIV RAD`: every header per
    /// radian and every derivative of the α = 0 rows (CLA, CMA; CLQ, CMQ,
    /// CLAD, CMAD) times 180/π, printed to four figures as DATCOM does.
    fn per_radian(text: &str) -> String {
        let scale = |cell: &str| -> String {
            let Ok(v) = cell.parse::<f64>() else {
                return cell.to_string();
            };
            let v = v * stability_core::data::datcom::PER_RADIAN;
            let e = if v == 0.0 {
                0
            } else {
                v.abs().log10().floor() as i32
            };
            format!("{:.3}E{:+03}", v / 10f64.powi(e), e)
        };
        let mut page = "";
        let mut out = String::new();
        for line in text.lines() {
            if line.contains("CHARACTERISTICS AT ANGLE OF ATTACK") {
                page = "static";
            } else if line.trim() == "DYNAMIC DERIVATIVES" {
                page = "dynamic";
            }
            let line = line.replace("(PER DEGREE)", "(PER RADIAN)");
            let tokens: Vec<&str> = line.split_whitespace().collect();
            let row = line.starts_with(' ')
                && tokens.first().is_some_and(|t| t.parse::<f64>() == Ok(0.0));
            // the derivative columns, by position in the row
            let columns: &[usize] = match (page, row, tokens.len()) {
                ("static", true, 12) => &[7, 8],
                ("dynamic", true, 10) => &[1, 2, 3, 4],
                _ => &[],
            };
            assert!(
                !row || page.is_empty() || !columns.is_empty(),
                "a row the test does not know: {line}"
            );
            let mut line = line.clone();
            let mut from = 0;
            for &k in columns {
                let new = scale(tokens[k]);
                assert_eq!(new.len(), tokens[k].len(), "{}", tokens[k]);
                let at = from + line[from..].find(tokens[k]).unwrap();
                line.replace_range(at..at + new.len(), &new);
                from = at + new.len();
            }
            out.push_str(&line);
            out.push('\n');
        }
        out
    }

    #[test]
    fn a_table_headed_per_radian_is_read_per_radian() {
        let radian = per_radian(FILE);
        assert!(radian.contains("DYNAMIC DERIVATIVES (PER RADIAN)"));
        let (o, r) = (output(), parse("rad.out", &radian).unwrap());
        assert_eq!(o.points.len(), r.points.len());
        for (d, r) in o.points.iter().zip(&r.points) {
            let close = |a: Option<f64>, b: Option<f64>| match (a, b) {
                (Some(a), Some(b)) => (a - b).abs() <= 1e-3 * a.abs(),
                (a, b) => a == b,
            };
            for (a, b) in [
                (d.cla, r.cla),
                (d.cma, r.cma),
                (d.clq, r.clq),
                (d.cmq, r.cmq),
                (d.clad, r.clad),
                (d.cmad, r.cmad),
                (d.cd, r.cd),
            ] {
                assert!(close(a, b), "M = {}: {a:?} per degree, {b:?} read", d.mach);
            }
        }
        // line 123's CLA 4.505E-02 per degree is printed 2.581E+00 per radian
        assert!(radian.contains("2.581E+00"), "the test's file");
        assert!((at(&r, 0.2).cla.unwrap() - 0.04505).abs() < 1e-5);
        // a header that states no unit is an error at the table's columns
        let bare = FILE.replacen("DYNAMIC DERIVATIVES (PER DEGREE)", "DYNAMIC DERIVATIVES", 1);
        let e = parse("d.out", &bare).unwrap_err().to_string();
        assert!(
            e.starts_with("d.out:136:") && e.contains("states no unit"),
            "{e}"
        );
    }

    #[test]
    fn the_tables_of_the_60_degree_delta() {
        use stability_core::geometry::Size;
        let p = Planform::new(60f64.to_radians(), 0.0, Size::RootChord(10.0)).unwrap();
        let o = output();
        let t = stability_core::data::datcom::tables(&o.points, &p, o.apex_x).unwrap();
        // XCG 3.333333, x̄ = 10/3: h_r = (3.333333 − 3.3333…)/6.6667 = −5e-8
        assert!((t.reference_cg + 5e-8).abs() < 1e-9, "{}", t.reference_cg);
        // a = 0.04505 per degree = 2.581175 per radian at M 0.2
        let a = t.lift_slope.at(0.2).unwrap().value;
        assert!((a - 2.581_174_867).abs() < 1e-8, "{a}");
        // H₀ = h_r − CMA/CLA = −5e-5 + 0.01684/0.04505 = 0.373758 at M 0.2
        let h0 = t.aerodynamic_centre.at(0.2).unwrap().value;
        assert!(
            (h0 - (t.reference_cg + 0.01684 / 0.04505)).abs() < 1e-12,
            "{h0}"
        );
        // z_ẇ (CLAD) is NDM at M 1.05–1.3 (lines 700–1058): there the
        // computed value is kept; at M 1.0 and 1.4 it is DATCOM's
        let z_wdot = t.derivatives.0.iter().find(|d| d.name == "z_wdot").unwrap();
        assert_eq!(z_wdot.missing, [1.05, 1.1, 1.15, 1.2, 1.3]);
        let d = stability_core::design::examples::tailless_delta_45();
        let used = |m: f64| {
            let one =
                stability_core::aerodynamics::models::derivative_tables::DerivativeTables(vec![
                    z_wdot.clone(),
                ]);
            one.apply(&d, t.reference_cg, m).unwrap().0.z_wdot
        };
        assert_eq!(used(1.2), d.z_wdot);
        // line 1136: CLAD −1.630E-02 at M 1.4, z_ẇ = −½C_Lα̇ per radian
        assert!((used(1.4) - 0.5 * 1.630e-2 * 180.0 / std::f64::consts::PI).abs() < 1e-12);
        // a planform of another size is refused, naming the reference
        let big = Planform::new(60f64.to_radians(), 0.0, Size::RootChord(12.0)).unwrap();
        let e = stability_core::data::datcom::tables(&o.points, &big, o.apex_x).unwrap_err();
        assert!(e.to_string().contains("reference area"), "{e}");
        // located at the flight-condition row of M 0.2 (line 119)
        let e = located("d.out", FILE, &e).to_string();
        assert!(e.starts_with("d.out:119:1: reference area"), "{e}");
    }
}
