//! A minimal event-driven hard-disk gas: the floor the engine's speed is measured against.
//!
//! It runs the suite's gas scene (equal elastic disks in a square box, no gravity; or in a
//! square periodic box, `scenes::periodic_gas`, its cells wrapping round and pairs met through
//! their nearest images) with the
//! design of the fastest published event-driven codes and nothing else: one pending event
//! per disk, cells of one diameter with crossing events, a calendar queue, collision counters
//! for stale events, plain `f64` times. It has none of what makes the engine exact and
//! general: no double-double clock, no total order for simultaneous events, no colliders but
//! the four walls, no groups, masses, restitution, gravity or resting contact, no events
//! handed to a caller. Its rounding decides near-ties however it falls, so it is not exact,
//! and it is not part of the engine: `exact2d-bench minimal` runs both on the same scenes to
//! show what a machine gives the leanest design, and what exactness and generality cost on
//! top of it (`BENCHMARKS.md`).
//!
//! Its results are checked independently (`tests/minimal_gas.rs`): energy is conserved, no two
//! disks overlap and none leaves the box, and its first collisions are the engine's, pair for
//! pair, until rounding makes the two chaotic trajectories part.

use exact2d::scene::Scene;

/// "No disk" in a cell or a list.
const NONE: u32 = u32::MAX;

/// What a disk's next event is with, when not another disk (whose slot is stored instead).
const WALL_X: u32 = u32::MAX - 1;
const WALL_Y: u32 = u32::MAX - 2;
/// Crossings into the cell to the left, right, below, above.
const CROSS_LEFT: u32 = u32::MAX - 3;
const CROSS_RIGHT: u32 = u32::MAX - 4;
const CROSS_DOWN: u32 = u32::MAX - 5;
const CROSS_UP: u32 = u32::MAX - 6;

/// How many disks a cell holds: with cells of side below `sqrt(2)` diameters (there are at
/// least three cells a side), no five centres a diameter apart fit in one.
const CELL_CAPACITY: usize = 4;

/// Nodes per calendar day the bucket width aims at.
const NODES_PER_DAY: f64 = 2.0;

/// The latest calendar day: later times (and infinite ones) are clamped to it.
const MAX_DAY: u64 = 1 << 62;

/// A disk, with its pending event, in one cache line.
#[derive(Clone, Copy)]
#[repr(C, align(64))]
struct Disk {
    /// Position at time `t`, and velocity.
    x: f64,
    y: f64,
    vx: f64,
    vy: f64,
    t: f64,
    /// The time of its pending event (the earlier of its collision and its crossing).
    due: f64,
    /// What the pending event is with (a disk's slot, or one of the constants above).
    partner: u32,
    /// The partner's collision count when the event was predicted.
    partner_count: u32,
    /// Collisions so far: an event predicted with this disk is stale once it changes.
    count: u32,
    /// The cell it is listed in.
    cell: u32,
}

/// A disk's earliest collision (with a disk or a wall), kept so that a crossing only checks
/// the disks of the cells it brings into reach.
#[derive(Clone, Copy)]
struct Collision {
    time: f64,
    partner: u32,
    partner_count: u32,
}

const NO_COLLISION: Collision = Collision {
    time: f64::INFINITY,
    partner: NONE,
    partner_count: 0,
};

/// A minimal hard-disk gas in the square box `[0, side]^2` (see the module documentation).
pub struct MinimalGas {
    disks: Vec<Disk>,
    collisions_pending: Vec<Collision>,
    radius: f64,
    side: f64,
    /// Whether the box is periodic (no walls; cells and pairs wrap round).
    periodic: bool,
    /// Cells a side, the side of a cell, and each cell's disks (`NONE` in free places).
    cells_per_side: usize,
    cell_side: f64,
    cells: Vec<[u32; CELL_CAPACITY]>,
    /// The calendar: per disk its links, per bucket the first disk of its list, and the
    /// overflow list (days at or past `horizon`).
    links: Vec<[u32; 2]>,
    heads: Vec<u32>,
    overflow: u32,
    per_width: f64,
    cursor: u64,
    horizon: u64,
    now: f64,
    collisions: u64,
}

