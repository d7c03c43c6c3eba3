//! A derivative set from one notation into another (`convert`), by the
//! factors derived in `stability-core/specs/notation.toml` (see
//! docs/notations.md): the values, and the file or JSON object they are
//! written as. No value that is not finite is written: a conversion that
//! overflows is an error at the value that caused it.

use crate::diag::InputError;
use crate::input::dimensional_notation::{DIMENSIONAL, DimensionalFile};
use crate::input::rows::{C_L, DERIVATIVES, FLIGHT, QUARTIC};
use crate::input::tabled::{needed_rows, uses_parameter};
use crate::input::{AnyFile, DerivativeFile};
use serde::Serialize;
use stability_core::data::dimensional::{
    DimensionalDerivatives, DimensionalModel, Reference, THETA0_MAX,
};
use stability_core::data::notation::{Notation, NotationError, Values, tables};
use stability_core::numerics::display::{Num, sig};
use std::collections::BTreeMap;
use std::fmt::Write;

/// A notation a set can be written in: one of
/// `stability-core/specs/notation.toml`'s, or the dimensional one (AVL's is
/// read only).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Target {
    Table(Notation),
    Dimensional,
}

impl Target {
    pub fn name(self) -> &'static str {
        match self {
            Target::Table(n) => n.name(),
            Target::Dimensional => DIMENSIONAL,
        }
    }
}

/// The notation a file is written in (`notation`), and the form its values
/// were read in (`american_cl` for an `american` file in the C_L/C_D form).
pub fn written_in(any: &AnyFile) -> (&str, &'static str) {
    match any {
        AnyFile::Report(f) => (f.notation.as_str(), f.form),
        AnyFile::Dimensional(_) => (DIMENSIONAL, DIMENSIONAL),
    }
}

/// A conversion done: what it writes. (One per conversion: its size does
/// not matter.)
#[allow(clippy::large_enum_variant)]
pub enum Conversion<'a> {
    /// Into one of the notations of `stability-core/specs/notation.toml`.
    Table {
        input: std::borrow::Cow<'a, DerivativeFile>,
        from: &'a str,
        to: Notation,
        values: Values,
    },
    /// Into `notation = "dimensional"`.
    Dimensional(Dimensional<'a>),
}

/// Converts `any`, written in notation `from`, into `to`: every value of
/// the result finite ([`crate::finite`]), and a dimensional result one that
/// a dimensional file can hold (g > 0, |θ₀| ≤ 89°). (Whether the target
/// notation can express the whole set is [`Conversion::toml`]'s check: the
/// JSON gives `null` for a value the input does not determine.)
pub fn convert<'a>(
    any: &'a AnyFile,
    from: &'a str,
    to: Target,
) -> Result<Conversion<'a>, InputError> {
    let c = conversion(any, from, to)?;
    match &c {
        Conversion::Table {
            input,
            from,
            to,
            values,
        } => crate::finite::guard(&input.path, &ConvertJson::new(input, from, *to, values))?,
        Conversion::Dimensional(d) => crate::finite::guard(d.path, &d.view())?,
    }
    Ok(c)
}

fn conversion<'a>(
    any: &'a AnyFile,
    from: &'a str,
    to: Target,
) -> Result<Conversion<'a>, InputError> {
    use std::borrow::Cow;
    match (any, to) {
        (AnyFile::Dimensional(d), Target::Dimensional) => {
            stability_attitude(d)?;
            Ok(Conversion::Dimensional(Dimensional {
                path: &d.path,
                from,
                model: d.model.in_stability_axes(),
                reference: d.reference,
                warnings: &d.warnings,
            }))
        }
        (AnyFile::Dimensional(d), Target::Table(to)) => {
            let input = d.to_derivative_file()?;
            let values = converted(&input, to)?;
            Ok(Conversion::Table {
                input: Cow::Owned(input),
                from,
                to,
                values,
            })
        }
        (AnyFile::Report(input), Target::Table(to)) => {
            let values = converted(input, to)?;
            Ok(Conversion::Table {
                input: Cow::Borrowed(input),
                from,
                to,
                values,
            })
        }
        (AnyFile::Report(input), Target::Dimensional) => {
            let Some(dim) = &input.dimensional else {
                return Err(InputError::file(
                    &input.path,
                    "--to dimensional needs the flight condition in seconds: a [dimensional] table with V, rho, S, chord and mass (SI)",
                ));
            };
            let c_l = input.derivatives.c_l;
            if c_l <= 0.0 {
                return Err(input.error_at(
                    C_L,
                    format!(
                        "--to dimensional: C_L = {} gives g = C_L·V/τ ≤ 0, which a dimensional set cannot hold (its g is positive): the report's set must be of level flight with C_L > 0",
                        Num(c_l)
                    ),
                ));
            }
            let (model, reference) = DimensionalModel::from_report_with(&input.derivatives, dim);
            Ok(Conversion::Dimensional(Dimensional {
                path: &input.path,
                from,
                model,
                reference: Some(reference),
                warnings: &input.warnings,
            }))
        }
    }
}

