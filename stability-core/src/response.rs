//! Responses (§11): the report's two-degree-of-freedom step response
//! (eqs 44–45) and the full longitudinal response from the state-space form
//! of eqs (2), solved exactly.
//!
//! # Eqs (44)–(45), recovered
//! With û = 0 and no lift from the control, rows 2 and 3 of eqs (2) are
//! `−[z_w ŵ + (z_ẇ/μ₁ − 1)Dŵ] − (z_q/μ₁ + 1)Dθ = 0` and
//! `−(μ₁/i_B)m_w ŵ − (m_ẇ/i_B)Dŵ + D²θ − (m_q/i_B)Dθ = m₀` (D = d/dt̂).
//! Eliminating Dθ and dividing by (z_ẇ/μ₁ − 1) gives
//! `D²ŵ + b·Dŵ + k·ŵ = g·m₀` with (eq 45)
//! `b = (m_ẇ/i_B)(z_q/μ₁ + 1)/(z_ẇ/μ₁ − 1) + z_w/(z_ẇ/μ₁ − 1) − m_q/i_B ≈ B`,
//! `k = (μ₁/i_B)m_w(z_q/μ₁ + 1)/(z_ẇ/μ₁ − 1) − (m_q/i_B)z_w/(z_ẇ/μ₁ − 1) ≈ C`,
//! and `g = (z_q/μ₁ + 1)/(1 − z_ẇ/μ₁)`. The report takes g = 1 (its eq 44
//! has m₀ alone on the right, an approximation of the same order as
//! b ≈ B), and from rest its solution is
//! `ŵ/m₀ = (1/k)[1 − (√k/√(k − b²/4))·e^(−bt̂/2)·sin(√(k − b²/4)·t̂ + tan⁻¹(√(k − b²/4)/(b/2)))]`
//! (the OCR drops the t̂ inside the sine). [`TwoDof::printed`] is that
//! formula; [`TwoDof::w`] is the solution for any b, k, g.
//!
//! # The full response
//! State x = (û, ŵ, q̂, θ), q̂ = dθ/dt̂; from eqs (2), in units of τ:
//! `A·Dŵ = z_u û + z_w ŵ + (z_q/μ₁ + 1)q̂ + z₀` (A = 1 − z_ẇ/μ₁),
//! `Dû = x_u û + x_w ŵ + (x_ẇ/μ₁)Dŵ + (x_q/μ₁)q̂ − C_L θ + x₀`,
//! `Dq̂ = (μ₁/i_B)(m_u û + m_w ŵ) + (m_ẇ/i_B)Dŵ + (m_q/i_B)q̂ + m₀`, `Dθ = q̂`.
//! For a step input the augmented system (x, 1) is linear and autonomous,
//! so x(t̂ + h) = exp(M·h)·x(t̂) exactly: [`StateSpace::simulate`] samples the
//! exact solution through the matrix exponential (nalgebra's Padé scaling
//! and squaring), not a fixed-step integrator.

use crate::Derivatives;
use nalgebra::{DMatrix, DVector};
use serde::Serialize;

/// The two-degree-of-freedom equation of §11: D²ŵ + bDŵ + kŵ = g·m₀.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TwoDof {
    pub b: f64,
    pub k: f64,
    /// The exact right-hand factor (z_q/μ₁ + 1)/(1 − z_ẇ/μ₁); the report
    /// uses 1.
    pub g: f64,
}

impl TwoDof {
    /// Eq (45) from a derivative set.
    pub fn of(d: &Derivatives) -> TwoDof {
        let e = d.z_wdot / d.mu1 - 1.0;
        let f = d.z_q / d.mu1 + 1.0;
        TwoDof {
            b: d.m_wdot / d.i_b * f / e + d.z_w / e - d.m_q / d.i_b,
            k: d.mu1 / d.i_b * d.m_w * f / e - d.m_q / d.i_b * d.z_w / e,
            g: f / -e,
        }
    }

    /// The report's printed solution of eq (44) (as recovered), ŵ/m₀ at t̂,
    /// valid for an oscillatory pair (k > b²/4); `None` otherwise.
    pub fn printed(&self, t: f64) -> Option<f64> {
        let (b, k) = (self.b, self.k);
        let wd2 = k - b * b / 4.0;
        if !(wd2 > 0.0 && k > 0.0) {
            return None;
        }
        let wd = wd2.sqrt();
        let phase = wd.atan2(b / 2.0);
        Some((1.0 - k.sqrt() / wd * (-b * t / 2.0).exp() * (wd * t + phase).sin()) / k)
    }

    /// ŵ(t̂)/m₀ from rest for the step g·m₀ (g = 1: the report's form; use
    /// `self.g` for the exact one), for any b and k.
    pub fn w(&self, t: f64, g: f64) -> f64 {
        second_order_step(self.b, self.k, t) * g
    }
}

