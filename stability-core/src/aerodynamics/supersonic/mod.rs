//! Linear supersonic theory of flat triangular and cropped-delta wings:
//! the lift slope a = ∂C_L/∂α, the aerodynamic centre H₀ and the damping
//! derivatives z_q, m_q, z_ẇ, m_ẇ in the report's notation (§3, §7: forces
//! on ½ρV²S, moments on ½ρV²Sc̄, rates per qc̄/V and α̇c̄/V, c̄ the M.A.C., h
//! the c.g. aft of the M.A.C.'s leading edge in M.A.C.), on both sides of
//! the sonic leading edge β cot Λ = 1 (β = √(M² − 1)): the report's eq (36)
//! (Mangler; Ribner & Malvestuto, subsonic leading edges) and the theory
//! that takes over from it where the leading edge turns supersonic.
//!
//! The wing: straight leading edge swept Λ from the apex, unswept (hence
//! supersonic) trailing edge, streamwise tips, taper λ ∈ [0, 1). With the
//! leading and trailing edges supersonic the only subsonic edges are the
//! tips, and the problem is direct: the potential is the source integral
//! over the wing (Puckett 1946), corrected in the tip Mach cones by
//! Evvard's reduced area (NACA TN 1382 / Rep. 951, 1950). With subsonic
//! leading edges the true delta's potentials are Ribner & Malvestuto's
//! (eq 36), and a cropped wing's are theirs corrected behind the tips by
//! the same theorem of Evvard's, taken along the Mach lines. To first order
//! in frequency the oscillatory source kernel (Miles, *The Potential Theory
//! of Unsteady Supersonic Flow*, 1959, ch. 5; Garrick & Rubinow, NACA Rep.
//! 846, 1946) adds the α̇ terms. `docs/damping-theories.md` derives every
//! formula used here.
//!
//! | module | what | route |
//! | --- | --- | --- |
//! | [`eq36`](mod@eq36) | eq (36) for subsonic leading edges and the functions of Fig 18 | closed form (elliptic integrals) |
//! | [`subsonic_edge`] | the cropped delta with subsonic leading edges: the true delta's potentials less the tips' corrections | closed-form potentials, integrated along the Mach lines and over the tip regions |
//! | [`strip`] | Ackeret's two-dimensional values and their strip integrals; the true delta exactly | closed form |
//! | [`evvard`] | the cropped delta with supersonic leading edges: strip values less the tip deficits | closed-form weights, integrated over the tip regions |
//! | [`source`] | the same seven potential integrals from the source integral at each receiver (supersonic leading edges) | independent numerical route (tests) |
//! | [`coefficients`] | the lift slope and aerodynamic centre with their Mach derivatives (eqs 27–29) | closed forms; the cropped delta by a tested numerical derivative |
//! | [`transonic`] | where (36)'s low-frequency theory is valid as M → 1⁺ | stated rule |
//! | [`wave_drag`] | zero-lift wave drag against the edge parameter (the note's Fig 1) | linear theory, numerical |

pub mod coefficients;
pub mod configuration;
pub mod downwash;
pub mod eq36;
pub mod evvard;
pub mod quadrature;
pub mod source;
pub mod strip;
pub mod subsonic_edge;
pub mod transonic;
pub mod wave_drag;

use crate::derivatives::DampingDerivatives;
use crate::geometry::{self, GeometryError, Planform, Size};
use crate::numerics::invalid::Invalid;
pub use coefficients::{EdgeCoefficients, edge_coefficients};
use eq36::{Fig18, eq36};
use serde::Serialize;
use std::f64::consts::PI;

/// |β cot Λ − 1| at or below which the leading edge counts as sonic.
///
/// Both theories are continuous at β cot Λ = 1 for every taper
/// (`tests/it/supersonic.rs`), so the choice decides only which formula is
/// evaluated there; 1e-9 covers the rounding of β cot Λ (the 60° delta at
/// M = 2 computes 1.0000000000000002) with a margin of seven decades, and
/// the subsonic-edge theory differs from its sonic-edge limit by
/// O(1 − β²cot²Λ), i.e. by 2e-9 relatively at the tolerance.
pub const SONIC_EDGE_TOLERANCE: f64 = 1e-9;

/// The planform in the units of this module: a [`Planform`] of unit root
/// chord (every result here is non-dimensional). A thin view: the
/// geometric rules — semi-span, area, aspect ratio, M.A.C. and its leading
/// edge (§2.2) — are `Planform`'s, reached through `Deref`, so that each is
/// defined once, in `geometry`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(transparent)]
pub struct Wing(Planform);

