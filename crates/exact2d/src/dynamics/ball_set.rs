//! Storage for balls: slots with generations and the counters that invalidate predictions.

use glam::DVec2;

use super::{BallHandle, Sleep, Spin, Support, Time, Trajectory};
use crate::geometry::{ColliderHandle, CollisionGroups};

/// What a ball rarely has: the sensors it overlaps now (in the order it entered them), the
/// surface that supports it (see [`Support`]) and the other solid colliders it touched when
/// it settled (see [`Hold`](super::Hold)). Usually none, so one thin pointer.
#[derive(Clone, Debug, Default)]
pub(crate) struct Extra(Option<Box<ExtraData>>);

#[derive(Clone, Debug, Default)]
struct ExtraData {
    sensors: Vec<ColliderHandle>,
    support: Option<Support>,
    /// Solid colliders the ball touched when it settled, besides its support, that do not
    /// hold it (it slides along them) or hold it with the support (a wedge): touched all along
    /// the support's motion, they are not predicted against while it lasts.
    touching: Vec<ColliderHandle>,
    /// The line the ball last slid on (its segment, unit normal and a point of it): a ball
    /// settling back on it, still on it, slides on it again, never on a line recomputed from
    /// its rounded position (a ball knocked off and settling back at every micro-hop of a
    /// ball on it would otherwise walk into it by a rounding a time).
    line: Option<(ColliderHandle, DVec2, DVec2)>,
    /// While the ball sleeps (see `dynamics/sleep.rs`).
    sleep: Option<Sleep>,
}

impl Extra {
    pub(crate) fn from_sensors(handles: Vec<ColliderHandle>) -> Self {
        Self((!handles.is_empty()).then(|| {
            Box::new(ExtraData {
                sensors: handles,
                support: None,
                touching: Vec::new(),
                line: None,
                sleep: None,
            })
        }))
    }

    /// The sensors, in the order the ball entered them.
    pub(crate) fn sensors(&self) -> &[ColliderHandle] {
        self.0.as_deref().map_or(&[], |d| d.sensors.as_slice())
    }

    pub(crate) fn contains(&self, handle: ColliderHandle) -> bool {
        self.sensors().contains(&handle)
    }

    pub(crate) fn push(&mut self, handle: ColliderHandle) {
        self.0.get_or_insert_default().sensors.push(handle);
    }

    /// Removes sensor `handle`; returns whether it was there.
    pub(crate) fn remove(&mut self, handle: ColliderHandle) -> bool {
        let Some(data) = self.0.as_mut() else {
            return false;
        };
        let Some(at) = data.sensors.iter().position(|&h| h == handle) else {
            return false;
        };
        data.sensors.remove(at);
        self.shrink();
        true
    }

    /// The surface supporting the ball, if any.
    pub(crate) fn support(&self) -> Option<&Support> {
        self.0.as_deref().and_then(|d| d.support.as_ref())
    }

    /// Sets the supporting surface; the colliders touched beside it are forgotten (see
    /// [`Self::set_touching`]).
    pub(crate) fn set_support(&mut self, support: Option<Support>) {
        match support {
            Some(s) => {
                let data = self.0.get_or_insert_default();
                data.support = Some(s);
                data.touching.clear();
            }
            None => {
                if let Some(data) = self.0.as_mut() {
                    data.support = None;
                    data.touching.clear();
                }
                self.shrink();
            }
        }
    }

    /// The line the ball last slid on: its segment, unit normal and a point of it.
    pub(crate) fn line(&self) -> Option<(ColliderHandle, DVec2, DVec2)> {
        self.0.as_deref().and_then(|d| d.line)
    }

    /// Remembers the line the ball slides on now.
    pub(crate) fn set_line(&mut self, line: (ColliderHandle, DVec2, DVec2)) {
        self.0.get_or_insert_default().line = Some(line);
    }

    /// The solid colliders touched beside the support (empty without one).
    pub(crate) fn touching(&self) -> &[ColliderHandle] {
        self.0.as_deref().map_or(&[], |d| d.touching.as_slice())
    }

    /// Sets the colliders touched beside the support; only while there is one.
    pub(crate) fn set_touching(&mut self, touching: Vec<ColliderHandle>) {
        if let Some(data) = self.0.as_mut().filter(|d| d.support.is_some()) {
            data.touching = touching;
        }
    }

