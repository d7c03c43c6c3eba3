//! Stability tests and standards: Routh's test (§4), the report's damping
//! standard (§8, eq 41), static and manoeuvre margins (§9, eq 42) and the
//! MIL-F-8785C damping levels.

pub use crate::dynamics::modes::CYCLES_CONSTANT;
pub mod cap;

use crate::dynamics::modes::{Mode, ModeName, Modes, Origin};
use crate::{Derivatives, Quartic};
use serde::Serialize;

/// The limit of §8 without the report's s ≈ √C: B = 2√(C/(1 + (2π/ln 2)²))
/// = 0.21930·√C takes the pair λ² + Bλ + C exactly one cycle to halve
/// (with k = ln 2/2π, r = −B/2 and s = √(C − B²/4), k·s/(−r) = 1 gives
/// B = 2k√C/√(1 + k²)).
fn one_cycle_exact() -> f64 {
    let k = CYCLES_CONSTANT;
    2.0 * k / (1.0 + k * k).sqrt()
}

// ------------------------------------------------------------------ §4 Routh

/// Routh's test of §4.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Routh {
    /// R = BCD − AD² − B²E (±inf or 0 where it leaves f64's range; its
    /// sign is exact even then).
    pub discriminant: f64,
    /// All of A, B, C, D, E and R have the same (strict) sign.
    pub stable: bool,
    /// |R| is within its rounding error (8ε·(|BCD| + |AD²| + |B²E|)) of
    /// zero: the motion is on the stability boundary to working precision,
    /// and `stable` may go either way with the coefficients' last bits.
    pub marginal: bool,
}

impl Routh {
    /// §4: "the necessary and sufficient conditions for stability are that
    /// all coefficients of the quartic and in addition Routh's discriminant
    /// R = BCD − AD² − B²E must be of the same sign".
    ///
    /// R's three products are formed with an exponent of their own
    /// (`roots::binary::Wide`), so that neither overflow nor underflow can
    /// change its sign: R is homogeneous (R(ρ⁴A, ρ³B, ρ²C, ρD, E) = ρ⁶R),
    /// so its sign is the same at every scale at which the roots are
    /// found, and the verdict agrees with them.
    pub fn of(q: &Quartic) -> Routh {
        let (sum, abs, r) = Routh::discriminant(q);
        let sign = |x: f64| {
            if x > 0.0 {
                1
            } else if x < 0.0 {
                -1
            } else {
                0
            }
        };
        let s = sign(sum);
        let all = [q.a, q.b, q.c, q.d, q.e].map(sign);
        let stable = s != 0 && all.iter().all(|&x| x == s);
        Routh {
            discriminant: r,
            stable,
            marginal: sum.abs() <= 8.0 * f64::EPSILON * abs,
        }
    }

    /// R = BCD − AD² − B²E and Σ|terms| on a common scale 2^k, and R
    /// itself: in plain f64 when every coefficient is zero or within
    /// 1e±90 (no product of three can leave f64's range, and the result is
    /// the same to the bit), else with `Wide` numbers.
    fn discriminant(q: &Quartic) -> (f64, f64, f64) {
        use crate::numerics::roots::binary::{Wide, ldexp};
        let in_range = |x: f64| x == 0.0 || (1e-90..1e90).contains(&x.abs());
        if q.to_array().iter().all(|&x| in_range(x)) {
            let t = [q.b * q.c * q.d, -q.a * q.d * q.d, -q.b * q.b * q.e];
            let r = t[0] + t[1] + t[2];
            return (r, t[0].abs() + t[1].abs() + t[2].abs(), r);
        }
        let [a, b, c, d, e] = q.to_array().map(Wide::new);
        let minus = Wide::new(-1.0);
        let terms = [
            b.mul(c).mul(d),
            minus.mul(a).mul(d).mul(d),
            minus.mul(b).mul(b).mul(e),
        ];
        let (sum, abs, exp) = Wide::sum(&terms);
        (sum, abs, ldexp(sum, exp))
    }
}

