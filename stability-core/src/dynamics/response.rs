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
use crate::dynamics::quartic::LEADING_COEFFICIENT_MIN;
use crate::numerics::display::Num;
use crate::numerics::invalid::Invalid;
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

/// A state of the longitudinal motion, eqs (2), in units of τ.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum State {
    /// û = u/V.
    U,
    /// ŵ = w/V (the incidence change, rad).
    W,
    /// q̂ = dθ/dt̂.
    Q,
    /// θ (rad).
    Theta,
}

impl State {
    /// The four states, in the order of eqs (2).
    pub const ALL: [State; 4] = [State::U, State::W, State::Q, State::Theta];

    /// `u`, `w`, `q`, `theta` (the CSV's `u_hat`, … without the hat).
    pub fn name(self) -> &'static str {
        match self {
            State::U => "u",
            State::W => "w",
            State::Q => "q",
            State::Theta => "theta",
        }
    }

    /// `û`, `ŵ`, `q̂`, `θ`.
    pub fn symbol(self) -> &'static str {
        match self {
            State::U => "û",
            State::W => "ŵ",
            State::Q => "q̂",
            State::Theta => "θ",
        }
    }
}

/// The most steps [`StateSpace::simulate`] takes (10⁶ samples of 40
/// bytes).
pub const MAX_STEPS: usize = 1_000_000;

/// The largest ‖M·h‖₁ of a step: beyond it the matrix exponential's
/// scaling and squaring loses accuracy (about ε‖M·h‖ relative; nalgebra's
/// does not return at all past ~1e35).
pub const MAX_STEP_NORM: f64 = 1e6;

/// Why a response cannot be computed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ResponseError {
    #[error(
        "A = 1 − z_ẇ/μ₁ = {} (z_ẇ = {}, μ₁ = {}): the equations of motion have no state-space form",
        Num(*a), Num(*z_wdot), Num(*mu1)
    )]
    SingularMass { a: f64, z_wdot: f64, mu1: f64 },
    #[error("{0}")]
    Derivatives(#[from] Invalid<&'static str>),
    #[error(
        "the state matrix overflows f64 (terms such as μ₁m_w/i_B exceed {}): the derivatives are too large",
        Num(f64::MAX)
    )]
    MatrixOverflow,
    #[error("the input {quantity} must be a finite number, not {}", Num(*value))]
    NonFiniteInput { quantity: &'static str, value: f64 },
    #[error("the time span must be positive and finite, not {}", Num(*until))]
    Until { until: f64 },
    #[error("the step count must lie between 1 and {MAX_STEPS}, not {steps}")]
    Steps { steps: usize },
    #[error(
        "the step t̂ = {} is too long for this system (its fastest rate ‖M‖₁ = {} per τ unit): ‖M‖·h = {} exceeds {}, beyond which the matrix exponential loses accuracy; {}",
        Num(*step), Num(*rate), Num(rate * step), Num(MAX_STEP_NORM),
        StiffAdvice(*min_steps)
    )]
    TooStiff {
        /// ‖M‖₁ (1/τ).
        rate: f64,
        /// The step h = until/steps (τ).
        step: f64,
        /// The fewest steps over the span that would do.
        min_steps: f64,
    },
}

struct StiffAdvice(f64);

impl std::fmt::Display for StiffAdvice {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.0 <= MAX_STEPS as f64 {
            write!(f, "take at least {} steps", self.0)
        } else if self.0.is_finite() {
            write!(
                f,
                "it would take {:.3e} steps, more than the {MAX_STEPS} allowed: shorten the time span",
                self.0
            )
        } else {
            write!(f, "no step count would do: shorten the time span")
        }
    }
}

/// The state-space form of eqs (2), in units of τ.
#[derive(Debug, Clone, PartialEq)]
pub struct StateSpace {
    /// The states, in order (û is left out when neglected).
    pub states: Vec<State>,
    /// ẋ = A x + B (x₀, z₀, m₀).
    pub a: DMatrix<f64>,
    pub b: DMatrix<f64>,
}