    /// The ball's sleep, while it sleeps.
    pub(crate) fn sleep(&self) -> Option<&Sleep> {
        self.0.as_deref().and_then(|d| d.sleep.as_ref())
    }

    /// The ball's sleep, to change its contacts or dependents.
    pub(crate) fn sleep_mut(&mut self) -> Option<&mut Sleep> {
        self.0.as_deref_mut().and_then(|d| d.sleep.as_mut())
    }

    /// Puts the ball to sleep (`Some`) or takes its sleep away, returning the old one.
    pub(crate) fn set_sleep(&mut self, sleep: Option<Sleep>) -> Option<Sleep> {
        let old = match sleep {
            Some(s) => self.0.get_or_insert_default().sleep.replace(s),
            None => self.0.as_mut().and_then(|d| d.sleep.take()),
        };
        self.shrink();
        old
    }

    fn shrink(&mut self) {
        if self.0.as_ref().is_some_and(|d| {
            d.sensors.is_empty() && d.support.is_none() && d.line.is_none() && d.sleep.is_none()
        }) {
            self.0 = None;
        }
    }
}

/// What predicting against a ball reads, in one cache line: its path, its radius, and the
/// counters that tell whether it is live and whether a prediction against it is current.
#[derive(Clone, Debug)]
#[repr(C, align(64))]
pub(crate) struct Kinematics {
    pub trajectory: Trajectory,
    pub radius: f64,
    /// Even while the slot holds a ball; odd while it is free.
    generation: u32,
    /// Bumped (by 2) whenever the ball's trajectory changes (or the ball is removed): events
    /// other balls predicted against the old trajectory are then out of date. Only ever grows,
    /// across reuse of the slot, so an event predicted against an earlier occupant can never
    /// be mistaken for a current one. Its lowest bit says whether the ball is supported
    /// (its acceleration is then its [`Support`]'s, not gravity): a prediction reads it with
    /// the rest of the line.
    version: u32,
}

impl Kinematics {
    fn is_live(&self) -> bool {
        self.generation % 2 == 0
    }

    /// Whether the ball is supported (see [`BallSet::acceleration`]).
    #[inline]
    pub(crate) fn is_supported(&self) -> bool {
        self.version & 1 == 1
    }
}

/// What a ball's events read only when they happen: 24 bytes (its mass and restitution are
/// kept apart, see [`BallSet`]).
#[derive(Clone, Debug)]
pub(crate) struct Properties {
    pub groups: CollisionGroups,
    pub user_data: u64,
    pub extra: Extra,
}

/// Balls in slots, their hot and cold halves in two arrays; iteration is in slot order.
///
/// A million balls should fit in 200 MB with everything the engine keeps about them, and a
/// prediction should touch one cache line per candidate ball: a slot is a 64-byte
/// [`Kinematics`] line plus 24 bytes of [`Properties`], and 16 bytes of [`Material`] once two
/// balls differ in mass or restitution (while all share them, as the balls of a hard-disk gas
/// do, the shared pair stands for every ball's). A slot is live when its generation is even
/// (a removal makes it odd, reuse even again), which spares an `Option` tag, and the rarely
/// used list of sensors a ball is inside lives out of line.
#[derive(Clone, Default)]
pub(crate) struct BallSet {
    kinematics: Vec<Kinematics>,
    properties: Vec<Properties>,
    /// Every slot's mass and restitution once [`Shared::Mixed`]; empty before.
    materials: Vec<Material>,
    free: Vec<u32>,
    len: usize,
    shared: Shared,
    /// Every slot's spin (see `dynamics/rough.rs`), or empty while no ball has spin, friction
    /// or a moment of inertia of its own: frictionless worlds keep none.
    spins: Vec<Spin>,
    /// Whether restatements carry each position's residual ([`Self::rebase`]): once the world
    /// has had gravity or a table. Without either (a gas) paths are restated as before.
    carrying: bool,
    /// Every slot's residual, what its `p0` left out, while `carrying` (empty until a ball is
    /// first restated so); kept beside the slots, not in their cache line.
    residuals: Vec<DVec2>,
}

