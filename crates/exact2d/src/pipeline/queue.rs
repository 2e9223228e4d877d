//! The queue of pending events: an indexed 4-ary heap with one node per ball.
//!
//! A ball's node stands for the earlier of its two pending events (see [`super::pending`]) and
//! is replaced in place whenever the ball is predicted again (O(log n)), so the heap never holds
//! more nodes than there are balls. This replaced a lazily-invalidated `BinaryHeap`, where
//! every re-prediction pushed a new entry and old ones lingered until popped.

use super::pending::{Entry, IDLE, Pending, PendingQueue};

const NOWHERE: u32 = u32::MAX;

/// Children per node. A 4-ary heap is half as deep as a binary one, and a node's four children
/// (16 bytes each) share one or two cache lines, so sifting through a large heap misses the
/// cache about half as often (measured: see `BENCHMARKS.md`).
const ARITY: usize = 4;

/// A heap node: the leading part of its ball's due time, and the ball. Nodes compare by
/// `time`, and only on a tie by the whole entry, so sifting touches 16 bytes per node.
#[derive(Clone, Copy)]
struct Node {
    time: f64,
    owner: u32,
}

/// The queue of pending events: a 4-ary min-heap holding at most one node per ball (for the
/// earlier of its two pending events), indexed by ball so that a ball's node is replaced or
/// removed in place (O(log n)). Nothing stale accumulates: the heap never holds more nodes than
/// there are balls.
#[derive(Clone, Default)]
pub(crate) struct EventQueue {
    heap: Vec<Node>,
    /// Per ball slot, what it has pending.
    pending: Vec<Pending>,
    /// Per ball slot, the position of its node in `heap`, or `NOWHERE`.
    position: Vec<u32>,
}

impl EventQueue {
    /// Makes room for balls in slots below `slots` without reallocating.
    pub(crate) fn reserve_slots(&mut self, slots: usize) {
        let more = slots.saturating_sub(self.pending.len());
        let _ = self.pending.try_reserve_exact(more);
        let _ = self.position.try_reserve_exact(more);
        let _ = self
            .heap
            .try_reserve_exact(slots.saturating_sub(self.heap.len()));
    }

    /// The earliest entry.
    pub(crate) fn peek(&self) -> Option<Entry> {
        let node = self.heap.first()?;
        self.pending[node.owner as usize].due(node.owner)
    }

    /// Takes the node at `at` out of the heap.
    fn unlink(&mut self, at: usize) {
        let owner = self.heap[at].owner;
        self.position[owner as usize] = NOWHERE;
        let last = self.heap.pop().expect("a node is in the heap");
        if at < self.heap.len() {
            self.heap[at] = last;
            self.position[last.owner as usize] = at as u32;
            self.sift_up(at);
            let at = self.position[last.owner as usize] as usize;
            self.sift_down(at);
        }
    }

    fn due(&self, node: Node) -> Entry {
        self.pending[node.owner as usize]
            .due(node.owner)
            .expect("a ball in the heap has an event due")
    }

    fn precedes(&self, a: Node, b: Node) -> bool {
        if a.time != b.time {
            return a.time < b.time;
        }
        self.due(a).precedes(&self.due(b))
    }

