//! The closed choices of the command line as clap value enums, each value
//! with its one-line meaning in `--help`; the lists and their meanings come
//! from the library (the registry of its damping theories and aerodynamic
//! models, [`stability_core::aerodynamics::theory::Row`], and its notations), not
//! restated here.

use clap::ValueEnum;
use clap::builder::PossibleValue;
use stability_core::aerodynamics::models::aero::AeroModelName;
use stability_core::criteria::cap::AirplaneClass;
use stability_core::data::notation::Notation;
use stability_core::design::case::{DampingModel, FrequencyMethod};
use stability_core::numerics::display::Num;
use stability_io::input::dimensional_notation::DIMENSIONAL;
use std::sync::OnceLock;

/// The model options of `analyze` and `sweep`: the config's damping model,
/// aerodynamic model and frequency parameter replaced.
#[derive(Debug, Clone, Default, clap::Args)]
pub struct ModelArgs {
    /// Override the config's damping model. With lifting-surface the
    /// lattice is solved once per planform and Mach number; with
    /// lifting-surface-frequency each design point's ω̄ is iterated (a sweep
    /// interpolates between solved frequencies).
    #[arg(long, value_enum)]
    pub damping: Option<DampingArg>,
    /// Override the config's aerodynamic model (lift slope and aerodynamic
    /// centre; a table in the config still wins).
    #[arg(long, value_enum)]
    pub aero: Option<AeroArg>,
    /// Evaluate a frequency-dependent damping theory at ω̄ = ωc̄/V = W, not
    /// iterated: lifting-surface (else quasi-steady),
    /// lifting-surface-frequency, transonic-frequency, faired.
    #[arg(long = "omega-bar", value_name = "W", value_parser = positive)]
    pub omega_bar: Option<f64>,
    /// Take the lift slope, aerodynamic centre, C_D0 and z_w, m_w, z_q,
    /// m_q, z_ẇ, m_ẇ from a Digital DATCOM output (for006.dat), moved from
    /// its moment centre to the config's c.g. (in place of the config's
    /// `[model] datcom`; its `[model.tables]` still win; docs/tables.md).
    #[arg(long, value_name = "FILE")]
    pub datcom: Option<String>,
    /// How the roots take the air forces' dependence on frequency (for a
    /// frequency-dependent damping model, `faired` among them): p, the
    /// default, solves each root with the air forces at its own complex
    /// frequency (exact); p-k with real derivatives at its own ω̄; k puts the
    /// derivatives at the short period's ω̄ into the quartic (before).
    #[arg(long = "frequency-method", value_enum)]
    pub frequency_method: Option<FrequencyMethodArg>,
}

/// How the roots take the frequency (`--frequency-method`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrequencyMethodArg(pub FrequencyMethod);

impl ValueEnum for FrequencyMethodArg {
    fn value_variants<'a>() -> &'a [Self] {
        static ALL: OnceLock<Vec<FrequencyMethodArg>> = OnceLock::new();
        ALL.get_or_init(|| FrequencyMethod::ALL.map(FrequencyMethodArg).to_vec())
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        Some(PossibleValue::new(self.0.name()).help(self.0.describe()))
    }
}

impl ModelArgs {
    /// The overrides of a config these options make.
    pub fn overrides(&self) -> stability_io::config::Overrides {
        stability_io::config::Overrides {
            damping: self.damping.map(|d| d.0),
            aero: self.aero.map(|a| a.0),
            omega_bar: self.omega_bar,
            datcom: self.datcom.clone(),
            frequency_method: self.frequency_method.map(|m| m.0),
            ..Default::default()
        }
    }
}

/// A damping model: `faired` or one of the library's theories.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DampingArg(pub DampingModel);

impl ValueEnum for DampingArg {
    fn value_variants<'a>() -> &'a [Self] {
        static ALL: OnceLock<Vec<DampingArg>> = OnceLock::new();
        ALL.get_or_init(|| DampingModel::ALL.into_iter().map(DampingArg).collect())
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        Some(PossibleValue::new(self.0.name()).help(self.0.row().help()))
    }
}

/// A MIL-F-8785C airplane class (§1.3), for the Category C floors of the
/// short-period frequency requirement.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClassArg(pub AirplaneClass);

impl ValueEnum for ClassArg {
    fn value_variants<'a>() -> &'a [Self] {
        static ALL: OnceLock<Vec<ClassArg>> = OnceLock::new();
        ALL.get_or_init(|| AirplaneClass::ALL.map(ClassArg).to_vec())
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        Some(PossibleValue::new(self.0.name()).help(self.0.describe()))
    }
}

/// An aerodynamic model (`--aero`): the library's named models.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AeroArg(pub AeroModelName);

impl ValueEnum for AeroArg {
    fn value_variants<'a>() -> &'a [Self] {
        static ALL: OnceLock<Vec<AeroArg>> = OnceLock::new();
        ALL.get_or_init(|| AeroModelName::ALL.map(AeroArg).to_vec())
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        Some(PossibleValue::new(self.0.name()).help(self.0.row().help()))
    }
}

/// The notation only AVL's output is read in (`st_file`), never written.
pub const AVL: &str = "avl";

