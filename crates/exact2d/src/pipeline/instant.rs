//! What happened at the current instant: the bookkeeping of zero-time chains.
//!
//! Bodies that touch at one instant can hand impulses among themselves in a chain of
//! collisions at that same instant: a Newton's cradle passes its momentum down a row, a ball
//! aimed into a corner bounces off both walls. Handled one after another in the total order,
//! such a chain is exact, and usually short. But a chain can also come back to a contact it has
//! already responded to at this instant: a ball between two walls of an exact-fit channel bounces
//! from one to the other for ever (elastic) or a geometrically shrinking number of times
//! (inelastic), a row of balls jammed between walls does the same. The world records, for the
//! current instant only, which contacts have responded (and how often) and each ball's velocity
//! before its first response; a contact that would respond more than [`RESPONSES`] times is a
//! *jam*, and the bodies touching it are resolved together (see `pipeline/jam.rs`). Their contacts
//! are then *closed* for the rest of the instant: a contact now between two of them is tangential
//! (their velocities meet every contact to within the rounding of a solve).
//!
//! The records are cleared whenever the clock moves on, and whenever the caller changes the
//! world between two events (a new velocity starts a new chain).

use glam::DVec2;

use super::COLLAPSE_FLOOR;
use crate::dynamics::Time;

/// How many times a contact responds in sequence at one instant before it is a jam: 2.
///
/// Sequential chains that pass impulses to and fro and then end are exact and common: two
/// balls striking a third from both sides, two touching strikers hitting a row, each contact
/// responding twice. A chain that needs a contact a third time is taken to be looping.
pub(crate) const RESPONSES: u32 = 2;

/// A contact between two bodies: a ball and a collider, or two balls (smaller slot first).
/// Ordered (by kind, then slots) only so that sets of pairs can be searched.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Pair {
    /// Ball slot, collider slot.
    Collider(u32, u32),
    /// Two ball slots, the smaller first.
    Balls(u32, u32),
}

impl Pair {
    /// The pair of two balls in either order.
    pub(crate) fn balls(a: u32, b: u32) -> Self {
        Pair::Balls(a.min(b), a.max(b))
    }
}

/// A contact that responded in the current chain.
#[derive(Clone, Copy)]
struct Fired {
    pair: Pair,
    /// How many times it responded.
    times: u32,
    /// Its balls' velocities before its first response (in the pair's order; the second is
    /// unused for a collider). A ball's first response is that of the first contact recorded
    /// with it, so these are also its velocities before the chain.
    before: [DVec2; 2],
    /// What its responses added to the observables (`pipeline/observables.rs`): the virial,
    /// and the momentum given to the collider.
    virial: f64,
    given: DVec2,
}

/// An impulse of the current chain other than a response's (a jam's contact, a settle, a
/// group's strike) that a jam of the chain would undo: one recorded when every ball of its
/// contact had responded already (a jam starts again from the velocities before those
/// responses), with what it added to the observables.
#[derive(Clone, Copy)]
struct Noted {
    pair: Pair,
    virial: f64,
    given: DVec2,
}

/// A response recorded in the current chain (see [`Instant::respond`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Response(usize);

/// How long a zero-time chain lasts at most, in collapse floors of the clock from its first
/// event: 8. A rattle whose every bounce follows the last within the floor has a wall respond
/// a third time (a jam) by its fifth bounce, within four floors, so a chain begun at any of
/// its bounces holds its jam. Without a cap, a busy world at a large clock (a floor of 1e-6 s
/// at t = 1e6 s, events closer than that) would be one endless chain, whose response counts
/// would jam contacts that met thrice in a minute and whose closures would outlast their jams
/// (a closed contact is sought again only `SNAP_ULPS` deeper, `pipeline/predict.rs`).
pub(crate) const CHAIN_FLOORS: f64 = 8.0;

