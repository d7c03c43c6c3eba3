//! The reader for AVL's stability-derivative output: `st_file` names the
//! `.st` file (relative to the derivative file), `[dimensional]` gives what
//! AVL does not (mass, I_y, rho; V for seconds). The derivatives come from
//! the `.st` file alone, so a `[derivatives]`, `[flight]`, `[report]` or
//! `[parameters]` table beside it is an error, not silently ignored.

use super::dimensional::{Dims, Given};
use super::raw::{Ctx, RawFile, Table};
use super::rows::{C_D, I_B, MU};
use super::{Origin, Reading};
use crate::Failure;
use crate::diag::InputError;
use stability_core::Derivatives;
use stability_core::analysis::Dimensional;
use stability_core::data::notation::avl::{self as st, AvlError, StFile};
use stability_core::data::notation::{N_ROWS, report_values, tables};
use stability_core::numerics::display::Num;
use std::path::Path;

/// The notation AVL's output is read in (`st_file`), never written.
pub const AVL: &str = "avl";

pub fn read(cx: &Ctx<'_>, raw: &RawFile, dims: &Dims) -> Result<Reading, Failure> {
    let Some(st_rel) = &raw.st_file else {
        return Err(cx
            .err(
                raw.notation.span(),
                "st_file",
                "the avl notation needs `st_file = \"case.st\"`, AVL's ST output (relative to this file)",
            )
            .into());
    };
    no_stray_tables(cx, raw)?;
    let named_at = cx.err(st_rel.span(), "st_file", "");
    let st_path = Path::new(cx.path)
        .parent()
        .unwrap_or(Path::new("."))
        .join(st_rel.get_ref());
    let shown = st_path.display().to_string();
    let st_text = crate::files::read_input(&st_path).map_err(|f| match f {
        Failure::Io(e) => Failure::Io(e.named_at(&named_at)),
        other => other,
    })?;
    let st = st::parse_st(&st_text).map_err(|e| st_error(&shown, &st_text, &e))?;
    check_st(&shown, &st_text, &st)?;
    let origin = Origin {
        span: st_rel.span(),
        field: "st_file".into(),
    };
    reading(cx, dims, &st, origin).map_err(Failure::from)
}

/// The tables only the notations of the specs have.
fn no_stray_tables(cx: &Ctx<'_>, raw: &RawFile) -> Result<(), InputError> {
    for (name, t) in [
        ("derivatives", &raw.derivatives),
        ("flight", &raw.flight),
        ("report", &raw.report),
        ("parameters", &raw.parameters),
    ] {
        let Some(t) = t else { continue };
        let first = t.get_ref().keys().min_by_key(|k| k.span().start);
        let (span, field) = match first {
            Some(k) => (
                k.span(),
                format!("[{name}] {}", crate::diag::quote(k.get_ref())),
            ),
            None => (Table::span(t), format!("[{name}]")),
        };
        return Err(cx.err(
            span,
            field,
            format!(
                "notation `avl` takes every derivative and flight quantity from `st_file` (mass, I_y, rho and V from [dimensional]): a [{name}] table would be ignored; remove it, or convert the file first"
            ),
        ));
    }
    Ok(())
}

/// AVL's error, at its line of the `.st` file.
fn st_error(shown: &str, text: &str, e: &AvlError) -> InputError {
    // an empty file's error is at its first line
    let line = e.line().max(1);
    let message = e.to_string();
    let message = message
        .strip_prefix(&format!("line {line}: "))
        .unwrap_or(&message)
        .to_string();
    InputError::at_line(shown, text, line, message)
}

/// The line of the `.st` file where `name =` is first written.
fn line_of(text: &str, name: &str) -> usize {
    text.lines()
        .position(|l| {
            l.split('=')
                .any(|part| part.split_whitespace().last() == Some(name))
        })
        .map_or(0, |i| i + 1)
}

