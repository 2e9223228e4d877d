//! Sleeping balls: a ball at rest on what it touches costs nothing until something moves it.
//!
//! When a ball's contacts hold it against gravity and it is slow (the criterion is stated and
//! justified in `dynamics/sleep.rs`), it *falls asleep*: its velocity is dropped, its
//! position kept to the bit, and it leaves the ball grid and the event queue. In its place the
//! world lists a static circle of its radius and restitution at its position, its *proxy*,
//! with its collision groups: to every other ball it is that circle, so settling on it,
//! sliding and pivoting over it, resting in the pocket of two of them and leaving it are the
//! resting machinery that colliders already have (`dynamics/support.rs`). A ball bouncing on a
//! sleeping ball with restitution below 1 comes to rest after finitely many events, at the
//! accumulation of its bounces, as on a floor. Proxies are internal: `World::colliders`,
//! `collider`, `collider_count` and `remove_collider` never show them, and a contact with one
//! is reported as the [`BallContactEvent`] of the two balls.
//!
//! # The support graph, and when a ball wakes
//!
//! A sleeping ball records its *contacts* when it falls asleep: the colliders and the proxies
//! of balls asleep before it that it touches, with their normals. Those sleeping balls list it
//! as a *dependent*. A ball asleep alone only lists balls asleep before it; the members of an
//! island ([`World::try_sleep_group`]) list each other too, so walks over the graph allow for
//! cycles (a wake is idempotent; a push that comes back to a sleeper counts as taken). A
//! sleeping ball's circle is touched as far as two balls touch (`balls_touch`).
//! A sleeping ball wakes (its proxy goes, it is a ball at rest in the grid again, predicted
//! afresh, and every awake ball sliding on its proxy or resting against it is released) when:
//! - a ball meets it with a push its contacts cannot take (`dynamics::takes`: the push is
//!   followed through the sleepers under it) and not too gentle to matter
//!   (`dynamics::gentle`: one that could give it no more than its sleep speed); the contact
//!   is then a normal two-ball collision. A push they take leaves it asleep, and the mover
//!   bounces off it with the pair's restitution, as off a static circle;
//! - one of its contacts goes away (a collider removed, a sleeping ball woken or removed) and
//!   the others no longer hold it against gravity: so a pile whose floor is removed wakes as a
//!   whole, at rest, and falls at `g t^2 / 2`. Where the others still hold it, it sleeps on,
//!   and if the contact gone was its support, the contact left that gravity presses it on
//!   hardest becomes its support;
//! - it is removed (its dependents then lose that contact), or given a velocity;
//! - gravity changes ([`World::set_gravity`] wakes every ball, and each settles and sleeps
//!   again where it still rests).
//!
//! A woken ball is at rest under gravity: what it touches decides afresh, at once (it settles,
//! slides, falls), and if it rests it sleeps again at its next settle. So that no instant can
//! loop between the two, a ball falls asleep at most [`SLEEPS_PER_INSTANT`] times at one
//! instant.
//!
//! [`BallContactEvent`]: crate::BallContactEvent

use glam::DVec2;

use super::World;
use super::event::{BallContactEvent, Event};
use super::group::GROUP_GAP;
use super::pending::{Entry, PendingQueue};
use super::step::balls_touch;
use crate::broad::Place;
use crate::dynamics::{
    BallHandle, NO_COLLIDER, Roughness, Sleep, Support, Time, Touch, Trajectory, gentle, rests,
    sleep_speed, takes,
};
use crate::geometry::{Circle, Collider, ColliderHandle, Shape};

/// The most times one ball falls asleep at one instant (a ball woken and put back to sleep
/// by a chain of contacts at one instant stays awake after that, and sleeps at its next
/// settle): 2.
pub const SLEEPS_PER_INSTANT: u32 = 2;

/// A body another rests on: a collider, or a sleeping ball.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Body {
    /// A static collider.
    Collider(ColliderHandle),
    /// A ball (asleep, while another rests on it).
    Ball(BallHandle),
}

