//! One solve per (configuration, Mach number, ω̄): a process-wide cache of
//! [`ConfigurationLattice::solve`], as [`crate::aerodynamics::lifting_surface::cache`] is
//! for the wing alone, so that the design points of a sweep that share a
//! configuration and a flight condition share its solve.
//!
//! Keyed by the bits of every number the lattice depends on — the wing's
//! four, and for each surface present its kind, its four, its apex x and
//! height z — and of M and ω̄ (below [`OMEGA_BAR_QUASI_STEADY`], 0). A
//! surface's incidence and the body are not in the lattice and not in the
//! key. Each entry is solved once, by the first thread to ask; others
//! asking meanwhile wait for it. At most [`CAPACITY`] entries; [`clear`]
//! empties it.

use super::ConfigurationError;
use super::ConfigurationLattice;
use crate::aerodynamics::lifting_surface::ConfigurationSolution;
use crate::aerodynamics::lifting_surface::derivatives::Extrapolate;
use crate::aerodynamics::lifting_surface::{
    Harmonic, LiftingSurfaceError, OMEGA_BAR_QUASI_STEADY, frequency,
};
use crate::geometry::Trapezoid;
use crate::geometry::configuration::{Configuration, SurfaceKind};
use crate::numerics::memo::Memo;

/// Most entries.
pub const CAPACITY: usize = 1 << 12;

type Key = (Vec<u64>, u64, u64);

static SOLUTIONS: Memo<Key, Result<ConfigurationSolution, ConfigurationError>> =
    Memo::new(CAPACITY);

fn shape(t: &Trapezoid) -> [u64; 4] {
    [t.root_chord, t.tip_chord, t.semi_span, t.sweep_le].map(f64::to_bits)
}

/// The bits of every number of `cfg` the lattice depends on.
pub fn key(cfg: &Configuration) -> Vec<u64> {
    let mut k = shape(&cfg.wing).to_vec();
    for s in cfg.surfaces() {
        k.push(match s.kind {
            SurfaceKind::Tailplane => 1,
            SurfaceKind::Foreplane => 2,
        });
        k.extend(shape(&s.shape));
        k.extend([s.x.to_bits(), s.z.to_bits()]);
    }
    k
}

/// The solution of `cfg` at (`mach`, `omega_bar`), from the cache or solved
/// into it (at the default lattice, [`ConfigurationLattice::new`]).
pub fn solution(
    cfg: &Configuration,
    mach: f64,
    omega_bar: f64,
) -> Result<ConfigurationSolution, ConfigurationError> {
    if !(mach.is_finite() && (0.0..1.0).contains(&mach)) {
        return Err(LiftingSurfaceError::Mach(mach).into());
    }
    if !(omega_bar.is_finite() && omega_bar >= 0.0) {
        return Err(LiftingSurfaceError::Frequency(omega_bar).into());
    }
    let omega_bar = if omega_bar < OMEGA_BAR_QUASI_STEADY {
        0.0
    } else {
        omega_bar
    };
    let key = (key(cfg), mach.to_bits(), omega_bar.to_bits());
    SOLUTIONS.get_or_solve(key, || {
        ConfigurationLattice::new(cfg)?.solve(mach, omega_bar)
    })
}

/// As [`solution`], with the harmonic solution had as `harmonic` says:
/// [`Harmonic::Interpolated`] interpolates, as the wing's
/// [`crate::aerodynamics::lifting_surface::frequency::FrequencyTable`] does, between
/// solutions at its nodes (each cached here, so the design points of a
/// sweep or a sizing that share a configuration and a Mach number share
/// them): a frequency iteration solves a few nodes, not every iterate.
/// Outside the nodes, and [`Harmonic::Direct`], as [`solution`].
pub fn solution_with(
    cfg: &Configuration,
    mach: f64,
    omega_bar: f64,
    harmonic: Harmonic,
) -> Result<ConfigurationSolution, ConfigurationError> {
    let stencil = match harmonic {
        Harmonic::Interpolated => frequency::stencil(omega_bar),
        Harmonic::Direct => None,
    };
    let Some((j, w)) = stencil else {
        return solution(cfg, mach, omega_bar);
    };
    let node = |m: usize| solution(cfg, mach, frequency::NODES[j + m]);
    let mut out = node(0)?;
    scale(&mut out, w[0], None);
    for (m, &wm) in w.iter().enumerate().skip(1) {
        scale(&mut out, wm, Some(&node(m)?));
    }
    out.total.omega_bar = omega_bar;
    out.parts
        .iter_mut()
        .for_each(|p| p.solution.omega_bar = omega_bar);
    Ok(out)
}

/// `acc` ← `acc` + `w`·`add` (every number of the total and each part), or
/// `acc` ← `w`·`acc` without `add`. The parts of one configuration come in
/// one order at every ω̄.
fn scale(acc: &mut ConfigurationSolution, w: f64, add: Option<&ConfigurationSolution>) {
    let (a, b) = if add.is_some() { (1.0, w) } else { (w, 0.0) };
    let add = add.unwrap_or(acc).clone();
    acc.total = acc.total.combine(&add.total, a, b);
    for (p, q) in acc.parts.iter_mut().zip(&add.parts) {
        p.solution = p.solution.combine(&q.solution, a, b);
    }
}

/// How many solves the cache has made.
pub fn solves() -> usize {
    SOLUTIONS.solves()
}

/// Empties the cache (and zeroes [`solves`]).
pub fn clear() {
    SOLUTIONS.clear();
}
