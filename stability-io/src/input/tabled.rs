//! The reader for the notations of `stability-core/specs/notation.toml`
//! (report, garner, ribner, lehrian, duncan, perkins, american): each
//! quantity under the notation's own name in `[derivatives]` or `[flight]`,
//! quantities the notation lacks in `[report]`, its parameters in
//! `[parameters]`. Nothing is silently defaulted or dropped: an unknown
//! name is an error with the nearest valid one, a name given twice is an
//! error, and the one default (American notation's C_xalphadot, C_xq = 0)
//! is announced.

use super::dimensional::Dims;
use super::raw::{Ctx, RawFile, Table};
use super::rows::{C_D, DERIVATIVES, FLIGHT, I_B, MU, QUARTIC, X_Q, X_WDOT};
use super::suggest::did_you_mean;
use super::{Origin, Reading, notations};
use crate::diag::{InputError, quote};
use stability_core::data::notation::{N_ROWS, Notation, NotationError, Parameters, Values, tables};
use stability_core::numerics::display::Num;

/// Rows a notation may leave out, taken as 0, with the reason given in the
/// warning that says so.
const OPTIONAL: &[(&str, &[usize], &str)] = &[
    (
        "american",
        &[X_WDOT, X_Q],
        "Etkin & Reid's tables neglect them",
    ),
    (
        AMERICAN_CL,
        &[X_WDOT, X_Q],
        "the drag's α̇ and q derivatives are usually neglected",
    ),
];

/// Rows a notation needs beyond the quartic's, and why.
const NEEDED: &[(&str, usize, &str)] = &[(
    AMERICAN_CL,
    C_D,
    "the C_L/C_D form needs the trim drag coefficient: X_u = −½ρVS(C_Du + 2C_D), Z_w = −½ρVS(C_Lα + C_D)",
)];

/// The rows notation `to` needs beyond the quartic's (the C_L/C_D form's
/// C_D).
pub fn needed_rows(to: Notation) -> impl Iterator<Item = usize> {
    NEEDED
        .iter()
        .filter(move |(n, _, _)| *n == to.name())
        .map(|&(_, row, _)| row)
}

/// The C_L/C_D form of American notation
/// (`stability-core/specs/notation.toml`), which a file with
/// `notation = "american"` may be written in.
pub const AMERICAN_CL: &str = "american_cl";

/// A notation's values as read, and where each was written.
struct Own {
    values: Values,
    origins: [Option<Origin>; N_ROWS],
}

pub fn read(cx: &Ctx<'_>, raw: &RawFile, dims: &Dims) -> Result<Reading, InputError> {
    let name = raw.notation.get_ref();
    let Some(notation) = Notation::named(name) else {
        return Err(cx.err(
            raw.notation.span(),
            "notation",
            format!(
                "unknown notation `{}`{}; the notations are: {}",
                quote(name),
                did_you_mean(name, notations()),
                notations().join(", ")
            ),
        ));
    };
    if let Some(st) = &raw.st_file {
        return Err(cx.err(
            st.span(),
            "st_file",
            "`st_file` belongs to notation = \"avl\"",
        ));
    }
    let notation = american_form(cx, raw, notation)?;
    let parameters = parameters(cx, raw, notation)?;
    let mut own = own_values(cx, raw, notation)?;
    let mut warnings = Vec::new();
    required(cx, raw, notation, &mut own, &mut warnings)?;
    let extra = report_table(cx, &raw.report, notation, &own)?;
    let mut report = notation
        .to_report(&own.values, &parameters)
        .map_err(|e| conversion_error(cx, raw, notation, &own, &e))?;
    let mut origins = own.origins;
    for i in 0..N_ROWS {
        if report[i].is_none() && extra.values[i].is_some() {
            report[i] = extra.values[i];
            origins[i] = extra.origins[i].clone();
        }
    }
    from_dimensional(dims, &mut report, &mut origins);
    Ok(Reading {
        report,
        origins,
        parameters,
        dimensional: dims.dimensional(),
        warnings,
        form: notation.name(),
    })
}

