//! A config's `[uncertainty]` table: a distribution on any
//! input, correlations between them, and damping theories with weights —
//! the [`stability_core::uncertainty::Study`] of `delta-stability
//! uncertainty` and of Python's `uncertainty()`.
//!
//! ```toml
//! [uncertainty.i_b]            # the value itself (the default for flight inputs)
//! dist = "normal"
//! relative_sd = 0.1            # sd = 0.1 × mean; mean defaults to the config's i_b
//!
//! [uncertainty.m_q]            # a derivative: an error on its computed value
//! error = "multiplicative"     # the default for derivatives; or "additive"
//! dist = "uniform"
//! low = 0.8
//! high = 1.2
//!
//! [uncertainty.cg]
//! dist = "triangular"
//! low = 0.22
//! mode = 0.25
//! high = 0.30
//!
//! [uncertainty.mass]           # with a physical [flight]: altitude, mass, I_y
//! dist = "samples"
//! file = "masses.csv"          # one number a line (a header line allowed); or values = [...]
//!
//! [uncertainty.model]          # model-form uncertainty
//! damping = ["faired", "lifting-surface"]
//! weights = [0.7, 0.3]         # default: equal
//!
//! [uncertainty]
//! correlation = [{ between = ["i_b", "cg"], rho = 0.5 }]
//! sampling = "sobol"           # Owen-scrambled Sobol′ points; default "random"
//! ```
//!
//! Inputs: `mu1`, `i_b`, `cl_m2`, `cg`; `altitude`, `mass`, `I_y` (a
//! physical flight condition, in its units; `mass` is the weight where
//! `[flight]` gives one); the derivatives `x_u` … `m_q`. Distributions:
//! `normal` (`mean`, `sd` or `relative_sd`), `lognormal` (`median` or
//! `mu`, and `sigma`, of ln x), `uniform` (`low`, `high`), `triangular`
//! (`low`, `mode`, `high`), `samples` (`values` or `file`). A mean or
//! median not given is the nominal value (1 for a multiplicative error, 0
//! for an additive one). Correlations are between the inputs' normal
//! scores (a Gaussian copula). Every error names the file, line and field.

use super::Config;
use crate::Failure;
use crate::diag::{InputError, quote};
use crate::input::toml_error;
use serde::Deserialize;
use stability_core::design::case::DampingModel;
use stability_core::design::flight::{Air, Altitude, Mass};
use stability_core::numerics::display::Num;
use stability_core::uncertainty::dist::{Dist, DistError};
use stability_core::uncertainty::{ErrorKind, Input, Quantity, Sampling, Study, StudyError};
use std::collections::BTreeMap;
use toml::Spanned;

#[derive(Deserialize)]
struct WithUncertainty {
    uncertainty: Option<Spanned<BTreeMap<String, Spanned<toml::Value>>>>,
}

