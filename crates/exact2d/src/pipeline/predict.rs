//! Predicting a ball's next event: the earliest over every partner it could meet.
//!
//! This is the only place that chooses candidate partners, and it asks the broad phase
//! ([`crate::broad`]) for them: the balls of the ball's 3 x 3 block of cells, and the colliders
//! listed in the cells its path crosses, walked in time order until the walk is past the
//! earliest contact found. The broad phase never drops a partner that could be first, so the
//! result is the same as trying every body (the brute-force reference test checks this event
//! for event, bit for bit).
//!
//! # Predictions are pure
//!
//! A candidate's time depends only on the current trajectories of the bodies involved, never on
//! when it is computed: a ball against a collider is solved from the ball's own `t0`, a pair of
//! balls from the later of their two `t0`s, with the other ball's state evaluated there. So the
//! same pair predicted from either ball, or predicted again later, gives the same bits, and a
//! brute-force reference that re-predicts everything after every event reproduces the engine's
//! event sequence exactly.
//!
//! # Unresolvable contacts
//!
//! A contact predicted a positive time `tau` after its base that the clock cannot resolve
//! (`base.resolved_after(tau)` is `None`, see [`crate::dynamics::RESOLUTION`]) is dropped, as a
//! graze would be.
//! Contacts *now* (`tau = 0`, the touching-contact policy) are always kept.

use glam::DVec2;

use super::World;
use super::group::held_together;
use super::instant::{ALWAYS, Instant, Pair};
use super::pending::{EventKey, Kind, PendingQueue, Prediction};
use super::step::{balls_touch, hop_floor, micro_hop};
use crate::broad::Place;
use crate::dynamics::{
    BallSet, Kinematics, Properties, SETTLE_HEIGHT, Support, Time, Touch, sooner, touching_gap,
};
use crate::geometry::{Collider, ColliderHandle, CollisionGroups, Feature, Shape};
use crate::toi::{
    Crossing, Motion, point_crossing, segment_crossing, time_of_impact_ball_ball,
    time_of_impact_ball_point,
};

impl World {
    /// Predicts ball `index` afresh from now: finds its earliest collision or sensor crossing,
    /// and queues the earlier of that and its next cell crossing.
    ///
    /// A ball in a cell stays registered there: it is inside the grown cell until its next
    /// crossing, which the queue handles before anything later, so its 3 x 3 block still
    /// holds every ball it can touch first. (Moving it to the cell of its centre at every
    /// prediction cost 4% of a gas's instructions and changed no event.) A far ball moves
    /// into the cell where it is, if the cells cover it now.
    pub(crate) fn schedule(&mut self, index: u32) {
        // On a table a ball that moves or turns is on the cloth, in its phase.
        if self.table.is_some() {
            self.lay_on_table(index);
        }
        let Some(ball) = self.balls.kinematics(index) else {
            return;
        };
        // A sleeping ball has no events (it is a circle to the others).
        if ball.is_supported() && self.is_asleep(index) {
            return;
        }
        // In a periodic box a ball on an edge and moving out wraps first.
        let ball = if self.periodic.is_some() {
            self.wrap_now(index);
            self.balls.kinematics(index).expect("live ball")
        } else {
            ball
        };
        if self.grid.place(index) == Place::Far {
            let acceleration = self.balls.acceleration(index, self.gravity);
            let p = ball.trajectory.position_at(self.time, acceleration);
            let place = self.grid.place_of(p);
            self.register_in_grid(index, place);
        }
        let best = self.predict_near(index);
        let (crossing, bound) = self.crossing_and_bound(index, self.time, best);
        let prediction = self.search_colliders(index, bound, best);
        self.queue_crossing(index, self.time, prediction, crossing);
    }

    /// Ball `index`'s next cell crossing after `from`, and how far along its path its
    /// colliders need searching (see [`Self::static_bound`]), given `best`, its earliest event
    /// found so far.
    ///
    /// A ball on a straight path that is well inside its grown cell at `from` and at `best`
    /// stays inside in between (the cell is convex), so it cannot cross before `best`: its
    /// crossing would never be handled (`best`, or the prediction again that replaces it,
    /// comes first), and it is not computed (`None`). The search then stops at `best`, where
    /// it would stop anyway.
    #[inline]
    fn crossing_and_bound(
        &self,
        index: u32,
        from: Time,
        best: Option<Prediction>,
    ) -> (Option<Time>, Time) {
        if let Some(until) = best.map(|b| b.key.time) {
            if self.stays_in_cell(index, from, until) {
                return (None, until);
            }
        }
        let crossing = self.next_crossing(index, from);
        (crossing, self.static_bound(index, from, crossing))
    }

    /// Whether ball `index`, in a cell of the ball grid and on a straight path, is inside its
    /// grown cell, with room for rounding, at `from` and at `until`.
    fn stays_in_cell(&self, index: u32, from: Time, until: Time) -> bool {
        // Straight: no gravity (without it no ball is supported either).
        if self.gravity != DVec2::ZERO || self.balls.is_supported(index) {
            return false;
        }
        let (Some(cell), Some(ball)) = (self.grid.cell_box(index), self.balls.kinematics(index))
        else {
            return false;
        };
        // Far more room than the rounding of these positions and of the crossing's own
        // computation, which would otherwise decide a path along the border differently.
        let inner = cell.inflated_relative(-1e-9);
        let inside = |t: Time| inner.contains_point(ball.trajectory.position_at(t, DVec2::ZERO));
        inside(from) && inside(until)
    }

    /// Registers ball `index` at `place` in the ball grid; if that moved it into a new cell,
    /// records whether any collider is within reach of that cell (a ball that stays in it can
    /// then skip its search for colliders, see [`Self::static_prediction`]).
    pub(crate) fn register_in_grid(&mut self, index: u32, place: Place) {
        let radius = self.balls.kinematics(index).map_or(0.0, |b| b.radius);
        if self.grid.register_sized(index, place, radius) {
            if let Some(cell) = self.grid.cell_box(index) {
                // Room for the rounding of the crossing time and of the walk's boxes.
                let near = self.statics.meets(&cell.inflated_relative(1e-9));
                self.grid.set_near_statics(index, near);
            }
        }
    }

    /// Ball `index`'s groups, for checking against a partner ball's; `None` if every two
    /// balls meet (see [`crate::broad::BallGrid::all_meet`]), so no check is needed.
    fn partner_groups(&self, index: u32) -> Option<CollisionGroups> {
        if self.grid.all_meet() {
            None
        } else {
            self.balls.properties(index).map(|p| p.groups)
        }
    }

