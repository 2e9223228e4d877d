//! The world: balls, colliders, the clock, and the calls that change them.

use glam::DVec2;

use super::WorldError;
#[cfg(not(feature = "heap-queue"))]
use super::calendar::CalendarQueue as EventQueue;
use super::group::Group;
use super::instant::Instant;
use super::observables::Observables;
use super::pending::{PendingQueue, Prediction};
use super::periodic::Periodic;
#[cfg(feature = "heap-queue")]
use super::queue::EventQueue;
use super::sleep::{Body, Sleepers};
use crate::broad::{Aabb, BallGrid, Place, StaticGrid};
use crate::dynamics::{
    Ball, BallDesc, BallHandle, BallSet, Extra, Kinematics, Material, NO_COLLIDER, Properties,
    Roughness, Spin, Table, Time, Trajectory, contact_velocity, roll_of,
};
use crate::geometry::{
    Circle, Collider, ColliderDesc, ColliderHandle, ColliderSet, Feature, Segment, Shape, ShapeDesc,
};

/// How deep, relative to the contact distance, a new body may overlap another and still count
/// as touching: `1e-9` (so `1e-9` of a radius of 1).
///
/// Positions that touch in exact arithmetic (a ball resting against a diagonal wall, balls
/// packed in a lattice) often come out overlapping by a rounding error; rejecting them would
/// make such scenes impossible to write. The engine itself never needs the tolerance: a pair
/// that overlaps by a rounding error is treated as touching (see [`crate::toi`]).
pub const OVERLAP_TOLERANCE: f64 = 1e-9;

/// How deep the engine lets two touching bodies overlap, at most: [`OVERLAP_TOLERANCE`] of
/// their contact distance `reach` (as deep as a placement may be), plus the touching distance
/// of resting contact, [`SETTLE_HEIGHT`](crate::SETTLE_HEIGHT) of the contact's coordinate
/// scale (`coordinates + reach`, `coordinates` the largest magnitude of a coordinate of the
/// two): 256 units in the last place of it, within which a gap is rounding. Near the origin
/// the first term rules: a ball of radius 0.5 there may overlap a floor by `5e-10` (and
/// `1e-14`). Far from the origin, or for bodies tiny against their coordinates, where
/// `1e-9` of the contact distance is only a few units in the last place of the coordinates,
/// the second does: at `x = 1e9` the same ball may overlap by `5.7e-5`, where one unit in
/// the last place is already `1.2e-7`. Checked after every event by `exact2d soak`, the fuzz
/// targets and `exact2d-hunt`.
#[must_use]
pub fn overlap_bound(coordinates: f64, reach: f64) -> f64 {
    OVERLAP_TOLERANCE * reach + crate::SETTLE_HEIGHT * (coordinates + reach)
}

/// Counts of the events a world has handled.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct EventCounts {
    /// Bounces off solid colliders.
    pub contacts: u64,
    /// Ball-ball collisions.
    pub ball_contacts: u64,
    /// Sensor entries.
    pub sensor_enters: u64,
    /// Sensor exits.
    pub sensor_exits: u64,
    /// Internal: a ball came to rest or began to slide on a collider (no [`Event`] is
    /// returned for it; see [`World::ball_support`]).
    ///
    /// [`Event`]: crate::Event
    pub settles: u64,
    /// Internal: a supported ball reached the end of its support (a segment's end, or the next
    /// edge of a pivot).
    pub leaves: u64,
    /// Jams: zero-time chains that came back to a contact, resolved as one simultaneous impact
    /// of the bodies touching it (counted once each; the event that came back is returned as
    /// usual). See `ARCHITECTURE.md`, zero-time chains.
    pub jams: u64,
    /// Collisions (counted in `contacts` or `ball_contacts` too) that a group of balls pressed
    /// together under gravity took as one body, every contact it keeps pushing: resolved
    /// exactly without letting the group go (see `ARCHITECTURE.md`, groups).
    pub rigid_hits: u64,
    /// Internal: a ball at rest on what it touches fell asleep (see [`World::ball_asleep`]).
    pub sleeps: u64,
    /// Internal: a sleeping ball woke.
    pub wakes: u64,
    /// Internal: a phase of a ball under friction ended (its slip vanished and it rolls, it
    /// rolled to a stop, or its spin stopped), on a surface or on a table's cloth.
    pub phase_ends: u64,
}

impl EventCounts {
    /// Collisions: bounces off colliders plus ball-ball collisions (sensor events excluded).
    #[must_use]
    pub fn collisions(&self) -> u64 {
        self.contacts + self.ball_contacts
    }

    /// Everything the world handled that changed a ball: collisions, sensor events, and the
    /// internal settles, leaves, sleeps, wakes and phase ends (jams excluded: each is counted as the
    /// collision that came back).
    #[must_use]
    pub fn handled(&self) -> u64 {
        self.collisions()
            + self.sensor_enters
            + self.sensor_exits
            + self.settles
            + self.leaves
            + self.sleeps
            + self.wakes
            + self.phase_ends
    }
}

