//! What a configuration adds to its wing: the increment
//! ΔSolution = (configuration total − wing alone) by one method at one
//! (M, ω̄), which the design-point pipeline adds to the wing's own model
//! (`crate::design::case`, `crate::aerodynamics::models::aero`) so that every wing theory keeps its
//! wing and gains the surfaces and the body.
//!
//! The method by Mach number, the bands of the faired model
//! ([`crate::aerodynamics::models::faired`]):
//!
//! | Mach number | the increment |
//! | --- | --- |
//! | M ≤ 0.9 | the multi-surface doublet lattice ([`Configuration::solve_subsonic`]) |
//! | 0.9 < M < 1.2 | faired: each number the monotone cubic (Fritsch–Carlson slopes, `aero::monotone_slopes`) through the lattice's value at 0.9 (slope: backward difference over 0.02) and the supersonic theory's at 1.2 (slope: central difference over 10⁻⁴) — the faired model's stated join |
//! | M ≥ 1.2 | the supersonic theory ([`Configuration::solve_supersonic`]) |
//!
//! The Mach derivatives of the increment's lift slope and moment (for
//! eqs 25–29) are the fairing's own in the band, else central differences
//! over [`MACH_STEP`]: the surfaces' Mach derivatives are included.

use crate::aerodynamics::lifting_surface::configuration::ConfigurationError;
use crate::aerodynamics::lifting_surface::{ConfigurationSolution, Contribution};
use crate::aerodynamics::lifting_surface::{Harmonic, Solution, store};
use crate::aerodynamics::models::faired::{
    LATTICE_SLOPE_STEP, LIFTING_SURFACE_LIMIT, SUPERSONIC_FROM, SUPERSONIC_SLOPE_STEP,
};
use crate::geometry::configuration::{Configuration, Part};
use crate::numerics::interpolation::{hermite, monotone_slopes};
use serde::Serialize;

/// The step of the increment's Mach derivatives outside the band.
pub const MACH_STEP: f64 = 1e-3;

/// A configuration's increment over its wing at one (M, ω̄).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Increment {
    /// Total less the wing alone.
    pub solution: Solution,
    /// Each added part's share (the wing's own share of the total, less the
    /// wing alone, as `Part::Wing` when the method gives one: the
    /// surfaces' interference on the wing). They sum to `solution`.
    pub parts: Vec<Contribution>,
    /// d ℓ_α/dM and d μ_α/dM of `solution` (`None` from
    /// [`Configuration::increment_at`], which does not compute them).
    pub d_lift_alpha: Option<f64>,
    pub d_moment_alpha: Option<f64>,
}

/// The six numbers of a [`Solution`].
fn numbers(s: &Solution) -> [f64; 6] {
    [
        s.lift_alpha,
        s.moment_alpha,
        s.lift_alphadot,
        s.moment_alphadot,
        s.lift_q,
        s.moment_q,
    ]
}

fn from_numbers(n: [f64; 6], mach: f64, omega_bar: f64) -> Solution {
    Solution {
        mach,
        omega_bar,
        lift_alpha: n[0],
        moment_alpha: n[1],
        lift_alphadot: n[2],
        moment_alphadot: n[3],
        lift_q: n[4],
        moment_q: n[5],
    }
}

/// a − b, number by number.
fn minus(a: &Solution, b: &Solution) -> Solution {
    let (x, y) = (numbers(a), numbers(b));
    from_numbers(std::array::from_fn(|i| x[i] - y[i]), a.mach, a.omega_bar)
}

/// The increment's parts: every part but the wing as it is, the wing's
/// share less the wing alone where it differs (interference).
fn parts_less_wing(config: &ConfigurationSolution, alone: &Solution) -> Vec<Contribution> {
    let mut out = Vec::new();
    for c in &config.parts {
        if c.part == Part::Wing {
            let d = minus(&c.solution, alone);
            if numbers(&d).iter().any(|v| *v != 0.0) {
                out.push(Contribution {
                    part: Part::Wing,
                    solution: d,
                });
            }
        } else {
            out.push(*c);
        }
    }
    out
}