/// One sample of a response.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Sample {
    /// t̂ (units of τ).
    pub t: f64,
    /// û = u/V (0 when û is neglected).
    pub u: f64,
    /// ŵ = w/V (= the incidence change, rad).
    pub w: f64,
    /// q̂ = dθ/dt̂.
    pub q: f64,
    /// θ (rad).
    pub theta: f64,
}

impl Sample {
    /// The value of state `s`.
    pub fn get(&self, s: State) -> f64 {
        match s {
            State::U => self.u,
            State::W => self.w,
            State::Q => self.q,
            State::Theta => self.theta,
        }
    }

    fn new(t: f64, states: &[State], x: &DVector<f64>) -> Sample {
        let mut full = [0.0; 4];
        for (i, s) in states.iter().enumerate() {
            full[*s as usize] = x[i];
        }
        let [u, w, q, theta] = full;
        Sample { t, u, w, q, theta }
    }
}

/// Why a response stopped before `until`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, thiserror::Error)]
#[serde(rename_all = "snake_case")]
pub enum Stop {
    /// The next sample would not be finite: a divergent motion grew past
    /// f64's range after the last sample, at t̂.
    #[error("the motion diverged past f64's range after t̂ = {}", Num(*t))]
    Overflow { t: f64 },
}

/// A response: its samples, and why it stopped early, if it did.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Response {
    pub samples: Vec<Sample>,
    /// `None`: every one of the `steps + 1` samples was computed.
    pub stopped: Option<Stop>,
}

/// The rows of eqs (2) solved for the derivatives of (û, ŵ, q̂, θ): the
/// matrix A and the input matrix B of ẋ = A x + B (x₀, z₀, m₀).
fn state_rows(d: &Derivatives, a_mass: f64) -> ([[f64; 4]; 4], [[f64; 3]; 4]) {
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
    (rows, inputs)
}

impl Input {
    /// Every value finite.
    fn check(&self) -> Result<(), ResponseError> {
        let finite = |quantity, value: f64| {
            if value.is_finite() {
                Ok(())
            } else {
                Err(ResponseError::NonFiniteInput { quantity, value })
            }
        };
        match *self {
            Input::Step { x0, z0, m0 } => {
                finite("x0", x0)?;
                finite("z0", z0)?;
                finite("m0", m0)
            }
            Input::Initial { u, w, q, theta } => {
                finite("u", u)?;
                finite("w", w)?;
                finite("q", q)?;
                finite("theta", theta)
            }
        }
    }
}

impl StateSpace {
    pub fn new(d: &Derivatives, simp: Simplifications) -> Result<StateSpace, ResponseError> {
        d.check()?;
        let mut d = *d;
        if simp.neglect_zq_zwdot {
            d.z_q = 0.0;
            d.z_wdot = 0.0;
        }
        let a_mass = 1.0 - d.z_wdot / d.mu1;
        if a_mass.abs() < LEADING_COEFFICIENT_MIN {
            return Err(ResponseError::SingularMass {
                a: a_mass,
                z_wdot: d.z_wdot,
                mu1: d.mu1,
            });
        }
        let (rows, inputs) = state_rows(&d, a_mass);
        let states: Vec<State> = State::ALL
            .into_iter()
            .filter(|s| !(simp.neglect_u && *s == State::U))
            .collect();
        let n = states.len();
        let k = |i: usize| states[i] as usize;
        let a = DMatrix::from_fn(n, n, |i, j| rows[k(i)][k(j)]);
        let b = DMatrix::from_fn(n, 3, |i, j| inputs[k(i)][j]);
        if !(a.iter().chain(b.iter()).all(|v| v.is_finite())) {
            return Err(ResponseError::MatrixOverflow);
        }
        Ok(StateSpace { states, a, b })
    }

