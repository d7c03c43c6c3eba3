//! One Mach box solve per (wing, M, ω̄) per process, as the doublet
//! lattice's [`crate::aerodynamics::lifting_surface::cache`]: keyed by the wing's shape
//! (a [`Trapezoid`] of root chord 1, [`crate::aerodynamics::lifting_surface::cache::unit_wing`])
//! and the bits of M and ω̄, on the grid [`MachBoxSpec::for_wing`].
//! A hit takes a read lock and copies the [`Solution`]: no allocation.
//! [`solution_with`] with [`Harmonic::Interpolated`] interpolates between
//! the lattice's frequency nodes ([`frequency::NODES`], each solved once
//! here), as a sweep's frequency iteration does on the lattice's
//! [`crate::aerodynamics::lifting_surface::FrequencyTable`].

use super::{MachBoxError, MachBoxSpec, OMEGA_BAR_QUASI_STEADY, solve};
use crate::aerodynamics::lifting_surface::precomputed as frozen;
use crate::aerodynamics::lifting_surface::{Harmonic, Solution, frequency};
use crate::geometry::Trapezoid;
use crate::numerics::memo::Memo;

/// Most entries before the cache starts afresh.
pub const CAPACITY: usize = 1 << 14;

/// A solution's key: the wing's root chord, tip chord, semi-span and
/// leading-edge sweep, M and ω̄, as bits.
type Key = ([u64; 4], u64, u64);

static SOLUTIONS: Memo<Key, Result<Solution, MachBoxError>> = Memo::new(CAPACITY);

/// The solution of `wing` at (`mach`, `omega_bar`), from the cache or
/// solved into it.
pub fn solution(wing: &Trapezoid, mach: f64, omega_bar: f64) -> Result<Solution, MachBoxError> {
    let omega_bar = if (0.0..OMEGA_BAR_QUASI_STEADY).contains(&omega_bar) {
        0.0
    } else {
        omega_bar
    };
    let shape = [
        wing.root_chord,
        wing.tip_chord,
        wing.semi_span,
        wing.sweep_le,
    ]
    .map(f64::to_bits);
    let key = (shape, mach.to_bits(), omega_bar.to_bits());
    if let Some(s) = frozen::get(&(frozen::Kind::MachBox, key.0, key.1, key.2)) {
        return Ok(s);
    }
    SOLUTIONS.get_or_solve(key, || {
        solve(wing, mach, omega_bar, MachBoxSpec::for_wing(wing, mach))
    })
}

/// Every solution this process has solved (not those read from
/// [`frozen`]): part of what `cargo xtask tables` writes.
pub fn solved() -> Vec<(frozen::Key, Solution)> {
    SOLUTIONS
        .entries()
        .into_iter()
        .filter_map(|(k, v)| v.ok().map(|s| ((frozen::Kind::MachBox, k.0, k.1, k.2), s)))
        .collect()
}

/// Below this β = √(M² − 1) [`solution_with`] solves at every ω̄ instead
/// of interpolating: the Mach box's frequency dependence sharpens towards
/// M = 1 (its phases σx = κM²x/β²), and between the nodes the cubic was
/// measured 3.9·10⁻³ of C_Lα off at M = 1.03 (β = 0.25, ω̄ = 0.12) on the
/// 45° delta against 6.3·10⁻⁴ at M = 1.05 (β = 0.32)
/// (`tests/supersonic_oscillatory_cache.rs`).
pub const INTERPOLATED_FROM_BETA: f64 = 0.3;

/// The solution at (`mach`, `omega_bar`) solved there
/// ([`Harmonic::Direct`], [`solution`]) or interpolated
/// ([`Harmonic::Interpolated`], from β ≥ [`INTERPOLATED_FROM_BETA`]): the
/// piecewise-cubic Lagrange interpolation of the four [`frequency::NODES`]
/// around ω̄ ([`frequency::stencil`]), each node solved once; outside the
/// nodes (ω̄ ≤ 0.001 or > 4) solved there. Within 10⁻³ of C_Lα of the
/// direct solve on the note's deltas at M = 1.05–2.
pub fn solution_with(
    wing: &Trapezoid,
    mach: f64,
    omega_bar: f64,
    harmonic: Harmonic,
) -> Result<Solution, MachBoxError> {
    let interpolable = mach * mach - 1.0 >= INTERPOLATED_FROM_BETA * INTERPOLATED_FROM_BETA;
    let stencil = match harmonic {
        Harmonic::Interpolated if interpolable => frequency::stencil(omega_bar),
        _ => None,
    };
    let Some(at) = stencil else {
        return solution(wing, mach, omega_bar);
    };
    let out = frequency::combine_stencil(at, |k| solution(wing, mach, frequency::NODES[k]))?;
    Ok(Solution { omega_bar, ..out })
}

/// The Mach box's own frequency nodes from β = [`INTERPOLATED_FROM_BETA`]
/// on: the quasi-steady solution and the lattice's [`frequency::NODES`]
/// from 0.05, without their geometric run towards 0. There the lattice
/// needs it for the ω̄ ln ω̄ of subsonic flow; supersonic flow has none —
/// the Mach box's numbers go as c₀ + c₂ω̄² (measured: the 45° delta at
/// M = 1.3 and the 60° at M = 2, ω̄ = 0.001 to 0.1), which the cubic
/// through 0, 0.05, 0.1, 0.15 carries exactly.
pub const SUPERSONIC_NODES: [f64; 33] = [
    0.0, 0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4, //
    0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.1, 1.2, 1.3, 1.4, 1.5, 1.6, 1.7, 1.8, 1.9, 2.0, //
    2.25, 2.5, 2.75, 3.0, 3.25, 3.5, 3.75, 4.0,
];

/// The solution at (`mach`, `omega_bar`) interpolated between the four
/// frequency nodes around ω̄ at any M the Mach box takes (solved at ω̄
/// outside the nodes): on [`SUPERSONIC_NODES`] from β =
/// [`INTERPOLATED_FROM_BETA`], on the lattice's [`frequency::NODES`] (their
/// geometric run towards 0 following the quasi-steady logarithm's onset)
/// below — [`solution_with`]'s interpolation without its lower bound in β,
/// for [`crate::aerodynamics::lifting_surface::mach_table`], whose report- and
/// sweep-wide use states the error below β = 0.3.
pub fn interpolated(wing: &Trapezoid, mach: f64, omega_bar: f64) -> Result<Solution, MachBoxError> {
    let nodes: &[f64] = if mach * mach - 1.0 >= INTERPOLATED_FROM_BETA * INTERPOLATED_FROM_BETA {
        &SUPERSONIC_NODES
    } else {
        &frequency::NODES
    };
    let Some(at) = frequency::stencil_in(nodes, omega_bar) else {
        return solution(wing, mach, omega_bar);
    };
    let out = frequency::combine_stencil(at, |k| solution(wing, mach, nodes[k]))?;
    Ok(Solution { omega_bar, ..out })
}

/// How many solves the cache has made.
pub fn solves() -> usize {
    SOLUTIONS.solves()
}

/// Empties the cache (and zeroes [`solves`]).
pub fn clear() {
    SOLUTIONS.clear();
}
