//! §6: the zero-lift wave drag against the edge parameter (Fig 1, linear
//! theory standing for the note's experimental curve), the aerodynamic
//! coefficients and the stiffness derivatives of the two wings across Mach
//! number (Figs 2–3, 5–12), and Fig 4 (the lift slope against aspect
//! ratio, [`super::lifting_surface`]).

use super::regimes::{self, Basis};
use super::study::{WINGS, machs};
use super::{Plate, Study};
use rayon::prelude::*;
use stability_core::aerodynamics::models::aero::defaults;
use stability_core::aerodynamics::supersonic::wave_drag::{NOTE_RIDGE, fig1_series};
use stability_core::design::case::CaseResult;
use stability_core::design::study::grid;
use stability_core::geometry::{Planform, Size};
use stability_io::plot::{Figure, Series, VerticalLine, short};

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
        "The faired model's own: the doublet lattice's steady lift slope to M = 0.9, linear supersonic theory's (36) from 1.2 (4/β past the sonic leading edge), a monotone cubic between (docs/models.md).",
    ),
    (
        "6",
        "Aerodynamic centre",
        "H₀ (fraction of M.A.C.)",
        |r| r.coefficients.aerodynamic_centre.value,
        "The faired model's own: the doublet lattice's neutral point to M = 0.9, linear theory's ½ (two-thirds of the root chord) from 1.2, a monotone cubic between.",
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
            let fig = study.pair(id, title, y, &|r| Some(f(r)));
            Plate::new(
                regimes::faired(fig, study, &WINGS, Basis::Coefficients),
                caption,
            )
        })
        .collect();
    // Fig 4 after Fig 3: the lift slope against aspect ratio
    out.insert(2, super::lifting_surface::fig4());
    out
}

/// Fig 1, the section before the rest of §6 ([`crate::SECTIONS`]), drawn
/// without the study.
pub fn wave_drag_plates() -> Vec<Plate> {
    vec![fig1()]
}

/// The edge parameters m = β cot Λ of Fig 1: by 0.02 to 1.2, through the
/// peaks at m = 1 − f = 0.7 (the ridge sonic) and m = 1 (the leading
/// edge), then by 0.05 to 3, where the curve is smooth.
fn fig1_edge_parameters() -> Vec<f64> {
    let mut ms = grid(0.02, 1.2, 0.02);
    ms.extend(grid(1.25, 3.0, 0.05));
    ms
}

/// C_Dw·β/τ² of the blend `aero::defaults::wave_drag` (the wave drag of
/// Fig 2's C_D0) at edge parameter `m`, on the 45° delta (cot Λ = 1, so
/// β = m): a function of m alone, as linear theory's.
fn blend_scaled(m: f64) -> f64 {
    let Ok(wing) = Planform::new(45f64.to_radians(), 0.0, Size::RootChord(1.0)) else {
        return f64::NAN;
    };
    let tau = defaults::THICKNESS;
    defaults::wave_drag(&wing, m.hypot(1.0)).value * m / (tau * tau)
}

/// The edge parameters of the note's wing of sweep `deg` over the Mach
/// numbers where Fig 2 takes the supersonic wave drag (from
/// `defaults::SUPERSONIC_LIMIT` to the study's last): (from, to).
fn wing_edge_parameters(deg: f64) -> (f64, f64) {
    let last = machs().last().copied().unwrap_or(2.0);
    let m = |mach: f64| (mach * mach - 1.0).sqrt() / deg.to_radians().tan();
    (m(defaults::SUPERSONIC_LIMIT), m(last))
}

