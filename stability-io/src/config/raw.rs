//! A config as TOML gives it: spanned values, before any checks.

use serde::Deserialize;
use toml::Spanned;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawConfig {
    pub planform: Spanned<RawPlanform>,
    pub flight: Spanned<RawFlight>,
    #[serde(default)]
    pub model: Option<Spanned<RawModel>>,
    /// The control derivatives, read by [`crate::control`].
    #[serde(default)]
    pub control: Option<toml::Value>,
    /// The uncertainty study, read by [`super::uncertainty`].
    #[serde(default)]
    pub uncertainty: Option<toml::Value>,
    /// What the aircraft is (its MIL-F-8785C class).
    #[serde(default)]
    pub aircraft: Option<Spanned<RawAircraft>>,
    /// The configuration's surfaces and body, read by [`super::surfaces`].
    #[serde(default)]
    pub tailplane: Option<Spanned<RawSurface>>,
    #[serde(default)]
    pub foreplane: Option<Spanned<RawSurface>>,
    #[serde(default)]
    pub body: Option<Spanned<RawBody>>,
}

/// `[tailplane]`, `[foreplane]`: `[planform]`'s keys and the placement.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawSurface {
    pub sweep: Spanned<f64>,
    #[serde(default)]
    pub taper: Option<Spanned<f64>>,
    pub root_chord: Option<Spanned<f64>>,
    pub span: Option<Spanned<f64>>,
    pub area: Option<Spanned<f64>>,
    /// Its apex aft of the wing's apex (negative ahead).
    pub x: Spanned<f64>,
    /// Its height above the wing's plane.
    #[serde(default)]
    pub z: Option<Spanned<f64>>,
    /// Degrees.
    #[serde(default)]
    pub incidence: Option<Spanned<f64>>,
}

impl RawSurface {
    /// Its planform keys, as `[planform]`'s.
    pub fn planform(&self) -> RawPlanform {
        RawPlanform {
            sweep: self.sweep.clone(),
            taper: self.taper.clone(),
            root_chord: self.root_chord.clone(),
            span: self.span.clone(),
            area: self.area.clone(),
        }
    }
}

/// `[body]`: eq (43)'s forebody.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawBody {
    /// Its length ahead of the wing's apex.
    pub length_ahead: Spanned<f64>,
    pub diameter: Spanned<f64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawAircraft {
    /// The MIL-F-8785C class, §1.3: `I`, `II-C`, `II-L`, `III` or `IV`.
    pub class: Option<Spanned<String>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawPlanform {
    pub sweep: Spanned<f64>,
    #[serde(default)]
    pub taper: Option<Spanned<f64>>,
    pub root_chord: Option<Spanned<f64>>,
    pub span: Option<Spanned<f64>>,
    pub area: Option<Spanned<f64>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawFlight {
    pub mach: Spanned<f64>,
    pub cg: Spanned<f64>,
    /// The non-dimensional flight condition (or the physical one below).
    pub mu1: Option<Spanned<f64>>,
    pub i_b: Option<Spanned<f64>>,
    pub cl_m2: Option<Spanned<f64>>,
    /// The physical flight condition instead ([`super::physical`]).
    pub units: Option<Spanned<String>>,
    pub altitude: Option<Spanned<f64>>,
    pub geometric_altitude: Option<Spanned<f64>>,
    pub rho: Option<Spanned<f64>>,
    pub speed_of_sound: Option<Spanned<f64>>,
    pub mass: Option<Spanned<f64>>,
    pub weight: Option<Spanned<f64>>,
    #[serde(rename = "I_y")]
    pub i_y: Option<Spanned<f64>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawModel {
    pub damping: Option<Spanned<String>>,
    pub aero: Option<Spanned<String>>,
    pub omega_bar: Option<Spanned<f64>>,
    pub iterate_frequency: Option<bool>,
    pub frequency_method: Option<Spanned<String>>,
    /// A DATCOM output (`for006.dat`) whose tables the model takes.
    pub datcom: Option<Spanned<String>>,
    pub tables: Option<Spanned<RawTables>>,
}

/// The tables by name: the coefficients of §6 (`lift_slope`,
/// `zero_lift_drag`, `drag_due_to_lift`, `aerodynamic_centre`) and the
/// derivatives of the report's notation (`m_q`, `z_wdot` or `z_ẇ`, …).
pub type RawTables = std::collections::BTreeMap<String, Spanned<RawTable>>;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawTable {
    pub mach: Option<Vec<Spanned<f64>>>,
    #[serde(alias = "values")]
    pub value: Option<Vec<Spanned<f64>>>,
    pub file: Option<Spanned<String>>,
    /// A derivative's: `value` (the default) or `increment`.
    pub mode: Option<Spanned<String>>,
    /// A derivative's: the c.g. h its values are about (default: the
    /// case's).
    pub cg: Option<Spanned<f64>>,
}
