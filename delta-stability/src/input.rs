//! Derivative files: a derivative set in any notation of
//! `specs/notation.toml` (or AVL's `.st` output) and its flight condition,
//! as TOML.
//!
//! ```toml
//! notation = "report"
//! [derivatives]      # all twelve, report notation (§3, eqs 9–20)
//! x_u = -0.05
//! # x_w x_wdot x_q z_u z_w z_wdot z_q m_u m_w m_wdot m_q
//! [flight]
//! c_l = 0.3          # lift coefficient, eq (24)
//! mu1 = 50.0         # relative density m/(½ρSc̄) > 0
//! i_b = 0.08         # pitching inertia B/(mc̄²) > 0
//! [dimensional]      # optional: times in seconds
//! V = 250.0          # true airspeed, m/s
//! rho = 0.41         # air density, kg/m³
//! S = 93.0           # wing area, m²
//! chord = 6.6        # the chord of the derivatives and of μ₁, m
//! mass = 12000.0     # kg
//! ```
//!
//! In another notation the names are that notation's (`delta-stability
//! convert --help` lists them). Quantities a notation does not define come
//! in a `[report]` table in the report's names; μ₁ and i_B may instead come
//! from `[dimensional]` (`mass`, `rho`, `S`, `chord`, and `I_y` in kg·m²).
//! Duncan's notation needs `[parameters] lt = l_t/c̄`. For AVL, `st_file`
//! names the `.st` output and `[dimensional]` gives `mass`, `I_y`, `rho`, `V`.

use crate::diag::InputError;
use serde::Deserialize;
use stability_core::Derivatives;
use stability_core::analysis::Dimensional;
use stability_core::notation::{
    N_ROWS, Notation, Values, avl, derivatives_from_report, row, tables,
};
use std::collections::BTreeMap;
use std::ops::Range;
use std::path::Path;
use toml::Spanned;

/// The notations a derivative file may be written in.
pub fn notations() -> Vec<&'static str> {
    let mut v: Vec<&str> = tables::NOTATIONS.to_vec();
    v.push("avl");
    v
}

/// The rows of a derivative set: the twelve derivatives …
pub const DERIVATIVE_ROWS: [&str; 12] = [
    "x_u", "x_w", "x_wdot", "x_q", "z_u", "z_w", "z_wdot", "z_q", "m_u", "m_w", "m_wdot", "m_q",
];
/// … and the flight rows.
pub const FLIGHT_ROWS: [&str; 4] = ["c_l", "mu", "i_b", "c_d"];

type Table = Spanned<BTreeMap<Spanned<String>, Spanned<f64>>>;

/// A table's entries: key and value, with their spans.
type Entries<'t> = Vec<(&'t Spanned<String>, &'t Spanned<f64>)>;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFile {
    notation: Spanned<String>,
    derivatives: Option<Table>,
    flight: Option<Table>,
    report: Option<Table>,
    parameters: Option<Table>,
    dimensional: Option<Spanned<RawDimensional>>,
    st_file: Option<Spanned<String>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawDimensional {
    #[serde(rename = "V")]
    v: Option<Spanned<f64>>,
    rho: Option<Spanned<f64>>,
    #[serde(rename = "S")]
    s: Option<Spanned<f64>>,
    chord: Option<Spanned<f64>>,
    mass: Option<Spanned<f64>>,
    #[serde(rename = "I_y")]
    i_y: Option<Spanned<f64>>,
}

/// A derivative file, read and checked.
#[derive(Debug, Clone, PartialEq)]
pub struct DerivativeFile {
    pub path: String,
    pub notation: String,
    /// The derivative set in the report's notation.
    pub derivatives: Derivatives,
    /// All report-notation values known (by row).
    pub report: Values,
    /// Dimensionless parameters (l_t/c̄).
    pub parameters: [f64; 1],
    /// The dimensional flight condition, when given.
    pub dimensional: Option<Dimensional>,
    /// Inconsistencies worth a user's attention (not errors).
    pub warnings: Vec<String>,
}

