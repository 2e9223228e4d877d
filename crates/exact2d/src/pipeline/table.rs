//! A table seen from above: every moving or turning ball is supported by the cloth, which
//! gives it the constant accelerations of its phase (`dynamics/table.rs`) until the phase
//! ends.
//!
//! The cloth is a support without a collider or a line (`Support::on_table`): its
//! acceleration is the phase's, and its `rub` carries the spin's and the roll's rates and
//! when the phase ends. So the rest of the pipeline needs nothing new: predictions use the
//! acceleration as any support's, an impact lifts the ball off it (as off any support) and
//! the ball is laid on the cloth again before it is predicted ([`World::lay_on_table`], from
//! `schedule`), from its state after the impact; the end of a phase is the support's `Leave`
//! event, where what ended is snapped to its exact value ([`World::end_table_phase`]). A ball
//! at rest without spin has no phase: it is a free ball, without acceleration.
//!
//! A few rules belong to the table alone, for what the cloth presses together: the cushion
//! hold ([`World::hold_at_cushion`]), the join of a pressed cluster
//! ([`World::join_on_table`]), the cushions a ball slides along for its phase, and phases that
//! end within a tick ending now (`ARCHITECTURE.md`, "A table seen from above").

use glam::DVec2;

use super::instant::Pair;
use super::observables::split;
use super::step::{balls_touch, hop_floor, micro_hop};
use super::{World, WorldError};
use crate::dynamics::{
    BallHandle, ClothPhase, NO_COLLIDER, OnCloth, PARALLEL, Support, Table, Touch,
    contact_velocity, sooner,
};
use crate::geometry::{ColliderHandle, Feature, Shape};

impl World {
    /// Makes the world a table seen from above with this cloth (`Some`), or takes the table
    /// away (`None`). With a table every ball slides, rolls and spins to rest under the
    /// cloth's friction (see [`Table`]), and carries a roll (its angular velocity about the
    /// horizontal axes, [`World::set_ball_roll`]); the world's gravity must be zero. Every
    /// ball is restated now and goes on under the new law. Taking the table away leaves the
    /// balls moving at their velocities, without rolls.
    ///
    /// # Errors
    /// [`WorldError::InvalidTable`] naming a value out of its range (gravity finite and
    /// positive, every coefficient finite and non-negative); [`WorldError::TableAndGravity`]
    /// if the world has gravity.
    pub fn set_table(&mut self, table: Option<Table>) -> Result<(), WorldError> {
        if let Some((name, value, range)) = table.as_ref().and_then(Table::invalid) {
            return Err(WorldError::InvalidTable { name, value, range });
        }
        if table.is_some() && self.gravity != DVec2::ZERO {
            return Err(WorldError::TableAndGravity);
        }
        if table.is_some() && self.periodic.is_some() {
            return Err(WorldError::PeriodicWith("a table"));
        }
        self.instant.forget();
        let time = self.time;
        let all: Vec<u32> = self.balls.iter().map(|(i, _, _)| i).collect();
        for &index in &all {
            let acceleration = self.acceleration(index);
            self.balls.rebase(index, time, acceleration);
            if self.balls.is_supported(index) {
                self.balls.set_support(index, None, time);
            }
            if table.is_none() && self.balls.spin(index).is_some() {
                self.balls
                    .spin_mut(index)
                    .set_roll(time, DVec2::ZERO, DVec2::ZERO);
            }
        }
        self.table = table;
        if self.table.is_some() {
            self.balls.carry_residuals();
        }
        for &index in &all {
            self.trajectory_changed(index);
        }
        Ok(())
    }

    /// The table's cloth, if the world is a table seen from above.
    #[must_use]
    pub fn table(&self) -> Option<Table> {
        self.table
    }

