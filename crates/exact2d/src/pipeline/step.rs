//! The event loop: take the earliest live prediction, move the bodies involved to its time,
//! respond, predict them again.
//!
//! ```text
//! loop:
//!     entry = earliest entry in the queue (stop if it is later than the target time)
//!     crossing (its ball leaves its broad-phase cell)   -> move the ball to its new cell and
//!                                                          add its new neighbours' candidates
//!     outdated (its partner changed, or was removed)    -> predict its ball again
//!     live                                              -> clock = entry.time;
//!                                                          restate the balls at that time,
//!                                                          respond, predict them again,
//!                                                          hand the event to the caller
//! ```
//!
//! Only the balls involved are touched; every other ball keeps its closed-form trajectory, so
//! advancing the clock is free and frame boundaries never change a result.

use super::event::{BallContactEvent, ContactEvent, Event, SensorEvent};
use super::pending::{Entry, Kind};
use super::{World, WorldError};
use glam::DVec2;

use crate::dynamics::{
    Next, SETTLE_HEIGHT, Support, Time, Touch, rebound, rebound_backed, reflect,
};
use crate::geometry::{ColliderHandle, Feature, Segment, Shape};

enum Status {
    Crossing,
    Outdated,
    Live,
}

impl Kind {
    /// Whether events of this kind are handled inside the loop, not returned to the caller.
    fn is_internal(self) -> bool {
        matches!(self, Kind::Settle | Kind::Leave | Kind::Crossing)
    }
}

impl World {
    /// Handles the next event if it happens at or before `until`, and returns it; otherwise
    /// moves the clock to `until` and returns `None`.
    ///
    /// This is the primitive the others are built on. A caller that reacts to events (removes a
    /// brick that reached zero hit points, adds a ball) does so between two calls, and the world
    /// goes on from the changed state.
    ///
    /// Several events at the same time are handled one per call, in the total order (time,
    /// kind, slot indices); with `until` infinite and no event left, the clock stays put.
    ///
    /// # Errors
    /// [`WorldError::TimeBeforeNow`] if `until` is before the current time or NaN.
    pub fn step_until(&mut self, until: f64) -> Result<Option<Event>, WorldError> {
        if !(until >= self.time.seconds()) {
            return Err(WorldError::TimeBeforeNow {
                requested: until,
                now: self.time.seconds(),
            });
        }
        let until = Time::new(until);
        while let Some(entry) = self.peek_live(until) {
            // Applying the event predicts its balls again, which replaces the entry.
            self.time = self.time.max(entry.key.time);
            match entry.key.kind {
                Kind::Settle => self.apply_settle(entry),
                Kind::Leave => self.apply_leave(entry),
                _ => return Ok(Some(self.apply(entry))),
            }
        }
        if until.seconds().is_finite() {
            self.time = self.time.max(until);
        }
        Ok(None)
    }

    /// Handles the next event, whenever it is, and returns it; `None` if no event will ever
    /// happen (the clock then stays put).
    pub fn step(&mut self) -> Option<Event> {
        self.step_until(f64::INFINITY).unwrap_or(None)
    }

    /// Handles every event up to and including time `t`, then leaves every body exactly at `t`.
    /// Returns the number of events handled. A renderer calls this once per frame.
    ///
    /// # Errors
    /// [`WorldError::TimeBeforeNow`] if `t` is before the current time or NaN.
    pub fn advance_to(&mut self, t: f64) -> Result<u64, WorldError> {
        let mut handled = 0;
        while self.step_until(t)?.is_some() {
            handled += 1;
        }
        Ok(handled)
    }

    /// [`advance_to`](Self::advance_to), appending every event handled to `events`.
    ///
    /// # Errors
    /// As [`advance_to`](Self::advance_to).
    pub fn advance_to_collect(
        &mut self,
        t: f64,
        events: &mut Vec<Event>,
    ) -> Result<u64, WorldError> {
        let before = events.len();
        while let Some(event) = self.step_until(t)? {
            events.push(event);
        }
        Ok((events.len() - before) as u64)
    }

    /// The time of the next event or internal change (a ball settling on a collider or
    /// reaching the end of its support), if any (handling cell crossings and outdated
    /// predictions on the way).
    pub fn next_event_time(&mut self) -> Option<f64> {
        self.peek_live(Time::new(f64::INFINITY))
            .map(|entry| entry.key.time.seconds())
    }

