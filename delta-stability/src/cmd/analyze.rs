//! `delta-stability analyze CONFIG [--json] [--state-space OUT.json]
//! [--write-derivatives OUT.toml]`: a
//! planform at a flight condition → derivatives (§5–7) → quartic (§4) →
//! modes → criteria (§8–9); with a physical flight condition
//! ([`stability_io::config::physical`]), μ₁, i_B, C_L and τ from it and the modes
//! in seconds too.

use crate::Failure;
use crate::output::print_as;
use crate::page::analysis_page;
use stability_core::Derivatives;
use stability_core::aerodynamics::damping::Theory;
use stability_core::aerodynamics::models::aero::{Coefficients, Origin};
use stability_core::aerodynamics::models::derivative_tables::Mode;
use stability_core::criteria::Margins;
use stability_core::design::case::{CaseResult, DampingModel, FrequencyIteration, FrequencyMethod};
use stability_core::design::flight::{FlightPoint, PhysicalFlight};
use stability_core::numerics::display::sig;
use stability_io::config::{self, Overrides, overridden};
use stability_io::design_point::{Results, results};
use stability_io::format::Format;
use stability_io::views::AnalyzeJson;
use std::fmt::Write;

use super::quartic::EngineeringArgs;
use crate::args::ModelArgs;

/// The command's options.
#[derive(Debug, Clone, clap::Args)]
pub struct Args {
    /// The design-point config (TOML).
    pub config: String,
    #[command(flatten)]
    pub model: ModelArgs,
    /// Override the Mach number.
    #[arg(long, value_parser = crate::args::finite)]
    pub mach: Option<f64>,
    /// Override the c.g. position h (fraction of the M.A.C.).
    #[arg(long, value_parser = crate::args::finite)]
    pub cg: Option<f64>,
    /// Print one JSON object (keys derivatives, coefficients, modes, criteria, mode_shapes, …; with a physical flight condition also flight, damp and short_period_frequency).
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub engineering: EngineeringArgs,
    /// Write the design point as a derivative file (report notation, with the physical flight condition as `[dimensional]` and the config's `[control]`; every number exact) that quartic, response, sensitivity and convert read.
    #[arg(long, value_name = "OUT.toml")]
    pub write_derivatives: Option<String>,
}

impl Args {
    /// The values that replace the config's.
    pub fn overrides(&self) -> Overrides {
        Overrides {
            mach: self.mach,
            cg: self.cg,
            ..self.model.overrides()
        }
    }
}