/// y(t) of y″ + b·y′ + k·y = 1 with y(0) = y′(0) = 0, for every b, k:
/// `y = (1/k)[1 − e^(−σt)(C + σS)]` with σ = b/2, Δ = k − σ², and C = cos ωt,
/// S = sin(ωt)/ω for Δ = ω² > 0, C = cosh ωt, S = sinh(ωt)/ω for Δ = −ω² < 0
/// (S → t as ω → 0); for k = 0, `y = (t − (1 − e^(−bt))/b)/b` or t²/2.
pub fn second_order_step(b: f64, k: f64, t: f64) -> f64 {
    let sigma = b / 2.0;
    if k.abs() <= 1e-12 * (b * b + 1.0) {
        return if b.abs() > 1e-12 {
            (t + (-b * t).exp_m1() / b) / b
        } else {
            t * t / 2.0
        };
    }
    let delta = k - sigma * sigma;
    let w = delta.abs().sqrt();
    let (c, s) = if w * t < 1e-4 {
        // series: cos/cosh ≈ 1 ∓ (wt)²/2, sin(wt)/w ≈ t(1 ∓ (wt)²/6)
        let sign = if delta > 0.0 { -1.0 } else { 1.0 };
        let x2 = (w * t) * (w * t);
        (1.0 + sign * x2 / 2.0, t * (1.0 + sign * x2 / 6.0))
    } else if delta > 0.0 {
        ((w * t).cos(), (w * t).sin() / w)
    } else {
        ((w * t).cosh(), (w * t).sinh() / w)
    };
    (1.0 - (-sigma * t).exp() * (c + sigma * s)) / k
}

/// Simplifications of the full response (Fig 38; §11's two degrees of
/// freedom).
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize)]
pub struct Simplifications {
    /// Set z_q = z_ẇ = 0 (the report's Fig 38).
    pub neglect_zq_zwdot: bool,
    /// Hold û = 0 (two degrees of freedom).
    pub neglect_u: bool,
}

/// What disturbs the aircraft.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum Input {
    /// A step of the moment m₀ (and of the forces x₀, z₀), from rest: an
    /// elevon applied instantaneously (§11), in the units of eqs (2).
    Step { x0: f64, z0: f64, m0: f64 },
    /// No input; the initial state (û, ŵ, q̂, θ).
    Initial { u: f64, w: f64, q: f64, theta: f64 },
}

/// Why a response cannot be computed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ResponseError {
    #[error("A = 1 − z_ẇ/μ₁ = 0 (z_ẇ = μ₁): the equations of motion have no state-space form")]
    SingularMass,
    #[error("non-finite derivative set")]
    NonFinite,
    #[error("the time span must be positive and finite, and the step count between 1 and 10⁷")]
    BadTimes,
}

/// The state-space form of eqs (2), in units of τ.
#[derive(Debug, Clone, PartialEq)]
pub struct StateSpace {
    /// The state names, in order.
    pub states: Vec<&'static str>,
    /// ẋ = A x + B (x₀, z₀, m₀).
    pub a: DMatrix<f64>,
    pub b: DMatrix<f64>,
}

/// One sample of a response.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Sample {
    /// t̂ (units of τ).
    pub t: f64,
    /// û = u/V.
    pub u: f64,
    /// ŵ = w/V (= the incidence change, rad).
    pub w: f64,
    /// q̂ = dθ/dt̂.
    pub q: f64,
    /// θ (rad).
    pub theta: f64,
}

