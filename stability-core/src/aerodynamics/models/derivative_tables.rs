//! The user's own derivatives (`[model.tables]`): a table
//! against Mach number of any of the twelve derivatives of the report's
//! notation (§3, eqs 9–20: x_u, x_w, x_ẇ, x_q, z_u, z_w, z_ẇ, z_q, m_u, m_w,
//! m_ẇ, m_q), either the value itself or an increment added to the
//! computed one, optionally about another c.g. than the case's (a
//! DATCOM output's moment centre, [`crate::data::datcom`]).
//!
//! A table about another c.g. h_r is applied there: the computed set is
//! moved from the case's h to h_r by the transfer formulas of
//! [`transfer`], the table replaces (or increments) its derivative, and the
//! set is moved back. The interpolation is the tables' own
//! ([`Table`]: monotone cubic Hermite in Mach, exact at the nodes).

use crate::Derivatives;
use crate::aerodynamics::models::aero::{AeroError, Table, TableOrigin};
use crate::numerics::display::{Num, sig};
use serde::Serialize;

/// The derivatives a table may give, by their names in the report's
/// notation (the rows of `specs/notation.toml`).
pub const NAMES: [&str; 12] = [
    "x_u", "x_w", "x_wdot", "x_q", "z_u", "z_w", "z_wdot", "z_q", "m_u", "m_w", "m_wdot", "m_q",
];

/// Other spellings accepted for a derivative: the report's dotted ones.
pub const ALIASES: [(&str, &str); 3] = [("x_ẇ", "x_wdot"), ("z_ẇ", "z_wdot"), ("m_ẇ", "m_wdot")];

/// The derivative called `name` (a name of [`NAMES`] or an alias).
pub fn named(name: &str) -> Option<&'static str> {
    NAMES
        .iter()
        .copied()
        .find(|n| *n == name)
        .or_else(|| ALIASES.iter().find(|(a, _)| *a == name).map(|(_, n)| *n))
}

/// The field of `d` called `name` (one of [`NAMES`]).
fn slot<'d>(d: &'d mut Derivatives, name: &str) -> &'d mut f64 {
    match name {
        "x_u" => &mut d.x_u,
        "x_w" => &mut d.x_w,
        "x_wdot" => &mut d.x_wdot,
        "x_q" => &mut d.x_q,
        "z_u" => &mut d.z_u,
        "z_w" => &mut d.z_w,
        "z_wdot" => &mut d.z_wdot,
        "z_q" => &mut d.z_q,
        "m_u" => &mut d.m_u,
        "m_w" => &mut d.m_w,
        "m_wdot" => &mut d.m_wdot,
        _ => &mut d.m_q,
    }
}

/// The value of derivative `name` in `d`.
pub fn get(d: &Derivatives, name: &str) -> f64 {
    *slot(&mut d.clone(), name)
}

/// How a table's value is used.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Mode {
    /// The table's value replaces the computed one.
    Value,
    /// The table's value is added to the computed one.
    Increment,
}

impl Mode {
    /// `value` or `increment`.
    pub fn parse(s: &str) -> Option<Mode> {
        match s {
            "value" => Some(Mode::Value),
            "increment" => Some(Mode::Increment),
            _ => None,
        }
    }
}

/// What is done at a Mach number outside a table's range.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Outside {
    /// An error naming the table and its range (the user's tables).
    Refuse,
    /// The computed value, said in the output (a DATCOM quantity printed
    /// `NDM` at some Mach numbers: its table covers the others).
    Computed,
}

/// One derivative's table.
#[derive(Debug, Clone, PartialEq)]
pub struct DerivativeTable {
    /// The derivative, one of [`NAMES`].
    pub name: &'static str,
    pub table: Table,
    pub mode: Mode,
    /// The c.g. h (fraction of the M.A.C. aft of its leading edge) the
    /// table's values are about; `None`: the case's own.
    pub reference_cg: Option<f64>,
    pub outside: Outside,
    /// Mach numbers inside the table's range at which its source gave
    /// nothing (DATCOM's `NDM`): between the two nodes around one of them
    /// the table says nothing either, and `outside` applies.
    pub missing: Vec<f64>,
}

impl DerivativeTable {
    /// The table's value at `mach`, `None` where it says nothing (outside
    /// its range or across a missing Mach number) and `outside` is
    /// [`Outside::Computed`].
    fn at(&self, mach: f64) -> Result<Option<f64>, AeroError> {
        let computed = self.outside == Outside::Computed;
        let v = match self.table.at(mach) {
            Ok(v) => v.value,
            Err(AeroError::OutsideTable { .. }) if computed => return Ok(None),
            Err(AeroError::OutsideTable { mach, lo, hi }) => {
                return Err(AeroError::OutsideDerivativeTable {
                    derivative: self.name,
                    mach,
                    lo,
                    hi,
                });
            }
            Err(e) => return Err(e),
        };
        let below = self
            .table
            .points()
            .map(|p| p.0)
            .filter(|m| *m <= mach)
            .last();
        let above = self.table.points().map(|p| p.0).find(|m| *m >= mach);
        let across = match (below, above) {
            (Some(a), Some(b)) => self.missing.iter().any(|m| a < *m && *m < b),
            _ => false,
        };
        Ok(if across && computed { None } else { Some(v) })
    }
}

