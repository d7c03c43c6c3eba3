//! `[tailplane]`, `[foreplane]` and `[body]`: the configuration's parts
//! beside the wing (docs/configurations.md).
//!
//! ```toml
//! [tailplane]            # and/or [foreplane]: [planform]'s keys …
//! sweep = 45.0           # leading-edge sweep, degrees
//! taper = 0.3
//! span = 8.0             # one size: root_chord, span or area
//! x = 16.0               # … and its apex (the leading edge of its root chord)
//!                        # aft of the wing's apex, in the config's length unit (negative: ahead)
//! z = 0.5                # height above the wing's plane, up positive (default 0)
//! incidence = -1.0       # degrees relative to the wing (default 0; trim only)
//!
//! [body]                 # eq (43)'s forebody (Munk's slender body)
//! length_ahead = 6.0     # its length ahead of the wing's apex
//! diameter = 2.0         # its base diameter
//! ```

use super::Reader;
use super::raw::{RawBody, RawConfig, RawSurface};
use crate::diag::InputError;
use crate::limits::{self, Limit};
use stability_core::geometry::configuration::Body;
use stability_core::geometry::configuration::Configuration;
use stability_core::geometry::configuration::Surface;
use stability_core::geometry::configuration::SurfaceKind;
use stability_core::geometry::{Planform, Trapezoid};
use toml::Spanned;

/// Any finite position (in the config's length unit).
const POSITION: Limit = Limit {
    what: "the position",
    lo: -1e9,
    hi: 1e9,
    lo_included: true,
};

/// A surface's incidence relative to the wing, degrees.
const INCIDENCE: Limit = Limit {
    what: "the incidence (degrees)",
    lo: -45.0,
    hi: 45.0,
    lo_included: true,
};

/// The configuration the config's `[tailplane]`, `[foreplane]` and
/// `[body]` give with the wing `wing`; `None` if it gives none of them.
pub(super) fn configuration(
    r: &mut Reader<'_>,
    raw: &RawConfig,
    wing: &Planform,
) -> Result<Option<Configuration>, InputError> {
    if raw.tailplane.is_none() && raw.foreplane.is_none() && raw.body.is_none() {
        return Ok(None);
    }
    let mut c = Configuration::wing_alone(Trapezoid::from(wing));
    if let Some(t) = &raw.tailplane {
        c.tailplane = Some(surface(r, t, SurfaceKind::Tailplane)?);
    }
    if let Some(f) = &raw.foreplane {
        c.foreplane = Some(surface(r, f, SurfaceKind::Foreplane)?);
    }
    if let Some(b) = &raw.body {
        r.spans.push(("[body]".into(), b.span()));
        c.body = Some(body(r, b.get_ref())?);
    }
    Ok(Some(c))
}

/// One surface from its table.
fn surface(
    r: &mut Reader<'_>,
    s: &Spanned<RawSurface>,
    kind: SurfaceKind,
) -> Result<Surface, InputError> {
    let section = format!("[{}]", kind.name());
    r.spans.push((section.clone(), s.span()));
    let raw = s.get_ref();
    let shape = super::planform_in(r, &raw.planform(), s.span(), &section)?;
    let x = r.value(&raw.x, &format!("{section} x"), &POSITION)?;
    let z = match &raw.z {
        Some(z) => r.value(z, &format!("{section} z"), &POSITION)?,
        None => 0.0,
    };
    let incidence = match &raw.incidence {
        Some(i) => r.value(i, &format!("{section} incidence"), &INCIDENCE)?,
        None => 0.0,
    };
    if kind == SurfaceKind::Tailplane && x <= 0.0 {
        let m = format!(
            "a tailplane's apex lies aft of the wing's apex (x > 0, in the config's length unit), not at x = {x}; a surface ahead is a [foreplane]"
        );
        return Err(r.err_field(&format!("{section} x"), m));
    }
    if kind == SurfaceKind::Foreplane && x >= 0.0 {
        let m = format!(
            "a foreplane's apex lies ahead of the wing's apex (x < 0, in the config's length unit), not at x = {x}; a surface aft is a [tailplane]"
        );
        return Err(r.err_field(&format!("{section} x"), m));
    }
    Ok(Surface {
        kind,
        shape: Trapezoid::from(&shape),
        x,
        z,
        incidence: incidence.to_radians(),
    })
}

