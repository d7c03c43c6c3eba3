//! The theories of §7 the damping derivatives come from, as one registry:
//! each theory's row ([`Row`]: its name in configs and on the command
//! line, the report's equations, what it is, where it is valid and what it
//! supplies) is read by the command line's `--help`, the Python package's
//! `theories(details=True)`, the error messages and the docs' table. A new
//! theory is a variant here with its row in the registry's table, and its
//! derivatives in `damping` (the match there fails to compile until it has
//! them). Its own module so that `damping` and `warnings`, which both name
//! theories, need not import each other.

use crate::numerics::display::excerpt;
use serde::Serialize;
use std::fmt;
use std::str::FromStr;

/// A theory of the damping derivatives; serializes as its name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Theory {
    Garrick,
    GarnerTaper,
    Slender,
    Supersonic,
    Transonic,
    TransonicFrequency,
    LiftingSurface,
    LiftingSurfaceFrequency,
}

/// What a front end says about a model: one row of the registry.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct Row {
    /// The name in configs, on the command line and in Python.
    pub name: &'static str,
    /// The report's equations, `(32)–(33)`, or the section and method where
    /// the report quotes a theory without printing it; empty for none.
    pub equations: &'static str,
    /// What it is, in a line.
    pub summary: &'static str,
    /// Where it applies (Mach numbers, planforms, frequencies).
    pub validity: &'static str,
    /// What it supplies to the derivative set.
    pub supplies: &'static str,
    /// Where it comes from.
    pub source: &'static str,
}

impl Row {
    /// The summary with the equations and the validity, as `--help` lists
    /// a choice: "Garrick's …, incompressible (eqs (32)–(33)); valid: …".
    pub fn help(&self) -> String {
        let eqs = match self.equations {
            "" => return format!("{}; valid: {}", self.summary, self.validity),
            e if !e.starts_with('(') => "",
            e if e.contains(['–', ',']) => "eqs ",
            _ => "eq ",
        };
        format!(
            "{} ({eqs}{}); valid: {}",
            self.summary, self.equations, self.validity
        )
    }
}

/// How a theory takes the frequency parameter ω̄ = ωc̄/V.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Frequency {
    /// Quasi-steady: no ω̄.
    None,
    /// Quasi-steady, or at a ω̄ given (`--omega-bar`).
    Given,
    /// At the short period's own ω̄ = s/μ₁, iterated (or a ω̄ given).
    Iterated,
}

/// A theory's row and how it is evaluated.
struct Entry {
    theory: Theory,
    row: Row,
    frequency: Frequency,
    /// The doublet lattice's ([`crate::aerodynamics::lifting_surface`]), for any
    /// straight-tapered wing.
    lattice: bool,
}

/// The pair of damping-in-pitch and acceleration derivatives every theory
/// gives.
const PAIRS: &str = "z_q, z_ẇ, m_q, m_ẇ";

