//! A uniform grid of balls with cell-crossing events, so that a ball is predicted only against
//! balls near it.
//!
//! Cells are squares of side `L = 2.2 r` for a radius capacity `r` (every ball in the grid has a
//! radius of at most `r`). A ball is *registered* in one cell, and its centre stays inside that
//! cell grown by a margin `m = 0.09 r` until its next *crossing*, an internal event at the first
//! time its path reaches the grown cell's boundary. So two balls registered in cells that are
//! not neighbours (3 x 3) are more than `L - 2m = 2.02 r` apart and cannot touch: a ball's
//! contacts are all with balls in its own 3 x 3 block. When a ball crosses, it is registered
//! in the cell that holds its centre and predicted against the balls of the cells that have just
//! become its neighbours; when its trajectory changes, it is registered afresh where it is.
//! Crossings never change a trajectory, so they never change an event's time.
//!
//! Cell coordinates are unbounded integers; a fixed table of lists holds them modulo its
//! power-of-two size (a cell and its aliases share a list, which costs an extra candidate now
//! and then, never a missed one).
//!
//! Cells cover a *region*: a box around every place a ball was added and every collider, grown
//! with a margin. A ball outside it (one that escaped its container and falls forever, say) is
//! kept in a *far* list that every ball checks and that checks every ball, with one crossing
//! event when its path comes back into the region. Without that, a ball falling forever would
//! cross cells forever, and the next real event would never be reached. Far balls are correct
//! at any distance, and free while the list is empty; a ball whose cell coordinate would not be
//! exact in 32 bits (beyond `2^30` cells) is far too.
//!
//! In a periodic box ([`BallGrid::set_periodic`], `broad/torus.rs`) the cells tile the box
//! exactly, there is no far list, every ball joins (it must wrap at the edges), and a
//! neighbour in a cell across an edge is reported with the shift of the image it is seen
//! through.
//!
//! Only balls that can meet other balls join: the grid keeps the union of every ball's group
//! masks, and a ball whose groups cannot meet that union (in a brick breaker, every ball) costs
//! nothing here.

use glam::DVec2;

use super::path::{Aabb, floor, time_of_exit, time_within};
use super::torus::Torus;
use crate::geometry::CollisionGroups;
use crate::toi::Motion;

const NONE: u32 = u32::MAX;
/// `cx` of a ball that is not in the grid.
const ABSENT: i32 = i32::MIN;
/// `cx` of a ball in the far list.
const FAR: i32 = i32::MAX;
/// Cell coordinates are kept in 32 bits (a link is 16 bytes); a ball farther than this many
/// cells from the origin is far.
const FAR_LIMIT: f64 = (1u64 << 30) as f64;
/// Cell side and margin, in units of the radius capacity.
const CELL_PER_RADIUS: f64 = 2.2;
const MARGIN_PER_RADIUS: f64 = 0.09;
/// `cy` of a far ball kept out of the cells for its size (see [`BallGrid::register_sized`]);
/// other far balls have `cy` 0.
const OUTSIZE: i32 = 1;
/// A ball more than this many times the cells' radius capacity is kept out of the cells
/// rather than have them grown for it ([`BallGrid::takes_outsize`]), while there are few such
/// balls. Grown, the cells would hold some `ratio^2` small balls each: one ball ten times the
/// others' radius made a gas twelve times slower (BENCHMARKS.md, "One large ball among small
/// ones"). Below this ratio the cells grow, as they did for every ball before.
const OUTSIZE_RATIO: f64 = 4.0;
/// The most balls kept out of the cells for their size: each is checked by every
/// prediction of a ball in a cell, and checks every ball at its own.
const OUTSIZE_MOST: usize = 16;
/// Balls are *sparse* when the mean spacing between them in the region, `sqrt(area / balls)`,
/// exceeds this many cells of `CELL_PER_RADIUS` radii; they stop being sparse below
/// `DENSE_SPACING` such cells (the gap keeps the grid from resizing back and forth).
const SPARSE_SPACING: f64 = 16.0;
const DENSE_SPACING: f64 = 8.0;

/// Where a ball is registered.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Place {
    /// Not in the grid.
    Absent,
    /// In the far list.
    Far,
    /// In a cell.
    Cell(i32, i32),
}

#[derive(Clone, Copy)]
struct Link {
    cx: i32,
    cy: i32,
    next: u32,
    prev: u32,
}

const UNLINKED: Link = Link {
    cx: ABSENT,
    cy: 0,
    next: NONE,
    prev: NONE,
};

