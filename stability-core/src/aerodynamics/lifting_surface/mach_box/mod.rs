//! Supersonic lifting-surface theory at any frequency: the Mach box method
//! for a straight-tapered wing in harmonic pitch and plunge, giving the same
//! [`Solution`] as the subsonic doublet lattice
//! ([`crate::aerodynamics::lifting_surface`]) for M > 1 — lift slope and aerodynamic
//! centre at ω̄, z_ẇ, m_ẇ, z_q, m_q about any c.g. by
//! [`Solution::derivatives`].
//!
//! # The method
//! The velocity potential of the oscillating wing is the oscillatory
//! supersonic source integral of the normalwash over the forward Mach cone
//! (Garrick & Rubinow, NACA Rep. 846, 1946; J.W. Miles, *The Potential
//! Theory of Unsteady Supersonic Flow*, 1959, ch. 5), discretised on boxes
//! whose diagonals are Mach lines — the Mach box method of S. Pines,
//! J. Dugundji and J. Neuringer, "Aerodynamic flutter derivatives for a
//! flexible wing with supersonic and subsonic edges", J. Aero. Sci. 22(10),
//! 1955, pp. 693–700, and H. Zartarian & P.T. Hsu, WADC TR 56-97, 1955/56,
//! with the off-wing "diaphragm" of subsonic edges (its normalwash makes
//! the potential vanish there). Chosen over the constant-pressure panel
//! method (Appa, J. Aircraft 24(10), 1987) because the potential needs no
//! linear system — the influence is causal, so the boxes are swept row
//! after row (the earlier rows' sum a causal convolution, done by fast
//! online convolution, [`upstream`]; no factorisation) — and because on a
//! wing with supersonic edges it is a direct quadrature of the exact
//! integral, to which it converges; the method also treats subsonic
//! leading edges and tips (the diaphragm) without a Kutta condition.
//! Improved over the classic method in two ways: boxes cut by an edge
//! carry their exact wing-area fraction ([`grid`]), and the loads follow
//! from the potential itself (lift and moment by parts, [`march`]), not
//! from differenced potentials.
//!
//! - [`across`]: the integral across the Mach cone both quadratures take,
//!   by its power series;
//! - [`influence`]: the box influence coefficients of the oscillatory
//!   kernel e^{−iσX}cos(νR)/R;
//! - [`grid`]: the characteristic grid, the boxes' classes and fractions;
//! - [`march`]: the row-by-row sweep and the loads;
//! - [`direct`]: the wing's own part of the potential, by quadrature at
//!   each receiving point;
//! - [`edge`]: the diaphragm's edge singularity (box weights and exact
//!   near-field coefficients of the upwash a/√d);
//! - [`upstream`]: the earlier rows' sum, a causal convolution, by relaxed
//!   (online) FFT multiplication or term by term;
//!
//! Its solutions are stored, one solve per (wing, M, p̄), by
//! [`crate::aerodynamics::lifting_surface::store`].
//!
//! # Convergence
//! With supersonic edges the error falls as the square of the box size
//! (the wing's potential is exact, the loads' quadrature along the strips
//! second order); [`MachBoxSpec::richardson`] combines the solutions of N
//! and N/2 strips, (4X_N − X_{N/2})/3. With a subsonic leading edge the
//! α̇ parts converge about as 1/N: `docs/supersonic-oscillatory.md`
//! tabulates the convergence against the exact reverse-flow values and
//! against the first-order theories (eq (36)).
//!
//! # Limits
//! Linear, inviscid, thin, flat wing, M > 1 and below the hypersonic
//! range. The trailing edge must be supersonic (β cot|Λ_TE| ≥ 1, so that
//! the wake does not act on the wing; no Kutta condition). Near M = 1 the
//! boxes (Δx = βΔy) grow short and the grid long ([`MAX_ROWS`];
//! [`MachBoxSpec::for_wing`] takes fewer strips there). Subsonic leading
//! edges: the diaphragm's upwash carries the edge's 1/√d singularity
//! exactly ([`edge`]); on the default grid within 0.6 % of eq (36) in
//! C_Lα, H₀, z_θ̇ and m_θ̇ (on m_q) for β cot Λ from 0.3 to 0.93, 1–4 %
//! in z_θ̇ between 0.95 and 1, where the diaphragm is narrower than a box
//! (`docs/supersonic-oscillatory.md`).
//! Below ω̄ = [`OMEGA_BAR_QUASI_STEADY`] the quasi-steady values are those
//! at ω̄ = 10⁻⁴ (the quadrature parts divided by ω̄; an O(ω̄²) error of
//! 10⁻⁸).

