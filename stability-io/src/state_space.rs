//! The state-space export (`--state-space FILE.json` of `quartic` and
//! `analyze`): the linear model ẋ = A x + B δ of [`stability_core::linear`]
//! as JSON, with a python-control script (`FILE.py`) and a MATLAB script
//! (`FILE.m`) beside it that build the same system and print its `damp()`
//! table.
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
use stability_core::linear::{LinearModel, STATES, TimeUnit};
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
    eigenvalues: Vec<Root>,
    python_control: String,
    matlab: String,
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

/// The python-control script.
pub fn python_snippet(e: &Export<'_>) -> String {
    let mut s = String::new();
    for line in describe(e).lines() {
        let _ = writeln!(s, "# {line}");
    }
    s.push_str("import numpy as np\nimport control as ct\n\nA = np.array([\n");
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
    let names = "[\"u_over_V\", \"alpha\", \"q\", \"theta\"]";
    let _ = writeln!(
        s,
        "sys = ct.ss(A, B, np.eye(4), np.zeros((4, 1)),\n           states={names}, outputs={names}, inputs=[{input:?}])\n\nif __name__ == \"__main__\":\n    ct.damp(sys)"
    );
    s
}

/// The MATLAB script.
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
    let input = e.model.input.clone().unwrap_or_else(|| "none".into());
    let names = "{'u/V', 'alpha', 'q', 'theta'}";
    let _ = writeln!(
        s,
        "sys = ss(A, B, eye(4), zeros(4, 1), 'StateName', {names}, ...\n    'OutputName', {names}, 'InputName', {{'{input}'}});\ndamp(sys)"
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
