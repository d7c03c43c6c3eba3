//! The descriptor system E ẋ = A x of the dimensional equations (state u, w,
//! q, θ) and its characteristic quartic det(λE − A), whose coefficients are
//! generated from `specs/dimensional.toml` (eqs D1–D2; see
//! `docs/dimensional-formulas.md`).

use super::DimensionalModel;
use crate::Quartic;
use nalgebra::Matrix4;

/// The inputs of the general quartic, eq (D1): the fifteen derivatives per
/// unit mass and inertia, the trim velocities and the two gravity terms.
/// A flat, allocation-free view of a [`DimensionalModel`], which is how
/// users build it ([`DimensionalModel::system`]).
#[derive(Debug, Clone, Copy, PartialEq, derive_quartic::Quartic)]
#[quartic(spec = "specs/dimensional.toml")]
pub struct DescriptorSystem {
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
    /// U₀ (ft/s or m/s).
    pub u0: f64,
    /// W₀ (ft/s or m/s).
    pub w0: f64,
    /// g cos θ₀.
    pub g_cos: f64,
    /// g sin θ₀.
    pub g_sin: f64,
}

impl DescriptorSystem {
    /// The characteristic quartic det(λE − A), λ in 1/s (eq D2).
    #[inline]
    #[must_use]
    pub fn quartic(&self) -> Quartic {
        Quartic::from_array(self.quartic_coefficients())
    }

    /// E of E ẋ = A x, state (u, w, q, θ):
    /// `[[1 − X_u̇, −X_ẇ, 0, 0], [−Z_u̇, 1 − Z_ẇ, 0, 0], [−M_u̇, −M_ẇ, 1, 0], [0, 0, 0, 1]]`.
    #[must_use]
    pub fn e(&self) -> Matrix4<f64> {
        #[rustfmt::skip]
        let e = Matrix4::new(
            1.0 - self.x_udot, -self.x_wdot,      0.0, 0.0,
            -self.z_udot,      1.0 - self.z_wdot, 0.0, 0.0,
            -self.m_udot,      -self.m_wdot,      1.0, 0.0,
            0.0,               0.0,               0.0, 1.0,
        );
        e
    }

    /// A of E ẋ = A x, state (u, w, q, θ):
    /// `[[X_u, X_w, X_q − W₀, −g cos θ₀], [Z_u, Z_w, Z_q + U₀, −g sin θ₀], [M_u, M_w, M_q, 0], [0, 0, 1, 0]]`.
    #[must_use]
    pub fn a(&self) -> Matrix4<f64> {
        #[rustfmt::skip]
        let a = Matrix4::new(
            self.x_u, self.x_w, self.x_q - self.w0, -self.g_cos,
            self.z_u, self.z_w, self.z_q + self.u0, -self.g_sin,
            self.m_u, self.m_w, self.m_q,           0.0,
            0.0,      0.0,      1.0,                0.0,
        );
        a
    }

    /// The state matrix E⁻¹A of ẋ = E⁻¹A x, when E is regular.
    #[must_use]
    pub fn state_matrix(&self) -> Option<Matrix4<f64>> {
        self.e().try_inverse().map(|inv| inv * self.a())
    }
}

impl DimensionalModel {
    /// The flat inputs of the general quartic (eq D1).
    #[must_use]
    pub fn system(&self) -> DescriptorSystem {
        let d = &self.derivatives;
        let t = &self.trim;
        DescriptorSystem {
            x_u: d.x_u,
            x_w: d.x_w,
            x_wdot: d.x_wdot,
            x_udot: d.x_udot,
            x_q: d.x_q,
            z_u: d.z_u,
            z_w: d.z_w,
            z_wdot: d.z_wdot,
            z_udot: d.z_udot,
            z_q: d.z_q,
            m_u: d.m_u,
            m_w: d.m_w,
            m_wdot: d.m_wdot,
            m_udot: d.m_udot,
            m_q: d.m_q,
            u0: t.u0,
            w0: t.w0,
            g_cos: t.g * t.theta0.cos(),
            g_sin: t.g * t.theta0.sin(),
        }
    }

    /// The characteristic quartic det(λE − A), λ in 1/s (eq D2).
    #[must_use]
    pub fn quartic(&self) -> Quartic {
        self.system().quartic()
    }

    /// (E, A) of the descriptor system E ẋ = A x, state (u, w, q, θ):
    /// for mode shapes (the eigenvectors of the pencil) and state-space
    /// export.
    #[must_use]
    pub fn descriptor(&self) -> (Matrix4<f64>, Matrix4<f64>) {
        let s = self.system();
        (s.e(), s.a())
    }

    /// The state matrix E⁻¹A (state u, w, q, θ; u, w in ft/s or m/s, q in
    /// rad/s, θ in rad), when E is regular.
    #[must_use]
    pub fn state_matrix(&self) -> Option<Matrix4<f64>> {
        self.system().state_matrix()
    }
}
