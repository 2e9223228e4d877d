//! Predicting a ball's next event: the earliest over every partner it could meet.
//!
//! This is the only place that enumerates candidate partners. It tries every collider and every
//! ball (O(N) per prediction); a broad phase replaces the enumeration, not the rules below.
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

use super::World;
use super::queue::{EventKey, Kind};
use crate::dynamics::{BallRecord, Time};
use crate::geometry::{Collider, ColliderHandle, Feature, Shape};
use crate::toi::{
    Crossing, time_of_impact_ball_ball, time_of_impact_ball_circle, time_of_impact_ball_segment,
};

impl World {
    /// The earliest event of ball `index` in the total event order, with the partner's tag
    /// (its `version` for a ball, its generation for a collider).
    pub(crate) fn predict(&self, index: u32) -> Option<(EventKey, u32)> {
        let ball = self.balls.record(index)?;
        let mut best: Option<(EventKey, u32)> = None;
        for (handle, collider) in self.colliders.iter() {
            if !collider.groups.interact(ball.groups) {
                continue;
            }
            let horizon = best.map_or(Time::new(f64::INFINITY), |(key, _)| key.time);
            if let Some(key) = self.collider_candidate(index, ball, handle, collider, horizon) {
                let key = EventKey {
                    time: key.time.max(self.time),
                    ..key
                };
                if best.is_none_or(|(b, _)| key < b) {
                    best = Some((key, handle.generation));
                }
            }
        }
        for (other, partner) in self.balls.iter() {
            if other == index || !partner.groups.interact(ball.groups) {
                continue;
            }
            let horizon = best.map_or(Time::new(f64::INFINITY), |(key, _)| key.time);
            let Some(time) = self.ball_candidate(index, ball, other, partner, horizon) else {
                continue;
            };
            let key = EventKey {
                time: time.max(self.time),
                kind: Kind::BallContact,
                first: index.min(other),
                second: index.max(other),
                feature: 0,
            };
            if best.is_none_or(|(b, _)| key < b) {
                best = Some((key, self.balls.slots[other as usize].version));
            }
        }
        best
    }

    /// Ball `index` against one collider: the next contact (solid), or the next entry or exit
    /// (sensor, depending on whether the ball is inside it now), at an absolute time no later
    /// than `horizon` (which is only a pruning bound: ties at `horizon` are kept).
    pub(crate) fn collider_candidate(
        &self,
        index: u32,
        ball: &BallRecord,
        handle: ColliderHandle,
        collider: &Collider,
        horizon: Time,
    ) -> Option<EventKey> {
        let base = ball.trajectory.t0;
        let motion = ball.trajectory.motion_at(base, self.gravity);
        let crossing = if collider.sensor && ball.sensors.contains(&handle) {
            Crossing::Exit
        } else {
            Crossing::Enter
        };
        let relative_horizon = relative(horizon, base);
        let (tau, feature) = match &collider.shape {
            Shape::Segment(s) => {
                let c = time_of_impact_ball_segment(
                    &motion,
                    ball.radius,
                    s,
                    crossing,
                    relative_horizon,
                )?;
                (c.time, Feature::from(c.feature))
            }
            Shape::Circle(c) => {
                let t = time_of_impact_ball_circle(
                    &motion,
                    ball.radius,
                    c.center,
                    c.radius,
                    crossing,
                    relative_horizon,
                )?;
                (t, Feature::Circle)
            }
        };
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

    /// Balls `i` and `j` against each other: the absolute time of their next contact, solved
    /// from the later of their two trajectory origins, with the smaller slot index first so the
    /// result does not depend on which ball asks.
    fn ball_candidate(
        &self,
        i: u32,
        ball_i: &BallRecord,
        j: u32,
        ball_j: &BallRecord,
        horizon: Time,
    ) -> Option<Time> {
        let (first, second) = if i < j {
            (ball_i, ball_j)
        } else {
            (ball_j, ball_i)
        };
        let base = first.trajectory.t0.max(second.trajectory.t0);
        let g = self.gravity;
        let t = time_of_impact_ball_ball(
            first.trajectory.position_at(base, g),
            first.trajectory.velocity_at(base, g),
            first.radius,
            second.trajectory.position_at(base, g),
            second.trajectory.velocity_at(base, g),
            second.radius,
            relative(horizon, base),
        )?;
        base.resolved_after(t)
    }
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
