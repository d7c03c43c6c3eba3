//! The MIL-F-8785C short-period frequency requirement (§3.2.2.1.1,
//! "Short-period frequency and acceleration sensitivity", Figures 1–3):
//! the undamped natural frequency ω_sp of the short period against the
//! acceleration sensitivity n/α, in lines of constant control anticipation
//! parameter CAP = ω_sp²/(n/α), beside the damping-ratio limits of
//! §3.2.2.1.2 ([`crate::criteria::short_period_level`]).
//!
//! Reference: MIL-F-8785C, *Military Specification: Flying Qualities of
//! Piloted Airplanes*, 5 November 1980, §3.2.2.1.1 and its Figures 1
//! (Category A), 2 (Category B) and 3 (Category C); background in
//! Moorhouse & Woodcock, AFWAL-TR-81-3109 (1982).
//!
//! # n/α
//! n/α is the steady normal acceleration per unit incidence (g/rad),
//! n/α = (V/g)·(1/T_θ₂) with 1/T_θ₂ ≈ −Z_w, the heave damping per unit
//! mass (1/s). In the report's notation Z_w/m = z_w/τ and V/(gτ) =
//! ½ρSV²/W = 1/C_L in level flight, so
//!
//!   n/α = −z_w·V/(g·τ) = −z_w/C_L,
//!
//! ([`n_alpha`]); with z_w = −(∂C_L/∂α + C_D) (eq 12) this is the familiar
//! (ρV²S/2W)·C_Lα, plus the drag term. For a dimensional set, n/α =
//! −Z_w·U₀/g ([`n_alpha_dimensional`]).
//!
//! # The limits
//! Each level is a band of CAP (1/(g·s²), i.e. rad/s² per g/rad) with, in
//! Categories A and C, a floor on ω_sp and, in Category C, on n/α (the
//! Category C floors depend on the airplane's class, §1.3):
//!
//! | | Level 1 | Level 2 | Level 3 |
//! | --- | --- | --- | --- |
//! | A (Fig 1) | 0.28 ≤ CAP ≤ 3.6, ω_sp ≥ 1.0 | 0.16 ≤ CAP ≤ 10, ω_sp ≥ 0.6 | CAP ≥ 0.16 |
//! | B (Fig 2) | 0.085 ≤ CAP ≤ 3.6 | 0.038 ≤ CAP ≤ 10 | CAP ≥ 0.038 |
//! | C (Fig 3) | 0.16 ≤ CAP ≤ 3.6, ω_sp ≥ 0.87 (0.7), n/α ≥ 2.7 (2.0) | 0.096 ≤ CAP ≤ 10, ω_sp ≥ 0.6 (0.4), n/α ≥ 1.8 (1.0) | CAP ≥ 0.096 |
//!
//! (Category C: Classes I, II-C and IV; in brackets Classes II-L and III.)
//! Every bound is inclusive.
//!
//! # Limits of this module
//! The figures' lines are given here as the numbers that label them. They
//! were taken from secondary sources — implementations of the
//! MIL-STD-1797A forms of Figures 1 and 2 (whose Category A and B lines
//! are those of MIL-F-8785C) and textbook tabulations of Figure 3 — because
//! no legible copy of the standard's figures was within reach; the
//! Category C floors on ω_sp and n/α are the least certain. The figures
//! span n/α = 1 to 100 g/rad; outside it the levels are those of the
//! lines extended. Check them against the standard before relying on them.

use crate::criteria::{Category, Level};
use serde::Serialize;

/// The airplane classes of MIL-F-8785C §1.3 (the Category C floors differ
/// between I, II-C, IV and II-L, III).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum AirplaneClass {
    /// Small, light airplanes.
    #[serde(rename = "I")]
    I,
    /// Medium weight, low-to-medium manoeuvrability, carrier-based.
    #[serde(rename = "II-C")]
    IIC,
    /// Medium weight, low-to-medium manoeuvrability, land-based.
    #[serde(rename = "II-L")]
    IIL,
    /// Large, heavy, low-to-medium manoeuvrability.
    #[serde(rename = "III")]
    III,
    /// High manoeuvrability (fighters, attack).
    #[serde(rename = "IV")]
    IV,
}

