//! Storage for balls: slots with generations and the counters that invalidate predictions.
//!
//! A million balls should fit in 200 MB with everything the engine keeps about them, so a slot
//! is kept small: 104 bytes. A slot is live when its generation is even (a removal makes it
//! odd, reuse makes it even again), which spares an `Option` tag, and the rarely used list of
//! sensors a ball is inside lives out of line.

use super::{BallHandle, Trajectory};
use crate::geometry::{ColliderHandle, CollisionGroups};

/// The sensors a ball overlaps now, in the order it entered them: usually none, so one thin
/// pointer until the first.
#[derive(Clone, Debug, Default)]
// A boxed `Vec` on purpose: one thin pointer (8 bytes) in every ball's slot, where a `Vec` or
// a boxed slice would take 24 or 16 bytes for a list that is almost always empty.
#[allow(clippy::box_collection)]
pub(crate) struct SensorList(Option<Box<Vec<ColliderHandle>>>);

impl SensorList {
    pub(crate) fn from_vec(handles: Vec<ColliderHandle>) -> Self {
        Self((!handles.is_empty()).then(|| Box::new(handles)))
    }

    pub(crate) fn as_slice(&self) -> &[ColliderHandle] {
        self.0.as_deref().map_or(&[], Vec::as_slice)
    }

    pub(crate) fn contains(&self, handle: ColliderHandle) -> bool {
        self.as_slice().contains(&handle)
    }

    pub(crate) fn push(&mut self, handle: ColliderHandle) {
        self.0.get_or_insert_default().push(handle);
    }

    /// Removes `handle`; returns whether it was there.
    pub(crate) fn remove(&mut self, handle: ColliderHandle) -> bool {
        let Some(list) = self.0.as_mut() else {
            return false;
        };
        let Some(at) = list.iter().position(|&h| h == handle) else {
            return false;
        };
        list.remove(at);
        if list.is_empty() {
            self.0 = None;
        }
        true
    }
}

/// Everything the engine keeps about a live ball. The fields a prediction reads come first
/// (see [`Slot`]).
#[derive(Clone, Debug)]
#[repr(C)]
pub(crate) struct BallRecord {
    pub trajectory: Trajectory,
    pub radius: f64,
    pub groups: CollisionGroups,
    pub mass: f64,
    pub restitution: f64,
    pub user_data: u64,
    pub sensors: SensorList,
}

/// A slot. `version` only ever grows, across reuse of the slot, so an event predicted
/// against an earlier occupant can never be mistaken for a current one.
///
/// Laid out in declaration order so that what predicting against this ball reads (liveness,
/// version, trajectory, radius, groups: 72 bytes) is contiguous, touching as few cache lines as
/// a 104-byte slot can.
#[repr(C)]
pub(crate) struct Slot {
    /// Even while the slot holds a ball; odd while it is free.
    generation: u32,
    /// Bumped whenever the ball's trajectory changes (or the ball is removed): events other
    /// balls predicted against the old trajectory are then out of date.
    pub version: u32,
    /// Meaningful only while the slot is live.
    ball: BallRecord,
}

impl Slot {
    fn is_live(&self) -> bool {
        self.generation % 2 == 0
    }
}

/// Balls in slots; iteration is in slot order.
#[derive(Default)]
pub(crate) struct BallSet {
    slots: Vec<Slot>,
    free: Vec<u32>,
    len: usize,
}

impl BallSet {
    /// Makes room for `additional` more balls without reallocating.
    pub(crate) fn reserve(&mut self, additional: usize) {
        let new = additional.saturating_sub(self.free.len());
        self.slots.reserve_exact(new);
    }

    pub(crate) fn insert(&mut self, ball: BallRecord) -> BallHandle {
        self.len += 1;
        if let Some(index) = self.free.pop() {
            let slot = &mut self.slots[index as usize];
            slot.generation = slot.generation.wrapping_add(1);
            slot.ball = ball;
            return BallHandle {
                index,
                generation: slot.generation / 2,
            };
        }
        let index = u32::try_from(self.slots.len()).expect("fewer than 2^32 balls");
        self.slots.push(Slot {
            generation: 0,
            version: 0,
            ball,
        });
        BallHandle {
            index,
            generation: 0,
        }
    }

