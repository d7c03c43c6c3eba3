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
//! # or, instead of mu1, i_b and cl_m2, a physical flight condition
//! # ([`physical`]): units = "si" | "ft", altitude (or geometric_altitude,
//! # or rho with speed_of_sound), mass (or weight), I_y
//!
//! [model]               # optional
//! damping = "faired"    # the default: one lifting surface through M = 1 (docs/damping-theories.md); or faired-theories, faired-slender,
//!                       # garrick, garner-taper, slender, supersonic, transonic, transonic-frequency,
//!                       # lifting-surface, lifting-surface-frequency
//! aero = "default"      # or lifting-surface: lift slope and aerodynamic centre from the lifting surface (0 ≤ M ≤ 3)
//! omega_bar = 0.3       # lifting-surface: the ω̄ it is evaluated at (default 0, quasi-steady);
//!                       # the iterated theories and faired: the starting ω̄ (default √(−m_w/(μ₁i_B)))
//! iterate_frequency = true
//! frequency_method = "p" # how the roots take the air forces' frequency: "p" (the default: each root
//!                       # at its own complex frequency, exact), "p-k", or "k" (the derivatives at the short period's ω̄)
//! datcom = "for006.dat" # optional: a DATCOM output's tables (docs/tables.md)
//! [model.tables]        # optional: the user's curves instead of the defaults
//! lift_slope = { mach = [0.5, 0.9, 1.2], value = [3.1, 3.6, 3.4] }
//! zero_lift_drag = { file = "cd0.csv" }   # two columns, Mach and value (a header line optional)
//! # drag_due_to_lift, aerodynamic_centre likewise
//! m_q = { mach = [0.5, 1.2], values = [-0.9, -0.6], mode = "value", cg = 0.25 }
//! z_u = { file = "dz_u.csv", mode = "increment" }   # added to the computed z_u
//! # any of x_u x_w x_wdot x_q z_u z_w z_wdot z_q m_u m_w m_wdot m_q (z_ẇ, m_ẇ too)
//! ```
//!
//! An optional `[aircraft]` table states what the aircraft is: `class =
//! "IV"` (MIL-F-8785C §1.3: `I`, `II-C`, `II-L`, `III`, `IV`), whose
//! Category C floors the short-period frequency requirement applies
//! ([`Config::class`]; a command line's `--class` wins). An optional
//! `[control]` table gives the control derivatives of
//! `--state-space` (`[control]`). Each value must lie in its
//! range ([`limits`]); every error names the file, line and field.

pub mod overrides;
pub mod physical;
pub mod raw;
pub mod surfaces;
pub mod tables;
pub mod uncertainty;

use crate::Failure;
use crate::diag::{InputError, quote};
use crate::input::datcom::Datcom;
use crate::input::toml_error;
use crate::limits;
use raw::{RawConfig, RawModel, RawPlanform};
use stability_core::aerodynamics::damping::DampingError;
use stability_core::aerodynamics::lifting_surface::LiftingSurfaceError;
use stability_core::aerodynamics::models::aero::{AeroError, AeroModel, AeroModelName};
use stability_core::criteria::cap::AirplaneClass;
use stability_core::design::case::{Case, CaseError, DampingModel, FrequencyMethod};
use stability_core::geometry::{GeometryError, Planform, Size};
use stability_core::numerics::display::{Num, sig};
use std::ops::Range;
use std::path::Path;
use toml::Spanned;

pub use overrides::{Overrides, apply, overridden};
pub use tables::read_csv_table;