/// Read a derivative file from disk.
pub fn read(path: &str) -> Result<DerivativeFile, InputError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| InputError::file(path, format!("cannot read the file: {e}")))?;
    parse(path, &text)
}

/// The TOML parser's error, at its line, naming the table and key it arose
/// in (`[derivatives] m_q`).
pub fn toml_error(path: &str, text: &str, e: &toml::de::Error) -> InputError {
    let span = e.span().unwrap_or(0..0);
    let message = e.message().trim().to_string();
    let start = span.start.min(text.len());
    let line_start = text[..start].rfind('\n').map_or(0, |i| i + 1);
    let line = text[line_start..].lines().next().unwrap_or("").trim();
    let header = |l: &str| {
        let l = l.trim();
        (l.starts_with('[') && l.contains(']')).then(|| l[..=l.find(']').unwrap_or(0)].to_string())
    };
    let table = header(line)
        .or_else(|| text[..line_start].lines().rev().find_map(header))
        .unwrap_or_default();
    let named = message
        .split('`')
        .nth(1)
        .filter(|_| message.starts_with("missing field") || message.starts_with("unknown field"))
        .map(str::to_string);
    let key = named.or_else(|| {
        (header(line).is_none())
            .then(|| line.split('=').next().unwrap_or("").trim().to_string())
            .filter(|k| !k.is_empty())
    });
    let field = match key {
        Some(k) => format!("{table} {k}").trim().to_string(),
        None => table,
    };
    InputError::at(path, text, span, field, message)
}

struct Ctx<'a> {
    path: &'a str,
    text: &'a str,
}

impl Ctx<'_> {
    fn err(
        &self,
        span: Range<usize>,
        field: impl Into<String>,
        message: impl Into<String>,
    ) -> InputError {
        InputError::at(self.path, self.text, span, field, message)
    }

    /// A table's values by key, every value finite.
    fn table<'t>(&self, name: &str, t: &'t Option<Table>) -> Result<Entries<'t>, InputError> {
        let Some(t) = t else { return Ok(Vec::new()) };
        let mut out = Vec::new();
        for (k, v) in t.get_ref() {
            let x = *v.get_ref();
            if !x.is_finite() {
                return Err(self.err(
                    v.span(),
                    format!("[{name}] {}", k.get_ref()),
                    format!("{x} is not a finite number"),
                ));
            }
            out.push((k, v));
        }
        Ok(out)
    }
}

