//! Sizing a tailplane (or foreplane) to the note's §8 standard
//! (`delta-stability size-tail`).
//!
//! The family: the config's surface with its sweep, taper, aspect ratio
//! and apex fixed and its area S_T varied, every length scaled by
//! √(S_T/S_T,given). The answer: the smallest area at which the design
//! point meets the one-cycle standard — every root judged
//! ([`crate::analysis::verdict::overall`]) — at every Mach number of the range.
//!
//! The search: the wing alone first (area 0: no surface needed); then a
//! scan of areas spaced geometrically, by a factor
//! (1/[`SMALLEST`])^(1/([`SCAN`] − 1)) ≈ 1.33, from [`SMALLEST`] of the
//! smaller of the limit and the wing's area up to the limit (the wing's
//! area, S_T = S, unless asked otherwise: then [`SCAN`] areas) — so the
//! scan starts where tails are, whatever the limit, never at areas where
//! the numbers overflow; then bisection between the last scanned area that
//! fails and the first that meets, to a relative width of [`TOLERANCE`]. The verdict
//! need not be monotone in area (a larger tail moves the neutral point aft
//! and changes the short period's frequency as well as its damping): the
//! scan finds the first meeting area on its grid, and bisection the
//! boundary within that step; a window of meeting areas narrower than one
//! scan step (a factor (1/[`SMALLEST`])^(1/([`SCAN`] − 1)) ≈ 1.33) can be
//! missed. Where no area up to the limit meets, the answer says so.

use crate::aerodynamics::lifting_surface::Harmonic;
use crate::criteria::Verdict;
use crate::design::case::{Case, evaluate_point_with};
use crate::geometry::Trapezoid;

use crate::geometry::configuration::{Configuration, Surface, SurfaceKind};
use rayon::prelude::*;
use serde::Serialize;
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Areas scanned before bisection, up to a limit of the wing's area.
pub const SCAN: usize = 25;
/// The smallest scanned area, as a fraction of the limit or of the wing's
/// area, whichever is smaller.
pub const SMALLEST: f64 = 1e-3;
/// Bisection stops when the bracket's width is below this fraction of
/// its upper end.
pub const TOLERANCE: f64 = 1e-3;

/// One Mach number's outcome at an area.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MachOutcome {
    pub mach: f64,
    /// The overall verdict; `None` where the point has no result.
    pub verdict: Option<Verdict>,
    pub cycles_to_half: Option<f64>,
    /// Why the point has no result.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
}

/// The sizing's answer.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Sizing {
    pub surface: SurfaceKind,
    /// The smallest area meeting the standard at every Mach number (0: the
    /// wing alone meets it); `None`: no area up to `limit` does.
    pub area: Option<f64>,
    /// The config's own area of the surface.
    pub given_area: f64,
    /// The largest area tried.
    pub limit: f64,
    /// V̄ = S_T·l/(S·c̄), l from the c.g. to the surface's M.A.C. quarter
    /// chord (negative ahead), at `area`.
    pub volume: Option<f64>,
    /// The verdict at each Mach number at `area` (at `limit` when none).
    pub outcomes: Vec<MachOutcome>,
}

/// Why a surface cannot be sized.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SizingError {
    #[error(
        "the config has no [{0}] to size: add one (its sweep, taper, a size and x; docs/configurations.md) — its shape and apex are the family, its area is what is found"
    )]
    NoSurface(&'static str),
    #[error("give at least one Mach number")]
    NoMach,
    #[error("the largest area must be a positive number, not {0}")]
    Limit(f64),
}

/// `shape` scaled about its apex by `f` (every length).
fn scaled(shape: &Trapezoid, f: f64) -> Trapezoid {
    Trapezoid {
        root_chord: shape.root_chord * f,
        tip_chord: shape.tip_chord * f,
        semi_span: shape.semi_span * f,
        ..*shape
    }
}

/// The sizing problem: the case, its configuration and the family.
struct Family<'a> {
    case: &'a Case,
    config: Configuration,
    surface: Surface,
    machs: &'a [f64],
    /// The index of the Mach number that failed last ([`Family::meets`]).
    hardest: AtomicUsize,
}

