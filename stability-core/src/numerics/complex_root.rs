//! A root of an analytic function of one complex variable by the secant
//! method: what the p-method needs of a characteristic determinant whose
//! air forces depend on the root itself (no polynomial, so no companion
//! matrix; the derivative is not at hand, and near a simple root the
//! secant converges with order 1.618).

use num_complex::Complex64;

/// The root of `f` the secant iteration from `z0`, `z1` reaches, once a
/// step is at most `tol`·max(1, |z|); None if `f` is not defined at an
/// iterate, the two values are equal, or `max_steps` pass first.
pub fn secant(
    f: impl Fn(Complex64) -> Option<Complex64>,
    (z0, z1): (Complex64, Complex64),
    tol: f64,
    max_steps: usize,
) -> Option<Complex64> {
    let (mut a, mut b) = (z0, z1);
    let (mut fa, mut fb) = (f(a)?, f(b)?);
    for _ in 0..max_steps {
        if fb == Complex64::default() {
            return Some(b);
        }
        let slope = (fb - fa) / (b - a);
        if slope == Complex64::default() || !slope.is_finite() {
            return None;
        }
        let step = fb / slope;
        (a, fa) = (b, fb);
        b -= step;
        if step.norm() <= tol * b.norm().max(1.0) {
            return Some(b);
        }
        fb = f(b)?;
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The roots of z² + 1 and of e^z − 2 (ln 2 + 2πi·n, the one nearest).
    #[test]
    fn finds_the_nearest_root() {
        let i = Complex64::new(0.0, 1.0);
        let r = secant(
            |z| Some(z * z + 1.0),
            (Complex64::new(0.3, 0.8), Complex64::new(0.2, 0.9)),
            1e-14,
            50,
        );
        assert!((r.unwrap() - i).norm() < 1e-13);
        let target = Complex64::new(2f64.ln(), 2.0 * std::f64::consts::PI);
        let r = secant(
            |z| Some(z.exp() - 2.0),
            (Complex64::new(0.5, 6.0), Complex64::new(0.6, 6.1)),
            1e-14,
            50,
        );
        assert!((r.unwrap() - target).norm() < 1e-13);
        assert!(secant(|_| None, (i, -i), 1e-14, 5).is_none());
    }
}