/// `[body]`.
fn body(r: &mut Reader<'_>, b: &RawBody) -> Result<Body, InputError> {
    Ok(Body {
        length_ahead: r.value(&b.length_ahead, "[body] length_ahead", &limits::SIZE)?,
        diameter: r.value(&b.diameter, "[body] diameter", &limits::SIZE)?,
    })
}

#[cfg(test)]
mod tests {
    const BASE: &str = "[planform]\nsweep = 45.0\nroot_chord = 10.0\n[flight]\nmach = 1.5\ncg = 0.25\nmu1 = 50.0\ni_b = 0.08\ncl_m2 = 0.05\n";

    fn error(extra: &str) -> String {
        crate::config::parse("c.toml", &format!("{BASE}{extra}"))
            .unwrap_err()
            .to_string()
    }

    #[test]
    fn surfaces_and_body_are_read_in_the_configs_unit() {
        let c = crate::config::parse(
            "c.toml",
            &format!(
                "{BASE}[tailplane]\nsweep = 45.0\ntaper = 0.2\nroot_chord = 4.0\nx = 12.0\nz = 0.5\nincidence = -2.0\n[foreplane]\nsweep = 60.0\narea = 1.0\nx = -5.0\n[body]\nlength_ahead = 8.0\ndiameter = 1.5\n"
            ),
        )
        .unwrap();
        let k = c.configuration.as_ref().unwrap();
        let t = k.tailplane.unwrap();
        // a cropped 45° delta of c₀ = 4, λ = 0.2: semi-span c₀(1 − λ)/tan 45° = 3.2
        assert_eq!((t.shape.root_chord, t.x, t.z), (4.0, 12.0, 0.5));
        assert!((t.shape.tip_chord - 0.8).abs() < 1e-12);
        assert!((t.shape.semi_span - 3.2).abs() < 1e-12);
        assert!((t.incidence + 2f64.to_radians()).abs() < 1e-15);
        let f = k.foreplane.unwrap();
        assert!((f.shape.area() - 1.0).abs() < 1e-12);
        assert_eq!(k.body.unwrap().diameter, 1.5);
        assert_eq!(c.case.aero.configuration.as_deref(), Some(k));
        assert_eq!(c.tables.configuration.as_deref(), Some(k));
        assert!((k.wing.root_chord - 10.0).abs() < 1e-12);
    }

    #[test]
    fn errors_name_the_line_and_field_and_say_what_to_do() {
        let e = error("[tailplane]\nsweep = 45.0\nroot_chord = 2.0\nx = -3.0\n");
        assert!(
            e.starts_with("c.toml:13:") && e.contains("[tailplane] x"),
            "{e}"
        );
        assert!(e.contains("a surface ahead is a [foreplane]"), "{e}");
        let e = error("[foreplane]\nsweep = 45.0\nroot_chord = 2.0\nx = 3.0\n");
        assert!(
            e.contains("[foreplane] x") && e.contains("[tailplane]"),
            "{e}"
        );
        let e = error("[tailplane]\nsweep = 45.0\nroot_chord = 2.0\nspan = 3.0\nx = 3.0\n");
        assert!(
            e.contains("[tailplane] span") && e.contains("only one size"),
            "{e}"
        );
        let e = error("[tailplane]\nsweep = 95.0\nroot_chord = 2.0\nx = 3.0\n");
        assert!(
            e.starts_with("c.toml:11:") && e.contains("[tailplane] sweep"),
            "{e}"
        );
        let e = error("[body]\nlength_ahead = 8.0\ndiameter = -1.0\n");
        assert!(
            e.contains("[body] diameter") && e.contains("positive"),
            "{e}"
        );
        let e = error("[tailplane]\nsweep = 45.0\nroot_chord = 2.0\nx = 3.0\nheight = 1.0\n");
        assert!(e.contains("height"), "{e}");
    }
}
