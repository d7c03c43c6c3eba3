//! Lifting-surface solutions solved ahead of time, as an explicit value: a
//! file of solutions ([`Precomputed`]) that a caller hands to the store
//! ([`super::store::preload`]) so that it need not solve them — the note's
//! study preloads the Mach box and near-sonic lattice solutions it needs
//! (a near-sonic Mach box solve takes seconds: its grid grows to 300 rows).
//! Nothing is read behind the caller's back.
//!
//! The file holds what the solvers give for each key, to the last bit (each
//! number in Rust's shortest round-trip form), and in its header the
//! fingerprint of every solver it holds solutions of ([`fingerprint`]: a
//! hash of the solver's source, its words left out). A file whose
//! fingerprint for any solver differs from the solver's own is stale as a
//! whole ([`PrecomputedError::Stale`]): after a change to a solver its old
//! values never come back; `cargo xtask tables` writes the file afresh.

use super::solution::{Key, ReducedFrequency, Shape, Solution, Solver};
use std::collections::HashSet;

mod fingerprints {
    include!(concat!(env!("OUT_DIR"), "/fingerprints.rs"));
}

/// The solvers whose solutions a file may hold.
pub const SOLVERS: [Solver; 2] = [Solver::NearSonicLattice, Solver::MachBox];

/// The fingerprint of `solver` as built (a hash of the tokens of every
/// source file its numbers depend on: `stability-core/build.rs`); `None`
/// for a solver whose solutions are not stored ahead of time.
pub fn fingerprint(solver: Solver) -> Option<u64> {
    match solver {
        Solver::Lattice | Solver::NearSonicLattice => Some(fingerprints::LATTICE),
        Solver::MachBox => Some(fingerprints::MACH_BOX),
        Solver::ConfigurationLattice => None,
    }
}

/// The file's header line (after its comment lines).
pub const HEADER: &str = "solver,root_chord,tip_chord,semi_span,sweep_le,mach,sigma_bar,omega_bar,lift_alpha,moment_alpha,lift_alphadot,moment_alphadot,lift_q,moment_q";

/// The comment line that carries the fingerprints.
const FINGERPRINTS: &str = "# fingerprints:";

/// Why a file of solutions cannot be used.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum PrecomputedError {
    #[error(
        "the precomputed solutions were made by another {solver} (fingerprint {file:016x}, now {current:016x}): they are stale; run `cargo xtask tables` to solve them afresh",
        solver = solver.name()
    )]
    Stale {
        solver: Solver,
        file: u64,
        current: u64,
    },
    #[error("the precomputed solutions' file has no fingerprint for the {}: run `cargo xtask tables`", solver.name())]
    NoFingerprint { solver: Solver },
    #[error("precomputed solutions, line {line}: {what}")]
    Line { line: usize, what: String },
}

/// A file of solutions, each keyed as the store keys it.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Precomputed {
    entries: Vec<(Key<Shape>, Solution)>,
}

impl Precomputed {
    /// The solutions of a file's text, if every solver it holds solutions
    /// of has the fingerprint it was made with.
    pub fn parse(text: &str) -> Result<Precomputed, PrecomputedError> {
        let mut marks: Vec<(Solver, u64)> = Vec::new();
        let mut entries = Vec::new();
        for (n, line) in text.lines().enumerate() {
            let bad = |what: &str| PrecomputedError::Line {
                line: n + 1,
                what: what.to_string(),
            };
            if let Some(rest) = line.strip_prefix(FINGERPRINTS) {
                for mark in rest.split_whitespace() {
                    let (name, hex) = mark
                        .split_once('=')
                        .ok_or_else(|| bad("a fingerprint is solver=hex"))?;
                    let solver = Solver::parse(name).ok_or_else(|| bad("unknown solver"))?;
                    let value = u64::from_str_radix(hex, 16).map_err(|e| bad(&e.to_string()))?;
                    marks.push((solver, value));
                }
                continue;
            }
            if line.starts_with('#') || line == HEADER || line.trim().is_empty() {
                continue;
            }
            entries.push(entry(line).map_err(|what| bad(&what))?);
        }
        let used: HashSet<Solver> = entries.iter().map(|(k, _)| k.solver).collect();
        for solver in used {
            let current = fingerprint(solver).ok_or(PrecomputedError::NoFingerprint { solver })?;
            match marks.iter().find(|(s, _)| *s == solver) {
                None => return Err(PrecomputedError::NoFingerprint { solver }),
                Some(&(_, file)) if file != current => {
                    return Err(PrecomputedError::Stale {
                        solver,
                        file,
                        current,
                    });
                }
                Some(_) => {}
            }
        }
        Ok(Precomputed { entries })
    }

    /// The solutions, as keys and values.
    pub fn entries(&self) -> &[(Key<Shape>, Solution)] {
        &self.entries
    }

    /// Whether the file holds the solution at `key`.
    pub fn contains(&self, key: &Key<Shape>) -> bool {
        self.entries.iter().any(|(k, _)| k == key)
    }

