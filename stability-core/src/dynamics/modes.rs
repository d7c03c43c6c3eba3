//! The modes of motion from the quartic's roots (§4, eq 8; §9's ω̄).
//!
//! The roots are in units of 1/τ (τ = m/(½ρSV), §3). Two complex pairs are
//! the short-period oscillation (the faster pair) and the phugoid (the
//! slower); either may split into two real roots, which are reported as
//! aperiodic modes. For a root λ = r ± is:
//!
//! - period `2π/s` (τ units);
//! - time to half amplitude `ln 2/(−r)` when r < 0 (time to double
//!   amplitude `ln 2/r` when r > 0);
//! - cycles to half amplitude `(ln 2/2π)·s/(−r) = 0.11032·s/(−r)` (eq 8);
//! - damping ratio `ζ = −r/|λ|`, undamped frequency `ωₙ = |λ|`;
//! - frequency parameter `ω̄ = 2πf·c̄/V = s/μ₁` (§9), since f = s/(2πτ)
//!   and τ·V/c̄ = μ₁.

use arrayvec::ArrayVec;
use num_complex::Complex64;
use serde::Serialize;
use std::f64::consts::{LN_2, PI};

/// The report's constant of eq (8): cycles to half amplitude =
/// 0.11032·s/(−r); exactly ln 2/(2π), the ratio of the time to half
/// amplitude ln 2/(−r) to the period 2π/s per unit s/(−r).
pub const CYCLES_CONSTANT: f64 = LN_2 / (2.0 * PI);

/// Which motion a root (or pair) is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ModeName {
    /// The faster oscillatory pair.
    ShortPeriod,
    /// The slower oscillatory pair (the report's "long period" mode).
    Phugoid,
    /// A real root.
    Aperiodic,
}

/// The axis of the rigid aircraft's motion a mode belongs to. The
/// program solves the longitudinal (pitch-plane) equations, eqs (2)–(4);
/// the lateral-directional axis (sideslip, roll and yaw: Dutch roll, roll
/// and spiral modes) is to come beside it (`dynamics::lateral`), its modes
/// named and judged on their own axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Axis {
    /// The pitch plane: the short period, the phugoid.
    Longitudinal,
}

impl ModeName {
    /// The axis of the mode.
    pub fn axis(self) -> Axis {
        match self {
            ModeName::ShortPeriod | ModeName::Phugoid | ModeName::Aperiodic => Axis::Longitudinal,
        }
    }

    /// The name in a table: "short period", "phugoid", or for a root of a
    /// pair that split "aperiodic (sp)", "aperiodic (ph)", "aperiodic (?)".
    pub fn label(self, origin: Option<Origin>) -> String {
        match (self, origin) {
            (ModeName::Aperiodic, Some(o)) => format!(
                "aperiodic ({})",
                match o {
                    Origin::ShortPeriod => "sp",
                    Origin::Phugoid => "ph",
                    Origin::Unknown => "?",
                }
            ),
            (name, _) => name.as_str().replace('_', " "),
        }
    }

    pub fn as_str(self) -> &'static str {
        match self {
            ModeName::ShortPeriod => "short_period",
            ModeName::Phugoid => "phugoid",
            ModeName::Aperiodic => "aperiodic",
        }
    }
}

/// What an aperiodic root is the remnant of.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Origin {
    /// The short-period pair split into two real roots.
    ShortPeriod,
    /// The phugoid split into two real roots.
    Phugoid,
    /// All four roots are real.
    Unknown,
}

/// One mode: an oscillatory pair (represented by its root with s > 0) or a
/// real root. Quantities in units of τ; `None` where undefined.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Mode {
    pub name: ModeName,
    /// For an aperiodic root, the pair it came from.
    pub origin: Option<Origin>,
    /// r (1/τ).
    pub re: f64,
    /// s ≥ 0 (1/τ); 0 for a real root.
    pub im: f64,
    /// 2π/s (τ), oscillatory modes only.
    pub period: Option<f64>,
    /// ln 2/(−r) (τ) when the mode decays.
    pub time_to_half: Option<f64>,
    /// ln 2/r (τ) when the mode grows.
    pub time_to_double: Option<f64>,
    /// 0.11032·s/(−r), eq (8): oscillatory and decaying modes.
    pub cycles_to_half: Option<f64>,
    /// 0.11032·s/r: oscillatory and growing modes.
    pub cycles_to_double: Option<f64>,
    /// ζ = −r/|λ| (zero roots: undefined).
    pub damping_ratio: Option<f64>,
    /// ωₙ = |λ| (1/τ).
    pub natural_frequency: f64,
    /// ω̄ = s/μ₁ = 2πf·c̄/V (§9), oscillatory modes only.
    pub frequency_parameter: Option<f64>,
}

