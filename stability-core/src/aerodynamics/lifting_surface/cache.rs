//! One solve per (wing, Mach number, ω̄): a process-wide cache of the
//! lattice's solutions, so that the design points of a sweep, a study or a
//! frequency iteration that share a wing and a flight condition share its
//! solve — whatever their c.g., μ₁ or i_B (axis transfer and eqs 2–4 need
//! no new solve).
//!
//! Keyed by the wing's shape (a [`Trapezoid`] of root chord 1, so that
//! [`unit_wing`]'s three numbers name it; the derivatives do not depend on
//! scale) and the bits of M and ω̄. Each entry is solved once, by the first
//! thread to ask; others asking meanwhile wait for it. A hit takes a read
//! lock and copies six numbers: no allocation. The cache holds at most
//! [`CAPACITY`] entries of each kind and starts afresh beyond; [`clear`]
//! empties it (benchmarks that must pay for their solves).

use super::frequency::FrequencyTable;
use super::{Lattice, LatticeSpec, LiftingSurfaceError, OMEGA_BAR_QUASI_STEADY, Solution, Steady};
use crate::geometry::Trapezoid;
use std::collections::HashMap;
use std::hash::Hash;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, OnceLock, PoisonError, RwLock};

/// How a harmonic solution (ω̄ > 0) is had.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Harmonic {
    /// Solved at the ω̄ asked for (and cached at it).
    #[default]
    Direct,
    /// Interpolated in the wing's [`FrequencyTable`] at that Mach number:
    /// for a frequency iteration at many design points (a sweep), where
    /// every point's ω̄ differs.
    Interpolated,
}

/// Most entries of each kind (solutions, steady solutions, tables).
pub const CAPACITY: usize = 1 << 14;

/// The wing of aspect ratio A, taper λ and leading-edge sweep Λ (rad) with
/// root chord 1: the shape the cache is keyed by.
pub fn unit_wing(
    aspect_ratio: f64,
    taper: f64,
    sweep_le: f64,
) -> Result<Trapezoid, LiftingSurfaceError> {
    Trapezoid::from_aspect_ratio(aspect_ratio, taper, sweep_le, 1.0)
        .map_err(|e| LiftingSurfaceError::Planform(e.to_string()))
}

/// The solution of `wing` at (`mach`, `omega_bar`), from the cache or solved
/// into it (at the default lattice, [`LatticeSpec::for_wing`]).
pub fn solution(
    wing: &Trapezoid,
    mach: f64,
    omega_bar: f64,
    harmonic: Harmonic,
) -> Result<Solution, LiftingSurfaceError> {
    check(mach, omega_bar)?;
    let c = cache();
    if harmonic == Harmonic::Interpolated && omega_bar >= OMEGA_BAR_QUASI_STEADY {
        return table(wing, mach)?.at(omega_bar);
    }
    let omega_bar = if omega_bar < OMEGA_BAR_QUASI_STEADY {
        0.0
    } else {
        omega_bar
    };
    let key = (shape(wing), mach.to_bits(), omega_bar.to_bits());
    get_or_solve(&c.solutions, key, || lattice(wing)?.solve(mach, omega_bar))
}

/// The steady solution of `wing` at `mach` with its Mach derivatives
/// ([`Lattice::solve_steady`]), from the cache or solved into it; its
/// quasi-steady [`Solution`] serves [`solution`] at ω̄ = 0 too.
pub fn steady(wing: &Trapezoid, mach: f64) -> Result<Steady, LiftingSurfaceError> {
    check(mach, 0.0)?;
    let c = cache();
    let key = (shape(wing), mach.to_bits());
    let s = get_or_solve(&c.steady, key, || lattice(wing)?.solve_steady(mach))?;
    // the same numbers `solve(M, 0)` gives, bit for bit
    slot(&c.solutions, (key.0, key.1, 0f64.to_bits())).get_or_init(|| Ok(s.solution));
    Ok(s)
}

/// The frequency table of `wing` at `mach`, from the cache or made (its
/// nodes are solved as they are asked for).
pub fn table(wing: &Trapezoid, mach: f64) -> Result<Arc<FrequencyTable>, LiftingSurfaceError> {
    check(mach, 0.0)?;
    table_in(&cache().tables, wing, mach, lattice)
}

