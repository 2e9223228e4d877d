//! The queue of pending events as a calendar queue (Brown 1988): buckets of equal width in
//! time, one intrusive list node per ball, O(1) expected per operation.
//!
//! # Design
//!
//! Like [`super::queue::EventQueue`], the queue holds one node per ball, for the earlier of its
//! two pending events ([`Pending::due`]), and replaces it in place when the ball is predicted
//! again. A node's *day* is `floor((t - origin) / width)` of its due time's leading double `t`,
//! and a node of day `d` sits in the doubly linked list of bucket `d mod buckets` if `d` is
//! before the *horizon*, and in the unsorted *overflow* list (the far future) otherwise. Links
//! are `u32` ball slots stored beside the due time, so a node is 16 bytes and is unlinked in
//! O(1); where a node sits is never stored: it follows from its day.
//!
//! The queue keeps the earliest node (`first`) up to date after every change, so
//! [`CalendarQueue::peek`] only reads it. When `first` is removed or moved later, the next one
//! is found by visiting days from the *cursor* (a day no node is before) onward, looking in
//! each day's bucket for the nodes of exactly that day. When the calendar is empty, the
//! earliest day in the overflow starts a new year: the cursor jumps there, the horizon moves a
//! year (`buckets` days) past it, and the overflow nodes before it move into buckets.
//!
//! The layout adapts: the number of buckets is kept a power of two within a factor of two of
//! the number of nodes, and each rebuild (on growth, shrinking, or when finding nodes has cost
//! too much work: see [`WORK_PER_FIND`]) re-estimates the width from the spread of the due
//! times, so the front of the queue holds about [`NODES_PER_DAY`] nodes per bucket.
//!
//! # Why the order is exactly the heap's
//!
//! The day is computed with one subtraction, one multiplication by a positive constant and a
//! clamped truncation, each monotone (IEEE rounding is monotone), so `t1 <= t2` implies
//! `day(t1) <= day(t2)`, and equal times share a day. Hence the minimum over all nodes by the
//! full order ([`Entry::precedes`]) has the smallest day, and it is found among the nodes of
//! that day, compared exactly as the heap compares them (leading double, then the whole
//! entry). Nothing is approximate: width and origin only decide how work is spread, never
//! which entry comes first; and the day is recomputed the same way wherever it is needed, so
//! it never disagrees with itself. Every node's day is at least the cursor (a node due before
//! it moves the cursor back), which is all the search relies on.
//!
//! # Measured against the heap
//!
//! Wall-clock comparisons on the shared benchmark machine stayed inside its noise (±15%), so
//! the choice was made on counts that do not vary from run to run (`BENCHMARKS.md`): under
//! callgrind and cachegrind the world with this queue executes 3% to 8% fewer instructions on
//! every scene of the suite (gases, brick board, free balls, pegs) and, on the gas of 10^5
//! balls, has 17% fewer misses in a 1 MB last level, for the same events bit for bit. The world
//! uses it; the `heap-queue` feature switches back to the 4-ary heap to repeat the
//! measurement. Memory: a ball's pending events (48 bytes, as in the heap) and its 16-byte
//! node share one 64-byte record, so a look at a node in a bucket and the change of a ball's
//! entry each touch one cache line; plus a 4-byte bucket head per 0.5 to 2 balls, against the
//! heap's 20 bytes of node and position per ball.

use super::pending::{Entry, IDLE, Pending, PendingQueue};

/// The end of a list, and "no ball".
const NIL: u32 = u32::MAX;
/// `prev` of a node that is in no list (its ball has nothing pending).
const DETACHED: u32 = u32::MAX - 1;
/// `prev` of the node at the head of its list.
const HEAD: u32 = u32::MAX - 2;

/// The largest day, `2^62`: later days (times far beyond a year, infinite times) are clamped
/// to it, which keeps `day + buckets` far from overflowing a `u64` and the clamp monotone.
const MAX_DAY: u64 = 1 << 62;

/// The fewest buckets: below this, resizing would cost more than it saves.
const MIN_BUCKETS: usize = 16;

/// How many nodes per bucket the queue grows at, and the inverse at which it shrinks: the
/// bucket count stays within a factor of two of the number of nodes either way.
const RESIZE_RATIO: usize = 2;

/// The number of nodes per day the width aims at, at the front of the queue. The engine's
/// events spread over about a mean time between collisions; with about as many buckets as
/// balls, a year then spans a few of those, and few nodes spill into the overflow.
const NODES_PER_DAY: f64 = 2.0;

