//! `sweep` with a physical flight condition ([`crate::config::physical`]):
//! μ₁, i_B and C_L·M² follow from it and each point's planform (its area
//! and M.A.C.; the grid keeps the root chord, so they change with the
//! sweep angle), V = M·a, C_L and τ from each point's Mach number — at a
//! fixed altitude and weight C_L·M² is constant (eq 24), so C_L ∝ 1/M²
//! and τ ∝ 1/M. The rows then carry the columns [`COLUMNS`] too, the
//! modes in seconds.

use crate::config::physical::Physical;
use stability_core::analysis::Analysis;
use stability_core::case::Case;
use stability_core::flight::PhysicalFlight;
use stability_core::geometry::Planform;

/// The columns a physical flight condition adds, after the results.
pub const COLUMNS: [&str; 9] = [
    "v_m_s",
    "c_l",
    "tau_s",
    "sp_re_s",
    "sp_im_s",
    "sp_natural_frequency_rad_s",
    "sp_period_s",
    "ph_re_s",
    "ph_im_s",
];

/// The physical flight condition of each of the grid's planforms.
pub struct PhysicalAxis {
    flights: Vec<PhysicalFlight>,
    /// μ₁ and i_B of each planform, as written in the rows.
    text: Vec<[Box<str>; 2]>,
}

impl PhysicalAxis {
    /// The condition with each planform; `mu1` and `ib` ranges are refused
    /// (the condition fixes μ₁ and i_B).
    pub fn new(
        physical: &Physical,
        planforms: &[Planform],
        ranges: [(&str, bool); 2],
    ) -> Result<PhysicalAxis, String> {
        for (flag, given) in ranges {
            if given {
                return Err(format!(
                    "--{flag}: the config's flight condition is physical (mass, I_y, altitude…), which fixes μ₁ and i_B; vary the config's mass, I_y or altitude instead, or give mu1, i_b and cl_m2 in [flight]"
                ));
            }
        }
        let mut num = zmij::Buffer::new();
        let mut flights = Vec::with_capacity(planforms.len());
        let mut text = Vec::with_capacity(planforms.len());
        for p in planforms {
            let f = physical
                .with_planform(p)
                .map_err(|e| format!("at a sweep of {}°: {e}", p.sweep_le.to_degrees()))?;
            text.push([num.format(f.mu1()).into(), num.format(f.i_b()).into()]);
            flights.push(f);
        }
        Ok(PhysicalAxis { flights, text })
    }

    /// Puts planform `k`'s μ₁, i_B and C_L·M² into `case`.
    pub fn apply(&self, k: usize, case: &mut Case) {
        self.flights[k].apply(case);
    }

    /// Planform `k`'s μ₁ and i_B as written.
    pub fn text(&self, k: usize) -> [&str; 2] {
        [&self.text[k][0], &self.text[k][1]]
    }

    /// The [`COLUMNS`] of a point on planform `k` at Mach `mach`.
    pub fn seconds(&self, k: usize, mach: f64, a: &Analysis) -> [Option<f64>; 9] {
        let Ok(p) = self.flights[k].at_mach(mach) else {
            return [None; 9];
        };
        let t = p.tau;
        let sp = a.modes.short_period();
        let ph = a.modes.phugoid();
        [
            Some(p.speed),
            Some(p.c_l),
            Some(t),
            sp.map(|m| m.re / t),
            sp.map(|m| m.im / t),
            sp.map(|m| m.natural_frequency / t),
            sp.and_then(|m| m.period).map(|x| x * t),
            ph.map(|m| m.re / t),
            ph.map(|m| m.im / t),
        ]
    }
}