    /// The earliest live entry at or before `until`, left on the queue. Cell crossings above
    /// it are handled; outdated entries are replaced by predicting their balls again. Entries
    /// after `until` are not touched: an outdated entry is re-predicted only when it comes due,
    /// since its ball's partner often changes again before then and early work would be wasted.
    fn peek_live(&mut self, until: Time) -> Option<Entry> {
        while let Some(entry) = self.queue.peek() {
            if entry.key.time > until {
                return None;
            }
            match self.status(&entry) {
                Status::Live => return Some(entry),
                Status::Crossing => self.cross(entry.owner, entry.key.time),
                Status::Outdated => self.schedule(entry.owner),
            }
        }
        None
    }

    fn status(&self, entry: &Entry) -> Status {
        let partner = entry.partner();
        let partner_live = match entry.key.kind {
            Kind::BallContact => self.balls.is_current(partner, entry.partner_tag),
            Kind::Contact | Kind::Sensor | Kind::Settle | Kind::Leave => {
                self.colliders.is_live(partner, entry.partner_tag)
            }
            Kind::Crossing => return Status::Crossing,
        };
        if partner_live {
            Status::Live
        } else {
            Status::Outdated
        }
    }

    fn apply(&mut self, entry: Entry) -> Event {
        self.time = self.time.max(entry.key.time);
        match entry.key.kind {
            Kind::Contact => self.apply_contact(entry),
            Kind::BallContact => self.apply_ball_contact(entry),
            Kind::Sensor => self.apply_sensor(entry),
            kind => {
                debug_assert!(kind.is_internal());
                unreachable!("internal events are handled before they reach `apply`")
            }
        }
    }

    fn apply_contact(&mut self, entry: Entry) -> Event {
        let (index, time, gravity) = (entry.owner, self.time, self.gravity);
        let handle = ColliderHandle {
            index: entry.key.second,
            generation: entry.partner_tag,
        };
        let collider = *self.colliders.get(handle).expect("live collider");
        let feature = feature_from_rank(entry.key.feature);
        let (_, restitution) = self.balls.mass_and_restitution(index).expect("live ball");
        let acceleration = self.balls.acceleration(index, gravity);
        let ball = self.balls.kinematics_mut(index).expect("live ball");
        let last = ball.trajectory.t0;
        ball.trajectory = ball.trajectory.rebased(time, acceleration);
        let (p, v) = (ball.trajectory.p0, ball.trajectory.v0);
        let (n, point) = collider.shape.contact(feature, p);
        let restitution = if self.recent(last) {
            1.0
        } else {
            restitution * collider.restitution
        };
        let mut v2 = reflect(v, n, restitution);
        // An approach so slow against the speed that rounding ate the whole impulse would be
        // found again at once, forever: the smallest impulse the velocity can hold instead.
        let mut extra = f64::EPSILON * v.length();
        let unit = n.normalize_or_zero();
        while v2.dot(n) < 0.0 && extra.is_finite() && extra > 0.0 {
            v2 += unit * extra;
            extra *= 2.0;
        }
        let ball = self.balls.kinematics_mut(index).expect("live ball");
        ball.trajectory.v0 = v2;
        if self.balls.is_supported(index) {
            // Knocked off its support; it settles again if it still rests there.
            self.balls.set_support(index, None);
        }
        let normal = n.normalize_or_zero();
        self.counts.contacts += 1;
        let event = ContactEvent {
            time: time.seconds(),
            ball: self.balls.handle(index),
            collider: handle,
            feature,
            point,
            normal,
            normal_speed: (-v.dot(normal)).max(0.0),
        };
        self.trajectory_changed(index);
        Event::Contact(event)
    }

