//! One Mach box solve per (wing, M, ω̄) per process, as the doublet
//! lattice's [`crate::lifting_surface::cache`]: keyed by the wing's shape
//! (a [`Trapezoid`] of root chord 1, [`crate::lifting_surface::cache::unit_wing`])
//! and the bits of M and ω̄, on the grid [`MachBoxSpec::for_wing`].
//! A hit takes a read lock and copies the [`Solution`]: no allocation.

use super::{MachBoxError, MachBoxSpec, OMEGA_BAR_QUASI_STEADY, solve};
use crate::geometry::Trapezoid;
use crate::lifting_surface::Solution;
use std::collections::HashMap;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, OnceLock, PoisonError, RwLock};

/// Most entries before the cache starts afresh.
pub const CAPACITY: usize = 1 << 14;

type Key = ([u64; 4], u64, u64);
type Slot = Arc<OnceLock<Result<Solution, MachBoxError>>>;

fn map() -> &'static RwLock<HashMap<Key, Slot>> {
    static MAP: OnceLock<RwLock<HashMap<Key, Slot>>> = OnceLock::new();
    MAP.get_or_init(Default::default)
}

static SOLVES: AtomicUsize = AtomicUsize::new(0);

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
    let read = map().read().unwrap_or_else(PoisonError::into_inner);
    if let Some(done) = read.get(&key).and_then(|slot| slot.get()) {
        return done.clone();
    }
    drop(read);
    let slot = {
        let mut write = map().write().unwrap_or_else(PoisonError::into_inner);
        if write.len() >= CAPACITY && !write.contains_key(&key) {
            write.clear();
        }
        write.entry(key).or_default().clone()
    };
    slot.get_or_init(|| {
        SOLVES.fetch_add(1, Ordering::SeqCst);
        solve(wing, mach, omega_bar, MachBoxSpec::for_wing(wing, mach))
    })
    .clone()
}

/// How many solves the cache has made.
pub fn solves() -> usize {
    SOLVES.load(Ordering::SeqCst)
}

/// Empties the cache (and zeroes [`solves`]).
pub fn clear() {
    map()
        .write()
        .unwrap_or_else(PoisonError::into_inner)
        .clear();
    SOLVES.store(0, Ordering::SeqCst);
}
