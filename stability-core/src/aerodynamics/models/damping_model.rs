//! The damping model as a type ([`DampingModel`]): the named models of the
//! command line and configs (`--damping`, `[model] damping`) — the default
//! `faired`, the note's own `faired-theories`, `faired-slender` and each
//! single theory of [`crate::aerodynamics::theory`] — each owning its
//! regimes and joins through Mach number, its frequency policy
//! ([`FrequencyPolicy`]), the origin of its own coefficients, and the
//! methods of a configuration's increment. Whatever asks which theory
//! applies where — a design point, a configuration, a tail sizing, the
//! study's figures, the uncertainty study, Python — asks the model.

use super::faired;
use super::increment::Increment;
use super::regime::{Regime, RegimeKind};
use crate::aerodynamics::damping::{
    Damping, DampingError, TheoryCoefficients, WingInput, damping_derivatives_with,
    theory_coefficients,
};
use crate::aerodynamics::lifting_surface::Harmonic;
use crate::aerodynamics::lifting_surface::configuration::ConfigurationError;
use crate::aerodynamics::lifting_surface::mach_range::MACH_RANGE_MAX;
use crate::aerodynamics::theory::{Row, Theory, UnknownTheory};
use crate::geometry::Planform;
use crate::geometry::configuration::Configuration;
use serde::Serialize;

/// Which damping derivatives a case uses; serializes as its name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum DampingModel {
    /// One theory, wherever it is asked for (errors outside its domain).
    Theory(Theory),
    /// The default ([`crate::aerodynamics::models::faired`]): one frequency-dependent linear
    /// lifting-surface theory at the short period's own ω̄ from M = 0 to 3
    /// — the doublet lattice, its sonic extrapolation at M = 1, the Mach box
    /// above — with one stated join through the sonic point, from M = 0.99 to
    /// the Mach box's first Mach number (which depends on the planform); linear supersonic theory beyond M = 3; the lift
    /// slope and aerodynamic centre from the same theory.
    #[default]
    Faired,
    /// The theories faired through Mach number as the note built its Figs
    /// 19–24, `faired-theories` ([`crate::aerodynamics::models::faired::theories`], the default
    /// before `faired`): lifting-surface theory at the short period's own ω̄
    /// to M = 0.9, Mangler's transonic theory (38)–(40) at M = 1, linear
    /// supersonic theory from M = 1.2 ((36), then the supersonic-edge
    /// theory past the sonic leading edge), joined between by stated
    /// cubics; the lift slope and aerodynamic centre from the same
    /// theories.
    FairedTheories,
    /// The previous slender-wing fairing, `faired-slender`
    /// ([`crate::aerodynamics::models::faired::slender`]): slender-wing theory (37) to
    /// M = 1, blended into linear supersonic theory over 1 ≤ M ≤ 1.2, (36)
    /// held at its sonic-leading-edge values past the sonic edge, with a
    /// warning; quasi-steady, and the default methods' lift slope and
    /// aerodynamic centre.
    FairedSlender,
}

impl Serialize for DampingModel {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.name())
    }
}

impl DampingModel {
    /// Whether the derivatives depend on μ₁ and i_B. They do not, except
    /// through the frequency parameter ω̄ = s/μ₁ of a frequency-dependent
    /// theory: μ₁ and i_B enter the equations of motion (eqs 2, 4), not the
    /// derivatives of §5–7. So a sweep over them need evaluate the
    /// aerodynamics once per planform, Mach number and c.g. (The warnings
    /// may depend on them: `supersonic`'s low-frequency rule is checked at
    /// the short period's ω̄.)
    pub fn depends_on_mass(self) -> bool {
        self.uses_frequency()
    }

    /// Whether the model's derivatives depend on the frequency parameter ω̄
    /// at some Mach number and it is iterated (Mangler's (39)–(40),
    /// `lifting-surface-frequency`, `faired`, `faired-theories`).
    pub fn uses_frequency(self) -> bool {
        match self {
            DampingModel::Theory(t) => t.uses_frequency(),
            DampingModel::Faired | DampingModel::FairedTheories => true,
            DampingModel::FairedSlender => false,
        }
    }