/// Units of work (buckets visited, nodes looked at, nodes moved from the overflow) each search
/// for the next node may cost on average before the layout is deemed stale. A rebuild is
/// forced once the excess over this allowance exceeds the cost of a rebuild, so the total
/// work stays within a constant factor of the allowance.
const WORK_PER_FIND: i64 = 16;

/// A ball's node: the leading double of its due time, and its links.
#[derive(Clone, Copy)]
struct Node {
    time: f64,
    next: u32,
    prev: u32,
}

const FREE: Node = Node {
    time: 0.0,
    next: NIL,
    prev: DETACHED,
};

/// Everything the queue keeps about a ball, in one cache line: an operation on a ball's entry,
/// or a look at a node while searching a bucket, then touches one line rather than two.
#[derive(Clone, Copy)]
#[repr(C, align(64))]
struct Slot {
    pending: Pending,
    node: Node,
}

/// The queue of pending events as a calendar queue: the same interface and the same order as
/// [`super::queue::EventQueue`], with O(1) expected work per operation.
#[derive(Clone)]
pub(crate) struct CalendarQueue {
    /// Per ball slot, what it has pending and its node, in one cache line.
    slots: Vec<Slot>,
    /// Per bucket, the first node of its list (a power-of-two count).
    heads: Vec<u32>,
    /// The first node of the overflow list.
    overflow: u32,
    /// Nodes in lists, and of those the nodes in the overflow.
    len: usize,
    far: usize,
    /// The earliest node (`NIL` if none).
    first: u32,
    /// Days are counted from `origin` in units of `1 / per_width` (both finite, positive).
    origin: f64,
    per_width: f64,
    /// No node is due before day `cursor`; nodes before day `horizon` are in buckets.
    cursor: u64,
    horizon: u64,
    /// Work allowance left (negative: overspent); see [`WORK_PER_FIND`].
    credit: i64,
    /// Work done by searches in all (a statistic for tests).
    spent: u64,
    /// Buckets made room for ([`Self::reserve_slots`]): the table is not shrunk below.
    planned_buckets: usize,
}

impl Default for CalendarQueue {
    fn default() -> Self {
        Self {
            slots: Vec::new(),
            heads: vec![NIL; MIN_BUCKETS],
            overflow: NIL,
            len: 0,
            far: 0,
            first: NIL,
            origin: 0.0,
            per_width: 1.0,
            cursor: 0,
            horizon: MIN_BUCKETS as u64,
            credit: 0,
            spent: 0,
            planned_buckets: 0,
        }
    }
}

impl CalendarQueue {
    /// Makes room for balls in slots below `slots` without reallocating.
    pub(crate) fn reserve_slots(&mut self, slots: usize) {
        let more = slots.saturating_sub(self.slots.len());
        let _ = self.slots.try_reserve_exact(more);
        // And the buckets for as many entries, kept when the queue shrinks: the table grows
        // in place and leaves no freed smaller tables behind (which the allocator may keep
        // resident). Only a hint: room that cannot be had is neither made nor kept.
        if let Some(buckets) = slots.checked_next_power_of_two() {
            let more = buckets.saturating_sub(self.heads.len());
            if self.heads.try_reserve_exact(more).is_ok() {
                self.planned_buckets = self.planned_buckets.max(buckets);
            }
        }
    }

    /// The earliest entry.
    pub(crate) fn peek(&self) -> Option<Entry> {
        (self.first != NIL).then(|| self.due(self.first))
    }

    /// Whether ball `owner`'s new pending `new` (due at a time leading with `time`), its node
    /// unlinked but still holding its old time, and `old` its previous pending, comes before
    /// every other. Whole entries are formed only to break a tie of leading doubles.
    fn leads(&self, owner: u32, old: &Pending, new: &Pending, time: f64) -> bool {
        let due = || {
            new.due(owner)
                .expect("a pending with a due time has an entry")
        };
        if self.first != owner {
            if self.first == NIL {
                return true;
            }
            let other_time = self.slots[self.first as usize].node.time;
            if time != other_time {
                return time < other_time;
            }
            return due().precedes(&self.due(self.first));
        }
        // Still first if it moved no later: it preceded every other node before.
        let before = self.slots[owner as usize].node.time;
        time < before
            || (time == before
                && !old
                    .due(owner)
                    .expect("the first node had an event due")
                    .precedes(&due()))
    }