    /// The position of state `s` in the state vector, if it is kept.
    pub fn index_of(&self, s: State) -> Option<usize> {
        self.states.iter().position(|x| *x == s)
    }

    /// The exact response at `steps + 1` equally spaced times from 0 to
    /// `until` (τ units), through exp(M·h) of the augmented system (see
    /// the module documentation). Refuses a step too long for the matrix
    /// exponential ([`MAX_STEP_NORM`]) and more than [`MAX_STEPS`] steps;
    /// stops early, before any non-finite value, if a divergent motion
    /// overflows, and says so in [`Response::stopped`].
    pub fn simulate(
        &self,
        input: Input,
        until: f64,
        steps: usize,
    ) -> Result<Response, ResponseError> {
        if !(until > 0.0 && until.is_finite()) {
            return Err(ResponseError::Until { until });
        }
        if steps == 0 || steps > MAX_STEPS {
            return Err(ResponseError::Steps { steps });
        }
        input.check()?;
        let (m, x0) = self.augmented(input);
        let h = until / steps as f64;
        let rate = m.column_iter().map(|c| c.lp_norm(1)).fold(0.0, f64::max);
        if rate * h > MAX_STEP_NORM || (rate * h).is_nan() {
            return Err(ResponseError::TooStiff {
                rate,
                step: h,
                min_steps: (rate * until / MAX_STEP_NORM).ceil(),
            });
        }
        let phi = (m * h).exp();
        let mut x = x0;
        let mut samples = Vec::with_capacity(steps + 1);
        for i in 0..=steps {
            let t = i as f64 * h;
            if !x.iter().all(|v| v.is_finite()) {
                let last = samples.last().map_or(0.0, |s: &Sample| s.t);
                return Ok(Response {
                    samples,
                    stopped: Some(Stop::Overflow { t: last }),
                });
            }
            samples.push(Sample::new(t, &self.states, &x));
            x = &phi * x;
        }
        Ok(Response {
            samples,
            stopped: None,
        })
    }

    /// The augmented system d/dt (x, 1) = [[A, B·v], [0, 0]] (x, 1) of a
    /// step input v (or of none), and its initial state.
    fn augmented(&self, input: Input) -> (DMatrix<f64>, DVector<f64>) {
        let n = self.a.nrows();
        let (v, start) = match input {
            Input::Step { x0, z0, m0 } => ([x0, z0, m0], [0.0; 4]),
            Input::Initial { u, w, q, theta } => ([0.0; 3], [u, w, q, theta]),
        };
        let forcing = &self.b * DVector::from_row_slice(&v);
        let mut m = DMatrix::zeros(n + 1, n + 1);
        m.view_mut((0, 0), (n, n)).copy_from(&self.a);
        m.view_mut((0, n), (n, 1)).copy_from(&forcing);
        let mut x = DVector::zeros(n + 1);
        for (i, s) in self.states.iter().enumerate() {
            x[i] = start[*s as usize];
        }
        x[n] = 1.0;
        (m, x)
    }
}

/// A response asked for (§11): what disturbs the aircraft, the span
/// (τ units), the number of intervals and what is neglected.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Request {
    pub input: Input,
    pub until: f64,
    pub steps: usize,
    pub simplifications: Simplifications,
}

/// A response over the whole span with the report's own closed form
/// beside it.
#[derive(Debug, Clone, PartialEq)]
pub struct Computed {
    /// The exact response, `steps + 1` samples from 0 to `until`.
    pub samples: Vec<Sample>,
    /// For a step of m₀ alone (no control force x₀, z₀): eq (45)'s
    /// two-degree-of-freedom ŵ at each sample, from eq (44) as printed with
    /// the same simplifications applied.
    pub eq45: Option<Vec<f64>>,
    /// The incremental normal load factor at the c.g. at each sample,
    /// n_z = (q̂ − Dŵ)/C_L ([`load_factor`]); `None` where C_L ≤ 0.
    pub n_z: Option<Vec<f64>>,
}

