//! The results of an uncertainty study (issue 23) as JSON and CSV: what
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

use crate::csv::number;
use serde::Serialize;
use stability_core::uncertainty::sobol::Indices;
use stability_core::uncertainty::stats::{Proportion, Quantiles, Z95};
use stability_core::uncertainty::{Dist, ErrorKind, Levels, Study, Summary};

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
    pub results: &'a [Summary],
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
            results,
        }
    }
}

/// The CSV rows of one Mach number's results (no header).
pub fn csv_rows(s: &Summary) -> String {
    let mut out = String::new();
    let mut row = |q: &str, v: f64, lo: f64, hi: f64| {
        out.push_str(&format!(
            "{},{q},{},{},{}\n",
            number(s.mach),
            number(v),
            number(lo),
            number(hi)
        ));
    };
    let nan = f64::NAN;
    row("samples", s.samples as f64, nan, nan);
    row("evaluated", s.evaluated as f64, nan, nan);
    row("errors", s.errors as f64, nan, nan);
    let mut p = |q: &str, p: &Proportion| row(q, p.p, p.low, p.high);
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
    if let Some(sobol) = &s.sobol {
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

fn levels(p: &mut impl FnMut(&str, &Proportion), name: &str, l: &Levels) {
    p(&format!("p_{name}_1"), &l.level_1);
    p(&format!("p_{name}_2"), &l.level_2);
    p(&format!("p_{name}_3"), &l.level_3);
    p(&format!("p_{name}_4"), &l.worse_than_level_3);
    p(&format!("p_{name}_not_assessed"), &l.not_assessed);
}

fn quantiles(row: &mut impl FnMut(&str, f64, f64, f64), name: &str, q: &Quantiles) {
    for (p, v) in q.probabilities.iter().zip(&q.values) {
        let pct = (p * 100.0).round() as u32;
        row(&format!("{name}_q{pct:02}"), *v, f64::NAN, f64::NAN);
    }
}

fn indices(row: &mut impl FnMut(&str, f64, f64, f64), output: &str, factor: &str, i: &Indices) {
    row(
        &format!("sobol_first_{output}_{factor}"),
        i.first,
        i.first - Z95 * i.first_se,
        i.first + Z95 * i.first_se,
    );
    row(
        &format!("sobol_total_{output}_{factor}"),
        i.total,
        i.total - Z95 * i.total_se,
        i.total + Z95 * i.total_se,
    );
}