/// An exact, event-driven 2D world of balls and static colliders.
///
/// Balls move in closed form between events; every collision is handled at its exact time of
/// impact. See the [crate documentation](crate) for a tour.
///
/// A clone is an independent world in the same state, to the bit, at any instant (inside a
/// zero-time chain, with groups held and balls asleep): given the same calls, the two go on
/// with the same events and bits (the engine keeps no state outside the world: no clock, no
/// random numbers). Branching a run (a search over actions, a perturbation test) is a clone.
#[derive(Clone)]
pub struct World {
    pub(crate) gravity: DVec2,
    pub(crate) time: Time,
    pub(crate) balls: BallSet,
    pub(crate) colliders: ColliderSet,
    /// When the collider in each slot was added (a contact at a trajectory's origin before
    /// the current chain was decided then only with a collider that was there: see
    /// `Instant::is_closed`).
    pub(crate) collider_born: Vec<Time>,
    pub(crate) queue: EventQueue,
    /// The broad phase: static colliders by cell, and balls that can meet balls by cell.
    pub(crate) statics: StaticGrid,
    pub(crate) grid: BallGrid,
    pub(crate) counts: EventCounts,
    /// Scratch space for a prediction's candidate balls.
    pub(crate) near: Vec<u32>,
    /// The same in a periodic box, with each candidate's image shift.
    pub(crate) near_images: Vec<(u32, DVec2)>,
    /// Scratch space for a jam's cluster: each ball slot's index in the cluster being found,
    /// `u32::MAX` for none (every entry is `u32::MAX` between jams; grown on a jam's demand,
    /// so a world without jams never allocates it). See `World::cluster`.
    pub(crate) cluster_slots: Vec<u32>,
    /// Collisions of a ball less than this long after its previous event are elastic (the TC
    /// model); 0: off.
    pub(crate) collapse_time: f64,
    /// What happened at the current instant: the bookkeeping of zero-time chains.
    pub(crate) instant: Instant,
    /// Groups of balls held by their contacts (see `pipeline/group.rs`).
    pub(crate) groups: Vec<Group>,
    /// The next group's number.
    pub(crate) next_group: u32,
    /// The sleeping balls (see `pipeline/sleep.rs`).
    pub(crate) sleepers: Sleepers,
    /// Whether balls at rest may fall asleep (see [`World::set_sleeping`]).
    pub(crate) sleeping: bool,
    /// The table's cloth, if the world is a table seen from above (see
    /// `pipeline/table.rs`).
    pub(crate) table: Option<Table>,
    /// The accumulators a run can read without an event callback (see
    /// `pipeline/observables.rs`).
    pub(crate) observables: Observables,
    /// The periodic box's images of each ball, if the world is one (see
    /// `pipeline/periodic.rs`; the box itself is the ball grid's).
    pub(crate) periodic: Option<Periodic>,
}

impl Default for World {
    fn default() -> Self {
        Self {
            gravity: DVec2::ZERO,
            time: Time::ZERO,
            balls: BallSet::default(),
            colliders: ColliderSet::default(),
            collider_born: Vec::new(),
            queue: EventQueue::default(),
            statics: StaticGrid::default(),
            grid: BallGrid::default(),
            counts: EventCounts::default(),
            near: Vec::new(),
            near_images: Vec::new(),
            cluster_slots: Vec::new(),
            collapse_time: 0.0,
            instant: Instant::default(),
            groups: Vec::new(),
            next_group: 0,
            sleepers: Sleepers::default(),
            sleeping: false,
            table: None,
            observables: Observables::default(),
            periodic: None,
        }
    }
}

impl World {
    /// An empty world without gravity, at time 0.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// An empty world with uniform `gravity` (an acceleration applied to every ball), at time 0.
    ///
    /// # Errors
    /// [`WorldError::NotFinite`] if `gravity` is not finite.
    pub fn with_gravity(gravity: DVec2) -> Result<Self, WorldError> {
        check_finite(gravity, "gravity")?;
        let mut world = Self {
            gravity,
            ..Self::default()
        };
        if gravity != DVec2::ZERO {
            world.balls.carry_residuals();
        }
        Ok(world)
    }

    /// The current time: every ball is reported at this time.
    #[must_use]
    pub fn time(&self) -> f64 {
        self.time.seconds()
    }

    /// The current time exactly (event times are kept to about 1e-32 relative; see [`Time`]).
    #[must_use]
    pub fn exact_time(&self) -> Time {
        self.time
    }

    /// The uniform gravity.
    #[must_use]
    pub fn gravity(&self) -> DVec2 {
        self.gravity
    }

    /// Sets the *collapse time* `t_c` of the TC model (Luding and McNamara, "How to handle the
    /// inelastic collapse of a dissipative hard-sphere gas with the TC model", Granular Matter
    /// 1998): a collision of a ball less than `t_c` after its previous event (any change of its
    /// path) is elastic, whatever the restitutions. Inelastic balls can otherwise collide
    /// infinitely often in a finite time (a cluster in a cooling gas, a ball driven into a
    /// cusp), until their collisions come closer than the clock resolves. `0` (the default)
    /// turns it off. A physical `t_c` is the duration of a real contact, small against the
    /// time between collisions.
    ///
    /// # Errors
    /// [`WorldError::InvalidCollapseTime`] if `t_c` is negative or not finite.
    pub fn set_collapse_time(&mut self, t_c: f64) -> Result<(), WorldError> {
        if !(t_c >= 0.0 && t_c.is_finite()) {
            return Err(WorldError::InvalidCollapseTime(t_c));
        }
        self.collapse_time = t_c;
        Ok(())
    }

    /// The collapse time of the TC model (see [`set_collapse_time`](Self::set_collapse_time)).
    #[must_use]
    pub fn collapse_time(&self) -> f64 {
        self.collapse_time
    }

    /// Counts of the events handled so far.
    #[must_use]
    pub fn event_counts(&self) -> EventCounts {
        self.counts
    }

