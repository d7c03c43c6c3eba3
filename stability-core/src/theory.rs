//! The theories of §7 the damping derivatives come from (the table in
//! `damping`): their names in configs and on the command line, and the
//! report's equations for each. Its own module so that `damping` and
//! `warnings`, which both name theories, need not import each other.

use crate::display::excerpt;
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

impl Theory {
    pub const ALL: [Theory; 8] = [
        Theory::Garrick,
        Theory::GarnerTaper,
        Theory::Slender,
        Theory::Supersonic,
        Theory::Transonic,
        Theory::TransonicFrequency,
        Theory::LiftingSurface,
        Theory::LiftingSurfaceFrequency,
    ];

    /// The theory's name in configs and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Theory::Garrick => "garrick",
            Theory::GarnerTaper => "garner-taper",
            Theory::Slender => "slender",
            Theory::Supersonic => "supersonic",
            Theory::Transonic => "transonic",
            Theory::TransonicFrequency => "transonic-frequency",
            Theory::LiftingSurface => "lifting-surface",
            Theory::LiftingSurfaceFrequency => "lifting-surface-frequency",
        }
    }

    /// The report's equations (for the lifting surface, which the report
    /// quotes but does not print, its section and method).
    pub fn equations(self) -> &'static str {
        match self {
            Theory::Garrick => "(32)–(33)",
            Theory::GarnerTaper => "(34)–(35)",
            Theory::Slender => "(37)",
            Theory::Supersonic => "(36)",
            Theory::Transonic => "(38)",
            Theory::TransonicFrequency => "(39)–(40)",
            Theory::LiftingSurface | Theory::LiftingSurfaceFrequency => "§7, doublet lattice",
        }
    }

    /// The equations as messages cite them, in parentheses: `(39)–(40)`,
    /// `(§7, doublet lattice)`.
    pub fn cited(self) -> &'static str {
        match self {
            Theory::LiftingSurface | Theory::LiftingSurfaceFrequency => "(§7, doublet lattice)",
            t => t.equations(),
        }
    }

    /// Whether the derivatives depend on the frequency parameter ω̄ and it
    /// is iterated to the short period's own (ω̄ = s/μ₁).
    pub fn uses_frequency(self) -> bool {
        matches!(
            self,
            Theory::TransonicFrequency | Theory::LiftingSurfaceFrequency
        )
    }

    /// Whether the theory takes a frequency parameter ω̄ at all: the
    /// iterated ones, and `lifting-surface` (quasi-steady, or at a given
    /// ω̄).
    pub fn takes_omega_bar(self) -> bool {
        self.uses_frequency() || self == Theory::LiftingSurface
    }

    /// Whether the theory is the doublet lattice's
    /// ([`crate::lifting_surface`]), for any straight-tapered wing.
    pub fn is_lifting_surface(self) -> bool {
        matches!(
            self,
            Theory::LiftingSurface | Theory::LiftingSurfaceFrequency
        )
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
