//! A physical flight condition: the air (an altitude in the 1976 standard
//! atmosphere, or ρ and the speed of sound directly), the mass or weight,
//! the pitching moment of inertia I_y and the wing's area and reference
//! chord, in SI or ft–slug units — and from them the report's
//! non-dimensional flight parameters (§3, eq 24) and its unit of time.
//!
//! With S the wing area, c̄ the reference chord (the M.A.C. of the
//! planform, [`Planform::reference_chord`]), m the mass, W = m·g₀ the
//! weight, ρ the density and a the speed of sound:
//!
//! - relative density μ₁ = m/(½ρSc̄) (§3);
//! - pitching inertia i_B = I_y/(mc̄²) (§3; the report's B is I_y);
//! - C_L·M² = W/(½ρa²S) (eq 24), constant in level flight at one altitude
//!   and weight;
//! - at Mach number M: V = M·a, C_L = W/(½ρV²S) = (C_L·M²)/M² and
//!   τ = m/(½ρSV) (§3), so that a root λ̂ (units of 1/τ) is λ = λ̂/τ in 1/s.
//!
//! So in a sweep over Mach number at a fixed altitude and weight μ₁, i_B
//! and C_L·M² stay fixed while V, C_L and τ change with M (C_L ∝ 1/M²,
//! τ ∝ 1/M); `tests/flight.rs` checks both.
//!
//! Units: `"si"` is metres, kilograms, newtons and seconds; `"ft"` is feet,
//! slugs, pounds-force and seconds. The weight is m·g₀ with the standard
//! g₀ = 9.806 65 m/s² = 32.174 05 ft/s² in either system (a weight in lbf
//! is a mass in lbm), so a weight and a mass give the same condition.
//!
//! # Altitudes
//! An altitude is the *pressure* altitude that flight manuals and
//! flight-test reports quote, which in the standard atmosphere is the
//! geopotential altitude H ([`Atmosphere::at_geopotential`]); a true
//! (geometric) height Z is given explicitly as such
//! ([`Atmosphere::at_geometric`]). Both lie between 0 and 86 km.

use crate::analysis::{Dimensional, STANDARD_GRAVITY};
use crate::design::atmosphere::{Atmosphere, AtmosphereError};
use crate::design::case::Case;
use crate::geometry::Planform;
use crate::numerics::invalid::{self, Invalid};
pub use crate::units::{Units, UnknownUnits};
use serde::Serialize;

/// An altitude, in the units' length.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Altitude {
    /// Pressure altitude, = geopotential altitude in the standard
    /// atmosphere: what flight manuals and reports quote.
    Pressure(f64),
    /// True (geometric) height above sea level.
    Geometric(f64),
}

/// Where the density and speed of sound come from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Air {
    /// The U.S. Standard Atmosphere, 1976, at an altitude.
    Standard(Altitude),
    /// ρ and a as given, in the units (kg/m³ and m/s, or slug/ft³ and ft/s).
    Given { density: f64, speed_of_sound: f64 },
}

/// The mass, or the weight W = m·g₀, in the units (kg or N; slug or lbf).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Mass {
    Mass(f64),
    Weight(f64),
}

/// A physical flight condition, before it meets a wing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlightCondition {
    pub units: Units,
    pub air: Air,
    pub mass: Mass,
    /// The pitching moment of inertia I_y (the report's B), kg·m² or slug·ft².
    pub pitch_inertia: f64,
}

/// A quantity of a physical flight condition.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FlightInput {
    Altitude,
    Density,
    SpeedOfSound,
    Mass,
    Weight,
    PitchInertia,
    Area,
    Chord,
    Mach,
}

impl std::fmt::Display for FlightInput {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            FlightInput::Altitude => "the altitude",
            FlightInput::Density => "the density ρ",
            FlightInput::SpeedOfSound => "the speed of sound",
            FlightInput::Mass => "the mass",
            FlightInput::Weight => "the weight",
            FlightInput::PitchInertia => "the pitching moment of inertia I_y",
            FlightInput::Area => "the wing area S",
            FlightInput::Chord => "the reference chord c̄",
            FlightInput::Mach => "the Mach number",
        })
    }
}

