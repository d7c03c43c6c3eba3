//! The state-space export (`--state-space FILE.json` of `quartic` and
//! `analyze`): the linear model ẋ = A x + B δ of [`stability_core::dynamics::linear`]
//! as JSON, with a python-control script (`FILE.py`) and a MATLAB script
//! (`FILE.m`) beside it that build the same system, print its `damp()`
//! table and its step response (`STEP_DEG` degrees of the control over
//! `T_FINAL`, ten periods of the fastest mode; the python-control script
//! plots it with `--plot FILE.png`).
//!
//! The outputs y = C x + D δ are the states, the flight-path angle
//! γ = θ − α and the normal load factor at the c.g. n_z = (V/g)(q − α̇)
//! ([`stability_core::dynamics::linear::LinearModel::outputs`], derived there, after
//! Etkin & Reid §4.2–4.3): `outputs`, `C` and `D` in the JSON.
//!
//! x = (u/V, α, q, θ). Time is in seconds when the flight condition is
//! dimensional (`[dimensional]`, or a physical `[flight]` in a config);
//! otherwise in the report's unit τ (q is then q̂ = dθ/dt̂).
//!
//! B needs a control derivative: a `[control]` table in the derivative
//! file or config ([`crate::control`]),
//!
//! ```toml
//! [control]
//! name = "elevator"   # optional; what δ is (default "delta")
//! C_mdelta = -1.20    # ∂C_m/∂δ per radian (moment on ½ρV²Sc̄)
//! C_zdelta = -0.35    # ∂C_Z/∂δ per radian (Z down), or C_Ldelta = ∂C_L/∂δ (C_Z = −C_L); default 0
//! C_xdelta = 0.0      # ∂C_X/∂δ per radian; default 0
//! ```
//!
//! in the report's stability axes. Without it the file has A only (`B` is
//! `null`, and the scripts use a zero input column named `none`).

use crate::csv::exact as lit;
use crate::diag::InputError;
use num_complex::Complex64;
use serde::Serialize;
use stability_core::dynamics::linear::{LinearModel, Outputs, STATES, TimeUnit};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// What the export is of.
pub struct Export<'a> {
    /// The input file.
    pub source: &'a str,
    /// The command that wrote it (`quartic`, `analyze`).
    pub command: &'a str,
    pub model: &'a LinearModel,
    /// τ (s), when known.
    pub tau: Option<f64>,
    /// The four roots in the model's unit of time.
    pub eigenvalues: [Complex64; 4],
}

#[derive(Serialize)]
struct Root {
    re: f64,
    im: f64,
}

#[derive(Serialize)]
struct ExportJson<'a> {
    source: &'a str,
    generated_by: String,
    states: [&'static str; 4],
    state_units: [&'static str; 4],
    time_unit: &'static str,
    tau_s: Option<f64>,
    inputs: Vec<String>,
    #[serde(rename = "A")]
    a: [[f64; 4]; 4],
    #[serde(rename = "B")]
    b: Option<[[f64; 1]; 4]>,
    outputs: Vec<&'static str>,
    output_units: Vec<&'static str>,
    #[serde(rename = "C")]
    c: Vec<[f64; 4]>,
    #[serde(rename = "D")]
    d: Vec<[f64; 1]>,
    /// The scripts' step response: the deflection (deg) and span.
    step_deg: f64,
    t_final: f64,
    eigenvalues: Vec<Root>,
    python_control: String,
    matlab: String,
}

/// The deflection of the scripts' step response, degrees.
pub const STEP_DEG: f64 = 1.0;

/// The span of the scripts' step response: ten periods 2π/|λ| of the
/// fastest root (10 where every root is zero), in the model's unit.
pub fn t_final(e: &Export<'_>) -> f64 {
    let fastest = e.eigenvalues.iter().map(|z| z.norm()).fold(0.0, f64::max);
    if fastest > 0.0 && (20.0 * std::f64::consts::PI / fastest).is_finite() {
        20.0 * std::f64::consts::PI / fastest
    } else {
        10.0
    }
}

/// The unit of each output: the states', then γ's (rad) and n_z's (1: g's).
fn output_units(m: &LinearModel, o: &Outputs) -> Vec<&'static str> {
    let mut u = m.state_units().to_vec();
    u.extend(["rad", "1"]);
    u.truncate(o.names.len());
    u
}

