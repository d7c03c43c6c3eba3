//! The study: its inputs, one sample's evaluation, and the run.

use super::dist::{CorrelationError, Dist, DistError, cholesky, phi};
use super::quasi::Sampling;
use super::sobol::Indices;
use super::stats::{Proportion, Quantiles};
use crate::aerodynamics::lifting_surface::Harmonic;
use crate::analysis::Analysis;
use crate::criteria::{Category, Verdict, phugoid_level, short_period_level};
use crate::design::case::{Case, DampingModel, FrequencyMethod, evaluate_point_with};
use crate::design::flight::{Air, Altitude, FlightCondition, Mass};
use crate::numerics::roots::{Complex64, RootsError, solve_quartic};
use crate::{Derivatives, Quartic};
use serde::Serialize;

/// The twelve aerodynamic derivatives an error can be put on, by their
/// names in [`Derivatives::QUARTIC_INPUTS`].
pub const AERO_DERIVATIVES: [&str; 12] = [
    "x_u", "x_w", "x_wdot", "x_q", "z_u", "z_w", "z_wdot", "z_q", "m_u", "m_w", "m_wdot", "m_q",
];

/// A quantity that can be uncertain.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Quantity {
    Mu1,
    IB,
    ClM2,
    Cg,
    /// The physical flight condition's altitude (in its units), mass (or
    /// weight, as the condition gives it) and I_y.
    Altitude,
    Mass,
    PitchInertia,
    /// One of [`AERO_DERIVATIVES`], by index.
    Derivative(usize),
}

impl Quantity {
    /// Every quantity's name, as configs spell it.
    pub fn names() -> impl Iterator<Item = &'static str> {
        ["mu1", "i_b", "cl_m2", "cg", "altitude", "mass", "I_y"]
            .into_iter()
            .chain(AERO_DERIVATIVES)
    }

    pub fn parse(name: &str) -> Option<Quantity> {
        Some(match name {
            "mu1" => Quantity::Mu1,
            "i_b" => Quantity::IB,
            "cl_m2" => Quantity::ClM2,
            "cg" => Quantity::Cg,
            "altitude" => Quantity::Altitude,
            "mass" => Quantity::Mass,
            "I_y" => Quantity::PitchInertia,
            d => Quantity::Derivative(AERO_DERIVATIVES.iter().position(|n| *n == d)?),
        })
    }

    pub fn name(self) -> &'static str {
        match self {
            Quantity::Mu1 => "mu1",
            Quantity::IB => "i_b",
            Quantity::ClM2 => "cl_m2",
            Quantity::Cg => "cg",
            Quantity::Altitude => "altitude",
            Quantity::Mass => "mass",
            Quantity::PitchInertia => "I_y",
            Quantity::Derivative(i) => AERO_DERIVATIVES[i],
        }
    }

    /// A quantity of the physical flight condition.
    pub fn is_physical(self) -> bool {
        matches!(
            self,
            Quantity::Altitude | Quantity::Mass | Quantity::PitchInertia
        )
    }

    /// Whether a sample with this quantity changed needs the aerodynamics
    /// again (not only the quartic).
    fn changes_aero(self) -> bool {
        matches!(
            self,
            Quantity::ClM2 | Quantity::Cg | Quantity::Altitude | Quantity::Mass
        )
    }
}

/// How a drawn number acts on its quantity.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ErrorKind {
    /// The number is the quantity's value.
    Value,
    /// The quantity is its nominal value times the number.
    Multiplicative,
    /// The quantity is its nominal value plus the number.
    Additive,
}

impl ErrorKind {
    pub fn apply(self, nominal: f64, x: f64) -> f64 {
        match self {
            ErrorKind::Value => x,
            ErrorKind::Multiplicative => nominal * x,
            ErrorKind::Additive => nominal + x,
        }
    }
}

/// One uncertain input.
#[derive(Debug, Clone, PartialEq)]
pub struct Input {
    pub quantity: Quantity,
    pub error: ErrorKind,
    pub dist: Dist,
}