/// The registry, in the order of [`Theory::ALL`] (a test checks it).
const THEORIES: [Entry; 8] = [
    Entry {
        theory: Theory::Garrick,
        row: Row {
            name: "garrick",
            equations: "(32)–(33)",
            summary: "Garrick's low-aspect-ratio theory, incompressible",
            validity: "true deltas of low aspect ratio, M → 0 (warns above M = 0.7)",
            supplies: "z_θ̇, m_θ̇ (split into z_q, z_ẇ, m_q, m_ẇ by slender-wing theory's z_ẇ, m_ẇ)",
            source: "I.E. Garrick's low-aspect-ratio theory (after R.T. Jones), as the note quotes it",
        },
        frequency: Frequency::None,
        lattice: false,
    },
    Entry {
        theory: Theory::GarnerTaper,
        row: Row {
            name: "garner-taper",
            equations: "(34)–(35)",
            summary: "Garner's version of it for taper 1/7",
            validity: "taper 1/7 only, M → 0 (warns above M = 0.7)",
            supplies: "z_θ̇, m_θ̇ (split as garrick's)",
            source: "H.C. Garner's taper-1/7 version of the same theory",
        },
        frequency: Frequency::None,
        lattice: false,
    },
    Entry {
        theory: Theory::Slender,
        row: Row {
            name: "slender",
            equations: "(37)",
            summary: "Ribner's slender-wing theory",
            validity: "slender wings (small β·A), any Mach number to the sonic leading edge",
            supplies: PAIRS,
            source: "H.S. Ribner, slender-wing theory, NACA TN 1423 (1947)",
        },
        frequency: Frequency::None,
        lattice: false,
    },
    Entry {
        theory: Theory::Supersonic,
        row: Row {
            name: "supersonic",
            equations: "(36)",
            summary: "supersonic linear theory (M > 1): Mangler, Ribner & Malvestuto for subsonic leading edges, conical flow beyond the sonic edge",
            validity: "M > 1; true deltas, and cropped ones while the tips' Mach waves do not meet on the wing; ω̄(c₀/c̄)M²/(M² − 1) small (warns past it)",
            supplies: "z_q, z_ẇ, m_q, m_ẇ, and its own lift slope and aerodynamic centre",
            source: "K.W. Mangler; H.S. Ribner & F.S. Malvestuto, NACA Rep. 908 (1948); conical flow for supersonic leading edges (`supersonic`)",
        },
        frequency: Frequency::None,
        lattice: false,
    },
    Entry {
        theory: Theory::Transonic,
        row: Row {
            name: "transonic",
            equations: "(38)",
            summary: "Mangler's transonic theory at M = 1, steady",
            validity: "M within 0.2 of 1",
            supplies: PAIRS,
            source: "K.W. Mangler's low-frequency theory at M = 1",
        },
        frequency: Frequency::None,
        lattice: false,
    },
    Entry {
        theory: Theory::TransonicFrequency,
        row: Row {
            name: "transonic-frequency",
            equations: "(39)–(40)",
            summary: "the same with its frequency terms, ω̄ iterated to the short period's own",
            validity: "M near 1, ω̄ > 0",
            supplies: PAIRS,
            source: "K.W. Mangler, with the frequency-dependent terms",
        },
        frequency: Frequency::Iterated,
        lattice: false,
    },
    Entry {
        theory: Theory::LiftingSurface,
        row: Row {
            name: "lifting-surface",
            equations: "§7, doublet lattice, Mach box",
            summary: "Multhopp–Garner and Lehrian's lifting-surface theory by the doublet lattice (Albano & Rodden) below M = 1 and the Mach box (Pines, Dugundji & Neuringer) above, quasi-steady or at --omega-bar W",
            validity: "any straight-tapered wing, 0 ≤ M ≤ 3 (lattice below M = 1, sonic extrapolation at 1, Mach box above)",
            supplies: "z_q, z_ẇ, m_q, m_ẇ (with --aero lifting-surface also the lift slope and aerodynamic centre)",
            source: "Multhopp–Garner, Lehrian; the doublet lattice of Albano & Rodden (1969) with the kernel of Rodden, Taylor & McIntosh (1998) (`lifting_surface`); the Mach box of Pines, Dugundji & Neuringer (1955) (`lifting_surface::mach_box`)",
        },
        frequency: Frequency::Given,
        lattice: true,
    },
    Entry {
        theory: Theory::LiftingSurfaceFrequency,
        row: Row {
            name: "lifting-surface-frequency",
            equations: "§7, doublet lattice, Mach box",
            summary: "the same at the short period's own ω̄, iterated (a sweep interpolates between solved ω̄)",
            validity: "any straight-tapered wing, 0 ≤ M ≤ 3 (lattice below M = 1, sonic extrapolation at 1, Mach box above)",
            supplies: PAIRS,
            source: "as lifting-surface",
        },
        frequency: Frequency::Iterated,
        lattice: true,
    },
];