    /// How the model takes the motion's frequency at Mach `mach` — for the
    /// wing and a configuration's increment alike.
    pub fn frequency_at(self, mach: f64) -> FrequencyPolicy {
        let iterated = match self {
            DampingModel::Theory(Theory::LiftingSurface) => return FrequencyPolicy::Given,
            DampingModel::Theory(t) => t.uses_frequency(),
            DampingModel::Faired => mach <= MACH_RANGE_MAX,
            DampingModel::FairedTheories => faired::theories::iterates_frequency_at(mach),
            DampingModel::FairedSlender => false,
        };
        if iterated {
            FrequencyPolicy::ShortPeriod
        } else {
            FrequencyPolicy::QuasiSteady
        }
    }

    /// Whether the model's derivatives depend on ω̄ at Mach `mach` and it is
    /// iterated to the short period's ([`FrequencyPolicy::ShortPeriod`]).
    pub fn uses_frequency_at(self, mach: f64) -> bool {
        self.frequency_at(mach) == FrequencyPolicy::ShortPeriod
    }

    /// Every model: the two fairings, then the theories (in the order of
    /// [`Theory::ALL`]).
    pub const ALL: [DampingModel; 3 + Theory::ALL.len()] = {
        let mut out = [DampingModel::Faired; 3 + Theory::ALL.len()];
        out[1] = DampingModel::FairedTheories;
        out[2] = DampingModel::FairedSlender;
        let mut i = 0;
        while i < Theory::ALL.len() {
            out[3 + i] = DampingModel::Theory(Theory::ALL[i]);
            i += 1;
        }
        out
    };

