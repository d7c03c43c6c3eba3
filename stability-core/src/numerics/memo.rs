//! A process-wide table of solutions, each computed once: what the
//! lifting-surface caches share (the configuration lattice's,
//! [`crate::aerodynamics::lifting_surface::configuration::cache`], and the Mach box's,
//! [`crate::aerodynamics::lifting_surface::mach_box::cache`]).
//!
//! Each entry is solved once, by the first thread to ask; others asking
//! meanwhile wait for it (a [`OnceLock`] per key). A hit takes a read lock
//! and clones the value. At most `capacity` entries: a new key beyond it
//! starts the table afresh (the solves are deterministic, so a cleared
//! entry is solved again to the same bits). [`Memo::solves`] counts the
//! solves since the last [`Memo::clear`], for tests that a sweep shares them.

use std::collections::HashMap;
use std::hash::Hash;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, OnceLock, PoisonError, RwLock};

type Slot<V> = Arc<OnceLock<V>>;

/// Values by key, each solved once per process (see the module's
/// documentation). Made in a `static` by [`Memo::new`].
pub struct Memo<K, V> {
    map: OnceLock<RwLock<HashMap<K, Slot<V>>>>,
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

    fn map(&self) -> &RwLock<HashMap<K, Slot<V>>> {
        self.map.get_or_init(Default::default)
    }

    /// The value at `key`, from the table or by `solve` into it.
    pub fn get_or_solve(&self, key: K, solve: impl FnOnce() -> V) -> V {
        let read = self.map().read().unwrap_or_else(PoisonError::into_inner);
        if let Some(done) = read.get(&key).and_then(|slot| slot.get()) {
            return done.clone();
        }
        drop(read);
        let slot = {
            let mut write = self.map().write().unwrap_or_else(PoisonError::into_inner);
            if write.len() >= self.capacity && !write.contains_key(&key) {
                write.clear();
            }
            write.entry(key).or_default().clone()
        };
        slot.get_or_init(|| {
            self.solves.fetch_add(1, Ordering::SeqCst);
            solve()
        })
        .clone()
    }

    /// Puts `value` at `key` as if solved (not counted as a solve), unless
    /// the key holds a value already.
    pub fn insert(&self, key: K, value: V) {
        let slot = {
            let mut write = self.map().write().unwrap_or_else(PoisonError::into_inner);
            if write.len() >= self.capacity && !write.contains_key(&key) {
                write.clear();
            }
            write.entry(key).or_default().clone()
        };
        let _ = slot.set(value);
    }

    /// Whether the table holds a value at `key`.
    pub fn contains(&self, key: &K) -> bool {
        let read = self.map().read().unwrap_or_else(PoisonError::into_inner);
        read.get(key).is_some_and(|slot| slot.get().is_some())
    }

    /// Every solved entry, key and value (in no order).
    pub fn entries(&self) -> Vec<(K, V)>
    where
        K: Clone,
    {
        let read = self.map().read().unwrap_or_else(PoisonError::into_inner);
        read.iter()
            .filter_map(|(k, slot)| slot.get().map(|v| (k.clone(), v.clone())))
            .collect()
    }

    /// How many solves the table has made since it was last cleared.
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
}
