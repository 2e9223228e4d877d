//! What the queue orders: event keys in their total order, and what each ball has pending.
//!
//! Each live ball has at most two pending events: its earliest collision or sensor crossing
//! (its *physical* prediction) and its next cell crossing of the broad phase. The queue orders
//! balls by the earlier of the two, so it holds one entry per ball whatever happens, and nothing
//! stale accumulates. When a ball's partner changes trajectory (its `version` grows) or a
//! collider is removed (its generation grows), the entry becomes *outdated*, detected by
//! comparing those counters when it comes up: the ball's other candidates were all later than
//! it, so the ball is simply predicted again then (algs4's `CollisionSystem` compares counters
//! the same way, with one entry per pair).

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
    /// Ball coming to rest on a collider, or sliding on from touching it (internal).
    Settle = 3,
    /// Supported ball reaching the end of its support (internal).
    Leave = 4,
    /// Ball leaving its broad-phase cell (internal; changes no trajectory).
    Crossing = 5,
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

/// A ball's pending event as the queue hands it out: the event, the ball that predicted it
/// (its *owner*) and the partner's `version` (a ball) or generation (a collider) at the time.
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
    pub(crate) fn precedes(&self, other: &Self) -> bool {
        match self.key.cmp(&other.key) {
            Ordering::Less => true,
            Ordering::Greater => false,
            Ordering::Equal => self.owner < other.owner,
        }
    }
}

/// A ball's earliest collision or sensor crossing, with the partner's tag (its `version` for
/// a ball, its generation for a collider).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Prediction {
    pub key: EventKey,
    pub tag: u32,
}

impl Prediction {
    /// How far a search for an earlier prediction than `best` must look: its time, or the
    /// end of time.
    #[inline]
    pub(crate) fn horizon(best: Option<Self>) -> Time {
        best.map_or(Time::new(f64::INFINITY), |b| b.key.time)
    }

    /// The earlier of two predictions (`best` on a tie).
    pub(crate) fn earlier(candidate: Option<Self>, best: Option<Self>) -> Option<Self> {
        match (candidate, best) {
            (Some(c), Some(b)) if b.key <= c.key => best,
            (Some(_), _) => candidate,
            (None, _) => best,
        }
    }
}

/// A [`Prediction`] stored without its owner (the slot it is stored in): 32 bytes.
#[derive(Clone, Copy)]
pub(crate) struct Stored {
    time: Time,
    partner: u32,
    tag: u32,
    kind: Kind,
    feature: u8,
}

impl Stored {
    pub(crate) fn new(owner: u32, p: Prediction) -> Self {
        let partner = if p.key.first == owner {
            p.key.second
        } else {
            p.key.first
        };
        Self {
            time: p.key.time,
            partner,
            tag: p.tag,
            kind: p.key.kind,
            feature: p.key.feature,
        }
    }

    pub(crate) fn prediction(&self, owner: u32) -> Prediction {
        let (first, second) = if self.kind == Kind::BallContact {
            (owner.min(self.partner), owner.max(self.partner))
        } else {
            (owner, self.partner)
        };
        Prediction {
            key: EventKey {
                time: self.time,
                kind: self.kind,
                first,
                second,
                feature: self.feature,
            },
            tag: self.tag,
        }
    }
}

/// What a ball has pending: its earliest collision or sensor crossing, and its next cell
/// crossing (infinite if none). The queue orders balls by the earlier of the two.
#[derive(Clone, Copy)]
pub(crate) struct Pending {
    pub physical: Option<Stored>,
    pub crossing: Time,
}

pub(crate) const NO_CROSSING: Time = Time::new(f64::INFINITY);

pub(crate) const IDLE: Pending = Pending {
    physical: None,
    crossing: NO_CROSSING,
};

impl Pending {
    /// The time of [`Self::due`]'s entry, without forming it: the earlier of the two times,
    /// the prediction on a tie (a crossing is last among the kinds at one time).
    #[inline]
    pub(crate) fn due_time(&self) -> Option<Time> {
        let crossing = (self.crossing != NO_CROSSING).then_some(self.crossing);
        match (self.physical, crossing) {
            (Some(p), Some(c)) if c < p.time => Some(c),
            (Some(p), _) => Some(p.time),
            (None, c) => c,
        }
    }

    /// The event due first, as an entry of `owner`.
    pub(crate) fn due(&self, owner: u32) -> Option<Entry> {
        let crossing = (self.crossing != NO_CROSSING).then_some(Entry {
            key: EventKey {
                time: self.crossing,
                kind: Kind::Crossing,
                first: owner,
                second: 0,
                feature: 0,
            },
            owner,
            partner_tag: 0,
        });
        let physical = self.physical.map(|s| {
            let p = s.prediction(owner);
            Entry {
                key: p.key,
                owner,
                partner_tag: p.tag,
            }
        });
        match (physical, crossing) {
            (Some(p), Some(c)) if c.key < p.key => Some(c),
            (Some(p), _) => Some(p),
            (None, c) => c,
        }
    }
}

/// What both event queues share: a table of what each ball has pending, and how it is set.
/// A queue only says where a ball's [`Pending`] is and re-orders it when it changes.
pub(crate) trait PendingQueue {
    /// What ball `owner` has pending, if the queue has seen it.
    fn pending(&self, owner: u32) -> Option<&Pending>;

    /// Replaces what ball `owner` has pending ([`IDLE`]: nothing), and re-orders it.
    fn put(&mut self, owner: u32, pending: Pending);

    /// Ball `owner`'s stored collision or sensor crossing.
    fn physical(&self, owner: u32) -> Option<Prediction> {
        let pending = self.pending(owner)?;
        pending.physical.map(|s| s.prediction(owner))
    }

    /// Sets ball `owner`'s earliest collision or sensor crossing and its next cell crossing.
    fn set(&mut self, owner: u32, physical: Option<Prediction>, crossing: Option<Time>) {
        let pending = Pending {
            physical: physical.map(|p| Stored::new(owner, p)),
            crossing: crossing.unwrap_or(NO_CROSSING),
        };
        self.put(owner, pending);
    }

    /// Sets ball `owner`'s earliest collision or sensor crossing, keeping its cell crossing.
    fn set_physical(&mut self, owner: u32, physical: Option<Prediction>) {
        let crossing = self.pending(owner).map_or(NO_CROSSING, |p| p.crossing);
        let pending = Pending {
            physical: physical.map(|p| Stored::new(owner, p)),
            crossing,
        };
        self.put(owner, pending);
    }

    /// Removes everything ball `owner` has pending.
    fn remove(&mut self, owner: u32) {
        self.put(owner, IDLE);
    }
}
