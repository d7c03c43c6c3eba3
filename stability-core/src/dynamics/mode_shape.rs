//! Mode shapes: the eigenvector of each mode of a [`LinearModel`], as
//! Etkin & Reid (*Dynamics of Flight*, 3rd ed., 1996, §6.2, their mode
//! diagrams) and AVL's eigenmode output show it — each state's magnitude
//! and phase relative to θ.
//!
//! For an eigenvalue λ of A the eigenvector v solves (A − λI)v = 0. With
//! M = A − λI of rank 3 (a simple eigenvalue), the vector of the signed
//! 3×3 minors of any three rows of M (their generalised cross product) is
//! orthogonal to those rows, and so to the fourth, which depends on them:
//! it is v. Of the four choices of three rows the one of largest norm is
//! kept (the others may vanish when a row is a multiple of another). The
//! vector is then scaled so that θ = 1: a component u/θ = |u/θ|·e^{iφ}
//! with φ > 0 *leads* θ by φ, for the root with positive imaginary part
//! (the motion is Re(v·e^{λt})). Where θ takes no part in a mode (|θ| is
//! below 1e-9 of the largest component) the largest component is the
//! reference instead, and [`ModeShape::reference`] says so.
//!
//! q is in the model's unit of time: q̂ per rad of θ in units of τ
//! (q̂/θ = λ̂), rad/s per rad in seconds (q/θ = λ).

use crate::dynamics::linear::{LinearModel, STATES};
use crate::dynamics::modes::{Mode, ModeName, Origin};
use nalgebra::Matrix4;
use num_complex::Complex64;
use serde::{Serialize, Serializer};

/// The index of θ in the state vector.
const THETA: usize = 3;

/// The eigenvector of `a` for its eigenvalue `lambda` (any scale), or
/// `None` when (A − λI) has rank below 3 or λ is not an eigenvalue to
/// working precision.
pub fn eigenvector(a: &Matrix4<f64>, lambda: Complex64) -> Option<[Complex64; 4]> {
    let m: [[Complex64; 4]; 4] = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let diag = if i == j {
                lambda
            } else {
                Complex64::new(0.0, 0.0)
            };
            Complex64::new(a[(i, j)], 0.0) - diag
        })
    });
    let scale = m.iter().flatten().map(|z| z.norm()).fold(0.0, f64::max);
    let mut best: Option<([Complex64; 4], f64)> = None;
    for skip in 0..4 {
        let v = cross(&m, others(skip));
        let n = norm(&v);
        if best.is_none_or(|(_, b)| n > b) {
            best = Some((v, n));
        }
    }
    let (v, n) = best?;
    // the residual ‖Mv‖ against ‖M‖‖v‖: λ must be an eigenvalue
    let residual = (0..4)
        .map(|i| (0..4).map(|j| m[i][j] * v[j]).sum::<Complex64>().norm())
        .fold(0.0, f64::max);
    (n > 0.0 && n.is_finite() && residual <= 1e-8 * scale * n).then_some(v)
}

/// The generalised cross product of three rows of a 4×4 matrix: the
/// vector c with c_j = (−1)^j · det(the rows without column j).
fn cross(m: &[[Complex64; 4]; 4], rows: [usize; 3]) -> [Complex64; 4] {
    std::array::from_fn(|j| {
        let cols = others(j);
        let e = |r: usize, c: usize| m[rows[r]][cols[c]];
        let det = e(0, 0) * (e(1, 1) * e(2, 2) - e(1, 2) * e(2, 1))
            - e(0, 1) * (e(1, 0) * e(2, 2) - e(1, 2) * e(2, 0))
            + e(0, 2) * (e(1, 0) * e(2, 1) - e(1, 1) * e(2, 0));
        if j % 2 == 0 { det } else { -det }
    })
}

/// The three indices of 0..4 other than `k`, in order.
fn others(k: usize) -> [usize; 3] {
    std::array::from_fn(|i| if i < k { i } else { i + 1 })
}

fn norm(v: &[Complex64; 4]) -> f64 {
    v.iter().map(|z| z.norm_sqr()).sum::<f64>().sqrt()
}

/// A state's part in a mode: magnitude and phase (degrees, in (−180, 180])
/// relative to the reference state.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Component {
    pub magnitude: f64,
    pub phase_deg: f64,
}

