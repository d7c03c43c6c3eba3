//! Streaming statistics of a Monte Carlo run: proportions with their
//! confidence intervals, and quantiles from a fixed-size reservoir.

use rand::rngs::ChaCha8Rng;
use rand::{RngExt, SeedableRng};
use serde::Serialize;

/// z of the two-sided 95 % interval, Φ⁻¹(0.975).
pub const Z95: f64 = 1.959_963_984_540_054;

/// A proportion of samples, with its 95 % Wilson score interval (Wilson
/// 1927, *J. Amer. Statist. Assoc.* 22:209–212; recommended over the
/// normal approximation by Brown, Cai & DasGupta 2001, *Statist. Sci.*
/// 16:101–133): well-behaved at p near 0 or 1 and for small n.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Proportion {
    pub count: u64,
    pub n: u64,
    /// count/n (NaN when n = 0).
    pub p: f64,
    pub low: f64,
    pub high: f64,
}

impl Proportion {
    pub fn of(count: u64, n: u64) -> Proportion {
        if n == 0 {
            return Proportion {
                count,
                n,
                p: f64::NAN,
                low: f64::NAN,
                high: f64::NAN,
            };
        }
        let nf = n as f64;
        let p = count as f64 / nf;
        let z2 = Z95 * Z95;
        let centre = (p + z2 / (2.0 * nf)) / (1.0 + z2 / nf);
        let half = Z95 / (1.0 + z2 / nf) * (p * (1.0 - p) / nf + z2 / (4.0 * nf * nf)).sqrt();
        Proportion {
            count,
            n,
            p,
            // exact at the ends: 0 of n has 0 as its lower bound
            low: if count == 0 {
                0.0
            } else {
                (centre - half).max(0.0)
            },
            high: if count == n {
                1.0
            } else {
                (centre + half).min(1.0)
            },
        }
    }

    /// The binomial standard error √(p(1−p)/n).
    pub fn se(&self) -> f64 {
        (self.p * (1.0 - self.p) / self.n as f64).sqrt()
    }
}

/// Values kept for quantiles: every one up to the capacity, then a
/// uniform random subset of that size (Vitter's Algorithm R, *ACM Trans.
/// Math. Softw.* 11:37–57, 1985), fed in sample order from its own
/// seeded stream — so the same seed keeps the same values. The quantiles
/// are exact up to [`RESERVOIR`] values; beyond, those of a simple random
/// sample of that size (a standard error of about √(p(1−p)/65536) ≈ 0.002
/// in probability at the median). Chosen over the P² estimator (Jain &
/// Chlamtac 1985), whose error has no such bound.
#[derive(Debug)]
pub struct Reservoir {
    seen: u64,
    values: Vec<f64>,
    rng: ChaCha8Rng,
}

/// The reservoir's capacity.
pub const RESERVOIR: usize = 1 << 16;

/// The quantiles reported.
pub const PROBABILITIES: [f64; 7] = [0.01, 0.05, 0.25, 0.5, 0.75, 0.95, 0.99];

/// A distribution's quantiles at [`PROBABILITIES`], with how many values
/// they are of.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Quantiles {
    /// The samples that had the quantity.
    pub n: u64,
    pub probabilities: Vec<f64>,
    /// NaN where there were none.
    pub values: Vec<f64>,
}

impl Reservoir {
    pub fn new(seed: u64) -> Reservoir {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        rng.set_stream(u64::MAX);
        Reservoir {
            seen: 0,
            values: Vec::new(),
            rng,
        }
    }

    /// One value (NaN ones are not values).
    pub fn push(&mut self, v: f64) {
        if v.is_nan() {
            return;
        }
        self.seen += 1;
        if self.values.len() < RESERVOIR {
            self.values.push(v);
        } else {
            let k = self.rng.random_range(0..self.seen);
            if (k as usize) < RESERVOIR {
                self.values[k as usize] = v;
            }
        }
    }

    /// The quantiles (type 7 of Hyndman & Fan 1996: linear between order
    /// statistics, numpy's and R's default).
    pub fn quantiles(&self) -> Quantiles {
        let mut v = self.values.clone();
        v.sort_by(f64::total_cmp);
        let q = |p: f64| {
            if v.is_empty() {
                return f64::NAN;
            }
            let h = (v.len() - 1) as f64 * p;
            let (lo, frac) = (h.floor() as usize, h - h.floor());
            let hi = (lo + 1).min(v.len() - 1);
            v[lo] + frac * (v[hi] - v[lo])
        };
        Quantiles {
            n: self.seen,
            probabilities: PROBABILITIES.to_vec(),
            values: PROBABILITIES.iter().map(|&p| q(p)).collect(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_wilson_interval_has_its_textbook_value() {
        // Brown, Cai & DasGupta's example scale: 10 of 20 — centre 0.5,
        // half-width z√(pq/n + z²/4n²)/(1 + z²/n) = 0.2007...
        let p = Proportion::of(10, 20);
        let half = Z95 * (0.25 / 20.0 + Z95 * Z95 / 1600.0).sqrt() / (1.0 + Z95 * Z95 / 20.0);
        assert!((p.low - (0.5 - half)).abs() < 1e-15 && (p.high - (0.5 + half)).abs() < 1e-15);
        assert!((half - 0.2007).abs() < 1e-3);
        let none = Proportion::of(0, 100);
        assert_eq!(none.low, 0.0);
        assert!(none.high > 0.03 && none.high < 0.04, "{none:?}"); // ≈ 3.7/n
    }

    #[test]
    fn the_quantiles_of_few_values_are_exact() {
        let mut r = Reservoir::new(1);
        for k in (0..=100).rev() {
            r.push(k as f64);
        }
        let q = r.quantiles();
        assert_eq!(q.values, vec![1.0, 5.0, 25.0, 50.0, 75.0, 95.0, 99.0]);
    }

    #[test]
    fn a_full_reservoir_keeps_a_uniform_sample() {
        let mut r = Reservoir::new(2);
        let n = 4 * RESERVOIR as u64;
        for k in 0..n {
            r.push(k as f64 / n as f64);
        }
        let q = r.quantiles();
        for (p, v) in q.probabilities.iter().zip(&q.values) {
            assert!(
                (p - v).abs() < 5.0 * (p * (1.0 - p) / RESERVOIR as f64).sqrt(),
                "{p} {v}"
            );
        }
    }
}
