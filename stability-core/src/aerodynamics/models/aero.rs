//! The aerodynamic coefficients against Mach number (§6): zero-lift drag
//! C_D0, drag due to lift K = ∂C_D/∂C_L² (eq 22), lift slope a = ∂C_L/∂α and
//! aerodynamic centre H₀ (fraction of the M.A.C. aft of its leading edge) —
//! each with its exact Mach derivative, which the stiffness derivatives of
//! eqs (9)–(14), (27)–(29) need.
//!
//! The report read these off curves (Figs 1–6) that did not survive. Here
//! each comes either from the user's table ([`Table`], Mach against value,
//! monotone cubic Hermite interpolation) or from a named, documented default
//! method ([`defaults`]); `docs/models.md` sets out the choices.

use super::damping_model::DampingModel;
pub use super::defaults;
pub use super::error::AeroError;
pub use super::table::{Table, TableOrigin};
pub use crate::aerodynamics::damping::{OwnTheory, TheoryCoefficients};
use crate::aerodynamics::lifting_surface::Harmonic;
pub use crate::numerics::interpolation::{Value, hermite, monotone_slopes};

use crate::aerodynamics::lifting_surface::{Steady, mach_range, store};
use crate::aerodynamics::models::derivative_tables::DerivativeTables;
use crate::aerodynamics::models::increment::Increment;
use crate::aerodynamics::theory::Row;
use crate::geometry::Planform;
use crate::geometry::Trapezoid;
use crate::geometry::configuration::Configuration;
use serde::Serialize;

/// Where a coefficient comes from. The precedence is one rule
/// ([`AeroModel::at_configured`]): the user's table; else, under
/// [`Source::Default`], the damping model's own value where it gives one
/// ([`TheoryCoefficients`]); else the method of [`defaults`].
#[derive(Debug, Clone, PartialEq, Default)]
pub enum Source {
    /// The default: the theory of the case's damping model where that
    /// theory gives this coefficient itself — with `--damping supersonic`
    /// at M > 1 the lift slope and aerodynamic centre of linear supersonic
    /// theory, eq (36)'s πA/(2E) and H₀ for subsonic leading edges, the
    /// supersonic-edge theory's beyond (`supersonic::edge_coefficients`) —
    /// and the method of [`defaults`] otherwise.
    #[default]
    Default,
    /// The method of [`defaults`] (docs/models.md), whatever the damping
    /// model.
    Method,
    /// The user's table: wins over every other source.
    Table(Table),
    /// The lifting surface's quasi-steady solution
    /// ([`lifting_surface_coefficients`]), 0 ≤ M ≤ 3 (the doublet lattice
    /// below M = 1, the Mach box above, a stated join through the sonic
    /// point between 0.99 and the Mach box): for the lift slope and the
    /// aerodynamic centre, with their Mach derivatives. It gives no
    /// drag: for C_D0 and K it means [`Source::Default`] (K = 1/a with the
    /// lattice's a).
    LiftingSurface,
}

/// The named aerodynamic models of configs (`[model] aero = …`) and of the
/// command line (`--aero`): where the lift slope and aerodynamic centre
/// come from when no table gives them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AeroModelName {
    /// The methods of [`defaults`] (docs/models.md).
    Default,
    /// The doublet lattice below M = 1 ([`Source::LiftingSurface`]).
    LiftingSurface,
}

impl AeroModelName {
    pub const ALL: [AeroModelName; 2] = [AeroModelName::Default, AeroModelName::LiftingSurface];

    /// The model's row of the registry ([`crate::aerodynamics::theory::Row`]).
    pub fn row(self) -> &'static Row {
        match self {
            AeroModelName::Default => &Row {
                name: "default",
                equations: "",
                summary: "the default: DATCOM lift slope and a slender-to-2-D aerodynamic centre subsonic, linear conical-flow theory supersonic, faired between (docs/models.md)",
                validity: "any Mach number",
                supplies: "the lift slope and aerodynamic centre with their Mach derivatives (eqs 25–29), C_D0 and K",
                source: "USAF DATCOM; linear conical-flow theory (docs/models.md)",
            },
            AeroModelName::LiftingSurface => &Row {
                name: "lifting-surface",
                equations: "",
                summary: "lift slope and aerodynamic centre from the lifting surface: the doublet lattice below M = 1 (exact Mach derivatives), the Mach box above, joined through the sonic point (slender-wing theory) between M = 0.99 and the Mach box (docs/lattice-near-sonic.md)",
                validity: "0 ≤ M ≤ 3",
                supplies: "the lift slope and aerodynamic centre with their Mach derivatives (eqs 25–29)",
                source: "the doublet lattice of `lifting_surface` (Albano & Rodden 1969), the Mach box (Pines, Dugundji & Neuringer 1955), slender-wing theory at M = 1 (Jones, NACA Rep. 835)",
            },
        }
    }

    pub fn name(self) -> &'static str {
        self.row().name
    }

    /// The model of this name, or `None`.
    pub fn parse(s: &str) -> Option<AeroModelName> {
        Self::ALL.into_iter().find(|m| m.name() == s)
    }
}