    /// How many events (internal ones included) the world has handled at the current
    /// instant, and how many balls had them: what a check that the clock moves on compares
    /// (see [`STALL_EVENTS_PER_BALL`](crate::STALL_EVENTS_PER_BALL) and `ARCHITECTURE.md`,
    /// zero-time chains). Both are zero once the clock has moved past the last event, and the
    /// count starts again whenever the caller changes the world.
    #[must_use]
    pub fn instant_events(&self) -> (u64, usize) {
        if self.instant.is_at(self.time) {
            self.instant.events()
        } else {
            (0, 0)
        }
    }

    /// Makes room for `additional` more balls, so that adding them allocates nothing more
    /// (a scene of a million balls then takes exactly the memory it needs, with no growth
    /// slack). Like [`Vec::reserve_exact`], only a hint for speed and memory: adding balls
    /// works without it.
    pub fn reserve_balls(&mut self, additional: usize) {
        self.balls.reserve(additional);
        let slots = self.balls.slot_count().saturating_add(additional);
        self.queue.reserve_slots(slots);
        self.grid.reserve_slots(slots);
        self.reserve_periodic_slots(slots);
    }

    /// Adds a ball at the current time.
    ///
    /// # Errors
    /// If a number is not finite, the radius or mass is not positive, the restitution is not
    /// in `[0, 1]`, or the ball would overlap (deeper than [`OVERLAP_TOLERANCE`]) a solid
    /// collider or a ball it interacts with. Touching is allowed.
    pub fn add_ball(&mut self, desc: BallDesc) -> Result<BallHandle, WorldError> {
        check_finite(desc.position, "ball position")?;
        check_finite(desc.velocity, "ball velocity")?;
        check_positive(desc.radius, WorldError::InvalidRadius)?;
        check_positive(desc.mass, WorldError::InvalidMass)?;
        check_restitution(desc.restitution)?;
        let spin = check_spin(&desc, self.time)?;
        if desc.roll != DVec2::ZERO && self.table.is_none() {
            return Err(WorldError::RollWithoutTable);
        }
        self.check_periodic_ball(desc.position, desc.radius)?;
        self.make_room_for(&desc);
        self.check_ball_overlaps(&desc)?;
        self.instant.forget();
        // Sensors it starts inside, in slot order (as if it had entered them in that order).
        let mut inside = Vec::new();
        self.statics.near_point(desc.position, |slot| {
            if let Some((handle, collider)) = self.colliders.at(slot) {
                if collider.sensor
                    && collider.groups.interact(desc.groups)
                    && overlaps(&collider.shape, desc.position, desc.radius)
                {
                    inside.push(handle);
                }
            }
        });
        inside.sort_unstable_by_key(|h| h.index);
        let trajectory = Trajectory {
            p0: desc.position,
            v0: desc.velocity,
            t0: self.time,
        };
        let material = Material {
            mass: desc.mass,
            restitution: desc.restitution,
        };
        let properties = Properties {
            groups: desc.groups,
            user_data: desc.user_data,
            extra: Extra::from_sensors(inside),
        };
        let handle = self
            .balls
            .insert(trajectory, desc.radius, material, properties, spin);
        self.note_periodic_ball(handle.index);
        if self.grid.admits(desc.groups) {
            let place = self.grid.place_of(desc.position);
            self.register_in_grid(handle.index, place);
        }
        self.schedule(handle.index);
        self.refit_ball_grid();
        Ok(handle)
    }

    /// Grows the broad phase for a new ball: the static grid's padding to its radius, the
    /// ball grid's group union (admitting balls that can now meet a ball) and cell size.
    fn make_room_for(&mut self, desc: &BallDesc) {
        self.statics.fit_radius(desc.radius);
        let grew = self.grid.note_groups(desc.groups);
        // Balls already here that can meet a ball only now (the group union grew) join the
        // grid, and their radii count for its cells as much as the new ball's.
        let joining: Vec<u32> = if grew {
            self.balls
                .iter()
                .filter(|&(i, _, p)| {
                    self.grid.place(i) == Place::Absent
                        && self.grid.admits(p.groups)
                        && !self.is_asleep(i)
                })
                .map(|(i, _, _)| i)
                .collect()
        } else {
            Vec::new()
        };
        let mut radius = if self.grid.admits(desc.groups) {
            desc.radius
        } else {
            0.0
        };
        for &index in &joining {
            radius = radius.max(self.balls.kinematics(index).expect("live ball").radius);
        }
        // A ball far larger than the cells' balls is kept out of them, while such balls are
        // few, rather than have every ball's cell grown for it (`broad/ball_grid.rs`). The
        // decision is on the largest radius: balls joining with it (the group union grew)
        // that the cells do not fit either are kept out too, whatever their size and count
        // (`BallGrid::register_sized`; far, so still checked by every ball).
        if radius > 0.0 && !self.grid.fits(radius) && !self.grid.takes_outsize(radius) {
            self.grid.set_capacity(radius);
            self.relink_ball_grid();
        }
        if self.grid.admits(desc.groups) {
            let here = Aabb {
                min: desc.position,
                max: desc.position,
            };
            self.cover_with_ball_grid(here);
        }
        for index in joining {
            self.register_where_it_is(index);
        }
    }

    /// Registers every member of the ball grid afresh and predicts it afresh: new cells make
    /// new neighbours that no crossing will ever introduce. Rare: radii only grow past the
    /// capacity a few times, and the cells follow the balls' spacing within a factor of two.
    fn relink_ball_grid(&mut self) {
        let members = self.grid.unlink_all();
        for &index in &members {
            let record = self.balls.kinematics(index).expect("live ball");
            let p = record
                .trajectory
                .position_at(self.time, self.acceleration(index));
            let place = self.grid.place_of(p);
            self.register_in_grid(index, place);
        }
        for index in members {
            self.schedule(index);
        }
    }

