//! The modes in seconds, as MATLAB's and python-control's `damp()` list
//! them: each eigenvalue λ = r ± is (1/s) with its damping ratio
//! ζ = −r/|λ|, undamped natural frequency ωₙ = |λ| (rad/s), period 2π/s
//! (s), time to half amplitude ln 2/(−r) or to double ln 2/r (s) and
//! cycles to half (or double) amplitude (eq 8) — the quantities of
//! [`crate::dynamics::modes`], for roots in 1/s.
//!
//! A derivative set in the report's notation gives its roots in 1/τ;
//! [`Damp::of_tau`] divides them by τ (s). A dimensional set (per unit
//! mass, in seconds) gives them directly ([`Damp::of_roots`]).

use crate::dynamics::modes::{Mode, ModeName, Modes, Origin};
use num_complex::Complex64;
use serde::{Serialize, Serializer};

/// The modes of four roots in 1/s, fastest first.
#[derive(Debug, Clone, PartialEq)]
pub struct Damp(pub Modes);

impl Damp {
    /// The modes of four roots in 1/s (conjugates in pairs, any order).
    pub fn of_roots(roots_per_s: &[Complex64; 4]) -> Damp {
        // μ₁ = 0: the frequency parameter ω̄ = s/μ₁ is left undefined (a
        // table in seconds has no use for it)
        Damp(Modes::identify(roots_per_s, 0.0))
    }

    /// The modes of four roots in 1/τ, with τ in seconds.
    pub fn of_tau(roots: &[Complex64; 4], tau: f64) -> Damp {
        Damp::of_roots(&roots.map(|z| z / tau))
    }

    /// The modes, fastest first (times in s, rates in 1/s and rad/s).
    pub fn modes(&self) -> &[Mode] {
        self.0.as_slice()
    }
}

/// One row of the table, as the JSON's `damp` list carries it.
#[derive(Serialize)]
struct Row {
    mode: ModeName,
    origin: Option<Origin>,
    re_s: f64,
    im_s: f64,
    damping_ratio: Option<f64>,
    natural_frequency_rad_s: f64,
    period_s: Option<f64>,
    time_to_half_s: Option<f64>,
    time_to_double_s: Option<f64>,
    cycles_to_half: Option<f64>,
    cycles_to_double: Option<f64>,
}

impl Serialize for Damp {
    /// As a list of `{mode, origin, re_s, im_s, damping_ratio,
    /// natural_frequency_rad_s, period_s, time_to_half_s,
    /// time_to_double_s, cycles_to_half, cycles_to_double}`.
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(self.modes().iter().map(|m| Row {
            mode: m.name,
            origin: m.origin,
            re_s: m.re,
            im_s: m.im,
            damping_ratio: m.damping_ratio,
            natural_frequency_rad_s: m.natural_frequency,
            period_s: m.period,
            time_to_half_s: m.time_to_half,
            time_to_double_s: m.time_to_double,
            cycles_to_half: m.cycles_to_half,
            cycles_to_double: m.cycles_to_double,
        }))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::{LN_2, PI};

    #[test]
    fn a_pair_in_seconds_by_hand() {
        // λ = (−0.5 ± 4i)/τ with τ = 2 s: r = −0.25/s, s = 2 rad/s;
        // period π s, t½ = ln 2/0.25 s, ωₙ = √(0.0625 + 4) rad/s,
        // ζ = 0.25/ωₙ, cycles = t½/period.
        let c = |re, im| Complex64::new(re, im);
        let roots = [c(-0.5, 4.0), c(-0.5, -4.0), c(-0.01, 0.1), c(-0.01, -0.1)];
        let d = Damp::of_tau(&roots, 2.0);
        let sp = &d.modes()[0];
        let wn = 4.0625f64.sqrt();
        assert_eq!(sp.name, ModeName::ShortPeriod);
        assert!((sp.period.unwrap() - PI).abs() < 1e-15);
        assert!((sp.time_to_half.unwrap() - LN_2 / 0.25).abs() < 1e-14);
        assert!((sp.natural_frequency - wn).abs() < 1e-15);
        assert!((sp.damping_ratio.unwrap() - 0.25 / wn).abs() < 1e-15);
        assert!((sp.cycles_to_half.unwrap() - LN_2 / 0.25 / PI).abs() < 1e-14);
        assert_eq!(sp.frequency_parameter, None);
    }
}
