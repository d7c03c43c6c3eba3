//! Lifting-surface solutions solved ahead of time: every Mach box solve
//! and every refined near-sonic lattice solve at a frequency node that the
//! note's study (`delta-stability report`) makes, written by
//! `cargo xtask tables` into `stability-core/data/lifting-surface-solutions.csv`
//! and read here on first use, so that the report does not spend minutes
//! on them. (A near-sonic Mach box solve at the short period's ω̄ takes
//! 1–12 s: its grid grows to 300 rows and the kernel's phases to tens of
//! radians; a refined lattice at the sonic extrapolation's anchors, up to
//! 84 × 16 boxes, about a second.)
//!
//! The file is what the solvers give for each key, to the last bit (each
//! number printed as Rust's shortest round-trip form), and nothing else: a
//! wing, Mach number or ω̄ it does not hold is solved as before.
//! `tests/frozen_solutions.rs` solves a sample of its entries again and
//! asserts they agree. After a change to either solver, its tables in Mach
//! number or frequency, or the study's wings, run `cargo xtask tables`
//! (about a quarter of an hour on 2 cores): the file's diff shows what the
//! change did. Until then the report is slower, not different.

use crate::aerodynamics::lifting_surface::Solution;
use std::collections::HashMap;
use std::sync::OnceLock;

/// Which solver a solution comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Kind {
    /// The Mach box (`lifting_surface::mach_box::solve`), on its default grid.
    MachBox,
    /// The doublet lattice refined near M = 1
    /// (`LatticeSpec::for_mach`), at a frequency node.
    NearSonicLattice,
}

impl Kind {
    fn name(self) -> &'static str {
        match self {
            Kind::MachBox => "mach-box",
            Kind::NearSonicLattice => "near-sonic-lattice",
        }
    }

    fn parse(s: &str) -> Option<Kind> {
        [Kind::MachBox, Kind::NearSonicLattice]
            .into_iter()
            .find(|k| k.name() == s)
    }
}

/// A solution's key: its solver; the unit wing's root chord, tip chord,
/// semi-span and leading-edge sweep; M and ω̄ — the numbers as bits.
pub type Key = (Kind, [u64; 4], u64, u64);

/// The file's text.
const TEXT: &str = include_str!("../../../data/lifting-surface-solutions.csv");

/// The file's header line (after its comment lines).
pub const HEADER: &str = "solver,root_chord,tip_chord,semi_span,sweep_le,mach,omega_bar,lift_alpha,moment_alpha,lift_alphadot,moment_alphadot,lift_q,moment_q";

/// The environment variable that, set to a path, makes `delta-stability
/// report` ignore the file, solve everything and write what it solved to
/// the path in the file's form: how `cargo xtask tables` makes it.
pub const WRITE_ENV: &str = "DELTA_STABILITY_WRITE_SOLUTIONS";

/// With [`WRITE_ENV`], this variable set (to anything) keeps the file's
/// entries: the report reads them and writes them with what it had to
/// solve besides (`cargo xtask tables --add`, after adding a wing).
pub const KEEP_ENV: &str = "DELTA_STABILITY_WRITE_SOLUTIONS_KEEP";

static TABLE: OnceLock<HashMap<Key, Solution>> = OnceLock::new();

/// The frozen solution at `key`, if the file holds it (none while
/// [`WRITE_ENV`] is set).
pub fn get(key: &Key) -> Option<Solution> {
    static IGNORED: OnceLock<bool> = OnceLock::new();
    let ignored = || std::env::var_os(WRITE_ENV).is_some() && std::env::var_os(KEEP_ENV).is_none();
    if *IGNORED.get_or_init(ignored) {
        return None;
    }
    TABLE.get_or_init(|| parse(TEXT)).get(key).copied()
}

/// Every entry of the file, in the file's order.
pub fn entries() -> Vec<(Key, Solution)> {
    let mut out: Vec<(Key, Solution)> = TABLE
        .get_or_init(|| parse(TEXT))
        .iter()
        .map(|(k, s)| (*k, *s))
        .collect();
    out.sort_by(|a, b| order(&a.0, &b.0));
    out
}

