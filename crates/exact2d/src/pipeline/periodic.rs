//! A periodic box: the world as a torus (see `broad/torus.rs` for the maths of positions,
//! wraps and images).
//!
//! A ball's path is kept inside the box `[0, Lx) x [0, Ly)`. When its centre reaches an edge
//! (the ball grid's crossing out of a cell on that edge) the path is restated there and moved
//! one box length, and the ball counts one image more in that direction; its unwrapped
//! position is its position plus its images times the box's sides. Two balls meet through
//! their nearest images: a prediction sees a partner in a cell across an edge at its path
//! moved by that cell's image shift, and an event finds the same image as the nearest one of
//! the centres' difference (the two touch, and the box is at least 6.6 radii across).
//!
//! What a periodic box allows: balls of radius up to `min(Lx, Ly) / 6.6` (three ball-grid
//! cells across), and static colliders clear of its edges by more than the largest ball's
//! radius, so that no ball meets a collider's image across an edge. Not (yet) gravity, a
//! table or sleeping balls: the machinery of rest (supports, groups, sleepers' circles) sees
//! no images. A world without a periodic box never reads any of this.

use std::collections::{BTreeMap, VecDeque};

use glam::DVec2;

use super::World;
use super::error::WorldError;
use super::step::COLLAPSE_FLOOR;
use crate::broad::{Place, Torus};
use crate::dynamics::{BallHandle, Time};
use crate::geometry::Shape;

/// What a periodic world keeps beside the ball grid's [`Torus`]: each slot's images (16
/// bytes a ball) and the wraps still standing.
#[derive(Clone, Debug, Default)]
pub(crate) struct Periodic {
    /// The images ball `i` has moved through (its unwrapped position is its position plus
    /// these times the box's sides).
    images: Vec<[i64; 2]>,
    /// The wraps that are still the origins of their balls' paths, by slot: when the ball
    /// wrapped, and the origin of its path before the wraps that led to it (its last event).
    /// A wrap restates a path but is no event of the ball's, and the rule that a collision
    /// soon after a ball's previous event is elastic (`World::recent`) must not count it.
    /// A ball whose path began at a wrap has had no event since; in a gas whose free path is
    /// short against the box that is about one ball in (box side / free path): 80 to 100 of
    /// 10^5 disks at packing 0.4 and 16 to 26 at 0.7 (measured), where a table of every
    /// ball's last wrap took 32 bytes a ball.
    wraps: BTreeMap<u32, (Time, Time)>,
    /// The same wraps' times and slots, in the order they came, to forget them once their
    /// balls' paths have changed (see [`World::forget_wraps`]); an entry whose slot wrapped
    /// again since is forgotten, its newer one stands.
    wrap_order: VecDeque<(Time, u32)>,
}

impl World {
    /// Makes the world a periodic box `[0, size.x) x [0, size.y)`: its opposite edges are
    /// glued, a ball leaving through one comes back through the other, and two balls meet
    /// through their nearest images. Positions come out in the box; a ball's unwrapped
    /// position ([`World::ball_unwrapped_position`]) adds the box lengths it has crossed.
    ///
    /// Only on a world without balls, without gravity and without a table. Static colliders
    /// (present or added later) must keep clear of the box's edges by more than the radius of
    /// the largest ball, and a ball's radius may be at most `min(size.x, size.y) / 6.6`.
    ///
    /// # Errors
    /// [`WorldError::InvalidPeriodicBox`] if a side is not positive and finite;
    /// [`WorldError::PeriodicNotEmpty`] if the world has balls (or is already periodic);
    /// [`WorldError::PeriodicWith`] if it has gravity or a table.
    pub fn set_periodic(&mut self, size: DVec2) -> Result<(), WorldError> {
        if !(size.x > 0.0 && size.y > 0.0 && size.is_finite()) {
            return Err(WorldError::InvalidPeriodicBox(size));
        }
        if self.balls.len() > 0 || self.periodic.is_some() {
            return Err(WorldError::PeriodicNotEmpty);
        }
        if self.gravity != DVec2::ZERO {
            return Err(WorldError::PeriodicWith("gravity"));
        }
        if self.table.is_some() {
            return Err(WorldError::PeriodicWith("a table"));
        }
        let torus = Torus::new(size, 0.0);
        for (_, collider) in self.colliders.iter() {
            check_clear(&torus, &collider.shape, 0.0)?;
        }
        self.grid.set_periodic(size);
        self.periodic = Some(Periodic::default());
        Ok(())
    }

