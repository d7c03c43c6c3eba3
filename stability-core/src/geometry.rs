//! Planform geometry of straight-tapered delta wings (§2.2).
//!
//! The wing has a straight leading edge swept by Λ, an unswept trailing
//! edge, root chord c₀ and tip chord c_t = λc₀ (λ = 0: a true delta).
//! Then, with s the semi-span:
//!
//! - s = c₀(1 − λ)/tan Λ, b = 2s;
//! - S = ½bc₀(1 + λ) (§2.2, first form);
//! - standard mean chord c̄ₛ = S/b = ½c₀(1 + λ);
//! - mean aerodynamic chord c̄ = (2/3)c₀(1 + λ + λ²)/(1 + λ)
//!   = (4/3)c̄ₛ[1 − λ/(1 + λ)²];
//! - x̄ (leading edge of the M.A.C. from the apex) = ȳ tan Λ
//!   = (c₀/3)(1 − λ)(1 + 2λ)/(1 + λ), ȳ = (b/6)(1 + 2λ)/(1 + λ);
//! - A = b²/S = 2b/(c₀(1 + λ)) = 4 cot Λ (1 − λ)/(1 + λ) = 3 cot Λ_c/4 (1 − λ)/(1 + λ),
//!   since the sweep of the line at fraction f of the chord is
//!   tan Λ_f = (1 − f) tan Λ;
//! - h = (x₀ − x̄)/c̄ = x₀/c̄ − (1 + λ − 2λ²)/(2(1 + λ + λ²)).
//!
//! All the printed forms of §2.2 check against each other and against a
//! numerical integration over the planform (tests/it/geometry.rs); the OCR
//! garbles their symbols (c̄ for the S.M.C. and the M.A.C. alike, x̄ for the
//! M.A.C.) but not their content.
//!
//! # The report's reference chord
//! §3 defines μ₁ with "the aerodynamic mean chord", and the derivatives'
//! lengths (eqs 9–20) are that chord: §7 restates Garrick's result, written
//! with the S.M.C. c̄ₛ (S = Ac̄ₛ², trailing edge at x = 2c̄ₛ), "in the
//! notation of this report" with the factor c̄ₛ/c̄ = 3/4 and h measured on
//! the M.A.C.; the appendix's "standard length" row gives (4/3)c̄ₛ. For the
//! report's true deltas the two agree, (4/3)c̄ₛ = c̄. For a tapered wing they
//! differ (for λ = 1/7, c̄ = 1.1875c̄ₛ); the report's eqs (34)–(35) use the
//! factor 3/2 of the true delta (see `damping`), i.e. (4/3)c̄ₛ. This crate
//! takes the M.A.C. as the reference chord ([`Planform::reference_chord`]),
//! as §3 says, and reproduces (34)–(35) as printed.

use crate::numerics::display::Num;
use serde::Serialize;
use std::f64::consts::PI;

/// β cot Λ, β = √(M² − 1), at a supersonic Mach number: the leading edge
/// swept by Λ lies inside the Mach cone (is subsonic) while β cot Λ < 1.
pub fn beta_cot(sweep_le: f64, mach: f64) -> f64 {
    (mach * mach - 1.0).sqrt() / sweep_le.tan()
}

/// The Mach number at which a leading edge swept by Λ turns sonic,
/// β cot Λ = 1: M = √(1 + tan²Λ) = sec Λ (√2 for 45°, 2 for 60°).
pub fn sonic_leading_edge_mach(sweep_le: f64) -> f64 {
    let t = sweep_le.tan();
    (1.0 + t * t).sqrt()
}

/// Why a planform is not a straight-tapered delta.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum GeometryError {
    #[error(
        "the leading-edge sweep must lie strictly between 0° and 90°, not {}°",
        Num(*.0)
    )]
    Sweep(f64),
    #[error("the taper ratio must lie in [0, 1) (0: a true delta), not {}", Num(*.0))]
    Taper(f64),
    #[error("the size ({name}) must be a positive finite number, not {value}", name = .0, value = Num(*.1))]
    Size(&'static str, f64),
}

