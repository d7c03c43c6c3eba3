//! Which MIL-F-8785C airplane class (§1.3) a design point is assessed as,
//! and where that came from.
//!
//! The class matters to one requirement only: the Category C floors on
//! ω_sp and n/α of the short-period frequency requirement (§3.2.2.1.1,
//! Fig 3: Classes I, II-C and IV against II-L and III;
//! [`stability_core::criteria::cap`]). The damping-ratio limits (§3.2.2.1.2) and the
//! phugoid's (§3.2.1.2) depend on the flight-phase category, not the
//! class, and Categories A and B of the frequency requirement do not
//! either. So the rule is: the class given on the command line (or as an
//! argument); else the one the config states (`[aircraft] class`); else
//! none — every class-independent level is still assessed, and Category C
//! of the frequency requirement is not, with the reason printed.

use stability_core::criteria::cap::AirplaneClass;

/// Where the class came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ClassSource {
    /// Given with the command (`--class`, an argument).
    Given,
    /// The config's `[aircraft] class`.
    Config,
    /// Neither: Category C of the frequency requirement not assessed.
    NotGiven,
}

/// The class a design point is assessed as, and where it came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ClassChoice {
    pub class: Option<AirplaneClass>,
    pub source: ClassSource,
}

impl ClassChoice {
    /// `given` if there is one, else `stated` by the input, else none.
    pub fn of(given: Option<AirplaneClass>, stated: Option<AirplaneClass>) -> ClassChoice {
        let (class, source) = match (given, stated) {
            (Some(c), _) => (Some(c), ClassSource::Given),
            (None, Some(c)) => (Some(c), ClassSource::Config),
            (None, None) => (None, ClassSource::NotGiven),
        };
        ClassChoice { class, source }
    }

    /// The choice in words, `flag` naming how a class is given (`--class`,
    /// `class=`).
    pub fn describe(&self, flag: &str) -> String {
        match (self.class, self.source) {
            (Some(c), ClassSource::Given) => {
                format!("Class {} ({}), given by {flag}", c.name(), c.describe())
            }
            (Some(c), _) => format!(
                "Class {} ({}), from the config's [aircraft] class",
                c.name(),
                c.describe()
            ),
            (None, _) => format!(
                "class not given, and Category C's floors depend on it (§1.3); give {flag} or [aircraft] class"
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_given_class_wins_then_the_configs() {
        let (iv, iii) = (Some(AirplaneClass::IV), Some(AirplaneClass::III));
        let c = ClassChoice::of(iv, iii);
        assert_eq!((c.class, c.source), (iv, ClassSource::Given));
        let c = ClassChoice::of(None, iii);
        assert_eq!((c.class, c.source), (iii, ClassSource::Config));
        assert!(c.describe("--class").starts_with("Class III (large"));
        let c = ClassChoice::of(None, None);
        assert_eq!((c.class, c.source), (None, ClassSource::NotGiven));
        assert!(
            c.describe("--class").contains("not given") && c.describe("-c").contains("give -c")
        );
    }
}
