//! A design report's §10 section, for a config with a tailplane,
//! foreplane or body: the parts as given, and at each Mach number each
//! part's share of the lift slope, the aerodynamic centre and the damping
//! in pitch m_θ̇ = m_q + m_ẇ (docs/configurations.md).

use super::Design;
use stability_core::geometry::configuration::Configuration;
use stability_core::geometry::configuration::Surface;
use stability_core::numerics::display::sig;
use std::fmt::Write;

/// The section's HTML (empty without a configuration).
pub fn section(d: &Design) -> String {
    let Some(c) = &d.cfg.configuration else {
        return String::new();
    };
    let mut s = format!(
        "<h2 id=\"configuration\">§10 The surfaces and body</h2><p>The note's §10: damping \"can be made by the addition of a forebody, foreplane, or tailplane\". Each part's increment over the wing is added to the wing's own model at the wing's own frequency (docs/configurations.md): {}.</p><ul>",
        d.cfg.case.damping.increment_methods(c)
    );
    for surface in c.surfaces() {
        s.push_str(&surface_item(c, surface, d.cfg.case.h));
    }
    if let Some(b) = &c.body {
        let _ = write!(
            s,
            "<li>body (eq 43): {} ahead of the wing's apex, base diameter {}</li>",
            sig(b.length_ahead, 4),
            sig(b.diameter, 4)
        );
    }
    s.push_str("</ul>");
    s.push_str(&table(d));
    s
}

/// One surface in words: area, ratio, position and tail volume.
fn surface_item(c: &Configuration, t: &Surface, h: f64) -> String {
    let w = &c.wing;
    let quarter = t.x + t.shape.x_mac() + 0.25 * t.shape.mac();
    let cg = w.x_mac() + h * w.mac();
    let volume = t.shape.area() * (quarter - cg) / (w.area() * w.mac());
    format!(
        "<li>{}: area {} (S_T/S = {}), Λ = {}°, taper {}, apex {} aft of the wing's, {} above its plane; V̄ = S_T·l/(S·c̄) = {} at h = {}</li>",
        t.kind.name(),
        sig(t.shape.area(), 4),
        sig(t.shape.area() / w.area(), 3),
        sig(t.shape.sweep_le.to_degrees(), 3),
        sig(t.shape.taper(), 3),
        sig(t.x, 4),
        sig(t.z, 3),
        sig(volume, 3),
        sig(h, 3)
    )
}

/// Each Mach number's shares: per part ∂C_L/∂α, its H₀ term and m_θ̇.
fn table(d: &Design) -> String {
    let mut s = String::from(
        "<div class=\"scroll\"><table><tr><th>M</th><th>part</th><th>∂C_L/∂α</th><th>H₀ term</th><th>m_q</th><th>m_ẇ</th><th>m_θ̇</th><th>H₀ shift (all parts)</th></tr>\n",
    );
    for (m, r) in d.results() {
        let Some(sh) = &r.result.configuration else {
            continue;
        };
        for (k, p) in sh.parts.iter().enumerate() {
            let shift = if k == 0 {
                sig(sh.aerodynamic_centre_shift, 3)
            } else {
                String::new()
            };
            let name = serde_json::to_value(p.part)
                .ok()
                .and_then(|v| v.as_str().map(str::to_string))
                .unwrap_or_default();
            let _ = writeln!(
                s,
                "<tr><td>{}</td><td>{name}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{shift}</td></tr>",
                if k == 0 { sig(m, 3) } else { String::new() },
                sig(p.lift_slope, 4),
                sig(p.aerodynamic_centre, 3),
                sig(p.m_q, 4),
                sig(p.m_wdot, 4),
                sig(p.m_q + p.m_wdot, 4)
            );
        }
    }
    s.push_str("</table></div>\n");
    s
}