    fn apply_ball_contact(&mut self, entry: Entry) -> Event {
        let (i, j, time, gravity) = (entry.key.first, entry.key.second, self.time, self.gravity);
        let restate = |world: &mut World, index: u32| {
            let (mass, restitution) = world.balls.mass_and_restitution(index).expect("live ball");
            let acceleration = world.balls.acceleration(index, gravity);
            let ball = world.balls.kinematics_mut(index).expect("live ball");
            let last = ball.trajectory.t0;
            ball.trajectory = ball.trajectory.rebased(time, acceleration);
            let state = (
                ball.trajectory.p0,
                ball.trajectory.v0,
                acceleration,
                ball.radius,
            );
            (state, mass, restitution, last)
        };
        let ((pi, vi, ai, ri), mi, ei, last_i) = restate(self, i);
        let ((pj, vj, aj, rj), mj, ej, last_j) = restate(self, j);
        let n = pj - pi;
        let mut restitution = ei * ej;
        if self.recent(last_i) || self.recent(last_j) {
            restitution = 1.0;
        }
        // A ball of an inelastic zero-time chain that the impulse would push into a wall it
        // touches is backed by the wall: both contacts are resolved at once. So is a ball
        // resting on a floor that a micro-hop collision pushes into it.
        let floor = hop_floor(pi, vi, ai, pj, vj, aj, ri + rj);
        let backed = if restitution < 1.0 || floor.is_some() {
            let time = self.time;
            let backing = |world: &World, index: u32, last: Time, p: DVec2, r: f64, push: DVec2| {
                (last == time || floor.is_some())
                    .then(|| world.backing_wall(index, p, r, push))
                    .flatten()
            };
            match backing(self, i, last_i, pi, ri, -n) {
                Some(w) => Some((true, w)),
                None => backing(self, j, last_j, pj, rj, n).map(|w| (false, w)),
            }
        } else {
            None
        };
        let floor = floor.unwrap_or(0.0);
        let (mut vi2, mut vj2) = match backed {
            Some((true, w)) => rebound_backed(vi, mi, vj, mj, n, restitution, floor, w),
            Some((false, w)) => {
                let (vj2, vi2) = rebound_backed(vj, mj, vi, mi, -n, restitution, floor, w);
                (vi2, vj2)
            }
            None => rebound(vi, mi, vj, mj, n, restitution, floor),
        };
        // As for a collider: if rounding ate the impulse, the smallest one that holds.
        let mut extra = f64::EPSILON * vi.length().max(vj.length());
        let unit = n.normalize_or_zero();
        let total = mi + mj;
        while n.dot(vj2 - vi2) < 0.0 && extra.is_finite() && extra > 0.0 {
            vi2 -= unit * (extra * (mj / total));
            vj2 += unit * (extra * (mi / total));
            extra *= 2.0;
        }
        self.balls.kinematics_mut(i).expect("live").trajectory.v0 = vi2;
        self.balls.kinematics_mut(j).expect("live").trajectory.v0 = vj2;
        for index in [i, j] {
            if self.balls.is_supported(index) {
                self.balls.set_support(index, None);
            }
        }
        let normal = n.normalize_or_zero();
        self.counts.ball_contacts += 1;
        let event = BallContactEvent {
            time: time.seconds(),
            a: self.balls.handle(i),
            b: self.balls.handle(j),
            point: pi + normal * ri,
            normal,
            normal_speed: (vi - vj).dot(normal).max(0.0),
        };
        // Both balls' partners learn of both changes before either is predicted again, so
        // neither prediction is outdated at birth.
        self.balls.bump_version(i);
        self.balls.bump_version(j);
        self.schedule(i);
        self.schedule(j);
        Event::BallContact(event)
    }

    fn apply_sensor(&mut self, entry: Entry) -> Event {
        let (index, time, gravity) = (entry.owner, self.time, self.gravity);
        let handle = ColliderHandle {
            index: entry.key.second,
            generation: entry.partner_tag,
        };
        let ball_handle = self.balls.handle(index);
        let acceleration = self.balls.acceleration(index, gravity);
        let ball = self.balls.kinematics_mut(index).expect("live ball");
        // Restating the trajectory at the crossing makes the next search start there, so the
        // crossing just handled is not found again.
        ball.trajectory = ball.trajectory.rebased(time, acceleration);
        let position = ball.trajectory.p0;
        let sensors = &mut self.balls.properties_mut(index).expect("live ball").extra;
        let entered = !sensors.remove(handle);
        if entered {
            sensors.push(handle);
        }
        let event = SensorEvent {
            time: time.seconds(),
            ball: ball_handle,
            collider: handle,
            feature: feature_from_rank(entry.key.feature),
            position,
        };
        self.trajectory_changed(index);
        if entered {
            self.counts.sensor_enters += 1;
            Event::SensorEnter(event)
        } else {
            self.counts.sensor_exits += 1;
            Event::SensorExit(event)
        }
    }
}