/// Fig 1, wave drag at zero lift against the edge parameter: linear
/// theory for the note's sections (`supersonic::wave_drag`, a double wedge
/// with its ridge at 0.3c) beside the blend Fig 2 uses. The note's curve,
/// through rocket-model data (§6: measured C_D0 less a friction drag of
/// 0.005), did not survive; these stand for it (docs/models.md, "Fig 1").
pub fn fig1() -> Plate {
    let ms = fig1_edge_parameters();
    // each point a quadrature of its own: in parallel
    let theory = ms
        .par_iter()
        .map(|&m| {
            let drag = fig1_series(&[m]).ok().and_then(|p| p.first().copied());
            (m, drag.map_or(f64::NAN, |p| p.scaled_drag))
        })
        .collect();
    let blend = ms.iter().map(|&m| (m, blend_scaled(m))).collect();
    let mut fig = Figure::new(
        "1",
        "Wave drag at zero lift (linear theory)",
        "m = β cot Λ = cot Λ/tan μ",
        "C_Dw·β/τ²",
    )
    .with(Series::new(
        format!("linear theory, double wedge, ridge at {NOTE_RIDGE}c"),
        theory,
    ))
    .with(Series::new(
        "blend used for Fig 2, (16/3)m/√(1 + m²)",
        blend,
    ));
    fig.markers = vec![
        VerticalLine {
            x: 1.0 - NOTE_RIDGE,
            label: "ridge sonic".into(),
        },
        VerticalLine {
            x: 1.0,
            label: "leading edge sonic".into(),
        },
    ];
    let spans: Vec<String> = WINGS
        .iter()
        .map(|&deg| {
            let (a, b) = wing_edge_parameters(deg);
            format!("{deg}° delta, m = {}–{}", short(a), short(b))
        })
        .collect();
    Plate::new(
        fig,
        format!(
            "Stands in for the note's Fig 1, whose curve through rocket-model data (§6: measured C_D0 less 0.005 friction) did not survive: linear theory (Puckett 1946) for a true delta with double-wedge sections, τ = 0.06 and the ridge at 0.3c as the note's sections (eq 23), C_Dw·β/τ² against m = β cot Λ, μ the Mach angle. Its peaks, where the ridge and the leading edge turn sonic, are linear theory's; real flow smooths them. Beside it the blend that Fig 2's C_D0 uses (docs/models.md, \"Fig 1\"). The note's wings at M = {}–{}: {}.",
            short(defaults::SUPERSONIC_LIMIT),
            short(machs().last().copied().unwrap_or(2.0)),
            spans.join("; ")
        ),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(s: &Series, m: f64) -> f64 {
        s.points
            .iter()
            .find(|p| stability_core::numerics::grid::on(p.0, m))
            .map_or(f64::NAN, |p| p.1)
    }

    #[test]
    fn fig1_is_linear_theory_beside_the_blend_in_its_own_files() {
        let plate = fig1();
        assert_eq!(plate.name(), "fig01");
        let [(svg_name, svg), (csv_name, csv)] = plate.files().unwrap();
        assert_eq!(
            (svg_name.as_str(), csv_name.as_str()),
            ("fig01.svg", "fig01.csv")
        );
        let svg = String::from_utf8(svg).unwrap();
        assert!(svg.contains("Fig. 1 — Wave drag at zero lift"));
        assert!(svg.contains("ridge sonic") && svg.contains("leading edge sonic"));
        let csv = String::from_utf8(csv).unwrap();
        assert!(
            csv.starts_with("m = β cot Λ = cot Λ/tan μ,\"C_Dw·β/τ² [linear theory"),
            "{csv}"
        );
        assert!(csv.lines().any(|l| l.starts_with("0.7,")), "{csv}");
        let [theory, blend] = &plate.figure.series[..] else {
            panic!("two series")
        };
        // docs/models.md's table, "Fig 1"
        for (m, lin, bl) in [
            (0.3, 1.317, 1.533),
            (1.0, 7.107, 3.771),
            (2.0, 5.180, 4.770),
        ] {
            assert!(
                (at(theory, m) - lin).abs() < 2e-3,
                "m = {m}: {}",
                at(theory, m)
            );
            assert!(
                (at(blend, m) - bl).abs() < 2e-3,
                "m = {m}: {}",
                at(blend, m)
            );
        }
        // the blend in closed form, (16/3)m/√(1 + m²), whatever the sweep
        let p60 = Planform::new(60f64.to_radians(), 0.0, Size::RootChord(1.0)).unwrap();
        for &(m, v) in &blend.points {
            let closed = 16.0 / 3.0 * m / m.hypot(1.0);
            assert!((v - closed).abs() < 1e-12 * closed, "m = {m}");
            let mach = (m * 60f64.to_radians().tan()).hypot(1.0);
            let tau2 = defaults::THICKNESS.powi(2);
            let beta = (mach * mach - 1.0).sqrt();
            assert!((defaults::wave_drag(&p60, mach).value * beta / tau2 - v).abs() < 1e-9);
        }
        // linear theory's highest point where the leading edge turns sonic
        let top = theory
            .points
            .iter()
            .max_by(|a, b| a.1.total_cmp(&b.1))
            .unwrap();
        assert!((top.0 - 1.0).abs() < 1e-9, "{top:?}");
        // no regime bands: Fig 1 is not against Mach number
        assert!(plate.figure.bands.is_empty() && plate.figure.regions.is_empty());
    }

    #[test]
    fn the_wings_edge_parameters_are_beta_cot_sweep() {
        // 45°: cot Λ = 1, m = β; 60°: m = β/√3
        let (a, b) = wing_edge_parameters(45.0);
        assert!((a - 0.44f64.sqrt()).abs() < 1e-12 && (b - 3f64.sqrt()).abs() < 1e-12);
        let (a, b) = wing_edge_parameters(60.0);
        assert!((a - (0.44f64 / 3.0).sqrt()).abs() < 1e-12 && (b - 1.0).abs() < 1e-12);
    }
}
