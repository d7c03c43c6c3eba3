//! The results of an uncertainty study as JSON and CSV: what
//! `delta-stability uncertainty` writes and Python's `uncertainty()`
//! returns.
//!
//! The CSV is long: one row per (Mach number, quantity), with the value
//! and its 95 % interval — `p_standard_met` (the §8 one-cycle standard on
//! the short period), `p_meets`, `p_fails`, `p_divergent` (the overall
//! verdict, every root judged), `p_sp_level_a_1` … `p_sp_level_c_4`,
//! `p_sp_level_a_not_assessed`, `p_ph_level_1` …, the quantiles
//! `cycles_to_half_q05` …, `damping_ratio_q50` …, and with Sobol indices
//! `sobol_first_margin_i_b`, `sobol_total_damping_ratio_m_q`, … (the
//! interval ±1.96 standard errors); also `samples`, `evaluated`,
//! `errors`.
//!
//! A proportion of no samples, or a quantile of none, has no value: it is
//! `None` in the views ([`SummaryJson`]: `null` in JSON, empty in the CSV,
//! "—" on the page), so that every number left is checked finite by the
//! guard every writer passes ([`crate::finite`]).

use crate::csv::number;
use serde::Serialize;
use stability_core::uncertainty::sobol::Indices;
use stability_core::uncertainty::stats::{Proportion, Quantiles, Z95};
use stability_core::uncertainty::{Dist, ErrorKind, Levels, Sensitivity, Study, Summary};

/// The CSV's header.
pub const CSV_HEADER: &str = "mach,quantity,value,low,high";

/// One uncertain input, for JSON.
#[derive(Debug, Clone, Serialize)]
pub struct InputJson {
    pub name: &'static str,
    pub error: &'static str,
    pub dist: &'static str,
}

/// The whole run, for JSON.
#[derive(Debug, Clone, Serialize)]
pub struct UncertaintyJson<'a> {
    pub file: &'a str,
    pub samples: u64,
    pub seed: u64,
    pub sobol: bool,
    /// "random" or "sobol" (Owen-scrambled Sobol′ points).
    pub sampling: &'static str,
    pub inputs: Vec<InputJson>,
    pub damping_models: Vec<&'static str>,
    pub results: Vec<SummaryJson<'a>>,
}

/// A proportion of samples: its value and 95 % interval absent when it is
/// of no samples (`n` = 0).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ProportionJson {
    pub count: u64,
    pub n: u64,
    pub p: Option<f64>,
    pub low: Option<f64>,
    pub high: Option<f64>,
}

impl From<&Proportion> for ProportionJson {
    fn from(p: &Proportion) -> Self {
        let of = |v: f64| (p.n > 0).then_some(v);
        ProportionJson {
            count: p.count,
            n: p.n,
            p: of(p.p),
            low: of(p.low),
            high: of(p.high),
        }
    }
}

/// The MIL-F-8785C levels' proportions.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LevelsJson {
    pub level_1: ProportionJson,
    pub level_2: ProportionJson,
    pub level_3: ProportionJson,
    pub worse_than_level_3: ProportionJson,
    pub not_assessed: ProportionJson,
}

impl From<&Levels> for LevelsJson {
    fn from(l: &Levels) -> Self {
        LevelsJson {
            level_1: (&l.level_1).into(),
            level_2: (&l.level_2).into(),
            level_3: (&l.level_3).into(),
            worse_than_level_3: (&l.worse_than_level_3).into(),
            not_assessed: (&l.not_assessed).into(),
        }
    }
}

/// Quantiles: absent when no sample had the quantity (`n` = 0).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct QuantilesJson {
    pub n: u64,
    pub probabilities: Vec<f64>,
    pub values: Vec<Option<f64>>,
}

impl From<&Quantiles> for QuantilesJson {
    fn from(q: &Quantiles) -> Self {
        QuantilesJson {
            n: q.n,
            probabilities: q.probabilities.clone(),
            values: q.values.iter().map(|&v| (q.n > 0).then_some(v)).collect(),
        }
    }
}

/// One Mach number's results as they are written ([`Summary`]'s fields,
/// with what is of no samples absent).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SummaryJson<'a> {
    pub mach: f64,
    pub samples: u64,
    pub evaluated: u64,
    pub errors: u64,
    pub first_error: Option<&'a str>,
    pub standard_met: ProportionJson,
    pub meets: ProportionJson,
    pub fails: ProportionJson,
    pub divergent: ProportionJson,
    pub short_period_level_a: LevelsJson,
    pub short_period_level_b: LevelsJson,
    pub short_period_level_c: LevelsJson,
    pub phugoid_level: LevelsJson,
    pub cycles_to_half: QuantilesJson,
    pub damping_ratio: QuantilesJson,
    pub sobol: Option<&'a Sensitivity>,
}

impl<'a> From<&'a Summary> for SummaryJson<'a> {
    fn from(s: &'a Summary) -> Self {
        SummaryJson {
            mach: s.mach,
            samples: s.samples,
            evaluated: s.evaluated,
            errors: s.errors,
            first_error: s.first_error.as_deref(),
            standard_met: (&s.standard_met).into(),
            meets: (&s.meets).into(),
            fails: (&s.fails).into(),
            divergent: (&s.divergent).into(),
            short_period_level_a: (&s.short_period_level_a).into(),
            short_period_level_b: (&s.short_period_level_b).into(),
            short_period_level_c: (&s.short_period_level_c).into(),
            phugoid_level: (&s.phugoid_level).into(),
            cycles_to_half: (&s.cycles_to_half).into(),
            damping_ratio: (&s.damping_ratio).into(),
            sobol: s.sobol.as_ref(),
        }
    }
}

