//! The U.S. Standard Atmosphere, 1976, from sea level to 86 km.
//!
//! Reference: U.S. Committee on Extension to the Standard Atmosphere
//! (COESA), *U.S. Standard Atmosphere, 1976*, NOAA-S/T 76-1562 /
//! NASA-TM-X-74335, U.S. Government Printing Office, Washington D.C.,
//! October 1976 ("the standard"). Below 32 km it is identical with the ICAO
//! standard atmosphere.
//!
//! The standard defines the lower atmosphere by seven layers in which the
//! *molecular-scale* temperature T_M varies linearly with *geopotential*
//! altitude H (its Table 4), with a constant mean molecular weight M₀ up to
//! 80 km. Pressure follows from the hydrostatic equation (its eqs 33a and
//! 33b), density from the equation of state (eq 42), speed of sound from
//! eq (50) and dynamic viscosity from Sutherland's law (eq 51). Between 80 and
//! 86 km the kinetic temperature T differs from T_M by the ratio M/M₀ of its
//! Table 8; pressure, density and speed of sound depend on T_M only, so they
//! are unaffected.
//!
//! Symbols are the standard's: Z geometric altitude (m), H geopotential
//! altitude (m′, geopotential metres), T_M, T (K), P (Pa), ρ (kg/m³),
//! C_s (m/s), μ (N·s/m²).
//!
//! # Limits
//! - Geometric altitude 0 ≤ Z ≤ 86 000 m, i.e. geopotential
//!   0 ≤ H ≤ 84 852.05 m′ (the standard prints the upper bound as
//!   84.8520 km′, its rounding of eq 18 applied to 86 km). The standard's
//!   tables start at −5 km; this module refuses negative altitudes, as it
//!   refuses the region above 86 km where the standard's composition model
//!   (diffusive separation, no hydrostatic layers) takes over. Either is an
//!   [`AtmosphereError`], never an extrapolation.
//! - Speed of sound and viscosity, like the standard's own tables, are given
//!   to 86 km only.
//! - Between the 0.5 km points of Table 8 (80–86 km) M/M₀ is interpolated
//!   linearly in Z; the standard tabulates it without prescribing an
//!   interpolation.

pub use crate::units::{FOOT, KG_PER_SLUG, NEWTON_PER_LBF};
use serde::Serialize;

/// Standard acceleration of gravity g₀ = 9.80665 m/s²; also g₀′, the
/// constant that defines the geopotential metre (m²/(s²·m′)).
pub const G0: f64 = crate::units::STANDARD_GRAVITY;
/// Universal gas constant R* = 8.31432 × 10³ N·m/(kmol·K), the standard's
/// value (not the later CODATA one).
pub const R_STAR: f64 = 8.314_32e3;
/// Sea-level mean molecular weight M₀ = 28.9644 kg/kmol.
pub const M0: f64 = 28.9644;
/// Effective Earth radius r₀ = 6 356 766 m used in eq (18).
pub const R0: f64 = 6_356_766.0;
/// Ratio of specific heats of air γ = 1.40.
pub const GAMMA: f64 = 1.40;
/// Sutherland's constant β = 1.458 × 10⁻⁶ kg/(s·m·K^½), eq (51).
pub const SUTHERLAND_BETA: f64 = 1.458e-6;
/// Sutherland's constant S = 110.4 K, eq (51).
pub const SUTHERLAND_S: f64 = 110.4;
/// Sea-level pressure P₀ = 101 325 Pa.
pub const P0: f64 = 101_325.0;
/// Sea-level temperature T₀ = 288.15 K.
pub const T0: f64 = 288.15;
/// Upper limit of the model, geometric: 86 km.
pub const Z_MAX: f64 = 86_000.0;

/// The pascal per lbf/ft².
const PA_PER_PSF: f64 = 0.453_592_37 * G0 / (FOOT * FOOT);

/// Table 4: the base geopotential altitude H_b (m′) and the molecular-scale
/// temperature gradient L_M,b (K/m′) of the seven layers, b = 0 … 6.
const LAYERS: [(f64, f64); 7] = [
    (0.0, -6.5e-3),
    (11_000.0, 0.0),
    (20_000.0, 1.0e-3),
    (32_000.0, 2.8e-3),
    (47_000.0, 0.0),
    (51_000.0, -2.8e-3),
    (71_000.0, -2.0e-3),
];

