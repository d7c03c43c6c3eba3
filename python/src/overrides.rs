//! The command line's overrides of a config as keyword arguments:
//! `analyze(…, mach=, cg=, damping=, aero=, omega_bar=, datcom=,
//! frequency_method=)` and `sweep(…, damping=, aero=, omega_bar=, datcom=,
//! frequency_method=)` are `--mach`, `--cg`, `--damping`, `--aero`,
//! `--omega-bar`, `--datcom` and `--frequency-method`, applied by the command line's own
//! [`stability_io::config::apply`] (each value within its range, the same
//! messages).

use crate::errors::{argument, failure};
use crate::inputs;
use pyo3::prelude::*;
use stability_core::aerodynamics::models::aero::AeroModelName;
use stability_core::design::case::{DampingModel, FrequencyMethod};
use stability_io::config::{Config, Overrides, apply};
use stability_io::input::suggest::did_you_mean;

/// The model options, as given (names not yet parsed).
#[derive(Debug, Default, Clone, Copy)]
pub struct Model<'a> {
    /// `faired` (the default), `faired-slender` or a §7 theory.
    pub damping: Option<&'a str>,
    /// `default` or `lifting-surface` (the lattice's lift slope and
    /// aerodynamic centre, eqs 25–29's inputs).
    pub aero: Option<&'a str>,
    /// A frequency-dependent theory at ω̄ = W, not iterated.
    pub omega_bar: Option<f64>,
    /// A DATCOM output's tables (`--datcom FILE`).
    pub datcom: Option<&'a str>,
    /// `p` (the default), `p-k` or `k` (`--frequency-method`).
    pub frequency_method: Option<&'a str>,
}

/// The frequency method named `name`.
fn frequency_method(name: &str) -> PyResult<FrequencyMethod> {
    FrequencyMethod::parse(name).ok_or_else(|| {
        let names = FrequencyMethod::ALL.map(FrequencyMethod::name);
        argument(
            "frequency_method",
            format!(
                "unknown frequency method `{name}`{}; the methods: {}",
                did_you_mean(name, names),
                names.join(", ")
            ),
        )
    })
}

/// The damping model named `name`.
fn damping(name: &str) -> PyResult<DampingModel> {
    DampingModel::parse(name).map_err(|e| {
        let hint = did_you_mean(name, DampingModel::ALL.map(DampingModel::name));
        argument("damping", format!("unknown damping model: {e}{hint}"))
    })
}

/// The aerodynamic model named `name`.
fn aero(name: &str) -> PyResult<AeroModelName> {
    AeroModelName::parse(name).ok_or_else(|| {
        let names = AeroModelName::ALL.map(AeroModelName::name);
        argument(
            "aero",
            format!(
                "unknown aerodynamic model `{name}`{}; the models: {}",
                did_you_mean(name, names),
                names.join(", ")
            ),
        )
    })
}

/// The config read, with the overrides applied as the command line
/// applies its flags.
pub fn overridden(
    config: &Bound<'_, PyAny>,
    mach: Option<f64>,
    cg: Option<f64>,
    model: Model<'_>,
) -> PyResult<Config> {
    let mut cfg = inputs::config(config)?;
    let o = Overrides {
        damping: model.damping.map(damping).transpose()?,
        mach,
        cg,
        aero: model.aero.map(aero).transpose()?,
        omega_bar: model.omega_bar,
        datcom: model.datcom.map(str::to_string),
        frequency_method: model.frequency_method.map(frequency_method).transpose()?,
    };
    apply(&mut cfg, &o).map_err(failure)?;
    Ok(cfg)
}
