//! The Mach box's solutions between Mach numbers: solved at a fixed set of
//! Mach numbers per wing ([`nodes`]) and interpolated — what a report or a
//! sweep over many Mach numbers uses instead of one Mach box solve per
//! Mach number (a near-sonic solve takes about a second: the grid
//! Δx = βΔy grows to [`crate::aerodynamics::lifting_surface::mach_box::MAX_ROWS`] rows as
//! β → 0).
//!
//! # The scheme, and why
//! The variable is β = √(M² − 1), in which the Mach box's grid and its
//! phases κM²/β² are written. Nodes are equally spaced in β on two pieces
//! that meet where the leading edge turns sonic, β = tan Λ (where the
//! loads' Mach derivative has the logarithm of E(k′) at k′ → 1 —
//! continuous, not smooth), so that no stencil spans it:
//! - from the first Mach box Mach number ([`super::mach_range::first_mach_box_mach`])
//!   to β = tan Λ, steps of at most [`STEP_SUBSONIC_EDGE`] (0.05): at the
//!   short period's ω̄ the unsteady numbers turn on a scale of about 0.2 in
//!   β there (the 45° delta's μ_α̇ at ω̄ = 0.5 swings by 13 % between
//!   β = 0.48 and 0.69);
//! - from there to M = 3, steps of at most [`STEP_SUPERSONIC_EDGE`] (0.1),
//!   where the solution is smooth and slowly varying.
//!
//! Between them, the piecewise-cubic Lagrange interpolation on the four
//! nodes of the piece around β (as [`super::frequency`] does in ω̄; fewer
//! where a piece has fewer), each node interpolated in ω̄ between the
//! frequency nodes ([`store::mach_box_interpolated`]).
//! Its slope gives the quasi-steady Mach derivatives of eqs (27)–(29):
//! d/dM = (M/β) d/dβ.
//!
//! # Accuracy (measured, `tests/it/mach_table.rs`)
//! Against direct Mach box solves at Mach numbers between the nodes on
//! the note's deltas and a cropped delta, ω̄ = 0 … 0.8: within 2·10⁻³ of
//! C_Lα in every number, most of it the frequency interpolation below
//! β = 0.3 (3.9·10⁻³ there, see
//! [`crate::aerodynamics::lifting_surface::store::INTERPOLATED_FROM_BETA`]).

use super::LiftingSurfaceError;
use super::derivatives::Extrapolate;
use super::mach_box::MAX_ROWS;
use super::solution::Solver;
use super::store;
use super::{OMEGA_BAR_QUASI_STEADY, Solution, Trapezoid};
use rayon::prelude::*;

/// The highest Mach number the dispatch takes.
pub const MACH_RANGE_MAX: f64 = 3.0;

/// The fewest strips the dispatch lets the Mach box use: at 32 strips
/// (extrapolated with 16) the supersonic-edged deltas are within 4·10⁻³ of
/// the exact reverse-flow values (`docs/supersonic-oscillatory.md`,
/// convergence table).
pub const MACH_BOX_MIN_STRIPS: usize = 32;

/// The first Mach number the dispatch gives to the Mach box: where its
/// grid holds [`MACH_BOX_MIN_STRIPS`] strips within [`MAX_ROWS`] rows
/// (rows = ⌈x_end(N − ½)/(βs)⌉, x_end the wing's aftmost point, s its
/// semi-span) and its trailing edge is supersonic (β ≥ tan|Λ_TE|, which
/// the method needs), whichever is the later.
pub fn first_mach_box_mach(wing: &Trapezoid) -> f64 {
    let x_end = wing
        .root_chord
        .max(wing.leading_edge_at(wing.semi_span) + wing.tip_chord);
    let n = MACH_BOX_MIN_STRIPS as f64 - 0.5;
    let grid = x_end * n / (MAX_ROWS as f64 * wing.semi_span);
    let trailing_edge = wing.sweep_te().tan().abs();
    let beta = grid.max(trailing_edge) * (1.0 + 1e-9);
    (1.0 + beta * beta).sqrt()
}