/// The grid of balls that can meet other balls.
#[derive(Clone)]
pub(crate) struct BallGrid {
    /// Every ball in the grid has a radius of at most this.
    capacity: f64,
    cell: f64,
    margin: f64,
    bits_x: u32,
    mask_x: i32,
    mask_y: i32,
    heads: Vec<u32>,
    links: Vec<Link>,
    far: Vec<u32>,
    /// Where cells are used; outside it balls are far.
    region: Option<Aabb>,
    members: usize,
    /// Per slot, a bit set while a collider may lie within reach of the ball's grown cell
    /// (see [`Self::set_near_statics`]).
    near_statics: Vec<u64>,
    /// Slots the world has made room for ([`Self::reserve_slots`]).
    planned_slots: usize,
    memberships: u32,
    filters: u32,
    /// The intersections of every ball's group masks (see [`Self::all_meet`]).
    common_memberships: u32,
    common_filters: u32,
    /// The periodic box, if the world is one.
    torus: Option<Torus>,
    /// How many balls are kept out of the cells for their size.
    outsize: usize,
}

impl Default for BallGrid {
    fn default() -> Self {
        let bits = 5;
        Self {
            capacity: 0.0,
            cell: 0.0,
            margin: 0.0,
            bits_x: bits,
            mask_x: (1 << bits) - 1,
            mask_y: (1 << bits) - 1,
            heads: vec![NONE; 1 << (2 * bits)],
            links: Vec::new(),
            far: Vec::new(),
            region: None,
            members: 0,
            near_statics: Vec::new(),
            planned_slots: 0,
            memberships: 0,
            filters: 0,
            common_memberships: !0,
            common_filters: !0,
            torus: None,
            outsize: 0,
        }
    }
}

impl BallGrid {
    /// Plans for balls in slots below `slots`: the links are allocated for all of them once
    /// the first ball joins (balls that never meet balls cost nothing).
    pub(crate) fn reserve_slots(&mut self, slots: usize) {
        self.planned_slots = self.planned_slots.max(slots);
    }

    /// Adds a ball's groups to the union. Returns whether the union grew (balls outside the
    /// grid may now belong in it).
    pub(crate) fn note_groups(&mut self, groups: CollisionGroups) -> bool {
        let (m, f) = (
            self.memberships | groups.memberships,
            self.filters | groups.filter,
        );
        let grew = (m, f) != (self.memberships, self.filters);
        (self.memberships, self.filters) = (m, f);
        self.common_memberships &= groups.memberships;
        self.common_filters &= groups.filter;
        grew
    }

    /// Whether every two balls noted so far meet: a group bit every ball is a member of and
    /// every ball's filter lets through. Then a prediction need not read a partner's groups
    /// (they live in the cold half of its slot). Conservative: a removed ball still counts.
    pub(crate) fn all_meet(&self) -> bool {
        self.common_memberships & self.common_filters != 0
    }

    /// Whether a ball with these groups can meet some ball, so belongs in the grid.
    pub(crate) fn admits(&self, groups: CollisionGroups) -> bool {
        self.torus.is_some()
            || (groups.memberships & self.filters != 0 && self.memberships & groups.filter != 0)
    }

    /// Makes the grid a periodic box's (before any ball joins): its cells tile the box.
    pub(crate) fn set_periodic(&mut self, size: DVec2) {
        self.torus = Some(Torus::new(size, CELL_PER_RADIUS * self.capacity));
        self.region = None;
    }

    /// The periodic box, if the world is one.
    pub(crate) fn torus(&self) -> Option<&Torus> {
        self.torus.as_ref()
    }

    /// Whether ball `index` is registered in a cell on a periodic box's edge (only there can
    /// its centre be on or past an edge).
    pub(crate) fn on_torus_edge(&self, index: u32) -> bool {
        match (self.torus, self.place(index)) {
            (Some(t), Place::Cell(cx, cy)) => t.on_edge(cx, cy),
            _ => false,
        }
    }

    /// The largest radius a periodic box's cells can take, or infinity.
    pub(crate) fn largest_radius(&self) -> f64 {
        self.torus
            .map_or(f64::INFINITY, |t| largest_periodic_radius(t.size))
    }

    /// Whether balls of `radius` fit the current cells.
    pub(crate) fn fits(&self, radius: f64) -> bool {
        radius <= self.capacity
    }

    /// Whether a ball of `radius`, which does not fit the cells, is better kept out of them
    /// (far: checked by every ball, and checking every ball) than the cells grown for it: it
    /// is more than [`OUTSIZE_RATIO`] times their capacity, and fewer than [`OUTSIZE_MOST`]
    /// balls are kept out so. Never in a periodic box, which has no far balls.
    pub(crate) fn takes_outsize(&self, radius: f64) -> bool {
        self.torus.is_none()
            && self.capacity > 0.0
            && radius > OUTSIZE_RATIO * self.capacity
            && self.outsize < OUTSIZE_MOST
    }

    /// Whether ball `index` is kept out of the cells for its size.
    pub(crate) fn is_outsize(&self, index: u32) -> bool {
        self.links
            .get(index as usize)
            .is_some_and(|l| l.cx == FAR && l.cy == OUTSIZE)
    }