/// The walls of a closed gas: each segment joins two corners of the square `[0, side]^2`
/// along one side, and every side has one.
fn check_walls(scene: &Scene, side: f64) -> Result<(), String> {
    let corners = [[0.0, 0.0], [side, 0.0], [side, side], [0.0, side]];
    let corner = |p: [f64; 2]| corners.iter().position(|&c| c == p);
    let mut sides: Vec<(usize, usize)> = scene
        .segments
        .iter()
        .filter_map(|s| Some((corner(s.a)?, corner(s.b)?)))
        .map(|(a, b)| (a.min(b), a.max(b)))
        .collect();
    sides.sort_unstable();
    if scene.segments.len() != 4 || sides != [(0, 1), (0, 3), (1, 2), (2, 3)] {
        return Err(unsupported(
            "its segments are not the four walls of a square [0, side]^2",
        ));
    }
    Ok(())
}

/// Why a scene is not a gas the minimal code can run.
fn unsupported(what: &str) -> String {
    format!("the minimal gas runs only the suite's hard-disk gas: {what}")
}

impl MinimalGas {
    /// The gas of `scene`, which must be like the suite's: no gravity, balls colliding with
    /// each other, equal radii, unit restitution, equal masses, no circles, and the four
    /// walls of a square `[0, side]^2` as its only segments, with every ball inside; or no
    /// segments and a square periodic box (`"periodic": [side, side]`).
    ///
    /// # Errors
    /// A message naming what the scene has that the minimal gas does not support.
    pub fn new(scene: &Scene) -> Result<Self, String> {
        if scene.gravity != [0.0, 0.0] || !scene.ball_ball || !scene.circles.is_empty() {
            return Err(unsupported("gravity, circles or balls that do not collide"));
        }
        let Some(first) = scene.balls.first() else {
            return Err(unsupported("no balls"));
        };
        let (radius, mass) = (first.radius, first.mass);
        if scene
            .balls
            .iter()
            .any(|b| b.radius != radius || b.mass != mass || b.restitution != 1.0)
        {
            return Err(unsupported("unequal radii or masses, or inelastic balls"));
        }
        let periodic = scene.periodic.is_some();
        let side = match scene.periodic {
            Some([lx, ly]) if lx == ly && scene.segments.is_empty() => lx,
            Some(_) => {
                return Err(unsupported(
                    "a periodic box that is not square, or walls in it",
                ));
            }
            None => {
                let side = scene
                    .segments
                    .iter()
                    .flat_map(|s| [s.a[0], s.a[1], s.b[0], s.b[1]])
                    .fold(0.0, f64::max);
                check_walls(scene, side)?;
                side
            }
        };
        let diameter = 2.0 * radius;
        let cells_per_side = (side / diameter) as usize;
        if cells_per_side < 3 {
            return Err(unsupported("a box under 3 diameters wide"));
        }
        if cells_per_side.saturating_mul(cells_per_side) > 64 * scene.balls.len() {
            return Err(unsupported(
                "a gas so sparse that its cells would take over 64 per ball",
            ));
        }
        let cell_side = side / cells_per_side as f64;
        let buckets = scene.balls.len().next_power_of_two();
        let mut gas = Self {
            disks: Vec::with_capacity(scene.balls.len()),
            collisions_pending: vec![NO_COLLISION; scene.balls.len()],
            radius,
            side,
            periodic,
            cells_per_side,
            cell_side,
            cells: vec![[NONE; CELL_CAPACITY]; cells_per_side * cells_per_side],
            links: vec![[NONE; 2]; scene.balls.len()],
            heads: vec![NONE; buckets],
            overflow: NONE,
            per_width: 1.0,
            cursor: 0,
            horizon: buckets as u64,
            now: 0.0,
            collisions: 0,
        };
        for (k, b) in scene.balls.iter().enumerate() {
            let [x, y] = b.pos;
            // Touching a wall, up to rounding, is inside (as in the engine).
            let inside = |p: f64| {
                if periodic {
                    (0.0..side).contains(&p)
                } else {
                    p > 0.0 && p < side && (p - radius).min(side - radius - p) >= -1e-9 * radius
                }
            };
            if !(inside(x) && inside(y)) {
                return Err(unsupported("a ball outside the box"));
            }
            let cell = gas.cell_of(x, y);
            gas.disks.push(Disk {
                x,
                y,
                vx: b.vel[0],
                vy: b.vel[1],
                t: 0.0,
                due: f64::INFINITY,
                partner: NONE,
                partner_count: 0,
                count: 0,
                cell,
            });
            let slot = gas.cells[cell as usize].iter_mut().find(|s| **s == NONE);
            let Some(slot) = slot else {
                return Err(unsupported("balls that overlap"));
            };
            *slot = k as u32;
        }
        // No two disks overlap (beyond rounding): each is checked against its 3 x 3 block.
        for k in 0..gas.disks.len() {
            let d = gas.disks[k];
            for cell in gas.block(d.cell) {
                for &j in &gas.cells[cell] {
                    let Some(o) = gas.disks.get(j as usize).filter(|_| j as usize != k) else {
                        continue;
                    };
                    let (dx, dy) = gas.nearest(o.x - d.x, o.y - d.y);
                    if (dx * dx + dy * dy).sqrt() < diameter * (1.0 - 1e-9) {
                        return Err(unsupported("balls that overlap"));
                    }
                }
            }
        }
        // Every disk's first event, then a bucket width from their mean time.
        for k in 0..gas.disks.len() {
            gas.store(k, gas.earliest_collision(k, NONE));
        }
        let finite: Vec<f64> = gas
            .disks
            .iter()
            .map(|d| d.due)
            .filter(|t| t.is_finite())
            .collect();
        if !finite.is_empty() {
            let mean = finite.iter().sum::<f64>() / finite.len() as f64;
            let width = NODES_PER_DAY * mean / gas.disks.len() as f64;
            if width.is_normal() && (1.0 / width).is_normal() {
                gas.per_width = 1.0 / width;
            }
        }
        for k in 0..gas.disks.len() {
            gas.link(k as u32);
        }
        Ok(gas)
    }