    pub(crate) fn remove(&mut self, handle: BallHandle) -> Option<BallRecord> {
        self.get(handle)?;
        let slot = &mut self.slots[handle.index as usize];
        slot.generation = slot.generation.wrapping_add(1);
        slot.version = slot.version.wrapping_add(1);
        let sensors = std::mem::take(&mut slot.ball.sensors);
        let ball = BallRecord {
            sensors,
            ..slot.ball.clone()
        };
        self.free.push(handle.index);
        self.len -= 1;
        Some(ball)
    }

    /// Marks ball `index`'s trajectory as changed: predictions against it are outdated.
    pub(crate) fn bump_version(&mut self, index: u32) {
        let slot = &mut self.slots[index as usize];
        slot.version = slot.version.wrapping_add(1);
    }

    /// Whether slot `index` holds a ball whose trajectory is still the one of `version`.
    pub(crate) fn is_current(&self, index: u32, version: u32) -> bool {
        let slot = &self.slots[index as usize];
        slot.is_live() && slot.version == version
    }

    /// The `version` of slot `index`.
    pub(crate) fn version(&self, index: u32) -> u32 {
        self.slots[index as usize].version
    }

    pub(crate) fn get(&self, handle: BallHandle) -> Option<&BallRecord> {
        let slot = self.slots.get(handle.index as usize)?;
        (slot.is_live() && slot.generation / 2 == handle.generation).then_some(&slot.ball)
    }

    pub(crate) fn record(&self, index: u32) -> Option<&BallRecord> {
        let slot = self.slots.get(index as usize)?;
        slot.is_live().then_some(&slot.ball)
    }

    pub(crate) fn record_mut(&mut self, index: u32) -> Option<&mut BallRecord> {
        let slot = self.slots.get_mut(index as usize)?;
        slot.is_live().then_some(&mut slot.ball)
    }

    pub(crate) fn handle(&self, index: u32) -> BallHandle {
        BallHandle {
            index,
            generation: self.slots[index as usize].generation / 2,
        }
    }

    /// The number of slots, live or free.
    pub(crate) fn slot_count(&self) -> usize {
        self.slots.len()
    }

    pub(crate) fn len(&self) -> usize {
        self.len
    }

    /// Live balls in slot order, with their slot index.
    pub(crate) fn iter(&self) -> impl Iterator<Item = (u32, &BallRecord)> {
        self.slots
            .iter()
            .enumerate()
            .filter(|(_, s)| s.is_live())
            .map(|(i, s)| (i as u32, &s.ball))
    }

    /// Live balls in slot order, mutably.
    pub(crate) fn iter_mut(&mut self) -> impl Iterator<Item = &mut BallRecord> {
        self.slots
            .iter_mut()
            .filter(|s| s.is_live())
            .map(|s| &mut s.ball)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dynamics::Time;
    use glam::DVec2;

    fn record(x: f64) -> BallRecord {
        BallRecord {
            trajectory: Trajectory {
                p0: DVec2::new(x, 0.0),
                v0: DVec2::ZERO,
                t0: Time::ZERO,
            },
            radius: 1.0,
            mass: 1.0,
            restitution: 1.0,
            groups: CollisionGroups::ALL,
            user_data: 0,
            sensors: SensorList::default(),
        }
    }

    #[test]
    fn a_reused_slot_refuses_the_old_handle_and_outdates_old_versions() {
        let mut set = BallSet::default();
        let a = set.insert(record(1.0));
        let version = set.version(a.index);
        assert!(set.remove(a).is_some());
        assert!(set.get(a).is_none() && set.record(a.index).is_none());
        assert!(!set.is_current(a.index, version));
        let b = set.insert(record(2.0));
        assert_eq!(b.index, a.index);
        assert_ne!(b.generation, a.generation);
        assert!(set.get(a).is_none() && set.remove(a).is_none());
        assert_eq!(set.get(b).unwrap().trajectory.p0.x, 2.0);
        assert!(!set.is_current(b.index, version));
        assert_eq!(set.len(), 1);
    }

    #[test]
    fn a_slot_stays_small() {
        // The memory budget (200 bytes per ball, everything included) counts on this.
        assert_eq!(std::mem::size_of::<Slot>(), 104);
    }
}