/// A ball's mass and restitution (fixed when it is added).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Material {
    pub mass: f64,
    pub restitution: f64,
}

/// The mass and restitution of every ball added so far, if they are all the same (compared
/// bit for bit). A collision then reads neither ball's, and the set keeps no table of them.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
enum Shared {
    /// No ball yet.
    #[default]
    Nothing,
    /// Every ball has this mass and this restitution.
    Same(f64, f64),
    /// Two balls differ (for good: removals do not bring it back).
    Mixed,
}

impl BallSet {
    /// Makes room for `additional` more balls without reallocating.
    pub(crate) fn reserve(&mut self, additional: usize) {
        // Only a hint: room that cannot be had is simply not made.
        let new = additional.saturating_sub(self.free.len());
        let _ = self.kinematics.try_reserve_exact(new);
        let _ = self.properties.try_reserve_exact(new);
        if self.shared == Shared::Mixed {
            let _ = self.materials.try_reserve_exact(new);
        }
    }

    /// Adds a ball on `trajectory`, returning its handle.
    pub(crate) fn insert(
        &mut self,
        trajectory: Trajectory,
        radius: f64,
        material: Material,
        properties: Properties,
        spin: Spin,
    ) -> BallHandle {
        let handle = self.insert_slot(trajectory, radius, material, properties);
        if !spin.is_still() || !self.spins.is_empty() {
            *self.spin_mut(handle.index) = spin;
        }
        handle
    }

    fn insert_slot(
        &mut self,
        trajectory: Trajectory,
        radius: f64,
        material: Material,
        properties: Properties,
    ) -> BallHandle {
        self.len += 1;
        self.shared = match self.shared {
            Shared::Nothing => Shared::Same(material.mass, material.restitution),
            Shared::Same(mass, restitution)
                if mass.to_bits() == material.mass.to_bits()
                    && restitution.to_bits() == material.restitution.to_bits() =>
            {
                self.shared
            }
            Shared::Same(mass, restitution) => {
                // The first ball that differs: every slot so far gets the shared pair (a free
                // slot's is never read), with room for as many slots as were reserved.
                let mut materials = Vec::new();
                let _ = materials.try_reserve_exact(self.kinematics.capacity());
                materials.resize(self.kinematics.len(), Material { mass, restitution });
                self.materials = materials;
                Shared::Mixed
            }
            Shared::Mixed => Shared::Mixed,
        };
        if let Some(index) = self.free.pop() {
            let i = index as usize;
            let k = &mut self.kinematics[i];
            k.generation = k.generation.wrapping_add(1);
            (k.trajectory, k.radius) = (trajectory, radius);
            self.properties[i] = properties;
            if let Some(r) = self.residuals.get_mut(i) {
                *r = DVec2::ZERO;
            }
            if let Some(m) = self.materials.get_mut(i) {
                *m = material;
            }
            return BallHandle {
                index,
                generation: k.generation / 2,
            };
        }
        let index = u32::try_from(self.kinematics.len()).expect("fewer than 2^32 balls");
        self.kinematics.push(Kinematics {
            trajectory,
            radius,
            generation: 0,
            version: 0,
        });
        self.properties.push(properties);
        if self.shared == Shared::Mixed {
            self.materials.push(material);
        }
        BallHandle {
            index,
            generation: 0,
        }
    }

    /// Removes a ball; `false` if the handle is not live.
    pub(crate) fn remove(&mut self, handle: BallHandle) -> bool {
        if self.get(handle).is_none() {
            return false;
        }
        let i = handle.index as usize;
        let k = &mut self.kinematics[i];
        k.generation = k.generation.wrapping_add(1);
        k.version = k.version.wrapping_add(2) & !1;
        self.properties[i].extra = Extra::default();
        self.free.push(handle.index);
        self.len -= 1;
        true
    }

    /// From now on, restatements carry each position's residual (see [`Self::rebase`]).
    pub(crate) fn carry_residuals(&mut self) {
        self.carrying = true;
    }