    /// The day of time `t`: monotone in `t`, the same for equal times.
    fn day(&self, t: f64) -> u64 {
        let x = (t - self.origin) * self.per_width;
        // Truncation toward zero, then negative days sent to 0: monotone. (Below `MAX_DAY` the
        // value fits an `i64`, whose conversion is one instruction where a `u64`'s is several.)
        if x < MAX_DAY as f64 {
            (x as i64).max(0) as u64
        } else {
            MAX_DAY
        }
    }

    /// Ball `owner`'s due entry (it has one: its node is in a list).
    fn due(&self, owner: u32) -> Entry {
        self.slots[owner as usize]
            .pending
            .due(owner)
            .expect("a ball in the queue has an event due")
    }

    /// Whether ball `a`'s node precedes ball `b`'s.
    fn precedes(&self, a: u32, b: u32) -> bool {
        let (ta, tb) = (
            self.slots[a as usize].node.time,
            self.slots[b as usize].node.time,
        );
        if ta != tb {
            return ta < tb;
        }
        self.due(a).precedes(&self.due(b))
    }

    /// The head of the list a node of day `day` belongs in.
    fn head_mut(&mut self, day: u64) -> &mut u32 {
        if day < self.horizon {
            let mask = self.heads.len() as u64 - 1;
            &mut self.heads[(day & mask) as usize]
        } else {
            &mut self.overflow
        }
    }

    /// Puts ball `owner`'s node (its time set) at the head of its day's list.
    fn link(&mut self, owner: u32) {
        let day = self.day(self.slots[owner as usize].node.time);
        if day >= self.horizon {
            self.far += 1;
        }
        self.len += 1;
        let head = self.head_mut(day);
        let next = std::mem::replace(head, owner);
        if next != NIL {
            self.slots[next as usize].node.prev = owner;
        }
        let node = &mut self.slots[owner as usize].node;
        node.next = next;
        node.prev = HEAD;
    }

    /// Takes ball `owner`'s node out of its list.
    fn unlink(&mut self, owner: u32) {
        let Node { time, next, prev } = self.slots[owner as usize].node;
        let day = self.day(time);
        if day >= self.horizon {
            self.far -= 1;
        }
        self.len -= 1;
        if prev == HEAD {
            *self.head_mut(day) = next;
        } else {
            self.slots[prev as usize].node.next = next;
        }
        if next != NIL {
            self.slots[next as usize].node.prev = prev;
        }
        let node = &mut self.slots[owner as usize].node;
        node.next = NIL;
        node.prev = DETACHED;
    }

    /// Finds the earliest node again after `first` was removed or moved later.
    fn find_first(&mut self) {
        self.first = NIL;
        if self.len == 0 {
            return;
        }
        loop {
            if let Some(owner) = self.search() {
                self.first = owner;
                break;
            }
            if self.len == self.far {
                self.new_year();
            } else {
                // A whole year of empty days before the nodes in buckets: the layout is stale.
                self.rebuild();
            }
        }
        self.credit = (self.credit + WORK_PER_FIND).min(self.rebuild_cost());
        if self.credit < -self.rebuild_cost() {
            self.rebuild();
        }
    }

    fn spend(&mut self, units: u32) {
        self.credit -= i64::from(units);
        self.spent += u64::from(units);
    }

    /// The cost of a rebuild in units of work, which is also the overspending that forces one.
    fn rebuild_cost(&self) -> i64 {
        (self.slots.len() + self.heads.len()) as i64
    }

    /// The earliest node in buckets, if one is due within a year of the cursor; the cursor
    /// moves to its day (or a year on if there is none).
    fn search(&mut self) -> Option<u32> {
        let end = self.horizon.min(self.cursor + self.heads.len() as u64);
        let mask = self.heads.len() as u64 - 1;
        let mut work = 0;
        let mut found = None;
        while self.cursor < end {
            let day = self.cursor;
            let mut at = self.heads[(day & mask) as usize];
            let mut best = NIL;
            work += 1;
            while at != NIL {
                let node = self.slots[at as usize].node;
                if self.day(node.time) == day && (best == NIL || self.precedes(at, best)) {
                    best = at;
                }
                at = node.next;
                work += 1;
            }
            if best != NIL {
                found = Some(best);
                break;
            }
            self.cursor += 1;
        }
        self.spend(work);
        found
    }