    /// Resizes the ball grid's cells if the balls' spacing calls for it (see
    /// [`BallGrid::wanted_cell`]).
    fn refit_ball_grid(&mut self) {
        if let Some(cell) = self.grid.wanted_cell() {
            self.grid.set_cell(cell);
            self.relink_ball_grid();
        }
    }

    /// Makes the ball grid's region cover `b`; far balls now inside it move into cells.
    fn cover_with_ball_grid(&mut self, b: Aabb) {
        if self.grid.cover(b) {
            for index in self.grid.far_balls() {
                self.register_where_it_is(index);
            }
        }
    }

    /// Registers ball `index` in the cell where it is now, and queues its next crossing.
    fn register_where_it_is(&mut self, index: u32) {
        let record = self.balls.kinematics(index).expect("live ball");
        let p = record
            .trajectory
            .position_at(self.time, self.acceleration(index));
        let place = self.grid.place_of(p);
        self.register_in_grid(index, place);
        self.queue_pending(index, self.time, self.queue.physical(index));
    }

    fn check_ball_overlaps(&self, desc: &BallDesc) -> Result<(), WorldError> {
        // The first overlapped collider in slot order, as a scan of every collider would give.
        let mut overlapped: Option<ColliderHandle> = None;
        let mut sleeper: Option<u32> = None;
        self.statics.near_point(desc.position, |slot| {
            if let Some((handle, collider)) = self.colliders.at(slot) {
                if !collider.sensor
                    && collider.groups.interact(desc.groups)
                    && overlaps_deeply(&collider.shape, desc.position, desc.radius)
                {
                    // A sleeping ball's circle is that ball.
                    if let Some(ball) = self.sleepers.ball_of(slot) {
                        sleeper = Some(sleeper.map_or(ball, |b| b.min(ball)));
                    } else if overlapped.is_none_or(|h| handle.index < h.index) {
                        overlapped = Some(handle);
                    }
                }
            }
        });
        if let Some(handle) = overlapped {
            return Err(WorldError::OverlapsCollider(handle));
        }
        if let Some(ball) = sleeper {
            return Err(WorldError::OverlapsBall(self.balls.handle(ball)));
        }
        if !self.grid.admits(desc.groups) {
            return Ok(());
        }
        let mut overlapped: Option<u32> = None;
        // A ball the cells do not fit (kept out of them: `broad/ball_grid.rs`) may overlap
        // balls beyond its cell's block: it is checked against every ball, as a far ball is.
        let place = if self.grid.fits(desc.radius) {
            self.grid.place_of(desc.position)
        } else {
            Place::Far
        };
        self.grid.near_place(place, u32::MAX, |index, shift| {
            let (other, properties) = self.balls.get(self.balls.handle(index)).expect("live");
            if !properties.groups.interact(desc.groups) {
                return;
            }
            let p = other
                .trajectory
                .position_at(self.time, self.acceleration(index))
                + shift;
            let reach = other.radius + desc.radius;
            if p.distance(desc.position) - reach < -OVERLAP_TOLERANCE * reach {
                overlapped = Some(overlapped.map_or(index, |o| o.min(index)));
            }
        });
        match overlapped {
            Some(index) => Err(WorldError::OverlapsBall(self.balls.handle(index))),
            None => Ok(()),
        }
    }

    /// Removes a ball, returning its last state.
    ///
    /// # Errors
    /// [`WorldError::NoSuchBall`] if the handle is not live.
    pub fn remove_ball(&mut self, handle: BallHandle) -> Result<Ball, WorldError> {
        let ball = self.ball(handle).ok_or(WorldError::NoSuchBall(handle))?;
        self.instant.forget();
        // Asleep, it wakes first: what rests on it loses it.
        self.wake(handle.index);
        if let Some(group) = self.held_group(handle.index) {
            self.let_go(group);
        }
        self.balls.remove(handle);
        self.grid.unregister(handle.index);
        self.queue.remove(handle.index);
        self.refit_ball_grid();
        Ok(ball)
    }

    /// Sets a ball's velocity from now on. Only this ball's prediction is redone; other balls'
    /// predictions involving it are redone when they come up.
    ///
    /// # Errors
    /// [`WorldError::NoSuchBall`] or [`WorldError::NotFinite`].
    pub fn set_ball_velocity(
        &mut self,
        handle: BallHandle,
        velocity: DVec2,
    ) -> Result<(), WorldError> {
        check_finite(velocity, "ball velocity")?;
        if self.balls.get(handle).is_none() {
            return Err(WorldError::NoSuchBall(handle));
        }
        self.instant.forget();
        self.wake(handle.index);
        let (time, acceleration) = (self.time, self.acceleration(handle.index));
        self.balls.rebase(handle.index, time, acceleration);
        let record = self
            .balls
            .kinematics_mut(handle.index)
            .expect("checked live");
        record.trajectory.v0 = velocity;
        // A new velocity lifts a supported ball off its support; if it still rests there, it
        // settles again at once.
        if self.balls.is_supported(handle.index) {
            self.set_support(handle.index, None);
        }
        self.trajectory_changed(handle.index);
        Ok(())
    }

