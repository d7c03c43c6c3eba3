//! A derivative set's stability, whole: the quartic (eqs 4–6), Routh's test
//! (§4), the roots and modes (eqs 7–8), the short-period approximations and
//! the damping standard (§8).

pub mod engineering;
pub mod verdict;

use crate::criteria::{DampingStandard, FlyingQualities, Routh, ShortPeriodApproximation, Verdict};
use crate::dynamics::classical::{first_approximation, refine, relative_errors};
use crate::dynamics::modes::{Axis, Modes};
use crate::numerics::display::Num;
use crate::numerics::invalid::Invalid;
use crate::numerics::roots::{RootsError, solve_quartic};
use crate::{Derivatives, Quartic};
use num_complex::Complex64;
use serde::Serialize;

/// Why a derivative set has no analysis.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum AnalysisError {
    #[error(transparent)]
    Invalid(#[from] Invalid<&'static str>),
    #[error(
        "A = 1 − z_ẇ/μ₁ = {} (z_ẇ = {}, μ₁ = {}) is within {} of zero: the quartic degenerates to a cubic and the equations of motion have no solution for ẇ",
        Num(*a), Num(*z_wdot), Num(*mu1), Num(LEADING_COEFFICIENT_MIN)
    )]
    LeadingCoefficientZero { a: f64, z_wdot: f64, mu1: f64 },
    #[error(
        "the quartic's coefficient {coefficient} overflows f64 (its terms exceed {}): the derivatives are too large",
        Num(f64::MAX)
    )]
    Overflow { coefficient: &'static str },
    #[error("the roots could not be computed: {0}")]
    Roots(#[from] RootsError),
    #[error(
        "Routh's test ({}) contradicts the roots (largest real part {}): please report this quartic",
        if *routh_stable { "stable" } else { "unstable" },
        Num(*largest_re)
    )]
    RouthDisagrees { routh_stable: bool, largest_re: f64 },
}

/// A root with |r| ≤ ON_AXIS·|λ| lies on the imaginary axis to working
/// precision: the sign of its real part may be beyond what the roots'
/// accuracy (normwise, ~ε|λ| times the condition) resolves, and Routh's
/// verdict is not checked against it.
pub const ON_AXIS: f64 = 1e-9;

pub use crate::dynamics::quartic::LEADING_COEFFICIENT_MIN;

/// Routh's verdict against the roots' real parts: they must agree unless
/// the quartic is on the stability boundary to working precision (R
/// marginal, or a root within [`ON_AXIS`] of the axis). A disagreement
/// otherwise would be a wrong answer: an error, never a result.
pub(crate) fn agree(routh: &Routh, roots: &[Complex64; 4]) -> Result<(), AnalysisError> {
    let on_axis = roots.iter().any(|z| z.re.abs() <= ON_AXIS * z.norm());
    let largest_re = roots.iter().map(|z| z.re).fold(f64::NEG_INFINITY, f64::max);
    let decaying = largest_re < 0.0;
    if routh.marginal || on_axis || routh.stable == decaying {
        Ok(())
    } else {
        Err(AnalysisError::RouthDisagrees {
            routh_stable: routh.stable,
            largest_re,
        })
    }
}

/// A derivative set's inputs checked ([`Derivatives::check`]).
pub fn check(d: &Derivatives) -> Result<(), AnalysisError> {
    Ok(d.check()?)
}

pub use crate::units::STANDARD_GRAVITY;

/// The flight condition in dimensional form, for times in seconds.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Dimensional {
    /// True airspeed V (m/s).
    pub v: f64,
    /// Air density ρ (kg/m³).
    pub rho: f64,
    /// Wing area S (m²).
    pub s: f64,
    /// The reference chord c̄ of the derivatives and of μ₁ (m).
    pub chord: f64,
    /// Mass m (kg).
    pub mass: f64,
}

impl Dimensional {
    /// The unit of time τ = m/(½ρSV) (s), §3.
    pub fn tau(&self) -> f64 {
        self.mass / (0.5 * self.rho * self.s * self.v)
    }

    /// The relative density these values imply, μ₁ = m/(½ρSc̄), §3.
    pub fn mu1(&self) -> f64 {
        self.mass / (0.5 * self.rho * self.s * self.chord)
    }

    /// The lift coefficient of level flight, W/(½ρV²S), eq (24), with
    /// W = m·[`STANDARD_GRAVITY`].
    pub fn c_l(&self) -> f64 {
        self.mass * STANDARD_GRAVITY / (0.5 * self.rho * self.v * self.v * self.s)
    }
}

/// How the report's own method (eq 7 and its refinement) fares against the
/// exact roots.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ClassicalCheck {
    /// Eq (7)'s short-period and phugoid roots (s ≥ 0).
    pub short_period: (f64, f64),
    pub phugoid: (f64, f64),
    /// |λ₇ − λ|/|λ| for each.
    pub short_period_error: f64,
    pub phugoid_error: f64,
    /// Iterations of the successive approximation to 1e-12, and whether it
    /// converged.
    pub refinement_iterations: usize,
    pub refinement_converged: bool,
}