/// Names Python and MATLAB take (`u/V` is not an identifier).
fn script_name(n: &str) -> String {
    n.replace('/', "_over_")
}

/// A's rows.
fn rows(m: &LinearModel) -> [[f64; 4]; 4] {
    std::array::from_fn(|i| std::array::from_fn(|j| m.a[(i, j)]))
}

fn describe(e: &Export<'_>) -> String {
    let time = match e.model.time {
        TimeUnit::Seconds => "time in seconds, q in rad/s".to_string(),
        TimeUnit::Tau => {
            "time in the report's unit tau = m/(rho S V/2), q = dtheta/dt_hat".to_string()
        }
    };
    let input = match &e.model.input {
        Some(n) => format!("input: {n} (rad)"),
        None => "no control derivative given: a zero input column".into(),
    };
    format!(
        "states x = (u/V, alpha, q, theta); {time}; {input}.\nWritten by `delta-stability {} {} --state-space`.",
        e.command, e.source
    )
}

/// The python-control script: the system, its `damp()` table and its
/// step response (a table; a plot with `--plot FILE.png`).
pub fn python_snippet(e: &Export<'_>) -> String {
    let mut s = String::new();
    for line in describe(e).lines() {
        let _ = writeln!(s, "# {line}");
    }
    s.push_str(
        "import sys as _sys\n\nimport numpy as np\nimport control as ct\n\nA = np.array([\n",
    );
    for r in rows(e.model) {
        let _ = writeln!(s, "    [{}],", r.map(lit).join(", "));
    }
    s.push_str("])\n");
    let input = e.model.input.clone().unwrap_or_else(|| "none".into());
    match e.model.b {
        Some(b) => {
            let col: Vec<String> = b.iter().map(|&x| format!("[{}]", lit(x))).collect();
            let _ = writeln!(s, "B = np.array([{}])", col.join(", "));
        }
        None => s.push_str("B = np.zeros((4, 1))\n"),
    }
    let o = e.model.outputs();
    s.push_str("# outputs: the states, gamma = theta - alpha and n_z = (V/g)(q - alpha_dot), the normal load factor at the c.g.\nC = np.array([\n");
    for r in &o.c {
        let _ = writeln!(s, "    [{}],", r.map(lit).join(", "));
    }
    let d: Vec<String> = o.d.iter().map(|&x| format!("[{}]", lit(x))).collect();
    let _ = writeln!(s, "])\nD = np.array([{}])", d.join(", "));
    let names = |v: &[&str]| {
        let q: Vec<String> = v.iter().map(|n| format!("{:?}", script_name(n))).collect();
        format!("[{}]", q.join(", "))
    };
    let _ = writeln!(
        s,
        "STATES = {}\nOUTPUTS = {}\nINPUT = {input:?}\nTIME_UNIT = {:?}\nSTEP_DEG = {}  # the step of the control, degrees\nT_FINAL = {}  # ten periods of the fastest mode\n",
        names(&STATES),
        names(&o.names),
        e.model.time.symbol(),
        lit(STEP_DEG),
        lit(t_final(e)),
    );
    s.push_str(PYTHON_MAIN);
    s
}

/// The python-control script's step response and main.
const PYTHON_MAIN: &str = r#"sys = ct.ss(A, B, C, D, states=STATES, outputs=OUTPUTS, inputs=[INPUT])


def step(n=401):
    """The outputs' response to a step of STEP_DEG degrees from rest: t and y[output, time]."""
    t = np.linspace(0.0, T_FINAL, n)
    r = ct.step_response(sys, T=t)
    y = np.asarray(r.outputs).reshape(len(OUTPUTS), -1) * np.radians(STEP_DEG)
    return np.asarray(r.time), y


if __name__ == "__main__":
    ct.damp(sys)
    if not np.any(B):
        print("no control derivatives ([control]): no step response")
        _sys.exit(0)
    t, y = step()
    print(f"step response to {STEP_DEG} deg of {INPUT} (time in {TIME_UNIT}):")
    print(" ".join(f"{n:>14}" for n in ["t"] + OUTPUTS))
    for k in range(0, len(t), 40):
        print(" ".join(f"{v:14.6e}" for v in [t[k]] + list(y[:, k])))
    if "--plot" in _sys.argv:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        out = _sys.argv[_sys.argv.index("--plot") + 1]
        fig, axes = plt.subplots(len(OUTPUTS), 1, sharex=True, figsize=(7, 2 * len(OUTPUTS)))
        for ax, name, row in zip(axes, OUTPUTS, y):
            ax.plot(t, row)
            ax.set_ylabel(name)
        axes[-1].set_xlabel(f"t ({TIME_UNIT})")
        fig.savefig(out)
        print("wrote", out)
