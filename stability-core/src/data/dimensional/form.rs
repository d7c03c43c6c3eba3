//! The forms in which handbooks print a longitudinal derivative table, and
//! their conversion to the model's form (per unit mass and inertia), written
//! once here:
//!
//! - per unit mass and inertia, the model's own: X_u = (∂X/∂u)/m, …,
//!   M_q = (∂M/∂q)/I_y (NASA CR-2144's tables; Etkin & Reid's longitudinal
//!   system matrix holds them so: X_u/m, Z_ẇ/m, M_q/I_y);
//! - per force and moment (Etkin & Reid 1996, Table 4.4's dimensional
//!   derivatives: X_u = ∂X/∂u in N·s/m, Z_ẇ in kg, M_q in N·m·s, …): X and
//!   Z divided by the mass m, M by the pitching inertia I_y;
//! - per unit mass with α in place of w (Nelson 1998, §4.2–4.3: Z_α = U₀Z_w,
//!   M_α = U₀M_w, M_α̇ = U₀M_ẇ, as w = U₀α in stability axes): divided by U₀.
//!
//! And the plausibility of a set: a rate derivative or a root faster than
//! [`RATE_MAX`] is not an aircraft's, and a table per force typed as per
//! unit mass gives exactly that ([`implausible`]).

use super::{DimensionalDerivatives, DimensionalModel};

/// The form of a printed table, as a file's `form` names it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Form {
    /// Per unit mass (X, Z) and pitching inertia (M): the model's.
    PerUnitMass,
    /// Per force and moment, with the mass and I_y (Etkin & Reid, Table 4.4).
    PerForce,
    /// Per unit mass, the w derivatives per α (Nelson, ch. 4).
    Alpha,
}

impl Form {
    pub const ALL: [Form; 3] = [Form::PerUnitMass, Form::PerForce, Form::Alpha];

    /// `per_unit_mass`, `per_force`, `alpha` (the file's spelling).
    pub fn as_str(self) -> &'static str {
        match self {
            Form::PerUnitMass => "per_unit_mass",
            Form::PerForce => "per_force",
            Form::Alpha => "alpha",
        }
    }

    pub fn parse(s: &str) -> Option<Form> {
        Form::ALL.into_iter().find(|f| f.as_str() == s)
    }

    /// What the form's values are, in words.
    pub fn describe(self) -> &'static str {
        match self {
            Form::PerUnitMass => {
                "per unit mass and inertia, X_u = (∂X/∂u)/m, M_q = (∂M/∂q)/I_y (as CR-2144 prints them)"
            }
            Form::PerForce => {
                "per force and moment, X_u = ∂X/∂u in N·s/m or lbf·s/ft, M_q = ∂M/∂q (Etkin & Reid Table 4.4), with [reference] mass (or weight) and I_y"
            }
            Form::Alpha => {
                "per unit mass, with Z_alpha = U₀Z_w, M_alpha = U₀M_w, M_alphadot = U₀M_ẇ (Nelson ch. 4) in place of the w derivatives"
            }
        }
    }
}

/// The α-form names and the w derivative each stands for (times U₀).
pub const ALPHA_NAMES: [(&str, &str); 6] = [
    ("X_alpha", "X_w"),
    ("X_alphadot", "X_wdot"),
    ("Z_alpha", "Z_w"),
    ("Z_alphadot", "Z_wdot"),
    ("M_alpha", "M_w"),
    ("M_alphadot", "M_wdot"),
];

/// The w derivative an α-form name stands for.
pub fn w_name_of(alpha_name: &str) -> Option<&'static str> {
    ALPHA_NAMES
        .iter()
        .find(|(a, _)| *a == alpha_name)
        .map(|(_, w)| *w)
}

/// The mass and pitching inertia a table per force is divided by.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Inertia {
    /// m (kg or slug).
    pub mass: f64,
    /// I_y (kg·m² or slug·ft²).
    pub i_y: f64,
}