/// The derivative tables of a case, applied in order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct DerivativeTables(pub Vec<DerivativeTable>);

/// What one table did at a design point: the computed value and the one
/// used, both about the case's c.g.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TableUse {
    pub derivative: &'static str,
    pub origin: TableOrigin,
    pub mode: Mode,
    /// The c.g. the table is about, when not the case's.
    pub reference_cg: Option<f64>,
    /// The table's Mach range.
    pub range: (f64, f64),
    /// The table's value at this Mach number (about `reference_cg`);
    /// `None` outside its range, where the computed value is kept.
    pub table: Option<f64>,
    /// The computed value about the case's c.g.
    pub computed: f64,
    /// The value used, about the case's c.g.
    pub used: f64,
}

impl TableUse {
    /// The table's use in words (a page's).
    pub fn describe(&self) -> String {
        let (lo, hi) = self.range;
        let about = self
            .reference_cg
            .map_or(String::new(), |h| format!(" about h = {}", sig(h, 3)));
        let what = match (self.table, self.mode) {
            (None, _) => format!(
                "computed ({} gives none at this Mach number: NDM here, or outside M {}–{})",
                self.origin.describe(),
                Num(lo),
                Num(hi)
            ),
            (Some(v), Mode::Value) => {
                format!("{} {}{about}", self.origin.describe(), sig(v, 5))
            }
            (Some(v), Mode::Increment) => format!(
                "computed {} + {}'s increment {}{about}",
                sig(self.computed, 5),
                self.origin.describe(),
                sig(v, 5)
            ),
        };
        format!("{} = {}: {what}", self.derivative, sig(self.used, 5))
    }
}

/// The derivative set moved from one c.g. to another `delta` = h_new −
/// h_old (fractions of c̄) aft, by rigid-body kinematics: the vertical
/// velocity at the new point is w + qΔc̄ and a force Z at the old point
/// has the moment −ΔZc̄ about the new one, so (report notation, §3)
///
/// - m_w′ = m_w − Δz_w, m_u′ = m_u − Δz_u, m_ẇ′ = m_ẇ − Δz_ẇ;
/// - z_q′ = z_q − Δz_w, x_q′ = x_q − Δx_w;
/// - m_q′ = m_q − Δ(z_q + m_w) + Δ²z_w;
///
/// the forces' other derivatives unchanged, and the q̇ derivatives this
/// introduces (−Δz_ẇ, −Δm_ẇ + Δ²z_ẇ) neglected as the note neglects q̇. In
/// NACA coefficients (C_Lα = −z_w − C_D, C_Lq = −2z_q, C_mq = 2m_q) these
/// are C_mα′ = C_mα + (C_Lα + C_D)Δ, C_Lq′ = C_Lq − 2(C_Lα + C_D)Δ and
/// C_mq′ = C_mq − 2Δ(C_mα − ½C_Lq) − 2Δ²(C_Lα + C_D) — B. Etkin & L.D.
/// Reid, *Dynamics of Flight*, 3rd ed. 1996, §5.6's moment-transfer rule,
/// and USAF DATCOM §7.1.1 (C_Lq = (½ + 2x̄/c̄)C_Lα); slender-wing theory (37)
/// obeys them exactly in h.
pub fn transfer(d: &Derivatives, delta: f64) -> Derivatives {
    Derivatives {
        m_w: d.m_w - delta * d.z_w,
        m_u: d.m_u - delta * d.z_u,
        m_wdot: d.m_wdot - delta * d.z_wdot,
        z_q: d.z_q - delta * d.z_w,
        x_q: d.x_q - delta * d.x_w,
        m_q: d.m_q - delta * (d.z_q + d.m_w) + delta * delta * d.z_w,
        ..*d
    }
}