impl std::ops::Deref for Wing {
    type Target = Planform;
    fn deref(&self) -> &Planform {
        &self.0
    }
}

/// Why the supersonic-edge theory cannot be applied.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum SupersonicError {
    #[error(transparent)]
    Invalid(#[from] Invalid<&'static str>),
    #[error("the leading-edge sweep must lie strictly between 0° and 90°, not {0}°")]
    Sweep(f64),
    #[error("the taper ratio must lie in [0, 1), not {0}")]
    Taper(f64),
    #[error("supersonic theory needs M > 1, not M = {0}")]
    SubsonicMach(f64),
    #[error(
        "the supersonic-edge theory needs β cot Λ ≥ 1; at M = {mach} β cot Λ = {beta_cot:.6} (the leading edge turns sonic at M = {sonic:.4}): use eq (36)"
    )]
    SubsonicLeadingEdge {
        mach: f64,
        beta_cot: f64,
        sonic: f64,
    },
    /// `limit` is the least 2βs/c₀ of the theory: 1 with supersonic
    /// leading edges ([`evvard`]), the taper with subsonic ones
    /// ([`subsonic_edge`]).
    #[error(
        "at M = {mach} the Mach waves from one tip reach the other (2β·s/c₀ = {two_beta_s:.4} < {limit}; taper {taper}): Evvard's single reflection does not hold"
    )]
    TipsInteract {
        mach: f64,
        taper: f64,
        two_beta_s: f64,
        limit: f64,
    },
    #[error(
        "the ridge of a double-wedge section must lie strictly inside the chord (0 < f < 1), not {0}"
    )]
    Ridge(f64),
    #[error("the frequency parameter ω̄ must be positive and finite, not {0}")]
    Frequency(f64),
    #[error(
        "ω̄·c₀/c̄ = {scaled:.4} is at or above the low-frequency limit {limit}: (36) is valid at no Mach number for this frequency"
    )]
    FrequencyTooHigh { scaled: f64, limit: f64 },
}

impl Wing {
    /// A wing of leading-edge sweep `sweep_le` (rad, in (0, π/2)) and taper
    /// λ ∈ [0, 1), checked by [`Planform::new`].
    pub fn new(sweep_le: f64, taper: f64) -> Result<Wing, SupersonicError> {
        if !sweep_le.is_finite() {
            return Err(Invalid::NonFinite {
                quantity: "the sweep",
                value: sweep_le,
            }
            .into());
        }
        match Planform::new(sweep_le, taper, Size::RootChord(1.0)) {
            Ok(p) => Ok(Wing(p)),
            Err(GeometryError::Sweep(deg)) => Err(SupersonicError::Sweep(deg)),
            Err(_) => Err(SupersonicError::Taper(taper)),
        }
    }

    /// The planform of unit root chord.
    pub fn planform(&self) -> &Planform {
        &self.0
    }

    /// cot Λ.
    pub fn cot(&self) -> f64 {
        1.0 / self.sweep_le.tan()
    }

    /// The pitch axis x₀/c₀ for the c.g. at h ([`Planform::xo_over_root_chord`]).
    pub fn axis(&self, h: f64) -> f64 {
        self.xo_over_root_chord(h)
    }

    /// The edge parameter β cot Λ at Mach `mach` ([`geometry::beta_cot`]).
    pub fn beta_cot(&self, mach: f64) -> f64 {
        geometry::beta_cot(self.sweep_le, mach)
    }

    /// The Mach number at which the leading edge is sonic, √(1 + tan²Λ)
    /// ([`geometry::sonic_leading_edge_mach`]).
    pub fn sonic_mach(&self) -> f64 {
        geometry::sonic_leading_edge_mach(self.sweep_le)
    }
}

/// The same planform scaled to unit root chord (the derivatives do not
/// depend on the scale).
impl From<&Planform> for Wing {
    fn from(p: &Planform) -> Self {
        Wing(Planform {
            root_chord: 1.0,
            ..*p
        })
    }
}

/// The six outputs of a theory at one Mach number and c.g.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Derivatives {
    /// a = ∂C_L/∂α per radian (z_w = −a).
    pub lift_slope: f64,
    /// H₀, the aerodynamic centre aft of the M.A.C.'s leading edge, in M.A.C.
    pub aerodynamic_centre: f64,
    /// z_q, z_ẇ, m_q, m_ẇ.
    pub damping: DampingDerivatives,
}

