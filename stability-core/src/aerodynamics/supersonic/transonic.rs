//! Issue 11, item 2: where eq (36)'s low-frequency theory holds as M → 1⁺.
//!
//! (36) is linear supersonic theory to first order in frequency: the
//! oscillatory source kernel e^{−iωM²(x−ξ)/(Vβ²)} cos(ωM R/(Vβ²))/R (Miles,
//! *The Potential Theory of Unsteady Supersonic Flow*, 1959, §5.3) is
//! replaced by (1 − iωM²(x − ξ)/(Vβ²))/R. The expansion parameter is the
//! kernel's phase across the wing; over the root chord c₀, with the
//! report's ω̄ = ωc̄/V,
//!
//! κ = ω̄ (c₀/c̄) M²/(M² − 1),
//!
//! the report's "ω̄/(M² − 1) ≪ 1" (§7) made exact (c₀/c̄ = 3/2 for a true
//! delta, M² → 1 at the join). As β → 0 at fixed ω̄, κ grows without bound,
//! and (36)'s acceleration derivatives grow like ln(1/β) (see
//! [`z_wdot_eq36_near_sonic`]): a property of the truncated expansion, not of
//! the flow. Its z_q, m_q and lift slope tend to (37) and are unaffected.
//!
//! **The rule.** (36)'s z_ẇ, m_ẇ are used only where κ ≤ [`LOW_FREQUENCY_LIMIT`];
//! below the Mach number where κ reaches it ([`validity_mach`]) the α̇
//! derivatives come from Mangler's transonic theory (38)–(40) at the same
//! ω̄ — in the faired model. `--damping supersonic`, asked for by name,
//! keeps its own and carries `Warning::LowFrequency` (ω̄/(M² − 1), κ and
//! [`validity_mach`]) at the short period's ω̄, or
//! `Warning::FrequencyUnchecked` ([`largest_omega_bar`]) without one
//! (`damping::low_frequency`). The limit 0.5 comes from the exact two-dimensional oscillatory
//! theory (Garrick & Rubinow, NACA Rep. 846, 1946: the kernel e^{−iλX}J₀(μX),
//! λ = ωM²/(Vβ²), μ = ωM/(Vβ²)), computed for a plate of chord c₀ by
//! `scripts/supersonic_low_frequency.py`: the first-order theory's
//! quadrature (damping) lift is then within 5 %, its pitching moment about
//! mid-chord within 9 %, of the exact values, at every M from 1.05 to 2 —
//! the error is a function of κ alone to within 1 %, growing as κ² (0.2 %
//! at κ = 0.1, 18 % at κ = 1).
//!
//! **The matching point.** Near M = 1, (36)'s
//! z_ẇ ≈ −(πA/4)[1 − ½cot²Λ(6 ln 4 − 6 − 3 ln(β² cot²Λ))] and Mangler's
//! (39)–(40) z_ẇ = −(πA/4)[1 − ½cot²Λ(4.959 − 3 ln(ω̄ cot²Λ))] have the same
//! logarithm, β² in one where ω̄ stands in the other; they are equal where
//! β² = ω̄/2.412 ([`MATCHING_RATIO`], independent of Λ). The two theories
//! are the two ends of one asymptotic expansion (β² ≫ ω̄ and β² ≪ ω̄), and
//! [`matching_mach`] ≤ [`validity_mach`] bound the range the faired model
//! has to bridge.

use super::{SupersonicError, Wing};
use crate::numerics::invalid::Invalid;
use serde::Serialize;
use std::f64::consts::PI;

/// The largest kernel phase κ = ω̄(c₀/c̄)M²/(M² − 1) at which (36)'s
/// acceleration derivatives are used (module doc: 5 % on the damping lift,
/// 9 % on the moment in the exact two-dimensional check).
pub const LOW_FREQUENCY_LIMIT: f64 = 0.5;

