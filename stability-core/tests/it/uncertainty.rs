//! Uncertainty propagation (issue 23) against independent routes: a
//! single uniform input whose verdict flips at a value found by bisection
//! on the analysis; a plain-loop Monte Carlo with its own generator over
//! `evaluate` (the analyze path); the same bits on 1, 2 and 8 threads.

use rand::SeedableRng;
use rand::rngs::ChaCha12Rng;
use rand_distr::{Distribution, LogNormal, Normal, Uniform};
use stability_core::analysis::Analysis;
use stability_core::criteria::Verdict;
use stability_core::design::case::{Case, DampingModel, evaluate};
use stability_core::design::study::report_wing;
use stability_core::uncertainty::{
    Dist, ErrorKind, Input, Options, Quantity, Sampling, Study, Summary,
};

/// The 60° delta at M = 0.9 with the quasi-steady slender fairing.
fn base() -> Case {
    Case {
        damping: DampingModel::FairedSlender,
        ..report_wing(60.0, 0.9)
    }
}

fn m_q() -> Quantity {
    Quantity::parse("m_q").unwrap()
}

/// The §8 verdict of the base point with `e` added to m_q, by the full
/// analysis (eq 7's check included), not the study's path.
fn verdict_with_m_q_plus(e: f64) -> Verdict {
    let r = evaluate(&base()).unwrap();
    let d = stability_core::Derivatives {
        m_q: r.derivatives.m_q + e,
        ..r.derivatives
    };
    Analysis::of(&d).unwrap().verdict
}

/// The error at which the verdict changes, by bisection on [0, 2.2] (it is divergent from 2.3).
fn flip() -> f64 {
    let (mut lo, mut hi) = (0.0, 2.2);
    assert_eq!(verdict_with_m_q_plus(lo), Verdict::Meets);
    assert_eq!(verdict_with_m_q_plus(hi), Verdict::Fails);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        match verdict_with_m_q_plus(mid) {
            Verdict::Meets => lo = mid,
            _ => hi = mid,
        }
    }
    lo
}

fn within(p: f64, expected: f64, se: f64, what: &str) {
    assert!(
        (p - expected).abs() <= 3.0 * se,
        "{what}: {p} against {expected} (3σ = {})",
        3.0 * se
    );
}

#[test]
fn a_single_uniform_input_gives_the_fraction_of_its_range_and_sobol_indices_of_one() {
    let e_star = flip();
    assert!(e_star > 0.2 && e_star < 2.0, "{e_star}");
    let input = Input {
        quantity: m_q(),
        error: ErrorKind::Additive,
        dist: Dist::Uniform {
            low: 0.0,
            high: 2.2,
        },
    };
    let study = Study::new(base(), None, vec![input], &[], &[]).unwrap();
    let options = Options {
        samples: 20_000,
        seed: 3,
        sobol: true,
        sampling: Sampling::Random,
    };
    let s = &study.run(&[0.9], &options, &|_| {})[0];
    assert_eq!((s.samples, s.evaluated, s.errors), (20_000, 20_000, 0));
    // the verdict is met for e < e*: P = e*/2.2
    let p = e_star / 2.2;
    within(s.standard_met.p, p, s.standard_met.se(), "P(§8)");
    assert!(s.standard_met.low <= p && p <= s.standard_met.high);
    // nothing grows here: the overall verdict is the standard's
    assert_eq!(s.meets.count, s.standard_met.count);
    assert_eq!(s.divergent.count, 0);
    // one input explains all the variance
    let sobol = s.sobol.as_ref().unwrap();
    assert_eq!(sobol.factors, vec!["m_q"]);
    for ix in [&sobol.margin, &sobol.damping_ratio] {
        let i = ix.as_ref().unwrap()[0];
        within(i.first, 1.0, i.first_se, "S1");
        within(i.total, 1.0, i.total_se, "ST");
        assert!(i.first_se < 0.05 && i.total_se < 0.05, "{i:?}");
    }
}