    /// Restates ball `index`'s path from `t` under `acceleration`, and gives the origin of the
    /// path it had and its record. While carrying residuals, what the new `p0` leaves out is
    /// kept for the next restatement ([`Trajectory::rebased_carrying`]); otherwise it is rounded
    /// away, as it always was (inline: a gas restates two balls at every collision).
    #[inline(always)]
    pub(crate) fn rebase(
        &mut self,
        index: u32,
        t: Time,
        acceleration: DVec2,
    ) -> (Time, &mut Kinematics) {
        if self.carrying {
            return self.rebase_carrying(index, t, acceleration);
        }
        let k = &mut self.kinematics[index as usize];
        debug_assert!(k.is_live(), "a live ball is restated");
        let origin = k.trajectory.t0;
        k.trajectory = k.trajectory.rebased(t, acceleration);
        (origin, k)
    }

    /// [`Self::rebase`] while carrying residuals.
    #[inline(never)]
    fn rebase_carrying(
        &mut self,
        index: u32,
        t: Time,
        acceleration: DVec2,
    ) -> (Time, &mut Kinematics) {
        let i = index as usize;
        if self.residuals.len() < self.kinematics.len() {
            self.residuals.resize(self.kinematics.len(), DVec2::ZERO);
        }
        let k = &mut self.kinematics[i];
        debug_assert!(k.is_live(), "a live ball is restated");
        let origin = k.trajectory.t0;
        let (path, residual) = k
            .trajectory
            .rebased_carrying(t, acceleration, self.residuals[i]);
        k.trajectory = path;
        self.residuals[i] = residual;
        (origin, k)
    }

    /// Ball `index`'s residual (zero while none is kept).
    pub(crate) fn residual(&self, index: u32) -> DVec2 {
        self.residuals
            .get(index as usize)
            .copied()
            .unwrap_or(DVec2::ZERO)
    }

    /// Forgets ball `index`'s residual: its path was set afresh (placed, asleep, wrapped).
    pub(crate) fn clear_residual(&mut self, index: u32) {
        if let Some(r) = self.residuals.get_mut(index as usize) {
            *r = DVec2::ZERO;
        }
    }

    /// Ball `index`'s spin; `None` while no ball has any (the table is empty).
    #[inline]
    pub(crate) fn spin(&self, index: u32) -> Option<&Spin> {
        self.spins.get(index as usize)
    }

    /// Ball `index`'s spin, to change it (the table is made, every ball still, if need be).
    pub(crate) fn spin_mut(&mut self, index: u32) -> &mut Spin {
        if self.spins.len() < self.kinematics.len() {
            self.spins.resize(self.kinematics.len(), Spin::STILL);
        }
        &mut self.spins[index as usize]
    }

    /// Marks ball `index`'s trajectory as changed: predictions against it are outdated.
    pub(crate) fn bump_version(&mut self, index: u32) {
        let k = &mut self.kinematics[index as usize];
        k.version = k.version.wrapping_add(2);
    }

    /// Sets or clears ball `index`'s support, which changes its trajectory: predictions
    /// against it are outdated.
    ///
    /// A rough ball's spin follows (see `dynamics/rolling.rs`): from `now` it turns as the
    /// support's friction says, or at the spin it has if the support has none.
    pub(crate) fn set_support(&mut self, index: u32, support: Option<Support>, now: Time) {
        let k = &mut self.kinematics[index as usize];
        k.version = (k.version.wrapping_add(2) & !1) | u32::from(support.is_some());
        if let Some(spin) = self.spins.get_mut(index as usize) {
            let rub = support.and_then(|s| s.rub);
            let alpha = rub.map_or(0.0, |r| r.alpha);
            let omega = rub.and_then(|r| r.omega);
            if spin.alpha != alpha || omega.is_some() {
                let omega = omega.unwrap_or_else(|| spin.omega_at(now));
                spin.set_motion(now, omega, alpha);
            }
            // On a table the roll turns with the phase too (`dynamics/table.rs`).
            let roll_rate = rub.map_or(DVec2::ZERO, |r| r.roll_rate);
            if spin.roll_rate != roll_rate {
                spin.set_roll(now, spin.roll_at(now), roll_rate);
            }
        }
        self.properties[index as usize].extra.set_support(support);
    }

