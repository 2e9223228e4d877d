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
use crate::dynamics::{Time, collide_balls, reflect};
use crate::geometry::{ColliderHandle, Feature};

enum Status {
    Crossing,
    Outdated,
    Live,
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
        if let Some(entry) = self.peek_live(until) {
            // Applying the event predicts its balls again, which replaces the entry.
            return Ok(Some(self.apply(entry)));
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

    /// The time of the next event, if any (handling cell crossings and outdated predictions on
    /// the way).
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
            Kind::Contact | Kind::Sensor => self.colliders.is_live(partner, entry.partner_tag),
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
            Kind::Crossing => unreachable!("crossings are handled before they reach `apply`"),
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
        let restitution = self.balls.properties(index).expect("live ball").restitution;
        let ball = self.balls.kinematics_mut(index).expect("live ball");
        ball.trajectory = ball.trajectory.rebased(time, gravity);
        let (p, v) = (ball.trajectory.p0, ball.trajectory.v0);
        let (n, point) = collider.shape.contact(feature, p);
        ball.trajectory.v0 = reflect(v, n, restitution * collider.restitution);
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
            let properties = world.balls.properties(index).expect("live ball");
            let (mass, restitution) = (properties.mass, properties.restitution);
            let ball = world.balls.kinematics_mut(index).expect("live ball");
            ball.trajectory = ball.trajectory.rebased(time, gravity);
            (
                ball.trajectory.p0,
                ball.trajectory.v0,
                mass,
                ball.radius,
                restitution,
            )
        };
        let (pi, vi, mi, ri, ei) = restate(self, i);
        let (pj, vj, mj, _, ej) = restate(self, j);
        let n = pj - pi;
        let (vi2, vj2) = collide_balls(vi, mi, vj, mj, n, ei * ej);
        self.balls.kinematics_mut(i).expect("live").trajectory.v0 = vi2;
        self.balls.kinematics_mut(j).expect("live").trajectory.v0 = vj2;
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
        let ball = self.balls.kinematics_mut(index).expect("live ball");
        // Restating the trajectory at the crossing makes the next search start there, so the
        // crossing just handled is not found again.
        ball.trajectory = ball.trajectory.rebased(time, gravity);
        let position = ball.trajectory.p0;
        let sensors = &mut self.balls.properties_mut(index).expect("live ball").sensors;
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

fn feature_from_rank(rank: u8) -> Feature {
    match rank {
        0 => Feature::SegmentInterior,
        1 => Feature::SegmentEndA,
        2 => Feature::SegmentEndB,
        _ => Feature::Circle,
    }
}