    /// How far along its path ball `index` needs its colliders searched now, with `crossing`
    /// its next cell crossing after `from`: up to that crossing for a ball in a cell (each
    /// crossing searches on to the next, see [`Self::cross`]), so the search stays inside the
    /// cell, where the ball spends most of its time in a dense scene; the whole path otherwise.
    fn static_bound(&self, index: u32, from: Time, crossing: Option<Time>) -> Time {
        match (self.grid.place(index), crossing) {
            (Place::Cell(..), Some(c)) if c > from => c,
            _ => Time::new(f64::INFINITY),
        }
    }

    /// Handles ball `index`'s cell crossing at `time`: registers it in its new cell, adds the
    /// balls that just became its neighbours to its prediction, and queues its next event.
    pub(crate) fn cross(&mut self, index: u32, time: Time) {
        // In a periodic box, a ball leaving through an edge wraps: predicted afresh.
        if self.periodic.is_some() && self.wrap_at_crossing(index, time) {
            return;
        }
        let p = self
            .balls
            .kinematics(index)
            .expect("live ball")
            .trajectory
            .position_at(time, self.balls.acceleration(index, self.gravity));
        let old = self.grid.place(index);
        let place = self.grid.place_of(p);
        self.register_in_grid(index, place);
        let ball = self.balls.kinematics(index).expect("live ball");
        let groups = self.partner_groups(index);
        let mut best = self.queue.physical(index);
        let now = self.time;
        // (Outside a periodic box every shift is zero.)
        self.grid.new_neighbours(index, old, |other, shift| {
            let horizon = Prediction::horizon(best);
            let me = (index, ball, groups);
            let candidate = seen_prediction(self, now, self.gravity, me, (other, shift), horizon);
            best = Prediction::earlier(candidate, best);
        });
        let (crossing, bound) = self.crossing_and_bound(index, time, best);
        if matches!(old, Place::Cell(..)) {
            // Its colliders were searched up to this crossing: on to the next one.
            let start = time.since(ball.trajectory.t0).max(0.0);
            best = self.static_prediction(index, start, bound, best);
        }
        self.queue_crossing(index, time, best, crossing);
    }

    /// Queues ball `index`'s earliest collision or sensor crossing, `physical`, with its next
    /// cell crossing after `from`; the queue orders the ball by the earlier of the two.
    ///
    /// A crossing the clock cannot place after `from` (a ball so slow, at a time so large,
    /// that its next crossing rounds to now) would be handled again and again at the same
    /// instant. Such a ball leaves the cells for the far list, where it needs no crossing to
    /// meet anyone: it is predicted again against every ball, and every ball predicted from
    /// then on checks it.
    pub(crate) fn queue_pending(&mut self, index: u32, from: Time, physical: Option<Prediction>) {
        let crossing = self.next_crossing(index, from);
        self.queue_crossing(index, from, physical, crossing);
    }

    /// [`Self::queue_pending`] with the ball's next crossing after `from` already found.
    fn queue_crossing(
        &mut self,
        index: u32,
        from: Time,
        physical: Option<Prediction>,
        crossing: Option<Time>,
    ) {
        let stalled = crossing.is_some_and(|c| c <= from);
        // (A periodic box has no far list: such a ball keeps its cell, without a crossing.)
        if stalled && matches!(self.grid.place(index), Place::Cell(..)) && self.periodic.is_none() {
            self.register_in_grid(index, Place::Far);
            let physical = self.predict(index, Time::new(f64::INFINITY));
            let crossing = self.next_crossing(index, from).filter(|&c| c > from);
            self.queue.set(index, physical, crossing);
        } else {
            // A far ball whose return the clock cannot place simply stays far.
            self.queue
                .set(index, physical, crossing.filter(|_| !stalled));
        }
    }

    /// Ball `index`'s next cell crossing after `from` (for a far ball, its next chance of
    /// coming back into the cells), if any.
    fn next_crossing(&self, index: u32, from: Time) -> Option<Time> {
        // Balls outside the ball grid (every ball of a brick breaker) never cross.
        if self.grid.place(index) == Place::Absent {
            return None;
        }
        let trajectory = self.balls.kinematics(index).expect("live ball").trajectory;
        let base = trajectory.t0;
        let motion = trajectory.motion_at(base, self.balls.acceleration(index, self.gravity));
        let tau = self
            .grid
            .crossing(index, &motion, from.since(base).max(0.0));
        tau.is_finite().then(|| base.after(tau).max(self.time))
    }

    /// The earliest collision or sensor crossing of ball `index`: against the balls near it
    /// first (usually the earliest, and cheap), then along its path through the static grid,
    /// as far as `bound` (see [`Self::static_bound`]).
    fn predict(&mut self, index: u32, bound: Time) -> Option<Prediction> {
        let best = self.predict_near(index);
        self.search_colliders(index, bound, best)
    }

    /// Ball `index`'s earliest event from now as far as `bound` along its path among the
    /// colliders, or `best` if earlier (see [`Self::static_prediction`]).
    #[inline]
    fn search_colliders(
        &mut self,
        index: u32,
        bound: Time,
        best: Option<Prediction>,
    ) -> Option<Prediction> {
        let Some(ball) = self.balls.kinematics(index) else {
            return best;
        };
        let start = self.time.since(ball.trajectory.t0).max(0.0);
        self.static_prediction(index, start, bound, best)
    }