/// The records of one instant.
#[derive(Clone, Default)]
pub(crate) struct Instant {
    time: Time,
    /// When the current chain began: its first event (see [`Instant::at`]).
    start: Time,
    /// Events handled at `time` (internal ones included), since the records were last cleared.
    events: u64,
    /// Balls with an event at `time`, in the order of their first.
    balls: Vec<u32>,
    /// Contacts that responded in the current chain, in the order of their first response.
    fired: Vec<Fired>,
    /// Contacts resolved together at `time`: tangential for the rest of it.
    closed: Vec<Pair>,
    /// The chain's other impulses a jam would undo (see [`Noted`]).
    noted: Vec<Noted>,
}

impl Instant {
    /// Moves the records to `time`. A new instant clears the counts of the last one; the
    /// chain's records (which contacts responded, the velocities before, the closures) go on
    /// while each event follows the one before within [`COLLAPSE_FLOOR`] of the clock, and are
    /// cleared after: a ball between two walls a rounding error wider than it rattles from one
    /// to the other at times the clock can only just tell apart (9e-15 s a bounce, measured),
    /// and that chain is a jam as much as one at a single instant.
    ///
    /// The floor is the one within which a ball's collision after its last event is elastic
    /// (`World::recent`), and measured the same way, from event to event: so every rattle the
    /// floor keeps elastic is one chain, which the third response of a contact ends as a jam.
    /// Reckoned from the chain's first event instead, a chain held a rattle only if five of
    /// its bounces fitted in the floor; a ball in a funnel's neck 4e-13 wider than it, struck
    /// sideways at 44 m/s at t = 0.037 (floor 3.4e-14 s), crossed it every 9.1e-15 s: four
    /// bounces to a chain, each wall responding twice, then a new chain, elastic for ever
    /// (`exact2d-hunt --table` seed 1826674). A chain still ends [`CHAIN_FLOORS`] floors after
    /// its first event.
    #[inline]
    pub(crate) fn at(&mut self, time: Time) {
        if time != self.time {
            let previous = std::mem::replace(&mut self.time, time);
            self.events = 0;
            self.balls.clear();
            let floor = COLLAPSE_FLOOR * time.seconds().abs();
            if !(time.since(previous) <= floor && time.since(self.start) <= CHAIN_FLOORS * floor) {
                self.start = time;
                self.fired.clear();
                self.closed.clear();
                self.noted.clear();
            }
        }
    }

    /// Clears every record of this instant and chain (the caller changed the world).
    pub(crate) fn forget(&mut self) {
        self.start = self.time;
        self.events = 0;
        self.balls.clear();
        self.fired.clear();
        self.closed.clear();
        self.noted.clear();
    }

    /// An event of ball `ball` at this instant.
    #[inline]
    pub(crate) fn note_event(&mut self, ball: u32) {
        self.events += 1;
        if !self.balls.contains(&ball) {
            self.balls.push(ball);
        }
    }

    /// Whether the records are for `time`.
    pub(crate) fn is_at(&self, time: Time) -> bool {
        self.time == time
    }

    /// Events handled at this instant, and how many balls had them.
    pub(crate) fn events(&self) -> (u64, usize) {
        (self.events, self.balls.len())
    }

    /// `pair` responds now, its balls' velocities before the response being `before` (in the
    /// pair's order): the record of the response (for [`Self::note_response`]); `None` if it
    /// has already responded [`RESPONSES`] times in this chain: then it is a jam, and nothing
    /// is recorded.
    #[inline]
    pub(crate) fn respond(&mut self, pair: Pair, before: [DVec2; 2]) -> Option<Response> {
        match self.fired.iter().position(|f| f.pair == pair) {
            Some(at) if self.fired[at].times >= RESPONSES => None,
            Some(at) => {
                self.fired[at].times += 1;
                Some(Response(at))
            }
            None => {
                self.fired.push(Fired {
                    pair,
                    times: 1,
                    before,
                    virial: 0.0,
                    given: DVec2::ZERO,
                });
                Some(Response(self.fired.len() - 1))
            }
        }
    }