    /// Sets a ball's roll (its angular velocity about the horizontal axes, radians per
    /// second; see [`BallDesc::roll`](crate::BallDesc::roll)) from now on: the ball's phase on
    /// the cloth is taken again from its new state.
    ///
    /// # Errors
    /// [`WorldError::NoSuchBall`], [`WorldError::NotFinite`], or
    /// [`WorldError::RollWithoutTable`] if the world has no table.
    pub fn set_ball_roll(&mut self, handle: BallHandle, roll: DVec2) -> Result<(), WorldError> {
        if !roll.is_finite() {
            return Err(WorldError::NotFinite("ball roll"));
        }
        if self.balls.get(handle).is_none() {
            return Err(WorldError::NoSuchBall(handle));
        }
        if self.table.is_none() {
            return Err(WorldError::RollWithoutTable);
        }
        self.instant.forget();
        let index = handle.index;
        self.lift_off_table(index);
        let (time, radius) = (
            self.time,
            self.balls.kinematics(index).expect("live").radius,
        );
        self.balls
            .spin_mut(index)
            .set_roll(time, contact_velocity(roll, radius), DVec2::ZERO);
        self.trajectory_changed(index);
        Ok(())
    }

    /// Restates ball `index` now and takes it off the cloth (its phase is taken again when it
    /// is next predicted).
    pub(crate) fn lift_off_table(&mut self, index: u32) {
        let (time, acceleration) = (self.time, self.acceleration(index));
        self.balls.rebase(index, time, acceleration);
        if self.balls.is_supported(index) {
            self.balls.set_support(index, None, time);
        }
    }

    /// On a table, lays ball `index` (not supported: an impact has just lifted it off the
    /// cloth, or it was added or set moving) on the cloth in the phase its state now gives;
    /// nothing if it is at rest without spin or roll.
    pub(crate) fn lay_on_table(&mut self, index: u32) {
        let Some(table) = self.table else {
            return;
        };
        let time = self.time;
        let Some(ball) = self.balls.kinematics(index) else {
            return;
        };
        if ball.is_supported() {
            return;
        }
        let v = ball.trajectory.v0;
        let spin = self.balls.spin(index).copied();
        let (c, w) = spin.map_or((DVec2::ZERO, 0.0), |s| (s.roll_at(time), s.omega_at(time)));
        if v == DVec2::ZERO && c == DVec2::ZERO && w == 0.0 {
            return;
        }
        let inertia = spin.map_or(crate::DEFAULT_INERTIA, |s| s.inertia);
        let start = OnCloth {
            v,
            c,
            w,
            radius: ball.radius,
            inertia,
        };
        // What ends sooner than the clock can tell from now ends now: a slip too small to
        // point anywhere (`OnCloth::slip`) or to slide for a tick leaves the ball rolling as
        // the slide would, a roll too slow to last a tick stops, so does a spin. (Its end
        // would be dropped as unresolvable, and the phase's acceleration go on.)
        let short = |d: Option<f64>| d.is_some_and(|d| !time.resolves(d));
        let mut on = start;
        let phase = loop {
            let Some(phase) = on.phase(&table) else {
                break None;
            };
            if phase.rolling && on.c != -on.v {
                on = on.rolled();
            } else if short(phase.translation_end) {
                on = if phase.rolling {
                    OnCloth {
                        v: DVec2::ZERO,
                        c: DVec2::ZERO,
                        ..on
                    }
                } else {
                    on.rolled()
                };
            } else if short(phase.spin_end) {
                on.w = 0.0;
            } else {
                break Some(phase);
            }
        };
        // A free ball on a table has no acceleration: restating it now is exact motion.
        self.balls.rebase(index, time, DVec2::ZERO);
        let record = self.balls.kinematics_mut(index).expect("live ball");
        record.trajectory.v0 = on.v;
        let p = record.trajectory.p0;
        if on != start {
            let turning = self.balls.spin_mut(index);
            turning.set_roll(time, on.c, DVec2::ZERO);
            turning.set_omega(time, on.w);
        }
        let Some(phase) = phase else {
            return;
        };
        // The ball's spin is kept from now on (`BallSet::set_support` turns it and its roll
        // with the phase only where it is).
        self.balls.spin_mut(index);
        let radius = self.balls.kinematics(index).expect("live ball").radius;
        let (along, until) = self.slid_along(index, (p, on.v, radius), &phase);
        self.balls
            .set_support(index, Some(Support::on_table(p, &phase, until, time)), time);
        if !along.is_empty() {
            let properties = self.balls.properties_mut(index).expect("live ball");
            properties.extra.set_touching(along);
        }
    }

