//! Observables for physicists: accumulators a run can read without an event callback.
//!
//! - The *collision virial* `W`: the sum, over every impulse two balls exchange, of
//!   `(p_i - p_j) . J_i`, with `p_i`, `p_j` the centres at the impact and `J_i` the impulse
//!   ball `i` receives from ball `j`. For a normal impulse of magnitude `J` between balls
//!   touching at contact distance `d` it is `d J` (positive: balls push each other apart); a
//!   friction impulse is perpendicular to `p_i - p_j` and adds nothing. With the kinetic
//!   energy `K` and `G = sum_i m_i p_i . v_i`, a run without gravity (nothing acts between
//!   events) obeys
//!   `G(t1) - G(t0) = int 2 K dt + W + sum over impulses from colliders of p_i . J_i`,
//!   which `tests/observables.rs` checks to the rounding in a closed box.
//! - Per collider, the *momentum transferred* to it: minus the sum of the impulses it gave
//!   balls (a ball bouncing off a wall on its right gives that wall momentum along `+x`), and
//!   the number of *impacts* on it: its [`ContactEvent`](crate::ContactEvent)s.
//!
//! Every path that changes a ball's velocity by an impulse through a contact adds to them:
//! binary collisions (micro-hops and collisions backed by a support among them), bounces,
//! jams (each contact row's multiplier, from the impact's solve and from the hold's
//! projection), a group's strikes taken as one body, settles (the velocity they drop, given
//! to the surfaces that hold the ball), friction at impacts, contacts with sleeping balls
//! (ball-ball impulses: they count in the virial, and the sleeper's supports get nothing) and
//! on a table the cushion hold and the joins. A zero-time chain's responses that a jam undoes
//! (it starts again from the velocities before the chain) are taken back when the jam's own
//! impulses are added, through the chain's ledger (`pipeline/instant.rs`).
//!
//! Excluded, because they are continuous forces of resting contact rather than impulses: a
//! ball's acceleration on its support (sliding, pivoting over a corner, turning onto the next
//! segment of a polyline), a group's held accelerations, the friction of a surface or of a
//! table's cloth during a phase (and a phase's end, which snaps what ended to its exact value),
//! and the speed a ball drops as it falls asleep (at most its sleep speed). Nor does a sleeping
//! ball pass a push it takes on to the colliders under it. Should rounding refuse every solve
//! of a jam (its balls then stop), that stop is not counted: its impulses are not known.

use glam::DVec2;

use super::World;
use super::instant::Pair;
use crate::dynamics::{ContactRow, Time};
use crate::geometry::{ColliderHandle, Shape};

/// What a run has accumulated since [`since`](Self::since): the collision virial (see
/// [`collision_virial`](Self::collision_virial)); the momentum and impacts of each collider are
/// read through [`World::collider_momentum`] and [`World::collider_impacts`].
///
/// Reading them changes nothing: the same events happen, bit for bit, whether or not anyone
/// looks. [`World::reset_observables`] starts them again (after equilibration, say).
#[derive(Clone, Debug, Default)]
pub struct Observables {
    virial: f64,
    since: Time,
    /// Per collider slot (proxies of sleeping balls included, always zero).
    colliders: Vec<Tally>,
}

/// What a collider has taken.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Tally {
    momentum: DVec2,
    impacts: u64,
}

impl Observables {
    /// The collision virial since [`since`](Self::since): the sum, over every impulse
    /// exchanged between two balls, of `(p_i - p_j) . J_i`, `p_i` and `p_j` the centres at the
    /// impact and `J_i` the impulse ball `i` received from ball `j` (so each normal impulse
    /// adds its magnitude times the contact distance, and friction adds nothing). Units: mass
    /// times length squared over time (kg m^2 / s: an impulse times a length).
    ///
    /// In a box of area `A` without gravity, the pressure follows from it as
    /// `P A = N k T + W / (2 (t1 - t0))` in two dimensions (`k T` the mean kinetic energy of a
    /// ball, `W` this over `t1 - t0`).
    ///
    /// Counted: binary collisions, jams (each contact's impulse, from the impact's solve), a
    /// group's strikes, contacts with sleeping balls; on a table, joins of balls the cloth
    /// presses together. Not counted: the forces of resting contact between balls a group
    /// holds together under gravity (continuous, not impulses).
    #[must_use]
    pub fn collision_virial(&self) -> f64 {
        self.virial
    }

