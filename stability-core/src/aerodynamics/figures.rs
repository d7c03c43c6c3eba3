//! The data of the note's lifting-surface figures, as series for a plot
//! (the command-line program draws them):
//! - Fig 4, "Slope of lift curve for various angles of sweep (incompressible
//!   flow)": C_Lα against aspect ratio, one series per sweep;
//! - Figs 14–15, "Incompressible damping in pitch, −z_θ̇" and "… derivative,
//!   −m_θ̇" of the delta planform against aspect ratio: Garrick's
//!   low-aspect-ratio theory, eqs (32)–(33), beside the lifting surface (the
//!   note's Multhopp–Garner and Lehrian curves, which did not survive the
//!   OCR).
//!
//! The note's figures are lost, and the OCR does not say which sweeps, taper
//! or c.g. they used: the caller chooses them.

use crate::aerodynamics::damping::{Theory, WingInput, damping_derivatives};
use crate::aerodynamics::lifting_surface::{Lattice, LatticeSpec, LiftingSurfaceError};
use crate::geometry::Trapezoid;
use serde::Serialize;

/// One curve of Fig 4: C_Lα (per radian, incompressible, quasi-steady)
/// against aspect ratio at one leading-edge sweep and taper.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LiftSlopeSeries {
    /// Leading-edge sweep Λ (degrees).
    pub sweep_le_deg: f64,
    pub taper: f64,
    /// (A, C_Lα).
    pub points: Vec<(f64, f64)>,
}

/// Fig 4: for each leading-edge sweep (degrees) a series of C_Lα at M = 0
/// against the aspect ratios given, for trapezoids of taper `taper`, each
/// at its default lattice ([`LatticeSpec::for_wing`]).
pub fn lift_slope_against_aspect_ratio(
    sweeps_le_deg: &[f64],
    aspect_ratios: &[f64],
    taper: f64,
) -> Result<Vec<LiftSlopeSeries>, LiftingSurfaceError> {
    sweeps_le_deg
        .iter()
        .map(|&sweep| {
            let points = aspect_ratios
                .iter()
                .map(|&a| {
                    let wing = trapezoid(a, taper, sweep)?;
                    let lattice = Lattice::new(&wing, LatticeSpec::for_wing(&wing))?;
                    Ok((a, lattice.solve(0.0, 0.0)?.lift_slope()))
                })
                .collect::<Result<_, LiftingSurfaceError>>()?;
            Ok(LiftSlopeSeries {
                sweep_le_deg: sweep,
                taper,
                points,
            })
        })
        .collect()
}

fn trapezoid(a: f64, taper: f64, sweep_deg: f64) -> Result<Trapezoid, LiftingSurfaceError> {
    Trapezoid::from_aspect_ratio(a, taper, sweep_deg.to_radians(), 1.0)
        .map_err(|e| LiftingSurfaceError::Planform(e.to_string()))
}

/// One point of Figs 14–15: a true delta of aspect ratio A at c.g. h,
/// incompressible and quasi-steady.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DampingInPitchPoint {
    pub aspect_ratio: f64,
    /// −z_θ̇ and −m_θ̇ by Garrick's theory, eqs (32)–(33).
    pub garrick_z: f64,
    pub garrick_m: f64,
    /// −z_θ̇ and −m_θ̇ by the lifting surface (doublet lattice).
    pub lifting_surface_z: f64,
    pub lifting_surface_m: f64,
}

/// Figs 14–15: −z_θ̇ and −m_θ̇ of true deltas (unswept trailing edge,
/// A = 4 cot Λ) at c.g. `h`, M = 0, quasi-steady, by Garrick's theory and by
/// the lifting surface, at each aspect ratio given (0 < A, Λ < 90°).
pub fn damping_in_pitch_against_aspect_ratio(
    aspect_ratios: &[f64],
    h: f64,
) -> Result<Vec<DampingInPitchPoint>, LiftingSurfaceError> {
    aspect_ratios
        .iter()
        .map(|&a| {
            let sweep = (4.0 / a).atan();
            let wing = trapezoid(a, 0.0, sweep.to_degrees())?;
            let lattice = Lattice::new(&wing, LatticeSpec::for_wing(&wing))?;
            let d = lattice.solve(0.0, 0.0)?.derivatives(h, 0.0)?;
            let input = WingInput {
                aspect_ratio: a,
                sweep_le: sweep,
                taper: 0.0,
            };
            let g = damping_derivatives(Theory::Garrick, &input, h, 0.0, None)
                .map_err(|e| LiftingSurfaceError::Planform(e.to_string()))?
                .derivatives;
            Ok(DampingInPitchPoint {
                aspect_ratio: a,
                garrick_z: -g.z_thetadot(),
                garrick_m: -g.m_thetadot(),
                lifting_surface_z: -d.z_thetadot,
                lifting_surface_m: -d.m_thetadot,
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn fig_4_rises_with_aspect_ratio_and_falls_with_sweep() {
        let s = lift_slope_against_aspect_ratio(&[0.0, 45.0], &[1.0, 4.0], 0.5).unwrap();
        let (unswept, swept) = (&s[0].points, &s[1].points);
        assert!(unswept[1].1 > unswept[0].1 && swept[1].1 > swept[0].1);
        assert!(unswept[1].1 > swept[1].1);
        // below the slender value πA/2 and the 2-D 2π
        assert!(unswept[0].1 < PI / 2.0 && unswept[1].1 < 2.0 * PI);
    }

    #[test]
    fn figs_14_15_meet_garrick_at_small_aspect_ratio() {
        let p = damping_in_pitch_against_aspect_ratio(&[0.05, 2.0], 0.25).unwrap();
        // Garrick's theory is slender-wing theory: the lattice tends to it
        assert!(
            (p[0].lifting_surface_z / p[0].garrick_z - 1.0).abs() < 0.03,
            "{p:?}"
        );
        assert!(
            (p[0].lifting_surface_m / p[0].garrick_m - 1.0).abs() < 0.03,
            "{p:?}"
        );
        // and falls well below it at A = 2 (the note: "poor agreement")
        assert!(p[1].lifting_surface_z < 0.8 * p[1].garrick_z, "{p:?}");
        assert!(p[1].lifting_surface_m < 0.8 * p[1].garrick_m, "{p:?}");
    }
}
