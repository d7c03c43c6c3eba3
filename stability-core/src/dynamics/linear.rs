//! The longitudinal motion as a linear state-space model, ẋ = A x + B δ,
//! with the states an engineer reads and exports: x = (u/V, α, q, θ) —
//! the speed change as a fraction of V, the incidence α = w/V (rad), the
//! pitch rate q and the pitch angle θ (rad) — and at most one control δ
//! (rad).
//!
//! The model is in one of two units of time ([`TimeUnit`]): the report's τ
//! (§3: t̂ = t/τ, q̂ = dθ/dt̂, eqs 2) or seconds. From eqs (2) in units of τ
//! ([`crate::dynamics::response::StateSpace`]) the model in seconds follows by the
//! change of variable q = q̂/τ and d/dt = (1/τ)d/dt̂:
//! A_s = (1/τ)·D·A_τ·D⁻¹, B_s = (1/τ)·D·B_τ with D = diag(1, 1, 1/τ, 1).
//!
//! A derivative set in dimensional form (per unit mass and inertia, states
//! u, w in m/s or ft/s, q in rad/s, θ) enters through
//! [`LinearModel::of_dimensional`], which divides u and w by the reference
//! speed V: A = S⁻¹·A_dim·S, B = S⁻¹·B_dim with S = diag(V, V, 1, 1).
//!
//! # The control
//! A control deflection δ (rad) with the coefficient derivatives C_Xδ,
//! C_Zδ (forces on ½ρV²S, along the report's stability axes, X forward and
//! Z down) and C_mδ (moment on ½ρV²Sc̄) is a step of eqs (2)'s x₀ = C_Xδ·δ,
//! z₀ = C_Zδ·δ and m₀ = (μ₁/i_B)·C_mδ·δ: the angular acceleration in units
//! of τ is M·τ²/B = C_m·½ρV²Sc̄·τ²/(i_B·mc̄²) = (μ₁/i_B)·C_m, and the
//! vertical one Z·τ/(mV) = C_Z.
//!
//! # The outputs: γ and n_z at the c.g.
//! Beside the states the model gives y = C x + D δ ([`LinearModel::outputs`],
//! [`OUTPUTS`]): the states themselves, the flight-path angle γ = θ − α
//! (level flight, stability axes: Etkin & Reid, *Dynamics of flight*, 3rd
//! ed., §4.2–4.3; Stevens & Lewis, *Aircraft control and simulation*, 2nd
//! ed., §2.5 and §3.8), and the incremental normal load factor at the c.g.
//! n_z = −a_z/g, positive up. In body (here stability) axes the c.g.'s
//! acceleration along z is a_z = ẇ − U₀q (U₀ = V; no gravity term changes
//! to first order in level flight, θ₀ = 0), so with α = w/V
//!
//! n_z = (V/g)(q − α̇) = (V/g)·γ̇.
//!
//! α̇ is row 2 of the state equation, α̇ = A₂·x + B₂δ, so the n_z row is
//! C = (V/g)(e_q − A₂), D = −(V/g)B₂ (e_q the unit row of q): the output is
//! exact, not the short-period approximation n_z ≈ (n/α)·α. In units of τ
//! (dγ/dt̂ = τγ̇) the factor is V/(gτ) = ½ρV²S/W = 1/C_L (eq 24), so that
//! n_z = (q̂ − Dŵ)/C_L; in seconds it is V/g = τ/C_L
//! ([`LinearModel::load_factor`]).

use crate::Derivatives;
use crate::dynamics::response::{ResponseError, Simplifications, StateSpace};
use nalgebra::{Matrix4, Vector4};
use num_complex::Complex64;
use serde::Serialize;

/// The unit of time of a model (and of its eigenvalues).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum TimeUnit {
    /// The report's τ = m/(½ρSV) (§3); q is q̂ = dθ/dt̂.
    Tau,
    /// Seconds; q in rad/s.
    Seconds,
}

impl TimeUnit {
    /// `"tau"` or `"s"`.
    pub fn symbol(self) -> &'static str {
        match self {
            TimeUnit::Tau => "tau",
            TimeUnit::Seconds => "s",
        }
    }
}

