//! The one store of the unsteady solutions of wings and configurations:
//! each solved once per process, by the first thread to ask (others asking
//! meanwhile wait for it), keyed by one [`Key`] — the solver, the geometry
//! (a wing's unit [`Shape`], a configuration's numbers), the Mach number and
//! the reduced frequency p̄ — in one [`Memo`] per kind of value: a wing's
//! [`Solution`], its [`Steady`] solution with Mach derivatives, a
//! configuration's [`ConfigurationSolution`]. So the design points of a
//! sweep, a study or a frequency iteration that share a wing and a flight
//! condition share its solve, whatever their c.g., μ₁ or i_B (axis transfer
//! and eqs 2–4 need no new solve). A hit takes a read lock and copies the
//! value: no allocation for a wing.
//!
//! [`Harmonic::Interpolated`] takes a harmonic solution from the solutions
//! at the frequency nodes around ω̄ ([`super::frequency`]), each itself a
//! stored solve, instead of one solve per ω̄: what a frequency iteration
//! at many design points uses.
//!
//! Solutions solved ahead of time come in only by [`preload`] of an
//! explicit [`Precomputed`] file (the note's study does it); nothing else
//! fills the store but the solvers. Which solver serves which Mach number
//! is [`super::mach_range`]'s dispatch; this module solves what it is asked.

use super::configuration::{ConfigurationError, ConfigurationLattice};
use super::derivatives::Extrapolate;
use super::frequency::{NODES, combine_stencil, stencil_in};
use super::mach_box::{self, MachBoxSpec};
use super::near_sonic::near_sonic_by;
use super::precomputed::Precomputed;
use super::solution::{
    ConfigurationSolution, Key, ReducedFrequency, Shape, Solution, Solver, Steady, shape,
};
use super::{Lattice, LatticeSpec, LiftingSurfaceError, OMEGA_BAR_QUASI_STEADY};
use crate::geometry::Trapezoid;
use crate::geometry::configuration::{Configuration, SurfaceKind};
use crate::numerics::memo::Memo;

/// How a harmonic solution (ω̄ > 0) is had.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Harmonic {
    /// Solved at the ω̄ asked for (and stored at it).
    #[default]
    Direct,
    /// Interpolated between the solutions at the frequency nodes around ω̄
    /// ([`super::frequency`]): for a frequency iteration at many design
    /// points (a sweep), where every point's ω̄ differs.
    Interpolated,
}

/// Most entries of each kind before a kind starts afresh.
pub const CAPACITY: usize = 1 << 14;

/// The wings' solutions, every solver's.
static SOLUTIONS: Memo<Key<Shape>, Result<Solution, LiftingSurfaceError>> = Memo::new(CAPACITY);
/// The wings' steady solutions with their Mach derivatives.
static STEADY: Memo<Key<Shape>, Result<Steady, LiftingSurfaceError>> = Memo::new(CAPACITY);
/// The configurations' lattice solutions.
static CONFIGURATIONS: Memo<Key<Vec<u64>>, Result<ConfigurationSolution, ConfigurationError>> =
    Memo::new(CAPACITY);

/// The wing of aspect ratio A, taper λ and leading-edge sweep Λ (rad) with
/// root chord 1: the shape the store is keyed by. A and λ within a few
/// rounding errors of a number of twelve significant figures are taken as
/// that number ([`snapped`]), so that one shape scaled (a tail sizing's
/// trial surfaces) keeps one key.
pub fn unit_wing(
    aspect_ratio: f64,
    taper: f64,
    sweep_le: f64,
) -> Result<Trapezoid, LiftingSurfaceError> {
    Trapezoid::from_aspect_ratio(snapped(aspect_ratio), snapped(taper), sweep_le, 1.0)
        .map_err(|e| LiftingSurfaceError::Planform(e.to_string()))
}

