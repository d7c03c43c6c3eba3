//! `delta-stability response FILE --input step|initial --until T`: the
//! longitudinal response (§11), solved exactly.

use crate::Failure;
use crate::diag::InputError;
use crate::fmt::sig;
use crate::input;
use crate::output::atomic_write;
use crate::plot::{Figure, Series, num};
use stability_core::response::{Input, Simplifications, StateSpace, TwoDof};
use std::fmt::Write;
use std::path::Path;

/// The options of the command.
pub struct Options {
    pub file: String,
    pub input: String,
    pub until: f64,
    pub steps: usize,
    pub m0: f64,
    pub w0: f64,
    pub neglect_zq_zwdot: bool,
    pub neglect_u: bool,
    pub csv: Option<String>,
    pub svg: Option<String>,
}

pub fn run(o: &Options) -> Result<(), Failure> {
    let file = input::read(&o.file)?;
    for w in &file.warnings {
        eprintln!("warning: {w}");
    }
    let bad = |m: String| Failure::Input(InputError::file(&o.file, m));
    let input = match o.input.as_str() {
        "step" => Input::Step {
            x0: 0.0,
            z0: 0.0,
            m0: o.m0,
        },
        "initial" => Input::Initial {
            u: 0.0,
            w: o.w0,
            q: 0.0,
            theta: 0.0,
        },
        other => {
            return Err(bad(format!(
                "--input must be `step` or `initial`, not `{other}`"
            )));
        }
    };
    let simp = Simplifications {
        neglect_zq_zwdot: o.neglect_zq_zwdot,
        neglect_u: o.neglect_u,
    };
    let ss = StateSpace::new(&file.derivatives, simp).map_err(|e| bad(e.to_string()))?;
    let samples = ss
        .simulate(input, o.until, o.steps)
        .map_err(|e| bad(e.to_string()))?
        .samples;
    let tau = file.dimensional.map(|d| d.tau());
    // The report's closed form, eq (45), for the step (from the 2-DOF
    // equation as printed, with the same simplifications applied).
    let mut d = file.derivatives;
    if o.neglect_zq_zwdot {
        d.z_q = 0.0;
        d.z_wdot = 0.0;
    }
    let two = TwoDof::of(&d);
    let eq45 = |t: f64| match input {
        Input::Step { m0, .. } => Some(two.w(t, 1.0) * m0),
        Input::Initial { .. } => None,
    };

    let mut csv = String::new();
    let _ = write!(csv, "t_hat");
    if tau.is_some() {
        let _ = write!(csv, ",t_s");
    }
    let _ = writeln!(csv, ",u_hat,w_hat,q_hat,theta,w_hat_eq45");
    for s in &samples {
        let _ = write!(csv, "{}", num(s.t));
        if let Some(t) = tau {
            let _ = write!(csv, ",{}", num(s.t * t));
        }
        let _ = writeln!(
            csv,
            ",{},{},{},{},{}",
            num(s.u),
            num(s.w),
            num(s.q),
            num(s.theta),
            eq45(s.t).map(num).unwrap_or_default()
        );
    }
    if let Some(path) = &o.csv {
        atomic_write(Path::new(path), csv.as_bytes())
            .map_err(|e| bad(format!("cannot write {path}: {e}")))?;
    }
    if let Some(path) = &o.svg {
        let mut fig = Figure::new(
            "response",
            format!(
                "Response to {} — {}{}",
                if o.input == "step" {
                    "an elevon step m₀"
                } else {
                    "an initial ŵ"
                },
                o.file,
                match (o.neglect_zq_zwdot, o.neglect_u) {
                    (true, true) => " (z_q, z_ẇ and û neglected)",
                    (true, false) => " (z_q and z_ẇ neglected)",
                    (false, true) => " (û neglected)",
                    _ => "",
                }
            ),
            "t̂ = t/τ",
            "state (û, ŵ = α, θ in rad; q̂ = dθ/dt̂)",
        );
        let pick = |f: fn(&stability_core::response::Sample) -> f64| {
            samples.iter().map(|s| (s.t, f(s))).collect()
        };
        if !o.neglect_u {
            fig = fig.with(Series::new("û", pick(|s| s.u)));
        }
        fig = fig
            .with(Series::new("ŵ", pick(|s| s.w)))
            .with(Series::new("q̂", pick(|s| s.q)))
            .with(Series::new("θ", pick(|s| s.theta)));
        if matches!(input, Input::Step { .. }) {
            fig = fig.with(Series::new(
                "ŵ, eq (45) (2 d.o.f.)",
                samples
                    .iter()
                    .filter_map(|s| eq45(s.t).map(|w| (s.t, w)))
                    .collect(),
            ));
        }
        let svg = fig.to_svg().map_err(bad)?;
        atomic_write(Path::new(path), svg.as_bytes())
            .map_err(|e| bad(format!("cannot write {path}: {e}")))?;
    }
    if o.csv.is_none() && o.svg.is_none() {
        print!("{csv}");
    } else {
        let last = samples.last();
        println!(
            "{} samples from t̂ = 0 to {}{}; final ŵ = {}, θ = {}{}",
            samples.len(),
            sig(last.map_or(0.0, |s| s.t), 4),
            tau.map(|t| format!(" ({} s)", sig(o.until * t, 4)))
                .unwrap_or_default(),
            sig(last.map_or(0.0, |s| s.w), 5),
            sig(last.map_or(0.0, |s| s.theta), 5),
            if samples.len() < o.steps + 1 {
                " (stopped early: the motion diverged past f64)"
            } else {
                ""
            }
        );
        for p in [&o.csv, &o.svg].into_iter().flatten() {
            println!("wrote {p}");
        }
    }
    Ok(())
}
