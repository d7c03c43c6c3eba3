//! "How sure are the headline conclusions?": the note's two
//! headline conclusions (Summary; §9, Fig 33) as probabilities, under
//! stated distributions of the inputs it does not pin down — i_B and
//! C_L·M² (which it does not state), the c.g. (its Fig 26 moves it) and the
//! damping theory itself (model-form uncertainty, with weights):
//!
//! - the probability that the 45° tailless delta at μ₁ = 50 fails the §8
//!   one-cycle standard (eq 41; divergent counts as failing) at each Mach
//!   number in 0.97 < M < 1.5, and bounds on its failing throughout;
//! - the probability that the 60° delta meets it at μ₁ = 160 — 200 less the
//!   report's "about" ([`ABOUT`]) — at each Mach number of the μ₁ searches.
//!
//! Each study is an example config (`examples/delta-45-how-sure.toml`,
//! `examples/delta-60-how-sure.toml`, compiled in) whose `[uncertainty]`
//! table states every spread and its source, run by
//! [`stability_core::uncertainty`] from Owen-scrambled Sobol′ points with
//! [`SEED`]: `delta-stability uncertainty` on the same file with the same
//! seed and sample count gives the same numbers, bit for bit. The deciding
//! inputs are named by their total Sobol indices (Saltelli et al. 2010;
//! Jansen 1999) for the short period's ζ, which decides the standard
//! (cycles to half amplitude ln 2·√(1−ζ²)/(2πζ), eq 8), from a run of
//! [`SOBOL_SAMPLES`] rows.

use super::Plate;
use super::conclusions::{ABOUT, MU1_LIMIT};
use serde::Serialize;
use stability_core::numerics::display::sig;
use stability_core::uncertainty::stats::{Proportion, Z95};
use stability_core::uncertainty::{Options, Sampling, Study, Summary};
use stability_io::plot::{Band, Figure, Series};

/// Samples at each Mach number: the 95 % Wilson interval of a probability
/// is at most ±1.96·√(0.25/8192) = ±1.1 % (binomial, at p = ½; the
/// Sobol′ points' error is in practice smaller, without such a bound).
pub const SAMPLES: u64 = 8192;

/// Rows of the Sobol indices' design (k + 2 = 6 evaluations a row): their
/// standard errors are stated beside them.
pub const SOBOL_SAMPLES: u64 = 1024;

/// The seed of every run (the note's year).
pub const SEED: u64 = 1953;

/// What a headline claims of each sample.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Claim {
    /// The §8 standard is not met (fails or diverges).
    FailsStandard,
    /// The §8 standard is met.
    MeetsStandard,
}

/// One of the note's headline conclusions and the study that weighs it.
#[derive(Debug)]
pub struct Headline {
    /// The conclusion's id in [`super::conclusions::CONCLUSIONS`].
    pub id: &'static str,
    /// The example config, and its text (compiled in).
    pub file: &'static str,
    pub text: &'static str,
    /// The Mach numbers, as `--mach` takes them.
    pub machs: &'static str,
    pub claim: Claim,
    /// The probability asked, in words.
    pub question: &'static str,
    /// A series' label.
    pub label: &'static str,
}

/// The two headline conclusions.
pub const HEADLINES: [Headline; 2] = [
    Headline {
        id: "45-transonic",
        file: "examples/delta-45-how-sure.toml",
        text: include_str!("../data/delta-45-how-sure.toml"),
        machs: "0.98:1.48:0.02",
        claim: Claim::FailsStandard,
        question: "the probability that the 45° delta at μ₁ = 50 fails the one-cycle standard (0.97 < M < 1.5)",
        label: "45°, μ₁ = 50: P(fails §8)",
    },
    Headline {
        id: "60-mu1-limit",
        file: "examples/delta-60-how-sure.toml",
        text: include_str!("../data/delta-60-how-sure.toml"),
        machs: "0.5:2:0.05",
        claim: Claim::MeetsStandard,
        question: "the probability that the 60° delta meets the one-cycle standard at μ₁ = 160 (200/1.25, the low end of “about 200”)",
        label: "60°, μ₁ = 160: P(meets §8)",
    },
];

