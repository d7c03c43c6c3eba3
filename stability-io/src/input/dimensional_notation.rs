//! The reader for `notation = "dimensional"`: derivatives per unit mass
//! and inertia as handbooks print them (NASA CR-2144, Etkin & Reid,
//! Nelson), in body or stability axes, ft–slug–s or SI.
//!
//! ```toml
//! notation = "dimensional"
//! axes = "body"        # "body" or "stability" (required)
//! units = "ft"         # "ft": ft, slug, s, g = 32.174; "si": m, kg, s, g = 9.80665 (required)
//! [derivatives]        # per unit mass (X, Z) and per unit pitching inertia (M)
//! X_u = -0.021         # required: X_u X_w Z_u Z_w M_u M_w M_q
//! # optional, 0 if not given: X_wdot X_udot X_q Z_wdot Z_udot Z_q M_wdot M_udot
//! [flight]
//! U0 = 311.0           # trim velocity along x (or V and alpha0 in degrees)
//! W0 = 10.3            # trim velocity along z (body axes; 0 in stability axes)
//! theta0 = 1.9         # pitch attitude of x, degrees (required in body axes)
//! g = 32.174           # optional: the units' standard g
//! [reference]          # optional: for the report's notation (τ, μ₁, i_B, eq 41)
//! chord = 27.3         # the reference chord c̄ (ft or m)
//! rho = 5.909e-4       # with S and mass (or weight): μ₁ = m/(½ρSc̄)
//! S = 5500.0
//! weight = 636636.0    # lbf or N (or mass in slug or kg)
//! I_y = 3.31e7         # i_B = I_y/(mc̄²) (or mu1 = …, i_b = … directly)
//! ```
//!
//! A body-axis set is never read as stability axes: `axes` is required, a
//! body-axis set needs θ₀, and W₀ ≠ 0 in stability axes is an error. A name
//! of another notation (`C_Lalpha`, `x_u`, `mu1` …) is an error that says
//! which notation it belongs to; a misspelt one suggests the nearest.

mod forms;
mod plausible;

use super::DerivativeFile;
use super::raw::{Ctx, Entries, Table, toml_error};
use super::suggest::{did_you_mean, nearest};
use crate::diag::{InputError, quote};
use num_complex::Complex64;
use serde::Deserialize;
use stability_core::analysis::Analysis;
use stability_core::data::dimensional::report::GAMMA0_NEGLIGIBLE;
use stability_core::data::dimensional::{
    Axes, DimensionalAnalysis, DimensionalDerivatives, DimensionalError, DimensionalModel, Form,
    Reference, Trim, Units,
};
use stability_core::data::notation::{Notation, report_values, tables};
use stability_core::numerics::display::Num;
use stability_core::numerics::display::sig;
use std::collections::BTreeMap;
use std::ops::Range;
use toml::Spanned;

/// The notation's name in files.
pub const DIMENSIONAL: &str = "dimensional";

/// The derivatives a file must give.
const REQUIRED: [&str; 7] = ["X_u", "X_w", "Z_u", "Z_w", "M_u", "M_w", "M_q"];
/// The `[flight]` names.
const FLIGHT: [&str; 6] = ["U0", "W0", "theta0", "g", "V", "alpha0"];
/// The `[reference]` names.
const REFERENCE: [&str; 8] = ["chord", "rho", "S", "mass", "weight", "I_y", "mu1", "i_b"];

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFile {
    notation: Spanned<String>,
    /// The table's form: "per_unit_mass" (the default), "per_force", "alpha".
    form: Option<Spanned<String>>,
    axes: Option<Spanned<String>>,
    units: Option<Spanned<String>>,
    derivatives: Option<Table>,
    flight: Option<Table>,
    reference: Option<Table>,
    /// Tables of the other notations: named, to say where their contents go.
    dimensional: Option<Spanned<toml::Value>>,
    report: Option<Spanned<toml::Value>>,
    parameters: Option<Spanned<toml::Value>>,
    st_file: Option<Spanned<toml::Value>>,
}

/// A `notation = "dimensional"` file, read and checked.
#[derive(Debug, Clone)]
pub struct DimensionalFile {
    pub path: String,
    /// The form the `[derivatives]` table was printed in (converted into
    /// the model's, per unit mass and inertia).
    pub form: Form,
    pub model: DimensionalModel,
    /// The `[reference]` quantities, when given.
    pub reference: Option<Reference>,
    /// Inconsistencies worth a user's attention (not errors).
    pub warnings: Vec<String>,
    /// Where each value was given, by the file's name (`X_u`, `U0`,
    /// `chord`, …): an error with an empty message.
    pub origins: BTreeMap<&'static str, InputError>,
    /// The `notation` line: where an error with no value of its own goes.
    pub at_notation: InputError,
}