    /// The periodic box's sides, if the world is one (see [`World::set_periodic`]).
    #[must_use]
    pub fn periodic_box(&self) -> Option<DVec2> {
        self.periodic.as_ref()?;
        self.grid.torus().map(|t| t.size)
    }

    /// A ball's unwrapped position in a periodic box: its position plus the box lengths it
    /// has crossed since it was added (for diffusion: the displacement is this minus where
    /// it was added). Its position itself in a world without a periodic box.
    #[must_use]
    pub fn ball_unwrapped_position(&self, handle: BallHandle) -> Option<DVec2> {
        let ball = self.ball(handle)?;
        let (Some(size), Some([kx, ky])) = (self.periodic_box(), self.ball_images(handle)) else {
            return Some(ball.position);
        };
        // Exact products below 2^53 box lengths; the sum is rounded once.
        Some(ball.position + DVec2::new(kx as f64 * size.x, ky as f64 * size.y))
    }

    /// The box lengths a ball has crossed in a periodic box since it was added, along each
    /// axis (`+1` each time it left through `L`, `-1` through 0), counted so that its
    /// unwrapped position is its position ([`World::ball`], in the box) plus these times the
    /// sides: `[0, 0]` in a world without a periodic box. `None` for a handle not live.
    #[must_use]
    pub fn ball_images(&self, handle: BallHandle) -> Option<[i64; 2]> {
        let (record, _) = self.balls.get(handle)?;
        let (Some(periodic), Some(torus)) = (&self.periodic, self.grid.torus()) else {
            return Some([0, 0]);
        };
        let [kx, ky] = periodic
            .images
            .get(handle.index as usize)
            .copied()
            .unwrap_or_default();
        // A path may sit on the far edge of its box's closure (`x = L`, moving down the axis),
        // which is reported at 0: one box length more.
        let p = record
            .trajectory
            .position_at(self.time, self.acceleration(handle.index));
        let folded = |x: f64, l: f64| i64::from(x >= l) - i64::from(x < 0.0);
        Some([
            kx + folded(p.x, torus.size.x),
            ky + folded(p.y, torus.size.y),
        ])
    }

    /// The checks a ball must pass in a periodic box: inside it, and small enough for it and
    /// for the colliders' clearance of its edges.
    pub(crate) fn check_periodic_ball(
        &self,
        position: DVec2,
        radius: f64,
    ) -> Result<(), WorldError> {
        let Some(torus) = self.grid.torus() else {
            return Ok(());
        };
        if !torus.contains(position) {
            return Err(WorldError::OutsidePeriodicBox(position));
        }
        let largest = self.grid.largest_radius();
        if radius > largest {
            return Err(WorldError::TooLargeForPeriodicBox { radius, largest });
        }
        for (_, collider) in self.colliders.iter() {
            check_clear(torus, &collider.shape, radius)?;
        }
        Ok(())
    }

    /// The check a collider must pass in a periodic box: clear of its edges by more than the
    /// largest ball's radius.
    pub(crate) fn check_periodic_collider(&self, shape: &Shape) -> Result<(), WorldError> {
        let Some(torus) = self.grid.torus() else {
            return Ok(());
        };
        let largest = self
            .balls
            .iter()
            .map(|(_, k, _)| k.radius)
            .fold(0.0, f64::max);
        check_clear(torus, shape, largest)
    }

    /// Makes room for balls in slots below `slots` in the side table without reallocating
    /// (see [`World::reserve_balls`]).
    pub(crate) fn reserve_periodic_slots(&mut self, slots: usize) {
        if let Some(periodic) = &mut self.periodic {
            let more = slots.saturating_sub(periodic.images.len());
            let _ = periodic.images.try_reserve_exact(more);
        }
    }

