//! The run: chunks of rows drawn from their own streams, evaluated in
//! parallel, their sums added in chunk order.

use super::quasi::{Sampling, SobolSequence};
use super::sobol::SobolSums;
use super::stats::{Proportion, Reservoir};
use super::study::{
    AtMach, BATCH, CHUNK, Levels, MAX_FACTORS, Options, Outcome, Prepared, Sensitivity, Study,
    Summary,
};
use crate::criteria::Verdict;
use crate::design::case::Case;
use crate::numerics::roots::{Complex64, RootsError, solve_quartics};
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
    /// Empty, with the Sobol sums of `k` factors when `options` asks for
    /// the indices.
    fn new(options: &Options, k: usize) -> Tally {
        Tally {
            sobol: options
                .sobol
                .then(|| [SobolSums::new(k), SobolSums::new(k)]),
            ..Tally::default()
        }
    }

    /// One row's outcomes: A's, and with the indices B's then the k
    /// A_B^(i)'s — what [`AtMach::chunk_per_sample`] adds, in its order.
    fn row(&mut self, f: &[Result<Outcome, String>], k: usize) {
        self.add(&f[0]);
        let Some(sums) = &mut self.sobol else {
            return;
        };
        let mut ab = [[f64::NAN; MAX_FACTORS]; 2];
        for (i, fi) in f[2..2 + k].iter().enumerate() {
            ab[0][i] = output(fi, 0);
            ab[1][i] = output(fi, 1);
        }
        for (j, s) in sums.iter_mut().enumerate() {
            s.add(output(&f[0], j), output(&f[1], j), &ab[j][..k]);
        }
    }

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

/// Rows whose quartics are solved together by one [`solve_quartics`]
/// call (a multiple of its four lanes).
const BLOCK: usize = 32;

/// A block's samples, in row order (A; with the indices B and the
/// A_B^(i) after it), from their quartics to their outcomes. Allocated
/// once a chunk, reused block after block.
struct Block {
    prepared: Vec<Result<Prepared, String>>,
    /// The quartics of the prepared samples that have one, in order.
    coeffs: Vec<[f64; 5]>,
    roots: Vec<Result<[Complex64; 4], RootsError>>,
    outcomes: Vec<Result<Outcome, String>>,
}

impl Block {
    fn with_capacity(n: usize) -> Block {
        Block {
            prepared: Vec::with_capacity(n),
            coeffs: Vec::with_capacity(n),
            roots: Vec::with_capacity(n),
            outcomes: Vec::with_capacity(n),
        }
    }

    fn clear(&mut self) {
        self.prepared.clear();
        self.coeffs.clear();
        self.outcomes.clear();
    }

    /// Every prepared sample's roots by one [`solve_quartics`] call, and
    /// its outcome ([`Prepared::finish`]); a sample without a quartic
    /// keeps its error.
    fn solve(&mut self) {
        self.coeffs.extend(
            self.prepared
                .iter()
                .filter_map(|p| p.as_ref().ok())
                .map(|p| p.quartic.to_array()),
        );
        let n = self.coeffs.len();
        self.roots.resize(n, Err(RootsError::LeadingZero));
        solve_quartics(&self.coeffs, &mut self.roots[..n]);
        let mut roots = self.roots[..n].iter();
        for p in &self.prepared {
            self.outcomes.push(match p {
                Ok(p) => match roots.next() {
                    Some(r) => p.finish(*r),
                    None => Err("internal: a quartic without roots".to_string()),
                },
                Err(e) => Err(e.clone()),
            });
        }
    }
}

impl AtMach<'_> {
    /// Rows `rows` of chunk `chunk` (a generator on stream `chunk`), a
    /// [`BLOCK`] of rows at a time: each row's samples prepared up to
    /// their quartics, the block's quartics solved in one
    /// [`solve_quartics`] call (the bits of one [`crate::numerics::roots::solve_quartic`]
    /// each), then added row by row as [`AtMach::chunk_per_sample`] adds
    /// them.
    fn chunk(&self, options: &Options, chunk: u64, rows: usize, cases: &mut [Case]) -> Tally {
        let k = self.factors();
        let per_row = if options.sobol { k + 2 } else { 1 };
        let mut points = Points::new(options, chunk);
        let mut tally = Tally::new(options, k);
        let mut block = Block::with_capacity(BLOCK * per_row);
        let (mut za, mut zb, mut x) = ([0.0; MAX_FACTORS], [0.0; MAX_FACTORS], [0.0; MAX_FACTORS]);
        let mut first = 0;
        while first < rows {
            let end = (first + BLOCK).min(rows);
            block.clear();
            for row in first..end {
                points.fill(
                    chunk * CHUNK as u64 + row as u64,
                    &mut za[..k],
                    &mut zb[..k],
                );
                block
                    .prepared
                    .push(self.prepare_at(&za[..k], &mut x, cases));
                if !options.sobol {
                    continue;
                }
                block
                    .prepared
                    .push(self.prepare_at(&zb[..k], &mut x, cases));
                for i in 0..k {
                    let mut z = za;
                    z[i] = zb[i];
                    block.prepared.push(self.prepare_at(&z[..k], &mut x, cases));
                }
            }
            block.solve();
            for f in block.outcomes.chunks(per_row) {
                tally.row(f, k);
            }
            first = end;
        }
        tally
    }

    /// The sample at normal scores `z`, up to its quartic.
    fn prepare_at(&self, z: &[f64], x: &mut [f64], cases: &mut [Case]) -> Result<Prepared, String> {
        let model = self.values(z, x);
        self.prepare(x, model, &mut cases[model])
    }

    /// [`AtMach::chunk`] sample by sample, each quartic solved alone by
    /// [`AtMach::evaluate`]: the reference the batched path is held to.
    fn chunk_per_sample(
        &self,
        options: &Options,
        chunk: u64,
        rows: usize,
        cases: &mut [Case],
    ) -> Tally {
        let k = self.factors();
        let mut points = Points::new(options, chunk);
        let mut tally = Tally::new(options, k);
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
    /// each batch of chunks. The samples' quartics are solved many at once
    /// ([`solve_quartics`]).
    pub fn run(&self, options: &Options, progress: &(dyn Fn(u64) + Sync)) -> Summary {
        self.run_with(options, progress, true)
    }

    /// [`AtMach::run`] with each sample's quartic solved alone, as
    /// [`AtMach::evaluate`] does: the same [`Summary`], bit for bit, more
    /// slowly. The reference for tests and benchmarks.
    pub fn run_per_sample(&self, options: &Options, progress: &(dyn Fn(u64) + Sync)) -> Summary {
        self.run_with(options, progress, false)
    }

    fn run_with(
        &self,
        options: &Options,
        progress: &(dyn Fn(u64) + Sync),
        batched: bool,
    ) -> Summary {
        let n = options.samples;
        let chunks = n.div_ceil(CHUNK as u64);
        let mut total = Tally::new(options, self.factors());
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
                        match batched {
                            true => self.chunk(options, c, rows, cases),
                            false => self.chunk_per_sample(options, c, rows, cases),
                        }
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
