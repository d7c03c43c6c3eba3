//! `delta-stability uncertainty CONFIG --mach A:B:STEP --samples N [--seed S]
//! [--sobol] [--sampling random|sobol] [--json] [-o OUT.csv|OUT.json]`: the config's `[uncertainty]`
//! study ([`stability_io::config::uncertainty`]) run by Monte Carlo at each
//! Mach number ([`stability_core::uncertainty`]), with a progress bar.

use crate::Failure;
use crate::args::ModelArgs;
use crate::output::AtomicFile;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use stability_core::numerics::display::sig;
use stability_core::uncertainty::{Options, Sampling, Study};
use stability_io::config::overridden;
use stability_io::diag::InputError;
use stability_io::files::write_error;
use stability_io::format::Format;
use stability_io::sweep::parse_machs;
use stability_io::uncertainty::{
    CSV_HEADER, ProportionJson, QuantilesJson, SummaryJson, UncertaintyJson, csv_rows_of,
};
use std::io::Write as _;
use std::path::Path;

/// The command's options.
#[derive(Debug, Clone, clap::Args)]
pub struct Args {
    /// The design point and its `[uncertainty]` table (TOML).
    pub config: String,
    /// Mach numbers: A:B:STEP (inclusive), a list A,B,… or one value.
    #[arg(long, allow_hyphen_values = true)]
    pub mach: String,
    /// Monte Carlo samples at each Mach number.
    #[arg(long, default_value_t = 10_000, value_parser = clap::value_parser!(u64).range(1..=1_000_000_000_000))]
    pub samples: u64,
    /// The seed: the same seed gives the same results, bit for bit, on any
    /// number of threads.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Also the first-order and total Sobol indices of every input for the
    /// margin Δm_θ̇ (eq 41) and for ζ (k + 2 evaluations a sample, k inputs).
    #[arg(long)]
    pub sobol: bool,
    /// How the samples are drawn: random (ChaCha8, the default) or sobol
    /// (Owen-scrambled Sobol′ points, Burley 2020: an error nearer 1/N than
    /// 1/√N; best with N a power of two). Overrides the config's
    /// `sampling` in `[uncertainty]`.
    #[arg(long, value_parser = ["random", "sobol"])]
    pub sampling: Option<String>,
    /// Print one JSON object (keys file, samples, seed, sobol, sampling, inputs,
    /// damping_models, results[]: mach, samples, evaluated, errors,
    /// first_error, standard_met, meets, fails, divergent {count, n, p, low,
    /// high}, short_period_level_a/b/c and phugoid_level {level_1 …
    /// not_assessed}, cycles_to_half and damping_ratio {n, probabilities,
    /// values}, sobol {factors, margin[], damping_ratio[]: first, first_se,
    /// total, total_se}).
    #[arg(long)]
    pub json: bool,
    /// Write everything to OUT: .csv (long: mach, quantity, value, low,
    /// high) or .json.
    #[arg(short = 'o', long = "output")]
    pub output: Option<String>,
    #[command(flatten)]
    pub model: ModelArgs,
}

pub fn run(o: &Args) -> Result<(), Failure> {
    // every input read (the config, its tables, the study's samples files)
    // before any output is checked against them
    let (read, inputs) = stability_io::files::recording(|| read_study(o));
    let (study, sampling) = read?;
    let bad = |m: String| Failure::Input(InputError::file(&o.config, m));
    let outputs: Vec<_> = o
        .output
        .iter()
        .map(|out| crate::overwrite::Named::new("-o", out))
        .collect();
    crate::overwrite::refuse("CONFIG", &o.config, &inputs, &outputs)?;
    let file_format = o.output.as_deref().map(Format::of_file).transpose();
    let file_format = file_format.map_err(|e| bad(format!("-o: {e}")))?;
    let machs = parse_machs(&o.mach).map_err(&bad)?;
    let options = Options {
        samples: o.samples,
        seed: o.seed,
        sobol: o.sobol,
        sampling,
    };
    let bar = progress_bar(o.samples * machs.len() as u64);
    let mut results = Vec::with_capacity(machs.len());
    for (k, &m) in machs.iter().enumerate() {
        let done = k as u64 * o.samples;
        results.push(
            study
                .at_mach(m)
                .run(&options, &|n| bar.set_position(done + n)),
        );
    }
    bar.finish_and_clear();
    // every output from the one view, every number in it finite
    let view = UncertaintyJson::new(&o.config, &study, &options, &results).checked()?;
    if let (Some(out), Some(format)) = (&o.output, file_format) {
        write(Path::new(out), format, &o.config, &view)?;
    }
    crate::output::print_as(Format::printed(o.json), &o.config, &view, || {
        Ok(page(&view, &study.factor_names(), o, sampling))
    })
}

