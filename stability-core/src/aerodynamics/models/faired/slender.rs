//! `faired-slender`, the previous quasi-steady fairing: slender-wing theory
//! (37) through M = 1, blended into linear supersonic theory (36) above.

use super::super::regime::{Regime, RegimeKind};
use crate::aerodynamics::damping::{
    Damping, DampingError, Theory, WingInput, damping_derivatives_with,
};
use crate::aerodynamics::lifting_surface::Harmonic;
use crate::aerodynamics::warnings::{Warning, Warnings};
use crate::derivatives::DampingDerivatives;
use crate::geometry::{Planform, sonic_leading_edge_mach};

/// Where the blend starts: the sonic point, slender-wing theory's limit.
const SONIC: f64 = 1.0;

/// [`DampingModel::FairedSlender`](crate::design::case::DampingModel::FairedSlender),
/// the previous fairing: slender-wing theory (37) to M = 1, blended into
/// linear supersonic theory over 1 ≤ M ≤ 1 + [`SLENDER_FAIRING_WIDTH`] by the
/// weight w = 3x² − 2x³, x = (M − 1)/width (w·(36)'s logarithmic
/// singularity at M = 1 vanishes with w), that theory beyond — (36) held at
/// its values at the sonic leading edge past it, with
/// [`Warning::FairedHeldAtSonicEdge`]. Quasi-steady throughout.
pub fn damping(wing: &WingInput, h: f64, m: f64) -> Result<Damping, DampingError> {
    let at = |theory: Theory, m: f64| {
        damping_derivatives_with(theory, wing, h, m, None, Harmonic::Direct)
    };
    let slender = at(Theory::Slender, m)?;
    if m <= SONIC {
        return Ok(slender);
    }
    let sonic = sonic_leading_edge_mach(wing.sweep_le);
    let mut warnings = Warnings::default();
    let m_sup = if m >= sonic {
        warnings.push(Warning::FairedHeldAtSonicEdge { sonic });
        sonic * (1.0 - 1e-9)
    } else {
        m
    };
    let sup = at(Theory::Supersonic, m_sup)?;
    let x = ((m - SONIC) / SLENDER_FAIRING_WIDTH).clamp(0.0, 1.0);
    let w = x * x * (3.0 - 2.0 * x);
    let blend = |a: f64, b: f64| (1.0 - w) * a + w * b;
    let (a, b) = (slender.derivatives, sup.derivatives);
    Ok(Damping {
        theory: Theory::Supersonic,
        derivatives: DampingDerivatives {
            z_q: blend(a.z_q, b.z_q),
            z_wdot: blend(a.z_wdot, b.z_wdot),
            m_q: blend(a.m_q, b.m_q),
            m_wdot: blend(a.m_wdot, b.m_wdot),
        },
        in_phase: Default::default(),
        fig18: sup.fig18,
        warnings,
    })
}

/// The width in Mach number of the slender fairing's blend above M = 1.
pub const SLENDER_FAIRING_WIDTH: f64 = 0.2;

/// The slender fairing's regimes: slender-wing theory to M = 1, the blend
/// to 1 + [`SLENDER_FAIRING_WIDTH`], (36) beyond (held at the sonic leading
/// edge past it).
pub fn regimes(planform: &Planform) -> Vec<Regime> {
    let end = SONIC + SLENDER_FAIRING_WIDTH;
    let edge = sonic_leading_edge_mach(planform.sweep_le).max(end);
    let all = [
        (0.0, SONIC, RegimeKind::Subsonic, "slender-wing theory (37)"),
        (SONIC, end, RegimeKind::Faired, "blended into (36)"),
        (
            end,
            edge,
            RegimeKind::SubsonicEdge,
            "(36), subsonic leading edge",
        ),
        (
            edge,
            f64::INFINITY,
            RegimeKind::SupersonicEdge,
            "(36) held at the sonic leading edge",
        ),
    ];
    all.into_iter()
        .filter(|r| r.1 > r.0)
        .map(|(from, to, kind, label)| Regime {
            from,
            to,
            kind,
            label,
        })
        .collect()
}
