//! Each part's share of a design point's derivatives (`analyze --json`'s
//! `configuration` object): the wing's from the case's own models, the
//! surfaces' and the body's from the configuration's increment
//! ([`crate::aerodynamics::models::increment`]), about the case's c.g.; they sum to the totals
//! the design point uses before the user's derivative tables.

use crate::aerodynamics::lifting_surface::LiftingSurfaceError;
use crate::aerodynamics::models::aero::Coefficients;
use crate::aerodynamics::models::increment::Increment;
use crate::derivatives::DampingDerivatives;
use crate::geometry::configuration::Part;
use serde::Serialize;

/// One part's share.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PartShare {
    pub part: Part,
    /// Its lift slope (per radian, on the wing's S).
    pub lift_slope: f64,
    /// Its term of the aerodynamic centre H₀ = Σ(−μ_α)/a (the wing's:
    /// H₀,w a_w/a); the terms sum to H₀.
    pub aerodynamic_centre: f64,
    pub z_q: f64,
    pub m_q: f64,
    pub z_wdot: f64,
    pub m_wdot: f64,
}

/// The parts' shares and their totals.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Shares {
    pub parts: Vec<PartShare>,
    pub lift_slope: f64,
    pub aerodynamic_centre: f64,
    /// H₀ less the wing's own H₀,w: the aerodynamic centre's shift aft.
    pub aerodynamic_centre_shift: f64,
    pub z_q: f64,
    pub m_q: f64,
    pub z_wdot: f64,
    pub m_wdot: f64,
}

impl Shares {
    /// The shares at c.g. `h`: the wing's coefficients `wing` and damping
    /// `wing_damping`, the increment's in-phase parts from `steady` (ω̄ = 0)
    /// and its damping parts from `at_omega` (the run's ω̄).
    pub fn new(
        wing: &Coefficients,
        wing_damping: &DampingDerivatives,
        steady: &Increment,
        at_omega: &Increment,
        h: f64,
    ) -> Result<Shares, LiftingSurfaceError> {
        let a = wing.lift_slope.value + steady.solution.lift_alpha;
        let h0w = wing.aerodynamic_centre.value;
        let mut parts = vec![PartShare {
            part: Part::Wing,
            lift_slope: wing.lift_slope.value,
            aerodynamic_centre: h0w * wing.lift_slope.value / a,
            z_q: wing_damping.z_q,
            m_q: wing_damping.m_q,
            z_wdot: wing_damping.z_wdot,
            m_wdot: wing_damping.m_wdot,
        }];
        for (s, o) in steady.parts.iter().zip(&at_omega.parts) {
            let d = o.solution.derivatives(h, 0.0)?;
            let share = PartShare {
                part: s.part,
                lift_slope: s.solution.lift_alpha,
                aerodynamic_centre: -s.solution.moment_alpha / a,
                z_q: d.z_q,
                m_q: d.m_q,
                z_wdot: d.z_wdot,
                m_wdot: d.m_wdot,
            };
            // interference on the wing is the wing's share
            match parts.iter_mut().find(|p| p.part == s.part) {
                Some(p) => add(p, &share),
                None => parts.push(share),
            }
        }
        let sum = |f: fn(&PartShare) -> f64| parts.iter().map(f).sum::<f64>();
        let h0 = sum(|p| p.aerodynamic_centre);
        Ok(Shares {
            lift_slope: sum(|p| p.lift_slope),
            aerodynamic_centre: h0,
            aerodynamic_centre_shift: h0 - h0w,
            z_q: sum(|p| p.z_q),
            m_q: sum(|p| p.m_q),
            z_wdot: sum(|p| p.z_wdot),
            m_wdot: sum(|p| p.m_wdot),
            parts,
        })
    }
}

fn add(p: &mut PartShare, s: &PartShare) {
    p.lift_slope += s.lift_slope;
    p.aerodynamic_centre += s.aerodynamic_centre;
    p.z_q += s.z_q;
    p.m_q += s.m_q;
    p.z_wdot += s.z_wdot;
    p.m_wdot += s.m_wdot;
}
