//! Design-point configs for `analyze`, `sweep` and `report`: a planform, a
//! flight condition and the model choices, as TOML.
//!
//! ```toml
//! [planform]
//! sweep = 45.0          # leading-edge sweep Λ, degrees (0 < Λ < 90)
//! taper = 0.0           # c_t/c₀; 0 = a true delta
//! root_chord = 10.0     # one size: root_chord, span or area (any one unit)
//!
//! [flight]
//! mach = 0.9
//! cg = 0.25             # h: c.g. aft of the M.A.C.'s leading edge, fraction of the M.A.C.
//! mu1 = 50.0            # relative density m/(½ρSc̄)
//! i_b = 0.08            # pitching inertia B/(mc̄²)
//! cl_m2 = 0.05          # C_L·M² = W/(½ρa²S), constant in level flight (eq 24)
//!
//! [model]               # optional
//! damping = "faired"    # or garrick, garner-taper, slender, supersonic, transonic, transonic-frequency
//! omega_bar = 0.3       # starting ω̄ for transonic-frequency (default: √(−m_w/(μ₁i_B)))
//! iterate_frequency = true
//! [model.tables]        # optional: the user's curves instead of the defaults
//! lift_slope = { mach = [0.5, 0.9, 1.2], value = [3.1, 3.6, 3.4] }
//! zero_lift_drag = { file = "cd0.csv" }   # two columns, Mach and value, with a header
//! # drag_due_to_lift, aerodynamic_centre likewise
//! ```