/// The states of a [`LinearModel`], in order.
pub const STATES: [&str; 4] = ["u/V", "alpha", "q", "theta"];

/// The outputs of [`LinearModel::outputs`], in order: the states, γ and
/// n_z (see the module's documentation).
pub const OUTPUTS: [&str; 6] = ["u/V", "alpha", "q", "theta", "gamma", "n_z"];

/// The control derivatives of one control δ (rad), coefficients per
/// radian: C_Xδ and C_Zδ on ½ρV²S, C_mδ on ½ρV²Sc̄ (see the module's
/// documentation).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Control {
    /// What δ is ("elevator", "elevon", …).
    pub name: String,
    pub c_x: f64,
    pub c_z: f64,
    pub c_m: f64,
}

impl Control {
    /// The step of eqs (2)'s forcing (x₀, z₀, m₀) per radian of δ:
    /// (C_Xδ, C_Zδ, (μ₁/i_B)·C_mδ) (see the module's documentation).
    pub fn forcing(&self, d: &Derivatives) -> [f64; 3] {
        [self.c_x, self.c_z, d.mu1 / d.i_b * self.c_m]
    }
}

/// ẋ = A x + B δ with x = (u/V, α, q, θ) ([`STATES`]).
#[derive(Debug, Clone, PartialEq)]
pub struct LinearModel {
    pub a: Matrix4<f64>,
    /// The control column, when there is a control.
    pub b: Option<Vector4<f64>>,
    /// The control's name, when there is one.
    pub input: Option<String>,
    pub time: TimeUnit,
    /// n_z per unit rate of γ in the model's unit of time: 1/C_L per τ,
    /// V/g (s) in seconds; `None` where it is not known (C_L ≤ 0, or a
    /// dimensional set without g). See the module's documentation.
    pub load_factor: Option<f64>,
}

/// The output equation y = C x + D δ of [`OUTPUTS`] (n_z's row absent
/// when [`LinearModel::load_factor`] is not known).
#[derive(Debug, Clone, PartialEq)]
pub struct Outputs {
    /// The outputs' names, a prefix of [`OUTPUTS`] (5 or 6).
    pub names: Vec<&'static str>,
    /// C's rows.
    pub c: Vec<[f64; 4]>,
    /// D's column (zero without a control).
    pub d: Vec<f64>,
}

impl LinearModel {
    /// Eqs (2) of a derivative set in units of τ (the matrices of
    /// [`StateSpace`]), with B from `control` when one is given.
    pub fn of_report(d: &Derivatives, control: Option<&Control>) -> Result<Self, ResponseError> {
        let ss = StateSpace::new(d, Simplifications::default())?;
        let a = Matrix4::from_fn(|i, j| ss.a[(i, j)]);
        let b = control.map(|c| {
            let forcing = c.forcing(d);
            Vector4::from_fn(|i, _| (0..3).map(|k| ss.b[(i, k)] * forcing[k]).sum())
        });
        let model = LinearModel {
            a,
            b,
            input: control.map(|c| c.name.clone()),
            time: TimeUnit::Tau,
            load_factor: (d.c_l > 0.0).then(|| 1.0 / d.c_l),
        };
        if model.is_finite() {
            Ok(model)
        } else {
            Err(ResponseError::MatrixOverflow)
        }
    }

    /// A model in seconds from the dimensional matrices of states
    /// (u, w, q, θ) — u, w in m/s or ft/s — and the reference speed V in
    /// the same units (see the module's documentation); n_z's factor V/g
    /// is not known until [`LinearModel::with_gravity`] gives g.
    pub fn of_dimensional(
        a: Matrix4<f64>,
        b: Option<Vector4<f64>>,
        input: Option<String>,
        speed: f64,
    ) -> LinearModel {
        let s = [speed, speed, 1.0, 1.0];
        LinearModel {
            a: Matrix4::from_fn(|i, j| a[(i, j)] * s[j] / s[i]),
            b: b.map(|b| Vector4::from_fn(|i, _| b[i] / s[i])),
            input,
            time: TimeUnit::Seconds,
            load_factor: None,
        }
    }