    /// Ball `index`'s earliest collision among the balls near it (usually its earliest event,
    /// and cheap), or the end of its support's extent if earlier.
    fn predict_near(&mut self, index: u32) -> Option<Prediction> {
        // In a periodic box only a ball in a cell on an edge sees a partner through an image
        // (`broad/torus.rs`); the rest are predicted as in an open world.
        if self.periodic.is_some() && self.grid.on_torus_edge(index) {
            return self.predict_near_periodic(index);
        }
        let near = &mut self.near;
        near.clear();
        self.grid.near(index, |other, _| near.push(other));
        // A ball with no ball near it (every ball of a brick breaker) needs no groups.
        let groups = if self.near.is_empty() {
            None
        } else {
            self.partner_groups(index)
        };
        let ball = self.balls.kinematics(index)?;
        let (balls, now, gravity, near) = (&self.balls, self.time, self.gravity, &self.near);
        let mut best: Option<Prediction> = None;
        // First the end of a supported ball's support or phase, so that no ball is solved
        // for past it (on a table, where balls have accelerations of their own, most pairs
        // are then ruled out by a bound, `cannot_meet_by`, before their quartic).
        let base = ball.trajectory.t0;
        // A supported ball slides along its support (never predicted against: it touches it
        // all along) until it leaves its extent. (Its path is formed here only then; the
        // search for colliders forms it only if it searches.)
        if let Some((_, motion, Some(support))) = balls
            .is_supported(index)
            .then(|| path_of(balls, index, gravity))
            .flatten()
        {
            // Like a contact, a leave the clock cannot resolve (or place before the end of
            // time) is dropped: handled now, the ball would settle and leave again for ever.
            // A rough ball's phase on it ends then too (`pipeline/rolling.rs`).
            // A phase that ends sooner than the clock can tell ends now, never dropped: its
            // accelerations would go on for ever (its end snaps what ended, so the next phase
            // differs).
            let phase = support.rub.and_then(|r| r.end).map(|end| {
                let tau = end.since(base).max(0.0);
                if base.resolves(tau) { tau } else { 0.0 }
            });
            let leave = sooner(support.leave_time(&motion), phase);
            let leave = leave.and_then(|tau| base.resolved_after(tau));
            let leave = leave.map(|time| Prediction {
                key: EventKey {
                    time: time.max(now),
                    kind: Kind::Leave,
                    first: index,
                    second: support.collider.index,
                    feature: 0,
                },
                tag: support.collider.generation,
            });
            best = Prediction::earlier(leave, best);
        }
        // Every candidate's cache line is loaded once before any prediction: these loads do
        // not depend on each other, so their cache misses overlap, where inside the loop below
        // each would wait behind the previous candidate's arithmetic.
        let touched = near
            .iter()
            .fold(0u32, |acc, &other| acc ^ balls.version(other));
        std::hint::black_box(touched);
        let me = (index, ball, groups);
        if gravity.x.to_bits() | gravity.y.to_bits() == 0 {
            // Without gravity (a gas, a table seen from above) every gravity term folds away.
            best = nearest_of(best, near, |other, horizon| {
                ball_prediction(self, now, DVec2::ZERO, me, other, horizon)
            });
        } else {
            best = nearest_of(best, near, |other, horizon| {
                ball_prediction(self, now, gravity, me, other, horizon)
            });
        }
        best
    }

    /// [`Self::predict_near`] of a ball in a cell on a periodic box's edge: each partner seen
    /// through the image of its cell (`broad/torus.rs`). No ball is supported there (no
    /// gravity, no table). Out of line: most balls are off the edges.
    #[inline(never)]
    fn predict_near_periodic(&mut self, index: u32) -> Option<Prediction> {
        let mut near = std::mem::take(&mut self.near_images);
        near.clear();
        self.grid
            .near(index, |other, shift| near.push((other, shift)));
        let groups = if near.is_empty() {
            None
        } else {
            self.partner_groups(index)
        };
        let now = self.time;
        let best = self.balls.kinematics(index).and_then(|ball| {
            let me = (index, ball, groups);
            nearest_of(None, &near, |seen, horizon| {
                seen_prediction(self, now, DVec2::ZERO, me, seen, horizon)
            })
        });
        self.near_images = near;
        best
    }

    /// Ball `index`'s earliest contact or sensor crossing with a collider met along its path
    /// from `start` (relative to its trajectory's origin) to `bound`, if earlier than `best`
    /// (which is returned otherwise).
    fn static_prediction(
        &mut self,
        index: u32,
        start: f64,
        bound: Time,
        mut best: Option<Prediction>,
    ) -> Option<Prediction> {
        // Searched only up to its next crossing, a ball in a cell with no collider within
        // reach meets none.
        if bound.seconds().is_finite() && !self.grid.near_statics(index) {
            return best;
        }
        let (Some(ball), Some(properties)) =
            (self.balls.kinematics(index), self.balls.properties(index))
        else {
            return best;
        };
        let now = self.time;
        let Some((base, motion, support)) = path_of(&self.balls, index, self.gravity) else {
            return best;
        };
        let acceleration = motion.acceleration;
        let bound = relative(bound, base);
        let horizon = |best: Option<Prediction>| {
            best.map_or(f64::INFINITY, |b| relative(b.key.time, base))
                .min(bound)
        };
        let colliders = &self.colliders;
        let closures = Closures {
            instant: &self.instant,
            born: &self.collider_born,
        };
        self.statics.walk(&motion, start, horizon(best), |slot| {
            if let Some((handle, collider)) = colliders.at(slot) {
                // While pivoting onto the next segment, whose end point is the pivot, the
                // ball passes its tangent points at exactly the contact distance: grazes.
                // A segment coincident with the support (the same line, touched from the same
                // side) holds the ball just as well: predicted against, it would be grazed.
                let holding = support.is_some_and(|s| {
                    s.collider == handle
                        || properties.extra.touching().contains(&handle)
                        || s.wedge == Some(handle)
                        || s.next.is_some_and(|n| n.collider == handle)
                        || s.from == Some(handle)
                        || s.ends.contains(&Some(handle))
                        || (s.pivot.is_none()
                            && coincident(&collider.shape, s.normal, motion.position, ball.radius))
                });
                if !holding && collider.groups.interact(properties.groups) {
                    let horizon = best.map_or(Time::new(f64::INFINITY), |b| b.key.time);
                    let me = (index, ball, properties);
                    let motion = (acceleration, support);
                    let candidate =
                        collider_candidate(me, handle, collider, motion, &closures, horizon)
                            // A contact before now may be one before the collider was added.
                            .and_then(|key| {
                                if key.time < now {
                                    since_born(
                                        key, me, handle, collider, motion, &closures, horizon,
                                    )
                                } else {
                                    Some(key)
                                }
                            })
                            .map(|key| Prediction {
                                key: EventKey {
                                    time: key.time.max(now),
                                    ..key
                                },
                                tag: handle.generation,
                            });
                    best = Prediction::earlier(candidate, best);
                }
            }
            horizon(best)
        });
        best
    }

