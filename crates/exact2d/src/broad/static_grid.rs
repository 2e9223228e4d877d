//! A uniform grid of static colliders, walked along a ball's path.
//!
//! Each collider is listed in every cell its bounding box meets after growing it by `pad`, a
//! bound on every ball's radius (with a little room for rounding). A ball can only touch a
//! collider while its centre is inside that grown box, so walking the cells the centre's path
//! passes through, in time order, and stopping once the walk is past the earliest contact found,
//! meets every collider the ball can hit first. The walk goes in chunks of about one cell of
//! path; each chunk's cells are those under the box holding the path over that chunk, so
//! curved paths under gravity are covered exactly like straight ones.
//!
//! The grid covers the grown boxes of the colliders present when it was built, with a margin.
//! A collider added inside that region is inserted in place; one outside it, a ball larger than
//! `pad` allows, or many more colliders than the grid was sized for make it rebuild (cheap, and
//! rare: O(colliders + cells)).

use glam::DVec2;

use super::path::{Aabb, floor, path_aabb, span_for_length, time_within};
use crate::toi::Motion;

/// Cells per collider the grid aims for.
const CELLS_PER_COLLIDER: f64 = 2.0;
/// The most cells the grid ever has.
const MAX_CELLS: f64 = (1u32 << 22) as f64;

/// The uniform grid of static colliders.
#[derive(Clone)]
pub(crate) struct StaticGrid {
    origin: DVec2,
    cell: f64,
    /// `1 / cell`.
    per_cell: f64,
    nx: usize,
    ny: usize,
    /// Collider slot indices per cell, row-major.
    cells: Vec<Vec<u32>>,
    /// The region the cells cover.
    covered: Aabb,
    /// The smallest box holding every listed collider's grown box.
    content: Option<Aabb>,
    /// How far colliders' boxes are grown: at least the largest ball radius.
    pad: f64,
    /// Each collider slot's own bounding box, while live.
    boxes: Vec<Option<Aabb>>,
    /// Each listed collider slot's grown box (see [`Self::grown`]).
    grown: Vec<Aabb>,
    count: usize,
    built_for: usize,
    /// Per collider slot, the last walk that visited it (so a walk visits each once).
    seen: Vec<u32>,
    walk: u32,
}

impl Default for StaticGrid {
    fn default() -> Self {
        Self {
            origin: DVec2::ZERO,
            cell: 1.0,
            per_cell: 1.0,
            nx: 0,
            ny: 0,
            cells: Vec::new(),
            covered: Aabb {
                min: DVec2::ZERO,
                max: DVec2::ZERO,
            },
            content: None,
            pad: 0.0,
            boxes: Vec::new(),
            grown: Vec::new(),
            count: 0,
            built_for: 0,
            seen: Vec::new(),
            walk: 0,
        }
    }
}

impl StaticGrid {
    /// Makes room for balls of `radius`: grows `pad` (and rebuilds) if needed.
    pub(crate) fn fit_radius(&mut self, radius: f64) {
        if radius * 1.001 > self.pad {
            self.pad = radius * 1.25;
            self.rebuild();
        }
    }

    /// Lists the collider in slot `index`, with bounding box `aabb`.
    pub(crate) fn insert(&mut self, index: u32, aabb: Aabb) {
        let i = index as usize;
        if self.boxes.len() <= i {
            self.boxes.resize(i + 1, None);
            self.seen.resize(i + 1, 0);
            self.grown.resize(i + 1, aabb);
        }
        self.boxes[i] = Some(aabb);
        self.count += 1;
        let grown = self.grown(aabb);
        self.grown[i] = grown;
        if self.covered.contains(&grown) && self.count <= 4 * self.built_for + 16 {
            self.content = Some(self.content.map_or(grown, |c| c.union(grown)));
            self.for_cells(&grown, |cells| cells.push(index));
        } else {
            self.rebuild();
        }
    }

    /// Unlists the collider in slot `index`.
    pub(crate) fn remove(&mut self, index: u32) {
        let Some(aabb) = self.boxes.get_mut(index as usize).and_then(Option::take) else {
            return;
        };
        self.count -= 1;
        let grown = self.grown(aabb);
        self.for_cells(&grown, |cells| cells.retain(|&c| c != index));
    }