const NONE: u32 = u32::MAX;

/// The world's record of its sleeping balls.
#[derive(Clone, Default)]
pub(crate) struct Sleepers {
    /// Per collider slot, the ball slot sleeping as that collider ([`NONE`]: a real collider).
    by_collider: Vec<u32>,
    /// How many balls sleep.
    count: usize,
    /// The instant of the last fall asleep, and the balls that fell asleep at it.
    naps: (Time, Vec<u32>),
}

impl Sleepers {
    /// The ball sleeping as collider slot `slot`, if it is a proxy.
    #[inline]
    pub(crate) fn ball_of(&self, slot: u32) -> Option<u32> {
        self.by_collider
            .get(slot as usize)
            .copied()
            .filter(|&b| b != NONE)
    }

    /// How many balls sleep.
    pub(crate) fn count(&self) -> usize {
        self.count
    }

    fn set(&mut self, slot: u32, ball: u32) {
        let i = slot as usize;
        if self.by_collider.len() <= i {
            self.by_collider.resize(i + 1, NONE);
        }
        self.by_collider[i] = ball;
    }
}

impl World {
    /// Whether ball `index` sleeps.
    #[inline]
    pub(crate) fn is_asleep(&self, index: u32) -> bool {
        self.sleepers.count > 0
            && self.balls.is_supported(index)
            && self
                .balls
                .properties(index)
                .is_some_and(|p| p.extra.sleep().is_some())
    }

    /// The ball asleep as collider `handle`, if it is a proxy.
    pub(crate) fn sleeper_of(&self, handle: ColliderHandle) -> Option<u32> {
        if self.sleepers.count == 0 || !self.colliders.is_live(handle.index, handle.generation) {
            return None;
        }
        self.sleepers.ball_of(handle.index)
    }

    /// Whether collider slot `slot` is a proxy (see the module documentation).
    pub(crate) fn is_proxy(&self, slot: u32) -> bool {
        self.sleepers.count > 0 && self.sleepers.ball_of(slot).is_some()
    }

    /// A collider as the user sees it: a proxy is the ball asleep there.
    pub(crate) fn body_of(&self, handle: ColliderHandle) -> Body {
        match self.sleeper_of(handle) {
            Some(ball) => Body::Ball(self.balls.handle(ball)),
            None => Body::Collider(handle),
        }
    }

    /// Ball `index`, supported, falls asleep now if it meets the sleep criterion
    /// (`dynamics/sleep.rs`); returns whether it did. A member of a group at rest that the
    /// colliders and sleeping balls it touches hold alone lets its group go and sleeps.
    pub(crate) fn try_sleep(&mut self, index: u32) -> bool {
        let gravity = self.gravity;
        let g = gravity.length();
        if !self.resting() || !(g > 0.0) || !self.balls.is_supported(index) || self.is_asleep(index)
        {
            return false;
        }
        let acceleration = self.acceleration(index);
        if acceleration.length() > crate::dynamics::PARALLEL * g {
            return false;
        }
        let ball = self.balls.kinematics(index).expect("live ball");
        let (radius, trajectory) = (ball.radius, ball.trajectory);
        let v = trajectory.velocity_at(self.time, acceleration);
        if v.length() > sleep_speed(g, radius) {
            return false;
        }
        let (at, napped) = &self.sleepers.naps;
        if *at == self.time
            && napped.iter().filter(|&&b| b == index).count() >= SLEEPS_PER_INSTANT as usize
        {
            return false;
        }
        let p = trajectory.position_at(self.time, acceleration);
        let touched = self.touched_colliders(index, p, radius, crate::dynamics::NO_COLLIDER);
        let normals: Vec<DVec2> = touched.iter().map(|(_, _, t)| t.normal).collect();
        if !rests(gravity, &normals) {
            return false;
        }
        if let Some(group) = self.held_group(index) {
            self.let_go(group);
        }
        // The contact that pushes most against gravity stands for its support.
        let (first, _, touch) = touched
            .iter()
            .min_by(|a, b| a.2.normal.dot(gravity).total_cmp(&b.2.normal.dot(gravity)))
            .copied()
            .expect("a resting ball touches something");
        let contacts = touched.iter().map(|&(h, _, t)| (h, t.normal)).collect();
        self.fall_asleep(
            index,
            p,
            Support::asleep(first, touch.feature, touch.normal, p),
            contacts,
        );
        true
    }