impl DimensionalFile {
    /// An error about the value called `input`, where it was given (at the
    /// `notation` line when it was not given).
    pub fn error_at(&self, input: &str, message: impl Into<String>) -> InputError {
        let at = self.origins.get(input).unwrap_or(&self.at_notation);
        InputError {
            message: message.into(),
            ..at.clone()
        }
    }

    /// The analysis of the set, its errors placed at the value at fault.
    pub fn analysis(&self) -> Result<DimensionalAnalysis, InputError> {
        DimensionalAnalysis::of(&self.model, self.reference.as_ref()).map_err(|e| {
            let at = match blame(&e) {
                "notation" => self.most_extreme(),
                name => name,
            };
            let mut message = e.to_string();
            if matches!(e, DimensionalError::MassNotPositive { .. }) && self.form != Form::PerForce
            {
                message.push_str(" (or set form = \"per_force\" with [reference] mass and I_y)");
            }
            self.error_at(at, message)
        })
    }

    /// The input most extreme in magnitude, largest or smallest (the
    /// likeliest cause of an overflow).
    pub fn most_extreme(&self) -> &'static str {
        let t = &self.model.trim;
        let names = DimensionalDerivatives::NAMES
            .into_iter()
            .chain(["U0", "W0", "g"]);
        let values = self
            .model
            .derivatives
            .values()
            .into_iter()
            .chain([t.u0, t.w0, t.g]);
        let extreme = |v: f64| if v == 0.0 { 0.0 } else { v.abs().log10().abs() };
        names
            .zip(values)
            .max_by(|a, b| extreme(a.1).total_cmp(&extreme(b.1)))
            .map_or("notation", |(n, _)| n)
    }
}

/// The file's name of the value a library error is about.
fn blame(e: &DimensionalError) -> &'static str {
    match e {
        DimensionalError::Invalid(e) => e.quantity(),
        DimensionalError::Attitude { .. } => "theta0",
        DimensionalError::StabilityW0 { .. } => "W0",
        DimensionalError::Singular { .. } | DimensionalError::MassNotPositive { .. } => "Z_wdot",
        _ => "notation",
    }
}

/// Whether `text` is a `notation = "dimensional"` file (a file that does
/// not parse is not; its reader reports why).
pub fn is_dimensional(text: &str) -> bool {
    #[derive(Deserialize)]
    struct Peek {
        notation: Option<String>,
    }
    toml::from_str::<Peek>(text).is_ok_and(|p| p.notation.as_deref() == Some(DIMENSIONAL))
}

/// Read a `notation = "dimensional"` file's text.
pub fn parse(path: &str, text: &str) -> Result<DimensionalFile, InputError> {
    let raw: RawFile = toml::from_str(text).map_err(|e| toml_error(path, text, &e))?;
    let cx = Ctx { path, text };
    misplaced_tables(&cx, &raw)?;
    let mut r = Reader {
        cx: &cx,
        origins: BTreeMap::new(),
        warnings: Vec::new(),
        at_notation: cx.err(raw.notation.span(), "notation", ""),
    };
    r.unknown_fields(&raw)?;
    let axes = r.axes(&raw)?;
    let units = r.units(&raw)?;
    let form = r.form(&raw, axes)?;
    let trim = r.flight(&raw, axes, units)?;
    let given = r.given("reference", &raw.reference, &REFERENCE)?;
    let inertia = r.inertia(&raw, form, &given, units, trim.g)?;
    let derivatives = r.derivatives(&raw, form, &trim, inertia)?;
    let reference = r.reference(&raw, &given, form, units, trim.g)?;
    let mut file = DimensionalFile {
        path: path.to_string(),
        form,
        model: DimensionalModel {
            axes,
            units,
            derivatives,
            trim,
        },
        reference,
        warnings: r.warnings,
        origins: r.origins,
        at_notation: r.at_notation,
    };
    file.model
        .check()
        .map_err(|e| file.error_at(blame(&e), e.to_string()))?;
    if let Some(reference) = &file.reference {
        reference
            .check()
            .map_err(|e| file.error_at(blame(&e), e.to_string()))?;
    }
    let warnings = file.implausible();
    file.warnings.extend(warnings);
    Ok(file)
}