    /// The cushions ball `index` (centre `p`, velocity `v`, radius `radius`) touches now and
    /// slides along for the whole of `phase`: never deeper into one, on the phase's parabola,
    /// than half the overlap the engine allows ([`overlap_bound`](crate::overlap_bound)) or
    /// half its radius, and, on a slide too short to move it, not moving into it beyond the
    /// rounding of its direction (`PARALLEL` of its speed).
    /// They are not predicted against while the phase lasts, as a supported ball's touched
    /// surfaces are not (`Extra::touching`): a ball sliding along an exact-fit
    /// channel, both walls touched and its velocity and the cloth's pull along them to a
    /// rounding, would otherwise meet one wall then the other a tick later, for ever.
    ///
    /// A phase that never ends (a cloth without sliding friction, a ball that keeps its slip)
    /// moves the ball in a straight line: a cushion it moves along to within
    /// `PARALLEL` of its speed, the rounding of a channel's walls,
    /// is slid along until the ball would be that half-bound into it, and the phase is cut
    /// there (the second value, seconds from now), to be laid afresh. Predicted against
    /// instead, the wall of a channel whose walls face each other but for 5.7e-13 radians was
    /// met at once, its friction gave the ball a spin that stopped 1e-14 s later, and then the
    /// other wall was met, for ever (`--rough --table` hunt seed 2778192).
    fn slid_along(
        &self,
        index: u32,
        (p, v, radius): (DVec2, DVec2, f64),
        phase: &ClothPhase,
    ) -> (Vec<ColliderHandle>, Option<f64>) {
        let duration = phase.end();
        let a = phase.accel;
        let mut along = Vec::new();
        let mut until: Option<f64> = None;
        for (handle, _, touch) in self.touched_colliders(index, p, radius, NO_COLLIDER) {
            if self.is_proxy(handle.index) {
                continue;
            }
            let n = touch.normal;
            let (vn, an) = (v.dot(n), a.dot(n));
            let bound = crate::overlap_bound(p.abs().max_element(), touch.reach(radius));
            let Some(duration) = duration else {
                // Endless: the phase's acceleration is zero (see `OnCloth::phase`).
                if an != 0.0 || vn < -PARALLEL * v.length() {
                    continue;
                }
                if vn < 0.0 {
                    // At least a quarter of the bound (64 ulps of the coordinates) to go, so
                    // that each cut moves the ball on: a ball already near the band's edge
                    // is met as at any cushion (cut after a rounding of travel instead, a
                    // ball at 1e3 sliding in at 1.4e-10 m/s was laid afresh every 2e-5 s
                    // without moving).
                    let room = touch.gap + 0.5 * bound;
                    if !(room >= 0.25 * bound) {
                        continue;
                    }
                    let t = room / -vn;
                    if !self.time.resolves(t) {
                        continue;
                    }
                    until = sooner(until, Some(t));
                }
                along.push(handle);
                continue;
            };
            // Moving into it beyond the rounding of its direction on a slide too short to move
            // it by the rounding of its coordinates, the ball meets it (at once, touching): the
            // slide's end would restate it where it is, the cushion still ahead. A funnel's
            // neck at 1e9, a hair narrower than its ball, each end point met in turn and the
            // other slid along on a slide of 4e-7 s, restated the ball every 4e-7 s without
            // moving it while its path went on at 0.145 m/s (`--rough --table` seed 5230472:
            // a ball from above ran into it); met, the two points are a jam, which stops it.
            let travel = v.length() * duration + 0.5 * a.length() * duration * duration;
            if vn < -PARALLEL * v.length() && travel <= f64::EPSILON * p.abs().max_element() {
                continue;
            }
            // The deepest the ball goes into the cushion during the phase: `-(vn t + an t^2 / 2)`
            // at its end, or at its turning point if it turns back out.
            let depth = |t: f64| -(vn * t + 0.5 * an * t * t);
            let mut deepest = depth(duration).max(0.0);
            if an > 0.0 {
                let turn = -vn / an;
                if turn > 0.0 && turn < duration {
                    deepest = deepest.max(depth(turn));
                }
            }
            // Half the bound, or half the radius where the bound is wider than the ball (its
            // centre would cross the cushion's line, and it would pass: a box of 34 ulps at
            // 1e9, whose bound is 5.7e-5, left by a ball of radius 5e-7 moving into a wall at
            // 62 % of its speed on a slide that took it 2.6e-5 in, seed 5442333).
            if touch.gap - deepest >= -0.5 * bound.min(radius) {
                along.push(handle);
            }
        }
        (along, until)
    }