    /// Collisions handled so far (disk-disk and disk-wall).
    #[must_use]
    pub fn collisions(&self) -> u64 {
        self.collisions
    }

    /// The disks' positions and velocities at the time of the last event handled.
    #[must_use]
    pub fn state(&self) -> Vec<([f64; 2], [f64; 2])> {
        self.disks
            .iter()
            .map(|d| {
                let dt = self.now - d.t;
                ([d.x + d.vx * dt, d.y + d.vy * dt], [d.vx, d.vy])
            })
            .collect()
    }

    /// The radius every disk has, and the side of the box.
    #[must_use]
    pub fn geometry(&self) -> (f64, f64) {
        (self.radius, self.side)
    }

    /// Handles events until `collisions` collisions have been handled in all (or no event is
    /// left), calling `on_collision(a, b)` for each disk-disk collision (`a < b`).
    pub fn run(&mut self, collisions: u64, mut on_collision: impl FnMut(u32, u32)) {
        while self.collisions < collisions {
            let Some(i) = self.pop() else {
                return;
            };
            let disk = self.disks[i as usize];
            self.now = disk.due;
            match disk.partner {
                CROSS_LEFT | CROSS_RIGHT | CROSS_DOWN | CROSS_UP => self.cross(i as usize),
                WALL_X | WALL_Y => {
                    let d = &mut self.disks[i as usize];
                    let dt = self.now - d.t;
                    (d.x, d.y, d.t) = (d.x + d.vx * dt, d.y + d.vy * dt, self.now);
                    if disk.partner == WALL_X {
                        d.vx = -d.vx;
                    } else {
                        d.vy = -d.vy;
                    }
                    d.count += 1;
                    self.collisions += 1;
                    self.predict(i as usize, NONE);
                }
                j if self.disks[j as usize].count != disk.partner_count => {
                    // The partner collided since: stale.
                    self.predict(i as usize, NONE);
                }
                j => {
                    self.collide(i as usize, j as usize);
                    self.collisions += 1;
                    on_collision(i.min(j), i.max(j));
                    self.predict(i as usize, j);
                    self.predict(j as usize, i);
                }
            }
        }
    }

    /// Moves disks `i` and `j` to now and exchanges their normal velocities.
    fn collide(&mut self, i: usize, j: usize) {
        let now = self.now;
        for k in [i, j] {
            let d = &mut self.disks[k];
            let dt = now - d.t;
            (d.x, d.y, d.t) = (d.x + d.vx * dt, d.y + d.vy * dt, now);
            d.count += 1;
        }
        let (a, b) = (self.disks[i], self.disks[j]);
        let (nx, ny) = self.nearest(b.x - a.x, b.y - a.y);
        let f = (nx * (b.vx - a.vx) + ny * (b.vy - a.vy)) / (nx * nx + ny * ny);
        if f < 0.0 {
            let a = &mut self.disks[i];
            a.vx += f * nx;
            a.vy += f * ny;
            let b = &mut self.disks[j];
            b.vx -= f * nx;
            b.vy -= f * ny;
        }
    }