/// The size that fixes the planform's scale.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Size {
    RootChord(f64),
    Span(f64),
    Area(f64),
}

/// A straight-tapered delta wing.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Planform {
    /// Leading-edge sweep Λ (rad).
    pub sweep_le: f64,
    /// Taper ratio λ = c_t/c₀.
    pub taper: f64,
    /// Root chord c₀.
    pub root_chord: f64,
}

impl Planform {
    /// A planform from its leading-edge sweep (radians), taper and size.
    pub fn new(sweep_le: f64, taper: f64, size: Size) -> Result<Planform, GeometryError> {
        if !(sweep_le > 0.0 && sweep_le < PI / 2.0) {
            return Err(GeometryError::Sweep(sweep_le.to_degrees()));
        }
        if !(0.0..1.0).contains(&taper) {
            return Err(GeometryError::Taper(taper));
        }
        let unit = Planform {
            sweep_le,
            taper,
            root_chord: 1.0,
        };
        let (name, v) = match size {
            Size::RootChord(v) => ("root chord", v),
            Size::Span(v) => ("span", v),
            Size::Area(v) => ("area", v),
        };
        if !(v.is_finite() && v > 0.0) {
            return Err(GeometryError::Size(name, v));
        }
        let root_chord = match size {
            Size::RootChord(c) => c,
            Size::Span(b) => b / unit.span(),
            Size::Area(s) => (s / unit.area()).sqrt(),
        };
        if !(root_chord.is_finite() && root_chord > 0.0) {
            return Err(GeometryError::Size(name, v));
        }
        Ok(Planform {
            sweep_le,
            taper,
            root_chord,
        })
    }

    /// Tip chord c_t = λc₀.
    pub fn tip_chord(&self) -> f64 {
        self.taper * self.root_chord
    }

    /// Semi-span s = c₀(1 − λ)/tan Λ.
    pub fn semi_span(&self) -> f64 {
        self.root_chord * (1.0 - self.taper) / self.sweep_le.tan()
    }

    /// Span b.
    pub fn span(&self) -> f64 {
        2.0 * self.semi_span()
    }

    /// Area S = ½bc₀(1 + λ) (§2.2).
    pub fn area(&self) -> f64 {
        0.5 * self.span() * self.root_chord * (1.0 + self.taper)
    }

    /// Standard mean chord c̄ₛ = S/b = ½c₀(1 + λ) (§2.2).
    pub fn smc(&self) -> f64 {
        0.5 * self.root_chord * (1.0 + self.taper)
    }

    /// Mean aerodynamic chord c̄ = (2/3)c₀(1 + λ + λ²)/(1 + λ) (§2.2).
    pub fn mac(&self) -> f64 {
        let l = self.taper;
        2.0 / 3.0 * self.root_chord * (1.0 + l + l * l) / (1.0 + l)
    }

    /// The chord the report's derivatives and μ₁ refer to: the M.A.C. (§3).
    pub fn reference_chord(&self) -> f64 {
        self.mac()
    }

    /// x̄: leading edge of the M.A.C. from the apex,
    /// (c₀/3)(1 − λ)(1 + 2λ)/(1 + λ) (§2.2).
    pub fn x_mac(&self) -> f64 {
        let l = self.taper;
        self.root_chord / 3.0 * (1.0 - l) * (1.0 + 2.0 * l) / (1.0 + l)
    }

    /// ȳ: spanwise station of the M.A.C., (b/6)(1 + 2λ)/(1 + λ) (§2.2).
    pub fn y_mac(&self) -> f64 {
        let l = self.taper;
        self.span() / 6.0 * (1.0 + 2.0 * l) / (1.0 + l)
    }

    /// Aspect ratio A = 4 cot Λ (1 − λ)/(1 + λ) (§2.2).
    pub fn aspect_ratio(&self) -> f64 {
        4.0 / self.sweep_le.tan() * (1.0 - self.taper) / (1.0 + self.taper)
    }