// --------------------------------------------------- §8 the damping standard

/// The short-period approximations of §8 and §9.
///
/// Neglecting x_u, z_ẇ/μ₁ and z_q/μ₁ (and the couplings with u), B and C of
/// eq (6) reduce to the short-period pair's
/// `B ≈ −z_w − m_θ̇/i_B` and `C ≈ (m_q z_w − μ₁m_w)/i_B`, with
/// m_θ̇ = m_q + m_ẇ; then λ² + Bλ + C = 0 gives the short period, and
/// eq (7)–(8) with s ≈ √C give the report's
/// `cycles to half amplitude ≈ 0.2206·√((m_q z_w − μ₁m_w)/i_B) / (−z_w − m_θ̇/i_B)`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ShortPeriodApproximation {
    /// −z_w − m_θ̇/i_B.
    #[serde(rename = "B")]
    pub b: f64,
    /// (m_q z_w − μ₁ m_w)/i_B.
    #[serde(rename = "C")]
    pub c: f64,
    /// The root r + is of λ² + bλ + c (s ≥ 0; s = 0 when the pair is real).
    pub re: f64,
    pub im: f64,
    /// §8: 0.2206·√c/b (s ≈ √C), when c > 0 and b > 0.
    pub cycles_to_half_report: Option<f64>,
    /// 0.11032·s/(−r) with the pair's exact s, when it decays.
    pub cycles_to_half: Option<f64>,
    /// §9 / Fig 32: ω̄ ≈ √(−m_w/(μ₁ i_B)), when m_w < 0.
    pub frequency_parameter: Option<f64>,
}

impl ShortPeriodApproximation {
    pub fn of(d: &Derivatives) -> Self {
        let m_thetadot = d.m_q + d.m_wdot;
        let b = -d.z_w - m_thetadot / d.i_b;
        let c = (d.m_q * d.z_w - d.mu1 * d.m_w) / d.i_b;
        let disc = c - b * b / 4.0;
        let (re, im) = if disc >= 0.0 {
            (-b / 2.0, disc.sqrt())
        } else {
            // Two real roots: report the slower (the one that decides decay).
            let root = disc.abs().sqrt();
            let slow = if b >= 0.0 {
                -b / 2.0 + root
            } else {
                -b / 2.0 - root
            };
            (slow, 0.0)
        };
        let cycles_to_half_report =
            (c > 0.0 && b > 0.0).then(|| 2.0 * CYCLES_CONSTANT * c.sqrt() / b);
        let cycles_to_half = (im > 0.0 && re < 0.0).then(|| CYCLES_CONSTANT * im / -re);
        let frequency_parameter = (d.m_w < 0.0).then(|| (-d.m_w / (d.mu1 * d.i_b)).sqrt());
        ShortPeriodApproximation {
            b,
            c,
            re,
            im,
            cycles_to_half_report,
            cycles_to_half,
            frequency_parameter,
        }
    }
}

/// The damping standard of §8: the short period must damp to half amplitude
/// in one cycle.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DampingStandard {
    /// m_θ̇ = m_q + m_ẇ.
    pub m_thetadot: f64,
    /// Eq (41): m_θ̇max ≈ −z_w i_B − 0.2206·√(i_B(m_q z_w − μ₁m_w)).
    pub m_thetadot_max: Option<f64>,
    /// Δm_θ̇ = m_θ̇max − m_θ̇: positive when the standard is met (§8).
    pub margin: Option<f64>,
    /// The same limit without the report's s ≈ √C: the m_θ̇ at which the
    /// pair λ² + Bλ + C of §8 takes exactly one cycle to halve,
    /// B = 2√(C/(1 + (2π/ln 2)²)) = 0.21930·√C.
    pub m_thetadot_max_exact: Option<f64>,
    pub margin_exact: Option<f64>,
}

