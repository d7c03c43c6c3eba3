//! The engineer's part of a page (`quartic`, `analyze`): the MIL-F-8785C
//! short-period frequency requirement, the `damp()` table in seconds and
//! the mode shapes, from the library's [`Engineering`].

use crate::page::{aligned, half_or_double, root};
use stability_core::analysis::engineering::Engineering;
use stability_core::criteria::cap::ShortPeriodFrequency;
use stability_core::dynamics::damp::Damp;
use stability_core::dynamics::linear::TimeUnit;
use stability_core::dynamics::mode_shape::ModeShape;
use stability_core::dynamics::modes::Mode;
use stability_core::numerics::display::sig;
use std::fmt::Write;

fn cell(v: Option<f64>, digits: usize) -> String {
    v.map_or("—".into(), |x| sig(x, digits))
}

fn damp_row(m: &Mode) -> Vec<String> {
    let (t, tag) = half_or_double(m);
    vec![
        m.label(),
        root(m.re, m.im),
        cell(m.damping_ratio, 4),
        sig(m.natural_frequency, 4),
        cell(m.period, 4),
        format!("{}{tag}", cell(t, 4)),
        cell(m.cycles_to_half.or(m.cycles_to_double.map(|c| -c)), 4),
    ]
}

/// The `damp()` table: one row per mode, in seconds.
pub fn damp_table(d: &Damp) -> String {
    let header = [
        "mode",
        "eigenvalue (1/s)",
        "ζ",
        "ωₙ (rad/s)",
        "period (s)",
        "t½ / t×2 (s)",
        "cycles ½",
    ];
    let mut rows = vec![header.map(String::from).to_vec()];
    rows.extend(d.modes().iter().map(damp_row));
    aligned(&rows)
}

/// The mode shapes: each state's magnitude and phase relative to θ.
pub fn mode_shapes_table(shapes: &[ModeShape], time: TimeUnit) -> String {
    let q = match time {
        TimeUnit::Seconds => "|q| (rad/s)",
        TimeUnit::Tau => "|q̂| (1/τ)",
    };
    let header = ["mode", "|u/V|", "∠u/V", "|α|", "∠α", q, "∠q", "|θ|", "∠θ"];
    let mut rows = vec![header.map(String::from).to_vec()];
    for m in shapes {
        let mut row = vec![m.name.label(m.origin)];
        for c in m.components() {
            row.push(sig(c.magnitude, 4));
            row.push(format!("{:.1}°", c.phase_deg));
        }
        rows.push(row);
    }
    aligned(&rows)
}

/// §3.2.2.1.1 in a line, with the class assessed (`class`, in words).
pub fn frequency_line(f: &ShortPeriodFrequency, class: &str) -> String {
    format!(
        "MIL-F-8785C short-period frequency (§3.2.2.1.1), ω_sp = {} rad/s, n/α = {} g/rad, CAP = ω_sp²/(n/α) = {} 1/(g·s²): Category A {}, B {}, C {} ({class})",
        sig(f.natural_frequency_rad_s, 4),
        sig(f.n_alpha, 4),
        sig(f.cap, 3),
        f.a.as_str(),
        f.b.as_str(),
        f.c.map_or("not assessed", |l| l.as_str()),
    )
}

/// The damp table and the mode shapes, under their headings.
pub fn tables(e: &Engineering) -> String {
    let mut s = String::new();
    if let Some(d) = &e.damp {
        let _ = writeln!(s, "\ndamp(): the modes in seconds");
        s.push_str(&damp_table(d));
    }
    if !e.mode_shapes.is_empty() {
        let q = match e.model.time {
            TimeUnit::Seconds => "q in rad/s per rad of θ",
            TimeUnit::Tau => "q̂ = dθ/dt̂ in 1/τ per rad of θ",
        };
        let _ = writeln!(
            s,
            "\nMode shapes (eigenvectors relative to θ, as Etkin & Reid §6.2 show them; phase in degrees, + leads θ; {q}):"
        );
        s.push_str(&mode_shapes_table(&e.mode_shapes, e.model.time));
    }
    s
}
