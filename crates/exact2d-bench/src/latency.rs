//! The machine's memory latency by working-set size: a chain of dependent loads through
//! cache lines in a random cyclic order, so no load can start before the previous one ends and
//! no prefetcher can guess the next.
//!
//! An event-driven simulation of many balls touches a few dozen scattered lines per event,
//! several of them one after another (queue, ball, its cell, the cell's balls), so this
//! latency, at the size of a world's data, bounds how fast its events can go. `exact2d-bench
//! latency` prints it (`BENCHMARKS.md`).

use std::time::Instant;

use crate::rng::SplitMix64;

/// One cache line holding the index of the next line of the chain.
#[derive(Clone, Copy)]
#[repr(C, align(64))]
struct Line {
    next: u32,
    _rest: [u32; 15],
}

/// `lines` cache lines linked into one random cycle (Sattolo's algorithm): following `next`
/// from any line visits every line once before coming back.
///
/// # Panics
/// If `lines` is 0 or does not fit a `u32`.
fn chain(lines: usize, seed: u64) -> Vec<Line> {
    assert!(
        lines > 0 && u32::try_from(lines).is_ok(),
        "a chain of {lines} lines"
    );
    let mut order: Vec<u32> = (0..lines as u32).collect();
    let mut rng = SplitMix64::new(seed);
    for i in (1..lines).rev() {
        // j < i, never i itself: the permutation is a single cycle.
        let j = rng.below(i as u64) as usize;
        order.swap(i, j);
    }
    let mut chain = vec![
        Line {
            next: 0,
            _rest: [0; 15]
        };
        lines
    ];
    for (k, &line) in order.iter().enumerate() {
        chain[line as usize].next = order[(k + 1) % lines];
    }
    chain
}

/// Follows the chain `steps` times from line 0; the line reached.
fn follow(chain: &[Line], steps: usize) -> u32 {
    let mut at = 0u32;
    for _ in 0..steps {
        at = chain[at as usize].next;
    }
    at
}

/// The mean wall time, in nanoseconds, of one load in a chain of dependent loads through a
/// working set of `bytes` (rounded to whole 64-byte lines, at least one), over `steps` loads.
///
/// # Panics
/// If the working set has more lines than a `u32` counts.
#[must_use]
pub fn dependent_load_ns(bytes: usize, steps: usize) -> f64 {
    let chain = chain((bytes / 64).max(1), 1);
    // One lap first, so the pages are mapped and the measurement sees only the loads.
    std::hint::black_box(follow(&chain, chain.len()));
    let start = Instant::now();
    std::hint::black_box(follow(&chain, steps));
    start.elapsed().as_secs_f64() * 1e9 / steps.max(1) as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_chain_is_one_cycle_through_every_line() {
        for lines in [1, 2, 3, 64, 1000] {
            let chain = chain(lines, 7);
            let mut seen = vec![false; lines];
            let mut at = 0u32;
            for _ in 0..lines {
                assert!(!seen[at as usize], "{lines} lines: line {at} visited twice");
                seen[at as usize] = true;
                at = chain[at as usize].next;
            }
            assert_eq!(at, 0, "{lines} lines: the walk does not close");
            assert_eq!(follow(&chain, lines), 0);
        }
    }
}