impl DampingStandard {
    pub fn of(d: &Derivatives) -> Self {
        let m_thetadot = d.m_q + d.m_wdot;
        let g = d.i_b * (d.m_q * d.z_w - d.mu1 * d.m_w);
        let (max, max_exact) = if g >= 0.0 {
            (
                Some(-d.z_w * d.i_b - 2.0 * CYCLES_CONSTANT * g.sqrt()),
                Some(-d.z_w * d.i_b - one_cycle_exact() * g.sqrt()),
            )
        } else {
            (None, None)
        };
        DampingStandard {
            m_thetadot,
            m_thetadot_max: max,
            margin: max.map(|m| m - m_thetadot),
            m_thetadot_max_exact: max_exact,
            margin_exact: max_exact.map(|m| m - m_thetadot),
        }
    }
}

/// The §8 standard, "damp to half amplitude in less than one cycle",
/// applied to the short period: the one verdict that `quartic`, `sweep`,
/// `report` and every JSON output report.
///
/// - An oscillatory short period r ± is meets it when it decays (r < 0) and
///   its cycles to half amplitude, 0.11032·s/(−r) (eq 8), are at most one;
///   it fails when it decays more slowly or is neutral (r = 0: it never
///   halves); it is divergent when r > 0.
/// - A short period split into two real roots has no cycle to count: it
///   meets the standard when both roots decay (the motion halves before
///   completing any cycle), fails when one is neutral (a zero root), and is
///   divergent when one grows. Only the short period's own roots count: a
///   divergent phugoid is not a short-period verdict.
/// - With four real roots the two of largest modulus are taken as the
///   short period's.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    Meets,
    Fails,
    Divergent,
}

impl Verdict {
    /// The verdict of a set of modes (see the type's documentation).
    pub fn of(modes: &Modes) -> Verdict {
        if let Some(sp) = modes.short_period() {
            return Verdict::of_oscillatory(sp);
        }
        let mut remnant = modes
            .iter()
            .filter(|m| m.name == ModeName::Aperiodic)
            .filter(|m| matches!(m.origin, Some(Origin::ShortPeriod) | Some(Origin::Unknown)));
        // Four reals (origin unknown) are sorted fastest first: the short
        // period's are the first two.
        let (first, second) = (remnant.next(), remnant.next());
        [first, second]
            .into_iter()
            .flatten()
            .map(|m| Verdict::of_decay(m.re))
            .max()
            .unwrap_or(Verdict::Meets)
    }

    fn of_oscillatory(sp: &Mode) -> Verdict {
        match Verdict::of_decay(sp.re) {
            Verdict::Meets => match sp.cycles_to_half {
                Some(c) if c <= 1.0 => Verdict::Meets,
                _ => Verdict::Fails,
            },
            other => other,
        }
    }

    /// A real part's contribution: decaying, neutral or growing.
    fn of_decay(re: f64) -> Verdict {
        if re > 0.0 {
            Verdict::Divergent
        } else if re == 0.0 {
            Verdict::Fails
        } else {
            Verdict::Meets
        }
    }

    /// `meets`, `fails`, `divergent` (the CSV and JSON spelling).
    pub fn as_str(self) -> &'static str {
        match self {
            Verdict::Meets => "meets",
            Verdict::Fails => "fails",
            Verdict::Divergent => "divergent",
        }
    }

    /// Whether the standard is met.
    pub fn is_met(self) -> bool {
        self == Verdict::Meets
    }
}

// ----------------------------------------------------------- §9 the margins

/// Static margin from E, eq (42): `E = 2(μ₁/i_B)·C_L²·a·K_n`, a = ∂C_L/∂α.
pub fn static_margin_from_e(e: f64, d: &Derivatives, lift_slope: f64) -> Option<f64> {
    let den = 2.0 * d.mu1 / d.i_b * d.c_l * d.c_l * lift_slope;
    (den != 0.0 && den.is_finite()).then(|| e / den)
}

/// E from the static margin, eq (42).
pub fn e_from_static_margin(k_n: f64, d: &Derivatives, lift_slope: f64) -> f64 {
    2.0 * d.mu1 / d.i_b * d.c_l * d.c_l * lift_slope * k_n
}

