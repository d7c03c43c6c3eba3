//! Low-discrepancy (quasi-Monte Carlo) sampling: Owen-scrambled Sobol′
//! points (Sobol′ 1967, *USSR Comput. Math. Math. Phys.* 7:86–112; the
//! direction numbers of Joe & Kuo 2008), scrambled and shuffled by the
//! hash-based Owen scrambling of Burley (2020), "Practical hash-based Owen
//! scrambling", *J. Computer Graphics Techniques* 9(4):1–20, as the
//! `sobol_burley` crate computes it, seeded from the user's seed.
//!
//! # Why
//! A Monte Carlo estimate's error falls as 1/√N; over the first N = 2^m
//! points of a scrambled Sobol′ sequence — a (t, m, s)-net in base 2 —
//! it falls as O((log N)^{s−1}/N) for integrands of bounded variation, and
//! scrambling (Owen 1995, 1997) keeps the estimate unbiased with a root
//! mean square error o(1/√N) for every square-integrable one. In one
//! dimension the net puts exactly one point in each interval
//! [j/N, (j+1)/N), so the share of points below any u is within 1/N of u.
//! Draw N a power of two (every [`super::CHUNK`] is one) to keep the nets.
//!
//! # Points to inputs
//! Coordinate j of point i is a u in (0, 1): the scrambled 32-bit integer
//! n as u = (n + ½)/2³², never 0 or 1; the inputs' normal scores are
//! z = Φ⁻¹(u) ([`inverse_phi`]), which the Gaussian copula and the inverse
//! distribution functions then map as for random samples
//! ([`super::dist`]).
//!
//! # The Saltelli design
//! The Sobol indices' A and B matrices are the first and second k
//! coordinates of one 2k-dimensional sequence (Saltelli et al. 2010,
//! *Comput. Phys. Commun.* 181:259–270, §3: "a quasi-random sequence of
//! dimension 2k", A its left half and B its right).
//!
//! # Length
//! The crate's sequence has 2^16 points. Point i is point i mod 2^16 of
//! the sequence seeded by (seed, ⌊i/2^16⌋): past 2^16 points each further
//! block of 2^16 is an independent scrambled replicate, itself a net.

use sobol_burley::parts::{hash, owen_scramble_rev, sobol_rev};

/// How a run draws its points.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Sampling {
    /// Pseudo-random normal scores: ChaCha8 on a stream per chunk.
    #[default]
    Random,
    /// Owen-scrambled Sobol′ points ([`SobolSequence`]).
    Sobol,
}

impl Sampling {
    /// Its name in configs and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Sampling::Random => "random",
            Sampling::Sobol => "sobol",
        }
    }

    /// The sampling named `name` ("random" or "sobol").
    pub fn parse(name: &str) -> Option<Sampling> {
        match name {
            "random" => Some(Sampling::Random),
            "sobol" => Some(Sampling::Sobol),
            _ => None,
        }
    }
}

/// Points of one sequence (one sequence's length: 2^16 points).
pub const SEQUENCE_LENGTH: u64 = 1 << 16;

/// The coordinates a point has (the crate's direction numbers).
pub const DIMENSIONS: u32 = sobol_burley::NUM_DIMENSIONS;

/// An Owen-scrambled Sobol′ sequence, seeded.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SobolSequence {
    seed: u64,
}

/// SplitMix64's finaliser (Steele, Lea & Flood 2014): a 64-bit seed and a
/// block index to a 32-bit scramble seed, every bit of both mixed in.
fn mix(seed: u64, block: u64) -> u32 {
    let mut z = seed ^ block.wrapping_mul(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^= z >> 31;
    (z ^ (z >> 32)) as u32
}

impl SobolSequence {
    pub fn new(seed: u64) -> SobolSequence {
        SobolSequence { seed }
    }

    /// Coordinate `dim` (< [`DIMENSIONS`]) of point `index` as the
    /// scrambled 32-bit integer: `sobol_burley::sample` before its
    /// conversion to f32 (which keeps 23 of the bits).
    #[inline]
    pub fn bits(&self, index: u64, dim: u32) -> u32 {
        let seed = mix(self.seed, index / SEQUENCE_LENGTH);
        let i = (index % SEQUENCE_LENGTH) as u32;
        // Burley 2020 §4: the index shuffled by a nested uniform scramble
        // of its own (which maps each aligned block of 2^m points onto
        // one), then the point's coordinate Owen-scrambled per dimension.
        let shuffled = owen_scramble_rev(i.reverse_bits(), hash(seed ^ 0x79c6_8e4a));
        let sobol = sobol_rev(shuffled, dim);
        let scramble = (dim >> 2)
            ^ seed.wrapping_mul(0x9c8f_2d3b)
            ^ [0x912f_69ba, 0x174f_18ab, 0x691e_72ca, 0xb40c_c1b8][dim as usize & 3];
        owen_scramble_rev(sobol, hash(scramble)).reverse_bits()
    }

    /// Coordinate `dim` of point `index` in (0, 1): (n + ½)/2³².
    #[inline]
    pub fn uniform(&self, index: u64, dim: u32) -> f64 {
        (f64::from(self.bits(index, dim)) + 0.5) * (1.0 / 4_294_967_296.0)
    }

    /// Coordinate `dim` of point `index` as a standard normal score,
    /// Φ⁻¹ of [`SobolSequence::uniform`].
    #[inline]
    pub fn normal(&self, index: u64, dim: u32) -> f64 {
        inverse_phi(self.uniform(index, dim))
    }
}

/// Horner's rule on `c` (constant first).
#[inline]
fn poly(c: &[f64; 8], x: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, &k| acc * x + k)
}

