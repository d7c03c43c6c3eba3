//! What every section draws on: the two wings of the note (45° and 60°
//! tailless deltas) evaluated across Mach number, and the same near M = 1
//! with Mangler's frequency-dependent theory; and the same study under
//! other values of the inputs the note does not state ([`Assumed`]), which
//! the conclusions are swept over.

use rayon::prelude::*;
use stability_core::aerodynamics::damping::Theory;
use stability_core::aerodynamics::lifting_surface::Harmonic;
use stability_core::design::case::{Case, CaseResult, DampingModel, evaluate_harmonic};
use stability_core::design::study::{grid, report_wing};
use stability_core::geometry::{Planform, Size};
use stability_io::plot::{Figure, Series};

/// The note's two wings, by leading-edge sweep (degrees).
pub const WINGS: [f64; 2] = [45.0, 60.0];

/// The note's sub-critical speeds, M ≤ 0.9: where it finds the damping and
/// frequency rising with Mach number and m_ẇ negligible (§7 (a), §11), and
/// where it trusts lifting-surface theory ("a reliable prediction of the
/// effects of compressibility up to a Mach number of about 0.9", §7).
pub const SUBCRITICAL: f64 = 0.9;

/// The Mach number at which the note applies supersonic theory (36) to its
/// wings (§7, §10, Fig 17: "at M = 1.2").
pub const NOTE_SUPERSONIC: f64 = 1.2;

/// The Mach numbers of the figures: from 0.5 in steps of 0.05 while the
/// default damping model is the plain lattice on both wings — smooth in
/// Mach number, one lattice per wing and Mach number — then in steps of
/// 0.01 to 2.0, through the refined lattice, the join and the Mach box,
/// where the curves turn (the model's first regime's end:
/// `DampingModel::regimes`).
pub fn machs() -> Vec<f64> {
    let coarse_to = WINGS
        .iter()
        .filter_map(|&deg| Planform::new(deg.to_radians(), 0.0, Size::RootChord(1.0)).ok())
        .filter_map(|p| DampingModel::default().regimes(&p).first().map(|r| r.to))
        .fold(2.0, f64::min);
    let mut ms = grid(0.5, coarse_to, 0.05);
    ms.extend(grid(coarse_to + 0.01, 2.0, 0.01));
    ms
}

/// One case's result as the report evaluates it (`None` where a theory
/// does not apply): whole (eq 7's check too), the lattice's harmonic
/// solutions of the frequency-dependent models (the default `faired` below
/// M = 1.2) interpolated in each wing's frequency table, so that the study,
/// its sweeps over the unstated inputs and the largest-μ₁ searches solve the
/// lattice once per wing, Mach number and tabled ω̄, not once per iterate.
pub fn eval(case: &Case) -> Option<CaseResult> {
    evaluate_harmonic(case, Harmonic::Interpolated).ok()
}

/// Each case's result ([`eval`]), in parallel.
pub fn eval_all(cases: Vec<Case>) -> Vec<Option<CaseResult>> {
    cases.par_iter().map(eval).collect()
}

/// The note's wing of sweep `deg` across the Mach numbers `ms`, varied by
/// `vary`.
pub fn across(deg: f64, ms: &[f64], vary: impl Fn(Case) -> Case) -> Vec<Option<CaseResult>> {
    eval_all(ms.iter().map(|&m| vary(report_wing(deg, m))).collect())
}

/// The cases of the note's wing of sweep `deg` across `ms` with the values
/// `assumed`, varied by `vary`.
fn wing_cases(assumed: Assumed, deg: f64, ms: &[f64], vary: impl Fn(Case) -> Case) -> Vec<Case> {
    ms.iter()
        .map(|&m| vary(assumed.apply(report_wing(deg, m))))
        .collect()
}

/// A curve of `f` over a Mach grid of results (non-finite where no result).
pub fn curve(
    label: &str,
    ms: &[f64],
    rs: &[Option<CaseResult>],
    f: impl Fn(&CaseResult) -> Option<f64>,
) -> Series {
    Series::new(
        label,
        ms.iter()
            .zip(rs)
            .map(|(&m, r)| (m, r.as_ref().and_then(&f).unwrap_or(f64::NAN)))
            .collect(),
    )
}

/// A figure against Mach number.
pub fn mach_fig(id: &str, title: &str, y: &str) -> Figure {
    Figure::new(id, title, "Mach number M", y)
}

/// A wing's label in the legends.
pub fn label(deg: f64) -> String {
    format!("{deg}° delta")
}

/// An input of the study that the note does not state.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Assumption {
    /// The pitching inertia i_B = B/(mc̄²).
    IB,
    /// C_L·M² of level flight (eq 24).
    ClM2,
}

impl Assumption {
    pub const ALL: [Assumption; 2] = [Assumption::IB, Assumption::ClM2];

