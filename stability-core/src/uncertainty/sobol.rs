//! Variance-based global sensitivity: first-order and total Sobol indices
//! from the radial design of Saltelli et al. (2010), "Variance based
//! sensitivity analysis of model output. Design and estimator for the
//! total sensitivity index", *Comput. Phys. Commun.* 181:259–270.
//!
//! Two independent sample matrices A and B (N rows, k factors) and the k
//! matrices A_B^(i) — A with its column i from B — give, for each factor i
//! and V = Var(Y):
//!
//! - first order, S_i = V_i/V with V_i ≈ (1/N) Σ f(B)_j (f(A_B^(i))_j − f(A)_j)
//!   (Saltelli 2010, Table 2 (b));
//! - total, S_Ti = V_Ti/V with V_Ti ≈ (1/2N) Σ (f(A)_j − f(A_B^(i))_j)²
//!   (Jansen 1999, Saltelli 2010 Table 2 (f)).
//!
//! V is estimated from the 2N values f(A) and f(B). The sums stream: each
//! row adds to them, and rows are added in a fixed order, so the indices
//! do not depend on how the rows were shared among threads. Each index's
//! standard error is that of its sum's mean, divided by V.

use serde::Serialize;

/// The running sums of one output's estimators over k factors.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SobolSums {
    rows: u64,
    sum: f64,
    sum2: f64,
    first: Vec<f64>,
    first2: Vec<f64>,
    total: Vec<f64>,
    total2: Vec<f64>,
}

/// A factor's indices and their standard errors.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Indices {
    pub first: f64,
    pub first_se: f64,
    pub total: f64,
    pub total_se: f64,
}

impl SobolSums {
    pub fn new(k: usize) -> SobolSums {
        SobolSums {
            first: vec![0.0; k],
            first2: vec![0.0; k],
            total: vec![0.0; k],
            total2: vec![0.0; k],
            ..SobolSums::default()
        }
    }

    /// The rows added.
    pub fn rows(&self) -> u64 {
        self.rows
    }

    /// One row: f(A), f(B) and f(A_B^(i)) for each factor i. A row with a
    /// value that is not finite is left out (its count is the caller's).
    pub fn add(&mut self, a: f64, b: f64, ab: &[f64]) -> bool {
        if !(a.is_finite() && b.is_finite() && ab.iter().all(|v| v.is_finite())) {
            return false;
        }
        self.rows += 1;
        self.sum += a + b;
        self.sum2 += a * a + b * b;
        for (i, &abi) in ab.iter().enumerate() {
            let f = b * (abi - a);
            let t = 0.5 * (a - abi) * (a - abi);
            self.first[i] += f;
            self.first2[i] += f * f;
            self.total[i] += t;
            self.total2[i] += t * t;
        }
        true
    }

    /// Another set of sums added to these (in the caller's fixed order).
    pub fn merge(&mut self, o: &SobolSums) {
        self.rows += o.rows;
        self.sum += o.sum;
        self.sum2 += o.sum2;
        let add = |x: &mut [f64], y: &[f64]| x.iter_mut().zip(y).for_each(|(x, y)| *x += y);
        add(&mut self.first, &o.first);
        add(&mut self.first2, &o.first2);
        add(&mut self.total, &o.total);
        add(&mut self.total2, &o.total2);
    }

    /// The variance of the output, from f(A) and f(B).
    pub fn variance(&self) -> f64 {
        let n = 2.0 * self.rows as f64;
        let mean = self.sum / n;
        (self.sum2 / n - mean * mean) * n / (n - 1.0)
    }