/// The seven potential integrals from which every derivative follows
/// (root chord 1, trailing edge at x = 1, Φ the upper-surface potential per
/// unit V of a unit downwash distribution, Φz = w):
///
/// - `te0`, `te1`: ∫ Φ₀ dy along the trailing edge for w = 1 and w = x;
/// - `ar0`, `ar1`: ∫∫ Φ₀ dS for w = 1 and w = x; `arx0`: ∫∫ x Φ₀ dS, w = 1;
/// - `te_f`, `ar_f`: the same for the first-order kernel term Φ₁ (kernel
///   factor (ξ − x), w = 1), ∫ Φ₁ dy along the trailing edge and ∫∫ Φ₁ dS.
///
/// The lift and the moment follow from the pressure ΔC_p = (4/V²)(Φ_t + VΦ_x)
/// integrated by parts, since Φ = 0 on a supersonic leading edge.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PotentialIntegrals {
    pub te0: f64,
    pub te1: f64,
    pub ar0: f64,
    pub ar1: f64,
    pub arx0: f64,
    pub te_f: f64,
    pub ar_f: f64,
}

impl PotentialIntegrals {
    /// The derivatives about the c.g. `h` (docs/damping-theories.md,
    /// "From the potential to the derivatives"):
    /// a = −4 te0/S, x_ac = (te0 − ar0)/te0,
    /// z_q = 4(te1 − x₀te0)/(c̄S),
    /// m_q = 4[(te1 − ar1) − x₀(te0 − ar0) − x₀(te1 − x₀te0)]/(Sc̄²),
    /// z_ẇ = 4[(M²/β²)te_f + ar0]/(c̄S),
    /// m_ẇ = 4[(M²/β²)(te_f − ar_f) + arx0 − x₀((M²/β²)te_f + ar0)]/(Sc̄²).
    pub fn derivatives(&self, wing: &Wing, mach: f64, h: f64) -> Derivatives {
        let s = wing.area();
        let c = wing.mac();
        let x0 = wing.axis(h);
        let r = mach * mach / (mach * mach - 1.0);
        let lift_a = self.te0;
        let x_ac = (self.te0 - self.ar0) / self.te0;
        let lift_q = self.te1 - x0 * self.te0;
        let lift_ad = r * self.te_f + self.ar0;
        let moment_q = (self.te1 - self.ar1) - x0 * (self.te0 - self.ar0) - x0 * lift_q;
        let moment_ad = r * (self.te_f - self.ar_f) + self.arx0 - x0 * lift_ad;
        Derivatives {
            lift_slope: -4.0 * lift_a / s,
            aerodynamic_centre: (x_ac - wing.x_mac()) / c,
            damping: DampingDerivatives {
                z_q: 4.0 * lift_q / (c * s),
                z_wdot: 4.0 * lift_ad / (c * s),
                m_q: 4.0 * moment_q / (s * c * c),
                m_wdot: 4.0 * moment_ad / (s * c * c),
            },
        }
    }
}

fn check_mach(mach: f64) -> Result<f64, SupersonicError> {
    if !mach.is_finite() {
        return Err(Invalid::NonFinite {
            quantity: "the Mach number",
            value: mach,
        }
        .into());
    }
    if mach <= 1.0 {
        return Err(SupersonicError::SubsonicMach(mach));
    }
    Ok((mach * mach - 1.0).sqrt())
}

/// The supersonic-edge theory at `mach`: the true delta in closed form
/// ([`strip::true_delta`]), a cropped delta by [`evvard::integrals`]. Needs
/// β cot Λ ≥ 1 − [`SONIC_EDGE_TOLERANCE`] (within the tolerance, the
/// sonic-edge formula) and, for a cropped wing, 2βs ≥ c₀ (no Mach wave
/// from one tip reaches the other). In the tolerance's band below the
/// edge (β cot Λ < 1) a cropped wing's integrals are
/// [`subsonic_edge::integrals`] — equal to Evvard's at the edge to
/// rounding, and valid there where 2βs = 2β cot Λ·(1 − λ) falls below c₀
/// by rounding (λ = ½).
pub fn supersonic_edge(wing: &Wing, mach: f64, h: f64) -> Result<Derivatives, SupersonicError> {
    let beta = check_mach(mach)?;
    if !h.is_finite() {
        return Err(Invalid::NonFinite {
            quantity: "h",
            value: h,
        }
        .into());
    }
    let m = beta * wing.cot();
    if EdgeRegime::of(m) == EdgeRegime::SubsonicEdge {
        return Err(SupersonicError::SubsonicLeadingEdge {
            mach,
            beta_cot: m,
            sonic: wing.sonic_mach(),
        });
    }
    if wing.taper == 0.0 {
        return Ok(strip::true_delta(mach, h));
    }
    let integrals = if m < 1.0 {
        subsonic_edge::integrals(wing, mach)?
    } else {
        evvard::integrals(wing, mach)?
    };
    Ok(integrals.derivatives(wing, mach, h))
}