impl Family<'_> {
    /// The configuration with the surface of area `area` (none at 0).
    fn with_area(&self, area: f64) -> Configuration {
        let mut c = self.config.clone();
        let s = (area > 0.0).then(|| Surface {
            shape: scaled(
                &self.surface.shape,
                (area / self.surface.shape.area()).sqrt(),
            ),
            ..self.surface
        });
        match self.surface.kind {
            SurfaceKind::Tailplane => c.tailplane = s,
            SurfaceKind::Foreplane => c.foreplane = s,
        }
        c
    }

    /// The outcome at one Mach number with the configuration `config`,
    /// evaluated as a sweep's point is (the lattice's harmonic solutions
    /// interpolated between frequency nodes, [`Harmonic::Interpolated`]).
    fn outcome(&self, config: &Arc<Configuration>, mach: f64) -> MachOutcome {
        let mut case = self.case.clone();
        case.mach = mach;
        case.aero.configuration = Some(config.clone());
        match evaluate_point_with(&case, Harmonic::Interpolated) {
            Ok(r) => MachOutcome {
                mach,
                verdict: Some(crate::analysis::verdict::overall(&r.analysis)),
                cycles_to_half: r
                    .analysis
                    .modes
                    .short_period()
                    .and_then(|m| m.cycles_to_half),
                error: None,
            },
            Err(e) => MachOutcome {
                mach,
                verdict: None,
                cycles_to_half: None,
                error: Some(e.to_string()),
            },
        }
    }

    /// The outcome at each Mach number with the surface of area `area`
    /// (the Mach numbers in parallel).
    fn outcomes(&self, area: f64) -> Vec<MachOutcome> {
        let config = Arc::new(self.with_area(area));
        self.machs
            .par_iter()
            .map(|&mach| self.outcome(&config, mach))
            .collect()
    }

    /// Whether the standard is met at every Mach number with the surface of
    /// area `area`. The first failure ends the trial, so the order is
    /// chosen to find one cheaply: the Mach number that failed last (an
    /// area that fails mostly fails where the previous one did), then those
    /// where the damping model takes the surfaces by a supersonic method (no
    /// lattice: [`crate::aerodynamics::models::damping_model::DampingModel::supersonic_increment_from`]), then the rest.
    fn meets(&self, area: f64) -> bool {
        let config = Arc::new(self.with_area(area));
        let hardest = self.hardest.load(Ordering::Relaxed);
        let n = self.machs.len();
        let supersonic = self.case.damping.supersonic_increment_from(&config);
        let cheap = |i: &usize| self.machs[*i] >= supersonic;
        let rest = |c: bool| (0..n).filter(move |i| cheap(i) == c && *i != hardest);
        let order = (hardest < n)
            .then_some(hardest)
            .into_iter()
            .chain(rest(true))
            .chain(rest(false));
        for i in order {
            if self.outcome(&config, self.machs[i]).verdict != Some(Verdict::Meets) {
                self.hardest.store(i, Ordering::Relaxed);
                return false;
            }
        }
        true
    }

    /// V̄ at `area`.
    fn volume(&self, area: f64) -> f64 {
        if area == 0.0 {
            // no surface (its scaled shape has no M.A.C.)
            return 0.0;
        }
        let w = &self.config.wing;
        let f = (area / self.surface.shape.area()).sqrt();
        let shape = scaled(&self.surface.shape, f);
        let quarter = self.surface.x + shape.x_mac() + 0.25 * shape.mac();
        let cg = w.x_mac() + self.case.h * w.mac();
        area * (quarter - cg) / (w.area() * w.mac())
    }
}

/// Whether every Mach number has a result that meets the standard.
pub fn meets_all(outcomes: &[MachOutcome]) -> bool {
    outcomes.iter().all(|o| o.verdict == Some(Verdict::Meets))
}

/// The smallest area of the case's `kind` surface (its configuration's,
/// [`crate::aerodynamics::models::aero::AeroModel::configuration`]) meeting the standard at
/// every Mach number of `machs`, up to `limit` (`None`: the wing's area).
pub fn size_surface(
    case: &Case,
    kind: SurfaceKind,
    machs: &[f64],
    limit: Option<f64>,
) -> Result<Sizing, SizingError> {
    let f = family(case, kind, machs)?;
    let limit = limit.unwrap_or(f.config.wing.area());
    if !(limit.is_finite() && limit > 0.0) {
        return Err(SizingError::Limit(limit));
    }
    let surface = f.surface;
    let area = search(&f, limit);
    let at = area.unwrap_or(limit);
    Ok(Sizing {
        surface: kind,
        area,
        given_area: surface.shape.area(),
        limit,
        volume: area.map(|a| f.volume(a)),
        outcomes: f.outcomes(at),
    })
}

/// The family of the case's `kind` surface over `machs`.
fn family<'a>(
    case: &'a Case,
    kind: SurfaceKind,
    machs: &'a [f64],
) -> Result<Family<'a>, SizingError> {
    let config = case.aero.configuration_for(&case.planform);
    let surface = config.as_ref().and_then(|c| match kind {
        SurfaceKind::Tailplane => c.tailplane,
        SurfaceKind::Foreplane => c.foreplane,
    });
    let (Some(config), Some(surface)) = (config, surface) else {
        return Err(SizingError::NoSurface(kind.name()));
    };
    if machs.is_empty() {
        return Err(SizingError::NoMach);
    }
    Ok(Family {
        case,
        config,
        surface,
        machs,
        hardest: AtomicUsize::new(usize::MAX),
    })
}

/// The outcome at each Mach number of `machs` with the case's `kind`
/// surface scaled to `area` (0: none) — the evaluation [`size_surface`]
/// judges each area by, for drawing a family's members.
pub fn outcomes_at(
    case: &Case,
    kind: SurfaceKind,
    machs: &[f64],
    area: f64,
) -> Result<Vec<MachOutcome>, SizingError> {
    Ok(family(case, kind, machs)?.outcomes(area))
}

/// The scan, then bisection ([`size_surface`]).
fn search(f: &Family<'_>, limit: f64) -> Option<f64> {
    if f.meets(0.0) {
        return Some(0.0);
    }
    let ratio = (1.0 / SMALLEST).powf(1.0 / (SCAN - 1) as f64);
    let mut below = 0.0;
    let mut area = limit.min(f.config.wing.area()) * SMALLEST;
    loop {
        if f.meets(area) {
            return Some(bisect(f, below, area));
        }
        if area >= limit {
            return None;
        }
        below = area;
        // the last step lands on the limit itself
        area = if area * ratio * (1.0 + 1e-9) >= limit {
            limit
        } else {
            area * ratio
        };
    }
}

/// The boundary between `lo` (fails) and `hi` (meets).
fn bisect(f: &Family<'_>, mut lo: f64, mut hi: f64) -> f64 {
    while hi - lo > TOLERANCE * hi {
        let mid = 0.5 * (lo + hi);
        if f.meets(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    hi
}