/// Manoeuvre margin from C (§9, "with some approximation"):
/// `C ≈ (μ₁/i_B)·a·H_m`.
///
/// The report prints `C = −(μ₁/i_B)(∂C_L/∂α)H_m`; with C ≈ (m_q z_w −
/// μ₁m_w)/i_B, z_w ≈ −a and H_m = −m_w/a − m_q/μ₁ (the stick-fixed
/// manoeuvre margin, positive when stable), the sign is `+`: a stable
/// aircraft has C > 0 and H_m > 0.
pub fn manoeuvre_margin_from_c(c: f64, d: &Derivatives, lift_slope: f64) -> Option<f64> {
    let den = d.mu1 / d.i_b * lift_slope;
    (den != 0.0 && den.is_finite()).then(|| c / den)
}

/// C from the manoeuvre margin (§9).
pub fn c_from_manoeuvre_margin(h_m: f64, d: &Derivatives, lift_slope: f64) -> f64 {
    d.mu1 / d.i_b * lift_slope * h_m
}

/// The stick-fixed neutral point at constant speed, and the static margin
/// of the c.g. ahead of it.
///
/// Moving the c.g. aft by Δh (fractions of the M.A.C.) transfers the
/// normal force's moment to it: m_w grows by −z_w·Δh (eq 14: m_w =
/// (h − H₀)(a + C_D) with z_w = −(a + C_D), eq 12). So m_w vanishes at
///
///   h_n = h + m_w/z_w,
///
/// the neutral point — for the wing alone its aerodynamic centre H₀ — and
/// the static margin is h_n − h, the distance of the c.g. ahead of it,
/// here in per cent of the M.A.C. (positive: statically stable in
/// incidence). Unlike eq (42)'s K_n = −(dC_m/dC_L) at constant C_L·M²,
/// which [`static_margin_from_e`] recovers from the quartic's E, this
/// holds the speed fixed: K_n includes the change of the pitching moment
/// with Mach number along the level-flight line (m_u, Mach tuck: through
/// E = (μ₁/i_B)C_L(m_w z_u − z_w m_u)), so it is zero at h_n only where
/// m_u = 0 there (H₀ independent of Mach number).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct NeutralPoint {
    /// h_n, a fraction of the M.A.C. aft of its leading edge (as h).
    pub neutral_point: f64,
    /// h_n − h, per cent of the M.A.C.
    pub static_margin_pct: f64,
}

impl NeutralPoint {
    /// The neutral point and static margin of a derivative set at c.g.
    /// `h`; `None` where z_w = 0 (no normal force: no neutral point) or a
    /// value is not finite.
    pub fn of(d: &Derivatives, h: f64) -> Option<NeutralPoint> {
        let neutral_point = h + d.m_w / d.z_w;
        let static_margin_pct = 100.0 * (neutral_point - h);
        (d.z_w != 0.0 && neutral_point.is_finite() && static_margin_pct.is_finite()).then_some(
            NeutralPoint {
                neutral_point,
                static_margin_pct,
            },
        )
    }
}

/// The margins of §9 from the quartic's coefficients, and where the c.g.
/// is known the neutral point and static margin ([`NeutralPoint`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Margins {
    /// K_n (stick fixed), eq (42): −dC_m/dC_L at constant C_L·M², from E
    /// (it includes the Mach-number terms, m_u).
    pub static_margin: Option<f64>,
    /// H_m (stick fixed), §9.
    pub manoeuvre_margin: Option<f64>,
    /// h_n, where m_w = 0 (fraction of the M.A.C.; [`NeutralPoint`]).
    pub neutral_point: Option<f64>,
    /// h_n − h, per cent of the M.A.C.
    pub static_margin_pct: Option<f64>,
}

impl Margins {
    /// K_n and H_m (the c.g. unknown: no neutral point).
    pub fn of(q: &Quartic, d: &Derivatives, lift_slope: f64) -> Self {
        Margins {
            static_margin: static_margin_from_e(q.e, d, lift_slope),
            manoeuvre_margin: manoeuvre_margin_from_c(q.c, d, lift_slope),
            neutral_point: None,
            static_margin_pct: None,
        }
    }

