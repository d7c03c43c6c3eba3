//! The supersonic aerodynamics of a configuration: each surface by the
//! program's theories, with the wing's downwash at the tailplane and its
//! lag.
//!
//! - **Each surface** — the wing, a tailplane, a foreplane — by linear
//!   supersonic theory ([`supersonic::edge_theory`]: eq (36) while its
//!   leading edge is subsonic, the supersonic-edge theory past it),
//!   evaluated in its own M.A.C. about its own M.A.C.'s leading edge and
//!   moved to the wing's S, c̄ and axis by [`moved`]. The theories cover
//!   deltas and cropped deltas (unswept trailing edge), as a config's
//!   surfaces are.
//! - **The tailplane in the wing's downwash.** Its incidence is
//!   α_T = α + (pitch-rate normalwash) − ε(t − l/V), the downwash ε at the
//!   tail proportional to the wing's lift, ε = κ·C_L,wing with
//!   κ = (dε/dα)/a_w ([`downwash::gradient`], the Trefftz-plane value),
//!   delayed by the time l/V the wake takes from the wing's aerodynamic
//!   centre to the tail's. To first order in the rates
//!   C_L,wing(t − l/V) = a_w α − a_w(l/c̄)(α̇c̄/V) + ℓ_α̇,w(α̇c̄/V) + ℓ_q,w(qc̄/V),
//!   so the tail keeps (1 − dε/dα) of its incidence response, gains
//!   dε/dα·(l/c̄) − κℓ_α̇,w of it as an α̇ response (the lag: the tail's
//!   share of z_ẇ and m_ẇ) and loses κℓ_q,w of it from its pitch-rate
//!   response (the downwash of the wing's own pitch-rate lift, which keeps
//!   the axis transfer of [`Solution::derivatives`] consistent).
//! - **A foreplane's** downwash on the wing (and the tail) is neglected:
//!   stated, not modelled. In supersonic flow a surface has no influence
//!   ahead of its Mach cone, so the wing does not act on a foreplane.
//! - **The body**: eq (43) ([`Body::solution`]).
//!
//! The theories are quasi-steady (first order in frequency): the ω̄ asked
//! for is recorded, the values do not depend on it.

use super::downwash;
use crate::aerodynamics::lifting_surface::Solution;
use crate::aerodynamics::lifting_surface::configuration::ConfigurationError;
use crate::aerodynamics::lifting_surface::{ConfigurationSolution, Contribution};
use crate::aerodynamics::supersonic::{self, Wing};
use crate::geometry::configuration::{Body, Configuration, Part, SurfaceKind};
use crate::geometry::{Planform, Size, Trapezoid};

/// Where a surface's trailing edge may be swept by rounding (|tan Λ_TE|).
const UNSWEPT_TE: f64 = 1e-9;

impl Configuration {
    /// The configuration's response at M > 1 and ω̄ (0: quasi-steady),
    /// each surface by linear supersonic theory ([`own_solution`]).
    pub fn solve_supersonic(
        &self,
        mach: f64,
        omega_bar: f64,
    ) -> Result<ConfigurationSolution, ConfigurationError> {
        self.solve_supersonic_by(mach, omega_bar, |t, what| {
            own_solution(t, what, mach, omega_bar)
        })
    }

    /// As [`Configuration::solve_supersonic`], each surface's response in
    /// its own M.A.C. (about its own M.A.C.'s leading edge) from `by`
    /// (given the surface's planform and name): linear supersonic theory,
    /// or the Mach box.
    pub fn solve_supersonic_by(
        &self,
        mach: f64,
        omega_bar: f64,
        by: impl Fn(&Trapezoid, &str) -> Result<Solution, ConfigurationError>,
    ) -> Result<ConfigurationSolution, ConfigurationError> {
        if !(mach.is_finite() && mach > 1.0) {
            return Err(ConfigurationError::Geometry(format!(
                "the supersonic configuration theory needs a finite M > 1, not {mach}"
            )));
        }
        let wing = by(&self.wing, "the wing")?;
        let mut parts = vec![Contribution {
            part: Part::Wing,
            solution: wing,
        }];
        for surface in self.surfaces() {
            let own = by(&surface.shape, surface.kind.name())?;
            let placement = Placement::of(&surface.shape, surface.x, &self.wing);
            let mut s = moved(&own, &placement);
            let part = match surface.kind {
                SurfaceKind::Tailplane => {
                    let lag = (placement.offset + own.aerodynamic_centre() * placement.chord_ratio
                        - wing.aerodynamic_centre())
                    .max(0.0);
                    let de = downwash::gradient(
                        wing.lift_alpha,
                        self.wing.aspect_ratio(),
                        self.wing.semi_span,
                        surface.z,
                    );
                    s = in_downwash(&s, &wing, de, lag);
                    Part::Tailplane
                }
                SurfaceKind::Foreplane => Part::Foreplane,
            };
            parts.push(Contribution { part, solution: s });
        }
        if let Some(body) = &self.body {
            check_body(body)?;
            parts.push(Contribution {
                part: Part::Body,
                solution: body.solution(&self.wing, mach, omega_bar),
            });
        }
        let total = sum(&parts, mach, omega_bar);
        Ok(ConfigurationSolution { total, parts })
    }
}

