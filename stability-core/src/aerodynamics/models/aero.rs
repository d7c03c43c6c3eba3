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

use crate::aerodynamics::lifting_surface::{LiftingSurfaceError, Steady, cache, mach_range};
use crate::aerodynamics::models::derivative_tables::DerivativeTables;
use crate::aerodynamics::models::increment::Increment;
use crate::aerodynamics::theory::Row;
use crate::geometry::Planform;
use crate::geometry::Trapezoid;
use crate::geometry::configuration::Configuration;
use crate::numerics::display::Num;
use serde::Serialize;
use std::f64::consts::PI;

/// A coefficient's value and its Mach derivative at one Mach number.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Value {
    pub value: f64,
    /// d(value)/dM, exact (analytic, or the interpolant's own derivative).
    pub d_mach: f64,
}

impl Value {
    pub fn new(value: f64, d_mach: f64) -> Value {
        Value { value, d_mach }
    }
}

/// Why a coefficient cannot be given.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum AeroError {
    #[error("a table needs at least two points, not {0}")]
    TooShort(usize),
    #[error("the table's Mach and value columns have different lengths ({0} and {1})")]
    Lengths(usize, usize),
    #[error(
        "row {row}: Mach {} does not increase on the row before ({}); the Mach column must increase strictly",
        Num(*mach), Num(*previous)
    )]
    NotIncreasing {
        row: usize,
        mach: f64,
        previous: f64,
    },
    #[error("row {row}: {what} {} is not a finite number", Num(*value))]
    NonFinite {
        row: usize,
        what: &'static str,
        value: f64,
    },
    #[error(
        "Mach {} is outside the table's range [{}, {}] (tables are not extrapolated)",
        Num(*mach), Num(*lo), Num(*hi)
    )]
    OutsideTable { mach: f64, lo: f64, hi: f64 },
    #[error(
        "Mach {} is outside the range [{}, {}] of the table of {derivative} (tables are not extrapolated: extend the table, or drop it to use the computed value)",
        Num(*mach), Num(*lo), Num(*hi)
    )]
    OutsideDerivativeTable {
        derivative: &'static str,
        mach: f64,
        lo: f64,
        hi: f64,
    },
    #[error(
        "Mach {} is outside the default models' range [0, {}]",
        Num(*.0), defaults::MACH_MAX
    )]
    OutsideDefaults(f64),
    #[error(
        "the lifting-surface model's lift slope and aerodynamic centre come from a subsonic theory: they need 0 ≤ M < 1, not M = {}; at and above M = 1 use the default model",
        Num(*.0)
    )]
    LatticeMach(f64),
    #[error("the lifting-surface lift slope and aerodynamic centre: {0}")]
    LiftingSurface(LiftingSurfaceError),
    #[error("the configuration's surfaces and body: {0}")]
    Configuration(crate::aerodynamics::lifting_surface::configuration::ConfigurationError),
}

/// A table of a coefficient against Mach number, interpolated by the
/// monotone piecewise cubic Hermite scheme of F.N. Fritsch and R.E. Carlson,
/// "Monotone piecewise cubic interpolation", SIAM J. Numer. Anal. 17(2),
/// 1980: C¹, exact at the nodes, and without overshoot — where the data are
/// monotone on an interval, so is the interpolant.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    mach: Vec<f64>,
    value: Vec<f64>,
    slope: Vec<f64>,
    origin: TableOrigin,
}

/// Whose table it is: the user's, or one made from a DATCOM output
/// ([`crate::data::datcom`]). Serializes as `"table"` or `"datcom"`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum TableOrigin {
    #[default]
    User,
    Datcom,
}

impl TableOrigin {
    /// In words (a page's).
    pub fn describe(self) -> &'static str {
        match self {
            TableOrigin::User => "your table",
            TableOrigin::Datcom => "DATCOM's output",
        }
    }
}

impl Serialize for TableOrigin {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(match self {
            TableOrigin::User => "table",
            TableOrigin::Datcom => "datcom",
        })
    }
}