    /// K_n, H_m, and the neutral point and static margin at c.g. `h`.
    pub fn at_cg(q: &Quartic, d: &Derivatives, lift_slope: f64, h: f64) -> Self {
        let n = NeutralPoint::of(d, h);
        Margins {
            neutral_point: n.map(|n| n.neutral_point),
            static_margin_pct: n.map(|n| n.static_margin_pct),
            ..Margins::of(q, d, lift_slope)
        }
    }
}

// ------------------------------------------------------------- MIL-F-8785C

/// MIL-F-8785C flight-phase categories (§1.5): A non-terminal, rapid
/// manoeuvring or precise tracking; B non-terminal, gradual; C terminal
/// (take-off, approach, landing).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Category {
    A,
    B,
    C,
}

/// A flying-qualities level: 1 (adequate), 2 (adequate with increased
/// workload), 3 (controllable), or worse than 3.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Level {
    One,
    Two,
    Three,
    WorseThanThree,
}

impl Level {
    /// 1, 2, 3, or 4 for worse than Level 3 (a sweep's column).
    pub fn number(self) -> u8 {
        match self {
            Level::One => 1,
            Level::Two => 2,
            Level::Three => 3,
            Level::WorseThanThree => 4,
        }
    }

    pub fn as_str(self) -> &'static str {
        match self {
            Level::One => "Level 1",
            Level::Two => "Level 2",
            Level::Three => "Level 3",
            Level::WorseThanThree => "worse than Level 3",
        }
    }
}

impl Serialize for Level {
    /// As [`Level::as_str`]: `"Level 1"` … `"worse than Level 3"`.
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.as_str())
    }
}

/// MIL-F-8785C §3.2.2.1.2, Table IV: the short-period damping-ratio
/// limits (ζ_min, ζ_max) of each level. Category A and C: Level 1 0.35–1.30,
/// Level 2 0.25–2.00; Category B: Level 1 0.30–2.00, Level 2 0.20–2.00;
/// Level 3: ζ ≥ 0.15.
pub fn short_period_level(zeta: f64, category: Category) -> Level {
    let (l1, l2) = match category {
        Category::A | Category::C => ((0.35, 1.30), (0.25, 2.00)),
        Category::B => ((0.30, 2.00), (0.20, 2.00)),
    };
    let within = |(lo, hi): (f64, f64)| zeta >= lo && zeta <= hi;
    if within(l1) {
        Level::One
    } else if within(l2) {
        Level::Two
    } else if zeta >= 0.15 {
        Level::Three
    } else {
        Level::WorseThanThree
    }
}

/// MIL-F-8785C §3.2.1.2: phugoid stability. Level 1 ζ ≥ 0.04, Level 2
/// ζ ≥ 0, Level 3 time to double amplitude ≥ 55 s. `time_to_double_s` is
/// needed only when ζ < 0 (a real divergent root has ζ = −1).
pub fn phugoid_level(zeta: f64, time_to_double_s: Option<f64>) -> Level {
    if zeta >= 0.04 {
        Level::One
    } else if zeta >= 0.0 {
        Level::Two
    } else if time_to_double_s.is_some_and(|t| t >= 55.0) {
        Level::Three
    } else {
        Level::WorseThanThree
    }
}

/// The short period's MIL-F-8785C levels in the three flight-phase
/// categories.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ShortPeriodLevels {
    pub damping_ratio: f64,
    #[serde(rename = "A")]
    pub a: Level,
    #[serde(rename = "B")]
    pub b: Level,
    #[serde(rename = "C")]
    pub c: Level,
}

/// The phugoid's MIL-F-8785C level.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PhugoidLevel {
    pub damping_ratio: f64,
    pub level: Level,
}

/// The MIL-F-8785C levels of a set of modes: the short period's (when it
/// oscillates) and the phugoid's (when it oscillates; a divergent one needs
/// τ in seconds for its time to double).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FlyingQualities {
    pub short_period: Option<ShortPeriodLevels>,
    pub phugoid: Option<PhugoidLevel>,
}