/// Table 8: M/M₀ at geometric altitudes 80.0, 80.5, …, 86.0 km.
const MOLECULAR_WEIGHT_RATIO: [f64; 13] = [
    1.000_000, 0.999_996, 0.999_989, 0.999_971, 0.999_941, 0.999_909, 0.999_870, 0.999_829,
    0.999_786, 0.999_741, 0.999_694, 0.999_641, 0.999_579,
];

/// An altitude the 1976 standard atmosphere (as implemented here) does not
/// cover.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum AtmosphereError {
    /// The altitude is NaN or infinite.
    #[error("altitude {0} is not a finite number")]
    NotFinite(f64),
    /// Below sea level (Z < 0).
    #[error(
        "altitude {geometric_m} m (geometric) is below sea level: the 1976 standard atmosphere is implemented from 0 to 86 km"
    )]
    BelowSeaLevel {
        /// The geometric altitude asked for, m.
        geometric_m: f64,
    },
    /// Above 86 km geometric (84 852 m′ geopotential), where the standard's
    /// hydrostatic layers end.
    #[error(
        "altitude {geometric_m} m (geometric) is above 86 km, the top of the 1976 standard's hydrostatic layers"
    )]
    AboveModel {
        /// The geometric altitude asked for, m.
        geometric_m: f64,
    },
}

/// Geopotential altitude H (m′) of a geometric altitude Z (m), eq (18):
/// H = r₀Z/(r₀ + Z).
pub fn geopotential_from_geometric(z: f64) -> f64 {
    R0 * z / (R0 + z)
}

/// Geometric altitude Z (m) of a geopotential altitude H (m′), the inverse
/// of eq (18): Z = r₀H/(r₀ − H).
pub fn geometric_from_geopotential(h: f64) -> f64 {
    R0 * h / (R0 - h)
}

/// The state of the standard atmosphere at one altitude, SI units.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Atmosphere {
    /// Geometric altitude Z, m.
    pub geometric_altitude: f64,
    /// Geopotential altitude H, m′.
    pub geopotential_altitude: f64,
    /// Kinetic temperature T, K (equal to T_M below 80 km).
    pub temperature: f64,
    /// Molecular-scale temperature T_M, K.
    pub molecular_temperature: f64,
    /// Pressure P, Pa.
    pub pressure: f64,
    /// Density ρ, kg/m³.
    pub density: f64,
    /// Speed of sound C_s, m/s.
    pub speed_of_sound: f64,
    /// Dynamic viscosity μ, N·s/m² (Pa·s).
    pub dynamic_viscosity: f64,
}

impl Atmosphere {
    /// The atmosphere at geometric altitude `z` (m).
    pub fn at_geometric(z: f64) -> Result<Self, AtmosphereError> {
        if !z.is_finite() {
            return Err(AtmosphereError::NotFinite(z));
        }
        if z < 0.0 {
            return Err(AtmosphereError::BelowSeaLevel { geometric_m: z });
        }
        if z > Z_MAX {
            return Err(AtmosphereError::AboveModel { geometric_m: z });
        }
        Ok(Self::evaluate(z, geopotential_from_geometric(z)))
    }

    /// The atmosphere at geopotential altitude `h` (m′). In the standard
    /// atmosphere this is also the pressure altitude that altimeters and
    /// most flight-test reports quote.
    pub fn at_geopotential(h: f64) -> Result<Self, AtmosphereError> {
        if !h.is_finite() {
            return Err(AtmosphereError::NotFinite(h));
        }
        if h < 0.0 {
            return Err(AtmosphereError::BelowSeaLevel {
                geometric_m: geometric_from_geopotential(h),
            });
        }
        // r₀ − H > 0 for every H below 86 km; beyond, the check below fires
        // before the inverse of eq (18) could blow up.
        if h > geopotential_from_geometric(Z_MAX) {
            let z = if h < R0 {
                geometric_from_geopotential(h)
            } else {
                f64::INFINITY
            };
            return Err(AtmosphereError::AboveModel { geometric_m: z });
        }
        Ok(Self::evaluate(geometric_from_geopotential(h).min(Z_MAX), h))
    }