/// How one printed value relates to the model's value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Printed {
    /// Per unit mass and inertia: as it is.
    PerUnitMass,
    /// Per force or moment: X and Z divided by m, M by I_y (Etkin & Reid
    /// 1996, Table 4.4's derivatives into their system matrix).
    PerForce(Inertia),
    /// Per α or α̇ (Nelson 1998, ch. 4: Z_α = U₀Z_w, M_α = U₀M_w,
    /// M_α̇ = U₀M_ẇ): divided by U₀.
    PerAlpha { u0: f64 },
}

impl Printed {
    /// The model's value (per unit mass and inertia, per w) of the
    /// derivative `name` (one of [`DimensionalDerivatives::NAMES`]) printed
    /// as `value`. The one place the forms are converted.
    pub fn per_unit_mass(self, name: &str, value: f64) -> f64 {
        match self {
            Printed::PerUnitMass => value,
            Printed::PerForce(i) if name.starts_with('M') => value / i.i_y,
            Printed::PerForce(i) => value / i.mass,
            Printed::PerAlpha { u0 } => value / u0,
        }
    }
}

/// The fastest rate of a physical aircraft's longitudinal motion, s⁻¹: no
/// root of a real aircraft's quartic, and no rate derivative (X_u, X_w,
/// Z_u, Z_w, M_q, U₀M_ẇ) is faster; a table per force typed as per unit
/// mass gives thousands. The 747's fastest rate derivative is
/// |M_q| = 0.34 s⁻¹ and the Navion's 2.05 s⁻¹; their fastest roots 0.96
/// and 3.6 s⁻¹.
pub const RATE_MAX: f64 = 100.0;

/// The largest plausible ratio of an added mass (X_ẇ, X_u̇, Z_ẇ, Z_u̇) to
/// the mass, and of a rate derivative's length (X_q, Z_q) to U₀.
pub const RATIO_MAX: f64 = 1.0;

/// The class of a derivative, by which its magnitude is judged.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Class {
    /// X_u, X_w, Z_u, Z_w, M_q: a rate, s⁻¹.
    Rate,
    /// M_ẇ, M_u̇: U₀ times it is a rate, s⁻¹.
    RateOverU0,
    /// M_w, M_u: U₀ times it is a stiffness, s⁻².
    StiffnessOverU0,
    /// X_q, Z_q: a velocity, over U₀ a ratio.
    Velocity,
    /// X_ẇ, X_u̇, Z_ẇ, Z_u̇: an added mass over the aircraft's.
    AddedMass,
}

impl Class {
    /// The class of the derivative `name` ([`DimensionalDerivatives::NAMES`]).
    pub fn of(name: &str) -> Class {
        match name {
            "X_u" | "X_w" | "Z_u" | "Z_w" | "M_q" => Class::Rate,
            "M_wdot" | "M_udot" => Class::RateOverU0,
            "M_w" | "M_u" => Class::StiffnessOverU0,
            "X_q" | "Z_q" => Class::Velocity,
            _ => Class::AddedMass,
        }
    }

    /// The measure of a value of the class at `u0` (|X_u|, |U₀M_w|,
    /// |Z_q|/U₀, |Z_ẇ|, …) and its bound.
    pub fn measure(self, value: f64, u0: f64) -> (f64, f64) {
        match self {
            Class::Rate => (value.abs(), RATE_MAX),
            Class::RateOverU0 => ((u0 * value).abs(), RATE_MAX),
            Class::StiffnessOverU0 => ((u0 * value).abs(), RATE_MAX * RATE_MAX),
            Class::Velocity => ((value / u0).abs(), RATIO_MAX),
            Class::AddedMass => (value.abs(), RATIO_MAX),
        }
    }

    /// The measure of derivative `name`, in symbols (`|U₀·M_w| (s⁻²)`).
    pub fn measure_name(self, name: &str) -> String {
        match self {
            Class::Rate => format!("|{name}| (s⁻¹)"),
            Class::RateOverU0 => format!("|U₀·{name}| (s⁻¹)"),
            Class::StiffnessOverU0 => format!("|U₀·{name}| (s⁻²)"),
            Class::Velocity => format!("|{name}|/U₀"),
            Class::AddedMass => format!("|{name}| (an added mass over the mass)"),
        }
    }
}