/// Why a physical flight condition has no non-dimensional form.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FlightError {
    #[error(transparent)]
    Invalid(#[from] Invalid<FlightInput>),
    #[error("the altitude: {0}")]
    Atmosphere(#[from] AtmosphereError),
}

fn positive(quantity: FlightInput, value: f64) -> Result<f64, FlightError> {
    Ok(invalid::positive(quantity, value)?)
}

/// A physical flight condition with its wing, in SI units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PhysicalFlight {
    /// The units it was given in (for display).
    pub units: Units,
    /// The standard atmosphere's state, when the air came from an altitude.
    pub atmosphere: Option<Atmosphere>,
    /// Which altitude was given, when one was.
    pub altitude: Option<Altitude>,
    /// ρ, kg/m³.
    pub density: f64,
    /// a, m/s.
    pub speed_of_sound: f64,
    /// m, kg.
    pub mass: f64,
    /// W = m·g₀, N.
    pub weight: f64,
    /// I_y, kg·m².
    pub pitch_inertia: f64,
    /// S, m².
    pub area: f64,
    /// c̄, m.
    pub chord: f64,
}

impl FlightCondition {
    /// The condition with a wing of `area` and reference chord `chord`,
    /// both in the condition's units (ft², ft or m², m).
    pub fn resolve(&self, area: f64, chord: f64) -> Result<PhysicalFlight, FlightError> {
        let u = self.units;
        let (atmosphere, altitude, density, speed_of_sound) = match self.air {
            Air::Standard(alt) => {
                let atm = match alt {
                    Altitude::Pressure(h) => Atmosphere::at_geopotential(h * u.length())?,
                    Altitude::Geometric(z) => Atmosphere::at_geometric(z * u.length())?,
                };
                (Some(atm), Some(alt), atm.density, atm.speed_of_sound)
            }
            Air::Given {
                density,
                speed_of_sound,
            } => (
                None,
                None,
                positive(FlightInput::Density, density)? * u.density(),
                positive(FlightInput::SpeedOfSound, speed_of_sound)? * u.length(),
            ),
        };
        let mass = match self.mass {
            Mass::Mass(m) => positive(FlightInput::Mass, m)? * u.mass(),
            Mass::Weight(w) => positive(FlightInput::Weight, w)? * u.force() / STANDARD_GRAVITY,
        };
        Ok(PhysicalFlight {
            units: u,
            atmosphere,
            altitude,
            density,
            speed_of_sound,
            mass,
            weight: mass * STANDARD_GRAVITY,
            pitch_inertia: positive(FlightInput::PitchInertia, self.pitch_inertia)? * u.inertia(),
            area: positive(FlightInput::Area, area)? * u.length().powi(2),
            chord: positive(FlightInput::Chord, chord)? * u.length(),
        })
    }

    /// The condition with the planform's area and reference chord (the
    /// M.A.C.), its size read in the condition's units.
    pub fn for_planform(&self, p: &Planform) -> Result<PhysicalFlight, FlightError> {
        self.resolve(p.area(), p.reference_chord())
    }
}

/// A physical flight condition at one Mach number.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FlightPoint {
    pub mach: f64,
    /// V = M·a, m/s.
    pub speed: f64,
    /// ½ρV², Pa.
    pub dynamic_pressure: f64,
    /// C_L = W/(½ρV²S) of level flight (eq 24).
    pub c_l: f64,
    /// τ = m/(½ρSV), s (§3).
    pub tau: f64,
}

impl PhysicalFlight {
    /// μ₁ = m/(½ρSc̄), §3.
    pub fn mu1(&self) -> f64 {
        self.mass / (0.5 * self.density * self.area * self.chord)
    }

    /// i_B = I_y/(mc̄²), §3.
    pub fn i_b(&self) -> f64 {
        self.pitch_inertia / (self.mass * self.chord * self.chord)
    }

    /// C_L·M² = W/(½ρa²S), eq (24).
    pub fn cl_m2(&self) -> f64 {
        self.weight / (0.5 * self.density * self.speed_of_sound.powi(2) * self.area)
    }

    /// The condition at Mach number `mach` (V = M·a).
    pub fn at_mach(&self, mach: f64) -> Result<FlightPoint, FlightError> {
        let mach = positive(FlightInput::Mach, mach)?;
        let speed = mach * self.speed_of_sound;
        let dynamic_pressure = 0.5 * self.density * speed * speed;
        Ok(FlightPoint {
            mach,
            speed,
            dynamic_pressure,
            c_l: self.weight / (dynamic_pressure * self.area),
            tau: self.mass / (0.5 * self.density * self.area * speed),
        })
    }

    /// The dimensional flight condition of [`crate::analysis`] at a point.
    pub fn dimensional(&self, point: &FlightPoint) -> Dimensional {
        Dimensional {
            v: point.speed,
            rho: self.density,
            s: self.area,
            chord: self.chord,
            mass: self.mass,
        }
    }

    /// Puts this condition's μ₁, i_B and C_L·M² into a design point.
    pub fn apply(&self, case: &mut Case) {
        case.mu1 = self.mu1();
        case.i_b = self.i_b();
        case.cl_m2 = self.cl_m2();
    }