    /// [`Self::register`] for a ball of `radius`: one that does not fit the cells (outside a
    /// periodic box, whose cells always grow) is far wherever it is, and stays far until the
    /// cells grow to fit it (the world registers every member afresh then). A ball's contacts
    /// then stay in its 3 x 3 block for every ball in a cell, and a far ball is checked by and
    /// against every ball, so no partner is missed. Returns whether its place changed.
    pub(crate) fn register_sized(&mut self, index: u32, place: Place, radius: f64) -> bool {
        if self.fits(radius) || self.torus.is_some() {
            return self.register(index, place);
        }
        if self.is_outsize(index) {
            return false;
        }
        self.unregister(index);
        self.register(index, Place::Far);
        self.links[index as usize].cy = OUTSIZE;
        self.outsize += 1;
        true
    }

    /// Resizes the cells for balls up to `radius`. Every member must be
    /// registered again afterwards ([`Self::unlink_all`] first).
    pub(crate) fn set_capacity(&mut self, radius: f64) {
        // Growth is geometric, so radii added in increasing order resize O(log) times.
        self.capacity = radius.max(1.25 * self.capacity);
        if let Some(torus) = &mut self.torus {
            // As large as the box allows: three cells across it.
            self.capacity = radius.max(self.capacity.min(largest_periodic_radius(torus.size)));
            *torus = Torus::new(torus.size, CELL_PER_RADIUS * self.capacity);
        }
        self.cell = self.cell.max(CELL_PER_RADIUS * self.capacity);
        self.margin = MARGIN_PER_RADIUS * self.capacity;
    }

    /// The cell side the members call for, if it differs enough from the current one that
    /// every member should be registered again ([`Self::set_cell`]).
    ///
    /// Cells of `CELL_PER_RADIUS` radii suit balls that are close together. Sparse balls (a
    /// few balls, or tiny ones, in a large region) would cross such cells far more often than
    /// they meet anything: one ball of radius 1e-9 in a unit box crosses 4e8 cells a second
    /// at unit speed. So when the mean spacing of the members in the region is large, the
    /// cells follow it instead (about one ball per cell), within a factor of two, which
    /// bounds the crossings by the spacing and keeps resizes rare (O(log n) as balls come).
    pub(crate) fn wanted_cell(&self) -> Option<f64> {
        if self.torus.is_some() {
            return None;
        }
        let base = CELL_PER_RADIUS * self.capacity;
        let region = self.region?;
        let size = region.max - region.min;
        let spacing = (size.x * size.y / self.members.max(1) as f64).sqrt();
        if !(spacing.is_finite() && base > 0.0) {
            return None;
        }
        let sparse = self.cell > base;
        let wanted =
            if spacing > SPARSE_SPACING * base || (sparse && spacing > DENSE_SPACING * base) {
                spacing
            } else {
                base
            };
        let ratio = wanted / self.cell;
        let off = if wanted == base {
            self.cell != base
        } else {
            !(0.5..=2.0).contains(&ratio)
        };
        off.then_some(wanted)
    }

    /// Sets the cell side (at least `CELL_PER_RADIUS` radius capacities). Every member must be
    /// registered again afterwards ([`Self::unlink_all`] first).
    pub(crate) fn set_cell(&mut self, cell: f64) {
        self.cell = cell.max(CELL_PER_RADIUS * self.capacity);
    }

    /// Unregisters every ball, returning the slot indices of the members in slot order.
    pub(crate) fn unlink_all(&mut self) -> Vec<u32> {
        let members: Vec<u32> = (0..self.links.len() as u32)
            .filter(|&i| self.links[i as usize].cx != ABSENT)
            .collect();
        self.heads.fill(NONE);
        self.far.clear();
        self.links.fill(UNLINKED);
        self.members = 0;
        self.outsize = 0;
        members
    }

    /// Where ball `index` is registered.
    pub(crate) fn place(&self, index: u32) -> Place {
        match self.links.get(index as usize) {
            None => Place::Absent,
            Some(link) if link.cx == ABSENT => Place::Absent,
            Some(link) if link.cx == FAR => Place::Far,
            Some(link) => Place::Cell(link.cx, link.cy),
        }
    }

    /// Grows the region to cover `b` (with a margin). Returns whether it grew, so that far
    /// balls now inside it can be brought in.
    pub(crate) fn cover(&mut self, b: Aabb) -> bool {
        if self.torus.is_some() {
            return false;
        }
        if self.region.is_some_and(|r| r.contains(&b)) {
            return false;
        }
        let union = self.region.map_or(b, |r| r.union(b));
        let margin = (4.0 * self.cell).max(0.125 * (union.max - union.min).max_element());
        self.region = Some(union.inflated(margin));
        true
    }

    /// The balls in the far list, in the order they went there.
    pub(crate) fn far_balls(&self) -> Vec<u32> {
        self.far.clone()
    }

    /// The place for a centre at `p`.
    #[inline]
    pub(crate) fn place_of(&self, p: DVec2) -> Place {
        if let Some(torus) = &self.torus {
            return torus_place(torus, p);
        }
        let c = p / self.cell;
        let inside = self.region.is_some_and(|r| r.contains_point(p));
        if inside && c.x.abs() < FAR_LIMIT && c.y.abs() < FAR_LIMIT {
            Place::Cell(floor(c.x) as i32, floor(c.y) as i32)
        } else {
            Place::Far
        }
    }

