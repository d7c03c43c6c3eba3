//! What a configuration adds to its wing: the increment
//! ΔSolution = (configuration total − wing alone) by one method at one
//! (M, ω̄), which the design-point pipeline adds to the wing's own model
//! (`crate::design::case`, `super::aero`) so that every wing theory keeps
//! its wing and gains the surfaces and the body.
//!
//! The methods ([`Method`]): the multi-surface lattice below M = 1
//! (`Configuration::solve_subsonic`), and above it each surface by the Mach
//! box or by linear supersonic theory with the wing's downwash at the
//! tailplane (`Configuration::solve_supersonic_by`). Which method at which
//! Mach number, and the joins between, is the damping model's
//! ([`super::damping_model::DampingModel::increment`]: `faired`'s through
//! M = 1, [`super::faired::increment`]; the note's bands,
//! [`super::faired::theories::increment`]). The Mach derivatives of the
//! increment's lift slope and moment (for eqs 25–29) are central
//! differences over [`MACH_STEP`] within one method.

use crate::aerodynamics::lifting_surface::configuration::ConfigurationError;
use crate::aerodynamics::lifting_surface::{ConfigurationSolution, Contribution};
use crate::aerodynamics::lifting_surface::{Harmonic, Solution, mach_table, store};
use crate::geometry::Trapezoid;
use crate::geometry::configuration::{Configuration, Part};
use serde::Serialize;

/// The step of the increment's Mach derivatives outside the band.
pub const MACH_STEP: f64 = 1e-3;

/// A configuration's increment over its wing at one (M, ω̄).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Increment {
    /// Total less the wing alone.
    pub solution: Solution,
    /// Each added part's share (the wing's own share of the total, less the
    /// wing alone, as `Part::Wing` when the method gives one: the
    /// surfaces' interference on the wing). They sum to `solution`.
    pub parts: Vec<Contribution>,
    /// d ℓ_α/dM and d μ_α/dM of `solution` (`None` from
    /// [`DampingModel::increment`](crate::aerodynamics::models::damping_model::DampingModel::increment), which does not compute them).
    pub d_lift_alpha: Option<f64>,
    pub d_moment_alpha: Option<f64>,
}

pub(super) fn from_numbers(n: [f64; 6], mach: f64, omega_bar: f64) -> Solution {
    Solution {
        mach,
        omega_bar,
        lift_alpha: n[0],
        moment_alpha: n[1],
        lift_alphadot: n[2],
        moment_alphadot: n[3],
        lift_q: n[4],
        moment_q: n[5],
    }
}

/// a − b, number by number.
fn minus(a: &Solution, b: &Solution) -> Solution {
    let (x, y) = (a.numbers(), b.numbers());
    from_numbers(std::array::from_fn(|i| x[i] - y[i]), a.mach, a.omega_bar)
}

/// The increment's parts: every part but the wing as it is, the wing's
/// share less the wing alone where it differs (interference).
fn parts_less_wing(config: &ConfigurationSolution, alone: &Solution) -> Vec<Contribution> {
    let mut out = Vec::new();
    for c in &config.parts {
        if c.part == Part::Wing {
            let d = minus(&c.solution, alone);
            if d.numbers().iter().any(|v| *v != 0.0) {
                out.push(Contribution {
                    part: Part::Wing,
                    solution: d,
                });
            }
        } else {
            out.push(*c);
        }
    }
    out
}

impl Configuration {
    /// Whether anything is added to the wing.
    pub fn has_additions(&self) -> bool {
        self.tailplane.is_some() || self.foreplane.is_some() || self.body.is_some()
    }
}

/// A method of a configuration's aerodynamics at one Mach number.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// The multi-surface doublet lattice (M < 1).
    Lattice,
    /// Each surface by the Mach box, with the wing's downwash at the
    /// tailplane (M ≥ the surfaces' first Mach box Mach numbers).
    MachBox,
    /// Each surface by linear supersonic theory, with the wing's downwash
    /// at the tailplane (M > 1).
    Supersonic,
}

/// The increment of `config` and its parts at (`mach`, `omega_bar`) by one
/// `method`: the configuration less its wing alone by the same method.
pub fn by_method(
    config: &Configuration,
    mach: f64,
    omega_bar: f64,
    method: Method,
    harmonic: Harmonic,
) -> Result<(Solution, Vec<Contribution>), ConfigurationError> {
    let alone = Configuration::wing_alone(config.wing);
    let solve = |c: &Configuration| match method {
        Method::Lattice => c.solve_subsonic_with(mach, omega_bar, harmonic),
        Method::Supersonic => c.solve_supersonic(mach, omega_bar),
        Method::MachBox => c.solve_supersonic_by(mach, omega_bar, |t, what| {
            mach_box_surface(t, what, &config.wing, mach, omega_bar)
        }),
    };
    let (with, without) = (solve(config)?, solve(&alone)?);
    let parts = parts_less_wing(&with, &without.total);
    Ok((minus(&with.total, &without.total), parts))
}