/// A config, read and checked.
#[derive(Debug, Clone)]
pub struct Config {
    pub path: String,
    pub case: Case,
    /// The physical flight condition, when `[flight]` gives one
    /// ([`physical`]); `case` then holds the μ₁, i_B and C_L·M² it gives.
    pub physical: Option<physical::Physical>,
    /// The user's own tables (`[model.tables]`), which win over a DATCOM
    /// output's.
    pub tables: AeroModel,
    /// The DATCOM output the model takes its tables from (`[model]
    /// datcom`, `--datcom`).
    pub datcom: Option<Datcom>,
    /// The MIL-F-8785C class `[aircraft] class` states, if it does.
    pub class: Option<AirplaneClass>,
    /// The tailplane, foreplane and body (`[tailplane]`, `[foreplane]`,
    /// `[body]`), if any is given; the case's model carries it too
    /// (`case.aero.configuration`).
    pub configuration: Option<stability_core::geometry::configuration::Configuration>,
    text: String,
    /// Where each value (and table) was written: field and span.
    spans: Vec<(String, Range<usize>)>,
    /// Values replaced from the command line: field and flag (`--mach 1.2`).
    overridden: Vec<(&'static str, String)>,
}

/// Whether a file's text is a design-point config (it has `[planform]`)
/// rather than a derivative file.
pub fn is_config(text: &str) -> bool {
    toml::from_str::<toml::Table>(text).is_ok_and(|t| t.contains_key("planform"))
}

/// What a command that reads derivative files says of a config.
pub const NOT_A_DERIVATIVE_FILE: &str = "this is a design-point config ([planform]), not a derivative file: `delta-stability analyze` analyses it, and `analyze CONFIG --write-derivatives OUT.toml` writes its design point as a derivative file for quartic and convert (response and sensitivity read a config as it is)";

/// What `analyze`, `sweep` and `report` say of a derivative file.
pub const NOT_A_CONFIG: &str = "this is a derivative file (`notation = …`), not a design-point config: `delta-stability quartic`, `response` and `sensitivity` read it; a config has [planform] and [flight] (delta-stability analyze --help)";

/// Read a config file (a regular file of at most
/// [`crate::files::MAX_INPUT_BYTES`]).
pub fn read(path: &str) -> Result<Config, Failure> {
    let text = crate::files::read_input(Path::new(path))?;
    parse(path, &text)
}

/// The spans of a config's values, collected as they are read.
struct Reader<'a> {
    path: &'a str,
    text: &'a str,
    spans: Vec<(String, Range<usize>)>,
}

impl Reader<'_> {
    fn err(&self, span: Range<usize>, field: &str, m: String) -> InputError {
        InputError::at(self.path, self.text, span, field, m)
    }

    /// An error at the value recorded under `field` (the file's start if
    /// none was).
    fn err_field(&self, field: &str, m: String) -> InputError {
        let span = self
            .spans
            .iter()
            .rev()
            .find(|(f, _)| f == field)
            .map_or(0..0, |(_, s)| s.clone());
        self.err(span, field, m)
    }

    /// `v` within `limit`, its span recorded under `field`.
    fn value(
        &mut self,
        v: &Spanned<f64>,
        field: &str,
        limit: &limits::Limit,
    ) -> Result<f64, InputError> {
        self.spans.push((field.to_string(), v.span()));
        limit
            .check(*v.get_ref())
            .map_err(|m| self.err(v.span(), field, m))
    }
}

/// Parse a config's text (a CSV table it names is read from disk,
/// relative to `path`).
pub fn parse(path: &str, text: &str) -> Result<Config, Failure> {
    let derivative_file = toml::from_str::<toml::Table>(text)
        .is_ok_and(|t| t.contains_key("notation") && !t.contains_key("planform"));
    if derivative_file {
        return Err(InputError::file(path, NOT_A_CONFIG).into());
    }
    let raw: RawConfig = toml::from_str(text).map_err(|e| toml_error(path, text, &e))?;
    // every file the config names is an input of the run, read or not
    for file in uncertainty::named_files(path, text) {
        crate::files::note_input(&file);
    }
    let mut r = Reader {
        path,
        text,
        spans: vec![
            ("[planform]".into(), raw.planform.span()),
            ("[flight]".into(), raw.flight.span()),
        ],
    };
    let planform = planform(&mut r, &raw.planform)?;
    let f = raw.flight.get_ref();
    let mach = r.value(&f.mach, "[flight] mach", &limits::MACH)?;
    let h = r.value(&f.cg, "[flight] cg", &limits::CG)?;
    let ([mu1, i_b, cl_m2], physical) =
        physical::flight_parameters(&mut r, f, raw.flight.span(), &planform)?;
    let mut case = Case {
        planform,
        mach,
        h,
        mu1,
        i_b,
        cl_m2,
        aero: AeroModel::default(),
        damping: DampingModel::Faired,
        omega_bar: None,
        iterate_frequency: true,
        frequency_method: Default::default(),
    };
    let (tables, datcom) = match &raw.model {
        Some(m) => {
            r.spans.push(("[model]".into(), m.span()));
            model(&mut r, m.get_ref(), &mut case)?
        }
        None => (AeroModel::default(), None),
    };
    let class = match &raw.aircraft {
        Some(a) => class(&mut r, a.get_ref())?,
        None => None,
    };
    let configuration = surfaces::configuration(&mut r, &raw, &case.planform)?;
    case.aero.configuration = configuration.clone().map(std::sync::Arc::new);
    let mut tables = tables;
    tables.configuration = case.aero.configuration.clone();
    Ok(Config {
        path: path.to_string(),
        case,
        physical,
        tables,
        datcom,
        class,
        configuration,
        text: text.to_string(),
        spans: r.spans,
        overridden: Vec::new(),
    })
}

