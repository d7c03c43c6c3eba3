//! Numbers and fields in the CSV files the program writes (the figures'
//! data, a response's time history): one rule for every number.

use stability_core::numerics::display::round_to;

/// The significant digits of a CSV number.
pub const CSV_DIGITS: usize = 12;

/// The number as TOML, Python and MATLAB read it back to the same f64:
/// Rust's shortest round-trip form (`0.1`, `-3.0`, `1e-7`); for finite
/// numbers (`NaN` and `inf` are not numbers to TOML or MATLAB).
pub fn exact(x: f64) -> String {
    format!("{x:?}")
}

/// A CSV number: rounded to [`CSV_DIGITS`] significant digits, then written
/// as the shortest decimal that reads back as that rounded value — plain
/// (`0.57`, `-123456.789012`) from 1e-5 to 1e16 in magnitude, in exponent
/// form outside (`1e-300`, not 300 digits). So the Mach grid's
/// 0.5 + 0.01·7 = 0.5700000000000001 is written 0.57 — float noise from
/// building the grid is not data — while a computed value keeps 12
/// significant digits, more than any model here is accurate to. Empty for a
/// value that is not finite (never NaN in the output).
pub fn number(v: f64) -> String {
    if !v.is_finite() {
        return String::new();
    }
    let r = round_to(v, CSV_DIGITS);
    let a = r.abs();
    if r == 0.0 || (1e-5..1e16).contains(&a) {
        format!("{r}")
    } else {
        format!("{r:e}")
    }
}

/// A CSV field, quoted when it holds a comma, a quote or a line break.
pub fn field(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_short_and_read_back() {
        assert_eq!(number(0.11371015967272328), "0.113710159673");
        assert_eq!(number(-123456.78901234567), "-123456.789012");
        assert_eq!(number(0.5 + 0.01 * 7.0), "0.57");
        assert_eq!(number(-0.0), "0");
        assert_eq!(number(f64::NAN), "");
        for (v, text) in [(1e-300, "1e-300"), (-2.5e-7, "-2.5e-7"), (3e20, "3e20")] {
            assert_eq!(number(v), text);
            assert_eq!(number(v).parse::<f64>().unwrap(), v);
        }
        // the longest a number can be: 12 digits, sign, point, exponent
        assert!(number(-1.23456789012345e-300).len() <= 20);
    }

    #[test]
    fn fields_are_quoted_when_needed() {
        assert_eq!(field("a,b"), "\"a,b\"");
        assert_eq!(field("say \"x\""), "\"say \"\"x\"\"\"");
        assert_eq!(field("plain"), "plain");
    }
}