impl Configuration {
    /// Whether anything is added to the wing.
    pub fn has_additions(&self) -> bool {
        self.tailplane.is_some() || self.foreplane.is_some() || self.body.is_some()
    }

    /// The configuration and its wing alone by one method (no fairing):
    /// the supersonic theory, or the lattice.
    fn by_method(
        &self,
        mach: f64,
        omega_bar: f64,
        supersonic: bool,
        harmonic: Harmonic,
    ) -> Result<(Solution, Vec<Contribution>), ConfigurationError> {
        let alone = Configuration::wing_alone(self.wing);
        let (with, without) = if supersonic {
            (
                self.solve_supersonic(mach, omega_bar)?,
                alone.solve_supersonic(mach, omega_bar)?,
            )
        } else {
            (
                self.solve_subsonic_with(mach, omega_bar, harmonic)?,
                alone.solve_subsonic_with(mach, omega_bar, harmonic)?,
            )
        };
        let parts = parts_less_wing(&with, &without.total);
        Ok((minus(&with.total, &without.total), parts))
    }

    /// The increment at (M, ω̄) by the table's methods, with its parts and
    /// the Mach derivatives of its in-phase numbers.
    pub fn increment(&self, mach: f64, omega_bar: f64) -> Result<Increment, ConfigurationError> {
        self.increment_with(mach, omega_bar, true, Harmonic::Direct)
    }

    /// As [`Configuration::increment`] without the Mach derivatives outside
    /// the faired band (a third of the solves): the damping's, at each ω̄ of
    /// a frequency iteration.
    pub fn increment_at(&self, mach: f64, omega_bar: f64) -> Result<Increment, ConfigurationError> {
        self.increment_with(mach, omega_bar, false, Harmonic::Direct)
    }

    /// As [`Configuration::increment_at`], the lattice's harmonic solutions
    /// had as `harmonic` says ([`Harmonic::Interpolated`]: a sweep's or a
    /// sizing's frequency iterations, which share the nodes).
    pub fn increment_at_with(
        &self,
        mach: f64,
        omega_bar: f64,
        harmonic: Harmonic,
    ) -> Result<Increment, ConfigurationError> {
        self.increment_with(mach, omega_bar, false, harmonic)
    }

    fn increment_with(
        &self,
        mach: f64,
        omega_bar: f64,
        mach_derivatives: bool,
        harmonic: Harmonic,
    ) -> Result<Increment, ConfigurationError> {
        if !mach.is_finite() || mach < 0.0 {
            return Err(ConfigurationError::Geometry(format!(
                "the Mach number must be finite and ≥ 0, not {mach}"
            )));
        }
        if mach > LIFTING_SURFACE_LIMIT && mach < SUPERSONIC_FROM {
            return self.faired(mach, omega_bar, harmonic);
        }
        let sup = mach >= SUPERSONIC_FROM;
        let (solution, parts) = self.by_method(mach, omega_bar, sup, harmonic)?;
        if !mach_derivatives {
            return Ok(Increment {
                solution,
                parts,
                d_lift_alpha: None,
                d_moment_alpha: None,
            });
        }
        let h = MACH_STEP.min(mach);
        let lo = self.by_method(mach - h, omega_bar, sup, harmonic)?.0;
        let hi = self
            .by_method(mach + MACH_STEP, omega_bar, sup, harmonic)?
            .0;
        let w = h + MACH_STEP;
        Ok(Increment {
            d_lift_alpha: Some((hi.lift_alpha - lo.lift_alpha) / w),
            d_moment_alpha: Some((hi.moment_alpha - lo.moment_alpha) / w),
            solution,
            parts,
        })
    }