impl StateSpace {
    pub fn new(d: &Derivatives, simp: Simplifications) -> Result<StateSpace, ResponseError> {
        if !d.quartic_input_values().iter().all(|v| v.is_finite()) {
            return Err(ResponseError::NonFinite);
        }
        let mut d = *d;
        if simp.neglect_zq_zwdot {
            d.z_q = 0.0;
            d.z_wdot = 0.0;
        }
        let a_mass = 1.0 - d.z_wdot / d.mu1;
        if a_mass.abs() < 1e-12 {
            return Err(ResponseError::SingularMass);
        }
        // Dŵ = (z_u û + z_w ŵ + (z_q/μ₁ + 1) q̂ + z₀)/A
        let wdot = [d.z_u, d.z_w, d.z_q / d.mu1 + 1.0, 0.0].map(|c| c / a_mass);
        let wdot_in = [0.0, 1.0 / a_mass, 0.0];
        let xw = d.x_wdot / d.mu1;
        let mw = d.m_wdot / d.i_b;
        let rows = [
            [
                d.x_u + xw * wdot[0],
                d.x_w + xw * wdot[1],
                d.x_q / d.mu1 + xw * wdot[2],
                -d.c_l,
            ],
            wdot,
            [
                d.mu1 / d.i_b * d.m_u + mw * wdot[0],
                d.mu1 / d.i_b * d.m_w + mw * wdot[1],
                d.m_q / d.i_b + mw * wdot[2],
                0.0,
            ],
            [0.0, 0.0, 1.0, 0.0],
        ];
        let inputs = [
            [1.0, xw * wdot_in[1], 0.0],
            wdot_in,
            [0.0, mw * wdot_in[1], 1.0],
            [0.0, 0.0, 0.0],
        ];
        let keep: Vec<usize> = if simp.neglect_u {
            vec![1, 2, 3]
        } else {
            vec![0, 1, 2, 3]
        };
        let names = ["u", "w", "q", "theta"];
        let n = keep.len();
        let a = DMatrix::from_fn(n, n, |i, j| rows[keep[i]][keep[j]]);
        let b = DMatrix::from_fn(n, 3, |i, j| inputs[keep[i]][j]);
        Ok(StateSpace {
            states: keep.iter().map(|&i| names[i]).collect(),
            a,
            b,
        })
    }

    /// The exact response at `steps + 1` equally spaced times from 0 to
    /// `until` (τ units). Stops early, before any non-finite value, if a
    /// divergent motion overflows.
    pub fn simulate(
        &self,
        input: Input,
        until: f64,
        steps: usize,
    ) -> Result<Vec<Sample>, ResponseError> {
        if !(until > 0.0 && until.is_finite()) || steps == 0 || steps > 10_000_000 {
            return Err(ResponseError::BadTimes);
        }
        let n = self.a.nrows();
        let has_u = self.states[0] == "u";
        // Augmented state (x, 1): d/dt (x, 1) = [[A, B·v], [0, 0]] (x, 1).
        let (v, x0) = match input {
            Input::Step { x0, z0, m0 } => (DVector::from_vec(vec![x0, z0, m0]), DVector::zeros(n)),
            Input::Initial { u, w, q, theta } => {
                let full = [u, w, q, theta];
                let start = if has_u { 0 } else { 1 };
                (
                    DVector::zeros(3),
                    DVector::from_fn(n, |i, _| full[start + i]),
                )
            }
        };
        let forcing = &self.b * v;
        let mut m = DMatrix::zeros(n + 1, n + 1);
        m.view_mut((0, 0), (n, n)).copy_from(&self.a);
        m.view_mut((0, n), (n, 1)).copy_from(&forcing);
        let h = until / steps as f64;
        let phi = (m * h).exp();
        let mut x = DVector::zeros(n + 1);
        x.rows_mut(0, n).copy_from(&x0);
        x[n] = 1.0;
        let mut out = Vec::with_capacity(steps + 1);
        for i in 0..=steps {
            if !x.iter().all(|v| v.is_finite()) {
                break;
            }
            let get = |name: &str| {
                self.states
                    .iter()
                    .position(|s| *s == name)
                    .map_or(0.0, |j| x[j])
            };
            out.push(Sample {
                t: i as f64 * h,
                u: get("u"),
                w: get("w"),
                q: get("q"),
                theta: get("theta"),
            });
            x = &phi * x;
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_printed_form_equals_the_general_solution_when_oscillatory() {
        let two = TwoDof {
            b: 1.3,
            k: 9.0,
            g: 1.0,
        };
        for i in 0..50 {
            let t = i as f64 * 0.1;
            let p = two.printed(t).unwrap();
            assert!((p - two.w(t, 1.0)).abs() < 1e-14, "t = {t}");
        }
        // steady state 1/k
        assert!((two.w(200.0, 1.0) - 1.0 / 9.0).abs() < 1e-15);
    }

    #[test]
    fn the_general_step_satisfies_its_ode() {
        // y'' + b y' + k y = 1 checked by central differences, every regime.
        for (b, k) in [
            (1.0, 5.0),
            (4.0, 4.0),
            (5.0, 1.0),
            (-0.4, 3.0),
            (2.0, 0.0),
            (0.0, 0.0),
            (1.0, -2.0),
        ] {
            let h = 1e-3;
            for i in 1..40 {
                let t = i as f64 * 0.05;
                let y = |t| second_order_step(b, k, t);
                let ypp = (y(t + h) - 2.0 * y(t) + y(t - h)) / (h * h);
                let yp = (y(t + h) - y(t - h)) / (2.0 * h);
                let res = ypp + b * yp + k * y(t) - 1.0;
                assert!(res.abs() < 1e-5, "b={b} k={k} t={t}: residual {res}");
            }
            assert_eq!(second_order_step(b, k, 0.0), 0.0);
        }
    }
}
