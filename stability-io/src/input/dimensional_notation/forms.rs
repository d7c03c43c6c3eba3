//! A handbook's `[derivatives]` table as printed: its
//! form (`form = "per_unit_mass" | "per_force" | "alpha"`, or inferred: the
//! α form where an α name is present, else per unit mass), the mass and
//! inertia a table per force needs, and the values in the model's form by
//! [`Printed::per_unit_mass`], the one conversion. Every unknown name of
//! the file is reported at once, each at its line, with the nearest valid
//! name.

use super::{RawFile, Reader, unknown_name};
use crate::diag::{InputError, quote};
use crate::input::raw::Table;
use crate::input::suggest::did_you_mean;
use stability_core::data::dimensional::form::{ALPHA_NAMES, w_name_of};
use stability_core::data::dimensional::{
    Axes, DimensionalDerivatives, Form, Inertia, Printed, Trim, Units,
};
use stability_core::numerics::display::Num;
use std::ops::Range;

/// The names a `[derivatives]` table may hold: the model's and the α form's.
pub(super) fn derivative_names() -> Vec<&'static str> {
    let mut v = DimensionalDerivatives::NAMES.to_vec();
    v.extend(ALPHA_NAMES.iter().map(|(a, _)| *a));
    v
}

/// An unknown name: its table, the key, the table's valid names.
type Unknown<'t> = (&'t str, &'t toml::Spanned<String>, &'t [&'t str]);

/// The most unknown names listed one by one (the rest are counted).
const LISTED: usize = 6;

impl Reader<'_> {
    /// Every name of `[derivatives]`, `[flight]` and `[reference]` that is
    /// not one of its table's: one error at the first, listing each with
    /// its file:line and the nearest valid name (or where it belongs).
    pub(super) fn unknown_fields(&self, raw: &RawFile) -> Result<(), InputError> {
        let derivatives = derivative_names();
        let tables: [(&str, &Option<Table>, &[&str]); 3] = [
            ("derivatives", &raw.derivatives, &derivatives),
            ("flight", &raw.flight, &super::FLIGHT),
            ("reference", &raw.reference, &super::REFERENCE),
        ];
        let mut unknown: Vec<Unknown<'_>> = Vec::new();
        for (name, table, valid) in tables {
            let Some(t) = table else { continue };
            for k in t.get_ref().keys() {
                if !valid.contains(&k.get_ref().as_str()) {
                    unknown.push((name, k, valid));
                }
            }
        }
        unknown.sort_by_key(|(_, k, _)| k.span().start);
        let Some((table, first, valid)) = unknown.first() else {
            return Ok(());
        };
        let field = format!("[{table}] {}", quote(first.get_ref()));
        let message = if unknown.len() == 1 {
            unknown_name(first.get_ref(), table, valid)
        } else {
            format!(
                "{} unknown fields, each at its line:{}",
                unknown.len(),
                self.listed(&unknown)
            )
        };
        Err(self.err(first.span(), field, message))
    }

    /// `f.toml:12: [derivatives] `Z_alfa`: did you mean `Z_alpha`?`, one
    /// a line, at most [`LISTED`].
    fn listed(&self, unknown: &[Unknown<'_>]) -> String {
        let mut lines: Vec<String> = unknown
            .iter()
            .take(LISTED)
            .map(|(table, k, valid)| {
                let at = self.err(k.span(), "", "");
                let hint = short_hint(k.get_ref(), table, valid);
                format!(
                    "\n  {}:{}: [{table}] `{}`{hint}",
                    at.file,
                    at.line,
                    quote(k.get_ref())
                )
            })
            .collect();
        if unknown.len() > LISTED {
            lines.push(format!("\n  and {} more", unknown.len() - LISTED));
        }
        lines.concat()
    }
}

/// What to write instead of an unknown name, briefly.
fn short_hint(key: &str, table: &str, valid: &[&str]) -> String {
    let long = unknown_name(key, table, valid);
    if let Some(i) = long.find(": it belongs in") {
        return long[i..].to_string();
    }
    if long.contains("is a quantity of") {
        let of = long.split(", not of this file's").next().unwrap_or("");
        return format!(": {}", of.trim_start_matches(&format!("`{}` ", quote(key))));
    }
    let hint = did_you_mean(key, valid.iter().copied());
    hint.strip_prefix("; ")
        .map(|h| format!(": {h}"))
        .unwrap_or_default()
}

impl Reader<'_> {
    /// The table's form: `form` when given (an α name then needs
    /// `form = "alpha"`), else the α form where an α name is present, else
    /// per unit mass. The α form is defined in stability axes (w = U₀α).
    pub(super) fn form(&self, raw: &RawFile, axes: Axes) -> Result<Form, InputError> {
        let names = Form::ALL.map(Form::as_str);
        let keys: Vec<&toml::Spanned<String>> = raw
            .derivatives
            .as_ref()
            .map(|t| t.get_ref().keys().collect())
            .unwrap_or_default();
        // the first α name in the file's order
        let alpha = keys
            .iter()
            .filter(|k| w_name_of(k.get_ref()).is_some())
            .min_by_key(|k| k.span().start);
        let form = match &raw.form {
            None if alpha.is_some() => Form::Alpha,
            None => Form::PerUnitMass,
            Some(f) => Form::parse(f.get_ref()).ok_or_else(|| {
                self.err(
                    f.span(),
                    "form",
                    format!(
                        "unknown form `{}`{}; the forms are: {}",
                        quote(f.get_ref()),
                        did_you_mean(f.get_ref(), names),
                        Form::ALL
                            .map(|f| format!("\"{}\" ({})", f.as_str(), f.describe()))
                            .join("; ")
                    ),
                )
            })?,
        };
        if let (Some(k), true) = (alpha, form != Form::Alpha) {
            let w = w_name_of(k.get_ref()).unwrap_or("");
            return Err(self.err(
                k.span(),
                format!("[derivatives] {}", k.get_ref()),
                format!(
                    "`{}` = U₀·{w} is a name of form = \"alpha\" (Nelson ch. 4), but this file says form = \"{}\": give {w} = {}/U0 in this form, or set form = \"alpha\"",
                    k.get_ref(),
                    form.as_str(),
                    k.get_ref()
                ),
            ));
        }
        if let (Some(k), Axes::Body) = (alpha, axes) {
            return Err(self.err(
                k.span(),
                format!("[derivatives] {}", k.get_ref()),
                "the α form (Z_alpha = U₀Z_w, w = U₀α) is defined in stability axes: with axes = \"body\" give the w derivatives",
            ));
        }
        Ok(form)
    }

    /// The mass and I_y of a table per force, from `[reference]` (mass, or
    /// weight/g; I_y); `None` in the other forms.
    pub(super) fn inertia(
        &self,
        raw: &RawFile,
        form: Form,
        r: &super::Given,
        units: Units,
        g: f64,
    ) -> Result<Option<Inertia>, InputError> {
        if form != Form::PerForce {
            return Ok(None);
        }
        let get = |k: &str| r.get(k).map(|(v, _)| *v);
        let mass = get("mass").or_else(|| get("weight").map(|w| w / g));
        let (mass_unit, i_unit) = match units {
            Units::Si => ("kg", "kg·m²"),
            Units::Ft => ("slug", "slug·ft²"),
        };
        let (Some(mass), Some(i_y)) = (mass, get("I_y")) else {
            let span = raw.form.as_ref().map_or(0..0, |f| f.span());
            return Err(self.err(
                span,
                "form",
                format!("form = \"per_force\": the table per force and moment is divided by the mass and the pitching inertia, which it needs in [reference]: mass ({mass_unit}) or weight, and I_y ({i_unit})"),
            ));
        };
        for (name, v) in [("mass", mass), ("I_y", i_y)] {
            if !(v.is_finite() && v > 0.0) {
                let key = if name == "mass" && get("mass").is_none() {
                    "weight"
                } else {
                    name
                };
                return Err(self.at_given(
                    r,
                    key,
                    "reference",
                    format!(
                        "{name} must be a positive finite number, not {}: a table per force is divided by it",
                        Num(v)
                    ),
                ));
            }
        }
        Ok(Some(Inertia { mass, i_y }))
    }
}

