//! The characteristic equation solved at its own roots: the air forces at
//! each root's complex reduced frequency p̄ = s/μ₁ (the p-method), not at
//! the steady oscillation of the short period's ω̄ (the k-method).
//!
//! # The equations
//! Eq (4) with the wing's air forces as transfer functions of p̄: the
//! incidence column's z_w + z_ẇp̄ and m_w + m_ẇp̄ become the whole
//! incidence response at p̄, the rate column's z_q and m_q their values at
//! p̄. A theory solved on steady oscillations gives, at each real ω̄, the
//! damping derivatives z_ẇ, m_ẇ, z_q, m_q and the change of the in-phase
//! incidence derivatives from steady, Δz_w and Δm_w ([`AtFrequency`]):
//! real functions of ω̄, even in ω̄ (the transfer functions are real on the
//! real p̄ axis). Their analytic continuation to the complex
//! ω_c = −ip̄ = ω̄ − iσ̄ is the air forces at p̄ (the incidence response is
//! z_w + Δz_w(ω_c) + p̄z_ẇ(ω_c)), and the determinant of eq (4) with them
//! is an analytic function of s whose zeros are the exact roots
//! (Hassig, J. Aircraft 8(11), 1971; Edwards, Ashley & Breakwell, AIAA J.
//! 17(4), 1979). The rate response's quadrature part (a q̇ derivative, an
//! aerodynamic inertia of order m_q̇/(μ₁²i_B) beside the aircraft's) is
//! neglected, as the k-method neglects it.
//!
//! # The continuation
//! By the Lagrange polynomial through six real ω̄ ([`Stencil`]) evaluated
//! at ω_c: the nodes centred on the root's ω̄ and spaced by its |σ̄| (at
//! least [`SPACING_MIN`]), or symmetric about ω̄ = 0 (using the evenness)
//! for a slow or aperiodic root. Its error is of order
//! |σ̄|⁶f⁽⁶⁾/720 × 30: checked against the exact reverse-flow forces
//! continued analytically (`scripts/supersonic_p_method_reference.py`) and
//! against Theodorsen's function at complex p̄ (`tests/it/p_method.rs`).
//!
//! # The methods side by side ([`FrequencyMethod`])
//! - `k`: the quartic with the derivatives at the short period's ω̄, every
//!   root (the k-method of flutter analysis; the default before);
//! - `p-k`: each root with the damping and the in-phase derivatives at its
//!   own ω̄ = |Im p̄|, real (Rodden & Johnson, MSC Nastran Aeroelastic
//!   Analysis User's Guide, 1994, §2.6);
//! - `p`: each root with the air forces at its own complex p̄ (the exact
//!   root of linear theory).

use crate::Derivatives;
use num_complex::Complex64;
use serde::Serialize;

/// How the air forces' dependence on frequency enters the roots.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Hash)]
pub enum FrequencyMethod {
    /// The quartic with the derivatives at the short period's ω̄.
    K,
    /// Each root with real derivatives at its own ω̄.
    PK,
    /// Each root with the air forces at its own complex p̄ (exact).
    #[default]
    P,
}

impl FrequencyMethod {
    pub const ALL: [FrequencyMethod; 3] =
        [FrequencyMethod::K, FrequencyMethod::PK, FrequencyMethod::P];

    /// Its name on the command line and in configs.
    pub fn name(self) -> &'static str {
        match self {
            FrequencyMethod::K => "k",
            FrequencyMethod::PK => "p-k",
            FrequencyMethod::P => "p",
        }
    }

    /// The method of this name (`pk` accepted for `p-k`).
    pub fn parse(s: &str) -> Option<FrequencyMethod> {
        let s = if s == "pk" { "p-k" } else { s };
        Self::ALL.into_iter().find(|m| m.name() == s)
    }

    /// What it is, in a phrase.
    pub fn describe(self) -> &'static str {
        match self {
            FrequencyMethod::K => {
                "k-method: the derivatives at the short period's ω̄, in the quartic"
            }
            FrequencyMethod::PK => "p-k method: each root with real derivatives at its own ω̄",
            FrequencyMethod::P => {
                "p-method: each root with the air forces at its own complex frequency (exact)"
            }
        }
    }
}

impl Serialize for FrequencyMethod {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.name())
    }
}

/// A theory's aerodynamics at one real ω̄: the derivative set with the
/// damping derivatives at ω̄, and the change of the in-phase incidence
/// derivatives z_w, m_w from their steady values (the set's own).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AtFrequency {
    pub derivatives: Derivatives,
    pub dz_w: f64,
    pub dm_w: f64,
}

