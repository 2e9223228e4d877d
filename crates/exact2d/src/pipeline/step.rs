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
use super::instant::Pair;
use super::observables::split;
use super::pending::{Entry, Kind};
use super::predict::SNAP_ULPS;
use super::{World, WorldError};
use glam::DVec2;

use crate::dynamics::{
    Hold, NO_COLLIDER, Next, PARALLEL, SETTLE_HEIGHT, Support, Time, Touch, rebound,
    rebound_backed, reflect, restated_bounce, sleep_speed,
};
use crate::geometry::{Collider, ColliderHandle, Feature, Segment, Shape};

/// What [`World::handle_next_until`] handled.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Handled {
    /// An event, the one [`World::step_until`] would return.
    Event(Event),
    /// An internal change, which `step_until` handles without returning: a ball settled on a
    /// collider, or reached the end of its support or of its phase on a table's cloth.
    /// [`EventCounts`](crate::EventCounts) counts it (a settle, leave or phase end) when it
    /// changed the ball, not when it only predicted it again (a leave whose rounded time found
    /// the centre short of the end).
    Internal,
    /// Nothing at or before the time asked for: the clock is there now (if it is finite).
    Nothing,
}

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
        // Each call checks `until` against the clock again; a change at or before `until`
        // never moves the clock past it, so the check passes, and these are the steps of one
        // loop over the queue.
        loop {
            match self.handle_next_until(until)? {
                Handled::Event(event) => return Ok(Some(event)),
                Handled::Internal => {}
                Handled::Nothing => return Ok(None),
            }
        }
    }

    /// [`step_until`](Self::step_until) one change at a time: handles the next event or
    /// internal change (a ball settling on a collider, reaching the end of its support or of
    /// its phase on a table's cloth) if it happens at or before `until`, and says which;
    /// otherwise moves the clock to `until` and returns [`Handled::Nothing`].
    ///
    /// `step_until` is this called until it returns an event or nothing, so the two take the
    /// very same steps, bit for bit. A caller that must see every change (a test harness that
    /// checks that the clock moves on, for which a run of internal changes inside one
    /// `step_until` would never return) calls this instead.
    ///
    /// # Errors
    /// As [`step_until`](Self::step_until).
    pub fn handle_next_until(&mut self, until: f64) -> Result<Handled, WorldError> {
        if !(until >= self.time.seconds()) {
            return Err(WorldError::TimeBeforeNow {
                requested: until,
                now: self.time.seconds(),
            });
        }
        let until = Time::new(until);
        let Some(entry) = self.peek_live(until) else {
            if until.seconds().is_finite() {
                self.time = self.time.max(until);
            }
            return Ok(Handled::Nothing);
        };
        // Applying the event predicts its balls again, which replaces the entry.
        self.time = self.time.max(entry.key.time);
        self.note_event(&entry)?;
        match entry.key.kind {
            Kind::Settle => self.apply_settle(entry),
            Kind::Leave => self.apply_leave(entry),
            _ => return Ok(Handled::Event(self.apply(entry))),
        }
        Ok(Handled::Internal)
    }

    /// Records an event at the current instant; a stall (more events at one instant than the
    /// zero-time chains allow, see [`STALL_EVENTS_PER_BALL`]) is an error naming its bodies.
    fn note_event(&mut self, entry: &Entry) -> Result<(), WorldError> {
        self.instant.at(self.time);
        self.instant.note_event(entry.owner);
        if entry.key.kind == Kind::BallContact {
            self.instant.note_event(entry.partner());
        }
        let (events, balls) = self.instant.events();
        if events <= STALL_EVENTS_PER_BALL * (balls as u64 + 1) {
            return Ok(());
        }
        let partner = entry.partner();
        let (ball, other_ball, collider) = match entry.key.kind {
            Kind::BallContact => (entry.owner, Some(self.balls.handle(partner)), None),
            _ => {
                let handle = self.colliders.at(partner).map(|(h, _)| h);
                (entry.owner, None, handle)
            }
        };
        Err(WorldError::Stalled {
            time: self.time.seconds(),
            events,
            ball: self.balls.handle(ball),
            other_ball,
            collider,
        })
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
            // A held ball's leave has no collider: its group lets go then, if still there.
            Kind::Leave if partner == NO_COLLIDER.index => true,
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
        if let Some(sleeper) = self.sleepers.ball_of(entry.key.second) {
            return self.apply_sleeper_contact(entry, sleeper);
        }
        let event = self.bounce_off_collider(entry);
        self.counts.contacts += 1;
        self.observables.impact(entry.key.second);
        Event::Contact(event)
    }

    /// Ball `entry.owner` bounces off collider `entry.key.second` now (uncounted).
    pub(crate) fn bounce_off_collider(&mut self, entry: Entry) -> ContactEvent {
        let (index, time, gravity) = (entry.owner, self.time, self.gravity);
        let handle = ColliderHandle {
            index: entry.key.second,
            generation: entry.partner_tag,
        };
        let collider = *self.colliders.get(handle).expect("live collider");
        let feature = feature_from_rank(entry.key.feature);
        let (_, restitution) = self.balls.mass_and_restitution(index).expect("live ball");
        let acceleration = self.balls.acceleration(index, gravity);
        let (last, ball) = self.balls.rebase(index, time, acceleration);
        let (p, v) = (ball.trajectory.p0, ball.trajectory.v0);
        let (n, point) = collider.shape.contact(feature, p);
        let normal = n.normalize_or_zero();
        let mut event = ContactEvent {
            time: time.seconds(),
            ball: self.balls.handle(index),
            collider: handle,
            feature,
            point,
            normal,
            normal_speed: (-v.dot(normal)).max(0.0),
            impulse: 0.0,
            tangential_impulse: 0.0,
        };
        let mass = self.balls.mass_and_restitution(index).expect("live ball").0;
        // On a table, a ball the cloth presses into the cushion it meets this slowly is held
        // against it at once (`World::hold_at_cushion`), as a ball settles on a floor.
        if let Some(v2) = self
            .table
            .and_then(|_| self.hold_at_cushion(index, v, (&collider.shape, feature), handle))
        {
            event.impulse = mass * (v2 - v).dot(normal);
            self.leave_with(index, v2);
            return event;
        }
        let pair = Pair::Collider(index, handle.index);
        let Some(response) = self.instant.respond(pair, [v, DVec2::ZERO]) else {
            self.resolve_jam(&[index]);
            event.impulse = mass * (self.velocity_now(index) - v).dot(normal);
            return event;
        };
        let recent = self.last_event_recent(index, last);
        // With sleeping on, a ball that meets a surface again within the collapse floor and no
        // faster than it sleeps is rattling in a gap too narrow for the clock (between two
        // sleeping balls, in an exact-fit channel): its touching contacts are resolved at
        // once, as a jam, rather than bounce elastically across the gap for ever.
        if recent && self.resting() {
            let radius = self.balls.kinematics(index).expect("live ball").radius;
            if event.normal_speed <= sleep_speed(gravity.length(), radius) {
                self.resolve_jam(&[index]);
                event.impulse = mass * (self.velocity_now(index) - v).dot(normal);
                return event;
            }
        }
        let restitution = if recent {
            1.0
        } else {
            restitution * collider.restitution
        };
        // A group takes the strike of one of its members on a surface as one body while every
        // contact it keeps pushes (`pipeline/rigid.rs`).
        if self.held_group(index).is_some() && event.normal_speed > 0.0 {
            let target = restitution * event.normal_speed;
            if let Some(v2) = self.hit_group_by_collider(index, handle.index, normal, target) {
                event.impulse = mass * (v2 - v).dot(normal);
                return event;
            }
        }
        let mut v2 = reflect(v, n, restitution);
        // An approach so slow against the speed that rounding ate the whole impulse would be
        // found again at once, forever: the smallest impulse the velocity can hold instead.
        let mut extra = f64::EPSILON * v.length();
        let unit = n.normalize_or_zero();
        while v2.dot(n) < 0.0 && extra.is_finite() && extra > 0.0 {
            v2 += unit * extra;
            extra *= 2.0;
        }
        // The bounce leaves from the restated position, a rounding off the exact contact
        // line: its normal speed is the one that carries the same energy from there.
        // (Without gravity nothing pulls a ball in: not even its radius is looked up.)
        if gravity != DVec2::ZERO {
            let radius = self.balls.kinematics(index).expect("live ball").radius;
            let rounding = SNAP_ULPS * f64::EPSILON * (p.abs().max_element() + radius);
            v2 = restated_bounce(v2, n, p - point, radius, gravity, rounding);
        }
        event.impulse = mass * (v2 - v).dot(normal);
        if !recent {
            let surface = collider.roughness();
            (v2, event.tangential_impulse) =
                self.rub_on_surface(index, v2, normal, event.impulse, surface);
        }
        // The observables: the collider's impulse, friction included.
        let (w, given) = self.take_from_collider(p, handle.index, (v2 - v) * mass);
        self.instant.note_response(response, w, given);
        if self.table.is_some() {
            v2 = self
                .hold_at_cushion(index, v2, (&collider.shape, feature), handle)
                .unwrap_or(v2);
        }
        self.leave_with(index, v2);
        event
    }

    /// Ball `index`, restated now, leaves a collider at `v`: knocked off its support if it
    /// has one (it settles again if it still rests there), and predicted again.
    fn leave_with(&mut self, index: u32, v: DVec2) {
        self.balls
            .kinematics_mut(index)
            .expect("live ball")
            .trajectory
            .v0 = v;
        if self.balls.is_supported(index) {
            self.set_support(index, None);
        }
        self.trajectory_changed(index);
    }

    fn apply_ball_contact(&mut self, entry: Entry) -> Event {
        self.collide_pair(entry.key.first, entry.key.second)
    }

    /// Balls `i < j` collide now.
    pub(crate) fn collide_pair(&mut self, i: u32, j: u32) -> Event {
        let (time, gravity) = (self.time, self.gravity);
        let restate = |world: &mut World, index: u32| {
            let (mass, restitution) = world.balls.mass_and_restitution(index).expect("live ball");
            let acceleration = world.balls.acceleration(index, gravity);
            let (last, ball) = world.balls.rebase(index, time, acceleration);
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
        // In a periodic box the two meet through their nearest images.
        let pj = self.image_near(pi, pj);
        let n = pj - pi;
        let normal = n.normalize_or_zero();
        self.counts.ball_contacts += 1;
        let mut event = BallContactEvent {
            time: time.seconds(),
            a: self.balls.handle(i),
            b: self.balls.handle(j),
            point: pi + normal * ri,
            normal,
            normal_speed: (vi - vj).dot(normal).max(0.0),
            impulse: 0.0,
            tangential_impulse: 0.0,
        };
        let pair = Pair::balls(i, j);
        let before = if i < j { [vi, vj] } else { [vj, vi] };
        let Some(response) = self.instant.respond(pair, before) else {
            self.resolve_jam(&[i, j]);
            event.impulse = mj * (self.velocity_now(j) - vj).dot(normal);
            return Event::BallContact(event);
        };
        let mut restitution = ei * ej;
        let recent = self.last_event_recent(i, last_i) || self.last_event_recent(j, last_j);
        if recent {
            restitution = 1.0;
        }
        // A pair pulled together (one of them supported) is never left a smaller hop than
        // the micro-hop floor, and the supported ball that such a collision drives into its
        // support is backed by it: both contacts are resolved at once (in sequence, a ball
        // resting on a floor would bounce off it at every hop of a ball above). Any other
        // wall a ball is driven into is met next, at this instant; should the chain come back
        // to a contact, it is a jam.
        let floor = hop_floor(pi, vi, ai, pj, vj, aj, ri + rj);
        // On a table, a pair the cloth presses together that would hop no higher than the
        // floor moves on as one (`World::join_on_table`), rather than micro-hop for ever.
        if let Some(f) = floor.filter(|_| self.table.is_some()) {
            if restitution * (vi - vj).dot(normal) <= f {
                let v = self.join_on_table(i, j);
                event.impulse = mj * (v - vj).dot(normal);
                return Event::BallContact(event);
            }
        }
        // With sleeping on, a pair pulled together that meets no faster than a ball sleeps
        // rests: its cluster is resolved at once, and the contacts that it leaves separating
        // no faster hold (a group, `pipeline/group.rs`), rather than micro-hop on each other
        // (see `ARCHITECTURE.md`, resting pairs).
        if floor.is_some()
            && self.resting()
            && (vi - vj).dot(normal) <= sleep_speed(gravity.length(), ri.min(rj))
        {
            self.resolve_jam(&[i, j]);
            event.impulse = mj * (self.velocity_now(j) - vj).dot(normal);
            return Event::BallContact(event);
        }
        // With sleeping on, a pair falling freely together (neither supported) that meets no
        // faster than a ball sleeps stops against each other: its bounce is dropped, as a
        // jam's resting contact's is, rather than ring on through the touching balls by ever
        // slower bounces (a poured gas clusters as it falls and lands as columns of touching
        // balls: ARCHITECTURE.md, resting pairs).
        if floor.is_none()
            && !recent
            && self.resting()
            && gravity != DVec2::ZERO
            && (vi - vj).dot(normal) <= sleep_speed(gravity.length(), ri.min(rj))
        {
            restitution = 0.0;
        }
        // A group takes a free ball's strike as one body while every contact it keeps pushes
        // (`pipeline/rigid.rs`), rather than let go and meet again as a jam of its cluster.
        let free = |world: &World, index: u32| !world.balls.is_supported(index);
        let held = |world: &World, index: u32| world.held_group(index).is_some();
        let strike = match (held(self, i), held(self, j)) {
            (true, false) if free(self, j) => Some((i, j, normal)),
            (false, true) if free(self, i) => Some((j, i, -normal)),
            _ => None,
        };
        if let Some((member, other, towards)) = strike {
            let approach = (vi - vj).dot(normal);
            let target = (restitution * approach).max(floor.unwrap_or(0.0));
            if let Some((vm, vo)) = self.hit_group_by_ball(member, other, towards, target) {
                let vj2 = if member == j { vm } else { vo };
                event.impulse = mj * (vj2 - vj).dot(normal);
                return Event::BallContact(event);
            }
        }
        let backed = floor.and_then(|_| {
            let support_into = |index: u32, push: DVec2| {
                let support = self.balls.is_supported(index).then(|| {
                    self.balls
                        .properties(index)
                        .and_then(|p| p.extra.support().copied())
                });
                support
                    .flatten()
                    .map(|s| (s.normal, s.collider))
                    .filter(|(normal, _)| normal.dot(push) < 0.0)
            };
            match support_into(i, -n) {
                Some(w) => Some((true, w)),
                None => support_into(j, n).map(|w| (false, w)),
            }
        });
        let free_pair = floor.is_none();
        let floor = floor.unwrap_or(0.0);
        let (mut vi2, mut vj2) = match backed {
            Some((true, (w, _))) => rebound_backed(vi, mi, vj, mj, n, restitution, floor, w),
            Some((false, (w, _))) => {
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
        event.impulse = mj * (vj2 - vj).dot(normal);
        // The observables: the virial `(pi - pj) . J_i = n . J_j` (`J_j` the impulse `j`
        // receives from `i`; a free ball takes only the other's), and a support's push on the
        // ball it backs (the pair's whole change of momentum).
        let w = match backed {
            Some((false, _)) => -n.dot((vi2 - vi) * mi),
            _ => n.dot((vj2 - vj) * mj),
        };
        self.observables.add_virial(w);
        self.instant.note_response(response, w, DVec2::ZERO);
        if let Some((backed_i, (_, support))) = backed {
            let (ball, p) = if backed_i { (i, pi) } else { (j, pj) };
            let push = (vi2 - vi) * mi + (vj2 - vj) * mj;
            self.note_impulse(Pair::Collider(ball, support.index), p, p, push);
        }
        if free_pair && !recent {
            (vi2, vj2, event.tangential_impulse) =
                self.rub_pair((i, vi2), (j, vj2), normal, event.impulse);
        }
        self.balls.kinematics_mut(i).expect("live").trajectory.v0 = vi2;
        self.balls.kinematics_mut(j).expect("live").trajectory.v0 = vj2;
        for index in [i, j] {
            if self.balls.is_supported(index) {
                self.set_support(index, None);
            }
        }
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
        // Restating the trajectory at the crossing makes the next search start there, so the
        // crossing just handled is not found again.
        let (_, ball) = self.balls.rebase(index, time, acceleration);
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
    /// keeps only its velocity along the surface that holds it and slides on it (or pivots on
    /// a point, or, held by two surfaces at an angle, stays put).
    ///
    /// What holds it is decided over every solid collider it touches now, this one first (see
    /// [`Hold`]): a ball settling on a second wall of an exact-fit channel slides along both,
    /// held by the one gravity pulls it into; the others it touches are not predicted against
    /// while it slides (it touches them all along).
    fn apply_settle(&mut self, entry: Entry) {
        let (index, time, gravity) = (entry.owner, self.time, self.gravity);
        let handle = ColliderHandle {
            index: entry.key.second,
            generation: entry.partner_tag,
        };
        let acceleration = self.balls.acceleration(index, gravity);
        self.balls.rebase(index, time, acceleration);
        if self.settle(index, handle) {
            self.counts.settles += 1;
            if !self.try_sleep(index) {
                self.schedule(index);
            }
        } else {
            // Nothing it touches can hold it (a rounding of its support's pull): it flies.
            if self.balls.is_supported(index) {
                self.set_support(index, None);
            }
            self.trajectory_changed(index);
        }
    }

    /// Ball `index`, whose trajectory starts now, comes to rest on what it touches, `first`
    /// first (see [`Self::apply_settle`]): its support is set, its velocity restricted to it.
    /// `false` if nothing it touches holds it (its trajectory is then unchanged).
    pub(crate) fn settle(&mut self, index: u32, first: ColliderHandle) -> bool {
        let gravity = self.gravity;
        let ball = self.balls.kinematics(index).expect("live ball");
        let (p, v, radius) = (ball.trajectory.p0, ball.trajectory.v0, ball.radius);
        let ball_v = v;
        // Surfaces it leaves faster than a settling hop would are not holding it: it flies
        // off them (and meets them again later, if it comes back).
        let g = gravity.length();
        let mut touched = self.touched_colliders(index, p, radius, first);
        let mut k = 0;
        touched.retain(|(_, _, touch)| {
            k += 1;
            let rise = (2.0 * g * touch.height(p, radius)).sqrt();
            k == 1 || v.dot(touch.normal) <= rise
        });
        let normals: Vec<DVec2> = touched.iter().map(|(_, _, t)| t.normal).collect();
        let (k, mut wedge) = match Hold::of(gravity, &normals) {
            Hold::Free => return false,
            Hold::Slide(k) => (k, None),
            Hold::Rest(k, j) => (k, Some(j)),
        };
        let (holder, collider, touch) = touched[k];
        let mut support = self.support_on(index, holder, &collider.shape, &touch, (p, radius));
        // A slide that pushes into another surface it touches at all (within the rounding
        // `Hold` allows) would press into it, unseen (it is touched, not predicted against):
        // that corner holds the ball at rest instead.
        if wedge.is_none() {
            // (Into it beyond the rounding of the slide's direction, as `Hold` has it: the
            // opposite wall of an exact-fit channel is parallel to the slide.)
            let slack = PARALLEL * support.acceleration.length();
            wedge = (0..touched.len())
                .find(|&i| i != k && support.acceleration.dot(touched[i].2.normal) < -slack);
        }
        if let Some(j) = wedge {
            support.wedge = Some(touched[j].0);
            support.acceleration = DVec2::ZERO;
        }
        let (p, mut v) = support.restrict(p, v);
        // Sliding into another surface it touches no faster than the settling hop it lost
        // (the slide's direction is the only one left, and that surface blocks it), it stops
        // against that surface: a corner held by both. Without this a ball settling at a jam,
        // whose contacts are closed for the instant, would slide on into it. A faster
        // approach is a contact now, and bounces. (Into it beyond the rounding of the slide's
        // direction, as for the wedge above: a ball sliding along an exact-fit channel
        // approaches the opposite wall by a rounding of its speed, and slides on.)
        let parallel = PARALLEL * v.length();
        let corner = (0..touched.len()).find(|&i| {
            let t = &touched[i].2;
            let approach = -v.dot(t.normal);
            i != k && approach > parallel && approach <= (2.0 * g * t.height(p, radius)).sqrt()
        });
        if corner.is_some() {
            v = DVec2::ZERO;
        }
        let ball = self.balls.kinematics_mut(index).expect("live ball");
        (ball.trajectory.p0, ball.trajectory.v0) = (p, v);
        // Friction may drive the slide where gravity does not (a spinning ball pushed along
        // the floor): into another surface it touches, that corner holds it too, at rest and
        // frictionless (`pipeline/rolling.rs`); otherwise it would settle, meet that surface
        // at once, settle again, and so on at one instant.
        if wedge.is_none() {
            support = self.rubbed(index, support);
            let slack = PARALLEL * support.acceleration.length();
            wedge = (0..touched.len())
                .find(|&i| i != k && support.acceleration.dot(touched[i].2.normal) < -slack);
            if let Some(j) = wedge {
                support.wedge = Some(touched[j].0);
                (support.acceleration, support.rub) = (DVec2::ZERO, None);
                let ball = self.balls.kinematics_mut(index).expect("live ball");
                ball.trajectory.v0 = DVec2::ZERO;
            }
        }
        self.set_rubbed_support(index, support);
        if support.pivot.is_none() {
            if let Some(properties) = self.balls.properties_mut(index) {
                properties
                    .extra
                    .set_line((support.collider, support.normal, support.origin));
            }
        }
        // At rest it touches the others all along; sliding, only those it slides along (an
        // exact-fit channel's other wall): a surface at an angle to the slide is met or left,
        // and predicted against as usual.
        let along = support.normal.perp();
        let others = touched
            .iter()
            .enumerate()
            .filter(|&(i, (_, _, t))| {
                i != k && (wedge.is_some() || t.normal.dot(along).abs() <= PARALLEL)
            })
            .map(|(_, &(h, _, _))| h)
            .collect();
        if let Some(properties) = self.balls.properties_mut(index) {
            properties.extra.set_touching(others);
        }
        // The observables: the velocity dropped, given to what holds the ball (its support,
        // and the second surface of a wedge or corner, each its share along its normal).
        let record = self.balls.kinematics(index).expect("live ball");
        let (p, dropped) = (record.trajectory.p0, record.trajectory.v0 - ball_v);
        if dropped != DVec2::ZERO {
            let mass = self.balls.mass_and_restitution(index).expect("live ball").0;
            let change = dropped * mass;
            let holder = touched[k].0.index;
            match wedge.or(corner) {
                Some(j) => {
                    let (first, second) = split(change, touched[k].2.normal, touched[j].2.normal);
                    self.note_impulse(Pair::Collider(index, holder), p, p, first);
                    let other = touched[j].0.index;
                    self.note_impulse(Pair::Collider(index, other), p, p, second);
                }
                None => self.note_impulse(Pair::Collider(index, holder), p, p, change),
            }
        }
        true
    }

    /// Whether a ball of `radius` centred at `p` touches the collider in `slot` at `touch`:
    /// as [`Touch::touches`] has it, or for a sleeping ball's circle (its proxy) as two balls
    /// touch ([`balls_touch`]: within their micro-hop too), since it is a ball.
    pub(crate) fn touches_collider_at(
        &self,
        slot: u32,
        touch: &Touch,
        p: DVec2,
        radius: f64,
    ) -> bool {
        if self.is_proxy(slot) {
            let reach = touch.reach(radius);
            touch.gap >= -0.5 * reach && balls_touch(touch.gap, p.abs().max_element(), reach)
        } else {
            touch.touches(p, radius)
        }
    }

    /// The solid colliders ball `index` (centre `p`) touches now (see [`Touch::touches`]),
    /// `first` first (if it is one of them; [`NO_COLLIDER`] for none) and the others in slot
    /// order, with their touches.
    pub(crate) fn touched_colliders(
        &self,
        index: u32,
        p: DVec2,
        radius: f64,
        first: ColliderHandle,
    ) -> Vec<(ColliderHandle, Collider, Touch)> {
        let Some(groups) = self.balls.properties(index).map(|p| p.groups) else {
            return Vec::new();
        };
        let mut touched = Vec::new();
        let mut add = |handle: ColliderHandle, collider: &Collider| {
            if collider.sensor || !collider.groups.interact(groups) {
                return;
            }
            if let Some(touch) = Touch::of(&collider.shape, p, radius) {
                if self.touches_collider_at(handle.index, &touch, p, radius) {
                    touched.push((handle, *collider, touch));
                }
            }
        };
        if let Some(collider) = self.colliders.get(first) {
            add(first, collider);
        }
        // The slots listed in the cell, each once and in order (slots, not copies of their
        // colliders: sorting those was 1 % of a drop-and-merge box's instructions).
        let mut rest = Vec::with_capacity(16);
        self.statics.near_point(p, |slot| rest.push(slot));
        rest.sort_unstable();
        rest.dedup();
        for slot in rest {
            if let Some((handle, collider)) = self.colliders.at(slot) {
                if handle != first {
                    add(handle, collider);
                }
            }
        }
        touched
    }

    /// The support of ball `index` (centre `p`, `radius`) on collider `handle` where it
    /// touches it: sliding on a segment's interior, or pivoting on an end point or a circle.
    /// A ball that overlaps the surface (by no more than [`Touch::touches`] allows) slides at
    /// its depth: it is never moved out.
    fn support_on(
        &self,
        index: u32,
        handle: ColliderHandle,
        shape: &Shape,
        touch: &Touch,
        (p, radius): (DVec2, f64),
    ) -> Support {
        let mut support = match (shape, touch.point) {
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
                    self.gravity,
                )
            }
            (Shape::Circle(_), None) => unreachable!("a circle is touched at a point"),
        };
        support.origin += touch.normal * touch.gap;
        if let (Shape::Segment(_), None) = (shape, touch.point) {
            // Back on the line it last slid on, and still on it (to within the rounding of a
            // position on it, a few ulps: any further, and moving it there could move it into
            // another surface it touches): it slides on that very line (see `Extra::line`),
            // unless that line lies further out than the ball is in. The line undoes a walk
            // into the surface, a rounding a knock; moved out beyond touching, a ball of an
            // exact-fit row (two balls filling a box's width, rough hunt seed 20402167) was
            // moved into its partner by up to the whole rounding each time it came back to
            // the wall, some 7 ulps a cycle, until they overlapped past `overlap_bound`.
            let last = self.balls.properties(index).and_then(|p| p.extra.line());
            let rounding = LINE_ULPS * f64::EPSILON * (p.abs().max_element() + radius);
            let inside = (-touch.gap).max(0.0);
            if let Some((_, _, origin)) = last.filter(|&(h, n, origin)| {
                let out = (origin - p).dot(n);
                h == handle && n == touch.normal && out.abs() <= rounding && out <= inside
            }) {
                support.origin = origin;
            }
        }
        support
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
        if let Some(held) = support.held {
            self.counts.leaves += 1;
            self.let_go(held.group);
            return;
        }
        if support.table().is_some() {
            self.end_table_phase(index, &support);
            return;
        }
        if self.end_phase(index, &support) {
            return;
        }
        let origin = self.balls.kinematics(index).expect("live ball").trajectory;
        let (_, ball) = self.balls.rebase(index, time, support.acceleration);
        let progressed = ball.trajectory.p0 != origin.p0;
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
        // Whether this leave is the extent's end, as predicted from the trajectory's origin
        // (`predict_near`), rather than the end of a friction phase come a rounding early:
        // only then is an unmoved centre one stuck at the end (asked only of such a centre).
        let extent_due = || {
            let base = origin.t0;
            support
                .leave_time(&origin.motion_at(base, support.acceleration))
                .and_then(|tau| base.resolved_after(tau))
                .is_some_and(|end| end <= time)
        };
        if inside && (progressed || !extent_due()) {
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
        self.set_support(index, next);
        self.counts.leaves += 1;
        self.schedule(index);
    }
}

/// How far, in units in the last place of its coordinates, a ball may be off the line it last
/// slid on and still settle back on that line: 4, the rounding of a position on it.
const LINE_ULPS: f64 = 4.0;

/// The most events the world handles at one instant per ball involved (plus one) before it
/// reports a stall ([`WorldError::Stalled`]) rather than go on: a safety net, never reached by
/// the zero-time chains the engine allows (see `ARCHITECTURE.md`: at one instant each contact
/// responds in sequence at most once before its jam is resolved, and each ball settles or
/// leaves a support a bounded number of times).
pub const STALL_EVENTS_PER_BALL: u64 = 1000;

/// Collisions of a ball closer than this fraction of the clock after its previous event
/// (`2^-40`, about a picosecond at t = 1 s) are elastic whatever the collapse time, except at
/// the very same instant (simultaneous impacts stay as they are): the TC model's remedy at the
/// clock's own scale. Without it, inelastic collapse (a cluster of balls, or a ball in a
/// cusp, colliding infinitely often in a finite time) would go on until collisions came closer
/// than the clock resolves ([`RESOLUTION`](crate::RESOLUTION), `2^-100`), were dropped, and
/// the balls sank into each other.
pub const COLLAPSE_FLOOR: f64 = 9.094_947_017_729_282e-13;

/// The smallest hop, as a fraction of their contact distance, that a collision leaves two
/// balls pulled together: `2^-30`, the order of [`OVERLAP_TOLERANCE`](crate::OVERLAP_TOLERANCE)
/// (or, far from the origin, [`MICRO_HOP_ULPS`] units in the last place of the coordinates,
/// if that is more: see [`micro_hop`]).
///
/// A ball bouncing on a ball that rests on a floor (balls are never supported by balls)
/// would make inelastic hops that shrink below the rounding of their gap, and the two would
/// sink into each other. Instead a collision never leaves such a pair a smaller hop, and a
/// touching pair that hops less collides at once: the top ball jitters by this fraction of the
/// contact distance, invisibly, at a bounded energy (`m |pull|` times the hop, per such
/// collision), with no overlap. (It was once a fraction of the coordinates' magnitude: at
/// x = 1e6 a ball of radius 0.5 hopped 1e-3, and an elastic stack gained 3.1e-4 of its energy.)
pub const MICRO_HOP: f64 = 9.313_225_746_154_785e-10;

/// The least micro-hop, in units in the last place of the contact's coordinate scale: 64,
/// well above the rounding of a gap computed there (a few ulps).
pub const MICRO_HOP_ULPS: f64 = 64.0;

/// The micro-hop of two balls of contact distance `reach` at coordinates of magnitude
/// `coordinates` (see [`MICRO_HOP`]).
#[must_use]
pub fn micro_hop(coordinates: f64, reach: f64) -> f64 {
    (MICRO_HOP * reach).max(MICRO_HOP_ULPS * f64::EPSILON * (coordinates + reach))
}

/// Whether two balls `gap` apart (negative: overlapping), with contact distance `reach` at
/// coordinates of magnitude `coordinates`, touch: within [`SETTLE_HEIGHT`] of the coordinate
/// scale, as a ball touches a surface, or within their [`micro_hop`], since a pair pulled
/// together meets at once up to that far apart (see `hop_floor`). A sleeping ball's circle
/// touches as the ball would.
pub(crate) fn balls_touch(gap: f64, coordinates: f64, reach: f64) -> bool {
    gap <= (SETTLE_HEIGHT * (coordinates + reach)).max(micro_hop(coordinates, reach))
}

/// For balls at `pi`, `pj` (velocities `vi`, `vj`, accelerations `ai`, `aj`, contact
/// distance `reach`) that their relative acceleration, with the curvature of their relative
/// path, pulls together, the separation speed that makes them hop [`micro_hop`] apart; `None`
/// if nothing pulls them together.
///
/// This is a ball bouncing on a ball that rests on a floor (a ball is never *supported* by a
/// ball). Its inelastic hops would shrink below the rounding of the gap, and the two would sink
/// into each other; instead a collision never leaves them a smaller hop than this, and a
/// touching pair that hops less collides at once and gets it. The top ball then jitters by
/// the micro-hop, invisibly, at a bounded energy, with no overlap.
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
    let coordinates = pi.abs().max_element().max(pj.abs().max_element());
    Some((2.0 * -pull * micro_hop(coordinates, reach)).sqrt())
}

impl World {
    /// Whether a ball whose previous event was at `last` collides again within the world's
    /// collapse time (see [`World::set_collapse_time`]), or a positive time shorter than
    /// [`COLLAPSE_FLOOR`] of the clock: the collision is then elastic.
    pub(super) fn recent(&self, last: Time) -> bool {
        let since = self.time.since(last);
        since < self.collapse_time
            || (since > 0.0 && since < COLLAPSE_FLOOR * self.time.seconds().abs())
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
    /// `end` that leads away from `other`, or one collinear with `from` (to within `PARALLEL`)
    /// whose interior holds `end`, seen from the ball's side (its normal facing the ball),
    /// turning least from the way `from` went; with that normal. (A longer segment under
    /// `from` goes on from `end` too: the ball slides onto it rather than pivot on `end` and
    /// drop into it.)
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
            } else if s.distance(end) <= near && s.direction().perp_dot(way).abs() <= PARALLEL {
                // `end` lies on its interior and it runs along `from` (collinear segments that
                // overlap, the ball touching both all along): it goes on from there to its end
                // ahead. (One that only crosses there is met as any other surface is: its
                // other parts may lie anywhere, and a support's `next` is not predicted
                // against.)
                if (s.b() - s.a()).dot(way) > 0.0 {
                    s.b()
                } else {
                    s.a()
                }
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
