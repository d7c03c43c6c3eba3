//! The lattice: the half wing divided into boxes, each with its doublet
//! line and collocation point (E. Albano and W.P. Rodden, AIAA J. 7(2),
//! 1969, §"Method").
//!
//! The half wing 0 ≤ y ≤ s of a [`Trapezoid`] is cut into spanwise strips,
//! and each strip into equal chordwise boxes (constant fractions of the
//! local chord), so that every box is a trapezoid with streamwise sides.
//! A box's doublet line is its quarter-chord line and its collocation
//! point is at three-quarters of its chord (the "1/4–3/4 rule", exact for
//! the two-dimensional flat plate in steady flow). The other half enters as
//! the mirror image of each line (symmetric motions only).
//!
//! # Convergence, and the default lattice
//! Measured (`examples/lifting_surface_convergence.rs`, tabled in
//! `docs/damping-theories.md`): the steady derivatives converge as O(N⁻²)
//! in either direction once the strips are narrow where the load changes
//! fast — at the root (the apex's kink) always, and at a side edge — so the
//! default spacing is cosine there ([`Spacing::Auto`]), with the
//! collocation point at the strip's mid-angle (J.E. Lan, "A quasi-vortex-
//! lattice method in thin wing theory", J. Aircraft 11(9), 1974, spanwise).
//! The α̇ derivatives converge chordwise only as O(N⁻¹), a known property of
//! the doublet lattice (the oscillatory kernel integrated across a strip is
//! logarithmic in x₀, which pressure concentrated on lines resolves only to
//! first order). The default therefore solves three lattices, N, N/2 and
//! N/4 boxes per strip on the same strips, and extrapolates each result
//! (L.F. Richardson and J.A. Gaunt, "The deferred approach to the limit",
//! Phil. Trans. R. Soc. A 226, 1927): X = (8X_N − 6X_{N/2} + X_{N/4})/3,
//! exact for X_N = X + a/N + b/N²; the coarser two cost a third more than the
//! finest alone.

use super::LiftingSurfaceError;
use super::doublet_line::{DoubletLine, LineRule};
use super::kernel::I1Approximation;
use crate::geometry::Trapezoid;
use serde::Serialize;
use std::f64::consts::PI;

/// How the strips' edges are spaced across the half-span.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Spacing {
    /// Equal strips, collocation at mid-span.
    Uniform,
    /// Cosine spacing over the half-span, y = s(1 − cos θ)/2 for equal steps
    /// of θ in [0, π], collocation at the mid-angle: narrow strips at the
    /// root (the apex's kink) and at the tip (a side edge, where the load
    /// falls like √(s − y)).
    Cosine,
    /// Half-cosine spacing, y = s(1 − cos(θ/2)), θ in [0, π], collocation at
    /// the mid-angle: narrow strips at the root only, for pointed tips
    /// (whose load vanishes with the chord; narrow strips there only slow
    /// the convergence).
    RootCosine,
    /// [`Spacing::RootCosine`] for a pointed tip (c_t = 0),
    /// [`Spacing::Cosine`] for a side edge.
    Auto,
}

/// Whether the results are extrapolated over chordwise densities.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Extrapolation {
    /// The lattice as it is.
    None,
    /// Richardson's extrapolation over N, N/2, N/4 boxes per strip (N a
    /// multiple of 4); see the module's documentation.
    Chordwise,
    /// [`Extrapolation::Chordwise`] on n and on n/2 strips (n even), then
    /// Richardson's extrapolation in the strips, X = (4X_n − X_{n/2})/3
    /// (exact for X_n = X + c/n²).
    Richardson,
}

/// The lattice's density: boxes per strip, strips per half wing, how the
/// strips are spaced, the kernel's approximation and the extrapolation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct LatticeSpec {
    /// Chordwise boxes per strip (of the finest lattice).
    pub chordwise: usize,
    /// Strips on the half wing.
    pub spanwise: usize,
    pub spacing: Spacing,
    /// How the kernel's integral I₁ is approximated.
    pub kernel: I1Approximation,
    /// How the kernel's oscillatory part is integrated across each line.
    pub line_rule: LineRule,
    pub extrapolation: Extrapolation,
}

