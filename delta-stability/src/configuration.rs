//! A configuration's parts on a page (`analyze`, the design report's §10):
//! each part's share of the lift slope, aerodynamic centre and damping
//! derivatives ([`Shares`], docs/configurations.md).

use stability_core::design::shares::Shares;
use stability_core::numerics::display::sig;

/// The parts' shares as lines of a table, the header first and the totals
/// last.
pub fn share_lines(s: &Shares) -> Vec<String> {
    let mut out = vec![format!(
        "{:<10} {:>10} {:>10} {:>10} {:>10} {:>10} {:>10}",
        "part", "∂C_L/∂α", "H₀ term", "z_q", "m_q", "z_ẇ", "m_ẇ"
    )];
    let row = |name: &str, v: [f64; 6]| {
        format!(
            "{:<10} {:>10} {:>10} {:>10} {:>10} {:>10} {:>10}",
            name,
            sig(v[0], 4),
            sig(v[1], 4),
            sig(v[2], 4),
            sig(v[3], 4),
            sig(v[4], 4),
            sig(v[5], 4)
        )
    };
    for p in &s.parts {
        let name = serde_json::to_value(p.part)
            .ok()
            .and_then(|v| v.as_str().map(str::to_string))
            .unwrap_or_default();
        out.push(row(
            &name,
            [
                p.lift_slope,
                p.aerodynamic_centre,
                p.z_q,
                p.m_q,
                p.z_wdot,
                p.m_wdot,
            ],
        ));
    }
    out.push(row(
        "total",
        [
            s.lift_slope,
            s.aerodynamic_centre,
            s.z_q,
            s.m_q,
            s.z_wdot,
            s.m_wdot,
        ],
    ));
    out
}

/// The one-line summary: the aerodynamic centre's shift and m_θ̇'s change.
pub fn summary(s: &Shares) -> String {
    let wing = s.parts.first();
    let dm = wing.map_or(0.0, |w| (s.m_q + s.m_wdot) - (w.m_q + w.m_wdot));
    format!(
        "the surfaces and body move the aerodynamic centre {} M.A.C. aft and change m_θ̇ by {}",
        sig(s.aerodynamic_centre_shift, 3),
        sig(dm, 4)
    )
}