// AS 241's coefficients as Wichura printed them (20 digits), rounded by
// the compiler: numerators and denominators (constant first) for
// |p − ½| ≤ 0.425, then r = √(−ln min(p, 1 − p)) ≤ 5 and beyond.
#[allow(clippy::excessive_precision)]
mod ppnd16 {
    pub(super) const A: [f64; 8] = [
        3.387_132_872_796_366_608,
        133.141_667_891_784_377_45,
        1_971.590_950_306_551_442_7,
        13_731.693_765_509_461_125,
        45_921.953_931_549_871_457,
        67_265.770_927_008_700_853,
        33_430.575_583_588_128_105,
        2_509.080_928_730_122_672_7,
    ];
    pub(super) const B: [f64; 8] = [
        1.0,
        42.313_330_701_600_911_252,
        687.187_007_492_057_908_3,
        5_394.196_021_424_751_107_7,
        21_213.794_301_586_595_867,
        39_307.895_800_092_710_61,
        28_729.085_735_721_942_674,
        5_226.495_278_852_545_925,
    ];
    pub(super) const C: [f64; 8] = [
        1.423_437_110_749_683_577_34,
        4.630_337_846_156_545_295_9,
        5.769_497_221_460_691_405_5,
        3.647_848_324_763_204_605_04,
        1.270_458_252_452_368_382_58,
        0.241_780_725_177_450_611_77,
        0.022_723_844_989_269_184_583_3,
        7.745_450_142_783_414_076_4e-4,
    ];
    pub(super) const D: [f64; 8] = [
        1.0,
        2.053_191_626_637_758_821_87,
        1.676_384_830_183_803_849_4,
        0.689_767_334_985_100_004_55,
        0.148_103_976_427_480_074_59,
        0.015_198_666_563_616_457_196_6,
        5.475_938_084_995_344_946e-4,
        1.050_750_071_644_416_843_24e-9,
    ];
    pub(super) const E: [f64; 8] = [
        6.657_904_643_501_103_777_2,
        5.463_784_911_164_114_369_9,
        1.784_826_539_917_291_335_8,
        0.296_560_571_828_504_891_23,
        0.026_532_189_526_576_123_093,
        0.001_242_660_947_388_078_438_6,
        2.711_555_568_743_487_578_15e-5,
        2.010_334_399_292_288_132_65e-7,
    ];
    pub(super) const F: [f64; 8] = [
        1.0,
        0.599_832_206_555_887_937_69,
        0.136_929_880_922_735_805_31,
        0.014_875_361_290_850_614_852_5,
        7.868_691_311_456_132_591e-4,
        1.846_318_317_510_054_681_8e-5,
        1.421_511_758_316_445_888_7e-7,
        2.044_263_103_389_939_785_64e-15,
    ];
}

/// The standard normal quantile Φ⁻¹(p) for p in (0, 1), to about 1 part
/// in 10¹⁶: Wichura's algorithm AS 241, PPND16 (*Appl. Statist.*
/// 37:477–484, 1988), rational approximations in three ranges of p.
/// ±∞ at p = 0 or 1; NaN outside [0, 1].
pub fn inverse_phi(p: f64) -> f64 {
    if !(0.0..=1.0).contains(&p) {
        return f64::NAN;
    }
    let q = p - 0.5;
    if q.abs() <= 0.425 {
        let r = 0.180_625 - q * q;
        return q * poly(&ppnd16::A, r) / poly(&ppnd16::B, r);
    }
    let tail = if q < 0.0 { p } else { 1.0 - p };
    if tail == 0.0 {
        return f64::INFINITY.copysign(q);
    }
    let r = (-tail.ln()).sqrt();
    let x = if r <= 5.0 {
        poly(&ppnd16::C, r - 1.6) / poly(&ppnd16::D, r - 1.6)
    } else {
        poly(&ppnd16::E, r - 5.0) / poly(&ppnd16::F, r - 5.0)
    };
    x.copysign(q)
}

#[cfg(test)]
mod tests {
    use super::super::dist::phi;
    use super::super::sobol::SobolSums;
    use super::*;

