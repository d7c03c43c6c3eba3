//! `delta-stability quartic FILE [--json]`: the stability quartic of a
//! derivative set (eqs 4–6), its roots and modes (§4, eqs 7–8), Routh's
//! test, the §8 damping standard and the MIL-F-8785C levels.

use crate::Failure;
use crate::diag::InputError;
use crate::fmt::sig;
use crate::input::{self, DerivativeFile};
use serde_json::{Value, json};
use stability_core::analysis::Analysis;
use stability_core::criteria::{Category, Verdict, phugoid_level, short_period_level};
use stability_core::modes::Mode;

pub fn run(file: &str, json: bool) -> Result<(), Failure> {
    let input = input::read(file)?;
    for w in &input.warnings {
        eprintln!("warning: {w}");
    }
    let analysis =
        Analysis::of(&input.derivatives).map_err(|e| InputError::file(file, e.to_string()))?;
    if json {
        println!(
            "{}",
            serde_json::to_string_pretty(&to_json(&input, &analysis)).unwrap_or_default()
        );
    } else {
        print!("{}", table(&input, &analysis));
    }
    Ok(())
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

fn cell(v: Option<f64>) -> String {
    v.map_or("—".to_string(), |x| sig(x, 4))
}

pub fn table(input: &DerivativeFile, a: &Analysis) -> String {
    analysis_table(
        &format!(
            "Stability quartic of {} (eqs 4–6; the errata of docs/errata.md applied)",
            input.path
        ),
        a,
        input.dimensional.map(|d| d.tau()),
    )
}

/// The §8 verdict in words, with the cycles to half amplitude behind it.
fn verdict_text(a: &Analysis) -> String {
    let sp = a.modes.short_period();
    let cycles = sp.and_then(|m| m.cycles_to_half);
    match (a.verdict, sp, cycles) {
        (Verdict::Meets, Some(_), Some(c)) => {
            format!("met: {} cycles to half amplitude", sig(c, 3))
        }
        (Verdict::Meets, _, _) => "met: the short period is aperiodic and decays".into(),
        (Verdict::Fails, Some(_), Some(c)) => {
            format!("NOT MET: {} cycles to half amplitude", sig(c, 3))
        }
        (Verdict::Fails, _, _) => "NOT MET: the short period is neutral (it never halves)".into(),
        (Verdict::Divergent, Some(_), _) => "NOT MET: the short period is divergent".into(),
        (Verdict::Divergent, None, _) => {
            "NOT MET: the short period is aperiodic and one of its roots grows".into()
        }
    }
}

/// The analysis as a readable page, under `title`.
pub fn analysis_table(title: &str, a: &Analysis, tau: Option<f64>) -> String {
    use std::fmt::Write;
    let mut s = String::new();
    let q = &a.quartic;
    let _ = writeln!(s, "{title}");
    let _ = writeln!(
        s,
        "  A λ⁴ + B λ³ + C λ² + D λ + E = 0,  λ in units of 1/τ, τ = m/(½ρSV)"
    );
    for (name, v) in ["A", "B", "C", "D", "E"].iter().zip(q.to_array()) {
        let _ = writeln!(s, "  {name} = {:>14}", sig(v, 7));
    }
    let _ = writeln!(
        s,
        "\nRouth (§4): R = BCD − AD² − B²E = {}: {}",
        sig(a.routh.discriminant, 6),
        if a.routh.stable {
            "stable (A…E and R all of one sign)"
        } else {
            "UNSTABLE"
        }
    );
    if let Some(t) = tau {
        let _ = writeln!(s, "τ = {} s", sig(t, 5));
    }
    let _ = writeln!(
        s,
        "\nModes (times in τ{}):",
        if tau.is_some() {
            "; seconds in brackets"
        } else {
            ""
        }
    );
    let mut rows: Vec<[String; 8]> = vec![[
        "mode".into(),
        "root (1/τ)".into(),
        "period".into(),
        "t½ / t×2".into(),
        "cycles ½".into(),
        "ζ".into(),
        "ωₙ (1/τ)".into(),
        "ω̄".into(),
    ]];
    for m in a.modes.iter() {
        let root = if m.im > 0.0 {
            format!("{} ± {}i", sig(m.re, 5), sig(m.im, 5))
        } else {
            sig(m.re, 5)
        };
        let (t, tag) = match (m.time_to_half, m.time_to_double) {
            (Some(t), _) => (Some(t), ""),
            (None, Some(t)) => (Some(t), " ×2"),
            _ => (None, ""),
        };
        let with_s = |x: Option<f64>| match (x, tau) {
            (Some(v), Some(tau)) => format!("{} ({} s)", sig(v, 4), sig(v * tau, 3)),
            _ => cell(x),
        };
        let name = match m.origin {
            Some(o) if m.name.as_str() == "aperiodic" => format!(
                "aperiodic ({})",
                match o {
                    stability_core::modes::Origin::ShortPeriod => "sp",
                    stability_core::modes::Origin::Phugoid => "ph",
                    stability_core::modes::Origin::Unknown => "?",
                }
            ),
            _ => m.name.as_str().replace('_', " "),
        };
        rows.push([
            name,
            root,
            with_s(m.period),
            format!("{}{tag}", with_s(t)),
            cell(m.cycles_to_half.or(m.cycles_to_double.map(|c| -c))),
            cell(m.damping_ratio),
            sig(m.natural_frequency, 4),
            cell(m.frequency_parameter),
        ]);
    }
    let widths: Vec<usize> = (0..8)
        .map(|k| rows.iter().map(|r| r[k].chars().count()).max().unwrap_or(0))
        .collect();
    for r in &rows {
        let mut line = String::from(" ");
        for (k, cellv) in r.iter().enumerate() {
            let pad = widths[k] - cellv.chars().count();
            if k == 0 {
                line.push_str(&format!(" {cellv}{}", " ".repeat(pad)));
            } else {
                line.push_str(&format!("  {}{cellv}", " ".repeat(pad)));
            }
        }
        let _ = writeln!(s, "{line}");
    }
    if let Some(c) = &a.classical {
        let _ = writeln!(
            s,
            "\nThe report's eq (7): short period {} ± {}i (error {}%), phugoid {} ± {}i (error {}%); refined by successive approximation in {} iterations{}",
            sig(c.short_period.0, 5),
            sig(c.short_period.1, 5),
            sig(100.0 * c.short_period_error, 3),
            sig(c.phugoid.0, 5),
            sig(c.phugoid.1, 5),
            sig(100.0 * c.phugoid_error, 3),
            c.refinement_iterations,
            if c.refinement_converged {
                ""
            } else {
                " (not converged)"
            }
        );
    }
    let sp = &a.short_period_approximation;
    let ds = &a.damping_standard;
    let _ = writeln!(
        s,
        "\nShort-period approximation (§8–9: x_u, z_ẇ/μ₁, z_q/μ₁ neglected): B ≈ {}, C ≈ {}, root ≈ {} ± {}i, cycles to ½ ≈ {} (report's 0.2206√C/B: {})",
        sig(sp.b, 5),
        sig(sp.c, 5),
        sig(sp.re, 5),
        sig(sp.im, 5),
        cell(sp.cycles_to_half),
        cell(sp.cycles_to_half_report)
    );
    let verdict = verdict_text(a);
    let _ = writeln!(
        s,
        "Damping standard (§8: half amplitude within one cycle): {verdict}"
    );
    let _ = writeln!(
        s,
        "  eq (41): m_θ̇ = {}, m_θ̇max = {}, Δm_θ̇ = {} (exact second-order limit: {})",
        sig(ds.m_thetadot, 5),
        cell(ds.m_thetadot_max),
        cell(ds.margin),
        cell(ds.margin_exact)
    );
    if let Some(z) = a.modes.short_period().and_then(|m| m.damping_ratio) {
        let _ = writeln!(
            s,
            "MIL-F-8785C short period, ζ = {}: Category A {}, B {}, C {}",
            sig(z, 3),
            short_period_level(z, Category::A).as_str(),
            short_period_level(z, Category::B).as_str(),
            short_period_level(z, Category::C).as_str()
        );
    }
    if let Some(m) = a.modes.phugoid()
        && let Some(z) = m.damping_ratio
    {
        let t2 = tau.and_then(|t| m.time_to_double.map(|x| x * t));
        let _ = writeln!(
            s,
            "MIL-F-8785C phugoid, ζ = {}: {}",
            sig(z, 3),
            phugoid_level(z, t2).as_str()
        );
    }
    s
}
