//! Ackeret's two-dimensional supersonic flat plate to first order in
//! frequency, its strip integrals over a delta, and the true delta with
//! supersonic leading edges, which they give exactly.
//!
//! **Two dimensions.** J. Ackeret, "Luftkräfte auf Flügel, die mit
//! grösserer als Schallgeschwindigkeit bewegt werden", ZFM 16 (1925):
//! ΔC_p = 4α/β. To first order in frequency (I.E. Garrick and S.I.
//! Rubinow, NACA Rep. 846, 1946; J.W. Miles, *The Potential Theory of
//! Unsteady Supersonic Flow*, 1959, §5.3) a plunging plate carries
//! ΔC_p = (4/β)[α − (α̇x/V)/β²], x from its leading edge; a pitch rate q
//! about x₀ adds ΔC_p = 4q(x − x₀)/(βV). Per chord c, about h (fraction of
//! c): a = 4/β, H₀ = ½, z_q = −(4/β)(½ − h), m_q = −(4/β)(⅓ − h + h²),
//! z_ẇ = 2/β³, m_ẇ = (4/β³)(⅓ − h/2); m_θ̇ = m_q + m_ẇ about the leading
//! edge is −(4/3β)(M² − 2)/(M² − 1), the classical result (negative
//! damping for M < √2 about a forward axis).
//!
//! **The true delta.** With supersonic leading edges every source's aft
//! Mach cone lies on the wing up to the trailing edge (its half-width grows
//! as 1/β < cot Λ), so the trailing-edge and area integrals of the
//! potential by which the lift and moment are written
//! (`PotentialIntegrals`) take their two-dimensional values source by
//! source: *every* derivative of the true delta is exactly its strip
//! integral — a = 4/β (A.E. Puckett, J. Aero. Sci. 13, 1946; H.J. Stewart,
//! Q. Appl. Math. 4, 1946), centre of pressure at ⅔c₀, and the damping
//! derivatives below, independent of Λ.

use super::{Derivatives, PotentialIntegrals, Wing};
use crate::derivatives::DampingDerivatives;

/// Ackeret's flat plate per chord, c.g. at fraction `h` of the chord.
pub fn two_dimensional(mach: f64, h: f64) -> Derivatives {
    let beta = (mach * mach - 1.0).sqrt();
    let b3 = beta * beta * beta;
    Derivatives {
        lift_slope: 4.0 / beta,
        aerodynamic_centre: 0.5,
        damping: DampingDerivatives {
            z_q: -4.0 / beta * (0.5 - h),
            z_wdot: 2.0 / b3,
            m_q: -4.0 / beta * (1.0 / 3.0 - h + h * h),
            m_wdot: 4.0 / b3 * (1.0 / 3.0 - 0.5 * h),
        },
    }
}

/// The true delta with supersonic (or sonic) leading edges, c.g. at h on
/// the M.A.C. (c̄ = ⅔c₀): a = 4/β, H₀ = ½, z_q = −(4/β)(½ − h),
/// m_q = −(4/β)(h² − h + ⅜), z_ẇ = 2/β³, m_ẇ = (2/β³)(⅝ − h) — the strip
/// integrals of [`two_dimensional`] over the triangle. At β cot Λ = 1 these
/// are eq (36)'s values (E = π/2, H = ⅔, A = 4/β).
pub fn true_delta(mach: f64, h: f64) -> Derivatives {
    let beta = (mach * mach - 1.0).sqrt();
    let b3 = beta * beta * beta;
    Derivatives {
        lift_slope: 4.0 / beta,
        aerodynamic_centre: 0.5,
        damping: DampingDerivatives {
            z_q: -4.0 / beta * (0.5 - h),
            z_wdot: 2.0 / b3,
            m_q: -4.0 / beta * (h * h - h + 0.375),
            m_wdot: 2.0 / b3 * (0.625 - h),
        },
    }
}

/// The planform moments ⟨xᵏ⟩ = ∫∫ xᵏ dS of the cropped delta (c₀ = 1),
/// k = 0…3: 2 cot Λ x_tᵏ⁺²/(k + 2) + 2s(1 − x_tᵏ⁺¹)/(k + 1), x_t = 1 − λ the
/// tip's leading edge, s = x_t cot Λ.
pub fn moments(wing: &Wing) -> [f64; 4] {
    let xt = 1.0 - wing.taper;
    let cot = wing.cot();
    let s = wing.semi_span();
    std::array::from_fn(|k| {
        let k = k as i32;
        2.0 * cot * xt.powi(k + 2) / f64::from(k + 2)
            + 2.0 * s * (1.0 - xt.powi(k + 1)) / f64::from(k + 1)
    })
}

/// The strip integrals of two-dimensional theory over the wing: the
/// [`PotentialIntegrals`] with every source's aft cone complete
/// (Φ₀ = −(1/β)∫w dξ along each strip, Φ₁ = −(1/β)∫w(ξ − x) dξ):
/// te0 = −⟨1⟩/β, te1 = −⟨x⟩/β, ar0 = −⟨1 − x⟩/β, ar1 = −⟨x − x²⟩/β,
/// arx0 = −⟨1 − x²⟩/(2β), te_f = ⟨1 − x⟩/β, ar_f = ⟨(1 − x)²⟩/(2β).
pub fn strip_integrals(wing: &Wing, mach: f64) -> PotentialIntegrals {
    let beta = (mach * mach - 1.0).sqrt();
    let [m0, m1, m2, _] = moments(wing);
    PotentialIntegrals {
        te0: -m0 / beta,
        te1: -m1 / beta,
        ar0: -(m0 - m1) / beta,
        ar1: -(m1 - m2) / beta,
        arx0: -(m0 - m2) / (2.0 * beta),
        te_f: (m0 - m1) / beta,
        ar_f: (m0 - 2.0 * m1 + m2) / (2.0 * beta),
    }
}
