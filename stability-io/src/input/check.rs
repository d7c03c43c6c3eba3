//! What every reader's result must satisfy: the fifteen quantities of the
//! quartic present, μ₁ and i_B positive, every value finite (a conversion
//! that overflows is named at the value that caused it), and the
//! dimensional flight condition consistent with the non-dimensional one.

use super::dimensional::Dims;
use super::raw::{Ctx, RawFile};
use super::rows::{I_B, MU};
use super::{DerivativeFile, Origin, Reading};
use crate::diag::InputError;
use stability_core::Derivatives;
use stability_core::data::notation::{N_ROWS, Notation, derivatives_from_report, row, tables};
use stability_core::numerics::display::Num;

/// The error at a row's origin (or at the notation, when it has none).
fn at_origin(cx: &Ctx<'_>, raw: &RawFile, origin: &Option<Origin>, message: String) -> InputError {
    match origin {
        Some(o) => cx.err(o.span.clone(), o.field.clone(), message),
        None => cx.err(raw.notation.span(), "notation", message),
    }
}

pub fn finish(
    cx: &Ctx<'_>,
    raw: &RawFile,
    dims: &Dims,
    r: Reading,
) -> Result<DerivativeFile, InputError> {
    finite(cx, raw, &r)?;
    let d = complete(cx, raw, &r)?;
    positive(cx, raw, &r, &d)?;
    let mut warnings = r.warnings;
    warnings.extend(consistency(cx.path, dims, &d));
    let origins = r
        .origins
        .iter()
        .map(|o| {
            o.as_ref()
                .map(|o| cx.err(o.span.clone(), o.field.clone(), ""))
        })
        .collect();
    Ok(DerivativeFile {
        path: cx.path.into(),
        notation: raw.notation.get_ref().clone(),
        form: r.form,
        derivatives: d,
        report: r.report,
        parameters: r.parameters,
        dimensional: r.dimensional,
        origins,
        warnings,
    })
}

/// Every value read is finite; one that is not overflowed in the
/// conversion into the report's notation.
fn finite(cx: &Ctx<'_>, raw: &RawFile, r: &Reading) -> Result<(), InputError> {
    for i in 0..N_ROWS {
        let Some(v) = r.report[i].filter(|v| !v.is_finite()) else {
            continue;
        };
        let name = Notation::REPORT.names()[i].unwrap_or(tables::ROWS[i]);
        return Err(at_origin(
            cx,
            raw,
            &r.origins[i],
            format!(
                "in the report's notation this is {name} = {}: the conversion overflows (no derivative is this large)",
                Num(v)
            ),
        ));
    }
    Ok(())
}

/// The report's derivative set, or an error naming what is missing.
fn complete(cx: &Ctx<'_>, raw: &RawFile, r: &Reading) -> Result<Derivatives, InputError> {
    derivatives_from_report(&r.report).map_err(|missing| {
        let names: Vec<String> = missing
            .iter()
            .map(|m| {
                let n = row(m).and_then(|i| Notation::REPORT.names()[i]).unwrap_or(m);
                format!("`{n}`")
            })
            .collect();
        cx.err(
            raw.notation.span(),
            "notation",
            format!(
                "the derivative set lacks {} (in the report's names); give them in a [report] table, or μ₁ and i_B through [dimensional] (mass, rho, S, chord, I_y)",
                names.join(", ")
            ),
        )
    })
}

fn positive(cx: &Ctx<'_>, raw: &RawFile, r: &Reading, d: &Derivatives) -> Result<(), InputError> {
    for (row, v, what) in [
        (MU, d.mu1, "the relative density μ₁ = m/(½ρSc̄)"),
        (I_B, d.i_b, "the pitching inertia i_B = B/(mc̄²)"),
    ] {
        if v <= 0.0 {
            return Err(at_origin(
                cx,
                raw,
                &r.origins[row],
                format!("{what} must be positive, not {}", Num(v)),
            ));
        }
    }
    Ok(())
}

/// Warnings where `[dimensional]` disagrees with μ₁, C_L or i_B.
fn consistency(path: &str, dims: &Dims, d: &Derivatives) -> Vec<String> {
    let mut out = Vec::new();
    if let Some(dim) = dims.dimensional() {
        let mu1 = dim.mu1();
        if (mu1 - d.mu1).abs() > 0.01 * d.mu1 {
            out.push(format!(
                "{path}: the relative density is μ₁ = {} but [dimensional] gives m/(½ρSc̄) = {mu1:.4}; the quartic uses {}",
                Num(d.mu1),
                Num(d.mu1)
            ));
        }
        let c_l = dim.c_l();
        if (c_l - d.c_l).abs() > 0.01 * d.c_l.abs().max(1e-3) {
            out.push(format!(
                "{path}: the lift coefficient is {} but [dimensional] gives W/(½ρV²S) = {c_l:.4} (g = 9.80665 m/s²); the quartic uses {}",
                Num(d.c_l),
                Num(d.c_l)
            ));
        }
    }
    if let Some((i_b, _)) = dims.i_b()
        && (i_b - d.i_b).abs() > 0.01 * d.i_b
    {
        out.push(format!(
            "{path}: the pitching inertia is i_B = {} but [dimensional] gives I_y/(mc̄²) = {i_b:.4}; the quartic uses {}",
            Num(d.i_b),
            Num(d.i_b)
        ));
    }
    out
}