    /// A model in seconds with n_z's factor V/g from the trim speed and
    /// g (same length unit); a model in τ, or a non-positive g, as it is.
    pub fn with_gravity(mut self, speed: f64, g: f64) -> LinearModel {
        let k = speed / g;
        if self.time == TimeUnit::Seconds && g > 0.0 && k.is_finite() {
            self.load_factor = Some(k);
        }
        self
    }

    /// The output equation y = C x + D δ: the states, γ = θ − α and, when
    /// the factor is known, n_z = k(q − α̇) with α̇ = A₂x + B₂δ (see the
    /// module's documentation).
    pub fn outputs(&self) -> Outputs {
        let row = |i: usize| [0, 1, 2, 3].map(|j| self.a[(i, j)]);
        let b_alpha = self.b.map_or(0.0, |b| b[1]);
        let unit =
            |k: usize| -> [f64; 4] { std::array::from_fn(|j| if j == k { 1.0 } else { 0.0 }) };
        let mut c: Vec<[f64; 4]> = (0..4).map(unit).collect();
        c.push([0.0, -1.0, 0.0, 1.0]);
        let mut d = vec![0.0; 5];
        if let Some(k) = self.load_factor {
            let alpha_dot = row(1);
            c.push([0, 1, 2, 3].map(|j| k * (unit(2)[j] - alpha_dot[j])));
            // -(k·B₂) with 0 for no control, never -0
            d.push(if b_alpha == 0.0 { 0.0 } else { -k * b_alpha });
        }
        Outputs {
            names: OUTPUTS[..c.len()].to_vec(),
            c,
            d,
        }
    }

    /// This model in seconds, given τ (s); a model already in seconds is
    /// returned as it is.
    pub fn in_seconds(&self, tau: f64) -> LinearModel {
        if self.time == TimeUnit::Seconds {
            return self.clone();
        }
        let d = [1.0, 1.0, 1.0 / tau, 1.0];
        LinearModel {
            a: Matrix4::from_fn(|i, j| d[i] * self.a[(i, j)] / d[j] / tau),
            b: self.b.map(|b| Vector4::from_fn(|i, _| d[i] * b[i] / tau)),
            input: self.input.clone(),
            time: TimeUnit::Seconds,
            load_factor: self.load_factor.map(|k| k * tau),
        }
    }

    /// The unit of each state: `1`, `rad`, `rad/s` (or `rad/tau`), `rad`.
    pub fn state_units(&self) -> [&'static str; 4] {
        let q = match self.time {
            TimeUnit::Tau => "rad/tau",
            TimeUnit::Seconds => "rad/s",
        };
        ["1", "rad", q, "rad"]
    }

    /// Whether every entry is finite (n_z's factor too).
    pub fn is_finite(&self) -> bool {
        self.a
            .iter()
            .chain(self.b.iter().flatten())
            .chain(self.load_factor.iter())
            .all(|v| v.is_finite())
    }