    /// Ball `index`'s phase on the cloth (`support`) ends now (its `Leave` came): what ended
    /// is snapped to its exact value (the slip vanishes: `c = -v`; a rolling ball stops:
    /// `v = c = 0`; the spin stops: `w = 0`) and the ball is laid on the cloth again in the
    /// next phase.
    pub(crate) fn end_table_phase(&mut self, index: u32, support: &Support) {
        let Some(ends) = support.table() else {
            return;
        };
        let time = self.time;
        let due = |end: Option<crate::dynamics::Time>| {
            end.is_some_and(|end| end <= time || !time.resolves(end.since(time)))
        };
        let rolling = support.rub.is_some_and(|r| r.rolling);
        let (translation, spin) = (due(ends.translation), due(ends.spin));
        self.balls.rebase(index, time, support.acceleration);
        let record = self.balls.kinematics_mut(index).expect("live ball");
        if translation && rolling {
            record.trajectory.v0 = DVec2::ZERO;
        }
        let v = record.trajectory.v0;
        self.balls.set_support(index, None, time);
        let turning = self.balls.spin_mut(index);
        if translation {
            let c = if rolling { DVec2::ZERO } else { -v };
            turning.set_roll(time, c, DVec2::ZERO);
        }
        if spin {
            turning.set_omega(time, 0.0);
        }
        self.counts.phase_ends += 1;
        self.trajectory_changed(index);
    }

    /// On a table, balls `i` and `j`, which the cloth presses together and which touch with
    /// a hop under the micro-hop floor, move on as one with every ball pressed to them so
    /// (touching, pulled together, and meeting or parting no faster than their own floor:
    /// the cluster, grown ball by ball): each takes the cluster's velocity (momentum kept)
    /// and its roll (the mean of the rolls weighted by `k m`, their rotational inertias over
    /// `r^2`), so their phases are the same from now on and nothing presses them (a
    /// perfectly inelastic impact, in every direction; each ball keeps its spin). If the
    /// cluster then moves into a cushion one of its balls touches, or the cloth presses it
    /// there, it stops against it as one (see `Self::pressed_into_cushions`). Returns the
    /// common velocity.
    ///
    /// Without this, the pair's inelastic hops would shrink to the micro-hop floor and go on
    /// at that height for as long as the cloth pressed them (a crawl of the clock), and a
    /// stack of touching balls would be joined pair by pair for ever, each join unsettling
    /// the next pair; both were found by the hunt's touching stacks laid on a table. Energy
    /// only falls (Jensen's inequality, for the velocities and for the rolls).
    pub(crate) fn join_on_table(&mut self, i: u32, j: u32) -> DVec2 {
        let (v, cluster) = self.join_with(vec![i, j], &[]);
        for &index in &cluster {
            self.schedule(index);
        }
        v
    }