    /// Notes a new ball in slot `index` (no images yet).
    pub(crate) fn note_periodic_ball(&mut self, index: u32) {
        if let Some(periodic) = &mut self.periodic {
            let i = index as usize;
            if periodic.images.len() <= i {
                periodic.images.resize(i + 1, [0, 0]);
            }
            periodic.images[i] = [0, 0];
            periodic.wraps.remove(&index);
        }
    }

    /// At ball `index`'s crossing at `time`, in a periodic box: if it leaves through an edge,
    /// wraps it there ([`Self::wrap`]) and predicts it afresh. Returns whether it wrapped.
    pub(crate) fn wrap_at_crossing(&mut self, index: u32, time: Time) -> bool {
        if !self.wrap(index, time) {
            return false;
        }
        self.schedule(index);
        true
    }

    /// Ball `index`, about to be predicted now: if it is on an edge and moving out (placed
    /// there, or left there by an event's rounding), it wraps now, so that its cell's box,
    /// whose edge side is the edge itself, holds it strictly (a centre on that side, moving
    /// out, would otherwise leave unseen: its exit there is at the very start of the path).
    pub(crate) fn wrap_now(&mut self, index: u32) {
        // A ball registered in a cell inside the box is inside it (its cell's box holds it).
        if self.grid.on_torus_edge(index) {
            let time = self.time;
            self.wrap(index, time);
        }
    }

    /// If ball `index` leaves the box through an edge at `time`, or is a hair past one
    /// moving in (see [`Torus::wrap`]): moves
    /// the clock to `time` (a crossing is otherwise handled without moving it: it changes no
    /// path, but a wrap does, and every event before it has been handled), restates the
    /// ball's path there, moved into the box, counts the image and registers it in its new
    /// cell. Its partners' predictions against the old path are out of date (its version is
    /// bumped); the caller predicts it. Returns whether it wrapped.
    fn wrap(&mut self, index: u32, time: Time) -> bool {
        let Some(torus) = self.grid.torus().copied() else {
            return false;
        };
        if !matches!(self.grid.place(index), Place::Cell(..)) {
            return false;
        }
        let acceleration = self.acceleration(index);
        let record = self.balls.kinematics(index).expect("live ball");
        let restated = record.trajectory.rebased(time, acceleration);
        let (p, k) = torus.wrap(restated.p0, restated.v0);
        if k == [0, 0] && p == restated.p0 {
            return false;
        }
        self.time = self.time.max(time);
        let origin = record.trajectory.t0;
        let record = self.balls.kinematics_mut(index).expect("live ball");
        record.trajectory = restated;
        record.trajectory.p0 = p;
        self.balls.clear_residual(index);
        if let Some(periodic) = self.periodic.as_mut().filter(|_| k != [0, 0]) {
            let images = &mut periodic.images[index as usize];
            images[0] += i64::from(k[0]);
            images[1] += i64::from(k[1]);
            // A path that itself began at a wrap keeps the event before that one.
            let event = match periodic.wraps.get(&index) {
                Some(&(at, before)) if at == origin => before,
                _ => origin,
            };
            periodic.wraps.insert(index, (time, event));
            periodic.wrap_order.push_back((time, index));
            self.forget_wraps();
        }
        let place = self.grid.place_of(p);
        self.register_in_grid(index, place);
        self.balls.bump_version(index);
        true
    }

    /// Whether ball `index`'s last event was recent (`World::recent`): its path's origin
    /// `origin`, unless that was a wrap, whose record then gives the event before it.
    ///
    /// A wrap's record is looked up only if the origin lies within twice the rule's window
    /// of now (the collapse time, or [`COLLAPSE_FLOOR`] of the clock), or not before now:
    /// the rule calls an event recent only if it lies within the window, and an event
    /// before a wrap lies further back than the wrap, so if the wrap is not within the
    /// window neither is the event (the factor of two covers the roundings of `since`). So
    /// the answer is the one a record of every ball's last wrap gives.
    #[inline]
    pub(crate) fn last_event_recent(&self, index: u32, origin: Time) -> bool {
        let Some(periodic) = &self.periodic else {
            return self.recent(origin);
        };
        let since = self.time.since(origin);
        let floor = COLLAPSE_FLOOR * self.time.seconds().abs();
        if since > 0.0 && since >= 2.0 * self.collapse_time && since >= 2.0 * floor {
            return false;
        }
        let last = match periodic.wraps.get(&index) {
            Some(&(at, before)) if at == origin => before,
            _ => origin,
        };
        self.recent(last)
    }