    /// This condition at `point`, for JSON (SI keys, units in the names).
    pub fn json(&self, point: &FlightPoint) -> FlightJson {
        let (pressure_altitude, geometric_altitude) = match self.atmosphere {
            Some(a) => (Some(a.geopotential_altitude), Some(a.geometric_altitude)),
            None => (None, None),
        };
        FlightJson {
            units: self.units,
            atmosphere: match self.altitude {
                Some(Altitude::Pressure(_)) => "us1976, pressure (geopotential) altitude",
                Some(Altitude::Geometric(_)) => "us1976, geometric altitude",
                None => "given: rho and speed of sound",
            },
            pressure_altitude_m: pressure_altitude,
            geometric_altitude_m: geometric_altitude,
            density_kg_m3: self.density,
            speed_of_sound_m_s: self.speed_of_sound,
            mass_kg: self.mass,
            weight_n: self.weight,
            pitch_inertia_kg_m2: self.pitch_inertia,
            area_m2: self.area,
            chord_m: self.chord,
            mach: point.mach,
            speed_m_s: point.speed,
            dynamic_pressure_pa: point.dynamic_pressure,
            mu1: self.mu1(),
            i_b: self.i_b(),
            cl_m2: self.cl_m2(),
            c_l: point.c_l,
            tau_s: point.tau,
        }
    }
}

/// A physical flight condition as `analyze --json` prints it (`flight`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FlightJson {
    pub units: Units,
    pub atmosphere: &'static str,
    pub pressure_altitude_m: Option<f64>,
    pub geometric_altitude_m: Option<f64>,
    pub density_kg_m3: f64,
    pub speed_of_sound_m_s: f64,
    pub mass_kg: f64,
    pub weight_n: f64,
    pub pitch_inertia_kg_m2: f64,
    pub area_m2: f64,
    pub chord_m: f64,
    pub mach: f64,
    pub speed_m_s: f64,
    pub dynamic_pressure_pa: f64,
    pub mu1: f64,
    pub i_b: f64,
    pub cl_m2: f64,
    pub c_l: f64,
    pub tau_s: f64,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_convert_by_their_definitions() {
        assert_eq!(Units::parse("ft"), Ok(Units::Ft));
        assert!(Units::parse("SI").is_err());
        // 1 slug = 14.593 902 937 206 kg; 1 lbf = 4.448 221 615 260 5 N
        assert!((Units::Ft.mass() - 14.593_902_937_206).abs() < 1e-9);
        assert!((Units::Ft.force() - 4.448_221_615_260_5).abs() < 1e-12);
        // 1 slug/ft³ = 515.378 818 kg/m³; 1 slug·ft² = 1.355 817 948 kg·m²
        assert!((Units::Ft.density() - 515.378_818_4).abs() < 1e-6);
        assert!((Units::Ft.inertia() - 1.355_817_948_3).abs() < 1e-9);
        assert!((Units::Ft.gravity() - 32.174_048_556).abs() < 1e-8);
    }

    #[test]
    fn a_weight_and_its_mass_are_the_same_condition() {
        let air = Air::Given {
            density: 0.4,
            speed_of_sound: 300.0,
        };
        let by = |mass| FlightCondition {
            units: Units::Si,
            air,
            mass,
            pitch_inertia: 1e5,
        };
        let a = by(Mass::Mass(10_000.0)).resolve(50.0, 5.0).unwrap();
        let b = by(Mass::Weight(10_000.0 * STANDARD_GRAVITY))
            .resolve(50.0, 5.0)
            .unwrap();
        assert!((a.mass - b.mass).abs() < 1e-9 && (a.weight - b.weight).abs() < 1e-6);
    }

    #[test]
    fn nonsense_is_refused_by_name() {
        let c = FlightCondition {
            units: Units::Si,
            air: Air::Standard(Altitude::Pressure(-10.0)),
            mass: Mass::Mass(1.0),
            pitch_inertia: 1.0,
        };
        assert!(matches!(
            c.resolve(1.0, 1.0),
            Err(FlightError::Atmosphere(_))
        ));
        let c = FlightCondition {
            air: Air::Standard(Altitude::Pressure(0.0)),
            mass: Mass::Weight(f64::NAN),
            ..c
        };
        assert!(matches!(
            c.resolve(1.0, 1.0),
            Err(FlightError::Invalid(Invalid::NonFinite {
                quantity: FlightInput::Weight,
                ..
            }))
        ));
        let p = FlightCondition {
            mass: Mass::Mass(1.0),
            ..c
        }
        .resolve(1.0, 1.0)
        .unwrap();
        assert!(p.at_mach(0.0).is_err() && p.at_mach(f64::INFINITY).is_err());
    }
}
