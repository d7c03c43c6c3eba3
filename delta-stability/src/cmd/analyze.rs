//! `delta-stability analyze CONFIG [--json] [--state-space OUT.json]`: a
//! planform at a flight condition → derivatives (§5–7) → quartic (§4) →
//! modes → criteria (§8–9); with a physical flight condition
//! ([`crate::config::physical`]), μ₁, i_B, C_L and τ from it and the modes
//! in seconds too.

use crate::Failure;
use crate::config::{self, limits};
use crate::diag::{InputError, num};
use crate::fmt::sig;
use crate::output::print;
use crate::page::analysis_page;
use serde::Serialize;
use stability_core::Derivatives;
use stability_core::aero::AeroModelName;
use stability_core::case::{CaseResult, DampingModel, FrequencyIteration, evaluate};
use stability_core::criteria::Margins;
use stability_core::damping::Theory;
use stability_core::engineering::Engineering;
use stability_core::flight::{FlightJson, FlightPoint, PhysicalFlight};
use stability_core::json::CaseView;
use std::fmt::Write;

use super::quartic::Options;

/// Overrides of the config from the command line.
#[derive(Debug, Default, Clone)]
pub struct Overrides {
    pub damping: Option<DampingModel>,
    pub mach: Option<f64>,
    pub cg: Option<f64>,
    pub aero: Option<AeroModelName>,
    /// `--omega-bar W`: the frequency-dependent theories at ω̄ = W (not
    /// iterated).
    pub omega_bar: Option<f64>,
}

/// The config with the command line's overrides applied, each within its
/// range (`analyze`'s and `sweep`'s).
pub fn overridden(path: &str, o: &Overrides) -> Result<config::Config, Failure> {
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
        cfg.overridden_by("[model] omega_bar", format!("--omega-bar {}", num(w)));
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

/// A design point's results: the library's, and the engineer's.
pub struct Results {
    pub result: CaseResult,
    /// The physical flight condition at the point's Mach number.
    pub flight: Option<(PhysicalFlight, FlightPoint)>,
    pub engineering: Engineering,
}

/// The design point evaluated, with its physical flight condition and the
/// engineer's outputs, every number finite, or the error at the field it
/// arises from (what `analyze` prints; the Python package raises the same).
pub fn results(cfg: &config::Config, o: &Options) -> Result<Results, Failure> {
    let flight = match &cfg.physical {
        Some(p) => {
            let point = p
                .flight
                .at_mach(cfg.case.mach)
                .map_err(|e| cfg.error_at("[flight] mach", e.to_string()))?;
            Some((p.flight, point))
        }
        None => None,
    };
    let result = evaluate(&cfg.case).map_err(|e| cfg.explain(&e))?;
    let control = crate::state_space::read_control(&cfg.path, cfg.text())?;
    let tau = flight.map(|(_, p)| p.tau);
    let engineering = Engineering::of_report(
        &result.derivatives,
        &result.analysis,
        tau,
        control.as_ref(),
        o.class,
    );
    match engineering {
        Ok(engineering) if crate::cmd::quartic::is_finite(&result.analysis) => Ok(Results {
            result,
            flight,
            engineering,
        }),
        _ => Err(cfg
            .error_at(
                "[flight]",
                "the analysis overflows f64: no result can be written",
            )
            .into()),
    }
}

pub fn run(path: &str, o: &Overrides, options: &Options) -> Result<(), Failure> {
    let cfg = overridden(path, o)?;
    let res = results(&cfg, options)?;
    for w in &res.result.warnings {
        crate::output::warn(&format!("warning: {w}"));
    }
    if let Some(out) = &options.state_space {
        let tau = res.flight.map(|(_, p)| p.tau);
        let roots = res.result.analysis.roots;
        crate::state_space::write(
            out,
            &crate::state_space::Export {
                source: path,
                command: "analyze",
                model: &res.engineering.model,
                tau,
                eigenvalues: tau.map_or(roots, |t| roots.map(|z| z / t)),
            },
        )?;
    }
    if options.json {
        print(&format!(
            "{}\n",
            serde_json::to_string_pretty(&to_json(&cfg, &res)).unwrap_or_default()
        ))?;
    } else {
        print(&page(&cfg, &res))?;
    }
    Ok(())
}

/// The `analyze --json` object: the config's path, the physical flight
/// condition when there is one, the design point as the library
/// serializes it and the engineer's outputs (`damp`, `mode_shapes`,
/// `short_period_frequency`).
#[derive(Serialize)]
pub struct AnalyzeJson<'a> {
    file: &'a str,
    #[serde(skip_serializing_if = "Option::is_none")]
    flight: Option<FlightJson>,
    #[serde(flatten)]
    point: CaseView<'a>,
    #[serde(flatten)]
    engineering: &'a Engineering,
}