/// One input's table.
#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct RawInput {
    dist: String,
    error: Option<String>,
    mean: Option<f64>,
    sd: Option<f64>,
    relative_sd: Option<f64>,
    median: Option<f64>,
    mu: Option<f64>,
    sigma: Option<f64>,
    low: Option<f64>,
    mode: Option<f64>,
    high: Option<f64>,
    values: Option<Vec<f64>>,
    file: Option<String>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawModelForm {
    damping: Vec<String>,
    weights: Option<Vec<f64>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawCorrelation {
    between: [String; 2],
    rho: f64,
}

/// The config's uncertainty study, if it has an `[uncertainty]` table.
pub fn read(cfg: &Config) -> Result<Option<Study>, Failure> {
    let (path, text) = (cfg.path.as_str(), cfg.text());
    let raw: WithUncertainty = toml::from_str(text).map_err(|e| toml_error(path, text, &e))?;
    let Some(table) = raw.uncertainty else {
        return Ok(None);
    };
    let whole = table.span();
    let at = |span: std::ops::Range<usize>, field: String, m: String| {
        Failure::Input(InputError::at(path, text, span, field, m))
    };
    let (mut inputs, mut correlations, mut models) = (Vec::new(), Vec::new(), Vec::new());
    for (name, value) in table.get_ref() {
        let span = value.span();
        let v = value.get_ref().clone();
        match name.as_str() {
            "correlation" => {
                let field = "[uncertainty] correlation".to_string();
                let list = Vec::<RawCorrelation>::deserialize(v).map_err(|e| {
                    at(span.clone(), field.clone(), format!("{}; write correlation = [{{ between = [\"i_b\", \"cg\"], rho = 0.5 }}]", e.message().trim()))
                })?;
                correlations = list
                    .into_iter()
                    .map(|c| {
                        let [a, b] = c.between;
                        (a, b, c.rho)
                    })
                    .collect();
            }
            "model" => {
                models =
                    model_form(v).map_err(|m| at(span.clone(), "[uncertainty.model]".into(), m))?;
                honoured(cfg, &models).map_err(|m| at(span, "[uncertainty.model]".into(), m))?;
            }
            // how to sample, not a distribution: [`sampling`]'s
            "sampling" => {}
            _ => inputs.push(input(cfg, name, v, span)?),
        }
    }
    let flight = cfg.physical.as_ref().map(|p| p.condition);
    Study::new(cfg.case.clone(), flight, inputs, &correlations, &models)
        .map(Some)
        .map_err(|e| {
            let key = key_of(&e);
            let field = match key {
                "correlation" => "[uncertainty] correlation".to_string(),
                "model" => "[uncertainty.model] weights".to_string(),
                "" => "[uncertainty]".to_string(),
                n => format!("[uncertainty.{n}]"),
            };
            let span = table.get_ref().get(key).map_or(whole, |v| v.span());
            at(span, field, e.to_string())
        })
}

/// The files `[uncertainty]` names (`file = "masses.csv"` of a samples
/// distribution), relative to the config at `path`, whether or not the
/// run reads them: inputs of the run all the same
/// ([`crate::files::note_input`]). A table that does not parse names none
/// here (its reader says why).
pub fn named_files(path: &str, text: &str) -> Vec<std::path::PathBuf> {
    let Ok(doc) = toml::from_str::<toml::Table>(text) else {
        return Vec::new();
    };
    let Some(toml::Value::Table(u)) = doc.get("uncertainty") else {
        return Vec::new();
    };
    u.values()
        .filter_map(|v| v.get("file").and_then(toml::Value::as_str))
        .map(|f| super::relative(path, f))
        .collect()
}

/// The config's `sampling = "random" | "sobol"` in `[uncertainty]`
/// ([`stability_core::uncertainty::quasi`]), if it has one.
pub fn sampling(cfg: &Config) -> Result<Option<Sampling>, Failure> {
    let (path, text) = (cfg.path.as_str(), cfg.text());
    let raw: WithUncertainty = toml::from_str(text).map_err(|e| toml_error(path, text, &e))?;
    let Some(value) = raw
        .uncertainty
        .and_then(|t| t.into_inner().remove("sampling"))
    else {
        return Ok(None);
    };
    let span = value.span();
    let name = value.get_ref().as_str();
    let shown = name.map_or_else(|| value.get_ref().to_string(), str::to_string);
    name.and_then(Sampling::parse).map(Some).ok_or_else(|| {
        Failure::Input(InputError::at(
            path,
            text,
            span,
            "[uncertainty] sampling".to_string(),
            format!(
                "`{}` is not a sampling: write sampling = \"random\" (pseudo-random, the default) or \"sobol\" (Owen-scrambled Sobol′ points)",
                quote(&shown)
            ),
        ))
    })
}

/// The key of `[uncertainty]` a study's error is about ("" the table).
fn key_of(e: &StudyError) -> &'static str {
    match e {
        StudyError::Correlation(_) | StudyError::NotUncertain(_) => "correlation",
        StudyError::Weights => "model",
        StudyError::Dist(n, _)
        | StudyError::NeedsPhysical(n)
        | StudyError::FixedByPhysical(n)
        | StudyError::DerivativeValue(n)
        | StudyError::Duplicate(n) => n,
        StudyError::NoAltitude => "altitude",
        StudyError::TooMany => "",
    }
}

/// The command line's model options against `[uncertainty.model]`, which
/// fixes the study's damping models: `--damping` would change nothing (an
/// error, not ignored), and `--omega-bar` must apply to every model.
fn honoured(cfg: &Config, models: &[(DampingModel, f64)]) -> Result<(), String> {
    let names = || {
        models
            .iter()
            .map(|(m, _)| m.name())
            .collect::<Vec<_>>()
            .join(", ")
    };
    if let Some(flag) = cfg.overridden_flag("[model] damping") {
        return Err(format!(
            "{flag}: [uncertainty.model] gives the study's damping models ({}), so --damping would change nothing; give the models there, or remove [uncertainty.model] to study --damping's model alone",
            names()
        ));
    }
    if let Some(flag) = cfg.overridden_flag("[model] omega_bar")
        && let Some((m, _)) = models.iter().find(|(m, _)| !m.takes_omega_bar())
    {
        return Err(format!(
            "{flag}: the damping model `{}` of [uncertainty.model] ({}) takes no frequency parameter; remove --omega-bar, or that model",
            m.name(),
            names()
        ));
    }
    Ok(())
}