impl Default for LatticeSpec {
    /// The default lattice: 12 chordwise boxes on 16 strips
    /// ([`Spacing::Auto`]), Desmarais' kernel, the graded line rule,
    /// Richardson's extrapolation
    /// over 12, 6 and 3 boxes per strip — 192 + 96 + 48 boxes on the half
    /// wing. Its convergence is in `docs/damping-theories.md`.
    fn default() -> LatticeSpec {
        LatticeSpec {
            chordwise: 12,
            spanwise: 16,
            spacing: Spacing::Auto,
            kernel: I1Approximation::Desmarais,
            line_rule: LineRule::Graded,
            extrapolation: Extrapolation::Richardson,
        }
    }
}

impl LatticeSpec {
    /// Most boxes on a half wing (the dense complex matrix of 4000² takes
    /// 256 MB).
    pub const MAX_BOXES: usize = 4000;

    /// The default lattice for `wing`: [`LatticeSpec::default`] (16 strips)
    /// up to aspect ratio 4, and two more strips for each unit of aspect
    /// ratio beyond (24 at A = 8) — the α̇ derivatives of wings of larger
    /// aspect ratio need the narrower strips to stay within 0.5 % of a
    /// lattice twice as dense (`docs/damping-theories.md`).
    pub fn for_wing(wing: &Trapezoid) -> LatticeSpec {
        let extra = (wing.aspect_ratio() - 4.0 - 1e-9).max(0.0).ceil() as usize;
        LatticeSpec {
            spanwise: 16 + 2 * extra,
            ..LatticeSpec::default()
        }
    }

    /// Above this Mach number [`LatticeSpec::for_mach`] refines the lattice
    /// chordwise; at and below it, it is [`LatticeSpec::for_wing`] unchanged.
    pub const REFINED_ABOVE: f64 = 0.9;

    /// The default lattice for `wing` at Mach `mach`: [`LatticeSpec::for_wing`]
    /// up to M = [`Self::REFINED_ABOVE`], and above it as many more chordwise
    /// boxes as keep the Prandtl–Glauert stretched box length Δx/β at its
    /// value at M = 0.9 — N = 12·β(0.9)/β rounded up to a multiple of 4
    /// (20 at M = 0.95, 28 at 0.98, 40 at 0.99, 56 at 0.995, 84 at 0.998), at
    /// most [`Self::MAX_BOXES`] on the half wing.
    ///
    /// Why Δx ∝ β: the steady kernel is the incompressible one on the
    /// stretched wing x/β (Albano & Rodden 1969, eq 11), whose chord c/β
    /// grows as M → 1, and the oscillatory increment's structure near the
    /// Mach plane, x₀ ≲ βr, shrinks with it (the kernel's u₁ = (MR − x₀)/(β²r),
    /// [`super::kernel`]). Measured at M = 0.95 and 0.98 on the note's
    /// deltas, ω̄ = 0–0.6 (`docs/lattice-near-sonic.md`): the α̇-carrying
    /// numbers converge chordwise at first order as below M = 0.9, and this
    /// lattice is within 2·10⁻² (absolute) of one 96 boxes deep; near M = 1
    /// its 16 strips, not its boxes, limit it (up to 6·10⁻² in the
    /// quasi-steady α̇ numbers at M = 0.98).
    pub fn for_mach(wing: &Trapezoid, mach: f64) -> LatticeSpec {
        let base = LatticeSpec::for_wing(wing);
        if !(mach > Self::REFINED_ABOVE && mach < 1.0) {
            return base;
        }
        let beta = (1.0 - mach * mach).sqrt();
        let beta_09 = (1.0 - Self::REFINED_ABOVE * Self::REFINED_ABOVE).sqrt();
        let wanted = (base.chordwise as f64 * beta_09 / beta / 4.0).ceil() as usize * 4;
        let most = Self::MAX_BOXES / base.spanwise / 4 * 4;
        LatticeSpec {
            chordwise: wanted.clamp(base.chordwise, most.max(base.chordwise)),
            ..base
        }
    }