    /// The eigenvalues of A by nalgebra's Schur decomposition, conjugates
    /// adjacent: for a set with no quartic of its own. (A derivative set in
    /// the report's notation has exact roots from its quartic, which these
    /// agree with to rounding.)
    pub fn eigenvalues(&self) -> [Complex64; 4] {
        let ev = self.a.complex_eigenvalues();
        let mut out = [ev[0], ev[1], ev[2], ev[3]];
        out.sort_by(|x, y| y.norm().total_cmp(&x.norm()).then(y.im.total_cmp(&x.im)));
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::design::examples::tailless_delta_45_coupled;

    #[test]
    fn seconds_and_tau_have_the_same_motion() {
        // ẋ_s = A_s x_s must be ẋ_τ/τ with q = q̂/τ: check on a vector.
        let d = tailless_delta_45_coupled();
        let c = Control {
            name: "elevon".into(),
            c_x: 0.01,
            c_z: -0.4,
            c_m: -0.3,
        };
        let m = LinearModel::of_report(&d, Some(&c)).unwrap();
        let tau = 2.5;
        let s = m.in_seconds(tau);
        let x_tau = Vector4::new(0.01, 0.02, -0.03, 0.04);
        let x_s = Vector4::new(x_tau[0], x_tau[1], x_tau[2] / tau, x_tau[3]);
        let dx_tau = m.a * x_tau + m.b.unwrap() * 0.1;
        let dx_s = s.a * x_s + s.b.unwrap() * 0.1;
        // d/dt = (1/τ) d/dt̂, and dq/dt = (1/τ²) dq̂/dt̂
        let expect = [
            dx_tau[0] / tau,
            dx_tau[1] / tau,
            dx_tau[2] / (tau * tau),
            dx_tau[3] / tau,
        ];
        for i in 0..4 {
            assert!((dx_s[i] - expect[i]).abs() < 1e-15, "{i}");
        }
        // the control: m₀ = (μ₁/i_B)·C_mδ enters q̂'s row through B's m₀
        // column (1), plus m_ẇ/i_B times the ẇ row's z₀ term.
        let a_mass = 1.0 - d.z_wdot / d.mu1;
        let wdot = c.c_z / a_mass;
        assert!((m.b.unwrap()[1] - wdot).abs() < 1e-15);
        let q = d.mu1 / d.i_b * c.c_m + d.m_wdot / d.i_b * wdot;
        assert!((m.b.unwrap()[2] - q).abs() < 1e-12);
    }

    #[test]
    fn dimensional_states_scale_by_the_speed() {
        let a = Matrix4::new(
            -0.02, 0.1, 0.0, -32.2, -0.3, -1.1, 300.0, 0.0, 0.0001, -0.01, -0.9, 0.0, 0.0, 0.0,
            1.0, 0.0,
        );
        let m = LinearModel::of_dimensional(a, None, None, 300.0);
        assert_eq!(m.a[(0, 3)], -32.2 / 300.0);
        assert_eq!(m.a[(1, 2)], 1.0);
        assert!((m.a[(2, 0)] - 0.03).abs() < 1e-15);
        // a similarity transform keeps the eigenvalues
        let (e1, e2) = (
            a.complex_eigenvalues().map(|z| z.norm()).sum(),
            m.a.complex_eigenvalues().map(|z| z.norm()).sum(),
        );
        assert!(((e1 - e2) / e1).abs() < 1e-12);
    }

    /// The step (x₀, z₀, m₀) of δ rad of `c` on `d`, as a response input.
    fn step(c: &Control, d: &Derivatives, delta: f64) -> crate::dynamics::response::Input {
        let [x0, z0, m0] = c.forcing(d).map(|f| f * delta);
        crate::dynamics::response::Input::Step { x0, z0, m0 }
    }

    #[test]
    fn n_z_is_the_rate_of_gamma_over_c_l_and_the_output_row_gives_it() {
        use crate::dynamics::response::{Request, computed};
        // an independent route: n_z = (V/g)·dγ/dt = (1/C_L)·dγ/dt̂ with
        // γ = θ − ŵ differenced from the simulated response (central
        // differences, h = 1e-4 τ: error h²γ‴/6 ≈ 1e-8 here)
        let d = tailless_delta_45_coupled();
        let c = Control {
            name: "elevon".into(),
            c_x: 0.0,
            c_z: -0.5,
            c_m: -0.3,
        };
        let delta = 0.01;
        let h = 1e-4;
        let request = Request {
            input: step(&c, &d, delta),
            until: 4.0,
            steps: 40_000,
            simplifications: Default::default(),
        };
        let r = computed(&d, &request).unwrap();
        let n_z = r.n_z.as_ref().expect("C_L > 0");
        let gamma: Vec<f64> = r.samples.iter().map(|s| s.theta - s.w).collect();
        let m = LinearModel::of_report(&d, Some(&c)).unwrap();
        let o = m.outputs();
        assert_eq!(o.names, OUTPUTS);
        let peak = n_z.iter().fold(0.0_f64, |a, n| a.max(n.abs()));
        // (from k = 2: γ̇ jumps at t̂ = 0, where the step is applied)
        for k in (2..40_000).step_by(997) {
            let fd = (gamma[k + 1] - gamma[k - 1]) / (2.0 * h) / d.c_l;
            assert!(
                (n_z[k] - fd).abs() < 1e-5 * peak,
                "t̂ = {}: {} vs {fd}",
                r.samples[k].t,
                n_z[k]
            );
            // y = C x + D δ, row n_z, on the same state
            let s = &r.samples[k];
            let x = [s.u, s.w, s.q, s.theta];
            let y: f64 = (0..4).map(|j| o.c[5][j] * x[j]).sum::<f64>() + o.d[5] * delta;
            assert!((y - n_z[k]).abs() < 1e-12 * peak, "{y} vs {}", n_z[k]);
            let g: f64 = (0..4).map(|j| o.c[4][j] * x[j]).sum();
            assert!((g - gamma[k]).abs() < 1e-15);
        }
        // at t̂ = 0⁺ only the control's lift acts: n_z = −C_Zδ·δ/(A·C_L)
        let a_mass = 1.0 - d.z_wdot / d.mu1;
        let n0 = -c.c_z * delta / (a_mass * d.c_l);
        assert!((n_z[0] - n0).abs() < 1e-14, "{} vs {n0}", n_z[0]);
        // the same in seconds: V/g = τ/C_L and q in rad/s
        let tau = 2.5;
        let ms = m.in_seconds(tau);
        assert_eq!(ms.load_factor, Some(tau / d.c_l));
        let os = ms.outputs();
        let s = &r.samples[1234];
        let y: f64 = os.c[5][0] * s.u + os.c[5][1] * s.w + os.c[5][2] * s.q / tau + os.d[5] * delta;
        assert!((y - n_z[1234]).abs() < 1e-12 * peak);
    }

    #[test]
    fn steady_n_z_per_elevator_is_the_manoeuvre_value() {
        use crate::dynamics::response::{Request, Simplifications, computed};
        // u held (the short period's two degrees of freedom), z_q = 0 and
        // no control lift: the steady pull-up has Dŵ = Dq̂ = 0, and the two
        // equations z_w ŵ + q̂ = 0, (μ₁/i_B)m_w ŵ + (m_q/i_B)q̂ + m₀ = 0 give
        // q̂ = C_mδ·δ/H_m, with a = −z_w and the stick-fixed manoeuvre
        // margin H_m = −m_w/a − m_q/μ₁ (§9; crate::criteria): so
        // n_z/δ = q̂/(C_L·δ) = C_mδ/(C_L·H_m).
        let mut d = tailless_delta_45_coupled();
        d.z_q = 0.0;
        let c = Control {
            name: "elevon".into(),
            c_x: 0.0,
            c_z: 0.0,
            c_m: -0.3,
        };
        let delta = 0.02;
        let a = -d.z_w;
        let h_m = -d.m_w / a - d.m_q / d.mu1;
        assert!(h_m > 0.0);
        let expect = c.c_m * delta / (d.c_l * h_m);
        let request = Request {
            input: step(&c, &d, delta),
            until: 200.0,
            steps: 2000,
            simplifications: Simplifications {
                neglect_u: true,
                ..Default::default()
            },
        };
        let r = computed(&d, &request).unwrap();
        let n_z = *r.n_z.unwrap().last().unwrap();
        assert!(((n_z - expect) / expect).abs() < 1e-9, "{n_z} vs {expect}");
        // with û free the phugoid settles into level flight again: the
        // steady state of ẋ = A x + B δ has q = α̇ = 0, so n_z = 0
        let m = LinearModel::of_report(&d, Some(&c)).unwrap();
        let x = -m.a.try_inverse().unwrap() * m.b.unwrap() * delta;
        let o = m.outputs();
        let n: f64 = (0..4).map(|j| o.c[5][j] * x[j]).sum::<f64>() + o.d[5] * delta;
        assert!(n.abs() < 1e-12 * expect.abs(), "{n}");
    }
}
