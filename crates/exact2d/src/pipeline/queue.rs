//! The queue of pending events: one entry per ball, an indexed binary heap, and a total order.
//!
//! Each live ball has at most one entry: its earliest pending event, a collision, a sensor
//! crossing, or an internal cell crossing of the broad phase. A ball's entry is replaced in place
//! whenever the ball is predicted again, so the heap holds at most one entry per ball and nothing
//! stale ever accumulates. When a ball's partner changes trajectory (its `version` grows) or a
//! collider is removed (its generation grows), the entry becomes *outdated*, detected by
//! comparing those counters when it comes up: the ball's other candidates were all later than
//! it, so the ball is simply predicted again then (algs4's `CollisionSystem` compares counters
//! the same way, with one entry per pair).
//!
//! This replaced a lazily-invalidated `BinaryHeap` (where every re-prediction pushed a new
//! entry and old ones lingered until popped): the heap is now bounded by the number of balls.
//! A calendar queue, O(1) per operation, has not been tried yet (see `BENCHMARKS.md`).

use std::cmp::Ordering;

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
    /// Ball leaving its broad-phase cell (internal; changes no trajectory).
    Crossing = 3,
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

/// A ball's pending event: the event, the ball that predicted it (its *owner*) and the
/// partner's `version` (a ball) or generation (a collider) at the time.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Entry {
    pub key: EventKey,
    pub owner: u32,
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

    /// The queue order: the event order, then the owner (two balls may hold the same pair
    /// event).
    fn precedes(&self, other: &Self) -> bool {
        match self.key.cmp(&other.key) {
            Ordering::Less => true,
            Ordering::Greater => false,
            Ordering::Equal => self.owner < other.owner,
        }
    }
}

const NOWHERE: u32 = u32::MAX;

/// A heap node: the leading part of its entry's time, and the entry's owner. Nodes compare by
/// `time`, and only on a tie by the whole entry, so sifting touches 16 bytes per node.
#[derive(Clone, Copy)]
struct Node {
    time: f64,
    owner: u32,
}

/// The queue of pending events: a binary min-heap holding at most one entry per ball, indexed
/// by ball so that a ball's entry is replaced or removed in place (O(log n)). Nothing stale
/// accumulates: the heap never holds more entries than there are balls.
#[derive(Default)]
pub(crate) struct EventQueue {
    heap: Vec<Node>,
    /// Per ball slot, its entry (meaningful while it is in the heap).
    entries: Vec<Entry>,
    /// Per ball slot, the position of its node in `heap`, or `NOWHERE`.
    position: Vec<u32>,
}

impl EventQueue {
    /// Makes `entry` its owner's only entry.
    pub(crate) fn set(&mut self, entry: Entry) {
        let owner = entry.owner as usize;
        if self.position.len() <= owner {
            self.position.resize(owner + 1, NOWHERE);
            self.entries.resize(owner + 1, entry);
        }
        let node = Node {
            time: entry.key.time.seconds(),
            owner: entry.owner,
        };
        let at = self.position[owner];
        if at == NOWHERE {
            self.entries[owner] = entry;
            self.heap.push(node);
            self.sift_up(self.heap.len() - 1);
        } else {
            let earlier = entry.precedes(&self.entries[owner]);
            self.entries[owner] = entry;
            self.heap[at as usize] = node;
            if earlier {
                self.sift_up(at as usize);
            } else {
                self.sift_down(at as usize);
            }
        }
    }

    /// Removes ball `owner`'s entry, if it has one.
    pub(crate) fn remove(&mut self, owner: u32) {
        let Some(&at) = self.position.get(owner as usize) else {
            return;
        };
        if at == NOWHERE {
            return;
        }
        let at = at as usize;
        self.position[owner as usize] = NOWHERE;
        let last = self.heap.pop().expect("a node is in the heap");
        if at < self.heap.len() {
            self.heap[at] = last;
            self.position[last.owner as usize] = at as u32;
            // The moved node may belong above or below its new place.
            self.sift_up(at);
            let at = self.position[last.owner as usize] as usize;
            self.sift_down(at);
        }
    }

    /// Ball `owner`'s entry.
    pub(crate) fn get(&self, owner: u32) -> Option<&Entry> {
        let at = *self.position.get(owner as usize)?;
        (at != NOWHERE).then(|| &self.entries[owner as usize])
    }

    /// The earliest entry.
    pub(crate) fn peek(&self) -> Option<&Entry> {
        self.heap.first().map(|n| &self.entries[n.owner as usize])
    }

    fn precedes(&self, a: Node, b: Node) -> bool {
        if a.time != b.time {
            return a.time < b.time;
        }
        self.entries[a.owner as usize].precedes(&self.entries[b.owner as usize])
    }

    fn sift_up(&mut self, mut at: usize) {
        let node = self.heap[at];
        while at > 0 {
            let parent = (at - 1) / 2;
            if !self.precedes(node, self.heap[parent]) {
                break;
            }
            self.heap[at] = self.heap[parent];
            self.position[self.heap[at].owner as usize] = at as u32;
            at = parent;
        }
        self.heap[at] = node;
        self.position[node.owner as usize] = at as u32;
    }

    fn sift_down(&mut self, mut at: usize) {
        let node = self.heap[at];
        let n = self.heap.len();
        loop {
            let left = 2 * at + 1;
            if left >= n {
                break;
            }
            let right = left + 1;
            let child = if right < n && self.precedes(self.heap[right], self.heap[left]) {
                right
            } else {
                left
            };
            if !self.precedes(self.heap[child], node) {
                break;
            }
            self.heap[at] = self.heap[child];
            self.position[self.heap[at].owner as usize] = at as u32;
            at = child;
        }
        self.heap[at] = node;
        self.position[node.owner as usize] = at as u32;
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
            owner: first * 10 + second,
            partner_tag: 0,
        }
    }

    #[test]
    fn pops_by_time_then_kind_then_indices() {
        let mut q = EventQueue::default();
        q.set(entry(2.0, Kind::Contact, 0, 0));
        q.set(entry(1.0, Kind::Sensor, 0, 2));
        q.set(entry(1.0, Kind::Contact, 5, 1));
        q.set(entry(1.0, Kind::Contact, 3, 9));
        q.set(entry(1.0, Kind::BallContact, 0, 1));
        let order: Vec<_> = std::iter::from_fn(|| {
            let top = *q.peek()?;
            q.remove(top.owner);
            Some((top.key.time.seconds(), top.key.first))
        })
        .collect();
        assert_eq!(
            order,
            vec![(1.0, 3), (1.0, 5), (1.0, 0), (1.0, 0), (2.0, 0)]
        );
    }
}
