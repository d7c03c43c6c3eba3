//! Dimensional derivative sets as handbooks print them: forces
//! per unit mass and moments per unit pitching inertia, in body or
//! stability axes, in ft–slug–s or SI, with a trim attitude θ₀ and trim
//! velocities U₀, W₀. The equations (state u, w, q, θ), in descriptor form
//! E ẋ = A x:
//!
//! ```text
//! (1 − X_u̇)u̇ − X_ẇ ẇ      = X_u u + X_w w + (X_q − W₀) q − g cos θ₀ · θ
//! −Z_u̇ u̇ + (1 − Z_ẇ) ẇ    = Z_u u + Z_w w + (Z_q + U₀) q − g sin θ₀ · θ
//! −M_u̇ u̇ − M_ẇ ẇ + q̇      = M_u u + M_w w + M_q q
//! θ̇                         = q
//! ```
//!
//! Their characteristic quartic det(λE − A) (eqs D1–D2) is generated from
//! `specs/dimensional.toml`; eq (4) of the report is its special case (level
//! flight in stability axes, no u̇ terms). The u̇ derivatives are optional
//! (zero unless given): a body-axis set whose ẇ and q derivatives are α̇ and
//! flight-path effects needs them (α̇ = (U₀ẇ − W₀u̇)/V²), and rotating a set
//! from body into stability axes brings them in ([`DimensionalModel::in_stability_axes`]).
//! See `docs/dimensional.md`.
//!
//! - [`system`]: the flat quartic inputs ([`DescriptorSystem`]) and the
//!   matrices E, A, E⁻¹A;
//! - [`report`]: the conversion to and from the report's notation
//!   ([`Reference`]: c̄, μ₁, i_B);
//! - [`analysis`]: roots in 1/s, modes in seconds, Routh, the §8 verdict,
//!   MIL-F-8785C levels ([`DimensionalAnalysis`]).
//!
//! The 747 of NASA CR-2144, flight condition 9, body axes, as printed:
//!
//! ```
//! use stability_core::data::dimensional::{
//!     Axes, DimensionalAnalysis, DimensionalDerivatives, DimensionalModel, Reference, Trim, Units,
//! };
//! let model = DimensionalModel {
//!     axes: Axes::Body,
//!     units: Units::Ft,
//!     derivatives: DimensionalDerivatives {
//!         x_u: -0.00276, x_w: 0.0389, z_u: -0.065, z_w: -0.317, z_wdot: 0.00556, z_q: -5.16,
//!         m_u: 0.000193, m_w: -0.00105, m_wdot: -0.000116, m_q: -0.339,
//!         ..Default::default()
//!     },
//!     trim: Trim { u0: 771.5069, w0: 62.0740, theta0: 4.6f64.to_radians(), g: 32.174 },
//! };
//! let reference = Reference::physical(5.9092e-4, 5500.0, 27.3, 636_636.0 / 32.174, 3.31e7);
//! let a = DimensionalAnalysis::of(&model, Some(&reference)).unwrap();
//! let ph = a.modes.phugoid().unwrap();          // 1/s and s
//! assert!((ph.damping_ratio.unwrap() - 0.0485).abs() < 5e-5);
//! assert!((ph.period.unwrap() - 93.49).abs() < 0.01);
//! // the same motion in stability axes, and the state matrix E⁻¹A
//! let st = model.in_stability_axes();
//! assert!(st.trim.w0 == 0.0 && st.derivatives.m_udot != 0.0);
//! let a_matrix = model.state_matrix().unwrap();
//! assert!((a_matrix.trace() - (-0.7457561 / 0.99444)).abs() < 1e-6);
//! // and in the report's notation (τ = μ₁c̄/V)
//! let eq = model.to_report(&reference);
//! assert!((eq.tau - 15.732).abs() < 1e-3 && !eq.is_exact());
//! ```

pub mod analysis;
pub mod form;
pub mod json;
pub mod report;
pub mod system;

pub use analysis::{DimensionalAnalysis, DimensionalError};
pub use form::{Form, Inertia, Printed};
pub use report::{Dropped, Reference, ReportEquivalent};
pub use system::DescriptorSystem;

use nalgebra::Matrix4;
use serde::Serialize;

