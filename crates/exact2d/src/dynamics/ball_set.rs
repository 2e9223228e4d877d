//! Storage for balls: slots with generations and the counters that invalidate predictions.

use super::{BallHandle, Trajectory};
use crate::geometry::{ColliderHandle, CollisionGroups};

/// Everything the engine keeps about a live ball.
#[derive(Clone, Debug)]
pub(crate) struct BallRecord {
    pub trajectory: Trajectory,
    pub radius: f64,
    pub mass: f64,
    pub restitution: f64,
    pub groups: CollisionGroups,
    pub user_data: u64,
    /// The sensors this ball overlaps now, in the order it entered them.
    pub sensors: Vec<ColliderHandle>,
}

/// A slot. `version` only ever grows, across reuse of the slot, so an event predicted
/// against an earlier occupant can never be mistaken for a current one.
pub(crate) struct Slot {
    pub generation: u32,
    /// Bumped whenever the ball's trajectory changes (or the ball is removed): events other
    /// balls predicted against the old trajectory are then out of date.
    pub version: u32,
    pub ball: Option<BallRecord>,
}

/// Balls in slots; iteration is in slot order.
#[derive(Default)]
pub(crate) struct BallSet {
    pub(crate) slots: Vec<Slot>,
    free: Vec<u32>,
    len: usize,
}

impl BallSet {
    pub(crate) fn insert(&mut self, ball: BallRecord) -> BallHandle {
        self.len += 1;
        if let Some(index) = self.free.pop() {
            let slot = &mut self.slots[index as usize];
            slot.ball = Some(ball);
            return BallHandle {
                index,
                generation: slot.generation,
            };
        }
        let index = u32::try_from(self.slots.len()).expect("fewer than 2^32 balls");
        self.slots.push(Slot {
            generation: 0,
            version: 0,
            ball: Some(ball),
        });
        BallHandle {
            index,
            generation: 0,
        }
    }

    pub(crate) fn remove(&mut self, handle: BallHandle) -> Option<BallRecord> {
        let slot = self.slots.get_mut(handle.index as usize)?;
        if slot.generation != handle.generation {
            return None;
        }
        let ball = slot.ball.take()?;
        slot.generation = slot.generation.wrapping_add(1);
        slot.version = slot.version.wrapping_add(1);
        self.free.push(handle.index);
        self.len -= 1;
        Some(ball)
    }

    /// Marks ball `index`'s trajectory as changed: predictions against it are outdated.
    pub(crate) fn bump_version(&mut self, index: u32) {
        let slot = &mut self.slots[index as usize];
        slot.version = slot.version.wrapping_add(1);
    }

    pub(crate) fn get(&self, handle: BallHandle) -> Option<&BallRecord> {
        let slot = self.slots.get(handle.index as usize)?;
        (slot.generation == handle.generation).then_some(slot.ball.as_ref()?)
    }

    pub(crate) fn record(&self, index: u32) -> Option<&BallRecord> {
        self.slots.get(index as usize)?.ball.as_ref()
    }

    pub(crate) fn record_mut(&mut self, index: u32) -> Option<&mut BallRecord> {
        self.slots.get_mut(index as usize)?.ball.as_mut()
    }

    pub(crate) fn handle(&self, index: u32) -> BallHandle {
        BallHandle {
            index,
            generation: self.slots[index as usize].generation,
        }
    }

    pub(crate) fn len(&self) -> usize {
        self.len
    }

    /// Live balls in slot order, with their slot index.
    pub(crate) fn iter(&self) -> impl Iterator<Item = (u32, &BallRecord)> {
        self.slots
            .iter()
            .enumerate()
            .filter_map(|(i, s)| s.ball.as_ref().map(|b| (i as u32, b)))
    }
}
