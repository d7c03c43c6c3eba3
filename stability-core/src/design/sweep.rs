//! A Cartesian grid of design points — Mach × sweep × c.g. × μ₁ × i_B
//! (× altitude × mass × I_y at a physical flight condition) about a base
//! [`Case`] — evaluated in parallel (rayon), with the results
//! in columns ([`Points`]), from which `delta-stability sweep`'s CSV or
//! JSON rows and the Python package's arrays are had (their columns are
//! stability-io's table, `stability_io::sweep::columns`).
//!
//! ```
//! use stability_core::design::study::report_wing;
//! use stability_core::design::sweep::{Axes, Sweep};
//! let base = report_wing(60.0, 0.9);
//! let axes = Axes {
//!     mach: vec![0.6, 0.9, 1.5],
//!     mu1: vec![50.0, 450.0],
//!     ..Axes::around(&base)
//! };
//! let points = Sweep::new(base, axes).unwrap().run(false);
//! assert_eq!(points.len(), 6);
//! assert!(points.errors.is_empty() && points.sp_re.iter().all(|re| *re < 0.0));
//! ```
//!
//! # Cost
//! The last axis varies fastest. The aerodynamics (§5–7) are evaluated once
//! per (Mach, sweep, c.g.) and only the quartic per μ₁ and i_B — unless the
//! damping model iterates ω̄, which depends on them
//! ([`DampingModel::depends_on_mass`]). The lifting surface is solved once
//! per (planform, Mach, ω̄), whatever the c.g., μ₁ or i_B
//! ([`crate::aerodynamics::lifting_surface::store`]); [`Sweep::prepare`] solves those in
//! parallel before the points are evaluated. With
//! `lifting-surface-frequency` each point's frequency iteration interpolates
//! in the wing's [`crate::aerodynamics::lifting_surface::FrequencyTable`]
//! ([`Harmonic::Interpolated`]) rather than solving at every iterate;
//! [`Sweep::with_harmonic`] can ask for direct solves instead.
//!
//! # A physical flight condition
//! [`Sweep::with_flight`] fixes an altitude (or ρ and a), a mass and I_y
//! ([`crate::design::flight`]): each planform's μ₁, i_B and C_L·M² then follow from
//! its area and M.A.C. (they change with the sweep angle at a fixed root
//! chord), the μ₁ and i_B axes are not used, and [`Sweep::flight_point`]
//! gives V, C_L and τ at each point's Mach number (C_L·M² is constant at a
//! fixed altitude and weight, eq 24, so C_L ∝ 1/M² and τ ∝ 1/M).
//! [`Sweep::physical`] also takes axes of the condition itself — pressure
//! altitudes, masses and I_y ([`Axes::FLIGHT_NAMES`], the last three
//! dimensions of the grid) — and each point's condition is then resolved
//! with its planform ([`FlightCondition::for_planform`]): μ₁, i_B, C_L·M²
//! and the speed of sound follow from its altitude, mass and I_y.

use crate::Derivatives;
use crate::aerodynamics::lifting_surface::Harmonic;
use crate::analysis::{Analysis, AnalysisError};
use crate::criteria::Verdict;
use crate::design::case::{Case, CaseError, CaseResult, DampingModel, evaluate_point_with};
use crate::design::flight::{
    Air, Altitude, FlightCondition, FlightError, FlightPoint, Mass, PhysicalFlight,
};
use crate::geometry::{GeometryError, Planform, Size};
use num_complex::Complex64;
use rayon::prelude::*;
use std::ops::Range;

/// The grid's axes, in output order; the last varies fastest. Sweeps are
/// leading-edge sweeps in degrees (the base planform's taper and size
/// kept).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Axes {
    pub mach: Vec<f64>,
    pub sweep_deg: Vec<f64>,
    pub cg: Vec<f64>,
    pub mu1: Vec<f64>,
    pub i_b: Vec<f64>,
    /// At a physical flight condition ([`Sweep::physical`]) only: pressure
    /// altitudes (1976 standard atmosphere), masses and pitching moments
    /// of inertia I_y, in the condition's units (m or ft, kg or slug,
    /// kg·m² or slug·ft²); each point's μ₁, i_B and C_L·M² follow from
    /// them. Empty: the condition's own value.
    pub altitude: Vec<f64>,
    pub mass: Vec<f64>,
    pub i_y: Vec<f64>,
}