/// The lattice's steady solution of the planform's shape at Mach `m`, with
/// its Mach derivatives: one solve per (shape, M), cached
/// ([`store::lattice_steady`]).
///
/// At any M in [0, 3] ([`mach_range::steady`]): the lattice's exact Mach
/// derivatives up to M = 0.99 (the refined lattice above 0.9); above M = 1
/// the Mach box's table in Mach number and its slope
/// ([`crate::aerodynamics::lifting_surface::mach_table`]). Between M = 0.99 and the Mach
/// box's first Mach number an error (the quasi-steady α̇ derivatives are
/// infinite at M = 1; [`lifting_surface_coefficients`] joins the lift
/// slope and aerodynamic centre across). The Mach box's warning (a subsonic leading edge
/// beyond its verified range) is not carried: see the damping theory's.
pub fn lifting_surface_steady(p: &Planform, m: f64) -> Result<Steady, AeroError> {
    let wing = store::unit_wing(p.aspect_ratio(), p.taper, p.sweep_le)
        .map_err(AeroError::LiftingSurface)?;
    mach_range::steady(&wing, m)
        .map(|(s, _)| s)
        .map_err(AeroError::LiftingSurface)
}

/// The lattice's (or the Mach box's) quasi-steady lift slope and
/// aerodynamic centre with their Mach derivatives at any M in [0, 3]
/// ([`mach_range::coefficients`]): [`lifting_surface_steady`]'s, and
/// between M = 0.99 and the Mach box's first Mach number the stated join
/// through linear theory's sonic point (slender-wing theory, the note's
/// (37)).
pub fn lifting_surface_coefficients(
    p: &Planform,
    m: f64,
) -> Result<mach_range::SteadyCoefficients, AeroError> {
    let wing = store::unit_wing(p.aspect_ratio(), p.taper, p.sweep_le)
        .map_err(AeroError::LiftingSurface)?;
    mach_range::coefficients(&wing, m).map_err(AeroError::LiftingSurface)
}

/// The aerodynamic model: one source per coefficient.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct AeroModel {
    pub lift_slope: Source,
    pub zero_lift_drag: Source,
    pub drag_due_to_lift: Source,
    pub aerodynamic_centre: Source,
    /// The user's (or DATCOM's) derivative tables, applied to the
    /// derivative set computed from the above
    /// ([`crate::aerodynamics::models::derivative_tables`]).
    pub derivatives: DerivativeTables,
    /// The configuration (tailplane, foreplane, body) whose increment over
    /// the wing is added to the wing's coefficients and damping
    /// ([`crate::aerodynamics::models::increment`]); its wing is replaced by the
    /// case's planform. `None`: the wing alone.
    pub configuration: Option<std::sync::Arc<Configuration>>,
}

/// A configuration's share of one design point's coefficients: the wing's
/// own coefficients (the model's, before the increment) and the increment
/// at ω̄ = 0 they were added to.
#[derive(Debug, Clone, PartialEq)]
pub struct Configured {
    pub wing: Coefficients,
    pub increment: Increment,
}

/// Where one coefficient of [`Coefficients`] came from; serializes as
/// `"table"`, `"method"`, `"lifting-surface"` or the damping model's name.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Origin {
    /// The user's table.
    Table,
    /// A table made from a DATCOM output ([`crate::data::datcom`]).
    Datcom,
    /// The method of [`defaults`] (for K = ∂C_D/∂C_L²: 1/a of the lift
    /// slope used, whatever its origin).
    Method,
    /// The damping model's own theory.
    DampingModel(OwnTheory),
    /// The doublet lattice's steady solution ([`Source::LiftingSurface`]).
    LiftingSurface,
}