impl Headline {
    /// The example's study and its sampling.
    pub fn study(&self) -> Result<(Study, Sampling), String> {
        let cfg = stability_io::config::parse(self.file, self.text).map_err(|e| e.to_string())?;
        let study = stability_io::config::uncertainty::read(&cfg)
            .map_err(|e| e.to_string())?
            .ok_or_else(|| format!("{}: no [uncertainty] table", self.file))?;
        let sampling = stability_io::config::uncertainty::sampling(&cfg)
            .map_err(|e| e.to_string())?
            .unwrap_or_default();
        Ok((study, sampling))
    }

    pub fn mach_numbers(&self) -> Vec<f64> {
        stability_io::sweep::parse_range("mach", self.machs).unwrap_or_default()
    }

    /// The study run with `samples` a Mach number (the probabilities) and,
    /// when `sobol_samples` > 0, again with that many rows of the Saltelli
    /// design (the indices).
    pub fn answer(&'static self, samples: u64, sobol_samples: u64) -> Result<Answer, String> {
        let _ = crate::study::preload();
        let (study, sampling) = self.study()?;
        let machs = self.mach_numbers();
        let options = Options {
            samples,
            seed: SEED,
            sobol: false,
            sampling,
        };
        let results = study.run(&machs, &options, &|_| {});
        let indices = match sobol_samples {
            0 => Vec::new(),
            n => {
                let o = Options {
                    samples: n,
                    sobol: true,
                    ..options
                };
                study.run(&machs, &o, &|_| {})
            }
        };
        Ok(Answer {
            headline: self,
            factors: study.factor_names(),
            models: study.models().iter().map(|m| m.name()).collect(),
            sampling,
            results,
            indices,
        })
    }

    /// The command that gives the same numbers.
    pub fn command(&self, samples: u64) -> String {
        format!(
            "delta-stability uncertainty {} --mach {} --samples {samples} --seed {SEED}",
            self.file, self.machs
        )
    }
}

/// One headline weighed.
#[derive(Debug)]
pub struct Answer {
    pub headline: &'static Headline,
    pub factors: Vec<&'static str>,
    pub models: Vec<&'static str>,
    pub sampling: Sampling,
    /// The probabilities' run, a summary per Mach number.
    pub results: Vec<Summary>,
    /// The indices' run (empty when not asked for).
    pub indices: Vec<Summary>,
}

/// A factor's Sobol indices for ζ, averaged over the Mach numbers.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Deciding {
    pub factor: &'static str,
    pub first: f64,
    pub total: f64,
    /// The largest standard error of a total index averaged.
    pub total_se: f64,
}

impl Answer {
    /// The claim's probability in one summary, with its Wilson interval.
    pub fn probability(&self, s: &Summary) -> Proportion {
        let met = s.standard_met;
        match self.headline.claim {
            Claim::MeetsStandard => met,
            Claim::FailsStandard => Proportion::of(met.n - met.count, met.n),
        }
    }

    /// (Mach, the claim's probability) at each Mach number.
    pub fn by_mach(&self) -> Vec<(f64, Proportion)> {
        self.results
            .iter()
            .map(|s| (s.mach, self.probability(s)))
            .collect()
    }

    /// Bounds on the probability that the claim holds at every Mach number
    /// at once (the runs share their samples, but the summaries keep no
    /// joint counts): at most the least of them; at least
    /// 1 − Σ(1 − p) (Boole's inequality), or 0.
    pub fn throughout(&self) -> (f64, f64) {
        let ps: Vec<f64> = self.by_mach().iter().map(|(_, p)| p.p).collect();
        let most = ps.iter().copied().fold(1.0, f64::min);
        let least = (1.0 - ps.iter().map(|p| 1.0 - p).sum::<f64>()).max(0.0);
        (least, most)
    }