    fn sift_up(&mut self, mut at: usize) {
        let node = self.heap[at];
        while at > 0 {
            let parent = (at - 1) / ARITY;
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
            let first = ARITY * at + 1;
            if first >= n {
                break;
            }
            let mut child = first;
            for other in first + 1..(first + ARITY).min(n) {
                if self.precedes(self.heap[other], self.heap[child]) {
                    child = other;
                }
            }
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

impl PendingQueue for EventQueue {
    fn pending(&self, owner: u32) -> Option<&Pending> {
        self.pending.get(owner as usize)
    }

    fn put(&mut self, owner: u32, pending: Pending) {
        let i = owner as usize;
        if self.pending.len() <= i {
            self.pending.resize(i + 1, IDLE);
            self.position.resize(i + 1, NOWHERE);
        }
        self.pending[i] = pending;
        let at = self.position[i];
        let Some(due) = pending.due(owner) else {
            if at != NOWHERE {
                self.unlink(at as usize);
            }
            return;
        };
        let node = Node {
            time: due.key.time.seconds(),
            owner,
        };
        let at = if at == NOWHERE {
            self.heap.push(node);
            self.heap.len() - 1
        } else {
            self.heap[at as usize] = node;
            at as usize
        };
        // The node may belong above or below its place.
        self.sift_up(at);
        self.sift_down(self.position[i] as usize);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dynamics::Time;
    use crate::pipeline::pending::{EventKey, Kind, NO_CROSSING, Prediction, Stored};

    fn prediction(time: f64, kind: Kind, first: u32, second: u32) -> Prediction {
        Prediction {
            key: EventKey {
                time: Time::new(time),
                kind,
                first,
                second,
                feature: 0,
            },
            tag: 7,
        }
    }

    fn drain(q: &mut EventQueue) -> Vec<(f64, Kind, u32, u32)> {
        std::iter::from_fn(|| {
            let top = q.peek()?;
            q.remove(top.owner);
            Some((
                top.key.time.seconds(),
                top.key.kind,
                top.owner,
                top.partner(),
            ))
        })
        .collect()
    }

    #[test]
    fn pops_by_time_then_kind_then_indices_then_owner() {
        let mut q = EventQueue::default();
        q.set(0, Some(prediction(2.0, Kind::Contact, 0, 0)), None);
        q.set(1, Some(prediction(1.0, Kind::Sensor, 1, 2)), None);
        q.set(5, Some(prediction(1.0, Kind::Contact, 5, 1)), None);
        q.set(3, Some(prediction(1.0, Kind::Contact, 3, 9)), None);
        // The same pair event held by both of its balls: the smaller owner first.
        q.set(8, Some(prediction(1.0, Kind::BallContact, 4, 8)), None);
        q.set(4, Some(prediction(1.0, Kind::BallContact, 4, 8)), None);
        assert_eq!(
            drain(&mut q),
            vec![
                (1.0, Kind::Contact, 3, 9),
                (1.0, Kind::Contact, 5, 1),
                (1.0, Kind::BallContact, 4, 8),
                (1.0, Kind::BallContact, 8, 4),
                (1.0, Kind::Sensor, 1, 2),
                (2.0, Kind::Contact, 0, 0),
            ]
        );
    }

    #[test]
    fn a_ball_is_due_at_the_earlier_of_its_event_and_its_crossing() {
        let mut q = EventQueue::default();
        let hit = prediction(2.0, Kind::BallContact, 1, 3);
        q.set(3, Some(hit), Some(Time::new(1.5)));
        q.set(1, None, Some(Time::new(1.75)));
        let top = q.peek().unwrap();
        assert_eq!((top.key.kind, top.owner), (Kind::Crossing, 3));
        // The stored prediction is kept whole behind the crossing.
        assert_eq!(q.physical(3), Some(hit));
        q.set(3, Some(hit), None);
        assert_eq!(
            drain(&mut q),
            vec![(1.75, Kind::Crossing, 1, 0), (2.0, Kind::BallContact, 3, 1)]
        );
        // A crossing at the same time as a collision comes after it.
        q.set(
            2,
            Some(prediction(1.0, Kind::Contact, 2, 0)),
            Some(Time::new(1.0)),
        );
        let top = q.peek().unwrap();
        assert_eq!(top.key.kind, Kind::Contact);
        q.set_physical(2, None);
        assert_eq!(q.peek().unwrap().key.kind, Kind::Crossing);
        q.remove(2);
        assert!(q.peek().is_none() && q.physical(2).is_none());
    }

    #[test]
    fn random_operations_agree_with_a_sorted_list() {
        // An independent reference: every due entry, sorted with the same order.
        let mut q = EventQueue::default();
        let mut state = 0x1234_5678_u64;
        let mut next = move |n: u64| {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1);
            (state >> 33) % n
        };
        let mut reference: Vec<Option<Entry>> = vec![None; 64];
        for _ in 0..20_000 {
            let owner = next(64) as u32;
            match next(4) {
                0 => {
                    q.remove(owner);
                    reference[owner as usize] = None;
                }
                _ => {
                    let other = next(64) as u32;
                    let time = next(50) as f64 * 0.5;
                    let kind = if other == owner {
                        Kind::Contact
                    } else {
                        Kind::BallContact
                    };
                    let (first, second) = if kind == Kind::Contact {
                        (owner, other)
                    } else {
                        (owner.min(other), owner.max(other))
                    };
                    let physical = Some(prediction(time, kind, first, second));
                    let crossing = (next(2) == 0).then(|| Time::new(next(50) as f64 * 0.5));
                    q.set(owner, physical, crossing);
                    reference[owner as usize] = Pending {
                        physical: physical.map(|p| Stored::new(owner, p)),
                        crossing: crossing.unwrap_or(NO_CROSSING),
                    }
                    .due(owner);
                }
            }
            let expected = reference
                .iter()
                .flatten()
                .copied()
                .reduce(|a, b| if b.precedes(&a) { b } else { a });
            assert_eq!(q.peek(), expected);
        }
    }

    #[test]
    fn a_ball_costs_the_queue_68_bytes() {
        assert_eq!(std::mem::size_of::<Pending>(), 48);
        assert_eq!(std::mem::size_of::<Node>() + std::mem::size_of::<u32>(), 20);
    }
}