    /// Group `group`, just formed by a jam, falls asleep whole if it is at rest: every member
    /// held still (its solved acceleration zero) and slow ([`sleep_speed`]), and each, taken
    /// from the lowest up (along gravity), held by the colliders, sleeping balls and members
    /// below it in that order that it touches (`-g` in the cone of their normals, as for one
    /// ball). An island of balls resting on each other thus sleeps at once, bottom up, with
    /// the support graph of balls asleep one after another. Where that test fails, the
    /// group's solve, which holds every member still, is the proof of rest (an arch, a wedge
    /// of nearly opposite neighbours): the members sleep and list each other. Returns whether
    /// it did; a group that does not is left as it is.
    pub(crate) fn try_sleep_group(&mut self, group: u32) -> bool {
        let gravity = self.gravity;
        let g = gravity.length();
        if !self.resting() || !(g > 0.0) {
            return false;
        }
        let Some(at) = self.groups.iter().position(|x| x.id == group) else {
            return false;
        };
        let up = -gravity / g;
        // Each member with its position and radius now, and the colliders the group's solve
        // held it against (they may lie a rounding further than a settle's touch: the member
        // was held there, still, with them).
        let members = &self.groups[at].members;
        let mut placed: Vec<(u32, DVec2, f64, Vec<ColliderHandle>)> =
            Vec::with_capacity(members.len());
        for &index in members {
            if self.balls.held_group(index) != Some(group) || self.is_asleep(index) {
                return false;
            }
            let acceleration = self.acceleration(index);
            if acceleration != DVec2::ZERO {
                return false;
            }
            let ball = self.balls.kinematics(index).expect("live ball");
            let v = ball.trajectory.velocity_at(self.time, acceleration);
            if v.length() > sleep_speed(g, ball.radius) {
                return false;
            }
            let (naps_at, napped) = &self.sleepers.naps;
            if *naps_at == self.time
                && napped.iter().filter(|&&b| b == index).count() >= SLEEPS_PER_INSTANT as usize
            {
                return false;
            }
            let p = ball.trajectory.position_at(self.time, acceleration);
            let pressed = self
                .balls
                .properties(index)
                .map_or_else(Vec::new, |q| q.extra.touching().to_vec());
            placed.push((index, p, ball.radius, pressed));
        }
        // The group's contacts between members touch for this test as far as the jam that
        // formed the group took them (fellows, `pipeline/jam.rs`: up to the group gap).
        let pairs = self.groups[at].pairs.clone();
        let fellows =
            |a: u32, b: u32, gap: f64, reach: f64| gap <= GROUP_GAP * reach && pairs.holds(a, b);
        // Lowest first; a tie in slot order.
        placed.sort_by(|a, b| a.1.dot(up).total_cmp(&b.1.dot(up)).then(a.0.cmp(&b.0)));
        // Each member held by what is below it in that order: checked before any sleeps.
        // Failing that (an arch: a ball pressed into its place by those above it; a ball in a
        // wedge of neighbours so nearly opposite that the cone test, to `PARALLEL`, sees no
        // wedge), the group's own solve is the proof of rest: it holds every member still
        // with the contacts it found, and the group sleeps as an island whose members list
        // each other (each touching something).
        let held = |world: &World, k: usize| {
            let (index, p, radius, ref pressed) = placed[k];
            let mut normals: Vec<DVec2> = world
                .resting_contacts(index, p, radius, pressed)
                .iter()
                .map(|(_, _, t)| t.normal)
                .collect();
            for &(other, q, r, _) in &placed[..k] {
                let d = p - q;
                let (length, reach) = (d.length(), radius + r);
                let coordinates = p.abs().max_element().max(q.abs().max_element());
                if length > 0.0
                    && (balls_touch(length - reach, coordinates, reach)
                        || fellows(index, other, length - reach, reach))
                {
                    normals.push(d / length);
                }
            }
            rests(gravity, &normals)
        };
        let bottom_up = (0..placed.len()).all(|k| held(self, k));
        // The group is gone: its members sleep where they are, one after another, each on
        // what it touches, the colliders it was held against, and the circles of its fellows
        // asleep before it.
        self.groups.swap_remove(at);
        for (k, (index, p, radius, pressed)) in placed.iter().enumerate() {
            let (index, p, radius) = (*index, *p, *radius);
            let mut pressed = pressed.clone();
            for &(other, q, r, _) in &placed[..k] {
                if fellows(index, other, p.distance(q) - (radius + r), radius + r) {
                    let sleep = self.balls.properties(other).and_then(|x| x.extra.sleep());
                    pressed.extend(sleep.map(|sleep| sleep.proxy));
                }
            }
            let touched = self.resting_contacts(index, p, radius, &pressed);
            let normals: Vec<DVec2> = touched.iter().map(|(_, _, t)| t.normal).collect();
            let first = touched
                .iter()
                .min_by(|a, b| a.2.normal.dot(gravity).total_cmp(&b.2.normal.dot(gravity)))
                .copied();
            match first {
                Some((first, _, touch)) if !bottom_up || rests(gravity, &normals) => {
                    let contacts = touched.iter().map(|&(h, _, t)| (h, t.normal)).collect();
                    self.fall_asleep(
                        index,
                        p,
                        Support::asleep(first, touch.feature, touch.normal, p),
                        contacts,
                    );
                }
                _ => {
                    // Not held after all (the circles below it round otherwise than the
                    // check): it moves under gravity again, at rest, predicted afresh.
                    let time = self.time;
                    let record = self.balls.kinematics_mut(index).expect("live ball");
                    record.trajectory = Trajectory {
                        p0: p,
                        v0: DVec2::ZERO,
                        t0: time,
                    };
                    self.balls.clear_residual(index);
                    self.balls.set_support(index, None, self.time);
                    self.balls.bump_version(index);
                    self.schedule(index);
                }
            }
        }
        if !bottom_up {
            // An island: each member lists the members it touches that fell asleep after it,
            // and is their dependent, so that it wakes when they go and they take its pushes.
            for (index, p, radius, pressed) in &placed {
                let index = *index;
                for (handle, _, touch) in self.resting_contacts(index, *p, *radius, pressed) {
                    let Some(other) = self.sleeper_of(handle) else {
                        continue;
                    };
                    let Some(sleep) = self
                        .balls
                        .properties_mut(index)
                        .and_then(|q| q.extra.sleep_mut())
                    else {
                        continue;
                    };
                    if sleep.contacts.iter().any(|&(h, _)| h == handle) {
                        continue;
                    }
                    sleep.contacts.push((handle, touch.normal));
                    if let Some(sleep) = self
                        .balls
                        .properties_mut(other)
                        .and_then(|q| q.extra.sleep_mut())
                    {
                        sleep.dependents.push(index);
                    }
                }
            }
        }
        true
    }