impl Mode {
    /// The mode's name in a table ([`ModeName::label`]).
    pub fn label(&self) -> String {
        self.name.label(self.origin)
    }

    /// The mode of root `lam` (its conjugate is implied), named `name`.
    pub fn of_root(lam: Complex64, name: ModeName, origin: Option<Origin>, mu1: f64) -> Mode {
        let r = lam.re;
        let s = lam.im.abs();
        let wn = modulus(lam);
        let oscillatory = s > 0.0;
        let positive = |x: f64| (x.is_finite() && x > 0.0).then_some(x);
        Mode {
            name,
            origin,
            re: r,
            im: s,
            period: if oscillatory {
                positive(2.0 * PI / s)
            } else {
                None
            },
            time_to_half: if r < 0.0 { positive(LN_2 / -r) } else { None },
            time_to_double: if r > 0.0 { positive(LN_2 / r) } else { None },
            cycles_to_half: if oscillatory && r < 0.0 {
                positive(CYCLES_CONSTANT * s / -r)
            } else {
                None
            },
            cycles_to_double: if oscillatory && r > 0.0 {
                positive(CYCLES_CONSTANT * s / r)
            } else {
                None
            },
            damping_ratio: if wn > 0.0 { Some(-r / wn) } else { None },
            natural_frequency: wn,
            frequency_parameter: if oscillatory && mu1 > 0.0 {
                positive(s / mu1)
            } else {
                None
            },
        }
    }

    /// Whether the mode grows (r > 0).
    pub fn is_divergent(&self) -> bool {
        self.re > 0.0
    }

    /// The mode's rates and times, in its own unit.
    pub fn times(&self) -> ModeTimes {
        ModeTimes {
            re: self.re,
            im: self.im,
            period: self.period,
            time_to_half: self.time_to_half,
            time_to_double: self.time_to_double,
            natural_frequency: self.natural_frequency,
        }
    }

    /// The same mode's rates and times in seconds, given τ in seconds.
    pub fn in_seconds(&self, tau: f64) -> ModeTimes {
        self.times().in_units_of(tau)
    }
}

/// A mode's rates and times in one unit of time: 1/τ and τ, or 1/s and s.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ModeTimes {
    pub re: f64,
    pub im: f64,
    pub period: Option<f64>,
    pub time_to_half: Option<f64>,
    pub time_to_double: Option<f64>,
    pub natural_frequency: f64,
}

impl ModeTimes {
    /// The same in a unit of time `unit` times the present one long (τ in
    /// seconds turns τ units into seconds; 1/τ turns seconds into τ):
    /// rates divided by it, times multiplied.
    pub fn in_units_of(self, unit: f64) -> ModeTimes {
        ModeTimes {
            re: self.re / unit,
            im: self.im / unit,
            period: self.period.map(|p| p * unit),
            time_to_half: self.time_to_half.map(|t| t * unit),
            time_to_double: self.time_to_double.map(|t| t * unit),
            natural_frequency: self.natural_frequency / unit,
        }
    }
}

/// |λ| as √(re² + im²), within an ulp of `hypot` at a fraction of its
/// cost; `hypot` only where the squares overflow or underflow.
fn modulus(z: Complex64) -> f64 {
    let n2 = z.norm_sqr();
    if n2.is_finite() && n2 >= f64::MIN_POSITIVE {
        n2.sqrt()
    } else {
        z.norm()
    }
}

/// The modes of a quartic, fastest first: two to four (a complex pair
/// counts once), held inline — identifying them allocates nothing.
#[derive(Debug, Clone, PartialEq)]
pub struct Modes(ArrayVec<Mode, 4>);

impl Serialize for Modes {
    /// As the list of modes.
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(self.iter())
    }
}

impl std::ops::Deref for Modes {
    type Target = [Mode];
    fn deref(&self) -> &[Mode] {
        &self.0
    }
}

impl Modes {
    /// The modes, fastest first.
    pub fn as_slice(&self) -> &[Mode] {
        &self.0
    }

