//! The hold model, the classic benchmark of event queues (Vaucher and Duval 1975, Jones
//! 1986): a queue holds one pending event per ball, and each *hold* takes the earliest event
//! and gives its ball a new one a random time later, as the event loop does. Exposed for the
//! benchmark crate only (feature `bench-internals`): it is how the two queues' costs are
//! measured apart from everything else a collision does.

use super::calendar::CalendarQueue;
use super::pending::{Entry, EventKey, Kind, PendingQueue, Prediction};
use super::queue::EventQueue;
use crate::dynamics::Time;

/// Which event queue to hold.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum QueueKind {
    /// The 4-ary heap (the `heap-queue` feature's).
    Heap,
    /// The calendar queue the world uses.
    Calendar,
}

enum Queue {
    Heap(EventQueue),
    Calendar(CalendarQueue),
}

/// A queue with one pending event per ball, ready for [`HoldModel::hold`].
pub struct HoldModel {
    queue: Queue,
    /// SplitMix64 state: increments are seeded, so runs are comparable.
    state: u64,
}

impl HoldModel {
    /// A queue of `kind` holding one event per ball for `balls` balls, at times uniform in
    /// `[0, 1)` drawn from `seed`.
    #[must_use]
    pub fn new(kind: QueueKind, balls: u32, seed: u64) -> Self {
        let queue = match kind {
            QueueKind::Heap => Queue::Heap(EventQueue::default()),
            QueueKind::Calendar => Queue::Calendar(CalendarQueue::default()),
        };
        let mut model = Self { queue, state: seed };
        for ball in 0..balls {
            let time = model.uniform();
            model.set(ball, time);
        }
        model
    }

    /// Takes the earliest event and gives its ball a new one a time uniform in `[0, 2)`
    /// later (mean 1, the mean time between a ball's events). Returns the time taken, or
    /// `None` for a queue without balls.
    pub fn hold(&mut self) -> Option<f64> {
        let entry = self.peek()?;
        let now = entry.key.time.seconds();
        let later = now + 2.0 * self.uniform();
        self.set(entry.owner, later);
        Some(now)
    }

    fn peek(&self) -> Option<Entry> {
        match &self.queue {
            Queue::Heap(q) => q.peek(),
            Queue::Calendar(q) => q.peek(),
        }
    }

    fn set(&mut self, ball: u32, time: f64) {
        let prediction = Prediction {
            key: EventKey {
                time: Time::new(time),
                kind: Kind::Contact,
                first: ball,
                second: 0,
                feature: 0,
            },
            tag: 0,
        };
        match &mut self.queue {
            Queue::Heap(q) => q.set(ball, Some(prediction), None),
            Queue::Calendar(q) => q.set(ball, Some(prediction), None),
        }
    }

    /// A uniform double in `[0, 1)` (SplitMix64).
    fn uniform(&mut self) -> f64 {
        self.state = self.state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn both_queues_hold_the_same_times_in_order() {
        let mut heap = HoldModel::new(QueueKind::Heap, 500, 9);
        let mut calendar = HoldModel::new(QueueKind::Calendar, 500, 9);
        let mut last = 0.0;
        for _ in 0..20_000 {
            let (a, b) = (heap.hold(), calendar.hold());
            assert_eq!(a, b);
            let now = a.expect("500 balls");
            assert!(now >= last, "time went back: {now} < {last}");
            last = now;
        }
        assert!(HoldModel::new(QueueKind::Heap, 0, 1).hold().is_none());
    }
}
