//! Validity limits approached: not errors, but what a user should know about
//! a result. Held inline (a design point's evaluation allocates nothing) and
//! written out only when displayed.

use crate::aerodynamics::theory::Theory;
use crate::numerics::display::Num;
use arrayvec::ArrayVec;
use serde::Serialize;
use std::fmt;

/// One validity limit approached.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Warning {
    /// A theory for a true delta applied to a tapered wing.
    TrueDeltaOnly { theory: Theory, taper: f64 },
    /// A transonic theory, (38) or (39)–(40), away from M ≈ 1.
    AwayFromSonic { theory: Theory, mach: f64 },
    /// Slender-wing theory (37) with βA not small.
    NotSlender { beta_a: f64 },
    /// An incompressible theory, (32)–(35), at a high subsonic Mach number.
    Incompressible { theory: Theory, mach: f64 },
    /// Supersonic linear theory at a Mach number where its low-frequency
    /// criterion κ = ω̄(c₀/c̄)M²/(M² − 1) ≤ 0.5 fails at the case's ω̄
    /// (`supersonic::transonic`): ν = ω̄/(M² − 1), and the Mach number above
    /// which it holds at this ω̄ (`None`: none, ω̄c₀/c̄ ≥ 0.5).
    LowFrequency {
        mach: f64,
        omega_bar: f64,
        nu: f64,
        kappa: f64,
        /// The criterion's limit on κ (`LOW_FREQUENCY_LIMIT`).
        limit: f64,
        validity_mach: Option<f64>,
    },
    /// Supersonic linear theory with no frequency to check its
    /// low-frequency criterion against: the largest ω̄ at which it holds.
    FrequencyUnchecked {
        mach: f64,
        omega_max: f64,
        limit: f64,
    },
    /// The faired model above the Mach number at which the leading edge
    /// turns supersonic: (36) held at its sonic-edge values.
    FairedHeldAtSonicEdge { sonic: f64 },
    /// The faired model between two theories (`faired::JOINS`): a guess.
    Faired {
        mach: f64,
        lower: Theory,
        lower_mach: f64,
        upper: Theory,
        upper_mach: f64,
    },
    /// The frequency iteration did not converge.
    FrequencyNotConverged { iterations: usize, last: f64 },
    /// Modes whose root at its own frequency (the p-method) was not found:
    /// these keep the k-method's root.
    ExactRootNotConverged { kept: usize },
    /// The doublet lattice close to M = 1.
    LatticeNearSonic { mach: f64 },
    /// The doublet lattice at a frequency its boxes barely resolve.
    LatticeHighFrequency { omega_bar: f64 },
    /// A tailplane nearer the wing than the far-wake downwash it is given
    /// holds for (`configuration::downwash`): its aerodynamic centre
    /// `at` behind the wing's apex, where the tips' Mach lines meet the
    /// centre line `from` behind it (in wing M.A.C.s).
    DownwashNearWing { mach: f64, at: f64, from: f64 },
    /// The Mach box with a subsonic leading edge below the β cot Λ down to
    /// which it was verified (`verified`,
    /// `lifting_surface::mach_range::MACH_BOX_VERIFIED_BETA_COT`), or just
    /// below sonic.
    MachBoxSubsonicEdge {
        mach: f64,
        beta_cot: f64,
        verified: f64,
    },
    /// Between M = 1 and the Mach box's first Mach number: a straight line.
    SonicBridge { mach: f64, mach_box_from: f64 },
    /// The faired model near M = 1 (0.99 < M < the Mach box's first Mach
    /// number) at an ω̄ below the sonic solution's verified
    /// `lifting_surface::near_sonic::SONIC_OMEGA_BAR_MIN`: evaluated there
    /// instead.
    SonicFrequencyRaised {
        mach: f64,
        omega_bar: f64,
        used: f64,
    },
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Warning::TrueDeltaOnly { theory, taper } => write!(
                f,
                "{theory}: the theory is for a true delta; taper {} is treated with the true delta's formulas at this aspect ratio",
                Num(taper)
            ),
            Warning::AwayFromSonic { theory, mach } => write!(
                f,
                "{theory} {}: a theory for M ≈ 1, applied at M = {}",
                theory.equations(),
                Num(mach)
            ),
            Warning::NotSlender { beta_a } => write!(
                f,
                "slender (37): slender-wing theory assumes βA ≪ 1; here βA = {beta_a:.2}"
            ),
            Warning::Incompressible { theory, mach } => write!(
                f,
                "{theory} {}: an incompressible theory, applied at M = {}",
                theory.equations(),
                Num(mach)
            ),
            Warning::LowFrequency {
                mach,
                omega_bar,
                nu,
                kappa,
                limit,
                validity_mach,
            } => low_frequency(f, mach, omega_bar, (nu, kappa, limit), validity_mach),
            Warning::FrequencyUnchecked {
                mach,
                omega_max,
                limit,
            } => write!(
                f,
                "supersonic: linear theory ((36) and past the sonic edge) is first order in frequency, valid for ω̄/(M² − 1) ≪ 1; at M = {} it holds for ω̄ ≤ {omega_max:.3} (κ = ω̄(c₀/c̄)M²/(M² − 1) ≤ {limit}), and no frequency was given to check",
                Num(mach)
            ),
            Warning::FairedHeldAtSonicEdge { sonic } => write!(
                f,
                "faired damping: the leading edge is supersonic above M = {sonic:.3}; (36) is held at its sonic-leading-edge values"
            ),
            Warning::Faired {
                mach,
                lower,
                lower_mach,
                upper,
                upper_mach,
            } => write!(
                f,
                "faired damping at M = {}: joined between {lower} {} at M = {} and {upper} {} at M = {} — a fairing, not a theory (docs/damping-theories.md, \"The faired model\")",
                Num(mach),
                lower.cited(),
                Num(lower_mach),
                upper.cited(),
                Num(upper_mach)
            ),
            Warning::FrequencyNotConverged { iterations, last } => write!(
                f,
                "the frequency parameter did not converge in {iterations} iterations (last ω̄ = {last:.6})"
            ),
            Warning::ExactRootNotConverged { kept } => write!(
                f,
                "{kept} mode{} not found at {} own complex frequency (heavily damped, beyond the p-method's continuation, or needing the theory at a frequency it refuses): {} the k-method's root (the derivatives at the short period's ω̄)",
                if kept == 1 { "" } else { "s" },
                if kept == 1 { "its" } else { "their" },
                if kept == 1 { "it keeps" } else { "each keeps" },
            ),
            Warning::LatticeNearSonic { .. }
            | Warning::LatticeHighFrequency { .. }
            | Warning::DownwashNearWing { .. }
            | Warning::MachBoxSubsonicEdge { .. }
            | Warning::SonicBridge { .. }
            | Warning::SonicFrequencyRaised { .. } => lifting_surface(self, f),
        }
    }
}

