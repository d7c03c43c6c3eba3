//! §6: the aerodynamic coefficients and the stiffness derivatives of the
//! two wings across Mach number (Figs 2–3, 5–12), and Fig 4 (the lift slope
//! against aspect ratio, [`super::lifting_surface`]).

use super::{Plate, Study};
use stability_core::case::CaseResult;

type Of = fn(&CaseResult) -> f64;

/// (figure, title, axis, value, caption) for each figure.
const FIGURES: [(&str, &str, &str, Of, &str); 10] = [
    (
        "2",
        "Drag coefficient at zero lift",
        "C_D0",
        |r| r.coefficients.zero_lift_drag.value,
        "C_D0: 0.01 subsonic; 0.005 friction + thin-wing wave drag supersonic; faired (docs/models.md).",
    ),
    (
        "3",
        "Drag due to lift",
        "K = ∂C_D/∂C_L²",
        |r| r.coefficients.drag_due_to_lift.value,
        "K = 1/(∂C_L/∂α): no leading-edge suction; §6's transonic rule.",
    ),
    (
        "5",
        "Slope of the lift curve",
        "∂C_L/∂α (per radian)",
        |r| r.coefficients.lift_slope.value,
        "DATCOM subsonic, linear conical-flow theory supersonic, faired between.",
    ),
    (
        "6",
        "Aerodynamic centre",
        "H₀ (fraction of M.A.C.)",
        |r| r.coefficients.aerodynamic_centre.value,
        "Slender-wing to two-dimensional blend subsonic; ½ supersonic.",
    ),
    (
        "7",
        "Force-linear velocity derivative x_w",
        "x_w",
        |r| r.derivatives.x_w,
        "Eq (11).",
    ),
    (
        "8",
        "Force-linear velocity derivative z_w",
        "z_w",
        |r| r.derivatives.z_w,
        "Eq (12).",
    ),
    (
        "9",
        "Moment-linear velocity derivative m_w",
        "−m_w",
        |r| -r.derivatives.m_w,
        "Eqs (14), (25), c.g. at h = 0.25.",
    ),
    (
        "10",
        "Force-linear velocity derivative x_u",
        "−x_u",
        |r| -r.derivatives.x_u,
        "Eqs (9), (28), level flight C_L·M² = 0.05 (eq 24).",
    ),
    (
        "11",
        "Force-linear velocity derivative z_u",
        "−z_u",
        |r| -r.derivatives.z_u,
        "Eqs (10), (27).",
    ),
    (
        "12",
        "Moment-linear velocity derivative m_u",
        "−m_u",
        |r| -r.derivatives.m_u,
        "Eqs (13), (29), trimmed.",
    ),
];

pub fn plates(study: &Study) -> Vec<Plate> {
    let mut out: Vec<Plate> = FIGURES
        .iter()
        .map(|&(id, title, y, f, caption)| {
            Plate::new(study.pair(id, title, y, &|r| Some(f(r))), caption)
        })
        .collect();
    // Fig 4 after Fig 3: the lift slope against aspect ratio
    out.insert(2, super::lifting_surface::fig4());
    out
}