    /// With the buckets empty, starts the year at the earliest day in the overflow and moves
    /// the overflow nodes due within the year into buckets.
    fn new_year(&mut self) {
        let mut start = MAX_DAY;
        let mut at = self.overflow;
        while at != NIL {
            start = start.min(self.day(self.slots[at as usize].node.time));
            at = self.slots[at as usize].node.next;
        }
        // Every node is in the overflow: take the list whole and link its nodes again.
        let mut at = std::mem::replace(&mut self.overflow, NIL);
        (self.len, self.far) = (0, 0);
        self.cursor = start;
        self.horizon = start + self.heads.len() as u64;
        while at != NIL {
            let next = self.slots[at as usize].node.next;
            self.link(at);
            self.spend(2);
            at = next;
        }
    }

    fn shrink_if_sparse(&mut self) {
        if self.heads.len() > MIN_BUCKETS && self.len * RESIZE_RATIO * 2 < self.heads.len() {
            self.rebuild();
        }
    }

    /// Lays every node out again: a bucket count near the number of nodes, a width estimated
    /// from their due times, the origin at the earliest. `first` is unchanged (the nodes are).
    fn rebuild(&mut self) {
        let buckets = self.len.next_power_of_two().max(MIN_BUCKETS);
        let earliest = self
            .linked()
            .map(|i| self.slots[i].node.time)
            .fold(f64::INFINITY, f64::min);
        self.origin = if earliest.is_finite() { earliest } else { 0.0 };
        if let Some(width) = self.estimate_width() {
            self.per_width = 1.0 / width;
        }
        self.heads.clear();
        self.heads.resize(buckets, NIL);
        self.heads.shrink_to(buckets.max(self.planned_buckets));
        self.overflow = NIL;
        self.cursor = self.day(earliest);
        self.horizon = self.cursor + buckets as u64;
        (self.len, self.far) = (0, 0);
        for i in 0..self.slots.len() {
            if self.slots[i].node.prev != DETACHED {
                self.link(i as u32);
            }
        }
        self.credit = 0;
    }

    /// The slots of the balls whose nodes are in lists.
    fn linked(&self) -> impl Iterator<Item = usize> + '_ {
        (0..self.slots.len()).filter(|&i| self.slots[i].node.prev != DETACHED)
    }

    /// A bucket width giving about [`NODES_PER_DAY`] nodes per day at the front of the queue:
    /// from the median distance of a due time from the origin, found (to within its binade,
    /// then interpolated) with a histogram of exponents, so far-future outliers weigh nothing.
    /// `None` if the times give no scale (all equal, or none finite).
    fn estimate_width(&self) -> Option<f64> {
        /// Binades of a positive double: its biased exponent (11 bits).
        const BINADES: usize = 2048;
        let mut histogram = vec![0u32; BINADES];
        let mut finite = 0usize;
        for i in self.linked() {
            let d = self.slots[i].node.time - self.origin;
            if d.is_finite() {
                finite += 1;
                if d > 0.0 {
                    histogram[(d.to_bits() >> 52) as usize & (BINADES - 1)] += 1;
                }
            }
        }
        let zeros = finite - histogram.iter().map(|&c| c as usize).sum::<usize>();
        // The median, or the first time after the origin if more than half are at it.
        let rank = (finite / 2).max(zeros + 1);
        if rank > finite {
            return None;
        }
        let mut below = zeros;
        for (binade, &count) in histogram.iter().enumerate() {
            let count = count as usize;
            if below + count < rank {
                below += count;
                continue;
            }
            // The binade spans [low, 2 low); assume its times spread evenly.
            let low = f64::from_bits((binade as u64) << 52).max(f64::MIN_POSITIVE);
            let median = low * (1.0 + (rank - below) as f64 / count as f64);
            let width = NODES_PER_DAY * median / rank as f64;
            return (width.is_normal() && (1.0 / width).is_normal()).then_some(width);
        }
        None
    }
}

impl PendingQueue for CalendarQueue {
    fn pending(&self, owner: u32) -> Option<&Pending> {
        self.slots.get(owner as usize).map(|s| &s.pending)
    }

