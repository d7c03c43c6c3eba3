//! One Mach box solve per (wing, M, ω̄) per process, as the doublet
//! lattice's [`crate::lifting_surface::cache`]: keyed by the wing's shape
//! (a [`Trapezoid`] of root chord 1, [`crate::lifting_surface::cache::unit_wing`])
//! and the bits of M and ω̄, on the grid [`MachBoxSpec::for_wing`].
//! A hit takes a read lock and copies the [`Solution`]: no allocation.

use super::{MachBoxError, MachBoxSpec, OMEGA_BAR_QUASI_STEADY, solve};
use crate::geometry::Trapezoid;
use crate::lifting_surface::Solution;
use crate::memo::Memo;

/// Most entries before the cache starts afresh.
pub const CAPACITY: usize = 1 << 14;

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
    SOLUTIONS.get_or_solve(key, || {
        solve(wing, mach, omega_bar, MachBoxSpec::for_wing(wing, mach))
    })
}

/// How many solves the cache has made.
pub fn solves() -> usize {
    SOLUTIONS.solves()
}

/// Empties the cache (and zeroes [`solves`]).
pub fn clear() {
    SOLUTIONS.clear();
}
