//! The damping derivatives of §7 — z_q, z_ẇ, m_q, m_ẇ and the
//! damping-in-pitch pair z_θ̇ = z_q + z_ẇ, m_θ̇ = m_q + m_ẇ (the OCR's z_δ,
//! m_ϕ, m_ý …) — from each theory the report uses, in the report's notation
//! (§3; lengths on the reference chord, h on the M.A.C., see `geometry`).
//! `docs/damping-theories.md` gives each formula as printed, as recovered,
//! and the evidence.
//!
//! The theories, with their equations, validity and sources, are the
//! registry of [`crate::aerodynamics::theory`].

pub use crate::aerodynamics::supersonic::eq36::{Fig18, eq36};
pub use crate::aerodynamics::theory::{Theory, UnknownTheory};
pub use crate::derivatives::DampingDerivatives;

use crate::aerodynamics::lifting_surface::{Harmonic, LiftingSurfaceError, mach_range, store};
use crate::aerodynamics::supersonic::{self, EdgeRegime, SupersonicError, Wing, transonic};
use crate::aerodynamics::warnings::{Warning, Warnings};
use crate::geometry::Planform;
use crate::numerics::display::{Num, OptNum};
use crate::numerics::interpolation::Value;
use crate::numerics::invalid::{self, Invalid};
use serde::Serialize;
use std::f64::consts::PI;

/// The planform quantities the theories use.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct WingInput {
    pub aspect_ratio: f64,
    /// Leading-edge sweep Λ (rad).
    pub sweep_le: f64,
    pub taper: f64,
}

impl From<&Planform> for WingInput {
    fn from(p: &Planform) -> Self {
        WingInput {
            aspect_ratio: p.aspect_ratio(),
            sweep_le: p.sweep_le,
            taper: p.taper,
        }
    }
}

/// The lift slope and aerodynamic centre a damping model's own theory
/// gives at one Mach number, each with its exact Mach derivative (eqs
/// 27–29 need them): what [`Source::Default`](crate::aerodynamics::models::aero::Source::Default) takes in place of the
/// methods of [`defaults`](crate::aerodynamics::models::defaults), so that z_w, m_w come from the same theory as
/// z_q, m_q, z_ẇ, m_ẇ.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TheoryCoefficients {
    /// Which theory gave them.
    pub model: OwnTheory,
    /// a = ∂C_L/∂α (per radian).
    pub lift_slope: Value,
    /// H₀, fraction of the M.A.C. aft of its leading edge.
    pub aerodynamic_centre: Value,
}

/// The theory a damping model's own coefficients come from: one theory of
/// the registry, or the join of `faired-theories` between the lattice and
/// linear supersonic theory. Serializes as the theory's name, the join as
/// `faired` (the key the output has always had).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OwnTheory {
    Theory(Theory),
    /// `faired-theories`' join between two theories.
    Joined,
}

impl OwnTheory {
    /// Its name in the output.
    pub fn name(self) -> &'static str {
        match self {
            OwnTheory::Theory(t) => t.name(),
            OwnTheory::Joined => "faired",
        }
    }
}

impl Serialize for OwnTheory {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.name())
    }
}

impl DampingDerivatives {
    /// Split a damping-in-pitch pair (z_θ̇, m_θ̇) — all Garrick's and Garner's
    /// theory gives — with the acceleration derivatives of slender-wing
    /// theory (37), z_ẇ = −πA/4, m_ẇ = z_ẇ(5/8 − h); for a true delta this
    /// is (37) exactly.
    fn split(z_thetadot: f64, m_thetadot: f64, a: f64, h: f64) -> Self {
        let z_wdot = -PI * a / 4.0;
        let m_wdot = z_wdot * (5.0 / 8.0 - h);
        DampingDerivatives {
            z_q: z_thetadot - z_wdot,
            z_wdot,
            m_q: m_thetadot - m_wdot,
            m_wdot,
        }
    }
}

