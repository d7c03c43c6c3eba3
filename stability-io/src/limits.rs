//! The range each design-point value may take, defined once for the
//! config, `analyze`'s overrides and `sweep`'s ranges. The ranges hold
//! every aircraft and keep every derived quantity far from overflow (a c.g.
//! at h = 1e308 is finite, but its derivatives are not).

use stability_core::display::Num;

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
    }
}