/// Why a study cannot be run.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum StudyError {
    #[error("`{0}` is uncertain twice")]
    Duplicate(&'static str),
    #[error("`{0}`: {1}")]
    Dist(&'static str, DistError),
    #[error(
        "`{0}` is a quantity of the physical flight condition: give one in [flight] (units, altitude, mass, I_y)"
    )]
    NeedsPhysical(&'static str),
    #[error(
        "`{0}` follows from the physical flight condition; make its altitude, mass or I_y uncertain instead"
    )]
    FixedByPhysical(&'static str),
    #[error(
        "the altitude cannot be uncertain where [flight] gives rho and speed_of_sound: give an altitude"
    )]
    NoAltitude,
    #[error("the derivative `{0}` takes a multiplicative or additive error, not a value")]
    DerivativeValue(&'static str),
    #[error("the correlation names `{0}`, which is not uncertain")]
    NotUncertain(String),
    #[error("correlations: {0}")]
    Correlation(#[from] CorrelationError),
    #[error("the damping models' weights must be positive and finite, one per model")]
    Weights,
    #[error("at most {MAX_FACTORS} uncertain inputs and the model")]
    TooMany,
}

/// Most factors (inputs, and the model's choice).
pub const MAX_FACTORS: usize = 24;

/// The rows of one chunk (one generator stream).
pub const CHUNK: usize = 256;

/// The chunks evaluated in parallel before their sums are added in order.
pub const BATCH: usize = 64;

/// A study: a design point (its Mach number set per run), its uncertain
/// inputs and correlations, and the damping theories with their weights.
#[derive(Debug, Clone)]
pub struct Study {
    base: Case,
    flight: Option<FlightCondition>,
    inputs: Vec<Input>,
    /// The lower Cholesky factor of the inputs' normal scores' correlation.
    chol: Option<Vec<f64>>,
    models: Vec<DampingModel>,
    cumulative: Vec<f64>,
}

impl Study {
    /// A study of `base` (with its physical condition `flight`, if any):
    /// `inputs` uncertain, `correlations` (names and ρ between their normal
    /// scores), and the damping `models` with `weights` (empty: the base's
    /// own model alone).
    pub fn new(
        base: Case,
        flight: Option<FlightCondition>,
        inputs: Vec<Input>,
        correlations: &[(String, String, f64)],
        models: &[(DampingModel, f64)],
    ) -> Result<Study, StudyError> {
        check_inputs(&inputs, flight.as_ref())?;
        let index = |name: &str| {
            inputs
                .iter()
                .position(|i| i.quantity.name() == name)
                .ok_or_else(|| StudyError::NotUncertain(name.to_string()))
        };
        let pairs = correlations
            .iter()
            .map(|(a, b, rho)| Ok((index(a)?, index(b)?, *rho)))
            .collect::<Result<Vec<_>, StudyError>>()?;
        let chol = match pairs.is_empty() {
            true => None,
            false => Some(cholesky(inputs.len(), &pairs)?),
        };
        let models = match models {
            [] => vec![(base.damping, 1.0)],
            m => m.to_vec(),
        };
        if models.iter().any(|(_, w)| !(w.is_finite() && *w > 0.0)) {
            return Err(StudyError::Weights);
        }
        let total: f64 = models.iter().map(|m| m.1).sum();
        let cumulative = models
            .iter()
            .scan(0.0, |c, m| {
                *c += m.1 / total;
                Some(*c)
            })
            .collect();
        let study = Study {
            base,
            flight,
            inputs,
            chol,
            models: models.iter().map(|m| m.0).collect(),
            cumulative,
        };
        if study.factors() > MAX_FACTORS {
            return Err(StudyError::TooMany);
        }
        Ok(study)
    }

    /// The factors of the Sobol indices: the inputs' names, then `model`
    /// when there is more than one damping theory.
    pub fn factor_names(&self) -> Vec<&'static str> {
        let mut names: Vec<_> = self.inputs.iter().map(|i| i.quantity.name()).collect();
        if self.models.len() > 1 {
            names.push("model");
        }
        names
    }

    fn factors(&self) -> usize {
        self.inputs.len() + usize::from(self.models.len() > 1)
    }

    pub fn inputs(&self) -> &[Input] {
        &self.inputs
    }

    pub fn models(&self) -> &[DampingModel] {
        &self.models
    }
}

/// Each quantity once, its distribution valid, physical ones with a
/// physical condition (and not mixed with μ₁, i_B, C_L·M²), derivatives
/// with an error.
fn check_inputs(inputs: &[Input], flight: Option<&FlightCondition>) -> Result<(), StudyError> {
    for (k, i) in inputs.iter().enumerate() {
        let name = i.quantity.name();
        if inputs[..k].iter().any(|j| j.quantity == i.quantity) {
            return Err(StudyError::Duplicate(name));
        }
        i.dist.check().map_err(|e| StudyError::Dist(name, e))?;
        match i.quantity {
            q if q.is_physical() && flight.is_none() => {
                return Err(StudyError::NeedsPhysical(name));
            }
            Quantity::Mu1 | Quantity::IB | Quantity::ClM2 if flight.is_some() => {
                return Err(StudyError::FixedByPhysical(name));
            }
            Quantity::Altitude if matches!(flight, Some(f) if matches!(f.air, Air::Given { .. })) =>
            {
                return Err(StudyError::NoAltitude);
            }
            Quantity::Derivative(_) if i.error == ErrorKind::Value => {
                return Err(StudyError::DerivativeValue(name));
            }
            _ => {}
        }
    }
    if inputs.len() > MAX_FACTORS {
        return Err(StudyError::TooMany);
    }
    Ok(())
}

