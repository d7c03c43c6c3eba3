//! The subsonic aerodynamics of a whole configuration from one doublet
//! lattice over all its surfaces: the wing, the
//! tailplane and the foreplane each cut into boxes as the wing's own
//! lattice is ([`crate::aerodynamics::lifting_surface`], each surface at
//! [`LatticeSpec::for_wing`] of its planform), all solved together, so
//! that every surface's load includes the others' influence — the wing's
//! downwash at the tail and its lag (the tail's share of z_ẇ and m_ẇ), the
//! foreplane's upwash and downwash on the wing.
//!
//! # Method
//! E. Albano and W.P. Rodden's doublet lattice (AIAA J. 7(2), 1969) over
//! several surfaces. The surfaces are flat, horizontal and parallel (no
//! dihedral), each at its own height z; symmetric motions only (the half
//! configuration and the mirror image of every box). A box's influence:
//! - on its own surface: exactly the wing lattice's (the same assembly, so
//!   a configuration of the wing alone is [`Lattice::solve`](crate::aerodynamics::lifting_surface::Lattice::solve) to rounding);
//! - on another surface in the same plane: the planar doublet line
//!   ([`crate::aerodynamics::lifting_surface::doublet_line`]), pair by pair;
//! - on a surface at a vertical distance z₀: the steady part from the
//!   horseshoe vortex in three dimensions (Biot–Savart with the
//!   Prandtl–Glauert stretching x/β) and the oscillatory increment of
//!   Landahl's non-planar kernel, K₁ and K₂ (M.T. Landahl, AIAA J. 5(5),
//!   1967), integrated across the line by Rodden, Taylor & McIntosh's
//!   quartic (J. Aircraft 35(5), 1998): see [`nonplanar`]. It tends
//!   continuously to the planar line as z₀ → 0 (tested).
//!
//! A surface no wider than the wing and nearer its plane than the width of
//! its strips lies in the wing's discrete wake: its strips are then the
//! wing's within its span, so that the wing's trailing legs lie on its
//! strip edges and never beside its collocation points (`layout.rs`, AVL's
//! advice for a tail behind a wing); otherwise each surface has strips of
//! its own ([`LatticeSpec::for_wing`] of its planform).
//!
//! The right-hand sides are the wing lattice's: unit incidence (normalwash
//! 1 on every surface) and unit pitch rate about the wing M.A.C.'s leading
//! edge, normalwash (x − x̄)/c̄ with x from the wing's apex — so every number
//! is on the wing's area S and M.A.C. c̄, moments about the wing M.A.C.'s
//! leading edge, ω̄ = ωc̄/V. At ω̄ = 0 the quasi-steady limit is exact (the
//! kernel's first-order term in frequency, as [`Lattice::solve`](crate::aerodynamics::lifting_surface::Lattice::solve)); the
//! extrapolation is the wing lattice's (Richardson's, over the same three
//! chordwise densities and two strip counts on every surface).
//!
//! Each part's [`Solution`] is the force on its own boxes; they sum to the
//! total. A surface of zero area (zero semi-span or chords) is absent. The
//! body (if any) is not in the lattice: its contribution (eq 43) is the
//! caller's to add.
//!
//! # Limits
//! Those of the wing lattice; a surface needs boxes short against the
//! wavelength (Δx·ω/V ≲ 0.5), which 12 boxes per chord give for
//! ω̄ ≲ 2c̄/c_r of each surface. Surfaces in one plane must not overlap in
//! plan (an error names them); surfaces very close in height over one
//! another need strips narrow against their distance. A tailplane in the
//! wing's plane, in its wake, converges in the strips at order ≈ 1 (not
//! the order 2 the default's strip extrapolation assumes): there the
//! default lattice lies 0.32 % (C_Lα), 1.1 % (z_q), 2.3 % (m_q) and
//! 0.0072c̄ (neutral point) from the converged answer, which this lattice's
//! own extrapolation at the observed orders and AVL's (with its surfaces
//! one component: no finite vortex cores between them) share to 0.31 % and
//! 0.0022c̄ (`tests/it/configuration_lattice_avl.rs`).
//!
//! # Checks
//! `tests/it/configuration_lattice*.rs` and `tests/it/configuration_tail_volume.rs`:
//! the wing alone is the wing's lattice to rounding; a tail far above is
//! the two isolated surfaces; the non-planar kernel tends to the planar one
//! as z → 0; panelaero's non-planar doublet lattice on the same boxes to
//! 0.001 % (M = 0.5, ω̄ = 0.3 and M = 0, ω̄ = 0.6); AVL within 0.35 % (tail
//! above, foreplane) and within 2.3 % and 0.007c̄ of AVL's extrapolation
//! (coplanar tail); the tail-volume formulas for m_q and m_ẇ within 4 %.

mod assemble;
mod layout;
pub mod nonplanar;