    /// Calls `visit` once for every collider whose grown box the path of `motion` meets in a
    /// cell it passes through between times `start` and `horizon` (relative to the motion), in
    /// roughly the order the path meets them. `visit` returns a new, possibly earlier, horizon:
    /// the walk stops once it is past it.
    pub(crate) fn walk(
        &mut self,
        motion: &Motion,
        start: f64,
        horizon: f64,
        mut visit: impl FnMut(u32) -> f64,
    ) {
        let Some(content) = self.content else {
            return;
        };
        if !(start <= horizon) {
            return;
        }
        self.walk = self.walk.wrapping_add(1);
        if self.walk == 0 {
            self.seen.fill(0);
            self.walk = 1;
        }
        // The common case (a ball with a ball contact or a wall close ahead): the whole path
        // up to the horizon lies in a 2 x 2 block of cells, and one box covers it.
        if horizon.is_finite() {
            let chunk = chunk_box(motion, start, horizon);
            if let Some(range) = self.cell_range(&chunk) {
                if range.1 <= range.0 + 1 && range.3 <= range.2 + 1 {
                    self.visit_cells(range, &chunk, horizon, &mut visit);
                    return;
                }
            } else {
                // Off the grid, the path meets no collider before the horizon.
                return;
            }
        }
        self.walk_in_chunks(motion, content, start, horizon, &mut visit);
    }

    /// The walk of a long path: chunks of about one cell of path, in time order.
    fn walk_in_chunks(
        &mut self,
        motion: &Motion,
        content: Aabb,
        start: f64,
        mut horizon: f64,
        visit: &mut impl FnMut(u32) -> f64,
    ) {
        let Some((enter, leave)) = time_within(motion, &content.inflated(0.5 * self.cell)) else {
            return;
        };
        let mut t = start.max(enter);
        while t <= leave.min(horizon) {
            let span = span_for_length(motion, t, self.cell);
            let mut end = (t + span).min(leave);
            // Past the point where a chunk of one cell no longer advances the clock (or for a
            // ball at rest), the rest of the path is one chunk.
            if !(end > t) || span < 1e-12 * t.abs() {
                end = leave;
            }
            // Nothing the ball can hit first lies beyond the horizon: the chunk stops there.
            let last = end.min(horizon);
            let chunk = if last.is_finite() {
                chunk_box(motion, t, last)
            } else {
                chunk_box(motion, t, t)
            };
            if let Some(range) = self.cell_range(&chunk) {
                horizon = self.visit_cells(range, &chunk, horizon, visit);
            }
            if !(end < leave && end < horizon && end.is_finite()) {
                break;
            }
            t = end;
        }
    }

    /// Visits the colliders listed in the cells of `range` whose grown boxes meet `chunk` and
    /// that this walk has not visited yet. Returns the horizon, lowered by what they gave.
    fn visit_cells(
        &mut self,
        (x0, x1, y0, y1): (usize, usize, usize, usize),
        chunk: &Aabb,
        mut horizon: f64,
        visit: &mut impl FnMut(u32) -> f64,
    ) -> f64 {
        let (seen, walk, grown) = (&mut self.seen, self.walk, &self.grown);
        for y in y0..=y1 {
            for x in x0..=x1 {
                for &c in &self.cells[y * self.nx + x] {
                    // A collider whose grown box misses the chunk cannot be touched in it; it
                    // stays unvisited for the chunks after.
                    if seen[c as usize] != walk && grown[c as usize].overlaps(chunk) {
                        seen[c as usize] = walk;
                        horizon = horizon.min(visit(c));
                    }
                }
            }
        }
        horizon
    }

    /// The inclusive range of cells `region` meets, or `None` if it misses the grid.
    fn cell_range(&self, region: &Aabb) -> Option<(usize, usize, usize, usize)> {
        cell_range(self.origin, self.per_cell, self.nx, self.ny, region)
    }

    /// Whether some listed collider's grown box meets `region`: if not, no ball of radius up
    /// to `pad` whose centre stays in `region` can touch any collider.
    pub(crate) fn meets(&self, region: &Aabb) -> bool {
        let Some((x0, x1, y0, y1)) = self.cell_range(region) else {
            return false;
        };
        (y0..=y1).any(|y| {
            (x0..=x1).any(|x| {
                self.cells[y * self.nx + x]
                    .iter()
                    .any(|&c| self.grown[c as usize].overlaps(region))
            })
        })
    }