/// What one sample yields.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Outcome {
    /// The §8 standard on the short period ([`crate::criteria::Verdict::of`]).
    pub standard: Verdict,
    /// The overall verdict, every root judged ([`crate::analysis::verdict::overall`]).
    pub overall: Verdict,
    /// The short period's MIL-F-8785C levels in Categories A, B, C and the
    /// phugoid's: 1–3, 4 for worse than Level 3, 0 not assessed.
    pub levels: [u8; 4],
    /// The short period's cycles to half amplitude (eq 8) and ζ; NaN where
    /// it does not oscillate (or grows, for the cycles).
    pub cycles_to_half: f64,
    pub damping_ratio: f64,
    /// Δm_θ̇ = m_θ̇max − m_θ̇ (eq 41); NaN where eq (41) has no limit.
    pub margin: f64,
}

impl Outcome {
    /// The outcome of an analysis; τ in seconds for the phugoid's time to
    /// double when known.
    pub fn of(a: &Analysis, tau: Option<f64>) -> Outcome {
        let sp = a.modes.short_period();
        let ph = a.modes.phugoid();
        let zeta = sp.and_then(|m| m.damping_ratio).unwrap_or(f64::NAN);
        let sp_level = |c| match zeta.is_finite() {
            true => short_period_level(zeta, c).number(),
            false => 0,
        };
        let ph_level = match ph.and_then(|m| m.damping_ratio) {
            Some(z) if z >= 0.0 => phugoid_level(z, None).number(),
            Some(z) => match (tau, ph.and_then(|m| m.time_to_double)) {
                (Some(t), Some(t2)) => phugoid_level(z, Some(t2 * t)).number(),
                _ => 0,
            },
            None => 0,
        };
        Outcome {
            standard: a.verdict,
            overall: crate::analysis::verdict::overall(a),
            levels: [
                sp_level(Category::A),
                sp_level(Category::B),
                sp_level(Category::C),
                ph_level,
            ],
            cycles_to_half: sp.and_then(|m| m.cycles_to_half).unwrap_or(f64::NAN),
            damping_ratio: zeta,
            margin: a.damping_standard.margin.unwrap_or(f64::NAN),
        }
    }
}

/// The study at one Mach number: each model's nominal point, which the
/// samples that need only a new quartic reuse.
pub struct AtMach<'a> {
    study: &'a Study,
    mach: f64,
    /// Per model: its design point at this Mach number, and its nominal
    /// derivatives where a sample needs only the quartic.
    cases: Vec<Case>,
    reuse: Vec<Option<Derivatives>>,
}

impl Study {
    /// The study at Mach number `mach`: each model's nominal point evaluated
    /// once (the lattice's solves cached for the samples).
    pub fn at_mach(&self, mach: f64) -> AtMach<'_> {
        let aero_varies = self.inputs.iter().any(|i| i.quantity.changes_aero());
        let cases: Vec<Case> = self
            .models
            .iter()
            // each sample's quartic is solved (many at once): the k-method,
            // the derivatives at the short period's ω̄, whatever the case's
            // own method (docs/exact-root.md, limits)
            .map(|&damping| Case {
                mach,
                damping,
                frequency_method: FrequencyMethod::K,
                ..self.base.clone()
            })
            .collect();
        let reuse = cases
            .iter()
            .map(|c| {
                let fixed = !c.iterate_frequency && c.omega_bar.is_some();
                let quasi = !c.damping.uses_frequency_at(mach) || fixed;
                let r = evaluate_point_with(c, Harmonic::Interpolated);
                match (quasi && !aero_varies, r) {
                    (true, Ok(r)) => Some(r.derivatives),
                    _ => None,
                }
            })
            .collect();
        AtMach {
            study: self,
            mach,
            cases,
            reuse,
        }
    }
}

/// A sample's error, as its message.
pub type SampleError = String;