    /// Ball `index` against one collider: see [`collider_candidate`].
    pub(crate) fn collider_candidate(
        &self,
        index: u32,
        handle: ColliderHandle,
        collider: &Collider,
        horizon: Time,
    ) -> Option<EventKey> {
        let ball = self.balls.kinematics(index)?;
        let properties = self.balls.properties(index)?;
        let me = (index, ball, properties);
        let acceleration = self.balls.acceleration(index, self.gravity);
        let support = if self.balls.is_supported(index) {
            properties.extra.support()
        } else {
            None
        };
        collider_candidate(
            me,
            handle,
            collider,
            (acceleration, support),
            &Closures {
                instant: &self.instant,
                born: &self.collider_born,
            },
            horizon,
        )
    }
}

/// What a collider's contact at a ball's origin is closed by (see [`Instant::is_closed`]).
struct Closures<'a> {
    /// The records of the current chain.
    instant: &'a Instant,
    /// When each collider was added, by slot ([`World::collider_born`]).
    born: &'a [Time],
}

/// When the collider in slot `index` was added, from `born` ([`World::collider_born`]).
#[inline]
fn born_at(born: &[Time], index: u32) -> Time {
    born.get(index as usize).copied().unwrap_or(Time::ZERO)
}

/// Ball `index`'s trajectory origin, its motion from there (under its support's acceleration
/// if it has one, else gravity's), and its support.
fn path_of(
    balls: &BallSet,
    index: u32,
    gravity: DVec2,
) -> Option<(Time, Motion, Option<&Support>)> {
    let ball = balls.kinematics(index)?;
    let base = ball.trajectory.t0;
    let motion = ball
        .trajectory
        .motion_at(base, balls.acceleration(index, gravity));
    let support = if balls.is_supported(index) {
        balls.properties(index)?.extra.support()
    } else {
        None
    };
    Some((base, motion, support))
}

/// Ball `index` against ball `other` (if they interact: `groups` are ball `index`'s, `None`
/// if every two balls do), as a prediction no later than `horizon` (ties kept): the absolute time
/// of their next contact, solved from the later of their two trajectory origins, keyed (and,
/// for a supported pair, solved) with the smaller slot index first, so the result does not
/// depend on which ball asks.
#[inline(always)]
fn ball_prediction(
    world: &World,
    now: Time,
    gravity: DVec2,
    (index, ball, groups): (u32, &Kinematics, Option<CollisionGroups>),
    other: u32,
    horizon: Time,
) -> Option<Prediction> {
    let partner = world.balls.kinematics(other)?;
    pair_prediction(
        world,
        now,
        gravity,
        (index, ball, groups),
        (other, partner),
        horizon,
    )
}

/// The earliest of `best` and `predict(other, horizon)` over the balls `near` (ties kept), the
/// horizon the earliest so far: kept as a time beside `best`, so a candidate that meets
/// nothing (most of them) copies no prediction.
#[inline(always)]
fn nearest_of<T: Copy>(
    mut best: Option<Prediction>,
    near: &[T],
    mut predict: impl FnMut(T, Time) -> Option<Prediction>,
) -> Option<Prediction> {
    let mut horizon = Prediction::horizon(best);
    for &other in near {
        if let Some(candidate) = predict(other, horizon) {
            if best.is_none_or(|b| candidate.key < b.key) {
                horizon = candidate.key.time;
                best = Some(candidate);
            }
        }
    }
    best
}

/// [`ball_prediction`] of a partner seen through the image moved by `shift` (zero: the
/// partner itself, as everywhere outside a periodic box's edge cells).
#[inline(always)]
fn seen_prediction(
    world: &World,
    now: Time,
    gravity: DVec2,
    me: (u32, &Kinematics, Option<CollisionGroups>),
    (other, shift): (u32, DVec2),
    horizon: Time,
) -> Option<Prediction> {
    if shift == DVec2::ZERO {
        ball_prediction(world, now, gravity, me, other, horizon)
    } else {
        image_prediction(world, now, me, other, shift, horizon)
    }
}

/// [`ball_prediction`] of a partner seen through a periodic box's image moved by `shift`.
/// Of the two, the ball of the larger slot index is the one moved (its path's origin, by
/// `shift` or `-shift`: `k L`, exact in `k`; the sum rounded once), as at their event
/// (`World::collide_pair`): the pair's time is then the same bits whichever ball asks.
/// Out of line: only balls near an edge ask.
#[inline(never)]
fn image_prediction(
    world: &World,
    now: Time,
    (index, ball, groups): (u32, &Kinematics, Option<CollisionGroups>),
    other: u32,
    shift: DVec2,
    horizon: Time,
) -> Option<Prediction> {
    let partner = world.balls.kinematics(other)?;
    if index < other {
        let mut partner = partner.clone();
        partner.trajectory.p0 += shift;
        pair_prediction(
            world,
            now,
            DVec2::ZERO,
            (index, ball, groups),
            (other, &partner),
            horizon,
        )
    } else {
        let mut ball = ball.clone();
        ball.trajectory.p0 -= shift;
        pair_prediction(
            world,
            now,
            DVec2::ZERO,
            (index, &ball, groups),
            (other, partner),
            horizon,
        )
    }
}

/// [`ball_prediction`] with the partner's kinematics given.
#[inline(always)]
fn pair_prediction(
    world: &World,
    now: Time,
    gravity: DVec2,
    (index, ball, groups): (u32, &Kinematics, Option<CollisionGroups>),
    (other, partner): (u32, &Kinematics),
    horizon: Time,
) -> Option<Prediction> {
    // One pointer for the world, not one per part: the loop over candidates keeps its
    // registers for the arithmetic.
    let balls = &world.balls;
    // The later origin (equal origins are the same bits, so either ball may be asked first).
    let base = ball.trajectory.t0.max(partner.trajectory.t0);
    let t = if ball.is_supported() || partner.is_supported() {
        supported_candidate(
            world,
            gravity,
            (index, ball),
            (other, partner),
            base,
            horizon,
        )?
    } else {
        // Both under gravity: their relative motion is straight, a quadratic. Its solution,
        // and the zero-time chain rule below, are the same bits with the balls swapped (see
        // `time_of_impact_ball_ball`), so the pair needs no ordering here.
        let (p1, v1) = state(ball, base, gravity);
        let (p2, v2) = state(partner, base, gravity);
        let t = time_of_impact_ball_ball(
            p1,
            v1,
            ball.radius,
            p2,
            v2,
            partner.radius,
            relative(horizon, base),
        )?;
        // Touching and approaching, or touching and meeting sooner than the clock can tell
        // from now: a contact now (dropped as unresolved, the second let the pair pass into
        // each other).
        let reach = ball.radius + partner.radius;
        let t = if t > 0.0
            && (touching_now(p1, v1, p2, v2, reach)
                || (!base.resolves(t) && touches(p1, p2, reach)))
        {
            0.0
        } else {
            t
        };
        // A contact at the base between balls whose last events were at the same instant (a
        // zero-time chain), approaching by less than the rounding of their velocities, is
        // tangential: in a cluster of touching inelastic balls moving together, the impulses
        // of such a chain are too small for the velocities to hold, and it would go round
        // without end. One closed at this instant, resolved with its jam, is sought again
        // only deeper (see `closed_depth`).
        if t == 0.0 {
            zero_time_contact(
                world,
                (index, ball, p1, v1),
                (other, partner, p2, v2),
                base,
                relative(horizon, base),
            )?
        } else {
            t
        }
    };
    let time = base.resolved_after(t)?;
    // The groups live in the other half of the slot: they are read only for a contact, which
    // most candidates do not have, and only if some two balls do not meet.
    if let Some(groups) = groups {
        if !balls.properties(other)?.groups.interact(groups) {
            return None;
        }
    }
    Some(Prediction {
        key: EventKey {
            time: time.max(now),
            kind: Kind::BallContact,
            first: index.min(other),
            second: index.max(other),
            feature: 0,
        },
        tag: balls.version(other),
    })
}

