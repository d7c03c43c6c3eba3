//! `delta-stability quartic FILE [--json] [--state-space OUT.json]`: the
//! stability quartic of a derivative set (eqs 4–6), its roots and modes
//! (§4, eqs 7–8), Routh's test, the §8 damping standard and the
//! MIL-F-8785C levels; with `[dimensional]`, the modes in seconds
//! (`damp()`) and the short-period frequency requirement; the mode shapes;
//! and the state-space model, written on request. The file is read and
//! analysed by [`stability_io::input`]; this command prints the page or
//! the JSON.

use crate::Failure;
use crate::args::ClassArg;
use crate::output::print_as;
use crate::page::analysis_page;
use stability_core::analysis::Analysis;
use stability_core::analysis::engineering::Engineering;
use stability_core::dynamics::linear::Control;
use stability_io::class::ClassChoice;
use stability_io::format::Format;
use stability_io::input::dimensional_notation::{self, DimensionalFile, is_dimensional};
use stability_io::input::{self, DerivativeFile};
use stability_io::views::{DimensionalJson, QuarticJson};
use std::path::Path;

/// The command's options.
#[derive(Debug, Clone, clap::Args)]
pub struct Args {
    /// The derivative file (TOML).
    pub file: String,
    /// Print one JSON object (keys coefficients, routh_discriminant, stable, roots, modes, criteria, mode_shapes; with `[dimensional]` also damp and short_period_frequency) instead of a table.
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub engineering: EngineeringArgs,
}

/// The options that write the engineer's outputs (`quartic`, `analyze`).
#[derive(Debug, Clone, clap::Args)]
pub struct EngineeringArgs {
    /// Write the state space ẋ = A x + B δ, x = (u/V, α, q, θ), with the outputs y = C x + D δ (the states, γ = θ − α and the load factor n_z = (V/g)(q − α̇) at the c.g.), in seconds when the flight condition is dimensional (else in τ), to OUT.json, with a python-control script OUT.py and a MATLAB script OUT.m beside it (damp() and the step response). B needs a `[control]` table (C_mdelta, and C_zdelta or C_Ldelta, C_xdelta: per radian; optional name); without one, A only.
    #[arg(long, value_name = "OUT.json")]
    pub state_space: Option<String>,
    /// The MIL-F-8785C airplane class (§1.3) whose Category C floors the short-period frequency requirement applies (only they depend on the class). Not given: analyze takes the config's `[aircraft] class`; without one (and always for quartic's files) Category C of that requirement is not assessed, and the page says so. (It was IV by default.)
    #[arg(long = "class", value_enum)]
    pub class: Option<ClassArg>,
}

impl EngineeringArgs {
    /// The class given with `--class`, if one was.
    pub fn class(&self) -> Option<stability_core::criteria::cap::AirplaneClass> {
        self.class.map(|c| c.0)
    }
}

/// How a class is given on the command line, in messages.
pub const CLASS_FLAG: &str = "--class";

/// A derivative file as `quartic` reads it: a dimensional set as it is,
/// any other in the report's notation with its `[control]` table.
enum Read {
    Dimensional(Box<DimensionalFile>),
    Report(Box<DerivativeFile>, Option<Control>),
}

fn read(file: &str) -> Result<Read, Failure> {
    let text = stability_io::files::read_input(Path::new(file))?;
    if is_dimensional(&text) {
        let d = dimensional_notation::parse(file, &text)?;
        return Ok(Read::Dimensional(Box::new(d)));
    }
    let input = input::parse(file, &text)?;
    let control = stability_io::control::read_control(file, &text)?;
    Ok(Read::Report(Box::new(input), control))
}

pub fn run(a: &Args) -> Result<(), Failure> {
    let (file, o) = (a.file.as_str(), &a.engineering);
    let (read, files) = stability_io::files::recording(|| read(file));
    let read = read?;
    let outputs = crate::overwrite::state_space(o.state_space.as_deref())?;
    crate::overwrite::refuse("FILE", file, &files, &outputs)?;
    let (input, control) = match read {
        Read::Dimensional(d) => return run_dimensional(&d, a),
        Read::Report(input, control) => (input, control),
    };
    crate::output::warn_all(&input.warnings);
    let (analysis, engineering) = input.evaluated(control.as_ref(), o.class())?;
    let class = ClassChoice::of(o.class(), None);
    let tau = input.tau();
    let view = QuarticJson::new(&input, &analysis, &engineering);
    crate::output::finite(file, &view)?;
    if let Some(out) = &o.state_space {
        let roots = tau.map_or(analysis.roots, |t| analysis.roots.map(|z| z / t));
        crate::state_space::write(
            out,
            &crate::state_space::Export {
                source: file,
                command: "quartic",
                model: &engineering.model,
                tau,
                eigenvalues: roots,
            },
        )?;
    }
    print_as(Format::printed(a.json), file, &view, || {
        Ok(table(&input, &analysis, &engineering, &class))
    })
}

pub fn table(
    input: &DerivativeFile,
    a: &Analysis,
    engineering: &Engineering,
    class: &ClassChoice,
) -> String {
    let mut s = analysis_page(
        &format!(
            "Stability quartic of {} (eqs 4–6; the errata of docs/errata.md applied)",
            input.path
        ),
        a,
        input.tau(),
    );
    s.push_str(&frequency_line(engineering, class));
    s.push_str(&crate::engineering::tables(engineering));
    s
}

/// The MIL-F-8785C short-period frequency requirement's line: the levels,
/// or why it is not assessed (CAP undefined); empty when it does not
/// apply (no oscillatory short period, or no times in seconds).
pub fn frequency_line(e: &Engineering, class: &ClassChoice) -> String {
    match (
        &e.short_period_frequency,
        &e.short_period_frequency_not_assessed,
    ) {
        (Some(f), _) => format!(
            "{}\n",
            crate::engineering::frequency_line(f, &class.describe(CLASS_FLAG))
        ),
        (None, Some(why)) => {
            format!("MIL-F-8785C short-period frequency (§3.2.2.1.1): not assessed: {why}\n")
        }
        (None, None) => String::new(),
    }
}

/// `quartic` of a `notation = "dimensional"` set: the general model
/// (eq D2), roots in 1/s, modes in seconds; the engineer's outputs (damp(),
/// mode shapes, the short-period frequency requirement, the state space)
/// from the set in stability axes.
fn run_dimensional(input: &DimensionalFile, args: &Args) -> Result<(), Failure> {
    crate::output::warn_all(&input.warnings);
    let (a, engineering) = input.evaluated(args.engineering.class())?;
    let class = ClassChoice::of(args.engineering.class(), None);
    let view = DimensionalJson::new(input, &a, &engineering);
    crate::output::finite(&input.path, &view)?;
    if let Some(out) = &args.engineering.state_space {
        crate::state_space::write(
            out,
            &crate::state_space::Export {
                source: &input.path,
                command: "quartic",
                model: &engineering.model,
                tau: None,
                eigenvalues: a.roots,
            },
        )?;
    }
    print_as(Format::printed(args.json), &input.path, &view, || {
        let title = format!(
            "Stability quartic of {} (notation \"dimensional\": the general longitudinal model, eqs D1–D2)",
            input.path
        );
        let mut page = crate::page::dimensional_page(&title, &a);
        page.push_str(&frequency_line(&engineering, &class));
        page.push_str(&crate::engineering::tables(&engineering));
        Ok(page)
    })
}
