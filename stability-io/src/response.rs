//! A derivative file's response (§11) as the command line and the Python
//! package ask for it — a step of the moment m₀ or an initial ŵ, over a
//! span in τ — with its errors placed (at z_ẇ where the equations have no
//! state-space form, else naming the options), and the time history as
//! CSV.

use crate::csv::number;
use crate::diag::InputError;
use crate::input::{DerivativeFile, rows};
use stability_core::dynamics::linear::Control;
use stability_core::dynamics::response::{
    Computed, ComputedError, Input, Request, ResponseError, Simplifications, computed,
};
use stability_core::numerics::display::Num;
use std::fmt::Write;

/// What disturbs the aircraft.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Disturbance {
    /// An elevon applied instantaneously: a step of the moment m₀, from
    /// rest.
    Step,
    /// No input: the motion from an initial disturbance ŵ(0) = w₀.
    Initial,
}

impl Disturbance {
    /// `step` or `initial`, as the options name them.
    pub fn name(self) -> &'static str {
        match self {
            Disturbance::Step => "step",
            Disturbance::Initial => "initial",
        }
    }

    /// The disturbance named `name`.
    pub fn parse(name: &str) -> Option<Disturbance> {
        [Disturbance::Step, Disturbance::Initial]
            .into_iter()
            .find(|d| d.name() == name)
    }
}

/// How the caller gave the response's span, step count and input, in its
/// own words — the command line's `--until-s 5`, `--elevator-deg 1e308`,
/// Python's `until=5`, `m0=1` — so that an error names what the user
/// wrote, never an option they did not give.
#[derive(Debug, Clone, PartialEq)]
pub struct Given {
    /// The span: `--until 3`, `--until-s 5`, `until=3`.
    pub span: String,
    /// The option of the span alone (`--until-s`), for advice.
    pub span_option: &'static str,
    /// The step count: `--steps 400`, `steps=400`.
    pub steps: String,
    /// The input: `--elevator-deg 1e308`, `--m0 1`, `--w0 0.01`, `m0=1`.
    pub input: String,
}

/// A response as asked for by name (`response`'s options).
#[derive(Debug, Clone, PartialEq)]
pub struct Spec {
    pub input: Disturbance,
    /// The end time, τ units.
    pub until: f64,
    /// The number of intervals.
    pub steps: usize,
    /// The size of the moment step (eqs 2 units).
    pub m0: f64,
    /// The forces of the step, x₀ and z₀ (eqs 2 units; 0 for the report's
    /// moment step): a control deflection's ([`control_step`]).
    pub x0: f64,
    pub z0: f64,
    /// The initial ŵ of `Initial`.
    pub w0: f64,
    pub neglect_zq_zwdot: bool,
    pub neglect_u: bool,
    /// How the caller gave them (for its messages).
    pub given: Given,
}

impl Spec {
    /// The library's request.
    pub fn request(&self) -> Request {
        let input = match self.input {
            Disturbance::Step => Input::Step {
                x0: self.x0,
                z0: self.z0,
                m0: self.m0,
            },
            Disturbance::Initial => Input::Initial {
                u: 0.0,
                w: self.w0,
                q: 0.0,
                theta: 0.0,
            },
        };
        Request {
            input,
            until: self.until,
            steps: self.steps,
            simplifications: Simplifications {
                neglect_zq_zwdot: self.neglect_zq_zwdot,
                neglect_u: self.neglect_u,
            },
        }
    }
}

/// How a caller writes its options, for the messages of [`Asked::spec`]:
/// the command line's `--until-s 5`, Python's `until_s=5`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Style {
    CommandLine,
    Keywords,
}

impl Style {
    /// The option whose keyword is `name` (`until_s`), as the caller
    /// writes it (`--until-s`, `until_s`).
    pub fn option(self, name: &str) -> String {
        match self {
            Style::CommandLine => format!("--{}", name.replace('_', "-")),
            Style::Keywords => name.to_string(),
        }
    }

    /// The option with its value (`--until-s 5`, `until_s=5`).
    pub fn given(self, name: &str, value: impl std::fmt::Display) -> String {
        match self {
            Style::CommandLine => format!("{} {value}", self.option(name)),
            Style::Keywords => format!("{name}={value}"),
        }
    }

    /// [`Given::span_option`]: the span's option.
    fn span_option(self, seconds: bool) -> &'static str {
        match (self, seconds) {
            (Style::CommandLine, false) => "--until",
            (Style::CommandLine, true) => "--until-s",
            (Style::Keywords, false) => "until",
            (Style::Keywords, true) => "until_s",
        }
    }
}

