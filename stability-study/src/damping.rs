//! §7: the damping theories (Figs 13, 16–18; Figs 14–15, Garrick beside
//! the lifting surface, from [`super::lifting_surface`]) and the default
//! model's damping derivatives (Figs 19–24), with Mangler's frequency-consistent
//! theory near M = 1 beside them.

use super::regimes::{self, Basis};
use super::study::{WINGS, curve, label, mach_fig};
use super::{Plate, Study};
use stability_core::aerodynamics::damping::{
    DampingDerivatives, Fig18, Theory, WingInput, damping_derivatives,
};
use stability_core::design::case::CaseResult;
use stability_core::design::study::{grid, intervals};
use stability_io::plot::{Figure, Series};

pub fn plates(study: &Study) -> Vec<Plate> {
    let mut out = vec![fig13()];
    out.extend(super::lifting_surface::figs_14_15());
    out.extend(supersonic(study));
    out.push(fig18());
    out.extend(faired(study));
    out
}

fn fig13() -> Plate {
    let hs = grid(0.0, 1.0, 0.01);
    let unit = WingInput {
        aspect_ratio: 1.0,
        sweep_le: 1.0,
        taper: 0.0,
    };
    let garrick = |f: fn(&DampingDerivatives) -> f64| -> Vec<(f64, f64)> {
        hs.iter()
            .map(|&h| {
                let d = damping_derivatives(Theory::Garrick, &unit, h, 0.0, None);
                (h, d.map(|d| -f(&d.derivatives)).unwrap_or(f64::NAN))
            })
            .collect()
    };
    Plate::new(
        Figure::new(
            "13",
            "Low aspect ratio theory (Garrick, incompressible)",
            "c.g. position h (fraction of M.A.C.)",
            "per unit aspect ratio",
        )
        .with(Series::new("−z_θ̇/A, eq (32)", garrick(|d| d.z_thetadot())))
        .with(Series::new("−m_θ̇/A, eq (33)", garrick(|d| d.m_thetadot()))),
        "Eqs (32)–(33): −z_θ̇ = (πA/4)(3 − 2h), −m_θ̇ = (πA/2)(h − 1)²; m_θ̇ vanishes with the axis at the trailing edge.",
    )
}

/// −f of the supersonic theory (36) for the wing of sweep `deg`, h = 0.25.
pub fn supersonic_series(ms: &[f64], deg: f64, f: fn(&DampingDerivatives) -> f64) -> Series {
    let sweep = deg.to_radians();
    let w = WingInput {
        aspect_ratio: 4.0 / sweep.tan(),
        sweep_le: sweep,
        taper: 0.0,
    };
    let points = ms
        .iter()
        .map(|&m| {
            let d = damping_derivatives(Theory::Supersonic, &w, 0.25, m, None);
            (m, d.map(|d| -f(&d.derivatives)).unwrap_or(f64::NAN))
        })
        .collect();
    Series::new(label(deg), points)
}

fn supersonic(study: &Study) -> [Plate; 2] {
    // one theory, no fairing: the sonic edges alone, where (36) ends
    let fig = |id: &str, title: &str, y: &str, f: fn(&DampingDerivatives) -> f64| {
        let fig = WINGS.iter().fold(mach_fig(id, title, y), |fig, &deg| {
            fig.with(supersonic_series(&study.ms, deg, f))
        });
        regimes::sonic_edges(fig, &WINGS)
    };
    [
        Plate::new(
            fig(
                "16",
                "Supersonic damping in pitch (Mangler, Ribner & Malvestuto)",
                "−z_θ̇",
                |d| d.z_thetadot(),
            ),
            "Linear supersonic theory, h = 0.25, M > 1: eq (36) recovered (docs/damping-theories.md) while the leading edge is subsonic, the supersonic-edge theory past the dashed line where it turns sonic (continuous there; supersonic::edge_theory).",
        ),
        Plate::new(
            fig(
                "17",
                "Supersonic damping in pitch derivative (Mangler, Ribner & Malvestuto)",
                "−m_θ̇",
                |d| d.m_thetadot(),
            ),
            "As Fig 16; §7's statement about the 45° delta at M = 1.2 (eq 36) is among the conclusions.",
        ),
    ]
}

