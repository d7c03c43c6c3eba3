//! `delta-stability response FILE --input step|initial --until T`: the
//! longitudinal response (§11), solved exactly. A response that cannot
//! reach `--until` (it overflows f64) is an error, not a short file.
//!
//! FILE is a derivative file or a design-point config (its design point
//! as `analyze` computes it). With a physical flight condition the span
//! may be in seconds (`--until-s`), and with a `[control]` table the input
//! a deflection of the control in degrees (`--elevator-deg`).

use crate::Failure;
use crate::args::ResponseInput;
use crate::output::{print, write_set};
use crate::overwrite::Named;
use stability_core::dynamics::linear::Control;
use stability_core::dynamics::response::{Computed, Sample};
use stability_core::numerics::display::sig;
use stability_io::design_point::read_set;
use stability_io::diag::InputError;
use stability_io::files::write_error;
use stability_io::input::DerivativeFile;
use stability_io::plot::{Figure, Series};
use stability_io::response::{Asked, Disturbance, Spec, Style, csv, respond};
use std::path::PathBuf;

/// The command's options (validated by clap: `until` positive and finite,
/// `steps` from 1 to the library's `MAX_STEPS`, `m0` and `w0` finite).
#[derive(Debug, Clone, clap::Args)]
pub struct Args {
    /// The derivative file (TOML), as for `quartic`, or a design-point config, as for `analyze`.
    pub file: String,
    /// What disturbs the aircraft.
    #[arg(long, value_enum, default_value = "step")]
    pub input: ResponseInput,
    /// End time, in units of τ (positive).
    #[arg(long, value_parser = crate::args::positive, allow_negative_numbers = true, required_unless_present = "until_s", conflicts_with = "until_s")]
    pub until: Option<f64>,
    /// End time in seconds (positive): needs τ, from a physical flight condition (a config's, or `[dimensional]`).
    #[arg(long = "until-s", value_name = "SECONDS", value_parser = crate::args::positive, allow_negative_numbers = true)]
    pub until_s: Option<f64>,
    /// A step of the control of the file's `[control]` table by this many degrees (finite), from rest: its force and moment derivatives, instead of --m0.
    #[arg(long = "elevator-deg", visible_alias = "elevon-deg", value_name = "DEG", value_parser = crate::args::finite, allow_negative_numbers = true, conflicts_with = "m0")]
    pub elevator_deg: Option<f64>,
    /// Number of intervals (1 to 10⁶).
    #[arg(long, default_value_t = 400, value_parser = clap::value_parser!(u32).range(1..=stability_core::dynamics::response::MAX_STEPS as i64))]
    pub steps: u32,
    /// Size of the moment step m₀ of `--input step` (eqs 2 units; finite; default 1).
    #[arg(long, value_parser = crate::args::finite, allow_negative_numbers = true)]
    pub m0: Option<f64>,
    /// Initial ŵ = w/V of `--input initial` (finite; default 0.01).
    #[arg(long, value_parser = crate::args::finite, allow_negative_numbers = true)]
    pub w0: Option<f64>,
    /// Set z_q = z_ẇ = 0 (the report's Fig 38).
    #[arg(long)]
    pub neglect_zq_zwdot: bool,
    /// Hold û = 0: two degrees of freedom (§11).
    #[arg(long)]
    pub neglect_u: bool,
    /// Write the time history as CSV.
    #[arg(long)]
    pub csv: Option<String>,
    /// Write a plot as SVG.
    #[arg(long)]
    pub svg: Option<String>,
}

impl Args {
    /// The library's response, as asked for, of `file` with its
    /// `[control]` ([`Asked::spec`], the options' checks Python shares).
    pub fn spec(
        &self,
        file: &DerivativeFile,
        control: Option<&Control>,
    ) -> Result<Spec, InputError> {
        Asked {
            input: match self.input {
                ResponseInput::Step => Disturbance::Step,
                ResponseInput::Initial => Disturbance::Initial,
            },
            until: self.until,
            until_s: self.until_s,
            steps: self.steps as usize,
            m0: self.m0,
            w0: self.w0,
            elevator_deg: self.elevator_deg,
            neglect_zq_zwdot: self.neglect_zq_zwdot,
            neglect_u: self.neglect_u,
            style: Style::CommandLine,
        }
        .spec(file, control)
    }
}

pub fn run(o: &Args) -> Result<(), Failure> {
    let (read, files) = stability_io::files::recording(|| read_set(&o.file, None));
    let (file, control) = read?;
    let read = files;
    let outputs: Vec<Named> = [("--csv", &o.csv), ("--svg", &o.svg)]
        .into_iter()
        .filter_map(|(what, p)| p.as_ref().map(|p| Named::new(what, p)))
        .collect();
    crate::overwrite::refuse("FILE", &o.file, &read, &outputs)?;
    crate::output::warn_all(&file.warnings);
    let spec = o.spec(&file, control.as_ref())?;
    let r = respond(&file, &spec)?;
    let tau = file.tau();
    let csv = csv(&r, tau);
    let mut files = Vec::new();
    for (path, text) in [(&o.csv, Some(&csv)), (&o.svg, None)] {
        let Some(path) = path else { continue };
        let bytes = match text {
            Some(t) => t.clone(),
            None => figure(o, &r)
                .to_svg()
                .map_err(|m| InputError::file(&o.file, m))?,
        };
        files.push((PathBuf::from(path), bytes.into_bytes()));
    }
    // the CSV and the plot as a set: both or neither
    write_set(&files).map_err(|(path, e)| write_error(&path, &e))?;
    if o.csv.is_none() && o.svg.is_none() {
        print(&csv)?;
    } else if let Some(last) = r.samples.last() {
        let mut text = format!(
            "{} samples from t̂ = 0 to {}{}; final ŵ = {}, θ = {}\n",
            r.samples.len(),
            sig(last.t, 4),
            tau.map(|t| format!(" ({} s)", sig(spec.until * t, 4)))
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

fn figure(o: &Args, r: &Computed) -> Figure {
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
