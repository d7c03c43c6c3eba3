//! `Derivatives`, `quartic()` → `Quartic` and `analyze()` → `Analysis`:
//! a derivative set's stability (eqs 4–8, Routh §4, the §8 standard), and
//! a design point's (§5–7 then the same). Their `to_dict()` is the command
//! line's `quartic --json` and `analyze --json`, serialized from the same
//! library views.

use crate::engineering;
use crate::errors::{argument, failure, input_error};
use crate::guard;
use crate::inputs::derivative_file;
use crate::json::{to_py, view_to_py};
use crate::overrides::{Model, overridden};
use crate::views::{Attr, always, dir, getattr, optional};
use numpy::{Complex64, IntoPyArray, PyArray1};
use pyo3::exceptions::{PyAttributeError, PyTypeError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use serde_json::Value;
use stability_core::design::case::CaseResult;
use stability_core::dynamics::linear::LinearModel;
use stability_core::dynamics::modes::Mode as CoreMode;
use stability_io::design_point::results;
use stability_io::input::DerivativeFile;
use stability_io::views::{AnalyzeJson, QuarticJson};
use std::path::{Path, PathBuf};

/// A longitudinal derivative set in the report's notation (§3, eqs 2–4):
/// the twelve non-dimensional derivatives and the three flight parameters
/// of the stability quartic.
///
/// Forces are made non-dimensional on ½ρSV (velocity derivatives x_u, x_w,
/// z_u, z_w: eqs 9–12), ½ρSc̄ (acceleration derivatives x_ẇ, z_ẇ, m_ẇ:
/// eqs 18–20) and ½ρSVc̄ (rate derivatives x_q, z_q, m_q: eqs 15–17);
/// moments carry a further c̄ (m_u, m_w: eqs 13–14). c_l is the lift
/// coefficient of the undisturbed flight (eq 24), mu1 the relative density
/// μ₁ = m/(½ρSc̄) and i_b the pitching inertia i_B = B/(mc̄²). Time is in
/// units of τ = m/(½ρSV).
///
/// Derivatives(x_u=…, x_w=…, …, i_b=…) takes all fifteen by these names
/// (`Derivatives.NAMES`); `Derivatives.read(source, notation=…)` reads
/// them from a file, a dict or keyword arguments in any notation. Frozen:
/// `d.replace(m_q=-1.0)` makes a changed copy.
#[pyclass(frozen, eq, module = "delta_stability")]
#[derive(Clone, PartialEq)]
pub struct Derivatives(pub stability_core::Derivatives);

impl Derivatives {
    /// As a derivative file's table in the report's notation.
    pub fn report_table(&self) -> toml::Table {
        let names = stability_core::Derivatives::QUARTIC_INPUTS;
        let values = self.0.quartic_input_values();
        let (mut d, mut f) = (toml::Table::new(), toml::Table::new());
        for (k, (n, v)) in names.iter().zip(values).enumerate() {
            let t = if k < 12 { &mut d } else { &mut f };
            t.insert(n.to_string(), toml::Value::Float(v));
        }
        let mut t = toml::Table::new();
        t.insert("notation".into(), toml::Value::String("report".into()));
        t.insert("derivatives".into(), toml::Value::Table(d));
        t.insert("flight".into(), toml::Value::Table(f));
        t
    }

    fn from_values(values: &[Option<f64>; 15]) -> Result<Self, Vec<&'static str>> {
        let names = stability_core::Derivatives::QUARTIC_INPUTS;
        let missing: Vec<&str> = names
            .iter()
            .zip(values)
            .filter(|(_, v)| v.is_none())
            .map(|(n, _)| *n)
            .collect();
        if !missing.is_empty() {
            return Err(missing);
        }
        let v = values.map(|x| x.unwrap_or(0.0));
        Ok(Derivatives(stability_core::Derivatives {
            x_u: v[0],
            x_w: v[1],
            x_wdot: v[2],
            x_q: v[3],
            z_u: v[4],
            z_w: v[5],
            z_wdot: v[6],
            z_q: v[7],
            m_u: v[8],
            m_w: v[9],
            m_wdot: v[10],
            m_q: v[11],
            c_l: v[12],
            mu1: v[13],
            i_b: v[14],
        }))
    }

    /// From keyword arguments by the report's names, each one required.
    fn from_kwargs(kwargs: Option<&Bound<'_, PyDict>>, base: Option<&Self>) -> PyResult<Self> {
        let names = stability_core::Derivatives::QUARTIC_INPUTS;
        let mut values: [Option<f64>; 15] = match base {
            Some(b) => b.0.quartic_input_values().map(Some),
            None => [None; 15],
        };
        if let Some(k) = kwargs {
            for (key, v) in k.iter() {
                let key: String = key.extract()?;
                let Some(i) = names.iter().position(|n| *n == key) else {
                    return Err(PyTypeError::new_err(format!(
                        "Derivatives has no quantity `{key}`; its quantities are {} (report notation; Derivatives.read takes the other notations)",
                        names.join(", ")
                    )));
                };
                values[i] = Some(
                    v.extract::<f64>()
                        .map_err(|_| PyTypeError::new_err(format!("{key} must be a number")))?,
                );
            }
        }
        Self::from_values(&values).map_err(|missing| {
            PyTypeError::new_err(format!(
                "Derivatives needs all fifteen quantities; missing: {}",
                missing.join(", ")
            ))
        })
    }
}