/// The time unit of a characteristic's roots, and τ = m/(½ρSV) in seconds
/// when it is known: what turns its rates and times into the other unit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Timebase {
    /// Roots in 1/τ (the report's notation, eqs 2–4).
    Tau(Option<f64>),
    /// Roots in 1/s (a dimensional set, eqs D1–D2).
    Seconds(Option<f64>),
}

impl Timebase {
    /// τ in seconds, when known.
    pub fn tau(self) -> Option<f64> {
        match self {
            Timebase::Tau(t) | Timebase::Seconds(t) => t,
        }
    }

    /// The factor from the roots' unit to 1/τ, when it is known.
    pub fn to_per_tau(self) -> Option<f64> {
        match self {
            Timebase::Tau(_) => Some(1.0),
            Timebase::Seconds(t) => t,
        }
    }

    /// The factor from the roots' unit to 1/s, when it is known.
    pub fn to_per_second(self) -> Option<f64> {
        match self {
            Timebase::Tau(t) => t.map(|t| 1.0 / t),
            Timebase::Seconds(_) => Some(1.0),
        }
    }
}

/// What every derivative set's analysis has, in whatever notation and
/// units: the characteristic quartic (eq 4, or det(λE − A) of eq D2), its
/// roots, Routh's test (§4), the modes (eq 8) and the §8 verdict.
#[derive(Debug, Clone, PartialEq)]
pub struct Characteristic {
    pub quartic: Quartic,
    pub routh: Routh,
    /// The four roots, conjugates adjacent, fastest first.
    pub roots: [Complex64; 4],
    pub modes: Modes,
    /// The §8 one-cycle standard applied to the short period.
    pub verdict: Verdict,
}

impl Characteristic {
    /// The roots, modes and verdict of `quartic`, whose coefficients are
    /// called `names` in errors. Its leading coefficient is the caller's to
    /// check (what A = 0 means depends on the model). `per_chord` gives the
    /// frequency parameter ω̄ = s/`per_chord` of each mode: μ₁ for roots in
    /// 1/τ, V/c̄ for roots in 1/s (0: undefined).
    pub fn of(
        quartic: Quartic,
        names: &[&'static str; 5],
        per_chord: f64,
    ) -> Result<Characteristic, AnalysisError> {
        check_finite(&quartic, names)?;
        let roots = solve_quartic(quartic.to_array())?;
        Characteristic::from_roots(quartic, roots, per_chord)
    }

    /// As [`Characteristic::of`] with the roots already found: `roots` =
    /// [`solve_quartic`]`(quartic.to_array())` (or [`crate::numerics::roots::solve_quartics`]'s,
    /// the same bits), of a quartic whose coefficients are finite. Routh's
    /// test, the modes and the verdict follow from them as in `of`.
    pub fn from_roots(
        quartic: Quartic,
        roots: [Complex64; 4],
        per_chord: f64,
    ) -> Result<Characteristic, AnalysisError> {
        let routh = Routh::of(&quartic);
        agree(&routh, &roots)?;
        let modes = Modes::identify(&roots, per_chord);
        Ok(Characteristic {
            quartic,
            routh,
            roots,
            verdict: Verdict::of(&modes),
            modes,
        })
    }

    /// The axis whose motion the characteristic quartic describes: the
    /// pitch plane's (eqs 2–4) — the only one today ([`Axis`]).
    pub fn axis(&self) -> Axis {
        Axis::Longitudinal
    }

    /// Whether every number the analysis would print is finite (absent
    /// ones, such as an aperiodic mode's period, are `None`, not infinite).
    pub fn is_finite(&self) -> bool {
        self.quartic.to_array().iter().all(|v| v.is_finite())
            && self
                .roots
                .iter()
                .all(|z| z.re.is_finite() && z.im.is_finite())
            && self.routh.discriminant.is_finite()
            && self
                .modes
                .iter()
                .all(|m| m.re.is_finite() && m.im.is_finite())
    }

    /// The MIL-F-8785C levels of the modes (a divergent phugoid's time to
    /// double needs seconds: the roots' own, or τ).
    pub fn flying_qualities(&self, time: Timebase) -> FlyingQualities {
        let tau = match time {
            Timebase::Tau(t) => t,
            Timebase::Seconds(_) => Some(1.0),
        };
        FlyingQualities::of(&self.modes, tau)
    }
}

/// The stability of a derivative set in the report's notation: its
/// [`Characteristic`] (roots in 1/τ) and the report's own quantities of
/// it.
#[derive(Debug, Clone, PartialEq)]
pub struct Analysis {
    pub characteristic: Characteristic,
    pub short_period_approximation: ShortPeriodApproximation,
    pub damping_standard: DampingStandard,
    /// The report's eq (7), when both modes are oscillatory.
    pub classical: Option<ClassicalCheck>,
}

impl std::ops::Deref for Analysis {
    type Target = Characteristic;
    fn deref(&self) -> &Characteristic {
        &self.characteristic
    }
}

impl Analysis {
    /// Analyse a derivative set. A zero root (E = 0) is a neutral mode and
    /// is reported as such; A = 0 is an error.
    pub fn of(d: &Derivatives) -> Result<Analysis, AnalysisError> {
        Analysis::with(d, true)
    }

