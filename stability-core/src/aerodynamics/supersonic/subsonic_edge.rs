//! The cropped delta with subsonic leading edges, β cot Λ < 1: the true
//! delta's potentials over the cropped planform, corrected behind each tip
//! by Evvard's theorem written for the potential.
//!
//! **The true delta** (subsonic leading edges; H.S. Ribner & F.S.
//! Malvestuto, NACA Rep. 908, 1948, after H.J. Stewart, Q. Appl. Math. 4,
//! 1946): with r = √(x²cot²Λ − y²), the upper-surface potentials of a unit
//! downwash and of the downwash w = x are (root chord 1, V = 1, Φz = w)
//!
//! Φ₀\[1\] = −r/E,  Φ₀\[x\] = −G x r,
//!
//! E, G Fig 18's functions of k² = 1 − β²cot²Λ ([`Fig18`]). They give eq (36)
//! exactly (`docs/damping-theories.md`), and at the sonic edge (k = 0,
//! E = π/2, G = 4/(3π)) they are the source integral itself, in closed form.
//! That each satisfies its boundary condition on the wing is tested
//! independently (`tests/it/supersonic.rs`: the downwash of the doublet sheet,
//! by the source solution of density Φ). To first order in frequency the
//! unsteady problem is the steady one with the downwash w(1 + iκξ) and
//! Φ = (1 − iκx)Ψ (κ = ωM²/(Vβ²)), so the kernel term of [`PotentialIntegrals`]
//! is Φ₁ = Φ₀\[x\] − xΦ₀\[1\], exactly as on a supersonic edge.
//!
//! **The tips.** Cropping changes the flow only in the aft Mach cone of the
//! cut-off part, i.e. behind the Mach line from each tip's leading corner;
//! the leading edge's diaphragm is ahead of it and unchanged. Behind it, at
//! a point P, Evvard's theorem (H.J. Evvard, NACA Rep. 951, 1950) removes
//! the sources ahead of the Mach line through T, where P's outboard
//! forward Mach line meets the tip — whatever those sources are, the
//! wing's downwash or the leading edge's diaphragm: in characteristic
//! coordinates U = x − βy, V = x + βy,
//!
//! Φ(P) = −(1/(2πβ)) ∫∫_{U > U_T} w dU dV/√((U_P − U)(V_P − V)).
//!
//! The V-integral at fixed U, g(U) = ∫ w dV/√(V_P − V), is the same for
//! every point of P's Mach line V = V_P, and along that line the true
//! delta's potential is −(1/(2πβ)) times g's Abel transform,
//! f(U₀) = ∫^{U₀} g dU/√(U₀ − U). So the removed part, the integral of g
//! beyond U_T against 1/√(U_P − U), is a truncated Abel integral of that
//! potential — ∫_{−∞}^a g/√(b − u) du = (1/π)∫_{−∞}^a f(t)√(b − a)/((b − t)√(a − t)) dt
//! (exchange the order in g = (1/π)∫f′(t)/√(u − t) dt, integrate by
//! parts) — and with t = U_T − (U_P − U_T)tan²θ
//!
//! Φ(P) = Φ_Δ(P) − (2/π) ∫₀^{θ_max} Φ_Δ(t, V_P) dθ,
//!
//! Φ_Δ the true delta's potential on its own (uncropped) planform beyond
//! the tip, θ_max where the line meets its leading edge. (At the tip itself
//! the correction is −Φ_Δ(P): the potential vanishes there, as it must on a
//! subsonic side edge.) No property of the leading edge enters, so this is
//! the route of [`super::evvard`] in another order; at the sonic edge both
//! apply, and they agree to rounding (tests/it/supersonic.rs) — the cropped
//! wing's theory is continuous in M across it. The same configuration
//! (streamwise tips, subsonic leading edges, supersonic trailing edge) is
//! the one of Malvestuto, Margolis & Ribner's lift and roll-damping theory,
//! NACA Rep. 970 (1950).
//!
//! **The integrals.** The seven [`PotentialIntegrals`] are the true delta's
//! r and x r over the cropped planform (chordwise by tanh-sinh, closed
//! ahead of the tip), plus twice the right tip's corrections: along the
//! trailing edge the θ-integral above; over the tip region the order is
//! exchanged, with t = U_T − σ², so that the integral along P's line V
//! (from T to the trailing edge, Q = 2(1 + βs − V) long in U) is closed:
//! ∫ √(U_P − U_T)/(U_P − t) dU_P = 2√Q − 2σ arctan(√Q/σ) = W₀, and with the
//! weight x_P, W₁ = ½[(2/3)Q^{3/2} − σ²W₀ + (U_T + V)W₀].
//!
//! **Limit.** One reflection per tip holds while no tip's Mach wave reaches
//! the other tip ahead of the trailing edge, c_t ≤ 2βs (then the two tips'
//! corrections add: neither tip's correction sees the other tip);
//! beyond it an error ([`SupersonicError::TipsInteract`]).