/// The tables of the other notations, each with where its contents go.
fn misplaced_tables(cx: &Ctx<'_>, raw: &RawFile) -> Result<(), InputError> {
    let reference = "in notation = \"dimensional\" the reference quantities go in [reference]: chord, rho, S, mass (or weight), I_y (or mu1, i_b)";
    for (name, v, message) in [
        ("[dimensional]", &raw.dimensional, reference),
        (
            "[report]",
            &raw.report,
            "a [report] table belongs to the notations of `convert --help`; a dimensional set gives its derivatives per unit mass and inertia in [derivatives]",
        ),
        (
            "[parameters]",
            &raw.parameters,
            "notation = \"dimensional\" has no parameters",
        ),
        (
            "st_file",
            &raw.st_file,
            "`st_file` belongs to notation = \"avl\"",
        ),
    ] {
        if let Some(v) = v {
            return Err(cx.err(v.span(), name, message));
        }
    }
    Ok(())
}

/// The reader's state: the file, and what it has recorded.
struct Reader<'a> {
    cx: &'a Ctx<'a>,
    origins: BTreeMap<&'static str, InputError>,
    warnings: Vec<String>,
    at_notation: InputError,
}

impl Reader<'_> {
    fn err(
        &self,
        span: Range<usize>,
        field: impl Into<String>,
        m: impl Into<String>,
    ) -> InputError {
        self.cx.err(span, field, m)
    }

    /// An error about the file at its `notation` line.
    fn at_notation(&self, field: &str, message: String) -> InputError {
        InputError {
            field: field.to_string(),
            message,
            ..self.at_notation.clone()
        }
    }

    fn axes(&self, raw: &RawFile) -> Result<Axes, InputError> {
        let Some(a) = &raw.axes else {
            return Err(self.at_notation(
                "axes",
                "missing field `axes`: say which axes the derivatives are referred to, axes = \"body\" (body axes at the trim attitude, as CR-2144 tabulates them: give [flight] theta0, U0 and W0) or axes = \"stability\" (x along the trim velocity, W0 = 0); a body-axis set read as stability axes gives a wrong phugoid with no other sign".into(),
            ));
        };
        let names = Axes::ALL.map(Axes::as_str);
        Axes::parse(a.get_ref()).ok_or_else(|| {
            self.err(
                a.span(),
                "axes",
                format!(
                    "unknown axes `{}`{}; the axes are: {}",
                    quote(a.get_ref()),
                    did_you_mean(a.get_ref(), names),
                    names.join(", ")
                ),
            )
        })
    }

    fn units(&self, raw: &RawFile) -> Result<Units, InputError> {
        let what = "\"ft\" (ft, slug, s; g = 32.174 ft/s²) or \"si\" (m, kg, s; g = 9.80665 m/s²)";
        let Some(u) = &raw.units else {
            return Err(self.at_notation(
                "units",
                format!("missing field `units`: the values' units, units = {what}"),
            ));
        };
        Units::parse(u.get_ref()).map_err(|_| {
            self.err(
                u.span(),
                "units",
                format!(
                    "unknown units `{}`{}; the units are {what}",
                    quote(u.get_ref()),
                    units_hint(u.get_ref())
                ),
            )
        })
    }

    /// Record where `name` was given.
    fn origin(&mut self, name: &'static str, span: Range<usize>, field: String) {
        let at = self.err(span, field, "");
        self.origins.insert(name, at);
    }
}

/// "; did you mean `ft`?" for a misspelt or a colloquial units word.
fn units_hint(word: &str) -> String {
    let names = Units::ALL.map(Units::name);
    if let Some(n) = nearest(word, names) {
        return format!("; did you mean `{n}`?");
    }
    let w = word.to_lowercase();
    let ft = [
        "feet",
        "foot",
        "ft-slug",
        "ft-slug-s",
        "fps",
        "imperial",
        "english",
        "us",
        "slug",
    ];
    let si = [
        "metric", "m", "mks", "metre", "meter", "metres", "meters", "kg", "m-kg-s",
    ];
    if ft.contains(&w.as_str()) {
        "; did you mean `ft`?".into()
    } else if si.contains(&w.as_str()) {
        "; did you mean `si`?".into()
    } else {
        String::new()
    }
}