/// Parse a derivative file's text.
pub fn parse(path: &str, text: &str) -> Result<DerivativeFile, InputError> {
    let raw: RawFile = toml::from_str(text).map_err(|e| toml_error(path, text, &e))?;
    let cx = Ctx { path, text };
    let notation_name = raw.notation.get_ref().clone();
    let mut warnings = Vec::new();

    // The dimensional table (every notation may give one).
    let dim_value = |name: &str, v: &Option<Spanned<f64>>| -> Result<Option<f64>, InputError> {
        match v {
            None => Ok(None),
            Some(v) => {
                let x = *v.get_ref();
                if x.is_finite() && x > 0.0 {
                    Ok(Some(x))
                } else {
                    Err(cx.err(
                        v.span(),
                        format!("[dimensional] {name}"),
                        format!("must be a positive finite number, not {x}"),
                    ))
                }
            }
        }
    };
    let (dv, drho, ds, dchord, dmass, diy) = match &raw.dimensional {
        Some(d) => {
            let d = d.get_ref();
            (
                dim_value("V", &d.v)?,
                dim_value("rho", &d.rho)?,
                dim_value("S", &d.s)?,
                dim_value("chord", &d.chord)?,
                dim_value("mass", &d.mass)?,
                dim_value("I_y", &d.i_y)?,
            )
        }
        None => (None, None, None, None, None, None),
    };
    let dim_span = raw.dimensional.as_ref().map_or(0..0, |d| d.span());
    let need_dim = |what: &str, v: Option<f64>, why: &str| {
        v.ok_or_else(|| {
            cx.err(
                dim_span.clone(),
                format!("[dimensional] {what}"),
                format!("missing: {why}"),
            )
        })
    };

    let mut report: Values = [None; N_ROWS];
    let mut parameters = [1.0];
    let at = |r: &str| row(r).unwrap_or(0);

    if notation_name == "avl" {
        let Some(st_rel) = &raw.st_file else {
            return Err(cx.err(raw.notation.span(), "st_file", "the avl notation needs `st_file = \"case.st\"`, AVL's ST output (relative to this file)"));
        };
        let st_path = Path::new(path)
            .parent()
            .unwrap_or(Path::new("."))
            .join(st_rel.get_ref());
        let shown = st_path.display().to_string();
        let st_text = std::fs::read_to_string(&st_path).map_err(|e| {
            cx.err(
                st_rel.span(),
                "st_file",
                format!("cannot read `{shown}`: {e}"),
            )
        })?;
        let st = avl::parse_st(&st_text).map_err(|e| {
            let line = e.line();
            InputError {
                file: shown.clone(),
                line,
                column: 1,
                field: String::new(),
                message: e.to_string(),
                source_line: st_text
                    .lines()
                    .nth(line.saturating_sub(1))
                    .map(str::to_string)
                    .filter(|_| line > 0),
            }
        })?;
        let r = avl::to_report(&st);
        warnings.extend(r.notes.iter().map(|n| format!("{path}: {n}")));
        for (name, v) in [
            ("x_u", r.x_u),
            ("x_w", r.x_w),
            ("x_wdot", 0.0),
            ("x_q", 0.0),
            ("z_u", r.z_u),
            ("z_w", r.z_w),
            ("z_wdot", 0.0),
            ("z_q", r.z_q),
            ("m_u", r.m_u),
            ("m_w", r.m_w),
            ("m_wdot", 0.0),
            ("m_q", r.m_q),
            ("c_l", r.c_l),
            ("c_d", st.cd),
        ] {
            report[at(name)] = Some(v);
        }
        let mass = need_dim("mass", dmass, "AVL's output has no mass (kg)")?;
        let rho = need_dim("rho", drho, "AVL's output has no air density (kg/m³)")?;
        let iy = need_dim("I_y", diy, "AVL's output has no pitching inertia (kg·m²)")?;
        report[at("mu")] = Some(mass / (0.5 * rho * st.sref * st.cref));
        report[at("i_b")] = Some(iy / (mass * st.cref * st.cref));
        let derivatives = finish(&cx, &report, &raw)?;
        let dimensional = dv.map(|v| Dimensional {
            v,
            rho,
            s: st.sref,
            chord: st.cref,
            mass,
        });
        return Ok(DerivativeFile {
            path: path.into(),
            notation: notation_name,
            derivatives,
            report,
            parameters,
            dimensional,
            warnings,
        });
    }

    let Some(notation) = Notation::named(&notation_name) else {
        return Err(cx.err(
            raw.notation.span(),
            "notation",
            format!(
                "unknown notation `{notation_name}`; the notations are: {}",
                notations().join(", ")
            ),
        ));
    };
    if let Some(st) = &raw.st_file {
        return Err(cx.err(
            st.span(),
            "st_file",
            "`st_file` belongs to notation = \"avl\"",
        ));
    }
    let names = notation.names();
    let report_names = Notation::REPORT.names();
    // Parameters.
    for (k, v) in cx.table("parameters", &raw.parameters)? {
        match tables::PARAMETERS.iter().position(|p| *p == k.get_ref()) {
            Some(i) => {
                let x = *v.get_ref();
                if x <= 0.0 {
                    return Err(cx.err(
                        v.span(),
                        format!("[parameters] {}", k.get_ref()),
                        format!("must be positive, not {x}"),
                    ));
                }
                parameters[i] = x;
            }
            None => {
                return Err(cx.err(
                    k.span(),
                    format!("[parameters] {}", k.get_ref()),
                    format!(
                        "unknown parameter; the parameters are: {}",
                        tables::PARAMETERS.join(", ")
                    ),
                ));
            }
        }
    }
    let uses_lt = notation_name == "duncan";
    if uses_lt
        && !raw
            .parameters
            .as_ref()
            .is_some_and(|t| t.get_ref().keys().any(|k| k.get_ref() == "lt"))
    {
        return Err(cx.err(
            raw.notation.span(),
            "[parameters] lt",
            "Duncan's derivatives are referred to the tail arm: give [parameters] lt = l_t/c̄",
        ));
    }
    // The notation's own values.
    let mut own: Values = [None; N_ROWS];
    let allowed = |rows: &[&str]| -> Vec<(usize, &'static str)> {
        rows.iter()
            .filter_map(|r| row(r))
            .filter_map(|i| names[i].map(|n| (i, n)))
            .collect()
    };
    for (table, rows, raw_t) in [
        ("derivatives", &DERIVATIVE_ROWS[..], &raw.derivatives),
        ("flight", &FLIGHT_ROWS[..], &raw.flight),
    ] {
        let ok = allowed(rows);
        for (k, v) in cx.table(table, raw_t)? {
            match ok.iter().find(|(_, n)| *n == k.get_ref()) {
                Some((i, _)) => own[*i] = Some(*v.get_ref()),
                None => {
                    let listed: Vec<&str> = ok.iter().map(|(_, n)| *n).collect();
                    return Err(cx.err(
                        k.span(),
                        format!("[{table}] {}", k.get_ref()),
                        format!(
                            "unknown field `{}`: not a {} of notation `{notation_name}`, whose {} are: {}",
                            k.get_ref(),
                            if table == "flight" { "flight quantity" } else { "derivative" },
                            if table == "flight" { "flight quantities" } else { "derivatives" },
                            listed.join(", ")
                        ),
                    ));
                }
            }
        }
    }
    // Quantities in the report's names, for rows this notation lacks.
    let mut extra: Values = [None; N_ROWS];
    for (k, v) in cx.table("report", &raw.report)? {
        let i = report_names
            .iter()
            .position(|n| *n == Some(k.get_ref().as_str()));
        match i {
            Some(i) if names[i].is_none() || notation == Notation::REPORT => {
                extra[i] = Some(*v.get_ref())
            }
            Some(i) => {
                return Err(cx.err(
                    k.span(),
                    format!("[report] {}", k.get_ref()),
                    format!(
                        "notation `{notation_name}` has this quantity: give it as `{}`",
                        names[i].unwrap_or("?")
                    ),
                ));
            }
            None => {
                return Err(cx.err(
                    k.span(),
                    format!("[report] {}", k.get_ref()),
                    "not a quantity of the report's notation",
                ));
            }
        }
    }
    // Required: the notation's names for the quartic's rows (optional ones
    // default to 0).
    let optional: &[&str] = if notation_name == "american" {
        &["x_wdot", "x_q"]
    } else {
        &[]
    };
    for r in DERIVATIVE_ROWS.iter().chain(["c_l", "mu", "i_b"].iter()) {
        let i = at(r);
        if let Some(n) = names[i]
            && own[i].is_none()
        {
            if optional.contains(r) {
                own[i] = Some(0.0);
            } else {
                let (table, span) = if DERIVATIVE_ROWS.contains(r) {
                    (
                        "derivatives",
                        raw.derivatives.as_ref().map_or(0..0, |t| t.span()),
                    )
                } else {
                    ("flight", raw.flight.as_ref().map_or(0..0, |t| t.span()))
                };
                return Err(cx.err(
                    span,
                    format!("[{table}] {n}"),
                    format!("missing field `{n}` (notation `{notation_name}`)"),
                ));
            }
        }
    }
    report = notation
        .to_report(&own, &parameters)
        .map_err(|e| InputError::file(path, e.to_string()))?;
    for i in 0..N_ROWS {
        if report[i].is_none() {
            report[i] = extra[i];
        }
    }
    // μ₁ and i_B from the dimensional table when the notation has none.
    if report[at("mu")].is_none()
        && let (Some(m), Some(rho), Some(s), Some(c)) = (dmass, drho, ds, dchord)
    {
        report[at("mu")] = Some(m / (0.5 * rho * s * c));
    }
    if report[at("i_b")].is_none()
        && let (Some(m), Some(iy), Some(c)) = (dmass, diy, dchord)
    {
        report[at("i_b")] = Some(iy / (m * c * c));
    }
    let derivatives = finish(&cx, &report, &raw)?;
    let dimensional = match (dv, drho, ds, dchord, dmass) {
        (Some(v), Some(rho), Some(s), Some(chord), Some(mass)) => Some(Dimensional {
            v,
            rho,
            s,
            chord,
            mass,
        }),
        _ => None,
    };
    if let Some(dims) = &dimensional {
        let mu1 = dims.mu1();
        if (mu1 - derivatives.mu1).abs() > 0.01 * derivatives.mu1 {
            warnings.push(format!(
                "{path}: the relative density is μ₁ = {} but [dimensional] gives m/(½ρSc̄) = {mu1:.4}; the quartic uses {}",
                derivatives.mu1, derivatives.mu1
            ));
        }
        let c_l = dims.c_l();
        if (c_l - derivatives.c_l).abs() > 0.01 * derivatives.c_l.abs().max(1e-3) {
            warnings.push(format!(
                "{path}: the lift coefficient is {} but [dimensional] gives W/(½ρV²S) = {c_l:.4} (g = 9.80665 m/s²); the quartic uses {}",
                derivatives.c_l, derivatives.c_l
            ));
        }
    }
    Ok(DerivativeFile {
        path: path.into(),
        notation: notation_name,
        derivatives,
        report,
        parameters,
        dimensional,
        warnings,
    })
}

