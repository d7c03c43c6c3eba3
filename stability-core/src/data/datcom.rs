//! USAF Digital DATCOM's longitudinal derivatives in the report's notation:
//! the static CLA, CMA, CD and the dynamic CLQ, CMQ,
//! CLAD, CMAD at α = 0, per Mach number, about DATCOM's moment centre on
//! its reference area and length — made into the tables of
//! `[model.tables]` ([`crate::aerodynamics::models::aero::Table`], [`crate::aerodynamics::models::derivative_tables`]).
//!
//! DATCOM prints every one of them per degree, the rates per qc̄/2V and
//! α̇c̄/2V (its tables' headers, `DERIVATIVE (PER DEGREE)` and `DYNAMIC
//! DERIVATIVES (PER DEGREE)`; the wing's C_Lq = (½ + 2x̄/c̄)C_Lα of DATCOM
//! §7.1.1.1 holds with its printed per-degree C_Lα). Per radian they are
//! the NACA coefficients of Ribner and Malvestuto, the appendix's second
//! column (notation `ribner` of `specs/notation.toml`), and the appendix's
//! conversion makes them the report's: z_w = −C_Lα − C_D, m_w = C_mα,
//! z_q = −½C_Lq, m_q = ½C_mq, z_ẇ = −½C_Lα̇, m_ẇ = ½C_mα̇.
//!
//! The tables are about DATCOM's moment centre h_r = (XCG − x_apex −
//! x̄)/c̄ (x̄ the M.A.C.'s leading edge aft of the apex, §2.2); the case's
//! c.g. is reached by [`crate::aerodynamics::models::derivative_tables::transfer`]. The lift slope
//! a = C_Lα, the aerodynamic centre H₀ = h_r − C_mα/C_Lα and C_D0 = C_D
//! (α = 0) become the coefficient tables of §6, from which x_u, z_u, m_u
//! follow (eqs 9, 10, 13, 27–29).

use crate::aerodynamics::models::aero::{AeroError, AeroModel, Source, Table, TableOrigin};
use crate::aerodynamics::models::derivative_tables::{
    DerivativeTable, DerivativeTables, Mode, Outside,
};
use crate::data::notation::{Notation, NotationError, Values, row, tables::PARAMETERS};
use crate::geometry::Planform;
use crate::numerics::display::Num;

/// DATCOM's per-degree derivatives times this are per radian.
pub const PER_RADIAN: f64 = 180.0 / std::f64::consts::PI;

/// The reference dimensions DATCOM prints above each table.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reference {
    /// SREF, the reference area.
    pub area: f64,
    /// CBARR, the longitudinal reference length.
    pub length: f64,
    /// XCG, the moment centre's x in DATCOM's axes (aft positive).
    pub moment_x: f64,
}

/// One Mach number of a DATCOM output at α = 0, as printed (per degree;
/// `None` where DATCOM printed `NDM`, `NaN` or nothing).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Point {
    pub mach: f64,
    pub reference: Reference,
    pub cd: Option<f64>,
    pub cla: Option<f64>,
    pub cma: Option<f64>,
    pub clq: Option<f64>,
    pub cmq: Option<f64>,
    pub clad: Option<f64>,
    pub cmad: Option<f64>,
}

/// The names of the report's derivatives a DATCOM point gives, with the
/// DATCOM quantity each comes from (the appendix's `ribner` column).
pub const DERIVATIVES: [(&str, &str); 6] = [
    ("z_w", "CLA"),
    ("m_w", "CMA"),
    ("z_q", "CLQ"),
    ("m_q", "CMQ"),
    ("z_wdot", "CLAD"),
    ("m_wdot", "CMAD"),
];

impl Point {
    /// The report's values (indexed by the notation's rows) about DATCOM's
    /// moment centre: per radian, then the appendix's conversion from
    /// Ribner and Malvestuto's notation.
    pub fn report_values(&self) -> Result<Values, NotationError> {
        let ribner = Notation::named("ribner").expect("the appendix's NACA column");
        let mut values: Values = [None; crate::data::notation::N_ROWS];
        let per_radian = [self.cla, self.cma, self.clq, self.cmq, self.clad, self.cmad];
        for ((name, _), v) in DERIVATIVES.iter().zip(per_radian) {
            values[row(name).expect("a report row")] = v.map(|x| x * PER_RADIAN);
        }
        values[row("c_d").expect("a report row")] = self.cd;
        if self.cd.is_none() {
            // z_w = −C_Lα − C_D needs C_D
            values[row("z_w").expect("a report row")] = None;
        }
        ribner.to_report(&values, &[1.0; PARAMETERS.len()])
    }
}

