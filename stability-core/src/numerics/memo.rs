//! A process-wide table of solutions, each computed once: what the
//! lifting-surface caches share (the configuration lattice's,
//! [`crate::aerodynamics::lifting_surface::store`], and the Mach box's,
//! [`crate::aerodynamics::lifting_surface::store`]).
//!
//! Each entry is solved once, by the first thread to ask; other threads
//! asking meanwhile wait for it — except a worker of a rayon pool, which
//! never waits for an entry another thread is solving: it solves the entry
//! too, and the first value stored is kept (the solves are deterministic:
//! the same bits). The solvers are parallel (rayon), so the thread solving
//! an entry may be waiting for the pool's workers: a worker blocked on that
//! entry would be one it waits for, and a worker asked for an entry it is
//! itself solving (a job it took up while its solve waits) would wait for
//! itself. (Both deadlocked: a `OnceLock` initialised by the solve.)
//! A hit takes a read lock and clones the value. At most `capacity`
//! entries: a new key beyond it starts the table afresh (a cleared entry is
//! solved again to the same bits). [`Memo::solves`] counts the entries
//! solved since the last [`Memo::clear`] (a worker's second solve of an
//! entry is not counted), for tests that a sweep shares them.

use std::collections::HashMap;
use std::hash::Hash;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Condvar, Mutex, OnceLock, PoisonError, RwLock};

/// An entry: its value once solved, and whether a thread that others wait
/// for is solving it.
struct Slot<V> {
    value: OnceLock<V>,
    solving: Mutex<bool>,
    solved: Condvar,
}

impl<V> Default for Slot<V> {
    fn default() -> Self {
        Slot {
            value: OnceLock::new(),
            solving: Mutex::new(false),
            solved: Condvar::new(),
        }
    }
}

/// Releases a slot's claim when its solve ends, stored or unwound (then
/// a waiting thread claims it and solves).
struct Claim<'a, V>(&'a Slot<V>);

impl<V> Drop for Claim<'_, V> {
    fn drop(&mut self) {
        *self
            .0
            .solving
            .lock()
            .unwrap_or_else(PoisonError::into_inner) = false;
        self.0.solved.notify_all();
    }
}

/// Values by key, each solved once per process (see the module's
/// documentation). Made in a `static` by [`Memo::new`].
pub struct Memo<K, V> {
    map: OnceLock<RwLock<HashMap<K, Arc<Slot<V>>>>>,
    solves: AtomicUsize,
    capacity: usize,
}

impl<K: Eq + Hash, V: Clone> Memo<K, V> {
    /// An empty table of at most `capacity` entries.
    pub const fn new(capacity: usize) -> Memo<K, V> {
        Memo {
            map: OnceLock::new(),
            solves: AtomicUsize::new(0),
            capacity,
        }
    }

    fn map(&self) -> &RwLock<HashMap<K, Arc<Slot<V>>>> {
        self.map.get_or_init(Default::default)
    }

    /// The slot of `key`, made empty if the table has none.
    fn slot(&self, key: K) -> Arc<Slot<V>> {
        let mut write = self.map().write().unwrap_or_else(PoisonError::into_inner);
        if write.len() >= self.capacity && !write.contains_key(&key) {
            write.clear();
        }
        write.entry(key).or_default().clone()
    }

    /// The value at `key`, from the table or by `solve` into it.
    pub fn get_or_solve(&self, key: K, solve: impl FnOnce() -> V) -> V {
        let read = self.map().read().unwrap_or_else(PoisonError::into_inner);
        if let Some(done) = read.get(&key).and_then(|slot| slot.value.get()) {
            return done.clone();
        }
        drop(read);
        let slot = self.slot(key);
        let worker = rayon::current_thread_index().is_some();
        let mut solving = slot.solving.lock().unwrap_or_else(PoisonError::into_inner);
        let claim = loop {
            if let Some(done) = slot.value.get() {
                return done.clone();
            }
            if !*solving {
                *solving = true;
                break Some(Claim(&slot));
            }
            if worker {
                break None;
            }
            solving = slot
                .solved
                .wait(solving)
                .unwrap_or_else(PoisonError::into_inner);
        };
        drop(solving);
        let value = solve();
        if slot.value.set(value).is_ok() {
            self.solves.fetch_add(1, Ordering::SeqCst);
        }
        drop(claim);
        slot.value.get().cloned().expect("stored above")
    }

