//! Number formatting for tables.

/// `v` with `digits` significant digits: fixed notation for magnitudes from
/// 1e-3 to 1e7, scientific (`1.234560e-5`) outside.
pub fn sig(v: f64, digits: usize) -> String {
    if !v.is_finite() {
        return format!("{v}");
    }
    if v == 0.0 {
        return "0".to_string();
    }
    let mag = v.abs().log10().floor() as i32;
    if (-3..7).contains(&mag) {
        let decimals = (digits as i32 - 1 - mag).max(0) as usize;
        format!("{v:.decimals$}")
    } else {
        format!("{v:.prec$e}", prec = digits.saturating_sub(1))
    }
}

#[cfg(test)]
mod tests {
    use super::sig;

    #[test]
    fn significant_digits() {
        assert_eq!(sig(1.012, 7), "1.012000");
        assert_eq!(sig(358.0071375, 7), "358.0071");
        assert_eq!(sig(-0.000123456789, 4), "-1.235e-4");
        assert_eq!(sig(0.0, 4), "0");
        assert_eq!(sig(12345678.0, 3), "1.23e7");
    }
}
