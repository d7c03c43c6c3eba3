//! Assembling the normalwash matrix and solving it: one dense LU per
//! (planform, Mach number, ω̄) and two right-hand sides, incidence and
//! pitch rate, from which every derivative follows by axis transfer
//! ([`Solution::derivatives`]).
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

use super::kernel::KernelFlow;
use super::lattice::Lattice;
use super::{LiftingSurfaceError, OMEGA_BAR_QUASI_STEADY, Solution};
use nalgebra::{DMatrix, Dyn, LU};
use num_complex::Complex64;

impl Lattice {
    /// The lattice's response at Mach `mach` (0 ≤ M < 1) and frequency
    /// parameter `omega_bar` (ω̄ = ωc̄/V ≥ 0, c̄ the M.A.C.).
    ///
    /// ω̄ > 0: the harmonic solution, one complex LU. ω̄ = 0: the
    /// quasi-steady limit, exactly — the first-order term of the kernel in
    /// frequency ([`super::kernel::first_order_numerator`]), one real LU:
    /// with D = D₀ + iω̄D₁ + O(ω̄² ln ω̄) the response to a frequency-free
    /// normalwash w̄ is f₀ + iω̄f₁, D₀f₀ = w̄, D₀f₁ = −D₁f₀. Below
    /// ω̄ = [`OMEGA_BAR_QUASI_STEADY`] the quasi-steady solution is returned
    /// (the quadrature parts divided by ω̄ would be rounding noise; the two
    /// differ there by O(ω̄ ln ω̄) < 10⁻⁴).
    pub fn solve(&self, mach: f64, omega_bar: f64) -> Result<Solution, LiftingSurfaceError> {
        if !(mach.is_finite() && (0.0..1.0).contains(&mach)) {
            return Err(LiftingSurfaceError::Mach(mach));
        }
        if !(omega_bar.is_finite() && omega_bar >= 0.0) {
            return Err(LiftingSurfaceError::Frequency(omega_bar));
        }
        if omega_bar < OMEGA_BAR_QUASI_STEADY {
            self.solve_quasi_steady(mach)
        } else {
            self.solve_harmonic(mach, omega_bar)
        }
    }

    /// The right-hand sides: unit incidence, and unit rate (x − x̄)/c̄.
    fn normalwash(&self) -> DMatrix<f64> {
        let (x_mac, mac) = (self.wing().x_mac(), self.wing().mac());
        let n = self.boxes().len();
        DMatrix::from_fn(n, 2, |i, col| match col {
            0 => 1.0,
            _ => (self.boxes()[i].x_c - x_mac) / mac,
        })
    }

    /// C_L and C_m (about the M.A.C.'s leading edge, nose up, on c̄) of a
    /// pressure distribution: each box's load acts at its doublet line's
    /// centre.
    fn loads<T>(&self, f: impl Iterator<Item = T>) -> (T, T)
    where
        T: Copy + std::ops::Mul<f64, Output = T> + std::ops::Add<Output = T> + Default,
    {
        let (x_mac, mac) = (self.wing().x_mac(), self.wing().mac());
        let half_area = 0.5 * self.wing().area();
        let mut lift = T::default();
        let mut moment = T::default();
        for (b, fj) in self.boxes().iter().zip(f) {
            let a = b.area / half_area;
            lift = lift + fj * a;
            moment = moment + fj * (-a * (b.line.xi - x_mac) / mac);
        }
        (lift, moment)
    }

    fn solve_harmonic(&self, mach: f64, omega_bar: f64) -> Result<Solution, LiftingSurfaceError> {
        let flow = KernelFlow::new(mach, omega_bar / self.wing().mac(), self.spec().kernel);
        let beta = flow.beta2.sqrt();
        let d = self.matrix(|line, x, y| {
            Complex64::new(line.steady(x, y, beta), 0.0) + line.oscillatory(x, y, &flow)
        });
        let rhs = self.normalwash().map(|v| Complex64::new(v, 0.0));
        let f = d
            .lu()
            .solve(&rhs)
            .ok_or(LiftingSurfaceError::Singular { mach, omega_bar })?;
        let (l1, m1) = self.loads(f.column(0).iter().copied());
        let (l2, m2) = self.loads(f.column(1).iter().copied());
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

    fn solve_quasi_steady(&self, mach: f64) -> Result<Solution, LiftingSurfaceError> {
        let beta2 = 1.0 - mach * mach;
        let beta = beta2.sqrt();
        let singular = LiftingSurfaceError::Singular {
            mach,
            omega_bar: 0.0,
        };
        let lu: LU<f64, Dyn, Dyn> = self.matrix(|line, x, y| line.steady(x, y, beta)).lu();
        let f0 = lu.solve(&self.normalwash()).ok_or(singular.clone())?;
        // D₁ per unit iω̄ = (1/c̄) × the first-order factor per unit iκ
        let mac = self.wing().mac();
        let d1 = self.matrix(|line, x, y| line.first_order(x, y, beta2) / mac);
        let f1 = lu.solve(&(-(d1 * f0.column(0)))).ok_or(singular)?;
        let (l1, m1) = self.loads(f0.column(0).iter().copied());
        let (l1dot, m1dot) = self.loads(f1.iter().copied());
        let (l2, m2) = self.loads(f0.column(1).iter().copied());
        Solution::checked(Solution {
            mach,
            omega_bar: 0.0,
            lift_alpha: l1,
            moment_alpha: m1,
            lift_alphadot: l1dot,
            moment_alphadot: m1dot,
            lift_q: l2,
            moment_q: m2,
        })
    }

    /// Dᵢⱼ = d(line j) + d(mirror of line j) at collocation point i.
    fn matrix<T>(&self, d: impl Fn(&super::doublet_line::DoubletLine, f64, f64) -> T) -> DMatrix<T>
    where
        T: nalgebra::Scalar + std::ops::Add<Output = T>,
    {
        let boxes = self.boxes();
        let n = boxes.len();
        DMatrix::from_fn(n, n, |i, j| {
            let (x, y) = (boxes[i].x_c, boxes[i].y_c);
            let line = boxes[j].line;
            d(&line, x, y) + d(&line.mirrored(), x, y)
        })
    }
}