    /// Sweep of the line through fraction `f` of the local chord
    /// (0: leading edge, ¼: quarter chord, 1: trailing edge):
    /// tan Λ_f = (1 − f) tan Λ, the trailing edge being unswept.
    pub fn sweep_at(&self, f: f64) -> f64 {
        ((1.0 - f) * self.sweep_le.tan()).atan()
    }

    /// Quarter-chord sweep Λ_c/4.
    pub fn quarter_chord_sweep(&self) -> f64 {
        self.sweep_at(0.25)
    }

    /// x₀/c₀ (c.g. from the apex, in root chords) for the c.g. at h
    /// (fraction of the M.A.C. aft of its leading edge).
    pub fn xo_over_root_chord(&self, h: f64) -> f64 {
        (self.x_mac() + h * self.mac()) / self.root_chord
    }

    /// h for the c.g. at x₀/c₀.
    pub fn h_from_xo_over_root_chord(&self, xo: f64) -> f64 {
        (xo * self.root_chord - self.x_mac()) / self.mac()
    }

    /// x₀/c̄ₛ as §7 uses it (the S.M.C. as unit):
    /// (4/3)h(1 + λ + λ²)/(1 + λ)² + (2/3)(1 − λ)(1 + 2λ)/(1 + λ)².
    pub fn xo_over_smc(&self, h: f64) -> f64 {
        (self.x_mac() + h * self.mac()) / self.smc()
    }
}

