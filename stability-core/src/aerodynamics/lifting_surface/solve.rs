//! Assembling the normalwash matrix and solving it: one dense LU per
//! lattice (three for the extrapolated default) per (planform, Mach number,
//! ω̄), with two right-hand sides, incidence and pitch rate, from which
//! every derivative follows by axis transfer ([`Solution::derivatives`]).
//!
//! With the lifting-pressure coefficients f = Δc_p of the boxes, the
//! normalwash at collocation point i is w̄ᵢ = Σⱼ Dᵢⱼ fⱼ, Dᵢⱼ the factor of box
//! j and of its mirror image. The boundary conditions (w̄ positive
//! downwards: an incidence) for a surface displaced by h(x, t) = h e^{iωt}
//! upwards are w̄ = −(1/V)(∂h/∂t + V∂h/∂x); for the two motions used:
//! - incidence oscillation (plunge) α = α₀e^{iωt}: w̄ = α₀;
//! - pitch θ = θ₀e^{iωt} about x = x_a, flight path fixed
//!   (h = −θ(x − x_a)): w̄ = θ₀[1 + iω̄(x − x_a)/c̄].
//!
//! So with the unit incidence w̄ = 1 and the unit rate w̄ = (x − x̄)/c̄
//! (x̄ the M.A.C.'s leading edge), pitch about any axis is
//! (1 + iω̄(x̄ − x_a)/c̄)·incidence + iω̄·rate: two solves serve every axis.

use super::derivatives::Extrapolate;
use super::doublet_line::{DoubletLine, FRAC_1_SQRT_3, GAUSS_BEYOND, LineRule};
use super::kernel::{self, KernelFlow, Radial};
use super::lattice::{Box, Grid, Lattice};
use super::{LiftingSurfaceError, OMEGA_BAR_QUASI_STEADY, Solution, Steady};
use arrayvec::ArrayVec;
use nalgebra::{DMatrix, Dyn, LU};
use num_complex::Complex64;
use rayon::prelude::*;

impl Lattice {
    /// The wing's response at Mach `mach` (0 ≤ M < 1) and frequency
    /// parameter `omega_bar` (ω̄ = ωc̄/V ≥ 0, c̄ the M.A.C.).
    ///
    /// ω̄ > 0: the harmonic solution, one complex LU per lattice. ω̄ = 0:
    /// the quasi-steady limit, exactly — the first-order term of the kernel
    /// in frequency ([`super::kernel::first_order_numerator`]), one real LU
    /// per lattice: with D = D₀ + iω̄D₁ + O(ω̄² ln ω̄) the response to a
    /// frequency-free normalwash w̄ is f₀ + iω̄f₁, D₀f₀ = w̄, D₀f₁ = −D₁f₀.
    /// Below ω̄ = [`OMEGA_BAR_QUASI_STEADY`] the quasi-steady solution is
    /// returned (the quadrature parts divided by ω̄ would be rounding noise).
    ///
    /// With [`super::Extrapolation::Richardson`] each number of the
    /// [`Solution`] is extrapolated over the three lattices.
    pub fn solve(&self, mach: f64, omega_bar: f64) -> Result<Solution, LiftingSurfaceError> {
        check_mach(mach)?;
        if !(omega_bar.is_finite() && omega_bar >= 0.0) {
            return Err(LiftingSurfaceError::Frequency(omega_bar));
        }
        self.extrapolated(|grid| {
            if omega_bar < OMEGA_BAR_QUASI_STEADY {
                self.solve_quasi_steady(grid, mach)
            } else {
                self.solve_harmonic(grid, mach, omega_bar)
            }
        })
    }

