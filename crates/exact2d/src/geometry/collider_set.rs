//! Storage for colliders: slots with generations.

use super::{Collider, ColliderHandle};

#[derive(Clone)]
struct Slot {
    generation: u32,
    collider: Option<Collider>,
}

/// Colliders in slots; a removed collider's slot is reused, with a new generation.
///
/// Iteration is in slot order, so it is the same in every run with the same calls.
#[derive(Clone, Default)]
pub(crate) struct ColliderSet {
    slots: Vec<Slot>,
    free: Vec<u32>,
    len: usize,
}

impl ColliderSet {
    pub(crate) fn insert(&mut self, collider: Collider) -> ColliderHandle {
        self.len += 1;
        if let Some(index) = self.free.pop() {
            let slot = &mut self.slots[index as usize];
            slot.collider = Some(collider);
            return ColliderHandle {
                index,
                generation: slot.generation,
            };
        }
        let index = u32::try_from(self.slots.len()).expect("fewer than 2^32 colliders");
        self.slots.push(Slot {
            generation: 0,
            collider: Some(collider),
        });
        ColliderHandle {
            index,
            generation: 0,
        }
    }

    pub(crate) fn remove(&mut self, handle: ColliderHandle) -> Option<Collider> {
        let slot = self.slots.get_mut(handle.index as usize)?;
        if slot.generation != handle.generation {
            return None;
        }
        let collider = slot.collider.take()?;
        slot.generation = slot.generation.wrapping_add(1);
        self.free.push(handle.index);
        self.len -= 1;
        Some(collider)
    }

    pub(crate) fn get(&self, handle: ColliderHandle) -> Option<&Collider> {
        let slot = self.slots.get(handle.index as usize)?;
        (slot.generation == handle.generation).then_some(slot.collider.as_ref()?)
    }

    /// The live collider in slot `index`, with its handle.
    pub(crate) fn at(&self, index: u32) -> Option<(ColliderHandle, &Collider)> {
        let slot = self.slots.get(index as usize)?;
        let handle = ColliderHandle {
            index,
            generation: slot.generation,
        };
        slot.collider.as_ref().map(|c| (handle, c))
    }

    /// Whether `index` holds a live collider of `generation`.
    pub(crate) fn is_live(&self, index: u32, generation: u32) -> bool {
        self.slots
            .get(index as usize)
            .is_some_and(|s| s.generation == generation && s.collider.is_some())
    }

    pub(crate) fn len(&self) -> usize {
        self.len
    }

    /// Live colliders in slot order.
    pub(crate) fn iter(&self) -> impl Iterator<Item = (ColliderHandle, &Collider)> {
        self.slots.iter().enumerate().filter_map(|(i, s)| {
            let handle = ColliderHandle {
                index: i as u32,
                generation: s.generation,
            };
            s.collider.as_ref().map(|c| (handle, c))
        })
    }
}
