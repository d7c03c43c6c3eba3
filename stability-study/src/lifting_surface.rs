//! The note's lifting-surface figures, from `stability_core::aerodynamics::figures`:
//! Fig 4 (§6, the lift slope against aspect ratio for several sweeps,
//! incompressible) and Figs 14–15 (§7, incompressible −z_θ̇ and −m_θ̇ of the
//! delta planform against aspect ratio: Garrick's low-aspect-ratio theory,
//! eqs (32)–(33), beside the lifting surface — the note's Multhopp–Garner
//! and Lehrian curves). Each wing is solved once, quasi-steady at M = 0, at
//! its default lattice; the wings in parallel.
//!
//! The note's figures did not survive the OCR, nor their sweeps, taper or
//! c.g.: the choices are stated in the captions.

use super::Plate;
use rayon::prelude::*;
use stability_core::aerodynamics::figures::{
    DampingInPitchPoint, damping_in_pitch_against_aspect_ratio, lift_slope_against_aspect_ratio,
};
use stability_io::plot::{Figure, Series};
use std::f64::consts::PI;

/// Fig 4's leading-edge sweeps (degrees) and taper.
pub const FIG4_SWEEPS: [f64; 4] = [0.0, 30.0, 45.0, 60.0];
pub const FIG4_TAPER: f64 = 0.5;

/// The aspect ratios of Fig 4.
fn fig4_aspect_ratios() -> Vec<f64> {
    vec![0.25, 0.5, 0.75, 1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0]
}

/// The c.g. of Figs 14–15: h = 0.25, x₀/c₀ = 0.5 for every true delta —
/// the middle of Lehrian's "practical C.G. range 0.4 < x₀/c₀ < 0.6".
pub const FIGS_14_15_CG: f64 = 0.25;

/// The aspect ratios of Figs 14–15 (true deltas, A = 4 cot Λ: the 60°
/// delta is A = 2.31, the 45° delta A = 4).
fn figs_14_15_aspect_ratios() -> Vec<f64> {
    vec![
        0.1, 0.25, 0.5, 0.75, 1.0, 1.5, 2.0, 2.31, 2.5, 3.0, 3.5, 4.0,
    ]
}

pub fn fig4() -> Plate {
    let ars = fig4_aspect_ratios();
    let series: Vec<Series> = FIG4_SWEEPS
        .par_iter()
        .map(|&sweep| {
            let points = lift_slope_against_aspect_ratio(&[sweep], &ars, FIG4_TAPER)
                .ok()
                .and_then(|mut s| s.pop())
                .map_or_else(Vec::new, |s| s.points);
            Series::new(format!("Λ = {sweep}°, lifting surface"), points)
        })
        .collect();
    let slender = ars
        .iter()
        .filter(|&&a| a <= 2.0)
        .map(|&a| (a, PI * a / 2.0))
        .collect();
    let fig = series.into_iter().fold(
        Figure::new(
            "4",
            "Slope of lift curve for various angles of sweep (incompressible flow)",
            "aspect ratio A",
            "∂C_L/∂α (per radian)",
        ),
        Figure::with,
    );
    Plate::new(
        fig.with(Series::new("slender wing, πA/2", slender)),
        format!(
            "Doublet lattice, M = 0, steady, leading-edge sweep Λ, taper {FIG4_TAPER} (the note's sweeps and taper are not recoverable); slender-wing theory's πA/2 where A is small. Each wing at its default lattice (docs/damping-theories.md)."
        ),
    )
}

/// Figs 14–15's points, one lattice per aspect ratio, in parallel.
fn damping_in_pitch() -> Vec<DampingInPitchPoint> {
    figs_14_15_aspect_ratios()
        .par_iter()
        .filter_map(|&a| damping_in_pitch_against_aspect_ratio(&[a], FIGS_14_15_CG).ok())
        .flatten()
        .collect()
}

pub fn figs_14_15() -> [Plate; 2] {
    let points = damping_in_pitch();
    let series = |label: &str, f: fn(&DampingInPitchPoint) -> f64| {
        Series::new(
            label,
            points.iter().map(|p| (p.aspect_ratio, f(p))).collect(),
        )
    };
    let fig = |id: &str, title: &str, y: &str| {
        Figure::new(id, title, "aspect ratio A (true delta, A = 4 cot Λ)", y)
    };
    let caption = |eq: &str| {
        format!(
            "Incompressible, quasi-steady, c.g. at h = {FIGS_14_15_CG} (x₀/c₀ = 0.5). Garrick's low-aspect-ratio theory {eq} is the slope at A → 0 of the lifting surface's curve (the doublet lattice standing for the note's Multhopp–Garner and Lehrian results): \"little reliability for any but very small values of aspect ratio\"."
        )
    };
    [
        Plate::new(
            fig(
                "14",
                "Incompressible damping in pitch, delta planform",
                "−z_θ̇",
            )
            .with(series("Garrick, eq (32)", |p| p.garrick_z))
            .with(series("lifting surface", |p| p.lifting_surface_z)),
            caption("(32)"),
        ),
        Plate::new(
            fig(
                "15",
                "Incompressible damping in pitch derivative, delta planform",
                "−m_θ̇",
            )
            .with(series("Garrick, eq (33)", |p| p.garrick_m))
            .with(series("lifting surface", |p| p.lifting_surface_m)),
            caption("(33)"),
        ),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_figures_have_every_curve_and_point() {
        let f4 = fig4();
        assert_eq!(f4.figure.series.len(), FIG4_SWEEPS.len() + 1);
        for s in &f4.figure.series[..FIG4_SWEEPS.len()] {
            assert_eq!(s.points.len(), fig4_aspect_ratios().len(), "{}", s.label);
            // rising with aspect ratio, below 2π
            assert!(s.points.windows(2).all(|w| w[1].1 > w[0].1), "{}", s.label);
            assert!(s.points.iter().all(|p| p.1 < 2.0 * PI));
        }
        let [f14, f15] = figs_14_15();
        for f in [&f14, &f15] {
            assert_eq!(f.figure.series.len(), 2);
            for s in &f.figure.series {
                assert_eq!(s.points.len(), figs_14_15_aspect_ratios().len());
                assert!(s.points.iter().all(|p| p.1.is_finite() && p.1 > 0.0));
            }
            // the lattice meets Garrick's line at small A and falls below it
            let (g, l) = (&f.figure.series[0].points, &f.figure.series[1].points);
            assert!((l[0].1 / g[0].1 - 1.0).abs() < 0.1, "{:?} {:?}", g[0], l[0]);
            assert!(l.last().unwrap().1 < 0.5 * g.last().unwrap().1);
        }
    }
}
