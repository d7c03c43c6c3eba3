//! The distributions of uncertain inputs, drawn from standard normals
//! through their quantile functions (a Gaussian copula): x = F⁻¹(Φ(z)).
//! Normal and lognormal inputs take z directly (x = μ + σz, x = e^{μ+σz});
//! uniform, triangular and sampled inputs through u = Φ(z). Correlated
//! inputs get correlated z = Lε, L the Cholesky factor of the correlation
//! matrix of the standard normals (Nelsen, *An Introduction to Copulas*,
//! 2nd ed. 2006, §3.1; the "NORTA" construction of Cario & Nelson 1997).

/// A distribution of an uncertain input (or of its error).
#[derive(Debug, Clone, PartialEq)]
pub enum Dist {
    /// Normal, mean and standard deviation (sd ≥ 0).
    Normal { mean: f64, sd: f64 },
    /// Lognormal: ln x normal with mean `mu` and standard deviation
    /// `sigma` (median e^mu).
    LogNormal { mu: f64, sigma: f64 },
    /// Uniform on [low, high].
    Uniform { low: f64, high: f64 },
    /// Triangular on [low, high] with its peak at `mode`.
    Triangular { low: f64, mode: f64, high: f64 },
    /// The empirical distribution of samples (sorted ascending on
    /// construction by [`Dist::samples`]): u ↦ the ⌊u·n⌋-th.
    Samples(Vec<f64>),
}

/// Why a distribution's parameters are not usable.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DistError {
    #[error("{0} is not a finite number")]
    NotFinite(&'static str),
    #[error("{0} must not be negative")]
    Negative(&'static str),
    #[error("low must be below high")]
    Order,
    #[error("the mode must lie within [low, high]")]
    Mode,
    #[error("no samples")]
    NoSamples,
}

impl Dist {
    /// The empirical distribution of `values` (any order; every one finite).
    pub fn samples(mut values: Vec<f64>) -> Result<Dist, DistError> {
        if values.is_empty() {
            return Err(DistError::NoSamples);
        }
        if values.iter().any(|v| !v.is_finite()) {
            return Err(DistError::NotFinite("a sample"));
        }
        values.sort_by(f64::total_cmp);
        Ok(Dist::Samples(values))
    }

    /// Its parameters checked: finite, spreads not negative, low < high,
    /// low ≤ mode ≤ high.
    pub fn check(&self) -> Result<(), DistError> {
        let finite = |name, v: f64| {
            if v.is_finite() {
                Ok(())
            } else {
                Err(DistError::NotFinite(name))
            }
        };
        match *self {
            Dist::Normal { mean, sd } => {
                finite("mean", mean)?;
                finite("sd", sd)?;
                if sd < 0.0 {
                    return Err(DistError::Negative("sd"));
                }
            }
            Dist::LogNormal { mu, sigma } => {
                finite("mu", mu)?;
                finite("sigma", sigma)?;
                if sigma < 0.0 {
                    return Err(DistError::Negative("sigma"));
                }
            }
            Dist::Uniform { low, high } => {
                finite("low", low)?;
                finite("high", high)?;
                if low >= high {
                    return Err(DistError::Order);
                }
            }
            Dist::Triangular { low, mode, high } => {
                finite("low", low)?;
                finite("mode", mode)?;
                finite("high", high)?;
                if low >= high {
                    return Err(DistError::Order);
                }
                if !(low..=high).contains(&mode) {
                    return Err(DistError::Mode);
                }
            }
            Dist::Samples(ref s) if s.is_empty() => return Err(DistError::NoSamples),
            Dist::Samples(_) => {}
        }
        Ok(())
    }

    /// The value at standard normal `z`: F⁻¹(Φ(z)).
    #[inline]
    pub fn at(&self, z: f64) -> f64 {
        match *self {
            Dist::Normal { mean, sd } => mean + sd * z,
            Dist::LogNormal { mu, sigma } => (mu + sigma * z).exp(),
            Dist::Uniform { low, high } => low + (high - low) * phi(z),
            Dist::Triangular { low, mode, high } => triangular_quantile(low, mode, high, phi(z)),
            Dist::Samples(ref s) => {
                let k = (phi(z) * s.len() as f64) as usize;
                s[k.min(s.len() - 1)]
            }
        }
    }

    /// The distribution's name in configs.
    pub fn name(&self) -> &'static str {
        match self {
            Dist::Normal { .. } => "normal",
            Dist::LogNormal { .. } => "lognormal",
            Dist::Uniform { .. } => "uniform",
            Dist::Triangular { .. } => "triangular",
            Dist::Samples(_) => "samples",
        }
    }
}