    /// The time the accumulators started from: 0, or the time of the last
    /// [`World::reset_observables`].
    #[must_use]
    pub fn since(&self) -> f64 {
        self.since.seconds()
    }

    /// [`since`](Self::since) exactly.
    #[must_use]
    pub fn exact_since(&self) -> Time {
        self.since
    }

    /// Collider slot `slot`'s record, if it has one (every slot a collider was added to does:
    /// [`Self::clear_collider`]).
    #[inline]
    fn tally(&mut self, slot: u32) -> Option<&mut Tally> {
        self.colliders.get_mut(slot as usize)
    }

    /// Adds `w` to the virial.
    #[inline]
    pub(crate) fn add_virial(&mut self, w: f64) {
        self.virial += w;
    }

    /// Collider slot `slot` takes momentum `given`.
    #[inline]
    pub(crate) fn give(&mut self, slot: u32, given: DVec2) {
        if let Some(t) = self.tally(slot) {
            t.momentum += given;
        }
    }

    /// An impact on collider slot `slot`.
    #[inline]
    pub(crate) fn impact(&mut self, slot: u32) {
        if let Some(t) = self.tally(slot) {
            t.impacts += 1;
        }
    }

    /// Collider slot `slot` holds a new collider, or none: its record starts at zero.
    pub(crate) fn clear_collider(&mut self, slot: u32) {
        let i = slot as usize;
        if self.colliders.len() <= i {
            self.colliders.resize(i + 1, Tally::default());
        }
        self.colliders[i] = Tally::default();
    }

    /// Zeroes every accumulator; they count from `now`.
    pub(crate) fn reset(&mut self, now: Time) {
        self.virial = 0.0;
        self.since = now;
        self.colliders.fill(Tally::default());
    }

    /// The momentum and impacts of collider slot `slot`.
    fn of(&self, slot: u32) -> Tally {
        self.colliders
            .get(slot as usize)
            .copied()
            .unwrap_or_default()
    }
}

impl World {
    /// The accumulators of the run since [`Observables::since`]: the collision virial (see
    /// [`Observables`]).
    #[must_use]
    pub fn observables(&self) -> &Observables {
        &self.observables
    }

    /// Zeroes the observables (the collision virial, and every collider's momentum and
    /// impacts) and records the current time as the one they start from
    /// ([`Observables::since`]): measuring after equilibration. Nothing else changes: the
    /// events that follow are the same, bit for bit.
    ///
    /// Between two events of one zero-time chain (rare: events a rounding of the clock
    /// apart), a jam that ends the chain starts again from the velocities before it, and what
    /// it takes back of the chain's earlier impulses is taken from the observables after the
    /// reset: they count the change of momentum since the reset, as the velocities do.
    pub fn reset_observables(&mut self) {
        self.observables.reset(self.time);
    }

    /// The momentum the balls have transferred to a collider since [`Observables::since`]:
    /// minus the sum of the impulses it gave them (mass times velocity, kg m / s), so a ball
    /// bouncing off a wall on its right gives it momentum along `+x`. A bounce of a ball of mass
    /// `m` at normal speed `u` off an elastic wall gives it `2 m u` along the ball's approach.
    ///
    /// Counted: every impulse the collider gives a ball: bounces (with their friction), its
    /// contacts' shares of a jam's impact and of the hold's projection after it, the velocity a
    /// settle on it drops, a group's strikes on it, the push it gives a ball backed by it in a
    /// collision with another ball; on a table, the cushion hold. Not counted, because they are
    /// continuous forces of resting contact, not impulses: the force holding a ball that
    /// rests, slides, rolls or pivots on it under gravity (with its friction), or a group of
    /// balls held against it, and the velocity a ball drops falling asleep on it.
    ///
    /// `None` if the handle is not a live collider. A removed collider's record is dropped; a
    /// new one starts at zero.
    #[must_use]
    pub fn collider_momentum(&self, handle: ColliderHandle) -> Option<DVec2> {
        self.collider(handle)?;
        Some(self.observables.of(handle.index).momentum)
    }