impl AirplaneClass {
    pub const ALL: [AirplaneClass; 5] = [
        AirplaneClass::I,
        AirplaneClass::IIC,
        AirplaneClass::IIL,
        AirplaneClass::III,
        AirplaneClass::IV,
    ];

    /// `I`, `II-C`, `II-L`, `III`, `IV`.
    pub fn name(self) -> &'static str {
        match self {
            AirplaneClass::I => "I",
            AirplaneClass::IIC => "II-C",
            AirplaneClass::IIL => "II-L",
            AirplaneClass::III => "III",
            AirplaneClass::IV => "IV",
        }
    }

    /// The class by its name (`I`, `II-C`, `II-L`, `III`, `IV`).
    pub fn parse(name: &str) -> Option<AirplaneClass> {
        AirplaneClass::ALL.into_iter().find(|c| c.name() == name)
    }

    /// What airplanes the class holds (§1.3), in words.
    pub fn describe(self) -> &'static str {
        match self {
            AirplaneClass::I => "small, light airplanes",
            AirplaneClass::IIC => "medium weight, low-to-medium manoeuvrability, carrier-based",
            AirplaneClass::IIL => "medium weight, low-to-medium manoeuvrability, land-based",
            AirplaneClass::III => "large, heavy, low-to-medium manoeuvrability (transports)",
            AirplaneClass::IV => "high manoeuvrability (fighters, attack)",
        }
    }

    /// Whether the class takes the lower Category C floors (II-L, III).
    fn heavy(self) -> bool {
        matches!(self, AirplaneClass::IIL | AirplaneClass::III)
    }
}

/// One level's region: a CAP band and floors on ω_sp (rad/s) and n/α
/// (g/rad).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Region {
    pub cap_min: f64,
    /// `None`: no upper bound.
    pub cap_max: Option<f64>,
    pub omega_min: Option<f64>,
    pub n_alpha_min: Option<f64>,
}

impl Region {
    fn contains(&self, omega: f64, n_alpha: f64) -> bool {
        let cap = omega * omega / n_alpha;
        cap >= self.cap_min
            && self.cap_max.is_none_or(|hi| cap <= hi)
            && self.omega_min.is_none_or(|lo| omega >= lo)
            && self.n_alpha_min.is_none_or(|lo| n_alpha >= lo)
    }
}

/// The regions of Levels 1, 2 and 3 of a category (see the module's
/// table).
pub fn regions(category: Category, class: AirplaneClass) -> [Region; 3] {
    let r = |cap_min, cap_max, omega_min, n_alpha_min| Region {
        cap_min,
        cap_max,
        omega_min,
        n_alpha_min,
    };
    match category {
        Category::A => [
            r(0.28, Some(3.6), Some(1.0), None),
            r(0.16, Some(10.0), Some(0.6), None),
            r(0.16, None, None, None),
        ],
        Category::B => [
            r(0.085, Some(3.6), None, None),
            r(0.038, Some(10.0), None, None),
            r(0.038, None, None, None),
        ],
        Category::C => {
            let (w1, n1, w2, n2) = if class.heavy() {
                (0.7, 2.0, 0.4, 1.0)
            } else {
                (0.87, 2.7, 0.6, 1.8)
            };
            [
                r(0.16, Some(3.6), Some(w1), Some(n1)),
                r(0.096, Some(10.0), Some(w2), Some(n2)),
                r(0.096, None, None, None),
            ]
        }
    }
}

/// The level of a short period of undamped natural frequency `omega`
/// (rad/s) at acceleration sensitivity `n_alpha` (g/rad) in `category`.
/// A non-positive or non-finite n/α or ω has no level better than worse
/// than Level 3.
pub fn frequency_level(
    omega: f64,
    n_alpha: f64,
    category: Category,
    class: AirplaneClass,
) -> Level {
    let valid = omega.is_finite() && omega > 0.0 && n_alpha.is_finite() && n_alpha > 0.0;
    let levels = [Level::One, Level::Two, Level::Three];
    match regions(category, class)
        .iter()
        .position(|region| valid && region.contains(omega, n_alpha))
    {
        Some(k) => levels[k],
        None => Level::WorseThanThree,
    }
}