    /// What ball `index` at `p` rests on and against: the colliders and sleeping balls it
    /// touches, and those of `pressed` (a group's held contacts) beside them.
    fn resting_contacts(
        &self,
        index: u32,
        p: DVec2,
        radius: f64,
        pressed: &[ColliderHandle],
    ) -> Vec<(ColliderHandle, Collider, Touch)> {
        let mut touched = self.touched_colliders(index, p, radius, NO_COLLIDER);
        for &handle in pressed {
            if touched.iter().any(|(h, _, _)| *h == handle) {
                continue;
            }
            if let Some(collider) = self.colliders.get(handle) {
                if let Some(touch) = Touch::of(&collider.shape, p, radius) {
                    touched.push((handle, *collider, touch));
                }
            }
        }
        touched
    }

    /// Puts ball `index` to sleep at `p` with `support` (at rest) and `contacts`.
    fn fall_asleep(
        &mut self,
        index: u32,
        p: DVec2,
        support: Support,
        contacts: Vec<(ColliderHandle, DVec2)>,
    ) {
        let time = self.time;
        let (radius, restitution, groups) = {
            let ball = self.balls.kinematics(index).expect("live ball");
            let properties = self.balls.properties(index).expect("live ball");
            let (_, restitution) = self.balls.mass_and_restitution(index).expect("live ball");
            (ball.radius, restitution, properties.groups)
        };
        // Its circle has its surface. A ball with friction stops turning too (it rolled to a
        // stop, or rests in a pocket that friction holds); a frictionless one keeps its spin,
        // which nothing it rests on can change.
        let roughness = self
            .balls
            .spin(index)
            .map_or(Roughness::SMOOTH, |s| s.roughness);
        if roughness.friction > 0.0 {
            self.balls.spin_mut(index).set_motion(time, 0.0, 0.0);
        }
        let record = self.balls.kinematics_mut(index).expect("live ball");
        record.trajectory = Trajectory {
            p0: p,
            v0: DVec2::ZERO,
            t0: time,
        };
        self.balls.clear_residual(index);
        self.balls.set_support(index, Some(support), self.time);
        // Its circle, for every other ball.
        let circle = Circle::new(p, radius).expect("a live ball's radius is positive");
        let proxy = Collider {
            shape: Shape::Circle(circle),
            sensor: false,
            restitution,
            groups,
            user_data: 0,
            friction: roughness.friction,
            tangential_restitution: roughness.tangential_restitution,
            rolling_resistance: roughness.rolling_resistance,
        };
        let handle = self.colliders.insert(proxy);
        self.note_born(handle.index);
        let (min, max) = proxy.shape.aabb();
        self.statics
            .insert(handle.index, crate::broad::Aabb { min, max });
        self.sleepers.set(handle.index, index);
        self.sleepers.count += 1;
        for &(contact, _) in &contacts {
            if let Some(under) = self.sleeper_of(contact) {
                if let Some(sleep) = self
                    .balls
                    .properties_mut(under)
                    .and_then(|p| p.extra.sleep_mut())
                {
                    sleep.dependents.push(index);
                }
            }
        }
        let sleep = Sleep {
            proxy: handle,
            since: time,
            contacts,
            dependents: Vec::new(),
        };
        self.balls
            .properties_mut(index)
            .expect("live ball")
            .extra
            .set_sleep(Some(sleep));
        if self.sleepers.naps.0 != time {
            self.sleepers.naps = (time, Vec::new());
        }
        self.sleepers.naps.1.push(index);
        // Out of the grid and the queue; the balls that could meet it meet its circle.
        let place = self.grid.place(index);
        let mut near = Vec::new();
        if place != Place::Absent {
            self.grid
                .near_place(place, index, |other, _| near.push(other));
        }
        self.grid.unregister(index);
        self.queue.set(index, None, None);
        self.balls.bump_version(index);
        self.counts.sleeps += 1;
        for other in near {
            self.meet_proxy(other, handle, &proxy);
        }
    }