    /// Sets a ball's angular velocity (radians per second, counter-clockwise positive) from
    /// now on. Spin changes no path by itself: only rough contacts (see [`Roughness`]) turn
    /// it into motion, so a frictionless ball's prediction is not redone; a ball with friction
    /// on a surface wakes if it sleeps and settles again at once (it may now slide or roll).
    ///
    /// # Errors
    /// [`WorldError::NoSuchBall`] or [`WorldError::NotFinite`].
    pub fn set_ball_spin(&mut self, handle: BallHandle, spin: f64) -> Result<(), WorldError> {
        if !spin.is_finite() {
            return Err(WorldError::NotFinite("ball spin"));
        }
        if self.balls.get(handle).is_none() {
            return Err(WorldError::NoSuchBall(handle));
        }
        if spin != 0.0 || self.balls.spin(handle.index).is_some() {
            let time = self.time;
            let index = handle.index;
            self.balls.spin_mut(index).set_omega(time, spin);
            // On a table the spin changes the ball's phase on the cloth.
            if self.table.is_some() {
                self.instant.forget();
                self.lift_off_table(index);
                self.trajectory_changed(index);
                return Ok(());
            }
            // A rough ball on a surface rubs it with its new spin: a sleeping one wakes, a
            // supported one settles again at once (see `pipeline/rolling.rs`).
            if self
                .balls
                .spin(index)
                .is_some_and(|s| s.roughness.friction > 0.0)
            {
                self.instant.forget();
                self.wake(index);
                if self.balls.is_supported(index) {
                    let acceleration = self.acceleration(index);
                    self.balls.rebase(index, time, acceleration);
                    self.set_support(index, None);
                    self.trajectory_changed(index);
                }
            }
        }
        Ok(())
    }

    /// Sets a ball's angle (its orientation, radians counter-clockwise, brought into
    /// `[-pi, pi]`) now; it turns on from there at its spin. The angle changes nothing else:
    /// balls are round.
    ///
    /// # Errors
    /// [`WorldError::NoSuchBall`] or [`WorldError::NotFinite`].
    pub fn set_ball_angle(&mut self, handle: BallHandle, angle: f64) -> Result<(), WorldError> {
        if !angle.is_finite() {
            return Err(WorldError::NotFinite("ball angle"));
        }
        if self.balls.get(handle).is_none() {
            return Err(WorldError::NoSuchBall(handle));
        }
        if angle != 0.0 || self.balls.spin(handle.index).is_some() {
            let time = self.time;
            self.balls.spin_mut(handle.index).set_angle(time, angle);
        }
        Ok(())
    }

    /// Adds a static collider at the current time.
    ///
    /// Balls whose predicted paths it cuts are predicted again; a ball whose path crossed the
    /// collider's place *before* now (when it did not exist) is restated from now on.
    ///
    /// # Errors
    /// If a number is not finite, a radius is not positive, a segment is degenerate, the
    /// restitution is not in `[0, 1]`, or a solid collider would overlap a ball it interacts
    /// with (deeper than [`OVERLAP_TOLERANCE`]).
    pub fn add_collider(&mut self, desc: ColliderDesc) -> Result<ColliderHandle, WorldError> {
        let shape = build_shape(desc.kind)?;
        self.check_periodic_collider(&shape)?;
        check_restitution(desc.restitution)?;
        check_roughness(desc.friction, desc.tangential_restitution)?;
        check_resistance(desc.rolling_resistance)?;
        let collider = Collider {
            shape,
            sensor: desc.sensor,
            restitution: desc.restitution,
            groups: desc.groups,
            user_data: desc.user_data,
            friction: desc.friction,
            tangential_restitution: desc.tangential_restitution,
            rolling_resistance: desc.rolling_resistance,
        };
        if !collider.sensor {
            for (index, ball, properties) in self.balls.iter() {
                let p = ball
                    .trajectory
                    .position_at(self.time, self.acceleration(index));
                if properties.groups.interact(collider.groups)
                    && overlaps_deeply(&shape, p, ball.radius)
                {
                    return Err(WorldError::OverlapsBall(self.balls.handle(index)));
                }
            }
        }
        self.instant.forget();
        let handle = self.colliders.insert(collider);
        self.note_born(handle.index);
        let (min, max) = shape.aabb();
        self.statics.insert(handle.index, Aabb { min, max });
        self.grid.mark_all_near_statics();
        self.cover_with_ball_grid(Aabb { min, max });
        self.collider_added(handle, &collider);
        self.refit_ball_grid();
        Ok(handle)
    }

    /// Records that the collider in slot `index` was added now.
    pub(crate) fn note_born(&mut self, index: u32) {
        let i = index as usize;
        if self.collider_born.len() <= i {
            self.collider_born.resize(i + 1, Time::ZERO);
        }
        self.collider_born[i] = self.time;
        self.observables.clear_collider(index);
    }

    /// Tells every interacting ball about a new collider: sensor membership, then either a
    /// restatement (if its path crossed the collider before now) or an earlier prediction.
    fn collider_added(&mut self, handle: ColliderHandle, collider: &Collider) {
        let indices: Vec<u32> = self
            .balls
            .iter()
            .filter(|&(i, _, p)| p.groups.interact(collider.groups) && !self.is_asleep(i))
            .map(|(i, _, _)| i)
            .collect();
        let time = self.time;
        for index in indices {
            let acceleration = self.acceleration(index);
            let record = self.balls.kinematics(index).expect("live");
            let p = record.trajectory.position_at(time, acceleration);
            if collider.sensor && overlaps(&collider.shape, p, record.radius) {
                let properties = self.balls.properties_mut(index).expect("live");
                properties.extra.push(handle);
            }
            self.offer_collider(index, handle, collider);
        }
    }