/// Every number finite, and the reference area and chord positive.
fn check_st(shown: &str, text: &str, s: &StFile) -> Result<(), InputError> {
    let values = [
        ("Sref", s.sref),
        ("Cref", s.cref),
        ("Bref", s.bref),
        ("Alpha", s.alpha_deg),
        ("Mach", s.mach),
        ("CLtot", s.cl),
        ("CDtot", s.cd),
        ("Cmtot", s.cm),
        ("CLa", s.cl_a),
        ("Cma", s.cm_a),
        ("CLq", s.cl_q),
        ("Cmq", s.cm_q),
    ];
    let optional = [("CDind", s.cd_ind), ("e", s.e), ("Xnp", s.xnp)];
    let all = values
        .into_iter()
        .chain(optional.into_iter().filter_map(|(n, v)| v.map(|v| (n, v))));
    for (name, v) in all {
        let positive = matches!(name, "Sref" | "Cref");
        let bad = if !v.is_finite() {
            "is not a finite number"
        } else if positive && v <= 0.0 {
            "must be positive: μ₁ = m/(½ρ Sref Cref) and i_B = I_y/(m Cref²) need it"
        } else {
            continue;
        };
        let mut e = InputError::at_line(
            shown,
            text,
            line_of(text, name),
            format!("{} {bad}", Num(v)),
        );
        e.field = name.into();
        return Err(e);
    }
    Ok(())
}

fn origin_of(g: &Given) -> Option<Origin> {
    Some(Origin {
        span: g.span.clone(),
        field: g.field.into(),
    })
}

fn reading(cx: &Ctx<'_>, dims: &Dims, st: &StFile, origin: Origin) -> Result<Reading, InputError> {
    let mass = dims.need(cx, &dims.mass, "mass", "AVL's output has no mass (kg)")?;
    let rho = dims.need(
        cx,
        &dims.rho,
        "rho",
        "AVL's output has no air density (kg/m³)",
    )?;
    let iy = dims.need(
        cx,
        &dims.i_y,
        "I_y",
        "AVL's output has no pitching inertia (kg·m²)",
    )?;
    for (given, from_st, name) in [(&dims.s, st.sref, "Sref"), (&dims.chord, st.cref, "Cref")] {
        if let Some(g) = given
            && (g.value - from_st).abs() > 1e-6 * from_st
        {
            return Err(cx.err(
                g.span.clone(),
                g.field,
                format!(
                    "notation `avl` takes this from the .st file's {name} = {}; remove it or make it agree",
                    Num(from_st)
                ),
            ));
        }
    }
    let r = st::to_report(st);
    let d = Derivatives {
        x_u: r.x_u,
        x_w: r.x_w,
        x_wdot: 0.0,
        x_q: 0.0,
        z_u: r.z_u,
        z_w: r.z_w,
        z_wdot: 0.0,
        z_q: r.z_q,
        m_u: r.m_u,
        m_w: r.m_w,
        m_wdot: 0.0,
        m_q: r.m_q,
        c_l: r.c_l,
        mu1: mass.value / (0.5 * rho.value * st.sref * st.cref),
        i_b: iy.value / (mass.value * st.cref * st.cref),
    };
    let mut report = report_values(&d);
    report[C_D] = Some(st.cd);
    let mut origins: [Option<Origin>; N_ROWS] =
        std::array::from_fn(|i| report[i].map(|_| origin.clone()));
    origins[MU] = origin_of(mass);
    origins[I_B] = origin_of(iy);
    let dimensional = dims.v.as_ref().map(|v| Dimensional {
        v: v.value,
        rho: rho.value,
        s: st.sref,
        chord: st.cref,
        mass: mass.value,
    });
    Ok(Reading {
        report,
        origins,
        parameters: [1.0; tables::PARAMETERS.len()],
        dimensional,
        warnings: r
            .notes
            .iter()
            .map(|n| format!("{}: {n}", cx.path))
            .collect(),
        form: AVL,
    })
}