impl World {
    /// Ball `entry.owner` rests on collider `entry.key.second` (see [`Touch::holds`]): it
    /// keeps only its velocity along the surface and slides on it (or pivots on a point, or,
    /// held by two surfaces that each push it into the other, stays put).
    fn apply_settle(&mut self, entry: Entry) {
        let (index, time, gravity) = (entry.owner, self.time, self.gravity);
        let handle = ColliderHandle {
            index: entry.key.second,
            generation: entry.partner_tag,
        };
        let collider = *self.colliders.get(handle).expect("live collider");
        let acceleration = self.balls.acceleration(index, gravity);
        let old = if self.balls.is_supported(index) {
            self.balls
                .properties(index)
                .and_then(|p| p.extra.support().copied())
        } else {
            None
        };
        let ball = self.balls.kinematics_mut(index).expect("live ball");
        ball.trajectory = ball.trajectory.rebased(time, acceleration);
        let (p, v, radius) = (ball.trajectory.p0, ball.trajectory.v0, ball.radius);
        let Some(touch) = Touch::of(&collider.shape, p, radius) else {
            self.schedule(index);
            return;
        };
        let mut support = match (&collider.shape, touch.point) {
            (Shape::Segment(s), None) => self.segment_support(index, handle, s, touch.normal, p),
            (shape, Some(point)) => {
                let other_end = match (shape, touch.feature) {
                    (Shape::Segment(s), Feature::SegmentEndA) => Some(s.b()),
                    (Shape::Segment(s), Feature::SegmentEndB) => Some(s.a()),
                    _ => None,
                };
                Support::pivot(
                    handle,
                    touch.feature,
                    point,
                    touch.normal,
                    other_end,
                    None,
                    gravity,
                )
            }
            (Shape::Circle(_), None) => unreachable!("a circle is touched at a point"),
        };
        if let Some(old) = old {
            // It was sliding on `old` into this surface: if this one pulls it back into `old`,
            // each holds it against the other.
            let crossed = old.normal.perp_dot(touch.normal).abs() > PARALLEL;
            if crossed && support.acceleration.dot(old.normal) < 0.0 {
                support.wedge = Some(old.collider);
                support.acceleration = DVec2::ZERO;
            }
        }
        let (p, v) = support.restrict(p, v);
        let ball = self.balls.kinematics_mut(index).expect("live ball");
        (ball.trajectory.p0, ball.trajectory.v0) = (p, v);
        self.balls.set_support(index, Some(support));
        self.counts.settles += 1;
        self.schedule(index);
    }

    /// Supported ball `entry.owner` reaches the end of its support: off a segment's end it
    /// flies, or pivots on the end point if its free flight would cut into it; at a corner of
    /// a pivot's polygon it turns onto the next edge unless its free flight clears the point.
    fn apply_leave(&mut self, entry: Entry) {
        let (index, time, gravity) = (entry.owner, self.time, self.gravity);
        let support = self
            .balls
            .properties(index)
            .and_then(|p| p.extra.support().copied());
        let Some(support) = support.filter(|_| self.balls.is_supported(index)) else {
            self.schedule(index);
            return;
        };
        let ball = self.balls.kinematics_mut(index).expect("live ball");
        let before = ball.trajectory.p0;
        ball.trajectory = ball.trajectory.rebased(time, support.acceleration);
        let progressed = ball.trajectory.p0 != before;
        let (p, v, radius) = (ball.trajectory.p0, ball.trajectory.v0, ball.radius);
        let s = support.coordinate(p);
        let forwards = s > 0.5 * (support.lo + support.hi);
        let tangent = support.normal.perp();
        // Leave times are rounded: a centre that is not past the end yet goes on to the next
        // representable time that is (moving on at all), so that a ball flying off is never
        // found sinking into the surface it left by a rounding error.
        let inside = if forwards {
            s < support.hi
        } else {
            s > support.lo
        };
        if inside && progressed {
            self.schedule(index);
            return;
        }
        let joined = support
            .next
            .filter(|n| n.joins && n.forwards == forwards && support.pivot.is_some());
        let onto = |world: &World, n: Next| Support {
            from: Some(support.collider),
            ..world.segment_support(index, n.collider, &n.segment, n.normal, p)
        };
        let next = match (support.pivot, joined) {
            (_, Some(n)) => Some(onto(self, n)),
            (None, None) => {
                let collider = self.colliders.get(support.collider).copied();
                match collider.map(|c| c.shape) {
                    Some(Shape::Segment(s)) => {
                        let b_ahead = (s.b() - s.a()).dot(tangent) > 0.0;
                        let ((end, feature), other) = if b_ahead == forwards {
                            ((s.b(), Feature::SegmentEndB), s.a())
                        } else {
                            ((s.a(), Feature::SegmentEndA), s.b())
                        };
                        let after = self.next_segment(index, support.collider, end, other, p);
                        let next = after.map(|(handle, s, normal)| Next {
                            collider: handle,
                            segment: s,
                            normal,
                            forwards,
                            joins: false,
                        });
                        // Flying off would cut into the end point: the centre must turn
                        // faster than gravity's normal pull allows.
                        let cuts = v.length_squared() + (p - end).dot(gravity) < 0.0;
                        let ahead = if forwards {
                            tangent
                        } else {
                            DVec2::ZERO - tangent
                        };
                        match next {
                            // Straight on (within `PARALLEL`; a segment turning up would have
                            // been hit before the end): it slides onto it now.
                            Some(n) if n.normal.dot(ahead) <= PARALLEL => Some(onto(self, n)),
                            next if cuts => Some(Support::pivot(
                                support.collider,
                                feature,
                                (end, radius),
                                support.normal,
                                Some(other),
                                next,
                                gravity,
                            )),
                            _ => None,
                        }
                    }
                    _ => None,
                }
            }
            (Some((point, _)), None) => {
                // The same test at a corner of the polygon: the arc through it would need more
                // normal pull than gravity gives (the normal force would be negative).
                if v.length_squared() + (p - point).dot(gravity) < 0.0 {
                    support.turned(forwards, gravity)
                } else {
                    None
                }
            }
        };
        if let Some(next) = next {
            let speed = v.dot(tangent) * next.normal.perp().dot(tangent).signum();
            let ball = self.balls.kinematics_mut(index).expect("live ball");
            ball.trajectory.v0 = next.normal.perp() * speed;
        }
        self.balls.set_support(index, next);
        self.counts.leaves += 1;
        self.schedule(index);
    }
}