    /// [`Self::join_on_table`] of the cluster grown from `cluster`, within a jam whose
    /// contacts `closed` are closed for the rest of the chain: a ball of such a contact that
    /// the cluster's common motion would approach (beyond the rounding of the speeds) joins
    /// the cluster too, so that the join leaves none of the jam's contacts approaching (one
    /// would be sought again only `SNAP_ULPS` deeper, see [`Self::hold_after_jam`]). Returns
    /// the common velocity and the cluster, laid on the cloth, for the caller to predict (a
    /// jam predicts every ball of its own cluster, which holds these, at its end).
    fn join_with(&mut self, mut cluster: Vec<u32>, closed: &[Pair]) -> (DVec2, Vec<u32>) {
        let time = self.time;
        let mut held = Vec::new();
        let (v, c) = loop {
            self.grow_pressed(&mut cluster);
            held.clear();
            let (v, c) = self.common_motion(&cluster, &mut held);
            let approached: Vec<u32> = closed
                .iter()
                .filter_map(|pair| match *pair {
                    Pair::Balls(a, b) if cluster.contains(&a) != cluster.contains(&b) => {
                        let (inside, outside) = if cluster.contains(&a) { (a, b) } else { (b, a) };
                        self.approaches(inside, v, outside).then_some(outside)
                    }
                    _ => None,
                })
                .collect();
            if approached.is_empty() {
                break (v, c);
            }
            for o in approached {
                if !cluster.contains(&o) {
                    cluster.push(o);
                }
            }
        };
        self.note_join(&cluster, v, &held);
        for &index in &cluster {
            self.balls
                .kinematics_mut(index)
                .expect("live")
                .trajectory
                .v0 = v;
            if self.balls.is_supported(index) {
                self.balls.set_support(index, None, time);
            }
            self.balls.spin_mut(index).set_roll(time, c, DVec2::ZERO);
            self.balls.bump_version(index);
        }
        // All on the cloth before any is predicted, so no prediction is outdated at birth.
        for &index in &cluster {
            self.lay_on_table(index);
        }
        (v, cluster)
    }

    /// Whether ball `outside` approaches ball `inside`, were `inside` moving at `v` now,
    /// beyond the rounding of their speeds.
    fn approaches(&self, inside: u32, v: DVec2, outside: u32) -> bool {
        let position = |index: u32| {
            let record = self.balls.kinematics(index).expect("live ball");
            record
                .trajectory
                .position_at(self.time, self.acceleration(index))
        };
        let n = (position(outside) - position(inside)).normalize_or_zero();
        let w = self.velocity_now(outside);
        (w - v).dot(n) < -4.0 * f64::EPSILON * (v.length() + w.length())
    }

    /// Grows `cluster` by every ball pressed to one of its balls (`Self::pressed_together`),
    /// ball by ball.
    fn grow_pressed(&self, cluster: &mut Vec<u32>) {
        let mut k = 0;
        while k < cluster.len() {
            let m = cluster[k];
            k += 1;
            let mut pressed = Vec::new();
            self.grid.near(m, |o, _| {
                if !cluster.contains(&o) && self.pressed_together(m, o) {
                    pressed.push(o);
                }
            });
            pressed.sort_unstable();
            for o in pressed {
                if !cluster.contains(&o) {
                    cluster.push(o);
                }
            }
        }
    }

    /// The observables of a join of `cluster` (restated now) at the common velocity `v`, held
    /// against cushions by `held` (see [`Self::pressed_into_cushions`], per unit of the
    /// cluster's mass): each cushion's impulse, and the virial of the impulses among the balls,
    /// `sum_i (p_i - p_0) . (m_i dv_i - J_i)` with `J_i` the cushions' impulses on ball `i`
    /// (the impulses among the balls add up to zero, so this is their virial whatever their
    /// split among the contacts). Not in the chain's ledger (see `pipeline/instant.rs`): a jam
    /// of the chain after a join takes back none of it.
    fn note_join(&mut self, cluster: &[u32], v: DVec2, held: &[Held]) {
        let place = |world: &World, index: u32| {
            let record = world.balls.kinematics(index).expect("live ball");
            let mass = world
                .balls
                .mass_and_restitution(index)
                .expect("live ball")
                .0;
            (record.trajectory.p0, record.trajectory.v0, mass)
        };
        let Some(&first) = cluster.first() else {
            return;
        };
        let origin = place(self, first).0;
        let (mut w, mut total) = (0.0, 0.0);
        for &index in cluster {
            let (p, vi, m) = place(self, index);
            w += (p - origin).dot((v - vi) * m);
            total += m;
        }
        for &(ball, slot, dv) in held {
            let p = place(self, ball).0;
            let j = dv * total;
            w -= (p - origin).dot(j);
            self.note_impulse(Pair::Collider(ball, slot), p, p, j);
        }
        self.observables.add_virial(w);
    }