/// The incremental normal load factor at the c.g., positive up, from q̂,
/// Dŵ = dŵ/dt̂ and C_L: n_z = (V/g)(q − α̇) = (q̂ − Dŵ)/C_L, since
/// V/(gτ) = ½ρV²S/W = 1/C_L in level flight (eq 24; the derivation is in
/// [`crate::dynamics::linear`]'s documentation).
pub fn load_factor(q_hat: f64, w_hat_rate: f64, c_l: f64) -> f64 {
    (q_hat - w_hat_rate) / c_l
}

impl StateSpace {
    /// Dŵ at a sample of the response to `input` (the ŵ row of
    /// ẋ = A x + B (x₀, z₀, m₀)).
    pub fn w_rate(&self, input: Input, s: &Sample) -> f64 {
        let Some(i) = self.index_of(State::W) else {
            return 0.0;
        };
        let v = match input {
            Input::Step { x0, z0, m0 } => [x0, z0, m0],
            Input::Initial { .. } => [0.0; 3],
        };
        let states: f64 = (0..self.states.len())
            .map(|j| self.a[(i, j)] * s.get(self.states[j]))
            .sum();
        states + (0..3).map(|k| self.b[(i, k)] * v[k]).sum::<f64>()
    }
}

/// Why a whole response cannot be had.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ComputedError {
    #[error("{0}")]
    Response(#[from] ResponseError),
    /// The motion overflowed f64 before `until`.
    #[error("the response stops at t̂ = {} of the {} asked for: {stop}", Num(*reached), Num(*until))]
    Stopped {
        reached: f64,
        until: f64,
        stop: Stop,
    },
    /// Eq (45)'s closed form overflowed f64 before `until`.
    #[error(
        "eq (45)'s two-degree-of-freedom response overflows f64 at t̂ = {}, before {}",
        Num(*t), Num(*until)
    )]
    ClosedFormOverflow { t: f64, until: f64 },
}

/// The response of `d` to `request` over its whole span, with eq (45)'s
/// closed form for a moment step (the same m₀, the same neglected terms),
/// or why the span cannot be reached.
pub fn computed(d: &Derivatives, request: &Request) -> Result<Computed, ComputedError> {
    let simp = request.simplifications;
    let ss = StateSpace::new(d, simp)?;
    let r = ss.simulate(request.input, request.until, request.steps)?;
    if let Some(stop) = r.stopped {
        let reached = r.samples.last().map_or(0.0, |s| s.t);
        let until = request.until;
        return Err(ComputedError::Stopped {
            reached,
            until,
            stop,
        });
    }
    let rate = |s: &Sample| ss.w_rate(request.input, s);
    let n_z: Vec<f64> = r
        .samples
        .iter()
        .map(|s| load_factor(s.q, rate(s), d.c_l))
        .collect();
    // undefined at C_L ≤ 0, or beyond f64 where C_L is tiny
    let n_z = (d.c_l > 0.0 && n_z.iter().all(|n| n.is_finite())).then_some(n_z);
    let Input::Step {
        x0: 0.0,
        z0: 0.0,
        m0,
    } = request.input
    else {
        return Ok(Computed {
            samples: r.samples,
            eq45: None,
            n_z,
        });
    };
    let mut d = *d;
    if simp.neglect_zq_zwdot {
        d.z_q = 0.0;
        d.z_wdot = 0.0;
    }
    let two = TwoDof::of(&d);
    let eq45: Vec<f64> = r.samples.iter().map(|s| two.w(s.t, 1.0) * m0).collect();
    if let Some(k) = eq45.iter().position(|v| !v.is_finite()) {
        let t = r.samples[k].t;
        return Err(ComputedError::ClosedFormOverflow {
            t,
            until: request.until,
        });
    }
    Ok(Computed {
        samples: r.samples,
        eq45: Some(eq45),
        n_z,
    })
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