/// `[uncertainty.model]`: the theories and their weights.
fn model_form(v: toml::Value) -> Result<Vec<(DampingModel, f64)>, String> {
    let raw = RawModelForm::deserialize(v).map_err(|e| e.message().trim().to_string())?;
    let weights = raw.weights.unwrap_or_else(|| vec![1.0; raw.damping.len()]);
    if weights.len() != raw.damping.len() || raw.damping.is_empty() {
        return Err(format!(
            "give one weight per damping model ({} models, {} weights)",
            raw.damping.len(),
            weights.len()
        ));
    }
    raw.damping
        .iter()
        .zip(weights)
        .map(|(d, w)| {
            DampingModel::parse(d).map(|m| (m, w)).map_err(|_| {
                let names = DampingModel::ALL.map(DampingModel::name);
                format!(
                    "unknown damping model `{}`{}; the models are: {}",
                    quote(d),
                    crate::input::suggest::did_you_mean(d, names),
                    names.join(", ")
                )
            })
        })
        .collect()
}

/// One input's table read: its quantity, error and distribution.
fn input(
    cfg: &Config,
    name: &str,
    v: toml::Value,
    span: std::ops::Range<usize>,
) -> Result<Input, Failure> {
    let field = format!("[uncertainty.{name}]");
    let err = |f: &str, m: String| {
        let field = if f.is_empty() {
            field.clone()
        } else {
            format!("{field} {f}")
        };
        Failure::Input(InputError::at(
            &cfg.path,
            cfg.text(),
            span.clone(),
            field,
            m,
        ))
    };
    let quantity = Quantity::parse(name).ok_or_else(|| {
        let names: Vec<_> = Quantity::names().collect();
        err(
            "",
            format!(
                "`{}` cannot be uncertain{}; the inputs are: {}, and the tables model and correlation",
                quote(name),
                crate::input::suggest::did_you_mean(name, names.iter().copied()),
                names.join(", ")
            ),
        )
    })?;
    if quantity.is_physical() && cfg.physical.is_none() {
        return Err(err(
            "",
            StudyError::NeedsPhysical(quantity.name()).to_string(),
        ));
    }
    let raw = RawInput::deserialize(v).map_err(|e| err("", e.message().trim().to_string()))?;
    let error = match raw.error.as_deref() {
        None if matches!(quantity, Quantity::Derivative(_)) => ErrorKind::Multiplicative,
        None | Some("value") => ErrorKind::Value,
        Some("multiplicative") => ErrorKind::Multiplicative,
        Some("additive") => ErrorKind::Additive,
        Some(o) => {
            return Err(err(
                "error",
                format!(
                    "`{}` is not an error kind: value, multiplicative or additive",
                    quote(o)
                ),
            ));
        }
    };
    let centre = match error {
        ErrorKind::Value => nominal(cfg, quantity),
        ErrorKind::Multiplicative => 1.0,
        ErrorKind::Additive => 0.0,
    };
    let dist = dist(cfg, &raw, centre).map_err(|(f, m)| err(f, m))?;
    dist.check().map_err(|e| {
        let (key, message) = written(&raw, &e);
        err(key, message)
    })?;
    Ok(Input {
        quantity,
        error,
        dist,
    })
}

/// The key of the table a distribution's error is about, as the user
/// wrote it (an `sd` computed from `relative_sd` is that key's), with the
/// message.
fn written(r: &RawInput, e: &DistError) -> (&'static str, String) {
    let param = match e {
        DistError::NotFinite(p) | DistError::Negative(p) => *p,
        DistError::Order => "high",
        DistError::Mode => "mode",
        DistError::NoSamples => "values",
    };
    match param {
        "sd" if r.sd.is_none() && r.relative_sd.is_some() => {
            ("relative_sd", format!("{e} (sd = relative_sd × |mean|)"))
        }
        "mu" if r.mu.is_none() => ("median", format!("{e} (mu = ln median)")),
        "a sample" => ("values", e.to_string()),
        p => (p, e.to_string()),
    }
}