    /// Looks at the oldest four records of wraps (a wrap adds one): forgets those whose slot
    /// wrapped again since, or whose ball's path has changed since (an event, or the ball
    /// removed), and moves those still standing to the back. So the records are the wraps
    /// still standing, and at most about a third as many again waiting to be looked at.
    fn forget_wraps(&mut self) {
        const LOOKS: usize = 4;
        let Some(periodic) = self.periodic.as_mut() else {
            return;
        };
        for _ in 0..LOOKS {
            let Some((at, slot)) = periodic.wrap_order.pop_front() else {
                return;
            };
            let Some(&(last, _)) = periodic.wraps.get(&slot) else {
                continue;
            };
            if last != at {
                continue;
            }
            let standing = self
                .balls
                .kinematics(slot)
                .is_some_and(|k| k.trajectory.t0 == at);
            if standing {
                periodic.wrap_order.push_back((at, slot));
            } else {
                periodic.wraps.remove(&slot);
            }
        }
    }

    /// `q` (a position of a ball that touches or is near the ball at `p`) at its image
    /// nearest `p`: `q` itself without a periodic box.
    #[inline]
    pub(crate) fn image_near(&self, p: DVec2, q: DVec2) -> DVec2 {
        match self.grid.torus() {
            None => q,
            Some(torus) => q + torus.nearest_shift(q - p),
        }
    }
}

/// Whether `shape`, grown by `radius`, lies strictly inside the box.
fn check_clear(torus: &Torus, shape: &Shape, radius: f64) -> Result<(), WorldError> {
    let (min, max) = shape.aabb();
    let clearance = min.min_element().min((torus.size - max).min_element());
    if clearance > radius {
        Ok(())
    } else {
        Err(WorldError::NearPeriodicEdge { clearance, radius })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::BallDesc;

    #[test]
    fn the_records_of_wraps_are_those_still_standing_and_few_waiting() {
        // 400 disks at packing 0.3, some 27 collisions a ball: the records kept are the wraps
        // still standing (their balls' paths' origins) and at most as many again waiting to
        // be looked at; and balls' paths do begin at recorded wraps. (That a collision finds
        // the record it needs is checked from outside in `tests/periodic.rs`.)
        let (n, side) = (20_u32, 20.0);
        let radius = (0.3 * side * side / (f64::from(n * n) * std::f64::consts::PI)).sqrt();
        let mut world = World::new();
        world.set_periodic(DVec2::splat(side)).unwrap();
        let mut handles = Vec::new();
        for k in 0..n * n {
            let p = DVec2::new(f64::from(k % n) + 0.5, f64::from(k / n) + 0.5);
            let angle = f64::from(k) * 2.399_963;
            let u = DVec2::new(angle.cos(), angle.sin());
            handles.push(
                world
                    .add_ball(BallDesc::new(p, radius).velocity(u))
                    .unwrap(),
            );
        }
        let mut wrapped_origins = 0;
        for round in 1..=20 {
            world.advance_to(f64::from(round)).unwrap();
            let periodic = world.periodic.as_ref().unwrap();
            let standing = periodic
                .wraps
                .iter()
                .filter(|&(&slot, &(at, _))| {
                    world.balls.kinematics(slot).unwrap().trajectory.t0 == at
                })
                .count();
            assert!(
                periodic.wrap_order.len() <= 2 * standing + 8,
                "{} records waiting, {standing} standing",
                periodic.wrap_order.len()
            );
            assert!(periodic.wraps.len() <= periodic.wrap_order.len());
            for h in &handles {
                let t0 = world.balls.kinematics(h.index).unwrap().trajectory.t0;
                let at_wrap = periodic
                    .wraps
                    .get(&h.index)
                    .is_some_and(|&(at, _)| at == t0);
                wrapped_origins += usize::from(at_wrap);
            }
        }
        assert!(world.event_counts().collisions() > 10_000);
        assert!(wrapped_origins > 20, "{wrapped_origins}");
    }
}