    /// Ball `other` learns of a new proxy `handle` (as of a new collider, see
    /// `World::add_collider`): restated if its path crossed the circle's place before now,
    /// else given the contact if it is earlier than its prediction.
    fn meet_proxy(&mut self, other: u32, handle: ColliderHandle, proxy: &Collider) {
        let Some(properties) = self.balls.properties(other) else {
            return;
        };
        if !properties.groups.interact(proxy.groups) {
            return;
        }
        self.grid.set_near_statics(other, true);
        self.offer_collider(other, handle, proxy);
    }

    /// Wakes ball `index` if it sleeps, and every sleeping ball that then no longer rests
    /// (see the module documentation); each is at rest, predicted afresh.
    pub(crate) fn wake(&mut self, index: u32) {
        if !self.is_asleep(index) {
            return;
        }
        let mut pending = vec![index];
        let mut woken = Vec::new();
        let mut gone = Vec::new();
        while let Some(ball) = pending.pop() {
            let Some(sleep) = self
                .balls
                .properties_mut(ball)
                .and_then(|p| p.extra.set_sleep(None))
            else {
                continue;
            };
            for &(contact, _) in &sleep.contacts {
                if let Some(under) = self.sleeper_of(contact) {
                    if let Some(s) = self
                        .balls
                        .properties_mut(under)
                        .and_then(|p| p.extra.sleep_mut())
                    {
                        s.dependents.retain(|&d| d != ball);
                    }
                }
            }
            self.colliders.remove(sleep.proxy);
            self.statics.remove(sleep.proxy.index);
            self.sleepers.set(sleep.proxy.index, NONE);
            self.sleepers.count -= 1;
            self.counts.wakes += 1;
            gone.push(sleep.proxy);
            // Its dependents lose it; those the rest no longer hold wake too.
            for dependent in sleep.dependents {
                if self.loses_contact(dependent, sleep.proxy) {
                    pending.push(dependent);
                }
            }
            let time = self.time;
            let record = self.balls.kinematics_mut(ball).expect("live ball");
            record.trajectory = Trajectory {
                p0: record.trajectory.p0,
                v0: DVec2::ZERO,
                t0: time,
            };
            let p = record.trajectory.p0;
            self.balls.set_support(ball, None, self.time);
            self.balls.bump_version(ball);
            let groups = self.balls.properties(ball).expect("live ball").groups;
            if self.grid.admits(groups) {
                let place = self.grid.place_of(p);
                self.register_in_grid(ball, place);
            }
            woken.push(ball);
        }
        self.release_held_by(&gone);
        for ball in woken {
            self.schedule(ball);
        }
    }