/// A response as the caller asks for it — the span in τ (`until`) or in
/// seconds (`until_s`, by the file's τ), a moment step `m0`, a step of the
/// `[control]` in degrees (`elevator_deg`) or an initial ŵ (`w0`) — made
/// into a [`Spec`] by [`Asked::spec`], the one place both front ends'
/// options are checked. The numbers are finite and the span positive (the
/// caller's parser checks that).
#[derive(Debug, Clone, PartialEq)]
pub struct Asked {
    pub input: Disturbance,
    pub until: Option<f64>,
    pub until_s: Option<f64>,
    pub steps: usize,
    pub m0: Option<f64>,
    pub w0: Option<f64>,
    pub elevator_deg: Option<f64>,
    pub neglect_zq_zwdot: bool,
    pub neglect_u: bool,
    pub style: Style,
}

impl Asked {
    /// The library's response, as asked for, of `file` with its
    /// `[control]`: the span in τ (from seconds by τ), the step from the
    /// control's deflection; the error names what is missing, in the
    /// caller's words.
    pub fn spec(
        &self,
        file: &DerivativeFile,
        control: Option<&Control>,
    ) -> Result<Spec, InputError> {
        let st = self.style;
        let bad = |m: String| InputError::file(&file.path, m);
        let (until, span) = match (self.until, self.until_s, file.tau()) {
            (Some(t), ..) => (t, (st.given("until", Num(t)), false)),
            (None, Some(s), Some(tau)) => {
                let g = format!("{} (t̂ = {})", st.given("until_s", Num(s)), Num(s / tau));
                (s / tau, (g, true))
            }
            (None, Some(s), None) => {
                return Err(bad(format!(
                    "{}: times in seconds need τ = m/(½ρSV): give a physical flight condition (a config's [flight] units, altitude, mass, I_y; or a derivative file's [dimensional] V, rho, S, chord, mass), or {} in units of τ",
                    st.given("until_s", s),
                    st.option("until")
                )));
            }
            (None, None, _) => {
                return Err(bad(format!(
                    "give the span: {} (units of τ) or {} (seconds)",
                    st.option("until"),
                    st.option("until_s")
                )));
            }
        };
        self.refuse_unused().map_err(|m| {
            bad(format!(
                "{m}: it does nothing with {}",
                st.given("input", self.input.name())
            ))
        })?;
        let (m0, w0) = (self.m0.unwrap_or(1.0), self.w0.unwrap_or(0.01));
        let input = match (self.input, self.elevator_deg) {
            (Disturbance::Initial, _) => st.given("w0", Num(w0)),
            (Disturbance::Step, Some(deg)) => st.given("elevator_deg", Num(deg)),
            (Disturbance::Step, None) => st.given("m0", Num(m0)),
        };
        let [x0, z0, m0] = match (self.elevator_deg, control) {
            (None, _) => [0.0, 0.0, m0],
            (Some(_), _) if self.input == Disturbance::Initial => {
                return Err(bad(format!(
                    "{} is a step of the control: it needs {}",
                    st.option("elevator_deg"),
                    st.given("input", "step")
                )));
            }
            (Some(deg), Some(c)) => control_step(file, c, deg),
            (Some(deg), None) => {
                return Err(bad(format!(
                    "{}: the file has no [control] table (C_mdelta, and C_zdelta or C_Ldelta, C_xdelta: per radian; see delta-stability quartic --help)",
                    st.given("elevator_deg", deg)
                )));
            }
        };
        Ok(Spec {
            input: self.input,
            until,
            steps: self.steps,
            m0,
            x0,
            z0,
            w0,
            neglect_zq_zwdot: self.neglect_zq_zwdot,
            neglect_u: self.neglect_u,
            given: Given {
                span: span.0,
                span_option: st.span_option(span.1),
                steps: st.given("steps", self.steps),
                input,
            },
        })
    }

    /// An option of the other input, which would be ignored: refused.
    fn refuse_unused(&self) -> Result<(), String> {
        let st = self.style;
        let (unused, of) = match self.input {
            Disturbance::Step => (self.w0.map(|_| "w0"), "initial"),
            Disturbance::Initial => (self.m0.map(|_| "m0"), "step"),
        };
        let what = |name: &str| match name {
            "w0" => "the initial ŵ",
            _ => "the moment step",
        };
        match unused {
            Some(name) => Err(format!(
                "{} is {} of {}",
                st.option(name),
                what(name),
                st.given("input", of)
            )),
            None => Ok(()),
        }
    }
}