/// The largest step in β between nodes below the sonic leading edge.
pub const STEP_SUBSONIC_EDGE: f64 = 0.05;

/// The largest step in β between nodes past the sonic leading edge.
pub const STEP_SUPERSONIC_EDGE: f64 = 0.1;

/// One piece of equally spaced nodes in β: from `lo`, `steps` steps of `h`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Piece {
    lo: f64,
    h: f64,
    steps: usize,
}

impl Piece {
    fn new(lo: f64, hi: f64, largest: f64) -> Piece {
        let steps = ((hi - lo) / largest).ceil().max(1.0) as usize;
        Piece {
            lo,
            h: (hi - lo) / steps as f64,
            steps,
        }
    }

    fn hi(&self) -> f64 {
        self.lo + self.h * self.steps as f64
    }

    /// Node k's β (the last one exactly `hi`, so that both pieces share it).
    fn beta(&self, k: usize) -> f64 {
        if k == self.steps {
            self.hi()
        } else {
            self.lo + self.h * k as f64
        }
    }
}

/// The β of the table's ends: the first Mach box Mach number's and M = 3's.
fn ends(wing: &Trapezoid) -> (f64, f64) {
    let first = first_mach_box_mach(wing);
    (
        (first * first - 1.0).sqrt(),
        (MACH_RANGE_MAX * MACH_RANGE_MAX - 1.0).sqrt(),
    )
}

/// The wing's pieces: below and past β = tan Λ (one piece where the
/// leading edge is sonic before the table starts or after it ends).
fn pieces(wing: &Trapezoid) -> [Option<Piece>; 2] {
    let (lo, hi) = ends(wing);
    let edge = wing.sweep_le.tan();
    if edge > lo && edge < hi {
        [
            Some(Piece::new(lo, edge, STEP_SUBSONIC_EDGE)),
            Some(Piece::new(edge, hi, STEP_SUPERSONIC_EDGE)),
        ]
    } else if edge >= hi {
        [Some(Piece::new(lo, hi, STEP_SUBSONIC_EDGE)), None]
    } else {
        [None, Some(Piece::new(lo, hi, STEP_SUPERSONIC_EDGE))]
    }
}

/// The Mach numbers of the wing's nodes, in order (each once).
pub fn nodes(wing: &Trapezoid) -> Vec<f64> {
    let mut out: Vec<f64> = Vec::new();
    for p in pieces(wing).into_iter().flatten() {
        for k in 0..=p.steps {
            let m = mach_of(p.beta(k));
            if out.last() != Some(&m) {
                out.push(m);
            }
        }
    }
    out
}

fn mach_of(beta: f64) -> f64 {
    (1.0 + beta * beta).sqrt()
}

/// The stencil at β: its piece, first node and node count (2 to 4).
fn stencil(wing: &Trapezoid, beta: f64) -> Option<(Piece, usize, usize)> {
    let [a, b] = pieces(wing);
    let piece = match (a, b) {
        (Some(a), _) if beta <= a.hi() => a,
        (_, Some(b)) => b,
        (Some(a), None) => a,
        (None, None) => return None,
    };
    let n = (piece.steps + 1).min(4);
    let i = (((beta - piece.lo) / piece.h).floor().max(0.0) as usize).min(piece.steps - 1);
    let first = i.saturating_sub(1).min(piece.steps + 1 - n);
    Some((piece, first, n))
}

/// Lagrange's weight of node `m` of the `n` nodes from `first`, and the
/// weight's derivative in β, at β.
fn weight(piece: &Piece, first: usize, n: usize, m: usize, beta: f64) -> (f64, f64) {
    let x = |k: usize| piece.beta(first + k);
    let xm = x(m);
    let others = || (0..n).filter(move |&k| k != m);
    let value = others().map(|k| (beta - x(k)) / (xm - x(k))).product();
    let slope = others()
        .map(|j| {
            others()
                .filter(|&k| k != j)
                .map(|k| (beta - x(k)) / (xm - x(k)))
                .product::<f64>()
                / (xm - x(j))
        })
        .sum();
    (value, slope)
}