    /// Identify the modes of the four roots (any order; complex roots come in
    /// conjugate pairs). `mu1` converts s to the frequency parameter.
    ///
    /// Two pairs: the pair of larger modulus is the short period. One pair
    /// and two reals: the pair is the short period if its modulus exceeds
    /// both reals' (the phugoid has split), else the phugoid (the short
    /// period has split). Four reals: aperiodic, origin unknown.
    pub fn identify(roots: &[Complex64; 4], mu1: f64) -> Modes {
        let zero = Complex64::new(0.0, 0.0);
        let (mut pairs, mut np) = ([zero; 4], 0);
        let (mut reals, mut nr) = ([0.0; 4], 0);
        for z in roots {
            if z.im > 0.0 {
                pairs[np] = *z;
                np += 1;
            } else if z.im == 0.0 {
                reals[nr] = z.re;
                nr += 1;
            }
        }
        let (pairs, reals) = (&mut pairs[..np], &mut reals[..nr]);
        pairs.sort_unstable_by(|a, b| modulus(*b).total_cmp(&modulus(*a)));
        reals.sort_unstable_by(|a, b| b.abs().total_cmp(&a.abs()));
        // at most four roots, so at most four modes: pushes cannot fail
        let mut modes = ArrayVec::<Mode, 4>::new();
        let aperiodic = |r: f64, origin| {
            Mode::of_root(
                Complex64::new(r, 0.0),
                ModeName::Aperiodic,
                Some(origin),
                mu1,
            )
        };
        match *pairs {
            [sp, ph] => {
                modes.push(Mode::of_root(sp, ModeName::ShortPeriod, None, mu1));
                modes.push(Mode::of_root(ph, ModeName::Phugoid, None, mu1));
            }
            [pair] => {
                let pair_is_fast = reals.iter().all(|r| modulus(pair) >= r.abs());
                let (name, origin) = if pair_is_fast {
                    (ModeName::ShortPeriod, Origin::Phugoid)
                } else {
                    (ModeName::Phugoid, Origin::ShortPeriod)
                };
                let pair_mode = Mode::of_root(pair, name, None, mu1);
                if pair_is_fast {
                    modes.push(pair_mode);
                }
                for &r in reals.iter() {
                    modes.push(aperiodic(r, origin));
                }
                if !pair_is_fast {
                    modes.push(pair_mode);
                }
            }
            _ => {
                for &r in reals.iter() {
                    modes.push(aperiodic(r, Origin::Unknown));
                }
            }
        }
        Modes(modes)
    }

    /// The short-period mode, if the short period is oscillatory.
    pub fn short_period(&self) -> Option<&Mode> {
        self.iter().find(|m| m.name == ModeName::ShortPeriod)
    }

    /// The phugoid, if it is oscillatory.
    pub fn phugoid(&self) -> Option<&Mode> {
        self.iter().find(|m| m.name == ModeName::Phugoid)
    }

