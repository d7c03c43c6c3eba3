//! The default methods of the coefficients, each a function of the
//! planform and Mach number (docs/models.md).

use crate::geometry::Planform;
use crate::numerics::interpolation::{Value, hermite};
use std::f64::consts::PI;

pub use crate::numerics::elliptic::ellip_e_and_slope;

/// Below this Mach number the subsonic methods apply.
pub const SUBSONIC_LIMIT: f64 = 0.8;
/// Above this Mach number the supersonic methods apply.
pub const SUPERSONIC_LIMIT: f64 = 1.2;
/// The default models hold for 0 ≤ M ≤ this.
pub const MACH_MAX: f64 = 3.0;
pub use crate::aerodynamics::supersonic::wave_drag::THICKNESS;

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
