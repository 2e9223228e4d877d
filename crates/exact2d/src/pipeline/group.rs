//! Groups: balls a jam leaves pressed together under gravity, held by their contacts.
//!
//! After a jam (see `pipeline/jam.rs`) some contacts of the cluster stay *active*: touching, their
//! balls neither approaching nor separating (those the impact left separating no faster than a
//! settling hop are made so: they rest, as a ball settles on a surface). Under gravity such
//! contacts also carry force: a column of balls on a floor, jammed under a ceiling, a row pressed
//! against a wall by a tilted gravity. Each ball's acceleration is then not gravity but what the
//! active contacts leave of it,
//!
//! ```text
//! minimise  sum_i m_i |a_i - g|^2 / 2   subject to   (a_b - a_a) . n >= 0  (a ball pair),
//!                                                    a_a . n >= 0         (a surface)
//! ```
//!
//! over the active contacts: the acceleration of frictionless rigid bodies in contact (the
//! same programme as an impact, `dynamics/impact.rs`, with gravity for the velocities). A
//! ball that gravity alone would keep moving keeps it; the others form a *group* and move
//! with these constant accelerations, each on a parabola, until the group lets go.
//!
//! Why no ball of a group enters another or a surface it touches: at an active contact the
//! relative normal velocity is zero and, where the contact pushes, so is the relative normal
//! acceleration, with the normal `n` of the moment the group formed. So the relative position
//! is `d(t) = d0 + dv t + da t^2 / 2` with `d0` along `n` and `dv`, `da` across it, and
//! `|d(t)|^2 = |d0|^2 + |dv t + da t^2 / 2|^2` never falls: two members can only slide apart.
//! A ball against a segment's line keeps its distance to it exactly, and past the segment's
//! end its distance to the end point only grows. Nor does a group add energy: the contact
//! forces act along `n`, across which the relative velocity is zero at all times, so they do
//! no work, and in real arithmetic `m |v|^2 / 2 - m g . p` stays what it was.
//!
//! A member never settles on a surface alone (its held acceleration already counts every
//! surface it touches; settling would let the group go at the instant it formed). The group
//! lets go (every member moves under gravity again, and what it touches decides afresh: a new
//! jam, a settle, a bounce) as soon as
//! - any member's trajectory changes: an event, a settle, a new velocity, its removal (the
//!   others' accelerations assumed its own), but for a strike the group takes as one body,
//!   every contact it keeps pushing, which leaves its accelerations as they are
//!   (`pipeline/rigid.rs`);
//! - a member's centre leaves the extent of a segment it is held against;
//! - two members, or a member and a point it is held against, could have slid apart by the
//!   touching distance (`SETTLE_HEIGHT` of the coordinate scale; with sleeping on,
//!   [`GROUP_GAP`] of their contact distance): the forces, along the normals the group formed
//!   with, would soon act between bodies no longer touching. The time is taken
//!   conservatively, from `|dv| t + |da| t^2 / 2`. (A jam takes two members that far apart
//!   or nearer as touching, *fellows*, `pipeline/jam.rs`, and the group it forms lets them
//!   slide as far again: members of a group are at most twice [`GROUP_GAP`] apart.)
//!
//! A group at rest (a column between floor and ceiling) therefore costs no events at all.

use super::World;
use super::instant::Pair;
use super::rigid::Kept;
use glam::DVec2;

use crate::dynamics::Support;
use crate::geometry::ColliderHandle;

/// With sleeping on, how far (as a share of their contact distance) two members, or a member
/// and a point it is held against, may slide apart before the group lets go: `1e-3`. A member
/// has then slid at most `sqrt(2 x 1e-3)`, 4.5 %, of the contact distance across the normal
/// the group formed with, so the force along that normal is off the true one by at most 2.6
/// degrees, and the two are a thousandth of their contact distance apart (0.4 mm for balls of
/// radius 0.2 m; a fiftieth of a pixel on the game's board) when it is solved afresh. The
/// members never overlap (their distance only grows) and the group's forces do no work, so
/// the gap costs neither soundness nor energy: it bounds how far the group's motion, a
/// parabola on the old normals, strays from the true slide. (It was `9.5e-6`, a pivot's
/// polygon's gap: a sliding pile then let its groups go every few hundred microseconds,
/// each a new jam of its cluster, and a 100-ball pile at e = 0.5 took 110 s of wall to rest;
/// at `1e-3`, 15 s.) Without sleeping the gap is the touching distance, as before.
pub(crate) const GROUP_GAP: f64 = 1e-3;

/// A group: its number, its balls, and the contacts between them that hold them.
#[derive(Clone)]
pub(crate) struct Group {
    pub id: u32,
    pub members: Vec<u32>,
    /// The active contacts between two members (searched for each neighbour a member is
    /// predicted against): not predicted against while it holds.
    pub pairs: HeldPairs,
    /// Every contact the group keeps (between members, and of members with colliders), as
    /// a cluster of its members, for a hit taken as one body (`pipeline/rigid.rs`).
    pub kept: Option<Box<Kept>>,
    /// The contacts of its members (between two, or with a collider) that pushed in the
    /// solve of its accelerations, sorted: the guess the next jam of its balls starts its
    /// accelerations from (`pipeline/jam.rs`, `World::pushed_before`).
    pub pushing: Vec<Pair>,
}