pub fn run(args: &Args) -> Result<(), Failure> {
    let (path, options) = (args.config.as_str(), &args.engineering);
    let (cfg, read) = stability_io::files::recording(|| overridden(path, &args.overrides()));
    let cfg = cfg?;
    let mut outputs = crate::overwrite::state_space(options.state_space.as_deref())?;
    if let Some(out) = &args.write_derivatives {
        outputs.push(crate::overwrite::Named::new("--write-derivatives", out));
    }
    crate::overwrite::refuse("CONFIG", path, &read, &outputs)?;
    let res = crate::output::while_running("solving the design point", || {
        results(&cfg, options.class())
    })?;
    for w in &res.result.warnings {
        crate::output::warn(&format!("warning: {w}"));
    }
    let view = AnalyzeJson::new(&cfg, &res);
    crate::output::finite(path, &view)?;
    if let Some(out) = &options.state_space {
        let tau = res.tau();
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
    if let Some(out) = &args.write_derivatives {
        write_derivatives(out, &cfg, &res)?;
    }
    print_as(Format::printed(args.json), path, &view, || {
        Ok(page(&cfg, &res))
    })
}

/// `--write-derivatives OUT.toml`: the design point as a derivative file
/// ([`stability_io::design_point::derivative_text`]), read back before it
/// is written, so that what is written is what the reader takes.
fn write_derivatives(out: &str, cfg: &config::Config, res: &Results) -> Result<(), Failure> {
    let made_by: Vec<String> = std::env::args().skip(1).collect();
    let made_by = format!("delta-stability {}", made_by.join(" "));
    let text = stability_io::design_point::derivative_text(cfg, res, &made_by);
    let back = stability_io::input::parse(out, &text)?;
    if back.derivatives != res.result.derivatives {
        let m = "--write-derivatives: the derivative file does not read back to the design point's set (a bug: please report it)";
        return Err(stability_io::diag::InputError::file(out, m).into());
    }
    crate::output::atomic_write(std::path::Path::new(out), text.as_bytes())
        .map_err(|e| stability_io::files::write_error(std::path::Path::new(out), &e))?;
    crate::output::warn(&format!("wrote the design point's derivatives to {out}"));
    Ok(())
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
    s.push_str(&super::quartic::frequency_line(
        &res.engineering,
        &res.class,
    ));
    margins(&mut s, &r.margins(&cfg.case), cfg.case.h);
    s.push_str(&crate::engineering::tables(&res.engineering));
    s
}

/// The §9 margins, and the neutral point and static margin with what
/// each means ([`stability_core::criteria::NeutralPoint`]).
fn margins(s: &mut String, m: &Margins, h: f64) {
    let or_dash = |v: Option<f64>, n| v.map_or("—".into(), |x| sig(x, n));
    let _ = writeln!(
        s,
        "Margins (§9): static K_n = {} (eq 42: −dC_m/dC_L at constant C_L·M², from E, with the Mach-number terms m_u), manoeuvre H_m = {}",
        or_dash(m.static_margin, 4),
        or_dash(m.manoeuvre_margin, 4)
    );
    let _ = writeln!(
        s,
        "  neutral point h_n = {} (m_w = 0 at constant speed: the aerodynamic centre), static margin h_n − h = {} % M.A.C. at h = {}",
        or_dash(m.neutral_point, 4),
        or_dash(m.static_margin_pct, 4),
        sig(h, 4)
    );
}

/// The physical flight condition and what it gives (§3, eq 24).
fn physical(s: &mut String, f: &PhysicalFlight, p: &FlightPoint) {
    use stability_core::design::flight::Altitude;
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
    aerodynamics(s, &r.coefficients, c.damping);
    for line in cfg.tables_summary() {
        let _ = writeln!(s, "  tables: {line}");
    }
    for t in &r.tables {
        let _ = writeln!(s, "    {}", t.describe());
    }
    // the damping four from value tables: the theory's are not used
    let tabled = ["z_q", "z_wdot", "m_q", "m_wdot"].iter().all(|n| {
        r.tables
            .iter()
            .any(|t| t.derivative == *n && t.table.is_some() && t.mode == Mode::Value)
    });
    let theory = format!(
        "{} {}",
        r.damping.theory.name(),
        r.damping.theory.equations()
    );
    let _ = writeln!(
        s,
        "  damping: {}; z_θ̇ = {}, m_θ̇ = {}",
        if tabled {
            format!("z_q, z_ẇ, m_q, m_ẇ from the tables (the theory {theory} not used)")
        } else {
            theory
        },
        sig(r.damping.derivatives.z_thetadot(), 4),
        sig(r.damping.derivatives.m_thetadot(), 4)
    );
    if let Some(shares) = &r.configuration {
        let _ = writeln!(
            s,
            "  configuration (§10; docs/configurations.md): {} — in the above, before any tables:",
            crate::configuration::summary(shares)
        );
        for line in crate::configuration::share_lines(shares) {
            let _ = writeln!(s, "    {line}");
        }
    }
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

/// The coefficients of §6, each with where it came from; a damping model
/// that supplies the lift slope and aerodynamic centre too says so.
fn aerodynamics(s: &mut String, a: &Coefficients, damping: DampingModel) {
    let o = &a.origin;
    let _ = writeln!(
        s,
        "  aerodynamics (§6): ∂C_L/∂α = {} (d/dM {}), C_D0 = {}, K = {}, H₀ = {}",
        sig(a.lift_slope.value, 4),
        sig(a.lift_slope.d_mach, 3),
        sig(a.zero_lift_drag.value, 3),
        sig(a.drag_due_to_lift.value, 3),
        sig(a.aerodynamic_centre.value, 3)
    );
    // the coefficients grouped by where they came from
    let named = [
        ("∂C_L/∂α", o.lift_slope),
        ("H₀", o.aerodynamic_centre),
        ("C_D0", o.zero_lift_drag),
        ("K", o.drag_due_to_lift),
    ];
    let mut groups: Vec<(Origin, Vec<&str>)> = Vec::new();
    for (name, origin) in named {
        match groups.iter_mut().find(|(o, _)| *o == origin) {
            Some((_, names)) => names.push(name),
            None => groups.push((origin, vec![name])),
        }
    }
    let from: Vec<String> = groups
        .iter()
        .map(|(o, names)| format!("{}: {}", names.join(", "), o.describe()))
        .collect();
    let _ = writeln!(s, "    from — {}", from.join("; "));
    if matches!(o.lift_slope, Origin::DampingModel(_)) {
        let _ = writeln!(
            s,
            "    (the damping model `{}` supplies the lift slope and aerodynamic centre as well as the damping derivatives; --aero lifting-surface, or lift_slope and aerodynamic_centre in [model.tables], take them from elsewhere)",
            damping.name()
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
    if f.method != FrequencyMethod::K {
        let _ = writeln!(
            s,
            "  roots by the {}: cycles to ½ {} (the k-method's above: {})",
            f.method.describe(),
            f.cycles_to_half.map_or("—".into(), |x| sig(x, 4)),
            f.cycles_to_half_converged.map_or("—".into(), |x| sig(x, 4)),
        );
    }
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