    /// The response `response` (just recorded by [`Self::respond`]) added `virial` and
    /// `given` to the observables: a jam of the chain would take them back.
    #[inline]
    pub(crate) fn note_response(&mut self, response: Response, virial: f64, given: DVec2) {
        if let Some(f) = self.fired.get_mut(response.0) {
            f.virial += virial;
            f.given += given;
        }
    }

    /// Contact `pair` gave an impulse now that added `virial` and `given` to the observables
    /// (not as a response of the chain): recorded if every ball of it has responded in this
    /// chain, since then a jam of the chain would undo it (see [`Noted`]).
    pub(crate) fn note(&mut self, pair: Pair, virial: f64, given: DVec2) {
        let responded = match pair {
            Pair::Collider(b, _) => self.velocity_before(b).is_some(),
            Pair::Balls(a, b) => {
                self.velocity_before(a).is_some() && self.velocity_before(b).is_some()
            }
        };
        if responded {
            self.noted.push(Noted {
                pair,
                virial,
                given,
            });
        }
    }

    /// A jam of the balls `in_cluster` (sorted) starts again from their velocities before the
    /// chain: the impulses of the chain's contacts among them (a ball and a collider, or two
    /// of them) are taken back. Returns the virial they added, and pushes onto `slots` each
    /// collider slot with the momentum it was given; their records are zeroed (the jam's own
    /// impulses are noted afresh).
    pub(crate) fn undo(&mut self, in_cluster: &[u32], slots: &mut Vec<(u32, DVec2)>) -> f64 {
        let inside = |b: u32| in_cluster.binary_search(&b).is_ok();
        let within = |pair: Pair| match pair {
            Pair::Collider(b, _) => inside(b),
            Pair::Balls(a, b) => inside(a) && inside(b),
        };
        let mut virial = 0.0;
        let mut take = |pair: Pair, w: &mut f64, given: &mut DVec2| {
            if !within(pair) {
                return;
            }
            virial += std::mem::take(w);
            let given = std::mem::take(given);
            if let (Pair::Collider(_, slot), true) = (pair, given != DVec2::ZERO) {
                slots.push((slot, given));
            }
        };
        for f in &mut self.fired {
            take(f.pair, &mut f.virial, &mut f.given);
        }
        for n in &mut self.noted {
            take(n.pair, &mut n.virial, &mut n.given);
        }
        self.noted
            .retain(|n| n.virial != 0.0 || n.given != DVec2::ZERO);
        virial
    }

    /// Ball `ball`'s velocity before its first response in this chain, if it had one.
    pub(crate) fn velocity_before(&self, ball: u32) -> Option<DVec2> {
        self.fired.iter().find_map(|f| match f.pair {
            Pair::Collider(b, _) | Pair::Balls(b, _) if b == ball => Some(f.before[0]),
            Pair::Balls(_, b) if b == ball => Some(f.before[1]),
            _ => None,
        })
    }

    /// Whether a contact `t` after `base` falls within this chain's reach: no later than
    /// [`COLLAPSE_FLOOR`] of the clock after `base`. For a closed pair such a contact is the
    /// one its jam resolved, met again by a rounding of the clock.
    #[inline]
    pub(crate) fn within_chain(base: Time, t: f64) -> bool {
        t <= COLLAPSE_FLOOR * base.seconds().abs()
    }

    /// Closes `pairs` for the rest of this instant.
    pub(crate) fn close(&mut self, pairs: impl IntoIterator<Item = Pair>) {
        self.closed.extend(pairs);
    }

