//! §10: the effect of taper on the damping in pitch (Fig 36): the 45°
//! delta with its tips cropped to taper 1/7, the c.g. held in place.

use super::regimes::{self, Basis};
use super::study::{across, curve, mach_fig};
use super::{Plate, Study};
use stability_core::design::case::Case;
use stability_core::geometry::{Planform, Size, cropped_h};
use stability_core::numerics::display::sig;

/// The cropped wing's taper ratio.
const TAPER: f64 = 1.0 / 7.0;

pub fn plates(study: &Study) -> Vec<Plate> {
    let sweep = 45f64.to_radians();
    let (Ok(h_crop), Ok(cropped)) = (
        cropped_h(0.25, sweep, TAPER),
        Planform::new(sweep, TAPER, Size::RootChord(10.0)),
    ) else {
        return Vec::new();
    };
    let rs = across(45.0, &study.ms, |c| Case {
        planform: cropped,
        h: h_crop,
        ..c
    });
    let m_thetadot =
        |r: &stability_core::design::case::CaseResult| Some(-r.damping.derivatives.m_thetadot());
    let fig = mach_fig(
        "36",
        "Effect of taper on the damping in pitch derivative m_θ̇",
        "−m_θ̇",
    )
    .with(curve(
        "45° true delta, h = 0.25",
        &study.ms,
        &study.results[0],
        m_thetadot,
    ))
    .with(curve(
        &format!(
            "tips cropped to taper 1/7, same c.g. (h = {})",
            sig(h_crop, 3)
        ),
        &study.ms,
        &rs,
        m_thetadot,
    ));
    vec![Plate::new(
        regimes::faired(fig, study, &[45.0], Basis::Both),
        "§10: cropping the tips acts like a shift of axis. The theories are the cropped wing's own — the lattice to M = 0.9, linear supersonic theory from M = 1.2 (with subsonic leading edges the true delta's potentials less the tips' corrections, supersonic::subsonic_edge) — but for Mangler's at M = 1, a true-delta theory taken at the cropped wing's aspect ratio.",
    )]
}
