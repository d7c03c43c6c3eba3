//! A config's design point evaluated: the library's result (§5–9), its
//! physical flight condition at the point's Mach number, and the
//! engineer's outputs — every number finite, or the error at the field it
//! arises from. What `analyze` prints and the Python package's `analyze()`
//! returns.

use crate::Failure;
use crate::class::ClassChoice;
use crate::config::Config;
use crate::input::analysis::OVERFLOW;
use stability_core::cap::AirplaneClass;
use stability_core::case::{CaseResult, evaluate};
use stability_core::engineering::Engineering;
use stability_core::flight::{FlightPoint, PhysicalFlight};

/// A design point's results: the library's, and the engineer's.
pub struct Results {
    pub result: CaseResult,
    /// The physical flight condition at the point's Mach number.
    pub flight: Option<(PhysicalFlight, FlightPoint)>,
    pub engineering: Engineering,
    /// The MIL-F-8785C class assessed, and where it came from.
    pub class: ClassChoice,
}

impl Results {
    /// τ = m/(½ρSV) in seconds, at a physical flight condition.
    pub fn tau(&self) -> Option<f64> {
        self.flight.map(|(_, p)| p.tau)
    }
}

/// The design point of `cfg` evaluated, with the short-period frequency
/// requirement of the class `given`, else the config's ([`ClassChoice`]).
pub fn results(cfg: &Config, given: Option<AirplaneClass>) -> Result<Results, Failure> {
    let class = ClassChoice::of(given, cfg.class);
    let flight = match &cfg.physical {
        Some(p) => {
            let point = p
                .flight
                .at_mach(cfg.case.mach)
                .map_err(|e| cfg.error_at("[flight] mach", e.to_string()))?;
            Some((p.flight, point))
        }
        None => None,
    };
    let result = evaluate(&cfg.case).map_err(|e| cfg.explain(&e))?;
    let control = crate::control::read_control(&cfg.path, cfg.text())?;
    let tau = flight.map(|(_, p)| p.tau);
    let engineering = Engineering::of_report(
        &result.derivatives,
        &result.analysis,
        tau,
        control.as_ref(),
        class.class,
    );
    match engineering {
        Ok(engineering) if result.analysis.is_finite() => Ok(Results {
            result,
            flight,
            engineering,
            class,
        }),
        _ => Err(cfg.error_at("[flight]", OVERFLOW).into()),
    }
}