    /// The faired band: each part's every number the monotone cubic
    /// between the lattice at 0.9 and the supersonic theory at 1.2, with
    /// the ends' slopes; the increment is their sum (so the parts sum to
    /// it, and its Mach derivative is theirs).
    fn faired(
        &self,
        mach: f64,
        omega_bar: f64,
        harmonic: Harmonic,
    ) -> Result<Increment, ConfigurationError> {
        let (m0, m1, st) = (
            LIFTING_SURFACE_LIMIT,
            SUPERSONIC_FROM,
            SUPERSONIC_SLOPE_STEP,
        );
        let ends = [
            self.by_method(m0, omega_bar, false, harmonic)?.1,
            self.by_method(m0 - LATTICE_SLOPE_STEP, omega_bar, false, harmonic)?
                .1,
            self.by_method(m1, omega_bar, true, harmonic)?.1,
            self.by_method(m1 - st, omega_bar, true, harmonic)?.1,
            self.by_method(m1 + st, omega_bar, true, harmonic)?.1,
        ];
        let of = |i: usize, part: Part| {
            ends[i]
                .iter()
                .find(|c| c.part == part)
                .map_or([0.0; 6], |c| numbers(&c.solution))
        };
        let mut order: Vec<Part> = Vec::new();
        for c in ends[0].iter().chain(ends[2].iter()) {
            if !order.contains(&c.part) {
                order.push(c.part);
            }
        }
        let mut parts = Vec::new();
        let (mut total, mut d) = ([0.0; 6], [0.0; 2]);
        for part in order {
            let (y0, b0, y1, c1, a1) = (
                of(0, part),
                of(1, part),
                of(2, part),
                of(3, part),
                of(4, part),
            );
            let v: [crate::numerics::interpolation::Value; 6] = std::array::from_fn(|i| {
                let s0 = (y0[i] - b0[i]) / LATTICE_SLOPE_STEP;
                let s1 = (a1[i] - c1[i]) / (2.0 * st);
                let (e0, e1) = monotone_slopes((y1[i] - y0[i]) / (m1 - m0), s0, s1);
                hermite((m0, y0[i], e0), (m1, y1[i], e1), mach)
            });
            for i in 0..6 {
                total[i] += v[i].value;
            }
            d[0] += v[0].d_mach;
            d[1] += v[1].d_mach;
            parts.push(Contribution {
                part,
                solution: from_numbers(v.map(|x| x.value), mach, omega_bar),
            });
        }
        Ok(Increment {
            solution: from_numbers(total, mach, omega_bar),
            parts,
            d_lift_alpha: Some(d[0]),
            d_moment_alpha: Some(d[1]),
        })
    }
}

impl Configuration {
    /// The configuration's response at M < 1 and ω̄ (0: quasi-steady), from
    /// the store ([`store::configuration`]): one solve of the multi-surface
    /// lattice per (configuration, M, ω̄). The lattice
    /// holds the lifting surfaces; a [`crate::geometry::configuration::Body`] is added as its own
    /// part by slender-body theory, eq (43) (`aerodynamics::body`), as
    /// in the supersonic theory.
    pub fn solve_subsonic(
        &self,
        mach: f64,
        omega_bar: f64,
    ) -> Result<ConfigurationSolution, ConfigurationError> {
        self.solve_subsonic_with(mach, omega_bar, Harmonic::Direct)
    }

    /// As [`Configuration::solve_subsonic`], the harmonic solution had as
    /// `harmonic` says ([`store::configuration`]).
    pub fn solve_subsonic_with(
        &self,
        mach: f64,
        omega_bar: f64,
        harmonic: Harmonic,
    ) -> Result<ConfigurationSolution, ConfigurationError> {
        let mut solution = store::configuration(self, mach, omega_bar, harmonic)?;
        if let Some(body) = &self.body {
            let b = body.solution(&self.wing, mach, omega_bar);
            let t = &mut solution.total;
            t.lift_alpha += b.lift_alpha;
            t.moment_alpha += b.moment_alpha;
            t.lift_alphadot += b.lift_alphadot;
            t.moment_alphadot += b.moment_alphadot;
            t.lift_q += b.lift_q;
            t.moment_q += b.moment_q;
            solution.parts.push(Contribution {
                part: Part::Body,
                solution: b,
            });
        }
        Ok(solution)
    }
}
