//! A config's design point evaluated: the library's result (§5–9), its
//! physical flight condition at the point's Mach number, and the
//! engineer's outputs — every number finite, or the error at the field it
//! arises from. What `analyze` prints and the Python package's `analyze()`
//! returns.
//!
//! The design point is also a derivative file ([`derivative_text`]): its
//! fifteen quartic inputs in the report's notation (§3), the physical
//! flight condition as `[dimensional]` and the config's `[control]`, every
//! number in the shortest form that reads back to the same f64, so that
//! `quartic`, `response`, `sensitivity` and `convert` read the very set
//! `analyze` analysed ([`derivative_file`] is that reading).

use crate::Failure;
use crate::class::ClassChoice;
use crate::config::Config;
use crate::csv::exact as lit;
use crate::input::analysis::OVERFLOW;
use crate::input::rows::{C_L, DERIVATIVE_ROWS, I_B, MU};
use crate::input::{DerivativeFile, parse};
use stability_core::analysis::engineering::Engineering;
use stability_core::criteria::cap::AirplaneClass;
use stability_core::data::notation::Notation;
use stability_core::design::case::{CaseResult, evaluate};
use stability_core::design::flight::{FlightPoint, PhysicalFlight};
use stability_core::dynamics::linear::Control;
use stability_core::numerics::display::sig;
use std::fmt::Write;

/// A design point's results: the library's, and the engineer's.
pub struct Results {
    pub result: CaseResult,
    /// The physical flight condition at the point's Mach number.
    pub flight: Option<(PhysicalFlight, FlightPoint)>,
    pub engineering: Engineering,
    /// The config's `[control]`, when it has one.
    pub control: Option<Control>,
    /// The MIL-F-8785C class assessed, and where it came from.
    pub class: ClassChoice,
}

impl Results {
    /// τ = m/(½ρSV) in seconds, at a physical flight condition.
    pub fn tau(&self) -> Option<f64> {
        self.flight.map(|(_, p)| p.tau)
    }
}

/// The design point of `cfg` evaluated, with the short-period frequency
/// requirement of the class `given`, else the config's ([`ClassChoice`]).
pub fn results(cfg: &Config, given: Option<AirplaneClass>) -> Result<Results, Failure> {
    let class = ClassChoice::of(given, cfg.class);
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
    let control = crate::control::read_control(&cfg.path, cfg.text())?;
    let tau = flight.map(|(_, p)| p.tau);
    let engineering = Engineering::of_report(
        &result.derivatives,
        &result.analysis,
        tau,
        control.as_ref(),
        class.class,
    );
    match engineering {
        Ok(engineering) if result.analysis.is_finite() => Ok(Results {
            result,
            flight,
            engineering,
            control,
            class,
        }),
        _ => Err(cfg.error_at("[flight]", OVERFLOW).into()),
    }
}

/// The design point of `cfg` at Mach number `mach`, as `analyze --mach`
/// makes it (the Mach number within its range, every other value the
/// config's; at a physical flight condition V, C_L and τ at that Mach
/// number): one point of a design's report across Mach.
pub fn at_mach(cfg: &Config, mach: f64, class: Option<AirplaneClass>) -> Result<Results, Failure> {
    let mut cfg = cfg.clone();
    let mach = crate::config::Overrides {
        mach: Some(mach),
        ..Default::default()
    };
    crate::config::apply(&mut cfg, &mach)?;
    results(&cfg, class)
}

/// A line of a comment: control characters (a newline in a path) shown
/// as spaces, so that the comment cannot end early.
fn comment(s: &str) -> String {
    s.chars()
        .map(|c| if c.is_control() { ' ' } else { c })
        .collect()
}

/// Where the design point's roots are each at its own frequency (the
/// p-method), the header line saying that the file's constant derivatives
/// give the k-method's roots instead.
fn constant_derivatives_line(r: &stability_core::design::case::CaseResult) -> Option<String> {
    let f = r.frequency.as_ref()?;
    if f.method == stability_core::dynamics::p_method::FrequencyMethod::K {
        return None;
    }
    let cycles = |c: Option<f64>| c.map_or("—".to_string(), |x| sig(x, 4));
    Some(format!(
        "Constant derivatives, at the short period's ω̄ = {}: their quartic's roots are the k-method's (short period {} cycles to half amplitude); analyze's are the {} ({} cycles).",
        sig(f.converged, 6),
        cycles(f.cycles_to_half_converged),
        f.method.describe(),
        cycles(f.cycles_to_half),
    ))
}

