//! What an engineer reads beside the report's quantities, for any
//! derivative set: the linear model ẋ = A x + B δ ([`crate::dynamics::linear`]),
//! the mode shapes ([`crate::dynamics::mode_shape`]) and — when times in seconds are
//! known — the `damp()` table ([`crate::dynamics::damp`]) and the MIL-F-8785C
//! short-period frequency requirement ([`crate::criteria::cap`]).
//!
//! Two ways in:
//! - a derivative set in the report's notation, its [`Analysis`] and τ
//!   when known ([`Engineering::of_report`]);
//! - any model already in seconds with states (u/V, α, q, θ) — e.g. a
//!   dimensional, body-axis set, through [`LinearModel::of_dimensional`] —
//!   with its four roots in 1/s (its quartic's, or
//!   [`LinearModel::eigenvalues`]) and its n/α when known
//!   ([`Engineering::of_model`]).

use crate::Derivatives;
use crate::analysis::Analysis;
use crate::criteria::cap::{AirplaneClass, ShortPeriodFrequency, n_alpha};
use crate::dynamics::damp::Damp;
use crate::dynamics::linear::{Control, LinearModel, TimeUnit};
use crate::dynamics::mode_shape::ModeShape;
use crate::dynamics::response::ResponseError;
use num_complex::Complex64;
use serde::Serialize;

/// The engineer's view of one derivative set.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Engineering {
    /// The state-space model, in seconds when they are known, else in τ.
    #[serde(skip)]
    pub model: LinearModel,
    /// The modes in seconds (when they are known).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub damp: Option<Damp>,
    /// Each mode's eigenvector, in the model's unit of time.
    pub mode_shapes: Vec<ModeShape>,
    /// §3.2.2.1.1, when the short period oscillates and ω_sp (rad/s) and
    /// n/α are known.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub short_period_frequency: Option<ShortPeriodFrequency>,
    /// Why §3.2.2.1.1 is not assessed where the short period oscillates in
    /// seconds and n/α was given, but CAP = ω_sp²/(n/α) is undefined (n/α
    /// not finite, as at C_L = 0, or zero): `short_period_frequency` is
    /// then absent.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub short_period_frequency_not_assessed: Option<String>,
}

impl Engineering {
    /// A derivative set in the report's notation with its analysis, τ (s)
    /// when known and the control derivatives when given; n/α = −z_w/C_L.
    pub fn of_report(
        d: &Derivatives,
        analysis: &Analysis,
        tau: Option<f64>,
        control: Option<&Control>,
        class: Option<AirplaneClass>,
    ) -> Result<Engineering, ResponseError> {
        let model = LinearModel::of_report(d, control)?;
        // the mode shapes are the model's eigenvectors, so at the roots of
        // the derivatives' own quartic: where the analysis's roots are each
        // at its own frequency (the p-method), the k-method's
        let own = Analysis::without_classical(d).ok();
        let shaped = own.as_ref().unwrap_or(analysis);
        let Some(tau) = tau else {
            return Ok(Engineering {
                mode_shapes: ModeShape::all(&model, &shaped.modes),
                model,
                damp: None,
                short_period_frequency: None,
                short_period_frequency_not_assessed: None,
            });
        };
        let roots = analysis.roots.map(|z| z / tau);
        let model = model.in_seconds(tau);
        let mode_shapes = ModeShape::all(
            &model,
            Damp::of_roots(&shaped.roots.map(|z| z / tau)).modes(),
        );
        Ok(Engineering {
            mode_shapes,
            ..Engineering::of_model(model, &roots, Some(n_alpha(d.z_w, d.c_l)), class)
        })
    }

    /// A model in seconds with its four roots (1/s) and n/α (g/rad) when
    /// known. A model in units of τ gets its mode shapes only.
    pub fn of_model(
        model: LinearModel,
        roots_per_s: &[Complex64; 4],
        n_alpha: Option<f64>,
        class: Option<AirplaneClass>,
    ) -> Engineering {
        let damp = Damp::of_roots(roots_per_s);
        let mode_shapes = ModeShape::all(&model, damp.modes());
        if model.time == TimeUnit::Tau {
            return Engineering {
                model,
                damp: None,
                mode_shapes,
                short_period_frequency: None,
                short_period_frequency_not_assessed: None,
            };
        }
        let assessed = match (damp.0.short_period(), n_alpha) {
            (Some(sp), Some(n)) => {
                Some(ShortPeriodFrequency::assess(sp.natural_frequency, n, class))
            }
            _ => None,
        };
        Engineering {
            model,
            damp: Some(damp),
            mode_shapes,
            short_period_frequency: assessed.clone().and_then(Result::ok),
            short_period_frequency_not_assessed: assessed.and_then(Result::err),
        }
    }
}