/// ω̄/β² at which (36)'s near-sonic z_ẇ equals Mangler's (39)–(40):
/// exp((4.959 − 6 ln 4 + 6)/3) = 2.4119.
pub const MATCHING_RATIO: f64 = 2.411_891_46;

/// The verdict of [`eq36_validity`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LowFrequency {
    /// The report's parameter ω̄/(M² − 1).
    pub nu: f64,
    /// κ = ω̄(c₀/c̄)M²/(M² − 1).
    pub kappa: f64,
    /// [`LOW_FREQUENCY_LIMIT`].
    pub limit: f64,
    /// κ ≤ limit.
    pub valid: bool,
}

fn check(mach: f64, omega_bar: f64) -> Result<(), SupersonicError> {
    if !(omega_bar.is_finite() && omega_bar > 0.0) {
        return Err(SupersonicError::Frequency(omega_bar));
    }
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
    Ok(())
}

/// Whether (36)'s acceleration derivatives hold at Mach `mach` and
/// frequency parameter ω̄ = ωc̄/V for this wing, by the rule of the module
/// doc.
pub fn eq36_validity(
    wing: &Wing,
    mach: f64,
    omega_bar: f64,
) -> Result<LowFrequency, SupersonicError> {
    check(mach, omega_bar)?;
    let b2 = mach * mach - 1.0;
    let kappa = omega_bar / wing.mac() * mach * mach / b2;
    Ok(LowFrequency {
        nu: omega_bar / b2,
        kappa,
        limit: LOW_FREQUENCY_LIMIT,
        valid: kappa <= LOW_FREQUENCY_LIMIT,
    })
}

/// The Mach number above which (36) is valid at ω̄ (κ = limit):
/// M² = κ_max/(κ_max − ω̄c₀/c̄). An error if ω̄c₀/c̄ ≥ κ_max, when no Mach
/// number will do (κ → ω̄c₀/c̄ as M → ∞).
pub fn validity_mach(wing: &Wing, omega_bar: f64) -> Result<f64, SupersonicError> {
    check(2.0, omega_bar)?;
    let scaled = omega_bar / wing.mac();
    if scaled >= LOW_FREQUENCY_LIMIT {
        return Err(SupersonicError::FrequencyTooHigh {
            scaled,
            limit: LOW_FREQUENCY_LIMIT,
        });
    }
    Ok((LOW_FREQUENCY_LIMIT / (LOW_FREQUENCY_LIMIT - scaled)).sqrt())
}

/// The largest ω̄ at which (36) is valid at Mach `mach` (κ = limit):
/// ω̄ = κ_max (c̄/c₀)(M² − 1)/M²; 0 at and below M = 1.
pub fn largest_omega_bar(wing: &Wing, mach: f64) -> f64 {
    let b2 = (mach * mach - 1.0).max(0.0);
    LOW_FREQUENCY_LIMIT * wing.mac() * b2 / (mach * mach)
}

/// The Mach number where (36)'s near-sonic z_ẇ equals Mangler's at ω̄:
/// M = √(1 + ω̄/[`MATCHING_RATIO`]).
pub fn matching_mach(omega_bar: f64) -> Result<f64, SupersonicError> {
    check(2.0, omega_bar)?;
    Ok((1.0 + omega_bar / MATCHING_RATIO).sqrt())
}

/// (36)'s z_ẇ to leading order as M → 1⁺ (E = 1 + O(k′² ln k′),
/// 1 − H = k′²(ln(4/k′) − 1) + o(k′²), k′ = β cot Λ):
/// z_ẇ ≈ −(πA/4)[1 − 3cot²Λ(ln(4/(β cot Λ)) − 1)] — growing like ln(1/β).
pub fn z_wdot_eq36_near_sonic(wing: &Wing, mach: f64) -> f64 {
    let cot = wing.cot();
    let kp = (mach * mach - 1.0).sqrt() * cot;
    -PI * wing.aspect_ratio() / 4.0 * (1.0 - 3.0 * cot * cot * ((4.0 / kp).ln() - 1.0))
}