/// `x` as the nearest number of twelve significant figures when that is
/// within four units in the last place of it (the rounding a product and
/// a quotient leave: 0.8000000000000002 is 0.8), else `x` itself.
pub fn snapped(x: f64) -> f64 {
    // formatted on the stack: the store's lookups are on the hot path,
    // which allocates nothing
    use std::io::Write;
    let mut buf = [0u8; 40];
    let mut out = std::io::Cursor::new(&mut buf[..]);
    if write!(out, "{x:.11e}").is_err() {
        return x;
    }
    let len = out.position() as usize;
    let Some(decimal) = std::str::from_utf8(&buf[..len])
        .ok()
        .and_then(|s| s.parse::<f64>().ok())
    else {
        return x;
    };
    let ulp = f64::from_bits(x.abs().to_bits() + 1) - x.abs();
    if (decimal - x).abs() <= 4.0 * ulp {
        decimal
    } else {
        x
    }
}

/// ω̄ below [`OMEGA_BAR_QUASI_STEADY`] as the quasi-steady 0.
fn quasi_steady_below(omega_bar: f64) -> f64 {
    if (0.0..OMEGA_BAR_QUASI_STEADY).contains(&omega_bar) {
        0.0
    } else {
        omega_bar
    }
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

/// The stored solution of `wing` by `solver` at (`mach`, `omega_bar`), or
/// `solve`d into the store.
fn wing_solution(
    solver: Solver,
    wing: &Trapezoid,
    mach: f64,
    omega_bar: f64,
    solve: impl FnOnce() -> Result<Solution, LiftingSurfaceError>,
) -> Result<Solution, LiftingSurfaceError> {
    let key = Key::new(
        solver,
        shape(wing),
        mach,
        ReducedFrequency::harmonic(omega_bar),
    );
    SOLUTIONS.get_or_solve(key, solve)
}

/// The doublet lattice's solution of `wing` (on its default boxes,
/// [`LatticeSpec::for_wing`]) at (`mach`, `omega_bar`), 0 ≤ M < 1, solved
/// there or interpolated between the frequency nodes as `harmonic` says
/// (below the first node its values, beyond the last a direct solve).
pub fn lattice(
    wing: &Trapezoid,
    mach: f64,
    omega_bar: f64,
    harmonic: Harmonic,
) -> Result<Solution, LiftingSurfaceError> {
    check(mach, omega_bar)?;
    let at = |w: f64| {
        wing_solution(Solver::Lattice, wing, mach, w, || {
            Lattice::new(wing, LatticeSpec::for_wing(wing))?.solve(mach, w)
        })
    };
    by_harmonic(omega_bar, harmonic, at)
}

/// `at(ω̄)` (quasi-steady below [`OMEGA_BAR_QUASI_STEADY`]), or under
/// [`Harmonic::Interpolated`] the cubic through `at` at the four
/// [`NODES`] around ω̄: the nodes' first values below them, a direct
/// solve beyond.
fn by_harmonic(
    omega_bar: f64,
    harmonic: Harmonic,
    at: impl Fn(f64) -> Result<Solution, LiftingSurfaceError>,
) -> Result<Solution, LiftingSurfaceError> {
    let omega_bar = quasi_steady_below(omega_bar);
    if harmonic == Harmonic::Direct || omega_bar == 0.0 {
        return at(omega_bar);
    }
    if omega_bar <= NODES[0] {
        return Ok(Solution {
            omega_bar,
            ..at(NODES[0])?
        });
    }
    match stencil_in(&NODES, omega_bar) {
        Some(s) => Ok(Solution {
            omega_bar,
            ..combine_stencil(s, |k| at(NODES[k]))?
        }),
        None => at(omega_bar),
    }
}

/// The lattice's steady solution of `wing` at `mach` with its exact Mach
/// derivatives ([`Lattice::solve_steady`]); its quasi-steady [`Solution`]
/// serves [`lattice`] at ω̄ = 0 too, to the bit.
pub fn lattice_steady(wing: &Trapezoid, mach: f64) -> Result<Steady, LiftingSurfaceError> {
    check(mach, 0.0)?;
    let key = Key::new(
        Solver::Lattice,
        shape(wing),
        mach,
        ReducedFrequency::harmonic(0.0),
    );
    let s = STEADY.get_or_solve(key.clone(), || {
        Lattice::new(wing, LatticeSpec::for_wing(wing))?.solve_steady(mach)
    })?;
    SOLUTIONS.insert(key, Ok(s.solution));
    Ok(s)
}

/// [`super::near_sonic()`] (0.9 ≤ M ≤ 1) from the store: each refined
/// lattice's solution it needs (at M itself up to 0.99, at the
/// [`super::near_sonic::SONIC_ANCHORS`] beyond) solved once per (wing, M,
/// ω̄), or interpolated between its frequency nodes as `harmonic` says.
pub fn near_sonic(
    wing: &Trapezoid,
    mach: f64,
    omega_bar: f64,
    harmonic: Harmonic,
) -> Result<Solution, LiftingSurfaceError> {
    near_sonic_by(mach, omega_bar, |m| {
        let at = |w: f64| {
            wing_solution(Solver::NearSonicLattice, wing, m, w, || {
                Lattice::new(wing, LatticeSpec::for_mach(wing, m))?.solve(m, w)
            })
        };
        by_harmonic(omega_bar, harmonic, at)
    })
}

/// The steady solution with its exact Mach derivatives on the refined
/// lattice of [`LatticeSpec::for_mach`] at 0.9 ≤ M < 1 — the lattice
/// [`near_sonic`] solves there.
pub fn near_sonic_steady(wing: &Trapezoid, mach: f64) -> Result<Steady, LiftingSurfaceError> {
    check(mach, 0.0)?;
    let key = Key::new(
        Solver::NearSonicLattice,
        shape(wing),
        mach,
        ReducedFrequency::harmonic(0.0),
    );
    STEADY.get_or_solve(key, || {
        Lattice::new(wing, LatticeSpec::for_mach(wing, mach))?.solve_steady(mach)
    })
}

/// The Mach box's solution of `wing` at (`mach`, `omega_bar`), on its
/// default grid ([`MachBoxSpec::for_wing`]).
pub fn mach_box(
    wing: &Trapezoid,
    mach: f64,
    omega_bar: f64,
) -> Result<Solution, LiftingSurfaceError> {
    let omega_bar = quasi_steady_below(omega_bar);
    wing_solution(Solver::MachBox, wing, mach, omega_bar, || {
        Ok(mach_box::solve(
            wing,
            mach,
            omega_bar,
            MachBoxSpec::for_wing(wing, mach),
        )?)
    })
}

/// Below this β = √(M² − 1) [`mach_box_with`] solves at every ω̄ instead
/// of interpolating: the Mach box's frequency dependence sharpens towards
/// M = 1 (its phases σx = κM²x/β²), and between the nodes the cubic was
/// measured 3.9·10⁻³ of C_Lα off at M = 1.03 (β = 0.25, ω̄ = 0.12) on the
/// 45° delta against 6.3·10⁻⁴ at M = 1.05 (β = 0.32).
pub const INTERPOLATED_FROM_BETA: f64 = 0.3;

/// The Mach box's own frequency nodes from β = [`INTERPOLATED_FROM_BETA`]
/// on: the quasi-steady solution and the lattice's [`NODES`] from 0.05,
/// without their geometric run towards 0. There the lattice needs it for
/// the ω̄ ln ω̄ of subsonic flow; supersonic flow has none — the Mach box's
/// numbers go as c₀ + c₂ω̄² (measured: the 45° delta at M = 1.3 and the
/// 60° at M = 2, ω̄ = 0.001 to 0.1), which the cubic through 0, 0.05, 0.1,
/// 0.15 carries exactly.
pub const SUPERSONIC_NODES: [f64; 33] = [
    0.0, 0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4, //
    0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.1, 1.2, 1.3, 1.4, 1.5, 1.6, 1.7, 1.8, 1.9, 2.0, //
    2.25, 2.5, 2.75, 3.0, 3.25, 3.5, 3.75, 4.0,
];

/// The cubic through `at` at the four of `nodes` around ω̄, or a direct
/// solve outside them.
fn between_nodes<T: Clone, E>(
    nodes: &[f64],
    omega_bar: f64,
    at: impl Fn(f64) -> Result<T, E>,
    combine: impl Fn(&T, &T, f64, f64) -> T,
) -> Result<T, E> {
    let Some((j, w)) = stencil_in(nodes, omega_bar) else {
        return at(omega_bar);
    };
    let mut out = combine(&at(nodes[j])?, &at(nodes[j + 1])?, w[0], w[1]);
    for (m, &wm) in w.iter().enumerate().skip(2) {
        out = combine(&out, &at(nodes[j + m])?, 1.0, wm);
    }
    Ok(out)
}

/// The Mach box's solution solved at ω̄ ([`Harmonic::Direct`],
/// [`mach_box()`]) or interpolated ([`Harmonic::Interpolated`], from
/// β ≥ [`INTERPOLATED_FROM_BETA`]) between the four [`NODES`] around ω̄,
/// each solved once; outside the nodes solved there. Within 10⁻³ of C_Lα
/// of the direct solve on the note's deltas at M = 1.05–2.
pub fn mach_box_with(
    wing: &Trapezoid,
    mach: f64,
    omega_bar: f64,
    harmonic: Harmonic,
) -> Result<Solution, LiftingSurfaceError> {
    let interpolable = mach * mach - 1.0 >= INTERPOLATED_FROM_BETA * INTERPOLATED_FROM_BETA;
    if harmonic == Harmonic::Direct || !interpolable {
        return mach_box(wing, mach, omega_bar);
    }
    let out = between_nodes(
        &NODES,
        omega_bar,
        |w| mach_box(wing, mach, w),
        Solution::combine,
    )?;
    Ok(Solution { omega_bar, ..out })
}

/// The Mach box's solution interpolated between the four frequency nodes
/// around ω̄ at any M it takes (solved at ω̄ outside the nodes): on
/// [`SUPERSONIC_NODES`] from β = [`INTERPOLATED_FROM_BETA`], on the
/// lattice's [`NODES`] below — [`mach_box_with`]'s interpolation without
/// its lower bound in β, for [`super::mach_table`], whose report- and
/// sweep-wide use states the error below β = 0.3.
pub fn mach_box_interpolated(
    wing: &Trapezoid,
    mach: f64,
    omega_bar: f64,
) -> Result<Solution, LiftingSurfaceError> {
    let nodes: &[f64] = if mach * mach - 1.0 >= INTERPOLATED_FROM_BETA * INTERPOLATED_FROM_BETA {
        &SUPERSONIC_NODES
    } else {
        &NODES
    };
    let out = between_nodes(
        nodes,
        omega_bar,
        |w| mach_box(wing, mach, w),
        Solution::combine,
    )?;
    Ok(Solution { omega_bar, ..out })
}

/// The bits of every number of `cfg` its lattice depends on: the wing's
/// four, and for each surface present its kind, its four, its apex x and
/// height z (a surface's incidence and the body are not in the lattice).
pub fn configuration_key(cfg: &Configuration) -> Vec<u64> {
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

/// The multi-surface lattice's solution of `cfg` at (`mach`, `omega_bar`),
/// 0 ≤ M < 1 ([`ConfigurationLattice`], its default boxes), solved there
/// or interpolated between the frequency [`NODES`] as `harmonic` says
/// (outside the nodes solved there).
pub fn configuration(
    cfg: &Configuration,
    mach: f64,
    omega_bar: f64,
    harmonic: Harmonic,
) -> Result<ConfigurationSolution, ConfigurationError> {
    check(mach, omega_bar)?;
    let key = configuration_key(cfg);
    let at = |w: f64| {
        let w = quasi_steady_below(w);
        let k = Key::new(
            Solver::ConfigurationLattice,
            key.clone(),
            mach,
            ReducedFrequency::harmonic(w),
        );
        CONFIGURATIONS.get_or_solve(k, || ConfigurationLattice::new(cfg)?.solve(mach, w))
    };
    if harmonic == Harmonic::Direct {
        return at(omega_bar);
    }
    let mut out = between_nodes(&NODES, omega_bar, at, combine_configurations)?;
    out.total.omega_bar = omega_bar;
    out.parts
        .iter_mut()
        .for_each(|p| p.solution.omega_bar = omega_bar);
    Ok(out)
}

/// a·x + b·y, the total and each part (one configuration's parts come in
/// one order at every ω̄).
fn combine_configurations(
    x: &ConfigurationSolution,
    y: &ConfigurationSolution,
    a: f64,
    b: f64,
) -> ConfigurationSolution {
    let mut out = x.clone();
    out.total = x.total.combine(&y.total, a, b);
    for (p, q) in out.parts.iter_mut().zip(&y.parts) {
        p.solution = p.solution.combine(&q.solution, a, b);
    }
    out
}

/// Puts every solution of `file` into the store, as if solved: the store
/// then answers their keys without solving. Returns how many.
pub fn preload(file: &Precomputed) -> usize {
    for (key, s) in file.entries() {
        SOLUTIONS.insert(key.clone(), Ok(*s));
    }
    file.entries().len()
}

/// Every wing solution in the store by one of `solvers` (solved or
/// preloaded), in no order: what `cargo xtask tables` writes.
pub fn wing_solutions(solvers: &[Solver]) -> Vec<(Key<Shape>, Solution)> {
    SOLUTIONS
        .entries()
        .into_iter()
        .filter(|(k, _)| solvers.contains(&k.solver))
        .filter_map(|(k, v)| v.ok().map(|s| (k, s)))
        .collect()
}

/// Whether the store holds `wing`'s solution by `solver` at (`mach`,
/// `omega_bar`), solved or preloaded.
pub fn holds(solver: Solver, wing: &Trapezoid, mach: f64, omega_bar: f64) -> bool {
    let key = Key::new(
        solver,
        shape(wing),
        mach,
        ReducedFrequency::harmonic(omega_bar),
    );
    SOLUTIONS.contains(&key)
}

/// How many solves the store has made since it was last cleared (wings,
/// steady solutions and configurations; preloaded solutions are not
/// solves).
pub fn solves() -> usize {
    SOLUTIONS.solves() + STEADY.solves() + CONFIGURATIONS.solves()
}

/// How many configuration solves the store has made since it was last
/// cleared.
pub fn configuration_solves() -> usize {
    CONFIGURATIONS.solves()
}

/// Empties the store (benchmarks and tests that must pay for their
/// solves).
pub fn clear() {
    SOLUTIONS.clear();
    STEADY.clear();
    CONFIGURATIONS.clear();
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_shape_scaled_keeps_its_key_and_other_numbers_are_kept() {
        assert_eq!(snapped(0.8000000000000002), 0.8);
        assert_eq!(snapped(0.7999999999999999), 0.8);
        assert_eq!(snapped(4.0), 4.0);
        assert_eq!(snapped(0.0), 0.0);
        // not near a short decimal: as it is
        for x in [1.0 / 7.0, 4.0 / 3f64.sqrt(), std::f64::consts::PI] {
            assert_eq!(snapped(x), x);
        }
        // a tail of taper 0.3 scaled by 1.37 and back keeps its unit shape
        let t = Trapezoid::from_aspect_ratio(3.0, 0.3, 0.7, 3.0).unwrap();
        let f = 1.37;
        let s = Trapezoid {
            root_chord: t.root_chord * f,
            tip_chord: t.tip_chord * f,
            semi_span: t.semi_span * f,
            sweep_le: t.sweep_le,
        };
        let unit =
            |w: &Trapezoid| shape(&unit_wing(w.aspect_ratio(), w.taper(), w.sweep_le).unwrap());
        assert_eq!(unit(&s), unit(&t));
    }
}
