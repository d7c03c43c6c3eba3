//! The §7 damping theories and the subsonic lifting surface, on their own:
//! `damping_derivatives(theory, …)` and `lifting_surface(…)`.

use crate::errors::argument;
use crate::guard;
use crate::json::view_to_py;
use numpy::IntoPyArray;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use pyo3::types::PyList;
use stability_core::aerodynamics::damping::{
    Theory, WingInput, damping_derivatives as theory_derivatives,
};
use stability_core::aerodynamics::lifting_surface::{Lattice, LatticeSpec};
use stability_core::aerodynamics::models::aero::AeroModelName;
use stability_core::aerodynamics::theory::Row;
use stability_core::design::case::DampingModel;
use stability_core::geometry::{Planform, Size, Trapezoid};
use stability_io::input::suggest::did_you_mean;

/// A true or cropped delta of leading-edge sweep `sweep` (degrees) and
/// taper `taper` (its size does not enter non-dimensional results).
fn planform(sweep: f64, taper: f64) -> PyResult<Planform> {
    Planform::new(sweep.to_radians(), taper, Size::RootChord(1.0)).map_err(|e| {
        let field = match e {
            stability_core::geometry::GeometryError::Taper(_) => "taper",
            _ => "sweep",
        };
        argument(field, e)
    })
}

/// A registry row as a dict: name, equations, summary, validity,
/// supplies, source.
fn rows<'py>(
    py: Python<'py>,
    rows: impl Iterator<Item = &'static Row>,
) -> PyResult<Bound<'py, PyAny>> {
    let rows: Vec<&Row> = rows.collect();
    view_to_py(py, &rows)
}

