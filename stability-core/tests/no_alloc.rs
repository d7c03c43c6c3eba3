//! The hot path allocates nothing: the generated coefficient and gradient
//! functions, the quartic's roots and a derivative set's whole analysis
//! (roots at any scale, modes, Routh, §8 criteria, eq 7 check), and a
//! design point's evaluation from its planform (coefficients, derivatives
//! of every theory, the frequency iteration, warnings). A counting global
//! allocator sees no allocation while they run. (One test, so that no
//! other test's allocations run beside it.)

use stability_core::{Quartic, QuarticGradient};
use std::alloc::{GlobalAlloc, Layout, System};
use std::hint::black_box;
use std::sync::atomic::{AtomicUsize, Ordering};

struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

// SAFETY: forwards to the system allocator, counting calls.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
        // SAFETY: same contract as the caller's.
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: same contract as the caller's.
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn the_hot_path_does_not_allocate() {
    let d = stability_core::examples::tailless_delta_45_coupled();
    let before = ALLOCATIONS.load(Ordering::SeqCst);
    let mut acc = 0.0;
    for i in 0..1000 {
        let mut di = d;
        di.mu1 += i as f64;
        let q = Quartic::from_derivatives(black_box(&di));
        let g = QuarticGradient::of(black_box(&di));
        acc += q.b + g.rows[5][1];
        let r = stability_core::roots::solve_quartic(q.to_array()).expect("roots");
        let a = stability_core::analysis::Analysis::of(black_box(&di)).expect("analysis");
        let lean = stability_core::analysis::Analysis::without_classical(black_box(&di))
            .expect("analysis");
        acc += r[0].re + a.modes.len() as f64 + lean.routh.discriminant;
    }
    // the badly scaled, whose roots take the Newton-polygon path
    for i_b in [1e-160, 1e308] {
        let di = stability_core::Derivatives { i_b, ..d };
        let a = stability_core::analysis::Analysis::of(black_box(&di)).expect("analysis");
        acc += a.roots[0].re;
    }
    use stability_core::case::{DampingModel, evaluate};
    use stability_core::damping::Theory;
    let mut warned = 0;
    for (deg, mach, damping) in [
        (60.0, 0.6, DampingModel::Faired),
        (60.0, 1.1, DampingModel::Faired),
        (60.0, 1.8, DampingModel::Faired),
        (45.0, 1.3, DampingModel::Theory(Theory::Supersonic)),
        (45.0, 1.0, DampingModel::Theory(Theory::TransonicFrequency)),
        (45.0, 0.9, DampingModel::Theory(Theory::Garrick)),
    ] {
        let mut case = stability_core::study::report_wing(deg, mach);
        case.damping = damping;
        let r = evaluate(black_box(&case)).expect("a design point");
        warned += r.warnings.len();
        acc += r.analysis.quartic.e;
    }
    assert!(warned > 0, "the cases raise warnings too");
    let after = ALLOCATIONS.load(Ordering::SeqCst);
    black_box(acc);
    assert_eq!(after - before, 0, "allocations in the hot path");
}
