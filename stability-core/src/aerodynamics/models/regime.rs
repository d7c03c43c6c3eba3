//! A damping model's regimes: the ranges of Mach number over which it is
//! one theory, or a stated join between two.

/// What a damping model is over a range of Mach numbers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum RegimeKind {
    /// Subsonic: lifting-surface theory (the doublet lattice).
    Subsonic,
    /// The doublet lattice refined as M → 1 (`faired`, 0.9 < M ≤ 0.99).
    NearSonic,
    /// Faired between two theories: a guess (`faired-theories`), or the
    /// stated join through the sonic point (`faired`).
    Faired,
    /// Supersonic, the leading edge subsonic: (36).
    SubsonicEdge,
    /// Supersonic, the leading edge supersonic: the supersonic-edge theory.
    SupersonicEdge,
    /// The Mach box, the leading edge subsonic.
    MachBoxSubsonicEdge,
    /// The Mach box, the leading edge supersonic.
    MachBoxSupersonicEdge,
}

/// A range of Mach numbers and what a damping model is there.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Regime {
    pub from: f64,
    /// `f64::INFINITY` for the last.
    pub to: f64,
    pub kind: RegimeKind,
    /// In words, for a legend: "lifting surface", "joined through the
    /// sonic point", "Mach box, subsonic leading edge", ….
    pub label: &'static str,
}
