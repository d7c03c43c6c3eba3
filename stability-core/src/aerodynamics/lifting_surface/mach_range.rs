//! The wing's [`Solution`] at any Mach number from 0 to [`MACH_RANGE_MAX`]:
//! one dispatch over the three lifting-surface methods, cached.
//!
//! - 0 ≤ M ≤ 0.9: the doublet lattice on its default grid
//!   ([`store::lattice`], Albano & Rodden 1969), unchanged (at 0.9 the
//!   refined lattice is the default one);
//! - 0.9 < M ≤ 1: the refined lattice and its sonic extrapolation
//!   ([`store::near_sonic`], `docs/lattice-near-sonic.md`). Above M = 0.99
//!   (the extrapolation in β²) it needs ω̄ ≥ [`SONIC_OMEGA_BAR_MIN`], where
//!   it was verified: below, an error that says what to give instead;
//! - M ≥ [`first_mach_box_mach`]: the Mach box method
//!   ([`store::mach_box`], Pines, Dugundji &
//!   Neuringer 1955; `docs/supersonic-oscillatory.md`), with
//!   [`Warning::MachBoxSubsonicEdge`] where the leading edge is subsonic
//!   and β cot Λ < [`MACH_BOX_VERIFIED_BETA_COT`] (not verified there) or
//!   just below sonic, [`MACH_BOX_NEAR_SONIC_EDGE`] ≤ β cot Λ < 1 (the
//!   diaphragm narrower than a box: up to 4 % off eq (36));
//! - 1 < M < [`first_mach_box_mach`] (a few thousandths of Mach number on
//!   the note's deltas, where the Mach box's grid, Δx = βΔy, holds fewer
//!   than [`MACH_BOX_MIN_STRIPS`] strips within its row limit; up to where
//!   the trailing edge turns supersonic on a wing whose trailing edge is
//!   swept, which the Mach box needs): the straight
//!   line in M between the sonic point and the Mach box's first solution,
//!   with [`Warning::SonicBridge`] — a bridge, not a theory.
//!
//! [`steady`] gives the quasi-steady solution with its Mach derivatives
//! (for eqs 27–29): the lattice's exact ones up to M = 0.99, above M = 1
//! the Mach box's table in Mach number and the slope of its cubic
//! ([`super::mach_table`]).
//! [`coefficients`] gives its lift slope and aerodynamic centre at every
//! M, joined between M = 0.99 and [`first_mach_box_mach`] through the
//! sonic point of linear theory, slender-wing theory ([`sonic_steady`]).

use super::derivatives::Extrapolate;
pub use super::mach_table::{MACH_BOX_MIN_STRIPS, MACH_RANGE_MAX, first_mach_box_mach};
use super::near_sonic::{NEAR_SONIC_FROM, SONIC_ANCHORS, SONIC_OMEGA_BAR_MIN};
use super::{Harmonic, LiftingSurfaceError, Solution, Steady, Trapezoid, mach_table, store};

use crate::aerodynamics::warnings::Warning;
use crate::numerics::interpolation::{hermite, monotone_slopes};

/// The smallest β cot Λ at which the Mach box's subsonic leading edge was
/// verified: within 1 % of eq (36) (ω̄ → 0, h = ¼; m_θ̇ on the scale of
/// m_q) on the 45° delta at M = 1.2 and 1.3, the 60° at M = 1.6 and at
/// β cot Λ = 0.5 and 0.3, the edge's 1/√d upwash averaged exactly over its
/// boxes (`lifting_surface::mach_box::edge`; docs/supersonic-oscillatory.md).
pub const MACH_BOX_VERIFIED_BETA_COT: f64 = 0.3;

/// Below the sonic leading edge, from this β cot Λ to 1, the diaphragm
/// is narrower than one box and the Mach box's z_θ̇ was measured up to
/// 4 % off eq (36) (60° delta: −0.8 % at 0.93, −3.9 % at 0.993, within
/// 0.25 % again at 1): warned.
pub const MACH_BOX_NEAR_SONIC_EDGE: f64 = 0.95;

