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
use stability_core::aero::AeroModelName;
use stability_core::case::DampingModel;
use stability_core::display::Num;

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
        cfg.case.aero = cfg.case.aero.clone().with_name(a);
        cfg.overridden_by("[model] aero", format!("--aero {}", a.name()));
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
