//! A group takes a hit as one body, while every contact it keeps pushes.
//!
//! A group (`pipeline/group.rs`) is balls pressed together under gravity, each on a parabola
//! with the acceleration its contacts leave it. Its contacts are *kept*: touching, with no
//! relative normal velocity along the normals the group formed with. When a ball from outside
//! strikes a member (or a member strikes a collider), the exact answer is the simultaneous
//! impact of the group and the striker (`dynamics/impact.rs`): the least change of kinetic
//! energy that meets the struck contact's target (its restitution times the speed it
//! approached at) and makes no kept contact approach. The group used to let go at such an event
//! and its members met again at once: a jam of the whole touching cluster, the hold's three
//! solves from scratch, and every member predicted again. In a pile still being fed that was
//! most of the work (a 100-ball raft sliding on a frictionless floor, hit some fifty thousand
//! times a simulated second by the balls tumbling at its edges).
//!
//! Here the kept contacts are factorised once, at the group's first hit ([`Rigid`]: from 40
//! balls on their Gram matrix's sparse Cholesky factor, `dynamics/gram.rs`, which a settling
//! pile's groups of a hundred balls, formed anew at each jam, make some nine times faster than
//! the Gram-Schmidt basis), and a hit
//! is one step of the impact's dual method from the kept set, every kept contact active with
//! no impulse yet: the struck contact's gradient projected against the kept ones, the impulse
//! that meets its target, and each kept contact's share of it. If none of those shares is
//! negative (every kept contact pushes), the answer meets the impact's conditions of optimality
//! with the kept contacts as inequalities, touching and not approaching: it *is* the impact
//! (see [`Rigid`]), and the group goes on with it:
//!
//! - its accelerations stand: they depend on its contacts' normals, the masses and gravity,
//!   none of which a hit changes;
//! - its members still never enter each other or a surface: since the group formed, every
//!   relative motion across a kept contact has been along the contact (the impact keeps each
//!   relative normal velocity what it was, zero), so `|d|^2 = |d0|^2 + |s|^2` with `s` the slide
//!   so far, and the distance only grows (`pipeline/group.rs`);
//! - its forces still do no work (each acts along a normal across which the velocities are
//!   still zero), and the hit adds no energy (checked, against rounding);
//! - each member's time to let go is taken afresh from its new velocity, less what it has
//!   already slid across each contact (`sqrt(|d|^2 - reach^2)`) from the distance
//!   [`GROUP_GAP`](super::group::GROUP_GAP) allows.
//!
//! A hit that would part the group (a kept contact would pull: a member knocked off the
//! others or off the floor) is solved as the impact itself, every kept contact an inequality
//! ([`Hit::Parting`]). If that parts no kept contact faster than it rests at (the speed below
//! which a jam holds a contact touching rather than let it hop, `rest_speeds` in
//! `pipeline/jam.rs`: a settling hop, or with sleeping on the slower ball's sleep speed), the
//! contacts it would part rest, by the jam's own rule, and the group takes the hit whole: the
//! answer is the least change of kinetic energy that meets the struck contact's target with
//! every kept contact held as it is, which keeps the group's contacts, accelerations and times
//! to let go as a hit that every contact pushes does. Those it holds pull, as a jam's resting
//! contacts may; the energy check stands. A poured pile's strikes are often such (the 400-ball
//! pile at e = 0.8, seed 1, to t = 2.05: 5,823 rigid hits where 1,128, and 16,464 jams where
//! 18,568); before, each let the whole group go, and its members, touching and pulled
//! together, met again within microseconds as a jam of the whole cluster. A hit that parts a
//! kept contact faster, a striker that is itself supported or held, and every other event of
//! a member let the group go as before.

use glam::DVec2;

use super::World;
use super::instant::Pair;
use super::jam::{Cluster, RowsOf};
use crate::dynamics::{ContactRow, Hit, Rigid};