impl FlyingQualities {
    /// The levels of `modes`, with τ in seconds when known.
    pub fn of(modes: &Modes, tau: Option<f64>) -> FlyingQualities {
        let short_period =
            modes
                .short_period()
                .and_then(|m| m.damping_ratio)
                .map(|z| ShortPeriodLevels {
                    damping_ratio: z,
                    a: short_period_level(z, Category::A),
                    b: short_period_level(z, Category::B),
                    c: short_period_level(z, Category::C),
                });
        let phugoid = modes.phugoid().and_then(|m| {
            let t2 = tau.and_then(|t| m.time_to_double.map(|x| x * t));
            m.damping_ratio.map(|z| PhugoidLevel {
                damping_ratio: z,
                level: phugoid_level(z, t2),
            })
        });
        FlyingQualities {
            short_period,
            phugoid,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn delta() -> Derivatives {
        crate::design::examples::tailless_delta_45()
    }

    #[test]
    fn routh_of_a_product_of_stable_quadratics() {
        // (λ² + 2λ + 5)(λ² + 0.1λ + 0.2): A=1, B=2.1, C=5.4, D=0.9, E=1;
        // R = 2.1·5.4·0.9 − 0.81 − 4.41 = 4.986.
        let q = Quartic::from_array([1.0, 2.1, 5.4, 0.9, 1.0]);
        let r = Routh::of(&q);
        assert!((r.discriminant - 4.986).abs() < 1e-12);
        assert!(r.stable);
        // (λ² − 0.1λ + 5)(λ² + 2λ + 1): B = 1.9, C = 5.8, D = 9.9, E = 5;
        // R = 1.9·5.8·9.9 − 98.01 − 18.05 = −6.962 < 0.
        let q = Quartic::from_array([1.0, 1.9, 5.8, 9.9, 5.0]);
        let r = Routh::of(&q);
        assert!((r.discriminant + 6.962).abs() < 1e-9);
        assert!(!r.stable);
    }

    #[test]
    fn eq41_limit_gives_one_cycle_in_the_report_approximation() {
        let mut d = delta();
        let std = DampingStandard::of(&d);
        let max = std.m_thetadot_max.unwrap();
        // Put m_θ̇ at the limit (through m_ẇ, which leaves C unchanged):
        d.m_wdot = max - d.m_q;
        let approx = ShortPeriodApproximation::of(&d);
        assert!((approx.cycles_to_half_report.unwrap() - 1.0).abs() < 1e-12);
        // and the exact second-order limit gives exactly one cycle:
        let mut d2 = delta();
        d2.m_wdot = std.m_thetadot_max_exact.unwrap() - d2.m_q;
        let approx2 = ShortPeriodApproximation::of(&d2);
        assert!((approx2.cycles_to_half.unwrap() - 1.0).abs() < 1e-12);
    }

    #[test]
    fn short_period_approximation_by_hand() {
        let d = delta();
        let a = ShortPeriodApproximation::of(&d);
        // B = 3.2 + 0.85/0.08 = 13.825; C = (1.92 + 27.5)/0.08 = 367.75
        assert!((a.b - 13.825).abs() < 1e-12);
        assert!((a.c - 367.75).abs() < 1e-10);
        assert!(
            (a.cycles_to_half_report.unwrap() - 0.2206356 * 367.75f64.sqrt() / 13.825).abs() < 1e-6
        );
    }

    #[test]
    fn margins_round_trip() {
        let d = delta();
        let e = e_from_static_margin(0.12, &d, 3.0);
        assert!((static_margin_from_e(e, &d, 3.0).unwrap() - 0.12).abs() < 1e-15);
        let c = c_from_manoeuvre_margin(0.2, &d, 3.0);
        assert!((manoeuvre_margin_from_c(c, &d, 3.0).unwrap() - 0.2).abs() < 1e-15);
    }

    #[test]
    fn eq42_from_the_expansion_of_e() {
        // With m_u = 0 and z_u = −2C_L (no Mach effect): E = −2(μ₁/i_B)C_L²m_w,
        // and m_w = −a·K_n, so K_n = E·i_B/(2μ₁C_L²a) recovers it.
        let mut d = delta();
        d.z_u = -2.0 * d.c_l;
        let a = 3.0;
        d.m_w = -a * 0.1;
        let q = Quartic::from_derivatives(&d);
        assert!((static_margin_from_e(q.e, &d, a).unwrap() - 0.1).abs() < 1e-14);
    }

    fn verdict_of_roots(roots: [(f64, f64); 4]) -> Verdict {
        let roots = roots.map(|(re, im)| num_complex::Complex64::new(re, im));
        Verdict::of(&Modes::identify(&roots, 50.0))
    }

    #[test]
    fn one_verdict_for_every_short_period() {
        let ph = [(-0.01, 0.05), (-0.01, -0.05)];
        let with = |sp: [(f64, f64); 2], ph: [(f64, f64); 2]| {
            verdict_of_roots([sp[0], sp[1], ph[0], ph[1]])
        };
        // (ln 2/2π)·s/(−r) = 1 at s/(−r) = 2π/ln 2 = 9.0647: either side of it
        assert_eq!(with([(-1.0, 9.0), (-1.0, -9.0)], ph), Verdict::Meets);
        assert_eq!(with([(-1.0, 9.1), (-1.0, -9.1)], ph), Verdict::Fails);
        // neutral (r = 0) never halves: fails, not divergent, not met
        assert_eq!(with([(0.0, 9.0), (0.0, -9.0)], ph), Verdict::Fails);
        assert_eq!(with([(0.1, 9.0), (0.1, -9.0)], ph), Verdict::Divergent);
        // a split short period: both decay → meets; one grows → divergent;
        // a zero root → fails
        assert_eq!(with([(-3.0, 0.0), (-0.8, 0.0)], ph), Verdict::Meets);
        assert_eq!(with([(-3.0, 0.0), (0.8, 0.0)], ph), Verdict::Divergent);
        assert_eq!(with([(-3.0, 0.0), (0.0, 0.0)], ph), Verdict::Fails);
        // a divergent phugoid beside a split, decaying short period is not
        // a short-period divergence
        let growing_ph = [(0.01, 0.05), (0.01, -0.05)];
        assert_eq!(with([(-3.0, 0.0), (-0.8, 0.0)], growing_ph), Verdict::Meets);
        // nor beside an oscillatory one
        assert_eq!(
            with([(-1.0, 5.0), (-1.0, -5.0)], growing_ph),
            Verdict::Meets
        );
        // four reals: the two fastest are the short period's
        assert_eq!(
            verdict_of_roots([(-3.0, 0.0), (-2.0, 0.0), (0.01, 0.0), (-0.02, 0.0)]),
            Verdict::Meets
        );
        assert_eq!(
            verdict_of_roots([(-3.0, 0.0), (2.0, 0.0), (-0.01, 0.0), (-0.02, 0.0)]),
            Verdict::Divergent
        );
    }

    #[test]
    fn mil_levels() {
        assert_eq!(short_period_level(0.5, Category::A), Level::One);
        assert_eq!(short_period_level(0.3, Category::A), Level::Two);
        assert_eq!(short_period_level(0.3, Category::B), Level::One);
        assert_eq!(short_period_level(1.5, Category::C), Level::Two);
        assert_eq!(short_period_level(0.16, Category::B), Level::Three);
        assert_eq!(short_period_level(0.1, Category::B), Level::WorseThanThree);
        assert_eq!(short_period_level(2.5, Category::B), Level::Three);
        assert_eq!(phugoid_level(0.05, None), Level::One);
        assert_eq!(phugoid_level(0.01, None), Level::Two);
        assert_eq!(phugoid_level(-0.01, Some(60.0)), Level::Three);
        assert_eq!(phugoid_level(-0.01, Some(30.0)), Level::WorseThanThree);
    }
}