/// [`ball_prediction`] of two balls of which one at least is supported: the time of their
/// contact from `base`, if any before `horizon`. Out of line: a gas never asks.
#[inline(never)]
fn supported_candidate(
    world: &World,
    gravity: DVec2,
    (index, ball): (u32, &Kinematics),
    (other, partner): (u32, &Kinematics),
    base: Time,
    horizon: Time,
) -> Option<f64> {
    let balls = &world.balls;
    // Two balls held by one group keep their contact for as long as it holds them (see
    // `pipeline/group.rs`): what their accelerations' rounding says of it is no event.
    if held_together(&world.groups, |i| balls.held_group(i), index, other) {
        return None;
    }
    let (first, second, a1, a2) = if index < other {
        let (a1, a2) = (
            balls.acceleration(index, gravity),
            balls.acceleration(other, gravity),
        );
        (ball, partner, a1, a2)
    } else {
        let (a1, a2) = (
            balls.acceleration(other, gravity),
            balls.acceleration(index, gravity),
        );
        (partner, ball, a1, a2)
    };
    let closed = || {
        world
            .instant
            .is_closed(base, Pair::balls(index, other), ALWAYS)
    };
    supported_pair_time(first, a1, second, a2, base, relative(horizon, base), closed)
}

/// Whether a contact now (at `base`) of two free balls (slot, kinematics, and position and
/// velocity at `base`, each) is tangential (no contact: `None`), closed at this instant (the
/// time, from `base`, at which they have entered each other [`closed_depth`] deeper than now,
/// if before `horizon`), or a contact now (`Some(0.0)`): see [`ball_prediction`].
///
/// A pair its jam closed approaches afterwards only if something at the same instant changed
/// one of its balls again (a settle that stopped it, a ball outside the cluster that struck
/// it): then it meets again a moment later, rather than never.
#[cold]
#[inline(never)]
fn zero_time_contact(
    world: &World,
    (index, ball, p1, v1): (u32, &Kinematics, DVec2, DVec2),
    (other, partner, p2, v2): (u32, &Kinematics, DVec2, DVec2),
    base: Time,
    horizon: f64,
) -> Option<f64> {
    if ball.trajectory.t0 == partner.trajectory.t0 && rounding_approach(p1, v1, p2, v2) {
        return None;
    }
    if !world
        .instant
        .is_closed(base, Pair::balls(index, other), ALWAYS)
    {
        return Some(0.0);
    }
    let reach = ball.radius + partner.radius;
    let coordinates = p1.abs().max(p2.abs()).max_element();
    let depth = closed_depth(reach - (p2 - p1).length(), coordinates, reach);
    time_of_impact_ball_ball(p1, v1, ball.radius, p2, v2, partner.radius - depth, horizon)
        .and_then(|t| soonest(base, t))
}

/// Whether two balls at `p1`, `p2` (contact distance `reach`) touch now, within
/// [`SNAP_ULPS`]: asked of a pair that meets sooner than the clock can tell from now, which is
/// then a contact now. (Not touching, such a contact is one the clock cannot reach at all,
/// past `1e300` seconds: it is dropped, as documented at [`crate::RESOLUTION`].)
#[cold]
#[inline(never)]
fn touches(p1: DVec2, p2: DVec2, reach: f64) -> bool {
    let coordinates = p1.abs().max(p2.abs()).max_element();
    snaps((p2 - p1).length() - reach, coordinates, reach)
}

/// Whether a ball (`motion`, `radius`) touches `collider` now, within [`SNAP_ULPS`]: asked
/// of a contact sooner than the clock can tell from now (see [`touches`]).
#[cold]
#[inline(never)]
fn touches_collider(collider: &Collider, motion: &Motion, radius: f64) -> bool {
    let p = motion.position;
    Touch::of(&collider.shape, p, radius)
        .is_some_and(|t| snaps(t.gap, p.abs().max_element(), radius))
}

/// A contact sought deeper after its jam at `t` from `base`: no sooner than the clock can
/// tell from now, so that the chain moves on; none if it is now (the bodies are deeper than
/// that already: balls of a few ulps of their coordinates, where the snapping depth is more
/// than their size, would meet again at every response).
#[cold]
#[inline(never)]
fn soonest(base: Time, t: f64) -> Option<f64> {
    if !(t > 0.0) {
        return None;
    }
    Some(if base.resolves(t) { t } else { base.shortest() })
}

/// A ball's position and velocity at `t` under `acceleration`.
#[inline]
fn state(ball: &Kinematics, t: Time, acceleration: DVec2) -> (DVec2, DVec2) {
    (
        ball.trajectory.position_at(t, acceleration),
        ball.trajectory.velocity_at(t, acceleration),
    )
}