/// The table of `wing`'s lattice (made by `make`) at `mach` in `map`, made
/// if it is not there (its nodes are solved as they are asked for).
fn table_in(
    map: &RwLock<HashMap<(Shape, u64), Arc<FrequencyTable>>>,
    wing: &Trapezoid,
    mach: f64,
    make: impl FnOnce(&Trapezoid) -> Result<Lattice, LiftingSurfaceError>,
) -> Result<Arc<FrequencyTable>, LiftingSurfaceError> {
    table_made_in(map, wing, mach, |w| FrequencyTable::new(make(w)?, mach))
}

/// [`table_in`], the table made by `make`.
fn table_made_in(
    map: &RwLock<HashMap<(Shape, u64), Arc<FrequencyTable>>>,
    wing: &Trapezoid,
    mach: f64,
    make: impl FnOnce(&Trapezoid) -> Result<FrequencyTable, LiftingSurfaceError>,
) -> Result<Arc<FrequencyTable>, LiftingSurfaceError> {
    let key = (shape(wing), mach.to_bits());
    let read = map.read().unwrap_or_else(PoisonError::into_inner);
    if let Some(t) = read.get(&key) {
        return Ok(t.clone());
    }
    drop(read);
    let table = Arc::new(make(wing)?);
    let mut write = map.write().unwrap_or_else(PoisonError::into_inner);
    if write.len() >= CAPACITY {
        write.clear();
    }
    Ok(write.entry(key).or_insert(table).clone())
}

/// [`super::near_sonic()`] (0.9 ≤ M ≤ 1) from the cache: each refined
/// lattice's solution it needs (at M itself up to 0.99, at the
/// [`super::near_sonic::SONIC_ANCHORS`] beyond) solved once per (wing, M,
/// ω̄) — or, [`Harmonic::Interpolated`], interpolated in that lattice's
/// [`FrequencyTable`] (a frequency iteration's path: three tables' nodes
/// solved once per wing near M = 1, then a few dozen flops per iterate).
pub fn near_sonic(
    wing: &Trapezoid,
    mach: f64,
    omega_bar: f64,
    harmonic: Harmonic,
) -> Result<Solution, LiftingSurfaceError> {
    let c = cache();
    let refined = |w: &Trapezoid, m: f64| Lattice::new(w, LatticeSpec::for_mach(w, m));
    super::near_sonic::near_sonic_by(mach, omega_bar, |m| {
        if harmonic == Harmonic::Interpolated && omega_bar >= OMEGA_BAR_QUASI_STEADY {
            let make = |w: &Trapezoid| {
                let t = FrequencyTable::new(refined(w, m)?, m)?;
                Ok(t.frozen(
                    crate::aerodynamics::lifting_surface::precomputed::Kind::NearSonicLattice,
                    shape(w),
                ))
            };
            return table_made_in(&c.near_sonic_tables, wing, m, make)?.at(omega_bar);
        }
        let key = (shape(wing), m.to_bits(), omega_bar.to_bits());
        get_or_solve(&c.near_sonic, key, || refined(wing, m)?.solve(m, omega_bar))
    })
}

/// The steady solution with its exact Mach derivatives
/// ([`Lattice::solve_steady`]) on the refined lattice of
/// [`LatticeSpec::for_mach`] at 0.9 ≤ M < 1 — the lattice [`near_sonic`]
/// solves there — from the cache or solved into it.
pub fn near_sonic_steady(wing: &Trapezoid, mach: f64) -> Result<Steady, LiftingSurfaceError> {
    check(mach, 0.0)?;
    let key = (shape(wing), mach.to_bits());
    get_or_solve(&cache().near_sonic_steady, key, || {
        Lattice::new(wing, LatticeSpec::for_mach(wing, mach))?.solve_steady(mach)
    })
}

/// The near-sonic frequency tables' nodes this process has solved (not
/// those read from [`crate::aerodynamics::lifting_surface::precomputed`]): part of what `cargo xtask tables`
/// writes.
pub fn near_sonic_solved() -> Vec<(
    crate::aerodynamics::lifting_surface::precomputed::Key,
    Solution,
)> {
    let tables = cache()
        .near_sonic_tables
        .read()
        .unwrap_or_else(PoisonError::into_inner);
    tables.values().flat_map(|t| t.solved_nodes()).collect()
}