    /// A single lattice (no extrapolation) with Desmarais' kernel.
    pub fn new(chordwise: usize, spanwise: usize, spacing: Spacing) -> LatticeSpec {
        LatticeSpec {
            chordwise,
            spanwise,
            spacing,
            kernel: I1Approximation::Desmarais,
            line_rule: LineRule::Graded,
            extrapolation: Extrapolation::None,
        }
    }

    /// The same lattice with another line rule.
    pub fn with_line_rule(self, line_rule: LineRule) -> LatticeSpec {
        LatticeSpec { line_rule, ..self }
    }

    /// The same lattice with another kernel approximation.
    pub fn with_kernel(self, kernel: I1Approximation) -> LatticeSpec {
        LatticeSpec { kernel, ..self }
    }

    /// The same lattice with another extrapolation.
    pub fn with_extrapolation(self, extrapolation: Extrapolation) -> LatticeSpec {
        LatticeSpec {
            extrapolation,
            ..self
        }
    }

    /// The lattice with `factor` times as many boxes in each direction.
    pub fn scaled(self, factor: usize) -> LatticeSpec {
        LatticeSpec {
            chordwise: self.chordwise * factor,
            spanwise: self.spanwise * factor,
            ..self
        }
    }

    /// Boxes on the half wing (of the finest lattice).
    pub fn boxes(&self) -> usize {
        self.chordwise.saturating_mul(self.spanwise)
    }

    fn check(&self) -> Result<(), LiftingSurfaceError> {
        let (multiple, strips) = match self.extrapolation {
            Extrapolation::None => (1, 1),
            Extrapolation::Chordwise => (4, 1),
            Extrapolation::Richardson => (4, 2),
        };
        if self.chordwise == 0
            || self.spanwise == 0
            || !self.chordwise.is_multiple_of(multiple)
            || !self.spanwise.is_multiple_of(strips)
        {
            return Err(LiftingSurfaceError::Lattice {
                chordwise: self.chordwise,
                spanwise: self.spanwise,
                multiple,
            });
        }
        if self.boxes() > Self::MAX_BOXES {
            return Err(LiftingSurfaceError::TooManyBoxes {
                boxes: self.boxes(),
                max: Self::MAX_BOXES,
            });
        }
        Ok(())
    }

    /// The spec with [`Spacing::Auto`] resolved for `wing`.
    pub fn resolved(self, wing: &Trapezoid) -> LatticeSpec {
        let spacing = match self.spacing {
            Spacing::Auto if wing.tip_chord == 0.0 => Spacing::RootCosine,
            Spacing::Auto => Spacing::Cosine,
            other => other,
        };
        LatticeSpec { spacing, ..self }
    }

    /// The station of fraction t ∈ [0, 1] of the spacing's parameter.
    fn station(&self, t: f64, s: f64) -> f64 {
        let y = match self.spacing {
            Spacing::Uniform => s * t,
            // (`Auto` is resolved before it comes here)
            Spacing::Cosine | Spacing::Auto => 0.5 * s * (1.0 - (PI * t).cos()),
            Spacing::RootCosine => s * (1.0 - (0.5 * PI * t).cos()),
        };
        y.clamp(0.0, s)
    }

    /// The strips' edges, 0 = y₀ < y₁ < … < y_n = s, and each strip's
    /// collocation station at the mid-point of the spacing's parameter
    /// (mid-span for uniform strips, the mid-angle for cosine strips).
    fn strips(&self, s: f64, strips: usize) -> (Vec<f64>, Vec<f64>) {
        let n = strips as f64;
        let edges = (0..=strips)
            .map(|k| self.station(k as f64 / n, s))
            .collect();
        let centres = (0..strips)
            .map(|k| self.station((k as f64 + 0.5) / n, s))
            .collect();
        (edges, centres)
    }
}