/// A dimensional set's stability-axis attitude θ₀ − α₀ within the ±89°
/// a dimensional file holds.
fn stability_attitude(d: &DimensionalFile) -> Result<(), InputError> {
    let theta0 = d.model.in_stability_axes().trim.theta0;
    if theta0.abs() <= THETA0_MAX {
        return Ok(());
    }
    Err(d.error_at(
        "theta0",
        format!(
            "--to dimensional: in stability axes θ₀ = θ₀ − α₀ = {}°, beyond the ±89° a dimensional set holds (the x axis near the vertical): there is no such set in stability axes to write",
            sig(theta0.to_degrees(), 4)
        ),
    ))
}

impl Conversion<'_> {
    /// The reader's warnings about the set converted (for a dimensional
    /// set into a table, those of its turn into the report's notation).
    pub fn warnings(&self) -> &[String] {
        match self {
            Conversion::Table { input, .. } => &input.warnings,
            Conversion::Dimensional(d) => d.warnings,
        }
    }

    /// The converted set as a derivative file of the target notation, one
    /// the program's own reader accepts: an error (naming what is missing)
    /// when the target notation cannot express the set, as Ribner's C_Lα,
    /// which holds z_w with C_D, cannot without C_D.
    pub fn toml(&self) -> Result<String, InputError> {
        if let Conversion::Table {
            input, to, values, ..
        } = self
        {
            expressible(input, *to, values)?;
        }
        let text = self.unchecked_toml();
        self.reads_back(&text)?;
        Ok(text)
    }

    /// The file's path.
    fn path(&self) -> &str {
        match self {
            Conversion::Table { input, .. } => &input.path,
            Conversion::Dimensional(d) => d.path,
        }
    }

    /// The converted file, read back by the program's reader: a file it
    /// would refuse is never written.
    fn reads_back(&self, text: &str) -> Result<(), InputError> {
        const CONVERTED: &str = "<converted>";
        let read = match self {
            Conversion::Dimensional(_) => {
                crate::input::dimensional_notation::parse(CONVERTED, text)
                    .map(|_| ())
                    .map_err(crate::Failure::Input)
            }
            Conversion::Table { .. } => crate::input::parse(CONVERTED, text).map(|_| ()),
        };
        read.map_err(|e| {
            let why = match &e {
                crate::Failure::Input(e) => format!("{}{}", e.location(), e.message),
                crate::Failure::Io(e) => e.to_string(),
            };
            InputError::file(
                self.path(),
                format!("the converted file would not be read back ({why}); nothing written"),
            )
        })
    }

    fn unchecked_toml(&self) -> String {
        match self {
            Conversion::Table {
                input,
                from,
                to,
                values,
            } => to_toml(input, from, *to, values),
            Conversion::Dimensional(d) => d.toml(),
        }
    }

    /// The `convert --json` object.
    pub fn json(&self) -> serde_json::Value {
        let v = match self {
            Conversion::Table {
                input,
                from,
                to,
                values,
            } => serde_json::to_value(ConvertJson::new(input, from, *to, values)),
            Conversion::Dimensional(d) => serde_json::to_value(d.view()),
        };
        v.unwrap_or_default()
    }
}

/// The values in notation `to`, every one finite (the library refuses a
/// conversion that overflows; the error is placed at the value it came
/// from).
pub fn converted(input: &DerivativeFile, to: Notation) -> Result<Values, InputError> {
    to.from_report(&input.report, &input.parameters)
        .map_err(|e| {
            let (notation, quantity) = match &e {
                NotationError::Overflow { quantity, .. } => (to, *quantity),
                NotationError::NonFiniteInput { quantity, .. } => (Notation::REPORT, *quantity),
            };
            let row = notation
                .row_of(quantity)
                .or_else(|| tables::ROWS.iter().position(|r| *r == quantity));
            let source = row
                .and_then(|i| input.report[i].map(|v| (i, v)))
                .map(|(i, v)| {
                    format!(
                        " ({} = {} in the report's notation)",
                        Notation::REPORT.name_of(i),
                        Num(v)
                    )
                })
                .unwrap_or_default();
            let message = format!("{e}{source}; nothing written");
            match row {
                Some(i) => input.error_at(i, message),
                None => InputError::file(&input.path, message),
            }
        })
}