    /// Registers ball `index` at `place` (moving it if it is registered elsewhere). Returns
    /// whether its place changed.
    pub(crate) fn register(&mut self, index: u32, place: Place) -> bool {
        if self.place(index) == place {
            return false;
        }
        self.unregister(index);
        let i = index as usize;
        if self.links.len() <= i {
            // The first growth makes room for every slot the world planned for (so a big scene
            // pays no growth slack); later ones grow as a `Vec` does.
            let room = (i + 1).max(self.planned_slots);
            // Only a hint: room that cannot be had is simply not made.
            let _ = self
                .links
                .try_reserve_exact(room.saturating_sub(self.links.len()));
            // And the table of list heads for as many members: grown in place, it leaves no
            // freed smaller tables behind (which the allocator may keep resident).
            if let Some(heads) = room.checked_next_power_of_two() {
                let _ = self
                    .heads
                    .try_reserve_exact(heads.saturating_sub(self.heads.len()));
            }
            self.planned_slots = 0;
            self.links.resize(i + 1, UNLINKED);
            self.near_statics
                .resize(self.links.capacity().div_ceil(64), !0);
        }
        self.set_near_statics(index, true);
        match place {
            Place::Absent => return true,
            Place::Far => {
                self.links[i].cx = FAR;
                self.far.push(index);
            }
            Place::Cell(cx, cy) => {
                let slot = self.slot(cx, cy);
                let head = self.heads[slot];
                self.links[i] = Link {
                    cx,
                    cy,
                    next: head,
                    prev: NONE,
                };
                if head != NONE {
                    self.links[head as usize].prev = index;
                }
                self.heads[slot] = index;
            }
        }
        self.members += 1;
        if self.members > self.heads.len() {
            self.grow_table();
        }
        true
    }

    /// The box ball `index`'s centre stays in until its next crossing (its cell grown by the
    /// margin), if it is in a cell.
    pub(crate) fn cell_box(&self, index: u32) -> Option<Aabb> {
        let Place::Cell(cx, cy) = self.place(index) else {
            return None;
        };
        if let Some(torus) = &self.torus {
            return Some(self.torus_cell_box(torus, cx, cy));
        }
        let min = DVec2::new(cx as f64, cy as f64) * self.cell;
        Some(
            Aabb {
                min,
                max: min + self.cell,
            }
            .inflated(self.margin),
        )
    }

    /// Records whether a collider may lie within reach of ball `index` while it stays in its
    /// cell: if not, the ball needs no search for colliders until its next crossing. Set on
    /// each registration (the world then clears it if no collider is near), and for every
    /// ball when a collider is added ([`Self::mark_all_near_statics`]); a removed collider
    /// leaves it set, which only costs a search.
    pub(crate) fn set_near_statics(&mut self, index: u32, near: bool) {
        let (word, bit) = (index as usize / 64, index % 64);
        if let Some(w) = self.near_statics.get_mut(word) {
            *w = (*w & !(1 << bit)) | (u64::from(near) << bit);
        }
    }

    /// Whether a collider may lie within reach of ball `index` while it stays in its cell.
    pub(crate) fn near_statics(&self, index: u32) -> bool {
        self.near_statics
            .get(index as usize / 64)
            .is_none_or(|w| w >> (index % 64) & 1 == 1)
    }

    /// Marks every ball as possibly near a collider (one was just added).
    pub(crate) fn mark_all_near_statics(&mut self) {
        self.near_statics.fill(!0);
    }

    /// Removes ball `index` from the grid, if it is in it.
    pub(crate) fn unregister(&mut self, index: u32) {
        let i = index as usize;
        let Some(&link) = self.links.get(i) else {
            return;
        };
        match link.cx {
            ABSENT => return,
            FAR => {
                self.far.retain(|&b| b != index);
                if link.cy == OUTSIZE {
                    self.outsize -= 1;
                }
            }
            _ => {
                if link.prev == NONE {
                    let slot = self.slot(link.cx, link.cy);
                    self.heads[slot] = link.next;
                } else {
                    self.links[link.prev as usize].next = link.next;
                }
                if link.next != NONE {
                    self.links[link.next as usize].prev = link.prev;
                }
            }
        }
        self.links[i] = UNLINKED;
        self.members -= 1;
    }