/// The lifting-surface and configuration warnings in words (the lattice
/// near M = 1 and at high ω̄, the Mach box, the sonic bridge, a tail's
/// downwash); [`Warning`]'s other kinds write nothing here.
fn lifting_surface(w: &Warning, f: &mut fmt::Formatter<'_>) -> fmt::Result {
    match *w {
        Warning::LatticeNearSonic { mach } => write!(
            f,
            "lifting surface at M = {}: the lattice refined near M = 1 (within 3·10⁻² on each derivative, 1 % of C_Lα more from the sonic extrapolation above M = 0.99: docs/lattice-near-sonic.md), and linear theory fails towards M = 1",
            Num(mach)
        ),
        Warning::LatticeHighFrequency { omega_bar } => write!(
            f,
            "lifting surface at ω̄ = {omega_bar:.3}: the default lattice resolves ω̄ ≲ 2 (boxes short against the wavelength)"
        ),
        Warning::DownwashNearWing { mach, at, from } => write!(
            f,
            "tailplane at M = {}: the wing's downwash at it is the far wake's (Trefftz plane), which holds behind the point where the tips' Mach lines meet the centre line, {from:.2} M.A.C.s behind the wing's apex; the tail's centre is {at:.2} behind it, where linear theory's downwash is smaller (docs/configurations.md)",
            Num(mach)
        ),
        Warning::MachBoxSubsonicEdge {
            mach,
            beta_cot,
            verified,
        } if beta_cot < verified => {
            write!(
                f,
                "lifting surface at M = {}: the Mach box with a subsonic leading edge at β cot Λ = {beta_cot:.2}, below the {verified} down to which it was verified (within 1 % of eq (36); docs/supersonic-oscillatory.md)",
                Num(mach)
            )
        }
        Warning::MachBoxSubsonicEdge { mach, beta_cot, .. } => write!(
            f,
            "lifting surface at M = {}: the Mach box with a leading edge just subsonic, β cot Λ = {beta_cot:.3}: the diaphragm is narrower than one box, and z_θ̇ was measured up to 4 % off eq (36) there (docs/supersonic-oscillatory.md)",
            Num(mach)
        ),
        Warning::SonicBridge {
            mach,
            mach_box_from,
        } => write!(
            f,
            "lifting surface at M = {}: between the sonic point (M = 1) and the Mach box's first Mach number {mach_box_from:.4}, interpolated linearly in M — a bridge, not a theory",
            Num(mach)
        ),
        Warning::SonicFrequencyRaised {
            mach,
            omega_bar,
            used,
        } => write!(
            f,
            "faired at M = {}: the short period's ω̄ = {} is below the ω̄ = {} at which the sonic solution was verified; the derivatives are those at ω̄ = {} (the α̇ pair grows like ln(1/ω̄) as ω̄ → 0 near M = 1, so they understate it)",
            Num(mach),
            Num(omega_bar),
            Num(used),
            Num(used)
        ),
        _ => Ok(()),
    }
}