/// The change with ω̄ of a frequency-dependent theory's in-phase incidence
/// derivatives: Δz_w = z_w(ω̄) − z_w(0) and Δm_w = m_w(ω̄) − m_w(0) about
/// the same c.g. (the drag's share does not change). The k-method leaves
/// it out (its z_w and m_w are steady); the p-method's incidence response
/// at a complex frequency takes it in
/// ([`crate::dynamics::p_method`]).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct InPhase {
    pub dz_w: f64,
    pub dm_w: f64,
}

/// Why a theory cannot be applied.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DampingError {
    #[error("{theory}: {invalid}")]
    Invalid {
        theory: Theory,
        invalid: Invalid<&'static str>,
    },
    #[error("the leading-edge sweep must lie strictly between 0° and 90°, not {}°", Num(*degrees))]
    Sweep { degrees: f64 },
    #[error("supersonic theory (36) needs M > 1, not M = {}", Num(*mach))]
    SubsonicMach { mach: f64 },
    #[error("supersonic theory: {0}")]
    Supersonic(#[from] SupersonicError),
    #[error(
        "supersonic theory is a function of the planform: it needs the planform's own aspect ratio {}, not {}",
        Num(*planform), Num(*given)
    )]
    AspectRatio { given: f64, planform: f64 },
    #[error(
        "garner-taper (34)–(35) is Garner's result for taper 1/7 only; this wing has taper {}",
        Num(*taper)
    )]
    Taper { taper: f64 },
    #[error(
        "{theory} {} needs a frequency parameter ω̄ > 0, not {}",
        theory.cited(),
        OptNum(*omega_bar)
    )]
    Frequency {
        theory: Theory,
        omega_bar: Option<f64>,
    },
    #[error("lifting-surface theory: {0}")]
    LiftingSurface(#[from] LiftingSurfaceError),
}

/// The derivatives of one theory, and what is worth a warning.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Damping {
    pub theory: Theory,
    pub derivatives: DampingDerivatives,
    /// The in-phase incidence derivatives' change from steady at this ω̄
    /// (zero for a theory whose in-phase part does not depend on ω̄).
    pub in_phase: InPhase,
    /// The functions of Fig 18, for the supersonic theory.
    pub fig18: Option<Fig18>,
    /// Validity limits approached (not errors).
    pub warnings: Warnings,
}

/// The damping derivatives of `theory` for the wing at c.g. `h` and Mach
/// number `mach`; `omega_bar` is the frequency parameter ω̄ = ωc̄/V, used by
/// the theories that take one ([`Theory::takes_omega_bar`]: for
/// `lifting-surface` `None` is the quasi-steady limit) and, for the
/// low-frequency rule's warning (`low_frequency`), by `supersonic`. The
/// lifting surface's harmonic solutions are solved at ω̄
/// ([`Harmonic::Direct`]).
pub fn damping_derivatives(
    theory: Theory,
    wing: &WingInput,
    h: f64,
    mach: f64,
    omega_bar: Option<f64>,
) -> Result<Damping, DampingError> {
    damping_derivatives_with(theory, wing, h, mach, omega_bar, Harmonic::Direct)
}

