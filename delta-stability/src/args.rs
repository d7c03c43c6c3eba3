//! The closed choices of the command line as clap value enums, each value
//! with its one-line meaning in `--help`; the lists come from the library
//! (its damping theories and notations), not restated here.

use clap::ValueEnum;
use clap::builder::PossibleValue;
use stability_core::aero::AeroModelName;
use stability_core::cap::AirplaneClass;
use stability_core::case::DampingModel;
use stability_core::damping::Theory;
use stability_core::display::Num;
use stability_core::notation::Notation;
use stability_io::input::dimensional_notation::DIMENSIONAL;
use std::sync::OnceLock;

/// A damping model: `faired` or one of the library's theories.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DampingArg(pub DampingModel);

/// What each theory is, in a line (the names and equations are the
/// library's; a theory added there fails to compile here until described).
fn theory_meaning(t: Theory) -> &'static str {
    match t {
        Theory::Garrick => "Garrick's low-aspect-ratio theory, incompressible",
        Theory::GarnerTaper => "Garner's version of it for taper 1/7",
        Theory::Slender => "Ribner's slender-wing theory",
        Theory::Supersonic => {
            "supersonic linear theory (M > 1): Mangler, Ribner & Malvestuto for subsonic leading edges, conical flow beyond the sonic edge"
        }
        Theory::Transonic => "Mangler's transonic theory at M = 1, steady",
        Theory::TransonicFrequency => {
            "the same with its frequency terms, ω̄ iterated to the short period's own"
        }
        Theory::LiftingSurface => {
            "Multhopp–Garner and Lehrian's lifting-surface theory for any straight-tapered wing, M < 1, quasi-steady or at --omega-bar W"
        }
        Theory::LiftingSurfaceFrequency => {
            "the same at the short period's own ω̄, iterated (a sweep interpolates between solved ω̄)"
        }
    }
}

impl ValueEnum for DampingArg {
    fn value_variants<'a>() -> &'a [Self] {
        static ALL: OnceLock<Vec<DampingArg>> = OnceLock::new();
        ALL.get_or_init(|| DampingModel::ALL.into_iter().map(DampingArg).collect())
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        let help = match self.0 {
            DampingModel::Faired => {
                "the default, the note's fairing (Figs 19–24): the lifting surface at the short period's own ω̄ to M = 0.9, Mangler's transonic theory (39)–(40) at M = 1, linear supersonic theory (36) from 1.2, joined between by stated cubics; the lift slope and aerodynamic centre from the same theories"
                    .to_string()
            }
            DampingModel::FairedSlender => {
                "the previous, quasi-steady fairing (fast: no lattice): slender-wing theory (37) through M = 1, blended into (36) by M = 1.2, (36) held at its sonic-leading-edge values beyond the sonic edge"
                    .to_string()
            }
            DampingModel::Theory(t) => {
                let eqs = if !t.equations().starts_with('(') {
                    ""
                } else if t.equations().contains('–') {
                    "eqs "
                } else {
                    "eq "
                };
                format!("{}: {eqs}{}", theory_meaning(t), t.equations())
            }
        };
        Some(PossibleValue::new(self.0.name()).help(help))
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
        let help = match self.0 {
            AirplaneClass::I => "small, light airplanes",
            AirplaneClass::IIC => "medium weight, low-to-medium manoeuvrability, carrier-based",
            AirplaneClass::IIL => "medium weight, low-to-medium manoeuvrability, land-based",
            AirplaneClass::III => "large, heavy, low-to-medium manoeuvrability (transports)",
            AirplaneClass::IV => "high manoeuvrability (fighters, attack): the default",
        };
        Some(PossibleValue::new(self.0.name()).help(help))
    }
}

/// An aerodynamic model (`--aero`): the library's named models.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AeroArg(pub AeroModelName);

/// What each aerodynamic model is, in a line.
fn aero_meaning(m: AeroModelName) -> &'static str {
    match m {
        AeroModelName::Default => {
            "the default: DATCOM lift slope and a slender-to-2-D aerodynamic centre subsonic, linear conical-flow theory supersonic, faired between (docs/models.md)"
        }
        AeroModelName::LiftingSurface => {
            "lift slope and aerodynamic centre from the doublet lattice, with exact Mach derivatives; subsonic only (M ≥ 1 is an error)"
        }
    }
}

impl ValueEnum for AeroArg {
    fn value_variants<'a>() -> &'a [Self] {
        static ALL: OnceLock<Vec<AeroArg>> = OnceLock::new();
        ALL.get_or_init(|| AeroModelName::ALL.map(AeroArg).to_vec())
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        Some(PossibleValue::new(self.0.name()).help(aero_meaning(self.0)))
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