/// The names of the §7 damping theories (`damping_derivatives`' first
/// argument; a config's [model] damping also takes the fairings, see
/// `damping_models()`). With `details=True`, each theory's row of the
/// library's registry as a dict — `name`, `equations` (the report's),
/// `summary`, `validity` (where it applies), `supplies` (what it gives the
/// derivative set) and `source` — the same text as the command line's
/// `--help`.
#[pyfunction]
#[pyo3(signature = (*, details=false))]
pub fn theories(py: Python<'_>, details: bool) -> PyResult<Bound<'_, PyAny>> {
    if details {
        return rows(py, Theory::ALL.iter().map(|t| t.row()));
    }
    Ok(PyList::new(py, Theory::ALL.map(Theory::name))?.into_any())
}

/// The damping models a config or `analyze(…, damping=…)` takes: the
/// fairings (`faired`, the default: one lifting surface at the short
/// period's ω̄ through M = 1; `faired-theories`, the note's fairing of its
/// §7 theories as Figs 19–24; `faired-slender`) and the theories. With
/// `details=True`, each model's registry row as a dict (see `theories`).
#[pyfunction]
#[pyo3(signature = (*, details=false))]
pub fn damping_models(py: Python<'_>, details: bool) -> PyResult<Bound<'_, PyAny>> {
    if details {
        return rows(py, DampingModel::ALL.iter().map(|m| m.row()));
    }
    Ok(PyList::new(py, DampingModel::ALL.map(DampingModel::name))?.into_any())
}

/// The aerodynamic models `analyze(…, aero=…)` takes (the lift slope and
/// aerodynamic centre of eqs 25–29). With `details=True`, each model's
/// registry row as a dict (see `theories`).
#[pyfunction]
#[pyo3(signature = (*, details=false))]
pub fn aero_models(py: Python<'_>, details: bool) -> PyResult<Bound<'_, PyAny>> {
    if details {
        return rows(py, AeroModelName::ALL.iter().map(|m| m.row()));
    }
    Ok(PyList::new(py, AeroModelName::ALL.map(AeroModelName::name))?.into_any())
}

/// The damping derivatives of one §7 theory for a delta wing of
/// leading-edge sweep `sweep` (degrees) and taper `taper`, at c.g. `cg`
/// (h, fraction of the M.A.C. aft of its leading edge) and Mach number
/// `mach`, in the report's notation (§3). `theory` is one of `theories()`;
/// `theories(details=True)` gives each one's equations, validity and what
/// it supplies (the library's registry, as `--help` prints it).
///
/// Returns a dict: theory, equations, z_q, z_wdot, m_q, m_wdot,
/// z_thetadot = z_q + z_ẇ, m_thetadot = m_q + m_ẇ, fig18 (the functions of
/// Fig 18 for the supersonic theory, else None) and warnings (validity
/// limits approached). Raises InputError outside a theory's domain, and
/// for an unknown name with the nearest valid one.
#[pyfunction]
#[pyo3(signature = (theory, *, sweep, mach, cg=0.25, taper=0.0, omega_bar=None))]
pub fn damping_derivatives<'py>(
    py: Python<'py>,
    theory: &str,
    sweep: f64,
    mach: f64,
    cg: f64,
    taper: f64,
    omega_bar: Option<f64>,
) -> PyResult<Bound<'py, PyDict>> {
    guard(|| {
        let t: Theory = theory.parse().map_err(|e| {
            let hint = did_you_mean(theory, Theory::ALL.map(Theory::name));
            argument("theory", format!("{e}{hint}"))
        })?;
        let wing = WingInput::from(&planform(sweep, taper)?);
        let d =
            theory_derivatives(t, &wing, cg, mach, omega_bar).map_err(|e| argument("theory", e))?;
        let out = PyDict::new(py);
        out.set_item("theory", t.name())?;
        out.set_item("equations", t.equations())?;
        let x = d.derivatives;
        for (k, v) in [
            ("z_q", x.z_q),
            ("z_wdot", x.z_wdot),
            ("m_q", x.m_q),
            ("m_wdot", x.m_wdot),
            ("z_thetadot", x.z_thetadot()),
            ("m_thetadot", x.m_thetadot()),
        ] {
            out.set_item(k, v)?;
        }
        out.set_item("fig18", view_to_py(py, &d.fig18)?)?;
        let warnings: Vec<String> = d.warnings.iter().map(|w| w.to_string()).collect();
        out.set_item("warnings", warnings)?;
        Ok(out)
    })
}

/// The subsonic lifting surface of a delta wing (sweep in degrees, taper)
/// in harmonic pitching and plunging at Mach number `mach` (0 ≤ M < 1) and
/// frequency parameter `omega_bar` = ωc̄/V (0: quasi-steady, exactly): the
/// doublet-lattice method (Albano & Rodden 1969, with the quartic line
/// integration of Rodden, Taylor & McIntosh 1998 and Desmarais' kernel
/// approximation), on the default lattice with Richardson's extrapolation
/// — the lifting-surface theory the note's §7 relies on (Multhopp–Garner,
/// Lehrian).
///
/// The derivatives are taken about each c.g. `cg` (h; a number or an
/// array: one solve serves every c.g., by axis transfer) with drag
/// coefficient `c_d` in z_w and m_w (eqs 12, 14, 25). Returns a dict of
/// numpy arrays, one value per c.g.: cg, lift_slope (C_Lα per rad),
/// aerodynamic_centre (H₀, fraction of the M.A.C.), z_w, m_w, z_wdot,
/// m_wdot, z_q, m_q, z_thetadot, m_thetadot (report notation, §3), and the
/// solve itself under `solution` (a dict). Linear, inviscid, flat wing: no
/// leading-edge vortex. The GIL is released during the solve.
#[pyfunction]
#[pyo3(signature = (*, sweep, mach, taper=0.0, omega_bar=0.0, cg=None, c_d=0.0))]
pub fn lifting_surface<'py>(
    py: Python<'py>,
    sweep: f64,
    mach: f64,
    taper: f64,
    omega_bar: f64,
    cg: Option<&Bound<'py, PyAny>>,
    c_d: f64,
) -> PyResult<Bound<'py, PyDict>> {
    guard(|| {
        let cgs: Vec<f64> = match cg {
            None => vec![0.25],
            Some(v) => match v.extract::<f64>() {
                Ok(x) => vec![x],
                Err(_) => {
                    let listed = if v.hasattr("tolist")? {
                        v.call_method0("tolist")?
                    } else {
                        v.clone()
                    };
                    listed
                        .extract()
                        .map_err(|_| argument("cg", "expected a number or a sequence of numbers"))?
                }
            },
        };
        let wing = Trapezoid::from(&planform(sweep, taper)?);
        let solution = py
            .detach(|| {
                let lattice = Lattice::new(&wing, LatticeSpec::for_wing(&wing))?;
                lattice.solve(mach, omega_bar)
            })
            .map_err(|e| argument("lifting_surface", e))?;
        let derivs = cgs
            .iter()
            .map(|&h| solution.derivatives(h, c_d))
            .collect::<Result<Vec<_>, _>>()
            .map_err(|e| argument("cg", e))?;
        let out = PyDict::new(py);
        out.set_item("cg", cgs.clone().into_pyarray(py))?;
        type Get =
            fn(&stability_core::aerodynamics::lifting_surface::LiftingSurfaceDerivatives) -> f64;
        let columns: [(&str, Get); 10] = [
            ("lift_slope", |d| d.lift_slope),
            ("aerodynamic_centre", |d| d.aerodynamic_centre),
            ("z_w", |d| d.z_w),
            ("m_w", |d| d.m_w),
            ("z_wdot", |d| d.z_wdot),
            ("m_wdot", |d| d.m_wdot),
            ("z_q", |d| d.z_q),
            ("m_q", |d| d.m_q),
            ("z_thetadot", |d| d.z_thetadot),
            ("m_thetadot", |d| d.m_thetadot),
        ];
        for (name, get) in columns {
            let v: Vec<f64> = derivs.iter().map(get).collect();
            out.set_item(name, v.into_pyarray(py))?;
        }
        out.set_item("solution", view_to_py(py, &solution)?)?;
        Ok(out)
    })
}