/// As [`damping_derivatives`], the lifting surface's harmonic solutions had
/// as `harmonic` says (interpolated between frequencies, for a sweep).
pub fn damping_derivatives_with(
    theory: Theory,
    wing: &WingInput,
    h: f64,
    mach: f64,
    omega_bar: Option<f64>,
    harmonic: Harmonic,
) -> Result<Damping, DampingError> {
    for (quantity, value) in [("the c.g. position h", h), ("the Mach number", mach)] {
        invalid::finite(quantity, value)
            .map_err(|invalid| DampingError::Invalid { theory, invalid })?;
    }
    if !(wing.sweep_le > 0.0 && wing.sweep_le < PI / 2.0) {
        return Err(DampingError::Sweep {
            degrees: wing.sweep_le.to_degrees(),
        });
    }
    let mut out = Damping {
        theory,
        derivatives: DampingDerivatives::default(),
        in_phase: InPhase::default(),
        fig18: None,
        warnings: Warnings::default(),
    };
    out.derivatives = match theory {
        Theory::Slender | Theory::Transonic => slender(wing, h, mach, &mut out),
        Theory::Garrick => garrick(wing, h, mach, &mut out),
        Theory::GarnerTaper => garner_taper(wing, h, mach, &mut out)?,
        Theory::Supersonic => supersonic(wing, h, mach, omega_bar, &mut out)?,
        Theory::TransonicFrequency => transonic_frequency(wing, h, mach, omega_bar, &mut out)?,
        Theory::LiftingSurface | Theory::LiftingSurfaceFrequency => {
            lifting_surface(wing, h, mach, omega_bar, harmonic, &mut out)?
        }
    };
    // garner-taper is for taper 1/7; supersonic and the lifting surface
    // are theories of the cropped wing itself
    let own_rule = matches!(theory, Theory::GarnerTaper | Theory::Supersonic);
    if wing.taper > 0.0 && !own_rule && !theory.is_lifting_surface() {
        out.warnings.push(Warning::TrueDeltaOnly {
            theory,
            taper: wing.taper,
        });
    }
    Ok(out)
}

/// (37), and (38) for z_q and m_q (its acceleration derivatives are the
/// frequency-dependent ones of (39): in the steady limit, (37)'s).
fn slender(wing: &WingInput, h: f64, mach: f64, out: &mut Damping) -> DampingDerivatives {
    let a = wing.aspect_ratio;
    if out.theory == Theory::Transonic && (mach - 1.0).abs() > TRANSONIC_RANGE {
        out.warnings.push(Warning::AwayFromSonic {
            theory: out.theory,
            mach,
        });
    }
    let beta_a = a * (1.0 - mach * mach).abs().sqrt();
    if out.theory == Theory::Slender && beta_a > 1.0 {
        out.warnings.push(Warning::NotSlender { beta_a });
    }
    let z_wdot = -PI * a / 4.0;
    DampingDerivatives {
        z_q: -PI * a / 2.0 * (1.0 - h),
        z_wdot,
        m_q: -PI * a / 4.0 * (2.0 * h * h - 3.0 * h + 11.0 / 8.0),
        m_wdot: z_wdot * (5.0 / 8.0 - h),
    }
}

/// (32) z_θ̇ = −(πA/4)(3 − 2h), (33) m_θ̇ = −(πA/2)(h − 1)².
fn garrick(wing: &WingInput, h: f64, mach: f64, out: &mut Damping) -> DampingDerivatives {
    let a = wing.aspect_ratio;
    incompressible(mach, out);
    DampingDerivatives::split(
        -PI * a / 4.0 * (3.0 - 2.0 * h),
        -PI * a / 2.0 * (h - 1.0).powi(2),
        a,
        h,
    )
}

/// Garner, λ = 1/7: −½∂C_L/∂(φ̇c̄ₛ/V) = −πA(5/8 − x₀/(4c̄ₛ)),
/// −½∂C_m/∂(φ̇c̄ₛ/V) = −πA[49/64 − (7/8)x₀/c̄ₛ + ¼(x₀/c̄ₛ)²], with
/// x₀/c̄ₛ = (57/48)h + 9/16 and the report's factors 3/2 and 9/8:
/// z_θ̇ = −πA(0.7265625 − 0.4453125h), m_θ̇ = −(9/8)(0.3525390625)πA(h − 1)²
/// — the report's (34)–(35) print them rounded, 0.728 − 0.446h and 0.4.
fn garner_taper(
    wing: &WingInput,
    h: f64,
    mach: f64,
    out: &mut Damping,
) -> Result<DampingDerivatives, DampingError> {
    if (wing.taper - 1.0 / 7.0).abs() > 1e-3 {
        return Err(DampingError::Taper { taper: wing.taper });
    }
    let a = wing.aspect_ratio;
    incompressible(mach, out);
    let z = -PI * a * (0.726_562_5 - 0.445_312_5 * h);
    let m = -9.0 / 8.0 * 0.352_539_062_5 * PI * a * (h - 1.0).powi(2);
    Ok(DampingDerivatives::split(z, m, a, h))
}