    fn put(&mut self, owner: u32, pending: Pending) {
        let i = owner as usize;
        if self.slots.len() <= i {
            self.slots.resize(
                i + 1,
                Slot {
                    pending: IDLE,
                    node: FREE,
                },
            );
        }
        let old = std::mem::replace(&mut self.slots[i].pending, pending);
        if self.slots[i].node.prev != DETACHED {
            self.unlink(owner);
        }
        let was_first = self.first == owner;
        let Some(due_time) = pending.due_time() else {
            if was_first {
                self.find_first();
            }
            self.shrink_if_sparse();
            return;
        };
        let time = due_time.seconds();
        let leads = self.leads(owner, &old, &pending, time);
        self.slots[i].node.time = time;
        if leads {
            self.first = owner;
            self.cursor = self.day(time);
            if self.len == 0 {
                self.horizon = self.cursor + self.heads.len() as u64;
            }
        }
        self.link(owner);
        if was_first && !leads {
            self.find_first();
        }
        if self.len > RESIZE_RATIO * self.heads.len() {
            self.rebuild();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dynamics::Time;
    use crate::pipeline::pending::{EventKey, Kind, NO_CROSSING, Prediction, Stored};
    use crate::pipeline::queue::EventQueue;

    /// A deterministic generator (a 64-bit LCG's high bits).
    struct Lcg(u64);

    impl Lcg {
        fn below(&mut self, n: u64) -> u64 {
            self.0 = self
                .0
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (self.0 >> 33) % n
        }

        fn unit(&mut self) -> f64 {
            self.below(1 << 30) as f64 / (1u64 << 30) as f64
        }
    }

    fn prediction(time: Time, kind: Kind, first: u32, second: u32) -> Prediction {
        Prediction {
            key: EventKey {
                time,
                kind,
                first,
                second,
                feature: 0,
            },
            tag: 7,
        }
    }

    /// A time of one of the shapes the queue must order exactly: on a coarse grid (many equal
    /// times), over many magnitudes, near zero, far future, with a residual (equal leading
    /// doubles), or a little after `now` (the engine's pattern).
    fn random_time(rng: &mut Lcg, now: f64) -> Time {
        match rng.below(8) {
            0 => Time::new(rng.below(40) as f64 * 0.25),
            1 => Time::new(rng.unit() * 10f64.powi(rng.below(25) as i32 - 12)),
            2 => Time::new([0.0, 5e-324, 1e-300, f64::MIN_POSITIVE][rng.below(4) as usize]),
            3 => Time::new([1e300, f64::MAX, 1e20][rng.below(3) as usize]),
            4 => Time::new(rng.below(4) as f64).after(rng.below(3) as f64 * 1e-30),
            _ => Time::new(now + rng.unit() * 2.0),
        }
    }

    /// A random `set` of ball `owner` (among `balls`), as its arguments.
    fn random_set(
        rng: &mut Lcg,
        owner: u32,
        balls: u64,
        now: f64,
    ) -> (Option<Prediction>, Option<Time>) {
        let other = rng.below(balls) as u32;
        let time = random_time(rng, now);
        let physical = match rng.below(6) {
            0 => None,
            1 => Some(prediction(time, Kind::Sensor, owner, other)),
            2 | 3 if other != owner => Some(prediction(
                time,
                Kind::BallContact,
                owner.min(other),
                owner.max(other),
            )),
            _ => Some(prediction(time, Kind::Contact, owner, other)),
        };
        let crossing = (rng.below(3) == 0).then(|| random_time(rng, now));
        (physical, crossing)
    }

    /// Random operations on `queue` and on an independent reference (every ball's due entry,
    /// the earliest found by a linear scan), checking every peek; then a full drain against the
    /// reference sorted. Phases grow the number of balls through several resizes, run the
    /// engine's pattern (the earliest handled, balls set after it), and shrink by removals.
    fn check_against_reference(seed: u64, operations: usize) {
        let mut rng = Lcg(seed);
        let mut queue = CalendarQueue::default();
        let max_balls = 200 + rng.below(1800);
        let mut reference: Vec<Option<Entry>> = vec![None; max_balls as usize];
        let mut now = 0.0;
        for step in 0..operations {
            let phase = step * 3 / operations;
            let balls = match phase {
                0 => 1 + max_balls * step as u64 / (operations as u64 / 3).max(1),
                _ => max_balls,
            }
            .min(max_balls);
            let engine = phase == 1 && rng.below(4) != 0;
            let owner = match queue.peek() {
                Some(top) if engine => top.owner,
                _ => rng.below(balls) as u32,
            };
            if let Some(top) = queue.peek() {
                now = top.key.time.seconds().min(1e6);
            }
            let removal = if phase == 2 { 3 } else { 8 };
            if rng.below(removal) == 0 {
                queue.remove(owner);
                reference[owner as usize] = None;
            } else {
                let (physical, crossing) = random_set(&mut rng, owner, balls, now);
                if rng.below(4) == 0 {
                    queue.set_physical(owner, physical);
                    let crossing = reference_crossing(&queue, owner);
                    reference[owner as usize] = due(owner, physical, crossing);
                } else {
                    queue.set(owner, physical, crossing);
                    reference[owner as usize] = due(owner, physical, crossing);
                }
            }
            assert_eq!(
                queue.peek(),
                earliest(&reference),
                "seed {seed}, step {step}"
            );
            assert_eq!(
                queue.physical(owner),
                queue_physical(&reference, owner, &queue)
            );
        }
        let mut sorted: Vec<Entry> = reference.iter().flatten().copied().collect();
        sorted.sort_by(|a, b| a.key.cmp(&b.key).then(a.owner.cmp(&b.owner)));
        let drained: Vec<Entry> = std::iter::from_fn(|| {
            let top = queue.peek()?;
            queue.remove(top.owner);
            Some(top)
        })
        .collect();
        assert_eq!(drained, sorted, "seed {seed}: drain");
    }

    fn reference_crossing(queue: &CalendarQueue, owner: u32) -> Option<Time> {
        let crossing = queue.slots[owner as usize].pending.crossing;
        (crossing != NO_CROSSING).then_some(crossing)
    }

    /// What `physical` must return: checked against the stored pending (which the reference
    /// does not keep), only for consistency of the round trip.
    fn queue_physical(
        _: &[Option<Entry>],
        owner: u32,
        queue: &CalendarQueue,
    ) -> Option<Prediction> {
        queue.slots[owner as usize]
            .pending
            .physical
            .map(|s| s.prediction(owner))
    }

    fn due(owner: u32, physical: Option<Prediction>, crossing: Option<Time>) -> Option<Entry> {
        Pending {
            physical: physical.map(|p| Stored::new(owner, p)),
            crossing: crossing.unwrap_or(NO_CROSSING),
        }
        .due(owner)
    }

    fn earliest(reference: &[Option<Entry>]) -> Option<Entry> {
        reference
            .iter()
            .flatten()
            .copied()
            .reduce(|a, b| if b.precedes(&a) { b } else { a })
    }

    #[test]
    fn random_operations_agree_with_a_sorted_reference() {
        for seed in 0..24 {
            check_against_reference(seed, 6_000);
        }
    }

    #[test]
    fn random_operations_peek_the_same_as_the_heap() {
        for seed in 100..116 {
            let mut rng = Lcg(seed);
            let (mut heap, mut calendar) = (EventQueue::default(), CalendarQueue::default());
            let balls = 1 + rng.below(3000);
            heap.reserve_slots(balls as usize);
            calendar.reserve_slots(balls as usize);
            let mut now = 0.0;
            for step in 0..30_000 {
                let owner = match heap.peek() {
                    Some(top) if rng.below(3) != 0 => top.owner,
                    _ => rng.below(balls) as u32,
                };
                if rng.below(10) == 0 {
                    heap.remove(owner);
                    calendar.remove(owner);
                } else {
                    let (physical, crossing) = random_set(&mut rng, owner, balls, now);
                    if rng.below(5) == 0 {
                        heap.set_physical(owner, physical);
                        calendar.set_physical(owner, physical);
                    } else {
                        heap.set(owner, physical, crossing);
                        calendar.set(owner, physical, crossing);
                    }
                }
                assert_eq!(calendar.peek(), heap.peek(), "seed {seed}, step {step}");
                assert_eq!(calendar.physical(owner), heap.physical(owner));
                if let Some(top) = heap.peek() {
                    now = top.key.time.seconds().min(1e6);
                }
            }
        }
    }

    #[test]
    fn edge_cases() {
        let mut q = CalendarQueue::default();
        assert!(q.peek().is_none());
        q.remove(5);
        assert!(q.peek().is_none() && q.physical(5).is_none());
        // A single ball, moved earlier, later, to the far future and back.
        for t in [3.0, 1.0, 1e300, f64::MAX, 0.0, 5e-324, 2.0] {
            q.set(5, Some(prediction(Time::new(t), Kind::Contact, 5, 0)), None);
            assert_eq!(q.peek().unwrap().key.time.seconds(), t);
        }
        // Equal leading doubles: the residual decides, then the kind, then the owner.
        q.set(
            1,
            Some(prediction(Time::new(2.0).after(1e-30), Kind::Contact, 1, 0)),
            None,
        );
        q.set(2, None, Some(Time::new(2.0)));
        q.set(
            3,
            Some(prediction(Time::new(2.0), Kind::BallContact, 3, 4)),
            None,
        );
        q.set(
            4,
            Some(prediction(Time::new(2.0), Kind::BallContact, 3, 4)),
            None,
        );
        let order: Vec<(u32, Kind)> = std::iter::from_fn(|| {
            let top = q.peek()?;
            q.remove(top.owner);
            Some((top.owner, top.key.kind))
        })
        .collect();
        let expected = [
            (5, Kind::Contact),
            (3, Kind::BallContact),
            (4, Kind::BallContact),
            (2, Kind::Crossing),
            (1, Kind::Contact),
        ];
        assert_eq!(order, expected);
        assert!(q.peek().is_none());
        // Far-future only, then one event before every day seen so far.
        for owner in 0..100 {
            let t = Time::new(1e300 * (1.0 + owner as f64));
            q.set(owner, Some(prediction(t, Kind::Contact, owner, 0)), None);
        }
        assert_eq!(q.peek().unwrap().owner, 0);
        q.set(50, None, Some(Time::new(1e-300)));
        assert_eq!(q.peek().unwrap().owner, 50);
        q.remove(50);
        assert_eq!(q.peek().unwrap().owner, 0);
        q.set(7, None, Some(Time::new(-0.0)));
        assert_eq!(q.peek().unwrap().owner, 7);
    }

    #[test]
    fn many_equal_times_come_out_by_owner() {
        let mut q = CalendarQueue::default();
        for owner in (0..500).rev() {
            q.set(owner, None, Some(Time::new(1.0)));
        }
        for owner in 0..500 {
            let top = q.peek().unwrap();
            assert_eq!(top.owner, owner);
            q.remove(owner);
        }
        assert!(q.peek().is_none() && q.len == 0);
    }

    #[test]
    fn the_engine_pattern_costs_constant_work_per_event() {
        // 20 000 balls, each with one event spread over about a unit of time; the earliest is
        // handled and its ball set again a random interval later (mean 1).
        let mut rng = Lcg(3);
        let mut q = CalendarQueue::default();
        let n = 20_000;
        for owner in 0..n {
            q.set(owner, None, Some(Time::new(rng.unit())));
        }
        let (searches, spent) = (200_000, q.spent);
        for _ in 0..searches {
            let top = q.peek().unwrap();
            let now = top.key.time.seconds();
            q.set(top.owner, None, Some(Time::new(now + 2.0 * rng.unit())));
        }
        let work = q.spent - spent;
        assert!(q.heads.len() <= 2 * n as usize);
        assert!(
            work < 6 * searches,
            "{work} units of work for {searches} searches"
        );
    }

    #[test]
    fn buckets_reserved_for_the_slots_are_grown_into_in_place_and_kept() {
        // Every table the buckets grow through is the reserved one: none is left behind.
        let mut rng = Lcg(5);
        let mut q = CalendarQueue::default();
        let n = 5_000;
        q.reserve_slots(n as usize);
        let (table, capacity) = (q.heads.as_ptr(), q.heads.capacity());
        assert!(capacity >= (n as usize).next_power_of_two());
        for owner in 0..n {
            q.set(owner, None, Some(Time::new(rng.unit())));
        }
        assert!(q.heads.len() > 1_000);
        for owner in 0..n - 10 {
            q.set(owner, None, None);
        }
        assert!(q.heads.len() < 100, "{}", q.heads.len());
        assert_eq!((q.heads.as_ptr(), q.heads.capacity()), (table, capacity));
    }

    #[test]
    fn a_ball_costs_the_queue_64_bytes_and_a_bucket_4() {
        assert_eq!(std::mem::size_of::<Pending>(), 48);
        assert_eq!(std::mem::size_of::<Node>(), 16);
        assert_eq!(std::mem::size_of::<Slot>(), 64);
        assert_eq!(std::mem::align_of::<Slot>(), 64);
        assert_eq!(std::mem::size_of::<u32>(), 4);
    }
}