    /// The quasi-steady solution at `mach` ([`Lattice::solve`] at ω̄ = 0)
    /// with the exact Mach derivatives of its in-phase numbers, from the
    /// same LU: the steady matrix D₀(M) gives D₀f₀ = w̄ and
    /// D₀(df₀/dM) = −(dD₀/dM)f₀, dD₀/dM entry by entry in closed form
    /// ([`super::doublet_line::DoubletLine::steady_mach_rate`]) — the
    /// Prandtl–Glauert stretching differentiated, not a difference.
    /// Extrapolated as [`Lattice::solve`] is (the derivative of the
    /// extrapolated value).
    pub fn solve_steady(&self, mach: f64) -> Result<Steady, LiftingSurfaceError> {
        check_mach(mach)?;
        let steady = self.extrapolated(|grid| self.quasi_steady(grid, mach, true))?;
        let s = Solution::checked(steady.solution)?;
        let rates = [
            steady.d_lift_alpha,
            steady.d_moment_alpha,
            steady.d_lift_q,
            steady.d_moment_q,
        ];
        if rates.iter().all(|r| r.is_finite()) {
            Ok(Steady {
                solution: s,
                ..steady
            })
        } else {
            Err(LiftingSurfaceError::NotFinite {
                mach,
                omega_bar: 0.0,
            })
        }
    }

    /// `solve` on every lattice, extrapolated as the spec says (each lattice
    /// solved, finest first; see [`super::Extrapolation`]).
    fn extrapolated<T: Extrapolate + Send>(
        &self,
        solve: impl Fn(&Grid) -> Result<T, LiftingSurfaceError> + Sync,
    ) -> Result<T, LiftingSurfaceError> {
        // the lattices in parallel (each one's assembly too)
        let chordwise = |g: &[Grid]| -> Result<T, LiftingSurfaceError> {
            if g.len() == 1 {
                return solve(&g[0]);
            }
            let (finest, (middle, coarsest)) = rayon::join(
                || solve(&g[0]),
                || rayon::join(|| solve(&g[1]), || solve(&g[2])),
            );
            Ok(finest?.richardson(&middle?, &coarsest?))
        };
        let grids = self.grids();
        if grids.len() < 6 {
            return chordwise(grids).and_then(T::checked);
        }
        let (fine, coarse) = rayon::join(|| chordwise(&grids[..3]), || chordwise(&grids[3..]));
        T::checked(fine?.combine(&coarse?, 4.0 / 3.0, -1.0 / 3.0))
    }

    /// The right-hand sides: unit incidence, and unit rate (x − x̄)/c̄.
    fn normalwash(&self, boxes: &[Box]) -> DMatrix<f64> {
        let (x_mac, mac) = (self.wing().x_mac(), self.wing().mac());
        DMatrix::from_fn(boxes.len(), 2, |i, col| match col {
            0 => 1.0,
            _ => (boxes[i].x_c - x_mac) / mac,
        })
    }

    /// C_L and C_m (about the M.A.C.'s leading edge, nose up, on c̄) of a
    /// pressure distribution: each box's load acts at its doublet line's
    /// centre.
    fn loads<T>(&self, boxes: &[Box], f: impl Iterator<Item = T>) -> (T, T)
    where
        T: Copy + std::ops::Mul<f64, Output = T> + std::ops::Add<Output = T> + Default,
    {
        let (x_mac, mac) = (self.wing().x_mac(), self.wing().mac());
        let half_area = 0.5 * self.wing().area();
        let mut lift = T::default();
        let mut moment = T::default();
        for (b, fj) in boxes.iter().zip(f) {
            let a = b.area / half_area;
            lift = lift + fj * a;
            moment = moment + fj * (-a * (b.line.xi - x_mac) / mac);
        }
        (lift, moment)
    }

    fn solve_harmonic(
        &self,
        grid: &Grid,
        mach: f64,
        omega_bar: f64,
    ) -> Result<Solution, LiftingSurfaceError> {
        let boxes = &grid.boxes[..];
        let flow = KernelFlow::new(mach, omega_bar / self.wing().mac(), self.spec().kernel);
        let d = harmonic_matrix(grid, &flow, self.spec().line_rule);
        let f = complex_solve(&d, &self.normalwash(boxes));
        let (l1, m1) = self.loads(boxes, (0..boxes.len()).map(|i| f[(i, 0)]));
        let (l2, m2) = self.loads(boxes, (0..boxes.len()).map(|i| f[(i, 1)]));
        Solution::checked(Solution {
            mach,
            omega_bar,
            lift_alpha: l1.re,
            moment_alpha: m1.re,
            lift_alphadot: l1.im / omega_bar,
            moment_alphadot: m1.im / omega_bar,
            lift_q: l2.re,
            moment_q: m2.re,
        })
    }

    fn solve_quasi_steady(&self, grid: &Grid, mach: f64) -> Result<Solution, LiftingSurfaceError> {
        Ok(self.quasi_steady(grid, mach, false)?.solution)
    }