pub mod across;
pub mod direct;
pub mod edge;
pub mod grid;
pub mod influence;
pub mod march;
pub mod upstream;

use crate::aerodynamics::lifting_surface::Solution;
use crate::geometry::Trapezoid;
use num_complex::Complex64;
pub use upstream::Method;

/// Below this ω̄ the quasi-steady limit is returned (evaluated at
/// [`QUASI_STEADY_EVALUATION`]).
pub const OMEGA_BAR_QUASI_STEADY: f64 = 1e-6;

/// The ω̄ at which the quasi-steady limit is evaluated.
pub const QUASI_STEADY_EVALUATION: f64 = 1e-4;

/// The most strips a grid may have.
pub const MAX_STRIPS: usize = 400;

/// The most rows a grid may have (Δx = βΔy: the rows grow as 1/β towards
/// M = 1, and the diaphragm's march as the cube of the rows).
pub const MAX_ROWS: usize = 300;

/// Why the Mach box method cannot be applied.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MachBoxError {
    #[error(
        "the Mach box method is a supersonic theory: it needs M > 1, not M = {0} (use the doublet lattice below)"
    )]
    Mach(f64),
    #[error("the frequency parameter ω̄ = ωc̄/V must be finite and ≥ 0 (0: quasi-steady), not {0}")]
    Frequency(f64),
    #[error(
        "the trailing edge is subsonic at M = {mach} (β cot|Λ_TE| = {beta_cot:.4} < 1): the wake would act on the wing, which this method does not model; raise M above {sonic:.4}"
    )]
    SubsonicTrailingEdge {
        mach: f64,
        beta_cot: f64,
        sonic: f64,
    },
    #[error(
        "a Mach box grid needs between 4 and {max} strips (an even number for Richardson's extrapolation), not {0}",
        max = MAX_STRIPS
    )]
    Strips(usize),
    #[error(
        "{strips} strips at M = {mach} make a grid of {rows} rows, more than the {max} this method takes (the rows grow as 1/β towards M = 1): use fewer strips (MachBoxSpec::for_wing) or the transonic theories",
        max = MAX_ROWS
    )]
    TooManyRows {
        strips: usize,
        mach: f64,
        rows: usize,
    },
    #[error("the Mach box solution at M = {mach}, ω̄ = {omega_bar} is not finite")]
    NotFinite { mach: f64, omega_bar: f64 },
}

/// The grid: `strips` strips across the half span, and whether to
/// extrapolate over N and N/2 strips.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct MachBoxSpec {
    pub strips: usize,
    pub richardson: bool,
}

impl Default for MachBoxSpec {
    /// 128 strips, extrapolated (with 64): within 0.5 % of the exact
    /// reverse-flow values of supersonic-edged deltas at ω̄ ≤ 1
    /// (`tests/it/supersonic_oscillatory.rs`).
    fn default() -> Self {
        MachBoxSpec {
            strips: 128,
            richardson: true,
        }
    }
}

impl MachBoxSpec {
    /// The default grid ([`MachBoxSpec::default`]), or, where its rows
    /// would exceed [`MAX_ROWS`] (near M = 1), the most strips (even, at
    /// least 8) that keep within it.
    pub fn for_wing(wing: &Trapezoid, mach: f64) -> MachBoxSpec {
        let d = MachBoxSpec::default();
        let beta = (mach * mach - 1.0).max(0.0).sqrt();
        let fits = |n: usize| rows(wing, beta, n) <= MAX_ROWS;
        let strips = (8..=d.strips)
            .rev()
            .step_by(2)
            .find(|&n| fits(n))
            .unwrap_or(8);
        MachBoxSpec { strips, ..d }
    }
}

/// The rows of the grid of `strips` strips at β (as [`grid::Grid::new`]).
fn rows(wing: &Trapezoid, beta: f64, strips: usize) -> usize {
    let dx = beta * wing.semi_span / (strips as f64 - 0.5);
    let x_end = wing
        .root_chord
        .max(wing.leading_edge_at(wing.semi_span) + wing.tip_chord);
    let r = (x_end / dx).ceil();
    if r.is_finite() && r < 1e9 {
        r as usize
    } else {
        usize::MAX
    }
}

