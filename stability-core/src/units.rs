//! The two systems of units of the program's inputs, defined once: SI
//! (metres, kilograms, newtons, seconds) and the foot–slug system (feet,
//! slugs, pounds-force, seconds), used by physical flight conditions
//! ([`crate::design::flight`]) and by handbook derivative sets
//! ([`crate::data::dimensional`]).

use serde::Serialize;

/// Standard gravity g₀ = 9.806 65 m/s² (exact, by definition: 3rd CGPM,
/// 1901; ISO 80000-3).
pub const STANDARD_GRAVITY: f64 = 9.806_65;
/// The international foot, 0.3048 m exactly.
pub const FOOT: f64 = 0.3048;
/// The newton per pound-force: 1 lbf = 0.453 592 37 kg × g₀ = 4.448 221 615 260 5 N,
/// exactly.
pub const NEWTON_PER_LBF: f64 = 0.453_592_37 * STANDARD_GRAVITY;
/// The kilogram per slug (14.593 902 937 2 kg): lbf·s²/ft, exactly.
pub const KG_PER_SLUG: f64 = NEWTON_PER_LBF / FOOT;

/// The handbooks' g in ft/s², 32.174 (g₀/0.3048 = 32.174 05 to more
/// digits): the default g of a dimensional set in feet, as NASA CR-2144
/// states it.
pub const HANDBOOK_G_FT: f64 = 32.174;

/// A system of units.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Units {
    /// Metres, kilograms, newtons, seconds.
    Si,
    /// Feet, slugs, pounds-force, seconds.
    Ft,
}

/// A units word that is neither `si` nor `ft`.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("unknown units `{0}`: the units are `si` (m, kg, N, s) and `ft` (ft, slug, lbf, s)")]
pub struct UnknownUnits(pub String);

impl Units {
    /// Both systems, in the order `--help` lists them.
    pub const ALL: [Units; 2] = [Units::Si, Units::Ft];

    /// `si` or `ft`, as written in input files.
    pub fn name(self) -> &'static str {
        match self {
            Units::Si => "si",
            Units::Ft => "ft",
        }
    }

    /// The units word of an input file.
    pub fn parse(s: &str) -> Result<Units, UnknownUnits> {
        Units::ALL
            .into_iter()
            .find(|u| u.name() == s)
            .ok_or_else(|| UnknownUnits(s.to_string()))
    }

    /// Metres per unit of length (1 m or 1 ft = 0.3048 m).
    pub fn length(self) -> f64 {
        match self {
            Units::Si => 1.0,
            Units::Ft => FOOT,
        }
    }

    /// Kilograms per unit of mass (1 kg or 1 slug).
    pub fn mass(self) -> f64 {
        match self {
            Units::Si => 1.0,
            Units::Ft => KG_PER_SLUG,
        }
    }

    /// Newtons per unit of force (1 N or 1 lbf).
    pub fn force(self) -> f64 {
        match self {
            Units::Si => 1.0,
            Units::Ft => NEWTON_PER_LBF,
        }
    }

    /// kg/m³ per unit of density (kg/m³ or slug/ft³).
    pub fn density(self) -> f64 {
        self.mass() / self.length().powi(3)
    }

    /// kg·m² per unit of moment of inertia (kg·m² or slug·ft²).
    pub fn inertia(self) -> f64 {
        self.mass() * self.length().powi(2)
    }

    /// Standard gravity g₀ in the units' length per s², exactly
    /// (9.806 65 m/s², or 32.174 05 ft/s²): what turns a weight into a mass
    /// (a weight in lbf is a mass in lbm).
    pub fn gravity(self) -> f64 {
        STANDARD_GRAVITY / self.length()
    }

    /// The g of a handbook's equations of motion, the default of a
    /// dimensional set: 9.806 65 m/s², or the handbooks' 32.174 ft/s²
    /// ([`HANDBOOK_G_FT`]).
    pub fn handbook_gravity(self) -> f64 {
        match self {
            Units::Si => STANDARD_GRAVITY,
            Units::Ft => HANDBOOK_G_FT,
        }
    }

    /// The unit names (length, mass, force): `m, kg, N` or `ft, slug, lbf`.
    pub fn symbols(self) -> (&'static str, &'static str, &'static str) {
        match self {
            Units::Si => ("m", "kg", "N"),
            Units::Ft => ("ft", "slug", "lbf"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_two_gravities_differ_by_the_handbooks_rounding() {
        assert_eq!(Units::Si.gravity(), Units::Si.handbook_gravity());
        let g0_ft = Units::Ft.gravity();
        assert!((g0_ft - 32.174_048_556).abs() < 1e-8, "{g0_ft}");
        assert!((g0_ft - HANDBOOK_G_FT).abs() / g0_ft < 2e-6);
        for u in Units::ALL {
            assert_eq!(Units::parse(u.name()), Ok(u));
        }
        assert!(Units::parse("feet").is_err());
    }
}