/// One box of the half wing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Box {
    /// Its doublet line (quarter-chord line).
    pub line: DoubletLine,
    /// Collocation point (three-quarters of the local box chord, at the
    /// strip's collocation station).
    pub x_c: f64,
    pub y_c: f64,
    /// Area.
    pub area: f64,
}

/// The boxes of `wing` with `chordwise` boxes on each of `strips` strips
/// spaced as `spec` says.
fn boxes(wing: &Trapezoid, spec: &LatticeSpec, chordwise: usize, strips: usize) -> Vec<Box> {
    let (edges, centres) = spec.strips(wing.semi_span, strips);
    let strips: Vec<Strip> = edges
        .windows(2)
        .zip(&centres)
        .map(|(pair, &yc)| (pair[0], pair[1], yc))
        .collect();
    boxes_on(wing, &strips, chordwise)
}

/// A strip: its edges y₀ < y₁ and its collocation station.
pub(crate) type Strip = (f64, f64, f64);

/// The boxes of `wing` with `chordwise` boxes on each of the given strips.
fn boxes_on(wing: &Trapezoid, strips: &[Strip], chordwise: usize) -> Vec<Box> {
    let n = chordwise as f64;
    let mut boxes = Vec::with_capacity(chordwise * strips.len());
    for &(y0, y1, yc) in strips {
        let (ym, e) = (0.5 * (y0 + y1), 0.5 * (y1 - y0));
        let (c0, c1, cm, cc) = (
            wing.chord_at(y0),
            wing.chord_at(y1),
            wing.chord_at(ym),
            wing.chord_at(yc),
        );
        let (l0, l1, lc) = (
            wing.leading_edge_at(y0),
            wing.leading_edge_at(y1),
            wing.leading_edge_at(yc),
        );
        for k in 0..chordwise {
            let (f, g) = ((k as f64 + 0.25) / n, (k as f64 + 0.75) / n);
            let (xa, xb) = (l0 + f * c0, l1 + f * c1);
            boxes.push(Box {
                line: DoubletLine {
                    xi: 0.5 * (xa + xb),
                    eta: ym,
                    e,
                    tan_sweep: (xb - xa) / (2.0 * e),
                    chord: cm / n,
                },
                x_c: lc + g * cc,
                y_c: yc,
                area: (y1 - y0) * (c0 + c1) / (2.0 * n),
            });
        }
    }
    boxes
}

/// A wing's lattice (or, extrapolated, its three lattices): geometry only,
/// reusable for any Mach number and frequency.
#[derive(Debug, Clone, PartialEq)]
pub struct Lattice {
    wing: Trapezoid,
    spec: LatticeSpec,
    /// The finest lattice first.
    grids: Vec<Grid>,
}

/// One lattice: its boxes, strip by strip (`chordwise` to a strip, from the
/// leading edge).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Grid {
    pub boxes: Vec<Box>,
    pub chordwise: usize,
}

impl Lattice {
    /// The lattice of `wing` at density `spec`.
    pub fn new(wing: &Trapezoid, spec: LatticeSpec) -> Result<Lattice, LiftingSurfaceError> {
        spec.check()?;
        let spec = spec.resolved(wing);
        let levels: &[(usize, usize)] = match spec.extrapolation {
            Extrapolation::None => &[(1, 1)],
            Extrapolation::Chordwise => &[(1, 1), (2, 1), (4, 1)],
            Extrapolation::Richardson => &[(1, 1), (2, 1), (4, 1), (1, 2), (2, 2), (4, 2)],
        };
        let grids = levels
            .iter()
            .map(|(c, s)| Grid {
                boxes: boxes(wing, &spec, spec.chordwise / c, spec.spanwise / s),
                chordwise: spec.chordwise / c,
            })
            .collect();
        Ok(Lattice {
            wing: *wing,
            spec,
            grids,
        })
    }