/// The axes a set's derivatives are referred to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Axes {
    /// Body axes fixed in the aircraft (CR-2144's "body axis system"): the
    /// trim velocity has components U₀, W₀ and the x axis is at θ₀ to the
    /// horizon.
    Body,
    /// Stability axes: x along the trim velocity (W₀ = 0); θ₀ is then the
    /// flight-path angle γ₀.
    Stability,
}

impl Axes {
    pub const ALL: [Axes; 2] = [Axes::Body, Axes::Stability];

    /// `body`, `stability` (the file's spelling).
    pub fn as_str(self) -> &'static str {
        match self {
            Axes::Body => "body",
            Axes::Stability => "stability",
        }
    }

    pub fn parse(s: &str) -> Option<Axes> {
        Axes::ALL.into_iter().find(|a| a.as_str() == s)
    }
}

pub use crate::units::Units;

/// The derivatives per unit mass (X, Z) and per unit pitching inertia (M),
/// as CR-2144 and Etkin & Reid tabulate them: X_u = (∂X/∂u)/m, …,
/// M_q = (∂M/∂q)/I_y. The u̇ derivatives are optional in files (zero).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DimensionalDerivatives {
    pub x_u: f64,
    pub x_w: f64,
    pub x_wdot: f64,
    pub x_udot: f64,
    pub x_q: f64,
    pub z_u: f64,
    pub z_w: f64,
    pub z_wdot: f64,
    pub z_udot: f64,
    pub z_q: f64,
    pub m_u: f64,
    pub m_w: f64,
    pub m_wdot: f64,
    pub m_udot: f64,
    pub m_q: f64,
}

impl DimensionalDerivatives {
    /// The names of a file's `[derivatives]` table, in the order of
    /// [`Self::values`].
    pub const NAMES: [&'static str; 15] = [
        "X_u", "X_w", "X_wdot", "X_udot", "X_q", "Z_u", "Z_w", "Z_wdot", "Z_udot", "Z_q", "M_u",
        "M_w", "M_wdot", "M_udot", "M_q",
    ];

    /// The names that may be left out (taken as 0): the ẇ, u̇ and q
    /// derivatives of X and Z, and M's ẇ and u̇ derivatives.
    pub const OPTIONAL: [&'static str; 8] = [
        "X_wdot", "X_udot", "X_q", "Z_wdot", "Z_udot", "Z_q", "M_wdot", "M_udot",
    ];

    /// The values, in the order of [`Self::NAMES`].
    pub fn values(&self) -> [f64; 15] {
        [
            self.x_u,
            self.x_w,
            self.x_wdot,
            self.x_udot,
            self.x_q,
            self.z_u,
            self.z_w,
            self.z_wdot,
            self.z_udot,
            self.z_q,
            self.m_u,
            self.m_w,
            self.m_wdot,
            self.m_udot,
            self.m_q,
        ]
    }

    /// From the values in the order of [`Self::NAMES`].
    pub fn from_values(v: [f64; 15]) -> Self {
        let [
            x_u,
            x_w,
            x_wdot,
            x_udot,
            x_q,
            z_u,
            z_w,
            z_wdot,
            z_udot,
            z_q,
            m_u,
            m_w,
            m_wdot,
            m_udot,
            m_q,
        ] = v;
        DimensionalDerivatives {
            x_u,
            x_w,
            x_wdot,
            x_udot,
            x_q,
            z_u,
            z_w,
            z_wdot,
            z_udot,
            z_q,
            m_u,
            m_w,
            m_wdot,
            m_udot,
            m_q,
        }
    }

    /// Whether any u̇ derivative is non-zero.
    pub fn has_udot_terms(&self) -> bool {
        [self.x_udot, self.z_udot, self.m_udot]
            .iter()
            .any(|&v| v != 0.0)
    }
}

/// The trim (reference) flight condition of the linearisation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Trim {
    /// U₀, trim velocity along x (ft/s or m/s), positive.
    pub u0: f64,
    /// W₀, trim velocity along z (0 in stability axes).
    pub w0: f64,
    /// θ₀, pitch attitude of the x axis above the horizon (rad).
    pub theta0: f64,
    /// g (ft/s² or m/s²).
    pub g: f64,
}

