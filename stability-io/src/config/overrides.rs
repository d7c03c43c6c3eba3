//! A config's values replaced from outside the file: the command line's
//! `--mach`, `--cg`, `--damping`, `--aero`, `--omega-bar` and `--datcom`, and the
//! Python package's keywords of the same names. Each value is checked
//! against its range ([`crate::limits`]), and an error about a replaced
//! value names the flag that replaced it.

use super::Config;
use crate::Failure;
use crate::diag::InputError;
use crate::input::datcom::Datcom;
use crate::limits;
use stability_core::aerodynamics::models::aero::{AeroModelName, Source};
use stability_core::design::case::{DampingModel, FrequencyMethod};
use stability_core::numerics::display::Num;

/// Values that replace a config's.
#[derive(Debug, Default, Clone)]
pub struct Overrides {
    pub damping: Option<DampingModel>,
    pub mach: Option<f64>,
    pub cg: Option<f64>,
    pub aero: Option<AeroModelName>,
    /// `--omega-bar W`: the frequency-dependent theories at ω̄ = W (not
    /// iterated).
    pub omega_bar: Option<f64>,
    /// `--datcom FILE`: a DATCOM output's tables in place of the config's
    /// (`[model] datcom`); the config's own `[model.tables]` still win.
    pub datcom: Option<String>,
    /// `--frequency-method`: how the roots take the air forces' frequency.
    pub frequency_method: Option<FrequencyMethod>,
}

/// The config at `path` with `o` applied (`analyze`'s and `sweep`'s).
pub fn overridden(path: &str, o: &Overrides) -> Result<Config, Failure> {
    let mut cfg = super::read(path)?;
    apply(&mut cfg, o)?;
    Ok(cfg)
}

/// Applies the overrides to a config read, each within its range.
pub fn apply(cfg: &mut Config, o: &Overrides) -> Result<(), Failure> {
    let path = cfg.path.clone();
    let bad =
        |flag: &str, m: String| Failure::Input(InputError::file(&path, format!("{flag}: {m}")));
    if let Some(d) = o.damping {
        cfg.case.damping = d;
        cfg.overridden_by("[model] damping", format!("--damping {}", d.name()));
    }
    if let Some(m) = o.mach {
        cfg.case.mach = limits::MACH.check(m).map_err(|e| bad("--mach", e))?;
        cfg.overridden_by("[flight] mach", format!("--mach {}", Num(m)));
    }
    if let Some(h) = o.cg {
        cfg.case.h = limits::CG.check(h).map_err(|e| bad("--cg", e))?;
        cfg.overridden_by("[flight] cg", format!("--cg {}", Num(h)));
    }
    if let Some(file) = &o.datcom {
        let d = Datcom::load(std::path::Path::new(file), &cfg.case.planform)?;
        // (its lift slope and aerodynamic centre are tables: no named model applies to them)
        cfg.case.aero = d.tables.under(&cfg.tables);
        cfg.datcom = Some(d);
        cfg.overridden_by("[model] datcom", format!("--datcom {file}"));
    }
    if let Some(a) = o.aero {
        if let Some(tables) = aero_tables(cfg) {
            return Err(bad(
                &format!("--aero {}", a.name()),
                format!(
                    "the lift slope and the aerodynamic centre both come from {tables}, which win over a named aerodynamic model, so --aero would change nothing: remove --aero, or the tables it would replace"
                ),
            ));
        }
        cfg.case.aero = cfg.case.aero.clone().with_name(a);
        cfg.overridden_by("[model] aero", format!("--aero {}", a.name()));
    }
    if let Some(m) = o.frequency_method {
        cfg.case.frequency_method = m;
        cfg.overridden_by(
            "[model] frequency_method",
            format!("--frequency-method {}", m.name()),
        );
    }
    if let Some(w) = o.omega_bar {
        let w = limits::OMEGA_BAR
            .check(w)
            .map_err(|e| bad("--omega-bar", e))?;
        if !cfg.case.damping.takes_omega_bar() {
            return Err(bad("--omega-bar", no_omega_bar(cfg.case.damping)));
        }
        cfg.case.omega_bar = Some(w);
        cfg.case.iterate_frequency = false;
        cfg.overridden_by("[model] omega_bar", format!("--omega-bar {}", Num(w)));
    }
    Ok(())
}

/// Where the lift slope and the aerodynamic centre come from when both
/// are tables (the only coefficients a named model gives: `--aero` then
/// changes nothing), in words; `None` when either is not.
fn aero_tables(cfg: &Config) -> Option<String> {
    let table = |s: &Source| matches!(s, Source::Table(_));
    let aero = &cfg.case.aero;
    if !(table(&aero.lift_slope) && table(&aero.aerodynamic_centre)) {
        return None;
    }
    let mine = table(&cfg.tables.lift_slope) && table(&cfg.tables.aerodynamic_centre);
    Some(match (&cfg.datcom, mine) {
        (_, true) => "the config's [model.tables]".to_string(),
        (Some(d), false) => format!("the DATCOM output {}", d.output.path),
        (None, false) => "tables".to_string(),
    })
}

/// Why `--omega-bar` does not apply to `model`.
fn no_omega_bar(model: DampingModel) -> String {
    let takers: Vec<&str> = DampingModel::ALL
        .into_iter()
        .filter(|m| m.takes_omega_bar())
        .map(DampingModel::name)
        .collect();
    format!(
        "the damping model `{}` takes no frequency parameter; the models that do: {}",
        model.name(),
        takers.join(", ")
    )
}