#[pymethods]
impl Derivatives {
    /// The fifteen names, in the order of `to_array()`: x_u x_w x_wdot x_q
    /// z_u z_w z_wdot z_q m_u m_w m_wdot m_q c_l mu1 i_b.
    #[classattr]
    const NAMES: [&'static str; 15] = stability_core::Derivatives::QUARTIC_INPUTS;

    #[new]
    #[pyo3(signature = (**kwargs))]
    fn new(kwargs: Option<&Bound<'_, PyDict>>) -> PyResult<Self> {
        Self::from_kwargs(kwargs, None)
    }

    /// A derivative set read as `delta-stability quartic` reads it: from a
    /// path to a TOML file, a dict of the same shape (or flat: quantities
    /// by name beside `notation`), or keyword arguments, in any notation
    /// (`notation="american"`, …; `notations()` lists them), converted
    /// into the report's (appendix). Raises InputError with the command
    /// line's message.
    #[staticmethod]
    #[pyo3(signature = (source=None, /, *, notation=None, **kwargs))]
    fn read(
        source: Option<&Bound<'_, PyAny>>,
        notation: Option<&str>,
        kwargs: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<Self> {
        guard(|| {
            Ok(Derivatives(
                derivative_file(source, notation, kwargs)?.derivatives,
            ))
        })
    }

    /// From an array of the fifteen values in the order of `NAMES`.
    #[staticmethod]
    fn from_array(values: Vec<f64>) -> PyResult<Self> {
        if values.len() != 15 {
            return Err(argument(
                "values",
                format!(
                    "expected the 15 values of Derivatives.NAMES, not {}",
                    values.len()
                ),
            ));
        }
        let v: [Option<f64>; 15] = std::array::from_fn(|i| Some(values[i]));
        Self::from_values(&v).map_err(|_| argument("values", "missing values"))
    }

    /// The fifteen values in the order of `NAMES`, as a numpy array.
    fn to_array<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.0.quartic_input_values().to_vec().into_pyarray(py)
    }

    /// The fifteen values by name.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        view_to_py(py, &self.0)
    }

    /// A copy with the given quantities changed.
    #[pyo3(signature = (**kwargs))]
    fn replace(&self, kwargs: Option<&Bound<'_, PyDict>>) -> PyResult<Self> {
        Self::from_kwargs(kwargs, Some(self))
    }

