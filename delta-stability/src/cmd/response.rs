//! `delta-stability response FILE --input step|initial --until T`: the
//! longitudinal response (§11), solved exactly. A response that cannot
//! reach `--until` (it overflows f64) is an error, not a short file.

use crate::Failure;
use crate::args::ResponseInput;
use crate::diag::{InputError, num};
use crate::files::write_error;
use crate::fmt::sig;
use crate::input::{self, DerivativeFile, rows};
use crate::output::{atomic_write, print};
use crate::plot::{Figure, Series};
use stability_core::response::{
    Input, ResponseError, Sample, Simplifications, StateSpace, Stop, TwoDof,
};
use std::fmt::Write;
use std::path::Path;

/// The options of the command (validated by clap: `until` positive and
/// finite, `steps` from 1 to the library's `MAX_STEPS`, `m0` and `w0`
/// finite).
pub struct Options {
    pub file: String,
    pub input: ResponseInput,
    pub until: f64,
    pub steps: usize,
    pub m0: f64,
    pub w0: f64,
    pub neglect_zq_zwdot: bool,
    pub neglect_u: bool,
    pub csv: Option<String>,
    pub svg: Option<String>,
}

/// A computed response with the report's closed form beside it.
pub struct Computed {
    pub samples: Vec<Sample>,
    /// Eq (45)'s ŵ at each sample, for a step.
    pub eq45: Option<Vec<f64>>,
}

pub fn run(o: &Options) -> Result<(), Failure> {
    let file = input::read(&o.file)?;
    for w in &file.warnings {
        crate::output::warn(&format!("warning: {w}"));
    }
    let r = respond(o, &file)?;
    let tau = file.dimensional.map(|d| d.tau());
    let csv = csv_text(&r, tau);
    for (path, text) in [(&o.csv, Some(&csv)), (&o.svg, None)] {
        let Some(path) = path else { continue };
        let bytes = match text {
            Some(t) => t.clone(),
            None => figure(o, &r)
                .to_svg()
                .map_err(|m| InputError::file(&o.file, m))?,
        };
        atomic_write(Path::new(path), bytes.as_bytes())
            .map_err(|e| write_error(Path::new(path), &e))?;
    }
    if o.csv.is_none() && o.svg.is_none() {
        print(&csv)?;
    } else if let Some(last) = r.samples.last() {
        let mut text = format!(
            "{} samples from t̂ = 0 to {}{}; final ŵ = {}, θ = {}\n",
            r.samples.len(),
            sig(last.t, 4),
            tau.map(|t| format!(" ({} s)", sig(o.until * t, 4)))
                .unwrap_or_default(),
            sig(last.w, 5),
            sig(last.theta, 5),
        );
        for p in [&o.csv, &o.svg].into_iter().flatten() {
            text.push_str(&format!("wrote {p}\n"));
        }
        print(&text)?;
    }
    Ok(())
}

/// The response over the whole span asked for, or why it cannot be had
/// (`csv` and `svg` of the options are not used).
pub fn respond(o: &Options, file: &DerivativeFile) -> Result<Computed, InputError> {
    let bad = |m: String| InputError::file(&o.file, m);
    let input = match o.input {
        ResponseInput::Step => Input::Step {
            x0: 0.0,
            z0: 0.0,
            m0: o.m0,
        },
        ResponseInput::Initial => Input::Initial {
            u: 0.0,
            w: o.w0,
            q: 0.0,
            theta: 0.0,
        },
    };
    let simp = Simplifications {
        neglect_zq_zwdot: o.neglect_zq_zwdot,
        neglect_u: o.neglect_u,
    };
    let ss = StateSpace::new(&file.derivatives, simp).map_err(|e| match e {
        ResponseError::SingularMass { .. } => file.error_at(rows::Z_WDOT, e.to_string()),
        _ => bad(e.to_string()),
    })?;
    let r = ss
        .simulate(input, o.until, o.steps)
        .map_err(|e| bad(format!("--until {} --steps {}: {e}", num(o.until), o.steps)))?;
    if let Some(stop) = &r.stopped {
        return Err(bad(stopped_early(o, &r.samples, stop)));
    }
    let samples = r.samples;
    // the report's closed form, eq (45), for the step (from the 2-DOF
    // equation as printed, with the same simplifications applied)
    let mut d = file.derivatives;
    if o.neglect_zq_zwdot {
        d.z_q = 0.0;
        d.z_wdot = 0.0;
    }
    let two = TwoDof::of(&d);
    let eq45: Option<Vec<f64>> = matches!(input, Input::Step { .. })
        .then(|| samples.iter().map(|s| two.w(s.t, 1.0) * o.m0).collect());
    if let Some(k) = eq45
        .as_ref()
        .and_then(|w| w.iter().position(|v| !v.is_finite()))
    {
        return Err(bad(format!(
            "eq (45)'s two-degree-of-freedom response overflows f64 at t̂ = {}, before --until {}: ask for a shorter --until",
            num(samples[k].t),
            num(o.until)
        )));
    }
    Ok(Computed { samples, eq45 })
}

/// Why a response stopped before `--until`: the library's reason.
fn stopped_early(o: &Options, samples: &[Sample], stop: &Stop) -> String {
    let reached = samples.last().map_or(0.0, |s| s.t);
    format!(
        "the response stops at t̂ = {} of the {} asked for (--until): {stop}; ask for a shorter --until",
        num(reached),
        num(o.until)
    )
}

fn csv_text(r: &Computed, tau: Option<f64>) -> String {
    let mut csv = String::new();
    let _ = write!(csv, "t_hat");
    if tau.is_some() {
        let _ = write!(csv, ",t_s");
    }
    let _ = writeln!(csv, ",u_hat,w_hat,q_hat,theta,w_hat_eq45");
    for (k, s) in r.samples.iter().enumerate() {
        let _ = write!(csv, "{}", crate::plot::num(s.t));
        if let Some(t) = tau {
            let _ = write!(csv, ",{}", crate::plot::num(s.t * t));
        }
        let eq45 = r.eq45.as_ref().map(|w| crate::plot::num(w[k]));
        let _ = writeln!(
            csv,
            ",{},{},{},{},{}",
            crate::plot::num(s.u),
            crate::plot::num(s.w),
            crate::plot::num(s.q),
            crate::plot::num(s.theta),
            eq45.unwrap_or_default()
        );
    }
    csv
}

fn figure(o: &Options, r: &Computed) -> Figure {
    let mut fig = Figure::new(
        "response",
        format!(
            "Response to {} — {}{}",
            match o.input {
                ResponseInput::Step => "an elevon step m₀",
                ResponseInput::Initial => "an initial ŵ",
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
    let pick = |f: fn(&Sample) -> f64| r.samples.iter().map(|s| (s.t, f(s))).collect();
    if !o.neglect_u {
        fig = fig.with(Series::new("û", pick(|s| s.u)));
    }
    fig = fig
        .with(Series::new("ŵ", pick(|s| s.w)))
        .with(Series::new("q̂", pick(|s| s.q)))
        .with(Series::new("θ", pick(|s| s.theta)));
    if let Some(w) = &r.eq45 {
        let points = r.samples.iter().zip(w).map(|(s, &w)| (s.t, w)).collect();
        fig = fig.with(Series::new("ŵ, eq (45) (2 d.o.f.)", points));
    }
    fig
}