    /// The time disks `i` and `j` (positions taken at `now`) next touch while approaching.
    #[inline(always)]
    fn contact<const PERIODIC: bool>(&self, i: usize, j: usize) -> f64 {
        let (a, b) = (&self.disks[i], &self.disks[j]);
        let (ta, tb) = (self.now - a.t, self.now - b.t);
        let dx = (b.x + b.vx * tb) - (a.x + a.vx * ta);
        let dy = (b.y + b.vy * tb) - (a.y + a.vy * ta);
        let (dx, dy) = if PERIODIC {
            self.nearest(dx, dy)
        } else {
            (dx, dy)
        };
        let (dvx, dvy) = (b.vx - a.vx, b.vy - a.vy);
        let approach = dx * dvx + dy * dvy;
        if approach >= 0.0 {
            return f64::INFINITY;
        }
        let speed2 = dvx * dvx + dvy * dvy;
        let diameter = 2.0 * self.radius;
        let gap = dx * dx + dy * dy - diameter * diameter;
        let discriminant = approach * approach - speed2 * gap;
        if discriminant < 0.0 {
            return f64::INFINITY;
        }
        // The smaller root without cancellation; a pair overlapping by rounding meets now.
        self.now + (gap / (discriminant.sqrt() - approach)).max(0.0)
    }

    /// Disk `i`'s contact with disk `j` if it comes before `best`, else `best`.
    #[inline(always)]
    fn earlier_contact<const PERIODIC: bool>(
        &self,
        i: usize,
        j: u32,
        best: Collision,
    ) -> Collision {
        let time = self.contact::<PERIODIC>(i, j as usize);
        if time < best.time {
            Collision {
                time,
                partner: j,
                partner_count: self.disks[j as usize].count,
            }
        } else {
            best
        }
    }

    /// Disk `i`'s earliest collision from now (with a wall, or a disk of its 3 x 3 block
    /// other than `skip`).
    fn earliest_collision(&self, i: usize, skip: u32) -> Collision {
        let d = &self.disks[i];
        let dt = self.now - d.t;
        let (x, y) = (d.x + d.vx * dt, d.y + d.vy * dt);
        let (lo, hi) = (self.radius, self.side - self.radius);
        let wall = |p: f64, v: f64| {
            if v > 0.0 {
                ((hi - p) / v).max(0.0)
            } else if v < 0.0 {
                ((lo - p) / v).max(0.0)
            } else {
                f64::INFINITY
            }
        };
        let (wx, wy) = if self.periodic {
            (f64::INFINITY, f64::INFINITY)
        } else {
            (wall(x, d.vx), wall(y, d.vy))
        };
        let mut best = if self.periodic {
            NO_COLLISION
        } else if wx <= wy {
            Collision {
                time: self.now + wx,
                partner: WALL_X,
                partner_count: 0,
            }
        } else {
            Collision {
                time: self.now + wy,
                partner: WALL_Y,
                partner_count: 0,
            }
        };
        let n = self.cells_per_side;
        let (cx, cy) = (d.cell as usize % n, d.cell as usize / n);
        if self.periodic {
            // The block's columns and rows round the edges, found once (the box has at least
            // three cells a side, so they are nine distinct cells).
            let around = |c: usize| {
                [
                    if c == 0 { n - 1 } else { c - 1 },
                    c,
                    if c + 1 == n { 0 } else { c + 1 },
                ]
            };
            let columns = around(cx);
            for row in around(cy) {
                for column in columns {
                    for &j in &self.cells[row * n + column] {
                        if j != NONE && j as usize != i && j != skip {
                            best = self.earlier_contact::<true>(i, j, best);
                        }
                    }
                }
            }
            return best;
        }
        for row in cy.saturating_sub(1)..=(cy + 1).min(n - 1) {
            for column in cx.saturating_sub(1)..=(cx + 1).min(n - 1) {
                for &j in &self.cells[row * n + column] {
                    if j != NONE && j as usize != i && j != skip {
                        best = self.earlier_contact::<false>(i, j, best);
                    }
                }
            }
        }
        best
    }

    /// The cells of the 3 x 3 block around `cell` (fewer at a wall; round the edges in a
    /// periodic box, where the box has at least three cells a side, so nine distinct ones).
    #[inline(always)]
    fn block(&self, cell: u32) -> impl Iterator<Item = usize> + use<> {
        let n = self.cells_per_side as isize;
        let (cx, cy) = (cell as isize % n, cell as isize / n);
        let periodic = self.periodic;
        (-1..=1).flat_map(move |dy| {
            (-1..=1).filter_map(move |dx| {
                let (x, y) = (cx + dx, cy + dy);
                if periodic {
                    Some((y.rem_euclid(n) * n + x.rem_euclid(n)) as usize)
                } else if x < 0 || y < 0 || x >= n || y >= n {
                    None
                } else {
                    Some((y * n + x) as usize)
                }
            })
        })
    }