    /// The time (relative to `motion`) after `start` at which ball `index`'s centre leaves its
    /// cell grown by the margin: its next crossing. For a far ball, the next time its path
    /// reaches a side of the region shrunk by a cell (where it may be back inside; if not, the
    /// next such time is taken, at most a few times per path); infinite if it never comes back.
    pub(crate) fn crossing(&self, index: u32, motion: &Motion, start: f64) -> f64 {
        let (cx, cy) = match self.place(index) {
            Place::Absent => return f64::INFINITY,
            Place::Far => {
                // Kept out for its size, it never comes back into the cells by moving.
                let Some(region) = self.region.filter(|_| !self.is_outsize(index)) else {
                    return f64::INFINITY;
                };
                let inner = region.inflated(-self.cell);
                let inner = if inner.min.cmplt(inner.max).all() {
                    inner
                } else {
                    region
                };
                return match time_within(motion, &inner) {
                    Some((_, last)) if last > start => time_of_exit(motion, &inner, start),
                    _ => f64::INFINITY,
                };
            }
            Place::Cell(cx, cy) => (cx, cy),
        };
        if let Some(torus) = &self.torus {
            return self.torus_crossing(torus, (cx, cy), motion, start);
        }
        let min = DVec2::new(cx as f64, cy as f64) * self.cell;
        let bounds = Aabb {
            min,
            max: min + self.cell,
        }
        .inflated(self.margin);
        // A centre on the grown cell's boundary at `start` (a trajectory that begins where a
        // crossing was due: a collision tied with it, and handled first) crosses now if it
        // moves out (or, at rest there, is pulled out), and one outside crosses now. Its exit
        // is the root at `start` itself, which the search after `start` passes over: the ball
        // stayed registered in the cell it had left, outside the block of a ball that fell
        // asleep beside it, and ran 6 % of a contact distance into that ball's circle (plain
        // hunt seed 16038924). Asked at the trajectory's origin only: a ball inside there
        // crosses at a root the search finds, and the check costs the gases nothing further
        // along.
        if start == 0.0 {
            let out = |p: f64, v: f64, a: f64, lo: f64, hi: f64| {
                let heading = if v != 0.0 { v } else { a };
                p < lo || p > hi || (p == lo && heading < 0.0) || (p == hi && heading > 0.0)
            };
            let (p, v, a) = (motion.position, motion.velocity, motion.acceleration);
            if out(p.x, v.x, a.x, bounds.min.x, bounds.max.x)
                || out(p.y, v.y, a.y, bounds.min.y, bounds.max.y)
            {
                return start;
            }
        }
        time_of_exit(motion, &bounds, start)
    }

    /// Calls `visit` for every other ball that ball `index` could touch before its next
    /// crossing: the balls of its 3 x 3 block and the far list; for a far ball, every member.
    /// Each comes with the shift of the image it is seen through (zero but across a periodic
    /// box's edge).
    pub(crate) fn near(&self, index: u32, visit: impl FnMut(u32, DVec2)) {
        self.near_place(self.place(index), index, visit);
    }

    /// Calls `visit` for every ball but `index` that a ball at `place` could touch before its
    /// next crossing, with the shift of its image (see [`Self::near`]).
    pub(crate) fn near_place(&self, place: Place, index: u32, mut visit: impl FnMut(u32, DVec2)) {
        match place {
            Place::Absent => {}
            Place::Far => {
                for (other, link) in self.links.iter().enumerate() {
                    if link.cx != ABSENT && other as u32 != index {
                        visit(other as u32, DVec2::ZERO);
                    }
                }
            }
            Place::Cell(cx, cy) => {
                // In a periodic box, a block round a cell off the edges sees no image: it is
                // walked as in an open grid (most cells; the far list is empty there).
                if let Some(torus) = &self.torus {
                    if torus.on_edge(cx, cy) {
                        self.near_images(torus, cx, cy, index, &mut visit);
                        return;
                    }
                }
                // The nine list heads are loaded before any list is walked: the loads do not
                // depend on one another, so their cache misses overlap. (Loops over arrays
                // of three, which unroll, where ranges did not.)
                let (xs, ys) = ([cx - 1, cx, cx + 1], [cy - 1, cy, cy + 1]);
                let columns = xs.map(|x| (x & self.mask_x) as usize);
                let heads = ys.map(|y| {
                    let base = ((y & self.mask_y) << self.bits_x) as usize;
                    columns.map(|column| self.heads[base | column])
                });
                let mut visit = |other| visit(other, DVec2::ZERO);
                for (row, y) in heads.into_iter().zip(ys) {
                    for (head, x) in row.into_iter().zip(xs) {
                        self.in_list(head, x, y, &mut visit, index);
                    }
                }
                for &other in &self.far {
                    if other != index {
                        visit(other);
                    }
                }
            }
        }
    }

    /// Calls `visit` for the balls that became neighbours of ball `index` when it moved to its
    /// place from `old` (all of them if `old` was not a cell), with their images' shifts. In
    /// a periodic box both places are cells of the box and the ball did not wrap (a wrap
    /// predicts it afresh), so block coordinates relative to it tell the new cells.
    pub(crate) fn new_neighbours(&self, index: u32, old: Place, mut visit: impl FnMut(u32, DVec2)) {
        let (Place::Cell(ox, oy), Place::Cell(cx, cy)) = (old, self.place(index)) else {
            self.near(index, visit);
            return;
        };
        if let Some(torus) = &self.torus {
            self.new_images(torus, index, (ox, oy), (cx, cy), &mut visit);
            return;
        }
        let mut visit = |other| visit(other, DVec2::ZERO);
        for y in cy - 1..=cy + 1 {
            for x in cx - 1..=cx + 1 {
                if (x - ox).abs() > 1 || (y - oy).abs() > 1 {
                    self.in_cell(x, y, &mut visit, index);
                }
            }
        }
    }