impl Origin {
    /// Where the coefficient came from, in words (a page's).
    pub fn describe(self) -> String {
        match self {
            Origin::Table => "your table".to_string(),
            Origin::Datcom => "DATCOM's output (--datcom, [model] datcom)".to_string(),
            Origin::Method => "the default method (docs/models.md)".to_string(),
            Origin::DampingModel(own) => format!("the damping model `{}`'s own theory", own.name()),
            Origin::LiftingSurface => "the lifting surface (--aero lifting-surface)".to_string(),
        }
    }
}

impl Serialize for Origin {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(match self {
            Origin::Table => "table",
            Origin::Datcom => "datcom",
            Origin::Method => "method",
            Origin::DampingModel(own) => own.name(),
            Origin::LiftingSurface => "lifting-surface",
        })
    }
}

/// The origin of each coefficient.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Origins {
    pub lift_slope: Origin,
    pub zero_lift_drag: Origin,
    pub drag_due_to_lift: Origin,
    pub aerodynamic_centre: Origin,
}

impl Origins {
    /// One origin for all four.
    pub fn all(o: Origin) -> Origins {
        Origins {
            lift_slope: o,
            zero_lift_drag: o,
            drag_due_to_lift: o,
            aerodynamic_centre: o,
        }
    }
}

/// The coefficients at one Mach number.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Coefficients {
    pub mach: f64,
    /// a = ∂C_L/∂α (per radian).
    pub lift_slope: Value,
    /// C_D0.
    pub zero_lift_drag: Value,
    /// K = ∂C_D/∂C_L².
    pub drag_due_to_lift: Value,
    /// H₀, fraction of the M.A.C. aft of its leading edge.
    pub aerodynamic_centre: Value,
    /// Where each came from.
    pub origin: Origins,
}

/// The method of [`defaults`] `f`, inside the defaults' Mach range.
fn method(f: fn(&Planform, f64) -> Value, p: &Planform, m: f64) -> Result<Value, AeroError> {
    if (0.0..=defaults::MACH_MAX).contains(&m) {
        Ok(f(p, m))
    } else {
        Err(AeroError::OutsideDefaults(m))
    }
}

/// Which of the lattice's steady values a coefficient is, with its Mach
/// derivative (the lift slope or the aerodynamic centre of
/// [`mach_range::SteadyCoefficients`]).
type SteadyValue = fn(&mach_range::SteadyCoefficients) -> (f64, f64);

/// The rule of precedence for one coefficient: the table; else the
/// lattice, under [`Source::LiftingSurface`] for a coefficient it gives
/// (`lattice`: the planform and which of its steady values); else the
/// damping model's own value (`own`, under [`Source::Default`] only); else
/// the method.
fn resolve(
    source: &Source,
    m: f64,
    own: Option<(Value, OwnTheory)>,
    lattice: Option<(&Planform, SteadyValue)>,
    method: impl FnOnce() -> Result<Value, AeroError>,
) -> Result<(Value, Origin), AeroError> {
    match (source, own, lattice) {
        (Source::Table(t), _, _) => {
            let origin = match t.origin() {
                TableOrigin::User => Origin::Table,
                TableOrigin::Datcom => Origin::Datcom,
            };
            Ok((t.at(m)?, origin))
        }
        (Source::LiftingSurface, _, Some((p, of))) => {
            let (v, d) = of(&lifting_surface_coefficients(p, m)?);
            Ok((Value::new(v, d), Origin::LiftingSurface))
        }
        (Source::Default, Some((v, model)), _) => Ok((v, Origin::DampingModel(model))),
        _ => Ok((method()?, Origin::Method)),
    }
}

impl AeroModel {
    /// The model named `name`: the lift slope and aerodynamic centre from
    /// it, unless a table of this model gives them (a table wins); the
    /// other coefficients as they are.
    pub fn with_name(self, name: AeroModelName) -> AeroModel {
        let named = |s: Source| match (s, name) {
            (Source::Table(t), _) => Source::Table(t),
            (_, AeroModelName::Default) => Source::Default,
            (_, AeroModelName::LiftingSurface) => Source::LiftingSurface,
        };
        AeroModel {
            lift_slope: named(self.lift_slope),
            aerodynamic_centre: named(self.aerodynamic_centre),
            ..self
        }
    }

    /// The coefficients of `p` at Mach `m` from tables, the lattice and the
    /// methods of [`defaults`] (no damping model's own coefficients; a
    /// configuration's increment by the default damping model's methods).
    pub fn at(&self, p: &Planform, m: f64) -> Result<Coefficients, AeroError> {
        Ok(self.at_configured(p, m, None, DampingModel::default())?.0)
    }

