//! Grids of values: `a, a + step, …, b` as the decimals they stand for, and
//! the one tolerance by which a value is taken to lie on a grid.
//!
//! Every axis the program writes (the report's Mach numbers, a sweep's
//! ranges, the figures' abscissae) comes from [`grid`], rounded to
//! [`GRID_DIGITS`] significant digits by [`round`]; every comparison of a
//! computed value with a grid value (is M = 1.2 on this grid? is this the
//! last point?) allows [`GRID_TOLERANCE`].

/// The significant digits of a grid's values.
pub const GRID_DIGITS: usize = 12;

/// The tolerance of a comparison with a grid value, in the grid's own
/// units: far above the rounding of `a + k·step` (≈ 1e-15 relative) and
/// far below any step a grid is built with (≥ 1e-6).
pub const GRID_TOLERANCE: f64 = 1e-9;

/// `a, a + step, …` up to `b` (inclusive, within [`GRID_TOLERANCE`] of a
/// step), each rounded to [`GRID_DIGITS`] significant digits, so that the
/// grid's values are the decimals they stand for (0.5 + 7 × 0.01 is 0.57,
/// not 0.5700000000000001, in every file that prints them).
pub fn grid(a: f64, b: f64, step: f64) -> Vec<f64> {
    let valid = step > 0.0 && step.is_finite() && a.is_finite() && b.is_finite() && b >= a;
    if !valid {
        return vec![a];
    }
    let n = ((b - a) / step + GRID_TOLERANCE).floor() as usize;
    (0..=n).map(|i| round(a + step * i as f64)).collect()
}

/// `x` rounded to [`GRID_DIGITS`] significant decimal digits (the nearest
/// f64 to that decimal): a value without the noise of `a + k·step` or of
/// a conversion to degrees.
pub fn round(x: f64) -> f64 {
    crate::numerics::display::round_to(x, GRID_DIGITS)
}

/// Whether `x` is the grid value `at` (within [`GRID_TOLERANCE`]).
pub fn on(x: f64, at: f64) -> bool {
    (x - at).abs() <= GRID_TOLERANCE
}

/// Whether `x` lies in [a, b], the ends within [`GRID_TOLERANCE`].
pub fn within(x: f64, a: f64, b: f64) -> bool {
    x >= a - GRID_TOLERANCE && x <= b + GRID_TOLERANCE
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grids_are_the_decimals_they_stand_for() {
        let g = grid(0.5, 0.8, 0.1);
        assert_eq!(g, [0.5, 0.6, 0.7, 0.8]);
        // the decimals they stand for, to the bit
        assert_eq!(0.5 + 0.01 * 7.0, 0.5700000000000001);
        assert_eq!(grid(0.5, 0.6, 0.01)[7], 0.57);
        assert_eq!(grid(0.5, 2.0, 0.01)[70], 1.2);
        assert_eq!(round(45.00000000000001), 45.0);
        assert_eq!(grid(1.0, 0.5, 0.1), [1.0]);
        assert!(on(1.2000000000001, 1.2) && !on(1.2001, 1.2));
        assert!(within(0.9 + 1e-12, 0.5, 0.9) && !within(0.91, 0.5, 0.9));
    }
}
