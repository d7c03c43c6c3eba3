//! `batch_roots`: the quartic solver of `stability_core::numerics::roots` on arrays,
//! in parallel with the GIL released.

use crate::errors::argument;
use crate::guard;
use numpy::ndarray::Array2;
use numpy::{Complex64, IntoPyArray, PyArray2, PyReadonlyArray2};
use pyo3::prelude::*;
use rayon::prelude::*;
use stability_core::numerics::roots::{RootsError, solve_quartic};

/// Below this many quartics one thread solves them all.
const PARALLEL_FROM: usize = 4096;

/// The roots of each row [A, B, C, D, E] of `coefficients` (N × 5,
/// float64), as an N × 4 complex array; the first failure (row, why) when
/// `nan` is false, else NaN in the rows that have no roots.
fn solve(c: &[[f64; 5]], nan: bool) -> Result<Vec<Complex64>, (usize, RootsError)> {
    let mut out = vec![Complex64::new(f64::NAN, f64::NAN); 4 * c.len()];
    let one = |(i, (row, out)): (usize, (&[f64; 5], &mut [Complex64]))| match solve_quartic(*row) {
        Ok(r) => {
            out.copy_from_slice(&r);
            Ok(())
        }
        Err(_) if nan => Ok(()),
        Err(e) => Err((i, e)),
    };
    let rows = c.iter().zip(out.chunks_exact_mut(4)).enumerate();
    let first_failure = if c.len() < PARALLEL_FROM {
        rows.map(one).find_map(Result::err)
    } else {
        c.par_iter()
            .zip(out.par_chunks_exact_mut(4))
            .enumerate()
            .map(one)
            .filter_map(Result::err)
            .min_by_key(|(i, _)| *i)
    };
    match first_failure {
        Some(f) => Err(f),
        None => Ok(out),
    }
}

/// The four roots of each quartic Aλ⁴ + Bλ³ + Cλ² + Dλ + E (eq 5), for an
/// (N, 5) float64 array of [A, B, C, D, E] rows: an (N, 4) complex array,
/// each row by descending modulus with a complex pair adjacent (positive
/// imaginary part first). The solver of `delta-stability quartic`: exact
/// power-of-two scaling, then Ferrari's resolvent cubic with Newton
/// polishing, or the Aberth–Ehrlich iteration where the coefficients span
/// too many decades; every root's backward error is checked (≤ 1e-12).
/// Parallel for large N, the GIL released.
///
/// `errors="raise"`: InputError naming the first row without roots (A = 0,
/// a coefficient not finite, roots beyond f64's range); `errors="nan"`:
/// NaN in such rows. `delta_stability.batch_roots` takes any array of
/// shape (…, 5).
#[pyfunction]
#[pyo3(signature = (coefficients, *, nan=false))]
pub fn batch_roots<'py>(
    py: Python<'py>,
    coefficients: PyReadonlyArray2<'py, f64>,
    nan: bool,
) -> PyResult<Bound<'py, PyArray2<Complex64>>> {
    guard(|| {
        let view = coefficients.as_array();
        if view.ncols() != 5 {
            return Err(argument(
                "coefficients",
                format!(
                    "expected rows of the five coefficients [A, B, C, D, E], not {}",
                    view.ncols()
                ),
            ));
        }
        // copied while the GIL is held: no other thread can change it meanwhile
        let rows: Vec<[f64; 5]> = view
            .rows()
            .into_iter()
            .map(|r| [r[0], r[1], r[2], r[3], r[4]])
            .collect();
        let n = rows.len();
        let out = py
            .detach(|| solve(&rows, nan))
            .map_err(|(i, e)| argument("coefficients", format!("row {i} {:?}: {e}", rows[i])))?;
        let a = Array2::from_shape_vec((n, 4), out)
            .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))?;
        Ok(a.into_pyarray(py))
    })
}
