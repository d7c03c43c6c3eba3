//! The run: chunks of rows drawn from their own streams, evaluated in
//! parallel, their sums added in chunk order.

use super::quasi::{Sampling, SobolSequence};
use super::sobol::SobolSums;
use super::stats::{Proportion, Reservoir};
use super::study::{
    AtMach, BATCH, CHUNK, Levels, MAX_FACTORS, Options, Outcome, Sensitivity, Study, Summary,
};
use crate::case::Case;
use crate::criteria::Verdict;
use rand::rngs::ChaCha8Rng;
use rand::{RngExt, SeedableRng};
use rand_distr::StandardNormal;
use rayon::prelude::*;

/// Where a chunk's normal scores come from: its ChaCha8 stream, or the
/// scrambled Sobol′ points by their index ([`super::quasi`]).
enum Points {
    Random(Box<ChaCha8Rng>),
    /// The sequence, and whether B's coordinates are needed (the Sobol
    /// indices).
    Sobol(SobolSequence, bool),
}

impl Points {
    fn new(options: &Options, chunk: u64) -> Points {
        match options.sampling {
            Sampling::Random => {
                let mut rng = ChaCha8Rng::seed_from_u64(options.seed);
                rng.set_stream(chunk);
                Points::Random(Box::new(rng))
            }
            Sampling::Sobol => Points::Sobol(SobolSequence::new(options.seed), options.sobol),
        }
    }

    /// Row `index`'s scores of A and of B: random, A's then B's (B's drawn
    /// whether or not, to keep the stream); Sobol′, coordinates 0..k and,
    /// for the indices, k..2k of point `index` (Saltelli 2010 §3).
    #[inline]
    fn fill(&mut self, index: u64, za: &mut [f64], zb: &mut [f64]) {
        match self {
            Points::Random(rng) => {
                for z in za.iter_mut().chain(zb.iter_mut()) {
                    *z = rng.sample(StandardNormal);
                }
            }
            Points::Sobol(seq, with_b) => {
                let k = za.len() as u32;
                for (d, z) in za.iter_mut().enumerate() {
                    *z = seq.normal(index, d as u32);
                }
                if !*with_b {
                    return;
                }
                for (d, z) in zb.iter_mut().enumerate() {
                    *z = seq.normal(index, k + d as u32);
                }
            }
        }
    }
}

/// The sums of consecutive rows.
#[derive(Debug, Clone, Default)]
struct Tally {
    samples: u64,
    evaluated: u64,
    errors: u64,
    first_error: Option<String>,
    standard: u64,
    /// meets, fails, divergent
    overall: [u64; 3],
    /// per level kind (sp A, B, C, phugoid): counts of 0 (not assessed), 1–4
    levels: [[u64; 5]; 4],
    cycles: Vec<f64>,
    zeta: Vec<f64>,
    sobol: Option<[SobolSums; 2]>,
}

impl Tally {
    fn add(&mut self, o: &Result<Outcome, String>) {
        self.samples += 1;
        let o = match o {
            Ok(o) => o,
            Err(e) => {
                self.errors += 1;
                if self.first_error.is_none() {
                    self.first_error = Some(e.clone());
                }
                return;
            }
        };
        self.evaluated += 1;
        self.standard += u64::from(o.standard.is_met());
        self.overall[match o.overall {
            Verdict::Meets => 0,
            Verdict::Fails => 1,
            Verdict::Divergent => 2,
        }] += 1;
        for (counts, &l) in self.levels.iter_mut().zip(&o.levels) {
            counts[usize::from(l)] += 1;
        }
        self.cycles.push(o.cycles_to_half);
        self.zeta.push(o.damping_ratio);
    }

    /// Another chunk's tally after this one's; the reservoirs take its
    /// values in order.
    fn merge(&mut self, o: Tally, cycles: &mut Reservoir, zeta: &mut Reservoir) {
        self.samples += o.samples;
        self.evaluated += o.evaluated;
        self.errors += o.errors;
        if self.first_error.is_none() {
            self.first_error = o.first_error;
        }
        self.standard += o.standard;
        for k in 0..3 {
            self.overall[k] += o.overall[k];
        }
        for (a, b) in self.levels.iter_mut().zip(&o.levels) {
            a.iter_mut().zip(b).for_each(|(a, b)| *a += b);
        }
        o.cycles.iter().for_each(|&v| cycles.push(v));
        o.zeta.iter().for_each(|&v| zeta.push(v));
        if let (Some(a), Some(b)) = (&mut self.sobol, &o.sobol) {
            a[0].merge(&b[0]);
            a[1].merge(&b[1]);
        }
    }
}