/// Empties the cache (and zeroes [`solves`]).
pub fn clear() {
    let c = cache();
    c.solutions
        .write()
        .unwrap_or_else(PoisonError::into_inner)
        .clear();
    c.steady
        .write()
        .unwrap_or_else(PoisonError::into_inner)
        .clear();
    c.tables
        .write()
        .unwrap_or_else(PoisonError::into_inner)
        .clear();
    c.near_sonic
        .write()
        .unwrap_or_else(PoisonError::into_inner)
        .clear();
    c.near_sonic_tables
        .write()
        .unwrap_or_else(PoisonError::into_inner)
        .clear();
    c.near_sonic_steady
        .write()
        .unwrap_or_else(PoisonError::into_inner)
        .clear();
    SOLVES.store(0, Ordering::SeqCst);
}

/// How many solutions and steady solutions the cache has solved (not
/// counting a table's nodes, which [`FrequencyTable::solved`] counts).
pub fn solves() -> usize {
    SOLVES.load(Ordering::SeqCst)
}

static SOLVES: AtomicUsize = AtomicUsize::new(0);

type Slot<T> = Arc<OnceLock<Result<T, LiftingSurfaceError>>>;
type Shape = [u64; 4];

#[derive(Default)]
struct Cache {
    solutions: RwLock<HashMap<(Shape, u64, u64), Slot<Solution>>>,
    steady: RwLock<HashMap<(Shape, u64), Slot<Steady>>>,
    tables: RwLock<HashMap<(Shape, u64), Arc<FrequencyTable>>>,
    /// [`near_sonic`]'s solutions and tables, on the refined lattices of
    /// [`LatticeSpec::for_mach`] (which differ from the default above 0.9).
    near_sonic: RwLock<HashMap<(Shape, u64, u64), Slot<Solution>>>,
    near_sonic_tables: RwLock<HashMap<(Shape, u64), Arc<FrequencyTable>>>,
    /// [`near_sonic_steady`]'s solutions.
    near_sonic_steady: RwLock<HashMap<(Shape, u64), Slot<Steady>>>,
}

fn cache() -> &'static Cache {
    static CACHE: OnceLock<Cache> = OnceLock::new();
    CACHE.get_or_init(Cache::default)
}

fn check(mach: f64, omega_bar: f64) -> Result<(), LiftingSurfaceError> {
    if !(mach.is_finite() && (0.0..1.0).contains(&mach)) {
        return Err(LiftingSurfaceError::Mach(mach));
    }
    if !(omega_bar.is_finite() && omega_bar >= 0.0) {
        return Err(LiftingSurfaceError::Frequency(omega_bar));
    }
    Ok(())
}

fn shape(w: &Trapezoid) -> Shape {
    [w.root_chord, w.tip_chord, w.semi_span, w.sweep_le].map(f64::to_bits)
}

fn lattice(wing: &Trapezoid) -> Result<Lattice, LiftingSurfaceError> {
    Lattice::new(wing, LatticeSpec::for_wing(wing))
}

/// The entry `key` of `map`, solved by `solve` if it is not there (once:
/// whoever asks meanwhile waits).
fn get_or_solve<K: Hash + Eq + Copy, T: Clone>(
    map: &RwLock<HashMap<K, Slot<T>>>,
    key: K,
    solve: impl FnOnce() -> Result<T, LiftingSurfaceError>,
) -> Result<T, LiftingSurfaceError> {
    let read = map.read().unwrap_or_else(PoisonError::into_inner);
    if let Some(done) = read.get(&key).and_then(|slot| slot.get()) {
        return done.clone();
    }
    drop(read);
    slot(map, key)
        .get_or_init(|| {
            SOLVES.fetch_add(1, Ordering::SeqCst);
            solve()
        })
        .clone()
}

/// The slot of `key` in `map`, made empty if it is not there.
fn slot<K: Hash + Eq + Copy, T>(map: &RwLock<HashMap<K, Slot<T>>>, key: K) -> Slot<T> {
    let mut write = map.write().unwrap_or_else(PoisonError::into_inner);
    if write.len() >= CAPACITY && !write.contains_key(&key) {
        write.clear();
    }
    write.entry(key).or_default().clone()
}