/// The Mach-number step of a central difference of the Mach box long
/// enough that its discretisation error (≈ 10⁻⁴ of C_Lα, varying with M as
/// the edges cut the boxes differently) is not amplified into the
/// derivative (at 0.005 the 45° delta's dC_Lα/dM at M = 2 was 3 % off the
/// exact −4M/β³): what the tests difference the Mach box over. ([`steady`]
/// takes the slope of [`super::mach_table`]'s cubic, on nodes 0.05 apart
/// in β, instead.)
pub const MACH_BOX_STEP: f64 = 0.05;

/// Which method gave a [`Solution`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    Lattice,
    NearSonic,
    /// The line between the sonic point and the Mach box's first Mach number.
    SonicBridge,
    MachBox,
}

/// A solution, the method that gave it, and what is worth a warning.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AtMach {
    pub solution: Solution,
    pub method: Method,
    pub warning: Option<Warning>,
}

/// The wing's [`Solution`] at `mach` (0 ≤ M ≤ [`MACH_RANGE_MAX`]) and ω̄
/// (see the module's documentation for which method, where).
pub fn solution(
    wing: &Trapezoid,
    mach: f64,
    omega_bar: f64,
    harmonic: Harmonic,
) -> Result<AtMach, LiftingSurfaceError> {
    if !(mach.is_finite() && (0.0..=MACH_RANGE_MAX).contains(&mach)) {
        return Err(LiftingSurfaceError::MachRange(mach));
    }
    if !(omega_bar.is_finite() && omega_bar >= 0.0) {
        return Err(LiftingSurfaceError::Frequency(omega_bar));
    }
    let plain = |solution, method| AtMach {
        solution,
        method,
        warning: None,
    };
    // at 0.9 itself the refined lattice is the default one: one cache slot
    if mach <= NEAR_SONIC_FROM {
        let s = store::lattice(wing, mach, omega_bar, harmonic)?;
        return Ok(plain(s, Method::Lattice));
    }
    let first = first_mach_box_mach(wing);
    if mach >= first {
        return supersonic(wing, mach, omega_bar, harmonic);
    }
    if mach > SONIC_ANCHORS[0] && omega_bar < SONIC_OMEGA_BAR_MIN {
        return Err(LiftingSurfaceError::SonicFrequency {
            mach,
            omega_bar,
            first_mach_box: first,
        });
    }
    if mach <= 1.0 {
        let s = store::near_sonic(wing, mach, omega_bar, harmonic)?;
        return Ok(plain(s, Method::NearSonic));
    }
    let a = store::near_sonic(wing, 1.0, omega_bar, harmonic)?;
    let b = supersonic(wing, first, omega_bar, harmonic)?.solution;
    let t = (mach - 1.0) / (first - 1.0);
    let s = Solution {
        mach,
        ..a.combine(&b, 1.0 - t, t)
    };
    Ok(AtMach {
        solution: s,
        method: Method::SonicBridge,
        warning: Some(Warning::SonicBridge {
            mach,
            mach_box_from: first,
        }),
    })
}

/// The Mach box's solution (M > 1), solved at ω̄ or interpolated between
/// the frequency nodes as `harmonic` says
/// ([`store::mach_box_with`]), warned where the leading edge is
/// subsonic beyond the verified β cot Λ.
fn supersonic(
    wing: &Trapezoid,
    mach: f64,
    omega_bar: f64,
    harmonic: Harmonic,
) -> Result<AtMach, LiftingSurfaceError> {
    let s = match harmonic {
        Harmonic::Direct => store::mach_box(wing, mach, omega_bar)?,
        Harmonic::Interpolated => mach_table::solution(wing, mach, omega_bar)?.0,
    };
    Ok(AtMach {
        solution: s,
        method: Method::MachBox,
        warning: subsonic_edge_warning(wing, mach),
    })
}