impl DerivativeTables {
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    /// The computed set `d` (about c.g. `h`, at Mach `mach`) with the
    /// tables applied, and what each did. A table about another c.g. is
    /// applied there (see the module's documentation), before those about
    /// the case's c.g.: a value given at the case's c.g. is the one used.
    pub fn apply(
        &self,
        d: &Derivatives,
        h: f64,
        mach: f64,
    ) -> Result<(Derivatives, Vec<TableUse>), AeroError> {
        let mut out = *d;
        let mut given = Vec::with_capacity(self.0.len());
        // the tables about another c.g. first: a value at the case's own
        // is then what is used
        let order: Vec<&DerivativeTable> = (self.0.iter().filter(|t| t.reference_cg.is_some()))
            .chain(self.0.iter().filter(|t| t.reference_cg.is_none()))
            .collect();
        for t in &order {
            let r = t.reference_cg.unwrap_or(h);
            let mut there = transfer(&out, r - h);
            let value = t.at(mach)?;
            let x = slot(&mut there, t.name);
            match (value, t.mode) {
                (Some(v), Mode::Value) => *x = v,
                (Some(v), Mode::Increment) => *x += v,
                (None, _) => {}
            }
            out = transfer(&there, h - r);
            given.push(value);
        }
        let uses = order
            .iter()
            .zip(given)
            .map(|(t, table)| TableUse {
                derivative: t.name,
                origin: t.table.origin(),
                mode: t.mode,
                reference_cg: t.reference_cg.filter(|r| *r != h),
                range: t.table.range(),
                table,
                computed: get(d, t.name),
                used: get(&out, t.name),
            })
            .collect();
        Ok((out, uses))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::aerodynamics::damping::{Theory, WingInput, damping_derivatives};
    use crate::geometry::{Planform, Size};
    use std::f64::consts::PI;

    fn set() -> Derivatives {
        Derivatives {
            x_u: -0.03,
            x_w: 0.1,
            x_wdot: 0.01,
            x_q: -0.02,
            z_u: -0.6,
            z_w: -2.5,
            z_wdot: -0.8,
            z_q: -1.2,
            m_u: 0.02,
            m_w: -0.3,
            m_wdot: -0.4,
            m_q: -0.7,
            c_l: 0.3,
            mu1: 50.0,
            i_b: 0.08,
        }
    }

    /// Slender-wing theory (37) is a function of h: its damping
    /// derivatives at h = 0.4 are those at h = 0 moved by the transfer
    /// formulas, with its own z_w = −πA/2 and m_w = (h − ½)πA/2 (H₀ = ½).
    #[test]
    fn the_transfer_moves_slender_wing_theory_from_one_cg_to_another() {
        let p = Planform::new(60f64.to_radians(), 0.0, Size::RootChord(1.0)).unwrap();
        let w = WingInput::from(&p);
        let a = p.aspect_ratio();
        let at = |h: f64| {
            let dd = damping_derivatives(Theory::Slender, &w, h, 0.5, None)
                .unwrap()
                .derivatives;
            Derivatives {
                z_w: -PI * a / 2.0,
                m_w: (h - 0.5) * PI * a / 2.0,
                z_q: dd.z_q,
                z_wdot: dd.z_wdot,
                m_q: dd.m_q,
                m_wdot: dd.m_wdot,
                ..set()
            }
        };
        let moved = transfer(&at(0.0), 0.4);
        let there = at(0.4);
        for name in ["z_w", "m_w", "z_q", "m_q", "z_wdot", "m_wdot"] {
            let (x, y) = (get(&moved, name), get(&there, name));
            assert!(
                (x - y).abs() < 1e-12 * (1.0 + y.abs()),
                "{name}: {x} vs {y}"
            );
        }
    }

    #[test]
    fn the_transfer_by_hand_and_back() {
        let d = set();
        let t = transfer(&d, 0.2);
        // m_q' = m_q − Δ(z_q + m_w) + Δ²z_w = −0.7 − 0.2(−1.5) + 0.04(−2.5)
        assert!((t.m_q - (-0.7 + 0.3 - 0.1)).abs() < 1e-15);
        assert!((t.m_w - (-0.3 + 0.5)).abs() < 1e-15);
        assert!((t.z_q - (-1.2 + 0.5)).abs() < 1e-15);
        let back = transfer(&t, -0.2);
        for name in NAMES {
            assert!((get(&back, name) - get(&d, name)).abs() < 1e-14, "{name}");
        }
    }

    fn table(name: &'static str, mode: Mode, r: Option<f64>) -> DerivativeTable {
        DerivativeTable {
            name,
            table: Table::new(vec![0.5, 1.0], vec![-1.0, -2.0]).unwrap(),
            mode,
            reference_cg: r,
            outside: Outside::Refuse,
            missing: Vec::new(),
        }
    }

    #[test]
    fn values_and_increments_at_the_cases_cg_and_about_another() {
        let d = set();
        // at M 0.75 the table gives −1.5 (linear data: the Hermite is exact)
        let tables = DerivativeTables(vec![
            table("m_q", Mode::Value, None),
            table("z_u", Mode::Increment, None),
        ]);
        let (out, uses) = tables.apply(&d, 0.25, 0.75).unwrap();
        assert!((out.m_q + 1.5).abs() < 1e-15);
        assert!((out.z_u - (-0.6 - 1.5)).abs() < 1e-15);
        assert_eq!(uses[1].computed, -0.6);
        // m_w given about h = 0 as −1.5; at h = 0.25 it is −1.5 − 0.25z_w
        let about = DerivativeTables(vec![table("m_w", Mode::Value, Some(0.0))]);
        let (out, _) = about.apply(&d, 0.25, 0.75).unwrap();
        assert!((out.m_w - (-1.5 + 0.25 * 2.5)).abs() < 1e-14);
        let e = tables.apply(&d, 0.25, 1.2).unwrap_err();
        assert!(e.to_string().contains("m_q") && e.to_string().contains("[0.5, 1]"));
    }
}