    /// As [`Analysis::of`], without the eq (7) check (`classical` is
    /// `None`): the lean path of a sweep.
    pub fn without_classical(d: &Derivatives) -> Result<Analysis, AnalysisError> {
        Analysis::with(d, false)
    }

    /// The characteristic quartic of `d` (eqs 4–6) after the checks
    /// [`Analysis::of`] makes before it solves it: the derivatives valid,
    /// A clear of zero, every coefficient finite. Its roots, by
    /// [`solve_quartic`] or many at once by [`crate::numerics::roots::solve_quartics`],
    /// go to [`Analysis::without_classical_from_roots`].
    pub fn quartic_of(d: &Derivatives) -> Result<Quartic, AnalysisError> {
        check(d)?;
        let quartic = Quartic::from_derivatives(d);
        if quartic.a.abs() <= LEADING_COEFFICIENT_MIN {
            return Err(AnalysisError::LeadingCoefficientZero {
                a: quartic.a,
                z_wdot: d.z_wdot,
                mu1: d.mu1,
            });
        }
        check_finite(&quartic, &Derivatives::QUARTIC_COEFFICIENTS)?;
        Ok(quartic)
    }

    /// [`Analysis::without_classical`] of `d` from its quartic
    /// ([`Analysis::quartic_of`]) and that quartic's roots as
    /// [`solve_quartic`] gives them: the same analysis, bit for bit, when
    /// the roots were found in a batch.
    pub fn without_classical_from_roots(
        d: &Derivatives,
        quartic: Quartic,
        roots: Result<[Complex64; 4], RootsError>,
    ) -> Result<Analysis, AnalysisError> {
        let c = Characteristic::from_roots(quartic, roots?, d.mu1)?;
        Ok(Analysis::assemble(d, c, false))
    }

    fn with(d: &Derivatives, classical: bool) -> Result<Analysis, AnalysisError> {
        let quartic = Analysis::quartic_of(d)?;
        let roots = solve_quartic(quartic.to_array())?;
        let c = Characteristic::from_roots(quartic, roots, d.mu1)?;
        Ok(Analysis::assemble(d, c, classical))
    }

    /// This analysis with `roots` in place of its quartic's: the roots each
    /// solved at its own frequency ([`crate::dynamics::p_method`]), whose
    /// modes and verdict follow from them. The quartic, Routh's test and
    /// the eq (7) check stay those of the derivatives at the short period's
    /// ω̄ (the roots are not the quartic's, so they are not checked
    /// against Routh's test).
    /// `per_chord` as in [`Characteristic::of`] (μ₁ for roots in 1/τ).
    pub fn with_roots(mut self, roots: [Complex64; 4], per_chord: f64) -> Analysis {
        let c = &mut self.characteristic;
        c.roots = roots;
        c.modes = Modes::identify(&roots, per_chord);
        c.verdict = Verdict::of(&c.modes);
        self
    }

    /// The analysis of `d` around its characteristic `c`.
    fn assemble(d: &Derivatives, c: Characteristic, classical: bool) -> Analysis {
        let classical = if classical { classical_check(&c) } else { None };
        Analysis {
            characteristic: c,
            classical,
            short_period_approximation: ShortPeriodApproximation::of(d),
            damping_standard: DampingStandard::of(d),
        }
    }
}

/// Every coefficient of `quartic` finite, else the first that is not, by
/// its name in `names`.
fn check_finite(quartic: &Quartic, names: &[&'static str; 5]) -> Result<(), AnalysisError> {
    match quartic.to_array().iter().position(|c| !c.is_finite()) {
        Some(k) => Err(AnalysisError::Overflow {
            coefficient: names[k],
        }),
        None => Ok(()),
    }
}

/// The report's eq (7) and its refinement against the exact roots, when
/// both modes oscillate.
fn classical_check(c: &Characteristic) -> Option<ClassicalCheck> {
    let (sp, ph) = (c.modes.short_period()?, c.modes.phugoid()?);
    let q = c.quartic.to_array();
    let first = first_approximation(q).ok()?;
    let exact_sp = Complex64::new(sp.re, sp.im);
    let exact_ph = Complex64::new(ph.re, ph.im);
    let (e1, e2) = relative_errors(&first, exact_sp, exact_ph);
    let r = refine(q, &first, 500, 1e-12).ok();
    Some(ClassicalCheck {
        short_period: (first.short_period.root().re, first.short_period.root().im),
        phugoid: (first.phugoid.root().re, first.phugoid.root().im),
        short_period_error: e1,
        phugoid_error: e2,
        refinement_iterations: r.map_or(0, |r| r.iterations),
        refinement_converged: r.is_some_and(|r| r.converged),
    })
}