/// Why a DATCOM output cannot be used with a config's planform.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DatcomError {
    #[error(
        "DATCOM's reference {what} {} (at M = {}) is not the config's {} (the planform's {what}, in the same unit): the report's derivatives are on the wing's area and M.A.C.; give DATCOM SREF and CBARR equal to them, or a planform of this size",
        Num(*datcom), Num(*mach), Num(*planform)
    )]
    Reference {
        what: &'static str,
        mach: f64,
        datcom: f64,
        planform: f64,
    },
    #[error(
        "the moment centre XCG is {} at M = {} but {} at M = {}: one moment centre for the whole output, please",
        Num(*first), Num(*first_mach), Num(*other), Num(*mach)
    )]
    MomentCentres {
        first: f64,
        first_mach: f64,
        other: f64,
        mach: f64,
    },
    #[error("{what}: {error}")]
    Table { what: String, error: AeroError },
    #[error("M = {mach}: {error}")]
    Notation { mach: f64, error: NotationError },
    #[error("the output has no Mach number with both CLA and CMA at α = 0")]
    Empty,
}

/// A DATCOM output's tables in the report's notation.
#[derive(Debug, Clone, PartialEq)]
pub struct Tables {
    /// DATCOM's moment centre h_r (fraction of the M.A.C. aft of its
    /// leading edge).
    pub reference_cg: f64,
    /// a = C_Lα per radian.
    pub lift_slope: Table,
    /// H₀ = h_r − C_mα/C_Lα.
    pub aerodynamic_centre: Table,
    /// C_D at α = 0, where DATCOM prints it at two Mach numbers or more.
    pub zero_lift_drag: Option<Table>,
    /// z_w, m_w, z_q, m_q, z_ẇ, m_ẇ about h_r, each where DATCOM gives it
    /// (outside a table's range the computed value is kept).
    pub derivatives: DerivativeTables,
}

impl Tables {
    /// The aerodynamic model with these tables under the user's
    /// (`[model.tables]`): a coefficient's table of the user's wins over
    /// DATCOM's, and the user's derivative tables apply after DATCOM's (a
    /// value replaces DATCOM's, an increment adds to it).
    pub fn under(&self, user: &AeroModel) -> AeroModel {
        let pick = |mine: &Source, theirs: Option<&Table>| match (mine, theirs) {
            (Source::Table(_), _) | (_, None) => mine.clone(),
            (_, Some(t)) => Source::Table(t.clone()),
        };
        AeroModel {
            lift_slope: pick(&user.lift_slope, Some(&self.lift_slope)),
            aerodynamic_centre: pick(&user.aerodynamic_centre, Some(&self.aerodynamic_centre)),
            zero_lift_drag: pick(&user.zero_lift_drag, self.zero_lift_drag.as_ref()),
            drag_due_to_lift: user.drag_due_to_lift.clone(),
            derivatives: DerivativeTables(
                self.derivatives
                    .0
                    .iter()
                    .chain(&user.derivatives.0)
                    .cloned()
                    .collect(),
            ),
            configuration: user.configuration.clone(),
        }
    }
}

/// The moment centre h_r of a DATCOM output whose wing's apex is at
/// `apex_x` in DATCOM's axes, the wing being `planform` (same unit).
pub fn reference_cg(planform: &Planform, apex_x: f64, moment_x: f64) -> f64 {
    (moment_x - apex_x - planform.x_mac()) / planform.mac()
}

/// A table of (Mach, value) pairs, marked DATCOM's.
fn table(what: &str, points: Vec<(f64, f64)>) -> Result<Table, DatcomError> {
    let (mach, value): (Vec<f64>, Vec<f64>) = points.into_iter().unzip();
    Table::new(mach, value)
        .map(|t| t.with_origin(TableOrigin::Datcom))
        .map_err(|error| DatcomError::Table {
            what: what.to_string(),
            error,
        })
}

/// The reference area and length of each point checked against the
/// planform's (within 0.5 %: DATCOM prints them to three decimals), and
/// the one moment centre.
fn check_references(points: &[Point], planform: &Planform) -> Result<f64, DatcomError> {
    let first = points.first().ok_or(DatcomError::Empty)?;
    for p in points {
        let r = p.reference;
        for (what, datcom, planform) in [
            ("area", r.area, planform.area()),
            ("length", r.length, planform.mac()),
        ] {
            if (datcom - planform).abs() > 5e-3 * planform {
                return Err(DatcomError::Reference {
                    what,
                    mach: p.mach,
                    datcom,
                    planform,
                });
            }
        }
        if (r.moment_x - first.reference.moment_x).abs() > 1e-9 * (1.0 + r.moment_x.abs()) {
            return Err(DatcomError::MomentCentres {
                first: first.reference.moment_x,
                first_mach: first.mach,
                other: r.moment_x,
                mach: p.mach,
            });
        }
    }
    Ok(first.reference.moment_x)
}