/// The design point of `cfg` as a derivative file's text (report
/// notation), with a comment header naming the config (its path, size and
/// FNV-1a hash), the design point and `made_by` (the command that wrote
/// it). See the module's documentation.
pub fn derivative_text(cfg: &Config, res: &Results, made_by: &str) -> String {
    let (c, r, text) = (&cfg.case, &res.result, cfg.text());
    let mut s = String::new();
    let header = [
        format!(
            "The design point of {} as a derivative file (report notation, §3).",
            cfg.path
        ),
        format!(
            "Config: {} bytes, FNV-1a {:016x}; M = {}, h = {}, damping {}, dC_L/dalpha = {}.",
            text.len(),
            crate::files::fnv1a64(text.as_bytes()),
            lit(c.mach),
            lit(c.h),
            r.damping.theory.name(),
            sig(r.coefficients.lift_slope.value, 6),
        ),
        format!(
            "Written by `{}` (delta-stability {}).",
            made_by,
            crate::VERSION
        ),
        "Every number reads back to the value analyze used: quartic, response, sensitivity and convert read it.".into(),
    ];
    let mut header = header.to_vec();
    header.extend(constant_derivatives_line(r));
    for line in header {
        let _ = writeln!(s, "# {}", comment(&line));
    }
    s.push_str("notation = \"report\"\n\n[derivatives]\n");
    let d = &r.derivatives;
    let values = [
        d.x_u, d.x_w, d.x_wdot, d.x_q, d.z_u, d.z_w, d.z_wdot, d.z_q, d.m_u, d.m_w, d.m_wdot, d.m_q,
    ];
    for (name, v) in DERIVATIVE_ROWS.iter().zip(values) {
        let _ = writeln!(s, "{name} = {}", lit(v));
    }
    s.push_str("\n[flight]\n");
    for (row, v) in [(C_L, d.c_l), (MU, d.mu1), (I_B, d.i_b)] {
        let _ = writeln!(s, "{} = {}", Notation::REPORT.name_of(row), lit(v));
    }
    if let Some((f, p)) = &res.flight {
        let _ = writeln!(
            s,
            "\n[dimensional]      # the physical flight condition at M = {} (SI: V = M·a)",
            lit(c.mach)
        );
        for (name, v) in [
            ("V", p.speed),
            ("rho", f.density),
            ("S", f.area),
            ("chord", f.chord),
            ("mass", f.mass),
            ("I_y", f.pitch_inertia),
        ] {
            let _ = writeln!(s, "{name} = {}", lit(v));
        }
    }
    if let Some(k) = &res.control {
        let _ = writeln!(s, "\n[control]          # the config's, per radian");
        let _ = writeln!(s, "name = \"{}\"", k.name);
        for (name, v) in [
            ("C_xdelta", k.c_x),
            ("C_zdelta", k.c_z),
            ("C_mdelta", k.c_m),
        ] {
            let _ = writeln!(s, "{name} = {}", lit(v));
        }
    }
    s
}

/// The design point of `cfg` as the derivative file [`derivative_text`]
/// writes, read back by the derivative files' own reader, under the
/// config's path (an error about a value names the config as a whole: the
/// values are computed, not written in it).
pub fn derivative_file(cfg: &Config, res: &Results) -> Result<DerivativeFile, Failure> {
    let text = derivative_text(cfg, res, "delta-stability");
    let mut file = parse(&cfg.path, &text)?;
    file.origins.iter_mut().for_each(|o| *o = None);
    Ok(file)
}

/// What `response` and `sensitivity` read: a derivative file with its
/// `[control]`, or a config's design point as one ([`derivative_file`],
/// the config's warnings among the file's).
pub fn read_set(
    path: &str,
    class: Option<AirplaneClass>,
) -> Result<(DerivativeFile, Option<Control>), Failure> {
    let text = crate::files::read_input(std::path::Path::new(path))?;
    if !crate::config::is_config(&text) {
        let file = parse(path, &text)?;
        let control = crate::control::read_control(path, &text)?;
        return Ok((file, control));
    }
    let cfg = crate::config::parse(path, &text)?;
    let res = results(&cfg, class)?;
    let mut file = derivative_file(&cfg, &res)?;
    file.warnings
        .splice(0..0, res.result.warnings.iter().map(|w| w.to_string()));
    Ok((file, res.control))
}