    /// The coefficients [A, B, C, D, E] of the stability quartic, eq (5):
    /// the exact expansion of eq (4)'s determinant (eq 6 with the errata of
    /// docs/errata.md applied).
    fn quartic_coefficients<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.0.quartic_coefficients().to_vec().into_pyarray(py)
    }

    fn __getattr__(&self, name: &str) -> PyResult<f64> {
        let names = stability_core::Derivatives::QUARTIC_INPUTS;
        match names.iter().position(|n| *n == name) {
            Some(i) => Ok(self.0.quartic_input_values()[i]),
            None => Err(PyAttributeError::new_err(format!(
                "Derivatives has no attribute `{name}`"
            ))),
        }
    }

    fn __dir__(&self) -> Vec<&'static str> {
        let mut v = stability_core::Derivatives::QUARTIC_INPUTS.to_vec();
        v.extend([
            "NAMES",
            "read",
            "from_array",
            "to_array",
            "to_dict",
            "replace",
            "quartic_coefficients",
        ]);
        v
    }

    fn __repr__(&self) -> String {
        let names = stability_core::Derivatives::QUARTIC_INPUTS;
        let values = self.0.quartic_input_values();
        let parts: Vec<String> = names
            .iter()
            .zip(values)
            .map(|(n, v)| format!("{n}={v:?}"))
            .collect();
        format!("Derivatives({})", parts.join(", "))
    }
}

/// One mode of motion (§4, eq 8): an oscillatory pair (its root with
/// s > 0) or a real root, in units of τ (1/τ for rates); None where a
/// quantity is undefined. With τ known (a file's [dimensional]), `tau_s`
/// and the same times in seconds under `_s` names.
///
/// Attributes (the `to_dict()` keys): `name` (`short_period`, `phugoid`
/// or `aperiodic`), `origin` (for an aperiodic root, the pair it came
/// from), `re`, `im` (s ≥ 0), `root` (r + is, complex), `period` (2π/s),
/// `time_to_half` (ln 2/(−r)), `time_to_double` (ln 2/r),
/// `cycles_to_half` (0.11032·s/(−r), eq 8), `cycles_to_double`,
/// `damping_ratio` (ζ = −r/|λ|), `natural_frequency` (ωₙ = |λ|),
/// `frequency_parameter` (ω̄ = s/μ₁, §9); `tau_s`, `period_s`,
/// `time_to_half_s`, `time_to_double_s`, `re_s`, `im_s`,
/// `natural_frequency_s` when τ is known.
#[pyclass(frozen, module = "delta_stability")]
pub struct Mode {
    mode: CoreMode,
    tau: Option<f64>,
    json: Value,
}

/// The attributes of a [`Mode`]: its JSON's keys, those in seconds where
/// τ is known.
const MODE_ATTRS: &[Attr] = &[
    always("name", &["name"]),
    always("origin", &["origin"]),
    always("re", &["re"]),
    always("im", &["im"]),
    always("period", &["period"]),
    always("time_to_half", &["time_to_half"]),
    always("time_to_double", &["time_to_double"]),
    always("cycles_to_half", &["cycles_to_half"]),
    always("cycles_to_double", &["cycles_to_double"]),
    always("damping_ratio", &["damping_ratio"]),
    always("natural_frequency", &["natural_frequency"]),
    always("frequency_parameter", &["frequency_parameter"]),
    optional("period_s", &["period_s"], SECONDS),
    optional("time_to_half_s", &["time_to_half_s"], SECONDS),
    optional("time_to_double_s", &["time_to_double_s"], SECONDS),
    optional("re_s", &["re_s"], SECONDS),
    optional("im_s", &["im_s"], SECONDS),
    optional("natural_frequency_s", &["natural_frequency_s"], SECONDS),
];

/// When the JSON has the quantities in seconds.
const SECONDS: &str = "τ known (a physical flight condition, or a set with τ)";

impl Mode {
    fn new(mode: CoreMode, tau: Option<f64>) -> PyResult<Mode> {
        let json = serde_json::to_value(mode.timed(tau))
            .map_err(|e| PyTypeError::new_err(e.to_string()))?;
        Ok(Mode { mode, tau, json })
    }
}