    /// The quasi-steady solve of one lattice, and with `rates` the Mach
    /// derivatives of its in-phase numbers (else zeros).
    fn quasi_steady(
        &self,
        grid: &Grid,
        mach: f64,
        rates: bool,
    ) -> Result<Steady, LiftingSurfaceError> {
        let boxes = &grid.boxes[..];
        let beta2 = 1.0 - mach * mach;
        let beta = beta2.sqrt();
        let singular = LiftingSurfaceError::Singular {
            mach,
            omega_bar: 0.0,
        };
        let lu: LU<f64, Dyn, Dyn> = matrix(boxes, |line, x, y| line.steady(x, y, beta)).lu();
        let f0 = lu.solve(&self.normalwash(boxes)).ok_or(singular.clone())?;
        let d1 = self.first_order_matrix(grid, beta2);
        let f1 = lu.solve(&(-(d1 * f0.column(0)))).ok_or(singular.clone())?;
        let (l1, m1) = self.loads(boxes, f0.column(0).iter().copied());
        let (l1dot, m1dot) = self.loads(boxes, f1.iter().copied());
        let (l2, m2) = self.loads(boxes, f0.column(1).iter().copied());
        let solution = Solution::checked(Solution {
            mach,
            omega_bar: 0.0,
            lift_alpha: l1,
            moment_alpha: m1,
            lift_alphadot: l1dot,
            moment_alphadot: m1dot,
            lift_q: l2,
            moment_q: m2,
        })?;
        let [d_lift_alpha, d_moment_alpha, d_lift_q, d_moment_q] = if rates {
            let dd = matrix(boxes, |line, x, y| line.steady_mach_rate(x, y, mach));
            let df = lu.solve(&(-(dd * &f0))).ok_or(singular)?;
            let (dl1, dm1) = self.loads(boxes, df.column(0).iter().copied());
            let (dl2, dm2) = self.loads(boxes, df.column(1).iter().copied());
            [dl1, dm1, dl2, dm2]
        } else {
            [0.0; 4]
        };
        Ok(Steady {
            solution,
            d_lift_alpha,
            d_moment_alpha,
            d_lift_q,
            d_moment_q,
        })
    }

    /// D₁ per unit iω̄ = (1/c̄) × the first-order factor per unit iκ.
    fn first_order_matrix(&self, grid: &Grid, beta2: f64) -> DMatrix<f64> {
        let n = grid.boxes.len();
        let mut d1 = DMatrix::zeros(n, n);
        let rule = self.spec().line_rule;
        add_blocked(
            &mut d1,
            grid,
            rule,
            |_| (),
            each(|x0, y0, _| kernel::first_order_numerator(x0, y0, beta2)),
            |line, x, y| line.first_order(x, y, beta2, rule),
        );
        d1 / self.wing().mac()
    }
}

/// 0 ≤ M < 1, or the error.
pub(crate) fn check_mach(mach: f64) -> Result<(), LiftingSurfaceError> {
    if mach.is_finite() && (0.0..1.0).contains(&mach) {
        Ok(())
    } else {
        Err(LiftingSurfaceError::Mach(mach))
    }
}

/// D f = w̄ for the complex harmonic matrix, by faer's partially pivoted LU
/// (measured 2.7 times faster than nalgebra's at 192 boxes, one core). A
/// singular D shows as a non-finite solution, which [`Solution::checked`]
/// turns into an error.
pub(crate) fn complex_solve(d: &DMatrix<Complex64>, w: &DMatrix<f64>) -> faer::Mat<Complex64> {
    use faer::linalg::solvers::Solve;
    let n = d.nrows();
    let a = faer::Mat::<Complex64>::from_fn(n, n, |i, j| d[(i, j)]);
    let b = faer::Mat::<Complex64>::from_fn(n, w.ncols(), |i, j| Complex64::new(w[(i, j)], 0.0));
    a.partial_piv_lu().solve(&b)
}