/// The wing's solution at `mach` (first Mach box Mach number ≤ M ≤ 3) and
/// ω̄, interpolated in the table, and its derivative in Mach number (a
/// steady stencil's nodes solved in parallel).
pub fn solution(
    wing: &Trapezoid,
    mach: f64,
    omega_bar: f64,
) -> Result<(Solution, Solution), LiftingSurfaceError> {
    let beta = (mach * mach - 1.0).max(0.0).sqrt();
    let Some((piece, first, n)) = stencil(wing, beta) else {
        let s = store::mach_box(wing, mach, omega_bar)?;
        return Ok((s, s.combine(&s, 0.0, 0.0)));
    };
    let dbeta_dmach = mach / beta;
    let node =
        |m: usize| store::mach_box_interpolated(wing, mach_of(piece.beta(first + m)), omega_bar);
    // a steady stencil's missing nodes solved in parallel first (into the
    // store); once stored, a lookup that allocates nothing
    let steady = omega_bar < OMEGA_BAR_QUASI_STEADY;
    let held = |m: usize| store::holds(Solver::MachBox, wing, mach_of(piece.beta(first + m)), 0.0);
    if steady && !(0..n).all(held) {
        (0..n).into_par_iter().for_each(|m| {
            let _ = node(m);
        });
    }
    let (w, dw) = weight(&piece, first, n, 0, beta);
    let s0 = node(0)?;
    let (mut value, mut slope) = (
        s0.combine(&s0, w, 0.0),
        s0.combine(&s0, dw * dbeta_dmach, 0.0),
    );
    for m in 1..n {
        let (w, dw) = weight(&piece, first, n, m, beta);
        let s = node(m)?;
        value = value.combine(&s, 1.0, w);
        slope = slope.combine(&s, 1.0, dw * dbeta_dmach);
    }
    let tag = |s: Solution| Solution {
        mach,
        omega_bar,
        ..s
    };
    Ok((tag(value), tag(slope)))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn delta(deg: f64) -> Trapezoid {
        super::super::store::unit_wing(4.0 / deg.to_radians().tan(), 0.0, deg.to_radians()).unwrap()
    }

    #[test]
    fn the_pieces_meet_at_the_sonic_edge_and_span_the_table() {
        for deg in [45.0_f64, 60.0, 20.0] {
            let wing = delta(deg);
            let ms = nodes(&wing);
            assert_eq!(ms[0], first_mach_box_mach(&wing));
            assert!((ms[ms.len() - 1] - MACH_RANGE_MAX).abs() < 1e-12);
            assert!(ms.windows(2).all(|w| w[1] > w[0]));
            let edge = mach_of(deg.to_radians().tan());
            let lo = (ms[0] * ms[0] - 1.0).sqrt();
            if deg.to_radians().tan() > lo {
                assert!(ms.iter().any(|&m| (m - edge).abs() < 1e-12), "{deg}");
            }
            let betas: Vec<f64> = ms.iter().map(|m| (m * m - 1.0).sqrt()).collect();
            let largest = betas.windows(2).map(|w| w[1] - w[0]).fold(0.0, f64::max);
            assert!(largest <= STEP_SUPERSONIC_EDGE + 1e-12);
        }
    }

    #[test]
    fn lagrange_weights_reproduce_a_cubic_and_its_slope() {
        let p = Piece::new(0.2, 1.0, 0.05);
        let f = |x: f64| 1.0 - 2.0 * x + 0.5 * x * x * x;
        let df = |x: f64| -2.0 + 1.5 * x * x;
        for beta in [0.2, 0.23, 0.61, 0.999, 1.0] {
            let i = (((beta - p.lo) / p.h).floor() as usize).min(p.steps - 1);
            let first = i.saturating_sub(1).min(p.steps - 3);
            let (mut v, mut d) = (0.0, 0.0);
            for m in 0..4 {
                let (w, dw) = weight(&p, first, 4, m, beta);
                v += w * f(p.beta(first + m));
                d += dw * f(p.beta(first + m));
            }
            assert!((v - f(beta)).abs() < 1e-13, "{beta}");
            assert!((d - df(beta)).abs() < 1e-11, "{beta}");
        }
    }
}