    /// Sleeping ball `index` loses its contact `gone`; returns whether what is left no
    /// longer holds it (it must wake). If it still rests and `gone` was its support, the
    /// support becomes the contact left that gravity presses it on hardest, as when it fell
    /// asleep (a sleeping ball's support is always live); should none of them touch it as a
    /// surface does, it wakes.
    pub(crate) fn loses_contact(&mut self, index: u32, gone: ColliderHandle) -> bool {
        let gravity = self.gravity;
        let Some(sleep) = self
            .balls
            .properties_mut(index)
            .and_then(|p| p.extra.sleep_mut())
        else {
            return false;
        };
        let before = sleep.contacts.len();
        sleep.contacts.retain(|&(h, _)| h != gone);
        if sleep.contacts.len() == before {
            return false;
        }
        let contacts = sleep.contacts.clone();
        let normals: Vec<DVec2> = contacts.iter().map(|&(_, n)| n).collect();
        if !rests(gravity, &normals) {
            return true;
        }
        let supported_by_gone = self
            .balls
            .properties(index)
            .and_then(|p| p.extra.support())
            .is_some_and(|s| s.collider == gone);
        if !supported_by_gone {
            return false;
        }
        let ball = self.balls.kinematics(index).expect("live ball");
        let (p, radius) = (ball.trajectory.p0, ball.radius);
        let first = contacts
            .iter()
            .filter_map(|&(h, n)| {
                let collider = self.colliders.get(h)?;
                Touch::of(&collider.shape, p, radius).map(|touch| (h, n, touch))
            })
            .min_by(|a, b| a.1.dot(gravity).total_cmp(&b.1.dot(gravity)));
        let Some((handle, _, touch)) = first else {
            return true;
        };
        let time = self.time;
        self.balls.set_support(
            index,
            Some(Support::asleep(handle, touch.feature, touch.normal, p)),
            time,
        );
        false
    }