    /// Puts `value` at `key` as if solved (not counted as a solve), unless
    /// the key holds a value already.
    pub fn insert(&self, key: K, value: V) {
        let _ = self.slot(key).value.set(value);
    }

    /// Whether the table holds a value at `key`.
    pub fn contains(&self, key: &K) -> bool {
        let read = self.map().read().unwrap_or_else(PoisonError::into_inner);
        read.get(key).is_some_and(|slot| slot.value.get().is_some())
    }

    /// Every solved entry, key and value (in no order).
    pub fn entries(&self) -> Vec<(K, V)>
    where
        K: Clone,
    {
        let read = self.map().read().unwrap_or_else(PoisonError::into_inner);
        read.iter()
            .filter_map(|(k, slot)| slot.value.get().map(|v| (k.clone(), v.clone())))
            .collect()
    }

    /// How many entries the table has solved since it was last cleared.
    pub fn solves(&self) -> usize {
        self.solves.load(Ordering::SeqCst)
    }

    /// Empties the table and zeroes [`Memo::solves`].
    pub fn clear(&self) {
        self.map()
            .write()
            .unwrap_or_else(PoisonError::into_inner)
            .clear();
        self.solves.store(0, Ordering::SeqCst);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_key_is_solved_once_and_the_capacity_starts_it_afresh() {
        static MEMO: Memo<u32, u64> = Memo::new(2);
        assert_eq!(MEMO.get_or_solve(1, || 10), 10);
        assert_eq!(MEMO.get_or_solve(1, || 99), 10);
        assert_eq!(MEMO.solves(), 1);
        assert_eq!(MEMO.get_or_solve(2, || 20), 20);
        // a third key clears the two: 1 is solved again
        assert_eq!(MEMO.get_or_solve(3, || 30), 30);
        assert_eq!(MEMO.get_or_solve(1, || 11), 11);
        assert_eq!(MEMO.solves(), 4);
        MEMO.clear();
        assert_eq!(MEMO.solves(), 0);
        assert_eq!(MEMO.get_or_solve(3, || 31), 31);
    }

    #[test]
    fn threads_asking_at_once_share_one_solve() {
        static MEMO: Memo<u32, u64> = Memo::new(8);
        let n = std::thread::scope(|s| {
            let hs: Vec<_> = (0..4)
                .map(|_| {
                    s.spawn(|| {
                        MEMO.get_or_solve(7, || {
                            std::thread::sleep(std::time::Duration::from_millis(20));
                            70
                        })
                    })
                })
                .collect();
            hs.into_iter().map(|h| h.join().unwrap()).sum::<u64>()
        });
        assert_eq!(n, 280);
        assert_eq!(MEMO.solves(), 1);
    }

    /// A rayon worker asked for an entry it is itself solving (a job it
    /// took up while its solve waits for the pool) solves it again rather
    /// than wait for itself.
    #[test]
    fn a_worker_asked_again_for_the_entry_it_solves_does_not_wait_for_itself() {
        static MEMO: Memo<u32, u64> = Memo::new(8);
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .build()
            .unwrap();
        let v = pool.install(|| MEMO.get_or_solve(5, || MEMO.get_or_solve(5, || 50) + 1));
        // the inner solve stored 50 first; the outer returns what is stored
        assert_eq!((v, MEMO.get_or_solve(5, || 99), MEMO.solves()), (50, 50, 1));
    }

    /// A thread solving an entry with the pool's help is not kept waiting by
    /// the pool's one worker asking for the same entry: the worker solves it
    /// too, and both get the value stored first.
    #[test]
    fn a_solve_that_needs_the_pool_is_not_blocked_by_a_worker_asking_for_it() {
        use std::sync::mpsc::channel;
        static MEMO: Memo<u32, u64> = Memo::new(8);
        let pool = &rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .build()
            .unwrap();
        let (claimed, on_claim) = channel();
        let (worker_done, on_worker_done) = channel();
        std::thread::scope(|s| {
            let solver = s.spawn(move || {
                MEMO.get_or_solve(9, || {
                    claimed.send(()).unwrap();
                    // the worker has asked for entry 9 and returned
                    on_worker_done.recv().unwrap();
                    pool.install(|| 90)
                })
            });
            on_claim.recv().unwrap();
            let w = pool.install(|| MEMO.get_or_solve(9, || 91));
            worker_done.send(()).unwrap();
            assert_eq!((w, solver.join().unwrap()), (91, 91));
        });
        assert_eq!(MEMO.solves(), 1);
    }
}
