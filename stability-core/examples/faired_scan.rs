//! scratch: the faired model across Mach for the note's wings
use stability_core::case::{DampingModel, evaluate_harmonic};
use stability_core::lifting_surface::Harmonic;
use stability_core::study::report_wing;
use std::time::Instant;
fn main() {
    let t = Instant::now();
    for deg in [45.0, 60.0] {
        for m in [
            0.5, 0.7, 0.8, 0.85, 0.9, 0.93, 0.95, 0.97, 0.99, 1.0, 1.02, 1.05, 1.1, 1.15, 1.2, 1.3,
            1.4, 1.5, 1.6, 2.0,
        ] {
            let mut c = report_wing(deg, m);
            c.damping = DampingModel::Faired;
            match evaluate_harmonic(&c, Harmonic::Interpolated) {
                Ok(r) => {
                    let d = r.derivatives;
                    let sp = r.analysis.modes.short_period();
                    println!(
                        "{deg} M={m:.2} a={:.3} H0={:.3} zq={:.3} zwd={:.3} mq={:.3} mwd={:.3} mth={:.3} mw={:.3} wbar={:?} cyc={:?} verdict={:?} re={:?}",
                        r.coefficients.lift_slope.value,
                        r.coefficients.aerodynamic_centre.value,
                        d.z_q,
                        d.z_wdot,
                        d.m_q,
                        d.m_wdot,
                        d.m_q + d.m_wdot,
                        d.m_w,
                        r.frequency.map(|f| (f.converged, f.converged_ok)),
                        sp.and_then(|s| s.cycles_to_half),
                        r.analysis.verdict,
                        sp.map(|s| (s.re, s.im))
                    );
                }
                Err(e) => println!("{deg} M={m}: {e}"),
            }
        }
    }
    eprintln!("{:?}", t.elapsed());
}