    /// The observables of `held` (see [`Self::pressed_into_cushions`]) for a body of `mass`.
    fn note_held(&mut self, held: &[Held], mass: f64) {
        for &(ball, slot, dv) in held {
            let p = self
                .balls
                .kinematics(ball)
                .expect("live ball")
                .trajectory
                .p0;
            self.note_impulse(Pair::Collider(ball, slot), p, p, dv * mass);
        }
    }

    /// The common velocity and roll of `cluster` joined as one (momentum kept, rolls weighted
    /// by `k m`), held against the cushions its balls touch that it moves or is pressed into
    /// (see `Self::pressed_into_cushions`, which pushes onto `held`). Restates each ball now.
    fn common_motion(&mut self, cluster: &[u32], held: &mut Vec<Held>) -> (DVec2, DVec2) {
        let time = self.time;
        let (mut momentum, mut mass, mut turning, mut weight) =
            (DVec2::ZERO, 0.0, DVec2::ZERO, 0.0);
        let mut inertia = crate::DEFAULT_INERTIA;
        for (n, &index) in cluster.iter().enumerate() {
            let (m, _) = self.balls.mass_and_restitution(index).expect("live ball");
            let acceleration = self.acceleration(index);
            self.balls.rebase(index, time, acceleration);
            let record = self.balls.kinematics_mut(index).expect("live ball");
            let v = record.trajectory.v0;
            let (k, c) = self
                .balls
                .spin(index)
                .map_or((crate::DEFAULT_INERTIA, DVec2::ZERO), |s| {
                    (s.inertia, s.roll_at(time))
                });
            if n == 0 {
                inertia = k;
            }
            (momentum, mass) = (momentum + v * m, mass + m);
            (turning, weight) = (turning + c * (k * m), weight + k * m);
        }
        let (v, c) = (momentum / mass, turning / weight);
        // As one, they may be pressed into a cushion one of them touches: held there
        // together.
        self.pressed_into_cushions(cluster, (v, c, None), inertia, held)
    }

    /// On a table, after a jam's impact among `balls` (its contacts `pairs` closed for the
    /// rest of the chain): what the cloth presses together is held, as under gravity the
    /// jam's hold rests a ball on its surfaces and holds balls pressed together as a group
    /// (`World::hold`, in `pipeline/jam.rs`). Each ball is laid on the cloth in the phase its
    /// new velocity gives; one that phase presses into a cushion it touches is held against
    /// it (the cushion hold, `Self::pressed_into_cushions`); and two balls of a contact that
    /// their phases press together, meeting or parting no faster than their micro-hop floor,
    /// are joined ([`Self::join_on_table`]).
    ///
    /// Without this, the jam left such a contact tangential but pulled in by the new phases,
    /// and, closed, it was sought again only `SNAP_ULPS` deeper (the zero-time chain's
    /// `closed_depth`), where it was met and held or joined, 8 ulps of the coordinates deep:
    /// a cluster the cloth drove against a ball at a cushion bounced off it, jammed and was
    /// joined again every 1.2e-4 s, two of its balls 8 ulps deeper into each other each time
    /// (`--rough --table` hunt seed 2657960: 6.8e-9 of their contact distance at x = 1e6).
    pub(crate) fn hold_after_jam(&mut self, balls: &[u32], pairs: &[Pair]) {
        if self.table.is_none() {
            return;
        }
        let time = self.time;
        for &ball in balls {
            self.lay_on_table(ball);
            let Some(spin) = self.balls.spin(ball).copied() else {
                continue;
            };
            let v = self
                .balls
                .kinematics(ball)
                .expect("live ball")
                .trajectory
                .v0;
            let c = spin.roll_at(time);
            let mut held = Vec::new();
            let (held_v, held_c) =
                self.pressed_into_cushions(&[ball], (v, c, None), spin.inertia, &mut held);
            let mass = self.balls.mass_and_restitution(ball).expect("live ball").0;
            self.note_held(&held, mass);
            if (held_v, held_c) != (v, c) {
                self.lift_off_table(ball);
                let record = self.balls.kinematics_mut(ball).expect("live ball");
                record.trajectory.v0 = held_v;
                self.balls
                    .spin_mut(ball)
                    .set_roll(time, held_c, DVec2::ZERO);
                self.lay_on_table(ball);
            }
        }
        for pair in pairs {
            let Pair::Balls(a, b) = *pair else {
                continue;
            };
            // Balls joined already (by a join of this loop) have the same phase: nothing
            // presses them.
            if self.acceleration(a) != self.acceleration(b) && self.pressed_together(a, b) {
                self.join_with(vec![a, b], pairs);
            }
        }
    }