/// The report's derivative set, or an error naming what is missing or out
/// of range.
fn finish(cx: &Ctx<'_>, report: &Values, raw: &RawFile) -> Result<Derivatives, InputError> {
    let d = derivatives_from_report(report).map_err(|missing| {
        let names: Vec<String> = missing
            .iter()
            .map(|r| {
                let n = row(r).and_then(|i| Notation::REPORT.names()[i]).unwrap_or(r);
                format!("`{n}`")
            })
            .collect();
        cx.err(
            raw.notation.span(),
            "notation",
            format!(
                "the derivative set lacks {} (in the report's names); give them in a [report] table, or μ₁ and i_B through [dimensional] (mass, rho, S, chord, I_y)",
                names.join(", ")
            ),
        )
    })?;
    let locate = |name: &str| -> (Range<usize>, String) {
        for (t, label) in [
            (&raw.flight, "flight"),
            (&raw.report, "report"),
            (&raw.derivatives, "derivatives"),
        ] {
            if let Some(t) = t
                && let Some((k, v)) = t
                    .get_ref()
                    .iter()
                    .find(|(k, _)| k.get_ref() == name || k.get_ref().starts_with(name))
            {
                return (v.span(), format!("[{label}] {}", k.get_ref()));
            }
        }
        (raw.notation.span(), name.to_string())
    };
    if d.mu1 <= 0.0 {
        let (span, field) = locate(if raw.notation.get_ref() == "report" {
            "mu1"
        } else {
            "mu"
        });
        return Err(cx.err(
            span,
            field,
            format!(
                "the relative density μ₁ = m/(½ρSc̄) must be positive, not {}",
                d.mu1
            ),
        ));
    }
    if d.i_b <= 0.0 {
        let (span, field) = locate("i_b");
        return Err(cx.err(
            span,
            field,
            format!(
                "the pitching inertia i_B = B/(mc̄²) must be positive, not {}",
                d.i_b
            ),
        ));
    }
    if !d.quartic_input_values().iter().all(|v| v.is_finite()) {
        return Err(cx.err(
            raw.notation.span(),
            "notation",
            "the conversion overflows: a value is too large",
        ));
    }
    Ok(d)
}