/// A derivative off by orders from its class.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Implausible {
    /// Its name ([`DimensionalDerivatives::NAMES`]).
    pub name: &'static str,
    pub value: f64,
    pub class: Class,
    /// The class's measure of it ([`Class::measure`]) and its bound.
    pub measure: f64,
    pub bound: f64,
}

/// The derivatives off by orders from their class ([`Class`]): rates
/// (X_u, X_w, Z_u, Z_w, M_q, U₀M_ẇ, U₀M_u̇) above [`RATE_MAX`] s⁻¹,
/// stiffnesses (U₀M_w, U₀M_u) above [`RATE_MAX`]² s⁻², added masses (X_ẇ,
/// X_u̇, Z_ẇ, Z_u̇) and velocities over U₀ (X_q/U₀, Z_q/U₀) above
/// [`RATIO_MAX`]. In the model's form; what a table per force typed as per
/// unit mass shows.
pub fn implausible(model: &DimensionalModel) -> Vec<Implausible> {
    let u0 = model.trim.u0;
    DimensionalDerivatives::NAMES
        .into_iter()
        .zip(model.derivatives.values())
        .filter_map(|(name, value)| {
            let class = Class::of(name);
            let (measure, bound) = class.measure(value, u0);
            (measure > bound).then_some(Implausible {
                name,
                value,
                class,
                measure,
                bound,
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::data::dimensional::{Axes, Trim, Units};

    #[test]
    fn each_form_converts_as_its_source_defines_it() {
        let i = Inertia {
            mass: 2.0,
            i_y: 8.0,
        };
        assert_eq!(Printed::PerForce(i).per_unit_mass("Z_wdot", 1.0), 0.5);
        assert_eq!(Printed::PerForce(i).per_unit_mass("M_q", 1.0), 0.125);
        assert_eq!(Printed::PerForce(i).per_unit_mass("X_u", -4.0), -2.0);
        // Nelson's Navion: M_α = −8.8 s⁻² at U₀ = 176 ft/s is M_w = −0.05
        let navion = Printed::PerAlpha { u0: 176.0 };
        assert!((navion.per_unit_mass("M_w", -8.8) - -0.05).abs() < 1e-15);
        assert_eq!(Printed::PerUnitMass.per_unit_mass("M_q", -2.05), -2.05);
        assert_eq!(w_name_of("M_alphadot"), Some("M_wdot"));
        assert_eq!(w_name_of("M_w"), None);
        for f in Form::ALL {
            assert_eq!(Form::parse(f.as_str()), Some(f));
        }
    }

    #[test]
    fn a_table_per_force_read_as_per_unit_mass_is_implausible() {
        // Etkin & Reid's 747 (Table 4.4's values as printed, SI)
        let per_force = DimensionalDerivatives {
            x_u: -1.982e3,
            x_w: 4.025e3,
            z_u: -2.595e4,
            z_w: -9.030e4,
            z_wdot: 1.909e3,
            z_q: -4.524e5,
            m_u: 1.593e4,
            m_w: -1.563e5,
            m_wdot: -1.702e4,
            m_q: -1.521e7,
            ..Default::default()
        };
        let mut model = DimensionalModel {
            axes: Axes::Stability,
            units: Units::Si,
            derivatives: per_force,
            trim: Trim {
                u0: 235.9,
                w0: 0.0,
                theta0: 0.0,
                g: 9.81,
            },
        };
        let names: Vec<&str> = implausible(&model).iter().map(|x| x.name).collect();
        for n in [
            "X_u", "X_w", "Z_u", "Z_w", "Z_wdot", "Z_q", "M_w", "M_wdot", "M_q",
        ] {
            assert!(names.contains(&n), "{n}: {names:?}");
        }
        // divided by m and I_y, nothing is
        let i = Inertia {
            mass: 2.83176e6 / 9.81,
            i_y: 0.449e8,
        };
        let v = DimensionalDerivatives::NAMES.map(|n| {
            let k = DimensionalDerivatives::NAMES.iter().position(|x| *x == n);
            Printed::PerForce(i).per_unit_mass(n, per_force.values()[k.unwrap_or(0)])
        });
        model.derivatives = DimensionalDerivatives::from_values(v);
        assert!(implausible(&model).is_empty(), "{:?}", implausible(&model));
    }
}
