//! The three ways the roots take the air forces' frequency, side by side
//! on the note's wings (`docs/exact-root.md`): the k-method (the
//! derivatives at the short period's ω̄, in the quartic), p-k (each root
//! with real derivatives at its own ω̄) and the p-method (each root with the
//! air forces at its own complex frequency: the exact root of linear
//! theory, the default), by the default damping model
//! ([`stability_core::dynamics::p_method`]).

use stability_core::aerodynamics::lifting_surface::Harmonic;
use stability_core::design::case::{FrequencyMethod, evaluate_harmonic};
use stability_core::design::study::report_wing;

/// The marker of the table in `docs/exact-root.md`.
pub const METHODS_MARKER: &str = "methods";

/// The Mach numbers of the table.
const MACHS: [f64; 10] = [0.6, 0.9, 1.1, 1.2, 1.3, 1.42, 1.5, 1.7, 2.0, 2.5];

/// The note's two deltas.
const SWEEPS: [f64; 2] = [45.0, 60.0];

/// The short period's cycles to half amplitude (and ω̄) of the note's
/// deltas (μ₁ = 50, i_B = 0.08, h = 0.25) by each method, as a Markdown
/// table; "—" where the short period does not oscillate or the point
/// fails.
pub fn methods_table() -> String {
    let mut s = String::from(
        "| delta | M | k: cycles to ½ (ω̄) | p-k | p (exact) | p against k |\n| --- | --- | --- | --- | --- | --- |\n",
    );
    for deg in SWEEPS {
        for mach in MACHS {
            let at = |method| {
                let mut c = report_wing(deg, mach);
                c.frequency_method = method;
                let r = evaluate_harmonic(&c, Harmonic::Interpolated).ok()?;
                let sp = *r.analysis.modes.short_period()?;
                Some((sp.cycles_to_half?, sp.frequency_parameter?))
            };
            let [k, pk, p] = FrequencyMethod::ALL.map(at);
            let cell = |x: Option<(f64, f64)>| {
                x.map_or("—".to_string(), |(c, w)| format!("{c:.3} ({w:.3})"))
            };
            let change = match (k, p) {
                (Some((k, _)), Some((p, _))) => format!("{:+.0} %", 100.0 * (p / k - 1.0)),
                _ => "—".to_string(),
            };
            s.push_str(&format!(
                "| {deg}° | {mach} | {} | {} | {} | {change} |\n",
                cell(k),
                cell(pk),
                cell(p)
            ));
        }
    }
    s
}