/// Where the far-wake downwash given a tailplane at Mach `mach` does not
/// hold: the tail's aerodynamic centre (its own theory's) lies ahead of the
/// point where the Mach lines from the wing's tips meet the centre line,
/// x = (tip trailing edge) + β·s. Returns the warning (distances in wing
/// M.A.C.s behind the wing's apex), or `None`.
pub fn downwash_warning(
    config: &Configuration,
    mach: f64,
) -> Option<crate::aerodynamics::warnings::Warning> {
    let tail = config.tailplane.as_ref()?;
    if mach.is_nan() || mach <= 1.0 {
        return None;
    }
    let w = &config.wing;
    let own = own_solution(&tail.shape, "the tailplane", mach, 0.0).ok()?;
    let at = tail.x + tail.shape.x_mac() + own.aerodynamic_centre() * tail.shape.mac();
    let beta = (mach * mach - 1.0).sqrt();
    let from = w.leading_edge_at(w.semi_span) + w.tip_chord + beta * w.semi_span;
    (at < from).then(
        || crate::aerodynamics::warnings::Warning::DownwashNearWing {
            mach,
            at: at / w.mac(),
            from: from / w.mac(),
        },
    )
}

/// A body's sizes, positive and finite.
fn check_body(body: &Body) -> Result<(), ConfigurationError> {
    for (what, v) in [
        ("length ahead of the apex", body.length_ahead),
        ("diameter", body.diameter),
    ] {
        if !(v.is_finite() && v > 0.0) {
            return Err(ConfigurationError::Geometry(format!(
                "the body's {what} must be a positive length, not {v}"
            )));
        }
    }
    Ok(())
}

/// The parts' sum.
pub(crate) fn sum(parts: &[Contribution], mach: f64, omega_bar: f64) -> Solution {
    let mut t = Solution {
        mach,
        omega_bar,
        lift_alpha: 0.0,
        moment_alpha: 0.0,
        lift_alphadot: 0.0,
        moment_alphadot: 0.0,
        lift_q: 0.0,
        moment_q: 0.0,
    };
    for p in parts {
        let s = &p.solution;
        t.lift_alpha += s.lift_alpha;
        t.moment_alpha += s.moment_alpha;
        t.lift_alphadot += s.lift_alphadot;
        t.moment_alphadot += s.moment_alphadot;
        t.lift_q += s.lift_q;
        t.moment_q += s.moment_q;
    }
    t
}

/// The planform of a trapezoid with an unswept trailing edge (a delta or
/// cropped delta), or why the supersonic theories cannot take it.
pub fn as_planform(t: &Trapezoid, what: &str) -> Result<Planform, ConfigurationError> {
    let te = t.sweep_te().tan();
    if te.abs() > UNSWEPT_TE {
        return Err(ConfigurationError::Geometry(format!(
            "{what}: the supersonic theories cover deltas and cropped deltas (an unswept trailing edge), and its trailing edge is swept {:.3}°; give it as a [planform]-style sweep, taper and size",
            te.atan().to_degrees()
        )));
    }
    Planform::new(t.sweep_le, t.taper(), Size::RootChord(t.root_chord))
        .map_err(|e| ConfigurationError::Geometry(format!("{what}: {e}")))
}