use crate::diag::InputError;
use crate::input::toml_error;
use serde::Deserialize;
use stability_core::aero::{AeroError, AeroModel, Source, Table};
use stability_core::case::{Case, DampingModel};
use stability_core::geometry::{Planform, Size};
use std::path::Path;
use toml::Spanned;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawConfig {
    planform: Spanned<RawPlanform>,
    flight: Spanned<RawFlight>,
    #[serde(default)]
    model: Option<Spanned<RawModel>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawPlanform {
    sweep: Spanned<f64>,
    #[serde(default)]
    taper: Option<Spanned<f64>>,
    root_chord: Option<Spanned<f64>>,
    span: Option<Spanned<f64>>,
    area: Option<Spanned<f64>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFlight {
    mach: Spanned<f64>,
    cg: Spanned<f64>,
    mu1: Spanned<f64>,
    i_b: Spanned<f64>,
    cl_m2: Spanned<f64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawModel {
    damping: Option<Spanned<String>>,
    omega_bar: Option<Spanned<f64>>,
    iterate_frequency: Option<bool>,
    tables: Option<RawTables>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawTables {
    lift_slope: Option<Spanned<RawTable>>,
    zero_lift_drag: Option<Spanned<RawTable>>,
    drag_due_to_lift: Option<Spanned<RawTable>>,
    aerodynamic_centre: Option<Spanned<RawTable>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawTable {
    mach: Option<Vec<f64>>,
    value: Option<Vec<f64>>,
    file: Option<String>,
}

/// A config, read and checked.
#[derive(Debug, Clone)]
pub struct Config {
    pub path: String,
    pub case: Case,
}

/// Read a config file.
pub fn read(path: &str) -> Result<Config, InputError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| InputError::file(path, format!("cannot read the file: {e}")))?;
    parse(path, &text)
}

fn table_from(
    path: &str,
    text: &str,
    name: &str,
    t: &Spanned<RawTable>,
) -> Result<Table, InputError> {
    let field = format!("[model.tables] {name}");
    let raw = t.get_ref();
    let at = |m: String| InputError::at(path, text, t.span(), field.clone(), m);
    match (&raw.mach, &raw.value, &raw.file) {
        (Some(m), Some(v), None) => Table::new(m.clone(), v.clone()).map_err(|e| at(e.to_string())),
        (None, None, Some(f)) => {
            let file = Path::new(path).parent().unwrap_or(Path::new(".")).join(f);
            let shown = file.display().to_string();
            let csv = std::fs::read_to_string(&file)
                .map_err(|e| at(format!("cannot read the table `{shown}`: {e}")))?;
            read_csv_table(&shown, &csv)
        }
        _ => Err(at(
            "a table is either `mach = [...]` with `value = [...]`, or `file = \"name.csv\"`"
                .into(),
        )),
    }
}

/// A two-column CSV table (Mach, value) with one header line; errors name
/// the file and line.
pub fn read_csv_table(path: &str, csv: &str) -> Result<Table, InputError> {
    let mut mach = Vec::new();
    let mut value = Vec::new();
    let mut lines_of_rows = Vec::new();
    for (i, line) in csv.lines().enumerate() {
        let line_no = i + 1;
        let l = line.trim();
        if i == 0 || l.is_empty() || l.starts_with('#') {
            continue;
        }
        let cols: Vec<&str> = l.split(',').map(str::trim).collect();
        let bad = |m: String| InputError {
            file: path.to_string(),
            line: line_no,
            column: 1,
            field: String::new(),
            message: m,
            source_line: Some(line.to_string()),
        };
        if cols.len() != 2 {
            return Err(bad(format!(
                "expected two columns (Mach, value), found {}",
                cols.len()
            )));
        }
        let m: f64 = cols[0]
            .parse()
            .map_err(|_| bad(format!("`{}` is not a number", cols[0])))?;
        let v: f64 = cols[1]
            .parse()
            .map_err(|_| bad(format!("`{}` is not a number", cols[1])))?;
        mach.push(m);
        value.push(v);
        lines_of_rows.push(line_no);
    }
    Table::new(mach, value).map_err(|e| {
        let line = match &e {
            AeroError::NotIncreasing { row, .. } | AeroError::NonFinite { row, .. } => {
                lines_of_rows.get(row - 1).copied().unwrap_or(0)
            }
            _ => 0,
        };
        InputError {
            file: path.to_string(),
            line,
            column: 1,
            field: String::new(),
            message: e.to_string(),
            source_line: if line > 0 {
                csv.lines().nth(line - 1).map(str::to_string)
            } else {
                None
            },
        }
    })
}

/// Parse a config's text.
pub fn parse(path: &str, text: &str) -> Result<Config, InputError> {
    let raw: RawConfig = toml::from_str(text).map_err(|e| toml_error(path, text, &e))?;
    let err = |span: std::ops::Range<usize>, field: &str, m: String| {
        InputError::at(path, text, span, field, m)
    };
    let finite = |v: &Spanned<f64>, field: &str| {
        let x = *v.get_ref();
        if x.is_finite() {
            Ok(x)
        } else {
            Err(err(v.span(), field, format!("{x} is not a finite number")))
        }
    };
    let p = raw.planform.get_ref();
    let sweep = finite(&p.sweep, "[planform] sweep")?;
    let taper = match &p.taper {
        Some(t) => finite(t, "[planform] taper")?,
        None => 0.0,
    };
    let sizes: Vec<(&str, &Spanned<f64>)> = [
        ("root_chord", &p.root_chord),
        ("span", &p.span),
        ("area", &p.area),
    ]
    .into_iter()
    .filter_map(|(n, v)| v.as_ref().map(|v| (n, v)))
    .collect();
    let (size_name, size_v) = match sizes.as_slice() {
        [one] => *one,
        [] => {
            return Err(err(
                raw.planform.span(),
                "[planform]",
                "give one size: root_chord, span or area".into(),
            ));
        }
        [_, second, ..] => {
            return Err(err(
                second.1.span(),
                &format!("[planform] {}", second.0),
                "give only one size: root_chord, span or area".into(),
            ));
        }
    };
    let size_x = finite(size_v, &format!("[planform] {size_name}"))?;
    let size = match size_name {
        "root_chord" => Size::RootChord(size_x),
        "span" => Size::Span(size_x),
        _ => Size::Area(size_x),
    };
    let planform = Planform::new(sweep.to_radians(), taper, size).map_err(|e| {
        let (span, field) = match e {
            stability_core::geometry::GeometryError::Sweep(_) => {
                (p.sweep.span(), "[planform] sweep".to_string())
            }
            stability_core::geometry::GeometryError::Taper(_) => (
                p.taper.as_ref().map_or(raw.planform.span(), |t| t.span()),
                "[planform] taper".to_string(),
            ),
            stability_core::geometry::GeometryError::Size(..) => {
                (size_v.span(), format!("[planform] {size_name}"))
            }
        };
        err(span, &field, e.to_string())
    })?;
    let f = raw.flight.get_ref();
    let mach = finite(&f.mach, "[flight] mach")?;
    if mach <= 0.0 {
        return Err(err(
            f.mach.span(),
            "[flight] mach",
            format!("the Mach number must be positive, not {mach}"),
        ));
    }
    let h = finite(&f.cg, "[flight] cg")?;
    let positive = |v: &Spanned<f64>, field: &str, what: &str| {
        let x = finite(v, field)?;
        if x > 0.0 {
            Ok(x)
        } else {
            Err(err(
                v.span(),
                field,
                format!("{what} must be positive, not {x}"),
            ))
        }
    };
    let mu1 = positive(&f.mu1, "[flight] mu1", "the relative density μ₁")?;
    let i_b = positive(&f.i_b, "[flight] i_b", "the pitching inertia i_B")?;
    let cl_m2 = positive(&f.cl_m2, "[flight] cl_m2", "C_L·M² (eq 24)")?;

    let mut damping = DampingModel::Faired;
    let mut omega_bar = None;
    let mut iterate_frequency = true;
    let mut aero = AeroModel::default();
    if let Some(m) = &raw.model {
        let m = m.get_ref();
        if let Some(d) = &m.damping {
            damping = DampingModel::parse(d.get_ref())
                .map_err(|e| err(d.span(), "[model] damping", e.to_string()))?;
        }
        if let Some(w) = &m.omega_bar {
            omega_bar = Some(positive(
                w,
                "[model] omega_bar",
                "the frequency parameter ω̄",
            )?);
        }
        if let Some(it) = m.iterate_frequency {
            iterate_frequency = it;
        }
        if let Some(t) = &m.tables {
            let get = |name: &str, t: &Option<Spanned<RawTable>>| -> Result<Source, InputError> {
                match t {
                    Some(t) => Ok(Source::Table(table_from(path, text, name, t)?)),
                    None => Ok(Source::Default),
                }
            };
            aero = AeroModel {
                lift_slope: get("lift_slope", &t.lift_slope)?,
                zero_lift_drag: get("zero_lift_drag", &t.zero_lift_drag)?,
                drag_due_to_lift: get("drag_due_to_lift", &t.drag_due_to_lift)?,
                aerodynamic_centre: get("aerodynamic_centre", &t.aerodynamic_centre)?,
            };
        }
    }
    Ok(Config {
        path: path.to_string(),
        case: Case {
            planform,
            mach,
            h,
            mu1,
            i_b,
            cl_m2,
            aero,
            damping,
            omega_bar,
            iterate_frequency,
        },
    })
}