fn fig18() -> Plate {
    let bcs = grid(0.0, 0.999, 0.003);
    Plate::new(
        Figure::new(
            "18",
            "Functions H, E in the theory of Mangler, Ribner & Malvestuto",
            "β cot Λ = cot Λ/tan μ",
            "value",
        )
        .with(Series::new(
            "H = E·G",
            bcs.iter().map(|&b| (b, Fig18::at(b).h)).collect(),
        ))
        .with(Series::new(
            "1/E",
            bcs.iter().map(|&b| (b, 1.0 / Fig18::at(b).e)).collect(),
        )),
        "Complete elliptic integrals (the ellip crate); H → 1 and 1/E → 1 at M = 1, H → 2/3 and 1/E → 2/π as the leading edge turns sonic.",
    )
}

type Of = fn(&CaseResult) -> f64;

const FAIRED: [(&str, &str, &str, Of); 6] = [
    ("19", "Force-angular velocity derivative z_q", "z_q", |r| {
        r.derivatives.z_q
    }),
    ("20", "Force-acceleration derivative z_ẇ", "z_ẇ", |r| {
        r.derivatives.z_wdot
    }),
    (
        "21",
        "Damping in pitch derivative z_θ̇",
        "z_θ̇ = z_q + z_ẇ",
        |r| r.damping.derivatives.z_thetadot(),
    ),
    ("22", "Moment-angular velocity derivative m_q", "m_q", |r| {
        r.derivatives.m_q
    }),
    ("23", "Moment-acceleration derivative m_ẇ", "m_ẇ", |r| {
        r.derivatives.m_wdot
    }),
    (
        "24",
        "Damping in pitch derivative m_θ̇",
        "m_θ̇ = m_q + m_ẇ",
        |r| r.damping.derivatives.m_thetadot(),
    ),
];

/// Where z_ẇ > 0, in words, from the results (Fig 20's caption).
fn positive_zwdot(study: &Study) -> String {
    let parts: Vec<String> = WINGS
        .iter()
        .zip(&study.results)
        .map(|(deg, rs)| {
            let flags: Vec<bool> = rs
                .iter()
                .map(|r| r.as_ref().is_some_and(|r| r.derivatives.z_wdot > 0.0))
                .collect();
            format!(
                "{}° delta: {}",
                deg,
                super::summary::show_intervals(&intervals(&study.ms, &flags))
            )
        })
        .collect();
    format!("z_ẇ > 0 for M in ({}).", parts.join("; "))
}

fn faired(study: &Study) -> Vec<Plate> {
    let base = "The default model (docs/damping-theories.md, \"The faired model\"): one linear lifting-surface theory at the short period's own ω̄ — the doublet lattice below M = 1, its sonic extrapolation at M = 1, the Mach box above — joined only in the shaded band between M = 0.99 and the Mach box's first Mach number; beside them Mangler's (39)–(40) alone, ω̄ iterated, near M = 1.";
    FAIRED
        .iter()
        .map(|&(id, title, y, f)| {
            let fig = study.pair(id, title, y, &|r| Some(f(r))).with(curve(
                "45°, Mangler (39)–(40), consistent ω̄",
                &study.near_sonic,
                &study.mangler,
                |r| Some(f(r)),
            ));
            let caption = match id {
                "19" => base.to_string(),
                "20" => format!("As Fig 19; {}", positive_zwdot(study)),
                _ => "As Fig 19.".to_string(),
            };
            Plate::new(regimes::faired(fig, study, &WINGS, Basis::Damping), caption)
        })
        .collect()
}