pub fn to_json<'a>(cfg: &'a config::Config, res: &'a Results) -> AnalyzeJson<'a> {
    AnalyzeJson {
        file: &cfg.path,
        flight: res.flight.map(|(f, p)| f.json(&p)),
        point: res
            .result
            .view_timed(&cfg.case, res.flight.map(|(_, p)| p.tau)),
        engineering: &res.engineering,
    }
}

pub fn page(cfg: &config::Config, res: &Results) -> String {
    let r = &res.result;
    let mut s = String::new();
    let _ = writeln!(s, "Design point of {}", cfg.path);
    design_point(&mut s, cfg, r);
    if let Some((f, p)) = &res.flight {
        physical(&mut s, f, p);
    }
    derivatives(&mut s, &r.derivatives);
    s.push_str(&analysis_page(
        "The stability quartic (eqs 4–6):",
        &r.analysis,
        res.flight.map(|(_, p)| p.tau),
    ));
    if let Some(f) = &res.engineering.short_period_frequency {
        let _ = writeln!(s, "{}", crate::engineering::frequency_line(f));
    }
    let lift_slope = r.coefficients.lift_slope.value;
    let m = Margins::of(&r.analysis.quartic, &r.derivatives, lift_slope);
    let _ = writeln!(
        s,
        "Margins (§9): static K_n = {} (eq 42), manoeuvre H_m = {}",
        m.static_margin.map_or("—".into(), |x| sig(x, 4)),
        m.manoeuvre_margin.map_or("—".into(), |x| sig(x, 4))
    );
    s.push_str(&crate::engineering::tables(&res.engineering));
    s
}

/// The physical flight condition and what it gives (§3, eq 24).
fn physical(s: &mut String, f: &PhysicalFlight, p: &FlightPoint) {
    use stability_core::flight::Altitude;
    let u = f.units;
    let (len, mass, force) = u.symbols();
    let l = u.length();
    let air = match (f.altitude, f.atmosphere) {
        (Some(Altitude::Pressure(h)), Some(_)) => {
            format!(
                "pressure altitude {} {len}, 1976 standard atmosphere",
                sig(h, 6)
            )
        }
        (Some(Altitude::Geometric(z)), Some(_)) => {
            format!(
                "geometric altitude {} {len}, 1976 standard atmosphere",
                sig(z, 6)
            )
        }
        _ => "ρ and a as given".to_string(),
    };
    let _ = writeln!(
        s,
        "  physical flight condition ({} units; {air}): ρ = {} kg/m³, a = {} m/s, V = M·a = {} m/s{}, ½ρV² = {} Pa",
        u.name(),
        sig(f.density, 5),
        sig(f.speed_of_sound, 5),
        sig(p.speed, 5),
        if l == 1.0 {
            String::new()
        } else {
            format!(" ({} {len}/s)", sig(p.speed / l, 5))
        },
        sig(p.dynamic_pressure, 5),
    );
    let _ = writeln!(
        s,
        "    m = {} {mass} (W = {} {force}), I_y = {} {mass}·{len}², S = {} {len}², c̄ = {} {len} (the planform's M.A.C.)",
        sig(f.mass / u.mass(), 5),
        sig(f.weight / u.force(), 5),
        sig(f.pitch_inertia / u.inertia(), 5),
        sig(f.area / (l * l), 5),
        sig(f.chord / l, 5),
    );
    let _ = writeln!(
        s,
        "    → μ₁ = m/(½ρSc̄) = {}, i_B = I_y/(mc̄²) = {}, C_L·M² = W/(½ρa²S) = {}, C_L = {}, τ = m/(½ρSV) = {} s",
        sig(f.mu1(), 5),
        sig(f.i_b(), 4),
        sig(f.cl_m2(), 4),
        sig(p.c_l, 4),
        sig(p.tau, 5),
    );
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
    } else if c.damping == DampingModel::Theory(Theory::LiftingSurface) {
        let _ = writeln!(
            s,
            "  frequency parameter: {}",
            c.omega_bar
                .map_or("quasi-steady (ω̄ → 0)".into(), |w| format!(
                    "ω̄ = {}",
                    sig(w, 4)
                ))
        );
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