use super::{ConfigurationSolution, Contribution};
use crate::aerodynamics::lifting_surface::derivatives::Extrapolate;
use crate::aerodynamics::lifting_surface::kernel::KernelFlow;
use crate::aerodynamics::lifting_surface::solve::{check_mach, complex_solve};
use crate::aerodynamics::lifting_surface::{
    LatticeSpec, LiftingSurfaceError, OMEGA_BAR_QUASI_STEADY, Solution,
};
use crate::geometry::Trapezoid;
use crate::geometry::configuration::{Configuration, Part};
use layout::{Block, Member};
use nalgebra::{DMatrix, Dyn, LU};
use rayon::prelude::*;

/// A configuration's lattice: every surface's boxes, reusable for any Mach
/// number and frequency.
#[derive(Debug, Clone)]
pub struct ConfigurationLattice {
    wing: Trapezoid,
    spec: LatticeSpec,
    members: Vec<Member>,
}

impl ConfigurationLattice {
    /// The lattice of `cfg`, each surface at [`LatticeSpec::for_wing`] of
    /// its own planform.
    pub fn new(cfg: &Configuration) -> Result<ConfigurationLattice, ConfigurationError> {
        ConfigurationLattice::with_spec(cfg, LatticeSpec::for_wing)
    }

    /// The lattice of `cfg` with each surface at `spec_for` of its planform
    /// (every surface must have the same chordwise boxes and extrapolation;
    /// the wing's kernel and line rule serve all).
    pub fn with_spec(
        cfg: &Configuration,
        spec_for: impl Fn(&Trapezoid) -> LatticeSpec,
    ) -> Result<ConfigurationLattice, ConfigurationError> {
        let members = layout::members(cfg, spec_for)?;
        Ok(ConfigurationLattice {
            wing: cfg.wing,
            spec: members[0].lattice.spec(),
            members,
        })
    }

    /// The parts in the lattice (the wing first; absent surfaces left out).
    pub fn parts(&self) -> Vec<Part> {
        self.members.iter().map(|m| m.part).collect()
    }

    /// Boxes on the half configuration (of the finest lattice).
    pub fn boxes(&self) -> usize {
        self.members.iter().map(|m| m.lattice.boxes().len()).sum()
    }

    /// The response at Mach `mach` (0 ≤ M < 1) and ω̄ = ωc̄/V ≥ 0 (c̄ the
    /// wing's M.A.C.), extrapolated as the wing's lattice is.
    pub fn solve(
        &self,
        mach: f64,
        omega_bar: f64,
    ) -> Result<ConfigurationSolution, ConfigurationError> {
        check_mach(mach)?;
        if !(omega_bar.is_finite() && omega_bar >= 0.0) {
            return Err(LiftingSurfaceError::Frequency(omega_bar).into());
        }
        let used = layout::levels_solved(self.members[0].lattice.grids().len());
        let solve = |k: usize| -> Result<Parts, ConfigurationError> {
            let blocks: Vec<Block> = self.members.iter().map(|m| m.block(k)).collect();
            if omega_bar < OMEGA_BAR_QUASI_STEADY {
                self.quasi_steady(&blocks, mach)
            } else {
                self.harmonic(&blocks, mach, omega_bar)
            }
        };
        // the levels the extrapolation uses, solved side by side
        let solved: Vec<Parts> = (0..used)
            .into_par_iter()
            .map(solve)
            .collect::<Result<_, _>>()?;
        let chordwise = |k: usize| match used {
            1 => solved[k].clone(),
            _ => solved[k].richardson(&solved[k + 1], &solved[k + 2]),
        };
        let parts = if used < 6 {
            chordwise(0)
        } else {
            chordwise(0).combine(&chordwise(3), 4.0 / 3.0, -1.0 / 3.0)
        };
        self.finish(parts)
    }

    /// The total as the sum of the parts, every number checked finite.
    fn finish(&self, parts: Parts) -> Result<ConfigurationSolution, ConfigurationError> {
        let mut total = parts.0[0];
        for p in &parts.0[1..] {
            total = total.combine(p, 1.0, 1.0);
        }
        let all = std::iter::once(&total).chain(&parts.0);
        let finite = all.into_iter().all(|s| {
            [
                s.lift_alpha,
                s.moment_alpha,
                s.lift_alphadot,
                s.moment_alphadot,
                s.lift_q,
                s.moment_q,
            ]
            .iter()
            .all(|v| v.is_finite())
        });
        if !finite || total.lift_alpha == 0.0 {
            return Err(LiftingSurfaceError::NotFinite {
                mach: total.mach,
                omega_bar: total.omega_bar,
            }
            .into());
        }
        Ok(ConfigurationSolution {
            total,
            parts: self
                .members
                .iter()
                .zip(parts.0)
                .map(|(m, solution)| Contribution {
                    part: m.part,
                    solution,
                })
                .collect(),
        })
    }