    /// The file's text for `entries` (sorted by solver, wing, Mach number
    /// and frequency, as numbers), with the fingerprints of their solvers.
    pub fn write(entries: impl IntoIterator<Item = (Key<Shape>, Solution)>) -> String {
        let mut entries: Vec<_> = entries.into_iter().collect();
        entries.sort_by(|a, b| order(&a.0, &b.0));
        entries.dedup_by(|a, b| a.0 == b.0);
        let mut out = String::from(
            "# Lifting-surface solutions the note's study needs, solved ahead of time: written by\n\
             # `cargo xtask tables` (stability_core::aerodynamics::lifting_surface::precomputed). Do not edit.\n",
        );
        out.push_str(FINGERPRINTS);
        for solver in SOLVERS {
            if let Some(f) = fingerprint(solver) {
                out.push_str(&format!(" {}={f:016x}", solver.name()));
            }
        }
        out.push('\n');
        out.push_str(HEADER);
        out.push('\n');
        for (k, s) in &entries {
            out.push_str(k.solver.name());
            for x in numbers(k, s) {
                out.push_str(&format!(",{x:?}"));
            }
            out.push('\n');
        }
        out
    }
}

/// The file's numbers of one entry, in [`HEADER`]'s order.
fn numbers(k: &Key<Shape>, s: &Solution) -> [f64; 13] {
    let [c, t, sp, l] = k.geometry.map(f64::from_bits);
    let p = k.frequency();
    [
        c,
        t,
        sp,
        l,
        k.mach(),
        p.sigma_bar,
        p.omega_bar,
        s.lift_alpha,
        s.moment_alpha,
        s.lift_alphadot,
        s.moment_alphadot,
        s.lift_q,
        s.moment_q,
    ]
}

/// One line of the file: its solver and thirteen numbers.
fn entry(line: &str) -> Result<(Key<Shape>, Solution), String> {
    let (name, rest) = line.split_once(',').ok_or("no solver")?;
    let solver = Solver::parse(name).ok_or("unknown solver")?;
    if !SOLVERS.contains(&solver) {
        return Err(format!("the {name} solutions are not stored ahead of time"));
    }
    let v: Vec<f64> = rest
        .split(',')
        .map(str::parse::<f64>)
        .collect::<Result<_, _>>()
        .map_err(|e| e.to_string())?;
    let [
        c,
        t,
        s,
        l,
        mach,
        sigma_bar,
        omega_bar,
        la,
        ma,
        lad,
        mad,
        lq,
        mq,
    ] = v[..]
    else {
        return Err("13 numbers after the solver".to_string());
    };
    let p = ReducedFrequency {
        sigma_bar,
        omega_bar,
    };
    let key = Key::new(solver, [c, t, s, l].map(f64::to_bits), mach, p);
    let solution = Solution {
        mach,
        omega_bar,
        lift_alpha: la,
        moment_alpha: ma,
        lift_alphadot: lad,
        moment_alphadot: mad,
        lift_q: lq,
        moment_q: mq,
    };
    Ok((key, solution))
}

/// The file's order: by solver, then wing, Mach number and frequency as
/// numbers.
fn order(a: &Key<Shape>, b: &Key<Shape>) -> std::cmp::Ordering {
    let numbers = |k: &Key<Shape>| {
        let [c, t, s, l] = k.geometry.map(f64::from_bits);
        let p = k.frequency();
        [c, t, s, l, k.mach(), p.sigma_bar, p.omega_bar]
    };
    a.solver.cmp(&b.solver).then_with(|| {
        numbers(a)
            .iter()
            .zip(numbers(b).iter())
            .map(|(x, y)| x.total_cmp(y))
            .find(|o| o.is_ne())
            .unwrap_or(std::cmp::Ordering::Equal)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample() -> (Key<Shape>, Solution) {
        let key = Key::new(
            Solver::NearSonicLattice,
            [1.0, 0.0, 1.0, std::f64::consts::FRAC_PI_4].map(f64::to_bits),
            0.995,
            ReducedFrequency::harmonic(0.35),
        );
        let s = Solution {
            mach: 0.995,
            omega_bar: 0.35,
            lift_alpha: 4.0 / 3.0,
            moment_alpha: -0.1 - 0.2,
            lift_alphadot: 1e-300,
            moment_alphadot: -2.5e17,
            lift_q: std::f64::consts::PI,
            moment_q: -0.0,
        };
        (key, s)
    }

    #[test]
    fn the_writer_and_the_reader_agree_to_the_bit() {
        let (key, s) = sample();
        let back = Precomputed::parse(&Precomputed::write([(key.clone(), s)])).unwrap();
        assert_eq!(back.entries().len(), 1);
        let (k, got) = &back.entries()[0];
        assert_eq!(k, &key);
        for (a, b) in [
            (got.lift_alpha, s.lift_alpha),
            (got.moment_alpha, s.moment_alpha),
            (got.lift_alphadot, s.lift_alphadot),
            (got.moment_q, s.moment_q),
        ] {
            assert_eq!(a.to_bits(), b.to_bits());
        }
        assert_eq!(*got, s);
    }

    #[test]
    fn a_file_made_by_another_solver_is_stale_as_a_whole() {
        let (key, s) = sample();
        let text = Precomputed::write([(key, s)]);
        let current = fingerprint(Solver::NearSonicLattice).unwrap();
        let changed = text.replace(&format!("{current:016x}"), &format!("{:016x}", current ^ 1));
        assert_ne!(changed, text);
        assert_eq!(
            Precomputed::parse(&changed),
            Err(PrecomputedError::Stale {
                solver: Solver::NearSonicLattice,
                file: current ^ 1,
                current
            })
        );
        let unmarked: String = text
            .lines()
            .filter(|l| !l.starts_with(FINGERPRINTS))
            .map(|l| format!("{l}\n"))
            .collect();
        assert!(matches!(
            Precomputed::parse(&unmarked),
            Err(PrecomputedError::NoFingerprint { .. })
        ));
    }
}