/// [`Warning::MachBoxSubsonicEdge`] where the leading edge is subsonic
/// beyond the verified β cot Λ or just below sonic.
fn subsonic_edge_warning(wing: &Trapezoid, mach: f64) -> Option<Warning> {
    let beta_cot = (mach * mach - 1.0).sqrt() / wing.sweep_le.tan();
    let doubtful = beta_cot < MACH_BOX_VERIFIED_BETA_COT
        || (MACH_BOX_NEAR_SONIC_EDGE..1.0).contains(&beta_cot);
    (wing.sweep_le > 0.0 && doubtful).then_some(Warning::MachBoxSubsonicEdge {
        mach,
        beta_cot,
        verified: MACH_BOX_VERIFIED_BETA_COT,
    })
}

/// The quasi-steady solution at `mach` with its Mach derivatives (eqs
/// 27–29 need dC_Lα/dM and dH₀/dM): the lattice's exact ones
/// ([`Lattice::solve_steady`](super::Lattice::solve_steady)) below M = 0.99
/// — on the default lattice below 0.9 ([`store::lattice_steady`]), on the refined
/// one of [`store::near_sonic`] above ([`store::near_sonic_steady`]); from
/// [`first_mach_box_mach`] on, the Mach box's table in Mach number
/// ([`super::mach_table`], quasi-steady): the cubic through its four nodes
/// around M and the cubic's slope. Between M = 0.99 and [`first_mach_box_mach`]
/// an error ([`LiftingSurfaceError::SonicSteady`]): the quasi-steady α̇
/// derivatives are infinite at M = 1.
pub fn steady(
    wing: &Trapezoid,
    mach: f64,
) -> Result<(Steady, Option<Warning>), LiftingSurfaceError> {
    if mach.is_finite() && (0.0..=NEAR_SONIC_FROM).contains(&mach) {
        return Ok((store::lattice_steady(wing, mach)?, None));
    }
    let first = first_mach_box_mach(wing);
    if (NEAR_SONIC_FROM..=SONIC_ANCHORS[0]).contains(&mach) {
        return Ok((store::near_sonic_steady(wing, mach)?, None));
    }
    if mach.is_finite() && mach > SONIC_ANCHORS[0] && mach < first {
        return Err(LiftingSurfaceError::SonicSteady {
            mach,
            first_mach_box: first,
        });
    }
    if !mach.is_finite() || mach > MACH_RANGE_MAX {
        return Err(LiftingSurfaceError::MachRange(mach));
    }
    let (at, slope) = mach_table::solution(wing, mach, 0.0)?;
    let s = Steady {
        solution: at,
        d_lift_alpha: slope.lift_alpha,
        d_moment_alpha: slope.moment_alpha,
        d_lift_q: slope.lift_q,
        d_moment_q: slope.moment_q,
    };
    let warning = subsonic_edge_warning(wing, mach);
    Ok((s, warning))
}

/// The quasi-steady lift slope C_Lα and aerodynamic centre H₀ (fraction
/// of the M.A.C. aft of its leading edge), each with dX/dM, and whether
/// they come from the join across M = 1 ([`coefficients`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadyCoefficients {
    pub lift_slope: (f64, f64),
    pub aerodynamic_centre: (f64, f64),
    pub joined: bool,
}

impl From<&Steady> for SteadyCoefficients {
    fn from(s: &Steady) -> SteadyCoefficients {
        SteadyCoefficients {
            lift_slope: s.lift_slope(),
            aerodynamic_centre: s.aerodynamic_centre(),
            joined: false,
        }
    }
}

/// The lift slope and aerodynamic centre of linear theory at M = 1:
/// there the linearised equation loses its streamwise term and every wing
/// is a slender wing (R.T. Jones, NACA Rep. 835, 1946; the note's (37)):
/// C_Lα = πA/2, the lift growing with the square of the local span, so
/// that with a straight leading edge of sweep Λ ≥ 0 up to the tip's
/// leading corner x_t = s·tan Λ the centre lies at (2/3)x_t from the apex
/// (at the apex for Λ = 0). `None` for a forward-swept leading edge, whose
/// sections are not convex.
pub fn sonic_steady(wing: &Trapezoid) -> Option<(f64, f64)> {
    if wing.sweep_le.is_nan() || wing.sweep_le < 0.0 {
        return None;
    }
    let aspect_ratio = 4.0 * wing.semi_span * wing.semi_span / wing.area();
    let x_ac = 2.0 / 3.0 * wing.semi_span * wing.sweep_le.tan();
    let h0 = (x_ac - wing.x_mac()) / wing.mac();
    Some((std::f64::consts::PI * aspect_ratio / 2.0, h0))
}