#[pymethods]
impl Mode {
    /// The root r + is as a complex number (1/τ).
    #[getter]
    fn root(&self) -> Complex64 {
        Complex64::new(self.mode.re, self.mode.im)
    }
    /// τ = m/(½ρSV) in seconds, where it is known.
    #[getter]
    fn tau_s(&self) -> Option<f64> {
        self.tau
    }
    fn __getattr__<'py>(&self, py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyAny>> {
        getattr(py, "Mode", &self.json, MODE_ATTRS, name)
    }
    fn __dir__(&self) -> Vec<&'static str> {
        dir(MODE_ATTRS, &["root", "tau_s", "to_dict"])
    }
    /// The mode as the command line's JSON gives it.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        view_to_py(py, &self.mode.timed(self.tau))
    }
    fn __repr__(&self) -> String {
        let m = &self.mode;
        let c = m
            .cycles_to_half
            .map(|c| format!(", cycles_to_half={c:.4}"))
            .unwrap_or_default();
        format!("Mode({}, root={:?}{:+?}j{c})", m.name.as_str(), m.re, m.im)
    }
}

/// The modes as Python objects.
fn modes<'py>(
    py: Python<'py>,
    modes: &[CoreMode],
    tau: Option<f64>,
) -> PyResult<Bound<'py, PyList>> {
    let items = modes
        .iter()
        .map(|m| Bound::new(py, Mode::new(*m, tau)?))
        .collect::<PyResult<Vec<_>>>()?;
    PyList::new(py, items)
}

/// The mode named `name`, if there is one.
fn named_mode<'py>(
    py: Python<'py>,
    a: &stability_core::analysis::Analysis,
    tau: Option<f64>,
    short: bool,
) -> PyResult<Option<Bound<'py, Mode>>> {
    let m = if short {
        a.modes.short_period()
    } else {
        a.modes.phugoid()
    };
    m.map(|m| Bound::new(py, Mode::new(*m, tau)?)).transpose()
}

fn roots<'py>(
    py: Python<'py>,
    a: &stability_core::analysis::Analysis,
) -> Bound<'py, PyArray1<Complex64>> {
    a.roots.to_vec().into_pyarray(py)
}

fn coefficients<'py>(
    py: Python<'py>,
    a: &stability_core::analysis::Analysis,
) -> Bound<'py, PyArray1<f64>> {
    a.quartic.to_array().to_vec().into_pyarray(py)
}

/// The attributes the JSON answers, shared by [`Quartic`] and [`Analysis`].
const ANALYSIS_ATTRS: &[Attr] = &[
    always("stable", &["stable"]),
    always("tau_s", &["tau_s"]),
    always("verdict", &["verdict", "overall"]),
    always("verdict_reasons", &["verdict", "reasons"]),
    always("criteria", &["criteria"]),
    always("classical", &["classical_eq7"]),
    // the engineer's outputs
    always("mode_shapes", &["mode_shapes"]),
    optional("damp", &["damp"], SECONDS),
    optional(
        "short_period_frequency",
        &["short_period_frequency"],
        "τ known and n/α defined, the short period oscillating",
    ),
];

/// The attributes of a [`Quartic`].
const QUARTIC_ATTRS: &[Attr] = &[
    ANALYSIS_ATTRS[0],
    ANALYSIS_ATTRS[1],
    ANALYSIS_ATTRS[2],
    ANALYSIS_ATTRS[3],
    ANALYSIS_ATTRS[4],
    ANALYSIS_ATTRS[5],
    ANALYSIS_ATTRS[6],
    ANALYSIS_ATTRS[7],
    ANALYSIS_ATTRS[8],
    always("warnings", &["warnings"]),
    always("notation", &["notation"]),
];