    /// The factors by their total index for ζ averaged over the Mach
    /// numbers where it was found, largest first.
    pub fn deciding(&self) -> Vec<Deciding> {
        let rows: Vec<_> = self
            .indices
            .iter()
            .filter_map(|s| s.sobol.as_ref()?.damping_ratio.clone())
            .collect();
        let n = rows.len() as f64;
        let mut out: Vec<Deciding> = self
            .factors
            .iter()
            .enumerate()
            .map(|(k, &factor)| Deciding {
                factor,
                first: rows.iter().map(|r| r[k].first).sum::<f64>() / n,
                total: rows.iter().map(|r| r[k].total).sum::<f64>() / n,
                total_se: rows.iter().map(|r| r[k].total_se).fold(0.0, f64::max),
            })
            .filter(|d| d.total.is_finite())
            .collect();
        out.sort_by(|a, b| b.total.total_cmp(&a.total));
        out
    }

    /// Samples without a result, over all Mach numbers.
    pub fn errors(&self) -> u64 {
        self.results.iter().map(|s| s.errors).sum()
    }
}

/// Both headlines weighed: the section's figure, text and numbers.
#[derive(Debug)]
pub struct Certainty {
    pub answers: Vec<Answer>,
    pub samples: u64,
    pub sobol_samples: u64,
}

impl Certainty {
    /// Both headlines at [`SAMPLES`] and [`SOBOL_SAMPLES`].
    pub fn new() -> Result<Certainty, String> {
        Certainty::with(SAMPLES, SOBOL_SAMPLES)
    }

    pub fn with(samples: u64, sobol_samples: u64) -> Result<Certainty, String> {
        let answers = HEADLINES
            .iter()
            .map(|h| h.answer(samples, sobol_samples))
            .collect::<Result<_, _>>()?;
        Ok(Certainty {
            answers,
            samples,
            sobol_samples,
        })
    }

    /// The figure: each claim's probability against Mach number with its
    /// 95 % interval, the note's transonic range shaded.
    pub fn plate(&self) -> Plate {
        let mut f = Figure::new(
            "U1",
            "How sure are the headline conclusions? The probability of each",
            "Mach number M",
            "probability",
        );
        for a in &self.answers {
            let pts = a.by_mach();
            let series = |label: String, v: fn(&Proportion) -> f64| {
                Series::new(label, pts.iter().map(|(m, p)| (*m, v(p))).collect())
            };
            f = f.with(series(a.headline.label.to_string(), |p| p.p));
            f = f.with(series(format!("{}, 95 % low", a.headline.label), |p| p.low));
            f = f.with(series(format!("{}, 95 % high", a.headline.label), |p| {
                p.high
            }));
        }
        f.bands.push(Band {
            from: 0.97,
            to: 1.5,
            label: "the note's 0.97 < M < 1.5".into(),
        });
        f.y_range = Some((0.0, 1.0));
        let caption = format!(
            "{} samples a Mach number (Owen-scrambled Sobol′ points, seed {SEED}); each probability with its 95 % Wilson interval (at most ±{}). The inputs' distributions are stated in examples/delta-45-how-sure.toml and examples/delta-60-how-sure.toml.",
            self.samples,
            percent(Z95 * (0.25 / self.samples as f64).sqrt())
        );
        Plate::named("how-sure", f, caption)
    }
}

/// A share as a percentage: "98 %", "1.1 %".
pub fn percent(x: f64) -> String {
    format!("{} %", sig(100.0 * x, 2))
}

/// Bounds on a share: "between 3.0 % and 40 %", or the one share when both
/// print the same ("0 %", never "between 0 % and 0 %").
pub fn percent_range(least: f64, most: f64) -> String {
    let (a, b) = (percent(least), percent(most));
    match a == b {
        true => a,
        false => format!("between {a} and {b}"),
    }
}

/// The μ₁ of the 60° study, from the limit and the tolerance.
pub fn mu1_60() -> f64 {
    MU1_LIMIT / ABOUT
}