use super::eq36::Fig18;
use super::quadrature::tanh_sinh;
use super::{PotentialIntegrals, SupersonicError, Wing, check_mach};
use std::f64::consts::PI;

/// Nodes per unit of the tanh-sinh variable, as [`super::evvard`]'s: the
/// integrals to about 1e-11.
const LEVEL: usize = 12;

/// The wing at one Mach number in the quantities the integrals need.
struct Setup {
    beta: f64,
    /// β cot Λ (≤ 1).
    m: f64,
    /// cot Λ.
    cot: f64,
    /// The semi-span s and the tip's leading corner x_T = 1 − λ.
    s: f64,
    x_tip: f64,
}

impl Setup {
    /// (r, x) on the Mach line V at U = U_T − d, where `lead` is the line's
    /// distance in U from T to the (extended) leading edge, U_T − U_LE:
    /// r² = ¼β⁻²(1 + m)(U − U_LE)((1 + m)V − (1 − m)U).
    fn on_line(&self, v: f64, d: f64, lead: f64) -> (f64, f64) {
        let m = self.m;
        let u = v - 2.0 * self.beta * self.s - d;
        let to_edge = (lead - d).max(0.0);
        let other = ((1.0 + m) * v - (1.0 - m) * u).max(0.0);
        let r = ((1.0 + m) * to_edge * other).sqrt() / (2.0 * self.beta);
        (r, 0.5 * (u + v))
    }

    /// U_T − U_LE on the line V: 2mV/(1 + m) − 2βs (zero on the corner's
    /// Mach line).
    fn lead(&self, v: f64) -> f64 {
        (2.0 * self.m * v / (1.0 + self.m) - 2.0 * self.beta * self.s).max(0.0)
    }

    /// ∫ r dy and ∫ x r dy across the cropped planform at station x.
    fn across(&self, x: f64) -> f64 {
        let c2 = self.cot * self.cot;
        if x <= self.x_tip {
            return 0.5 * PI * c2 * x * x;
        }
        let xt = self.x_tip;
        c2 * (xt * (x * x - xt * xt).max(0.0).sqrt() + x * x * (xt / x).min(1.0).asin())
    }

    /// The true delta's part: [∫r dy at the trailing edge, ∫∫r dS, ∫∫x r dS].
    fn delta_part(&self) -> [f64; 3] {
        let xt = self.x_tip;
        let c2 = self.cot * self.cot;
        let [a0, a1] = tanh_sinh(
            |x| {
                let f = self.across(x);
                [f, x * f]
            },
            xt,
            1.0,
            LEVEL,
        );
        [
            self.across(1.0),
            0.5 * PI * c2 * xt.powi(3) / 3.0 + a0,
            0.5 * PI * c2 * xt.powi(4) / 4.0 + a1,
        ]
    }

    /// The right tip's correction at P = (x, y) behind its corner's Mach
    /// line, the operator −(2/π)∫₀^{θ_max} dθ applied to r and to x r along
    /// P's outboard Mach line (module doc).
    fn correction(&self, x: f64, y: f64) -> [f64; 2] {
        let v = x + self.beta * y;
        let q = 2.0 * self.beta * (self.s - y);
        let lead = self.lead(v);
        let top = (lead / q).sqrt().atan();
        let along = tanh_sinh(
            |th| {
                let tan = th.tan();
                let (r, x) = self.on_line(v, q * tan * tan, lead);
                [r, x * r]
            },
            0.0,
            top,
            LEVEL,
        );
        along.map(|a| -2.0 / PI * a)
    }

    /// The right tip's corrections integrated along the trailing edge
    /// behind the corner's Mach line, y from s − λ/β to s.
    fn trailing_edge_correction(&self) -> [f64; 2] {
        let s = self.s;
        let from = s - (1.0 - self.x_tip) / self.beta;
        tanh_sinh(|y| self.correction(1.0, y), from, s, LEVEL)
    }