impl SummaryJson<'_> {
    /// Whether no sample had a result at this Mach number.
    pub fn no_result(&self) -> bool {
        self.evaluated == 0
    }
}

impl<'a> UncertaintyJson<'a> {
    pub fn new(
        file: &'a str,
        study: &Study,
        options: &stability_core::uncertainty::Options,
        results: &'a [Summary],
    ) -> Self {
        let inputs = study
            .inputs()
            .iter()
            .map(|i| InputJson {
                name: i.quantity.name(),
                error: match i.error {
                    ErrorKind::Value => "value",
                    ErrorKind::Multiplicative => "multiplicative",
                    ErrorKind::Additive => "additive",
                },
                dist: Dist::name(&i.dist),
            })
            .collect();
        UncertaintyJson {
            file,
            samples: options.samples,
            seed: options.seed,
            sobol: options.sobol,
            sampling: options.sampling.name(),
            inputs,
            damping_models: study.models().iter().map(|m| m.name()).collect(),
            results: results.iter().map(SummaryJson::from).collect(),
        }
    }

    /// The view, every number in it finite ([`crate::finite::guard`]), and
    /// at least one Mach number with a result: else an error about the
    /// config `file`, saying why there is none.
    pub fn checked(self) -> Result<Self, crate::diag::InputError> {
        if let Some(r) = self.results.first()
            && self.results.iter().all(SummaryJson::no_result)
        {
            let machs: Vec<String> = self
                .results
                .iter()
                .map(|r| stability_core::numerics::display::Num(r.mach).to_string())
                .collect();
            return Err(crate::diag::InputError::file(
                self.file,
                format!(
                    "no sample has a result at any Mach number asked for (M = {}), so there is nothing to report; the first error, at M = {}: {}",
                    machs.join(", "),
                    stability_core::numerics::display::Num(r.mach),
                    r.first_error.unwrap_or("none given")
                ),
            ));
        }
        crate::finite::guard(self.file, &self)?;
        Ok(self)
    }
}

/// A value of the CSV: empty where absent.
fn cell(v: Option<f64>) -> String {
    v.map(number).unwrap_or_default()
}

/// The CSV rows of one Mach number's results (no header).
pub fn csv_rows(s: &Summary) -> String {
    csv_rows_of(&SummaryJson::from(s))
}

/// [`csv_rows`] of the view.
pub fn csv_rows_of(s: &SummaryJson<'_>) -> String {
    let mut out = String::new();
    let mut row = |q: &str, v: Option<f64>, lo: Option<f64>, hi: Option<f64>| {
        out.push_str(&format!(
            "{},{q},{},{},{}\n",
            number(s.mach),
            cell(v),
            cell(lo),
            cell(hi)
        ));
    };
    row("samples", Some(s.samples as f64), None, None);
    row("evaluated", Some(s.evaluated as f64), None, None);
    row("errors", Some(s.errors as f64), None, None);
    let mut p = |q: &str, p: &ProportionJson| row(q, p.p, p.low, p.high);
    p("p_standard_met", &s.standard_met);
    p("p_meets", &s.meets);
    p("p_fails", &s.fails);
    p("p_divergent", &s.divergent);
    for (name, l) in [
        ("sp_level_a", &s.short_period_level_a),
        ("sp_level_b", &s.short_period_level_b),
        ("sp_level_c", &s.short_period_level_c),
        ("ph_level", &s.phugoid_level),
    ] {
        levels(&mut p, name, l);
    }
    quantiles(&mut row, "cycles_to_half", &s.cycles_to_half);
    quantiles(&mut row, "damping_ratio", &s.damping_ratio);
    if let Some(sobol) = s.sobol {
        for (output, ix) in [
            ("margin", &sobol.margin),
            ("damping_ratio", &sobol.damping_ratio),
        ] {
            for (factor, i) in sobol.factors.iter().zip(ix.iter().flatten()) {
                indices(&mut row, output, factor, i);
            }
        }
    }
    out
}

type Row<'r> = dyn FnMut(&str, Option<f64>, Option<f64>, Option<f64>) + 'r;

fn levels(p: &mut impl FnMut(&str, &ProportionJson), name: &str, l: &LevelsJson) {
    p(&format!("p_{name}_1"), &l.level_1);
    p(&format!("p_{name}_2"), &l.level_2);
    p(&format!("p_{name}_3"), &l.level_3);
    p(&format!("p_{name}_4"), &l.worse_than_level_3);
    p(&format!("p_{name}_not_assessed"), &l.not_assessed);
}

fn quantiles(row: &mut Row<'_>, name: &str, q: &QuantilesJson) {
    for (p, v) in q.probabilities.iter().zip(&q.values) {
        let pct = (p * 100.0).round() as u32;
        row(&format!("{name}_q{pct:02}"), *v, None, None);
    }
}

fn indices(row: &mut Row<'_>, output: &str, factor: &str, i: &Indices) {
    row(
        &format!("sobol_first_{output}_{factor}"),
        Some(i.first),
        Some(i.first - Z95 * i.first_se),
        Some(i.first + Z95 * i.first_se),
    );
    row(
        &format!("sobol_total_{output}_{factor}"),
        Some(i.total),
        Some(i.total - Z95 * i.total_se),
        Some(i.total + Z95 * i.total_se),
    );
}