/// A surface's Mach box solution in its own M.A.C. at its own reduced
/// frequency ω̄c̄_s/c̄ (`omega_bar` is on the wing's M.A.C. `wing`),
/// recorded at the wing's ω̄: the Mach box of its unit wing tabulated in
/// Mach number and frequency ([`mach_table::solution`]: smooth in M, so
/// that the increment's Mach derivatives are, and its nodes shared by every
/// size of the surface). `harmonic` is the wing's: the table interpolates
/// either way.
fn mach_box_surface(
    t: &Trapezoid,
    what: &str,
    wing: &Trapezoid,
    mach: f64,
    omega_bar: f64,
) -> Result<Solution, ConfigurationError> {
    let unit = store::unit_wing(t.aspect_ratio(), t.taper(), t.sweep_le)
        .map_err(|e| ConfigurationError::Geometry(format!("{what}: {e}")))?;
    let own = omega_bar * t.mac() / wing.mac();
    let (s, _) = mach_table::solution(&unit, mach, own)
        .map_err(|e| ConfigurationError::Geometry(format!("{what} at M = {mach}: {e}")))?;
    Ok(Solution { omega_bar, ..s })
}

/// The increment by `method` at `mach`, with the Mach derivatives of its
/// in-phase numbers when asked (central differences over [`MACH_STEP`],
/// one-sided where the step would leave `[lo, ∞)`).
pub fn with_derivatives(
    config: &Configuration,
    mach: f64,
    omega_bar: f64,
    method: Method,
    harmonic: Harmonic,
    mach_derivatives: bool,
    lo: f64,
) -> Result<Increment, ConfigurationError> {
    let (solution, parts) = by_method(config, mach, omega_bar, method, harmonic)?;
    if !mach_derivatives {
        return Ok(Increment {
            solution,
            parts,
            d_lift_alpha: None,
            d_moment_alpha: None,
        });
    }
    let h = MACH_STEP.min(mach - lo).max(0.0);
    let below = by_method(config, mach - h, omega_bar, method, harmonic)?.0;
    let above = by_method(config, mach + MACH_STEP, omega_bar, method, harmonic)?.0;
    let w = h + MACH_STEP;
    Ok(Increment {
        d_lift_alpha: Some((above.lift_alpha - below.lift_alpha) / w),
        d_moment_alpha: Some((above.moment_alpha - below.moment_alpha) / w),
        solution,
        parts,
    })
}

/// The increment `a` + t(`b` − `a`), part by part (a part missing at one end
/// counts zero there), at `mach`: a stated straight join in Mach number;
/// its Mach derivative the line's slope `1/(mach_b − mach_a)` times the
/// difference.
pub fn line(
    a: &Increment,
    b: &Increment,
    t: f64,
    span: f64,
    mach: f64,
    omega_bar: f64,
) -> Increment {
    let of = |inc: &Increment, part: Part| {
        inc.parts
            .iter()
            .find(|c| c.part == part)
            .map_or([0.0; 6], |c| c.solution.numbers())
    };
    let mut order: Vec<Part> = Vec::new();
    for c in a.parts.iter().chain(b.parts.iter()) {
        if !order.contains(&c.part) {
            order.push(c.part);
        }
    }
    let parts: Vec<Contribution> = order
        .into_iter()
        .map(|part| {
            let (x, y) = (of(a, part), of(b, part));
            Contribution {
                part,
                solution: from_numbers(
                    std::array::from_fn(|i| x[i] + t * (y[i] - x[i])),
                    mach,
                    omega_bar,
                ),
            }
        })
        .collect();
    let (x, y) = (a.solution.numbers(), b.solution.numbers());
    Increment {
        solution: from_numbers(
            std::array::from_fn(|i| x[i] + t * (y[i] - x[i])),
            mach,
            omega_bar,
        ),
        parts,
        d_lift_alpha: Some((y[0] - x[0]) / span),
        d_moment_alpha: Some((y[1] - x[1]) / span),
    }
}

impl Configuration {
    /// The configuration's response at M < 1 and ω̄ (0: quasi-steady), from
    /// the store ([`store::configuration`]): one solve of the multi-surface
    /// lattice per (configuration, M, ω̄). The lattice
    /// holds the lifting surfaces; a [`crate::geometry::configuration::Body`] is added as its own
    /// part by slender-body theory, eq (43) (`aerodynamics::body`), as
    /// in the supersonic theory.
    pub fn solve_subsonic(
        &self,
        mach: f64,
        omega_bar: f64,
    ) -> Result<ConfigurationSolution, ConfigurationError> {
        self.solve_subsonic_with(mach, omega_bar, Harmonic::Direct)
    }

    /// As [`Configuration::solve_subsonic`], the harmonic solution had as
    /// `harmonic` says ([`store::configuration`]).
    pub fn solve_subsonic_with(
        &self,
        mach: f64,
        omega_bar: f64,
        harmonic: Harmonic,
    ) -> Result<ConfigurationSolution, ConfigurationError> {
        let mut solution = store::configuration(self, mach, omega_bar, harmonic)?;
        if let Some(body) = &self.body {
            let b = body.solution(&self.wing, mach, omega_bar);
            let t = &mut solution.total;
            t.lift_alpha += b.lift_alpha;
            t.moment_alpha += b.moment_alpha;
            t.lift_alphadot += b.lift_alphadot;
            t.moment_alphadot += b.moment_alphadot;
            t.lift_q += b.lift_q;
            t.moment_q += b.moment_q;
            solution.parts.push(Contribution {
                part: Part::Body,
                solution: b,
            });
        }
        Ok(solution)
    }
}