/// The message for a name that is not one of a table's in this notation:
/// where it belongs, or the nearest valid name.
fn unknown_name(key: &str, table: &str, valid: &[&str]) -> String {
    let derivatives = forms::derivative_names();
    let other_tables = [
        ("derivatives", &derivatives[..]),
        ("flight", &FLIGHT[..]),
        ("reference", &REFERENCE[..]),
    ];
    if let Some((t, _)) = other_tables
        .iter()
        .find(|(t, names)| *t != table && names.contains(&key))
    {
        return format!("unknown field `{key}` in [{table}]: it belongs in [{t}]");
    }
    if let Some(n) = other_notation(key) {
        return format!(
            "`{}` is a quantity of {n}, not of this file's notation = \"dimensional\", whose [{table}] names are: {} (per unit mass and inertia; `convert --help` lists the notations)",
            quote(key),
            valid.join(", ")
        );
    }
    format!(
        "unknown field `{}` in [{table}]{}; the names are: {}",
        quote(key),
        did_you_mean(key, valid.iter().copied()),
        valid.join(", ")
    )
}

/// The notation (other than this one) a name belongs to, as a file would
/// name it.
fn other_notation(key: &str) -> Option<String> {
    let n = Notation::all().find(|n| n.names().contains(&Some(key)))?;
    Some(match n.name() {
        "american_cl" => "notation = \"american\" in its C_L/C_D form".to_string(),
        name => format!("notation `{name}`"),
    })
}

impl Reader<'_> {
    fn entries<'t>(&self, name: &str, t: &'t Option<Table>) -> Result<Entries<'t>, InputError> {
        self.cx.entries(name, t)
    }
}

/// A `[flight]` or `[reference]` table's values by name, with their spans.
type Given = BTreeMap<&'static str, (f64, Range<usize>)>;

impl Reader<'_> {
    /// The values of table `name` (keys among `valid`), origins recorded.
    fn given(
        &mut self,
        name: &str,
        t: &Option<Table>,
        valid: &[&'static str],
    ) -> Result<Given, InputError> {
        let mut out = Given::new();
        for (k, v) in self.entries(name, t)? {
            let field = format!("[{name}] {}", quote(k.get_ref()));
            let Some(&key) = valid.iter().find(|n| **n == k.get_ref()) else {
                return Err(self.err(k.span(), field, unknown_name(k.get_ref(), name, valid)));
            };
            out.insert(key, (*v.get_ref(), v.span()));
            self.origin(key, v.span(), field);
        }
        Ok(out)
    }

    /// An error at a value given in `[flight]`.
    fn at_given(&self, g: &Given, key: &str, table: &str, message: String) -> InputError {
        let span = g.get(key).map_or(0..0, |(_, s)| s.clone());
        self.err(span, format!("[{table}] {key}"), message)
    }

    fn flight(&mut self, raw: &RawFile, axes: Axes, units: Units) -> Result<Trim, InputError> {
        let span = raw.flight.as_ref().map(Table::span);
        let Some(span) = span else {
            return Err(self.at_notation(
                "[flight]",
                "missing table [flight]: the trim, U0 (and W0 in body axes) or V and alpha0, theta0 in degrees (required in body axes), optionally g".into(),
            ));
        };
        let f = self.given("flight", &raw.flight, &FLIGHT)?;
        let (u0, w0) = self.velocities(&f, axes, span.clone())?;
        let theta0 = match (f.get("theta0"), axes) {
            (Some((t, _)), _) => t.to_radians(),
            (None, Axes::Stability) => 0.0,
            (None, Axes::Body) => {
                return Err(self.err(
                    span,
                    "[flight] theta0",
                    "missing field `theta0`: a body-axis set needs the pitch attitude θ₀ of its x axis (degrees; in level flight θ₀ = α₀ = atan(W0/U0)); without it the gravity terms g cos θ₀, g sin θ₀ are unknown",
                ));
            }
        };
        let g = self.gravity(&f, units)?;
        if let Some(v) = self.origins.get("V").cloned() {
            // U₀ and W₀ were computed from V (and α₀): errors about them go there.
            self.origins.insert("U0", v.clone());
            self.origins.insert("W0", v);
        }
        Ok(Trim { u0, w0, theta0, g })
    }

    /// (U₀, W₀) from U0 and W0, or from V and alpha0 (degrees).
    fn velocities(
        &mut self,
        f: &Given,
        axes: Axes,
        span: Range<usize>,
    ) -> Result<(f64, f64), InputError> {
        let get = |k: &str| f.get(k).map(|(v, _)| *v);
        if let (Some(_), Some(_)) = (get("U0"), get("V")) {
            return Err(self.at_given(
                f,
                "V",
                "flight",
                "give the trim velocity as U0 (and W0) or as V and alpha0, not both".into(),
            ));
        }
        if axes == Axes::Stability {
            for key in ["W0", "alpha0"] {
                if get(key).is_some_and(|v| v != 0.0) {
                    return Err(self.at_given(f, key, "flight", format!("{key} = {} in stability axes, where the x axis is along the trim velocity and W₀ = α₀ = 0 by definition; body-axis data need axes = \"body\"", Num(get(key).unwrap_or(0.0)))));
                }
            }
        }
        if let Some(v) = get("V") {
            let Some(alpha) = get("alpha0") else {
                if axes == Axes::Body {
                    return Err(self.at_given(f, "V", "flight", "with V, a body-axis set needs alpha0, the trim incidence of its x axis (degrees)".into()));
                }
                return Ok((v, 0.0));
            };
            let a = alpha.to_radians();
            return Ok((v * a.cos(), v * a.sin()));
        }
        if get("alpha0").is_some() {
            return Err(self.at_given(
                f,
                "alpha0",
                "flight",
                "alpha0 goes with V (U0 = V cos α₀, W0 = V sin α₀); with U0 give W0".into(),
            ));
        }
        let Some(u0) = get("U0") else {
            return Err(self.err(
                span,
                "[flight] U0",
                "missing field `U0`: the trim velocity along x (ft/s or m/s), or V and alpha0",
            ));
        };
        let w0 = get("W0").unwrap_or_else(|| {
            if axes == Axes::Body {
                self.warnings.push(format!("{}: [flight] W0 not given: taken as 0 (the body x axis along the trim velocity, α₀ = 0)", self.cx.path));
            }
            0.0
        });
        Ok((u0, w0))
    }

    /// g from `[flight] g` or the units' standard; g in the other units'
    /// magnitude is a units mistake.
    fn gravity(&self, f: &Given, units: Units) -> Result<f64, InputError> {
        let standard = units.handbook_gravity();
        let Some((g, _)) = f.get("g") else {
            return Ok(standard);
        };
        let other = Units::ALL
            .into_iter()
            .find(|u| *u != units)
            .unwrap_or(units);
        let og = other.handbook_gravity();
        if (g - og).abs() < 0.02 * og {
            return Err(self.at_given(f, "g", "flight", format!(
                "g = {} is the standard gravity in units = \"{}\", but the file says units = \"{}\" (g = {standard}): check the units of every value",
                Num(*g), other.name(), units.name()
            )));
        }
        Ok(*g)
    }
}

