//! The subsonic aerodynamics of a whole configuration from one doublet
//! lattice over all its surfaces (issue 21 item 2).

use super::{Configuration, ConfigurationError, ConfigurationSolution};

impl Configuration {
    /// The configuration's response at M < 1 and ω̄ (0: quasi-steady).
    pub fn solve_subsonic(
        &self,
        _mach: f64,
        _omega_bar: f64,
    ) -> Result<ConfigurationSolution, ConfigurationError> {
        Err(ConfigurationError::Unavailable(
            "the multi-surface doublet lattice",
        ))
    }
}