/// The contact time, after `base` and by `horizon`, of two balls at least one of which is
/// supported (accelerations `a1`, `a2`): the first's centre relative to the second's is a
/// parabola, to meet at the summed radius like a point; or now, for a touching pair pulled
/// together that hops less than the floor (see [`hop_floor`]). The zero-time chain rule of
/// [`ball_prediction`] holds here too, but drops only the contact now: a curved relative path
/// may come back to a genuine crossing later.
fn supported_pair_time(
    first: &Kinematics,
    a1: DVec2,
    second: &Kinematics,
    a2: DVec2,
    base: Time,
    horizon: f64,
    closed: impl Fn() -> bool,
) -> Option<f64> {
    let (p1, v1) = state(first, base, a1);
    let (p2, v2) = state(second, base, a2);
    let reach = first.radius + second.radius;
    if hop_floor(p1, v1, a1, p2, v2, a2, reach)
        .is_some_and(|floor| micro_contact(p1, v1, p2, v2, reach, floor))
        && !closed()
    {
        return Some(0.0);
    }
    if cannot_meet_by((p1, p2), v2 - v1, a2 - a1, reach, horizon) {
        return None;
    }
    let motion = Motion {
        position: p1 - p2,
        velocity: v1 - v2,
        acceleration: a1 - a2,
    };
    let t = if a1 == a2 {
        time_of_impact_ball_ball(p1, v1, first.radius, p2, v2, second.radius, horizon)?
    } else {
        time_of_impact_ball_point(&motion, DVec2::ZERO, reach, Crossing::Enter, horizon)?
    };
    // As for free balls: touching and approaching, or touching and meeting sooner than the
    // clock can tell from now, is a contact now.
    let t = if t > 0.0
        && (touching_now(p1, v1, p2, v2, reach) || (!base.resolves(t) && touches(p1, p2, reach)))
    {
        0.0
    } else {
        t
    };
    let rounding =
        || first.trajectory.t0 == second.trajectory.t0 && rounding_approach(p1, v1, p2, v2);
    if t == 0.0 && a1 == a2 && rounding() {
        return None;
    }
    if (t == 0.0 && rounding()) || (Instant::within_chain(base, t) && closed()) {
        // Tangential now, but their accelerations differ, or closed at this instant: only a
        // crossing later counts, one deeper by the snapping tolerance than they are now (so a
        // pair the jam left touching but pulled together meets again as soon as it has
        // entered that much, and never passes through; and so does one that something at
        // this instant set approaching again after its jam).
        let coordinates = p1.abs().max(p2.abs()).max_element();
        let depth = closed_depth(reach - (p2 - p1).length(), coordinates, reach);
        return point_crossing(
            &motion,
            DVec2::ZERO,
            reach - depth,
            Crossing::Enter,
            horizon,
            false,
            |t| t > 0.0,
        )
        .and_then(|t| soonest(base, t));
    }
    Some(t)
}

/// Whether two balls at `p1`, `p2` (relative velocity `v`, relative acceleration `a`, contact
/// distance `reach`), apart, cannot touch by `horizon`: their gap closes no faster than
/// `|v| t + |a| t^2 / 2`, so not before `2 gap / (|v| + sqrt(|v|^2 + 2 |a| gap))` (that sum's
/// root, without cancellation). A bound past the horizon, with room for rounding, rules the
/// pair out before its quartic is solved: most pairs on a table, where every ball has an
/// acceleration of its own. So does a gap that stays clear of zero along the line of centres
/// ([`least_gap`]): a pile's neighbours a hair apart, sliding past each other or parting
/// (the 400-ball pile to t = 1.8: 3.2 million quartics where 5.7 million, and none of those it
/// rules out had a contact before the horizon, solved beside it; most of those left are the
/// dear ones, with a contact to refine: 1.4 % fewer instructions on a 100-ball pile). A pair
/// it keeps is solved as before, so no prediction changes.
#[inline]
fn cannot_meet_by((p1, p2): (DVec2, DVec2), v: DVec2, a: DVec2, reach: f64, horizon: f64) -> bool {
    let d = p2 - p1;
    let distance = d.length();
    let gap = distance - reach;
    let coordinates = p1.abs().max(p2.abs()).max_element();
    // Touching (within the snapping and micro-hop distances), the rules of a contact now
    // apply, whatever the horizon.
    if !horizon.is_finite() || balls_touch(gap, coordinates, reach) {
        return false;
    }
    let (speed, pull) = (v.length(), a.length());
    let soonest = 2.0 * gap / (speed + (speed * speed + 2.0 * pull * gap).sqrt());
    if soonest * (1.0 - 1e-9) > horizon {
        return true;
    }
    // Along the line of centres: the distance is at least its part along the first line of
    // centres, so the gap is at least `gap + u t + w t^2 / 2`, `u` and `w` the relative
    // velocity's and acceleration's parts along it. Its least value up to the horizon, clear
    // of zero by far more than its rounding, rules the pair out (balls sliding past each
    // other, or parting, whatever their speed).
    let along = d / distance;
    let least = least_gap(gap, v.dot(along), a.dot(along), horizon);
    least > 1e-9 * reach + 64.0 * f64::EPSILON * (coordinates + reach)
}

/// The least of `gap + u t + w t^2 / 2` over `0 <= t <= horizon`, a finite horizon: at an
/// end, or at the turning point between them.
#[inline]
fn least_gap(gap: f64, u: f64, w: f64, horizon: f64) -> f64 {
    debug_assert!(horizon.is_finite());
    let least = gap.min(gap + u * horizon + 0.5 * w * horizon * horizon);
    if w > 0.0 && u < 0.0 && -u / w < horizon {
        least.min(gap - u * u / (2.0 * w))
    } else {
        least
    }
}

/// Whether balls at `p1`, `p2` (velocities `v1`, `v2`, contact distance `reach`) touch now,
/// to within [`SNAP_ULPS`], and approach each other: a contact now, as for a collider.
#[inline]
fn touching_now(p1: DVec2, v1: DVec2, p2: DVec2, v2: DVec2, reach: f64) -> bool {
    let q = p2 - p1;
    if !(q.dot(v2 - v1) < 0.0) {
        return false;
    }
    // Most pairs with a contact ahead are far apart: squared distances rule them out
    // before the root is taken.
    let coordinates = p1.abs().max(p2.abs()).max_element();
    let limit = reach + 2.0 * SNAP_ULPS * f64::EPSILON * (coordinates + reach);
    if q.length_squared() > limit * limit {
        return false;
    }
    let gap = q.length() - reach;
    snaps(gap, coordinates, reach) && touching_gap(gap, coordinates, reach)
}