/// The attributes of an [`Analysis`].
const DESIGN_POINT_ATTRS: &[Attr] = &[
    ANALYSIS_ATTRS[0],
    ANALYSIS_ATTRS[1],
    ANALYSIS_ATTRS[2],
    ANALYSIS_ATTRS[3],
    ANALYSIS_ATTRS[4],
    ANALYSIS_ATTRS[5],
    ANALYSIS_ATTRS[6],
    ANALYSIS_ATTRS[7],
    ANALYSIS_ATTRS[8],
    optional("flight", &["flight"], "a physical flight condition"),
    always("aerodynamics", &["aerodynamics"]),
    always("damping", &["damping"]),
    always("case", &["case"]),
];

/// Each class's attributes read from its JSON ([`crate::views`]).
pub const ATTRIBUTES: [(&str, &[Attr]); 3] = [
    ("Mode", MODE_ATTRS),
    ("Quartic", QUARTIC_ATTRS),
    ("Analysis", DESIGN_POINT_ATTRS),
];

/// The attributes both classes compute rather than read.
const OWN: [&str; 10] = [
    "coefficients",
    "routh",
    "roots",
    "modes",
    "short_period",
    "phugoid",
    "derivatives",
    "to_dict",
    "stable",
    "verdict",
];

/// The stability quartic of a derivative set and what follows from it:
/// `delta-stability quartic`'s result.
///
/// - `coefficients`: [A, B, C, D, E] of Aλ⁴ + Bλ³ + Cλ² + Dλ + E = 0
///   (eq 5), the exact expansion of eq (4) (eq 6, errata applied);
/// - `routh`: Routh's discriminant R = BCD − AD² − B²E and the §4 verdict
///   (stable when A…E and R have one sign); `stable`;
/// - `roots`: the four roots (1/τ), conjugates adjacent, fastest first;
/// - `modes`, `short_period`, `phugoid`: eq (8)'s quantities;
/// - `verdict` (`meets`, `fails` or `divergent`: every root judged, never
///   `meets` where a mode grows) and `verdict_reasons`; `criteria`: the §8
///   one-cycle standard on the short period alone (`criteria["verdict"]`),
///   eq (41)'s m_θ̇max, the short-period approximation of §8–9 and the
///   MIL-F-8785C levels;
/// - `classical`: the report's own eq (7) against the exact roots;
/// - `warnings`, `derivatives`, `tau_s`, `notation`, and `to_dict()` (the
///   `--json`, whose keys the attributes read).
#[pyclass(frozen, module = "delta_stability")]
pub struct Quartic {
    file: DerivativeFile,
    analysis: stability_core::analysis::Analysis,
    json: Value,
    /// The linear model `state_space()` exports (on demand).
    model: LinearModel,
}

#[pymethods]
impl Quartic {
    /// [A, B, C, D, E] (eq 5).
    #[getter]
    fn coefficients<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        coefficients(py, &self.analysis)
    }
    /// {"discriminant": R, "stable": bool, "marginal": bool} (§4).
    #[getter]
    fn routh<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        view_to_py(py, &self.analysis.routh)
    }
    /// The four roots (1/τ), complex.
    #[getter]
    fn roots<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<Complex64>> {
        roots(py, &self.analysis)
    }
    /// The four roots in 1/s (`roots` over τ), where τ is known; else None.
    #[getter]
    fn roots_s<'py>(&self, py: Python<'py>) -> Option<Bound<'py, PyArray1<Complex64>>> {
        engineering::roots_s(py, &self.analysis.roots, self.file.tau())
    }
    /// The linear model ẋ = A x + B δ, y = C x + D δ of eqs (2)–(3), as
    /// `quartic --state-space` exports it: a dict of its JSON's keys, `A`,
    /// `B`, `C`, `D` as 2-D arrays (`B`, `D` None without a `[control]`),
    /// in seconds where τ is known (`time_unit`), with the states', inputs'
    /// and outputs' names and units, `eigenvalues` and the python-control
    /// and MATLAB scripts' text (`python_control`, `matlab`).
    fn state_space<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let (file, a) = (&self.file, &self.analysis);
        let json = engineering::export(&file.path, "quartic", &self.model, file.tau(), a.roots)?;
        engineering::state_space(py, &json)
    }
    /// The modes, fastest first.
    #[getter]
    fn modes<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        modes(py, &self.analysis.modes, self.file.tau())
    }
    /// The short-period oscillation, if the faster pair oscillates.
    #[getter]
    fn short_period<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, Mode>>> {
        named_mode(py, &self.analysis, self.file.tau(), true)
    }
    /// The phugoid, if the slower pair oscillates.
    #[getter]
    fn phugoid<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, Mode>>> {
        named_mode(py, &self.analysis, self.file.tau(), false)
    }
    /// The derivative set, in the report's notation.
    #[getter]
    fn derivatives(&self) -> Derivatives {
        Derivatives(self.file.derivatives)
    }
    fn __getattr__<'py>(&self, py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyAny>> {
        getattr(py, "Quartic", &self.json, QUARTIC_ATTRS, name)
    }
    fn __dir__(&self) -> Vec<&'static str> {
        let mut own = OWN[..8].to_vec();
        own.extend(["roots_s", "state_space"]);
        dir(QUARTIC_ATTRS, &own)
    }
    /// Everything, as `delta-stability quartic FILE --json` prints it
    /// (`file` is the path, or "<dict>").
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_py(py, &self.json)
    }
    fn __repr__(&self) -> String {
        repr("Quartic", &self.analysis)
    }
}

