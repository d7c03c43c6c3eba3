//! How values are written in messages and tables: numbers short enough to
//! read (`1e308`, not 309 digits), quoted text cut to an excerpt, numbers
//! to a number of significant digits ([`sig`]). Every error message of the
//! crate writes its numbers and quotes through these.

use std::fmt;

/// A number for a message: its shortest round-trip form (`0.25`, `-1.5`,
/// `123456`) when that is short, scientific (`1e308`, `2.5e-12`)
/// otherwise; `NaN`, `inf` and `-inf` as such.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Num(pub f64);

impl fmt::Display for Num {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let x = self.0;
        let a = x.abs();
        if !x.is_finite() || x == 0.0 || (1e-4..1e15).contains(&a) {
            write!(f, "{x}")
        } else {
            write!(f, "{x:e}")
        }
    }
}

/// An optional number for a message: the number, or `none`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OptNum(pub Option<f64>);

impl fmt::Display for OptNum {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0 {
            Some(x) => Num(x).fmt(f),
            None => f.write_str("none"),
        }
    }
}

/// Text quoted in a message: at most [`Excerpt::MAX`] characters, with
/// `…` where it was cut.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Excerpt<'a>(pub &'a str);

impl Excerpt<'_> {
    /// The longest excerpt, in characters.
    pub const MAX: usize = 60;
}

impl fmt::Display for Excerpt<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0.char_indices().nth(Excerpt::MAX) {
            Some((cut, _)) => write!(f, "{}…", &self.0[..cut]),
            None => f.write_str(self.0),
        }
    }
}

/// Text cut to an excerpt, owned (for errors that keep what they quote).
pub fn excerpt(s: &str) -> String {
    Excerpt(s).to_string()
}

/// `v` rounded to `digits` significant decimal digits (through its decimal
/// representation, so that 0.5700000000000001 to 12 digits is the double
/// nearest 0.57); −0 becomes 0, and a value that is not finite is itself.
pub fn round_to(v: f64, digits: usize) -> f64 {
    if !v.is_finite() {
        return v;
    }
    let r: f64 = format!("{v:.prec$e}", prec = digits.saturating_sub(1))
        .parse()
        .unwrap_or(v);
    r + 0.0
}

/// `v` with `digits` significant digits, for tables: fixed notation for
/// magnitudes from 1e-3 to 1e7, scientific (`1.234560e-5`) outside; `0`
/// for zero, and `NaN`, `inf`, `-inf` as such.
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
    use super::*;

    #[test]
    fn numbers_are_short() {
        assert_eq!(Num(1e308).to_string(), "1e308");
        assert_eq!(Num(-f64::MAX).to_string(), "-1.7976931348623157e308");
        assert_eq!(Num(5e-324).to_string(), "5e-324");
        assert_eq!(Num(0.25).to_string(), "0.25");
        assert_eq!(Num(-3.0).to_string(), "-3");
        assert_eq!(Num(0.0).to_string(), "0");
        assert_eq!(Num(123456.0).to_string(), "123456");
        assert_eq!(Num(2.5e-12).to_string(), "2.5e-12");
        assert_eq!(Num(f64::NAN).to_string(), "NaN");
        assert_eq!(Num(f64::NEG_INFINITY).to_string(), "-inf");
        assert_eq!(OptNum(None).to_string(), "none");
        for x in [
            1e-300,
            1e-5,
            0.1 + 0.2,
            1e14,
            1e15,
            1e300,
            f64::MIN_POSITIVE,
        ] {
            let s = Num(x).to_string();
            assert!(s.len() <= 24, "{s}");
            assert_eq!(s.parse::<f64>().unwrap(), x, "round trip of {s}");
        }
    }

    #[test]
    fn significant_digits() {
        assert_eq!(sig(1.012, 7), "1.012000");
        assert_eq!(sig(358.0071375, 7), "358.0071");
        assert_eq!(sig(-0.000123456789, 4), "-1.235e-4");
        assert_eq!(sig(0.0, 4), "0");
        assert_eq!(sig(12345678.0, 3), "1.23e7");
    }

    #[test]
    fn excerpts_are_cut_at_a_character() {
        let long = "é".repeat(1000);
        let e = Excerpt(&long).to_string();
        assert_eq!(e.chars().count(), Excerpt::MAX + 1);
        assert!(e.ends_with('…'));
        assert_eq!(Excerpt("short").to_string(), "short");
    }
}