impl Table {
    /// A table from its columns; rows count from 1 in errors.
    pub fn new(mach: Vec<f64>, value: Vec<f64>) -> Result<Table, AeroError> {
        if mach.len() != value.len() {
            return Err(AeroError::Lengths(mach.len(), value.len()));
        }
        let n = mach.len();
        if n < 2 {
            return Err(AeroError::TooShort(n));
        }
        for i in 0..n {
            if !mach[i].is_finite() {
                return Err(AeroError::NonFinite {
                    row: i + 1,
                    what: "Mach",
                    value: mach[i],
                });
            }
            if !value[i].is_finite() {
                return Err(AeroError::NonFinite {
                    row: i + 1,
                    what: "value",
                    value: value[i],
                });
            }
            if i > 0 && mach[i] <= mach[i - 1] {
                return Err(AeroError::NotIncreasing {
                    row: i + 1,
                    mach: mach[i],
                    previous: mach[i - 1],
                });
            }
        }
        // Secants, then Fritsch–Carlson slopes.
        let delta: Vec<f64> = (0..n - 1)
            .map(|i| (value[i + 1] - value[i]) / (mach[i + 1] - mach[i]))
            .collect();
        let mut slope = vec![0.0; n];
        slope[0] = delta[0];
        slope[n - 1] = delta[n - 2];
        for i in 1..n - 1 {
            slope[i] = if delta[i - 1] * delta[i] <= 0.0 {
                0.0
            } else {
                (delta[i - 1] + delta[i]) / 2.0
            };
        }
        for i in 0..n - 1 {
            (slope[i], slope[i + 1]) = monotone_slopes(delta[i], slope[i], slope[i + 1]);
        }
        Ok(Table {
            mach,
            value,
            slope,
            origin: TableOrigin::User,
        })
    }

    /// The table marked as coming from `origin`.
    pub fn with_origin(self, origin: TableOrigin) -> Table {
        Table { origin, ..self }
    }

    /// Whose table it is.
    pub fn origin(&self) -> TableOrigin {
        self.origin
    }

    /// The Mach numbers and values, as given.
    pub fn points(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        self.mach.iter().copied().zip(self.value.iter().copied())
    }

    /// The Mach range covered.
    pub fn range(&self) -> (f64, f64) {
        (self.mach[0], self.mach[self.mach.len() - 1])
    }

    /// The interpolated value and its derivative at `m`.
    pub fn at(&self, m: f64) -> Result<Value, AeroError> {
        let (lo, hi) = self.range();
        if !(m >= lo && m <= hi) {
            return Err(AeroError::OutsideTable { mach: m, lo, hi });
        }
        let i = match self.mach.partition_point(|&x| x <= m) {
            0 => 0,
            k => (k - 1).min(self.mach.len() - 2),
        };
        Ok(hermite(
            (self.mach[i], self.value[i], self.slope[i]),
            (self.mach[i + 1], self.value[i + 1], self.slope[i + 1]),
            m,
        ))
    }
}

/// The end slopes d₀, d₁ of one interval whose secant is δ, made such that
/// the cubic Hermite interpolant on it is monotone where the data are (F.N.
/// Fritsch and R.E. Carlson, SIAM J. Numer. Anal. 17(2), 1980, §4): with
/// α = d₀/δ, β = d₁/δ, a slope against the secant's sign becomes 0, and
/// (α, β) is pulled radially into the circle α² + β² ≤ 9; δ = 0 gives flat
/// ends.
pub fn monotone_slopes(delta: f64, d0: f64, d1: f64) -> (f64, f64) {
    if delta == 0.0 {
        return (0.0, 0.0);
    }
    let (mut a, mut b) = ((d0 / delta).max(0.0), (d1 / delta).max(0.0));
    let s = a * a + b * b;
    if s > 9.0 {
        let t = 3.0 / s.sqrt();
        (a, b) = (t * a, t * b);
    }
    (a * delta, b * delta)
}

