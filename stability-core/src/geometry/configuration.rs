//! Configurations (§10): the wing with a tailplane, a foreplane (either or
//! both) and a body — the note's ways to improve the damping: "the
//! addition of a forebody, foreplane, or tailplane or by cropping the wing
//! tips".
//!
//! A configuration's aerodynamics come as the lattice's [`Solution`](crate::aerodynamics::lifting_surface::Solution) (the
//! response to incidence and to pitch rate, moments about the wing M.A.C.'s
//! leading edge), for the whole configuration and for each part, so that
//! every derivative follows about any c.g. by the same axis transfer
//! ([`Solution::derivatives`](crate::aerodynamics::lifting_surface::Solution::derivatives)). Everything stays on the wing's area S and
//! M.A.C. c̄, and h stays the c.g. on the wing's M.A.C.
//!
//! - subsonic: one doublet lattice over all the surfaces ([`configuration`](crate::aerodynamics::lifting_surface::configuration));
//! - supersonic: each surface by the program's theories with the wing's
//!   downwash at the tailplane and its lag ([`supersonic::configuration`](crate::aerodynamics::supersonic::configuration)).

use crate::geometry::Trapezoid;
use serde::Serialize;

/// A lifting surface of a configuration beside the wing.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum SurfaceKind {
    Tailplane,
    Foreplane,
}

impl SurfaceKind {
    /// Its name in configs and in the output (`tailplane`, `foreplane`).
    pub fn name(self) -> &'static str {
        match self {
            SurfaceKind::Tailplane => "tailplane",
            SurfaceKind::Foreplane => "foreplane",
        }
    }
}

/// A straight-tapered surface placed relative to the wing. Lengths are in
/// the unit of the wing's [`Trapezoid`] (the config's length unit).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Surface {
    pub kind: SurfaceKind,
    /// Its planform (root chord, tip chord, semi-span, leading-edge sweep).
    pub shape: Trapezoid,
    /// Its apex (the leading edge of its root chord) aft of the wing's
    /// apex; negative ahead.
    pub x: f64,
    /// Its height above the wing's plane, positive up.
    pub z: f64,
    /// Its incidence relative to the wing (rad). A linear theory's
    /// derivatives do not depend on it; it is kept for trim.
    pub incidence: f64,
}

/// A body (the forebody of eq (43)): its length ahead of the wing's apex
/// and its diameter, in the wing's length unit.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Body {
    pub length_ahead: f64,
    pub diameter: f64,
}

/// A configuration: the wing and what is added to it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Configuration {
    pub wing: Trapezoid,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tailplane: Option<Surface>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub foreplane: Option<Surface>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub body: Option<Body>,
}

impl Configuration {
    /// The wing alone.
    pub fn wing_alone(wing: Trapezoid) -> Configuration {
        Configuration {
            wing,
            tailplane: None,
            foreplane: None,
            body: None,
        }
    }

    /// The surfaces beside the wing, tailplane first.
    pub fn surfaces(&self) -> impl Iterator<Item = &Surface> {
        self.tailplane.iter().chain(self.foreplane.iter())
    }
}

/// A part of a configuration.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Part {
    Wing,
    Tailplane,
    Foreplane,
    Body,
}
