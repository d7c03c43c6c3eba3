//! `Solution::derivatives` — what a sweep over c.g., μ₁ and i_B calls once
//! per design point after one solve — allocates nothing: a counting global
//! allocator sees no allocation while it runs ([`allocations_in`]: the
//! allocations of the thread that asked).

use crate::allocations::allocations_in;
use stability_core::aerodynamics::lifting_surface::{Lattice, LatticeSpec, Spacing};
use stability_core::geometry::Trapezoid;
use std::hint::black_box;

#[test]
fn derivatives_from_a_solution_do_not_allocate() {
    let wing = Trapezoid::from_aspect_ratio(2.3, 0.0, 60f64.to_radians(), 1.0).unwrap();
    let solution = Lattice::new(&wing, LatticeSpec::new(4, 6, Spacing::Auto))
        .unwrap()
        .solve(0.5, 0.3)
        .unwrap();
    let (acc, n) = allocations_in(|| {
        let mut acc = 0.0;
        for i in 0..10_000 {
            let h = -0.2 + 1e-4 * i as f64;
            let d = black_box(&solution)
                .derivatives(black_box(h), 0.01)
                .unwrap();
            acc += d.m_q + d.z_wdot + d.m_w;
        }
        acc
    });
    assert_eq!(n, 0);
    assert!(acc.is_finite());
}