    /// [`Self::new_neighbours`] in a periodic box, from cell `(ox, oy)` to `(cx, cy)`. Out of
    /// line: a world without one never asks.
    #[inline(never)]
    fn new_images(
        &self,
        torus: &Torus,
        index: u32,
        (ox, oy): (i32, i32),
        (cx, cy): (i32, i32),
        visit: &mut impl FnMut(u32, DVec2),
    ) {
        for y in cy - 1..=cy + 1 {
            for x in cx - 1..=cx + 1 {
                if (x - ox).abs() > 1 || (y - oy).abs() > 1 {
                    self.in_image(torus, x, y, visit, index);
                }
            }
        }
    }

    /// [`Self::crossing`] of a ball in cell `cell` of a periodic box. Out of line.
    #[inline(never)]
    fn torus_crossing(&self, torus: &Torus, cell: (i32, i32), motion: &Motion, start: f64) -> f64 {
        time_of_exit(motion, &self.torus_cell_box(torus, cell.0, cell.1), start)
    }

    /// [`Self::near_place`] of a ball in cell `(cx, cy)` on a periodic box's edge, whose block
    /// reaches across it. Out of line: only edge cells ask.
    #[inline(never)]
    fn near_images(
        &self,
        torus: &Torus,
        cx: i32,
        cy: i32,
        index: u32,
        visit: &mut impl FnMut(u32, DVec2),
    ) {
        for y in cy - 1..=cy + 1 {
            for x in cx - 1..=cx + 1 {
                self.in_image(torus, x, y, visit, index);
            }
        }
    }

    /// Visits the balls of block cell `(x, y)` of a periodic box (one cell beyond an edge at
    /// most), but `except`, with the shift of the image that cell is seen through.
    fn in_image(
        &self,
        torus: &Torus,
        x: i32,
        y: i32,
        visit: &mut impl FnMut(u32, DVec2),
        except: u32,
    ) {
        let (wx, kx) = Torus::wrap_index(x, torus.n[0]);
        let (wy, ky) = Torus::wrap_index(y, torus.n[1]);
        let shift = torus.shift(kx, ky);
        self.in_cell(wx, wy, &mut |other| visit(other, shift), except);
    }

    /// The box a ball registered in cell `(cx, cy)` of a periodic box stays in until its next
    /// crossing: the cell grown by the margin, but not past the box's edges, where the ball
    /// wraps (`broad/torus.rs`).
    fn torus_cell_box(&self, torus: &Torus, cx: i32, cy: i32) -> Aabb {
        let (min, max) = torus.cell_bounds(cx, cy);
        let m = self.margin;
        let grow = |lo: f64, hi: f64, k: i32, n: i32, length: f64| {
            let lo = if k == 0 { 0.0 } else { lo - m };
            let hi = if k == n - 1 { length } else { hi + m };
            (lo, hi)
        };
        let (x0, x1) = grow(min.x, max.x, cx, torus.n[0], torus.size.x);
        let (y0, y1) = grow(min.y, max.y, cy, torus.n[1], torus.size.y);
        Aabb {
            min: DVec2::new(x0, y0),
            max: DVec2::new(x1, y1),
        }
    }

    #[inline]
    fn in_cell(&self, x: i32, y: i32, visit: &mut impl FnMut(u32), except: u32) {
        self.in_list(self.heads[self.slot(x, y)], x, y, visit, except);
    }

    /// Visits the balls of cell `(x, y)` but `except` in the list starting at `head`.
    fn in_list(&self, head: u32, x: i32, y: i32, visit: &mut impl FnMut(u32), except: u32) {
        let mut other = head;
        while other != NONE {
            let link = &self.links[other as usize];
            // Another cell sharing the list is skipped.
            if link.cx == x && link.cy == y && other != except {
                visit(other);
            }
            other = link.next;
        }
    }

    fn slot(&self, cx: i32, cy: i32) -> usize {
        (((cy & self.mask_y) << self.bits_x) | (cx & self.mask_x)) as usize
    }

    /// Doubles the table (alternately in x and y) and links every cell member again.
    fn grow_table(&mut self) {
        if self.mask_x <= self.mask_y {
            self.bits_x += 1;
            self.mask_x = (self.mask_x << 1) | 1;
        } else {
            self.mask_y = (self.mask_y << 1) | 1;
        }
        // In the same allocation when there is room (see `register`).
        self.heads.clear();
        self.heads
            .resize(((self.mask_x + 1) * (self.mask_y + 1)) as usize, NONE);
        for index in 0..self.links.len() {
            let link = self.links[index];
            if link.cx == ABSENT || link.cx == FAR {
                continue;
            }
            let slot = self.slot(link.cx, link.cy);
            let head = self.heads[slot];
            self.links[index].next = head;
            self.links[index].prev = NONE;
            if head != NONE {
                self.links[head as usize].prev = index as u32;
            }
            self.heads[slot] = index as u32;
        }
    }
}