/// Whether balls at `p1`, `p2` approach each other (with `v1`, `v2`) by no more than the
/// rounding error of their relative velocity.
fn rounding_approach(p1: DVec2, v1: DVec2, p2: DVec2, v2: DVec2) -> bool {
    let q = p2 - p1;
    let approach = -q.dot(v2 - v1);
    approach <= 4.0 * f64::EPSILON * q.length() * (v1.length() + v2.length())
}

/// Whether two balls (`p1`, `v1`; `p2`, `v2`; contact distance `reach`) touch within their
/// micro-hop ([`micro_hop`]) and separate slower than half `floor` (so their hop would be
/// under a quarter of the floor's): see [`hop_floor`].
fn micro_contact(p1: DVec2, v1: DVec2, p2: DVec2, v2: DVec2, reach: f64, floor: f64) -> bool {
    let d = p2 - p1;
    let length = d.length();
    let coordinates = p1.abs().max_element().max(p2.abs().max_element());
    let separating = (v2 - v1).dot(d) / length;
    (length - reach).abs() <= micro_hop(coordinates, reach) && separating < 0.5 * floor
}

/// A contact `key` of ball `index` with a collider met on its walk through the static grid
/// ([`collider_candidate`], solved from the ball's trajectory's origin), before now: if it is
/// before the collider was added, it is no contact (the ball's path passed the collider's
/// place while it was not there), and the first one from the collider's birth on is sought
/// instead, from the ball's state then.
///
/// A sleeping ball's circle is added where it came to rest, and only the balls near it then
/// are told of it (`World::fall_asleep`). A ball that passed that place earlier on its path,
/// or grazed it (a ball sliding past another in an exact-fit channel: rough hunt seed
/// 1029293), meets the circle later on its walk; solved from its own origin, its first
/// contact was then in the past, and taken now it was a collision at a distance.
///
/// Out of line and cold, called only for a contact before now: a second call of
/// [`collider_candidate`] inlined beside the walk's own cost a brick board 1.1 % of its
/// instructions (callgrind).
#[cold]
#[inline(never)]
fn since_born(
    key: EventKey,
    (index, ball, properties): (u32, &Kinematics, &Properties),
    handle: ColliderHandle,
    collider: &Collider,
    motion: (DVec2, Option<&Support>),
    closures: &Closures,
    horizon: Time,
) -> Option<EventKey> {
    let born = born_at(closures.born, handle.index);
    if key.time >= born {
        return Some(key);
    }
    // (`key.time` is never before the ball's origin, so the collider is the younger.)
    let mut since = ball.clone();
    since.trajectory = ball.trajectory.rebased(born, motion.0);
    collider_candidate(
        (index, &since, properties),
        handle,
        collider,
        motion,
        closures,
        horizon,
    )
}

/// Ball `index` against one collider: the next contact (solid), or the next entry or exit
/// (sensor, depending on whether the ball is inside it now), at an absolute time no later than
/// `horizon` (which is only a pruning bound: ties at `horizon` are kept). Not clamped to now.
///
/// A ball that rests on a solid collider at its base (see [`Touch::holds`]) settles on it
/// then, unless it is about to slide off a segment's end, is already held along a surface
/// with the same normal (its `support`'s: a coincident segment, which would hand it back and
/// forth), or is held by a group: the group's hold already counted every surface its members
/// touch, and a member settling alone would let the group go at the instant it formed.
///
/// A contact at the ball's origin is closed only with a collider there before it
/// (`closures`, see [`Instant::is_closed`]).
fn collider_candidate(
    (index, ball, properties): (u32, &Kinematics, &Properties),
    handle: ColliderHandle,
    collider: &Collider,
    (acceleration, support): (DVec2, Option<&Support>),
    closures: &Closures,
    horizon: Time,
) -> Option<EventKey> {
    let base = ball.trajectory.t0;
    let motion = ball.trajectory.motion_at(base, acceleration);
    // A ball on a table's cloth does not settle on a cushion: a sliding one the cloth presses
    // into a cushion it touches meets it now, and the cushion takes that pull at the bounce
    // (`World::hold_at_cushion`); a rolling one moves straight and never comes back.
    let on_table = support.and_then(|s| s.rub.filter(|r| r.table.is_some()));
    if let Some(rub) = on_table.filter(|r| !r.rolling && !collider.sensor) {
        if let Some(touch) = Touch::of(&collider.shape, motion.position, ball.radius) {
            let (p, v) = (motion.position, motion.velocity);
            if touch.holds_within(p, v, acceleration, ball.radius, rub.slack) {
                return Some(EventKey {
                    time: base,
                    kind: Kind::Contact,
                    first: index,
                    second: handle.index,
                    feature: touch.feature.rank(),
                });
            }
        }
    }
    let grouped = support.is_some_and(|s| s.held.is_some()) || on_table.is_some();
    if !collider.sensor && acceleration != DVec2::ZERO && !grouped {
        if let Some(touch) = Touch::of(&collider.shape, motion.position, ball.radius) {
            let same_line = support.is_some_and(|s| same_normal(s.normal, touch.normal));
            if !same_line
                && touch.holds(motion.position, motion.velocity, acceleration, ball.radius)
                && !slides_off_now(&collider.shape, &touch, &motion, ball.radius)
            {
                return Some(EventKey {
                    time: base,
                    kind: Kind::Settle,
                    first: index,
                    second: handle.index,
                    feature: touch.feature.rank(),
                });
            }
        }
    }
    let crossing = if collider.sensor && properties.extra.contains(handle) {
        Crossing::Exit
    } else {
        Crossing::Enter
    };
    let relative_horizon = relative(horizon, base);
    // `depth`: how much deeper than touching the crossing is sought (see below).
    let solve = |policy: bool, depth: f64| match &collider.shape {
        Shape::Segment(s) => {
            let radius = ball.radius - depth;
            let c = segment_crossing(&motion, radius, s, crossing, relative_horizon, policy)?;
            Some((c.time, Feature::from(c.feature)))
        }
        Shape::Circle(c) => {
            let reach = ball.radius + c.radius - depth;
            let t = point_crossing(
                &motion,
                c.center,
                reach,
                crossing,
                relative_horizon,
                policy,
                |_| true,
            )?;
            Some((t, Feature::Circle))
        }
    };
    let (mut tau, mut feature) = match touching_collider(collider, &motion, ball.radius) {
        Some(feature) => (0.0, feature),
        None => solve(true, 0.0)?,
    };
    // Touching now and meeting sooner than the clock can tell from now: now (dropped as
    // unresolved, the ball would pass into the collider).
    if tau > 0.0 && !base.resolves(tau) && touches_collider(collider, &motion, ball.radius) {
        tau = 0.0;
    }
    if Instant::within_chain(base, tau)
        && !collider.sensor
        && closures.instant.is_closed(
            base,
            Pair::Collider(index, handle.index),
            born_at(closures.born, handle.index),
        )
    {
        // Resolved with its jam at this instant: touching now is tangential. Only a crossing
        // later counts, and one deeper by the snapping tolerance than the ball is now: a ball
        // the jam left touching but pulled in (it could not be held) meets the surface again
        // as soon as it has entered it that much, and never passes through.
        let p = motion.position;
        let overlap = Touch::of(&collider.shape, p, ball.radius).map_or(0.0, |t| -t.gap);
        let depth = closed_depth(overlap, p.abs().max_element(), ball.radius);
        (tau, feature) = solve(false, depth)?;
        tau = soonest(base, tau)?;
    }
    Some(EventKey {
        time: base.resolved_after(tau)?,
        kind: if collider.sensor {
            Kind::Sensor
        } else {
            Kind::Contact
        },
        first: index,
        second: handle.index,
        feature: feature.rank(),
    })
}

