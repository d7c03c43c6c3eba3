//! Zero-lift wave drag of a thin true delta by linear theory, against the
//! edge parameter m = β cot Λ = cot Λ/tan μ (μ the Mach angle): the
//! theoretical curve of the note's Fig 1 ("wave drag at zero lift", §6).
//!
//! A.E. Puckett, "Supersonic wave drag of thin airfoils", J. Aero. Sci.
//! 13(9), 1946, 475–484 (also Puckett & Stewart, Q. Appl. Math. 5, 1947):
//! symmetric double-wedge sections of thickness ratio τ with the ridge at
//! the fraction f of every chord; the surface slope is τ/(2f) ahead of the
//! ridge and −τ/(2(1 − f)) behind, so the thickness is a sum of two uniform
//! source sheets, one behind the leading edge (a chevron from the apex with
//! edge parameter m) and one behind the ridge (a chevron from (fc₀, 0) with
//! edge parameter m/(1 − f)). The upper-surface potential is
//! φ(P) = −(1/π) ∫∫ z_ξ dξ dη/R = −(2/(πβ)) Σ z_ξ · (area of the sheet's part
//! of P's forecone in the characteristic variables σ = √u, ρ = √v), and the
//! drag C_D = −(4/S) ∫∫ φ_x z_x dS, integrated by parts along each chord,
//! needs φ only on the leading edge, the ridge and the trailing edge:
//! C_D·S = −4 ∫ [−z₁φ_le + (z₁ − z₂)φ_ridge + z₂φ_te] dy.
//! Linearised theory: C_D·β/τ² is a function of m and f alone; as m → ∞ it
//! tends to Ackeret's two-dimensional 1/(f(1 − f)), and as m → 0 it
//! vanishes like m (slender-body theory, drag ∝ τ² cot Λ). Sharp peaks
//! where the leading edge (m = 1) or the ridge (m = 1 − f) is sonic are a
//! feature of the double wedge in linear theory, not of the method.
//!
//! The note's sections are "comparable to the N.A.C.A. 4-digit series" with
//! the maximum thickness at 0.3c on average and τ = 0.06 (eq 23); a
//! round-nosed section has infinite linear-theory wave drag at a supersonic
//! leading edge, so the double wedge with f = 0.3, τ = 0.06 is the linear
//! theory that can stand for them. `aero::defaults::wave_drag` is a blend,
//! (16/3)τ² cot Λ/√(1 + m²), of the biconvex section's two-dimensional
//! value and a slender limit: it has no peak at the sonic edge and its
//! slender limit is not the theory's (docs/models.md compares them).

use super::SupersonicError;
use super::quadrature::{adaptive, tanh_sinh};
use crate::numerics::invalid::Invalid;
use std::f64::consts::PI;

/// The note's sections, as linear theory can take them: a double wedge,
/// ridge at 0.3c, τ = 0.06 (eq 23).
pub const NOTE_RIDGE: f64 = 0.3;

/// One point of the curve.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct WaveDragPoint {
    /// m = β cot Λ.
    pub edge_parameter: f64,
    /// C_D·β/τ².
    pub scaled_drag: f64,
}

/// The (σ, ρ)-area of P's forecone behind the chevron ξ ≥ x_v + |η| tan Λ_e,
/// written in the receiver's characteristic variables with x′ = x − x_v,
/// Y = βy and the edge parameter m_e = β cot Λ_e: the constraints
/// (m_e − 1)v ≤ 2m_e x′ − 2Y − (1 + m_e)u and
/// (m_e + 1)v ≤ 2m_e x′ + 2Y − (m_e − 1)u, with u, v ≥ 0.
fn chevron_area(xp: f64, y: f64, me: f64) -> f64 {
    if xp <= 0.0 {
        return 0.0;
    }
    // each constraint: a·v ≤ b + c·u
    let cons = [
        (me - 1.0, 2.0 * me * xp - 2.0 * y, -(1.0 + me)),
        (me + 1.0, 2.0 * me * xp + 2.0 * y, -(me - 1.0)),
    ];
    let bounds = |u: f64| {
        let (mut lo, mut hi) = (0.0f64, f64::INFINITY);
        for (a, b, c) in cons {
            let r = b + c * u;
            if a > 1e-14 {
                hi = hi.min(r / a);
            } else if a < -1e-14 {
                lo = lo.max(r / a);
            } else if r < 0.0 {
                hi = -1.0;
            }
        }
        (lo, hi)
    };
    // breakpoints: where two of the lines v = 0, v = (b + cu)/a cross, and u = 0
    let mut lines = vec![(0.0, 0.0)];
    for (a, b, c) in cons {
        if a.abs() > 1e-14 {
            lines.push((b / a, c / a));
        }
    }
    let mut br = vec![0.0];
    // a sonic edge (a = 0) bounds u alone: b + cu ≥ 0
    for (a, b, c) in cons {
        if a.abs() <= 1e-14 && c.abs() > 1e-14 && -b / c > 0.0 {
            br.push(-b / c);
        }
    }
    for i in 0..lines.len() {
        for j in i + 1..lines.len() {
            let (p, q) = (lines[i], lines[j]);
            if (q.1 - p.1).abs() > 1e-14 {
                let u = (p.0 - q.0) / (q.1 - p.1);
                if u > 0.0 && u.is_finite() {
                    br.push(u);
                }
            }
        }
    }
    br.push(4.0 * xp + 4.0 * y.abs()); // past any end: u + v ≤ 2x′ on the region
    br.sort_by(f64::total_cmp);
    let mut area = 0.0;
    for w in br.windows(2) {
        let mid = 0.5 * (w[0] + w[1]);
        let (lo, hi) = bounds(mid);
        if hi <= lo {
            continue;
        }
        let [a] = tanh_sinh(
            |s| {
                let (lo, hi) = bounds(s * s);
                [(hi.max(lo)).sqrt() - lo.sqrt()]
            },
            w[0].sqrt(),
            w[1].sqrt(),
            8,
        );
        area += a;
    }
    area
}