/// The fewest-spaced stencil: |σ̄| smaller than this takes this spacing.
pub const SPACING_MIN: f64 = 0.02;

/// Stencil nodes.
const N: usize = 6;

/// Six real ω̄ whose Lagrange polynomial continues the air forces to a
/// root's ω_c = −ip̄.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stencil {
    nodes: [f64; N],
    spacing: f64,
    centre: f64,
}

impl Stencil {
    /// The stencil for a root at p̄: spaced by h = max(|σ̄|, [`SPACING_MIN`]),
    /// centred on |ω̄| where every node stays above h/2, else on 0.
    pub fn around(p: Complex64) -> Stencil {
        let h = p.re.abs().max(SPACING_MIN);
        let w = p.im.abs();
        let centre = if w >= 3.0 * h { w } else { 0.0 };
        Stencil {
            nodes: std::array::from_fn(|j| centre + (j as f64 - 2.5) * h),
            spacing: h,
            centre,
        }
    }

    /// The nodes (signed: the ones below 0 take the value at |ω̄|).
    pub fn nodes(&self) -> [f64; N] {
        self.nodes
    }

    /// The ω̄ at which the aerodynamics are needed: |node| (the functions
    /// are even), each once, ascending — the first of the array's `.1`.
    pub fn abscissae(&self) -> ([f64; N], usize) {
        let mut a = self.nodes.map(f64::abs);
        a.sort_by(f64::total_cmp);
        let mut n = 0;
        for k in 0..N {
            if n == 0 || a[k] != a[n - 1] {
                a[n] = a[k];
                n += 1;
            }
        }
        (a, n)
    }

    /// The Lagrange weights of the nodes at `x`.
    pub fn weights(&self, x: Complex64) -> [Complex64; N] {
        std::array::from_fn(|j| {
            let mut w = Complex64::new(1.0, 0.0);
            for (m, &xm) in self.nodes.iter().enumerate() {
                if m != j {
                    w *= (x - xm) / (self.nodes[j] - xm);
                }
            }
            w
        })
    }

    /// Whether a root at p̄ is within the stencil's reach: ω_c within 1.5
    /// spacings of the real axis and inside the nodes' span.
    pub fn reaches(&self, p: Complex64) -> bool {
        let (w, s) = (p.im.abs(), p.re.abs());
        s <= 1.5 * self.spacing + 1e-15 && (w - self.centre).abs() <= 3.0 * self.spacing
    }
}

/// The position of input `name` in [`Derivatives::QUARTIC_INPUTS`]; a name
/// the spec lacks is a compile error where it is a constant.
const fn input(name: &str) -> usize {
    let inputs = Derivatives::QUARTIC_INPUTS;
    let mut k = 0;
    while k < inputs.len() {
        let (a, b) = (inputs[k].as_bytes(), name.as_bytes());
        if a.len() == b.len() {
            let mut i = 0;
            while i < a.len() && a[i] == b[i] {
                i += 1;
            }
            if i == a.len() {
                return k;
            }
        }
        k += 1;
    }
    panic!("not an input of the quartic's spec")
}

const Z_W: usize = input("z_w");
const M_W: usize = input("m_w");
const Z_WDOT: usize = input("z_wdot");
const M_WDOT: usize = input("m_wdot");
const Z_Q: usize = input("z_q");
const M_Q: usize = input("m_q");

/// The continued quantities at ω̄: z_ẇ, m_ẇ, z_q, m_q, Δz_w, Δm_w.
fn varying(a: &AtFrequency) -> [f64; 6] {
    let d = &a.derivatives;
    [d.z_wdot, d.m_wdot, d.z_q, d.m_q, a.dz_w, a.dm_w]
}

/// The stencil's samples, node by node (each node's |ω̄| looked up).
struct Samples {
    stencil: Stencil,
    at_nodes: [[f64; 6]; N],
    base: Derivatives,
}

impl Samples {
    fn new<E>(
        stencil: Stencil,
        sample: &mut impl FnMut(f64) -> Result<AtFrequency, E>,
    ) -> Result<Samples, E> {
        let (abscissae, n) = stencil.abscissae();
        let first = sample(abscissae[0])?;
        let mut values = [varying(&first); N];
        for k in 1..n {
            values[k] = varying(&sample(abscissae[k])?);
        }
        let find = |x: f64| {
            let k = abscissae[..n].iter().position(|a| *a == x.abs());
            values[k.unwrap_or_default()]
        };
        Ok(Samples {
            stencil,
            at_nodes: stencil.nodes.map(find),
            base: first.derivatives,
        })
    }