/// The form a `notation = "american"` file is written in: Etkin's C_x/C_z
/// form, or the C_L/C_D form ([`AMERICAN_CL`]) when its names are the
/// C_L/C_D form's; a file mixing the two is an error.
fn american_form(cx: &Ctx<'_>, raw: &RawFile, notation: Notation) -> Result<Notation, InputError> {
    let Some(cl) = Notation::named(AMERICAN_CL) else {
        return Ok(notation);
    };
    if notation.name() != "american" {
        return Ok(notation);
    }
    let own = |n: Notation, key: &str| n.names().contains(&Some(key));
    let mut first: [Option<(&str, std::ops::Range<usize>)>; 2] = [None, None];
    for t in [&raw.derivatives, &raw.flight].into_iter().flatten() {
        for k in t.get_ref().keys() {
            let key = k.get_ref().as_str();
            for (slot, n, other) in [(0, notation, cl), (1, cl, notation)] {
                if own(n, key) && !own(other, key) && first[slot].is_none() {
                    first[slot] = Some((key, k.span()));
                }
            }
        }
    }
    match first {
        [Some((cx_name, _)), Some((cl_name, span))] => Err(cx.err(
            span,
            format!("[derivatives] {cl_name}"),
            format!(
                "`{cl_name}` is of the C_L/C_D form and `{cx_name}` of the C_x/C_z form of American notation: write the set in one form (the C_L/C_D form: {})",
                cl.names().iter().flatten().copied().collect::<Vec<_>>().join(", ")
            ),
        )),
        [None, Some(_)] => Ok(cl),
        _ => Ok(notation),
    }
}

/// Whether the notation's conversion uses parameter `k` (found by
/// converting with two values of it, not from a list kept here).
pub fn uses_parameter(notation: Notation, k: usize) -> bool {
    let ones: Values = [Some(1.0); N_ROWS];
    let mut p: Parameters = [1.0; tables::PARAMETERS.len()];
    let a = notation.to_report(&ones, &p).ok();
    p[k] = 2.0;
    a != notation.to_report(&ones, &p).ok()
}

/// A conversion's error at the value it arose from: an overflow is named
/// by its report quantity, a value that is not finite by the notation's.
fn conversion_error(
    cx: &Ctx<'_>,
    raw: &RawFile,
    notation: Notation,
    own: &Own,
    e: &NotationError,
) -> InputError {
    let row = match e {
        NotationError::Overflow { quantity, .. } => Notation::REPORT.row_of(quantity),
        NotationError::NonFiniteInput { quantity, .. } => notation.row_of(quantity),
    }
    .or_else(|| match e {
        NotationError::Overflow { quantity, .. }
        | NotationError::NonFiniteInput { quantity, .. } => {
            tables::ROWS.iter().position(|r| r == quantity)
        }
    });
    match row.and_then(|i| own.origins[i].as_ref()) {
        Some(o) => cx.err(o.span.clone(), o.field.clone(), e.to_string()),
        None => cx.err(raw.notation.span(), "notation", e.to_string()),
    }
}

fn parameters(cx: &Ctx<'_>, raw: &RawFile, notation: Notation) -> Result<Parameters, InputError> {
    let mut out: Parameters = [1.0; tables::PARAMETERS.len()];
    let mut given = [false; tables::PARAMETERS.len()];
    for (k, v) in cx.entries("parameters", &raw.parameters)? {
        let field = format!("[parameters] {}", quote(k.get_ref()));
        let Some(i) = tables::PARAMETERS.iter().position(|p| *p == k.get_ref()) else {
            return Err(cx.err(
                k.span(),
                field,
                format!(
                    "unknown parameter{}; the parameters are: {}",
                    did_you_mean(k.get_ref(), tables::PARAMETERS),
                    tables::PARAMETERS.join(", ")
                ),
            ));
        };
        if !uses_parameter(notation, i) {
            return Err(cx.err(
                k.span(),
                field,
                format!("notation `{}` does not use this parameter", notation.name()),
            ));
        }
        let x = *v.get_ref();
        if x <= 0.0 {
            return Err(cx.err(v.span(), field, format!("must be positive, not {}", Num(x))));
        }
        (out[i], given[i]) = (x, true);
    }
    for (i, p) in tables::PARAMETERS.iter().enumerate() {
        if uses_parameter(notation, i) && !given[i] {
            return Err(cx.err(
                raw.notation.span(),
                format!("[parameters] {p}"),
                format!(
                    "notation `{}` is referred to a tail arm: give [parameters] {p} = l_t/c̄",
                    notation.name()
                ),
            ));
        }
    }
    Ok(out)
}