/// What a group keeps for a hit: its members as a cluster of the contacts it keeps (between
/// members, and of members with colliders), their masses, and the factorisation of those
/// contacts, made at the first hit.
#[derive(Clone)]
pub(crate) struct Kept {
    cluster: Cluster,
    masses: Vec<f64>,
    rigid: Option<Rigid>,
}

impl Kept {
    /// The kept contacts of a group: `members` (slots), with `masses`, and `rows` among them
    /// (indices into `members`; a surface's rows name theirs in `pairs`), with their pairs and
    /// contact distances.
    pub(super) fn new(
        members: Vec<u32>,
        masses: Vec<f64>,
        rows: Vec<ContactRow>,
        pairs: Vec<Pair>,
        reaches: Vec<f64>,
    ) -> Self {
        let restitutions = vec![0.0; rows.len()];
        Kept {
            cluster: Cluster {
                balls: members,
                pairs,
                rows,
                restitutions,
                reaches,
            },
            masses,
            rigid: None,
        }
    }
}

impl World {
    /// Balls `member`, held by a group, and `other`, free, collide now along `normal` (unit,
    /// from `member` to `other`), asked to separate at `target`: the group takes it as one
    /// body if every contact it keeps pushes, or if the impact parts none of them faster than
    /// it rests at (see the module documentation). Returns the new velocities of `member` and
    /// `other`, the group's and `other`'s trajectories restated; `None` (nothing changed) if
    /// it is no rigid hit.
    pub(super) fn hit_group_by_ball(
        &mut self,
        member: u32,
        other: u32,
        normal: DVec2,
        target: f64,
    ) -> Option<(DVec2, DVec2)> {
        let mass = self.balls.mass_and_restitution(other)?.0;
        let x = self.hit_group(member, Some((other, mass)), normal, target, None)?;
        Some((x.0, x.1?))
    }

    /// Ball `member`, held by a group, meets collider slot `slot` now along `normal` (unit,
    /// from the collider to the ball), asked to leave it at `target`: as
    /// [`Self::hit_group_by_ball`]. Returns the member's new velocity.
    pub(super) fn hit_group_by_collider(
        &mut self,
        member: u32,
        slot: u32,
        normal: DVec2,
        target: f64,
    ) -> Option<DVec2> {
        // The row's normal points from the collider to the ball: as a ball's contact with
        // a surface, from the member's side, its relative normal velocity is `n . v`.
        self.hit_group(member, None, normal, target, Some(slot))
            .map(|x| x.0)
    }