/// `[model] frequency_method`, a frequency method by its name.
fn frequency_method(
    r: &mut Reader<'_>,
    fm: &Spanned<String>,
) -> Result<FrequencyMethod, InputError> {
    r.spans.push(("[model] frequency_method".into(), fm.span()));
    FrequencyMethod::parse(fm.get_ref()).ok_or_else(|| {
        let names = FrequencyMethod::ALL.map(FrequencyMethod::name);
        r.err(
            fm.span(),
            "[model] frequency_method",
            format!(
                "unknown frequency method `{}`{}; the methods are: {}",
                quote(fm.get_ref()),
                crate::input::suggest::did_you_mean(fm.get_ref(), names),
                FrequencyMethod::ALL
                    .map(|m| format!("{} ({})", m.name(), m.describe()))
                    .join("; ")
            ),
        )
    })
}

/// `[aircraft] class`, a MIL-F-8785C class by its name.
fn class(r: &mut Reader<'_>, a: &raw::RawAircraft) -> Result<Option<AirplaneClass>, InputError> {
    let Some(c) = &a.class else {
        return Ok(None);
    };
    r.spans.push(("[aircraft] class".into(), c.span()));
    match AirplaneClass::parse(c.get_ref()) {
        Some(k) => Ok(Some(k)),
        None => {
            let names = AirplaneClass::ALL.map(AirplaneClass::name);
            let m = format!(
                "unknown MIL-F-8785C class `{}`{}; the classes (§1.3) are {}",
                quote(c.get_ref()),
                crate::input::suggest::did_you_mean(c.get_ref(), names),
                AirplaneClass::ALL
                    .map(|k| format!("{} ({})", k.name(), k.describe()))
                    .join(", ")
            );
            Err(r.err(c.span(), "[aircraft] class", m))
        }
    }
}

/// The one size given (root chord, span or area), its field and value.
fn size<'p>(
    r: &mut Reader<'_>,
    p: &'p RawPlanform,
    whole: Range<usize>,
    section: &str,
) -> Result<(Size, String, &'p Spanned<f64>), InputError> {
    let sizes: Vec<(&str, &Spanned<f64>)> = [
        ("root_chord", &p.root_chord),
        ("span", &p.span),
        ("area", &p.area),
    ]
    .into_iter()
    .filter_map(|(n, v)| v.as_ref().map(|v| (n, v)))
    .collect();
    let (name, v) = match sizes.as_slice() {
        [one] => *one,
        [] => {
            let m = "give one size: root_chord, span or area";
            return Err(r.err(whole, section, m.into()));
        }
        [_, second, ..] => {
            let field = format!("{section} {}", second.0);
            let m = "give only one size: root_chord, span or area";
            return Err(r.err(second.1.span(), &field, m.into()));
        }
    };
    let field = format!("{section} {name}");
    let x = r.value(v, &field, &limits::SIZE)?;
    let size = match name {
        "root_chord" => Size::RootChord(x),
        "span" => Size::Span(x),
        _ => Size::Area(x),
    };
    Ok((size, field, v))
}

fn planform(r: &mut Reader<'_>, p: &Spanned<RawPlanform>) -> Result<Planform, InputError> {
    planform_in(r, p.get_ref(), p.span(), "[planform]")
}