/// Which theory [`edge_theory`] used.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum EdgeRegime {
    /// β cot Λ < 1 − tolerance: eq (36) (Mangler; Ribner & Malvestuto).
    SubsonicEdge,
    /// |β cot Λ − 1| ≤ tolerance: the sonic edge, where the two agree.
    SonicEdge,
    /// β cot Λ > 1 + tolerance: this module's theory.
    SupersonicEdge,
}

impl EdgeRegime {
    /// The regime at the edge parameter β cot Λ, by [`SONIC_EDGE_TOLERANCE`].
    pub fn of(beta_cot: f64) -> EdgeRegime {
        if beta_cot < 1.0 - SONIC_EDGE_TOLERANCE {
            EdgeRegime::SubsonicEdge
        } else if beta_cot <= 1.0 + SONIC_EDGE_TOLERANCE {
            EdgeRegime::SonicEdge
        } else {
            EdgeRegime::SupersonicEdge
        }
    }
}

/// The result of [`edge_theory`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct EdgeDerivatives {
    pub regime: EdgeRegime,
    pub beta_cot: f64,
    pub derivatives: Derivatives,
}

/// The single entry point for M > 1, chosen by β cot Λ with
/// [`SONIC_EDGE_TOLERANCE`]: where the leading edge is subsonic, eq (36)
/// with its own lift slope πA/(2E) and aerodynamic centre H₀ = ½ (from
/// m_w = z_w(½ − h)) for the true delta ([`eq36_with_own_aero`]), the same
/// theory's potentials corrected behind the tips for a cropped one
/// ([`subsonic_edge`]); where it is supersonic (or sonic), the
/// supersonic-edge theory ([`supersonic_edge`]). Continuous in M across
/// the sonic edge for every taper (`tests/it/supersonic.rs`).
pub fn edge_theory(wing: &Wing, mach: f64, h: f64) -> Result<EdgeDerivatives, SupersonicError> {
    let beta = check_mach(mach)?;
    if !h.is_finite() {
        return Err(Invalid::NonFinite {
            quantity: "h",
            value: h,
        }
        .into());
    }
    let m = beta * wing.cot();
    let regime = EdgeRegime::of(m);
    let derivatives = match regime {
        EdgeRegime::SubsonicEdge if wing.taper == 0.0 => eq36_with_own_aero(wing, mach, h),
        EdgeRegime::SubsonicEdge => {
            subsonic_edge::integrals(wing, mach)?.derivatives(wing, mach, h)
        }
        _ => supersonic_edge(wing, mach, h)?,
    };
    Ok(EdgeDerivatives {
        regime,
        beta_cot: m,
        derivatives,
    })
}

/// Eq (36) as `damping::eq36` recovers it, with (36)'s own lift slope
/// a = πA/(2E) (z_w = −πA/(2E)) and aerodynamic centre ½ (m_w = z_w(½ − h)):
/// the true delta's theory. On a cropped wing with the cropped aspect
/// ratio it is not the cropped wing's: its a·S = (π/2E)·4s² is the lift of
/// the true delta of the same span, as if the wing aft of the tips' leading
/// corners carried none (a slender-wing result), where linear theory loses
/// lift only behind the tips' Mach lines — at the sonic edge, 45°, λ = 1/7,
/// a = 3.00 against the cropped wing's 3.72 ([`subsonic_edge`], which
/// [`edge_theory`] uses there).
pub fn eq36_with_own_aero(wing: &Wing, mach: f64, h: f64) -> Derivatives {
    let f = Fig18::at(wing.beta_cot(mach));
    let a = wing.aspect_ratio();
    Derivatives {
        lift_slope: PI * a / (2.0 * f.e),
        aerodynamic_centre: 0.5,
        damping: eq36(a, h, mach, f.e, f.h),
    }
}