impl Reader<'_> {
    /// The `[reference]` table: c̄ and μ₁ (from mu1, or rho, S and mass
    /// or weight) and i_B (from i_b, or I_y and the mass).
    /// A table per force may give only the mass and I_y it is divided by.
    fn reference(
        &self,
        raw: &RawFile,
        r: &Given,
        form: Form,
        units: Units,
        g: f64,
    ) -> Result<Option<Reference>, InputError> {
        let Some(table) = &raw.reference else {
            return Ok(None);
        };
        let inertia_only = ["mass", "weight", "I_y"];
        if form == Form::PerForce && r.keys().all(|k| inertia_only.contains(k)) {
            return Ok(None);
        }
        let need = |k: &str, why: &str| {
            r.get(k).map(|(v, _)| *v).ok_or_else(|| {
                self.err(
                    table.span(),
                    format!("[reference] {k}"),
                    format!("missing field `{k}`: {why}"),
                )
            })
        };
        for (a, b) in [
            ("mass", "weight"),
            ("mu1", "rho"),
            ("mu1", "S"),
            ("i_b", "I_y"),
        ] {
            if r.contains_key(a) && r.contains_key(b) {
                return Err(self.at_given(
                    r,
                    b,
                    "reference",
                    format!("give `{a}` or `{b}`, not both"),
                ));
            }
        }
        let chord = need(
            "chord",
            "the reference chord c̄ of the report's notation (ft or m)",
        )?;
        let mass = r
            .get("mass")
            .map(|(m, _)| *m)
            .or_else(|| r.get("weight").map(|(w, _)| w / g));
        let mass_why = format!(
            "with rho and S (or I_y) the mass is needed: mass ({}) or weight ({})",
            if units == Units::Ft { "slug" } else { "kg" },
            if units == Units::Ft { "lbf" } else { "N" }
        );
        let mu1 = match r.get("mu1") {
            Some((m, _)) => *m,
            None => {
                let rho = need("rho", "the air density, for μ₁ = m/(½ρSc̄) (or give mu1)")?;
                let s = need("S", "the wing area, for μ₁ = m/(½ρSc̄) (or give mu1)")?;
                let m = mass
                    .ok_or_else(|| self.err(table.span(), "[reference] mass", mass_why.clone()))?;
                m / (0.5 * rho * s * chord)
            }
        };
        let i_b = match r.get("i_b") {
            Some((i, _)) => *i,
            None => {
                let iy = need(
                    "I_y",
                    "the pitching inertia, for i_B = I_y/(mc̄²) (or give i_b)",
                )?;
                let m = mass
                    .ok_or_else(|| self.err(table.span(), "[reference] mass", mass_why.clone()))?;
                iy / (m * chord * chord)
            }
        };
        Ok(Some(reference_of(r, chord, mu1, i_b, mass)))
    }
}

