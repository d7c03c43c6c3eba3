//! The lattice: the half wing divided into boxes, each with its doublet
//! line and collocation point (E. Albano and W.P. Rodden, AIAA J. 7(2),
//! 1969, §"Method").
//!
//! The half wing 0 ≤ y ≤ s of a [`Trapezoid`] is cut into spanwise strips,
//! and each strip into equal chordwise boxes (constant fractions of the
//! local chord), so that every box is a trapezoid with streamwise sides.
//! A box's doublet line is its quarter-chord line and its collocation
//! point is at three-quarters of its chord, mid-span (the "1/4–3/4 rule",
//! exact for the two-dimensional flat plate in steady flow). The other half
//! enters as the mirror image of each line (symmetric motions only).

use super::LiftingSurfaceError;
use super::doublet_line::DoubletLine;
use super::kernel::I1Approximation;
use crate::geometry::Trapezoid;
use serde::Serialize;
use std::f64::consts::PI;

/// How the strips' edges are spaced across the half-span.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Spacing {
    /// Equal strips.
    Uniform,
    /// Cosine spacing over the half-span, y = s(1 − cos θ)/2 for equal steps
    /// of θ in [0, π]: narrow strips at the root (the apex's kink) and at the
    /// tip (a side edge, where the load falls like √(s − y)).
    Cosine,
}

/// The lattice's density: boxes per strip, strips per half wing, and how
/// the strips are spaced.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct LatticeSpec {
    /// Chordwise boxes per strip.
    pub chordwise: usize,
    /// Strips on the half wing.
    pub spanwise: usize,
    pub spacing: Spacing,
    /// How the kernel's integral I₁ is approximated.
    pub kernel: I1Approximation,
}

impl Default for LatticeSpec {
    /// The default lattice (see `docs/damping-theories.md` for its
    /// convergence): 12 chordwise boxes on 16 cosine-spaced strips, 192
    /// boxes on the half wing.
    fn default() -> LatticeSpec {
        LatticeSpec {
            chordwise: 12,
            spanwise: 16,
            spacing: Spacing::Cosine,
            kernel: I1Approximation::Desmarais,
        }
    }
}

impl LatticeSpec {
    /// Fewest boxes per direction.
    pub const MIN: usize = 1;
    /// Most boxes on a half wing (the dense complex matrix of 4000² takes
    /// 256 MB).
    pub const MAX_BOXES: usize = 4000;

    /// A lattice with Desmarais' kernel approximation.
    pub fn new(chordwise: usize, spanwise: usize, spacing: Spacing) -> LatticeSpec {
        LatticeSpec {
            chordwise,
            spanwise,
            spacing,
            kernel: I1Approximation::Desmarais,
        }
    }

    /// The same lattice with another kernel approximation.
    pub fn with_kernel(self, kernel: I1Approximation) -> LatticeSpec {
        LatticeSpec { kernel, ..self }
    }

    /// The lattice with `factor` times as many boxes in each direction.
    pub fn scaled(self, factor: usize) -> LatticeSpec {
        LatticeSpec {
            chordwise: self.chordwise * factor,
            spanwise: self.spanwise * factor,
            ..self
        }
    }

    /// Boxes on the half wing.
    pub fn boxes(&self) -> usize {
        self.chordwise * self.spanwise
    }

    fn check(&self) -> Result<(), LiftingSurfaceError> {
        if self.chordwise < Self::MIN || self.spanwise < Self::MIN {
            return Err(LiftingSurfaceError::Lattice {
                chordwise: self.chordwise,
                spanwise: self.spanwise,
            });
        }
        if self.chordwise.saturating_mul(self.spanwise) > Self::MAX_BOXES {
            return Err(LiftingSurfaceError::TooManyBoxes {
                boxes: self.chordwise.saturating_mul(self.spanwise),
                max: Self::MAX_BOXES,
            });
        }
        Ok(())
    }