/// The config's nominal value of a quantity (a derivative's: its own,
/// known only when computed; an error takes it).
fn nominal(cfg: &Config, q: Quantity) -> f64 {
    let c = &cfg.case;
    let f = cfg.physical.as_ref().map(|p| p.condition);
    match q {
        Quantity::Mu1 => c.mu1,
        Quantity::IB => c.i_b,
        Quantity::ClM2 => c.cl_m2,
        Quantity::Cg => c.h,
        Quantity::Altitude => match f.map(|f| f.air) {
            Some(Air::Standard(Altitude::Pressure(h) | Altitude::Geometric(h))) => h,
            _ => f64::NAN,
        },
        Quantity::Mass => match f.map(|f| f.mass) {
            Some(Mass::Mass(m) | Mass::Weight(m)) => m,
            None => f64::NAN,
        },
        Quantity::PitchInertia => f.map_or(f64::NAN, |f| f.pitch_inertia),
        Quantity::Derivative(_) => f64::NAN,
    }
}

type ParamError = (&'static str, String);

/// The distribution a table gives, its mean or median defaulting to
/// `centre`.
fn dist(cfg: &Config, r: &RawInput, centre: f64) -> Result<Dist, ParamError> {
    let need = |name: &'static str, v: Option<f64>| {
        v.ok_or((name, format!("the {} distribution needs `{name}`", r.dist)))
    };
    let centre = |v: Option<f64>, name: &'static str| match v {
        Some(v) => Ok(v),
        None if centre.is_finite() => Ok(centre),
        None => Err((
            name,
            format!(
                "give `{name}`: the nominal value is not known before the derivatives are computed (or the air is given as rho); or use error = \"multiplicative\""
            ),
        )),
    };
    Ok(match r.dist.as_str() {
        "normal" => {
            let mean = centre(r.mean, "mean")?;
            let sd = match (r.sd, r.relative_sd) {
                (Some(sd), None) => sd,
                (None, Some(rel)) => rel * mean.abs(),
                _ => return Err(("sd", "give one of `sd` and `relative_sd`".into())),
            };
            Dist::Normal { mean, sd }
        }
        "lognormal" => {
            let mu = match (r.mu, r.median) {
                (Some(mu), None) => mu,
                (Some(_), Some(_)) => {
                    return Err((
                        "mu",
                        "give one of `median` and `mu` (mu = ln median)".into(),
                    ));
                }
                (None, given) => ln_median(given, centre(r.median, "median")?)?,
            };
            Dist::LogNormal {
                mu,
                sigma: need("sigma", r.sigma)?,
            }
        }
        "uniform" => Dist::Uniform {
            low: need("low", r.low)?,
            high: need("high", r.high)?,
        },
        "triangular" => Dist::Triangular {
            low: need("low", r.low)?,
            mode: need("mode", r.mode)?,
            high: need("high", r.high)?,
        },
        "samples" => Dist::samples(samples(cfg, r)?).map_err(|e| ("values", e.to_string()))?,
        other => {
            return Err((
                "dist",
                format!(
                    "`{}` is not a distribution: normal, lognormal, uniform, triangular or samples",
                    quote(other)
                ),
            ));
        }
    })
}

/// ln of a lognormal's median — `given`, else the nominal value `median`
/// — which must be positive and finite.
fn ln_median(given: Option<f64>, median: f64) -> Result<f64, ParamError> {
    if median > 0.0 && median.is_finite() {
        return Ok(median.ln());
    }
    let m = match given {
        Some(_) => format!(
            "a lognormal's median is positive and finite, not {}",
            Num(median)
        ),
        None => format!(
            "give `median` (or `mu`, its logarithm): it defaults to the nominal value, {} here (an additive error's is 0), and a lognormal's median is positive; or use dist = \"normal\"",
            Num(median)
        ),
    };
    Err(("median", m))
}

/// The samples of `dist = "samples"`: `values = [...]` or a file of one
/// number a line.
fn samples(cfg: &Config, r: &RawInput) -> Result<Vec<f64>, ParamError> {
    match (&r.values, &r.file) {
        (Some(v), None) => Ok(v.clone()),
        (None, Some(f)) => {
            let file = super::relative(&cfg.path, f);
            let text = crate::files::read_input(&file).map_err(|e| ("file", e.to_string()))?;
            read_samples_csv(&file.display().to_string(), &text)
                .map_err(|e| ("file", e.to_string()))
        }
        _ => Err((
            "values",
            "give `values = [...]` or `file = \"samples.csv\"`".into(),
        )),
    }
}

