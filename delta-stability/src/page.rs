//! A derivative set's analysis as a readable page (`quartic`, `analyze`),
//! for every notation: the characteristic quartic (eqs 4–6, or eq D2) and
//! Routh's test (§4), the modes (eq 8) in the roots' unit and in seconds
//! where τ is known, the §8 verdict and the MIL-F-8785C levels; then what
//! the set's notation adds — the report's eq (7), short-period
//! approximation and eq (41), or a dimensional set's trim, its stability
//! axes and its report-notation equivalent. One set of helpers serves both.

use stability_core::analysis::verdict::Overall;
use stability_core::analysis::{Analysis, Characteristic, Timebase};
use stability_core::criteria::{DampingStandard, FlyingQualities, Verdict};
use stability_core::data::dimensional::analysis::InReportNotation;
use stability_core::data::dimensional::{Axes, DimensionalAnalysis, DimensionalModel, Units};
use stability_core::dynamics::modes::Mode;
use stability_core::numerics::display::sig;
use std::fmt::Write;

/// A value to 4 significant digits, or "—" where it does not exist.
pub fn cell(v: Option<f64>) -> String {
    v.map_or("—".to_string(), |x| sig(x, 4))
}

/// Rows of cells as an aligned table, two spaces between columns, the
/// first column left-aligned and the others right-aligned.
pub fn aligned<R: AsRef<[String]>>(rows: &[R]) -> String {
    let n = rows.iter().map(|r| r.as_ref().len()).max().unwrap_or(0);
    let widths: Vec<usize> = (0..n)
        .map(|k| {
            rows.iter()
                .filter_map(|r| r.as_ref().get(k))
                .map(|c| c.chars().count())
                .max()
                .unwrap_or(0)
        })
        .collect();
    let mut s = String::new();
    for r in rows {
        let mut line = String::from(" ");
        for (k, c) in r.as_ref().iter().enumerate() {
            let pad = " ".repeat(widths[k] - c.chars().count());
            if k == 0 {
                let _ = write!(line, " {c}{pad}");
            } else {
                let _ = write!(line, "  {pad}{c}");
            }
        }
        let _ = writeln!(s, "{}", line.trim_end());
    }
    s
}

/// The page of a derivative set in the report's notation, under `title`;
/// times also in seconds when τ (s) is known.
pub fn analysis_page(title: &str, a: &Analysis, tau: Option<f64>) -> String {
    let time = Timebase::Tau(tau);
    let mut s = String::new();
    let _ = writeln!(s, "{title}");
    characteristic(&mut s, a, time);
    modes(&mut s, a, time);
    overall(&mut s, a, time);
    classical(&mut s, a);
    approximation(&mut s, a);
    verdict(&mut s, a);
    eq41(&mut s, &a.damping_standard);
    levels(&mut s, &a.flying_qualities(time));
    s
}

/// The page of a `notation = "dimensional"` set, under `title`.
pub fn dimensional_page(title: &str, a: &DimensionalAnalysis) -> String {
    let time = a.timebase();
    let mut s = String::new();
    let _ = writeln!(s, "{title}");
    trim(&mut s, &a.model);
    characteristic(&mut s, a, time);
    if a.model.axes == Axes::Body {
        stability_axes(&mut s, &a.stability);
    }
    modes(&mut s, a, time);
    overall(&mut s, a, time);
    s.push('\n');
    verdict(&mut s, a);
    levels(&mut s, &a.flying_qualities);
    match &a.report {
        Some(r) => in_report_notation(&mut s, r, a.model.units),
        None => {
            let _ = writeln!(
                s,
                "\n(A [reference] table — chord, rho, S, mass or weight, I_y — adds the report's notation: τ, μ₁, i_B and eq (41)'s m_θ̇.)"
            );
        }
    }
    s
}

/// The unit of the roots, in words: `1/τ` or `1/s`.
fn rate_unit(time: Timebase) -> &'static str {
    match time {
        Timebase::Tau(_) => "1/τ",
        Timebase::Seconds(_) => "1/s",
    }
}

/// The quartic's coefficients, Routh's discriminant and (in τ units) τ.
fn characteristic(s: &mut String, c: &Characteristic, time: Timebase) {
    let polynomial = match time {
        Timebase::Tau(_) => "  A λ⁴ + B λ³ + C λ² + D λ + E = 0,  λ in units of 1/τ, τ = m/(½ρSV)",
        Timebase::Seconds(_) => {
            "\n  det(λE − A) = A λ⁴ + B λ³ + C λ² + D λ + E = 0,  λ in 1/s (eq D2; eq 4 is its special case)"
        }
    };
    let _ = writeln!(s, "{polynomial}");
    for (name, v) in ["A", "B", "C", "D", "E"].iter().zip(c.quartic.to_array()) {
        let _ = writeln!(s, "  {name} = {:>14}", sig(v, 7));
    }
    let _ = writeln!(
        s,
        "\nRouth (§4): R = BCD − AD² − B²E = {}: {}",
        sig(c.routh.discriminant, 6),
        if c.routh.stable {
            "stable (A…E and R all of one sign)"
        } else {
            "UNSTABLE"
        }
    );
    if let Timebase::Tau(Some(t)) = time {
        let _ = writeln!(s, "τ = {} s", sig(t, 5));
    }
}