/// C_D·β/τ² of the true delta with edge parameter `m` and ridge at `ridge`
/// (0 < f < 1), computed at β = 1 (the scaled drag depends on m alone).
pub fn scaled_wave_drag(m: f64, ridge: f64) -> Result<f64, SupersonicError> {
    if !(m.is_finite() && m > 0.0) {
        return Err(Invalid::NonFinite {
            quantity: "the edge parameter β cot Λ",
            value: m,
        }
        .into());
    }
    if !(ridge > 0.0 && ridge < 1.0) {
        return Err(SupersonicError::Ridge(ridge));
    }
    // β = 1, cot Λ = m, c₀ = 1, τ = 1: slopes z₁ = 1/(2f), z₂ = −1/(2(1 − f))
    let (z1, z2) = (0.5 / ridge, -0.5 / (1.0 - ridge));
    let mr = m / (1.0 - ridge);
    let phi = |x: f64, y: f64| {
        -2.0 / PI * (z1 * chevron_area(x, y, m) + (z2 - z1) * chevron_area(x - ridge, y, mr))
    };
    let s = m; // semi-span cot Λ at β = 1
    let integrand = |y: f64| {
        let le = y / m;
        let xr = ridge + (1.0 - ridge) * y / m;
        [-z1 * phi(le, y) + (z1 - z2) * phi(xr, y) + z2 * phi(1.0, y)]
    };
    let mut br = vec![0.0, s];
    for c in [
        1.0,
        1.0 - ridge,
        m * ridge / (m - 1.0).abs().max(1e-12),
        m * ridge / (m + 1.0),
    ] {
        if c > 0.0 && c < s {
            br.push(c);
        }
    }
    br.sort_by(f64::total_cmp);
    let mut sum = 0.0;
    for w in br.windows(2) {
        sum += adaptive(integrand, w[0], w[1], 1e-8, 18)[0];
    }
    // both halves; S = cot Λ = m
    Ok(-4.0 * 2.0 * sum / s)
}

/// The curve C_D·β/τ² against m = β cot Λ for the note's sections
/// ([`NOTE_RIDGE`]), at the given edge parameters.
pub fn fig1_series(edge_parameters: &[f64]) -> Result<Vec<WaveDragPoint>, SupersonicError> {
    edge_parameters
        .iter()
        .map(|&m| {
            Ok(WaveDragPoint {
                edge_parameter: m,
                scaled_drag: scaled_wave_drag(m, NOTE_RIDGE)?,
            })
        })
        .collect()
}

/// Mean weighted thickness-chord ratio of the report's sections, eq (23):
/// τ² = 0.0036.
pub const THICKNESS: f64 = 0.06;

/// C_Dw of a true delta of sweep Λ at Mach M > 1 with the note's sections
/// (τ = 0.06): (τ²/β)·[`scaled_wave_drag`](β cot Λ, 0.3).
pub fn wave_drag(sweep_le: f64, mach: f64) -> Result<f64, SupersonicError> {
    let wing = super::Wing::new(sweep_le, 0.0)?;
    let beta = super::check_mach(mach)?;
    let tau = THICKNESS;
    Ok(tau * tau / beta * scaled_wave_drag(beta * wing.cot(), NOTE_RIDGE)?)
}