/// Every quantity of the quartic that `to` names (and the C_L/C_D form's
/// C_D) determined by the input: else an error naming what the target
/// needs and the input lacks (`--to ribner needs C_D, for its C_La …`).
fn expressible(input: &DerivativeFile, to: Notation, values: &Values) -> Result<(), InputError> {
    let names = to.names();
    let needed = QUARTIC.iter().copied().chain(needed_rows(to));
    let Some((i, theirs)) = needed
        .filter(|&i| values[i].is_none())
        .find_map(|i| names[i].map(|n| (i, n)))
    else {
        return Ok(());
    };
    let rows = lacking_rows(input, to, i);
    let what: Vec<&str> = rows.iter().map(|&j| Notation::REPORT.name_of(j)).collect();
    let what = match what.as_slice() {
        [] => "a quantity the file does not give".to_string(),
        ["c_d"] => "C_D".to_string(),
        _ => what.join(" and "),
    };
    let give = if input.form == DIMENSIONAL {
        ", which a dimensional set does not carry apart from its other derivatives: convert to report, garner or american instead".to_string()
    } else {
        format!(": give {}", lacking_names(input, &rows))
    };
    Err(InputError::file(
        &input.path,
        format!(
            "--to {} needs {what}, for its `{theirs}` (the report's {}){give}",
            to.name(),
            Notation::REPORT.name_of(i)
        ),
    ))
}

/// The rows, unknown in the input, without which `to` cannot determine
/// its row `i` (found by giving each a value in turn).
fn lacking_rows(input: &DerivativeFile, to: Notation, i: usize) -> Vec<usize> {
    (0..input.report.len())
        .filter(|&j| input.report[j].is_none())
        .filter(|&j| {
            let mut probe = input.report;
            probe[j] = Some(1.0);
            to.from_report(&probe, &input.parameters)
                .is_ok_and(|v| v[i].is_some())
        })
        .collect()
}

/// Where the input's notation takes each of `rows`: `c_d in [flight]`.
fn lacking_names(input: &DerivativeFile, rows: &[usize]) -> String {
    let theirs = Notation::named(input.form);
    let names: Vec<String> = rows
        .iter()
        .map(|&j| match theirs.and_then(|n| n.names()[j]) {
            Some(n) if FLIGHT.contains(&j) => format!("{n} in [flight]"),
            Some(n) => format!("{n} in [derivatives]"),
            None => format!("{} in [report]", Notation::REPORT.name_of(j)),
        })
        .collect();
    names.join(" and ")
}

/// The `convert --json` object: the notations, the values in the target
/// notation by its names (null where the input does not determine one),
/// the report's values, and the parameters.
#[derive(Serialize)]
pub struct ConvertJson<'a> {
    from: &'a str,
    to: &'a str,
    values: BTreeMap<&'static str, Option<f64>>,
    report: BTreeMap<&'static str, f64>,
    parameters: BTreeMap<&'static str, f64>,
}

impl<'a> ConvertJson<'a> {
    pub fn new(
        input: &DerivativeFile,
        from: &'a str,
        to: Notation,
        values: &Values,
    ) -> ConvertJson<'a> {
        let theirs = to.names().iter().zip(values);
        let ours = Notation::REPORT.names().iter().zip(&input.report);
        ConvertJson {
            from,
            to: to.name(),
            values: theirs.filter_map(|(n, v)| n.map(|n| (n, *v))).collect(),
            report: ours.filter_map(|(n, v)| Some(((*n)?, (*v)?))).collect(),
            parameters: tables::PARAMETERS
                .iter()
                .copied()
                .zip(input.parameters)
                .collect(),
        }
    }
}

/// One table of the TOML output: the notation's names for `rows`.
fn section(s: &mut String, title: &str, rows: &[usize], to: Notation, values: &Values) {
    let entries: Vec<(usize, &str)> = rows
        .iter()
        .filter_map(|&i| to.names()[i].map(|n| (i, n)))
        .collect();
    if entries.is_empty() {
        return;
    }
    let _ = writeln!(s, "\n[{title}]");
    for (i, n) in entries {
        match values[i] {
            Some(v) => {
                let _ = writeln!(s, "{n} = {v:?}");
            }
            None => {
                let _ = writeln!(
                    s,
                    "# {n}: not determined by the input (a quantity it depends on is missing)"
                );
            }
        }
    }
}