    /// The mass and restitution of the ball in slot `index`, if live: the shared pair while
    /// every ball has it, else its own.
    #[inline]
    pub(crate) fn mass_and_restitution(&self, index: u32) -> Option<(f64, f64)> {
        self.kinematics(index)?;
        match self.shared {
            Shared::Same(mass, restitution) => Some((mass, restitution)),
            Shared::Mixed => {
                let m = self.materials[index as usize];
                Some((m.mass, m.restitution))
            }
            Shared::Nothing => None,
        }
    }

    /// Whether ball `index` is supported (read from its hot line).
    pub(crate) fn is_supported(&self, index: u32) -> bool {
        self.kinematics[index as usize].version & 1 == 1
    }

    /// Ball `index`'s acceleration: `gravity`, or its support's if it has one.
    #[inline]
    pub(crate) fn acceleration(&self, index: u32, gravity: DVec2) -> DVec2 {
        if self.is_supported(index) {
            self.properties[index as usize]
                .extra
                .support()
                .map_or(gravity, |s| s.acceleration)
        } else {
            gravity
        }
    }

    /// The group holding ball `index`, if any (see `pipeline/group.rs`).
    pub(crate) fn held_group(&self, index: u32) -> Option<u32> {
        self.is_supported(index)
            .then(|| self.properties[index as usize].extra.support())
            .flatten()
            .and_then(|s| s.held)
            .map(|h| h.group)
    }

    /// Whether slot `index` holds a ball whose trajectory is still the one of `version`.
    pub(crate) fn is_current(&self, index: u32, version: u32) -> bool {
        let k = &self.kinematics[index as usize];
        k.is_live() && k.version == version
    }

    /// The `version` of slot `index`.
    pub(crate) fn version(&self, index: u32) -> u32 {
        self.kinematics[index as usize].version
    }

    /// A live ball's two halves, by handle.
    pub(crate) fn get(&self, handle: BallHandle) -> Option<(&Kinematics, &Properties)> {
        let i = handle.index as usize;
        let k = self.kinematics.get(i)?;
        (k.is_live() && k.generation / 2 == handle.generation).then(|| (k, &self.properties[i]))
    }

    /// The path and radius of the ball in slot `index`, if live.
    pub(crate) fn kinematics(&self, index: u32) -> Option<&Kinematics> {
        let k = self.kinematics.get(index as usize)?;
        k.is_live().then_some(k)
    }

    pub(crate) fn kinematics_mut(&mut self, index: u32) -> Option<&mut Kinematics> {
        let k = self.kinematics.get_mut(index as usize)?;
        k.is_live().then_some(k)
    }

    /// The other properties of the ball in slot `index`, if live.
    pub(crate) fn properties(&self, index: u32) -> Option<&Properties> {
        self.kinematics(index)?;
        Some(&self.properties[index as usize])
    }

    pub(crate) fn properties_mut(&mut self, index: u32) -> Option<&mut Properties> {
        self.kinematics(index)?;
        Some(&mut self.properties[index as usize])
    }

    pub(crate) fn handle(&self, index: u32) -> BallHandle {
        BallHandle {
            index,
            generation: self.kinematics[index as usize].generation / 2,
        }
    }

    /// The number of slots, live or free.
    pub(crate) fn slot_count(&self) -> usize {
        self.kinematics.len()
    }

    pub(crate) fn len(&self) -> usize {
        self.len
    }

    /// Live balls in slot order, with their slot index.
    pub(crate) fn iter(&self) -> impl Iterator<Item = (u32, &Kinematics, &Properties)> {
        self.kinematics
            .iter()
            .zip(&self.properties)
            .enumerate()
            .filter(|(_, (k, _))| k.is_live())
            .map(|(i, (k, p))| (i as u32, k, p))
    }