/// A planform from `[planform]`'s keys in table `section` (`[planform]`,
/// `[tailplane]`, `[foreplane]`) spanning `whole`.
fn planform_in(
    r: &mut Reader<'_>,
    p: &RawPlanform,
    whole: Range<usize>,
    section: &str,
) -> Result<Planform, InputError> {
    let field = |k: &str| format!("{section} {k}");
    let any = limits::Limit {
        what: "the value",
        lo: f64::MIN,
        hi: f64::MAX,
        lo_included: true,
    };
    let sweep = r.value(&p.sweep, &field("sweep"), &any)?;
    let taper = match &p.taper {
        Some(t) => r.value(t, &field("taper"), &any)?,
        None => 0.0,
    };
    let (size, size_field, size_v) = size(r, p, whole.clone(), section)?;
    let planform = Planform::new(sweep.to_radians(), taper, size).map_err(|e| {
        let (span, field) = match e {
            GeometryError::Sweep(_) => (p.sweep.span(), field("sweep")),
            GeometryError::Taper(_) => {
                (p.taper.as_ref().map_or(whole, |t| t.span()), field("taper"))
            }
            GeometryError::Size(..) => (size_v.span(), size_field),
        };
        r.err(span, &field, e.to_string())
    })?;
    // a sweep a hair above 0° is valid, but its span is not finite
    let derived = [
        planform.span(),
        planform.area(),
        planform.mac(),
        planform.aspect_ratio(),
    ];
    if !derived.iter().all(|v| v.is_finite() && *v > 0.0) {
        return Err(r.err(
            p.sweep.span(),
            &field("sweep"),
            format!(
                "at a sweep of {}° the planform's span, area or aspect ratio is not a finite positive number",
                Num(sweep)
            ),
        ));
    }
    Ok(planform)
}

/// A file a config names, relative to the config's directory.
pub fn relative(config: &str, file: &str) -> std::path::PathBuf {
    Path::new(config)
        .parent()
        .unwrap_or(Path::new("."))
        .join(file)
}

/// `[model]`: the damping and aerodynamic models, the tables and the
/// DATCOM output; returns the user's tables and the DATCOM output.
fn model(
    r: &mut Reader<'_>,
    m: &RawModel,
    case: &mut Case,
) -> Result<(AeroModel, Option<Datcom>), Failure> {
    if let Some(d) = &m.damping {
        r.spans.push(("[model] damping".into(), d.span()));
        case.damping = DampingModel::parse(d.get_ref()).map_err(|_| {
            let names = DampingModel::ALL.map(DampingModel::name);
            r.err(
                d.span(),
                "[model] damping",
                format!(
                    "unknown damping model `{}`{}; the models are: {}",
                    quote(d.get_ref()),
                    crate::input::suggest::did_you_mean(d.get_ref(), names),
                    names.join(", ")
                ),
            )
        })?;
    }
    if let Some(w) = &m.omega_bar {
        case.omega_bar = Some(r.value(w, "[model] omega_bar", &limits::OMEGA_BAR)?);
    }
    if let Some(it) = m.iterate_frequency {
        case.iterate_frequency = it;
    }
    if let Some(fm) = &m.frequency_method {
        case.frequency_method = frequency_method(r, fm)?;
    }
    let user = match &m.tables {
        Some(t) => {
            r.spans.push(("[model.tables]".into(), t.span()));
            tables::user_tables(r.path, r.text, t.get_ref())?
        }
        None => AeroModel::default(),
    };
    let datcom = match &m.datcom {
        Some(d) => {
            r.spans.push(("[model] datcom".into(), d.span()));
            let file = relative(r.path, d.get_ref());
            let named_at = r.err(d.span(), "[model] datcom", String::new());
            Some(Datcom::load(&file, &case.planform).map_err(|e| match e {
                Failure::Io(e) => Failure::Io(e.named_at(&named_at)),
                other => other,
            })?)
        }
        None => None,
    };
    case.aero = match &datcom {
        Some(d) => d.tables.under(&user),
        None => user.clone(),
    };
    if let Some(a) = &m.aero {
        r.spans.push(("[model] aero".into(), a.span()));
        let name = AeroModelName::parse(a.get_ref()).ok_or_else(|| {
            let names = AeroModelName::ALL.map(AeroModelName::name);
            r.err(
                a.span(),
                "[model] aero",
                format!(
                    "unknown aerodynamic model `{}`{}; the models are: {}",
                    quote(a.get_ref()),
                    crate::input::suggest::did_you_mean(a.get_ref(), names.iter().copied()),
                    names.join(", ")
                ),
            )
        })?;
        // a table wins over the named model for its coefficient
        case.aero = case.aero.clone().with_name(name);
    }
    Ok((user, datcom))
}