    /// The atmosphere at geometric altitude `z_ft` in feet.
    pub fn at_geometric_ft(z_ft: f64) -> Result<Self, AtmosphereError> {
        Self::at_geometric(z_ft * FOOT)
    }

    /// The atmosphere at geopotential (pressure) altitude `h_ft` in
    /// geopotential feet.
    pub fn at_geopotential_ft(h_ft: f64) -> Result<Self, AtmosphereError> {
        Self::at_geopotential(h_ft * FOOT)
    }

    /// Every property from a consistent (Z, H) pair inside the model.
    fn evaluate(z: f64, h: f64) -> Self {
        let (t_m, p) = molecular_temperature_and_pressure(h);
        let t = t_m * molecular_weight_ratio(z);
        Self {
            geometric_altitude: z,
            geopotential_altitude: h,
            temperature: t,
            molecular_temperature: t_m,
            pressure: p,
            density: density(p, t_m),
            speed_of_sound: speed_of_sound(t_m),
            dynamic_viscosity: dynamic_viscosity(t),
        }
    }

    /// Kinematic viscosity η = μ/ρ, m²/s.
    pub fn kinematic_viscosity(&self) -> f64 {
        self.dynamic_viscosity / self.density
    }

    /// Density ratio σ = ρ/ρ₀.
    pub fn density_ratio(&self) -> f64 {
        self.density / density(P0, T0)
    }

    /// Density in slug/ft³.
    pub fn density_slug_ft3(&self) -> f64 {
        self.density * FOOT.powi(3) / KG_PER_SLUG
    }

    /// Pressure in lbf/ft².
    pub fn pressure_psf(&self) -> f64 {
        self.pressure / PA_PER_PSF
    }

    /// Speed of sound in ft/s.
    pub fn speed_of_sound_ft_s(&self) -> f64 {
        self.speed_of_sound / FOOT
    }

    /// Temperature in degrees Rankine.
    pub fn temperature_rankine(&self) -> f64 {
        self.temperature * 1.8
    }
}

/// T_M and P at geopotential altitude `h` (0 ≤ h ≤ 84 852 m′): eq (23),
/// T_M = T_M,b + L_M,b (H − H_b), and the hydrostatic eqs (33a), for
/// L_M,b ≠ 0,
///   P = P_b [T_M,b / (T_M,b + L_M,b (H − H_b))]^(g₀′M₀/(R* L_M,b)),
/// and (33b), for L_M,b = 0,
///   P = P_b exp[−g₀′M₀ (H − H_b)/(R* T_M,b)],
/// with the base values T_M,b, P_b carried up from T₀, P₀ layer by layer, as
/// the standard derives them.
fn molecular_temperature_and_pressure(h: f64) -> (f64, f64) {
    let (mut t_b, mut p_b) = (T0, P0);
    for (b, &(h_b, l_b)) in LAYERS.iter().enumerate() {
        let top = LAYERS.get(b + 1).map_or(f64::INFINITY, |layer| layer.0);
        let dh = h.min(top) - h_b;
        let t = t_b + l_b * dh;
        let p = if l_b == 0.0 {
            p_b * (-G0 * M0 * dh / (R_STAR * t_b)).exp()
        } else {
            p_b * (t_b / t).powf(G0 * M0 / (R_STAR * l_b))
        };
        if h <= top {
            return (t, p);
        }
        (t_b, p_b) = (t, p);
    }
    unreachable!("the last layer is open above")
}

