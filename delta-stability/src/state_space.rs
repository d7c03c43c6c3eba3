//! `--state-space FILE.json` (`quartic`, `analyze`): the linear model
//! ẋ = A x + B δ of [`stability_core::linear`] written as JSON, with a
//! python-control script (`FILE.py`) and a MATLAB script (`FILE.m`) beside
//! it that build the same system and print its `damp()` table.
//!
//! x = (u/V, α, q, θ). Time is in seconds when the flight condition is
//! dimensional (`[dimensional]`, or a physical `[flight]` in a config);
//! otherwise in the report's unit τ (q is then q̂ = dθ/dt̂).
//!
//! B needs a control derivative: a `[control]` table in the derivative
//! file or config,
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

use crate::Failure;
use crate::diag::{InputError, num};
use crate::files::write_error;
use crate::input::toml_error;
use crate::output::atomic_write;
use num_complex::Complex64;
use serde::{Deserialize, Serialize};
use stability_core::linear::{Control, LinearModel, STATES, TimeUnit};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use toml::Spanned;

#[derive(Deserialize)]
struct WithControl {
    control: Option<Spanned<RawControl>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
#[allow(non_snake_case)] // the fields are the coefficients' names
struct RawControl {
    name: Option<String>,
    C_xdelta: Option<Spanned<f64>>,
    C_zdelta: Option<Spanned<f64>>,
    C_Ldelta: Option<Spanned<f64>>,
    C_mdelta: Option<Spanned<f64>>,
}

/// The `[control]` table of a file's text, if it has one; every error
/// names the file, line and field.
pub fn read_control(path: &str, text: &str) -> Result<Option<Control>, InputError> {
    let raw: WithControl = toml::from_str(text).map_err(|e| toml_error(path, text, &e))?;
    let Some(c) = raw.control else {
        return Ok(None);
    };
    let span = c.span();
    let c = c.into_inner();
    let value = |field: &str, v: &Option<Spanned<f64>>| -> Result<Option<f64>, InputError> {
        match v {
            Some(v) if !v.get_ref().is_finite() => Err(InputError::at(
                path,
                text,
                v.span(),
                format!("[control] {field}"),
                format!("{} is not a finite number", num(*v.get_ref())),
            )),
            Some(v) => Ok(Some(*v.get_ref())),
            None => Ok(None),
        }
    };
    let Some(c_m) = value("C_mdelta", &c.C_mdelta)? else {
        let m = "missing field `C_mdelta`: the control's moment derivative ∂C_m/∂δ per radian";
        return Err(InputError::at(path, text, span, "[control] C_mdelta", m));
    };
    let c_z = match (
        value("C_zdelta", &c.C_zdelta)?,
        value("C_Ldelta", &c.C_Ldelta)?,
    ) {
        (Some(_), Some(_)) => {
            let s = c.C_Ldelta.as_ref().map_or(span, |v| v.span());
            let m = "[control] C_zdelta and [control] C_Ldelta both give the control's normal force (C_Z = −C_L): give one";
            return Err(InputError::at(path, text, s, "[control] C_Ldelta", m));
        }
        (Some(z), None) => z,
        (None, Some(l)) => -l,
        (None, None) => 0.0,
    };
    let name = c.name.unwrap_or_else(|| "delta".into());
    let plain = |ch: char| ch.is_ascii_alphanumeric() || "_- ".contains(ch);
    if name.is_empty() || name.chars().count() > 32 || !name.chars().all(plain) {
        let m = format!(
            "the control's name `{}` must be 1 to 32 letters, digits, spaces, `_` or `-` (it names the input in the scripts)",
            crate::diag::quote(&name)
        );
        return Err(InputError::at(path, text, span, "[control] name", m));
    }
    Ok(Some(Control {
        name,
        c_x: value("C_xdelta", &c.C_xdelta)?.unwrap_or(0.0),
        c_z,
        c_m,
    }))
}

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

/// The number as Python and MATLAB read it back exactly.
fn lit(x: f64) -> String {
    format!("{x:?}")
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
    let j = ExportJson {
        source: e.source,
        generated_by: format!("delta-stability {}", env!("CARGO_PKG_VERSION")),
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
    };
    format!("{}\n", serde_json::to_string_pretty(&j).unwrap_or_default())
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

/// Writes the export: the JSON, then the two scripts, each atomically.
pub fn write(out: &str, e: &Export<'_>) -> Result<(), Failure> {
    let [json, py, m] = paths(out)?;
    if !e.model.is_finite() {
        return Err(InputError::file(
            e.source,
            "the state matrix overflows f64: no state space can be written",
        )
        .into());
    }
    for (path, text) in [
        (&json, to_json(e)),
        (&py, python_snippet(e)),
        (&m, matlab_snippet(e)),
    ] {
        atomic_write(path, text.as_bytes()).map_err(|err| Failure::Io(write_error(path, &err)))?;
    }
    crate::output::warn(&format!(
        "wrote the state space to {} (and {}, {})",
        json.display(),
        py.display(),
        m.display()
    ));
    Ok(())
}