    /// The right-hand sides: unit incidence, and unit rate (x − x̄)/c̄.
    fn normalwash(&self, blocks: &[Block]) -> DMatrix<f64> {
        let (x_mac, mac) = (self.wing.x_mac(), self.wing.mac());
        let xs: Vec<f64> = blocks
            .iter()
            .flat_map(|b| b.grid.boxes.iter().map(|b| b.x_c))
            .collect();
        DMatrix::from_fn(xs.len(), 2, |i, col| match col {
            0 => 1.0,
            _ => (xs[i] - x_mac) / mac,
        })
    }

    /// Each member's C_L and C_m (on the wing's S and c̄, about the wing
    /// M.A.C.'s leading edge) of the pressures `f` (in block order).
    fn loads<T>(&self, blocks: &[Block], f: impl Fn(usize) -> T) -> Vec<(T, T)>
    where
        T: Copy + std::ops::Mul<f64, Output = T> + std::ops::Add<Output = T> + Default,
    {
        let (x_mac, mac) = (self.wing.x_mac(), self.wing.mac());
        let half_area = 0.5 * self.wing.area();
        let mut i = 0;
        blocks
            .iter()
            .map(|b| {
                let (mut lift, mut moment) = (T::default(), T::default());
                for bx in &b.grid.boxes {
                    let a = bx.area / half_area;
                    lift = lift + f(i) * a;
                    moment = moment + f(i) * (-a * (bx.line.xi - x_mac) / mac);
                    i += 1;
                }
                (lift, moment)
            })
            .collect()
    }

    fn harmonic(
        &self,
        blocks: &[Block],
        mach: f64,
        omega_bar: f64,
    ) -> Result<Parts, ConfigurationError> {
        let flow = KernelFlow::new(mach, omega_bar / self.wing.mac(), self.spec.kernel);
        let d = assemble::harmonic(blocks, &flow, self.spec.line_rule);
        let f = complex_solve(&d, &self.normalwash(blocks));
        let alpha = self.loads(blocks, |i| f[(i, 0)]);
        let rate = self.loads(blocks, |i| f[(i, 1)]);
        Ok(Parts(
            alpha
                .iter()
                .zip(&rate)
                .map(|((l1, m1), (l2, m2))| Solution {
                    mach,
                    omega_bar,
                    lift_alpha: l1.re,
                    moment_alpha: m1.re,
                    lift_alphadot: l1.im / omega_bar,
                    moment_alphadot: m1.im / omega_bar,
                    lift_q: l2.re,
                    moment_q: m2.re,
                })
                .collect(),
        ))
    }

    /// D₀f₀ = w̄, D₀f₁ = −D₁f₀ (as [`Lattice::solve`](crate::aerodynamics::lifting_surface::Lattice::solve) at ω̄ = 0).
    fn quasi_steady(&self, blocks: &[Block], mach: f64) -> Result<Parts, ConfigurationError> {
        let beta2 = 1.0 - mach * mach;
        let singular = LiftingSurfaceError::Singular {
            mach,
            omega_bar: 0.0,
        };
        let lu: LU<f64, Dyn, Dyn> = assemble::steady(blocks, beta2.sqrt()).lu();
        let f0 = lu.solve(&self.normalwash(blocks)).ok_or(singular.clone())?;
        let d1 = assemble::first_order(blocks, beta2, self.spec.line_rule) / self.wing.mac();
        let f1 = lu.solve(&(-(d1 * f0.column(0)))).ok_or(singular)?;
        let alpha = self.loads(blocks, |i| f0[(i, 0)]);
        let alphadot = self.loads(blocks, |i| f1[i]);
        let rate = self.loads(blocks, |i| f0[(i, 1)]);
        Ok(Parts(
            (0..alpha.len())
                .map(|k| Solution {
                    mach,
                    omega_bar: 0.0,
                    lift_alpha: alpha[k].0,
                    moment_alpha: alpha[k].1,
                    lift_alphadot: alphadot[k].0,
                    moment_alphadot: alphadot[k].1,
                    lift_q: rate[k].0,
                    moment_q: rate[k].1,
                })
                .collect(),
        ))
    }
}

/// Each member's solution at one level, in member order.
#[derive(Debug, Clone)]
struct Parts(Vec<Solution>);

impl Extrapolate for Parts {
    fn combine(&self, other: &Parts, a: f64, b: f64) -> Parts {
        Parts(
            self.0
                .iter()
                .zip(&other.0)
                .map(|(x, y)| x.combine(y, a, b))
                .collect(),
        )
    }

    /// Checked as a whole by the caller.
    fn checked(self) -> Result<Parts, LiftingSurfaceError> {
        Ok(self)
    }
}

/// Why a configuration has no solution.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ConfigurationError {
    #[error(transparent)]
    LiftingSurface(#[from] super::LiftingSurfaceError),
    #[error("{0}")]
    Geometry(String),
}