/// The wing's response at `mach` (> 1) and `omega_bar` (ω̄ = ωc̄/V ≥ 0) by
/// the Mach box method on the grid `spec`: moments about the M.A.C.'s
/// leading edge, in the report's notation (the [`Solution`] of the doublet
/// lattice).
pub fn solve(
    wing: &Trapezoid,
    mach: f64,
    omega_bar: f64,
    spec: MachBoxSpec,
) -> Result<Solution, MachBoxError> {
    solve_by(wing, mach, omega_bar, spec, Method::default())
}

/// [`solve`] with the earlier rows' sum done by `method` (the same numbers
/// to rounding; [`Method::Direct`] is the reference the tests compare
/// with).
pub fn solve_by(
    wing: &Trapezoid,
    mach: f64,
    omega_bar: f64,
    spec: MachBoxSpec,
    method: Method,
) -> Result<Solution, MachBoxError> {
    let beta = check(wing, mach, omega_bar)?;
    let n = spec.strips;
    let multiple = if spec.richardson { 2 } else { 1 };
    if !(4..=MAX_STRIPS).contains(&n) || !n.is_multiple_of(multiple) {
        return Err(MachBoxError::Strips(n));
    }
    let r = rows(wing, beta, n);
    if r > MAX_ROWS {
        return Err(MachBoxError::TooManyRows {
            strips: n,
            mach,
            rows: r,
        });
    }
    let evaluated = omega_bar.max(QUASI_STEADY_EVALUATION);
    let one = |strips: usize| solve_grid(wing, (mach, beta), evaluated, strips, method);
    let mut s = if spec.richardson {
        let (a, b) = rayon::join(|| one(n), || one(n / 2));
        let r = |x: f64, y: f64| (4.0 * x - y) / 3.0;
        Solution {
            lift_alpha: r(a.lift_alpha, b.lift_alpha),
            moment_alpha: r(a.moment_alpha, b.moment_alpha),
            lift_alphadot: r(a.lift_alphadot, b.lift_alphadot),
            moment_alphadot: r(a.moment_alphadot, b.moment_alphadot),
            lift_q: r(a.lift_q, b.lift_q),
            moment_q: r(a.moment_q, b.moment_q),
            ..a
        }
    } else {
        one(n)
    };
    if omega_bar < OMEGA_BAR_QUASI_STEADY {
        s.omega_bar = 0.0;
    }
    if s.numbers().iter().all(|v| v.is_finite()) {
        Ok(s)
    } else {
        Err(MachBoxError::NotFinite { mach, omega_bar })
    }
}

/// β, once M, ω̄ and the trailing edge are checked.
fn check(wing: &Trapezoid, mach: f64, omega_bar: f64) -> Result<f64, MachBoxError> {
    if !(mach.is_finite() && mach > 1.0) {
        return Err(MachBoxError::Mach(mach));
    }
    if !(omega_bar.is_finite() && omega_bar >= 0.0) {
        return Err(MachBoxError::Frequency(omega_bar));
    }
    let beta = (mach * mach - 1.0).sqrt();
    let tan_te = wing.sweep_te().tan().abs();
    // subsonic where β cot|Λ_TE| < 1, i.e. β < tan|Λ_TE|
    if beta < tan_te * (1.0 - 1e-12) {
        return Err(MachBoxError::SubsonicTrailingEdge {
            mach,
            beta_cot: beta / tan_te,
            sonic: (1.0 + tan_te * tan_te).sqrt(),
        });
    }
    Ok(beta)
}

/// One grid's solution at ω̄ > 0.
fn solve_grid(
    wing: &Trapezoid,
    (mach, beta): (f64, f64),
    omega_bar: f64,
    strips: usize,
    method: Method,
) -> Solution {
    let grid = grid::Grid::new(wing, beta, strips);
    let kappa = omega_bar / wing.mac();
    let (sigma, nu) = (
        kappa * mach * mach / (beta * beta),
        kappa * mach / (beta * beta),
    );
    let table = influence::Influence::new(grid.rows, sigma * grid.dx, nu * grid.dx);
    let flow = direct::Flow {
        beta,
        sigma,
        nu,
        x_mac: wing.x_mac(),
        mac: wing.mac(),
    };
    let phi = march::march(wing, &grid, &table, &flow, method);
    let [lift, moment]: [[Complex64; 2]; 2] = march::loads(wing, &grid, &phi, kappa);
    Solution {
        mach,
        omega_bar,
        lift_alpha: lift[0].re,
        moment_alpha: moment[0].re,
        lift_alphadot: lift[0].im / omega_bar,
        moment_alphadot: moment[0].im / omega_bar,
        lift_q: lift[1].re,
        moment_q: moment[1].re,
    }
}
