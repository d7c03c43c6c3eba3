//! §11: responses of the 45° delta to an elevon step: the report's
//! two-degree-of-freedom solution (Fig 37) and the exact response with and
//! without z_q, z_ẇ (Fig 38).

use super::{Plate, Study};
use stability_core::design::study::{grid, report_wing};
use stability_core::dynamics::response::{Input, Simplifications, StateSpace, TwoDof};
use stability_io::plot::{Figure, Series};

pub fn plates(_study: &Study) -> Vec<Plate> {
    vec![fig37(), fig38()]
}

fn fig37() -> Plate {
    let ts = grid(0.0, 2.0, 0.005);
    let mut f = Figure::new(
        "37",
        "Effect of Mach number on response (45° delta, two degrees of freedom)",
        "t̂ = t/τ",
        "ŵ/m₀ (eqs 44–45)",
    );
    for m in [0.8, 1.0, 1.2, 1.6] {
        if let Some(r) = super::study::eval(&report_wing(45.0, m)) {
            let two = TwoDof::of(&r.derivatives);
            f = f.with(Series::new(
                format!("M = {m}"),
                ts.iter().map(|&t| (t, two.w(t, 1.0))).collect(),
            ));
        }
    }
    Plate::new(
        f,
        "The report's two-degree-of-freedom solution of eq (44) (eq 45 as recovered) after an elevon step m₀.",
    )
}

fn fig38() -> Plate {
    let mut f = Figure::new(
        "38",
        "Effect of neglecting the damping in lift derivatives z_q, z_ẇ (45° delta, M = 1.2)",
        "t̂ = t/τ",
        "ŵ/m₀",
    );
    let step = Input::Step {
        x0: 0.0,
        z0: 0.0,
        m0: 1.0,
    };
    if let Some(r) = super::study::eval(&report_wing(45.0, 1.2)) {
        for (name, neglect) in [("with z_q, z_ẇ", false), ("z_q = z_ẇ = 0", true)] {
            let simp = Simplifications {
                neglect_zq_zwdot: neglect,
                neglect_u: true,
            };
            if let Ok(ss) = StateSpace::new(&r.derivatives, simp)
                && let Ok(s) = ss.simulate(step, 2.0, 400)
            {
                f = f.with(Series::new(
                    name,
                    s.samples.iter().map(|x| (x.t, x.w)).collect(),
                ));
            }
        }
    }
    Plate::new(
        f,
        "Exact solution of the state-space form (matrix exponential), û held at zero.",
    )
}