/// The cubic Hermite interpolant through (x₀, y₀, y₀′) and (x₁, y₁, y₁′), and
/// its derivative, at x.
pub fn hermite((x0, y0, d0): (f64, f64, f64), (x1, y1, d1): (f64, f64, f64), x: f64) -> Value {
    let h = x1 - x0;
    let t = (x - x0) / h;
    let (t2, t3) = (t * t, t * t * t);
    let h00 = 2.0 * t3 - 3.0 * t2 + 1.0;
    let h10 = t3 - 2.0 * t2 + t;
    let h01 = -2.0 * t3 + 3.0 * t2;
    let h11 = t3 - t2;
    let value = h00 * y0 + h10 * h * d0 + h01 * y1 + h11 * h * d1;
    let dh00 = (6.0 * t2 - 6.0 * t) / h;
    let dh10 = 3.0 * t2 - 4.0 * t + 1.0;
    let dh01 = (-6.0 * t2 + 6.0 * t) / h;
    let dh11 = 3.0 * t2 - 2.0 * t;
    Value::new(value, dh00 * y0 + dh10 * d0 + dh01 * y1 + dh11 * d1)
}

/// The default methods, each a function of the planform and Mach number.
pub mod defaults {
    use super::*;

    /// Below this Mach number the subsonic methods apply.
    pub const SUBSONIC_LIMIT: f64 = 0.8;
    /// Above this Mach number the supersonic methods apply.
    pub const SUPERSONIC_LIMIT: f64 = 1.2;
    /// The default models hold for 0 ≤ M ≤ this.
    pub const MACH_MAX: f64 = 3.0;
    /// Mean weighted thickness-chord ratio of the report's sections, eq (23):
    /// τ² = 0.0036.
    pub const THICKNESS: f64 = 0.06;

    /// E(m) and dE/dm = (E − K)/(2m) (the `ellip` crate takes the parameter
    /// m = k²); at m = 0 the limit −π/8.
    pub fn ellip_e_and_slope(m: f64) -> (f64, f64) {
        let e = ellip::ellipe(m).unwrap_or(f64::NAN);
        if m.abs() < 1e-12 {
            return (e, -PI / 8.0);
        }
        let k = ellip::ellipk(m).unwrap_or(f64::NAN);
        (e, (e - k) / (2.0 * m))
    }

    /// Subsonic lift slope, the DATCOM form of Helmbold's equation with the
    /// Prandtl–Glauert factor (USAF DATCOM §4.1.3.2; E. Polhamus, NASA TN
    /// D-3767 and CR-145):
    /// a = 2πA / (2 + √(A²(β² + tan²Λ_c/2)/κ² + 4)), β² = 1 − M², κ = 1.
    pub fn lift_slope_subsonic(p: &Planform, m: f64) -> Value {
        let a_r = p.aspect_ratio();
        let t = p.sweep_at(0.5).tan();
        let q = a_r * a_r * (1.0 - m * m + t * t) + 4.0;
        let sq = q.sqrt();
        let value = 2.0 * PI * a_r / (2.0 + sq);
        // dq/dM = −2A²M
        let d = 2.0 * PI * a_r / ((2.0 + sq) * (2.0 + sq)) / (2.0 * sq) * (2.0 * a_r * a_r * m);
        Value::new(value, d)
    }

    /// Supersonic lift slope of a flat delta by linear theory (H.J. Stewart,
    /// Q. Appl. Math. 4, 1946; A.E. Puckett, J. Aero. Sci. 13, 1946): with
    /// β cot Λ < 1 (subsonic leading edges) a = 2π cot Λ/E(k),
    /// k² = 1 − (β cot Λ)²; with β cot Λ ≥ 1 a = 4/β (Ackeret). The two
    /// meet at the sonic leading edge (E(0) = π/2). For a tapered wing the
    /// true-delta formula of the same leading edge is used.
    pub fn lift_slope_supersonic(p: &Planform, m: f64) -> Value {
        let cot = 1.0 / p.sweep_le.tan();
        let beta2 = m * m - 1.0;
        let mle2 = beta2 * cot * cot;
        if mle2 < 1.0 {
            let (e, de) = ellip_e_and_slope(1.0 - mle2);
            let value = 2.0 * PI * cot / e;
            // d(k²)/dM = −2M cot²Λ
            let d = -2.0 * PI * cot / (e * e) * de * (-2.0 * m * cot * cot);
            Value::new(value, d)
        } else {
            let beta = beta2.sqrt();
            Value::new(4.0 / beta, -4.0 * m / (beta * beta * beta))
        }
    }

