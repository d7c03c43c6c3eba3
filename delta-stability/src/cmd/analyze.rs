//! `delta-stability analyze CONFIG [--json]`: a planform at a flight
//! condition → derivatives (§5–7) → quartic (§4) → modes → criteria (§8–9).

use crate::Failure;
use crate::config::{self, limits};
use crate::diag::{InputError, num};
use crate::fmt::sig;
use crate::output::print;
use crate::page::analysis_page;
use serde::Serialize;
use stability_core::Derivatives;
use stability_core::case::{CaseResult, DampingModel, FrequencyIteration, evaluate};
use stability_core::criteria::Margins;
use stability_core::json::CaseView;
use std::fmt::Write;

/// Overrides of the config from the command line.
#[derive(Debug, Default, Clone)]
pub struct Overrides {
    pub damping: Option<DampingModel>,
    pub mach: Option<f64>,
    pub cg: Option<f64>,
}

/// The config with the command line's overrides applied, each within its
/// range.
fn overridden(path: &str, o: &Overrides) -> Result<config::Config, Failure> {
    let mut cfg = config::read(path)?;
    apply(&mut cfg, o)?;
    Ok(cfg)
}

/// Applies the overrides to a config read, each within its range (the
/// Python package's `analyze(…, mach=…)` too).
pub fn apply(cfg: &mut config::Config, o: &Overrides) -> Result<(), Failure> {
    let path = cfg.path.clone();
    let bad =
        |flag: &str, m: String| Failure::Input(InputError::file(&path, format!("{flag}: {m}")));
    if let Some(d) = o.damping {
        cfg.case.damping = d;
        cfg.overridden_by("[model] damping", format!("--damping {}", d.name()));
    }
    if let Some(m) = o.mach {
        cfg.case.mach = limits::MACH.check(m).map_err(|e| bad("--mach", e))?;
        cfg.overridden_by("[flight] mach", format!("--mach {}", num(m)));
    }
    if let Some(h) = o.cg {
        cfg.case.h = limits::CG.check(h).map_err(|e| bad("--cg", e))?;
        cfg.overridden_by("[flight] cg", format!("--cg {}", num(h)));
    }
    Ok(())
}

pub fn run(path: &str, o: &Overrides, json_out: bool) -> Result<(), Failure> {
    let cfg = overridden(path, o)?;
    let r = evaluated(&cfg)?;
    for w in &r.warnings {
        crate::output::warn(&format!("warning: {w}"));
    }
    if json_out {
        print(&format!(
            "{}\n",
            serde_json::to_string_pretty(&to_json(&cfg, &r)).unwrap_or_default()
        ))?;
    } else {
        print(&page(&cfg, &r))?;
    }
    Ok(())
}

/// The design point of a config, every number of its analysis finite, or
/// the error at the field it arises from (what `analyze` prints; the
/// Python package raises the same).
pub fn evaluated(cfg: &config::Config) -> Result<CaseResult, InputError> {
    let r = evaluate(&cfg.case).map_err(|e| cfg.explain(&e))?;
    if !crate::cmd::quartic::is_finite(&r.analysis) {
        return Err(cfg.error_at(
            "[flight]",
            "the analysis overflows f64: no result can be written",
        ));
    }
    Ok(r)
}

/// The `analyze --json` object: the config's path and the design point as
/// the library serializes it.
#[derive(Serialize)]
pub struct AnalyzeJson<'a> {
    file: &'a str,
    #[serde(flatten)]
    point: CaseView<'a>,
}

pub fn to_json<'a>(cfg: &'a config::Config, r: &'a CaseResult) -> AnalyzeJson<'a> {
    AnalyzeJson {
        file: &cfg.path,
        point: r.view(&cfg.case),
    }
}