impl AtMach<'_> {
    /// Rows `rows` of chunk `chunk` (a generator on stream `chunk`).
    fn chunk(&self, options: &Options, chunk: u64, rows: usize, cases: &mut [Case]) -> Tally {
        let k = self.factors();
        let mut points = Points::new(options, chunk);
        let mut tally = Tally {
            sobol: options
                .sobol
                .then(|| [SobolSums::new(k), SobolSums::new(k)]),
            ..Tally::default()
        };
        let (mut za, mut zb, mut x) = ([0.0; MAX_FACTORS], [0.0; MAX_FACTORS], [0.0; MAX_FACTORS]);
        let mut ab = [[f64::NAN; MAX_FACTORS]; 2];
        for row in 0..rows {
            points.fill(
                chunk * CHUNK as u64 + row as u64,
                &mut za[..k],
                &mut zb[..k],
            );
            let fa = self.sample(&za[..k], &mut x, cases);
            tally.add(&fa);
            let Some(sums) = &mut tally.sobol else {
                continue;
            };
            let fb = self.sample(&zb[..k], &mut x, cases);
            for i in 0..k {
                let mut z = za;
                z[i] = zb[i];
                let f = self.sample(&z[..k], &mut x, cases);
                ab[0][i] = output(&f, 0);
                ab[1][i] = output(&f, 1);
            }
            for (j, s) in sums.iter_mut().enumerate() {
                s.add(output(&fa, j), output(&fb, j), &ab[j][..k]);
            }
        }
        tally
    }

    fn sample(&self, z: &[f64], x: &mut [f64], cases: &mut [Case]) -> Result<Outcome, String> {
        let model = self.values(z, x);
        self.evaluate(x, model, &mut cases[model])
    }

    /// The run at this Mach number; `progress` is told the rows done after
    /// each batch of chunks.
    pub fn run(&self, options: &Options, progress: &(dyn Fn(u64) + Sync)) -> Summary {
        let n = options.samples;
        let chunks = n.div_ceil(CHUNK as u64);
        let mut total = Tally {
            sobol: options.sobol.then(|| {
                [
                    SobolSums::new(self.factors()),
                    SobolSums::new(self.factors()),
                ]
            }),
            ..Tally::default()
        };
        let mut cycles = Reservoir::new(options.seed);
        let mut zeta = Reservoir::new(options.seed ^ 0x9e37_79b9_7f4a_7c15);
        let mut first = 0;
        while first < chunks {
            let last = (first + BATCH as u64).min(chunks);
            let tallies: Vec<Tally> = (first..last)
                .into_par_iter()
                .map_init(
                    || self.cases().to_vec(),
                    |cases, c| {
                        let rows = (n - c * CHUNK as u64).min(CHUNK as u64) as usize;
                        self.chunk(options, c, rows, cases)
                    },
                )
                .collect();
            for t in tallies {
                total.merge(t, &mut cycles, &mut zeta);
            }
            progress(total.samples);
            first = last;
        }
        self.summary(total, &cycles, &zeta)
    }

    fn summary(&self, t: Tally, cycles: &Reservoir, zeta: &Reservoir) -> Summary {
        let e = t.evaluated;
        let sobol = t.sobol.map(|[m, z]| Sensitivity {
            factors: self.study().factor_names(),
            margin: m.indices(),
            damping_ratio: z.indices(),
            margin_rows: m.rows(),
            damping_ratio_rows: z.rows(),
        });
        Summary {
            mach: self.mach(),
            samples: t.samples,
            evaluated: e,
            errors: t.errors,
            first_error: t.first_error,
            standard_met: Proportion::of(t.standard, e),
            meets: Proportion::of(t.overall[0], e),
            fails: Proportion::of(t.overall[1], e),
            divergent: Proportion::of(t.overall[2], e),
            short_period_level_a: Levels::of(&t.levels[0], e),
            short_period_level_b: Levels::of(&t.levels[1], e),
            short_period_level_c: Levels::of(&t.levels[2], e),
            phugoid_level: Levels::of(&t.levels[3], e),
            cycles_to_half: cycles.quantiles(),
            damping_ratio: zeta.quantiles(),
            sobol,
        }
    }
}

/// Output `j` of a sample for the Sobol indices: 0 the margin Δm_θ̇, 1 ζ
/// (NaN where it has none or failed).
fn output(f: &Result<Outcome, String>, j: usize) -> f64 {
    match f {
        Ok(o) if j == 0 => o.margin,
        Ok(o) => o.damping_ratio,
        Err(_) => f64::NAN,
    }
}

impl Study {
    /// The run at each of `machs`, in order.
    pub fn run(
        &self,
        machs: &[f64],
        options: &Options,
        progress: &(dyn Fn(u64) + Sync),
    ) -> Vec<Summary> {
        machs
            .iter()
            .map(|&m| self.at_mach(m).run(options, progress))
            .collect()
    }
}
