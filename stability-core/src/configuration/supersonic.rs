//! The supersonic aerodynamics of a configuration: each surface by the
//! program's theories, with the wing's downwash at the tailplane and its
//! lag (issue 21 item 3).

use super::{Configuration, ConfigurationError, ConfigurationSolution};

impl Configuration {
    /// The configuration's response at M > 1 and ω̄ (0: quasi-steady).
    pub fn solve_supersonic(
        &self,
        _mach: f64,
        _omega_bar: f64,
    ) -> Result<ConfigurationSolution, ConfigurationError> {
        Err(ConfigurationError::Unavailable(
            "the supersonic configuration theory",
        ))
    }
}