/// A `[derivatives]` value read: the model's name, the value in the
/// model's form, and where it was written.
struct Read {
    index: usize,
    value: f64,
    span: Range<usize>,
    field: String,
}

impl Reader<'_> {
    /// The `[derivatives]` table in `form`, in the model's form (per unit
    /// mass and inertia, per w).
    pub(super) fn derivatives(
        &mut self,
        raw: &RawFile,
        form: Form,
        trim: &Trim,
        inertia: Option<Inertia>,
    ) -> Result<DimensionalDerivatives, InputError> {
        let Some(table) = &raw.derivatives else {
            return Err(self.at_notation(
                "[derivatives]",
                format!(
                    "missing table [derivatives]: the derivatives {}: {} (and optionally {})",
                    form.describe(),
                    super::REQUIRED.join(", "),
                    DimensionalDerivatives::OPTIONAL.join(", ")
                ),
            ));
        };
        let names = DimensionalDerivatives::NAMES;
        let mut values: [Option<Read>; 15] = Default::default();
        for (k, v) in self.entries("derivatives", &raw.derivatives)? {
            let key = k.get_ref().as_str();
            let field = format!("[derivatives] {}", quote(key));
            let (model_name, printed) = match (w_name_of(key), inertia) {
                (Some(w), _) => (w, Printed::PerAlpha { u0: trim.u0 }),
                (None, Some(i)) => (key, Printed::PerForce(i)),
                (None, None) => (key, Printed::PerUnitMass),
            };
            let Some(index) = names.iter().position(|n| *n == model_name) else {
                let m = unknown_name(key, "derivatives", &derivative_names());
                return Err(self.err(k.span(), field, m));
            };
            if let Some(first) = &values[index] {
                return Err(self.err(
                    k.span(),
                    field,
                    format!(
                        "{} is given twice: as {} and as `{key}`; give one",
                        names[index], first.field
                    ),
                ));
            }
            let value = printed.per_unit_mass(model_name, *v.get_ref());
            if !value.is_finite() {
                return Err(self.err(v.span(), field, format!(
                    "{key} = {} is {} in the model's form (per unit mass and inertia): the value, the mass, I_y or U₀ is out of range",
                    Num(*v.get_ref()), Num(value)
                )));
            }
            values[index] = Some(Read {
                index,
                value,
                span: v.span(),
                field,
            });
        }
        self.required(table, form, &values)?;
        let mut out = [0.0; 15];
        for r in values.into_iter().flatten() {
            out[r.index] = r.value;
            self.origin(names[r.index], r.span, r.field);
        }
        Ok(DimensionalDerivatives::from_values(out))
    }

    /// The first required derivative not given, as an error.
    fn required(
        &self,
        table: &Table,
        form: Form,
        values: &[Option<Read>; 15],
    ) -> Result<(), InputError> {
        let names = DimensionalDerivatives::NAMES;
        let Some(missing) = super::REQUIRED.iter().find(|n| {
            let i = names.iter().position(|x| x == *n).unwrap_or(0);
            values[i].is_none()
        }) else {
            return Ok(());
        };
        let alpha = ALPHA_NAMES
            .iter()
            .find(|(_, w)| w == missing)
            .map(|(a, _)| format!(" (or {a} = U₀·{missing} in form = \"alpha\")"))
            .unwrap_or_default();
        Err(self.err(
            table.span(),
            format!("[derivatives] {missing}"),
            format!(
                "missing field `{missing}`{alpha} (notation \"dimensional\" needs {}; {} are optional, 0 if not given; this table is {})",
                super::REQUIRED.join(", "),
                DimensionalDerivatives::OPTIONAL.join(", "),
                form.describe()
            ),
        ))
    }
}