    /// Ball `index` learns of a new solid collider `handle`: restated now if its path crossed
    /// the collider's place before now (when it did not exist), else given the contact if it
    /// is earlier than its prediction.
    pub(crate) fn offer_collider(
        &mut self,
        index: u32,
        handle: ColliderHandle,
        collider: &Collider,
    ) {
        let Some(key) = self.collider_candidate(index, handle, collider, Time::new(f64::INFINITY))
        else {
            return;
        };
        let time = self.time;
        if key.time < time {
            let acceleration = self.acceleration(index);
            self.balls.rebase(index, time, acceleration);
            self.trajectory_changed(index);
        } else if self.queue.physical(index).is_none_or(|p| key < p.key) {
            let prediction = Prediction {
                key,
                tag: handle.generation,
            };
            self.queue.set_physical(index, Some(prediction));
        }
    }

    /// Removes a collider. Balls whose next event was with it are predicted again when that
    /// event comes up; a ball inside a removed sensor gets no exit event.
    ///
    /// # Errors
    /// [`WorldError::NoSuchCollider`] if the handle is not live.
    pub fn remove_collider(&mut self, handle: ColliderHandle) -> Result<Collider, WorldError> {
        if self.sleeper_of(handle).is_some() {
            return Err(WorldError::NoSuchCollider(handle));
        }
        let collider = self
            .colliders
            .remove(handle)
            .ok_or(WorldError::NoSuchCollider(handle))?;
        self.instant.forget();
        self.observables.clear_collider(handle.index);
        self.statics.remove(handle.index);
        if collider.sensor {
            for properties in self.balls.properties_iter_mut() {
                properties.extra.remove(handle);
            }
        } else if self.gravity != DVec2::ZERO {
            // Sleeping balls it held wake, and with them what rests on them; balls it
            // supported fall (or settle again on what else holds them).
            let listing: Vec<u32> = self
                .balls
                .iter()
                .filter(|(_, _, p)| {
                    p.extra
                        .sleep()
                        .is_some_and(|s| s.contacts.iter().any(|&(h, _)| h == handle))
                })
                .map(|(i, _, _)| i)
                .collect();
            for index in listing {
                if self.loses_contact(index, handle) {
                    self.wake(index);
                }
            }
            self.release_held_by(&[handle]);
        }
        Ok(collider)
    }

    /// A snapshot of a live ball at the current time.
    #[must_use]
    pub fn ball(&self, handle: BallHandle) -> Option<Ball> {
        self.balls
            .get(handle)
            .map(|(k, p)| self.snapshot(handle.index, k, p))
    }

    /// The ball's closed-form path since its last event: its position at any time `t` up to its
    /// next event is `trajectory.position_at(t, world.ball_acceleration(handle))`.
    #[must_use]
    pub fn ball_trajectory(&self, handle: BallHandle) -> Option<Trajectory> {
        self.balls.get(handle).map(|(k, _)| k.trajectory)
    }

    /// What the rounding of the ball's trajectory's `p0` left out of its position when it was
    /// last restated, under half a unit in the last place of each coordinate: the next
    /// restatement adds it back, so that motion too small to show in one restatement is not
    /// lost (ARCHITECTURE.md, "The frozen component"). Zero in a world that has never had
    /// gravity or a table, whose paths are restated by rounding alone.
    #[must_use]
    pub fn ball_position_residual(&self, handle: BallHandle) -> Option<DVec2> {
        self.balls
            .get(handle)
            .map(|_| self.balls.residual(handle.index))
    }

    /// The ball's acceleration: the world's gravity, or, while it rests or slides on a
    /// collider, gravity without the part the collider holds (zero on a level floor or in a
    /// wedge).
    #[must_use]
    pub fn ball_acceleration(&self, handle: BallHandle) -> Option<DVec2> {
        self.balls
            .get(handle)
            .map(|_| self.acceleration(handle.index))
    }

    /// The collider a ball rests or slides on, and the feature it touches, if any: a ball
    /// that touches a solid collider under gravity without moving off it comes to rest on it
    /// (see `ARCHITECTURE.md`, resting contact).
    ///
    /// A ball resting on a sleeping ball has no collider support: see
    /// [`ball_holders`](Self::ball_holders). Nor has a ball on a table's cloth (see
    /// [`World::set_table`]).
    #[must_use]
    pub fn ball_support(&self, handle: BallHandle) -> Option<(ColliderHandle, Feature)> {
        let (_, properties) = self.balls.get(handle)?;
        if !self.balls.is_supported(handle.index) {
            return None;
        }
        properties
            .extra
            .support()
            .filter(|s| s.collider != NO_COLLIDER && !self.is_proxy(s.collider.index))
            .map(|s| (s.collider, s.feature))
    }

    /// Whether a ball sleeps: at rest on colliders and sleeping balls, it costs no events
    /// until something wakes it (see `ARCHITECTURE.md`, sleeping balls). `false` for a handle
    /// that is not live.
    #[must_use]
    pub fn ball_asleep(&self, handle: BallHandle) -> bool {
        self.balls.get(handle).is_some() && self.is_asleep(handle.index)
    }

    /// When a sleeping ball fell asleep; `None` if it is awake (or not live).
    #[must_use]
    pub fn ball_asleep_since(&self, handle: BallHandle) -> Option<f64> {
        let (_, properties) = self.balls.get(handle)?;
        properties.extra.sleep().map(|s| s.since.seconds())
    }