/// The quasi-steady lift slope and aerodynamic centre at any M in
/// [0, [`MACH_RANGE_MAX`]]: [`steady`]'s, and between M = 0.99
/// ([`SONIC_ANCHORS`]`[0]`) and [`first_mach_box_mach`] (0.0155 of Mach
/// number on the 45° delta, 0.0264 on the 60°), where the quasi-steady α̇
/// derivatives are infinite and `steady` refuses, a join: on each of
/// [0.99, 1] and [1, M_b] the cubic through the ends' values and slopes
/// (the lattice's exact one at 0.99, the Mach box's difference at M_b),
/// through the sonic point [`sonic_steady`] at M = 1, the slopes limited as
/// Fritsch and Carlson's so that no piece overshoots its ends (a peak at
/// M = 1 gets slope zero there). Without a sonic point (forward sweep) one
/// cubic from 0.99 to M_b. The join is stated, not a theory: `joined`.
pub fn coefficients(
    wing: &Trapezoid,
    mach: f64,
) -> Result<SteadyCoefficients, LiftingSurfaceError> {
    match steady(wing, mach) {
        Ok((s, _)) => Ok(SteadyCoefficients::from(&s)),
        Err(LiftingSurfaceError::SonicSteady { .. }) => sonic_join(wing, mach),
        Err(e) => Err(e),
    }
}

/// [`coefficients`] in the band (0.99, M_b).
fn sonic_join(wing: &Trapezoid, mach: f64) -> Result<SteadyCoefficients, LiftingSurfaceError> {
    let (m0, m1) = (SONIC_ANCHORS[0], first_mach_box_mach(wing));
    let (lo, hi) = (steady(wing, m0)?.0, steady(wing, m1)?.0);
    let ends = |f: fn(&Steady) -> (f64, f64)| {
        let ((y0, d0), (y1, d1)) = (f(&lo), f(&hi));
        [(m0, y0, d0), (m1, y1, d1)]
    };
    let sonic = sonic_steady(wing);
    let lift = join(ends(Steady::lift_slope), sonic.map(|s| s.0), mach);
    let centre = join(ends(Steady::aerodynamic_centre), sonic.map(|s| s.1), mach);
    Ok(SteadyCoefficients {
        lift_slope: lift,
        aerodynamic_centre: centre,
        joined: true,
    })
}

/// The monotone piecewise cubic at `mach` through the ends (m₀, y₀, y₀′)
/// and (m₁, y₁, y₁′) and the sonic value at M = 1 if any: (value, slope).
fn join(
    [(m0, y0, d0), (m1, y1, d1)]: [(f64, f64, f64); 2],
    sonic: Option<f64>,
    mach: f64,
) -> (f64, f64) {
    let piece = |(xa, ya, da): (f64, f64, f64), (xb, yb, db): (f64, f64, f64)| {
        let secant = (yb - ya) / (xb - xa);
        let (da, db) = monotone_slopes(secant, da, db);
        let v = hermite((xa, ya, da), (xb, yb, db), mach);
        (v.value, v.d_mach)
    };
    let Some(ys) = sonic else {
        return piece((m0, y0, d0), (m1, y1, d1));
    };
    // the slope at M = 1: zero at an extremum, else the harmonic mean of
    // the two secants (Fritsch & Butland)
    let (s0, s1) = ((ys - y0) / (1.0 - m0), (y1 - ys) / (m1 - 1.0));
    let ds = if s0 * s1 > 0.0 {
        2.0 * s0 * s1 / (s0 + s1)
    } else {
        0.0
    };
    if mach <= 1.0 {
        piece((m0, y0, d0), (1.0, ys, ds))
    } else {
        piece((1.0, ys, ds), (m1, y1, d1))
    }
}