fn to_toml(input: &DerivativeFile, from: &str, to: Notation, values: &Values) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "# {}, converted from notation `{from}` to `{}` by delta-stability",
        input.path,
        to.name()
    );
    let _ = writeln!(
        s,
        "# ({}); factors derived in stability-core/specs/notation.toml, see docs/notations.md",
        to.title()
    );
    let _ = writeln!(s, "notation = \"{}\"", to.name());
    section(&mut s, "derivatives", &DERIVATIVES, to, values);
    section(&mut s, "flight", &FLIGHT, to, values);
    let report_names = Notation::REPORT.names();
    let lacking: Vec<usize> = QUARTIC
        .into_iter()
        .filter(|&i| to.names()[i].is_none() && input.report[i].is_some())
        .collect();
    if !lacking.is_empty() {
        let _ = writeln!(
            s,
            "\n# quantities notation `{}` does not define, in the report's names",
            to.name()
        );
        let _ = writeln!(s, "[report]");
        for i in lacking {
            if let (Some(n), Some(v)) = (report_names[i], input.report[i]) {
                let _ = writeln!(s, "{n} = {v:?}");
            }
        }
    }
    for (k, p) in tables::PARAMETERS.iter().enumerate() {
        if uses_parameter(to, k) {
            let _ = writeln!(s, "\n[parameters]\n{p} = {:?}", input.parameters[k]);
        }
    }
    if let Some(d) = &input.dimensional {
        let _ = writeln!(
            s,
            "\n[dimensional]\nV = {:?}\nrho = {:?}\nS = {:?}\nchord = {:?}\nmass = {:?}",
            d.v, d.rho, d.s, d.chord, d.mass
        );
    }
    s
}

/// A conversion into `notation = "dimensional"`: the set in stability
/// axes, with its reference quantities.
pub struct Dimensional<'a> {
    /// The reader's warnings about the set converted.
    warnings: &'a [String],
    path: &'a str,
    from: &'a str,
    model: DimensionalModel,
    reference: Option<Reference>,
}

/// The `convert --to dimensional --json` object.
#[derive(Serialize)]
struct DimensionalJson<'a> {
    from: &'a str,
    to: &'a str,
    model: &'a DimensionalModel,
    reference: &'a Option<Reference>,
}

impl Dimensional<'_> {
    /// The `convert --to dimensional --json` object.
    fn view(&self) -> DimensionalJson<'_> {
        DimensionalJson {
            from: self.from,
            to: DIMENSIONAL,
            model: &self.model,
            reference: &self.reference,
        }
    }

    /// The set as a `notation = "dimensional"` file.
    fn toml(&self) -> String {
        let m = &self.model;
        let mut s = String::new();
        let _ = writeln!(
            s,
            "# {}, converted from notation `{}` to `dimensional` by delta-stability\n# (derivatives per unit mass and inertia in stability axes; see docs/dimensional.md)",
            self.path, self.from
        );
        let _ = writeln!(
            s,
            "notation = \"dimensional\"\naxes = \"{}\"\nunits = \"{}\"\n\n[derivatives]",
            m.axes.as_str(),
            m.units.name()
        );
        for (n, v) in DimensionalDerivatives::NAMES
            .iter()
            .zip(m.derivatives.values())
        {
            let _ = writeln!(s, "{n} = {v:?}");
        }
        let t = &m.trim;
        let _ = writeln!(
            s,
            "\n[flight]\nU0 = {:?}\nW0 = {:?}\ntheta0 = {:?}  # degrees\ng = {:?}",
            t.u0,
            t.w0,
            t.theta0.to_degrees(),
            t.g
        );
        if let Some(r) = &self.reference {
            let _ = writeln!(s, "\n[reference]\nchord = {:?}", r.chord);
            match &r.physical {
                Some(p) => {
                    let _ = writeln!(
                        s,
                        "rho = {:?}\nS = {:?}\nmass = {:?}\nI_y = {:?}",
                        p.rho, p.s, p.mass, p.i_y
                    );
                }
                None => {
                    let _ = writeln!(s, "mu1 = {:?}\ni_b = {:?}", r.mu1, r.i_b);
                }
            }
        }
        s
    }
}
