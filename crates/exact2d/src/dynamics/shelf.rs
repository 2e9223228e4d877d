//! Vectors kept from one solve to the next, so that a jam's solves do not allocate and free
//! the same few hundred vectors again and again.
//!
//! A pile's jam solves a few programmes over its cluster (an impact, a projection, a hold,
//! with friction some ten more), and each programme's dual method builds a basis of some
//! hundred vectors and a column of `R` for each, a residual for each step, and drops them all
//! at its end: in a rough pile, allocating and freeing them was a tenth of the instructions
//! (callgrind, `exact2d-bench piles --balls 200 --friction 0.5 --until 2`). A *shelf* is a
//! thread's stack of such vectors, emptied: [`take`] one (or a new one if the shelf is bare),
//! and [`give`] it back when done. What a vector held never reaches an answer (each is
//! cleared before it is handed out), so the bits are those of fresh allocations, and nothing
//! is shared between threads (each has its own shelves). A shelf keeps at most [`KEPT`]
//! vectors; the rest are freed. What it keeps is what the largest solve so far had in use at
//! once (a jam of a 400-ball cluster: some 800 basis vectors of up to 400 entries, ten
//! megabytes), memory that solve needed anyway; a world of free balls (a gas, a brick
//! breaker) solves nothing and keeps nothing.

use std::cell::RefCell;
use std::thread::LocalKey;

use glam::DVec2;

/// A thread's shelf of vectors of `T`.
pub(crate) type Shelf<T> = RefCell<Vec<Vec<T>>>;

/// The most vectors a shelf keeps: a large jam's basis (at most twice its balls: some 800
/// vectors over 400 balls) and the solves after it.
pub(crate) const KEPT: usize = 1024;

thread_local! {
    /// Numbers: columns of `R`, a step's rates.
    pub(crate) static REALS: Shelf<f64> = const { RefCell::new(Vec::new()) };
    /// Vectors over a cluster's balls: residuals.
    pub(crate) static VECTORS: Shelf<DVec2> = const { RefCell::new(Vec::new()) };
}

/// An empty vector from `shelf`, with the room it had, or a new one.
pub(crate) fn take<T: 'static>(shelf: &'static LocalKey<Shelf<T>>) -> Vec<T> {
    // During a thread's teardown the shelf may be gone: a new vector then.
    let mut v = shelf
        .try_with(|s| s.borrow_mut().pop())
        .ok()
        .flatten()
        .unwrap_or_default();
    v.clear();
    v
}

/// Gives `v` back to `shelf` for a later [`take`] (freed if the shelf is full, or if `v` never
/// held anything).
pub(crate) fn give<T: 'static>(shelf: &'static LocalKey<Shelf<T>>, v: Vec<T>) {
    if v.capacity() == 0 {
        return;
    }
    let _ = shelf.try_with(|s| {
        let mut s = s.borrow_mut();
        if s.len() < KEPT {
            s.push(v);
        }
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A vector taken is empty whatever it held when given back, and the shelf keeps no more
    /// than `KEPT`.
    #[test]
    fn a_taken_vector_is_empty_and_the_shelf_is_bounded() {
        thread_local! {
            static TEST: Shelf<u32> = const { RefCell::new(Vec::new()) };
        }
        give(&TEST, vec![1, 2, 3]);
        let v = take(&TEST);
        assert!(v.is_empty());
        assert!(v.capacity() >= 3);
        for _ in 0..KEPT + 10 {
            give(&TEST, vec![7]);
        }
        assert_eq!(TEST.with(|s| s.borrow().len()), KEPT);
        give(&TEST, Vec::new());
        assert_eq!(TEST.with(|s| s.borrow().len()), KEPT);
        assert!(take(&TEST).is_empty());
    }
}
