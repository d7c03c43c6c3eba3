//! A global allocator that counts the allocations of a thread that asks,
//! for the tests that show a hot path allocates nothing (`no_alloc`,
//! `lifting_surface_no_alloc`, `roots_batch`): one for the test binary.
//!
//! It counts only the allocations of the thread that asked
//! ([`allocations_in`]): the test harness's other threads (its output
//! capture, a timer, another test) allocate when they like, and counting
//! them made the test fail at random under load. The count is a
//! `const`-initialised thread-local `Cell`, which needs no allocation and
//! no destructor to read or write, so the allocator itself allocates
//! nothing to keep it.

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::hint::black_box;
use std::sync::atomic::{AtomicBool, Ordering};

struct Counting;

thread_local! {
    /// This thread's allocations while it counts them (`None`: it does not).
    static COUNTED: Cell<Option<usize>> = const { Cell::new(None) };
}

/// Run `f`, counting the allocations this thread makes meanwhile.
pub fn allocations_in<T>(f: impl FnOnce() -> T) -> (T, usize) {
    COUNTED.with(|c| c.set(Some(0)));
    let out = f();
    let n = COUNTED.with(|c| c.take()).unwrap_or(0);
    (out, n)
}

// SAFETY: forwards to the system allocator, counting the calls made on a
// thread that counts them.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        // `try_with`: no panic while the thread's locals are torn down
        let _ = COUNTED.try_with(|c| {
            if let Some(n) = c.get() {
                c.set(Some(n + 1));
            }
        });
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

/// The counter sees this thread's allocations and no other's.
#[test]
fn the_counter_counts_this_threads_allocations_only() {
    let (_, n) = allocations_in(|| black_box(Box::new(1u64)));
    assert_eq!(n, 1);
    static GO: AtomicBool = AtomicBool::new(false);
    static DONE: AtomicBool = AtomicBool::new(false);
    let worker = std::thread::spawn(|| {
        while !GO.load(Ordering::SeqCst) {
            std::hint::spin_loop();
        }
        for _ in 0..100 {
            black_box(vec![0u8; 64]);
        }
        DONE.store(true, Ordering::SeqCst);
    });
    let (_, n) = allocations_in(|| {
        GO.store(true, Ordering::SeqCst);
        while !DONE.load(Ordering::SeqCst) {
            std::hint::spin_loop();
        }
    });
    worker.join().unwrap();
    assert_eq!(n, 0, "another thread's allocations counted");
}