/// The harmonic Dᵢⱼ, steady plus oscillatory.
pub(crate) fn harmonic_matrix(
    grid: &Grid,
    flow: &KernelFlow,
    rule: LineRule,
) -> DMatrix<Complex64> {
    let beta = flow.beta2.sqrt();
    let mut d = matrix(&grid.boxes, |line, x, y| {
        Complex64::new(line.steady(x, y, beta), 0.0)
    });
    add_blocked(
        &mut d,
        grid,
        rule,
        |y0| Radial::new(y0, flow),
        |x0s, _, radial, out| kernel::increments_at(x0s, radial, flow, out),
        |line, x, y| line.oscillatory(x, y, flow, rule),
    );
    d
}

/// The stations and weights of the line rule for a strip pair: Σₖ wₖ f(x₀ₖ, y₀ₖ)
/// ≈ FP∫ f/(ȳ − η′)² dη′ — two-point Gauss beyond |ȳ| = [`GAUSS_BEYOND`]·e,
/// the quartic otherwise (as [`DoubletLine`]'s own rule for a point off its
/// strip). Each station: (η′, y₀, weight).
fn strip_rule(ybar: f64, e: f64, rule: LineRule) -> ([(f64, f64, f64); 5], usize) {
    let mut out = [(0.0, 0.0, 0.0); 5];
    if rule == LineRule::Graded && ybar.abs() > GAUSS_BEYOND * e {
        for (k, s) in [-FRAC_1_SQRT_3, FRAC_1_SQRT_3].into_iter().enumerate() {
            let y0 = ybar - s * e;
            out[k] = (s * e, y0, e / (y0 * y0));
        }
        return (out, 2);
    }
    let w = super::doublet_line::quartic_weights(ybar, e);
    for (k, s) in [-1.0, -0.5, 0.0, 0.5, 1.0].into_iter().enumerate() {
        out[k] = (s * e, ybar - s * e, w[k]);
    }
    (out, 5)
}

/// Adds the oscillatory (or first-order) part to `d`, strip pair by strip
/// pair: off the receiving point's own strip, every box pair of two strips
/// shares the spanwise distances y₀ of the rule's stations, so the
/// stations' weights and whatever `prep` makes of y₀ (the kernel's
/// [`Radial`] factors) are computed once per block. On its own strip each
/// pair takes `own` (the line's graded rule). `eval(x₀s, y₀, prepared,
/// out)` gives the kernel at a receiving box's x₀ to each line of the
/// sending strip at once (a kernel may take them four at a time;
/// [`each`] makes one of a pointwise kernel). Equal to the pairwise
/// assembly with [`DoubletLine`]'s methods (tested); only faster.
pub(crate) fn add_blocked<T, R>(
    d: &mut DMatrix<T>,
    grid: &Grid,
    rule: LineRule,
    prep: impl Fn(f64) -> R + Sync,
    eval: impl Fn(&[f64], f64, &R, &mut [T]) + Sync,
    own: impl Fn(&DoubletLine, f64, f64) -> T + Sync,
) where
    T: nalgebra::Scalar
        + Copy
        + Default
        + Send
        + std::ops::AddAssign
        + std::ops::Mul<f64, Output = T>,
{
    let (boxes, nc) = (&grid.boxes[..], grid.chordwise);
    let n = boxes.len();
    if n == 0 {
        return;
    }
    // each sending strip's columns (column-major: contiguous) in parallel
    let strips = d.as_mut_slice().par_chunks_mut(n * nc);
    strips.enumerate().for_each(|(k, columns)| {
        let ss = k * nc;
        // D[(i, j)], j in the strip ss..ss + nc
        let mut add = |i: usize, j: usize, v: T| columns[(j - ss) * n + i] += v;
        // one receiving box's x₀ to the strip's lines, their values, sums
        let (mut xs, mut values, mut sums) = (
            vec![0.0; nc],
            vec![T::default(); nc],
            vec![T::default(); nc],
        );
        for rs in (0..n).step_by(nc) {
            let y = boxes[rs].y_c;
            for mirror in [false, true] {
                let at = |j: usize| {
                    let l = boxes[j].line;
                    if mirror { l.mirrored() } else { l }
                };
                let receiving = boxes.iter().enumerate().skip(rs).take(nc);
                if rs == ss && !mirror {
                    for (i, b) in receiving {
                        for j in ss..ss + nc {
                            add(i, j, own(&at(j), b.x_c, y));
                        }
                    }
                    continue;
                }
                let (stations, m) = strip_rule(y - at(ss).eta, at(ss).e, rule);
                let prepared: ArrayVec<R, 5> =
                    stations[..m].iter().map(|&(_, y0, _)| prep(y0)).collect();
                for (i, b) in receiving {
                    sums.fill(T::default());
                    for (&(eta, y0, w), p) in stations[..m].iter().zip(&prepared) {
                        for (j, x) in (ss..).zip(xs.iter_mut()) {
                            let line = at(j);
                            *x = (b.x_c - line.xi) - eta * line.tan_sweep;
                        }
                        eval(&xs, y0, p, &mut values);
                        for (sum, &v) in sums.iter_mut().zip(&values) {
                            *sum += v * w;
                        }
                    }
                    for (j, &sum) in (ss..).zip(&sums) {
                        add(i, j, sum * at(j).factor());
                    }
                }
            }
        }
    });
}