/// A notation a derivative file may be written in: one of the library's
/// tables, or AVL's `.st` output.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum NotationArg {
    Table(Notation),
    Avl,
    /// Derivatives per unit mass and inertia (`notation = "dimensional"`).
    Dimensional,
}

impl NotationArg {
    pub fn name(self) -> &'static str {
        match self {
            NotationArg::Table(n) => n.name(),
            NotationArg::Avl => AVL,
            NotationArg::Dimensional => DIMENSIONAL,
        }
    }
}

/// What `--from dimensional` and `--to dimensional` say in `--help`.
const DIMENSIONAL_HELP: &str = "per unit mass and inertia as handbooks print them (X_u … M_q), body or stability axes, ft or si; to and from the report's notation with a [reference] table";

impl ValueEnum for NotationArg {
    fn value_variants<'a>() -> &'a [Self] {
        static ALL: OnceLock<Vec<NotationArg>> = OnceLock::new();
        ALL.get_or_init(|| {
            Notation::all()
                .map(NotationArg::Table)
                .chain([NotationArg::Avl, NotationArg::Dimensional])
                .collect()
        })
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        let help = match self {
            NotationArg::Table(n) => n.title(),
            NotationArg::Avl => {
                "AVL's ST output, read only: st_file = \"case.st\", [dimensional] mass, I_y, rho, V"
            }
            NotationArg::Dimensional => DIMENSIONAL_HELP,
        };
        Some(PossibleValue::new(self.name()).help(help))
    }
}

/// A notation that can be written: one of the library's tables, or the
/// dimensional one.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TargetNotation {
    Table(Notation),
    Dimensional,
}

impl ValueEnum for TargetNotation {
    fn value_variants<'a>() -> &'a [Self] {
        static ALL: OnceLock<Vec<TargetNotation>> = OnceLock::new();
        ALL.get_or_init(|| {
            Notation::all()
                .map(TargetNotation::Table)
                .chain([TargetNotation::Dimensional])
                .collect()
        })
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        Some(match self {
            TargetNotation::Table(n) => PossibleValue::new(n.name()).help(n.title()),
            TargetNotation::Dimensional => PossibleValue::new(DIMENSIONAL).help(DIMENSIONAL_HELP),
        })
    }
}

/// What disturbs the aircraft in `response`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ResponseInput {
    /// An elevon applied instantaneously: a step of the moment m₀ (--m0), from rest
    Step,
    /// No input: the motion from an initial disturbance ŵ(0) = --w0
    Initial,
}

/// A finite number (a command-line value).
pub fn finite(s: &str) -> Result<f64, String> {
    match s.trim().parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(x),
        Ok(x) => Err(format!("{x} is not a finite number")),
        Err(_) => Err(format!(
            "`{}` is not a number",
            stability_io::diag::quote(s)
        )),
    }
}

/// A positive finite number (a command-line value).
pub fn positive(s: &str) -> Result<f64, String> {
    let x = finite(s)?;
    if x > 0.0 {
        Ok(x)
    } else {
        Err(format!("{} is not positive", Num(x)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use stability_core::aerodynamics::damping::Theory;

    #[test]
    fn every_theory_of_the_library_is_a_choice() {
        let names: Vec<String> = DampingArg::value_variants()
            .iter()
            .filter_map(|v| v.to_possible_value())
            .map(|p| p.get_name().to_string())
            .collect();
        assert_eq!(names.len(), DampingModel::ALL.len());
        for t in Theory::ALL {
            assert!(names.contains(&t.name().to_string()));
        }
        for m in DampingModel::ALL {
            let parsed = DampingArg::from_str(m.name(), false).unwrap();
            assert_eq!(parsed.0, DampingModel::parse(m.name()).unwrap());
            assert_eq!(parsed.0, m);
        }
    }

    #[test]
    fn every_aerodynamic_model_of_the_library_is_a_choice() {
        for m in AeroModelName::ALL {
            assert_eq!(AeroArg::from_str(m.name(), false).unwrap().0, m);
        }
        assert_eq!(AeroArg::value_variants().len(), AeroModelName::ALL.len());
    }

    #[test]
    fn every_notation_is_readable_and_all_but_avl_writable() {
        for n in Notation::all() {
            assert_eq!(
                NotationArg::from_str(n.name(), false).unwrap(),
                NotationArg::Table(n)
            );
            assert_eq!(
                TargetNotation::from_str(n.name(), false).unwrap(),
                TargetNotation::Table(n)
            );
        }
        assert_eq!(
            NotationArg::from_str("avl", false).unwrap(),
            NotationArg::Avl
        );
        assert!(TargetNotation::from_str("avl", false).is_err());
        // the dimensional notation is read and written
        assert_eq!(
            NotationArg::from_str("dimensional", false).unwrap(),
            NotationArg::Dimensional
        );
        assert_eq!(
            TargetNotation::from_str("dimensional", false).unwrap(),
            TargetNotation::Dimensional
        );
    }

    #[test]
    fn values_are_finite() {
        assert!(finite("NaN").is_err() && finite("inf").is_err() && finite("x").is_err());
        assert_eq!(finite(" 2.5 "), Ok(2.5));
        assert!(positive("0").is_err() && positive("-1").is_err());
        assert!(positive("1e308").is_ok());
    }
}