    /// Calls `visit` for every collider listed in the cell holding `point`: every collider
    /// within `pad` of it is among them.
    pub(crate) fn near_point(&self, point: DVec2, mut visit: impl FnMut(u32)) {
        let at = Aabb {
            min: point,
            max: point,
        };
        if let Some((x0, x1, y0, y1)) =
            cell_range(self.origin, self.per_cell, self.nx, self.ny, &at)
        {
            for y in y0..=y1 {
                for x in x0..=x1 {
                    for &c in &self.cells[y * self.nx + x] {
                        visit(c);
                    }
                }
            }
        }
    }

    /// A collider's bounding box grown by `pad` and by a rounding allowance.
    fn grown(&self, aabb: Aabb) -> Aabb {
        aabb.inflated(self.pad + 1e-12 * aabb.magnitude())
    }

    fn for_cells(&mut self, region: &Aabb, mut f: impl FnMut(&mut Vec<u32>)) {
        if let Some((x0, x1, y0, y1)) =
            cell_range(self.origin, self.per_cell, self.nx, self.ny, region)
        {
            for y in y0..=y1 {
                for x in x0..=x1 {
                    f(&mut self.cells[y * self.nx + x]);
                }
            }
        }
    }

    /// Sizes the grid for the colliders listed now and lists them again.
    fn rebuild(&mut self) {
        let grown: Vec<(u32, Aabb)> = self
            .boxes
            .iter()
            .enumerate()
            .filter_map(|(i, b)| b.map(|b| (i as u32, self.grown(b))))
            .collect();
        self.built_for = grown.len();
        self.cells.clear();
        self.content = None;
        self.nx = 0;
        self.ny = 0;
        let Some(content) = grown.iter().map(|&(_, b)| b).reduce(Aabb::union) else {
            return;
        };
        let size = content.max - content.min;
        let target = (CELLS_PER_COLLIDER * grown.len() as f64).clamp(16.0, MAX_CELLS);
        // Square cells about `target` in number, but never so thin a box makes millions.
        let mut cell = (size.x * size.y / target).sqrt();
        cell = cell.max(size.max_element() / 1024.0);
        if !(cell > 0.0) || !cell.is_finite() {
            cell = 1.0_f64.max(size.max_element());
        }
        // One spare cell on every side, so the walk's slack never falls off the grid.
        self.origin = content.min - cell;
        self.nx = (size.x / cell).ceil() as usize + 2;
        self.ny = (size.y / cell).ceil() as usize + 2;
        self.cell = cell;
        self.per_cell = 1.0 / cell;
        self.covered = Aabb {
            min: self.origin,
            max: self.origin + DVec2::new(self.nx as f64, self.ny as f64) * cell,
        };
        self.cells = vec![Vec::new(); self.nx * self.ny];
        self.content = Some(content);
        for (index, b) in grown {
            self.grown[index as usize] = b;
            self.for_cells(&b, |cells| cells.push(index));
        }
    }
}

/// The box holding the path over `[t0, t1]`, grown by a rounding allowance.
fn chunk_box(motion: &Motion, t0: f64, t1: f64) -> Aabb {
    let chunk = path_aabb(motion, t0, t1);
    chunk.inflated_relative(1e-12)
}

/// The inclusive range of cells `region` meets, or `None` if it misses the grid.
fn cell_range(
    origin: DVec2,
    per_cell: f64,
    nx: usize,
    ny: usize,
    region: &Aabb,
) -> Option<(usize, usize, usize, usize)> {
    let (x0, x1) = axis_range(region.min.x, region.max.x, origin.x, per_cell, nx)?;
    let (y0, y1) = axis_range(region.min.y, region.max.y, origin.y, per_cell, ny)?;
    Some((x0, x1, y0, y1))
}

