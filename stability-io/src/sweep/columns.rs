//! The columns of a sweep's rows: one table, [`COLUMNS`], of each
//! column's name (the CSV's header, the JSON's key, the Python package's
//! column), unit, rows, value and meaning, in the rows' order. The command
//! line's rows ([`super::Grid::rows`]), the column list of `sweep --help`
//! ([`listing`]), and the Python package's `sweep()` columns and their
//! docs all come from it: a column is one row of the table.
//!
//! A column's value is had from a point's result in the library's columns
//! ([`Points`]), its grid values and, at a physical flight condition, its
//! speed, C_L and τ ([`FlightPoint`]).

use stability_core::Derivatives;
use stability_core::criteria::{Category, Level, phugoid_level, short_period_level};
use stability_core::design::flight::FlightPoint;
use stability_core::design::sweep::Points;

/// One point of a sweep, as a column reads it.
#[derive(Debug, Clone, Copy)]
pub struct Point<'a> {
    points: &'a Points,
    /// Its index in `points`.
    k: usize,
    /// The grid's sweep angle as given (the library's is its planform's,
    /// converted back from radians).
    sweep_deg: f64,
    /// At a physical flight condition, the point's V, C_L and τ (`None`
    /// without one, or where the point has no result).
    flight: Option<FlightPoint>,
}

impl<'a> Point<'a> {
    /// Point `k` of `points`, of the grid's sweep angle `sweep_deg`, at
    /// the flight point `flight` when the condition is physical.
    pub fn new(
        points: &'a Points,
        k: usize,
        sweep_deg: f64,
        flight: Option<FlightPoint>,
    ) -> Point<'a> {
        Point {
            points,
            k,
            sweep_deg,
            flight,
        }
    }

    /// The point's value in one of the library's columns.
    fn at(&self, column: &[f64]) -> Option<f64> {
        finite(column[self.k])
    }

    /// Root `i` (1/τ; conjugates adjacent, fastest first).
    fn root(&self, i: usize) -> num_complex::Complex64 {
        self.points.roots[self.k][i]
    }

    /// A rate in 1/τ as 1/s.
    fn per_second(&self, rate: f64) -> Option<f64> {
        self.flight.and_then(|f| finite(rate / f.tau))
    }

    /// A time in τ as seconds.
    fn seconds(&self, time: f64) -> Option<f64> {
        self.flight.and_then(|f| finite(time * f.tau))
    }

    /// A quartic input, when the derivatives were asked for.
    fn derivative(&self, input: fn(&Derivatives) -> f64) -> Option<f64> {
        let ds = self.points.derivatives.as_ref()?;
        finite(input(&ds[self.k]))
    }

    /// The short period's MIL-F-8785C level in `category` (§3.2.2.1.2),
    /// where its damping ratio is defined.
    fn sp_level(&self, category: Category) -> Option<f64> {
        let zeta = self.at(&self.points.sp_damping_ratio)?;
        Some(level(short_period_level(zeta, category)))
    }

    /// The phugoid's MIL-F-8785C level (§3.2.1.2): where it diverges, its
    /// time to double amplitude in seconds is needed (a physical flight
    /// condition's τ).
    fn ph_level(&self) -> Option<f64> {
        let zeta = self.at(&self.points.ph_damping_ratio)?;
        let re = self.points.ph_re[self.k];
        let t2 = self.flight.map(|f| std::f64::consts::LN_2 / re * f.tau);
        (zeta >= 0.0 || t2.is_some()).then(|| level(phugoid_level(zeta, t2)))
    }
}

fn finite(v: f64) -> Option<f64> {
    v.is_finite().then_some(v)
}

/// A level as its column gives it: 1, 2, 3, or 4 for worse than Level 3.
fn level(l: Level) -> f64 {
    f64::from(l.number())
}