    /// The right tip's corrections over its region: [∫∫ corr r, ∫∫ corr x r,
    /// ∫∫ x_P corr r] dS, lines V from the corner's, x_T + βs, to the
    /// trailing-edge tip's, 1 + βs (dS = dU dV/(2β)).
    fn area_correction(&self) -> [f64; 3] {
        let (beta, s) = (self.beta, self.s);
        let sum = tanh_sinh(
            |v| {
                let lead = self.lead(v);
                let q = (2.0 * (1.0 + beta * s - v)).max(0.0);
                let sq = q.sqrt();
                let a = v - 2.0 * beta * s;
                tanh_sinh(
                    |sigma| {
                        let (r, x) = self.on_line(v, sigma * sigma, lead);
                        let w0 = 2.0 * sq - 2.0 * sigma * sq.atan2(sigma);
                        let w1 = 0.5 * (2.0 / 3.0 * q * sq - sigma * sigma * w0 + (a + v) * w0);
                        [r * w0, x * r * w0, r * w1]
                    },
                    0.0,
                    lead.sqrt(),
                    LEVEL,
                )
            },
            self.x_tip + beta * s,
            1.0 + beta * s,
            LEVEL,
        );
        // (1/(2β))·(−1/π)·2 (the 2 of dt = 2σ dσ)
        sum.map(|a| -a / (PI * beta))
    }
}

impl Setup {
    /// The wing at `mach` (0 < β cot Λ ≤ 1 assumed), checking the limit
    /// c_t ≤ 2βs.
    fn new(wing: &Wing, mach: f64) -> Result<(Setup, Fig18), SupersonicError> {
        let beta = check_mach(mach)?;
        let s = wing.semi_span();
        let two_beta_s = 2.0 * beta * s;
        if two_beta_s < wing.taper {
            return Err(SupersonicError::TipsInteract {
                mach,
                taper: wing.taper,
                two_beta_s,
                limit: wing.taper,
            });
        }
        let cot = wing.cot();
        let m = (beta * cot).min(1.0);
        let setup = Setup {
            beta,
            m,
            cot,
            s,
            x_tip: 1.0 - wing.taper,
        };
        Ok((setup, Fig18::at(m)))
    }
}

/// The upper-surface potentials \[Φ₀\[1\], Φ₀\[x\]\] of the cropped delta with
/// subsonic leading edges at the point (x, y) of the wing (c₀ = 1; zero
/// off it, ahead of the trailing edge): the true delta's, −r/E and −G x r,
/// plus each tip's correction where the point lies behind its corner's
/// Mach line (module doc). What [`integrals`] integrates; public for the
/// test of its boundary condition.
pub fn potentials(wing: &Wing, mach: f64, x: f64, y: f64) -> Result<[f64; 2], SupersonicError> {
    let (w, f) = Setup::new(wing, mach)?;
    let r2 = (w.cot * x).powi(2) - y * y;
    if y.abs() >= w.s || r2 <= 0.0 {
        return Ok([0.0; 2]);
    }
    let r = r2.sqrt();
    let (mut pr, mut pxr) = (r, x * r);
    for side in [y, -y] {
        if x > w.x_tip + w.beta * (w.s - side) {
            let [c, cx] = w.correction(x, side);
            pr += c;
            pxr += cx;
        }
    }
    Ok([-pr / f.e, -f.g * pxr])
}

/// The [`PotentialIntegrals`] of the cropped delta with subsonic leading
/// edges at Mach `mach` (0 < β cot Λ ≤ 1; the caller checks the regime):
/// the true delta's potentials over the cropped planform plus both tips'
/// corrections (module doc). [`SupersonicError::TipsInteract`] where a
/// tip's Mach wave reaches the other tip, c_t > 2βs.
pub fn integrals(wing: &Wing, mach: f64) -> Result<PotentialIntegrals, SupersonicError> {
    let (w, f) = Setup::new(wing, mach)?;
    let [te, ar, arx] = w.delta_part();
    let [te_r, te_xr] = w.trailing_edge_correction();
    let [ar_r, ar_xr, ar_x_r] = w.area_correction();
    // Φ₀\[1\] = −r/E, Φ₀\[x\] = −G x r; both tips alike
    let (e, g) = (f.e, f.g);
    let te0 = -(te + 2.0 * te_r) / e;
    let te1 = -g * (te + 2.0 * te_xr);
    let ar0 = -(ar + 2.0 * ar_r) / e;
    let ar1 = -g * (arx + 2.0 * ar_xr);
    let arx0 = -(arx + 2.0 * ar_x_r) / e;
    Ok(PotentialIntegrals {
        te0,
        te1,
        ar0,
        ar1,
        arx0,
        te_f: te1 - te0,
        ar_f: ar1 - arx0,
    })
}