/// The inclusive range of the `n` cells along one axis that `[lo, hi]` meets. Scaling by the
/// reciprocal of the cell size instead of dividing by it rounds differently at cell borders,
/// which does not matter: boxes are listed and looked up with this same monotone mapping, so
/// two boxes that overlap always share a cell.
fn axis_range(lo: f64, hi: f64, origin: f64, per_cell: f64, n: usize) -> Option<(usize, usize)> {
    let (a, b) = ((lo - origin) * per_cell, (hi - origin) * per_cell);
    // Also `None` for NaN, and for an empty grid (`n` = 0).
    if n == 0 || !(b >= 0.0 && a < n as f64) {
        return None;
    }
    let last = (n - 1) as f64;
    Some((floor(a.max(0.0)) as usize, floor(b.min(last)) as usize))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(x: f64, y: f64, half: f64) -> Aabb {
        Aabb {
            min: DVec2::new(x - half, y - half),
            max: DVec2::new(x + half, y + half),
        }
    }

    fn walked(grid: &mut StaticGrid, motion: &Motion, horizon: f64) -> Vec<u32> {
        let mut visited = Vec::new();
        grid.walk(motion, 0.0, horizon, |c| {
            visited.push(c);
            f64::INFINITY
        });
        visited.sort_unstable();
        visited
    }

    #[test]
    fn a_walk_meets_the_boxes_along_the_path_and_not_distant_ones() {
        let mut grid = StaticGrid::default();
        grid.fit_radius(0.1);
        // A row of boxes along y = 0 and one far above.
        for i in 0..10 {
            grid.insert(i, square(f64::from(i) * 2.0, 0.0, 0.5));
        }
        grid.insert(10, square(10.0, 50.0, 0.5));
        let along = Motion::linear(DVec2::new(-5.0, 0.0), DVec2::new(1.0, 0.0));
        assert_eq!(
            walked(&mut grid, &along, f64::INFINITY),
            (0..10).collect::<Vec<_>>()
        );
        // A horizon stops the walk early (the boxes within a few cells of x = 0 only).
        let early = walked(&mut grid, &along, 6.0);
        assert!(early.contains(&0) && !early.contains(&9), "{early:?}");
        // Straight up through box 5 to the lone box.
        let up = Motion::linear(DVec2::new(10.0, -5.0), DVec2::new(0.0, 1.0));
        let seen = walked(&mut grid, &up, f64::INFINITY);
        assert!(
            seen.contains(&5) && seen.contains(&10) && !seen.contains(&0),
            "{seen:?}"
        );
        grid.remove(10);
        assert!(!walked(&mut grid, &up, f64::INFINITY).contains(&10));
    }

    #[test]
    fn meets_finds_only_grown_boxes_that_reach_the_region_and_an_empty_grid_has_none() {
        // Regression: on a grid with no collider (no cells), a region straddling the origin
        // mapped to cell 0 of zero cells and indexed out of bounds.
        let mut grid = StaticGrid::default();
        let around_origin = Aabb {
            min: DVec2::splat(-1.0),
            max: DVec2::splat(1.0),
        };
        assert!(!grid.meets(&around_origin));
        grid.near_point(DVec2::ZERO, |_| panic!("no collider"));
        grid.fit_radius(0.1);
        grid.insert(0, square(10.0, 0.0, 0.5)); // grown by the pad 0.125: x from 9.375
        let near = |x: f64| Aabb {
            min: DVec2::new(x, -0.1),
            max: DVec2::new(x + 1.0, 0.1),
        };
        assert!(grid.meets(&near(8.5)));
        assert!(!grid.meets(&near(8.3)));
        assert!(!grid.meets(&around_origin));
        grid.remove(0);
        assert!(!grid.meets(&near(8.5)));
    }

    #[test]
    fn a_falling_path_meets_the_boxes_it_passes_through_and_no_other() {
        let mut grid = StaticGrid::default();
        grid.fit_radius(0.1);
        grid.insert(0, square(0.0, 0.0, 0.5));
        grid.insert(1, square(4.0, 0.0, 0.5));
        grid.insert(2, square(2.0, 3.0, 0.5));
        // Thrown up from (0, 0.5) over to x = 4: y = 0.5 + t - t^2 / 4, apex (2, 1.5) well
        // below box 2's grown box (from y = 2.375), back at y = 0.5 at (4, 0.5) at t = 4.
        let throw = Motion {
            position: DVec2::new(0.0, 0.5),
            velocity: DVec2::new(1.0, 1.0),
            acceleration: DVec2::new(0.0, -0.5),
        };
        // Boxes 0 and 1 hold the path's ends; box 2 may share a cell with the apex, but its
        // grown box misses every chunk of the path, so it is never visited.
        let seen = walked(&mut grid, &throw, 4.5);
        assert_eq!(seen, vec![0, 1]);
        // With the horizon before the path reaches box 1, only box 0.
        assert_eq!(walked(&mut grid, &throw, 2.0), vec![0]);
    }
}