    /// What holds a ball against gravity: for a sleeping ball, the colliders and sleeping
    /// balls it rests on and against; for an awake ball resting or sliding on something, its
    /// support (and the second surface of a wedge); empty for a ball in flight (or a ball a
    /// group of balls holds, or a ball on a table's cloth). `None` if the handle is not live.
    #[must_use]
    pub fn ball_holders(&self, handle: BallHandle) -> Option<Vec<Body>> {
        let (_, properties) = self.balls.get(handle)?;
        if let Some(sleep) = properties.extra.sleep() {
            return Some(
                sleep
                    .contacts
                    .iter()
                    .map(|&(h, _)| self.body_of(h))
                    .collect(),
            );
        }
        let support = properties
            .extra
            .support()
            .filter(|s| self.balls.is_supported(handle.index) && s.collider != NO_COLLIDER);
        Some(support.map_or_else(Vec::new, |s| {
            std::iter::once(s.collider)
                .chain(s.wedge)
                .map(|h| self.body_of(h))
                .collect()
        }))
    }

    /// How many balls sleep.
    #[must_use]
    pub fn sleeping_count(&self) -> usize {
        self.sleepers.count()
    }

    /// Whether balls at rest may fall asleep (see [`ball_asleep`](Self::ball_asleep)): off by
    /// default. Off, a ball at rest on colliders still costs no events, but balls never rest
    /// on balls and a slow slide on a level floor goes on for ever, exactly; turning it off
    /// wakes every sleeping ball. On a table (see [`World::set_table`]) it changes nothing:
    /// balls there stop by the cloth's friction.
    pub fn set_sleeping(&mut self, sleeping: bool) {
        self.sleeping = sleeping;
        if !sleeping {
            self.instant.forget();
            let all: Vec<u32> = self.balls.iter().map(|(i, _, _)| i).collect();
            for index in all {
                self.wake(index);
            }
        }
    }

    /// Whether balls at rest may fall asleep (see [`set_sleeping`](Self::set_sleeping)).
    #[must_use]
    pub fn sleeping(&self) -> bool {
        self.sleeping
    }

    /// Sets the uniform gravity from now on (with a table, only zero: see
    /// [`World::set_table`]). Every ball is restated now and moves on under the
    /// new gravity: sleeping balls wake, supported balls are lifted off their supports, groups
    /// let go; each settles (and sleeps) again at once where it still rests.
    ///
    /// # Errors
    /// [`WorldError::NotFinite`] if `gravity` is not finite.
    pub fn set_gravity(&mut self, gravity: DVec2) -> Result<(), WorldError> {
        check_finite(gravity, "gravity")?;
        if self.table.is_some() && gravity != DVec2::ZERO {
            return Err(WorldError::TableAndGravity);
        }
        if self.periodic.is_some() && gravity != DVec2::ZERO {
            return Err(WorldError::PeriodicWith("gravity"));
        }
        self.instant.forget();
        let all: Vec<u32> = self.balls.iter().map(|(i, _, _)| i).collect();
        for &index in &all {
            self.wake(index);
        }
        while let Some(group) = self.groups.first().map(|g| g.id) {
            self.let_go(group);
        }
        let time = self.time;
        for &index in &all {
            let acceleration = self.acceleration(index);
            self.balls.rebase(index, time, acceleration);
            if self.balls.is_supported(index) {
                self.balls.set_support(index, None, self.time);
            }
        }
        self.gravity = gravity;
        if gravity != DVec2::ZERO {
            self.balls.carry_residuals();
        }
        for &index in &all {
            self.trajectory_changed(index);
        }
        Ok(())
    }

    /// The sensors a ball overlaps now, in the order it entered them.
    #[must_use]
    pub fn ball_sensors(&self, handle: BallHandle) -> Option<&[ColliderHandle]> {
        self.balls.get(handle).map(|(_, p)| p.extra.sensors())
    }

    /// Every live ball at the current time, in slot order.
    pub fn balls(&self) -> impl Iterator<Item = (BallHandle, Ball)> + '_ {
        self.balls
            .iter()
            .map(|(i, k, p)| (self.balls.handle(i), self.snapshot(i, k, p)))
    }

    /// The number of live balls.
    #[must_use]
    pub fn ball_count(&self) -> usize {
        self.balls.len()
    }

    /// A live collider.
    #[must_use]
    pub fn collider(&self, handle: ColliderHandle) -> Option<&Collider> {
        if self.sleeper_of(handle).is_some() {
            return None;
        }
        self.colliders.get(handle)
    }

    /// Every live collider, in slot order (sleeping balls are balls, not colliders).
    pub fn colliders(&self) -> impl Iterator<Item = (ColliderHandle, &Collider)> {
        self.colliders
            .iter()
            .filter(|(h, _)| !self.is_proxy(h.index))
    }

    /// The number of live colliders.
    #[must_use]
    pub fn collider_count(&self) -> usize {
        self.colliders.len() - self.sleepers.count()
    }

    fn snapshot(&self, index: u32, k: &Kinematics, p: &Properties) -> Ball {
        let acceleration = self.acceleration(index);
        let spin = self.balls.spin(index).copied().unwrap_or(Spin::STILL);
        let position = k.trajectory.position_at(self.time, acceleration);
        let (mass, restitution) = self.balls.mass_and_restitution(index).expect("a live ball");
        Ball {
            position: self.grid.torus().map_or(position, |t| t.reported(position)),
            velocity: k.trajectory.velocity_at(self.time, acceleration),
            radius: k.radius,
            mass,
            restitution,
            groups: p.groups,
            user_data: p.user_data,
            spin: spin.omega_at(self.time),
            roll: roll_of(spin.roll_at(self.time), k.radius),
            angle: spin.angle_at(self.time),
            inertia: spin.inertia,
            friction: spin.roughness.friction,
            tangential_restitution: spin.roughness.tangential_restitution,
            rolling_resistance: spin.roughness.rolling_resistance,
        }
    }

    /// The ball's trajectory changed: other balls' predictions against it are out of date,
    /// and its own prediction is redone.
    pub(crate) fn trajectory_changed(&mut self, index: u32) {
        self.balls.bump_version(index);
        self.schedule(index);
    }

    /// Whether the machinery of rest under gravity is on (sleeping balls, groups, resting
    /// pairs, see `pipeline/sleep.rs`): with sleeping on, except on a table, where balls stop
    /// by the cloth's friction and nothing pulls them in the plane.
    pub(crate) fn resting(&self) -> bool {
        self.sleeping && self.table.is_none()
    }

    /// Ball `index`'s acceleration now.
    #[inline]
    pub(crate) fn acceleration(&self, index: u32) -> DVec2 {
        self.balls.acceleration(index, self.gravity)
    }

    /// Lifts ball `index` off its support now: it moves on freely under gravity (and settles
    /// again at once if it still rests on something).
    pub(crate) fn release(&mut self, index: u32) {
        let (time, acceleration) = (self.time, self.acceleration(index));
        self.balls.rebase(index, time, acceleration);
        self.set_support(index, None);
        self.schedule(index);
    }
}