/// The notation's names for the rows of one table (`[derivatives]` or
/// `[flight]`).
fn names_for(notation: Notation, rows: &[usize]) -> Vec<(usize, &'static str)> {
    let names = notation.names();
    rows.iter()
        .filter_map(|&i| names[i].map(|n| (i, n)))
        .collect()
}

fn own_values(cx: &Ctx<'_>, raw: &RawFile, notation: Notation) -> Result<Own, InputError> {
    let mut own = Own {
        values: [None; N_ROWS],
        origins: std::array::from_fn(|_| None),
    };
    for (table, rows, t) in [
        ("derivatives", &DERIVATIVES[..], &raw.derivatives),
        ("flight", &FLIGHT[..], &raw.flight),
    ] {
        let ok = names_for(notation, rows);
        for (k, v) in cx.entries(table, t)? {
            let field = format!("[{table}] {}", quote(k.get_ref()));
            let Some(&(i, _)) = ok.iter().find(|(_, n)| *n == k.get_ref()) else {
                return Err(cx.err(k.span(), field, unknown(notation, table, k.get_ref())));
            };
            own.values[i] = Some(*v.get_ref());
            own.origins[i] = Some(Origin {
                span: v.span(),
                field,
            });
        }
    }
    Ok(own)
}

/// The message for a name that is not one of the table's in the notation.
fn unknown(notation: Notation, table: &str, key: &str) -> String {
    let (rows, other, what) = if table == "flight" {
        (
            &FLIGHT[..],
            ("derivatives", &DERIVATIVES[..]),
            "flight quantities",
        )
    } else {
        (&DERIVATIVES[..], ("flight", &FLIGHT[..]), "derivatives")
    };
    let listed: Vec<&str> = names_for(notation, rows).iter().map(|(_, n)| *n).collect();
    if names_for(notation, other.1).iter().any(|(_, n)| *n == key) {
        return format!(
            "unknown field `{key}` in [{table}]: it belongs in [{}]",
            other.0
        );
    }
    if let Some(theirs) = notation_of(key, notation) {
        return format!(
            "`{}` is a quantity of {theirs}, not of notation `{}`, whose {what} are: {} (`convert --help` lists the notations)",
            quote(key),
            notation.name(),
            listed.join(", ")
        );
    }
    format!(
        "unknown field `{}`{}: the {what} of notation `{}` are: {}",
        quote(key),
        did_you_mean(key, listed.iter().copied()),
        notation.name(),
        listed.join(", ")
    )
}

