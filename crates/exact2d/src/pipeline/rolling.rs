//! Rough balls on segments: the support's motion under friction (`dynamics/rolling.rs`), and
//! the events that end its phases.
//!
//! A ball that settles on, or slides onto, a segment it rubs (the pair has friction) moves
//! along it with the acceleration of its phase, not gravity's tangential part: sliding (kinetic
//! friction against the slip, the spin changing at a constant rate), rolling (the spin `v.t / r`)
//! or at rest under rolling resistance. The phase's end, when the slip vanishes or a rolling
//! ball stops, is a `Leave` event of its support at its analytic time: the ball is restated
//! there, its slip set to zero (or, stopping, its speed), and the next phase taken from that
//! state. A pivot's polygon (a corner, a peg, a sleeping ball) is rubbed edge by edge the
//! same way. Groups and wedges stay frictionless (the spin is kept through them).

use glam::DVec2;

use super::World;
use super::step::balls_touch;
use crate::dynamics::{NO_COLLIDER, OnLine, Rubbing, Support};

impl World {
    /// `support`, given to ball `index` now, with friction's share if the ball rubs it: a
    /// segment's interior or one edge of a pivot's polygon (not a group's hold or a wedge)
    /// whose pair with the ball has friction, pressed together.
    ///
    /// Around a pivot of reach `rho` the surface presses with `m (g_n - v^2 / rho)` (the
    /// centripetal part), and the contact point is at `-r n` from the centre as on a line, so
    /// a ball rolls over a corner, a peg or a sleeping ball as on the polygon's edges.
    pub(crate) fn rubbed(&self, index: u32, mut support: Support) -> Support {
        let plain = support.held.is_none() && support.wedge.is_none();
        let Some(spin) = self.balls.spin(index).filter(|_| plain) else {
            return support;
        };
        if self.presses_a_ball(index, &support) {
            return support;
        }
        let Some(collider) = self.colliders.get(support.collider) else {
            return support;
        };
        let pair = spin.roughness.pair(collider.roughness());
        if !(pair.friction > 0.0) {
            return support;
        }
        let (n, g) = (support.normal, self.gravity);
        let t = n.perp();
        let ball = self.balls.kinematics(index).expect("live ball");
        let v = ball
            .trajectory
            .velocity_at(self.time, self.acceleration(index));
        let turning = support
            .pivot
            .map_or(0.0, |(_, reach)| v.dot(t).powi(2) / reach);
        let g_n = -g.dot(n) - turning;
        if !(g_n > 0.0) {
            return support;
        }
        let on = OnLine {
            v: v.dot(t),
            w: spin.omega_at(self.time),
            radius: ball.radius,
            inertia: spin.inertia,
            g_t: g.dot(t),
            g_n,
            friction: pair.friction,
            resistance: pair.rolling_resistance,
        };
        let rub = on.rub();
        support.acceleration = t * rub.accel;
        support.rub = Some(Rubbing {
            omega: rub.rolling.then(|| on.v / on.radius),
            alpha: rub.alpha,
            end: rub.until.map(|d| self.time.after(d)),
            rolling: rub.rolling,
            roll_rate: DVec2::ZERO,
            table: None,
            slack: 0.0,
        });
        support
    }

    /// Whether ball `index` touches a ball other than its support (an awake one, or a sleeping
    /// one's circle): then it moves on its support frictionless, as the balls it touches
    /// do with it (friction among balls pressed together is their group's,
    /// `dynamics/contact_friction.rs`, and a jam's impulses', `dynamics/impact_friction.rs`).
    /// Rubbing alone among frictionless neighbours, a pile's bottom row was driven into them
    /// by its friction at every settle, each time a jam of the cluster: a 100-ball pile took
    /// 200 s of wall for 2 simulated seconds where it rested in 12.
    fn presses_a_ball(&self, index: u32, support: &Support) -> bool {
        let Some(ball) = self.balls.kinematics(index) else {
            return false;
        };
        let p = ball
            .trajectory
            .position_at(self.time, self.acceleration(index));
        let coordinates = p.abs().max_element();
        let mut touching = false;
        self.grid.near(index, |other, _| {
            if touching || other == index {
                return;
            }
            if let Some(partner) = self.balls.kinematics(other) {
                let q = partner
                    .trajectory
                    .position_at(self.time, self.acceleration(other));
                let reach = ball.radius + partner.radius;
                let scale = coordinates.max(q.abs().max_element());
                touching = balls_touch(p.distance(q) - reach, scale, reach);
            }
        });
        touching
            || self
                .touched_colliders(index, p, ball.radius, NO_COLLIDER)
                .iter()
                .any(|(h, _, _)| *h != support.collider && self.is_proxy(h.index))
    }

    /// Ball `index`'s phase on its support ends now (its `Leave` came at the phase's end):
    /// restated here, a slide's slip is set to zero (the analytic state: it rolls), a rolling
    /// ball's speed too (it stopped), and the next phase is taken from there. Returns `false`
    /// if the support's phase does not end now.
    pub(crate) fn end_phase(&mut self, index: u32, support: &Support) -> bool {
        // Due now, or so soon after now that the clock cannot tell.
        let due = |end: crate::dynamics::Time| {
            end <= self.time || !self.time.resolves(end.since(self.time))
        };
        let Some(rub) = support.rub.filter(|r| r.end.is_some_and(due)) else {
            return false;
        };
        let time = self.time;
        self.counts.phase_ends += 1;
        let t = support.normal.perp();
        self.balls.rebase(index, time, support.acceleration);
        let ball = self.balls.kinematics_mut(index).expect("live ball");
        let radius = ball.radius;
        if rub.rolling {
            ball.trajectory.v0 = DVec2::ZERO;
        }
        let v = ball.trajectory.v0.dot(t);
        self.balls.spin_mut(index).set_motion(time, v / radius, 0.0);
        // The next phase from gravity's part alone: the ended phase's acceleration, kept where
        // friction has no share now (the ball touches a ball it grazed meanwhile), went on
        // pushing it with no torque to match, adding energy (rough hunt seed 358890: a ball
        // whose slide ended over a ball passing below the segment it rolled on went on
        // speeding up at `mu g`, its spin fixed, 2 % of the energy's scale in 0.26 s).
        let next = support.smooth(self.gravity);
        // The ball stays on its line: it touches what it touched (an exact-fit channel's
        // other wall, parallel to it). Forgotten, that wall was predicted against again, met
        // at once (the walls' normals are opposite only to a rounding of the scene), and its
        // friction gave the ball a slip of a rounding: a slide of 2.5e-16 s, whose end
        // forgot it again, for ever (rough hunt seed 371712).
        let touching = self
            .balls
            .properties(index)
            .map(|p| p.extra.touching().to_vec())
            .unwrap_or_default();
        self.set_support(index, Some(next));
        if let Some(properties) = self.balls.properties_mut(index) {
            properties.extra.set_touching(touching);
        }
        if !self.try_sleep(index) {
            self.schedule(index);
        }
        true
    }
}