/// Below this sine of the angle between them, two supporting surfaces count as parallel.
const PARALLEL: f64 = 1e-9;

/// Collisions of a ball closer than this fraction of the clock after its previous event
/// (`2^-40`, about a picosecond at t = 1 s) are elastic whatever the collapse time, except at
/// the very same instant (simultaneous impacts stay as they are): the TC model's remedy at the
/// clock's own scale. Without it, inelastic collapse (a cluster of balls, or a ball in a
/// cusp, colliding infinitely often in a finite time) would go on until collisions came closer
/// than the clock resolves ([`RESOLUTION`](crate::RESOLUTION), `2^-100`), were dropped, and
/// the balls sank into each other.
pub const COLLAPSE_FLOOR: f64 = 9.094_947_017_729_282e-13;

/// The smallest hop, as a fraction of the coordinate scale, that a collision leaves two balls
/// pulled together: `2^-30`, the order of [`OVERLAP_TOLERANCE`](crate::OVERLAP_TOLERANCE).
///
/// A ball bouncing on a ball that rests on a floor (balls are never supported by balls)
/// would make inelastic hops that shrink below the rounding of their gap, and the two would
/// sink into each other. Instead a collision never leaves such a pair a smaller hop, and a
/// touching pair that hops less collides at once: the top ball jitters by this fraction of the
/// scale, invisibly, at a bounded energy, with no overlap.
pub const MICRO_HOP: f64 = 9.313_225_746_154_785e-10;

/// For balls at `pi`, `pj` (velocities `vi`, `vj`, accelerations `ai`, `aj`, contact
/// distance `reach`) that their relative acceleration, with the curvature of their relative
/// path, pulls together, the separation speed that makes them hop [`MICRO_HOP`] of the
/// coordinate scale apart; `None` if nothing pulls them together.
///
/// This is a ball bouncing on a ball that rests on a floor (a ball is never *supported* by a
/// ball). Its inelastic hops would shrink below the rounding of the gap, and the two would sink
/// into each other; instead a collision never leaves them a smaller hop than this, and a
/// touching pair that hops less collides at once and gets it. The top ball then jitters by
/// `MICRO_HOP` of the scale, invisibly, at a bounded energy, with no overlap.
pub(crate) fn hop_floor(
    pi: DVec2,
    vi: DVec2,
    ai: DVec2,
    pj: DVec2,
    vj: DVec2,
    aj: DVec2,
    reach: f64,
) -> Option<f64> {
    if ai == aj {
        // Same acceleration: their relative path is straight, and a contact is never lost.
        return None;
    }
    let d = pj - pi;
    let length = d.length();
    if !(length > 0.0) {
        return None;
    }
    let n = d / length;
    let v = vj - vi;
    let tangential = v - n * v.dot(n);
    let pull = (aj - ai).dot(n) + tangential.length_squared() / length;
    if !(pull < 0.0) {
        return None;
    }
    let scale = pi.abs().max_element().max(pj.abs().max_element()) + reach;
    Some((2.0 * -pull * MICRO_HOP * scale).sqrt())
}