impl Config {
    /// Where the model's tables come from, one line each (none without
    /// tables): the DATCOM output and which quantities it gives, and the
    /// user's own tables.
    pub fn tables_summary(&self) -> Vec<String> {
        let mut out = Vec::new();
        if let Some(d) = &self.datcom {
            let derivatives: Vec<&str> = d.tables.derivatives.0.iter().map(|t| t.name).collect();
            out.push(format!(
                "{}: the lift slope, aerodynamic centre{}, and {} (about h = {}, moved to the c.g.)",
                d.describe(),
                if d.tables.zero_lift_drag.is_some() { ", C_D0" } else { "" },
                derivatives.join(", "),
                sig(d.tables.reference_cg, 3),
            ));
        }
        let mine: Vec<String> = [
            ("lift_slope", &self.tables.lift_slope),
            ("zero_lift_drag", &self.tables.zero_lift_drag),
            ("drag_due_to_lift", &self.tables.drag_due_to_lift),
            ("aerodynamic_centre", &self.tables.aerodynamic_centre),
        ]
        .into_iter()
        .filter(|(_, s)| {
            matches!(
                s,
                stability_core::aerodynamics::models::aero::Source::Table(_)
            )
        })
        .map(|(n, _)| n.to_string())
        .chain(self.tables.derivatives.0.iter().map(|t| {
            let mode = match t.mode {
                stability_core::aerodynamics::models::derivative_tables::Mode::Value => "value",
                stability_core::aerodynamics::models::derivative_tables::Mode::Increment => {
                    "increment"
                }
            };
            match t.reference_cg {
                Some(h) => format!("{} ({mode}, about h = {})", t.name, sig(h, 3)),
                None => format!("{} ({mode})", t.name),
            }
        }))
        .collect();
        if !mine.is_empty() {
            out.push(format!("your [model.tables]: {}", mine.join(", ")));
        }
        out
    }

    /// The config's text, as read.
    pub fn text(&self) -> &str {
        &self.text
    }

    /// Records that the command line replaced `field` (`--mach 1.2`).
    pub fn overridden_by(&mut self, field: &'static str, flag: String) {
        self.overridden.push((field, flag));
    }

    /// The command-line flag that replaced `field` (`--damping faired`),
    /// if one did.
    pub fn overridden_flag(&self, field: &str) -> Option<&str> {
        self.overridden
            .iter()
            .find(|(f, _)| *f == field)
            .map(|(_, flag)| flag.as_str())
    }

    /// An error about `field` (`[flight] mach`, or a table `[flight]`): at
    /// its line, or naming the flag that replaced it.
    pub fn error_at(&self, field: &str, message: impl Into<String>) -> InputError {
        let message = message.into();
        if let Some((_, flag)) = self.overridden.iter().find(|(f, _)| *f == field) {
            return InputError::file(&self.path, format!("{flag}: {message}"));
        }
        let table = field.split(' ').next().unwrap_or(field);
        let found = self
            .spans
            .iter()
            .find(|(f, _)| f == field)
            .or_else(|| self.spans.iter().find(|(f, _)| f == table));
        match found {
            Some((f, span)) => {
                InputError::at(&self.path, &self.text, span.clone(), f.clone(), message)
            }
            None => InputError {
                field: field.to_string(),
                ..InputError::file(&self.path, message)
            },
        }
    }

    /// Where a configuration's failure is reported: its first table.
    fn configuration_field(&self) -> &'static str {
        match &self.configuration {
            Some(c) if c.tailplane.is_some() => "[tailplane]",
            Some(c) if c.foreplane.is_some() => "[foreplane]",
            Some(_) => "[body]",
            None => "[flight]",
        }
    }

    /// The design point's failure, at the field it arises from.
    pub fn explain(&self, e: &CaseError) -> InputError {
        let field = match e {
            CaseError::Aero(
                AeroError::OutsideTable { .. }
                | AeroError::OutsideDerivativeTable { .. }
                | AeroError::OutsideDefaults(_)
                | AeroError::LatticeMach(_),
            ) => "[flight] mach",
            CaseError::Aero(AeroError::Configuration(_)) | CaseError::Configuration(_) => {
                self.configuration_field()
            }
            CaseError::Aero(AeroError::LiftingSurface(_)) => "[model] aero",
            CaseError::Aero(_) => "[model.tables]",
            CaseError::Damping(DampingError::LiftingSurface(LiftingSurfaceError::Mach(_))) => {
                "[flight] mach"
            }
            CaseError::Damping(DampingError::Frequency { .. }) => "[model] omega_bar",
            CaseError::Damping(DampingError::Taper { .. }) => "[planform] taper",
            CaseError::Damping(DampingError::Sweep { .. }) => "[planform] sweep",
            CaseError::Damping(DampingError::Invalid { .. }) => "[flight] cg",
            CaseError::Damping(_) => "[model] damping",
            _ => "[flight]",
        };
        self.error_at(field, e.to_string())
    }
}