    /// `(dx, dy)`, a difference of two positions, at its nearest image in a periodic box (as
    /// it is otherwise).
    #[inline(always)]
    fn nearest(&self, dx: f64, dy: f64) -> (f64, f64) {
        if !self.periodic {
            return (dx, dy);
        }
        let (side, half) = (self.side, 0.5 * self.side);
        let fold = |d: f64| {
            if d > half {
                d - side
            } else if d < -half {
                d + side
            } else {
                d
            }
        };
        (fold(dx), fold(dy))
    }

    /// Disk `i`'s next crossing out of its cell, or `collision` if that comes first: the due
    /// time and partner of its pending event.
    fn crossing(&self, i: usize, collision: Collision) -> (f64, u32) {
        let d = &self.disks[i];
        let dt = self.now - d.t;
        let (x, y) = (d.x + d.vx * dt, d.y + d.vy * dt);
        let n = self.cells_per_side;
        let (cx, cy) = (d.cell as usize % n, d.cell as usize / n);
        let side = self.cell_side;
        let periodic = self.periodic;
        let exit = |p: f64, v: f64, c: usize, low: u32, high: u32| {
            if v > 0.0 && (c + 1 < n || periodic) {
                ((((c + 1) as f64 * side - p) / v).max(0.0), high)
            } else if v < 0.0 && (c > 0 || periodic) {
                (((c as f64 * side - p) / v).max(0.0), low)
            } else {
                (f64::INFINITY, NONE)
            }
        };
        let (tx, px) = exit(x, d.vx, cx, CROSS_LEFT, CROSS_RIGHT);
        let (ty, py) = exit(y, d.vy, cy, CROSS_DOWN, CROSS_UP);
        let (tau, partner) = if tx <= ty { (tx, px) } else { (ty, py) };
        if self.now + tau < collision.time {
            (self.now + tau, partner)
        } else {
            (collision.time, collision.partner)
        }
    }

    /// Predicts disk `i` afresh from now (never against `skip`, just collided with) and
    /// queues its next event.
    fn predict(&mut self, i: usize, skip: u32) {
        let collision = self.earliest_collision(i, skip);
        self.queue(i, collision);
    }

    /// Queues disk `i` anew for its earliest collision or its crossing (see [`Self::store`]).
    fn queue(&mut self, i: usize, collision: Collision) {
        // Out of the list of its old due day before the due time changes.
        self.unlink(i as u32);
        self.store(i, collision);
        self.link(i as u32);
    }

    /// Stores disk `i`'s earliest collision, and as its pending event the earlier of that and
    /// its crossing (not linking it into the calendar).
    fn store(&mut self, i: usize, collision: Collision) {
        self.collisions_pending[i] = collision;
        let (time, partner) = self.crossing(i, collision);
        let d = &mut self.disks[i];
        d.due = time;
        d.partner = partner;
        d.partner_count = collision.partner_count;
    }