/// The contacts between two balls among a group's, each as the number `a << 32 | b` (`a < b`),
/// sorted: searched for every pair of balls a member is predicted against (a search of the
/// [`Pair`]s themselves, which compare their kinds first, was 3 % of a 400-ball pile's time).
#[derive(Clone)]
pub(crate) struct HeldPairs(Vec<u64>);

impl HeldPairs {
    /// The pairs of two balls among `pairs`.
    fn new(pairs: &[Pair]) -> Self {
        let mut keys: Vec<u64> = pairs
            .iter()
            .filter_map(|pair| match *pair {
                Pair::Balls(a, b) => Some(Self::key(a, b)),
                Pair::Collider(..) => None,
            })
            .collect();
        keys.sort_unstable();
        HeldPairs(keys)
    }

    fn key(a: u32, b: u32) -> u64 {
        (u64::from(a.min(b)) << 32) | u64::from(a.max(b))
    }

    /// Whether balls `a` and `b`, in either order, are a pair among these.
    pub(crate) fn holds(&self, a: u32, b: u32) -> bool {
        self.0.binary_search(&Self::key(a, b)).is_ok()
    }
}

/// Whether balls `a` and `b` are held together by one of `groups` (see
/// [`World::held_group`]), through an active contact between them.
pub(crate) fn held_together(
    groups: &[Group],
    group_of: impl Fn(u32) -> Option<u32>,
    a: u32,
    b: u32,
) -> bool {
    let Some(id) = group_of(a) else {
        return false;
    };
    group_of(b) == Some(id) && groups.iter().any(|g| g.id == id && g.pairs.holds(a, b))
}

impl World {
    /// Sets ball `index`'s support, with friction's share (see `pipeline/rolling.rs`); if the
    /// ball was held by a group, the group lets go first (see the module documentation).
    pub(crate) fn set_support(&mut self, index: u32, support: Option<Support>) {
        if let Some(group) = self.held_group(index) {
            self.let_go(group);
        }
        let support = support.map(|s| self.rubbed(index, s));
        self.balls.set_support(index, support, self.time);
    }

    /// [`Self::set_support`] for a support that has had friction's share already (a settle
    /// needs it first, to see whether friction drives the ball into another surface).
    pub(crate) fn set_rubbed_support(&mut self, index: u32, support: Support) {
        if let Some(group) = self.held_group(index) {
            self.let_go(group);
        }
        self.balls.set_support(index, Some(support), self.time);
    }

    /// Ball `index` is held by group `group` from now on, with `acceleration`, for `until`,
    /// against the colliders `touching` beside its fellow members (its active contacts with
    /// colliders: not predicted against while the group holds, as the contacts between
    /// members are not).
    pub(crate) fn hold_member(
        &mut self,
        index: u32,
        acceleration: DVec2,
        (group, until): (u32, f64),
        touching: Vec<ColliderHandle>,
    ) {
        let p = self
            .balls
            .kinematics(index)
            .expect("live member")
            .trajectory
            .p0;
        let support = Support::held(acceleration, p, group, until);
        self.balls.set_support(index, Some(support), self.time);
        if let Some(properties) = self.balls.properties_mut(index) {
            properties.extra.set_touching(touching);
        }
    }

    /// The group holding ball `index`, if any.
    pub(crate) fn held_group(&self, index: u32) -> Option<u32> {
        if self.groups.is_empty() {
            return None;
        }
        self.balls.held_group(index)
    }

    /// Registers a new group of `members`, held together by the contacts `pairs`, keeping
    /// `kept` for a hit and the contacts `pushing` (sorted) that pushed in its accelerations'
    /// solve; returns its number.
    pub(crate) fn new_group(
        &mut self,
        members: Vec<u32>,
        pairs: Vec<Pair>,
        kept: Option<Box<Kept>>,
        pushing: Vec<Pair>,
    ) -> u32 {
        let id = self.next_group;
        self.next_group = self.next_group.wrapping_add(1);
        self.groups.push(Group {
            id,
            members,
            pairs: HeldPairs::new(&pairs),
            kept,
            pushing,
        });
        id
    }

    /// Group `group` lets go: each member is restated now under its held acceleration and
    /// moves under gravity from then on, predicted afresh.
    pub(crate) fn let_go(&mut self, group: u32) {
        self.let_go_but(group, &[]);
    }

    /// [`Self::let_go`], but the members in `predicted_later` (sorted) are not predicted
    /// afresh here: the caller predicts them once it has changed them (a jam, whose cluster's
    /// balls are all predicted at its end; predicted here too, each was predicted twice, the
    /// first time in vain).
    pub(crate) fn let_go_but(&mut self, group: u32, predicted_later: &[u32]) {
        let Some(at) = self.groups.iter().position(|g| g.id == group) else {
            return;
        };
        let members = self.groups.swap_remove(at).members;
        let time = self.time;
        for &member in &members {
            if self.balls.held_group(member) != Some(group) {
                continue;
            }
            let acceleration = self.acceleration(member);
            self.balls.rebase(member, time, acceleration);
            self.balls.set_support(member, None, self.time);
        }
        for &member in &members {
            if self.balls.kinematics(member).is_some()
                && predicted_later.binary_search(&member).is_err()
            {
                self.schedule(member);
            }
        }
    }
}