/// How a column's value is had from a point.
#[derive(Debug, Clone, Copy)]
pub enum Value {
    /// A value of the grid: written for every point, with a result or not.
    Grid(fn(&Point<'_>) -> f64),
    /// A number of the point's result (`None` where it is undefined).
    Number(fn(&Point<'_>) -> Option<f64>),
    Bool(fn(&Point<'_>) -> bool),
    /// A word of the program's own (a verdict), empty for none.
    Word(fn(&Point<'_>) -> &'static str),
    /// Why the point has no result; empty where it has one.
    Error,
}

/// Which rows carry a column.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum When {
    Always,
    /// At a physical flight condition only.
    Physical,
    /// With the derivatives asked for.
    Derivatives,
    /// With the derivatives asked for, without a physical flight condition
    /// (which has the column already).
    DerivativesNotPhysical,
}

impl When {
    /// Whether the rows of a sweep with `derivatives` asked for, at a
    /// `physical` flight condition or not, carry the column.
    pub fn holds(self, derivatives: bool, physical: bool) -> bool {
        match self {
            When::Always => true,
            When::Physical => physical,
            When::Derivatives => derivatives,
            When::DerivativesNotPhysical => derivatives && !physical,
        }
    }

    /// The condition in words (empty for always), naming the front end's
    /// way of asking for the derivatives (`derivatives`).
    pub fn words(self, derivatives: &str) -> String {
        match self {
            When::Always => String::new(),
            When::Physical => "at a physical flight condition".into(),
            When::Derivatives => format!("with {derivatives}"),
            When::DerivativesNotPhysical => {
                format!("with {derivatives}, without a physical flight condition")
            }
        }
    }
}

/// One column of a sweep's rows.
#[derive(Debug, Clone, Copy)]
pub struct Column {
    /// The CSV's header, the JSON's key, the Python package's column.
    pub name: &'static str,
    /// Its unit; empty for a pure number, a word or a message.
    pub unit: &'static str,
    pub when: When,
    pub value: Value,
    /// What it is, for `sweep --help` and the Python package's docs.
    pub description: &'static str,
}

const fn col(
    name: &'static str,
    unit: &'static str,
    value: Value,
    description: &'static str,
) -> Column {
    Column {
        name,
        unit,
        when: When::Always,
        value,
        description,
    }
}

impl Column {
    const fn only(self, when: When) -> Column {
        Column { when, ..self }
    }

    /// Its line in a listing: name, unit, meaning and when the rows carry
    /// it ([`When::words`]).
    pub fn line(&self, derivatives: &str) -> String {
        let unit = match self.unit {
            "" => String::new(),
            u => format!(" [{u}]"),
        };
        let when = match self.when.words(derivatives) {
            w if w.is_empty() => w,
            w => format!("; {w}"),
        };
        format!("{}{unit}: {}{when}", self.name, self.description)
    }
}

use Value::{Bool, Grid, Number, Word};
use When::{Derivatives as Asked, DerivativesNotPhysical, Physical};

/// The columns, in the rows' order.
#[rustfmt::skip]
pub const COLUMNS: &[Column] = &[
    col("mach", "", Grid(|p| p.points.mach[p.k]), "the Mach number"),
    col("sweep_deg", "deg", Grid(|p| p.sweep_deg), "the leading-edge sweep, as given"),
    col("cg", "M.A.C.", Grid(|p| p.points.cg[p.k]), "the c.g. position h, aft of the M.A.C.'s leading edge"),
    col("mu1", "", Grid(|p| p.points.mu1[p.k]), "the relative density μ₁ = m/(½ρSc̄) (at a physical flight condition the point's own)"),
    col("i_b", "", Grid(|p| p.points.i_b[p.k]), "the pitching inertia i_B = I_y/(mc̄²) (at a physical flight condition the point's own)"),
    col("altitude", "m or ft", Grid(|p| p.points.altitude[p.k]), "the point's pressure altitude (empty where the config gives the air's ρ and a)").only(Physical),
    col("mass", "kg or slug", Grid(|p| p.points.mass[p.k]), "the point's mass").only(Physical),
    col("I_y", "kg·m² or slug·ft²", Grid(|p| p.points.i_y[p.k]), "the point's pitching moment of inertia").only(Physical),
    col("stable", "", Bool(|p| p.points.stable[p.k] == Some(true)), "Routh's test (§4)"),
    col("verdict", "", Word(|p| p.points.verdict[p.k].map_or("", |v| v.as_str())), "the overall verdict, every root judged: meets (the one-cycle standard of §8), fails, divergent; never meets where a mode grows"),
    col("sp_re", "1/τ", Number(|p| p.at(&p.points.sp_re)), "the short period's root, real part"),
    col("sp_im", "1/τ", Number(|p| p.at(&p.points.sp_im)), "the short period's root, imaginary part"),
    col("sp_cycles_to_half", "", Number(|p| p.at(&p.points.sp_cycles_to_half)), "the short period's cycles to half amplitude (eq 8)"),
    col("sp_damping_ratio", "", Number(|p| p.at(&p.points.sp_damping_ratio)), "the short period's damping ratio ζ = −r/|λ|"),
    col("sp_omega_bar", "", Number(|p| p.at(&p.points.sp_omega_bar)), "the short period's frequency parameter ω̄ = s/μ₁ (§9)"),
    col("ph_re", "1/τ", Number(|p| p.at(&p.points.ph_re)), "the phugoid's root, real part"),
    col("ph_im", "1/τ", Number(|p| p.at(&p.points.ph_im)), "the phugoid's root, imaginary part"),
    col("m_thetadot", "", Number(|p| p.at(&p.points.m_thetadot)), "the damping derivative m_θ̇"),
    col("delta_m_thetadot", "", Number(|p| p.at(&p.points.delta_m_thetadot)), "Δm_θ̇, m_θ̇'s margin over eq (41)'s m_θ̇max"),
    col("ph_damping_ratio", "", Number(|p| p.at(&p.points.ph_damping_ratio)), "the phugoid's damping ratio"),
    col("ph_period", "τ", Number(|p| p.at(&p.points.ph_period)), "the phugoid's period"),
    col("sp_level_a", "", Number(|p| p.sp_level(Category::A)), "the short period's MIL-F-8785C level in Category A (1, 2, 3, or 4 for worse than Level 3)"),
    col("sp_level_b", "", Number(|p| p.sp_level(Category::B)), "the same in Category B"),
    col("sp_level_c", "", Number(|p| p.sp_level(Category::C)), "the same in Category C"),
    col("ph_level", "", Number(|p| p.ph_level()), "the phugoid's MIL-F-8785C level (where it diverges, from its time to double in seconds: a physical flight condition)"),
    col("root1_re", "1/τ", Number(|p| finite(p.root(0).re)), "the first root, real part (the four roots: conjugates adjacent, fastest first)"),
    col("root1_im", "1/τ", Number(|p| finite(p.root(0).im)), "the first root, imaginary part"),
    col("root2_re", "1/τ", Number(|p| finite(p.root(1).re)), "the second root, real part"),
    col("root2_im", "1/τ", Number(|p| finite(p.root(1).im)), "the second root, imaginary part"),
    col("root3_re", "1/τ", Number(|p| finite(p.root(2).re)), "the third root, real part"),
    col("root3_im", "1/τ", Number(|p| finite(p.root(2).im)), "the third root, imaginary part"),
    col("root4_re", "1/τ", Number(|p| finite(p.root(3).re)), "the fourth root, real part"),
    col("root4_im", "1/τ", Number(|p| finite(p.root(3).im)), "the fourth root, imaginary part"),
    col("k_n", "", Number(|p| p.at(&p.points.k_n)), "eq (42)'s static margin K_n = −dC_m/dC_L at constant C_L·M² (from the quartic's E: with the pitching moment's change with Mach number, m_u)"),
    col("neutral_point", "M.A.C.", Number(|p| p.at(&p.points.neutral_point)), "the neutral point h_n, where m_w = 0 at constant speed (the aerodynamic centre H₀)"),
    col("static_margin_pct", "% M.A.C.", Number(|p| p.at(&p.points.static_margin_pct)), "the static margin h_n − h (positive: stable in incidence)"),
    col("v_m_s", "m/s", Number(|p| p.flight.and_then(|f| finite(f.speed))), "the speed V = M·a").only(Physical),
    col("c_l", "", Number(|p| p.flight.and_then(|f| finite(f.c_l))), "the lift coefficient C_L of level flight (eq 24)").only(Physical),
    col("tau_s", "s", Number(|p| p.seconds(1.0)), "the unit of time τ = m/(½ρSV)").only(Physical),
    col("sp_re_s", "1/s", Number(|p| p.per_second(p.points.sp_re[p.k])), "the short period's root, real part").only(Physical),
    col("sp_im_s", "1/s", Number(|p| p.per_second(p.points.sp_im[p.k])), "the short period's root, imaginary part").only(Physical),
    col("sp_natural_frequency_rad_s", "rad/s", Number(|p| p.per_second(p.points.sp_re[p.k].hypot(p.points.sp_im[p.k]))), "the short period's natural frequency ωₙ").only(Physical),
    col("sp_period_s", "s", Number(|p| p.seconds(std::f64::consts::TAU / p.points.sp_im[p.k])), "the short period's period").only(Physical),
    col("ph_re_s", "1/s", Number(|p| p.per_second(p.points.ph_re[p.k])), "the phugoid's root, real part").only(Physical),
    col("ph_im_s", "1/s", Number(|p| p.per_second(p.points.ph_im[p.k])), "the phugoid's root, imaginary part").only(Physical),
    col("ph_period_s", "s", Number(|p| p.seconds(p.points.ph_period[p.k])), "the phugoid's period").only(Physical),
    col("root1_re_s", "1/s", Number(|p| p.per_second(p.root(0).re)), "the first root, real part").only(Physical),
    col("root1_im_s", "1/s", Number(|p| p.per_second(p.root(0).im)), "the first root, imaginary part").only(Physical),
    col("root2_re_s", "1/s", Number(|p| p.per_second(p.root(1).re)), "the second root, real part").only(Physical),
    col("root2_im_s", "1/s", Number(|p| p.per_second(p.root(1).im)), "the second root, imaginary part").only(Physical),
    col("root3_re_s", "1/s", Number(|p| p.per_second(p.root(2).re)), "the third root, real part").only(Physical),
    col("root3_im_s", "1/s", Number(|p| p.per_second(p.root(2).im)), "the third root, imaginary part").only(Physical),
    col("root4_re_s", "1/s", Number(|p| p.per_second(p.root(3).re)), "the fourth root, real part").only(Physical),
    col("root4_im_s", "1/s", Number(|p| p.per_second(p.root(3).im)), "the fourth root, imaginary part").only(Physical),
    col("x_u", "", Number(|p| p.derivative(|d| d.x_u)), "the quartic's input x_u (report notation, §3)").only(Asked),
    col("x_w", "", Number(|p| p.derivative(|d| d.x_w)), "x_w").only(Asked),
    col("x_wdot", "", Number(|p| p.derivative(|d| d.x_wdot)), "x_ẇ").only(Asked),
    col("x_q", "", Number(|p| p.derivative(|d| d.x_q)), "x_q").only(Asked),
    col("z_u", "", Number(|p| p.derivative(|d| d.z_u)), "z_u").only(Asked),
    col("z_w", "", Number(|p| p.derivative(|d| d.z_w)), "z_w").only(Asked),
    col("z_wdot", "", Number(|p| p.derivative(|d| d.z_wdot)), "z_ẇ").only(Asked),
    col("z_q", "", Number(|p| p.derivative(|d| d.z_q)), "z_q").only(Asked),
    col("m_u", "", Number(|p| p.derivative(|d| d.m_u)), "m_u").only(Asked),
    col("m_w", "", Number(|p| p.derivative(|d| d.m_w)), "m_w").only(Asked),
    col("m_wdot", "", Number(|p| p.derivative(|d| d.m_wdot)), "m_ẇ").only(Asked),
    col("m_q", "", Number(|p| p.derivative(|d| d.m_q)), "m_q").only(Asked),
    col("c_l", "", Number(|p| p.derivative(|d| d.c_l)), "the quartic's input c_l, the lift coefficient").only(DerivativesNotPhysical),
    col("error", "", Value::Error, "why the point has no result (outside a theory's validity, …); empty where it has one"),
];

/// The columns of the rows of a sweep with `derivatives` asked for, at a
/// `physical` flight condition or not, in order.
pub fn columns(derivatives: bool, physical: bool) -> impl Iterator<Item = &'static Column> {
    COLUMNS
        .iter()
        .filter(move |c| c.when.holds(derivatives, physical))
}

/// Every column, one line each ([`Column::line`]): the list of `sweep
/// --help` and of the Python package's docs.
pub fn listing(derivatives: &str) -> String {
    COLUMNS
        .iter()
        .map(|c| format!("  {}\n", c.line(derivatives)))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(derivatives: bool, physical: bool) -> Vec<&'static str> {
        columns(derivatives, physical).map(|c| c.name).collect()
    }

    #[test]
    fn the_rows_columns_in_order() {
        let plain = names(false, false);
        assert_eq!(plain.len(), 5 + 28 + 1);
        assert_eq!(plain[..5], ["mach", "sweep_deg", "cg", "mu1", "i_b"]);
        assert_eq!(plain[5..8], ["stable", "verdict", "sp_re"]);
        assert_eq!(
            plain[30..],
            ["k_n", "neutral_point", "static_margin_pct", "error"]
        );
        let physical = names(true, true);
        assert_eq!(physical.len(), 8 + 28 + 18 + 12 + 1);
        assert_eq!(physical[5..8], ["altitude", "mass", "I_y"]);
        assert_eq!(physical[36..39], ["v_m_s", "c_l", "tau_s"]);
        // the derivatives are the quartic's inputs in their order, c_l
        // last and only where the flight condition does not give it
        assert_eq!(physical[54..66], Derivatives::QUARTIC_INPUTS[..12]);
        let asked = names(true, false);
        assert_eq!(asked[33..46], Derivatives::QUARTIC_INPUTS[..13]);
        // every name once in any rows
        for (d, p) in [(false, false), (true, false), (false, true), (true, true)] {
            let mut n = names(d, p);
            let len = n.len();
            n.sort_unstable();
            n.dedup();
            assert_eq!(n.len(), len, "{d} {p}");
        }
    }

    #[test]
    fn a_listing_line_has_the_name_unit_meaning_and_condition() {
        let list = listing("--derivatives");
        assert_eq!(list.lines().count(), COLUMNS.len());
        assert!(list.contains("  sp_re [1/τ]: the short period's root, real part\n"));
        assert!(list.contains(
            "  tau_s [s]: the unit of time τ = m/(½ρSV); at a physical flight condition\n"
        ));
        assert!(list.contains("  m_q: m_q; with --derivatives\n"));
    }
}