    /// Moves disk `i` into the cell it crosses into, checks the disks that came into reach
    /// against its earliest collision, and queues its next event.
    fn cross(&mut self, i: usize) {
        let n = self.cells_per_side as isize;
        let (dx, dy) = match self.disks[i].partner {
            CROSS_LEFT => (-1, 0),
            CROSS_RIGHT => (1, 0),
            CROSS_DOWN => (0, -1),
            _ => (0, 1),
        };
        let old = self.disks[i].cell as usize;
        let members = &mut self.cells[old];
        if let Some(place) = members.iter_mut().find(|s| **s == i as u32) {
            *place = NONE;
        }
        let (mut cx, mut cy) = (old as isize % n + dx, old as isize / n + dy);
        if self.periodic && (!(0..n).contains(&cx) || !(0..n).contains(&cy)) {
            // Out through an edge of the periodic box: in again through the other, the disk's
            // stored position moved one box length.
            let d = &mut self.disks[i];
            let side = self.side;
            if cx < 0 {
                (cx, d.x) = (n - 1, d.x + side);
            } else if cx >= n {
                (cx, d.x) = (0, d.x - side);
            }
            if cy < 0 {
                (cy, d.y) = (n - 1, d.y + side);
            } else if cy >= n {
                (cy, d.y) = (0, d.y - side);
            }
        }
        let cell = (cy * n + cx) as usize;
        match self.cells[cell].iter_mut().find(|s| **s == NONE) {
            Some(place) => *place = i as u32,
            // Five centres a diameter apart do not fit in a cell; only a broken invariant
            // could bring this about.
            None => panic!("the minimal gas lost a disk: cell {cell} is full"),
        }
        self.disks[i].cell = cell as u32;
        let mut best = self.collisions_pending[i];
        // The cells one further on, beside the new one along the crossing.
        for k in -1..=1 {
            let (mut x, mut y) = if dx != 0 {
                (cx + dx, cy + k)
            } else {
                (cx + k, cy + dy)
            };
            if self.periodic {
                // One step past an edge at most: in again through the other.
                let wrap = |c: isize| {
                    if c < 0 {
                        c + n
                    } else if c >= n {
                        c - n
                    } else {
                        c
                    }
                };
                (x, y) = (wrap(x), wrap(y));
            } else if x < 0 || y < 0 || x >= n || y >= n {
                continue;
            }
            for &j in &self.cells[(y * n + x) as usize] {
                if j != NONE {
                    best = if self.periodic {
                        self.earlier_contact::<true>(i, j, best)
                    } else {
                        self.earlier_contact::<false>(i, j, best)
                    };
                }
            }
        }
        self.queue(i, best);
    }

    /// The cell holding point `(x, y)`.
    fn cell_of(&self, x: f64, y: f64) -> u32 {
        let n = self.cells_per_side;
        let c = |p: f64| ((p / self.cell_side) as usize).min(n - 1);
        (c(y) * n + c(x)) as u32
    }

    /// The calendar day of time `t`.
    fn day(&self, t: f64) -> u64 {
        let x = t * self.per_width;
        if x < MAX_DAY as f64 {
            (x as i64).max(0) as u64
        } else {
            MAX_DAY
        }
    }

    fn head_mut(&mut self, day: u64) -> &mut u32 {
        if day < self.horizon {
            let mask = self.heads.len() as u64 - 1;
            &mut self.heads[(day & mask) as usize]
        } else {
            &mut self.overflow
        }
    }

    /// Puts disk `i` at the head of its due day's list.
    fn link(&mut self, i: u32) {
        let day = self.day(self.disks[i as usize].due);
        let head = self.head_mut(day);
        let next = std::mem::replace(head, i);
        if next != NONE {
            self.links[next as usize][1] = i;
        }
        self.links[i as usize] = [next, NONE];
    }

    /// Takes disk `i` out of its list.
    fn unlink(&mut self, i: u32) {
        let [next, prev] = self.links[i as usize];
        if prev == NONE {
            let day = self.day(self.disks[i as usize].due);
            *self.head_mut(day) = next;
        } else {
            self.links[prev as usize][0] = next;
        }
        if next != NONE {
            self.links[next as usize][1] = prev;
        }
    }

    /// The disk whose event is earliest (ties to the smallest slot), left in the queue; `None`
    /// if no disk has an event due at a finite time.
    fn pop(&mut self) -> Option<u32> {
        let mask = self.heads.len() as u64 - 1;
        loop {
            while self.cursor < self.horizon {
                let mut at = self.heads[(self.cursor & mask) as usize];
                let (mut best, mut best_time) = (NONE, f64::INFINITY);
                while at != NONE {
                    let time = self.disks[at as usize].due;
                    if self.day(time) == self.cursor
                        && (time < best_time || (time == best_time && at < best))
                    {
                        (best, best_time) = (at, time);
                    }
                    at = self.links[at as usize][0];
                }
                if best != NONE {
                    return Some(best);
                }
                self.cursor += 1;
            }
            // The year is over and its buckets are empty: the next starts at the overflow's
            // earliest day, and its disks due within it move into buckets.
            let mut start = u64::MAX;
            let mut at = self.overflow;
            while at != NONE {
                start = start.min(self.day(self.disks[at as usize].due));
                at = self.links[at as usize][0];
            }
            if start >= MAX_DAY {
                return None;
            }
            self.cursor = start;
            self.horizon = start + self.heads.len() as u64;
            let mut at = std::mem::replace(&mut self.overflow, NONE);
            while at != NONE {
                let next = self.links[at as usize][0];
                self.link(at);
                at = next;
            }
        }
    }
}