impl Axes {
    /// Every axis the one value of `base`.
    pub fn around(base: &Case) -> Axes {
        Axes {
            mach: vec![base.mach],
            sweep_deg: vec![base.planform.sweep_le.to_degrees()],
            cg: vec![base.h],
            mu1: vec![base.mu1],
            i_b: vec![base.i_b],
            ..Axes::default()
        }
    }

    /// The physical flight condition's axes' names, as the columns are
    /// named (the config's `[flight]` keys).
    pub const FLIGHT_NAMES: [&'static str; 3] = ["altitude", "mass", "I_y"];

    /// Whether any of the physical flight condition's axes is given.
    pub fn has_flight_axes(&self) -> bool {
        !(self.altitude.is_empty() && self.mass.is_empty() && self.i_y.is_empty())
    }

    /// The axes' names, in order, as the columns are named.
    pub const NAMES: [&'static str; 5] = ["mach", "sweep_deg", "cg", "mu1", "i_b"];

    /// The number of values of each dimension of the grid (the flight
    /// condition's axes count one where they are empty).
    fn lens(&self) -> [usize; DIMS] {
        [
            self.mach.len(),
            self.sweep_deg.len(),
            self.cg.len(),
            self.mu1.len(),
            self.i_b.len(),
            self.altitude.len().max(1),
            self.mass.len().max(1),
            self.i_y.len().max(1),
        ]
    }
}

/// The grid's dimensions: [`Axes::NAMES`], then [`Axes::FLIGHT_NAMES`].
pub const DIMS: usize = 8;

/// Where the flight condition's axes' values are checked: the names of
/// [`Axes::FLIGHT_NAMES`] with the quantity each replaces.
impl Axes {
    fn flight_values(&self) -> [(&'static str, &[f64]); 3] {
        [
            ("altitude", &self.altitude),
            ("mass", &self.mass),
            ("I_y", &self.i_y),
        ]
    }
}

/// Most design points in one sweep.
pub const MAX_POINTS: usize = 200_000_000;

/// Why a grid cannot be swept. (A design point that cannot be evaluated is
/// not an error of the sweep: it is a [`PointError`] in the results.)
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SweepError {
    #[error("the axis `{axis}` has no values")]
    Empty { axis: &'static str },
    #[error("sweep {sweep_deg}°: {error}")]
    Planform {
        sweep_deg: f64,
        error: GeometryError,
    },
    #[error("the grid has {}; the limit is 2e8", count(*points, "points"))]
    TooLarge { points: Option<usize> },
    #[error("the flight condition at a sweep of {sweep_deg}°: {error}")]
    Flight { sweep_deg: f64, error: FlightError },
    #[error(
        "a physical flight condition fixes μ₁ and i_B (from the mass, I_y and the air): the `{axis}` axis must have one value, not {n}"
    )]
    FixedByFlight { axis: &'static str, n: usize },
    #[error(
        "the `{axis}` axis needs a physical flight condition (units, altitude, mass, I_y), from which μ₁, i_B and C_L·M² follow; without one vary μ₁ and i_B"
    )]
    NotPhysical { axis: &'static str },
    #[error(
        "the `altitude` axis varies the pressure altitude of the 1976 standard atmosphere, but the flight condition's air is {air}; give the base condition as a pressure altitude (`altitude`)"
    )]
    NotPressureAltitude { air: &'static str },
    #[error("the `{axis}` axis, {value}: {error}")]
    FlightAxis {
        axis: &'static str,
        value: f64,
        error: FlightError,
    },
}

/// A count of `what` in a message, bounded in length however large: exact
/// below a billion, else to three figures (`2.25e13 points`); `None` (more
/// than a `usize` holds) is "more than 1.8e19".
pub fn count(n: Option<usize>, what: &str) -> String {
    match n {
        Some(n) if n < 1_000_000_000 => format!("{n} {what}"),
        Some(n) => format!(
            "about {} {what}",
            crate::numerics::display::sig(n as f64, 3)
        ),
        None => format!(
            "more than {} {what}",
            crate::numerics::display::sig(usize::MAX as f64, 2)
        ),
    }
}

/// Why one design point has no result.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PointError {
    #[error("{0}")]
    Case(#[from] CaseError),
    #[error("{0}")]
    Analysis(#[from] AnalysisError),
    #[error("the design point's numbers overflow f64")]
    Overflow,
    #[error("the flight condition: {0}")]
    Flight(#[from] FlightError),
}

/// A grid about a base design point, ready to evaluate.
#[derive(Debug, Clone)]
pub struct Sweep {
    axes: Axes,
    base: Case,
    planforms: Vec<Planform>,
    harmonic: Harmonic,
    /// With a physical flight condition, that condition with each planform.
    flights: Option<Vec<PhysicalFlight>>,
    /// The physical flight condition as given (its axes' values replace
    /// its altitude, mass and I_y point by point).
    condition: Option<FlightCondition>,
}

impl Sweep {
    /// The grid of `axes` about `base` (whose other fields every point
    /// keeps). Every axis needs a value; each sweep must make a planform
    /// with the base's taper.
    pub fn new(base: Case, axes: Axes) -> Result<Sweep, SweepError> {
        if let Some((axis, _)) = axes.flight_values().iter().find(|(_, v)| !v.is_empty()) {
            return Err(SweepError::NotPhysical { axis });
        }
        Sweep::build(base, axes)
    }

    /// The grid of `axes` about `base` at the physical flight condition
    /// `flight`, whose altitude, mass and I_y the axes
    /// [`Axes::FLIGHT_NAMES`] may vary: each point's μ₁, i_B and C_L·M²
    /// then follow from its planform, altitude, mass and I_y (§3, eq 24)
    /// through [`FlightCondition::for_planform`] — as `analyze` computes
    /// them for a config at that altitude and mass. The μ₁ and i_B axes
    /// must hold one value each, which are not used.
    pub fn physical(base: Case, axes: Axes, flight: &FlightCondition) -> Result<Sweep, SweepError> {
        if !axes.altitude.is_empty() && !matches!(flight.air, Air::Standard(Altitude::Pressure(_)))
        {
            let air = match flight.air {
                Air::Standard(_) => "given by a geometric altitude",
                Air::Given { .. } => "given as ρ and the speed of sound",
            };
            return Err(SweepError::NotPressureAltitude { air });
        }
        let sweep = Sweep::build(base, axes)?.with_flight(flight)?;
        // every value of the flight axes makes a condition (the altitude
        // within the atmosphere's range, the mass and I_y positive)
        let p = &sweep.planforms[0];
        for (axis, values) in sweep.axes.flight_values() {
            for &value in values {
                let mut c = *flight;
                set_flight_value(&mut c, axis, value);
                c.for_planform(p)
                    .map_err(|error| SweepError::FlightAxis { axis, value, error })?;
            }
        }
        Ok(sweep)
    }

    fn build(base: Case, axes: Axes) -> Result<Sweep, SweepError> {
        for (axis, n) in Axes::NAMES.into_iter().zip(axes.lens()) {
            if n == 0 {
                return Err(SweepError::Empty { axis });
            }
        }
        let mut planforms = Vec::with_capacity(axes.sweep_deg.len());
        let base_deg = crate::numerics::grid::round(base.planform.sweep_le.to_degrees());
        for &s in &axes.sweep_deg {
            // the base's own sweep, exactly as it was given (not through
            // degrees and back: at a sonic leading edge the last bit counts)
            if crate::numerics::grid::round(s) == base_deg {
                planforms.push(base.planform);
                continue;
            }
            let p = Planform::new(s.to_radians(), base.planform.taper, Size::RootChord(1.0))
                .map_err(|error| SweepError::Planform {
                    sweep_deg: s,
                    error,
                })?;
            planforms.push(Planform {
                sweep_le: p.sweep_le,
                ..base.planform
            });
        }
        let points = axes
            .lens()
            .iter()
            .try_fold(1usize, |a, &d| a.checked_mul(d));
        if points.is_none_or(|n| n > MAX_POINTS) {
            return Err(SweepError::TooLarge { points });
        }
        // interpolated where each point iterates its own ω̄; a fixed ω̄ is
        // one direct solve per planform and Mach number, as `analyze`'s
        let harmonic = if base.damping.uses_frequency() && base.iterate_frequency {
            Harmonic::Interpolated
        } else {
            Harmonic::Direct
        };
        Ok(Sweep {
            axes,
            base,
            planforms,
            harmonic,
            flights: None,
            condition: None,
        })
    }

    /// The same grid at the physical flight condition `flight`: each
    /// planform's μ₁, i_B and C_L·M² from it (the μ₁ and i_B axes must then
    /// hold one value each, which are not used).
    pub fn with_flight(self, flight: &FlightCondition) -> Result<Sweep, SweepError> {
        for (axis, n) in [("mu1", self.axes.mu1.len()), ("i_b", self.axes.i_b.len())] {
            if n != 1 {
                return Err(SweepError::FixedByFlight { axis, n });
            }
        }
        let flights = self
            .planforms
            .iter()
            .map(|p| {
                flight.for_planform(p).map_err(|error| SweepError::Flight {
                    sweep_deg: p.sweep_le.to_degrees(),
                    error,
                })
            })
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Sweep {
            flights: Some(flights),
            condition: Some(*flight),
            ..self
        })
    }

    /// The physical flight condition of the point of indices `idx` (with
    /// the planform), when the grid has one.
    fn point_flight(&self, idx: [usize; DIMS]) -> Option<Result<PhysicalFlight, FlightError>> {
        let flights = self.flights.as_ref()?;
        let s = idx[1];
        if !self.axes.has_flight_axes() {
            return Some(Ok(flights[s]));
        }
        let mut c = self.condition?;
        for (k, (axis, values)) in self.axes.flight_values().into_iter().enumerate() {
            if let Some(&v) = values.get(idx[5 + k]) {
                set_flight_value(&mut c, axis, v);
            }
        }
        Some(c.for_planform(&self.planforms[s]))
    }

    /// The physical flight condition as given, when the grid has one.
    pub fn condition(&self) -> Option<&FlightCondition> {
        self.condition.as_ref()
    }

    /// The planforms of the sweep axis, in its order.
    pub fn planforms(&self) -> &[Planform] {
        &self.planforms
    }

    /// The physical flight condition of point `i` (its planform, altitude,
    /// mass and I_y), when the grid has one.
    pub fn flight(&self, i: usize) -> Option<PhysicalFlight> {
        self.point_flight(self.index(i))?.ok()
    }

    /// The physical flight condition of each planform (in the order of the
    /// sweep axis), when the grid has one.
    pub fn flights(&self) -> Option<&[PhysicalFlight]> {
        self.flights.as_deref()
    }

    /// V, C_L and τ of point `i`, when the grid has a physical flight
    /// condition.
    pub fn flight_point(&self, i: usize) -> Option<FlightPoint> {
        let f = self.flight(i)?;
        f.at_mach(self.axes.mach[self.index(i)[0]]).ok()
    }

    /// The same grid with the lifting surface's harmonic solutions had as
    /// `harmonic` says ([`Harmonic::Direct`]: each point's frequency
    /// iteration solves at every iterate, as `analyze` does).
    pub fn with_harmonic(self, harmonic: Harmonic) -> Sweep {
        Sweep { harmonic, ..self }
    }

    pub fn axes(&self) -> &Axes {
        &self.axes
    }

    pub fn base(&self) -> &Case {
        &self.base
    }

    /// The number of design points.
    pub fn len(&self) -> usize {
        self.axes.lens().iter().product()
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The axes' indices of point `i`.
    pub fn index(&self, i: usize) -> [usize; DIMS] {
        let dims = self.axes.lens();
        let mut k = i;
        let mut idx = [0usize; DIMS];
        for d in (0..DIMS).rev() {
            idx[d] = k % dims[d];
            k /= dims[d];
        }
        idx
    }

    /// The axes' indices of points `range`, in order (counted on, not
    /// divided out, point by point).
    pub fn indices(&self, range: Range<usize>) -> Indices {
        Indices {
            dims: self.axes.lens(),
            next: self.index(range.start),
            left: range.len(),
        }
    }

    /// Design point `i`, as [`Sweep::evaluate`] evaluates it.
    pub fn case(&self, i: usize) -> Case {
        let mut case = self.base.clone();
        let _ = self.set_point(self.index(i), &mut case);
        case
    }

    /// Makes `case` the point of indices `idx` (no clone per point), and
    /// returns its physical flight condition when the grid has one.
    fn set_point(
        &self,
        idx: [usize; DIMS],
        case: &mut Case,
    ) -> Result<Option<PhysicalFlight>, FlightError> {
        let [m, s, h, mu, ib, ..] = idx;
        case.planform = self.planforms[s];
        case.mach = self.axes.mach[m];
        case.h = self.axes.cg[h];
        case.mu1 = self.axes.mu1[mu];
        case.i_b = self.axes.i_b[ib];
        let flight = self.point_flight(idx).transpose()?;
        if let Some(f) = &flight {
            f.apply(case);
        }
        Ok(flight)
    }

    /// Whether the model needs the lifting surface's solves.
    fn uses_lattice(&self) -> bool {
        use crate::aerodynamics::models::aero::Source;
        let lattice_aero = [
            &self.base.aero.lift_slope,
            &self.base.aero.aerodynamic_centre,
        ]
        .iter()
        .any(|s| matches!(s, Source::LiftingSurface));
        let lattice_damping =
            matches!(self.base.damping, DampingModel::Theory(t) if t.is_lifting_surface());
        lattice_aero || lattice_damping
    }

    /// Solves the lifting surface once per (planform, Mach) in parallel —
    /// the first point of each, whose solves the others share — when the
    /// model uses it (else nothing). [`Sweep::run`] calls it; a caller of
    /// [`Sweep::evaluate`] may, or the first point to need a solve makes it.
    pub fn prepare(&self) {
        if !self.uses_lattice() {
            return;
        }
        let per_sweep = self.len() / (self.axes.mach.len() * self.axes.sweep_deg.len());
        let firsts: Vec<usize> = (0..self.axes.mach.len() * self.axes.sweep_deg.len())
            .map(|k| k * per_sweep)
            .collect();
        firsts.par_iter().for_each(|&i| {
            let _ = evaluate_point_with(&self.case(i), self.harmonic);
        });
    }

    /// Points `range` (within `0..len()`), in order, on this thread; with
    /// `derivatives`, their fifteen quartic inputs too.
    pub fn evaluate(&self, range: Range<usize>, derivatives: bool) -> Points {
        let mut out = Points::with_capacity(range.start, range.len(), derivatives);
        // the points that differ only in μ₁ and i_B (or I_y: a physical
        // condition holds μ₁ and i_B to one value each, and a grid without
        // one has no flight axes) share their aerodynamics
        let lens = self.axes.lens();
        let per_aero = lens[3] * lens[4] * lens[7];
        // a fixed ω̄ (not iterated, given) makes the derivatives independent
        // of μ₁ and i_B again
        let b = &self.base;
        let fixed = !b.iterate_frequency && b.omega_bar.is_some();
        let reuse = !b.damping.depends_on_mass() || fixed;
        let mut last: Option<(usize, CaseResult)> = None;
        let mut case = self.base.clone();
        for (i, idx) in range.clone().zip(self.indices(range)) {
            let flight = self.set_point(idx, &mut case);
            out.push_head(&case, flight.as_ref().ok().and_then(Option::as_ref));
            if let Err(e) = flight {
                out.push_err(e.into());
                continue;
            }
            let key = i / per_aero;
            match &last {
                Some((k, r)) if reuse && *k == key => {
                    // the point's own values checked as `evaluate_point` would
                    if let Err(e) = case.check() {
                        out.push_err(e.into());
                        continue;
                    }
                    let d = Derivatives {
                        mu1: case.mu1,
                        i_b: case.i_b,
                        ..r.derivatives
                    };
                    match Analysis::without_classical(&d) {
                        Ok(a) => out.push_ok(&d, &a, r.coefficients.lift_slope.value),
                        Err(e) => out.push_err(e.into()),
                    }
                }
                _ => match evaluate_point_with(&case, self.harmonic) {
                    Ok(r) => {
                        let lift_slope = r.coefficients.lift_slope.value;
                        out.push_ok(&r.derivatives, &r.analysis, lift_slope);
                        last = Some((key, r));
                    }
                    Err(e) => out.push_err(e.into()),
                },
            }
        }
        out
    }

    /// Every point, in parallel (after [`Sweep::prepare`]).
    pub fn run(&self, derivatives: bool) -> Points {
        self.prepare();
        const BLOCK: usize = 1 << 10;
        let n = self.len();
        let blocks: Vec<Points> = (0..n)
            .step_by(BLOCK)
            .collect::<Vec<_>>()
            .into_par_iter()
            .map(|b| self.evaluate(b..(b + BLOCK).min(n), derivatives))
            .collect();
        let mut out = Points::with_capacity(0, n, derivatives);
        for b in blocks {
            out.append(b);
        }
        out
    }
}

/// The axes' indices of consecutive points ([`Sweep::indices`]): the last
/// varies fastest.
#[derive(Debug, Clone)]
pub struct Indices {
    dims: [usize; DIMS],
    next: [usize; DIMS],
    left: usize,
}

impl Iterator for Indices {
    type Item = [usize; DIMS];

    fn next(&mut self) -> Option<[usize; DIMS]> {
        if self.left == 0 {
            return None;
        }
        self.left -= 1;
        let out = self.next;
        for d in (0..DIMS).rev() {
            self.next[d] += 1;
            if self.next[d] < self.dims[d] {
                break;
            }
            self.next[d] = 0;
        }
        Some(out)
    }
}

/// The results of consecutive design points, column by column: the grid
/// values, then what each point yields (not-a-number where a point has no
/// such value — no oscillatory short period, an error — and `None` for
/// `stable` and `verdict` where it has an error).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Points {
    /// The index in the grid of the first point.
    pub start: usize,
    pub mach: Vec<f64>,
    pub sweep_deg: Vec<f64>,
    pub cg: Vec<f64>,
    pub mu1: Vec<f64>,
    pub i_b: Vec<f64>,
    /// At a physical flight condition, the point's pressure altitude (NaN
    /// where the air was given as ρ and a), mass and I_y, in the
    /// condition's units; NaN without one.
    pub altitude: Vec<f64>,
    pub mass: Vec<f64>,
    pub i_y: Vec<f64>,
    /// Routh's test (§4).
    pub stable: Vec<Option<bool>>,
    /// The overall verdict, every root judged ([`crate::analysis::verdict`]): never
    /// `Meets` with a mode that grows.
    pub verdict: Vec<Option<Verdict>>,
    /// The short period's root (units of 1/τ), cycles to half amplitude
    /// (eq 8), damping ratio and frequency parameter ω̄ = s/μ₁.
    pub sp_re: Vec<f64>,
    pub sp_im: Vec<f64>,
    pub sp_cycles_to_half: Vec<f64>,
    pub sp_damping_ratio: Vec<f64>,
    pub sp_omega_bar: Vec<f64>,
    /// The phugoid's root, damping ratio and period (τ).
    pub ph_re: Vec<f64>,
    pub ph_im: Vec<f64>,
    pub ph_damping_ratio: Vec<f64>,
    pub ph_period: Vec<f64>,
    /// The four roots (1/τ), conjugates adjacent, fastest first.
    pub roots: Vec<[Complex64; 4]>,
    /// m_θ̇ and its margin Δm_θ̇ over eq (41)'s requirement.
    pub m_thetadot: Vec<f64>,
    pub delta_m_thetadot: Vec<f64>,
    /// K_n of eq (42), the neutral point h_n and the static margin h_n − h
    /// in % M.A.C. ([`crate::criteria::Margins::at_cg`]).
    pub k_n: Vec<f64>,
    pub neutral_point: Vec<f64>,
    pub static_margin_pct: Vec<f64>,
    /// The fifteen quartic inputs, when asked for (NaN where an error).
    pub derivatives: Option<Vec<Derivatives>>,
    /// The points with no result, by their position in these columns
    /// (0-based, increasing).
    pub errors: Vec<(usize, PointError)>,
}

impl Points {
    fn with_capacity(start: usize, n: usize, derivatives: bool) -> Points {
        let v = || Vec::with_capacity(n);
        Points {
            start,
            mach: v(),
            sweep_deg: v(),
            cg: v(),
            mu1: v(),
            i_b: v(),
            altitude: v(),
            mass: v(),
            i_y: v(),
            stable: Vec::with_capacity(n),
            verdict: Vec::with_capacity(n),
            sp_re: v(),
            sp_im: v(),
            sp_cycles_to_half: v(),
            sp_damping_ratio: v(),
            sp_omega_bar: v(),
            ph_re: v(),
            ph_im: v(),
            ph_damping_ratio: v(),
            ph_period: v(),
            roots: Vec::with_capacity(n),
            m_thetadot: v(),
            delta_m_thetadot: v(),
            k_n: v(),
            neutral_point: v(),
            static_margin_pct: v(),
            derivatives: derivatives.then(|| Vec::with_capacity(n)),
            errors: Vec::new(),
        }
    }

    /// The number of points.
    pub fn len(&self) -> usize {
        self.mach.len()
    }

    pub fn is_empty(&self) -> bool {
        self.mach.is_empty()
    }

    fn push_head(&mut self, c: &Case, flight: Option<&PhysicalFlight>) {
        self.mach.push(c.mach);
        self.sweep_deg.push(c.planform.sweep_le.to_degrees());
        self.cg.push(c.h);
        self.mu1.push(c.mu1);
        self.i_b.push(c.i_b);
        let [altitude, mass, i_y] = flight.map_or([f64::NAN; 3], |f| {
            let u = f.units;
            let altitude = f
                .atmosphere
                .map_or(f64::NAN, |a| a.geopotential_altitude / u.length());
            [altitude, f.mass / u.mass(), f.pitch_inertia / u.inertia()]
        });
        self.altitude.push(altitude);
        self.mass.push(mass);
        self.i_y.push(i_y);
    }

    /// A point's error (after its [`Points::push_head`]).
    fn push_err(&mut self, e: PointError) {
        let k = self.len() - 1;
        self.push_nothing();
        self.errors.push((k, e));
    }

    /// A point's results (after its [`Points::push_head`]); a point whose
    /// numbers overflow is an error, not a row of blanks.
    fn push_ok(&mut self, d: &Derivatives, a: &Analysis, lift_slope: f64) {
        if !finite(d, a) {
            return self.push_err(PointError::Overflow);
        }
        let sp = a.modes.short_period();
        let ph = a.modes.phugoid();
        let or_nan = |v: Option<f64>| v.unwrap_or(f64::NAN);
        self.stable.push(Some(a.routh.stable));
        self.verdict
            .push(Some(crate::analysis::verdict::overall(a)));
        self.sp_re.push(or_nan(sp.map(|m| m.re)));
        self.sp_im.push(or_nan(sp.map(|m| m.im)));
        self.sp_cycles_to_half
            .push(or_nan(sp.and_then(|m| m.cycles_to_half)));
        self.sp_damping_ratio
            .push(or_nan(sp.and_then(|m| m.damping_ratio)));
        self.sp_omega_bar
            .push(or_nan(sp.and_then(|m| m.frequency_parameter)));
        self.ph_re.push(or_nan(ph.map(|m| m.re)));
        self.ph_im.push(or_nan(ph.map(|m| m.im)));
        self.ph_damping_ratio
            .push(or_nan(ph.and_then(|m| m.damping_ratio)));
        self.ph_period.push(or_nan(ph.and_then(|m| m.period)));
        self.roots.push(a.roots);
        self.m_thetadot.push(a.damping_standard.m_thetadot);
        self.delta_m_thetadot
            .push(or_nan(a.damping_standard.margin));
        let h = self.cg.last().copied().unwrap_or(f64::NAN);
        let m = crate::criteria::Margins::at_cg(&a.quartic, d, lift_slope, h);
        self.k_n.push(or_nan(m.static_margin));
        self.neutral_point.push(or_nan(m.neutral_point));
        self.static_margin_pct.push(or_nan(m.static_margin_pct));
        if let Some(ds) = &mut self.derivatives {
            ds.push(*d);
        }
    }

    fn push_nothing(&mut self) {
        self.stable.push(None);
        self.verdict.push(None);
        self.roots.push([Complex64::new(f64::NAN, f64::NAN); 4]);
        for c in [
            &mut self.sp_re,
            &mut self.sp_im,
            &mut self.sp_cycles_to_half,
            &mut self.sp_damping_ratio,
            &mut self.sp_omega_bar,
            &mut self.ph_re,
            &mut self.ph_im,
            &mut self.ph_damping_ratio,
            &mut self.ph_period,
            &mut self.m_thetadot,
            &mut self.delta_m_thetadot,
            &mut self.k_n,
            &mut self.neutral_point,
            &mut self.static_margin_pct,
        ] {
            c.push(f64::NAN);
        }
        if let Some(ds) = &mut self.derivatives {
            ds.push(NAN_DERIVATIVES);
        }
    }

    /// `other`'s points after these.
    fn append(&mut self, mut other: Points) {
        let n = self.len();
        self.errors
            .extend(other.errors.drain(..).map(|(k, e)| (k + n, e)));
        macro_rules! columns {
            ($($c:ident),*) => { $( self.$c.append(&mut other.$c); )* };
        }
        columns!(
            mach,
            sweep_deg,
            cg,
            mu1,
            i_b,
            altitude,
            mass,
            i_y,
            stable,
            verdict,
            sp_re,
            sp_im,
            sp_cycles_to_half,
            sp_damping_ratio,
            sp_omega_bar,
            ph_re,
            ph_im,
            ph_damping_ratio,
            ph_period,
            roots,
            m_thetadot,
            delta_m_thetadot,
            k_n,
            neutral_point,
            static_margin_pct
        );
        if let (Some(a), Some(b)) = (&mut self.derivatives, &mut other.derivatives) {
            a.append(b);
        }
    }
}

const NAN_DERIVATIVES: Derivatives = Derivatives {
    x_u: f64::NAN,
    x_w: f64::NAN,
    x_wdot: f64::NAN,
    x_q: f64::NAN,
    z_u: f64::NAN,
    z_w: f64::NAN,
    z_wdot: f64::NAN,
    z_q: f64::NAN,
    m_u: f64::NAN,
    m_w: f64::NAN,
    m_wdot: f64::NAN,
    m_q: f64::NAN,
    c_l: f64::NAN,
    mu1: f64::NAN,
    i_b: f64::NAN,
};

/// Replaces the quantity of a flight condition that the axis `axis` of
/// [`Axes::FLIGHT_NAMES`] varies: the pressure altitude, the mass (in place
/// of a mass or a weight), I_y.
pub fn set_flight_value(c: &mut FlightCondition, axis: &str, value: f64) {
    match axis {
        "altitude" => c.air = Air::Standard(Altitude::Pressure(value)),
        "mass" => c.mass = Mass::Mass(value),
        _ => c.pitch_inertia = value,
    }
}

/// Whether every number a point's row would carry is finite.
fn finite(d: &Derivatives, a: &Analysis) -> bool {
    d.quartic_input_values().iter().all(|v| v.is_finite())
        && a.quartic.to_array().iter().all(|v| v.is_finite())
        && a.roots.iter().all(|z| z.re.is_finite() && z.im.is_finite())
        && a.routh.discriminant.is_finite()
        && a.damping_standard.m_thetadot.is_finite()
}