    /// Whether balls `a` and `b` touch and the cloth presses them together, meeting or
    /// parting no faster than their micro-hop floor (see `hop_floor`); or touch moving as
    /// one already (a cluster joined before, whose phases are the same), meeting or parting
    /// no faster than that floor for their acceleration.
    fn pressed_together(&self, a: u32, b: u32) -> bool {
        let (Some(ka), Some(kb)) = (self.balls.kinematics(a), self.balls.kinematics(b)) else {
            return false;
        };
        let (aa, ab) = (self.acceleration(a), self.acceleration(b));
        let (pa, va) = (
            ka.trajectory.position_at(self.time, aa),
            ka.trajectory.velocity_at(self.time, aa),
        );
        let (pb, vb) = (
            kb.trajectory.position_at(self.time, ab),
            kb.trajectory.velocity_at(self.time, ab),
        );
        let reach = ka.radius + kb.radius;
        let coordinates = pa.abs().max(pb.abs()).max_element();
        if !balls_touch(pa.distance(pb) - reach, coordinates, reach) {
            return false;
        }
        let n = (pb - pa).normalize_or_zero();
        let floor = if aa == ab {
            Some((2.0 * aa.length() * micro_hop(coordinates, reach)).sqrt())
        } else {
            hop_floor(pa, va, aa, pb, vb, ab, reach)
        };
        floor.is_some_and(|f| (vb - va).dot(n).abs() <= f)
    }

    /// On a table, ball `index` leaves cushion `shape` (met at `feature`) at `v` now. If the
    /// cloth drives it back into the cushion (its slip `u = v + c`, sliding, pulls it in at
    /// `mu_s g u.n / |u|`) while it touches it, leaving too slowly to hop higher than
    /// [`SETTLE_HEIGHT`](crate::SETTLE_HEIGHT) of its coordinate scale (the rule a ball
    /// settles on a floor by, with a pull beyond the rounding of the slip's direction,
    /// [`Touch::holds_within`]), it is held against the cushion: its velocity
    /// along the normal and its slip's part along the normal go to zero (the cushion, which
    /// on a real table touches the ball above its centre, takes both), and it slides on along
    /// the cushion. Returns the velocity it leaves with if it is held.
    ///
    /// Without this, the bounces of a ball pulled back into a cushion would accumulate at a
    /// finite time (a Zeno tail, as on a floor under gravity), each shorter than the last;
    /// with it they end where a hop becomes rounding, as on a floor. The hold only takes
    /// energy away (it removes a part of the velocity and of the roll). The test is the one
    /// `predict` uses to meet such a ball at once (with the acceleration of the phase it
    /// would leave in), so a ball held is not met again, and one not held leaves.
    ///
    /// What the cushion (`handle`) and any other it is then pressed into take goes to the
    /// observables.
    pub(crate) fn hold_at_cushion(
        &mut self,
        index: u32,
        v: DVec2,
        (shape, feature): (&Shape, Feature),
        handle: ColliderHandle,
    ) -> Option<DVec2> {
        let table = self.table?;
        let time = self.time;
        let spin = self.balls.spin(index).copied()?;
        let ball = self.balls.kinematics(index).expect("live ball");
        let (p, radius) = (ball.trajectory.p0, ball.radius);
        let c = spin.roll_at(time);
        let on = OnCloth {
            v,
            c,
            w: 0.0,
            radius,
            inertia: spin.inertia,
        };
        let phase = on.phase(&table).filter(|p| !p.rolling)?;
        // The feature met, as the contact has it: at a segment's end the kernel's interior
        // reaches a hair past the end point, where the nearest feature is the point (whose
        // curvature would let the ball fly off in the test), and the ball would bounce on
        // the interior towards an accumulation point.
        let touch = match (shape, feature) {
            (Shape::Segment(s), Feature::SegmentInterior) => Touch::on_interior(s, p, radius),
            _ => Touch::of(shape, p, radius)?,
        };
        if !touch.holds_within(p, v, phase.accel, radius, phase.slack) {
            return None;
        }
        let n = touch.normal;
        let mut held = vec![(index, handle.index, DVec2::ZERO - n * v.dot(n))];
        let (v, c) = (v - n * v.dot(n), c - n * c.dot(n));
        // Held so, the cloth may press it into another cushion it touches (a corner, a
        // wedge): then both hold it (see `Self::pressed_into_cushions`).
        let (v, c) = self.pressed_into_cushions(
            &[index],
            (v, c, Some((n, index, handle.index))),
            spin.inertia,
            &mut held,
        );
        self.balls.spin_mut(index).set_roll(time, c, spin.roll_rate);
        let mass = self.balls.mass_and_restitution(index).expect("live ball").0;
        self.note_held(&held, mass);
        Some(v)
    }