    /// Whether any mode grows.
    pub fn any_divergent(&self) -> bool {
        self.iter().any(Mode::is_divergent)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn c(re: f64, im: f64) -> Complex64 {
        Complex64::new(re, im)
    }

    /// The cycles to half amplitude of a decaying oscillation, counted on
    /// a numerical solution of ẍ + 2ζωẋ + ω²x = 0 (classical Runge–Kutta,
    /// not the closed form): the amplitude ratio of successive maxima gives
    /// the decay per cycle, δ = ln(aₙ/aₙ₊₁), and ln 2/δ cycles halve it.
    fn cycles_counted(zeta: f64, omega: f64) -> f64 {
        let f = |x: f64, v: f64| (v, -2.0 * zeta * omega * v - omega * omega * x);
        let h = 1e-4 / omega;
        let (mut x, mut v) = (1.0, 0.0);
        let mut peaks = Vec::new();
        let mut prev = (x, v);
        while peaks.len() < 8 {
            let (k1x, k1v) = f(x, v);
            let (k2x, k2v) = f(x + h / 2.0 * k1x, v + h / 2.0 * k1v);
            let (k3x, k3v) = f(x + h / 2.0 * k2x, v + h / 2.0 * k2v);
            let (k4x, k4v) = f(x + h * k3x, v + h * k3v);
            x += h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
            v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
            // a maximum: v crosses zero downwards (x there by linear
            // interpolation, error O(h²))
            if prev.1 > 0.0 && v <= 0.0 {
                let s = prev.1 / (prev.1 - v);
                peaks.push(prev.0 + s * (x - prev.0));
            }
            prev = (x, v);
        }
        let delta = (peaks[0] / peaks[7]).ln() / 7.0;
        LN_2 / delta
    }

    #[test]
    fn the_eq8_constant_is_the_reports_and_counts_cycles() {
        // The report prints 0.11032.
        assert!(
            (CYCLES_CONSTANT - 0.11032).abs() < 5e-6,
            "{CYCLES_CONSTANT}"
        );
        // The modes' cycles to half amplitude, which use it, against cycles
        // counted on simulated oscillations.
        for (zeta, omega) in [(0.05f64, 3.0f64), (0.12, 17.5), (0.3, 1.0)] {
            let r = -zeta * omega;
            let s = omega * (1.0 - zeta * zeta).sqrt();
            let m = Mode::of_root(c(r, s), ModeName::ShortPeriod, None, 50.0);
            let counted = cycles_counted(zeta, omega);
            let got = m.cycles_to_half.unwrap();
            assert!(
                (got - counted).abs() <= 1e-6 * counted,
                "ζ = {zeta}: {got} vs counted {counted}"
            );
        }
    }

    #[test]
    fn a_damped_pair_by_hand() {
        // λ = −0.5 ± 4i: period 2π/4, time to half ln2/0.5,
        // cycles = (ln2/2π)·4/0.5 = 0.8825424006, ζ = 0.5/√16.25.
        let m = Mode::of_root(c(-0.5, 4.0), ModeName::ShortPeriod, None, 50.0);
        assert!((m.period.unwrap() - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
        assert!((m.time_to_half.unwrap() - 1.386_294_361_119_890_6).abs() < 1e-15);
        assert!((m.cycles_to_half.unwrap() - 0.882_542_400_610_606_4).abs() < 1e-12);
        assert!((m.damping_ratio.unwrap() - 0.124_034_734_589_208_4).abs() < 1e-15);
        assert!((m.frequency_parameter.unwrap() - 0.08).abs() < 1e-16);
        assert_eq!(m.time_to_double, None);
        // cycles to half = time to half / period
        assert!(
            (m.cycles_to_half.unwrap() - m.time_to_half.unwrap() / m.period.unwrap()).abs() < 1e-15
        );
    }

    #[test]
    fn a_growing_pair_doubles() {
        let m = Mode::of_root(c(0.2, 3.0), ModeName::ShortPeriod, None, 50.0);
        assert_eq!(m.time_to_half, None);
        assert!((m.time_to_double.unwrap() - LN_2 / 0.2).abs() < 1e-15);
        assert!(m.damping_ratio.unwrap() < 0.0);
        assert!(m.is_divergent());
    }

    #[test]
    fn two_pairs_fastest_is_short_period() {
        let roots = [c(-0.01, 0.05), c(-0.01, -0.05), c(-1.0, 5.0), c(-1.0, -5.0)];
        let m = Modes::identify(&roots, 50.0);
        assert_eq!(m.len(), 2);
        assert_eq!(m.short_period().unwrap().re, -1.0);
        assert_eq!(m.phugoid().unwrap().im, 0.05);
    }

    #[test]
    fn a_split_short_period_leaves_the_phugoid_oscillatory() {
        let roots = [c(-3.0, 0.0), c(-0.8, 0.0), c(-0.01, 0.05), c(-0.01, -0.05)];
        let m = Modes::identify(&roots, 50.0);
        assert!(m.short_period().is_none());
        assert!(m.phugoid().is_some());
        let aperiodic: Vec<_> = m.iter().filter(|x| x.name == ModeName::Aperiodic).collect();
        assert_eq!(aperiodic.len(), 2);
        assert!(
            aperiodic
                .iter()
                .all(|x| x.origin == Some(Origin::ShortPeriod))
        );
    }

    #[test]
    fn a_split_phugoid_leaves_the_short_period_oscillatory() {
        let roots = [c(-1.0, 5.0), c(-1.0, -5.0), c(0.02, 0.0), c(-0.05, 0.0)];
        let m = Modes::identify(&roots, 50.0);
        assert!(m.short_period().is_some());
        assert!(m.any_divergent());
        assert_eq!(m[1].origin, Some(Origin::Phugoid));
    }

    #[test]
    fn seconds_scale_by_tau() {
        let m = Mode::of_root(c(-0.5, 4.0), ModeName::ShortPeriod, None, 50.0);
        let s = m.in_seconds(2.0);
        assert_eq!(s.period, Some(m.period.unwrap() * 2.0));
        assert_eq!(s.re, -0.25);
    }
}