/// [`add_blocked`]'s `eval` of a pointwise kernel `f(x₀, y₀, prepared)`.
pub(crate) fn each<R, T>(
    f: impl Fn(f64, f64, &R) -> T + Sync,
) -> impl Fn(&[f64], f64, &R, &mut [T]) + Sync {
    move |xs, y0, p, out| {
        for (o, &x) in out.iter_mut().zip(xs) {
            *o = f(x, y0, p);
        }
    }
}

/// Dᵢⱼ = d(line j) + d(mirror of line j) at collocation point i.
pub(crate) fn matrix<T>(boxes: &[Box], d: impl Fn(&DoubletLine, f64, f64) -> T + Sync) -> DMatrix<T>
where
    T: nalgebra::Scalar + Copy + Default + Send + std::ops::Add<Output = T>,
{
    let n = boxes.len();
    let mut out = DMatrix::from_element(n, n, T::default());
    if n == 0 {
        return out;
    }
    // column by column (contiguous), in parallel
    let columns = out.as_mut_slice().par_chunks_mut(n);
    columns.enumerate().for_each(|(j, column)| {
        let line = boxes[j].line;
        for (i, slot) in column.iter_mut().enumerate() {
            let (x, y) = (boxes[i].x_c, boxes[i].y_c);
            *slot = d(&line, x, y) + d(&line.mirrored(), x, y);
        }
    });
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::aerodynamics::lifting_surface::{LatticeSpec, Spacing};
    use crate::geometry::Trapezoid;

    #[test]
    fn the_blocked_assembly_is_the_pairwise_one() {
        let w = Trapezoid::new(1.0, 0.3, 1.6, 0.7).unwrap();
        let l = Lattice::new(&w, LatticeSpec::new(4, 12, Spacing::Cosine)).unwrap();
        let flow = KernelFlow::new(
            0.6,
            0.9,
            crate::aerodynamics::lifting_surface::I1Approximation::Desmarais,
        );
        let beta = flow.beta2.sqrt();
        let rule = LineRule::Graded;
        let blocked = harmonic_matrix(&l.grids()[0], &flow, rule);
        let pairwise = matrix(l.boxes(), |line, x, y| {
            Complex64::new(line.steady(x, y, beta), 0.0) + line.oscillatory(x, y, &flow, rule)
        });
        let scale = pairwise.iter().map(|v| v.norm()).fold(0.0, f64::max);
        let worst = (blocked - pairwise)
            .iter()
            .map(|v| v.norm())
            .fold(0.0, f64::max);
        assert!(worst < 1e-13 * scale, "{worst} of {scale}");
        let mut blocked = DMatrix::zeros(l.boxes().len(), l.boxes().len());
        add_blocked(
            &mut blocked,
            &l.grids()[0],
            rule,
            |_| (),
            each(|x0, y0, _| kernel::first_order_numerator(x0, y0, flow.beta2)),
            |line, x, y| line.first_order(x, y, flow.beta2, rule),
        );
        let pairwise = matrix(l.boxes(), |line, x, y| {
            line.first_order(x, y, flow.beta2, rule)
        });
        let scale = pairwise.iter().map(|v| v.abs()).fold(0.0, f64::max);
        let worst = (blocked - pairwise)
            .iter()
            .map(|v| v.abs())
            .fold(0.0, f64::max);
        assert!(worst < 1e-13 * scale, "{worst} of {scale}");
    }
}