impl Trim {
    /// The trim airspeed V = √(U₀² + W₀²).
    pub fn speed(&self) -> f64 {
        self.u0.hypot(self.w0)
    }

    /// The trim incidence of the x axis, α₀ = atan(W₀/U₀) (rad).
    pub fn alpha0(&self) -> f64 {
        self.w0.atan2(self.u0)
    }

    /// The flight-path angle γ₀ = θ₀ − α₀ (rad).
    pub fn gamma0(&self) -> f64 {
        self.theta0 - self.alpha0()
    }
}

/// A dimensional derivative set with its axes, units and trim: the library
/// type of `notation = "dimensional"`, and of a report-notation set with a
/// dimensional flight condition ([`DimensionalModel::from_report`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DimensionalModel {
    pub axes: Axes,
    pub units: Units,
    pub derivatives: DimensionalDerivatives,
    pub trim: Trim,
}

/// The largest |θ₀| accepted: the equations linearise about a trim
/// attitude, and at ±90° the x axis is vertical.
pub const THETA0_MAX: f64 = 89.0 * std::f64::consts::PI / 180.0;

impl DimensionalModel {
    /// The same motion referred to stability axes: x along the trim
    /// velocity (W₀ = 0, U₀ = V), θ₀ − α₀ = γ₀, the derivatives rotated by
    /// the trim incidence α₀ = atan(W₀/U₀). With c = cos α₀, s = sin α₀,
    /// (u, w)_body = T (u, w)_stab with T = [[c, −s], [s, c]] and the force
    /// rows are turned by Tᵀ, so E and A become Tᵀ E T and Tᵀ A T (T acting
    /// on the u, w block): the eigenvalues are unchanged, but the ẇ
    /// derivatives of a body-axis set generally give u̇ derivatives in
    /// stability axes (and u̇ ones ẇ ones). A stability-axis model is
    /// returned as it is.
    #[must_use]
    pub fn in_stability_axes(&self) -> DimensionalModel {
        if self.axes == Axes::Stability {
            return *self;
        }
        let alpha = self.trim.alpha0();
        let (s, c) = alpha.sin_cos();
        let mut t = Matrix4::identity();
        t[(0, 0)] = c;
        t[(0, 1)] = -s;
        t[(1, 0)] = s;
        t[(1, 1)] = c;
        let (e, a) = self.descriptor();
        let (e, a) = (t.transpose() * e * t, t.transpose() * a * t);
        let trim = Trim {
            u0: self.trim.speed(),
            w0: 0.0,
            theta0: self.trim.theta0 - alpha,
            g: self.trim.g,
        };
        // The q column's trim terms cancel exactly (s U₀ − c W₀ = 0,
        // s W₀ + c U₀ = V); X_q, Z_q turn as a force, without that rounding.
        let d = &self.derivatives;
        let derivatives = DimensionalDerivatives {
            x_q: c * d.x_q + s * d.z_q,
            z_q: -s * d.x_q + c * d.z_q,
            ..derivatives_of(&e, &a, &trim)
        };
        DimensionalModel {
            axes: Axes::Stability,
            units: self.units,
            derivatives,
            trim,
        }
    }
}

/// The derivatives whose E and A (with `trim`'s U₀, W₀) are these: the
/// inverse of [`DescriptorSystem::e`] and [`DescriptorSystem::a`].
fn derivatives_of(e: &Matrix4<f64>, a: &Matrix4<f64>, trim: &Trim) -> DimensionalDerivatives {
    DimensionalDerivatives {
        x_u: a[(0, 0)],
        x_w: a[(0, 1)],
        x_wdot: -e[(0, 1)],
        x_udot: 1.0 - e[(0, 0)],
        x_q: a[(0, 2)] + trim.w0,
        z_u: a[(1, 0)],
        z_w: a[(1, 1)],
        z_wdot: 1.0 - e[(1, 1)],
        z_udot: -e[(1, 0)],
        z_q: a[(1, 2)] - trim.u0,
        m_u: a[(2, 0)],
        m_w: a[(2, 1)],
        m_wdot: -e[(2, 1)],
        m_udot: -e[(2, 0)],
        m_q: a[(2, 2)],
    }
}