    /// The coefficients of `p` at Mach `m`, with the damping model's own
    /// lift slope and aerodynamic centre `own` where it gives them
    /// ([`Source`] states the precedence), and the wing's own coefficients
    /// and the configuration's increment when there is one, by the damping
    /// `model`'s methods ([`DampingModel::increment`]). The increment's
    /// in-phase lift ℓ_α and moment μ_α (about the M.A.C.'s leading edge,
    /// at ω̄ = 0) add to the wing's: a = a_w + Δℓ_α,
    /// H₀ = (H₀,w a_w − Δμ_α)/a, their Mach derivatives by the quotient
    /// rule with the increment's; C_D0 and K stay the wing's.
    pub fn at_configured(
        &self,
        p: &Planform,
        m: f64,
        own: Option<&TheoryCoefficients>,
        model: DampingModel,
    ) -> Result<(Coefficients, Option<Configured>), AeroError> {
        let wing = self.wing_coefficients(p, m, own)?;
        let Some(config) = self.configuration_for(p) else {
            return Ok((wing, None));
        };
        let inc = model
            .increment(&config, m, 0.0, Harmonic::Direct, true)
            .map_err(AeroError::Configuration)?;
        let (aw, hw) = (wing.lift_slope, wing.aerodynamic_centre);
        let a = Value::new(
            aw.value + inc.solution.lift_alpha,
            aw.d_mach + inc.d_lift_alpha.unwrap_or(0.0),
        );
        let mu = -hw.value * aw.value + inc.solution.moment_alpha;
        let d_mu =
            -(hw.d_mach * aw.value + hw.value * aw.d_mach) + inc.d_moment_alpha.unwrap_or(0.0);
        let h0 = Value::new(
            -mu / a.value,
            -(d_mu * a.value - mu * a.d_mach) / (a.value * a.value),
        );
        let total = Coefficients {
            lift_slope: a,
            aerodynamic_centre: h0,
            ..wing
        };
        Ok((
            total,
            Some(Configured {
                wing,
                increment: inc,
            }),
        ))
    }

    /// The model's configuration with the wing `p`, if it adds anything to
    /// the wing.
    pub fn configuration_for(&self, p: &Planform) -> Option<Configuration> {
        let c = self.configuration.as_ref().filter(|c| c.has_additions())?;
        Some(Configuration {
            wing: Trapezoid::from(p),
            ..(**c).clone()
        })
    }

    /// The wing's own coefficients ([`Source`] states the precedence).
    fn wing_coefficients(
        &self,
        p: &Planform,
        m: f64,
        own: Option<&TheoryCoefficients>,
    ) -> Result<Coefficients, AeroError> {
        let (lift_slope, ls) = resolve(
            &self.lift_slope,
            m,
            own.map(|t| (t.lift_slope, t.model)),
            Some((p, |c| c.lift_slope)),
            || method(defaults::lift_slope, p, m),
        )?;
        let (aerodynamic_centre, ac) = resolve(
            &self.aerodynamic_centre,
            m,
            own.map(|t| (t.aerodynamic_centre, t.model)),
            Some((p, |c| c.aerodynamic_centre)),
            || method(defaults::aerodynamic_centre, p, m),
        )?;
        let (zero_lift_drag, cd0) = resolve(&self.zero_lift_drag, m, None, None, || {
            method(defaults::zero_lift_drag, p, m)
        })?;
        // K = 1/a with the model's own lift slope (tables and lattice included)
        let (drag_due_to_lift, k) = resolve(&self.drag_due_to_lift, m, None, None, || {
            Ok(defaults::no_suction(lift_slope))
        })?;
        Ok(Coefficients {
            mach: m,
            lift_slope,
            zero_lift_drag,
            drag_due_to_lift,
            aerodynamic_centre,
            origin: Origins {
                lift_slope: ls,
                zero_lift_drag: cd0,
                drag_due_to_lift: k,
                aerodynamic_centre: ac,
            },
        })
    }
}