/// The step (x₀, z₀, m₀) of a deflection of `degrees` of the file's
/// `[control]` ([`Control::forcing`]).
pub fn control_step(file: &DerivativeFile, control: &Control, degrees: f64) -> [f64; 3] {
    control
        .forcing(&file.derivatives)
        .map(|f| f * degrees.to_radians())
}

/// The response of `file`'s set over the whole span asked for, or why it
/// cannot be had: each error names the option, as the caller gave it
/// ([`Given`]), that it is about.
pub fn respond(file: &DerivativeFile, spec: &Spec) -> Result<Computed, InputError> {
    let bad = |m: String| InputError::file(&file.path, m);
    let g = &spec.given;
    computed(&file.derivatives, &spec.request()).map_err(|e| match e {
        ComputedError::Response(e @ ResponseError::SingularMass { .. }) => {
            file.error_at(rows::Z_WDOT, e.to_string())
        }
        ComputedError::Response(
            e @ (ResponseError::Derivatives(_) | ResponseError::MatrixOverflow),
        ) => bad(e.to_string()),
        ComputedError::Response(ResponseError::NonFiniteInput { quantity, value }) => bad(format!(
            "{}: {} is {}, not a finite number: give a smaller value",
            g.input,
            disturbance(quantity),
            Num(value)
        )),
        ComputedError::Response(e @ ResponseError::Until { .. }) => {
            bad(format!("{}: {e}", g.span))
        }
        ComputedError::Response(e @ ResponseError::Steps { .. }) => {
            bad(format!("{}: {e}", g.steps))
        }
        ComputedError::Response(e @ ResponseError::TooStiff { .. }) => {
            bad(format!("{} {}: {e}", g.span, g.steps))
        }
        ComputedError::Stopped { reached, stop, .. } => bad(format!(
            "the response stops at t̂ = {} of the {} asked for ({}): {stop}; ask for a shorter {}",
            Num(reached),
            Num(spec.until),
            g.span,
            g.span_option
        )),
        ComputedError::ClosedFormOverflow { t, .. } => bad(format!(
            "eq (45)'s two-degree-of-freedom response overflows f64 at t̂ = {}, before t̂ = {} ({}): ask for a shorter {}",
            Num(t),
            Num(spec.until),
            g.span,
            g.span_option
        )),
    })
}

/// What the input `quantity` of the library's request is, in words that
/// name no option (the caller's option is named beside it).
fn disturbance(quantity: &str) -> &'static str {
    match quantity {
        "m0" => "the pitching moment it applies (eqs 2 units)",
        "x0" => "the force along x it applies (eqs 2 units)",
        "z0" => "the force along z it applies (eqs 2 units)",
        _ => "the initial disturbance it makes",
    }
}

/// The CSV's columns: t̂, t in seconds when τ is known, the states,
/// eq (45)'s ŵ (empty but for a step of m₀ alone), the flight-path angle
/// γ = θ − ŵ (rad) and the normal load factor at the c.g. n_z (empty where
/// C_L ≤ 0; [`stability_core::dynamics::response::load_factor`]).
pub fn columns(tau: Option<f64>) -> Vec<&'static str> {
    let mut c = vec!["t_hat"];
    if tau.is_some() {
        c.push("t_s");
    }
    c.extend([
        "u_hat",
        "w_hat",
        "q_hat",
        "theta",
        "w_hat_eq45",
        "gamma",
        "n_z",
    ]);
    c
}

/// The time history as CSV ([`columns`]; numbers by [`number`]).
pub fn csv(r: &Computed, tau: Option<f64>) -> String {
    let mut csv = columns(tau).join(",");
    csv.push('\n');
    let at = |v: &Option<Vec<f64>>, k: usize| v.as_ref().map(|v| number(v[k]));
    for (k, s) in r.samples.iter().enumerate() {
        let _ = write!(csv, "{}", number(s.t));
        if let Some(t) = tau {
            let _ = write!(csv, ",{}", number(s.t * t));
        }
        let _ = writeln!(
            csv,
            ",{},{},{},{},{},{},{}",
            number(s.u),
            number(s.w),
            number(s.q),
            number(s.theta),
            at(&r.eq45, k).unwrap_or_default(),
            number(s.theta - s.w),
            at(&r.n_z, k).unwrap_or_default(),
        );
    }
    csv
}
