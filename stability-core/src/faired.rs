//! The faired model (`faired`, the default): the §7 theories joined through
//! Mach number as the note built its Figs 19–24 — "with the aid of the
//! results of the various theories … the curves of Figs. 19 to 24 were
//! prepared" — each theory where the note trusts it, and between them a
//! stated join (docs/damping-theories.md, "The faired model"):
//!
//! | Mach number | damping derivatives | lift slope, aerodynamic centre |
//! | --- | --- | --- |
//! | M ≤ [`LIFTING_SURFACE_LIMIT`] (0.9) | lifting-surface theory at the short period's own ω̄ (the note: Multhopp–Garner "reliable … up to a Mach number of about 0.9") | the lattice's steady a, H₀ |
//! | 0.9 < M < 1 | faired: the lattice's values at 0.9 joined to Mangler's at M = 1 | faired: the lattice's at 0.9 joined to linear supersonic theory's at 1.2 |
//! | M = [`SONIC`] (1) | Mangler's transonic theory (38)–(40) at the short period's ω̄ ("claimed to be valid at M = 1.0") | (faired, as above) |
//! | 1 < M < 1.2 | faired: Mangler's at M = 1 joined to linear theory's at 1.2 | (faired, as above) |
//! | M ≥ [`SUPERSONIC_FROM`] (1.2) | linear supersonic theory: (36) while the leading edge is subsonic, the supersonic-edge theory past it (`supersonic::edge_theory`) | the same theory's |
//!
//! The bands are where the curve is a guess: the report draws them shaded.

use crate::geometry::{Planform, sonic_leading_edge_mach};

/// Up to this Mach number the faired model is lifting-surface theory (§7:
/// the Multhopp–Garner theory "provides what appears to be a reliable
/// prediction of the effects of compressibility up to a Mach number of
/// about 0.9").
pub const LIFTING_SURFACE_LIMIT: f64 = 0.9;

/// The Mach number of Mangler's transonic theory (38)–(40) ("claimed to be
/// valid at M = 1.0").
pub const SONIC: f64 = 1.0;

/// From this Mach number on the faired model is linear supersonic theory,
/// as the note applies (36) at M = 1.2 (§7, §10, Fig 17).
pub const SUPERSONIC_FROM: f64 = 1.2;

/// The two bands where the faired model joins one theory to the next:
/// [0.9, 1.0] (the lifting surface to Mangler's theory) and [1.0, 1.2]
/// (Mangler's theory to linear supersonic theory).
pub const JOINS: [(f64, f64); 2] = [(LIFTING_SURFACE_LIMIT, SONIC), (SONIC, SUPERSONIC_FROM)];

/// What the faired model is over a range of Mach numbers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum RegimeKind {
    /// Subsonic: lifting-surface theory.
    Subsonic,
    /// Faired between two theories: a guess.
    Faired,
    /// Supersonic, the leading edge subsonic: (36).
    SubsonicEdge,
    /// Supersonic, the leading edge supersonic: the supersonic-edge theory.
    SupersonicEdge,
}

/// A range of Mach numbers and what the faired model is there.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Regime {
    pub from: f64,
    /// `f64::INFINITY` for the last.
    pub to: f64,
    pub kind: RegimeKind,
    /// In words, for a legend: "lifting surface", "faired between
    /// theories", "(36), subsonic leading edge", "supersonic leading edge".
    pub label: &'static str,
}

/// The faired model's regimes for a planform, in Mach order: subsonic to
/// 0.9, the two joins, then (36) up to the Mach number where the leading
/// edge turns sonic, 1/cos Λ (`geometry::sonic_leading_edge_mach`), and the
/// supersonic-edge theory beyond. (Where the leading edge is already sonic
/// below 1.2 — sweep under 33.6° — the (36) regime is empty and left out.)
pub fn regimes(planform: &Planform) -> Vec<Regime> {
    let sonic_edge = sonic_leading_edge_mach(planform.sweep_le).max(SUPERSONIC_FROM);
    let all = [
        Regime {
            from: 0.0,
            to: LIFTING_SURFACE_LIMIT,
            kind: RegimeKind::Subsonic,
            label: "lifting surface",
        },
        Regime {
            from: JOINS[0].0,
            to: JOINS[0].1,
            kind: RegimeKind::Faired,
            label: "faired between theories",
        },
        Regime {
            from: JOINS[1].0,
            to: JOINS[1].1,
            kind: RegimeKind::Faired,
            label: "faired between theories",
        },
        Regime {
            from: SUPERSONIC_FROM,
            to: sonic_edge,
            kind: RegimeKind::SubsonicEdge,
            label: "(36), subsonic leading edge",
        },
        Regime {
            from: sonic_edge,
            to: f64::INFINITY,
            kind: RegimeKind::SupersonicEdge,
            label: "supersonic leading edge",
        },
    ];
    all.into_iter().filter(|r| r.to > r.from).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Size;

    #[test]
    fn the_regimes_tile_the_mach_axis_and_the_sonic_edge_is_where_beta_cot_is_one() {
        for deg in [45.0_f64, 60.0, 30.0] {
            let p = Planform::new(deg.to_radians(), 0.0, Size::RootChord(10.0)).unwrap();
            let r = regimes(&p);
            assert_eq!(r[0].from, 0.0);
            assert!(r.windows(2).all(|w| w[0].to == w[1].from));
            assert_eq!(r.last().unwrap().to, f64::INFINITY);
            let edge = r.last().unwrap().from;
            if deg > 35.0 {
                // β cot Λ = 1 there
                let beta = (edge * edge - 1.0).sqrt();
                assert!((beta / deg.to_radians().tan() - 1.0).abs() < 1e-12);
            } else {
                assert_eq!(edge, SUPERSONIC_FROM);
            }
        }
    }
}