    /// The strips' edges, 0 = y₀ < y₁ < … < y_n = s.
    fn strip_edges(&self, s: f64) -> Vec<f64> {
        let n = self.spanwise;
        (0..=n)
            .map(|k| {
                let t = k as f64 / n as f64;
                match self.spacing {
                    Spacing::Uniform => s * t,
                    Spacing::Cosine => 0.5 * s * (1.0 - (PI * t).cos()),
                }
            })
            .map(|y| y.clamp(0.0, s))
            .collect()
    }
}

/// One box of the half wing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Box {
    /// Its doublet line (quarter-chord line).
    pub line: DoubletLine,
    /// Collocation point (three-quarter chord, mid-span).
    pub x_c: f64,
    pub y_c: f64,
    /// Area.
    pub area: f64,
}

/// A wing's lattice: geometry only, reusable for any Mach number and
/// frequency.
#[derive(Debug, Clone, PartialEq)]
pub struct Lattice {
    wing: Trapezoid,
    spec: LatticeSpec,
    boxes: Vec<Box>,
}

impl Lattice {
    /// The lattice of `wing` at density `spec`.
    pub fn new(wing: &Trapezoid, spec: LatticeSpec) -> Result<Lattice, LiftingSurfaceError> {
        spec.check()?;
        let edges = spec.strip_edges(wing.semi_span);
        let n = spec.chordwise as f64;
        let mut boxes = Vec::with_capacity(spec.boxes());
        for pair in edges.windows(2) {
            let (y0, y1) = (pair[0], pair[1]);
            let (ym, e) = (0.5 * (y0 + y1), 0.5 * (y1 - y0));
            let (c0, c1, cm) = (wing.chord_at(y0), wing.chord_at(y1), wing.chord_at(ym));
            let (l0, l1, lm) = (
                wing.leading_edge_at(y0),
                wing.leading_edge_at(y1),
                wing.leading_edge_at(ym),
            );
            for k in 0..spec.chordwise {
                let f = (k as f64 + 0.25) / n;
                let (xa, xb) = (l0 + f * c0, l1 + f * c1);
                boxes.push(Box {
                    line: DoubletLine {
                        xi: 0.5 * (xa + xb),
                        eta: ym,
                        e,
                        tan_sweep: (xb - xa) / (2.0 * e),
                        chord: cm / n,
                    },
                    x_c: lm + (k as f64 + 0.75) / n * cm,
                    y_c: ym,
                    area: (y1 - y0) * (c0 + c1) / (2.0 * n),
                });
            }
        }
        Ok(Lattice {
            wing: *wing,
            spec,
            boxes,
        })
    }

    pub fn wing(&self) -> &Trapezoid {
        &self.wing
    }

    pub fn spec(&self) -> LatticeSpec {
        self.spec
    }

    pub fn boxes(&self) -> &[Box] {
        &self.boxes
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_boxes_tile_the_half_wing() {
        let w = Trapezoid::new(2.0, 0.5, 3.0, 0.6).unwrap();
        for spacing in [Spacing::Uniform, Spacing::Cosine] {
            let l = Lattice::new(&w, LatticeSpec::new(5, 7, spacing)).unwrap();
            let area: f64 = l.boxes().iter().map(|b| b.area).sum();
            assert!((area - w.area() / 2.0).abs() < 1e-12);
            // first moment of area about the apex: ∫(x_le + c/2)c dy
            for b in l.boxes() {
                assert!(b.y_c > 0.0 && b.y_c < w.semi_span);
                let le = w.leading_edge_at(b.y_c);
                assert!(b.x_c > le && b.x_c < le + w.chord_at(b.y_c));
                // the collocation point is half a box chord behind the line
                let x_line = b.line.xi + (b.y_c - b.line.eta) * b.line.tan_sweep;
                assert!((b.x_c - x_line - 0.5 * b.line.chord).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn bad_lattices_are_errors() {
        let w = Trapezoid::rectangle(4.0, 1.0).unwrap();
        assert!(matches!(
            Lattice::new(&w, LatticeSpec::new(0, 4, Spacing::Uniform)),
            Err(LiftingSurfaceError::Lattice { .. })
        ));
        assert!(matches!(
            Lattice::new(&w, LatticeSpec::new(100, 100, Spacing::Uniform)),
            Err(LiftingSurfaceError::TooManyBoxes { .. })
        ));
    }
}