impl World {
    /// Whether a ball whose previous event was at `last` collides again within the world's
    /// collapse time (see [`World::set_collapse_time`]), or a positive time shorter than
    /// [`COLLAPSE_FLOOR`] of the clock: the collision is then elastic.
    fn recent(&self, last: Time) -> bool {
        let since = self.time.since(last);
        since < self.collapse_time
            || (since > 0.0 && since < COLLAPSE_FLOOR * self.time.seconds().abs())
    }

    /// The unit normal of a solid collider that ball `index` (centre `p`, radius `r`) touches
    /// (within [`SETTLE_HEIGHT`]) and that an impulse along `push` would drive it into (the
    /// most directly), if any.
    fn backing_wall(&self, index: u32, p: DVec2, r: f64, push: DVec2) -> Option<DVec2> {
        let groups = self.balls.properties(index)?.groups;
        let near = SETTLE_HEIGHT * (p.abs().max_element() + r);
        let push = push.normalize_or_zero();
        let mut best: Option<(f64, DVec2)> = None;
        self.statics.near_point(p, |slot| {
            let Some((_, collider)) = self.colliders.at(slot) else {
                return;
            };
            if collider.sensor || !collider.groups.interact(groups) {
                return;
            }
            let Some(touch) = Touch::of(&collider.shape, p, r) else {
                return;
            };
            let into = push.dot(touch.normal);
            if touch.gap.abs() <= near && into < 0.0 && best.is_none_or(|b| into < b.0) {
                best = Some((into, touch.normal));
            }
        });
        best.map(|(_, normal)| normal)
    }

    /// Ball `index` (centre `p`) sliding on segment `handle`, on the side of `normal`, with
    /// the segments going on straight or turning away from its ends.
    fn segment_support(
        &self,
        index: u32,
        handle: ColliderHandle,
        s: &Segment,
        normal: DVec2,
        p: DVec2,
    ) -> Support {
        let radius = self.balls.kinematics(index).expect("live ball").radius;
        let mut support = Support::on_segment(handle, s.a(), s.b(), normal, radius, self.gravity);
        for (k, (end, other)) in [(s.a(), s.b()), (s.b(), s.a())].into_iter().enumerate() {
            let ahead = (end - other).normalize_or_zero();
            support.ends[k] = self
                .next_segment(index, handle, end, other, p)
                .filter(|(_, _, n)| n.dot(ahead) >= -PARALLEL)
                .map(|(h, _, _)| h);
        }
        support
    }

    /// The solid segment that goes on from `end` of segment `from` (whose other end is
    /// `other`), for ball `index` at `p`: one with an end point within [`SETTLE_HEIGHT`] of
    /// `end` that leads away from `other`, seen from the ball's side (its normal facing the
    /// ball), turning least from the way `from` went; with that normal.
    fn next_segment(
        &self,
        index: u32,
        from: ColliderHandle,
        end: DVec2,
        other: DVec2,
        p: DVec2,
    ) -> Option<(ColliderHandle, Segment, DVec2)> {
        let groups = self.balls.properties(index)?.groups;
        let near = SETTLE_HEIGHT * (end.abs().max_element() + (p - end).length());
        let way = (end - other).normalize_or_zero();
        let mut best: Option<(f64, ColliderHandle, Segment, DVec2)> = None;
        self.statics.near_point(end, |slot| {
            let Some((handle, collider)) = self.colliders.at(slot) else {
                return;
            };
            let Shape::Segment(s) = collider.shape else {
                return;
            };
            if handle == from || collider.sensor || !collider.groups.interact(groups) {
                return;
            }
            let far = if (s.a() - end).length() <= near {
                s.b()
            } else if (s.b() - end).length() <= near {
                s.a()
            } else {
                return;
            };
            let along = (far - end).normalize_or_zero();
            let normal = if s.signed_distance(p) >= 0.0 {
                s.normal()
            } else {
                DVec2::ZERO - s.normal()
            };
            let straightness = along.dot(way);
            if straightness > 0.0 && best.is_none_or(|b| straightness > b.0) {
                best = Some((straightness, handle, s, normal));
            }
        });
        best.map(|(_, handle, s, normal)| (handle, s, normal))
    }
}

fn feature_from_rank(rank: u8) -> Feature {
    match rank {
        0 => Feature::SegmentInterior,
        1 => Feature::SegmentEndA,
        2 => Feature::SegmentEndB,
        _ => Feature::Circle,
    }
}