/// One number a line; blank lines and `#` comments skipped; a first line
/// that is not a number is a header.
pub fn read_samples_csv(path: &str, csv: &str) -> Result<Vec<f64>, InputError> {
    let mut out = Vec::new();
    let mut first = true;
    for (i, line) in csv.lines().enumerate() {
        let l = line.trim();
        if l.is_empty() || l.starts_with('#') {
            continue;
        }
        match l.parse::<f64>() {
            Ok(x) if x.is_finite() => out.push(x),
            _ if first => {}
            _ => {
                return Err(InputError::at_line(
                    path,
                    csv,
                    i + 1,
                    format!("`{}` is not a finite number; one number a line", quote(l)),
                ));
            }
        }
        first = false;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::{Overrides, apply, parse};

    const BASE: &str = "[planform]\nsweep = 60.0\nroot_chord = 10.0\n[flight]\nmach = 1.5\ncg = 0.25\nmu1 = 50.0\ni_b = 0.08\ncl_m2 = 0.05\n";

    fn error(more: &str) -> String {
        let cfg = parse("c.toml", &format!("{BASE}{more}")).unwrap();
        read(&cfg).unwrap_err().to_string()
    }

    #[test]
    fn a_distributions_error_names_the_key_written_or_to_write() {
        // an additive error's median defaults to 0: no lognormal has it
        let e =
            error("[uncertainty.m_q]\nerror = \"additive\"\ndist = \"lognormal\"\nsigma = 0.2\n");
        assert!(e.contains("[uncertainty.m_q] median: give `median`"), "{e}");
        let e = error("[uncertainty.i_b]\ndist = \"lognormal\"\nmedian = -0.1\nsigma = 0.2\n");
        assert!(
            e.contains("[uncertainty.i_b] median: a lognormal's median is positive"),
            "{e}"
        );
        let e = error(
            "[uncertainty.i_b]\ndist = \"lognormal\"\nmedian = 0.1\nmu = -2.0\nsigma = 0.2\n",
        );
        assert!(e.contains("[uncertainty.i_b] mu: give one of"), "{e}");
        // sd = relative_sd·|mean| overflows: relative_sd is what was written
        let e = error("[uncertainty.i_b]\ndist = \"normal\"\nmean = 1e300\nrelative_sd = 1e300\n");
        assert!(
            e.contains("[uncertainty.i_b] relative_sd: sd is not a finite number"),
            "{e}"
        );
        let e = error("[uncertainty.i_b]\ndist = \"normal\"\nsd = -0.1\n");
        assert!(
            e.contains("[uncertainty.i_b] sd: sd must not be negative"),
            "{e}"
        );
    }

    #[test]
    fn an_override_the_study_cannot_honour_is_an_error() {
        let text = format!(
            "{BASE}[uncertainty.i_b]\ndist = \"normal\"\nrelative_sd = 0.1\n[uncertainty.model]\ndamping = [\"faired\", \"supersonic\"]\n"
        );
        let with = |o: Overrides| {
            let mut cfg = parse("c.toml", &text).unwrap();
            apply(&mut cfg, &o).unwrap();
            read(&cfg).map(|_| ()).map_err(|e| e.to_string())
        };
        let e = with(Overrides {
            damping: Some(DampingModel::Faired),
            ..Default::default()
        })
        .unwrap_err();
        assert!(e.contains("[uncertainty.model]: --damping faired: "), "{e}");
        // the supersonic theory takes no ω̄
        let e = with(Overrides {
            omega_bar: Some(0.3),
            ..Default::default()
        })
        .unwrap_err();
        assert!(
            e.contains("--omega-bar 0.3: the damping model `supersonic`"),
            "{e}"
        );
        assert!(with(Overrides::default()).is_ok());
    }

    #[test]
    fn a_samples_file_is_an_input_of_every_reading_of_the_config() {
        let text = format!("{BASE}[uncertainty.i_b]\ndist = \"samples\"\nfile = \"s.csv\"\n");
        let (cfg, read) = crate::files::recording(|| parse("dir/c.toml", &text));
        assert!(cfg.is_ok());
        assert_eq!(read, [std::path::PathBuf::from("dir/s.csv")]);
    }
}