/// Three inputs, one of which (the c.g.) needs the aerodynamics again.
fn three_inputs() -> Vec<Input> {
    vec![
        Input {
            quantity: Quantity::IB,
            error: ErrorKind::Value,
            dist: Dist::LogNormal {
                mu: 0.08f64.ln(),
                sigma: 0.3,
            },
        },
        Input {
            quantity: m_q(),
            error: ErrorKind::Additive,
            dist: Dist::Normal { mean: 1.9, sd: 0.6 },
        },
        Input {
            quantity: Quantity::Cg,
            error: ErrorKind::Value,
            dist: Dist::Uniform {
                low: 0.2,
                high: 0.4,
            },
        },
    ]
}

#[test]
fn the_probabilities_agree_with_a_plain_loop_monte_carlo() {
    let n = 3000;
    let study = Study::new(base(), None, three_inputs(), &[], &[]).unwrap();
    let options = Options {
        samples: n,
        seed: 11,
        sobol: false,
        sampling: Sampling::Random,
    };
    let s = &study.run(&[0.9], &options, &|_| {})[0];
    assert_eq!(s.errors, 0);
    // an independent loop: its own generator and distributions, the
    // analyze path (`evaluate`, eq 7's check and all)
    let mut rng = ChaCha12Rng::seed_from_u64(2024);
    let ib = LogNormal::new(0.08f64.ln(), 0.3).unwrap();
    let mq = Normal::new(1.9, 0.6).unwrap();
    let cg = Uniform::new(0.2, 0.4).unwrap();
    let (mut met, mut divergent, mut zeta) = (0u64, 0u64, Vec::new());
    for _ in 0..n {
        let case = Case {
            i_b: ib.sample(&mut rng),
            h: cg.sample(&mut rng),
            ..base()
        };
        let e = mq.sample(&mut rng);
        let r = evaluate(&case).unwrap();
        let d = stability_core::Derivatives {
            m_q: r.derivatives.m_q + e,
            ..r.derivatives
        };
        let a = Analysis::of(&d).unwrap();
        met += u64::from(a.verdict.is_met());
        divergent +=
            u64::from(stability_core::analysis::verdict::overall(&a) == Verdict::Divergent);
        if let Some(z) = a.modes.short_period().and_then(|m| m.damping_ratio) {
            zeta.push(z);
        }
    }
    let p_loop = met as f64 / n as f64;
    let se = |p: f64| (p * (1.0 - p) / n as f64).sqrt();
    let se2 = (se(p_loop).powi(2) + s.standard_met.se().powi(2)).sqrt();
    assert!(
        p_loop > 0.2 && p_loop < 0.8,
        "a case with both verdicts: {p_loop}"
    );
    within(s.standard_met.p, p_loop, se2, "P(§8) against the loop");
    let d_loop = divergent as f64 / n as f64;
    let se2 = (se(d_loop).powi(2) + s.divergent.se().powi(2))
        .sqrt()
        .max(1.0 / n as f64);
    within(s.divergent.p, d_loop, se2, "P(divergent) against the loop");
    // the medians of ζ: within a few standard errors of a median
    zeta.sort_by(f64::total_cmp);
    let median = zeta[zeta.len() / 2];
    let q = &s.damping_ratio;
    let (q25, q75) = (q.values[2], q.values[4]);
    let se_median = 1.2533 * (q75 - q25) / 1.349 / (n as f64).sqrt();
    within(q.values[3], median, 2.0f64.sqrt() * se_median, "median ζ");
}

fn run_on(threads: usize, study: &Study) -> Vec<Summary> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap();
    let options = Options {
        samples: 40_000,
        seed: 123_456_789,
        sobol: true,
        sampling: Sampling::Random,
    };
    pool.install(|| study.run(&[0.9, 1.5], &options, &|_| {}))
}

