//! A reader for USAF Digital DATCOM's printed output (`for006.dat`, issue
//! 21 item 5): per Mach number, the static table (`CHARACTERISTICS AT
//! ANGLE OF ATTACK AND IN SIDESLIP`: CD, CLA, CMA, … per degree) and the
//! dynamic one (`DYNAMIC DERIVATIVES`: CLQ, CMQ, CLAD, CMAD, … per degree)
//! at α = 0, with the reference area, length and moment centre printed
//! above each — the points of [`stability_core::datcom`], which makes them
//! the tables of `[model.tables]` in the report's notation.
//!
//! The printout is FORTRAN's: a page starts with carriage control `1`,
//! its title names the table, its flight-condition row gives the Mach
//! number first and the reference dimensions last (SREF, CBARR, BLREF,
//! XCG, ZCG); a table's column header begins `ALPHA`, and each value of a
//! row is taken under the header whose name ends nearest the value's end
//! (so that a blank entry shifts nothing). `NDM` (no DATCOM method),
//! `NaN`, `******` (overflow) and blanks are "not given". Pages may repeat;
//! several cases (`NEXT CASE`) add their Mach numbers. When the output
//! holds several configurations (`BUILD`), the last one printed is taken.
//! The wing's apex x (XW) is read from the echoed `$SYNTHS` cards (0 when
//! absent, DATCOM's default), and the moment centre XCG too where it
//! agrees with the tables' rounded one.

use crate::Failure;
use crate::diag::{InputError, quote};
use stability_core::datcom::{DatcomError, Point, Reference, Tables};
use stability_core::display::{Num, sig};
use stability_core::geometry::Planform;
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

/// One table row at α = 0 of one page.
struct Row {
    page: Page,
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
        let tables = stability_core::datcom::tables(&output.points, planform, output.apex_x)
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
        let toks = tokens(body);
        let first_number = toks.first().is_some_and(|(t, _)| t.parse::<f64>().is_ok());
        if self.flight_pending && first_number {
            self.flight_pending = false;
            self.flight = Some(self.flight_row(&toks, start + 1)?);
            return Ok(());
        }
        if toks.first().is_some_and(|(t, _)| *t == "ALPHA") {
            self.header = Some(toks.iter().map(|(t, r)| (t.to_string(), r.end)).collect());
            return Ok(());
        }
        if let (Some(header), Some((mach, reference)), true) =
            (&self.header, self.flight, first_number)
        {
            let cells = self.cells(header, &toks, start + 1)?;
            if cells.first().and_then(|(_, v)| *v) == Some(0.0) {
                self.rows.push(Row {
                    page: self.page,
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
            out[k].1 = value(t).map_err(|_| {
                self.err(
                    start,
                    r.clone(),
                    name,
                    format!("`{}` is not a number (nor NDM, NaN or ******)", quote(t)),
                )
            })?;
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
        let set = |slot: &mut Option<f64>, name: &str| {
            if let Some(v) = column(row, name) {
                *slot = Some(v);
            }
        };
        match row.page {
            Page::Static => {
                set(&mut p.cd, "CD");
                set(&mut p.cla, "CLA");
                set(&mut p.cma, "CMA");
            }
            _ => {
                set(&mut p.clq, "CLQ");
                set(&mut p.cmq, "CMQ");
                set(&mut p.clad, "CLAD");
                set(&mut p.cmad, "CMAD");
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
    }

    #[test]
    fn the_tables_of_the_60_degree_delta() {
        use stability_core::geometry::Size;
        let p = Planform::new(60f64.to_radians(), 0.0, Size::RootChord(10.0)).unwrap();
        let o = output();
        let t = stability_core::datcom::tables(&o.points, &p, o.apex_x).unwrap();
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
        let d = stability_core::examples::tailless_delta_45();
        let used = |m: f64| {
            let one = stability_core::derivative_tables::DerivativeTables(vec![z_wdot.clone()]);
            one.apply(&d, t.reference_cg, m).unwrap().0.z_wdot
        };
        assert_eq!(used(1.2), d.z_wdot);
        // line 1136: CLAD −1.630E-02 at M 1.4, z_ẇ = −½C_Lα̇ per radian
        assert!((used(1.4) - 0.5 * 1.630e-2 * 180.0 / std::f64::consts::PI).abs() < 1e-12);
        // a planform of another size is refused, naming the reference
        let big = Planform::new(60f64.to_radians(), 0.0, Size::RootChord(12.0)).unwrap();
        let e = stability_core::datcom::tables(&o.points, &big, o.apex_x).unwrap_err();
        assert!(e.to_string().contains("reference area"), "{e}");
        // located at the flight-condition row of M 0.2 (line 119)
        let e = located("d.out", FILE, &e).to_string();
        assert!(e.starts_with("d.out:119:1: reference area"), "{e}");
    }
}