"#;

/// The MATLAB script: the system, its `damp()` table and its step
/// response (plotted).
pub fn matlab_snippet(e: &Export<'_>) -> String {
    let mut s = String::new();
    for line in describe(e).lines() {
        let _ = writeln!(s, "% {line}");
    }
    s.push_str("A = [\n");
    for r in rows(e.model) {
        let _ = writeln!(s, "    {}", r.map(lit).join(" "));
    }
    s.push_str("];\n");
    match e.model.b {
        Some(b) => {
            let col: Vec<String> = b.iter().map(|&x| lit(x)).collect();
            let _ = writeln!(s, "B = [{}];", col.join("; "));
        }
        None => s.push_str("B = zeros(4, 1);\n"),
    }
    let o = e.model.outputs();
    s.push_str("% outputs: the states, gamma = theta - alpha and n_z = (V/g)(q - alpha_dot), the normal load factor at the c.g.\nC = [\n");
    for r in &o.c {
        let _ = writeln!(s, "    {}", r.map(lit).join(" "));
    }
    let d: Vec<String> = o.d.iter().map(|&x| lit(x)).collect();
    let _ = writeln!(s, "];\nD = [{}];", d.join("; "));
    let input = e.model.input.clone().unwrap_or_else(|| "none".into());
    let names = |v: &[&str]| {
        let q: Vec<String> = v.iter().map(|n| format!("'{n}'")).collect();
        format!("{{{}}}", q.join(", "))
    };
    let _ = writeln!(
        s,
        "sys = ss(A, B, C, D, 'StateName', {}, ...\n    'OutputName', {}, 'InputName', {{'{input}'}});\ndamp(sys)\nstep_deg = {};  % the step of the control, degrees\nt_final = {};  % ten periods of the fastest mode ({})\nif any(B)\n    step(sys * (step_deg * pi / 180), t_final)\nend",
        names(&STATES),
        names(&o.names),
        lit(STEP_DEG),
        lit(t_final(e)),
        e.model.time.symbol(),
    );
    s
}

/// The JSON of an export, with both scripts in it.
pub fn to_json(e: &Export<'_>) -> String {
    format!(
        "{}\n",
        serde_json::to_string_pretty(&view(e)).unwrap_or_default()
    )
}

/// Whether every number the export writes is finite (the guard of
/// [`crate::finite`]; the error names the field and `e.source`).
pub fn guard(e: &Export<'_>) -> Result<(), InputError> {
    crate::finite::guard(e.source, &view(e))
}

fn view<'a>(e: &'a Export<'a>) -> ExportJson<'a> {
    let outputs = e.model.outputs();
    ExportJson {
        source: e.source,
        generated_by: format!("delta-stability {}", crate::VERSION),
        states: STATES,
        state_units: e.model.state_units(),
        time_unit: e.model.time.symbol(),
        tau_s: e.tau,
        inputs: e.model.input.iter().cloned().collect(),
        a: rows(e.model),
        b: e.model.b.map(|b| std::array::from_fn(|i| [b[i]])),
        outputs: outputs.names.clone(),
        output_units: output_units(e.model, &outputs),
        c: outputs.c.clone(),
        d: outputs.d.iter().map(|&x| [x]).collect(),
        step_deg: STEP_DEG,
        t_final: t_final(e),
        eigenvalues: e
            .eigenvalues
            .iter()
            .map(|z| Root { re: z.re, im: z.im })
            .collect(),
        python_control: python_snippet(e),
        matlab: matlab_snippet(e),
    }
}

/// The three paths an export writes: `FILE.json`, `FILE.py`, `FILE.m`.
pub fn paths(out: &str) -> Result<[PathBuf; 3], InputError> {
    let p = Path::new(out);
    if p.extension().and_then(|e| e.to_str()) != Some("json") {
        return Err(InputError::file(
            out,
            "--state-space: the file must end in .json (the python-control and MATLAB scripts are written beside it, as .py and .m)",
        ));
    }
    Ok([
        p.to_path_buf(),
        p.with_extension("py"),
        p.with_extension("m"),
    ])
}