    pub fn symbol(self) -> &'static str {
        match self {
            Assumption::IB => "i_B",
            Assumption::ClM2 => "C_L·M²",
        }
    }

    /// The values a conclusion is swept over: i_B from 0.04 to 0.2 (a
    /// tailless delta's radius of gyration in pitch between 0.2c̄ and
    /// 0.45c̄); C_L·M² = W/(½ρa²S) from 0.02 to 0.2 (wing loadings of
    /// 30–50 lb/ft² from sea level to about 40 000 ft).
    pub fn range(self) -> (f64, f64) {
        match self {
            Assumption::IB => (0.04, 0.2),
            Assumption::ClM2 => (0.02, 0.2),
        }
    }

    /// Its value in `a`.
    pub fn of(self, a: Assumed) -> f64 {
        match self {
            Assumption::IB => a.i_b,
            Assumption::ClM2 => a.cl_m2,
        }
    }

    /// `a` with this input set to `v`.
    pub fn set(self, a: Assumed, v: f64) -> Assumed {
        match self {
            Assumption::IB => Assumed { i_b: v, ..a },
            Assumption::ClM2 => Assumed { cl_m2: v, ..a },
        }
    }
}

/// The values taken for the inputs the note does not state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Assumed {
    pub i_b: f64,
    pub cl_m2: f64,
}

impl Assumed {
    /// Ours: those of `stability_core::design::study::report_wing` (i_B = 0.08,
    /// C_L·M² = 0.05; docs/models.md).
    pub fn ours() -> Assumed {
        let c = report_wing(WINGS[0], 1.0);
        Assumed {
            i_b: c.i_b,
            cl_m2: c.cl_m2,
        }
    }

    /// `case` with these values.
    pub fn apply(self, case: Case) -> Case {
        Case {
            i_b: self.i_b,
            cl_m2: self.cl_m2,
            ..case
        }
    }
}

/// The shared results.
pub struct Study {
    /// The Mach numbers of the figures.
    pub ms: Vec<f64>,
    /// Each wing of [`WINGS`] at each Mach number, as the note builds it.
    pub results: [Vec<Option<CaseResult>>; 2],
    /// Mach numbers near 1, and the 45° wing there with Mangler's
    /// frequency-dependent theory (39)–(40), ω̄ iterated to consistency.
    pub near_sonic: Vec<f64>,
    pub mangler: Vec<Option<CaseResult>>,
    /// The values taken for the inputs the note does not state.
    pub assumed: Assumed,
}

impl Default for Study {
    fn default() -> Self {
        Self::new()
    }
}

impl Study {
    /// The study, the lifting-surface solutions it needs preloaded from
    /// [`PRECOMPUTED`] ([`preload`]; a stale file is not used).
    pub fn new() -> Study {
        let _ = preload();
        Study::compute()
    }

    /// The study, every solution solved (or taken from the store as it
    /// stands).
    pub fn compute() -> Study {
        let ms = machs();
        let results = WINGS.map(|deg| across(deg, &ms, |c| c));
        let near_sonic = grid(0.9, 1.1, 0.01);
        let mangler = across(45.0, &near_sonic, |c| Case {
            damping: DampingModel::Theory(Theory::TransonicFrequency),
            ..c
        });
        Study {
            ms,
            results,
            near_sonic,
            mangler,
            assumed: Assumed::ours(),
        }
    }

    /// The study with other values of the unstated inputs: both wings
    /// across the same Mach numbers (not Mangler's theory near M = 1, which
    /// only illustrates).
    pub fn assuming(assumed: Assumed) -> Study {
        let ms = machs();
        let results = WINGS.map(|deg| eval_all(wing_cases(assumed, deg, &ms, |c| c)));
        Study {
            ms,
            results,
            near_sonic: Vec::new(),
            mangler: Vec::new(),
            assumed,
        }
    }

    /// As [`across`], with this study's values of the unstated inputs.
    pub fn across(
        &self,
        deg: f64,
        ms: &[f64],
        vary: impl Fn(Case) -> Case,
    ) -> Vec<Option<CaseResult>> {
        eval_all(wing_cases(self.assumed, deg, ms, vary))
    }

    /// The note's wing of sweep `deg` at `mach`, with this study's values.
    pub fn case(&self, deg: f64, mach: f64) -> Case {
        self.assumed.apply(report_wing(deg, mach))
    }

    /// A figure with one curve of `f` per wing.
    pub fn pair(
        &self,
        id: &str,
        title: &str,
        y: &str,
        f: &dyn Fn(&CaseResult) -> Option<f64>,
    ) -> Figure {
        let mut fig = mach_fig(id, title, y);
        for (k, &deg) in WINGS.iter().enumerate() {
            fig = fig.with(curve(&label(deg), &self.ms, &self.results[k], f));
        }
        fig
    }
}

/// The lifting-surface solutions the study needs, solved ahead of time
/// (`cargo xtask tables`): the Mach box's and the near-sonic lattice's,
/// which take seconds each to solve.
pub const PRECOMPUTED: &str = include_str!("../data/lifting-surface-solutions.csv");

/// Puts [`PRECOMPUTED`] into the store of solutions (once per process), so
/// that the study need not solve them: how many. A stale file (made by
/// another solver) is refused whole, and the study solves afresh.
pub fn preload()
-> Result<usize, stability_core::aerodynamics::lifting_surface::precomputed::PrecomputedError> {
    use stability_core::aerodynamics::lifting_surface::precomputed::Precomputed;
    static DONE: std::sync::OnceLock<
        Result<usize, stability_core::aerodynamics::lifting_surface::precomputed::PrecomputedError>,
    > = std::sync::OnceLock::new();
    DONE.get_or_init(|| {
        Precomputed::parse(PRECOMPUTED)
            .map(|file| stability_core::aerodynamics::lifting_surface::store::preload(&file))
    })
    .clone()
}