/// How close, in units in the last place of the contact's coordinate scale (the largest
/// coordinate plus the contact distance), a gap is touching for a contact now: 8 ulps, where
/// the gap's own rounding (a few ulps) cannot tell it from zero.
///
/// Two walls of an exact-fit channel, or two balls in a box exactly two wide, are apart by
/// such a gap as often as they touch exactly; without this a ball between them would rattle
/// from one to the other at times the clock can barely tell apart (3.8e-19 s a bounce,
/// measured), where exact touching is a zero-time chain that ends (`pipeline/jam.rs`). A
/// contact taken this much early moves the ball at most this far from its exact path.
pub(crate) const SNAP_ULPS: f64 = 8.0;

/// How much deeper than touching a contact closed at this instant is next sought, for bodies
/// overlapping by `overlap` now (none if negative), at coordinates of magnitude
/// `coordinates`, contact distance `reach`: [`SNAP_ULPS`] deeper than they are.
fn closed_depth(overlap: f64, coordinates: f64, reach: f64) -> f64 {
    overlap.max(0.0) + SNAP_ULPS * f64::EPSILON * (coordinates + reach)
}

/// Whether `gap` (at coordinates of magnitude `coordinates`, contact distance `reach`) is
/// within [`SNAP_ULPS`] of touching (or overlapping).
fn snaps(gap: f64, coordinates: f64, reach: f64) -> bool {
    gap <= SNAP_ULPS * f64::EPSILON * (coordinates + reach)
}

/// The feature of a solid `collider` that a ball (`motion` from its base, `radius`) touches
/// now, to within [`SNAP_ULPS`], and approaches: a contact now, as the touching-contact policy
/// has it for a gap of zero. The ball's distance to a segment's line or to a circle's centre
/// rules most colliders out before the nearest feature is looked for.
fn touching_collider(collider: &Collider, motion: &Motion, radius: f64) -> Option<Feature> {
    if collider.sensor {
        return None;
    }
    let p = motion.position;
    let coordinates = p.abs().max_element();
    let near = match &collider.shape {
        Shape::Segment(s) => {
            let d = s.signed_distance(p);
            // Beside the interior and moving off the line (a ball that just bounced off a
            // brick), it approaches nothing of the segment: no nearest feature is needed.
            snaps(d.abs() - radius, coordinates, radius)
                && !((0.0..=1.0).contains(&s.projection(p))
                    && d * motion.velocity.dot(s.normal()) >= 0.0)
        }
        Shape::Circle(c) => {
            let reach = radius + c.radius;
            let limit = reach + SNAP_ULPS * f64::EPSILON * (coordinates + reach);
            (p - c.center).length_squared() <= limit * limit
        }
    };
    if !near {
        return None;
    }
    let touch = Touch::of(&collider.shape, p, radius)?;
    let reach = touch.reach(radius);
    (snaps(touch.gap, coordinates, reach)
        && touch.touches(p, radius)
        && motion.velocity.dot(touch.normal) < 0.0)
        .then_some(touch.feature)
}

/// Whether two unit normals are the same (parallel, same way).
fn same_normal(a: DVec2, b: DVec2) -> bool {
    a.dot(b) > 0.0 && a.perp_dot(b).abs() <= 1e-9
}

/// Whether a ball (centre `p`, `radius`) supported along a line of unit `normal` touches the
/// interior of `shape` (within [`SETTLE_HEIGHT`]) with that same normal: a segment on the same
/// line.
fn coincident(shape: &Shape, normal: DVec2, p: DVec2, radius: f64) -> bool {
    let Shape::Segment(_) = shape else {
        return false;
    };
    Touch::of(shape, p, radius).is_some_and(|touch| {
        touch.point.is_none()
            && same_normal(normal, touch.normal)
            && touch.gap.abs() <= SETTLE_HEIGHT * (p.abs().max_element() + radius)
    })
}

/// Whether a ball touching a segment's interior is at its end and moving off it: it then
/// leaves at once (as a free ball, or pivoting on the end point), rather than settling.
fn slides_off_now(shape: &Shape, touch: &Touch, motion: &Motion, radius: f64) -> bool {
    let (Shape::Segment(s), None) = (shape, touch.point) else {
        return false;
    };
    let t = touch.normal.perp();
    let (v, a) = (motion.velocity.dot(t), motion.acceleration.dot(t));
    let u = (motion.position - s.a()).dot(t);
    let length = (s.b() - s.a()).dot(t);
    let (lo, hi) = (length.min(0.0), length.max(0.0));
    let near = SETTLE_HEIGHT * (motion.position.abs().max_element() + radius);
    let out_high = v > 0.0 || (v == 0.0 && a > 0.0);
    let out_low = v < 0.0 || (v == 0.0 && a < 0.0);
    (hi - u <= near && out_high) || (u - lo <= near && out_low)
}

/// An absolute pruning horizon turned into one relative to `base`, widened by a few ulps so
/// that a candidate whose absolute time is exactly `horizon` is never pruned (a tie must reach
/// the total order).
fn relative(horizon: Time, base: Time) -> f64 {
    if horizon.seconds().is_finite() {
        let span = horizon.since(base);
        span + 4.0 * f64::EPSILON * span.abs() + f64::MIN_POSITIVE
    } else {
        f64::INFINITY
    }
}