/// The incompressible theories (32)–(35) warn above M = 0.7.
fn incompressible(mach: f64, out: &mut Damping) {
    if mach > 0.7 {
        out.warnings.push(Warning::Incompressible {
            theory: out.theory,
            mach,
        });
    }
}

/// The whole supersonic linear theory ([`supersonic::edge_theory`]): eq
/// (36) with subsonic leading edges (β cot Λ < 1), E and H from Fig 18,
/// its potentials corrected behind the tips for a cropped wing
/// ([`supersonic::subsonic_edge`]); the supersonic-edge theory beyond;
/// continuous at β cot Λ = 1 for every taper (within
/// [`supersonic::SONIC_EDGE_TOLERANCE`], so the 60° delta at M = 2 is
/// accepted). Warning: the low-frequency rule at ω̄ ([`low_frequency`]).
fn supersonic(
    wing: &WingInput,
    h: f64,
    mach: f64,
    omega_bar: Option<f64>,
    out: &mut Damping,
) -> Result<DampingDerivatives, DampingError> {
    if mach <= 1.0 {
        return Err(DampingError::SubsonicMach { mach });
    }
    let w = supersonic_wing(wing)?;
    let r = supersonic::edge_theory(&w, mach, h)?;
    if r.regime != EdgeRegime::SupersonicEdge {
        out.fig18 = Some(Fig18::at(r.beta_cot.min(1.0)));
    }
    low_frequency(&w, mach, omega_bar, out);
    Ok(r.derivatives.damping)
}

/// The planform of `wing` for the supersonic theory, which is a function of
/// its sweep and taper: its aspect ratio must be theirs (to 1e-9).
fn supersonic_wing(wing: &WingInput) -> Result<Wing, DampingError> {
    let w = Wing::new(wing.sweep_le, wing.taper)?;
    let planform = w.aspect_ratio();
    let given = wing.aspect_ratio;
    // false for a NaN too
    let same = (given - planform).abs() <= 1e-9 * planform;
    if !same {
        return Err(DampingError::AspectRatio { given, planform });
    }
    Ok(w)
}

/// The transonic side of linear supersonic theory, as a stated rule
/// (`supersonic::transonic`, docs/damping-theories.md): the theory is first
/// order in frequency and holds where κ = ω̄(c₀/c̄)M²/(M² − 1) ≤ 0.5
/// ([`supersonic::transonic::eq36_validity`]). At the case's ω̄ (the short
/// period's) a failure is a warning naming the criterion, ω̄/(M² − 1) and
/// the Mach number above which it holds ([`Warning::LowFrequency`]); with
/// no ω̄ (or one that is not positive) the warning gives the largest ω̄ at
/// which it holds at this M ([`Warning::FrequencyUnchecked`]). Not an
/// error: the user asked for this theory.
fn low_frequency(w: &Wing, mach: f64, omega_bar: Option<f64>, out: &mut Damping) {
    let checked = omega_bar.and_then(|om| transonic::eq36_validity(w, mach, om).ok());
    match (omega_bar, checked) {
        (Some(omega_bar), Some(v)) => {
            if !v.valid {
                out.warnings.push(Warning::LowFrequency {
                    mach,
                    omega_bar,
                    nu: v.nu,
                    kappa: v.kappa,
                    limit: v.limit,
                    validity_mach: transonic::validity_mach(w, omega_bar).ok(),
                });
            }
        }
        _ => out.warnings.push(Warning::FrequencyUnchecked {
            mach,
            omega_max: transonic::largest_omega_bar(w, mach),
            limit: transonic::LOW_FREQUENCY_LIMIT,
        }),
    }
}