/// Every quartic row the notation names must be given (or be one of its
/// announced optional rows).
fn required(
    cx: &Ctx<'_>,
    raw: &RawFile,
    notation: Notation,
    own: &mut Own,
    warnings: &mut Vec<String>,
) -> Result<(), InputError> {
    let names = notation.names();
    let optional = OPTIONAL.iter().find(|(n, _, _)| *n == notation.name());
    let mut defaulted = Vec::new();
    for i in QUARTIC {
        let (Some(n), None) = (names[i], own.values[i]) else {
            continue;
        };
        if let Some((_, rows, _)) = optional
            && rows.contains(&i)
        {
            own.values[i] = Some(0.0);
            defaulted.push(n);
            continue;
        }
        let (table, t) = if DERIVATIVES.contains(&i) {
            ("derivatives", &raw.derivatives)
        } else {
            ("flight", &raw.flight)
        };
        let span = t.as_ref().map_or(raw.notation.span(), Table::span);
        return Err(cx.err(
            span,
            format!("[{table}] {n}"),
            format!("missing field `{n}` (notation `{}`)", notation.name()),
        ));
    }
    for &(_, row, why) in NEEDED.iter().filter(|(n, _, _)| *n == notation.name()) {
        if own.values[row].is_none() {
            let n = names[row].unwrap_or(tables::ROWS[row]);
            let span = raw.flight.as_ref().map_or(raw.notation.span(), Table::span);
            return Err(cx.err(
                span,
                format!("[flight] {n}"),
                format!("missing field `{n}`: {why}"),
            ));
        }
    }
    if let (Some((_, _, why)), false) = (optional, defaulted.is_empty()) {
        warnings.push(format!(
            "{}: {} not given: taken as 0 ({why})",
            cx.path,
            defaulted.join(" and ")
        ));
    }
    Ok(())
}

/// The `[report]` table: quantities in the report's names that the
/// notation does not define (and that no other table gives).
fn report_table(
    cx: &Ctx<'_>,
    t: &Option<Table>,
    notation: Notation,
    own: &Own,
) -> Result<Own, InputError> {
    let mut extra = Own {
        values: [None; N_ROWS],
        origins: std::array::from_fn(|_| None),
    };
    let report_names = Notation::REPORT.names();
    for (k, v) in cx.entries("report", t)? {
        let field = format!("[report] {}", quote(k.get_ref()));
        let key = k.get_ref().as_str();
        let Some(i) = report_names.iter().position(|n| *n == Some(key)) else {
            let hint = did_you_mean(key, report_names.iter().flatten().copied());
            return Err(cx.err(
                k.span(),
                field,
                format!("not a quantity of the report's notation{hint}"),
            ));
        };
        // a quantity of [derivatives] or [flight] belongs there; the others
        // (τ, c_m, …) have no table but this one
        let in_tables = DERIVATIVES.contains(&i) || FLIGHT.contains(&i);
        if let (Some(theirs), true) = (notation.names()[i], in_tables) {
            let table = if FLIGHT.contains(&i) {
                "flight"
            } else {
                "derivatives"
            };
            let given = if own.values[i].is_some() {
                " (and it does)"
            } else {
                ""
            };
            return Err(cx.err(
                k.span(),
                field,
                format!(
                    "notation `{}` has this quantity: give it as `{theirs}` in [{table}]{given}",
                    notation.name()
                ),
            ));
        }
        extra.values[i] = Some(*v.get_ref());
        extra.origins[i] = Some(Origin {
            span: v.span(),
            field,
        });
    }
    Ok(extra)
}

/// μ₁ and i_B from `[dimensional]` where the notation gives none.
fn from_dimensional(dims: &Dims, report: &mut Values, origins: &mut [Option<Origin>; N_ROWS]) {
    for (row, derived) in [(MU, dims.mu1()), (I_B, dims.i_b())] {
        if report[row].is_none()
            && let Some((value, from)) = derived
        {
            report[row] = Some(value);
            origins[row] = Some(Origin {
                span: from.span.clone(),
                field: from.field.to_string(),
            });
        }
    }
}

/// The notation (other than `ours`) a name belongs to, in words: a
/// dimensional set's `X_u`, `U0` …, or another table's name.
fn notation_of(key: &str, ours: Notation) -> Option<String> {
    use stability_core::data::dimensional::DimensionalDerivatives;
    if DimensionalDerivatives::NAMES.contains(&key) || ["U0", "W0", "theta0"].contains(&key) {
        return Some(
            "notation = \"dimensional\" (derivatives per unit mass and inertia, as CR-2144 prints them)"
                .into(),
        );
    }
    let n = Notation::all().find(|n| *n != ours && n.names().contains(&Some(key)))?;
    Some(match n.name() {
        AMERICAN_CL => "notation = \"american\" in its C_L/C_D form".into(),
        name => format!("notation `{name}`"),
    })
}