/// The config's study and its sampling (the command line's `--sampling`,
/// else the config's).
fn read_study(o: &Args) -> Result<(Study, Sampling), Failure> {
    let cfg = overridden(&o.config, &o.model.overrides())?;
    let study = stability_io::config::uncertainty::read(&cfg)?.ok_or_else(|| {
        InputError::file(
            &o.config,
            "the config has no [uncertainty] table: give a distribution for an input, e.g. [uncertainty.i_b] dist = \"normal\", relative_sd = 0.1 (see `uncertainty --help`)",
        )
    })?;
    let sampling = match o.sampling.as_deref().and_then(Sampling::parse) {
        Some(s) => s,
        None => stability_io::config::uncertainty::sampling(&cfg)?.unwrap_or_default(),
    };
    Ok((study, sampling))
}

fn progress_bar(total: u64) -> ProgressBar {
    let bar = ProgressBar::with_draw_target(Some(total), ProgressDrawTarget::stderr());
    bar.set_style(
        ProgressStyle::with_template(
            "{spinner} [{bar:30}] {pos}/{len} samples ({per_sec}, eta {eta})",
        )
        .unwrap_or_else(|_| ProgressStyle::default_bar())
        .progress_chars("=> "),
    );
    bar
}

/// OUT written atomically in `format`: the JSON view or the long CSV (a
/// result of the config `source`).
fn write(
    out: &Path,
    format: Format,
    source: &str,
    view: &UncertaintyJson<'_>,
) -> Result<(), Failure> {
    let write_err = |e: std::io::Error| Failure::Io(write_error(out, &e));
    let text = format.document(source, view, || {
        let mut s = format!("{CSV_HEADER}\n");
        view.results
            .iter()
            .for_each(|r| s.push_str(&csv_rows_of(r)));
        Ok(s)
    })?;
    let mut file = AtomicFile::create(out).map_err(write_err)?;
    file.write_all(text.as_bytes()).map_err(write_err)?;
    file.commit().map_err(write_err)
}

/// A value of the page: "—" where absent.
fn shown(v: Option<f64>, digits: usize) -> String {
    v.map_or("—".into(), |v| sig(v, digits))
}

/// The page: one line per Mach number, then the Sobol indices.
fn page(view: &UncertaintyJson<'_>, factors: &[&str], o: &Args, sampling: Sampling) -> String {
    let results = &view.results;
    let pct = |p: &ProportionJson| match p.p {
        None => "—".to_string(),
        Some(v) => format!("{} [{}, {}]", sig(v, 3), shown(p.low, 3), shown(p.high, 3)),
    };
    let mut table = vec![
        [
            "Mach",
            "P(§8 met)",
            "P(meets)",
            "P(divergent)",
            "cycles ½ (5, 50, 95 %)",
            "ζ (5, 50, 95 %)",
            "errors",
        ]
        .map(String::from)
        .to_vec(),
    ];
    for r in results {
        let q = |q: &QuantilesJson| {
            format!(
                "{}, {}, {}",
                shown(q.values[1], 3),
                shown(q.values[3], 3),
                shown(q.values[5], 3)
            )
        };
        table.push(vec![
            sig(r.mach, 4),
            pct(&r.standard_met),
            pct(&r.meets),
            pct(&r.divergent),
            q(&r.cycles_to_half),
            q(&r.damping_ratio),
            r.errors.to_string(),
        ]);
    }
    let mut s = format!(
        "Uncertainty of {}: {} samples a Mach number ({}), seed {}; probabilities with 95 % Wilson intervals\n\
         §8: the short period halves within one cycle (eq 41); meets: that, and no mode grows; divergent: a mode grows\n",
        o.config,
        o.samples,
        match sampling {
            Sampling::Random => "random",
            Sampling::Sobol => "Owen-scrambled Sobol′ points",
        },
        o.seed
    );
    s.push_str(&crate::page::aligned(&table));
    for r in results.iter().filter(|r| r.first_error.is_some()) {
        let e = r.first_error.unwrap_or_default();
        let how_many = if r.no_result() {
            format!("no result: none of the {} samples has one", r.samples)
        } else {
            format!("{} samples had no result", r.errors)
        };
        s.push_str(&format!(
            "M = {}: {how_many}; the first: {e}\n",
            sig(r.mach, 4)
        ));
    }
    if o.sobol {
        s.push_str(&sobol_page(results, factors));
    }
    s
}

/// The Sobol indices (Saltelli 2010, Jansen 1999), each Mach number a row.
fn sobol_page(results: &[SummaryJson<'_>], factors: &[&str]) -> String {
    let mut s = String::from(
        "\nSobol indices, first order / total (Saltelli et al. 2010; Jansen 1999), of Δm_θ̇ (eq 41) and of ζ:\n",
    );
    let mut head = vec!["Mach".to_string()];
    for f in factors {
        head.push(format!("{f}: Δm_θ̇"));
        head.push(format!("{f}: ζ"));
    }
    let mut table = vec![head];
    for r in results {
        let mut row = vec![sig(r.mach, 4)];
        let sobol = r.sobol;
        for k in 0..factors.len() {
            for ix in [
                sobol.and_then(|x| x.margin.as_ref()),
                sobol.and_then(|x| x.damping_ratio.as_ref()),
            ] {
                row.push(ix.map_or("—".into(), |ix| {
                    format!("{} / {}", sig(ix[k].first, 2), sig(ix[k].total, 2))
                }));
            }
        }
        table.push(row);
    }
    s.push_str(&crate::page::aligned(&table));
    s
}