/// The lift slope and aerodynamic centre `theory` gives itself at `mach`,
/// with their exact Mach derivatives — what `aero::Source::Default` takes
/// in place of the default methods: for `supersonic` at M > 1, (36)'s
/// πA/(2E) and H₀ = ½ with subsonic leading edges, the supersonic-edge
/// theory's beyond ([`supersonic::edge_coefficients`]). `None` for the
/// other theories (no lift slope is part of them here) and where the
/// theory does not apply (M ≤ 1: its damping derivatives say why).
pub fn theory_coefficients(
    theory: Theory,
    planform: &Planform,
    mach: f64,
) -> Result<Option<TheoryCoefficients>, DampingError> {
    if theory != Theory::Supersonic || !(mach > 1.0 && mach.is_finite()) {
        return Ok(None);
    }
    let c = supersonic::edge_coefficients(&Wing::from(planform), mach)?;
    Ok(Some(TheoryCoefficients {
        model: OwnTheory::Theory(theory),
        lift_slope: c.lift_slope,
        aerodynamic_centre: c.aerodynamic_centre,
    }))
}

/// (39)–(40): (37) with Mangler's frequency functions in the acceleration
/// derivatives.
fn transonic_frequency(
    wing: &WingInput,
    h: f64,
    mach: f64,
    omega_bar: Option<f64>,
    out: &mut Damping,
) -> Result<DampingDerivatives, DampingError> {
    let w = match omega_bar {
        Some(w) if w.is_finite() && w > 0.0 => w,
        omega_bar => {
            return Err(DampingError::Frequency {
                theory: out.theory,
                omega_bar,
            });
        }
    };
    if (mach - 1.0).abs() > TRANSONIC_RANGE {
        out.warnings.push(Warning::AwayFromSonic {
            theory: out.theory,
            mach,
        });
    }
    let a = wing.aspect_ratio;
    let cot = 1.0 / wing.sweep_le.tan();
    let (k, _) = mangler_k(w, wing.sweep_le);
    let z_wdot = -PI * a / 4.0 * k;
    let extra = 9.0 / 64.0 * PI * cot.powi(3);
    Ok(DampingDerivatives {
        z_q: -PI * a / 2.0 * (1.0 - h),
        z_wdot,
        m_q: -PI * a / 4.0 * (2.0 * h * h - 3.0 * h + 11.0 / 8.0),
        m_wdot: z_wdot * (5.0 / 8.0 - h) - extra,
    })
}

/// The lifting surface of the wing's shape at any M in [0, 3]
/// ([`mach_range::solution`]: the doublet lattice below M = 1, its sonic
/// extrapolation at M = 1, the Mach box above), one cached solve per
/// (wing, M, ω̄): at ω̄ for
/// `lifting-surface-frequency`, which needs it; at the ω̄ given, or
/// quasi-steady (ω̄ = 0) when none is, for `lifting-surface`. The damping
/// four about `h` by axis transfer ([`crate::aerodynamics::lifting_surface::Solution::derivatives`]).
fn lifting_surface(
    wing: &WingInput,
    h: f64,
    mach: f64,
    omega_bar: Option<f64>,
    harmonic: Harmonic,
    out: &mut Damping,
) -> Result<DampingDerivatives, DampingError> {
    let w = match (out.theory, omega_bar) {
        (Theory::LiftingSurfaceFrequency, Some(w)) if w.is_finite() && w > 0.0 => w,
        (Theory::LiftingSurfaceFrequency, omega_bar) => {
            return Err(DampingError::Frequency {
                theory: out.theory,
                omega_bar,
            });
        }
        (_, w) => w.unwrap_or(0.0),
    };
    let shape = store::unit_wing(wing.aspect_ratio, wing.taper, wing.sweep_le)?;
    let at = mach_range::solution(&shape, mach, w, harmonic)?;
    let solution = at.solution;
    if mach > LATTICE_MACH && mach <= 1.0 {
        out.warnings.push(Warning::LatticeNearSonic { mach });
    }
    if let Some(warning) = at.warning {
        out.warnings.push(warning);
    }
    if w > LATTICE_OMEGA_BAR {
        out.warnings
            .push(Warning::LatticeHighFrequency { omega_bar: w });
    }
    let at_w = solution.derivatives(h, 0.0)?;
    // (the sonic solution has no steady limit — it is verified only from
    // ω̄ = 0.3 — so within the sonic band the in-phase change is not known
    // and is taken as zero)
    match mach_range::solution(&shape, mach, 0.0, harmonic) {
        Ok(steady) if w > 0.0 => {
            let steady = steady.solution.derivatives(h, 0.0)?;
            out.in_phase = InPhase {
                dz_w: at_w.z_w - steady.z_w,
                dm_w: at_w.m_w - steady.m_w,
            };
        }
        Err(LiftingSurfaceError::SonicFrequency { .. }) | Ok(_) => {}
        Err(e) => return Err(e.into()),
    }
    Ok(at_w.damping())
}

