//! §8: the one-cycle damping standard's margin Δm_θ̇ (eq 41) across sweep
//! (Fig 25), μ₁ and c.g. position (Fig 26).

use super::regimes::{self, Basis};
use super::study::{across, curve, label, mach_fig};
use super::{Plate, Study};
use stability_core::design::case::{Case, CaseResult};

/// Eq (41)'s margin Δm_θ̇ = m_θ̇max − m_θ̇.
pub fn margin(r: &CaseResult) -> Option<f64> {
    r.analysis.damping_standard.margin
}

/// The sweeps of Fig 25.
pub const SWEEPS: [f64; 4] = [30.0, 45.0, 60.0, 75.0];
/// The relative densities of Fig 26, on the delta of this sweep …
pub const MU1S: [f64; 4] = [50.0, 100.0, 200.0, 400.0];
pub const MU1S_WING: f64 = 60.0;
/// … and its c.g. positions, on the delta of this sweep.
pub const CGS: [f64; 2] = [0.15, 0.35];
pub const CGS_WING: f64 = 45.0;

pub fn plates(study: &Study) -> Vec<Plate> {
    let ms = &study.ms;
    let mut f25 = mach_fig(
        "25",
        "Ability to damp the short period to half amplitude in one cycle: sweep",
        "Δm_θ̇ = m_θ̇max − m_θ̇ (eq 41)",
    );
    for deg in SWEEPS {
        f25 = f25.with(curve(&label(deg), ms, &across(deg, ms, |c| c), margin));
    }
    f25.reference_lines.push((0.0, "standard met above".into()));
    let mut f26 = mach_fig(
        "26",
        "Ability to damp to half amplitude in one cycle: μ₁ and c.g. position",
        "Δm_θ̇ (eq 41)",
    );
    for mu1 in MU1S {
        let rs = across(MU1S_WING, ms, |c| Case { mu1, ..c });
        f26 = f26.with(curve(&format!("{MU1S_WING}°, μ₁ = {mu1}"), ms, &rs, margin));
    }
    for h in CGS {
        let rs = across(CGS_WING, ms, |c| Case { h, ..c });
        f26 = f26.with(curve(&format!("{CGS_WING}°, h = {h}"), ms, &rs, margin));
    }
    f26.reference_lines.push((0.0, "standard met above".into()));
    let f25 = regimes::faired(f25, study, &SWEEPS, Basis::Both);
    let f26 = regimes::faired(f26, study, &[MU1S_WING, CGS_WING], Basis::Both);
    vec![
        Plate::new(
            f25,
            "Δm_θ̇ > 0: the §8 approximation says the short period halves within one cycle. h = 0.25, μ₁ = 50.",
        ),
        Plate::new(
            f26,
            "The 60° delta at four relative densities, the 45° delta at two c.g. positions; §8's statements on them are among the conclusions.",
        ),
    ]
}
