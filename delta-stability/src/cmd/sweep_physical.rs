//! `sweep` with a physical flight condition ([`crate::config::physical`]):
//! the library's sweep ([`stability_core::sweep::Sweep::with_flight`]) gives
//! each planform its μ₁, i_B and C_L·M² (from its area and M.A.C.; the grid
//! keeps the root chord, so they change with the sweep angle) and each
//! point V = M·a, C_L and τ — at a fixed altitude and weight C_L·M² is
//! constant (eq 24), so C_L ∝ 1/M² and τ ∝ 1/M. The rows then carry the
//! columns [`COLUMNS`] too, the modes in seconds.

use stability_core::flight::FlightPoint;
use stability_core::sweep::{Points, Sweep};

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

/// A physical point's [`COLUMNS`] (`None` where undefined).
pub type Seconds = [Option<f64>; COLUMNS.len()];

/// μ₁ and i_B of each of the grid's planforms, as written in the rows.
pub struct PhysicalAxis {
    text: Vec<[Box<str>; 2]>,
}

impl PhysicalAxis {
    /// The text of the sweep's flight conditions (`None`: the sweep has
    /// none).
    pub fn of(sweep: &Sweep) -> Option<PhysicalAxis> {
        let mut num = zmij::Buffer::new();
        let text = sweep
            .flights()?
            .iter()
            .map(|f| [num.format(f.mu1()).into(), num.format(f.i_b()).into()])
            .collect();
        Some(PhysicalAxis { text })
    }

    /// Planform `k`'s μ₁ and i_B as written.
    pub fn text(&self, k: usize) -> [&str; 2] {
        [&self.text[k][0], &self.text[k][1]]
    }
}

/// Why `--mu1` or `--ib` cannot be given with a physical flight condition.
pub fn refuse_ranges(ranges: [(&str, bool); 2]) -> Result<(), String> {
    for (flag, given) in ranges {
        if given {
            return Err(format!(
                "--{flag}: the config's flight condition is physical (mass, I_y, altitude…), which fixes μ₁ and i_B; vary the config's mass, I_y or altitude instead, or give mu1, i_b and cl_m2 in [flight]"
            ));
        }
    }
    Ok(())
}

/// The [`COLUMNS`] of point `k` of `points`, at the flight point `p`.
pub fn seconds(p: Option<FlightPoint>, points: &Points, k: usize) -> Seconds {
    let Some(p) = p else {
        return [None; COLUMNS.len()];
    };
    let t = p.tau;
    let some = |v: f64| v.is_finite().then_some(v);
    let (sp_re, sp_im) = (points.sp_re[k], points.sp_im[k]);
    [
        Some(p.speed),
        Some(p.c_l),
        Some(t),
        some(sp_re / t),
        some(sp_im / t),
        some(sp_re.hypot(sp_im) / t),
        some(2.0 * std::f64::consts::PI / sp_im * t),
        some(points.ph_re[k] / t),
        some(points.ph_im[k] / t),
    ]
}