/// [`Warning::LowFrequency`] in words: (36)'s low-frequency rule failed at
/// the short period's ω̄ (`ratios`: ν = ω̄/(M² − 1), κ and the rule's limit).
fn low_frequency(
    f: &mut fmt::Formatter<'_>,
    mach: f64,
    omega_bar: f64,
    (nu, kappa, limit): (f64, f64, f64),
    validity_mach: Option<f64>,
) -> fmt::Result {
    write!(
        f,
        "supersonic: linear theory ((36) and past the sonic edge) is first order in frequency, valid for ω̄/(M² − 1) ≪ 1 (the rule: κ = ω̄(c₀/c̄)M²/(M² − 1) ≤ {limit}); at M = {} the short period's ω̄ = {omega_bar:.3} gives ω̄/(M² − 1) = {nu:.3}, κ = {kappa:.3}, so its z_ẇ, m_ẇ are outside it; ",
        Num(mach)
    )?;
    match validity_mach {
        Some(m) => write!(f, "at this ω̄ it holds above M = {m:.3}"),
        None => write!(f, "at this ω̄ it holds at no Mach number (ω̄c₀/c̄ ≥ {limit})"),
    }
}

impl Serialize for Warning {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

/// Up to eight warnings, in the order they arose; a ninth is dropped (no
/// evaluation raises more than five).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Warnings(ArrayVec<Warning, 8>);

impl Warnings {
    pub fn push(&mut self, w: Warning) {
        // full: dropped (see the type's documentation)
        let _ = self.0.try_push(w);
    }

    pub fn extend(&mut self, other: &Warnings) {
        for w in other {
            self.push(*w);
        }
    }

    pub fn len(&self) -> usize {
        self.0.len()
    }

    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    pub fn iter(&self) -> std::slice::Iter<'_, Warning> {
        self.0.iter()
    }
}

impl<'a> IntoIterator for &'a Warnings {
    type Item = &'a Warning;
    type IntoIter = std::slice::Iter<'a, Warning>;
    fn into_iter(self) -> Self::IntoIter {
        self.0.iter()
    }
}

impl Serialize for Warnings {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(self.iter())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn warnings_read_as_before_and_overflow_quietly() {
        let w = Warning::AwayFromSonic {
            theory: Theory::Transonic,
            mach: 1.5,
        };
        assert_eq!(
            w.to_string(),
            "transonic (38): a theory for M ≈ 1, applied at M = 1.5"
        );
        let mut ws = Warnings::default();
        for _ in 0..10 {
            ws.push(w);
        }
        assert_eq!(ws.len(), 8);
        assert_eq!(
            serde_json::to_string(&ws).unwrap().matches("M ≈ 1").count(),
            8
        );
    }
}
