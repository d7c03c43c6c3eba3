//! A config's flight condition in physical form: instead of `mu1`, `i_b`
//! and `cl_m2`,
//!
//! ```toml
//! [flight]
//! mach = 0.8
//! cg = 0.25
//! units = "si"            # "si": m, kg, N; "ft": ft, slug, lbf (and the planform's size with them)
//! altitude = 11000.0      # pressure altitude (= geopotential), 1976 standard atmosphere
//! # geometric_altitude = 11019.0           # a true height instead
//! # rho = 0.3639, speed_of_sound = 295.07  # or the air as given
//! mass = 12000.0          # or weight (N or lbf)
//! I_y = 150000.0          # pitching moment of inertia, kg·m² or slug·ft²
//! ```
//!
//! With the planform's area S and M.A.C. c̄ (its size read in the same
//! units) these give μ₁ = m/(½ρSc̄), i_B = I_y/(mc̄²) and C_L·M² =
//! W/(½ρa²S) ([`stability_core::design::flight`]), and at each Mach number V = M·a,
//! C_L and τ = m/(½ρSV), so that results come in seconds too. A quantity
//! given in both forms (`mu1` and `mass`, say) is an error naming both.

use super::Reader;
use super::raw::RawFlight;
use crate::diag::{InputError, quote};
use crate::limits;
use stability_core::design::case::Case;
use stability_core::design::flight::{
    Air, Altitude, FlightCondition, FlightError, FlightInput, Mass, PhysicalFlight, Units,
};
use stability_core::geometry::Planform;
use stability_core::numerics::display::Num;
use std::ops::Range;
use toml::Spanned;

/// A physical flight condition as given, and with the config's planform.
#[derive(Debug, Clone, PartialEq)]
pub struct Physical {
    pub condition: FlightCondition,
    pub flight: PhysicalFlight,
}

impl Physical {
    /// The condition with another planform (a sweep's): μ₁, i_B and C_L·M²
    /// follow its area and M.A.C.
    pub fn with_planform(&self, p: &Planform) -> Result<PhysicalFlight, FlightError> {
        self.condition.for_planform(p)
    }
}

/// A physical field's name and value as written.
type Field<'a> = (&'static str, &'a Spanned<f64>);

/// The physical fields given, in the order of the docs.
fn physical_fields(f: &RawFlight) -> Vec<Field<'_>> {
    [
        ("altitude", &f.altitude),
        ("geometric_altitude", &f.geometric_altitude),
        ("rho", &f.rho),
        ("speed_of_sound", &f.speed_of_sound),
        ("mass", &f.mass),
        ("weight", &f.weight),
        ("I_y", &f.i_y),
    ]
    .into_iter()
    .filter_map(|(n, v)| v.as_ref().map(|v| (n, v)))
    .collect()
}

const BOTH_FORMS: &str = "give the non-dimensional flight condition (mu1, i_b, cl_m2) or the physical one (units, altitude or rho with speed_of_sound, mass or weight, I_y), not both";

/// μ₁, i_B and C_L·M² of the config, and the physical condition they came
/// from when it is physical.
pub(super) fn flight_parameters(
    r: &mut Reader<'_>,
    f: &RawFlight,
    whole: Range<usize>,
    planform: &Planform,
) -> Result<([f64; 3], Option<Physical>), InputError> {
    let given = physical_fields(f);
    let nondimensional = [("mu1", &f.mu1), ("i_b", &f.i_b), ("cl_m2", &f.cl_m2)];
    if given.is_empty() && f.units.is_none() {
        let limits = [&limits::MU1, &limits::I_B, &limits::CL_M2];
        let mut out = [0.0; 3];
        for (k, (name, v)) in nondimensional.iter().enumerate() {
            let Some(v) = v else {
                let m = format!(
                    "missing field `{name}`: give mu1, i_b and cl_m2, or a physical flight condition (units, altitude, mass, I_y; see `analyze --help`)"
                );
                return Err(r.err(whole, &format!("[flight] {name}"), m));
            };
            out[k] = r.value(v, &format!("[flight] {name}"), limits[k])?;
        }
        return Ok((out, None));
    }
    for (name, v) in nondimensional {
        if let Some(v) = v {
            let other = counterpart(name, f, &given);
            let m = format!(
                "[flight] {name} and [flight] {other} both give {}: {BOTH_FORMS}",
                meaning(name)
            );
            return Err(r.err(v.span(), &format!("[flight] {name}"), m));
        }
    }
    let condition = condition(r, f, whole)?;
    let flight = condition
        .for_planform(planform)
        .map_err(|e| flight_error(r, f, &e))?;
    let values = [flight.mu1(), flight.i_b(), flight.cl_m2()];
    derived_within_limits(r, f, &values)?;
    Ok((values, Some(Physical { condition, flight })))
}