    /// The number of impacts on a collider since [`Observables::since`]: the
    /// [`ContactEvent`](crate::ContactEvent)s naming it (bounces, jams and strikes returned as
    /// contact events; not settles, slides or jams' other contacts). `None` if the handle is
    /// not a live collider.
    #[must_use]
    pub fn collider_impacts(&self, handle: ColliderHandle) -> Option<u64> {
        self.collider(handle)?;
        Some(self.observables.of(handle.index).impacts)
    }

    /// Ball at `p` receives impulse `j` from collider slot `slot`: momentum `-j` for a
    /// collider, virial `(p - q) . j` for a sleeping ball's proxy (centre `q`). Returns what
    /// was added (virial, momentum given), for the chain's ledger.
    #[inline]
    pub(crate) fn take_from_collider(&mut self, p: DVec2, slot: u32, j: DVec2) -> (f64, DVec2) {
        if self.is_proxy(slot) {
            let centre = match self.colliders.at(slot).map(|(_, c)| c.shape) {
                Some(Shape::Circle(c)) => c.center,
                _ => p,
            };
            let w = (p - centre).dot(j);
            self.observables.add_virial(w);
            (w, DVec2::ZERO)
        } else {
            self.observables.give(slot, DVec2::ZERO - j);
            (0.0, DVec2::ZERO - j)
        }
    }

    /// Contact `pair` gave an impulse now: for two balls `Pair::Balls(a, b)` at `pa`, `pb`,
    /// `j` is the one `a` received (virial `(pa - pb) . j`); for a ball at `pa` and a
    /// collider, the one the ball received (`pb` unused). Adds it to the observables and to
    /// the chain's ledger.
    pub(crate) fn note_impulse(&mut self, pair: Pair, pa: DVec2, pb: DVec2, j: DVec2) {
        if j == DVec2::ZERO {
            return;
        }
        let (w, given) = match pair {
            Pair::Balls(..) => {
                // In a periodic box, the two meet through their nearest images.
                let w = (pa - self.image_near(pa, pb)).dot(j);
                self.observables.add_virial(w);
                (w, DVec2::ZERO)
            }
            Pair::Collider(_, slot) => self.take_from_collider(pa, slot, j),
        };
        self.instant.note(pair, w, given);
    }

    /// The impulses `impulses` of contacts `rows` (of `pairs`) among balls at `positions`
    /// (indexed as the rows' balls), as a simultaneous impact's solve gives them (see
    /// `dynamics/impact.rs`): each its magnitude along the row's normal.
    pub(crate) fn note_rows(
        &mut self,
        rows: &[ContactRow],
        pairs: &[Pair],
        positions: &[DVec2],
        impulses: &[f64],
    ) {
        for ((row, &pair), &l) in rows.iter().zip(pairs).zip(impulses) {
            if l == 0.0 {
                continue;
            }
            match row.b {
                // `a` receives `-l n` from `b`.
                Some(b) => self.note_impulse(
                    pair,
                    positions[row.a],
                    positions[b],
                    DVec2::ZERO - row.normal * l,
                ),
                None => self.note_impulse(pair, positions[row.a], DVec2::ZERO, row.normal * l),
            }
        }
    }

    /// A jam starts again from the velocities its cluster's balls (`in_cluster`, sorted) had
    /// before the chain: what the chain's responses among them added is taken back.
    pub(crate) fn undo_chain(&mut self, in_cluster: &[u32]) {
        let mut slots = Vec::new();
        let virial = self.instant.undo(in_cluster, &mut slots);
        self.observables.add_virial(-virial);
        for (slot, given) in slots {
            self.observables.give(slot, DVec2::ZERO - given);
        }
    }
}

/// Splits `change`, a change of momentum that two surfaces of normals `n1` and `n2` (unit)
/// gave a ball, into their shares `a n1` and `b n2`, `a n1 + b n2 = change` (the second
/// taken as `change - a n1`, so that the shares add up to the change). Normals parallel (to
/// within [`PARALLEL`](crate::dynamics::PARALLEL) as a sine) give the whole to the first.
pub(crate) fn split(change: DVec2, n1: DVec2, n2: DVec2) -> (DVec2, DVec2) {
    let det = n1.perp_dot(n2);
    if !(det.abs() > crate::dynamics::PARALLEL) {
        return (change, DVec2::ZERO);
    }
    let first = n1 * (change.perp_dot(n2) / det);
    (first, change - first)
}