/// The modes as an aligned table under its heading: period, time to half
/// or double amplitude, cycles to half, ζ, ωₙ, ω̄; in τ units with seconds
/// in brackets where τ is known, or in seconds.
fn modes(s: &mut String, c: &Characteristic, time: Timebase) {
    let heading = match time {
        Timebase::Tau(None) => "Modes (times in τ):",
        Timebase::Tau(Some(_)) => "Modes (times in τ; seconds and rad/s in brackets):",
        Timebase::Seconds(_) => "Modes (rates in 1/s, times in s):",
    };
    let _ = writeln!(s, "\n{heading}");
    let (t, w) = match time {
        Timebase::Tau(_) => ("", "ωₙ (1/τ)"),
        Timebase::Seconds(_) => (" (s)", "ωₙ (rad/s)"),
    };
    let header = [
        "mode".to_string(),
        format!("root ({})", rate_unit(time)),
        format!("period{t}"),
        format!("t½ / t×2{t}"),
        "cycles ½".to_string(),
        "ζ".to_string(),
        w.to_string(),
        "ω̄".to_string(),
    ];
    let mut rows: Vec<[String; 8]> = vec![header];
    let seconds = match time {
        Timebase::Tau(tau) => tau,
        Timebase::Seconds(_) => None,
    };
    rows.extend(c.modes.iter().map(|m| mode_row(m, seconds)));
    s.push_str(&aligned(&rows));
}

/// A root `r ± si` (or `r`).
pub fn root(re: f64, im: f64) -> String {
    if im > 0.0 {
        format!("{} ± {}i", sig(re, 5), sig(im, 5))
    } else {
        sig(re, 5)
    }
}

/// The time to half amplitude, or to double with `×2`.
pub fn half_or_double(m: &Mode) -> (Option<f64>, &'static str) {
    match (m.time_to_half, m.time_to_double) {
        (Some(t), _) => (Some(t), ""),
        (None, Some(t)) => (Some(t), " ×2"),
        _ => (None, ""),
    }
}

/// One row of the modes table; with τ (s), times and rates in seconds in
/// brackets too.
fn mode_row(m: &Mode, tau: Option<f64>) -> [String; 8] {
    let (t, tag) = half_or_double(m);
    let with_s = |x: Option<f64>| match (x, tau) {
        (Some(v), Some(tau)) => format!("{} ({} s)", sig(v, 4), sig(v * tau, 3)),
        _ => cell(x),
    };
    [
        m.label(),
        root(m.re, m.im),
        with_s(m.period),
        format!("{}{tag}", with_s(t)),
        cell(m.cycles_to_half.or(m.cycles_to_double.map(|c| -c))),
        cell(m.damping_ratio),
        match tau {
            Some(tau) => format!(
                "{} ({} rad/s)",
                sig(m.natural_frequency, 4),
                sig(m.natural_frequency / tau, 3)
            ),
            None => sig(m.natural_frequency, 4),
        },
        cell(m.frequency_parameter),
    ]
}