    /// The inputs of eq (4) at the root s (1/τ): the damping derivatives
    /// continued to ω_c = −is/μ₁ (`method` P) or taken at ω̄ = |Im s|/μ₁
    /// (`PK`), the in-phase change with them.
    fn inputs(&self, s: Complex64, method: FrequencyMethod) -> [Complex64; 15] {
        let mu1 = self.base.mu1;
        let p = s / mu1;
        let x = match method {
            FrequencyMethod::P => Complex64::new(p.im, -p.re),
            _ => Complex64::new(p.im.abs(), 0.0),
        };
        let w = self.stencil.weights(x);
        let mut v = [Complex64::default(); 6];
        for (j, node) in self.at_nodes.iter().enumerate() {
            for k in 0..6 {
                v[k] += w[j] * node[k];
            }
        }
        let [z_wdot, m_wdot, z_q, m_q, dz_w, dm_w] = v;
        let mut d = self
            .base
            .quartic_input_values()
            .map(|x| Complex64::new(x, 0.0));
        d[Z_Q] = z_q;
        d[M_Q] = m_q;
        if method == FrequencyMethod::P && p.norm() > 1e-12 {
            d[Z_WDOT] = z_wdot + dz_w / p;
            d[M_WDOT] = m_wdot + dm_w / p;
        } else {
            d[Z_WDOT] = z_wdot;
            d[M_WDOT] = m_wdot;
            d[Z_W] += dz_w;
            d[M_W] += dm_w;
        }
        d
    }

    /// The determinant of eq (4) at s with the air forces at s.
    fn characteristic(&self, s: Complex64, method: FrequencyMethod) -> Complex64 {
        let c = Derivatives::quartic_coefficients_of(self.inputs(s, method));
        c.iter().fold(Complex64::default(), |acc, &k| acc * s + k)
    }
}

/// Stencils a root may move through before it is given up.
pub const MAX_RESTENCILS: usize = 4;

/// Relative step at which a root is converged (|Δs| ≤ TOL·max(1, |s|)).
pub const TOLERANCE: f64 = 1e-11;

/// The root of eq (4) with the air forces at the root itself, by `method`,
/// from the quartic's root `start` (1/τ); `sample` gives the aerodynamics
/// at a real ω̄. A real start is sought first on the real axis (the
/// determinant is real there: the continuation is even), then, where two
/// real roots have joined into a pair at their own frequency, off it.
/// `Ok(None)` where the secant does not converge or the root leaves
/// [`MAX_RESTENCILS`] stencils.
pub fn root<E>(
    sample: &mut impl FnMut(f64) -> Result<AtFrequency, E>,
    start: Complex64,
    mu1: f64,
    method: FrequencyMethod,
) -> Result<Option<Complex64>, E> {
    // a root found off the axis but on it to rounding is a real root
    let snap = |r: Complex64| {
        if r.im.abs() <= ON_AXIS * r.norm() {
            Complex64::new(r.re, 0.0)
        } else {
            r
        }
    };
    if start.im != 0.0 {
        return Ok(seek(sample, start, mu1, method, false, None)?.map(snap));
    }
    if let Some(r) = seek(sample, start, mu1, method, true, None)? {
        return Ok(Some(r));
    }
    let off = Complex64::new(start.re, 0.1 * start.re.abs().max(1e-3));
    Ok(seek(sample, off, mu1, method, false, None)?.map(snap))
}

/// The second real root of a pair that split at its own frequency: from
/// `start` (the pair's upper root), on the real axis, the first root
/// `found` divided out.
fn other_real<E>(
    sample: &mut impl FnMut(f64) -> Result<AtFrequency, E>,
    start: Complex64,
    found: Complex64,
    mu1: f64,
    method: FrequencyMethod,
) -> Result<Option<Complex64>, E> {
    let from = Complex64::new(start.re - start.im.abs(), 0.0);
    let from = if from == found {
        from * (1.0 + 1e-6)
    } else {
        from
    };
    seek(sample, from, mu1, method, true, Some(found))
}

/// A root within this of the real axis (relative to its modulus), found
/// off it, is real.
pub const ON_AXIS: f64 = 1e-9;

/// The secant from `start`, re-stencilled as the root moves; on the real
/// axis only if `real`; with the root `found` divided out, if given.
fn seek<E>(
    sample: &mut impl FnMut(f64) -> Result<AtFrequency, E>,
    start: Complex64,
    mu1: f64,
    method: FrequencyMethod,
    real: bool,
    found: Option<Complex64>,
) -> Result<Option<Complex64>, E> {
    let mut s = start;
    for _ in 0..MAX_RESTENCILS {
        let samples = Samples::new(Stencil::around(s / mu1), sample)?;
        let f = |z: Complex64| {
            let mut v = samples.characteristic(z, method);
            if let Some(r) = found {
                v /= z - r;
            }
            let v = if real { Complex64::new(v.re, 0.0) } else { v };
            v.is_finite().then_some(v)
        };
        let nudge = Complex64::new(1e-7 * s.norm().max(1e-3), 0.0);
        let secant = crate::numerics::complex_root::secant(f, (s, s + nudge), TOLERANCE, 60);
        let Some(next) = secant else {
            return Ok(None);
        };
        if samples.stencil.reaches(next / mu1) {
            return Ok(Some(next));
        }
        s = next;
    }
    Ok(None)
}