pub fn page(cfg: &config::Config, r: &CaseResult) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "Design point of {}", cfg.path);
    design_point(&mut s, cfg, r);
    derivatives(&mut s, &r.derivatives);
    s.push_str(&analysis_page(
        "The stability quartic (eqs 4–6):",
        &r.analysis,
        None,
    ));
    let lift_slope = r.coefficients.lift_slope.value;
    let m = Margins::of(&r.analysis.quartic, &r.derivatives, lift_slope);
    let _ = writeln!(
        s,
        "Margins (§9): static K_n = {} (eq 42), manoeuvre H_m = {}",
        m.static_margin.map_or("—".into(), |x| sig(x, 4)),
        m.manoeuvre_margin.map_or("—".into(), |x| sig(x, 4))
    );
    s
}

/// The planform, flight condition, coefficients and damping theory.
fn design_point(s: &mut String, cfg: &config::Config, r: &CaseResult) {
    let c = &cfg.case;
    let p = &c.planform;
    let _ = writeln!(
        s,
        "  planform (§2.2): Λ = {}°, taper {}, A = {}, M.A.C. = {}, S = {}",
        sig(p.sweep_le.to_degrees(), 4),
        sig(p.taper, 3),
        sig(p.aspect_ratio(), 4),
        sig(p.mac(), 4),
        sig(p.area(), 4)
    );
    let _ = writeln!(
        s,
        "  flight: M = {}, h = {}, μ₁ = {}, i_B = {}, C_L·M² = {} → C_L = {} (eq 24)",
        sig(c.mach, 4),
        sig(c.h, 3),
        sig(c.mu1, 4),
        sig(c.i_b, 3),
        sig(c.cl_m2, 3),
        sig(r.c_l, 4)
    );
    let a = &r.coefficients;
    let _ = writeln!(
        s,
        "  aerodynamics (§6): ∂C_L/∂α = {} (d/dM {}), C_D0 = {}, K = {}, H₀ = {}",
        sig(a.lift_slope.value, 4),
        sig(a.lift_slope.d_mach, 3),
        sig(a.zero_lift_drag.value, 3),
        sig(a.drag_due_to_lift.value, 3),
        sig(a.aerodynamic_centre.value, 3)
    );
    let _ = writeln!(
        s,
        "  damping: {} {}; z_θ̇ = {}, m_θ̇ = {}",
        r.damping.theory.name(),
        r.damping.theory.equations(),
        sig(r.damping.derivatives.z_thetadot(), 4),
        sig(r.damping.derivatives.m_thetadot(), 4)
    );
    if let Some(f) = &r.frequency {
        frequency(s, f);
    }
}

/// The frequency iteration of a frequency-dependent theory.
fn frequency(s: &mut String, f: &FrequencyIteration) {
    let _ = writeln!(
        s,
        "  frequency parameter: ω̄ {} → {} in {} iterations{}; m_θ̇ {} → {}, cycles to ½ {} → {}",
        sig(f.initial, 4),
        sig(f.converged, 4),
        f.iterations,
        if f.converged_ok {
            ""
        } else {
            " (not converged)"
        },
        sig(f.m_thetadot_initial, 4),
        sig(f.m_thetadot_converged, 4),
        f.cycles_to_half_initial.map_or("—".into(), |x| sig(x, 4)),
        f.cycles_to_half_converged.map_or("—".into(), |x| sig(x, 4)),
    );
}

/// The fifteen quartic inputs, five to a line.
fn derivatives(s: &mut String, d: &Derivatives) {
    let _ = writeln!(s, "\nDerivatives (report notation, §3):");
    let names = Derivatives::QUARTIC_INPUTS;
    let values = d.quartic_input_values();
    for row in 0..3 {
        let mut line = String::from(" ");
        for col in 0..5 {
            let i = row * 5 + col;
            let _ = write!(line, " {:>7} = {:<11}", names[i], sig(values[i], 5));
        }
        let _ = writeln!(s, "{}", line.trim_end());
    }
    let _ = writeln!(s);
}
