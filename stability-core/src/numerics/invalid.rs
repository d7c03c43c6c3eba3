//! A quantity whose value is not one it may take: not a finite number, or
//! not positive. One error for every such check of the crate's inputs;
//! each module's error names its quantities in its own terms (a name, a
//! [`crate::design::case::CaseInput`], a [`crate::design::flight::FlightInput`]) and wraps
//! this one.

use crate::numerics::display::Num;
use std::fmt;

/// A value that is not finite, or not positive where it must be.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum Invalid<Q: fmt::Display> {
    #[error("{quantity} must be a finite number, not {}", Num(*value))]
    NonFinite { quantity: Q, value: f64 },
    #[error("{quantity} must be positive, not {}", Num(*value))]
    NotPositive { quantity: Q, value: f64 },
}

impl<Q: fmt::Display + Copy> Invalid<Q> {
    /// The quantity at fault.
    pub fn quantity(&self) -> Q {
        match self {
            Invalid::NonFinite { quantity, .. } | Invalid::NotPositive { quantity, .. } => {
                *quantity
            }
        }
    }

    /// Its value.
    pub fn value(&self) -> f64 {
        match self {
            Invalid::NonFinite { value, .. } | Invalid::NotPositive { value, .. } => *value,
        }
    }
}

/// `value` if it is a finite number.
pub fn finite<Q: fmt::Display>(quantity: Q, value: f64) -> Result<f64, Invalid<Q>> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Invalid::NonFinite { quantity, value })
    }
}

/// `value` if it is a finite positive number.
pub fn positive<Q: fmt::Display>(quantity: Q, value: f64) -> Result<f64, Invalid<Q>> {
    if !value.is_finite() {
        Err(Invalid::NonFinite { quantity, value })
    } else if value <= 0.0 {
        Err(Invalid::NotPositive { quantity, value })
    } else {
        Ok(value)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn checks_say_what_is_wrong() {
        assert_eq!(finite("h", 0.25), Ok(0.25));
        let e = finite("h", f64::NAN).unwrap_err();
        assert_eq!(e.to_string(), "h must be a finite number, not NaN");
        assert_eq!((e.quantity(), e.value().is_nan()), ("h", true));
        assert_eq!(
            positive("mu1", -1e308).unwrap_err().to_string(),
            "mu1 must be positive, not -1e308"
        );
        assert!(matches!(
            positive("mu1", f64::INFINITY),
            Err(Invalid::NonFinite { .. })
        ));
        assert_eq!(positive("mu1", 5e-324), Ok(5e-324));
    }
}