    #[test]
    fn the_inverse_normal_inverts_phi_and_has_its_tabulated_values() {
        // Abramowitz & Stegun Table 26.5: z at 0.975, 0.995, 0.9995
        assert!((inverse_phi(0.975) - 1.959_963_984_540_054).abs() < 1e-15);
        assert!((inverse_phi(0.995) - 2.575_829_303_548_901).abs() < 1e-14);
        assert!((inverse_phi(0.0005) + 3.290_526_731_491_926).abs() < 1e-13);
        assert_eq!(inverse_phi(0.5), 0.0);
        // √2·erfinv(2p − 1) to 40 digits (mpmath 1.3), in the far tail
        for (p, z) in [
            (1e-12, -7.034_483_825_301_132),
            (1e-20, -9.262_340_089_798_408),
            (0.3, -0.524_400_512_708_040_8),
        ] {
            assert!((inverse_phi(p) / z - 1.0).abs() < 1e-15, "{p}");
        }
        // Φ(Φ⁻¹(p)) = p over the three ranges, down to the smallest u drawn
        let mut p = 0.5f64 / 4_294_967_296.0;
        while p < 1.0 {
            for u in [p, 1.0 - p] {
                let back = phi(inverse_phi(u));
                // relative to the tail where Φ resolves it (below ½: a
                // relative error ε in z is one of about z²ε in Φ), to u's
                // own rounding above
                let tail = u.min(1.0 - u);
                let z2 = inverse_phi(u).powi(2);
                let tol = if u < 0.5 {
                    1e-15 * (1.0 + z2) * tail
                } else {
                    4.0 * f64::EPSILON
                };
                assert!((back - u).abs() <= tol, "{u}: {back}");
            }
            p *= 1.37;
        }
        assert!(inverse_phi(1.5).is_nan());
        assert_eq!(inverse_phi(0.0), f64::NEG_INFINITY);
    }

    #[test]
    fn the_points_are_the_crates_samples_to_their_f32_precision() {
        // for seeds below 2^16 points: the crate's own `sample` with the
        // mixed seed; its f32 keeps the top 23 bits
        let s = SobolSequence::new(42);
        let seed = mix(42, 0);
        for i in [0u64, 1, 2, 77, 4095, 65_535] {
            for d in [0, 1, 5, 47] {
                let f = sobol_burley::sample(i as u32, d, seed);
                assert_eq!(f, f32::from_bits((s.bits(i, d) >> 9) | 0x3f80_0000) - 1.0);
            }
        }
    }

    #[test]
    fn each_power_of_two_prefix_is_stratified_in_every_coordinate() {
        // the (0, m, 1)-net property in each one-dimensional projection:
        // one point in each [j/N, (j+1)/N), for N = 2^m; in the replicate
        // past 2^16 points too
        for start in [0u64, SEQUENCE_LENGTH] {
            let s = SobolSequence::new(9);
            for m in [1u32, 4, 10] {
                let n = 1u64 << m;
                for d in [0, 3, 30] {
                    let mut seen = vec![false; n as usize];
                    for i in start..start + n {
                        let cell = (s.uniform(i, d) * n as f64) as usize;
                        assert!(!seen[cell], "m = {m}, dim {d}: two points in cell {cell}");
                        seen[cell] = true;
                    }
                }
            }
        }
    }

    /// The Ishigami function, sin x₁ + 7 sin² x₂ + 0.1 x₃⁴ sin x₁.
    fn ishigami(x: [f64; 3]) -> f64 {
        x[0].sin() + 7.0 * x[1].sin().powi(2) + 0.1 * x[2].powi(4) * x[0].sin()
    }

    #[test]
    fn a_six_dimensional_sequence_gives_the_ishigami_indices() {
        // Saltelli 2010 §3: A the first three coordinates, B the next
        // three; N = 2^13 rows. The analytic indices (Sobol' & Levitan
        // 1999; to four places in sobol.rs's test): S = (0.3139, 0.4424,
        // 0), S_T = (0.5576, 0.4424, 0.2437).
        let (s, st) = ([0.3139, 0.4424, 0.0], [0.5576, 0.4424, 0.2437]);
        let seq = SobolSequence::new(5);
        let x =
            |i: u64, d: u32| -std::f64::consts::PI + 2.0 * std::f64::consts::PI * seq.uniform(i, d);
        let mut sums = SobolSums::new(3);
        for i in 0..1u64 << 13 {
            let a = [x(i, 0), x(i, 1), x(i, 2)];
            let b = [x(i, 3), x(i, 4), x(i, 5)];
            let ab: Vec<f64> = (0..3)
                .map(|k| {
                    let mut y = a;
                    y[k] = b[k];
                    ishigami(y)
                })
                .collect();
            sums.add(ishigami(a), ishigami(b), &ab);
        }
        let got = sums.indices().unwrap();
        for k in 0..3 {
            // 0.005: a random design of this size has standard errors of
            // 0.005–0.016 (the iid estimate beside each index); measured
            // here: at most 0.0015 (S₁), ≤ 0.0003 for the totals
            assert!((got[k].first - s[k]).abs() < 0.005, "S{k}: {:?}", got[k]);
            assert!((got[k].total - st[k]).abs() < 0.005, "ST{k}: {:?}", got[k]);
        }
    }
}
