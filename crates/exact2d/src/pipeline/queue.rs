//! The queue of predicted events: a binary heap, lazy invalidation, and a total order.
//!
//! Each live ball has at most one *live* entry: its earliest predicted event. Entries are never
//! searched for or deleted. When a ball's prediction is replaced its `stamp` grows and the old
//! entry, popped later, is recognised as stale and dropped. When a ball's partner changes
//! trajectory (its `version` grows) or a collider is removed (its generation grows), the entry
//! is *outdated*: the ball's other candidates were all later than it, so the ball is simply
//! predicted again when the entry comes up (algs4's `CollisionSystem` compares counters the same
//! way; we keep one entry per ball instead of one per pair).

use std::cmp::Ordering;
use std::collections::BinaryHeap;

use crate::dynamics::Time;

/// Event kinds in their tie-breaking order at equal times.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub(crate) enum Kind {
    /// Ball against a solid collider.
    Contact = 0,
    /// Ball against ball.
    BallContact = 1,
    /// Ball entering or leaving a sensor.
    Sensor = 2,
}

/// The total order of events: time, then kind, then the slot indices involved (the ball's, then
/// the collider's; or the two balls', smaller first), then the feature. Two runs with the same
/// inputs therefore handle simultaneous events in the same order, bit for bit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct EventKey {
    pub time: Time,
    pub kind: Kind,
    pub first: u32,
    pub second: u32,
    pub feature: u8,
}

impl EventKey {
    fn tuple(&self) -> (Kind, u32, u32, u8) {
        (self.kind, self.first, self.second, self.feature)
    }
}

impl Eq for EventKey {}

impl Ord for EventKey {
    fn cmp(&self, other: &Self) -> Ordering {
        self.time
            .cmp(&other.time)
            .then_with(|| self.tuple().cmp(&other.tuple()))
    }
}

impl PartialOrd for EventKey {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

/// A queued prediction: the event, the ball that predicted it (its *owner*) with the owner's
/// stamp at the time, and the partner's `version` (a ball) or generation (a collider).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Entry {
    pub key: EventKey,
    pub owner: u32,
    pub owner_stamp: u32,
    pub partner_tag: u32,
}

impl Entry {
    /// The slot index of the partner (the other ball, or the collider).
    pub(crate) fn partner(&self) -> u32 {
        // A ball's own index is always `first` for collider events; for ball pairs the owner
        // may be either.
        if self.key.first == self.owner {
            self.key.second
        } else {
            self.key.first
        }
    }
}

impl Ord for Entry {
    fn cmp(&self, other: &Self) -> Ordering {
        // Reversed: `BinaryHeap` is a max-heap and we want the earliest event on top.
        other
            .key
            .cmp(&self.key)
            .then_with(|| (other.owner, other.owner_stamp).cmp(&(self.owner, self.owner_stamp)))
    }
}

impl PartialOrd for Entry {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

/// A min-queue of entries.
#[derive(Default)]
pub(crate) struct EventQueue {
    heap: BinaryHeap<Entry>,
}

impl EventQueue {
    pub(crate) fn push(&mut self, entry: Entry) {
        self.heap.push(entry);
    }

    pub(crate) fn peek(&self) -> Option<&Entry> {
        self.heap.peek()
    }

    pub(crate) fn pop(&mut self) -> Option<Entry> {
        self.heap.pop()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn entry(time: f64, kind: Kind, first: u32, second: u32) -> Entry {
        let key = EventKey {
            time: Time::new(time),
            kind,
            first,
            second,
            feature: 0,
        };
        Entry {
            key,
            owner: first,
            owner_stamp: 0,
            partner_tag: 0,
        }
    }

    #[test]
    fn pops_by_time_then_kind_then_indices() {
        let mut q = EventQueue::default();
        q.push(entry(2.0, Kind::Contact, 0, 0));
        q.push(entry(1.0, Kind::Sensor, 0, 0));
        q.push(entry(1.0, Kind::Contact, 5, 1));
        q.push(entry(1.0, Kind::Contact, 3, 9));
        q.push(entry(1.0, Kind::BallContact, 0, 1));
        let order: Vec<_> = std::iter::from_fn(|| q.pop())
            .map(|e| (e.key.time.seconds(), e.key.first))
            .collect();
        assert_eq!(
            order,
            vec![(1.0, 3), (1.0, 5), (1.0, 0), (1.0, 0), (2.0, 0)]
        );
    }
}