    /// Whether `pair`, in contact at `time` (the origin of the trajectories asked about),
    /// is closed there: in the current chain, from its start to now (a ball touching a
    /// surface, or a ball, tangentially by a rounding of its speed can meet it again a
    /// rounding of the clock later, and again: the same chain, as the jam it was; closed only
    /// at the one instant, it crawled on at 2e-18 s an event).
    ///
    /// Closed too: a contact at a `time` before this chain began, with a partner there since
    /// before it (`born`; a ball partner always was, see [`ALWAYS`]). The trajectory that
    /// starts at `time` was predicted then, against every body it could touch; a contact of
    /// it at that instant was either handled then (which would have ended the trajectory) or
    /// closed by that instant's jam, whose records are gone. Predicted again later, from a
    /// cell crossing or for a partner that changed, it must get the answer it got then.
    /// Answered "open", a ball a jam left sliding along a wall, approaching it by a rounding
    /// (4.3e-18 m/s), met the wall again at its origin, an event dated now, from its cell
    /// crossing 0.55 s ahead, where the grid had already listed it; it stopped outside that
    /// cell, unseen by a ball that then ran 0.22 of a contact distance into it
    /// (`exact2d-hunt` seed 14109010). A collider added since (a ball fallen asleep against
    /// the trajectory's ball becomes a circle then) was not there to be decided: its contact
    /// is open, as at any instant (taken for closed, balls resting against a new sleeper sank
    /// through it: 17 hunt seeds in 383,343).
    #[inline]
    pub(crate) fn is_closed(&self, time: Time, pair: Pair, born: Time) -> bool {
        if time.since(self.start) < 0.0 {
            return born.since(time) < 0.0;
        }
        !self.closed.is_empty() && self.time.since(time) >= 0.0 && self.closed.contains(&pair)
    }
}

/// When a ball partner came to be, for [`Instant::is_closed`]: before any trajectory's
/// origin. A ball added, or woken, starts a trajectory then, so it was there at the origin
/// of every pair's trajectories it is in.
pub(crate) const ALWAYS: Time = Time::new(f64::NEG_INFINITY);

#[cfg(test)]
mod tests {
    use super::*;

    /// A closure lasts for the chain that made it, and a contact at an origin before the
    /// current chain, with a partner there before it, is closed whatever the records say
    /// (hunt seed 14109010); with a collider added since, it is open.
    #[test]
    fn closures_last_their_chain_and_origins_before_it_are_closed() {
        let (pair, wall) = (Pair::Collider(1, 3), Time::ZERO);
        let other = Pair::balls(2, 1);
        let jam = Time::new(0.25);
        let mut instant = Instant::default();
        instant.at(jam);
        assert!(!instant.is_closed(jam, pair, wall), "nothing closed yet");
        instant.close([pair]);
        assert!(instant.is_closed(jam, pair, wall));
        assert!(
            !instant.is_closed(jam, other, ALWAYS),
            "only the closed pair"
        );
        // A rounding of the clock later: the same chain.
        let next = jam.after(COLLAPSE_FLOOR * 0.25 * 0.5);
        instant.at(next);
        assert!(instant.is_closed(jam, pair, wall) && instant.is_closed(next, pair, wall));
        assert!(!instant.is_closed(next, other, ALWAYS));
        // Far later: a new chain, whose records hold nothing; a trajectory begun in it is
        // open, one begun at the jam is closed, for any partner there before the jam.
        let later = Time::new(0.3);
        instant.at(later);
        assert!(!instant.is_closed(later, pair, wall));
        assert!(instant.is_closed(jam, pair, wall) && instant.is_closed(jam, other, ALWAYS));
        // A collider added at the jam's instant or since (a ball fallen asleep) is open.
        assert!(!instant.is_closed(jam, pair, jam));
        assert!(!instant.is_closed(jam, pair, Time::new(0.28)));
        // The caller changing the world starts a chain now: origins before it are closed.
        instant.forget();
        assert!(!instant.is_closed(later, pair, wall));
        assert!(instant.is_closed(next, other, ALWAYS));
    }
}
