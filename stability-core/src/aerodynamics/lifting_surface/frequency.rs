//! A wing's harmonic solutions between frequencies: solved at a fixed set
//! of ω̄ ([`NODES`]), each node on first use, and interpolated — what a
//! sweep's frequency iteration uses instead of one solve per iterate
//! (`sweep --damping lifting-surface-frequency`; the store's
//! [`super::Harmonic::Interpolated`]). [`FrequencyTable`] does the same for
//! a lattice of the caller's own boxes.
//!
//! # The scheme, and why
//! Measured on the note's deltas, a cropped delta and a trapezoid of A = 8
//! at M = 0–0.9 (`examples/lifting_surface_interpolation.rs`, tabled in
//! `docs/damping-theories.md`): the six numbers of a [`Solution`] are smooth
//! in ω̄ but for the α̇ pair, whose second derivative grows like 1/ω̄ towards
//! ω̄ = 0 (the kernel's ω̄ ln ω̄ term: linear theory's, and Desmarais'
//! approximation keeps it), and they change on the scale ω̄ ≈ 0.5 at
//! M = 0.8–0.9. Hence nodes geometric (ratio 2) from 0.001 to 0.064, where
//! only the logarithm matters, then spaced 0.05 up to 0.4, 0.1 up to 2 and
//! 0.25 up to 4; and piecewise-cubic Lagrange interpolation on the four
//! nodes around ω̄ (J.L. Lagrange's formula; the stencil centred on the
//! interval, shifted at the ends): continuous, exact at the nodes, with an
//! error O(h⁴f⁗) that the geometric spacing keeps uniform near 0.
//!
//! # Limits, and what is returned outside the nodes
//! - ω̄ < [`OMEGA_BAR_QUASI_STEADY`]: the quasi-steady solution, as
//!   [`Lattice::solve`] returns there;
//! - below the first node (0.001): the first node's values (the α̇ numbers
//!   change there by ~10⁻⁵ of themselves);
//! - beyond the last (ω̄ > 4): a direct solve (allocating; the lattice itself
//!   resolves ω̄ ≲ 2 on the note's wings, see the module's limits).
//!
//! Only the nodes an iteration visits are solved (each at most once, by one
//! thread; others wait for it): a sweep whose short periods lie in
//! 0.1 < ω̄ < 0.4 solves about nine.

use super::derivatives::Extrapolate;
use super::{Lattice, LiftingSurfaceError, OMEGA_BAR_QUASI_STEADY, Solution};
use std::sync::OnceLock;

/// The frequencies ω̄ at which the table solves the lattice.
pub const NODES: [f64; 38] = [
    0.001, 0.002, 0.004, 0.008, 0.016, 0.032, 0.064, //
    0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4, //
    0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.1, 1.2, 1.3, 1.4, 1.5, 1.6, 1.7, 1.8, 1.9, 2.0, //
    2.25, 2.5, 2.75, 3.0, 3.25, 3.5, 3.75, 4.0,
];

type Slot = OnceLock<Result<Solution, LiftingSurfaceError>>;

/// One wing's lattice at one Mach number, solved at [`NODES`] on demand.
#[derive(Debug)]
pub struct FrequencyTable {
    lattice: Lattice,
    mach: f64,
    quasi_steady: Slot,
    nodes: [Slot; NODES.len()],
}

impl FrequencyTable {
    /// The table of `lattice` at Mach `mach` (0 ≤ M < 1); nothing is solved
    /// yet.
    pub fn new(lattice: Lattice, mach: f64) -> Result<FrequencyTable, LiftingSurfaceError> {
        if !(mach.is_finite() && (0.0..1.0).contains(&mach)) {
            return Err(LiftingSurfaceError::Mach(mach));
        }
        Ok(FrequencyTable {
            lattice,
            mach,
            quasi_steady: OnceLock::new(),
            nodes: std::array::from_fn(|_| OnceLock::new()),
        })
    }

    pub fn mach(&self) -> f64 {
        self.mach
    }

    /// The solution at node `k`, solved on first use.
    pub fn node(&self, k: usize) -> Result<Solution, LiftingSurfaceError> {
        self.nodes[k]
            .get_or_init(|| self.lattice.solve(self.mach, NODES[k]))
            .clone()
    }