#[test]
fn a_seed_gives_the_same_bits_on_1_2_and_8_threads() {
    let mut inputs = three_inputs();
    inputs.truncate(2); // the quartic-only path; the c.g.'s below
    let study = Study::new(
        base(),
        None,
        inputs,
        &[("i_b".into(), "m_q".into(), -0.4)],
        &[
            (DampingModel::FairedSlender, 3.0),
            (DampingModel::parse("slender").unwrap(), 1.0),
        ],
    )
    .unwrap();
    let one = format!("{:?}", run_on(1, &study));
    assert_eq!(one, format!("{:?}", run_on(2, &study)));
    assert_eq!(one, format!("{:?}", run_on(8, &study)));
    // and the path that evaluates each design point
    let study = Study::new(base(), None, three_inputs(), &[], &[]).unwrap();
    let options = Options {
        samples: 3000,
        seed: 5,
        sobol: false,
        sampling: Sampling::Random,
    };
    let on = |t| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(t)
            .build()
            .unwrap();
        format!(
            "{:?}",
            pool.install(|| study.run(&[0.9], &options, &|_| {}))
        )
    };
    assert_eq!(on(1), on(8));
}

#[test]
fn model_form_uncertainty_weighs_each_theorys_probability() {
    // m_q's error uniform: each theory alone, then both with weights 1 : 3
    let input = || Input {
        quantity: m_q(),
        error: ErrorKind::Multiplicative,
        dist: Dist::Uniform {
            low: 0.0,
            high: 1.0,
        },
    };
    let options = Options {
        samples: 20_000,
        seed: 9,
        sobol: true,
        sampling: Sampling::Random,
    };
    let at = |b: Case| Case { mach: 1.5, ..b };
    let alone = |m: DampingModel| {
        let s = Study::new(at(base()), None, vec![input()], &[], &[(m, 1.0)]).unwrap();
        s.run(&[1.5], &options, &|_| {})[0].standard_met
    };
    let (a, b) = (
        DampingModel::FairedSlender,
        DampingModel::parse("supersonic").unwrap(),
    );
    let (pa, pb) = (alone(a), alone(b));
    let both = Study::new(at(base()), None, vec![input()], &[], &[(a, 1.0), (b, 3.0)]).unwrap();
    let s = &both.run(&[1.5], &options, &|_| {})[0];
    let expected = 0.25 * pa.p + 0.75 * pb.p;
    let se =
        (s.standard_met.se().powi(2) + (0.25 * pa.se()).powi(2) + (0.75 * pb.se()).powi(2)).sqrt();
    within(s.standard_met.p, expected, se, "the weighted theories");
    assert_eq!(s.sobol.as_ref().unwrap().factors, vec!["m_q", "model"]);
}

#[test]
fn samples_without_a_result_are_counted_not_fatal() {
    // i_B normal about 0.08 with sd 0.08: about 16 % negative
    let input = Input {
        quantity: Quantity::IB,
        error: ErrorKind::Value,
        dist: Dist::Normal {
            mean: 0.08,
            sd: 0.08,
        },
    };
    let study = Study::new(base(), None, vec![input], &[], &[]).unwrap();
    let options = Options {
        samples: 10_000,
        seed: 1,
        sobol: true,
        sampling: Sampling::Random,
    };
    let s = &study.run(&[0.9], &options, &|_| {})[0];
    let p_neg = 0.158_655_253_931_457; // Φ(−1)
    let p = s.errors as f64 / s.samples as f64;
    within(p, p_neg, (p_neg * (1.0 - p_neg) / 1e4).sqrt(), "P(i_B ≤ 0)");
    assert!(
        s.first_error.as_ref().unwrap().contains("i_b"),
        "{:?}",
        s.first_error
    );
    assert_eq!(s.evaluated + s.errors, s.samples);
}

#[test]
fn a_study_that_cannot_run_says_why() {
    let err = |inputs, corr: &[(String, String, f64)]| {
        Study::new(base(), None, inputs, corr, &[])
            .unwrap_err()
            .to_string()
    };
    let ib = |sd| Input {
        quantity: Quantity::IB,
        error: ErrorKind::Value,
        dist: Dist::Normal { mean: 0.08, sd },
    };
    assert!(err(vec![ib(-1.0)], &[]).contains("sd must not be negative"));
    assert!(err(vec![ib(0.01), ib(0.01)], &[]).contains("twice"));
    let mass = Input {
        quantity: Quantity::Mass,
        ..ib(0.01)
    };
    assert!(err(vec![mass], &[]).contains("physical flight condition"));
    assert!(err(vec![ib(0.01)], &[("i_b".into(), "mu1".into(), 0.5)]).contains("`mu1`"));
}
