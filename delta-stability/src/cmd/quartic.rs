//! `delta-stability quartic FILE [--json]`: the stability quartic of a
//! derivative set (eqs 4–6), its roots and modes (§4, eqs 7–8), Routh's
//! test, the §8 damping standard and the MIL-F-8785C levels.

use crate::Failure;
use crate::input::{self, DerivativeFile, rows};
use crate::output::print;
use crate::page::analysis_page;
use serde_json::{Value, json};
use stability_core::analysis::{Analysis, AnalysisError};
use stability_core::criteria::{Category, phugoid_level, short_period_level};
use stability_core::modes::Mode;

pub fn run(file: &str, json: bool) -> Result<(), Failure> {
    let input = input::read(file)?;
    for w in &input.warnings {
        crate::output::warn(&format!("warning: {w}"));
    }
    let analysis = Analysis::of(&input.derivatives)
        .map_err(|e| input.error_at(blame(&input, &e), e.to_string()))?;
    if !is_finite(&analysis) {
        let largest = largest_input(&input);
        return Err(input
            .error_at(
                largest,
                "the analysis overflows f64: no result can be written",
            )
            .into());
    }
    if json {
        print(&format!(
            "{}\n",
            serde_json::to_string_pretty(&to_json(&input, &analysis)).unwrap_or_default()
        ))?;
    } else {
        print(&table(&input, &analysis))?;
    }
    Ok(())
}

/// Whether every number the analysis would print is finite (absent ones,
/// such as an aperiodic mode's period, are `None`, not infinite).
pub fn is_finite(a: &Analysis) -> bool {
    a.quartic.to_array().iter().all(|v| v.is_finite())
        && a.roots.iter().all(|z| z.re.is_finite() && z.im.is_finite())
        && a.routh.discriminant.is_finite()
        && a.modes.iter().all(|m| m.re.is_finite() && m.im.is_finite())
}

/// The quartic input of largest magnitude (the likeliest cause of an
/// overflow).
fn largest_input(input: &DerivativeFile) -> usize {
    let mut best = (0.0, rows::QUARTIC[0]);
    for i in rows::QUARTIC {
        let v = input.report[i].map_or(0.0, f64::abs);
        if v > best.0 {
            best = (v, i);
        }
    }
    best.1
}

/// The row an analysis error is about.
fn blame(input: &DerivativeFile, e: &AnalysisError) -> usize {
    match e {
        AnalysisError::LeadingCoefficientZero(_) => rows::Z_WDOT,
        AnalysisError::NonPositiveParameter { mu1, .. } if *mu1 <= 0.0 => rows::MU,
        AnalysisError::NonPositiveParameter { .. } => rows::I_B,
        _ => largest_input(input),
    }
}

fn opt(v: Option<f64>) -> Value {
    match v {
        Some(x) if x.is_finite() => json!(x),
        _ => Value::Null,
    }
}

/// One mode as JSON (units of τ; seconds too when τ is known).
pub fn mode_json(m: &Mode, tau: Option<f64>) -> Value {
    let mut v = json!({
        "name": m.name.as_str(),
        "origin": m.origin,
        "re": m.re,
        "im": m.im,
        "period": opt(m.period),
        "time_to_half": opt(m.time_to_half),
        "time_to_double": opt(m.time_to_double),
        "cycles_to_half": opt(m.cycles_to_half),
        "cycles_to_double": opt(m.cycles_to_double),
        "damping_ratio": opt(m.damping_ratio),
        "natural_frequency": m.natural_frequency,
        "frequency_parameter": opt(m.frequency_parameter),
    });
    if let (Some(tau), Value::Object(map)) = (tau, &mut v) {
        let s = m.in_seconds(tau);
        map.insert("period_s".into(), opt(s.period));
        map.insert("time_to_half_s".into(), opt(s.time_to_half));
        map.insert("time_to_double_s".into(), opt(s.time_to_double));
        map.insert("re_s".into(), json!(s.re));
        map.insert("im_s".into(), json!(s.im));
    }
    v
}

fn levels_json(a: &Analysis, tau: Option<f64>) -> Value {
    let sp = a.modes.short_period().and_then(|m| m.damping_ratio);
    let short = sp.map(|z| {
        json!({
            "damping_ratio": z,
            "A": short_period_level(z, Category::A).as_str(),
            "B": short_period_level(z, Category::B).as_str(),
            "C": short_period_level(z, Category::C).as_str(),
        })
    });
    let ph = a.modes.phugoid().and_then(|m| {
        let t2 = tau.and_then(|t| m.time_to_double.map(|x| x * t));
        m.damping_ratio
            .map(|z| json!({ "damping_ratio": z, "level": phugoid_level(z, t2).as_str() }))
    });
    json!({ "short_period": short, "phugoid": ph })
}

/// The analysis as JSON: the keys `coefficients`, `routh_discriminant`,
/// `stable`, `roots`, `modes`, `criteria` (and `tau_s`).
pub fn analysis_json(a: &Analysis, tau: Option<f64>) -> serde_json::Map<String, Value> {
    let q = &a.quartic;
    let roots: Vec<Value> = a
        .roots
        .iter()
        .map(|z| {
            let mut v = json!({ "re": z.re, "im": z.im });
            if let (Some(t), Value::Object(map)) = (tau, &mut v) {
                map.insert("re_s".into(), json!(z.re / t));
                map.insert("im_s".into(), json!(z.im / t));
            }
            v
        })
        .collect();
    let sp = &a.short_period_approximation;
    let ds = &a.damping_standard;
    let v = json!({
        "coefficients": { "A": q.a, "B": q.b, "C": q.c, "D": q.d, "E": q.e },
        "routh_discriminant": a.routh.discriminant,
        "stable": a.routh.stable,
        "roots": roots,
        "modes": a.modes.iter().map(|m| mode_json(m, tau)).collect::<Vec<_>>(),
        "tau_s": opt(tau),
        "criteria": {
            "one_cycle_standard_met": a.verdict.is_met(),
            "verdict": a.verdict,
            "short_period_approximation": {
                "B": sp.b, "C": sp.c, "re": sp.re, "im": sp.im,
                "cycles_to_half_report": opt(sp.cycles_to_half_report),
                "cycles_to_half": opt(sp.cycles_to_half),
                "frequency_parameter": opt(sp.frequency_parameter),
            },
            "damping_standard": {
                "m_thetadot": ds.m_thetadot,
                "m_thetadot_max": opt(ds.m_thetadot_max),
                "margin": opt(ds.margin),
                "m_thetadot_max_exact": opt(ds.m_thetadot_max_exact),
                "margin_exact": opt(ds.margin_exact),
            },
            "mil_f_8785c": levels_json(a, tau),
        },
        "classical_eq7": a.classical,
    });
    match v {
        Value::Object(map) => map,
        _ => serde_json::Map::new(),
    }
}

pub fn to_json(input: &DerivativeFile, a: &Analysis) -> Value {
    let mut map = serde_json::Map::new();
    map.insert("file".into(), json!(input.path));
    map.insert("notation".into(), json!(input.notation));
    map.extend(analysis_json(a, input.dimensional.map(|d| d.tau())));
    map.insert("warnings".into(), json!(input.warnings));
    Value::Object(map)
}

pub fn table(input: &DerivativeFile, a: &Analysis) -> String {
    analysis_page(
        &format!(
            "Stability quartic of {} (eqs 4–6; the errata of docs/errata.md applied)",
            input.path
        ),
        a,
        input.dimensional.map(|d| d.tau()),
    )
}
