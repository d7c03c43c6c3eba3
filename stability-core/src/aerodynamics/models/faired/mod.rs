//! The faired model (`faired`, the default): one frequency-dependent
//! linear lifting-surface theory at the short period's own ω̄ from M = 0 to
//! [`MACH_RANGE_MAX`] (3), the sonic point included
//! ([`crate::aerodynamics::lifting_surface::mach_range`]; docs/damping-theories.md, "The
//! faired model"):
//!
//! | Mach number | damping derivatives | lift slope, aerodynamic centre |
//! | --- | --- | --- |
//! | M ≤ 0.9 | the doublet lattice at the short period's ω̄ (Albano & Rodden 1969) | the lattice's, steady |
//! | 0.9 < M ≤ 0.99 | the lattice refined as β → 0 | the same |
//! | 0.99 < M ≤ 1 | the quadratic in β² through the refined lattice at 0.99, 0.995, 0.998 (the sonic point, checked against Mangler's (39)–(40) and the Mach box from above) | joined ([`SONIC_JOIN`]) |
//! | 1 < M < M_b | the straight line between the sonic point and the Mach box's first Mach number M_b (1.0055 on the 45° delta, 1.0164 on the 60°) | joined |
//! | M_b ≤ M ≤ 3 | the Mach box at ω̄ (Pines, Dugundji & Neuringer 1955; subsonic edges as Evvard's diaphragm) | the Mach box's, quasi-steady |
//! | M > 3 | linear supersonic theory ((36), the supersonic-edge theory), quasi-steady, as `faired-theories` | the same |
//!
//! The one join left, [`SONIC_JOIN`] to M_b (0.99 to 1.0055 on the 45°
//! delta, to 1.0164 on the 60°), reaches further above M = 1 the more slender the
//! wing and passes through the sonic point: the quasi-steady lift slope and
//! aerodynamic centre through linear theory's sonic values (πA/2, the
//! centre at ⅔ of the tip's leading-edge station), the damping derivatives
//! between the sonic solution at ω̄ and the Mach box's. There, below
//! ω̄ = [`SONIC_OMEGA_BAR_MIN`] (0.3), where the sonic extrapolation was
//! not verified, the derivatives are taken at 0.3, with
//! [`Warning::SonicFrequencyRaised`]. (The note's wings at μ₁ = 50 have
//! their short periods at ω̄ ≥ 0.39 there.)
//!
//! The note's own construction — the lattice to 0.9, Mangler's theory at
//! M = 1, linear theory from 1.2 and cubics between — is
//! `faired-theories` ([`theories`]), the default before `faired`.
//!
//! A sweep's (or the report's) frequency iteration
//! ([`Harmonic::Interpolated`]) interpolates the lattice in ω̄ and the Mach
//! box in ω̄ and in Mach number ([`crate::aerodynamics::lifting_surface::mach_table`]);
//! the note's study reads its near-sonic solutions from [`crate::aerodynamics::lifting_surface::precomputed`].

pub mod slender;
pub mod theories;

use super::increment::{self, Increment, Method, with_derivatives};
use super::regime::{Regime, RegimeKind};
use crate::aerodynamics::damping::{
    Damping, DampingError, Theory, WingInput, damping_derivatives_with, theory_coefficients,
};
use crate::aerodynamics::damping::{OwnTheory, TheoryCoefficients};
use crate::aerodynamics::lifting_surface::configuration::ConfigurationError;
use crate::aerodynamics::lifting_surface::mach_range::{self, first_mach_box_mach};
use crate::aerodynamics::lifting_surface::near_sonic::{
    NEAR_SONIC_FROM, SONIC_ANCHORS, SONIC_OMEGA_BAR_MIN,
};
use crate::aerodynamics::lifting_surface::{Harmonic, LiftingSurfaceError, Trapezoid, store};
use crate::aerodynamics::warnings::Warning;
use crate::geometry::configuration::Configuration;
use crate::geometry::{Planform, sonic_leading_edge_mach};
use crate::numerics::interpolation::Value;

pub use crate::aerodynamics::lifting_surface::mach_range::MACH_RANGE_MAX;

/// Where the lift slope and aerodynamic centre leave the lattice for the
/// join through the sonic point (the first of the sonic extrapolation's
/// anchors, M = 0.99).
pub const SONIC_JOIN: f64 = SONIC_ANCHORS[0];

/// The unit wing (root chord 1) of a planform's shape.
fn unit_wing(planform: &Planform) -> Result<Trapezoid, LiftingSurfaceError> {
    store::unit_wing(planform.aspect_ratio(), planform.taper, planform.sweep_le)
}