impl AtMach<'_> {
    pub fn mach(&self) -> f64 {
        self.mach
    }

    pub fn study(&self) -> &Study {
        self.study
    }

    /// The factors: the inputs, and the model's choice when there are
    /// several.
    pub fn factors(&self) -> usize {
        self.study.factors()
    }

    /// Each model's design point at this Mach number.
    pub fn cases(&self) -> &[Case] {
        &self.cases
    }

    /// The inputs' values at the normal scores `z` (one per factor,
    /// independent): the inputs' scores correlated by the Cholesky factor,
    /// then each through its distribution; and the model's index.
    pub fn values(&self, z: &[f64], x: &mut [f64]) -> usize {
        let s = self.study;
        let n = s.inputs.len();
        for (k, input) in s.inputs.iter().enumerate() {
            let zk = match &s.chol {
                Some(l) => (0..=k).map(|j| l[k * n + j] * z[j]).sum(),
                None => z[k],
            };
            x[k] = input.dist.at(zk);
        }
        if s.models.len() > 1 {
            let u = phi(z[n]);
            s.cumulative
                .iter()
                .position(|c| u < *c)
                .unwrap_or(s.models.len() - 1)
        } else {
            0
        }
    }

    /// One sample: the inputs' values `x` ([`AtMach::values`]) with damping
    /// model `model`, `case` that model's design point to overwrite. Its
    /// quartic is solved alone; a run solves its samples' quartics many at
    /// once ([`Prepared`]), to the same bits.
    pub fn evaluate(
        &self,
        x: &[f64],
        model: usize,
        case: &mut Case,
    ) -> Result<Outcome, SampleError> {
        let p = self.prepare(x, model, case)?;
        let roots = solve_quartic(p.quartic.to_array());
        p.finish(roots)
    }

    /// [`AtMach::evaluate`] up to the quartic's roots: the sample's
    /// derivatives, τ and quartic ([`Analysis::quartic_of`]).
    pub fn prepare(
        &self,
        x: &[f64],
        model: usize,
        case: &mut Case,
    ) -> Result<Prepared, SampleError> {
        let s = self.study;
        let nominal = &self.cases[model];
        let (mut mu1, mut i_b, mut cl_m2, mut h) =
            (nominal.mu1, nominal.i_b, nominal.cl_m2, nominal.h);
        let mut tau = None;
        if let Some(f) = &s.flight {
            let pf = self
                .flight_condition(f, x)
                .for_planform(&nominal.planform)
                .map_err(|e| e.to_string())?;
            (mu1, i_b, cl_m2) = (pf.mu1(), pf.i_b(), pf.cl_m2());
            tau = pf.at_mach(self.mach).ok().map(|p| p.tau);
        }
        for (input, &v) in s.inputs.iter().zip(x) {
            let target = match input.quantity {
                Quantity::Mu1 => &mut mu1,
                Quantity::IB => &mut i_b,
                Quantity::ClM2 => &mut cl_m2,
                Quantity::Cg => &mut h,
                _ => continue,
            };
            *target = input.error.apply(*target, v);
        }
        let mut d = match &self.reuse[model] {
            Some(d) => Derivatives { mu1, i_b, ..*d },
            None => {
                (case.mu1, case.i_b, case.cl_m2, case.h) = (mu1, i_b, cl_m2, h);
                evaluate_point_with(case, Harmonic::Interpolated)
                    .map_err(|e| e.to_string())?
                    .derivatives
            }
        };
        for (input, &v) in s.inputs.iter().zip(x) {
            if let Quantity::Derivative(i) = input.quantity {
                let target = derivative_mut(&mut d, i);
                *target = input.error.apply(*target, v);
            }
        }
        let quartic = Analysis::quartic_of(&d).map_err(|e| e.to_string())?;
        Ok(Prepared {
            derivatives: d,
            tau,
            quartic,
        })
    }

    /// The physical flight condition with the sample's altitude, mass and
    /// I_y.
    fn flight_condition(&self, f: &FlightCondition, x: &[f64]) -> FlightCondition {
        let mut f = *f;
        for (input, &v) in self.study.inputs.iter().zip(x) {
            let e = input.error;
            match input.quantity {
                Quantity::Altitude => {
                    if let Air::Standard(a) = &mut f.air {
                        *a = match *a {
                            Altitude::Pressure(h) => Altitude::Pressure(e.apply(h, v)),
                            Altitude::Geometric(h) => Altitude::Geometric(e.apply(h, v)),
                        };
                    }
                }
                Quantity::Mass => {
                    f.mass = match f.mass {
                        Mass::Mass(m) => Mass::Mass(e.apply(m, v)),
                        Mass::Weight(w) => Mass::Weight(e.apply(w, v)),
                    };
                }
                Quantity::PitchInertia => f.pitch_inertia = e.apply(f.pitch_inertia, v),
                _ => {}
            }
        }
        f
    }
}