/// `Quartic(stable=True, verdict=meets, short_period=…)`.
fn repr(class: &str, a: &stability_core::analysis::Analysis) -> String {
    let sp = a
        .modes
        .short_period()
        .map(|m| format!(", short_period={:?}{:+?}j", m.re, m.im))
        .unwrap_or_default();
    let stable = if a.routh.stable { "True" } else { "False" };
    format!(
        "{class}(stable={stable}, verdict={}{sp})",
        a.verdict.as_str()
    )
}

/// The stability quartic of a derivative set (eqs 4–6), its roots, modes
/// (eqs 7–8), Routh's test (§4) and the §8 criteria: what
/// `delta-stability quartic FILE` computes.
///
/// The derivative set is a path to a TOML file, a dict of the same shape
/// or a flat one, a Derivatives, or keyword arguments — in any notation:
/// `quartic(notation="american", C_xu=…, …, C_W0=…, mass=…, I_y=…, …)`
/// (`notations()` lists them; the names are the TOML files'). Raises
/// InputError (a ValueError) with the command line's message, naming the
/// file (or "<dict>"), line and field.
#[pyfunction]
#[pyo3(signature = (source=None, /, *, notation=None, class_=None, **kwargs))]
pub fn quartic(
    py: Python<'_>,
    source: Option<&Bound<'_, PyAny>>,
    notation: Option<&str>,
    class_: Option<&str>,
    kwargs: Option<&Bound<'_, PyDict>>,
) -> PyResult<Quartic> {
    guard(|| {
        let file = derivative_file(source, notation, kwargs)?;
        let class = engineering::class(class_)?;
        let control = engineering::control(&file.path)?;
        let (analysis, json, model) = py
            .detach(|| -> Result<_, _> {
                let (a, engineering) = file.evaluated(control.as_ref(), class)?;
                let json = serde_json::to_value(QuarticJson::new(&file, &a, &engineering));
                Ok((a, json, engineering.model))
            })
            .map_err(|e| input_error(&e))?;
        let json = json.map_err(|e| PyTypeError::new_err(e.to_string()))?;
        Ok(Quartic {
            file,
            analysis,
            json,
            model,
        })
    })
}

