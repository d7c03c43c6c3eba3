//! The independent numerical route: the source integral evaluated at each
//! receiver, then integrated over the trailing edge and the wing.
//!
//! The upper-surface potential of a downwash w on a wing whose leading
//! edges are supersonic (A.E. Puckett, "Supersonic wave drag of thin
//! airfoils", J. Aero. Sci. 13, 1946; with the low-frequency kernel of J.W.
//! Miles, *The Potential Theory of Unsteady Supersonic Flow*, 1959, §5.3:
//! e^{−iωM²(x−ξ)/(Vβ²)} expanded to first order) is
//! Φ(P) = −(1/π) ∫∫_{E(P)} w(ξ)[1 − iωM²(x − ξ)/(Vβ²)] dξ dη / R,
//! R = √((x − ξ)² − β²(y − η)²), over Evvard's reduced area E(P) (see
//! [`super::evvard`]). In characteristic coordinates u, v about P, with
//! u = σ², v = ρ², dξ dη/R = 2 dσ dρ/β, so
//! Φ(P) = −(2/(πβ)) ∫dσ ∫₀^{ρ_max(σ)} w dρ: the singular kernel disappears,
//! the ρ-integral of a polynomial w is done exactly, and the σ-integral is
//! split where the bounds of E(P) (tip clips and the two leading-edge
//! branches, all straight lines in u, v) change over. The receivers are
//! integrated by adaptive Gauss–Kronrod quadrature.
//!
//! Nothing here is shared with [`super::evvard`] but the statement of
//! Evvard's area: the order of integration, the quadratures and the
//! treatment of the tips differ. It is slow (tens of milliseconds) and
//! serves the tests.

use super::quadrature::{adaptive, tanh_sinh};
use super::{PotentialIntegrals, Wing};
use std::f64::consts::PI;

/// The wing in the stretched coordinates X = x, Y = βy (c₀ = 1).
struct Stretched {
    m: f64,
    big_s: f64,
    x_tip: f64,
    beta: f64,
}

impl Stretched {
    fn new(wing: &Wing, mach: f64) -> Stretched {
        let beta = (mach * mach - 1.0).sqrt();
        Stretched {
            m: beta * wing.cot(),
            big_s: beta * wing.semi_span(),
            x_tip: 1.0 - wing.taper,
            beta,
        }
    }

    /// v_max(u) over E(P) for the receiver (x, Y) (0 past the end of E(P)).
    fn v_max(&self, x: f64, y: f64, u: f64) -> f64 {
        let m = self.m;
        let mut v = 2.0 * (self.big_s + y);
        if m - 1.0 > 1e-12 {
            v = v.min((2.0 * m * x - 2.0 * y - (1.0 + m) * u) / (m - 1.0));
        }
        v = v.min((2.0 * m * x + 2.0 * y - (m - 1.0) * u) / (m + 1.0));
        v.max(0.0)
    }

    /// The end of the u-range of E(P) and the points where its bound
    /// changes over, in order.
    fn u_breaks(&self, x: f64, y: f64) -> Vec<f64> {
        let m = self.m;
        let k = 2.0 * (self.big_s + y);
        let mut end = (2.0 * self.big_s - 2.0 * y).min((2.0 * m * x - 2.0 * y) / (1.0 + m));
        if m - 1.0 > 1e-12 {
            end = end.min((2.0 * m * x + 2.0 * y) / (m - 1.0));
        }
        let mut b = vec![0.0, end.max(0.0)];
        let mut cand = vec![x - y, (2.0 * m * x - 2.0 * y - (m - 1.0) * k) / (1.0 + m)];
        if m - 1.0 > 1e-12 {
            cand.push((2.0 * m * x + 2.0 * y - (m + 1.0) * k) / (m - 1.0));
        }
        b.extend(cand.into_iter().filter(|&u| u > 0.0 && u < end));
        b.sort_by(f64::total_cmp);
        b
    }

    /// [Φ₀ for w = 1, Φ₀ for w = x, Φ₁ for w = 1] at the receiver (x, Y).
    fn potentials(&self, x: f64, y: f64) -> [f64; 3] {
        let b = self.u_breaks(x, y);
        let mut acc = [0.0; 3];
        for w in b.windows(2) {
            let (s0, s1) = (w[0].sqrt(), w[1].sqrt());
            let part = tanh_sinh(
                |s| {
                    let r = self.v_max(x, y, s * s).sqrt();
                    [r, s * s * r, r * r * r]
                },
                s0,
                s1,
                8,
            );
            for i in 0..3 {
                acc[i] += part[i];
            }
        }
        let c = -2.0 / (PI * self.beta);
        let quad = (acc[1] + acc[2] / 3.0) / 2.0;
        [c * acc[0], c * (x * acc[0] - quad), -c * quad]
    }

    /// Breakpoints in Y ∈ [0, Y_max] at station x: the apex's and the tip
    /// corners' Mach lines and the reflection of the apex line.
    fn y_breaks(&self, x: f64) -> Vec<f64> {
        let top = (self.m * x).min(self.big_s);
        let mut b = vec![0.0, top];
        let dx = x - self.x_tip;
        for c in [x, self.big_s - dx, dx - self.big_s, 2.0 * self.big_s - x] {
            if c > 0.0 && c < top {
                b.push(c);
            }
        }
        b.sort_by(f64::total_cmp);
        b
    }

    fn across(&self, x: f64, tol: f64) -> [f64; 3] {
        let b = self.y_breaks(x);
        let mut acc = [0.0; 3];
        for w in b.windows(2) {
            let part = adaptive(|y| self.potentials(x, y), w[0], w[1], tol, 30);
            for i in 0..3 {
                acc[i] += part[i];
            }
        }
        acc
    }
}

/// The seven [`PotentialIntegrals`] by the direct route, to an absolute
/// tolerance of about `tol` per receiver integral.
pub fn integrals(wing: &Wing, mach: f64, tol: f64) -> PotentialIntegrals {
    let w = Stretched::new(wing, mach);
    let k = 2.0 / w.beta; // both halves, dy = dY/β
    let te = w.across(1.0, tol);
    let mut breaks = vec![0.0, 1.0];
    if w.x_tip > 0.0 && w.x_tip < 1.0 {
        breaks.insert(1, w.x_tip);
    }
    let mut area = [0.0; 4];
    for b in breaks.windows(2) {
        let part = adaptive(
            |x| {
                let [p0, p1, f] = w.across(x, tol);
                [p0, p1, x * p0, f]
            },
            b[0],
            b[1],
            tol,
            30,
        );
        for i in 0..4 {
            area[i] += part[i];
        }
    }
    PotentialIntegrals {
        te0: k * te[0],
        te1: k * te[1],
        ar0: k * area[0],
        ar1: k * area[1],
        arx0: k * area[2],
        te_f: k * te[2],
        ar_f: k * area[3],
    }
}
