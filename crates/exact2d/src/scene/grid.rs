//! A hierarchical grid of boxes: which stored boxes may meet a query box, without testing all
//! pairs.
//!
//! A box of largest side `s` lives at level `L`, the smallest with `2^L > s`, in the one cell
//! of side `2^L` that holds its min corner. A stored box `j` of level `L` meets a query box
//! `i` only if, on each axis, `j.min` lies in `[i.min - 2^L, i.max]` (its side is below
//! `2^L`), which covers at most three cells per axis. A query therefore visits, at each
//! occupied level at or above its own, a 3 x 3 block of cells; a pair whose query box is the
//! larger is found by the query in the other direction, so callers query both ways.
//!
//! Boxes of one size fill one level and cost O(1) each after an O(n log n) sort, whatever
//! their layout (a column, a lattice). Mixed sizes add one probe per occupied level. Boxes too
//! large or too far out for any level (side `>= 2^1000`, or not finite) are kept apart and met
//! by every query.
//!
//! Cell coordinates are `floor(x / 2^L)`: exact division by a power of two, rounded
//! monotonically and saturated to `i64`, so the inequalities above survive rounding.

use glam::DVec2;

/// The finest level: cells of side `2^-1000`. Smaller boxes share it (only speed suffers).
const MIN_LEVEL: i32 = -1000;
/// The coarsest level: cells of side `2^1000`. Larger boxes are kept apart as huge.
const MAX_LEVEL: i32 = 1000;

/// An axis-aligned box with its grid level (`None`: too large for any level).
#[derive(Clone, Copy, Debug)]
pub(super) struct Bounds {
    pub min: DVec2,
    pub max: DVec2,
    level: Option<i32>,
}

impl Bounds {
    pub fn new(min: DVec2, max: DVec2) -> Self {
        Self {
            min,
            max,
            level: level_of((max - min).max_element()),
        }
    }

    /// The same box moved by `by`.
    pub fn moved(&self, by: DVec2) -> Self {
        Self::new(self.min + by, self.max + by)
    }

    /// Whether the two closed boxes share a point.
    pub fn meets(&self, other: &Bounds) -> bool {
        self.min.cmple(other.max).all() && other.min.cmple(self.max).all()
    }
}

#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
struct Entry {
    level: i32,
    cell: [i64; 2],
    id: u32,
}

/// Boxes stored by id, sorted by (level, cell).
pub(super) struct Grid {
    entries: Vec<Entry>,
    /// The occupied levels, ascending.
    levels: Vec<i32>,
    huge: Vec<u32>,
    /// The smallest box holding every stored box of a level (`None` if there is none): a
    /// query that misses it meets none of them, and skips the searches (a periodic box's
    /// images of a ball inside it, most of them far off).
    extent: Option<(DVec2, DVec2)>,
}

impl Grid {
    /// A grid of the boxes `(id, bounds)`.
    pub fn new(boxes: impl Iterator<Item = (u32, Bounds)>) -> Self {
        let mut entries = Vec::new();
        let mut huge = Vec::new();
        let mut extent: Option<(DVec2, DVec2)> = None;
        for (id, bounds) in boxes {
            match bounds.level {
                Some(level) => {
                    entries.push(Entry {
                        level,
                        cell: cell_of(bounds.min, level),
                        id,
                    });
                    extent = Some(extent.map_or((bounds.min, bounds.max), |(lo, hi)| {
                        (lo.min(bounds.min), hi.max(bounds.max))
                    }));
                }
                None => huge.push(id),
            }
        }
        entries.sort_unstable();
        let mut levels: Vec<i32> = entries.iter().map(|e| e.level).collect();
        levels.dedup();
        Self {
            entries,
            levels,
            huge,
            extent,
        }
    }

    /// Calls `visit` with the id of every stored box that may meet `query` and is at least as
    /// large (by level), possibly more than once. Every id if `query` is huge.
    pub fn query(&self, query: &Bounds, visit: &mut impl FnMut(u32)) {
        self.huge.iter().for_each(|&id| visit(id));
        let Some(level) = query.level else {
            self.entries.iter().for_each(|e| visit(e.id));
            return;
        };
        let Some((lo, hi)) = self.extent else {
            return;
        };
        if !(query.min.cmple(hi).all() && lo.cmple(query.max).all()) {
            return;
        }
        let first = self.levels.partition_point(|&l| l < level);
        for &level in &self.levels[first..] {
            self.query_level(query, level, visit);
        }
    }

