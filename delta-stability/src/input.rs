//! Derivative files: a derivative set in the report's notation (§3) and
//! its flight condition, as TOML.
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

use crate::diag::InputError;
use serde::Deserialize;
use stability_core::Derivatives;
use stability_core::analysis::Dimensional;
use toml::Spanned;

/// The notations a derivative file may be written in.
pub const NOTATIONS: &[&str] = &["report"];

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFile {
    notation: Spanned<String>,
    derivatives: Spanned<RawDerivatives>,
    flight: Spanned<RawFlight>,
    dimensional: Option<Spanned<RawDimensional>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawDimensional {
    #[serde(rename = "V")]
    v: Spanned<f64>,
    rho: Spanned<f64>,
    #[serde(rename = "S")]
    s: Spanned<f64>,
    chord: Spanned<f64>,
    mass: Spanned<f64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawDerivatives {
    x_u: Spanned<f64>,
    x_w: Spanned<f64>,
    x_wdot: Spanned<f64>,
    x_q: Spanned<f64>,
    z_u: Spanned<f64>,
    z_w: Spanned<f64>,
    z_wdot: Spanned<f64>,
    z_q: Spanned<f64>,
    m_u: Spanned<f64>,
    m_w: Spanned<f64>,
    m_wdot: Spanned<f64>,
    m_q: Spanned<f64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFlight {
    c_l: Spanned<f64>,
    mu1: Spanned<f64>,
    i_b: Spanned<f64>,
}

/// A derivative file, read and checked.
#[derive(Debug, Clone, PartialEq)]
pub struct DerivativeFile {
    pub path: String,
    pub notation: String,
    pub derivatives: Derivatives,
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
    // The table: this line if it is a header, else the nearest header above.
    let table = header(line)
        .or_else(|| text[..line_start].lines().rev().find_map(header))
        .unwrap_or_default();
    // The key: the one named in the message (`missing field `m_q``), else
    // the one on this line.
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

/// Parse a derivative file's text.
pub fn parse(path: &str, text: &str) -> Result<DerivativeFile, InputError> {
    let raw: RawFile = toml::from_str(text).map_err(|e| toml_error(path, text, &e))?;
    let notation = raw.notation.get_ref();
    if !NOTATIONS.contains(&notation.as_str()) {
        return Err(InputError::at(
            path,
            text,
            raw.notation.span(),
            "notation",
            format!(
                "unknown notation `{notation}`; this version reads: {}",
                NOTATIONS.join(", ")
            ),
        ));
    }
    let d = raw.derivatives.get_ref();
    let f = raw.flight.get_ref();
    let named = [
        ("derivatives", "x_u", &d.x_u),
        ("derivatives", "x_w", &d.x_w),
        ("derivatives", "x_wdot", &d.x_wdot),
        ("derivatives", "x_q", &d.x_q),
        ("derivatives", "z_u", &d.z_u),
        ("derivatives", "z_w", &d.z_w),
        ("derivatives", "z_wdot", &d.z_wdot),
        ("derivatives", "z_q", &d.z_q),
        ("derivatives", "m_u", &d.m_u),
        ("derivatives", "m_w", &d.m_w),
        ("derivatives", "m_wdot", &d.m_wdot),
        ("derivatives", "m_q", &d.m_q),
        ("flight", "c_l", &f.c_l),
        ("flight", "mu1", &f.mu1),
        ("flight", "i_b", &f.i_b),
    ];
    for (table, name, v) in named {
        let x = *v.get_ref();
        let field = format!("[{table}] {name}");
        if !x.is_finite() {
            return Err(InputError::at(
                path,
                text,
                v.span(),
                field,
                format!("{x} is not a finite number"),
            ));
        }
        if matches!(name, "mu1" | "i_b") && x <= 0.0 {
            let what = if name == "mu1" {
                "the relative density μ₁ = m/(½ρSc̄)"
            } else {
                "the pitching inertia i_B = B/(mc̄²)"
            };
            return Err(InputError::at(
                path,
                text,
                v.span(),
                field,
                format!("{what} must be positive, not {x}"),
            ));
        }
    }
    let g = |v: &Spanned<f64>| *v.get_ref();
    let derivatives = Derivatives {
        x_u: g(&d.x_u),
        x_w: g(&d.x_w),
        x_wdot: g(&d.x_wdot),
        x_q: g(&d.x_q),
        z_u: g(&d.z_u),
        z_w: g(&d.z_w),
        z_wdot: g(&d.z_wdot),
        z_q: g(&d.z_q),
        m_u: g(&d.m_u),
        m_w: g(&d.m_w),
        m_wdot: g(&d.m_wdot),
        m_q: g(&d.m_q),
        c_l: g(&f.c_l),
        mu1: g(&f.mu1),
        i_b: g(&f.i_b),
    };
    let mut warnings = Vec::new();
    let dimensional = match &raw.dimensional {
        None => None,
        Some(dim) => {
            let dm = dim.get_ref();
            for (name, v) in [
                ("V", &dm.v),
                ("rho", &dm.rho),
                ("S", &dm.s),
                ("chord", &dm.chord),
                ("mass", &dm.mass),
            ] {
                let x = *v.get_ref();
                if !(x.is_finite() && x > 0.0) {
                    return Err(InputError::at(
                        path,
                        text,
                        v.span(),
                        format!("[dimensional] {name}"),
                        format!("must be a positive finite number, not {x}"),
                    ));
                }
            }
            let dims = Dimensional {
                v: g(&dm.v),
                rho: g(&dm.rho),
                s: g(&dm.s),
                chord: g(&dm.chord),
                mass: g(&dm.mass),
            };
            let mu1 = dims.mu1();
            if (mu1 - derivatives.mu1).abs() > 0.01 * derivatives.mu1 {
                warnings.push(format!(
                    "{path}: [flight] mu1 = {} but [dimensional] gives m/(½ρSc̄) = {mu1:.4}; the quartic uses mu1 = {}",
                    derivatives.mu1, derivatives.mu1
                ));
            }
            let c_l = dims.c_l();
            if (c_l - derivatives.c_l).abs() > 0.01 * derivatives.c_l.abs().max(1e-3) {
                warnings.push(format!(
                    "{path}: [flight] c_l = {} but [dimensional] gives W/(½ρV²S) = {c_l:.4} (g = 9.80665 m/s²); the quartic uses c_l = {}",
                    derivatives.c_l, derivatives.c_l
                ));
            }
            Some(dims)
        }
    };
    Ok(DerivativeFile {
        path: path.to_string(),
        notation: notation.clone(),
        derivatives,
        dimensional,
        warnings,
    })
}