    /// The model's row of the registry ([`crate::aerodynamics::theory`]).
    pub fn row(self) -> &'static Row {
        match self {
            DampingModel::Theory(t) => t.row(),
            DampingModel::Faired => &FAIRED,
            DampingModel::FairedTheories => &FAIRED_THEORIES,
            DampingModel::FairedSlender => &FAIRED_SLENDER,
        }
    }

    /// Whether the model takes a frequency parameter ω̄ at all
    /// ([`Theory::takes_omega_bar`]).
    pub fn takes_omega_bar(self) -> bool {
        match self {
            DampingModel::Theory(t) => t.takes_omega_bar(),
            DampingModel::Faired | DampingModel::FairedTheories => true,
            DampingModel::FairedSlender => false,
        }
    }

    pub fn name(self) -> &'static str {
        self.row().name
    }

    /// `faired`, `faired-slender` or a theory's name.
    pub fn parse(s: &str) -> Result<Self, UnknownDampingModel> {
        match DampingModel::ALL.into_iter().find(|m| m.name() == s) {
            Some(m) => Ok(m),
            None => Err(UnknownDampingModel(s.parse::<Theory>().unwrap_err())),
        }
    }

    /// The lift slope and aerodynamic centre the model's own theory gives
    /// at `mach`, with their Mach derivatives — taken by
    /// [`aero::Source::Default`](super::aero::Source::Default) in place of
    /// the default methods: the supersonic theory's at M > 1
    /// (`damping::theory_coefficients`), the fairings' everywhere
    /// ([`faired::coefficients`], [`faired::theories::coefficients`]).
    /// `faired-slender` gives none.
    pub fn own_coefficients(
        self,
        planform: &Planform,
        mach: f64,
    ) -> Result<Option<TheoryCoefficients>, DampingError> {
        match self {
            DampingModel::Theory(t) => theory_coefficients(t, planform, mach),
            DampingModel::Faired => faired::coefficients(planform, mach),
            DampingModel::FairedTheories => faired::theories::coefficients(planform, mach),
            DampingModel::FairedSlender => Ok(None),
        }
    }

    /// The wing's damping derivatives at c.g. `h` and Mach `mach`:
    /// `omega_bar` is the ω̄ the model takes there ([`Self::frequency_at`]:
    /// the short period's, iterated; the one given, `given`; or none,
    /// quasi-steady — where `supersonic` still checks its low-frequency
    /// rule at the short period's `omega_bar`), the lattice's harmonic
    /// solutions had as `harmonic` says.
    pub fn damping(
        self,
        wing: &WingInput,
        h: f64,
        mach: f64,
        omega_bar: Option<f64>,
        given: Option<f64>,
        harmonic: Harmonic,
    ) -> Result<Damping, DampingError> {
        match self {
            DampingModel::Theory(t @ Theory::LiftingSurface) => {
                damping_derivatives_with(t, wing, h, mach, given, harmonic)
            }
            DampingModel::Theory(t) => {
                damping_derivatives_with(t, wing, h, mach, omega_bar, harmonic)
            }
            DampingModel::Faired => faired::damping(wing, h, mach, omega_bar, harmonic),
            DampingModel::FairedTheories => {
                faired::theories::damping(wing, h, mach, omega_bar, harmonic)
            }
            DampingModel::FairedSlender => faired::slender::damping(wing, h, mach),
        }
    }

    /// The ω̄ at which a configuration's increment is taken with the wing's
    /// damping at Mach `mach`: the wing's own — the short period's
    /// `omega_bar` where the model iterates it, the `given` one, or 0
    /// (quasi-steady: a quasi-steady derivative does not depend on μ₁ or
    /// i_B).
    pub fn increment_omega_bar(self, mach: f64, omega_bar: Option<f64>, given: Option<f64>) -> f64 {
        match self.frequency_at(mach) {
            FrequencyPolicy::QuasiSteady => 0.0,
            FrequencyPolicy::Given => given.unwrap_or(0.0),
            FrequencyPolicy::ShortPeriod => omega_bar.unwrap_or(0.0),
        }
    }

    /// What a configuration adds to its wing at (`mach`, `omega_bar`) by
    /// this model's methods (docs/configurations.md): the lifting surface
    /// through M = 1 for `faired` and the lifting-surface theories
    /// ([`faired::increment`]: the multi-surface lattice, its bridge to the
    /// Mach box, the Mach box for every surface), the note's bands for the
    /// others ([`faired::theories::increment`]: the lattice to 0.9, linear
    /// supersonic theory from 1.2, a stated cubic between). With
    /// `mach_derivatives`, the Mach derivatives of its in-phase numbers
    /// (eqs 27–29).
    pub fn increment(
        self,
        config: &Configuration,
        mach: f64,
        omega_bar: f64,
        harmonic: Harmonic,
        mach_derivatives: bool,
    ) -> Result<Increment, ConfigurationError> {
        if self.is_lifting_surface() {
            faired::increment(config, mach, omega_bar, harmonic, mach_derivatives)
        } else {
            faired::theories::increment(config, mach, omega_bar, harmonic, mach_derivatives)
        }
    }

    /// The methods of [`Self::increment`] for `config`, in words (a page's).
    pub fn increment_methods(self, config: &Configuration) -> String {
        if self.is_lifting_surface() {
            format!(
                "up to M = {} by the multi-surface doublet lattice, from M = {:.4} (where every surface has its Mach box) by the Mach box for every surface with the tail in the wing's downwash, a straight bridge between, linear supersonic theory beyond M = {MACH_RANGE_MAX}",
                faired::SONIC_JOIN,
                faired::increment_mach_box_from(config)
            )
        } else {
            format!(
                "up to M = {} by the multi-surface doublet lattice, from M = {} by linear supersonic theory with the tail in the wing's downwash, faired between",
                faired::theories::LIFTING_SURFACE_LIMIT,
                faired::theories::SUPERSONIC_FROM
            )
        }
    }

    /// Whether the model is one lifting-surface theory through M = 1
    /// (`faired`, `lifting-surface`, `lifting-surface-frequency`).
    pub fn is_lifting_surface(self) -> bool {
        match self {
            DampingModel::Faired => true,
            DampingModel::Theory(t) => t.is_lifting_surface(),
            DampingModel::FairedTheories | DampingModel::FairedSlender => false,
        }
    }

    /// The Mach numbers from which a configuration's increment under this
    /// model needs no lattice solve (the supersonic methods): what a tail
    /// sizing tries last.
    pub fn supersonic_increment_from(self, config: &Configuration) -> f64 {
        if self.is_lifting_surface() {
            faired::increment_mach_box_from(config)
        } else {
            faired::theories::SUPERSONIC_FROM
        }
    }

    /// The model's regimes for a planform, in Mach order: which theory, or
    /// which stated join, over each range of Mach number. A single theory
    /// has none.
    pub fn regimes(self, planform: &Planform) -> Vec<Regime> {
        match self {
            DampingModel::Faired => faired::regimes(planform),
            DampingModel::FairedTheories => faired::theories::regimes(planform),
            DampingModel::FairedSlender => faired::slender::regimes(planform),
            DampingModel::Theory(_) => Vec::new(),
        }
    }

    /// Where the model's damping derivatives are joined between two
    /// theories ([`RegimeKind::Faired`]) on `planform`.
    pub fn damping_joins(self, planform: &Planform) -> Vec<(f64, f64)> {
        self.regimes(planform)
            .iter()
            .filter(|r| r.kind == RegimeKind::Faired)
            .map(|r| (r.from, r.to))
            .collect()
    }

    /// Where the model's own lift slope and aerodynamic centre are joined
    /// between two theories on `planform`: `faired`'s through the sonic
    /// point ([`faired::sonic_join`]), `faired-theories`' from the lattice
    /// at 0.9 to linear theory at 1.2.
    pub fn coefficient_joins(self, planform: &Planform) -> Vec<(f64, f64)> {
        match self {
            DampingModel::Faired | DampingModel::Theory(Theory::LiftingSurface) => {
                faired::sonic_join(planform).into_iter().collect()
            }
            DampingModel::FairedTheories => vec![faired::theories::COEFFICIENT_JOIN],
            _ => Vec::new(),
        }
    }
}