    /// The lattice of `wing` at density `spec` but on the strips `strips`
    /// gives for each of its levels (finest first, as [`Lattice::new`]
    /// makes them: level k has `spec.chordwise / c` boxes per strip for the
    /// (c, s) of [`Extrapolation`]'s levels) — a configuration's surface
    /// aligned with another's strips (`crate::aerodynamics::lifting_surface::configuration`).
    pub(crate) fn on_strips(
        wing: &Trapezoid,
        spec: LatticeSpec,
        strips: impl Fn(usize) -> Vec<Strip>,
    ) -> Result<Lattice, LiftingSurfaceError> {
        let mut lattice = Lattice::new(wing, spec)?;
        for (k, grid) in lattice.grids.iter_mut().enumerate() {
            grid.boxes = boxes_on(wing, &strips(k), grid.chordwise);
        }
        Ok(lattice)
    }

    /// The strips of level `k` (finest first).
    pub(crate) fn strips_of(&self, k: usize) -> Vec<Strip> {
        let g = &self.grids[k];
        g.boxes
            .iter()
            .step_by(g.chordwise)
            .map(|b| (b.line.eta - b.line.e, b.line.eta + b.line.e, b.y_c))
            .collect()
    }

    pub fn wing(&self) -> &Trapezoid {
        &self.wing
    }

    /// The spec, its spacing resolved.
    pub fn spec(&self) -> LatticeSpec {
        self.spec
    }

    /// The boxes of the finest lattice.
    pub fn boxes(&self) -> &[Box] {
        &self.grids[0].boxes
    }

    /// Every lattice solved, finest first.
    pub(crate) fn grids(&self) -> &[Grid] {
        &self.grids
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_boxes_tile_the_half_wing() {
        let w = Trapezoid::new(2.0, 0.5, 3.0, 0.6).unwrap();
        for spacing in [Spacing::Uniform, Spacing::Cosine, Spacing::RootCosine] {
            let l = Lattice::new(&w, LatticeSpec::new(5, 7, spacing)).unwrap();
            let area: f64 = l.boxes().iter().map(|b| b.area).sum();
            assert!((area - w.area() / 2.0).abs() < 1e-12);
            for b in l.boxes() {
                assert!(b.y_c > 0.0 && b.y_c < w.semi_span);
                let le = w.leading_edge_at(b.y_c);
                assert!(b.x_c > le && b.x_c < le + w.chord_at(b.y_c));
                // the collocation point is half the local box chord behind the line
                let x_line = b.line.xi + (b.y_c - b.line.eta) * b.line.tan_sweep;
                let local = w.chord_at(b.y_c) / 5.0;
                assert!((b.x_c - x_line - 0.5 * local).abs() < 1e-12);
                assert!((b.y_c - b.line.eta).abs() < b.line.e);
            }
        }
    }

    #[test]
    fn the_extrapolated_lattice_has_three_levels_on_one_set_of_strips() {
        let w = Trapezoid::new(2.0, 0.0, 3.0, 0.6).unwrap();
        let l = Lattice::new(&w, LatticeSpec::default()).unwrap();
        assert_eq!(l.spec().spacing, Spacing::RootCosine);
        let sizes: Vec<usize> = l.grids().iter().map(|g| g.boxes.len()).collect();
        assert_eq!(sizes, [192, 96, 48, 96, 48, 24]);
        assert_eq!(l.grids()[1].boxes[0].y_c, l.grids()[0].boxes[0].y_c);
    }

    #[test]
    fn bad_lattices_are_errors() {
        let w = Trapezoid::rectangle(4.0, 1.0).unwrap();
        assert!(matches!(
            Lattice::new(&w, LatticeSpec::new(0, 4, Spacing::Uniform)),
            Err(LiftingSurfaceError::Lattice { .. })
        ));
        assert!(matches!(
            Lattice::new(
                &w,
                LatticeSpec::new(6, 4, Spacing::Uniform)
                    .with_extrapolation(Extrapolation::Richardson)
            ),
            Err(LiftingSurfaceError::Lattice { multiple: 4, .. })
        ));
        assert!(matches!(
            Lattice::new(&w, LatticeSpec::new(100, 100, Spacing::Uniform)),
            Err(LiftingSurfaceError::TooManyBoxes { .. })
        ));
    }
}