/// A sample up to its quartic's roots ([`AtMach::prepare`]): what
/// [`Prepared::finish`] needs with them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Prepared {
    pub derivatives: Derivatives,
    /// τ in seconds, where the flight condition is physical.
    pub tau: Option<f64>,
    /// The characteristic quartic (eq 5), its coefficients finite.
    pub quartic: Quartic,
}

impl Prepared {
    /// The sample's outcome from its quartic's roots as [`solve_quartic`]
    /// gives them (or [`crate::numerics::roots::solve_quartics`], the same bits):
    /// [`AtMach::evaluate`]'s result.
    pub fn finish(
        &self,
        roots: Result<[Complex64; 4], RootsError>,
    ) -> Result<Outcome, SampleError> {
        let a = Analysis::without_classical_from_roots(&self.derivatives, self.quartic, roots)
            .map_err(|e| e.to_string())?;
        if !a.is_finite() {
            return Err("the sample's numbers overflow f64".to_string());
        }
        Ok(Outcome::of(&a, self.tau))
    }
}

/// The aerodynamic derivative `i` of [`AERO_DERIVATIVES`].
fn derivative_mut(d: &mut Derivatives, i: usize) -> &mut f64 {
    match i {
        0 => &mut d.x_u,
        1 => &mut d.x_w,
        2 => &mut d.x_wdot,
        3 => &mut d.x_q,
        4 => &mut d.z_u,
        5 => &mut d.z_w,
        6 => &mut d.z_wdot,
        7 => &mut d.z_q,
        8 => &mut d.m_u,
        9 => &mut d.m_w,
        10 => &mut d.m_wdot,
        _ => &mut d.m_q,
    }
}

/// How a run samples.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// Monte Carlo samples (rows of A).
    pub samples: u64,
    pub seed: u64,
    /// Also the Sobol indices: each row evaluates B and the A_B^(i) too
    /// (k + 2 design points a row). The probabilities are of A's rows
    /// whether or not.
    pub sobol: bool,
    /// Pseudo-random or Owen-scrambled Sobol′ points ([`super::quasi`]).
    pub sampling: Sampling,
}

/// The shares of the MIL-F-8785C levels among the evaluated samples.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Levels {
    pub level_1: Proportion,
    pub level_2: Proportion,
    pub level_3: Proportion,
    pub worse_than_level_3: Proportion,
    /// No oscillatory mode to judge (or a divergent phugoid without τ in
    /// seconds).
    pub not_assessed: Proportion,
}

impl Levels {
    pub(super) fn of(counts: &[u64; 5], n: u64) -> Levels {
        let p = |k: usize| Proportion::of(counts[k], n);
        Levels {
            level_1: p(1),
            level_2: p(2),
            level_3: p(3),
            worse_than_level_3: p(4),
            not_assessed: p(0),
        }
    }
}

/// The Sobol indices of one run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Sensitivity {
    /// The factors, in the order of the indices.
    pub factors: Vec<&'static str>,
    /// Of the margin Δm_θ̇ (eq 41) and of the short period's ζ: `None`
    /// where the output did not vary or too few rows had it.
    pub margin: Option<Vec<Indices>>,
    pub damping_ratio: Option<Vec<Indices>>,
    /// Rows used for each (those whose every evaluation had the output).
    pub margin_rows: u64,
    pub damping_ratio_rows: u64,
}

/// A run's results at one Mach number.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Summary {
    pub mach: f64,
    pub samples: u64,
    /// Samples with a result; the proportions are of these.
    pub evaluated: u64,
    pub errors: u64,
    /// The first sample's error, in sample order.
    pub first_error: Option<String>,
    /// The §8 one-cycle standard on the short period.
    pub standard_met: Proportion,
    /// The overall verdict: meets (no mode grows, the standard met), fails,
    /// divergent (any mode grows).
    pub meets: Proportion,
    pub fails: Proportion,
    pub divergent: Proportion,
    /// The short period's levels in Categories A, B, C (MIL-F-8785C
    /// §3.2.2.1.2) and the phugoid's (§3.2.1.2).
    pub short_period_level_a: Levels,
    pub short_period_level_b: Levels,
    pub short_period_level_c: Levels,
    pub phugoid_level: Levels,
    pub cycles_to_half: Quantiles,
    pub damping_ratio: Quantiles,
    pub sobol: Option<Sensitivity>,
}