/// A surface's response by linear supersonic theory in its own M.A.C.,
/// moments about its own M.A.C.'s leading edge: from the theory's
/// derivatives about h = 0, ℓ_α = a, μ_α = −H₀a, ℓ_α̇ = −z_ẇ, μ_α̇ = m_ẇ,
/// ℓ_q = −z_q, μ_q = m_q (the inverse of [`Solution::derivatives`] at h = 0).
pub fn own_solution(
    t: &Trapezoid,
    what: &str,
    mach: f64,
    omega_bar: f64,
) -> Result<Solution, ConfigurationError> {
    let p = as_planform(t, what)?;
    let e = supersonic::edge_theory(&Wing::from(&p), mach, 0.0)
        .map_err(|e| ConfigurationError::Geometry(format!("{what} at M = {mach}: {e}")))?;
    let d = e.derivatives;
    Ok(Solution {
        mach,
        omega_bar,
        lift_alpha: d.lift_slope,
        moment_alpha: -d.aerodynamic_centre * d.lift_slope,
        lift_alphadot: -d.damping.z_wdot,
        moment_alphadot: d.damping.m_wdot,
        lift_q: -d.damping.z_q,
        moment_q: d.damping.m_q,
    })
}

/// Where a surface sits against the wing: r = S_T/S, k = c̄_T/c̄ and
/// d = (x̄_T − x̄)/c̄, its M.A.C.'s leading edge aft of the wing's in wing
/// M.A.C.s.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Placement {
    pub area_ratio: f64,
    pub chord_ratio: f64,
    pub offset: f64,
}

impl Placement {
    /// The placement of surface `shape` whose apex is `x` aft of the apex
    /// of `wing`.
    pub fn of(shape: &Trapezoid, x: f64, wing: &Trapezoid) -> Placement {
        Placement {
            area_ratio: shape.area() / wing.area(),
            chord_ratio: shape.mac() / wing.mac(),
            offset: (x + shape.x_mac() - wing.x_mac()) / wing.mac(),
        }
    }
}

/// A surface's own [`Solution`] (its S_T, c̄_T, about its M.A.C.'s leading
/// edge) on the wing's S, c̄ and axis. With r, k, d of [`Placement`]: a
/// moment about the wing's axis is the surface's own plus −d times its
/// lift; a rate per α̇c̄_T/V is k times one per α̇c̄/V; and a unit pitch
/// rate about the wing's axis is k times one about the surface's plus the
/// uniform normalwash d:
/// ℓ_α′ = rℓ_α, μ_α′ = r(kμ_α − dℓ_α), ℓ_α̇′ = rkℓ_α̇,
/// μ_α̇′ = rk(kμ_α̇ − dℓ_α̇), ℓ_q′ = r(kℓ_q + dℓ_α),
/// μ_q′ = r[k(kμ_q − dℓ_q) + d(kμ_α − dℓ_α)].
pub fn moved(s: &Solution, p: &Placement) -> Solution {
    let (r, k, d) = (p.area_ratio, p.chord_ratio, p.offset);
    Solution {
        mach: s.mach,
        omega_bar: s.omega_bar,
        lift_alpha: r * s.lift_alpha,
        moment_alpha: r * (k * s.moment_alpha - d * s.lift_alpha),
        lift_alphadot: r * k * s.lift_alphadot,
        moment_alphadot: r * k * (k * s.moment_alphadot - d * s.lift_alphadot),
        lift_q: r * (k * s.lift_q + d * s.lift_alpha),
        moment_q: r
            * (k * (k * s.moment_q - d * s.lift_q) + d * (k * s.moment_alpha - d * s.lift_alpha)),
    }
}

/// A tailplane's response `tail` (on the wing's S, c̄, axis) in the
/// downwash of `wing`: dε/dα = `de` at the tail, lagged by `lag` (l/c̄,
/// the wing's aerodynamic centre to the tail's). With κ = dε/dα / a_w and
/// the tail's incidence response (ℓ, μ) = (ℓ_α, μ_α):
/// ℓ_α ← (1 − dε/dα)ℓ, ℓ_α̇ ← ℓ_α̇ + (dε/dα·l/c̄ − κℓ_α̇,w)ℓ,
/// ℓ_q ← ℓ_q − κℓ_q,w·ℓ, and μ likewise with μ_α.
pub fn in_downwash(tail: &Solution, wing: &Solution, de: f64, lag: f64) -> Solution {
    let kappa = de / wing.lift_alpha;
    let (l, m) = (tail.lift_alpha, tail.moment_alpha);
    let alphadot = de * lag - kappa * wing.lift_alphadot;
    let q = -kappa * wing.lift_q;
    Solution {
        lift_alpha: (1.0 - de) * l,
        moment_alpha: (1.0 - de) * m,
        lift_alphadot: tail.lift_alphadot + alphadot * l,
        moment_alphadot: tail.moment_alphadot + alphadot * m,
        lift_q: tail.lift_q + q * l,
        moment_q: tail.moment_q + q * m,
        ..*tail
    }
}