    /// How many nodes have been solved.
    pub fn solved(&self) -> usize {
        self.nodes.iter().filter(|n| n.get().is_some()).count()
    }

    /// The solution at `omega_bar`, interpolated (see the module's
    /// documentation for what is returned outside the nodes).
    /// Allocation-free once the nodes it needs are solved.
    pub fn at(&self, omega_bar: f64) -> Result<Solution, LiftingSurfaceError> {
        if !(omega_bar.is_finite() && omega_bar >= 0.0) {
            return Err(LiftingSurfaceError::Frequency(omega_bar));
        }
        if omega_bar < OMEGA_BAR_QUASI_STEADY {
            let qs = self
                .quasi_steady
                .get_or_init(|| self.lattice.solve(self.mach, 0.0));
            return qs.clone();
        }
        let last = NODES.len() - 1;
        if omega_bar > NODES[last] {
            return self.lattice.solve(self.mach, omega_bar);
        }
        if omega_bar <= NODES[0] {
            return Ok(Solution {
                omega_bar,
                ..self.node(0)?
            });
        }
        let at = stencil(omega_bar).ok_or(LiftingSurfaceError::Frequency(omega_bar))?;
        let out = combine_stencil(at, |k| self.node(k))?;
        Ok(Solution { omega_bar, ..out })
    }
}

/// The interpolation's stencil at `omega_bar`: the first of its four nodes,
/// j, and the weights of nodes j … j + 3 — for `NODES[0] < ω̄ ≤ NODES[last]`
/// (`None` outside). Any solution tabled at [`NODES`] (a configuration's,
/// `crate::aerodynamics::lifting_surface::configuration::cache`) is interpolated with it.
pub fn stencil(omega_bar: f64) -> Option<(usize, [f64; 4])> {
    stencil_in(&NODES, omega_bar)
}

/// [`stencil`] on the increasing `nodes` (at least four).
pub fn stencil_in(nodes: &[f64], omega_bar: f64) -> Option<(usize, [f64; 4])> {
    if !(omega_bar > nodes[0] && omega_bar <= nodes[nodes.len() - 1]) {
        return None;
    }
    // nodes[i] < ω̄ ≤ nodes[i + 1]; the stencil i − 1 … i + 2, shifted
    let i = nodes.partition_point(|&w| w < omega_bar) - 1;
    let j = i.saturating_sub(1).min(nodes.len() - 4);
    Some((j, [0, 1, 2, 3].map(|m| lagrange(nodes, j, m, omega_bar))))
}

/// Σₘ wₘ·node(j + m): the solutions at the stencil's four nodes
/// ([`stencil`]) combined with its weights; `node(k)` gives the solution
/// at `NODES[k]` (the lattice's table, the Mach box's cache).
pub(crate) fn combine_stencil<E>(
    (j, w): (usize, [f64; 4]),
    node: impl Fn(usize) -> Result<Solution, E>,
) -> Result<Solution, E> {
    let mut out = node(j)?.combine(&node(j + 1)?, w[0], w[1]);
    for (m, &wm) in w.iter().enumerate().skip(2) {
        out = out.combine(&node(j + m)?, 1.0, wm);
    }
    Ok(out)
}

/// The weight of node j + m in the cubic through nodes j … j + 3 at x.
fn lagrange(nodes: &[f64], j: usize, m: usize, x: f64) -> f64 {
    let xm = nodes[j + m];
    (0..4)
        .filter(|&k| k != m)
        .map(|k| (x - nodes[j + k]) / (xm - nodes[j + k]))
        .product()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_weights_reproduce_cubics() {
        for j in [0, 5, 20, NODES.len() - 4] {
            let x = 0.5 * (NODES[j + 1] + NODES[j + 2]);
            for p in 0..4 {
                let s: f64 = (0..4)
                    .map(|m| lagrange(&NODES, j, m, x) * NODES[j + m].powi(p))
                    .sum();
                assert!((s - x.powi(p)).abs() < 1e-12 * (1.0 + x.powi(p)), "{j} {p}");
            }
        }
    }

    #[test]
    fn nodes_increase() {
        assert!(NODES.windows(2).all(|w| w[0] < w[1]));
        const { assert!(NODES[0] > OMEGA_BAR_QUASI_STEADY) };
    }
}