    /// The lift slope at any Mach number: subsonic below
    /// [`SUBSONIC_LIMIT`], supersonic above [`SUPERSONIC_LIMIT`], and
    /// between them the cubic Hermite fairing matching both values and
    /// slopes (C¹; a documented guess where linear theories fail, as the
    /// report's Fig 5 was a faired guess).
    pub fn lift_slope(p: &Planform, m: f64) -> Value {
        faired(
            m,
            |x| lift_slope_subsonic(p, x),
            |x| lift_slope_supersonic(p, x),
        )
    }

    /// Zero-lift wave drag of a thin delta with the report's sections:
    /// C_Dw = (16/3)τ² cot Λ / √(1 + β² cot²Λ) — the blend of the
    /// two-dimensional linear-theory result for a biconvex section,
    /// (16/3)τ²/β (Ackeret), reached as β cot Λ → ∞, and the slender-wing
    /// limit (16/3)τ² cot Λ, independent of Mach number, as β cot Λ → 0
    /// (wave drag ∝ aspect ratio, as the area rule has it). A documented
    /// stand-in for the experimental curve of Fig 1.
    pub fn wave_drag(p: &Planform, m: f64) -> Value {
        let cot = 1.0 / p.sweep_le.tan();
        let k = 16.0 / 3.0 * THICKNESS * THICKNESS;
        let u = 1.0 + (m * m - 1.0) * cot * cot;
        Value::new(
            k * cot / u.sqrt(),
            -k * cot * cot * cot * m / (u * u.sqrt()),
        )
    }

    /// C_D0 as §6 describes it: 0.01 subsonic; 0.005 (friction) plus wave
    /// drag ([`wave_drag`]) supersonic; faired between.
    pub fn zero_lift_drag(p: &Planform, m: f64) -> Value {
        faired(
            m,
            |_| Value::new(0.01, 0.0),
            |x| {
                let w = wave_drag(p, x);
                Value::new(0.005 + w.value, w.d_mach)
            },
        )
    }

    /// K = ∂C_D/∂C_L² (eq 22) with no leading-edge suction, K = 1/a: the
    /// drag due to lift of a thin, sharp-edged delta, ΔC_D = C_L·α. At
    /// supersonic speeds it is linear theory's value (Robinson's, without
    /// suction); through the transonic range it is exactly §6's rule, the
    /// incompressible value times a_incomp/a.
    pub fn drag_due_to_lift(p: &Planform, m: f64) -> Value {
        no_suction(lift_slope(p, m))
    }

    /// K = 1/a and dK/dM = −(da/dM)/a²: the drag due to lift with no
    /// leading-edge suction, from a lift slope (the model's own, tables
    /// included).
    pub fn no_suction(a: Value) -> Value {
        Value::new(1.0 / a.value, -a.d_mach / (a.value * a.value))
    }

    /// Subsonic aerodynamic centre: H₀ = ¼ + ¼/√(1 + (βA/4)²) — between
    /// slender-wing theory's ½ (two-thirds of the root chord from the apex,
    /// R.T. Jones, NACA Rep. 835, 1946), approached as βA → 0, and the
    /// two-dimensional quarter chord as βA → ∞; H₀ = 0.43 at βA = 4, close
    /// to lifting-surface results for deltas (DATCOM Fig. 4.1.4.2-26).
    pub fn aerodynamic_centre_subsonic(p: &Planform, m: f64) -> Value {
        let a_r = p.aspect_ratio();
        let u = 1.0 + (a_r / 4.0).powi(2) * (1.0 - m * m);
        Value::new(
            0.25 + 0.25 / u.sqrt(),
            0.25 * (a_r / 4.0).powi(2) * m / (u * u.sqrt()),
        )
    }