impl Theory {
    /// Every theory, in the registry's order.
    pub const ALL: [Theory; THEORIES.len()] = {
        let mut out = [Theory::Garrick; THEORIES.len()];
        let mut i = 0;
        while i < THEORIES.len() {
            out[i] = THEORIES[i].theory;
            i += 1;
        }
        out
    };

    fn entry(self) -> &'static Entry {
        &THEORIES[self as usize]
    }

    /// The theory's row of the registry.
    pub fn row(self) -> &'static Row {
        &self.entry().row
    }

    /// The theory's name in configs and on the command line.
    pub fn name(self) -> &'static str {
        self.row().name
    }

    /// The report's equations (for the lifting surface, which the report
    /// quotes but does not print, its section and method).
    pub fn equations(self) -> &'static str {
        self.row().equations
    }

    /// The equations as messages cite them, in parentheses: `(39)–(40)`,
    /// `(§7, doublet lattice, Mach box)`.
    pub fn cited(self) -> String {
        match self.equations() {
            e if e.starts_with('(') => e.to_string(),
            e => format!("({e})"),
        }
    }

    /// Whether the derivatives depend on the frequency parameter ω̄ and it
    /// is iterated to the short period's own (ω̄ = s/μ₁).
    pub fn uses_frequency(self) -> bool {
        self.entry().frequency == Frequency::Iterated
    }

    /// Whether the theory takes a frequency parameter ω̄ at all: the
    /// iterated ones, and `lifting-surface` (quasi-steady, or at a given
    /// ω̄).
    pub fn takes_omega_bar(self) -> bool {
        self.entry().frequency != Frequency::None
    }

    /// Whether the theory is the doublet lattice's
    /// ([`crate::aerodynamics::lifting_surface`]), for any straight-tapered wing.
    pub fn is_lifting_surface(self) -> bool {
        self.entry().lattice
    }
}

impl fmt::Display for Theory {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Theory {
    type Err = UnknownTheory;
    fn from_str(s: &str) -> Result<Self, UnknownTheory> {
        Theory::ALL
            .into_iter()
            .find(|t| t.name() == s)
            .ok_or_else(|| UnknownTheory { name: excerpt(s) })
    }
}

/// A name that is not a theory's (quoted as an excerpt).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("unknown damping theory `{name}`; the theories are {}", TheoryList)]
pub struct UnknownTheory {
    pub name: String,
}

/// `` `garrick`, `garner-taper`, … ``
struct TheoryList;

impl fmt::Display for TheoryList {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, t) in Theory::ALL.iter().enumerate() {
            let sep = if i == 0 { "" } else { ", " };
            write!(f, "{sep}`{}`", t.name())?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_registry_is_in_the_order_of_the_variants_and_names_are_unique() {
        for (i, e) in THEORIES.iter().enumerate() {
            assert_eq!(e.theory as usize, i, "{}", e.row.name);
            assert_eq!(e.theory.row().name, e.row.name);
        }
        let mut names: Vec<&str> = Theory::ALL.iter().map(|t| t.name()).collect();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), THEORIES.len());
    }

    #[test]
    fn help_lines_cite_the_equations() {
        let h = Theory::Garrick.row().help();
        assert!(
            h.starts_with("Garrick's") && h.contains("incompressible (eqs (32)–(33)); valid: "),
            "{h}"
        );
        assert!(Theory::Slender.row().help().contains(" (eq (37)); valid: "));
        let h = Theory::LiftingSurface.row().help();
        assert!(
            h.contains(" (§7, doublet lattice, Mach box); valid: any straight-tapered wing"),
            "{h}"
        );
        assert_eq!(
            Theory::LiftingSurface.cited(),
            "(§7, doublet lattice, Mach box)"
        );
        assert_eq!(Theory::TransonicFrequency.cited(), "(39)–(40)");
    }
}