/// h of a c.g. fixed in space when the tips of a true delta (same apex,
/// root chord and leading edge) are cropped to taper λ: §10's "cropping as
/// a shift of axis" — the cropped wing's derivatives about its own M.A.C.
/// at this h replace the true delta's at `h_true`.
pub fn cropped_h(h_true: f64, sweep_le: f64, taper: f64) -> Result<f64, GeometryError> {
    let delta = Planform::new(sweep_le, 0.0, Size::RootChord(1.0))?;
    let cropped = Planform::new(sweep_le, taper, Size::RootChord(1.0))?;
    Ok(cropped.h_from_xo_over_root_chord(delta.xo_over_root_chord(h_true)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_45_degree_true_delta_by_hand() {
        // c₀ = 1, Λ = 45°: s = 1, b = 2, S = 1, A = 4, c̄ₛ = 0.5, c̄ = 2/3, x̄ = 1/3
        let p = Planform::new(PI / 4.0, 0.0, Size::RootChord(1.0)).unwrap();
        assert!((p.span() - 2.0).abs() < 1e-15);
        assert!((p.area() - 1.0).abs() < 1e-15);
        assert!((p.aspect_ratio() - 4.0).abs() < 1e-15);
        assert!((p.mac() - 2.0 / 3.0).abs() < 1e-15);
        assert!((p.x_mac() - 1.0 / 3.0).abs() < 1e-15);
        // §10: h = 0.25 on a true delta is x₀/c₀ = 0.5
        assert!((p.xo_over_root_chord(0.25) - 0.5).abs() < 1e-15);
        // §7: x₀/c̄ₛ = (4/3)(h + ½) for λ = 0
        assert!((p.xo_over_smc(0.4) - 4.0 / 3.0 * 0.9).abs() < 1e-15);
    }

    #[test]
    fn sizes_are_interchangeable() {
        let a = Planform::new(1.0, 0.2, Size::RootChord(7.0)).unwrap();
        let b = Planform::new(1.0, 0.2, Size::Span(a.span())).unwrap();
        let c = Planform::new(1.0, 0.2, Size::Area(a.area())).unwrap();
        assert!((b.root_chord - 7.0).abs() < 1e-12 && (c.root_chord - 7.0).abs() < 1e-12);
    }

    #[test]
    fn bad_planforms_name_the_limit() {
        assert_eq!(
            Planform::new(0.0, 0.0, Size::Span(1.0)),
            Err(GeometryError::Sweep(0.0))
        );
        assert!(matches!(
            Planform::new(PI / 2.0, 0.0, Size::Span(1.0)),
            Err(GeometryError::Sweep(_))
        ));
        assert_eq!(
            Planform::new(1.0, 1.0, Size::Span(1.0)),
            Err(GeometryError::Taper(1.0))
        );
        assert!(matches!(
            Planform::new(1.0, 0.0, Size::Area(f64::NAN)),
            Err(GeometryError::Size("area", _))
        ));
        assert!(matches!(
            Planform::new(1.0, 0.0, Size::RootChord(-2.0)),
            Err(GeometryError::Size(..))
        ));
    }
}

/// Why a trapezoid is not a wing.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum TrapezoidError {
    #[error("the {0} must be a positive finite length, not {1}")]
    Length(&'static str, f64),
    #[error("the tip chord must be a finite length ≥ 0 (0: a pointed tip), not {0}")]
    TipChord(f64),
    #[error("the leading-edge sweep must lie strictly between −90° and 90°, not {0}°")]
    Sweep(f64),
}

/// A straight-tapered trapezoidal wing of any sweep, taper and aspect ratio:
/// root chord c_r on the centre line with its leading edge at the origin,
/// tip chord c_t = λc_r at semi-span s, leading edge swept by Λ; the trailing
/// edge's sweep follows, tan Λ_TE = tan Λ − (c_r − c_t)/s. A [`Planform`]
/// (unswept trailing edge, 0 ≤ λ < 1) is the special case
/// `Trapezoid::from(&planform)`; a rectangle has Λ = 0, λ = 1.
///
/// With x aft from the apex and y outboard, the chord is
/// c(y) = c_r(1 − (1 − λ)y/s) and the leading edge x(y) = y tan Λ, so:
/// S = s(c_r + c_t); b = 2s; A = b²/S; the M.A.C.
/// c̄ = (2/S)∫₀ˢ c² dy = (2/3)c_r(1 + λ + λ²)/(1 + λ) at
/// ȳ = (2/S)∫₀ˢ yc dy = (s/3)(1 + 2λ)/(1 + λ), its leading edge at
/// x̄ = ȳ tan Λ — the integrals of §2.2 for a general trapezoid; for a
/// `Planform` they are §2.2's printed forms (`tests/it/geometry.rs` checks that
/// the two agree and that both match a numerical integration).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Trapezoid {
    /// Root chord c_r.
    pub root_chord: f64,
    /// Tip chord c_t (0: a pointed tip).
    pub tip_chord: f64,
    /// Semi-span s.
    pub semi_span: f64,
    /// Leading-edge sweep Λ (rad), positive swept back.
    pub sweep_le: f64,
}

impl Trapezoid {
    /// A trapezoid from its root and tip chords, semi-span and leading-edge
    /// sweep (radians).
    pub fn new(
        root_chord: f64,
        tip_chord: f64,
        semi_span: f64,
        sweep_le: f64,
    ) -> Result<Trapezoid, TrapezoidError> {
        if !(root_chord.is_finite() && root_chord > 0.0) {
            return Err(TrapezoidError::Length("root chord", root_chord));
        }
        if !(tip_chord.is_finite() && tip_chord >= 0.0) {
            return Err(TrapezoidError::TipChord(tip_chord));
        }
        if !(semi_span.is_finite() && semi_span > 0.0) {
            return Err(TrapezoidError::Length("semi-span", semi_span));
        }
        if sweep_le.is_nan() || sweep_le.abs() >= PI / 2.0 {
            return Err(TrapezoidError::Sweep(sweep_le.to_degrees()));
        }
        Ok(Trapezoid {
            root_chord,
            tip_chord,
            semi_span,
            sweep_le,
        })
    }

    /// The trapezoid of aspect ratio `aspect_ratio`, taper λ and
    /// leading-edge sweep (radians) with the given root chord:
    /// s = A c_r (1 + λ)/4.
    pub fn from_aspect_ratio(
        aspect_ratio: f64,
        taper: f64,
        sweep_le: f64,
        root_chord: f64,
    ) -> Result<Trapezoid, TrapezoidError> {
        if !(aspect_ratio.is_finite() && aspect_ratio > 0.0) {
            return Err(TrapezoidError::Length("aspect ratio", aspect_ratio));
        }
        Trapezoid::new(
            root_chord,
            taper * root_chord,
            aspect_ratio * root_chord * (1.0 + taper) / 4.0,
            sweep_le,
        )
    }

    /// An unswept rectangle of chord `chord` and aspect ratio `aspect_ratio`.
    pub fn rectangle(aspect_ratio: f64, chord: f64) -> Result<Trapezoid, TrapezoidError> {
        Trapezoid::from_aspect_ratio(aspect_ratio, 1.0, 0.0, chord)
    }

    /// Taper ratio λ = c_t/c_r.
    pub fn taper(&self) -> f64 {
        self.tip_chord / self.root_chord
    }

    /// Span b = 2s.
    pub fn span(&self) -> f64 {
        2.0 * self.semi_span
    }

    /// Area S = s(c_r + c_t).
    pub fn area(&self) -> f64 {
        self.semi_span * (self.root_chord + self.tip_chord)
    }

    /// Aspect ratio A = b²/S.
    pub fn aspect_ratio(&self) -> f64 {
        self.span() * self.span() / self.area()
    }

    /// The local chord c(y), 0 ≤ y ≤ s.
    pub fn chord_at(&self, y: f64) -> f64 {
        self.root_chord + (self.tip_chord - self.root_chord) * y / self.semi_span
    }

    /// The leading edge's x (aft of the apex) at station y.
    pub fn leading_edge_at(&self, y: f64) -> f64 {
        y * self.sweep_le.tan()
    }

    /// Mean aerodynamic chord c̄ = (2/3)c_r(1 + λ + λ²)/(1 + λ).
    pub fn mac(&self) -> f64 {
        let l = self.taper();
        2.0 / 3.0 * self.root_chord * (1.0 + l + l * l) / (1.0 + l)
    }

    /// The reference chord of the derivatives: the M.A.C., as for
    /// [`Planform::reference_chord`].
    pub fn reference_chord(&self) -> f64 {
        self.mac()
    }

    /// ȳ: spanwise station of the M.A.C., (s/3)(1 + 2λ)/(1 + λ).
    pub fn y_mac(&self) -> f64 {
        let l = self.taper();
        self.semi_span / 3.0 * (1.0 + 2.0 * l) / (1.0 + l)
    }

    /// x̄: leading edge of the M.A.C. aft of the apex, ȳ tan Λ.
    pub fn x_mac(&self) -> f64 {
        self.leading_edge_at(self.y_mac())
    }

    /// Sweep of the line through fraction `f` of the local chord
    /// (0: leading edge, ¼: quarter chord, 1: trailing edge):
    /// tan Λ_f = tan Λ − f(c_r − c_t)/s.
    pub fn sweep_at(&self, f: f64) -> f64 {
        (self.sweep_le.tan() - f * (self.root_chord - self.tip_chord) / self.semi_span).atan()
    }

    /// Trailing-edge sweep Λ_TE.
    pub fn sweep_te(&self) -> f64 {
        self.sweep_at(1.0)
    }

    /// The affine wing of the Prandtl–Glauert (Göthert) rule: spans scaled
    /// by β, chords kept, so that tan Λ′ = tan Λ/β and A′ = βA.
    pub fn affine(&self, beta: f64) -> Result<Trapezoid, TrapezoidError> {
        Trapezoid::new(
            self.root_chord,
            self.tip_chord,
            beta * self.semi_span,
            (self.sweep_le.tan() / beta).atan(),
        )
    }
}

impl From<&Planform> for Trapezoid {
    fn from(p: &Planform) -> Trapezoid {
        Trapezoid {
            root_chord: p.root_chord,
            tip_chord: p.tip_chord(),
            semi_span: p.semi_span(),
            sweep_le: p.sweep_le,
        }
    }
}

pub mod configuration;