/// Every root of eq (4) by `method` from the quartic's `roots` (1/τ,
/// conjugates adjacent): each upper root and each real root solved at its
/// own frequency ([`root`]), conjugates mirrored; two real roots that join
/// into a pair become it, a pair that splits becomes two real roots. A
/// root (or pair) whose own-frequency root is not found — a heavily damped
/// one, whose frequency lies beyond the continuation's reach — keeps the
/// quartic's, as does one whose stencil asks the theory for a frequency
/// it refuses (the sonic solution below ω̄ = 0.3, say); the second number
/// counts them. `K` returns `roots`.
pub fn roots<E>(
    sample: &mut impl FnMut(f64) -> Result<AtFrequency, E>,
    roots: [Complex64; 4],
    mu1: f64,
    method: FrequencyMethod,
) -> ([Complex64; 4], usize) {
    let mut out = roots;
    if method == FrequencyMethod::K {
        return (out, 0);
    }
    let (mut done, mut kept) = ([false; 4], 0);
    for k in 0..4 {
        let z = roots[k];
        if done[k] || z.im < 0.0 {
            continue;
        }
        done[k] = true;
        // its partner: the lower root nearest z̄, or, for a real start, the
        // nearest other real root (only if the two join)
        let partner = |done: &[bool; 4], real: bool| {
            (0..4)
                .filter(|&j| !done[j] && (roots[j].im < 0.0 || (real && roots[j].im == 0.0)))
                .min_by(|&a, &b| {
                    let d = |j: usize| (roots[j] - z.conj()).norm();
                    d(a).total_cmp(&d(b))
                })
        };
        let found = root(sample, z, mu1, method).ok().flatten();
        match found {
            Some(r) if r.im == 0.0 && z.im == 0.0 => out[k] = r,
            Some(r) if r.im == 0.0 => {
                // a pair that split into two real roots
                let c = partner(&done, false);
                let second = match c {
                    Some(_) => other_real(sample, z, r, mu1, method).ok().flatten(),
                    None => None,
                };
                match (c, second) {
                    (Some(c), Some(second)) => {
                        (out[k], out[c], done[c]) = (r, second, true);
                    }
                    (c, _) => {
                        kept += 1;
                        if let Some(c) = c {
                            done[c] = true;
                        }
                    }
                }
            }
            Some(r) => match partner(&done, z.im == 0.0) {
                Some(c) => {
                    let upper = Complex64::new(r.re, r.im.abs());
                    (out[k], out[c], done[c]) = (upper, upper.conj(), true);
                }
                None => kept += 1,
            },
            None => {
                kept += 1;
                if z.im > 0.0
                    && let Some(c) = partner(&done, false)
                {
                    done[c] = true;
                }
            }
        }
    }
    (out, kept)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_stencil_reproduces_a_quintic_off_the_axis_and_knows_its_reach() {
        let st = Stencil::around(Complex64::new(-0.1, 0.5));
        assert_eq!(st.abscissae().1, 6);
        let f = |x: Complex64| x * x * x * x * x - 2.0 * x * x + 0.3;
        let nodes = st.nodes;
        let x = Complex64::new(0.5, 0.1);
        let w = st.weights(x);
        let v: Complex64 = (0..N)
            .map(|j| w[j] * f(Complex64::new(nodes[j], 0.0)))
            .sum();
        assert!((v - f(x)).norm() < 1e-12);
        assert!(st.reaches(Complex64::new(-0.12, 0.55)));
        assert!(!st.reaches(Complex64::new(-0.3, 0.5)));
        // a slow root: symmetric about 0, three distinct ω̄
        let slow = Stencil::around(Complex64::new(-0.001, 0.004));
        let (a, n) = slow.abscissae();
        assert_eq!(n, 3);
        for (x, want) in a.iter().zip([0.01, 0.03, 0.05]) {
            assert!((x - want).abs() < 1e-15);
        }
        assert_eq!(FrequencyMethod::parse("pk"), Some(FrequencyMethod::PK));
        assert_eq!(FrequencyMethod::parse("p").map(|m| m.name()), Some("p"));
    }
}