fn check_finite(v: DVec2, what: &'static str) -> Result<(), WorldError> {
    if v.is_finite() {
        Ok(())
    } else {
        Err(WorldError::NotFinite(what))
    }
}

fn check_positive(x: f64, error: fn(f64) -> WorldError) -> Result<(), WorldError> {
    if x > 0.0 && x.is_finite() {
        Ok(())
    } else {
        Err(error(x))
    }
}

/// A new ball's spin, checked: finite spin, inertia in `(0, 1]`, a valid roughness.
fn check_spin(desc: &BallDesc, now: Time) -> Result<Spin, WorldError> {
    if !desc.spin.is_finite() {
        return Err(WorldError::NotFinite("ball spin"));
    }
    if !(desc.inertia > 0.0 && desc.inertia <= 1.0) {
        return Err(WorldError::InvalidInertia(desc.inertia));
    }
    check_roughness(desc.friction, desc.tangential_restitution)?;
    check_resistance(desc.rolling_resistance)?;
    check_finite(desc.roll, "ball roll")?;
    Ok(Spin {
        t0: now,
        angle: 0.0,
        omega: desc.spin,
        alpha: 0.0,
        roll: contact_velocity(desc.roll, desc.radius),
        roll_rate: DVec2::ZERO,
        inertia: desc.inertia,
        roughness: Roughness {
            friction: desc.friction,
            tangential_restitution: desc.tangential_restitution,
            rolling_resistance: desc.rolling_resistance,
        },
    })
}

fn check_roughness(friction: f64, tangential_restitution: f64) -> Result<(), WorldError> {
    if !(friction >= 0.0 && friction.is_finite()) {
        return Err(WorldError::InvalidFriction(friction));
    }
    if !(-1.0..=1.0).contains(&tangential_restitution) {
        return Err(WorldError::InvalidTangentialRestitution(
            tangential_restitution,
        ));
    }
    Ok(())
}

fn check_resistance(c: f64) -> Result<(), WorldError> {
    if c >= 0.0 && c.is_finite() {
        Ok(())
    } else {
        Err(WorldError::InvalidRollingResistance(c))
    }
}

fn check_restitution(e: f64) -> Result<(), WorldError> {
    if (0.0..=1.0).contains(&e) {
        Ok(())
    } else {
        Err(WorldError::InvalidRestitution(e))
    }
}

fn build_shape(desc: ShapeDesc) -> Result<Shape, WorldError> {
    match desc {
        ShapeDesc::Segment { a, b } => {
            check_finite(a, "segment end point")?;
            check_finite(b, "segment end point")?;
            Segment::new(a, b)
                .map(Shape::Segment)
                .ok_or(WorldError::DegenerateSegment)
        }
        ShapeDesc::Circle { center, radius } => {
            check_finite(center, "circle centre")?;
            check_positive(radius, WorldError::InvalidRadius)?;
            Ok(Shape::Circle(
                Circle::new(center, radius).ok_or(WorldError::InvalidRadius(radius))?,
            ))
        }
    }
}

/// The gap between a ball and a shape, and the contact distance it is measured against.
fn gap(shape: &Shape, center: DVec2, radius: f64) -> (f64, f64) {
    match shape {
        Shape::Segment(s) => (s.distance(center) - radius, radius),
        Shape::Circle(c) => (
            center.distance(c.center) - c.radius - radius,
            c.radius + radius,
        ),
    }
}

/// Whether a ball strictly overlaps a shape (sensor membership).
pub(crate) fn overlaps(shape: &Shape, center: DVec2, radius: f64) -> bool {
    gap(shape, center, radius).0 < 0.0
}

/// Whether a ball overlaps a shape deeper than the tolerance (placement validation).
fn overlaps_deeply(shape: &Shape, center: DVec2, radius: f64) -> bool {
    let (gap, reach) = gap(shape, center, radius);
    gap < -OVERLAP_TOLERANCE * reach
}