/// Level flight, eq (24): C_L·M² = W/(½ρa²S) is constant, so
/// C_L(M) = (C_L M²)/M² and dC_L/dM = −2C_L/M.
pub fn level_flight_lift(cl_m2: f64, m: f64) -> Value {
    let cl = cl_m2 / (m * m);
    Value::new(cl, -2.0 * cl / m)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Size;
    use std::f64::consts::PI;

    fn delta(deg: f64) -> Planform {
        Planform::new(deg.to_radians(), 0.0, Size::RootChord(1.0)).unwrap()
    }

    #[test]
    fn tables_interpolate_monotonically_with_exact_slopes() {
        let t = Table::new(vec![0.5, 0.9, 1.0, 1.2, 2.0], vec![3.0, 3.5, 3.6, 3.2, 2.4]).unwrap();
        // exact at the nodes
        assert_eq!(t.at(1.0).unwrap().value, 3.6);
        // no overshoot between monotone data
        for i in 0..=100 {
            let m = 1.2 + 0.8 * i as f64 / 100.0;
            let v = t.at(m).unwrap().value;
            assert!((2.4..=3.2).contains(&v), "{m}: {v}");
        }
        // the derivative is the interpolant's (central difference check)
        let h = 1e-6;
        let m = 0.77;
        let fd = (t.at(m + h).unwrap().value - t.at(m - h).unwrap().value) / (2.0 * h);
        assert!((fd - t.at(m).unwrap().d_mach).abs() < 1e-6);
        assert!(matches!(t.at(2.5), Err(AeroError::OutsideTable { .. })));
    }

    #[test]
    fn bad_tables_name_the_row() {
        assert_eq!(
            Table::new(vec![0.5, 0.9, 0.9], vec![1.0, 2.0, 3.0]),
            Err(AeroError::NotIncreasing {
                row: 3,
                mach: 0.9,
                previous: 0.9
            })
        );
        assert!(matches!(
            Table::new(vec![0.5], vec![1.0]),
            Err(AeroError::TooShort(1))
        ));
        assert!(matches!(
            Table::new(vec![0.5, f64::NAN], vec![1.0, 2.0]),
            Err(AeroError::NonFinite { row: 2, .. })
        ));
    }

    #[test]
    fn linear_theory_reaches_the_slender_wing_value_at_m1() {
        // a → 2π cot Λ = πA/2 as M → 1⁺ (E(1) = 1)
        for deg in [45.0, 60.0] {
            let p = delta(deg);
            let a = defaults::lift_slope_supersonic(&p, 1.0 + 1e-9).value;
            assert!((a - PI * p.aspect_ratio() / 2.0).abs() < 1e-6, "{deg}: {a}");
        }
    }

    #[test]
    fn the_two_supersonic_forms_meet_at_the_sonic_leading_edge() {
        let p = delta(45.0);
        let m_sonic = 2f64.sqrt(); // β cot 45° = 1
        let below = defaults::lift_slope_supersonic(&p, m_sonic - 1e-9).value;
        let above = defaults::lift_slope_supersonic(&p, m_sonic + 1e-9).value;
        assert!((below - above).abs() < 1e-6 && (above - 4.0).abs() < 1e-6);
    }

    #[test]
    fn default_slopes_are_exact_derivatives_and_fairings_are_c1() {
        let p = delta(60.0);
        let h = 1e-6;
        type Method = fn(&Planform, f64) -> Value;
        let fns: [(&str, Method); 5] = [
            ("lift slope", defaults::lift_slope),
            ("zero-lift drag", defaults::zero_lift_drag),
            ("drag due to lift", defaults::drag_due_to_lift),
            ("aerodynamic centre", defaults::aerodynamic_centre),
            ("wave drag", defaults::wave_drag),
        ];
        for (name, f) in fns {
            for m in [0.3, 0.79, 0.8, 0.95, 1.05, 1.2, 1.5, 2.5] {
                let fd = (f(&p, m + h).value - f(&p, m - h).value) / (2.0 * h);
                let d = f(&p, m).d_mach;
                assert!(
                    (fd - d).abs() < 1e-5 * (1.0 + d.abs()),
                    "{name} at M = {m}: {d} vs {fd}"
                );
            }
        }
    }

    #[test]
    fn supersonic_lift_slope_of_a_45_degree_delta_at_m_1_2() {
        // β cot Λ = √0.44 = 0.6633, k² = 0.56, E(0.56) = 1.31978755716003
        // (mpmath.ellipe(0.56)), a = 2π/E = 4.76076.
        let a = defaults::lift_slope_supersonic(&delta(45.0), 1.2).value;
        assert!((a - 2.0 * PI / 1.319_787_557_160_03).abs() < 1e-12, "{a}");
    }
}