    /// Releases every awake supported ball whose support, wedge or touched surfaces include
    /// one of `gone` (removed colliders, or the proxies of woken balls): it moves on under
    /// gravity, and settles again at once if it still rests.
    pub(crate) fn release_held_by(&mut self, gone: &[ColliderHandle]) {
        if gone.is_empty() || self.gravity == DVec2::ZERO {
            return;
        }
        let held: Vec<u32> = self
            .balls
            .iter()
            .filter(|&(i, _, p)| {
                self.balls.is_supported(i)
                    && p.extra.sleep().is_none()
                    && (p.extra.touching().iter().any(|h| gone.contains(h))
                        || p.extra.support().is_some_and(|s| {
                            gone.contains(&s.collider) || s.wedge.is_some_and(|w| gone.contains(&w))
                        }))
            })
            .map(|(i, _, _)| i)
            .collect();
        for index in held {
            self.release(index);
        }
    }

    /// Whether sleeping ball `index` takes a push from direction `d` (unit, from its centre to
    /// the pusher), followed through the sleepers under it (see `dynamics/sleep.rs`).
    fn push_taken(&self, index: u32, d: DVec2) -> bool {
        let contacts = |ball: u32| -> Vec<(DVec2, Option<u32>)> {
            let Some(sleep) = self.balls.properties(ball).and_then(|p| p.extra.sleep()) else {
                return Vec::new();
            };
            let mut list: Vec<(DVec2, Option<u32>)> = sleep
                .contacts
                .iter()
                .filter(|(h, _)| self.colliders.is_live(h.index, h.generation))
                .map(|&(h, n)| (n, self.sleeper_of(h)))
                .collect();
            // The balls asleep against it push back along their own normals to it.
            for &dependent in &sleep.dependents {
                let normal = self
                    .balls
                    .properties(dependent)
                    .and_then(|p| p.extra.sleep())
                    .and_then(|s| s.contacts.iter().find(|(h, _)| *h == sleep.proxy))
                    .map(|&(_, n)| n);
                if let Some(n) = normal {
                    list.push((-n, Some(dependent)));
                }
            }
            list
        };
        takes(index, d, &contacts)
    }

    /// Ball `entry.owner` meets sleeping ball `sleeper`'s circle: it bounces off it if the
    /// sleeper's contacts take the push, else the sleeper wakes and the two collide.
    pub(crate) fn apply_sleeper_contact(&mut self, entry: Entry, sleeper: u32) -> Event {
        let index = entry.owner;
        let p = self
            .balls
            .kinematics(index)
            .expect("live ball")
            .trajectory
            .position_at(self.time, self.acceleration(index));
        let v = self
            .balls
            .kinematics(index)
            .expect("live ball")
            .trajectory
            .velocity_at(self.time, self.acceleration(index));
        let resting = self.balls.kinematics(sleeper).expect("live ball");
        let (q, radius) = (resting.trajectory.p0, resting.radius);
        let d = (p - q).normalize_or_zero();
        let mass = |ball: u32| self.balls.mass_and_restitution(ball).expect("live ball").0;
        let slow = sleep_speed(self.gravity.length(), radius);
        let soft = gentle(-v.dot(d), mass(index), mass(sleeper), slow);
        if soft || self.push_taken(sleeper, d) {
            let contact = self.bounce_off_collider(entry);
            self.counts.ball_contacts += 1;
            let (mover, other) = (self.balls.handle(index), self.balls.handle(sleeper));
            // Named in slot order, the normal from the first to the second, as every
            // collision of two balls is.
            let (a, b, normal) = if index < sleeper {
                (mover, other, DVec2::ZERO - contact.normal)
            } else {
                (other, mover, contact.normal)
            };
            return Event::BallContact(BallContactEvent {
                time: contact.time,
                a,
                b,
                point: contact.point,
                normal,
                normal_speed: contact.normal_speed,
                impulse: contact.impulse,
                // Along the mover's own contact's `perp`: with the normal turned to point
                // from the first ball to the second, the sleeper's opposite impulse along the
                // turned `perp` is the same number.
                tangential_impulse: contact.tangential_impulse,
            });
        }
        self.wake(sleeper);
        self.collide_pair(index.min(sleeper), index.max(sleeper))
    }
}
