//! The analysis of a `notation = "dimensional"` set as a readable page
//! (`quartic`): the trim, the general quartic det(λE − A) (eq D2) and
//! Routh's test (§4), the set in stability axes, the modes in 1/s and
//! seconds (eq 8), the §8 verdict, the MIL-F-8785C levels and, with a
//! `[reference]`, the set in the report's notation with eq (41).

use crate::page::{aligned, verdict_words};
use stability_core::dimensional::analysis::InReportNotation;
use stability_core::dimensional::{Axes, DimensionalAnalysis, DimensionalModel, Units};
use stability_core::display::sig;
use stability_core::modes::{Mode, ModeName, Origin};
use std::fmt::Write;

/// A value to 4 significant digits, or "—" where it does not exist.
fn cell(v: Option<f64>) -> String {
    v.map_or("—".to_string(), |x| sig(x, 4))
}

/// The page, under `title`.
pub fn page(title: &str, a: &DimensionalAnalysis) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{title}");
    trim(&mut s, &a.model);
    coefficients(&mut s, a);
    if a.model.axes == Axes::Body {
        stability_axes(&mut s, &a.stability);
    }
    let _ = writeln!(s, "\nModes (rates in 1/s, times in s):");
    s.push_str(&modes_table(a));
    let _ = writeln!(
        s,
        "\nDamping standard (§8: half amplitude within one cycle): {}",
        verdict_words(a.verdict, &a.modes)
    );
    levels(&mut s, a);
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

fn units_label(u: Units) -> (&'static str, &'static str) {
    match u {
        Units::Ft => ("ft/s", "ft/s²"),
        Units::Si => ("m/s", "m/s²"),
    }
}

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

fn coefficients(s: &mut String, a: &DimensionalAnalysis) {
    let _ = writeln!(
        s,
        "\n  det(λE − A) = A λ⁴ + B λ³ + C λ² + D λ + E = 0,  λ in 1/s (eq D2; eq 4 is its special case)"
    );
    for (name, v) in ["A", "B", "C", "D", "E"].iter().zip(a.quartic.to_array()) {
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
}

/// The set turned into stability axes (by α₀), u̇ terms included.
fn stability_axes(s: &mut String, st: &DimensionalModel) {
    let names = stability_core::dimensional::DimensionalDerivatives::NAMES;
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

fn mode_name(m: &Mode) -> String {
    match (m.name, m.origin) {
        (ModeName::Aperiodic, Some(o)) => format!(
            "aperiodic ({})",
            match o {
                Origin::ShortPeriod => "sp",
                Origin::Phugoid => "ph",
                Origin::Unknown => "?",
            }
        ),
        _ => m.name.as_str().replace('_', " "),
    }
}

fn mode_row(m: &Mode) -> [String; 8] {
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
    [
        mode_name(m),
        root,
        cell(m.period),
        format!("{}{tag}", cell(t)),
        cell(m.cycles_to_half.or(m.cycles_to_double.map(|c| -c))),
        cell(m.damping_ratio),
        sig(m.natural_frequency, 4),
        cell(m.frequency_parameter),
    ]
}

fn modes_table(a: &DimensionalAnalysis) -> String {
    let header = [
        "mode",
        "root (1/s)",
        "period (s)",
        "t½ / t×2 (s)",
        "cycles ½",
        "ζ",
        "ωₙ (rad/s)",
        "ω̄",
    ];
    let mut rows: Vec<[String; 8]> = vec![header.map(String::from)];
    rows.extend(a.modes.iter().map(mode_row));
    aligned(&rows)
}

fn levels(s: &mut String, a: &DimensionalAnalysis) {
    let fq = &a.flying_qualities;
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
    let ds = &r.damping_standard;
    let _ = writeln!(
        s,
        "  eq (41): m_θ̇ = {}, m_θ̇max = {}, Δm_θ̇ = {} (exact second-order limit: {})",
        sig(ds.m_thetadot, 5),
        cell(ds.m_thetadot_max),
        cell(ds.margin),
        cell(ds.margin_exact)
    );
}