/// The report's eq (7) and its refinement, against the exact roots.
fn classical(s: &mut String, a: &Analysis) {
    let Some(c) = &a.classical else { return };
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

/// The §8 standard in words, with the cycles to half amplitude behind it
/// (dimensionless: the same in τ or in seconds). Met only where no mode
/// grows: a growing mode other than the short period is named instead.
pub fn verdict_text(c: &Characteristic) -> String {
    let sp = c.modes.short_period();
    let cycles = sp.and_then(|m| m.cycles_to_half);
    let overall = stability_core::analysis::verdict::overall(c);
    match (c.verdict, sp, cycles) {
        (Verdict::Meets, _, Some(n)) if overall == Verdict::Divergent => format!(
            "NOT MET: the aircraft diverges (the verdict above), though the short period alone halves in {} cycles",
            sig(n, 3)
        ),
        (Verdict::Meets, _, _) if overall != Verdict::Meets => {
            "NOT MET: another mode grows or is neutral (the verdict above)".into()
        }
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

/// The §8 standard's line.
fn verdict(s: &mut String, c: &Characteristic) {
    let _ = writeln!(
        s,
        "Damping standard (§8: the short period halves within one cycle, no mode grows): {}",
        verdict_text(c)
    );
}

/// The overall verdict, every root judged, and why.
fn overall(s: &mut String, c: &Characteristic, time: Timebase) {
    let o = Overall::of(c, time);
    let word = match o.overall {
        Verdict::Meets => "meets the standard",
        Verdict::Fails => "FAILS the standard",
        Verdict::Divergent => "DIVERGENT",
    };
    let _ = writeln!(
        s,
        "\nVerdict (every root): {word} — {}",
        o.reasons.join("; ")
    );
}

/// The short-period approximation (§8–9).
fn approximation(s: &mut String, a: &Analysis) {
    let sp = &a.short_period_approximation;
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
}

/// Eq (41): m_θ̇ against the one-cycle requirement.
fn eq41(s: &mut String, ds: &DampingStandard) {
    let _ = writeln!(
        s,
        "  eq (41): m_θ̇ = {}, m_θ̇max = {}, Δm_θ̇ = {} (exact second-order limit: {})",
        sig(ds.m_thetadot, 5),
        cell(ds.m_thetadot_max),
        cell(ds.margin),
        cell(ds.margin_exact)
    );
}

/// The MIL-F-8785C damping levels of the short period and the phugoid.
fn levels(s: &mut String, fq: &FlyingQualities) {
    if let Some(sp) = &fq.short_period {
        let _ = writeln!(
            s,
            "MIL-F-8785C short period, ζ = {}: Category A {}, B {}, C {}",
            sig(sp.damping_ratio, 3),
            sp.a.as_str(),
            sp.b.as_str(),
            sp.c.as_str()
        );
    }
    if let Some(ph) = &fq.phugoid {
        let _ = writeln!(
            s,
            "MIL-F-8785C phugoid, ζ = {}: {}",
            sig(ph.damping_ratio, 3),
            ph.level.as_str()
        );
    }
}

/// A dimensional set's units of speed and acceleration.
fn units_label(u: Units) -> (&'static str, &'static str) {
    match u {
        Units::Ft => ("ft/s", "ft/s²"),
        Units::Si => ("m/s", "m/s²"),
    }
}

/// A dimensional set's trim.
fn trim(s: &mut String, m: &DimensionalModel) {
    let t = &m.trim;
    let (v, acc) = units_label(m.units);
    let _ = writeln!(
        s,
        "  {} axes, units {}: U₀ = {} {v}, W₀ = {} {v} (V = {} {v}, α₀ = {}°), θ₀ = {}°, γ₀ = θ₀ − α₀ = {}°, g = {} {acc}",
        m.axes.as_str(),
        m.units.name(),
        sig(t.u0, 6),
        sig(t.w0, 5),
        sig(t.speed(), 6),
        sig(t.alpha0().to_degrees(), 4),
        sig(t.theta0.to_degrees(), 4),
        sig(t.gamma0().to_degrees(), 3),
        sig(t.g, 6)
    );
}

/// A body-axis set turned into stability axes (by α₀), u̇ terms included.
fn stability_axes(s: &mut String, st: &DimensionalModel) {
    let names = stability_core::data::dimensional::DimensionalDerivatives::NAMES;
    let values = st.derivatives.values();
    let cells: Vec<String> = names
        .iter()
        .zip(values)
        .filter(|(_, v)| *v != 0.0)
        .map(|(n, v)| format!("{n} = {}", sig(v, 4)))
        .collect();
    let _ = writeln!(
        s,
        "\nIn stability axes (turned by α₀; the modes are the same): U₀ = {}, θ₀ = γ₀ = {}°;\n  {}",
        sig(st.trim.u0, 6),
        sig(st.trim.theta0.to_degrees(), 3),
        cells.join(", ")
    );
}

/// A dimensional set in the report's notation, with eq (41).
fn in_report_notation(s: &mut String, r: &InReportNotation, units: Units) {
    let e = &r.equivalent;
    let d = &e.derivatives;
    let _ = writeln!(
        s,
        "\nIn the report's notation (§3; τ = μ₁c̄/V = {} s, μ₁ = {}, i_B = {}, c̄ = {} {}, C_L = gτ/V = {}):",
        sig(e.tau, 5),
        sig(d.mu1, 5),
        sig(d.i_b, 4),
        sig(r.reference.chord, 5),
        units.symbols().0,
        sig(d.c_l, 4)
    );
    let names = stability_core::Derivatives::QUARTIC_INPUTS;
    let cells: Vec<String> = names[..12]
        .iter()
        .zip(d.quartic_input_values())
        .map(|(n, v)| format!("{n} = {}", sig(v, 4)))
        .collect();
    let _ = writeln!(s, "  {}", cells.join(", "));
    if !e.is_exact() {
        let _ = writeln!(
            s,
            "  (inexact: eq (4) cannot hold X_u̇ = {}, Z_u̇ = {}, M_u̇ = {}, γ₀ = {}° of the stability-axis set; the modes above are the exact ones)",
            sig(e.dropped.x_udot, 3),
            sig(e.dropped.z_udot, 3),
            sig(e.dropped.m_udot, 3),
            sig(e.dropped.gamma0.to_degrees(), 3)
        );
    }
    eq41(s, &r.damping_standard);
}