/// Why CAP = ω_sp²/(n/α) is undefined at ω_sp (rad/s) and n/α (g/rad),
/// in words, or `None` when it is a finite number: n/α must be finite
/// (n/α = −z_w/C_L is not at C_L = 0, nor −Z_w·U₀/g at g → 0) and not 0
/// (at Z_w = 0 CAP is infinite), and CAP must not overflow.
pub fn not_assessed(omega: f64, n_alpha: f64) -> Option<String> {
    let cap = omega * omega / n_alpha;
    Some(if !n_alpha.is_finite() {
        "n/α is not finite (n/α = −z_w/C_L at C_L = 0, or −Z_w·U₀/g with g → 0): CAP = ω_sp²/(n/α) is undefined".to_string()
    } else if n_alpha == 0.0 {
        "n/α = 0 (Z_w = 0): CAP = ω_sp²/(n/α) is infinite".to_string()
    } else if !omega.is_finite() || !cap.is_finite() {
        format!(
            "CAP = ω_sp²/(n/α) overflows (ω_sp = {} rad/s, n/α = {} g/rad)",
            crate::numerics::display::Num(omega),
            crate::numerics::display::Num(n_alpha)
        )
    } else {
        return None;
    })
}

/// n/α = −z_w/C_L (g/rad), from the report's z_w and the level-flight
/// C_L (see the module's documentation).
pub fn n_alpha(z_w: f64, c_l: f64) -> f64 {
    -z_w / c_l
}

/// n/α = −Z_w·U₀/g (g/rad), from the dimensional Z_w (1/s), the speed U₀
/// and gravity g in the same units.
pub fn n_alpha_dimensional(z_w: f64, u0: f64, g: f64) -> f64 {
    -z_w * u0 / g
}

/// The short period against §3.2.2.1.1, in the three categories.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ShortPeriodFrequency {
    /// ω_sp, rad/s.
    pub natural_frequency_rad_s: f64,
    /// n/α, g/rad.
    pub n_alpha: f64,
    /// ω_sp²/(n/α), 1/(g·s²).
    pub cap: f64,
    /// The class whose Category C floors were applied; `None`: not given,
    /// and Category C not assessed (its floors differ by class; Categories
    /// A and B do not).
    pub class: Option<AirplaneClass>,
    #[serde(rename = "A")]
    pub a: Level,
    #[serde(rename = "B")]
    pub b: Level,
    /// Category C's level, with a class.
    #[serde(rename = "C")]
    pub c: Option<Level>,
}

impl ShortPeriodFrequency {
    /// The levels of ω_sp (rad/s) at n/α (g/rad), or why the requirement
    /// cannot be assessed there ([`not_assessed`]): no level is given on a
    /// CAP that is not a number.
    pub fn assess(
        omega: f64,
        n_alpha: f64,
        class: Option<AirplaneClass>,
    ) -> Result<ShortPeriodFrequency, String> {
        match not_assessed(omega, n_alpha) {
            Some(why) => Err(why),
            None => Ok(ShortPeriodFrequency::of(omega, n_alpha, class)),
        }
    }

    /// The levels of ω_sp (rad/s) at n/α (g/rad): Categories A and B
    /// whatever the class (their limits do not depend on it), Category C
    /// where the class is known.
    pub fn of(omega: f64, n_alpha: f64, class: Option<AirplaneClass>) -> ShortPeriodFrequency {
        // Categories A and B: any class gives the same regions
        let level = |c, class| frequency_level(omega, n_alpha, c, class);
        ShortPeriodFrequency {
            natural_frequency_rad_s: omega,
            n_alpha,
            cap: omega * omega / n_alpha,
            class,
            a: level(Category::A, AirplaneClass::IV),
            b: level(Category::B, AirplaneClass::IV),
            c: class.map(|k| level(Category::C, k)),
        }
    }
}
