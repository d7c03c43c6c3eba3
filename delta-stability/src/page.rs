//! The analysis of a derivative set as a readable page (`quartic`,
//! `analyze`): the quartic's coefficients (eqs 4–6) and Routh's test (§4),
//! the modes (eq 8), the report's eq (7), the short-period approximation
//! and the damping standard (§8–9, eq 41), the MIL-F-8785C levels.

use stability_core::analysis::Analysis;
use stability_core::criteria::{Category, Verdict, phugoid_level, short_period_level};
use stability_core::display::sig;
use stability_core::modes::{Mode, Modes, Origin};
use std::fmt::Write;

/// A value to 4 significant digits, or "—" where it does not exist.
fn cell(v: Option<f64>) -> String {
    v.map_or("—".to_string(), |x| sig(x, 4))
}

/// The analysis as a readable page, under `title`; times also in seconds
/// when τ (s) is known.
pub fn analysis_page(title: &str, a: &Analysis, tau: Option<f64>) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{title}");
    coefficients(&mut s, a, tau);
    let _ = writeln!(
        s,
        "\nModes (times in τ{}):",
        if tau.is_some() {
            "; seconds and rad/s in brackets"
        } else {
            ""
        }
    );
    s.push_str(&modes_table(a, tau));
    classical(&mut s, a);
    standard(&mut s, a);
    levels(&mut s, a, tau);
    s
}

/// Eq (6)'s coefficients, Routh's discriminant and τ.
fn coefficients(s: &mut String, a: &Analysis, tau: Option<f64>) {
    let _ = writeln!(
        s,
        "  A λ⁴ + B λ³ + C λ² + D λ + E = 0,  λ in units of 1/τ, τ = m/(½ρSV)"
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
    if let Some(t) = tau {
        let _ = writeln!(s, "τ = {} s", sig(t, 5));
    }
}

/// A mode's name in the table: "short period", or "aperiodic (sp)" for a
/// root of a pair that split.
fn mode_name(m: &Mode) -> String {
    match m.origin {
        Some(o) if m.name.as_str() == "aperiodic" => format!(
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

/// One row of the modes table.
fn mode_row(m: &Mode, tau: Option<f64>) -> [String; 8] {
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
    [
        mode_name(m),
        root,
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

/// The modes as an aligned table (period, time to half or double amplitude,
/// cycles to half, ζ, ωₙ, ω̄).
fn modes_table(a: &Analysis, tau: Option<f64>) -> String {
    let header = [
        "mode",
        "root (1/τ)",
        "period",
        "t½ / t×2",
        "cycles ½",
        "ζ",
        "ωₙ (1/τ)",
        "ω̄",
    ];
    let mut rows: Vec<[String; 8]> = vec![header.map(String::from)];
    rows.extend(a.modes.iter().map(|m| mode_row(m, tau)));
    aligned(&rows)
}

/// Rows as an aligned table: the first column left-aligned, the others
/// right-aligned.
pub fn aligned<const N: usize>(rows: &[[String; N]]) -> String {
    let widths: Vec<usize> = (0..N)
        .map(|k| rows.iter().map(|r| r[k].chars().count()).max().unwrap_or(0))
        .collect();
    let mut s = String::new();
    for r in rows {
        let mut line = String::from(" ");
        for (k, c) in r.iter().enumerate() {
            let pad = " ".repeat(widths[k] - c.chars().count());
            if k == 0 {
                let _ = write!(line, " {c}{pad}");
            } else {
                let _ = write!(line, "  {pad}{c}");
            }
        }
        let _ = writeln!(s, "{line}");
    }
    s
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

/// The §8 verdict in words, with the cycles to half amplitude behind it.
pub fn verdict_text(a: &Analysis) -> String {
    verdict_words(a.verdict, &a.modes)
}

/// The §8 verdict on `modes` in words (the cycles to half amplitude are
/// dimensionless: the same in τ or in seconds).
pub fn verdict_words(verdict: Verdict, modes: &Modes) -> String {
    let sp = modes.short_period();
    let cycles = sp.and_then(|m| m.cycles_to_half);
    match (verdict, sp, cycles) {
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

/// The short-period approximation and the damping standard (§8–9, eq 41).
fn standard(s: &mut String, a: &Analysis) {
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
    let _ = writeln!(
        s,
        "Damping standard (§8: half amplitude within one cycle): {}",
        verdict_text(a)
    );
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
fn levels(s: &mut String, a: &Analysis, tau: Option<f64>) {
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
}