/// The tables of a DATCOM output's points (in increasing Mach number) for
/// `planform`, whose apex DATCOM puts at `apex_x`.
pub fn tables(points: &[Point], planform: &Planform, apex_x: f64) -> Result<Tables, DatcomError> {
    let moment_x = check_references(points, planform)?;
    let h_r = reference_cg(planform, apex_x, moment_x);
    let mut lift = Vec::new();
    let mut centre = Vec::new();
    let mut drag = Vec::new();
    let mut rows: Vec<Vec<(f64, f64)>> = vec![Vec::new(); DERIVATIVES.len()];
    let mut missing: Vec<Vec<f64>> = vec![Vec::new(); DERIVATIVES.len()];
    for p in points {
        if let (Some(cla), Some(cma)) = (p.cla, p.cma) {
            lift.push((p.mach, cla * PER_RADIAN));
            centre.push((p.mach, h_r - cma / cla));
        }
        if let Some(cd) = p.cd {
            drag.push((p.mach, cd));
        }
        let values = p.report_values().map_err(|error| DatcomError::Notation {
            mach: p.mach,
            error,
        })?;
        for (k, (name, _)) in DERIVATIVES.iter().enumerate() {
            match values[row(name).expect("a report row")] {
                Some(v) => rows[k].push((p.mach, v)),
                None => missing[k].push(p.mach),
            }
        }
    }
    if lift.len() < 2 {
        return Err(DatcomError::Empty);
    }
    let mut derivatives = Vec::new();
    for (((name, from), points), missing) in DERIVATIVES.iter().zip(rows).zip(missing) {
        if points.len() < 2 {
            continue; // computed everywhere
        }
        derivatives.push(DerivativeTable {
            name,
            table: table(&format!("{from} → {name}"), points)?,
            mode: Mode::Value,
            reference_cg: Some(h_r),
            outside: Outside::Computed,
            missing,
        });
    }
    Ok(Tables {
        reference_cg: h_r,
        lift_slope: table("CLA → lift slope", lift)?,
        aerodynamic_centre: table("CMA/CLA → aerodynamic centre", centre)?,
        zero_lift_drag: match drag.len() {
            0 | 1 => None,
            _ => Some(table("CD → zero-lift drag", drag)?),
        },
        derivatives: DerivativeTables(derivatives),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Size;

    /// M = 0.2 of the 60° delta of `tests/fixtures/datcom/delta60_h0.0.out`
    /// (lines 119–138), by hand: per radian ×57.29578.
    #[test]
    fn the_appendix_conversion_by_hand() {
        let p = Point {
            mach: 0.2,
            reference: Reference {
                area: 57.735,
                length: 6.667,
                moment_x: 3.333,
            },
            cd: Some(0.006),
            cla: Some(4.505e-2),
            cma: Some(-1.684e-2),
            clq: Some(5.621e-2),
            cmq: Some(-2.687e-2),
            clad: Some(2.049e-2),
            cmad: Some(-1.148e-2),
        };
        let v = p.report_values().unwrap();
        let get = |n: &str| v[row(n).unwrap()].unwrap();
        // z_w = −(0.04505·57.29578) − 0.006 = −2.587175
        assert!(
            (get("z_w") - (-2.581175 - 0.006)).abs() < 1e-5,
            "{}",
            get("z_w")
        );
        // m_w = −0.01684·57.29578 = −0.964861
        assert!((get("m_w") + 0.964861).abs() < 1e-5);
        // z_q = −½·0.05621·57.29578 = −1.610298
        assert!((get("z_q") + 1.610298).abs() < 1e-5);
        // m_q = ½(−0.02687)·57.29578 = −0.769769
        assert!((get("m_q") + 0.769769).abs() < 1e-5);
        // z_ẇ = −½·0.02049·57.29578 = −0.586995; m_ẇ = ½(−0.01148)·57.29578 = −0.328878
        assert!((get("z_wdot") + 0.586995).abs() < 1e-5);
        assert!((get("m_wdot") + 0.328878).abs() < 1e-5);
    }

    #[test]
    fn the_moment_centre_of_the_macs_leading_edge_is_h_0() {
        // the 60° true delta of root chord 10: x̄ = 10/3, c̄ = 20/3
        let p = Planform::new(60f64.to_radians(), 0.0, Size::RootChord(10.0)).unwrap();
        assert!(reference_cg(&p, 0.0, 3.333333).abs() < 1e-6);
        // XCG at 5.0 (the quarter chord of the M.A.C.) is h = 0.25
        assert!((reference_cg(&p, 0.0, 5.0) - 0.25).abs() < 1e-12);
    }
}