    /// Each factor's indices; `None` with fewer than two rows or an output
    /// that does not vary.
    pub fn indices(&self) -> Option<Vec<Indices>> {
        let v = self.variance();
        if self.rows < 2 || v.is_nan() || v <= 0.0 {
            return None;
        }
        let n = self.rows as f64;
        let se = |s: f64, s2: f64| {
            let m = s / n;
            ((s2 / n - m * m).max(0.0) / (n - 1.0)).sqrt()
        };
        Some(
            (0..self.first.len())
                .map(|i| Indices {
                    first: self.first[i] / n / v,
                    first_se: se(self.first[i], self.first2[i]) / v,
                    total: self.total[i] / n / v,
                    total_se: se(self.total[i], self.total2[i]) / v,
                })
                .collect(),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;
    use rand::rngs::ChaCha8Rng;
    use rand_distr::{Distribution, Uniform};

    /// The Ishigami function, sin x₁ + a sin² x₂ + b x₃⁴ sin x₁ on
    /// [−π, π]³ (Ishigami & Homma 1990).
    fn ishigami(x: [f64; 3]) -> f64 {
        let (a, b) = (7.0, 0.1);
        x[0].sin() + a * x[1].sin().powi(2) + b * x[2].powi(4) * x[0].sin()
    }

    #[test]
    fn the_estimators_give_the_ishigami_functions_analytic_indices() {
        // The analytic indices for a = 7, b = 0.1 (Saltelli et al. 2010,
        // §5; Sobol' & Levitan 1999): V = a²/8 + bπ⁴/5 + b²π⁸/18 + 1/2,
        // V₁ = (1 + bπ⁴/5)²/2, V₂ = a²/8, V₁₃ = b²π⁸(1/18 − 1/50).
        let (a, b) = (7.0f64, 0.1f64);
        let pi4 = std::f64::consts::PI.powi(4);
        let v = a * a / 8.0 + b * pi4 / 5.0 + b * b * pi4 * pi4 / 18.0 + 0.5;
        let v1 = (1.0 + b * pi4 / 5.0).powi(2) / 2.0;
        let v2 = a * a / 8.0;
        let v13 = b * b * pi4 * pi4 * (1.0 / 18.0 - 1.0 / 50.0);
        let s = [v1 / v, v2 / v, 0.0];
        let st = [(v1 + v13) / v, v2 / v, v13 / v];
        // the published figures (to four places)
        assert!((s[0] - 0.3139).abs() < 1e-4 && (s[1] - 0.4424).abs() < 1e-4);
        assert!((st[0] - 0.5576).abs() < 1e-4 && (st[2] - 0.2437).abs() < 1e-4);

        let mut rng = ChaCha8Rng::seed_from_u64(7);
        let u = Uniform::new(-std::f64::consts::PI, std::f64::consts::PI).unwrap();
        let mut sums = SobolSums::new(3);
        for _ in 0..200_000 {
            let xa: [f64; 3] = std::array::from_fn(|_| u.sample(&mut rng));
            let xb: [f64; 3] = std::array::from_fn(|_| u.sample(&mut rng));
            let ab: Vec<f64> = (0..3)
                .map(|i| {
                    let mut x = xa;
                    x[i] = xb[i];
                    ishigami(x)
                })
                .collect();
            sums.add(ishigami(xa), ishigami(xb), &ab);
        }
        let got = sums.indices().unwrap();
        for i in 0..3 {
            let g = got[i];
            assert!(
                (g.first - s[i]).abs() < 4.0 * g.first_se,
                "S{i} {g:?} vs {}",
                s[i]
            );
            assert!(
                (g.total - st[i]).abs() < 4.0 * g.total_se,
                "ST{i} {g:?} vs {}",
                st[i]
            );
            assert!(g.first_se < 0.02 && g.total_se < 0.02, "{g:?}");
        }
    }

    #[test]
    fn rows_that_are_not_finite_are_left_out() {
        let mut s = SobolSums::new(1);
        assert!(!s.add(f64::NAN, 1.0, &[1.0]));
        assert!(s.add(1.0, 2.0, &[2.0]));
        assert_eq!(s.rows(), 1);
        assert!(s.indices().is_none(), "one row has no variance estimate");
    }
}