/// A design point's analysis: `delta-stability analyze CONFIG`'s result.
///
/// - `derivatives`: the derivative set of §5–7 (eqs 9–31 and the damping
///   theory's);
/// - `coefficients`, `routh`, `stable`, `roots`, `modes`, `short_period`,
///   `phugoid`, `verdict`, `criteria` (with the §9 margins, eq 42),
///   `classical`: as for `Quartic`;
/// - `aerodynamics`: the coefficients of §6 (∂C_L/∂α, C_D0, K, H₀ and
///   their Mach derivatives); `damping`: the theory, its equations and
///   z_θ̇, m_θ̇ (§7), with the frequency iteration of a frequency-dependent
///   theory; `case`: the planform's sizes and the flight condition;
/// - with a physical flight condition (`[flight] altitude`, `mass`, `I_y`):
///   `flight` (ρ, a, V = M·a, μ₁ = m/(½ρSc̄), i_B, C_L·M² of eq 24, τ) and
///   `tau_s`, and the modes in seconds too;
/// - the engineer's outputs: `mode_shapes` (each mode's eigenvector of the
///   linear model of eqs 2–3, θ = 1), `damp` (the modes in seconds, as
///   MATLAB's `damp`) and `short_period_frequency` (MIL-F-8785C's ω_sp
///   against n/α, the CAP and the levels) when τ is known;
/// - `warnings`: validity limits approached; `to_dict()`: the `--json`,
///   whose keys the attributes read.
#[pyclass(frozen, module = "delta_stability")]
pub struct Analysis {
    result: CaseResult,
    /// τ = m/(½ρSV) (s) at a physical flight condition.
    tau: Option<f64>,
    json: Value,
    /// The linear model `state_space()` exports (on demand), and the
    /// config's path.
    model: (LinearModel, String),
    /// `--write-derivatives`' file, and the config's path when it is a file.
    derivative_file: (String, Option<PathBuf>),
}

#[pymethods]
impl Analysis {
    #[getter]
    fn derivatives(&self) -> Derivatives {
        Derivatives(self.result.derivatives)
    }
    /// [A, B, C, D, E] (eq 5).
    #[getter]
    fn coefficients<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        coefficients(py, &self.result.analysis)
    }
    /// {"discriminant": R, "stable": bool, "marginal": bool} (§4).
    #[getter]
    fn routh<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        view_to_py(py, &self.result.analysis.routh)
    }
    /// The four roots (1/τ), complex.
    #[getter]
    fn roots<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<Complex64>> {
        roots(py, &self.result.analysis)
    }
    /// The four roots in 1/s (`roots` over τ) at a physical flight
    /// condition; else None.
    #[getter]
    fn roots_s<'py>(&self, py: Python<'py>) -> Option<Bound<'py, PyArray1<Complex64>>> {
        engineering::roots_s(py, &self.result.analysis.roots, self.tau)
    }
    /// The linear model of eqs (2)–(3), as `analyze --state-space` exports
    /// it (see `Quartic.state_space`).
    fn state_space<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let (model, path) = &self.model;
        let roots = self.result.analysis.roots;
        let json = engineering::export(path, "analyze", model, self.tau, roots)?;
        engineering::state_space(py, &json)
    }
    /// Writes the design point as a derivative file that `quartic()` and
    /// every command read: `analyze --write-derivatives OUT.toml`'s file
    /// (report notation, with τ where known), read back before it is
    /// written, never over the config. Raises InputError naming the path.
    fn write_derivatives(&self, path: PathBuf) -> PyResult<()> {
        let (text, config) = &self.derivative_file;
        let d = &self.result.derivatives;
        engineering::write_derivatives(&path, text, d, config.as_deref())
    }
    /// The modes, fastest first (with their times in seconds at a
    /// physical flight condition).
    #[getter]
    fn modes<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        modes(py, &self.result.analysis.modes, self.tau)
    }
    #[getter]
    fn short_period<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, Mode>>> {
        named_mode(py, &self.result.analysis, self.tau, true)
    }
    #[getter]
    fn phugoid<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, Mode>>> {
        named_mode(py, &self.result.analysis, self.tau, false)
    }
    /// The warnings, as the command line prints them.
    #[getter]
    fn warnings(&self) -> Vec<String> {
        self.result.warnings.iter().map(|w| w.to_string()).collect()
    }
    fn __getattr__<'py>(&self, py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyAny>> {
        getattr(py, "Analysis", &self.json, DESIGN_POINT_ATTRS, name)
    }
    fn __dir__(&self) -> Vec<&'static str> {
        let mut own = OWN[..8].to_vec();
        own.extend(["warnings", "roots_s", "state_space", "write_derivatives"]);
        dir(DESIGN_POINT_ATTRS, &own)
    }
    /// Everything, as `delta-stability analyze CONFIG --json` prints it.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_py(py, &self.json)
    }
    fn __repr__(&self) -> String {
        repr("Analysis", &self.result.analysis)
    }
}