/// M/M₀ at geometric altitude `z` (m): 1 below 80 km, Table 8 (linear in Z
/// between its 0.5 km entries) from 80 to 86 km.
fn molecular_weight_ratio(z: f64) -> f64 {
    const Z_TABLE: f64 = 80_000.0;
    const STEP: f64 = 500.0;
    if z <= Z_TABLE {
        return 1.0;
    }
    let x = ((z - Z_TABLE) / STEP).min((MOLECULAR_WEIGHT_RATIO.len() - 1) as f64);
    let i = (x.floor() as usize).min(MOLECULAR_WEIGHT_RATIO.len() - 2);
    let f = x - i as f64;
    MOLECULAR_WEIGHT_RATIO[i] + f * (MOLECULAR_WEIGHT_RATIO[i + 1] - MOLECULAR_WEIGHT_RATIO[i])
}

/// Density from the equation of state, eq (42) with T/M = T_M/M₀:
/// ρ = P M₀/(R* T_M).
fn density(p: f64, t_m: f64) -> f64 {
    p * M0 / (R_STAR * t_m)
}

/// Speed of sound, eq (50): C_s = (γ R* T/M)^½ = (γ R* T_M/M₀)^½.
fn speed_of_sound(t_m: f64) -> f64 {
    (GAMMA * R_STAR * t_m / M0).sqrt()
}

/// Dynamic viscosity by Sutherland's law, eq (51): μ = β T^{3/2}/(T + S),
/// with the kinetic temperature T.
fn dynamic_viscosity(t: f64) -> f64 {
    SUTHERLAND_BETA * t * t.sqrt() / (t + SUTHERLAND_S)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn geopotential_conversion_round_trips_and_matches_the_standards_upper_bound() {
        for z in [0.0, 1.0, 11_019.1, 47_350.1, 86_000.0] {
            let h = geopotential_from_geometric(z);
            assert!((geometric_from_geopotential(h) - z).abs() < 1e-9 * (1.0 + z));
        }
        // The standard's own pairing of the top of the model: 86 km ↔ 84.8520 km′.
        assert!((geopotential_from_geometric(86_000.0) - 84_852.0).abs() < 0.05);
    }

    #[test]
    fn the_base_pressures_are_continuous_across_each_layer_boundary() {
        for &(h_b, _) in &LAYERS[1..] {
            let (t_lo, p_lo) = molecular_temperature_and_pressure(h_b - 1e-6);
            let (t_hi, p_hi) = molecular_temperature_and_pressure(h_b + 1e-6);
            assert!((t_lo - t_hi).abs() < 1e-6, "T_M jumps at {h_b} m′");
            assert!((p_lo / p_hi - 1.0).abs() < 1e-9, "P jumps at {h_b} m′");
        }
    }

    #[test]
    fn the_molecular_weight_ratio_interpolates_table_8() {
        assert_eq!(molecular_weight_ratio(79_999.0), 1.0);
        assert_eq!(molecular_weight_ratio(86_000.0), 0.999_579);
        assert!((molecular_weight_ratio(85_250.0) - 0.5 * (0.999_694 + 0.999_641)).abs() < 1e-12);
    }

    #[test]
    fn altitudes_outside_0_to_86_km_are_typed_errors() {
        assert_eq!(
            Atmosphere::at_geometric(-1.0),
            Err(AtmosphereError::BelowSeaLevel { geometric_m: -1.0 })
        );
        assert_eq!(
            Atmosphere::at_geometric(86_000.5),
            Err(AtmosphereError::AboveModel {
                geometric_m: 86_000.5
            })
        );
        assert!(matches!(
            Atmosphere::at_geopotential(84_853.0),
            Err(AtmosphereError::AboveModel { .. })
        ));
        assert!(matches!(
            Atmosphere::at_geopotential(7.0e6),
            Err(AtmosphereError::AboveModel { .. })
        ));
        assert!(matches!(
            Atmosphere::at_geometric(f64::NAN),
            Err(AtmosphereError::NotFinite(_))
        ));
        assert!(matches!(
            Atmosphere::at_geopotential_ft(f64::INFINITY),
            Err(AtmosphereError::NotFinite(_))
        ));
        assert!(Atmosphere::at_geometric(86_000.0).is_ok());
        assert!(Atmosphere::at_geopotential(geopotential_from_geometric(86_000.0)).is_ok());
        let message = Atmosphere::at_geometric_ft(300_000.0)
            .unwrap_err()
            .to_string();
        assert!(message.contains("above 86 km"), "{message}");
    }
}