/// Where each input's spread comes from (as the example configs say).
fn source(factor: &str) -> &'static str {
    match factor {
        "i_b" => {
            "the range the report sweeps the unstated i_B over (a radius of gyration in pitch of 0.2c̄–0.45c̄), most likely at our assumed 0.08"
        }
        "cl_m2" => {
            "the report's range for the unstated C_L·M² (wing loadings of 30–50 lb/ft² from sea level to about 40 000 ft), most likely at our 0.05"
        }
        "cg" => "the note's h = 0.25, its Fig 26's 0.15 and 0.35 the ends of the travel",
        "model" => {
            "model-form: the note's own fairing of its theories (Figs 19–24) or the slender-wing fairing before it, weighted 3 to 1 (a judgement)"
        }
        _ => "",
    }
}

/// An input's distribution in words.
fn describe(d: &stability_core::uncertainty::Dist) -> String {
    use stability_core::uncertainty::Dist;
    match d {
        Dist::Triangular { low, mode, high } => {
            format!("triangular on [{low}, {high}], mode {mode}")
        }
        Dist::Uniform { low, high } => format!("uniform on [{low}, {high}]"),
        Dist::Normal { mean, sd } => format!("normal, mean {mean}, sd {sd}"),
        Dist::LogNormal { mu, sigma } => {
            format!("lognormal, median {}, σ(ln) {sigma}", sig(mu.exp(), 3))
        }
        Dist::Samples(v) => format!("{} samples", v.len()),
    }
}

/// One input of the JSON.
#[derive(Debug, Clone, Serialize)]
pub struct InputJson {
    pub name: &'static str,
    pub distribution: String,
    pub source: &'static str,
}

/// One Mach number of the JSON.
#[derive(Debug, Clone, Serialize)]
pub struct AtMachJson {
    pub mach: f64,
    pub p: f64,
    pub low: f64,
    pub high: f64,
    pub count: u64,
    pub n: u64,
    pub errors: u64,
}

/// One headline of the JSON.
#[derive(Debug, Clone, Serialize)]
pub struct HeadlineJson {
    pub conclusion: &'static str,
    pub question: &'static str,
    pub config: &'static str,
    pub command: String,
    pub inputs: Vec<InputJson>,
    pub damping_models: Vec<&'static str>,
    pub by_mach: Vec<AtMachJson>,
    /// Bounds on the claim holding at every Mach number at once.
    pub throughout_at_least: f64,
    pub throughout_at_most: f64,
    /// The factors by their total Sobol index for ζ, largest first.
    pub deciding: Vec<Deciding>,
    /// The total indices for ζ at each Mach number, in the order of
    /// `factors` (null where ζ did not vary).
    pub factors: Vec<&'static str>,
    pub total_indices_by_mach: Vec<IndicesAtMach>,
}

/// The total Sobol indices for ζ at one Mach number.
#[derive(Debug, Clone, Serialize)]
pub struct IndicesAtMach {
    pub mach: f64,
    pub total: Option<Vec<f64>>,
}

/// The section in summary.json.
#[derive(Debug, Clone, Serialize)]
pub struct CertaintyJson {
    pub samples: u64,
    pub sobol_samples: u64,
    pub seed: u64,
    pub sampling: &'static str,
    /// The largest half-width of a 95 % Wilson interval at these samples.
    pub interval_half_width: f64,
    pub headlines: Vec<HeadlineJson>,
}

impl Answer {
    fn inputs(&self) -> Vec<InputJson> {
        let Ok((study, _)) = self.headline.study() else {
            return Vec::new();
        };
        let mut v: Vec<InputJson> = study
            .inputs()
            .iter()
            .map(|i| InputJson {
                name: i.quantity.name(),
                distribution: describe(&i.dist),
                source: source(i.quantity.name()),
            })
            .collect();
        if self.models.len() > 1 {
            v.push(InputJson {
                name: "model",
                distribution: self.models.join(" or "),
                source: source("model"),
            });
        }
        v
    }