/// Above this Mach number the default lattice's chordwise boxes are long
/// against the Prandtl–Glauert stretched chord (warned).
pub const LATTICE_MACH: f64 = 0.9;

/// Above this ω̄ the default lattice's boxes are long against the
/// wavelength (warned; `docs/damping-theories.md`, limits).
pub const LATTICE_OMEGA_BAR: f64 = 2.0;

/// The transonic theories (38)–(40) warn further than this from M = 1.
pub const TRANSONIC_RANGE: f64 = 0.2;

/// Mangler's frequency functions, eq (40):
/// k(ω̄) = 1 − ½cot²Λ[4.959 − 3 ln(ω̄ cot²Λ)],
/// k′(ω̄) = ½π cot³Λ [4.959 − 3 ln(ω̄ cot²Λ)];
/// k = 1, k′ = 0 where 3 ln(ω̄ cot²Λ) = 4.959.
pub fn mangler_k(omega_bar: f64, sweep_le: f64) -> (f64, f64) {
    let cot = 1.0 / sweep_le.tan();
    let x = 4.959 - 3.0 * (omega_bar * cot * cot).ln();
    (1.0 - 0.5 * cot * cot * x, 0.5 * PI * cot.powi(3) * x)
}

/// Eq (30): x_q ≈ (H₀ − h)x_w.
pub fn x_q(h0: f64, h: f64, x_w: f64) -> f64 {
    (h0 - h) * x_w
}

/// Eq (31): x_ẇ ≈ (∂C_D/∂α)(H₀ − h).
pub fn x_wdot(h0: f64, h: f64, dcd_dalpha: f64) -> f64 {
    dcd_dalpha * (h0 - h)
}

/// Eq (43), Munk's slender-body estimate of a fuselage's damping in pitch:
/// Δm_θ̇ ≈ −2B_v(l − x)²/(Sc̄²) with B_v = πd²/4, i.e.
/// −½πd²(l − x)²/(Sc̄²): d the body's base diameter, l its length forward
/// of the wing apex, x the distance from the c.g. to the nose, in any one
/// unit of length.
pub fn fuselage_increment(d: f64, l: f64, x: f64, s: f64, chord: f64) -> f64 {
    -0.5 * PI * d * d * (l - x).powi(2) / (s * chord * chord)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for t in Theory::ALL {
            assert_eq!(t.name().parse::<Theory>(), Ok(t));
        }
        assert!(
            "mangler"
                .parse::<Theory>()
                .unwrap_err()
                .to_string()
                .contains("`transonic-frequency`")
        );
    }

    #[test]
    fn eq43_worked_example() {
        // S = 1000 ft², c̄ = 30 ft, l = 20 ft, x = 35 ft, d = 10 ft:
        // −(π/2)·100·225/(1000·900) = −0.03927 (the report prints −0.05).
        let dm = fuselage_increment(10.0, 20.0, 35.0, 1000.0, 30.0);
        assert!((dm + PI * 22500.0 / 1.8e6).abs() < 1e-15);
        assert!((dm + 0.039_27).abs() < 1e-5);
    }
}