/// The reference, physical when ρ, S, the mass and I_y were all given.
fn reference_of(r: &Given, chord: f64, mu1: f64, i_b: f64, mass: Option<f64>) -> Reference {
    let get = |k: &str| r.get(k).map(|(v, _)| *v);
    match (get("rho"), get("S"), mass, get("I_y")) {
        (Some(rho), Some(s), Some(m), Some(iy)) => Reference::physical(rho, s, chord, m, iy),
        _ => Reference::nondimensional(chord, mu1, i_b),
    }
}

impl DimensionalFile {
    /// The set in the report's notation, as the commands that work in it
    /// read it (`response`, `convert`): needs `[reference]`; what eq (4)
    /// cannot hold is left out with a warning that says how much it moves
    /// the modes.
    pub fn to_derivative_file(&self) -> Result<DerivativeFile, InputError> {
        let Some(reference) = &self.reference else {
            return Err(self.error_at(
                "notation",
                "the report's notation needs the reference quantities of the set: add a [reference] table with chord, and rho, S, mass (or weight) and I_y (or mu1 and i_b)",
            ));
        };
        let eq = self.model.to_report(reference);
        let mut warnings = self.warnings.clone();
        if !eq.is_exact() {
            warnings.push(self.dropped_warning(&eq)?);
        }
        let v = eq.v;
        let dimensional = reference.dimensional(v, self.model.units);
        let report = report_values(&eq.derivatives);
        Ok(DerivativeFile {
            path: self.path.clone(),
            notation: DIMENSIONAL.to_string(),
            form: DIMENSIONAL,
            derivatives: eq.derivatives,
            report,
            parameters: [1.0; tables::PARAMETERS.len()],
            dimensional,
            origins: vec![None; report.len()],
            warnings,
        })
    }

    /// What the report's eq (4) leaves out, and how far that moves the
    /// modes (the general model's roots against eq (4)'s, in 1/s).
    fn dropped_warning(
        &self,
        eq: &stability_core::data::dimensional::ReportEquivalent,
    ) -> Result<String, InputError> {
        let exact = self.analysis()?;
        // each root's move against the larger of the two roots' sizes: 0
        // for a zero root that stays, at most 200 % (never inf or NaN)
        let relative = |z: Complex64, w: Complex64| match z.norm().max(w.norm()) {
            0.0 => 0.0,
            size => (z - w).norm() / size,
        };
        let shift = Analysis::of(&eq.derivatives).ok().and_then(|a| {
            let worst = exact
                .roots
                .iter()
                .map(|&z| {
                    a.roots
                        .iter()
                        .map(|&w| relative(z, w / eq.tau))
                        .fold(f64::INFINITY, f64::min)
                })
                .fold(0.0, f64::max);
            worst
                .is_finite()
                .then(|| format!(" (the modes move by up to {:.2} % of |λ|)", 100.0 * worst))
        });
        let dropped = &eq.dropped;
        let mut left = Vec::new();
        for (name, v) in [
            ("X_u̇", dropped.x_udot),
            ("Z_u̇", dropped.z_udot),
            ("M_u̇", dropped.m_udot),
        ] {
            if v != 0.0 {
                left.push(format!("{name} = {}", sig(v, 3)));
            }
        }
        if dropped.gamma0.abs() > GAMMA0_NEGLIGIBLE {
            left.push(format!(
                "the flight-path angle γ₀ = {}°",
                sig(dropped.gamma0.to_degrees(), 3)
            ));
        }
        Ok(format!(
            "{}: the report's eq (4) (level flight, stability axes) cannot hold {} of this set in stability axes: left out{}",
            self.path,
            left.join(", "),
            shift.unwrap_or_default()
        ))
    }
}