/// The file's order: by solver, wing, Mach number, ω̄ (as numbers).
fn order(a: &Key, b: &Key) -> std::cmp::Ordering {
    let numbers = |k: &Key| {
        let [c, t, s, l] = k.1.map(f64::from_bits);
        [c, t, s, l, f64::from_bits(k.2), f64::from_bits(k.3)]
    };
    a.0.cmp(&b.0).then_with(|| {
        numbers(a)
            .iter()
            .zip(numbers(b).iter())
            .map(|(x, y)| x.total_cmp(y))
            .find(|o| o.is_ne())
            .unwrap_or(std::cmp::Ordering::Equal)
    })
}

/// The entries of a file's text (comment lines `#`, the header, then one
/// line per solution). A line that does not parse is a bug in the writer:
/// it panics, naming the line, so that the file's test fails.
pub fn parse(text: &str) -> HashMap<Key, Solution> {
    let mut out = HashMap::new();
    for (n, line) in text.lines().enumerate() {
        if line.starts_with('#') || line == HEADER || line.trim().is_empty() {
            continue;
        }
        let bad =
            |what: &str| -> ! { panic!("lifting-surface-solutions.csv line {}: {what}", n + 1) };
        let (kind, rest) = line.split_once(',').unwrap_or_else(|| bad("no solver"));
        let kind = Kind::parse(kind).unwrap_or_else(|| bad("unknown solver"));
        let v: Vec<f64> = rest
            .split(',')
            .map(|x| x.parse::<f64>())
            .collect::<Result<_, _>>()
            .unwrap_or_else(|e| bad(&e.to_string()));
        let [c, t, s, l, mach, omega_bar, la, ma, lad, mad, lq, mq] = v[..] else {
            bad("12 numbers after the solver")
        };
        let key = (
            kind,
            [c, t, s, l].map(f64::to_bits),
            mach.to_bits(),
            omega_bar.to_bits(),
        );
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
        out.insert(key, solution);
    }
    out
}

/// The file's text for `entries` (sorted), after a comment saying how it
/// was made.
pub fn write(entries: &mut [(Key, Solution)]) -> String {
    entries.sort_by(|a, b| order(&a.0, &b.0));
    let mut out = String::from(
        "# Lifting-surface solutions the note's study needs, solved ahead of time: written by\n\
         # `cargo xtask tables` (stability_core::frozen). Do not edit.\n",
    );
    out.push_str(HEADER);
    out.push('\n');
    for (k, s) in entries.iter() {
        let shape = k.1.map(f64::from_bits);
        let numbers = [
            shape[0],
            shape[1],
            shape[2],
            shape[3],
            f64::from_bits(k.2),
            f64::from_bits(k.3),
            s.lift_alpha,
            s.moment_alpha,
            s.lift_alphadot,
            s.moment_alphadot,
            s.lift_q,
            s.moment_q,
        ];
        out.push_str(k.0.name());
        for x in numbers {
            out.push_str(&format!(",{x:?}"));
        }
        out.push('\n');
    }
    out
}

/// What [`WRITE_ENV`] writes: everything this process solved that the
/// file could hold (the Mach box's cache and the near-sonic lattice's
/// frequency tables), with the file's own entries under [`KEEP_ENV`].
pub fn solved() -> Vec<(Key, Solution)> {
    let mut out = crate::aerodynamics::lifting_surface::mach_box::cache::solved();
    out.extend(crate::aerodynamics::lifting_surface::cache::near_sonic_solved());
    if std::env::var_os(KEEP_ENV).is_some() {
        out.extend(entries());
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_writer_and_the_reader_agree_to_the_bit() {
        let key = (
            Kind::NearSonicLattice,
            [1.0, 0.0, 1.0, std::f64::consts::FRAC_PI_4].map(f64::to_bits),
            0.995_f64.to_bits(),
            0.35_f64.to_bits(),
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
        let text = write(&mut [(key, s)]);
        let back = parse(&text);
        assert_eq!(back.len(), 1);
        let got = back[&key];
        for (a, b) in [
            (got.lift_alpha, s.lift_alpha),
            (got.moment_alpha, s.moment_alpha),
            (got.lift_alphadot, s.lift_alphadot),
            (got.moment_q, s.moment_q),
        ] {
            assert_eq!(a.to_bits(), b.to_bits());
        }
        assert_eq!(got, s);
    }
}