/// The join of the faired model's lift slope and aerodynamic centre about
/// M = 1 for a planform: from [`SONIC_JOIN`] to the Mach box's first Mach
/// number (the damping derivatives' part of it starts at M = 1).
pub fn sonic_join(planform: &Planform) -> Option<(f64, f64)> {
    let wing = unit_wing(planform).ok()?;
    Some((SONIC_JOIN, first_mach_box_mach(&wing)))
}

/// The faired model's regimes for a planform, in Mach order: the lattice
/// to [`SONIC_JOIN`], the join through the sonic point to the Mach box's
/// first Mach number, the Mach box to M = 3 (its leading edge subsonic,
/// then supersonic past 1/cos Λ), linear supersonic theory beyond.
pub fn regimes(planform: &Planform) -> Vec<Regime> {
    let Some((join_from, mach_box_from)) = sonic_join(planform) else {
        return theories::regimes(planform);
    };
    let edge = sonic_leading_edge_mach(planform.sweep_le).clamp(mach_box_from, MACH_RANGE_MAX);
    let beyond = if sonic_leading_edge_mach(planform.sweep_le) > MACH_RANGE_MAX {
        (RegimeKind::SubsonicEdge, "(36), subsonic leading edge")
    } else {
        (RegimeKind::SupersonicEdge, "supersonic leading edge")
    };
    let all = [
        (
            0.0,
            NEAR_SONIC_FROM,
            RegimeKind::Subsonic,
            "lifting surface",
        ),
        (
            NEAR_SONIC_FROM,
            join_from,
            RegimeKind::NearSonic,
            "lifting surface refined near M = 1",
        ),
        (
            join_from,
            mach_box_from,
            RegimeKind::Faired,
            "joined through the sonic point",
        ),
        (
            mach_box_from,
            edge,
            RegimeKind::MachBoxSubsonicEdge,
            "Mach box, subsonic leading edge",
        ),
        (
            edge,
            MACH_RANGE_MAX,
            RegimeKind::MachBoxSupersonicEdge,
            "Mach box, supersonic leading edge",
        ),
        (MACH_RANGE_MAX, f64::INFINITY, beyond.0, beyond.1),
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

/// The faired model's damping derivatives of the wing at c.g. `h`, Mach
/// `mach` and the short period's ω̄ (`omega_bar`), the harmonic solutions
/// had as `harmonic` says: `lifting-surface-frequency` at M ≤ 3 (at
/// ω̄ = [`SONIC_OMEGA_BAR_MIN`] where the sonic solution needs it, with
/// [`Warning::SonicFrequencyRaised`]), linear supersonic theory beyond.
pub fn damping(
    wing: &WingInput,
    h: f64,
    mach: f64,
    omega_bar: Option<f64>,
    harmonic: Harmonic,
) -> Result<Damping, DampingError> {
    let at = |theory: Theory, w: Option<f64>| {
        damping_derivatives_with(theory, wing, h, mach, w, harmonic)
    };
    if mach.is_finite() && mach > MACH_RANGE_MAX {
        return at(Theory::Supersonic, omega_bar);
    }
    match at(Theory::LiftingSurfaceFrequency, omega_bar) {
        Err(DampingError::LiftingSurface(LiftingSurfaceError::SonicFrequency { .. })) => {
            let used = SONIC_OMEGA_BAR_MIN;
            let mut d = at(Theory::LiftingSurfaceFrequency, Some(used))?;
            d.warnings.push(Warning::SonicFrequencyRaised {
                mach,
                omega_bar: omega_bar.unwrap_or(0.0),
                used,
            });
            Ok(d)
        }
        other => other,
    }
}

/// The faired model's lift slope and aerodynamic centre with their Mach
/// derivatives (eqs 27–29 need them): the lifting surface's quasi-steady
/// ones at M ≤ 3 ([`mach_range::coefficients`], joined through the sonic
/// point between [`SONIC_JOIN`] and the Mach box's first Mach number),
/// linear supersonic theory's beyond.
pub fn coefficients(
    planform: &Planform,
    mach: f64,
) -> Result<Option<TheoryCoefficients>, DampingError> {
    if !mach.is_finite() {
        return Ok(None);
    }
    if mach > MACH_RANGE_MAX {
        return theory_coefficients(Theory::Supersonic, planform, mach);
    }
    let c = mach_range::coefficients(&unit_wing(planform)?, mach)?;
    let value = |(v, d): (f64, f64)| Value::new(v, d);
    Ok(Some(TheoryCoefficients {
        // the lifting surface's, named as `--aero lifting-surface` and
        // `faired-theories` below M = 0.9 name them
        model: OwnTheory::Theory(Theory::LiftingSurface),
        lift_slope: value(c.lift_slope),
        aerodynamic_centre: value(c.aerodynamic_centre),
    }))
}

/// The first Mach number at which every surface of `config` has its Mach
/// box (each surface's [`first_mach_box_mach`], the latest): where
/// [`increment()`] leaves the bridge for the Mach box.
pub fn increment_mach_box_from(config: &Configuration) -> f64 {
    let unit = |t: &Trapezoid| store::unit_wing(t.aspect_ratio(), t.taper(), t.sweep_le).ok();
    std::iter::once(&config.wing)
        .chain(config.surfaces().map(|s| &s.shape))
        .filter_map(unit)
        .map(|w| first_mach_box_mach(&w))
        .fold(1.0, f64::max)
}

/// A configuration's increment over its wing by the faired model, one
/// lifting-surface theory through M = 1 as the wing's
/// (docs/configurations.md):
///
/// | Mach number | the increment |
/// | --- | --- |
/// | M ≤ [`SONIC_JOIN`] (0.99) | the multi-surface doublet lattice at M (its default boxes) |
/// | 0.99 < M < M_b | the bridge: the straight line in M from the lattice's increment at 0.99 to the Mach boxes' at M_b ([`increment_mach_box_from`]: 1.0055 for the 45° delta's own shape); the multi-surface lattice is not extrapolated to the sonic point |
/// | M_b ≤ M ≤ 3 | each surface by the Mach box at its own ω̄, the wing's downwash at the tailplane |
/// | M > 3 | each surface by linear supersonic theory, as beyond the wing's Mach box |
///
/// At the wing's ω̄ (`omega_bar`: the model's frequency policy); with
/// `mach_derivatives`, the Mach derivatives of its in-phase numbers
/// (central differences within one method, the line's slope in the
/// bridge).
pub fn increment(
    config: &Configuration,
    mach: f64,
    omega_bar: f64,
    harmonic: Harmonic,
    mach_derivatives: bool,
) -> Result<Increment, ConfigurationError> {
    if !mach.is_finite() || mach < 0.0 {
        return Err(ConfigurationError::Geometry(format!(
            "the Mach number must be finite and ≥ 0, not {mach}"
        )));
    }
    let from = increment_mach_box_from(config);
    let at = |m: f64, method: Method, lo: f64, d: bool| {
        with_derivatives(config, m, omega_bar, method, harmonic, d, lo)
    };
    if mach <= SONIC_JOIN {
        return at(mach, Method::Lattice, 0.0, mach_derivatives);
    }
    if mach < from {
        let a = at(SONIC_JOIN, Method::Lattice, 0.0, false)?;
        let b = at(from, Method::MachBox, from, false)?;
        let t = (mach - SONIC_JOIN) / (from - SONIC_JOIN);
        let line = increment::line(&a, &b, t, from - SONIC_JOIN, mach, omega_bar);
        return Ok(Increment {
            d_lift_alpha: line.d_lift_alpha.filter(|_| mach_derivatives),
            d_moment_alpha: line.d_moment_alpha.filter(|_| mach_derivatives),
            ..line
        });
    }
    if mach <= MACH_RANGE_MAX {
        return at(mach, Method::MachBox, from, mach_derivatives);
    }
    at(mach, Method::Supersonic, MACH_RANGE_MAX, mach_derivatives)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Size;

    #[test]
    fn the_regimes_tile_the_mach_axis_and_the_join_is_within_three_hundredths_of_sonic() {
        for deg in [45.0_f64, 60.0, 30.0] {
            let p = Planform::new(deg.to_radians(), 0.0, Size::RootChord(10.0)).unwrap();
            let r = regimes(&p);
            assert_eq!(r[0].from, 0.0);
            assert!(r.windows(2).all(|w| w[0].to == w[1].from));
            assert_eq!(r.last().unwrap().to, f64::INFINITY);
            let joins: Vec<&Regime> = r.iter().filter(|r| r.kind == RegimeKind::Faired).collect();
            let [join] = joins[..] else { panic!("{r:?}") };
            assert!(join.from >= 0.97 && join.to <= 1.03, "{deg}°: {join:?}");
            if deg > 35.0 {
                let edge = r
                    .iter()
                    .find(|r| r.kind == RegimeKind::MachBoxSupersonicEdge)
                    .unwrap()
                    .from;
                let beta = (edge * edge - 1.0).sqrt();
                assert!((beta / deg.to_radians().tan() - 1.0).abs() < 1e-12);
            }
        }
    }
}