impl Component {
    fn of(z: Complex64) -> Component {
        let phase = z.im.atan2(z.re).to_degrees();
        Component {
            magnitude: z.norm(),
            phase_deg: if phase <= -180.0 {
                phase + 360.0
            } else {
                phase
            },
        }
    }
}

/// The shape of one mode: its eigenvector scaled so that the reference
/// state (θ, unless θ takes no part) is 1.
#[derive(Debug, Clone, PartialEq)]
pub struct ModeShape {
    pub name: ModeName,
    pub origin: Option<Origin>,
    /// The eigenvalue (s ≥ 0 for a pair), in the model's unit of time.
    pub lambda: Complex64,
    /// The index into [`STATES`] of the component scaled to 1.
    pub reference: usize,
    /// The eigenvector, (u/V, α, q, θ).
    pub vector: [Complex64; 4],
}

impl ModeShape {
    /// The shape of `mode` (its root with s ≥ 0) in `model`, or `None`
    /// where the eigenvector is not determined (a multiple root).
    pub fn of(model: &LinearModel, mode: &Mode) -> Option<ModeShape> {
        let lambda = Complex64::new(mode.re, mode.im);
        let v = eigenvector(&model.a, lambda)?;
        let largest = (0..4)
            .max_by(|&i, &j| v[i].norm().total_cmp(&v[j].norm()))
            .unwrap_or(THETA);
        let reference = if v[THETA].norm() > 1e-9 * v[largest].norm() {
            THETA
        } else {
            largest
        };
        let r = v[reference];
        Some(ModeShape {
            name: mode.name,
            origin: mode.origin,
            lambda,
            reference,
            vector: v.map(|z| z / r),
        })
    }

    /// Every mode's shape that is determined, in the order of `modes`.
    pub fn all(model: &LinearModel, modes: &[Mode]) -> Vec<ModeShape> {
        modes
            .iter()
            .filter_map(|m| ModeShape::of(model, m))
            .collect()
    }

    /// The four components, (u/V, α, q, θ).
    pub fn components(&self) -> [Component; 4] {
        self.vector.map(Component::of)
    }
}

impl Serialize for ModeShape {
    /// `{mode, origin, re, im, reference, u_over_v, alpha, q, theta}`, each
    /// component `{magnitude, phase_deg}`.
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        #[derive(Serialize)]
        struct Json {
            mode: ModeName,
            origin: Option<Origin>,
            re: f64,
            im: f64,
            reference: &'static str,
            u_over_v: Component,
            alpha: Component,
            q: Component,
            theta: Component,
        }
        let [u, alpha, q, theta] = self.components();
        Json {
            mode: self.name,
            origin: self.origin,
            re: self.lambda.re,
            im: self.lambda.im,
            reference: STATES[self.reference],
            u_over_v: u,
            alpha,
            q,
            theta,
        }
        .serialize(s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_eigenvector_of_a_known_matrix() {
        // A = diag block: [[0, 1], [-4, -0.4]] ⊕ [[-1, 0], [0, -2]] has
        // λ = −0.2 ± i√3.96 with v ∝ (1, λ, 0, 0).
        let a = Matrix4::new(
            0.0, 1.0, 0.0, 0.0, -4.0, -0.4, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 0.0, -2.0,
        );
        let lam = Complex64::new(-0.2, 3.96f64.sqrt());
        let v = eigenvector(&a, lam).unwrap();
        let ratio = v[1] / v[0];
        assert!((ratio - lam).norm() < 1e-14);
        assert!(v[2].norm() < 1e-14 * v[0].norm() && v[3].norm() < 1e-14 * v[0].norm());
        // not an eigenvalue: refused
        assert!(eigenvector(&a, Complex64::new(-0.3, 2.0)).is_none());
    }

    #[test]
    fn phases_lie_in_the_half_open_interval() {
        assert_eq!(Component::of(Complex64::new(-1.0, -0.0)).phase_deg, 180.0);
        assert_eq!(Component::of(Complex64::new(-1.0, 0.0)).phase_deg, 180.0);
        assert!((Component::of(Complex64::new(0.0, 2.0)).phase_deg - 90.0).abs() < 1e-12);
    }
}
