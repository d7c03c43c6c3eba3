//! The run's batched root solving (issue 23 item 3): the samples'
//! quartics solved a block at a time by `solve_quartics` give the same
//! [`Summary`], bit for bit (every count, proportion, quantile and Sobol
//! index, compared through their `Debug` text, which prints each f64
//! exactly), as the reference path that solves each sample's quartic
//! alone (`run_per_sample`, `evaluate`'s own path) — with samples that
//! fail (i_B ≤ 0), that diverge and that meet the standard, random and
//! Sobol′ points, with and without the indices, a sample count that
//! leaves a short block and a short chunk, and two damping theories.

use stability_core::design::case::{Case, DampingModel};
use stability_core::design::study::report_wing;
use stability_core::uncertainty::{
    Dist, ErrorKind, Input, Options, Quantity, Sampling, Study, Summary,
};

/// The 60° delta with the quasi-steady slender fairing.
fn base(mach: f64) -> Case {
    Case {
        damping: DampingModel::FairedSlender,
        ..report_wing(60.0, mach)
    }
}

/// i_B normal wide enough that some draws are ≤ 0 (errors), m_q's error
/// additive and wide enough that some samples diverge and some meet.
fn inputs(cg: bool) -> Vec<Input> {
    let mut v = vec![
        Input {
            quantity: Quantity::IB,
            error: ErrorKind::Value,
            dist: Dist::Normal {
                mean: 0.08,
                sd: 0.035,
            },
        },
        Input {
            quantity: Quantity::parse("m_q").unwrap(),
            error: ErrorKind::Additive,
            dist: Dist::Normal { mean: 1.9, sd: 1.2 },
        },
    ];
    if cg {
        v.push(Input {
            quantity: Quantity::Cg,
            error: ErrorKind::Value,
            dist: Dist::Uniform {
                low: 0.2,
                high: 0.4,
            },
        });
    }
    v
}

/// Both paths on one study and options, on one thread; the batched
/// summaries returned after the comparison.
fn both(study: &Study, machs: &[f64], options: &Options) -> Vec<Summary> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    let (batched, reference): (Vec<_>, Vec<_>) = pool.install(|| {
        machs
            .iter()
            .map(|&m| {
                let at = study.at_mach(m);
                (
                    at.run(options, &|_| {}),
                    at.run_per_sample(options, &|_| {}),
                )
            })
            .unzip()
    });
    assert_eq!(format!("{batched:?}"), format!("{reference:?}"));
    batched
}

/// The summary has samples of every kind, so the comparison covers them.
fn assert_varied(s: &Summary) {
    assert!(s.errors > 0, "no sample failed at M = {}", s.mach);
    assert!(s.meets.count > 0, "no sample meets at M = {}", s.mach);
    assert!(
        s.divergent.count > 0,
        "no sample diverges at M = {}",
        s.mach
    );
    assert_eq!(s.evaluated + s.errors, s.samples);
}

#[test]
fn batched_roots_give_the_per_sample_summary_bit_for_bit() {
    let study = Study::new(base(1.5), None, inputs(false), &[], &[]).unwrap();
    for sampling in [Sampling::Random, Sampling::Sobol] {
        let options = Options {
            samples: 2 * 256 + 37, // a short chunk, a short block
            seed: 77,
            sobol: false,
            sampling,
        };
        for s in both(&study, &[0.9, 1.5], &options) {
            assert_eq!(s.samples, 549);
            assert_varied(&s);
        }
    }
}

#[test]
fn batched_roots_give_the_per_sample_sobol_indices_bit_for_bit() {
    let study = Study::new(
        base(1.5),
        None,
        inputs(false),
        &[("i_b".into(), "m_q".into(), 0.3)],
        &[
            (DampingModel::FairedSlender, 3.0),
            (DampingModel::parse("slender").unwrap(), 1.0),
        ],
    )
    .unwrap();
    for sampling in [Sampling::Random, Sampling::Sobol] {
        let options = Options {
            samples: 300,
            seed: 4,
            sobol: true,
            sampling,
        };
        for s in both(&study, &[1.5], &options) {
            assert_varied(&s);
            let sens = s.sobol.as_ref().expect("the indices were asked for");
            assert_eq!(sens.factors, ["i_b", "m_q", "model"]);
            assert!(sens.margin_rows > 0 && sens.damping_ratio_rows > 0);
        }
    }
}

#[test]
fn batched_roots_give_the_per_sample_summary_where_each_sample_is_a_design_point() {
    // the c.g. uncertain: every sample evaluates its design point, then
    // its quartic is solved in the block
    let study = Study::new(base(1.5), None, inputs(true), &[], &[]).unwrap();
    let options = Options {
        samples: 200,
        seed: 31,
        sobol: false,
        sampling: Sampling::Random,
    };
    let s = &both(&study, &[1.5], &options)[0];
    assert_varied(s);
}