    fn json(&self, samples: u64) -> HeadlineJson {
        let (least, most) = self.throughout();
        HeadlineJson {
            conclusion: self.headline.id,
            question: self.headline.question,
            config: self.headline.file,
            command: self.headline.command(samples),
            inputs: self.inputs(),
            damping_models: self.models.clone(),
            by_mach: self
                .results
                .iter()
                .map(|s| {
                    let p = self.probability(s);
                    AtMachJson {
                        mach: s.mach,
                        p: p.p,
                        low: p.low,
                        high: p.high,
                        count: p.count,
                        n: p.n,
                        errors: s.errors,
                    }
                })
                .collect(),
            throughout_at_least: least,
            throughout_at_most: most,
            deciding: self.deciding(),
            factors: self.factors.clone(),
            total_indices_by_mach: self
                .indices
                .iter()
                .map(|s| IndicesAtMach {
                    mach: s.mach,
                    total: s
                        .sobol
                        .as_ref()
                        .and_then(|x| x.damping_ratio.as_ref())
                        .map(|ix| ix.iter().map(|i| i.total).collect()),
                })
                .collect(),
        }
    }

    /// The least and the largest probability over Mach number, with where.
    fn range(&self) -> ((f64, f64), (f64, f64)) {
        let pts = self.by_mach();
        let lo = pts
            .iter()
            .map(|(m, p)| (p.p, *m))
            .fold((2.0, 0.0), |a, b| if b.0 < a.0 { b } else { a });
        let hi = pts
            .iter()
            .map(|(m, p)| (p.p, *m))
            .fold((-1.0, 0.0), |a, b| if b.0 > a.0 { b } else { a });
        (lo, hi)
    }

    /// The answer in a sentence.
    pub fn sentence(&self) -> String {
        let ((lo, m_lo), (hi, m_hi)) = self.range();
        let (least, most) = self.throughout();
        let ms = self.mach_numbers_text();
        let all = match self.headline.claim {
            Claim::FailsStandard => "failing at every one of them at once",
            Claim::MeetsStandard => "meeting it at every one at once",
        };
        let deciding: Vec<String> = self
            .deciding()
            .iter()
            .take(2)
            .map(|d| format!("{} (total index {})", d.factor, sig(d.total, 2)))
            .collect();
        format!(
            "{}: from {} (M = {m_lo:.2}) to {} (M = {m_hi:.2}) over M {ms}; {all}: {}. Deciding inputs: {}.",
            capitalised(self.headline.question),
            percent(lo),
            percent(hi),
            percent_range(least, most),
            if deciding.is_empty() {
                "—".to_string()
            } else {
                deciding.join(", ")
            }
        )
    }

    fn mach_numbers_text(&self) -> String {
        match (self.results.first(), self.results.last()) {
            (Some(a), Some(b)) => format!("{:.2}–{:.2}", a.mach, b.mach),
            _ => "—".into(),
        }
    }
}

/// `s` with its first letter a capital.
pub fn capitalised(s: &str) -> String {
    let mut c = s.chars();
    c.next()
        .map(|f| f.to_uppercase().chain(c).collect())
        .unwrap_or_default()
}

impl Certainty {
    pub fn json(&self) -> CertaintyJson {
        CertaintyJson {
            samples: self.samples,
            sobol_samples: self.sobol_samples,
            seed: SEED,
            sampling: self.answers.first().map_or("random", |a| a.sampling.name()),
            interval_half_width: Z95 * (0.25 / self.samples as f64).sqrt(),
            headlines: self.answers.iter().map(|a| a.json(self.samples)).collect(),
        }
    }

    /// The line beside the conclusions.
    pub fn conclusion_line(&self) -> String {
        let s: Vec<String> = self.answers.iter().map(Answer::sentence).collect();
        format!(
            "How sure (section “How sure are the headline conclusions?”): {}",
            s.join(" ")
        )
    }
}

#[cfg(test)]
mod tests {
    use super::percent_range;

    #[test]
    fn equal_bounds_print_as_one_share() {
        assert_eq!(percent_range(0.0, 0.0), "0 %");
        assert_eq!(percent_range(0.03, 0.4), "between 3.0 % and 40 %");
    }
}