    /// The hit of [`Self::hit_group_by_ball`] (`outsider`: the striker and its mass) or
    /// [`Self::hit_group_by_collider`] (`slot`: the collider's).
    fn hit_group(
        &mut self,
        member: u32,
        outsider: Option<(u32, f64)>,
        normal: DVec2,
        target: f64,
        slot: Option<u32>,
    ) -> Option<(DVec2, Option<DVec2>)> {
        let group = self.held_group(member)?;
        // A strike no faster than a contact rests at (a hop no higher than a settling hop;
        // with sleeping on, no faster than the slower ball sleeps) joins the group rather than
        // bounce off it: the group lets go and the jam that follows keeps the new contact too
        // (struck on and on instead, a member held against a wall bounced off it in a Zeno
        // sequence of ever smaller hits).
        let relative = match outsider {
            Some((other, _)) => self.velocity_now(other) - self.velocity_now(member),
            None => self.velocity_now(member),
        };
        let speed = -relative.dot(normal);
        if speed <= self.rest_speed(member, outsider.map(|(o, _)| o)) {
            return None;
        }
        let at = self.groups.iter().position(|g| g.id == group)?;
        let kept = self.groups[at].kept.as_ref()?;
        let n = kept.cluster.balls.len();
        let local = kept.cluster.balls.iter().position(|&b| b == member)?;
        let time = self.time;
        let mut v: Vec<DVec2> = Vec::with_capacity(n + 1);
        for &ball in &kept.cluster.balls {
            v.push(self.velocity_now(ball));
        }
        let row = match outsider {
            Some((other, _)) => {
                // Free (the caller's condition): under gravity alone.
                v.push(self.velocity_now(other));
                ContactRow {
                    a: local,
                    b: Some(n),
                    normal,
                    target,
                    slack: 0.0,
                }
            }
            None => ContactRow {
                a: local,
                b: None,
                normal,
                target,
                slack: 0.0,
            },
        };
        let kept = self.groups[at].kept.as_mut()?;
        let rows = &kept.cluster.rows;
        let rigid = kept
            .rigid
            .get_or_insert_with(|| Rigid::new(kept.masses.clone(), rows));
        let (x, impulses) = match rigid.hit(rows, outsider.map(|(_, m)| m), &v, row)? {
            Hit::Whole(x, impulses) => (x, impulses),
            Hit::Parting {
                held,
                held_impulses,
                impact,
            } => {
                // Held if the impact parts no kept contact faster than it rests at.
                let impact = impact?;
                let cluster = &self.groups[at].kept.as_ref()?.cluster;
                let rest = self.rest_speeds(cluster);
                let slow = |(row, &w): (&ContactRow, &f64)| row.relative(&impact) <= w;
                if !cluster.rows.iter().zip(&rest).all(slow) {
                    return None;
                }
                (held, held_impulses)
            }
        };
        self.counts.rigid_hits += 1;
        self.note_group_hit(at, outsider.map(|(o, _)| o), slot, row, &impulses);
        // The group's members and the striker start again now with their new velocities.
        let kept = self.groups[at]
            .kept
            .take()
            .expect("the group's kept contacts");
        let mut accelerations = Vec::with_capacity(n);
        for (&ball, &velocity) in kept.cluster.balls.iter().zip(&x) {
            let acceleration = self.balls.acceleration(ball, self.gravity);
            self.balls.rebase(ball, time, acceleration);
            let record = self.balls.kinematics_mut(ball).expect("live member");
            record.trajectory.v0 = velocity;
            accelerations.push(acceleration);
        }
        if let Some((other, _)) = outsider {
            let gravity = self.gravity;
            self.balls.rebase(other, time, gravity);
            let record = self.balls.kinematics_mut(other).expect("live ball");
            record.trajectory.v0 = x[n];
            self.balls.bump_version(other);
        }
        // Each member's time to let go, from its new velocity and what it has slid so far.
        let every: Vec<usize> = (0..kept.cluster.rows.len()).collect();
        let rows_of = RowsOf::new(&kept.cluster, &every);
        for (local, &ball) in kept.cluster.balls.iter().enumerate() {
            let mine = rows_of.of(local);
            let until = self.held_until(&kept.cluster, mine, local, &x, &accelerations, true);
            // The colliders it is held against beside the others stay what they were.
            let touching = (self.balls.properties(ball))
                .map(|p| p.extra.touching().to_vec())
                .unwrap_or_default();
            self.hold_member(ball, accelerations[local], (group, until), touching);
            self.balls.bump_version(ball);
        }
        let members = kept.cluster.balls.clone();
        self.groups[at].kept = Some(kept);
        // Every ball's partners learn of every change before any of them is predicted again.
        for &ball in &members {
            self.schedule(ball);
        }
        if let Some((other, _)) = outsider {
            self.schedule(other);
        }
        // A hit that leaves the group at rest puts it to sleep, as its forming would have.
        self.try_sleep_group(group);
        Some((x[local], outsider.map(|_| x[n])))
    }

    /// The observables of a hit on group `at` (its index in `groups`): `impulses` on its kept
    /// contacts and then on the struck contact `row`, with ball `outsider` (the row's `b`) or
    /// collider slot `slot`; before any trajectory is restated.
    fn note_group_hit(
        &mut self,
        at: usize,
        outsider: Option<u32>,
        slot: Option<u32>,
        row: ContactRow,
        impulses: &[f64],
    ) {
        let Some(kept) = self.groups[at].kept.as_ref() else {
            return;
        };
        let mut balls = kept.cluster.balls.clone();
        let mut rows = kept.cluster.rows.clone();
        let mut pairs = kept.cluster.pairs.clone();
        let member = balls[row.a];
        match (outsider, slot) {
            (Some(other), _) => {
                balls.push(other);
                pairs.push(Pair::balls(member, other));
            }
            (None, Some(slot)) => pairs.push(Pair::Collider(member, slot)),
            (None, None) => return,
        }
        rows.push(row);
        let positions: Vec<DVec2> = balls.iter().map(|&b| self.position_now(b)).collect();
        self.note_rows(&rows, &pairs, &positions, impulses);
    }

