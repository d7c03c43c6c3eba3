//! The range each design-point value may take, defined once for the
//! config, `analyze`'s overrides and `sweep`'s ranges. The ranges hold
//! every aircraft and keep every derived quantity far from overflow (a c.g.
//! at h = 1e308 is finite, but its derivatives are not).

use stability_core::numerics::display::Num;

/// A closed range [lo, hi] (or (0, hi] when `lo` is 0 and zero is excluded).
#[derive(Debug, Clone, Copy)]
pub struct Limit {
    /// The quantity, in words.
    pub what: &'static str,
    pub lo: f64,
    pub hi: f64,
    /// Whether `lo` itself is allowed.
    pub lo_included: bool,
}

impl Limit {
    /// `x` if it is finite and within the range, else why not.
    pub fn check(&self, x: f64) -> Result<f64, String> {
        let above = if self.lo_included {
            x >= self.lo
        } else {
            x > self.lo
        };
        if !x.is_finite() {
            Err(format!(
                "{} must be a finite number, not {}",
                self.what,
                Num(x)
            ))
        } else if !above && self.lo == 0.0 && !self.lo_included {
            Err(format!("{} must be positive, not {}", self.what, Num(x)))
        } else if !above || x > self.hi {
            let open = if self.lo_included { '[' } else { '(' };
            Err(format!(
                "{} must lie in {open}{}, {}], not {}",
                self.what,
                Num(self.lo),
                Num(self.hi),
                Num(x)
            ))
        } else {
            Ok(x)
        }
    }
}

const fn positive(what: &'static str, hi: f64) -> Limit {
    Limit {
        what,
        lo: 0.0,
        hi,
        lo_included: false,
    }
}

pub const MACH: Limit = Limit {
    what: "the Mach number",
    lo: 1e-3,
    hi: 100.0,
    lo_included: true,
};
/// Each of a list of Mach numbers within [`MACH`] (the first that is not,
/// and why), as every command and the Python package take them.
pub fn machs(ms: &[f64]) -> Result<(), String> {
    ms.iter().try_for_each(|&m| MACH.check(m).map(|_| ()))
}

pub const CG: Limit = Limit {
    what: "the c.g. position h (M.A.C.s aft of its leading edge)",
    lo: -100.0,
    hi: 100.0,
    lo_included: true,
};
pub const MU1: Limit = positive("the relative density μ₁", 1e9);
pub const I_B: Limit = positive("the pitching inertia i_B", 1e9);
pub const CL_M2: Limit = positive("C_L·M² (eq 24)", 1e3);
pub const OMEGA_BAR: Limit = positive("the frequency parameter ω̄", 1e3);
pub const SIZE: Limit = positive("the size", 1e9);
/// A Mach number of a `[model.tables]` table (M = 0 is a table's row, not
/// a flight condition).
pub const TABLE_MACH: Limit = Limit {
    what: "a table's Mach number",
    lo: 0.0,
    hi: 100.0,
    lo_included: true,
};
/// A value of a `[model.tables]` table: a coefficient of §6 or a
/// derivative of the report's notation, none of which reaches 10⁶ (so that
/// the quartic's coefficients, products of four of them with μ₁ and i_B,
/// stay far from overflow).
pub const TABLE_VALUE: Limit = Limit {
    what: "a table's value",
    lo: -1e6,
    hi: 1e6,
    lo_included: true,
};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_say_what_is_wrong() {
        assert_eq!(MU1.check(50.0), Ok(50.0));
        assert!(
            MU1.check(-3.0)
                .unwrap_err()
                .contains("must be positive, not -3")
        );
        let e = CG.check(1e308).unwrap_err();
        assert!(e.contains("[-100, 100], not 1e308"), "{e}");
        assert!(MACH.check(f64::NAN).unwrap_err().contains("finite"));
        assert!(machs(&[0.5, 1.2]).is_ok());
        for bad in [0.0, 1e-320, -0.5, 101.0] {
            let e = machs(&[0.5, bad]).unwrap_err();
            assert!(
                e.contains("the Mach number must lie in [0.001, 100]"),
                "{e}"
            );
        }
    }
}