/// The largest radius of a ball in a periodic box of sides `size`: three cells of
/// `CELL_PER_RADIUS` radii across its shorter side (the scene validation asks the same).
pub(crate) fn largest_periodic_radius(size: DVec2) -> f64 {
    size.min_element() / (3.0 * CELL_PER_RADIUS)
}

/// The place of a centre at `p` in a periodic box: the cell holding it. Out of line.
#[inline(never)]
fn torus_place(torus: &Torus, p: DVec2) -> Place {
    let (cx, cy) = torus.cell_of(p);
    Place::Cell(cx, cy)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn near(grid: &BallGrid, index: u32) -> Vec<u32> {
        let mut out = Vec::new();
        grid.near(index, |b, _| out.push(b));
        out.sort_unstable();
        out
    }

    #[test]
    fn neighbours_are_the_balls_of_the_3x3_block_even_when_cells_alias() {
        let mut grid = BallGrid::default();
        grid.set_capacity(0.5); // cells of side 1.1
        grid.cover(Aabb {
            min: DVec2::splat(-100.0),
            max: DVec2::splat(100.0),
        });
        let cell = 1.1;
        let at = |x: f64, y: f64| DVec2::new(x, y) * cell + 0.5;
        let places = [
            at(0.0, 0.0),
            at(1.0, 1.0),
            at(2.0, 0.0),
            at(-1.0, -1.0),
            at(32.0, 0.0),
        ];
        for (i, &p) in places.iter().enumerate() {
            let place = grid.place_of(p);
            grid.register(i as u32, place);
        }
        // Ball 4 is 32 cells away: the same list as ball 0 (a 32-wide table), not a neighbour.
        assert_eq!(near(&grid, 0), vec![1, 3]);
        assert_eq!(near(&grid, 1), vec![0, 2]);
        assert_eq!(near(&grid, 4), Vec::<u32>::new());
        grid.register(4, Place::Far);
        assert_eq!(near(&grid, 0), vec![1, 3, 4]);
        assert_eq!(near(&grid, 4), vec![0, 1, 2, 3]);
        grid.unregister(1);
        assert_eq!(near(&grid, 0), vec![3, 4]);
        assert_eq!(grid.place_of(DVec2::new(1e300, 0.0)), Place::Far);
        assert_eq!(grid.place_of(DVec2::new(0.0, -1000.0)), Place::Far);
        // A far ball coming back crosses into the region shrunk by a cell.
        let back = Motion::linear(DVec2::new(0.0, -1000.0), DVec2::new(0.0, 1.0));
        let t = grid.crossing(4, &back, 0.0);
        assert!((t - (1000.0 - 125.0 + 1.1)).abs() < 1e-9, "{t}");
    }

    #[test]
    fn a_table_grown_for_the_slots_reserved_stays_in_its_first_allocation() {
        let mut grid = BallGrid::default();
        grid.set_capacity(0.5);
        grid.cover(Aabb {
            min: DVec2::ZERO,
            max: DVec2::splat(200.0),
        });
        grid.reserve_slots(5000);
        let mut first = None;
        for i in 0..5000u32 {
            let p = DVec2::new(f64::from(i % 100), f64::from(i / 100)) * 1.1 + 0.5;
            let place = grid.place_of(p);
            grid.register(i, place);
            let table = (grid.heads.as_ptr(), grid.heads.capacity());
            assert_eq!(*first.get_or_insert(table), table, "ball {i}");
        }
        assert!(grid.heads.len() >= 5000);
    }

    #[test]
    fn a_ball_far_larger_than_the_cells_is_kept_out_of_them_until_they_fit_it() {
        let mut grid = BallGrid::default();
        grid.set_capacity(0.5);
        grid.cover(Aabb {
            min: DVec2::ZERO,
            max: DVec2::splat(100.0),
        });
        for i in 0..4u32 {
            let p = DVec2::new(f64::from(i) * 1.1 + 0.5, 0.5);
            assert!(grid.register_sized(i, grid.place_of(p), 0.5));
        }
        // Up to four times the capacity the cells grow; beyond, the ball is kept out.
        assert!(!grid.takes_outsize(2.0));
        assert!(grid.takes_outsize(2.1));
        let at = grid.place_of(DVec2::new(1.6, 0.5));
        assert!(grid.register_sized(4, at, 5.0));
        assert_eq!(grid.place(4), Place::Far);
        assert!(grid.is_outsize(4));
        // Registered again at a cell (by a crossing or a wake), it stays out, and it never
        // crosses back.
        assert!(!grid.register_sized(4, at, 5.0));
        assert!(grid.is_outsize(4));
        let motion = Motion::linear(DVec2::new(1.6, 0.5), DVec2::new(1.0, 0.0));
        assert_eq!(grid.crossing(4, &motion, 0.0), f64::INFINITY);
        // Every ball in a cell sees it, and it sees every ball.
        assert_eq!(near(&grid, 0), vec![1, 4]);
        assert_eq!(near(&grid, 4), vec![0, 1, 2, 3]);
        // At most `OUTSIZE_MOST` are kept out.
        for i in 5..5 + OUTSIZE_MOST as u32 - 1 {
            assert!(grid.takes_outsize(5.0));
            assert!(grid.register_sized(i, at, 5.0));
        }
        assert!(!grid.takes_outsize(5.0));
        // Removing one makes room for another; grown cells take them all back in.
        grid.unregister(4);
        assert!(grid.takes_outsize(5.0));
        grid.set_capacity(5.0);
        let members = grid.unlink_all();
        for &i in &members {
            assert!(grid.register_sized(i, grid.place_of(DVec2::splat(50.0)), 0.5));
        }
        assert!(members.iter().all(|&i| !grid.is_outsize(i)));
        assert!(grid.takes_outsize(20.1) && !grid.takes_outsize(20.0));
    }

    #[test]
    fn a_periodic_box_grows_its_cells_for_every_ball() {
        let mut grid = BallGrid::default();
        grid.set_capacity(0.5);
        grid.set_periodic(DVec2::splat(100.0));
        assert!(!grid.takes_outsize(5.0));
    }

    #[test]
    fn a_growing_table_keeps_every_list() {
        let mut grid = BallGrid::default();
        grid.set_capacity(0.5);
        grid.cover(Aabb {
            min: DVec2::ZERO,
            max: DVec2::splat(200.0),
        });
        for i in 0..5000u32 {
            let p = DVec2::new(f64::from(i % 100), f64::from(i / 100)) * 1.1 + 0.5;
            let place = grid.place_of(p);
            grid.register(i, place);
        }
        // Ball 150 sits at cell (50, 1): neighbours in rows 0..=2, columns 49..=51.
        assert_eq!(near(&grid, 150), vec![49, 50, 51, 149, 151, 249, 250, 251]);
    }

    #[test]
    fn a_crossing_is_where_the_centre_leaves_the_grown_cell() {
        let mut grid = BallGrid::default();
        grid.set_capacity(0.5); // cell 1.1, margin 0.045
        grid.register(0, Place::Cell(0, 0));
        let m = Motion::linear(DVec2::new(0.5, 0.5), DVec2::new(1.0, 0.0));
        assert!((grid.crossing(0, &m, 0.0) - 0.645).abs() < 1e-15);
        assert_eq!(
            grid.new_neighbours_of(0, Place::Cell(-1, 0)),
            Vec::<u32>::new()
        );
    }

    #[test]
    fn sparse_balls_get_cells_as_large_as_their_spacing_and_dense_ones_go_back() {
        // Regression: one ball of radius 1e-9 in a unit box crossed a cell every 2.2e-9 of
        // its path, and a step took minutes.
        let mut grid = BallGrid::default();
        grid.set_capacity(1e-9);
        grid.cover(Aabb {
            min: DVec2::ZERO,
            max: DVec2::ONE,
        });
        grid.register(0, grid.place_of(DVec2::splat(0.5)));
        let cell = grid
            .wanted_cell()
            .expect("a lone tiny ball wants larger cells");
        assert!(cell > 1.0, "{cell}");
        grid.set_cell(cell);
        assert_eq!(grid.wanted_cell(), None, "settled");
        // A million members in the same region: spacing 1.25e-3, still far above 2.2e-9.
        grid.members = 1_000_000;
        let cell = grid.wanted_cell().expect("denser: smaller cells");
        assert!((cell - 1.25e-3).abs() < 1e-4, "{cell}");
        grid.set_cell(cell);
        // A hundred times denser still, with balls of radius 1e-4: their spacing, 1.25e-4, is
        // under two cells of 2.2 radii, so the cells go back to 2.2 radii.
        grid.set_capacity(1e-4);
        grid.members = 100_000_000;
        assert_eq!(grid.wanted_cell(), Some(CELL_PER_RADIUS * 1e-4));
    }

    #[test]
    fn every_two_balls_meet_while_some_group_bit_is_in_every_membership_and_every_filter() {
        let mut grid = BallGrid::default();
        let groups = |memberships, filter| CollisionGroups {
            memberships,
            filter,
        };
        assert!(grid.all_meet(), "no balls");
        grid.note_groups(groups(0b011, 0b001));
        grid.note_groups(groups(0b001, 0b111));
        // Bit 0 is in both memberships and both filters.
        assert!(grid.all_meet());
        // A member of group 1 only, filtering group 1: it does not meet the first ball (whose
        // filter lacks bit 1), so predictions must check groups again.
        grid.note_groups(groups(0b010, 0b010));
        assert!(!groups(0b011, 0b001).interact(groups(0b010, 0b010)));
        assert!(!grid.all_meet());
    }

    impl BallGrid {
        fn new_neighbours_of(&self, index: u32, old: Place) -> Vec<u32> {
            let mut out = Vec::new();
            self.new_neighbours(index, old, |b, _| out.push(b));
            out
        }
    }
}