/// A design point — a planform at a flight condition with a damping model —
/// through the note's method: aerodynamic coefficients (§6), stiffness
/// derivatives (eqs 9–14, 25–29), damping derivatives of a §7 theory, the
/// quartic (eqs 4–6), modes (eq 8), Routh (§4), the §8 standard and the §9
/// margins: what `delta-stability analyze CONFIG` computes.
///
/// `config` is a path to a TOML file (examples/delta-45.toml) or a dict of
/// the same shape: {"planform": {"sweep": 45, "taper": 0, "root_chord": 10},
/// "flight": {"mach": 0.9, "cg": 0.25, "mu1": 50, "i_b": 0.08, "cl_m2":
/// 0.05}, "model": {"damping": "faired"}}; its flight condition may be
/// physical instead (`units`, `altitude`, `mass`, `I_y`: μ₁, i_B and C_L·M²
/// of eq 24 from them, and the modes in seconds). The keywords override
/// the config as the command line's flags do: `mach` (--mach), `cg` (h,
/// --cg), `damping` (--damping: `damping_models()`), `aero` (--aero:
/// `default` or `lifting-surface`, the doublet lattice's ∂C_L/∂α and H₀ with
/// their exact Mach derivatives for eqs 25–29, M < 1) and `omega_bar`
/// (--omega-bar: a frequency-dependent theory, eqs 39–40 or the lattice's,
/// at ω̄ = W instead of iterated to the short period's s/μ₁) and `datcom`
/// (--datcom: a Digital DATCOM output's tables, docs/tables.md), and
/// `frequency_method` (--frequency-method: `p`, the default, each root with
/// the air forces at its own complex frequency; `p-k`; `k`, the derivatives
/// at the short period's ω̄ in the quartic). Raises
/// InputError with the command line's message.
#[pyfunction]
#[pyo3(signature = (config, /, *, mach=None, cg=None, damping=None, aero=None, omega_bar=None, datcom=None, frequency_method=None, class_=None))]
#[allow(clippy::too_many_arguments)]
pub fn analyze(
    py: Python<'_>,
    config: &Bound<'_, PyAny>,
    mach: Option<f64>,
    cg: Option<f64>,
    damping: Option<&str>,
    aero: Option<&str>,
    omega_bar: Option<f64>,
    datcom: Option<&str>,
    frequency_method: Option<&str>,
    class_: Option<&str>,
) -> PyResult<Analysis> {
    guard(|| {
        let model = Model {
            damping,
            aero,
            omega_bar,
            datcom,
            frequency_method,
        };
        let cfg = overridden(config, mach, cg, model)?;
        let class = engineering::class(class_)?;
        let (r, json) = py
            .detach(|| -> Result<_, stability_io::Failure> {
                let r = results(&cfg, class)?;
                let json = serde_json::to_value(AnalyzeJson::new(&cfg, &r));
                Ok((r, json))
            })
            .map_err(failure)?;
        let json = json.map_err(|e| PyTypeError::new_err(e.to_string()))?;
        let tau = r.tau();
        let made_by = format!("delta_stability.analyze({})", cfg.path);
        let text = stability_io::design_point::derivative_text(&cfg, &r, &made_by);
        let file = Path::new(&cfg.path);
        let config = file.is_file().then(|| file.to_path_buf());
        Ok(Analysis {
            result: r.result,
            tau,
            json,
            model: (r.engineering.model, cfg.path.clone()),
            derivative_file: (text, config),
        })
    })
}