    /// The aerodynamic centre: subsonic as above; supersonic ½ (conical flow
    /// puts the centre of pressure of a flat delta at two-thirds of the root
    /// chord, the mid-point of the M.A.C.); faired between.
    pub fn aerodynamic_centre(p: &Planform, m: f64) -> Value {
        faired(
            m,
            |x| aerodynamic_centre_subsonic(p, x),
            |_| Value::new(0.5, 0.0),
        )
    }

    fn faired(m: f64, sub: impl Fn(f64) -> Value, sup: impl Fn(f64) -> Value) -> Value {
        if m <= SUBSONIC_LIMIT {
            sub(m)
        } else if m >= SUPERSONIC_LIMIT {
            sup(m)
        } else {
            let a = sub(SUBSONIC_LIMIT);
            let b = sup(SUPERSONIC_LIMIT);
            hermite(
                (SUBSONIC_LIMIT, a.value, a.d_mach),
                (SUPERSONIC_LIMIT, b.value, b.d_mach),
                m,
            )
        }
    }
}

/// Where a coefficient comes from. The precedence is one rule
/// ([`AeroModel::at_with`]): the user's table; else, under
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
/// ([`cache::steady`]).
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
    let wing = cache::unit_wing(p.aspect_ratio(), p.taper, p.sweep_le)
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
    let wing = cache::unit_wing(p.aspect_ratio(), p.taper, p.sweep_le)
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

/// The lift slope and aerodynamic centre a damping model's own theory
/// gives at one Mach number, each with its exact Mach derivative (eqs
/// 27–29 need them): what [`Source::Default`] takes in place of the
/// methods of [`defaults`], so that z_w, m_w come from the same theory as
/// z_q, m_q, z_ẇ, m_ẇ.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TheoryCoefficients {
    /// The damping model's name (`supersonic`).
    pub model: &'static str,
    /// a = ∂C_L/∂α (per radian).
    pub lift_slope: Value,
    /// H₀, fraction of the M.A.C. aft of its leading edge.
    pub aerodynamic_centre: Value,
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
    /// The damping model's own theory, by name.
    DampingModel(&'static str),
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
            Origin::DampingModel(name) => format!("the damping model `{name}`'s own theory"),
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
            Origin::DampingModel(name) => name,
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
    own: Option<(Value, &'static str)>,
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
    /// methods of [`defaults`] (no damping model's own coefficients).
    pub fn at(&self, p: &Planform, m: f64) -> Result<Coefficients, AeroError> {
        self.at_with(p, m, None)
    }

    /// The coefficients of `p` at Mach `m`, with the damping model's own
    /// lift slope and aerodynamic centre `own` where it gives them
    /// ([`Source`] states the precedence), and the configuration's
    /// increment added ([`AeroModel::at_configured`]).
    pub fn at_with(
        &self,
        p: &Planform,
        m: f64,
        own: Option<&TheoryCoefficients>,
    ) -> Result<Coefficients, AeroError> {
        Ok(self.at_configured(p, m, own)?.0)
    }

    /// As [`AeroModel::at_with`], with the wing's own coefficients and the
    /// configuration's increment when there is one. The increment's
    /// in-phase lift ℓ_α and moment μ_α (about the M.A.C.'s leading edge,
    /// at ω̄ = 0) add to the wing's: a = a_w + Δℓ_α,
    /// H₀ = (H₀,w a_w − Δμ_α)/a, their Mach derivatives by the quotient
    /// rule with the increment's; C_D0 and K stay the wing's.
    pub fn at_configured(
        &self,
        p: &Planform,
        m: f64,
        own: Option<&TheoryCoefficients>,
    ) -> Result<(Coefficients, Option<Configured>), AeroError> {
        let wing = self.wing_coefficients(p, m, own)?;
        let Some(config) = self.configuration_for(p) else {
            return Ok((wing, None));
        };
        let inc = config.increment(m, 0.0).map_err(AeroError::Configuration)?;
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