    /// Live balls' properties in slot order, mutably.
    pub(crate) fn properties_iter_mut(&mut self) -> impl Iterator<Item = &mut Properties> {
        self.kinematics
            .iter()
            .zip(&mut self.properties)
            .filter(|(k, _)| k.is_live())
            .map(|(_, p)| p)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dynamics::Time;
    use glam::DVec2;

    fn insert(set: &mut BallSet, x: f64) -> BallHandle {
        let trajectory = Trajectory {
            p0: DVec2::new(x, 0.0),
            v0: DVec2::ZERO,
            t0: Time::ZERO,
        };
        set.insert(trajectory, 1.0, UNIT, insert_properties(), Spin::STILL)
    }

    #[test]
    fn a_reused_slot_refuses_the_old_handle_and_outdates_old_versions() {
        let mut set = BallSet::default();
        let a = insert(&mut set, 1.0);
        let version = set.version(a.index);
        assert!(set.remove(a));
        assert!(set.get(a).is_none() && set.kinematics(a.index).is_none());
        assert!(!set.is_current(a.index, version));
        let b = insert(&mut set, 2.0);
        assert_eq!(b.index, a.index);
        assert_ne!(b.generation, a.generation);
        assert!(set.get(a).is_none() && !set.remove(a));
        assert_eq!(set.get(b).unwrap().0.trajectory.p0.x, 2.0);
        assert!(!set.is_current(b.index, version));
        assert_eq!(set.len(), 1);
        assert_eq!(set.iter().count(), 1);
    }

    #[test]
    fn mass_and_restitution_come_from_the_shared_pair_only_while_every_ball_has_it() {
        let mut set = BallSet::default();
        let a = insert(&mut set, 1.0);
        let b = insert(&mut set, 2.0);
        assert_eq!(set.shared, Shared::Same(1.0, 1.0));
        assert_eq!(set.mass_and_restitution(b.index), Some((1.0, 1.0)));
        assert!(set.materials.is_empty());
        set.reserve(100);
        let trajectory = set.get(a).unwrap().0.trajectory;
        let heavy = Material {
            mass: 3.0,
            restitution: 0.5,
        };
        let c = set.insert(trajectory, 1.0, heavy, insert_properties(), Spin::STILL);
        assert_eq!(set.shared, Shared::Mixed);
        assert_eq!(set.materials.len(), 3);
        // Made with the room reserved for the slots, so it does not grow by doubling.
        assert!(set.materials.capacity() >= set.kinematics.capacity());
        assert_eq!(set.mass_and_restitution(c.index), Some((3.0, 0.5)));
        assert_eq!(set.mass_and_restitution(a.index), Some((1.0, 1.0)));
        // Removing the odd ball out does not bring the shortcut back, and a removed ball has
        // neither.
        assert!(set.remove(c));
        assert_eq!(set.shared, Shared::Mixed);
        assert_eq!(set.mass_and_restitution(c.index), None);
        // A slot reused keeps the new ball's pair.
        let d = set.insert(trajectory, 1.0, UNIT, insert_properties(), Spin::STILL);
        assert_eq!(d.index, c.index);
        assert_eq!(set.mass_and_restitution(d.index), Some((1.0, 1.0)));
        assert_eq!(set.mass_and_restitution(b.index), Some((1.0, 1.0)));
    }

    #[test]
    fn spins_are_kept_only_once_a_ball_turns_or_is_rough() {
        let mut set = BallSet::default();
        let trajectory = Trajectory {
            p0: DVec2::ZERO,
            v0: DVec2::ZERO,
            t0: Time::new(5.0),
        };
        let still = Spin {
            t0: Time::new(5.0),
            ..Spin::STILL
        };
        let a = set.insert(trajectory, 1.0, UNIT, insert_properties(), still);
        assert!(set.spins.is_empty() && set.spin(a.index).is_none());
        let turning = Spin {
            omega: 2.0,
            ..still
        };
        let b = set.insert(trajectory, 1.0, UNIT, insert_properties(), turning);
        assert_eq!(set.spins.len(), 2);
        assert_eq!(set.spin(b.index).unwrap().omega, 2.0);
        assert_eq!(*set.spin(a.index).unwrap(), Spin::STILL);
    }

    const UNIT: Material = Material {
        mass: 1.0,
        restitution: 1.0,
    };

    fn insert_properties() -> Properties {
        Properties {
            groups: CollisionGroups::ALL,
            user_data: 0,
            extra: Extra::default(),
        }
    }

    #[test]
    fn a_slot_is_one_cache_line_and_24_bytes() {
        // The memory budget (200 bytes per ball, everything included) counts on this.
        assert_eq!(std::mem::size_of::<Kinematics>(), 64);
        assert_eq!(std::mem::align_of::<Kinematics>(), 64);
        assert_eq!(std::mem::size_of::<Properties>(), 24);
        assert_eq!(std::mem::size_of::<Material>(), 16);
    }
}
