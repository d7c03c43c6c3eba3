//! Diagnostics that point into a spec file: file, line, column and entry.
//!
//! After serde_derive's `Ctxt`: a [`Diagnostics`] collects problems through
//! `&self`, so every validation function can report and carry on, and it
//! cannot be dropped unchecked — it must be consumed by
//! [`Diagnostics::check`] or [`Diagnostics::finish`], or it panics in
//! `Drop` (a validation path that forgot its errors is a bug, not a silent
//! success). The collected problems come out as [`SpecErrors`], which turn
//! into one `syn::Error` in one place ([`SpecErrors::to_syn_error`]).

use quote::ToTokens;
use std::cell::RefCell;
use std::fmt;

/// One problem found in a spec, located at a file, line and column, inside a
/// named entry of the spec.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Diagnostic {
    pub file: String,
    pub line: usize,
    pub column: usize,
    /// The spec entry, e.g. "eq (6), coefficient `B`, printed term 4".
    pub entry: String,
    pub message: String,
    pub help: Option<String>,
}

impl Diagnostic {
    pub fn with_help(mut self, help: impl Into<String>) -> Self {
        self.help = Some(help.into());
        self
    }
}

impl fmt::Display for Diagnostic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}:{}: ", self.file, self.line, self.column)?;
        if !self.entry.is_empty() {
            write!(f, "{}: ", self.entry)?;
        }
        write!(f, "{}", self.message)?;
        if let Some(help) = &self.help {
            write!(f, "\n  = help: {help}")?;
        }
        Ok(())
    }
}

/// The collector of one spec's problems (see the module documentation).
#[derive(Debug)]
pub struct Diagnostics {
    /// `None` once consumed by `check` or `finish`.
    list: RefCell<Option<Vec<Diagnostic>>>,
}

impl Default for Diagnostics {
    fn default() -> Self {
        Self::new()
    }
}

impl Diagnostics {
    pub fn new() -> Self {
        Diagnostics {
            list: RefCell::new(Some(Vec::new())),
        }
    }

    /// Record a problem.
    pub fn push(&self, d: Diagnostic) {
        if let Some(list) = self.list.borrow_mut().as_mut() {
            list.push(d);
        }
    }

    /// How many problems have been recorded so far.
    pub fn count(&self) -> usize {
        self.list.borrow().as_ref().map_or(0, Vec::len)
    }

    /// Whether any problem has been recorded (a stage that needs the
    /// previous one whole stops here).
    pub fn has_errors(&self) -> bool {
        self.count() > 0
    }

    /// Consume the collector: `Ok(())` if nothing was reported.
    pub fn check(self) -> Result<(), SpecErrors> {
        let list = self.list.borrow_mut().take().unwrap_or_default();
        if list.is_empty() {
            Ok(())
        } else {
            Err(SpecErrors(list))
        }
    }

    /// Consume the collector with the value a validation produced: the value
    /// if nothing was reported. A validation that gave up (`None`) must have
    /// said why; if it did not, that is reported as an internal error rather
    /// than passed over.
    pub fn finish<T>(self, value: Option<T>, file: &str) -> Result<T, SpecErrors> {
        self.check()?;
        value.ok_or_else(|| {
            SpecErrors(vec![Diagnostic {
                file: file.to_string(),
                line: 1,
                column: 1,
                entry: String::new(),
                message: "internal error of derive-quartic: the spec was refused without a diagnostic; please report it".into(),
                help: None,
            }])
        })
    }
}

impl Drop for Diagnostics {
    fn drop(&mut self) {
        if self.list.get_mut().is_some() && !std::thread::panicking() {
            panic!("formula_engine::Diagnostics dropped without `check()` or `finish()`");
        }
    }
}

/// The problems found in one spec. A spec with any problem yields no model.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SpecErrors(pub Vec<Diagnostic>);

impl SpecErrors {
    pub fn iter(&self) -> impl Iterator<Item = &Diagnostic> {
        self.0.iter()
    }

    /// One compile error per diagnostic, all pointing at `at` (the spec
    /// path as the user wrote it in the macro call).
    pub fn to_syn_error(&self, at: &impl ToTokens) -> syn::Error {
        let errors = self
            .iter()
            .map(|d| syn::Error::new_spanned(at, d.to_string()));
        combine(errors).unwrap_or_else(|| syn::Error::new_spanned(at, "invalid spec"))
    }
}

/// Several compile errors as one (`None` if there are none).
pub fn combine(errors: impl IntoIterator<Item = syn::Error>) -> Option<syn::Error> {
    errors.into_iter().reduce(|mut first, e| {
        first.combine(e);
        first
    })
}

impl fmt::Display for SpecErrors {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, d) in self.0.iter().enumerate() {
            if i > 0 {
                writeln!(f)?;
            }
            write!(f, "{d}")?;
        }
        Ok(())
    }
}

impl std::error::Error for SpecErrors {}

#[cfg(test)]
mod tests {
    use super::*;

    fn diagnostic(message: &str) -> Diagnostic {
        Diagnostic {
            file: "s.toml".into(),
            line: 2,
            column: 5,
            entry: "row `x`".into(),
            message: message.into(),
            help: None,
        }
    }

    #[test]
    fn problems_are_collected_through_shared_references() {
        let diags = Diagnostics::new();
        let report = |d: &Diagnostics, m: &str| d.push(diagnostic(m));
        report(&diags, "first");
        report(&diags, "second");
        assert_eq!(diags.count(), 2);
        let errors = diags.check().unwrap_err();
        assert_eq!(
            errors.to_string(),
            "s.toml:2:5: row `x`: first\ns.toml:2:5: row `x`: second"
        );
    }

    #[test]
    fn finish_gives_the_value_only_when_nothing_was_reported() {
        assert_eq!(Diagnostics::new().finish(Some(3), "s.toml"), Ok(3));
        let diags = Diagnostics::new();
        diags.push(diagnostic("bad"));
        assert!(diags.finish(Some(3), "s.toml").is_err());
        let silent = Diagnostics::new()
            .finish(None::<i32>, "s.toml")
            .unwrap_err();
        assert!(silent.to_string().contains("internal error"), "{silent}");
    }

    #[test]
    #[should_panic(expected = "dropped without `check()` or `finish()`")]
    fn an_unchecked_collector_panics_when_dropped() {
        let diags = Diagnostics::new();
        diags.push(diagnostic("forgotten"));
    }

    #[test]
    fn one_syn_error_carries_every_diagnostic() {
        let errors = SpecErrors(vec![diagnostic("a"), diagnostic("b")]);
        let lit = syn::LitStr::new("spec.toml", proc_macro2::Span::call_site());
        let e = errors.to_syn_error(&lit);
        assert_eq!(e.into_iter().count(), 2);
    }
}