    /// The speed at or below which a contact of `member` with `other` (a surface if `None`)
    /// rests rather than bounces: a hop no higher than a settling hop under gravity's full
    /// pull, and with sleeping on no faster than the slower of the two sleeps (as a jam's
    /// contacts rest, `pipeline/jam.rs`).
    fn rest_speed(&self, member: u32, other: Option<u32>) -> f64 {
        let record = self.balls.kinematics(member).expect("live member");
        let (mut r, mut reach) = (record.radius, record.radius);
        let mut c = record.trajectory.p0.abs().max_element();
        if let Some(other) = other {
            let partner = self.balls.kinematics(other).expect("live ball");
            r = r.min(partner.radius);
            reach += partner.radius;
            c = c.max(partner.trajectory.p0.abs().max_element());
        }
        self.rest_speed_at(c, reach, r)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{BallDesc, ColliderDesc, Event};

    /// A member of a group keeps the colliders it is held against beside its fellow members
    /// (its `touching`, not predicted against while the group holds) through a hit the group
    /// takes as one body. Cleared by the hit's restatement, the floor under a stack's bottom
    /// ball was predicted against again, and a normal velocity of `-1e-19` that the hit's
    /// rounding left was a contact with it: the group let go, and its members met again as
    /// jams of their cluster (12,583 such contacts of kept colliders in 15 s of the 400-ball
    /// pile's wall).
    #[test]
    fn a_member_keeps_the_colliders_it_is_held_against_through_a_rigid_hit() {
        let (g, r, u, e) = (9.81, 0.2, 0.5, 0.5);
        let mut world = World::with_gravity(DVec2::new(0.0, -g)).unwrap();
        world.set_sleeping(true);
        let floor = world
            .add_collider(ColliderDesc::segment(
                DVec2::new(-100.0, 0.0),
                DVec2::new(100.0, 0.0),
            ))
            .unwrap();
        let mut add = |p: DVec2, w: DVec2| {
            (world.add_ball(BallDesc::new(p, r).velocity(w).restitution(e)))
                .unwrap()
                .index()
        };
        let bottom = add(DVec2::new(0.0, r), DVec2::new(u, 0.0));
        let top = add(DVec2::new(0.0, 3.0 * r), DVec2::new(u, 0.0));
        let touching = |world: &World, ball: u32| {
            let properties = world.balls.properties(ball).expect("live ball");
            properties.extra.touching().to_vec()
        };
        while world.step_until(0.5).unwrap().is_some() {}
        let group = world.held_group(bottom).expect("a group");
        assert_eq!(world.held_group(top), Some(group));
        assert_eq!(touching(&world, bottom), [floor]);
        assert!(touching(&world, top).is_empty());
        // A ball dropped onto the top one, moving along with the stack.
        let t0 = world.time();
        world
            .add_ball(
                BallDesc::new(DVec2::new(u * t0, 6.0 * r), r)
                    .velocity(DVec2::new(u, -2.0))
                    .restitution(e),
            )
            .unwrap();
        let hits = world.event_counts().rigid_hits;
        while !matches!(
            world.step_until(t0 + 1.0).unwrap(),
            Some(Event::BallContact(_))
        ) {}
        assert_eq!(world.event_counts().rigid_hits, hits + 1);
        assert_eq!(world.held_group(bottom), Some(group));
        assert_eq!(touching(&world, bottom), [floor]);
        assert!(touching(&world, top).is_empty());
    }
}