    /// Balls `balls` (touching each other, moving as one at `v` with the roll `c`, inertia
    /// `inertia` over `m r^2`, held already against a cushion of normal `held` if some, with
    /// the ball and the slot of that cushion),
    /// held against the cushions they touch that the cloth presses them into: against one,
    /// their velocity and slip lose their parts along its normal;
    /// against two that are not parallel (a corner, a wedge), both, so they stop, rather than
    /// be handed from one to the other at one instant, the slip shrinking by a projection
    /// each time. Returns the velocity and roll they keep, and pushes onto `taken` each change
    /// of velocity a cushion makes (for the observables: the ball, the cushion's slot, the
    /// change).
    fn pressed_into_cushions(
        &self,
        balls: &[u32],
        (mut v, mut c, mut held): (DVec2, DVec2, Option<(DVec2, u32, u32)>),
        inertia: f64,
        taken: &mut Vec<Held>,
    ) -> (DVec2, DVec2) {
        let Some(table) = self.table else {
            return (v, c);
        };
        // A cluster joined as one also stops against the cushions its balls touch and move
        // into (an inelastic impact of the whole, rather than each ball bouncing off its
        // cushion alone and the cluster joined again, at one instant, for ever).
        let joined = balls.len() > 1;
        for &index in balls {
            let ball = self.balls.kinematics(index).expect("live ball");
            let (p, radius) = (ball.trajectory.p0, ball.radius);
            for (h, _, t) in self.touched_colliders(index, p, radius, NO_COLLIDER) {
                if self.is_proxy(h.index) {
                    continue;
                }
                let on = OnCloth {
                    v,
                    c,
                    w: 0.0,
                    radius,
                    inertia,
                };
                let n = t.normal;
                let pressed = on
                    .phase(&table)
                    .filter(|p| !p.rolling)
                    .is_some_and(|phase| t.holds_within(p, v, phase.accel, radius, phase.slack));
                let into = joined && v.dot(n) < 0.0;
                if !pressed && !into {
                    continue;
                }
                if let Some((m, ball, slot)) = held.filter(|&(m, _, _)| n.dot(m) < 1.0 - PARALLEL) {
                    let (here, there) = split(DVec2::ZERO - v, n, m);
                    taken.push((index, h.index, here));
                    taken.push((ball, slot, there));
                    return (DVec2::ZERO, DVec2::ZERO);
                }
                taken.push((index, h.index, DVec2::ZERO - n * v.dot(n)));
                v -= n * v.dot(n);
                if pressed {
                    c -= n * c.dot(n);
                }
                held = Some((n, index, h.index));
            }
        }
        (v, c)
    }
}

/// A cushion's change of a velocity (see [`World::pressed_into_cushions`]): the ball it acts
/// on, the cushion's slot, the change (per unit of the mass that moves).
type Held = (u32, u32, DVec2);
