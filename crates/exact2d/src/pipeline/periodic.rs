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

use glam::DVec2;

use super::World;
use super::error::WorldError;
use crate::broad::{Place, Torus};
use crate::dynamics::{BallHandle, Time};
use crate::geometry::Shape;

/// What a periodic world keeps beside the ball grid's [`Torus`]: each slot's images.
#[derive(Clone, Debug, Default)]
pub(crate) struct Periodic {
    /// The images ball `i` has moved through (its unwrapped position is its position plus
    /// these times the box's sides).
    images: Vec<[i64; 2]>,
    /// When ball `i` last wrapped, and the origin of its path before the wraps that led to
    /// it (its last event): a wrap restates a path but is no event of the ball's, and the
    /// TC model's rule (a collision soon after a ball's previous event is elastic) must not
    /// count it.
    wrapped: Vec<(Time, Time)>,
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
            let _ = periodic.wrapped.try_reserve_exact(more);
        }
    }

    /// Notes a new ball in slot `index` (no images yet).
    pub(crate) fn note_periodic_ball(&mut self, index: u32) {
        if let Some(periodic) = &mut self.periodic {
            let i = index as usize;
            if periodic.images.len() <= i {
                periodic.images.resize(i + 1, [0, 0]);
                periodic.wrapped.resize(i + 1, (NEVER, NEVER));
            }
            periodic.images[i] = [0, 0];
            periodic.wrapped[i] = (NEVER, NEVER);
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
        if let Some(periodic) = self.periodic.as_mut().filter(|_| k != [0, 0]) {
            let i = index as usize;
            let images = &mut periodic.images[i];
            images[0] += i64::from(k[0]);
            images[1] += i64::from(k[1]);
            let (at, before) = periodic.wrapped[i];
            // A path that itself began at a wrap keeps the event before that one.
            let event = if origin == at { before } else { origin };
            periodic.wrapped[i] = (time, event);
        }
        let place = self.grid.place_of(p);
        self.register_in_grid(index, place);
        self.balls.bump_version(index);
        true
    }

    /// The time of ball `index`'s last event, its path's origin `origin` unless that was a
    /// wrap (see [`Periodic::wrapped`]).
    #[inline]
    pub(crate) fn last_event(&self, index: u32, origin: Time) -> Time {
        match &self.periodic {
            None => origin,
            Some(periodic) => match periodic.wrapped.get(index as usize) {
                Some(&(at, before)) if at == origin => before,
                _ => origin,
            },
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

/// No wrap yet: a time no path begins at.
const NEVER: Time = Time::new(f64::NEG_INFINITY);

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