/// The standard normal distribution function Φ(z) = ½·erfc(−z/√2).
#[inline]
pub fn phi(z: f64) -> f64 {
    0.5 * libm::erfc(-z * std::f64::consts::FRAC_1_SQRT_2)
}

/// The quantile of the triangular distribution on [a, b] with mode c at
/// probability u (Johnson, Kotz & Balakrishnan, *Continuous Univariate
/// Distributions* vol. 2, 1995, ch. 26 §9).
pub fn triangular_quantile(a: f64, c: f64, b: f64, u: f64) -> f64 {
    let fc = (c - a) / (b - a);
    if u < fc {
        a + (u * (b - a) * (c - a)).sqrt()
    } else {
        b - ((1.0 - u) * (b - a) * (b - c)).sqrt()
    }
}

/// Why a correlation matrix cannot be used.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CorrelationError {
    #[error("a correlation of {0} is outside [−1, 1]")]
    Range(f64),
    #[error(
        "the correlations are not consistent (the matrix is not positive definite): lower the largest"
    )]
    NotPositiveDefinite,
}

/// The lower Cholesky factor (row-major, n×n) of the correlation matrix
/// with unit diagonal and `pairs` (i, j, ρ) off it.
pub fn cholesky(n: usize, pairs: &[(usize, usize, f64)]) -> Result<Vec<f64>, CorrelationError> {
    let mut c = nalgebra::DMatrix::<f64>::identity(n, n);
    for &(i, j, rho) in pairs {
        if !(-1.0..=1.0).contains(&rho) || !rho.is_finite() {
            return Err(CorrelationError::Range(rho));
        }
        c[(i, j)] = rho;
        c[(j, i)] = rho;
    }
    let l = nalgebra::linalg::Cholesky::new(c)
        .ok_or(CorrelationError::NotPositiveDefinite)?
        .l();
    if (0..n).any(|i| l[(i, i)] <= 1e-12) {
        return Err(CorrelationError::NotPositiveDefinite);
    }
    Ok((0..n * n).map(|k| l[(k / n, k % n)]).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn phi_has_its_tabulated_values() {
        // Abramowitz & Stegun Table 26.1
        assert!((phi(0.0) - 0.5).abs() < 1e-16);
        assert!((phi(1.0) - 0.841_344_746_068_543).abs() < 1e-14);
        assert!((phi(-1.959_963_984_540_054) - 0.025).abs() < 1e-14);
    }

    #[test]
    fn the_triangular_quantile_inverts_the_distribution_function() {
        let (a, c, b) = (1.0f64, 2.0, 5.0);
        // F(x) = (x−a)²/((b−a)(c−a)) for x ≤ c, 1 − (b−x)²/((b−a)(b−c)) after
        for x in [1.5, 2.0, 3.0, 4.9] {
            let f = if x <= c {
                (x - a).powi(2) / ((b - a) * (c - a))
            } else {
                1.0 - (b - x).powi(2) / ((b - a) * (b - c))
            };
            assert!((triangular_quantile(a, c, b, f) - x).abs() < 1e-12);
        }
    }

    #[test]
    fn a_cholesky_factor_reproduces_its_correlation() {
        let l = cholesky(2, &[(0, 1, 0.6)]).unwrap();
        // L = [[1, 0], [ρ, √(1−ρ²)]]
        assert_eq!(l[0], 1.0);
        assert!((l[2] - 0.6).abs() < 1e-15 && (l[3] - 0.8).abs() < 1e-15);
        assert_eq!(
            cholesky(3, &[(0, 1, 0.9), (1, 2, 0.9), (0, 2, -0.9)]),
            Err(CorrelationError::NotPositiveDefinite)
        );
    }
}