/// What a non-dimensional field stands for, in words.
fn meaning(name: &str) -> &'static str {
    match name {
        "mu1" => "the relative density μ₁ = m/(½ρSc̄)",
        "i_b" => "the pitching inertia i_B = I_y/(mc̄²)",
        _ => "C_L·M² = W/(½ρa²S) (eq 24)",
    }
}

/// The physical field that gives the same quantity as `name`.
fn counterpart(name: &str, f: &RawFlight, given: &[Field<'_>]) -> &'static str {
    let first_of = |names: &[&'static str]| {
        names
            .iter()
            .copied()
            .find(|n| given.iter().any(|g| g.0 == *n))
    };
    let preferred: &[&'static str] = match name {
        "i_b" => &["I_y", "mass", "weight"],
        "cl_m2" => &["weight", "mass", "altitude", "geometric_altitude", "rho"],
        _ => &["mass", "weight", "altitude", "geometric_altitude", "rho"],
    };
    first_of(preferred)
        .or_else(|| given.first().map(|g| g.0))
        .unwrap_or(if f.units.is_some() { "units" } else { "I_y" })
}

/// The condition as written: units, air, mass, I_y.
fn condition(
    r: &mut Reader<'_>,
    f: &RawFlight,
    whole: Range<usize>,
) -> Result<FlightCondition, InputError> {
    for (name, v) in physical_fields(f) {
        r.spans.push((format!("[flight] {name}"), v.span()));
    }
    let units = units(r, f, whole.clone())?;
    let air = air(r, f, whole.clone())?;
    let mass = match (&f.mass, &f.weight) {
        (Some(m), None) => Mass::Mass(*m.get_ref()),
        (None, Some(w)) => Mass::Weight(*w.get_ref()),
        (Some(_), Some(w)) => {
            let m = "[flight] mass and [flight] weight both give the mass: give one";
            return Err(r.err(w.span(), "[flight] weight", m.into()));
        }
        (None, None) => {
            let m = "missing: give mass (kg or slug) or weight (N or lbf)";
            return Err(r.err(whole, "[flight] mass", m.into()));
        }
    };
    let Some(i_y) = &f.i_y else {
        let m =
            "missing: the pitching moment of inertia I_y (kg·m² or slug·ft²) gives i_B = I_y/(mc̄²)";
        return Err(r.err(whole, "[flight] I_y", m.into()));
    };
    Ok(FlightCondition {
        units,
        air,
        mass,
        pitch_inertia: *i_y.get_ref(),
    })
}

fn units(r: &mut Reader<'_>, f: &RawFlight, whole: Range<usize>) -> Result<Units, InputError> {
    let Some(u) = &f.units else {
        let m = "missing: a physical flight condition needs its units, \"si\" (m, kg, N) or \"ft\" (ft, slug, lbf); the planform's size is read in them too";
        return Err(r.err(whole, "[flight] units", m.into()));
    };
    r.spans.push(("[flight] units".into(), u.span()));
    Units::parse(u.get_ref()).map_err(|_| {
        let names = Units::ALL.map(Units::name);
        let hint = crate::input::suggest::did_you_mean(u.get_ref(), names);
        let m = format!(
            "unknown units `{}`: the units are `si` (m, kg, N, s) and `ft` (ft, slug, lbf, s){hint}",
            quote(u.get_ref())
        );
        r.err(u.span(), "[flight] units", m)
    })
}

/// The air: an altitude, a geometric altitude, or ρ with the speed of sound.
fn air(r: &mut Reader<'_>, f: &RawFlight, whole: Range<usize>) -> Result<Air, InputError> {
    let sources: Vec<Field<'_>> = [
        ("altitude", &f.altitude),
        ("geometric_altitude", &f.geometric_altitude),
        ("rho", &f.rho),
    ]
    .into_iter()
    .filter_map(|(n, v)| v.as_ref().map(|v| (n, v)))
    .collect();
    let (name, v) = match sources.as_slice() {
        [] if f.speed_of_sound.is_some() => {
            let m = "speed_of_sound needs rho beside it (or give an altitude instead)";
            let s = f.speed_of_sound.as_ref().map_or(whole, |v| v.span());
            return Err(r.err(s, "[flight] speed_of_sound", m.into()));
        }
        [] => {
            let m = "missing: give altitude (pressure altitude, 1976 standard atmosphere), geometric_altitude, or rho with speed_of_sound";
            return Err(r.err(whole, "[flight] altitude", m.into()));
        }
        [one] => *one,
        [first, second, ..] => {
            let m = format!(
                "[flight] {} and [flight] {} both give the air's density: give one",
                first.0, second.0
            );
            return Err(r.err(second.1.span(), &format!("[flight] {}", second.0), m));
        }
    };
    let x = *v.get_ref();
    match name {
        "altitude" => Ok(Air::Standard(Altitude::Pressure(x))),
        "geometric_altitude" => Ok(Air::Standard(Altitude::Geometric(x))),
        _ => match &f.speed_of_sound {
            Some(a) => Ok(Air::Given {
                density: x,
                speed_of_sound: *a.get_ref(),
            }),
            None => {
                let m = "rho needs speed_of_sound beside it (V = M·a), or give an altitude instead";
                Err(r.err(v.span(), "[flight] rho", m.into()))
            }
        },
    }
}

/// A resolution error at the field it comes from.
fn flight_error(r: &Reader<'_>, f: &RawFlight, e: &FlightError) -> InputError {
    let field = match e {
        FlightError::Atmosphere(_) => {
            if f.altitude.is_some() {
                "altitude"
            } else {
                "geometric_altitude"
            }
        }
        FlightError::Invalid(e) => match e.quantity() {
            FlightInput::Density => "rho",
            FlightInput::SpeedOfSound => "speed_of_sound",
            FlightInput::Mass => "mass",
            FlightInput::Weight => "weight",
            FlightInput::PitchInertia => "I_y",
            FlightInput::Area | FlightInput::Chord => {
                return r.err_field("[planform]", e.to_string());
            }
            FlightInput::Altitude | FlightInput::Mach => "altitude",
        },
    };
    r.err_field(&format!("[flight] {field}"), e.to_string())
}

/// μ₁, i_B and C_L·M² from the physical values, each within its range.
fn derived_within_limits(r: &Reader<'_>, f: &RawFlight, v: &[f64; 3]) -> Result<(), InputError> {
    let mass_field = if f.mass.is_some() { "mass" } else { "weight" };
    let checks = [
        (&limits::MU1, "μ₁ = m/(½ρSc̄)", mass_field),
        (&limits::I_B, "i_B = I_y/(mc̄²)", "I_y"),
        (&limits::CL_M2, "C_L·M² = W/(½ρa²S)", mass_field),
    ];
    for (k, (limit, what, field)) in checks.iter().enumerate() {
        if let Err(m) = limit.check(v[k]) {
            let m = format!(
                "{what} = {} from this flight condition and the planform: {m}",
                Num(v[k])
            );
            return Err(r.err_field(&format!("[flight] {field}"), m));
        }
    }
    Ok(())
}

/// Recomputes a design point's μ₁, i_B and C_L·M² for its planform.
pub fn apply(physical: &Physical, case: &mut Case) -> Result<PhysicalFlight, FlightError> {
    let flight = physical.with_planform(&case.planform)?;
    flight.apply(case);
    Ok(flight)
}