/// How a damping model takes the frequency of the motion (at one Mach
/// number).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum FrequencyPolicy {
    /// Quasi-steady: the derivatives of a slow motion (ω̄ → 0), whatever
    /// the short period.
    QuasiSteady,
    /// At the ω̄ the case gives (`--omega-bar`), quasi-steady without one.
    Given,
    /// At the short period's own ω̄ = s/μ₁, iterated to consistency: the
    /// derivatives of a steady oscillation at the decaying short period's
    /// frequency (the flutter engineer's k-method).
    ShortPeriod,
}

/// The default model: one lifting-surface theory through M = 1.
const FAIRED: Row = Row {
    name: "faired",
    equations: "Figs 19–24",
    summary: "the default: one frequency-dependent linear lifting-surface theory at the short period's own ω̄ from M = 0 to 3 (the doublet lattice, its sonic extrapolation at M = 1, the Mach box), one stated join through the sonic point between M = 0.99 and the Mach box's first Mach number (a little above M = 1; how far depends on the planform: docs/damping-theories.md tabulates it), linear supersonic theory beyond M = 3; the lift slope and aerodynamic centre from the same theory",
    validity: "any Mach number (the lifting surface 0 ≤ M ≤ 3); true and cropped deltas, trapezoids",
    supplies: "z_q, z_ẇ, m_q, m_ẇ, the lift slope and the aerodynamic centre",
    source: "Albano & Rodden (AIAA J. 7(2), 1969); Pines, Dugundji & Neuringer (J. Aero. Sci. 22(10), 1955); docs/damping-theories.md, \"The faired model\"",
};

/// The note's fairing of its theories, the default before `faired`.
const FAIRED_THEORIES: Row = Row {
    name: "faired-theories",
    equations: "Figs 19–24",
    summary: "the note's own fairing: the lifting surface at the short period's own ω̄ to M = 0.9, Mangler's transonic theory (39)–(40) at M = 1, linear supersonic theory (36) from 1.2, joined between by stated cubics; the lift slope and aerodynamic centre from the same theories",
    validity: "any Mach number; true and cropped deltas",
    supplies: "z_q, z_ẇ, m_q, m_ẇ, the lift slope and the aerodynamic centre",
    source: "the note's Figs 19–24 (docs/damping-theories.md, \"The note's fairing\")",
};

/// The previous, quasi-steady fairing.
const FAIRED_SLENDER: Row = Row {
    name: "faired-slender",
    equations: "(37), (36)",
    summary: "the previous, quasi-steady fairing (fast: no lattice): slender-wing theory (37) through M = 1, blended into (36) by M = 1.2, (36) held at its sonic-leading-edge values beyond the sonic edge",
    validity: "any Mach number; true and cropped deltas",
    supplies: "z_q, z_ẇ, m_q, m_ẇ",
    source: "Ribner (NACA TN 1423); Mangler; Ribner & Malvestuto (NACA Rep. 908)",
};

/// A damping model's name that is neither a fairing's nor a theory's.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{0}; or the fairings `faired` (the default), `faired-theories` and `faired-slender`")]
pub struct UnknownDampingModel(#[from] pub UnknownTheory);