    fn query_level(&self, query: &Bounds, level: i32, visit: &mut impl FnMut(u32)) {
        let side = pow2(level);
        let [x_hi, y_hi] = cell_of(query.max, level);
        let [x_lo, y_lo] = cell_of(query.min - side, level);
        // A query box is smaller than a cell, so a true range spans at most three cells; the
        // clamp only bites when `min - side` overflowed to -inf.
        let (x_lo, y_lo) = (
            x_lo.max(x_hi.saturating_sub(2)),
            y_lo.max(y_hi.saturating_sub(2)),
        );
        for x in x_lo..=x_hi {
            // Cells (x, y_lo..=y_hi) are contiguous in the sorted entries.
            let start = self
                .entries
                .partition_point(|e| (e.level, e.cell) < (level, [x, y_lo]));
            for entry in &self.entries[start..] {
                if (entry.level, entry.cell) > (level, [x, y_hi]) {
                    break;
                }
                visit(entry.id);
            }
        }
    }
}

/// The smallest level whose cells are wider than `size`, or `None` if there is none.
fn level_of(size: f64) -> Option<i32> {
    if !(size < pow2(MAX_LEVEL)) {
        return None;
    }
    // `log2` may be off by one near powers of two: settle the exact level with the loops.
    let mut level = (size.log2().floor() as i32)
        .saturating_add(1)
        .clamp(MIN_LEVEL, MAX_LEVEL);
    while level > MIN_LEVEL && pow2(level - 1) > size {
        level -= 1;
    }
    while pow2(level) <= size {
        level += 1;
    }
    Some(level)
}

/// The cell of side `2^level` holding `p`. Dividing by a power of two is exact (barring
/// overflow or underflow, where it still rounds monotonically), and `as` saturates.
fn cell_of(p: DVec2, level: i32) -> [i64; 2] {
    let side = pow2(level);
    [(p.x / side).floor() as i64, (p.y / side).floor() as i64]
}

/// `2^k` for `k` in `[MIN_LEVEL, MAX_LEVEL]`, built from its bits so it is exact.
fn pow2(k: i32) -> f64 {
    debug_assert!((MIN_LEVEL..=MAX_LEVEL).contains(&k));
    f64::from_bits(((k + 1023) as u64) << 52)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn level_cells_are_strictly_wider_than_the_box() {
        for size in [1e-300, 1e-9, 0.5, 1.0, 1.0 + f64::EPSILON, 3.0, 4.0, 1e300] {
            let level = level_of(size).unwrap();
            assert!(
                pow2(level) > size && pow2(level - 1) <= size,
                "size {size}: level {level}"
            );
        }
        assert_eq!(level_of(0.0), Some(MIN_LEVEL));
        assert_eq!(level_of(1e-310), Some(MIN_LEVEL));
        assert_eq!(level_of(pow2(MAX_LEVEL)), None);
        assert_eq!(level_of(f64::INFINITY), None);
    }

    /// Every stored box that meets a query is visited, as a brute force over all pairs says:
    /// queries inside, across and outside the stored boxes' extent, touching it at a corner,
    /// of mixed sizes, and with a huge box stored.
    #[test]
    fn queries_visit_every_box_they_meet() {
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        for with_huge in [false, true] {
            let mut boxes: Vec<Bounds> = (0..300)
                .map(|_| {
                    let min = DVec2::new(next() * 10.0, next() * 10.0);
                    let size = [0.01, 0.3, 2.0][(next() * 3.0) as usize];
                    Bounds::new(min, min + DVec2::splat(size))
                })
                .collect();
            if with_huge {
                boxes.push(Bounds::new(DVec2::splat(-1e308), DVec2::splat(1e308)));
            }
            let grid = Grid::new(boxes.iter().enumerate().map(|(i, b)| (i as u32, *b)));
            let (lo, hi) = grid.extent.expect("boxes of a level");
            let mut queries: Vec<Bounds> = (0..400)
                .map(|_| {
                    let min = DVec2::new(next() * 30.0 - 10.0, next() * 30.0 - 10.0);
                    Bounds::new(min, min + DVec2::splat(next() * 0.5))
                })
                .collect();
            // Touching the extent at its corners, and just missing it.
            queries.push(Bounds::new(hi, hi + DVec2::ONE));
            queries.push(Bounds::new(lo - DVec2::ONE, lo));
            queries.push(Bounds::new(hi + DVec2::splat(1e-9), hi + DVec2::ONE));
            for query in &queries {
                let mut seen = vec![false; boxes.len()];
                grid.query(query, &mut |id| seen[id as usize] = true);
                for (j, stored) in boxes.iter().enumerate() {
                    let larger = stored
                        .level
                        .is_none_or(|l| query.level.is_some_and(|q| l >= q));
                    if larger && stored.meets(query) {
                        assert!(seen[j], "box {j} {stored:?} meets {query:?} unseen");
                    }
                }
            }
        }
    }
}
