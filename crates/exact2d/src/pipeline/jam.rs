//! Jams: a zero-time chain that comes back to a contact is resolved as one simultaneous
//! impact of every body touching it.
//!
//! A contact that responds a second time at one instant (see `pipeline/instant.rs`) means the
//! bodies around it are passing impulses round a loop that, in sequence, would never end (a ball
//! between opposite walls, elastic) or end only after the speeds underflow (a wedge, a row of
//! inelastic balls between walls: thousands of events). Instead the world takes the *cluster* of
//! that contact, every ball connected to it through contacts that touch now (no more than
//! [`SETTLE_HEIGHT`] of the coordinate scale apart, or overlapping; with sleeping on, two
//! members of one group up to [`GROUP_GAP`] of their contact distance apart, `World::fellows`;
//! a static collider touches but does not connect), and resolves the cluster at once from the
//! velocities its balls had before the instant's first response (`dynamics/impact.rs`):
//!
//! - each contact asks to separate at its restitution times the speed at which it
//!   approached then (zero for those that did not approach): the impulse law of rigid bodies
//!   in unilateral contact. A heavy ball driving a light one into a wall bounces off it, the
//!   light one pinned;
//! - where those targets cannot all be met (a ball between opposite walls, asked to leave one
//!   and not enter the other), or meeting them would add kinetic energy, the impact is
//!   perfectly plastic: every target zero, the projection of the velocities onto those that
//!   enter nothing, which never adds energy. A ball driven across an exact-fit channel keeps
//!   only its speed along it; a wedge stops a ball driven into it;
//! - a contact with friction (both its bodies' coefficients above zero) also carries a
//!   tangential impulse within Coulomb's cone of its normal one, the most dissipative such
//!   (`dynamics/impact_friction.rs`); should neither frictional impact pass the energy check,
//!   the frictionless ones are tried;
//! - with sleeping on, under gravity and without friction, a jam none of whose contacts
//!   would bounce off faster than it rests at (`World::resolve_plastic`) is plastic: the
//!   hold's projection, which would hold each such bounce touching anyway, resolves it alone,
//!   and the impact is not solved (unless that projection pulls at a contact an impact would
//!   let part).
//!
//! Every contact of the cluster is then *closed* for the rest of the instant: the solve meets
//! them all to within the rounding of its own arithmetic (its slack), and a contact now between
//! two closed bodies at this instant is tangential. So the chain ends: at one instant, each
//! contact responds in sequence at most once before its cluster is resolved, and the touching
//! bodies (positions do not change within an instant) form each cluster once.

use glam::DVec2;

use super::World;
use super::group::GROUP_GAP;
use super::instant::Pair;
use super::rigid::Kept;
use super::step::{COLLAPSE_FLOOR, balls_touch};
use crate::dynamics::{
    ContactRow, Factored, NO_COLLIDER, PARALLEL, Roughness, Rub, SETTLE_HEIGHT, Support, Touch,
    frictional_hold, resolve_frictional_impact, resolve_impact_from, resolve_impact_guessed,
    resolve_impact_with_impulses, resolve_with_equalities_factored, sleep_speed,
};
use crate::geometry::{ColliderHandle, Shape};
use crate::toi::Motion;

/// The slack of a jam's contacts, in ulps of the fastest speed in the cluster: how far below
/// its target the solve may leave a contact, as the rounding of the velocities it writes.
const JAM_SLACK_ULPS: f64 = 16.0;

/// The balls from which a slow jam is tried as a plastic one ([`World::resolve_plastic`]):
/// the clusters whose impact the Gram matrix's factor solves, a contact joining at each
/// step (`GRAM_FROM` in `dynamics/impact.rs`). Below it the impact is cheap and a projection
/// that pulls is solved for nothing: tried on every slow jam, 32 frictionless 100-ball
/// piles took 90.8 s of wall where 64.7 s.
const PLASTIC_FROM: usize = 40;

/// The balls from which a hold's accelerations start from the contacts that pushed when the
/// groups of its balls were last solved ([`World::pushed_before`]), where they are at least
/// half of its active contacts, rather than from its projection's factor: the clusters whose
/// programmes the Gram matrix's factor solves. A pile's jams come microseconds apart on
/// nearly the same contacts, and those that pushed then push now; the projection's active
/// set holds every resting contact, a quarter of which pull, and the accelerations' solve
/// dropped those and added most of them back a step at a time (the 400-ball pile at seed 1
/// from t = 1.8 to 2.1, timed on the same programmes: 16.4 s where 62.8 s). Below it the
/// projection's factor, which costs nothing to reuse, is the quicker start (0.19 s where
/// 0.23 s over the same programmes of under 40 balls, t = 1.9 to 2.1, in a scratch build
/// that guessed for every cluster).
const WARM_FROM: usize = 40;

/// How far below zero, in units in the last place of a cluster's fastest speed times its
/// heaviest ball's mass, a plastic jam's impulse at a contact that neither parts nor
/// approaches may fall and count as a push ([`World::resolve_plastic`]): the projection's
/// rounding, which its slack (`JAM_SLACK_ULPS` of the speed) bounds, amplified by the masses.
const PULL_ULPS: f64 = 64.0;

/// A cluster of touching bodies: its balls (slots) and contacts.
#[derive(Clone)]
pub(super) struct Cluster {
    pub(super) balls: Vec<u32>,
    pub(super) pairs: Vec<Pair>,
    pub(super) rows: Vec<ContactRow>,
    /// Each contact's restitution.
    pub(super) restitutions: Vec<f64>,
    /// Each contact's contact distance.
    pub(super) reaches: Vec<f64>,
}

/// How fast (as a share of gravity's) the members of a group may be accelerated by its solve
/// and still be held still when the work check refuses that solve: `1e-6`. A thin wedge pins a
/// ball with forces of `1 / angle` times its weight, and the rounding of those is left in the
/// accelerations of the balls it presses on: a ball wedged between a wall and a ball pinned
/// between a floor and a ceiling 2.5e-6 radians apart (hunt seed 9063215) was solved to rise
/// at 7.4e-8 of gravity's acceleration, refused as working against gravity for the 1100 s the
/// group would hold, and fell back into its wedge every 1.3e-5 s instead, a jam each time,
/// sinking 1.8e-12 of its contact distance deeper at each. Held still, the group does no
/// work, and costs nothing until something strikes it. A wedge's rounding above this share
/// is refused as before (the channel of seed 8289229 rounded to 6e-4), unless the solve is
/// a worse answer of its own programme than rest ([`worse_than_still`]).
const STILL: f64 = 1e-6;

/// What the hold's projection makes of a cluster's velocities ([`World::projection`]).
struct Projection {
    /// The velocities projected.
    velocities: Vec<DVec2>,
    /// The factorisation of the contacts it ended meeting exactly (indices of the cluster's
    /// rows), none where a contact is stuck (friction).
    factored: Option<Factored>,
    /// Each contact's impulse (a pull where negative: an equality's).
    impulses: Vec<f64>,
}

/// What a hold's solve would make of a cluster (see [`World::group_of`]).
struct Hold {
    /// Each ball's solved acceleration (a member's zero where it is no more than rounding).
    accelerations: Vec<DVec2>,
    /// Each ball's acceleration as solved: what the work check judges (the members'
    /// accelerations zeroed where they are rounding, it passed groups whose solve it refuses,
    /// and their members sank into each other by a rounding at each jam).
    solved: Vec<DVec2>,
    /// Whether each ball is a member.
    held: Vec<bool>,
    /// The cluster's contacts that carry force between members.
    held_rows: Vec<usize>,
    /// The members (cluster indices, in order).
    members: Vec<usize>,
    /// How long each member is held (infinite for the rest).
    until: Vec<f64>,
    /// How long the group holds: the first member's time.
    lifetime: f64,
    /// The contacts between members, or of members with colliders, that pushed in the
    /// solve (sorted; none with friction).
    pushing: Vec<Pair>,
}

impl Hold {
    /// Holds no member past the time at which a contact of its slides to a stop: `ends`, one
    /// for each of the cluster's rows `active` (see [`frictional_hold`]); a kinetic force
    /// would turn round there and work on the balls.
    fn end_slips(&mut self, cluster: &Cluster, active: &[usize], ends: &[f64]) {
        for (&k, &end) in active.iter().zip(ends) {
            if end.is_finite() {
                let row = &cluster.rows[k];
                for at in std::iter::once(row.a).chain(row.b) {
                    if self.held[at] {
                        self.until[at] = self.until[at].min(end);
                    }
                }
            }
        }
        self.lifetime = self
            .members
            .iter()
            .map(|&at| self.until[at])
            .fold(f64::INFINITY, f64::min);
    }
}

impl World {
    /// Whether a ball of the cluster has friction (a contact has it only if both its bodies
    /// do).
    fn any_rough(&self, cluster: &Cluster) -> bool {
        cluster.balls.iter().any(|&b| {
            self.balls
                .spin(b)
                .is_some_and(|s| s.roughness.friction > 0.0)
        })
    }

    /// Each of the cluster's rows `active`: its pair's friction coefficient, and its slip
    /// with the balls' `velocities` (see [`Rub`]).
    fn rubs(&self, cluster: &Cluster, active: &[usize], velocities: &[DVec2]) -> Vec<Rub> {
        let ball = |at: usize| {
            self.balls
                .spin(cluster.balls[at])
                .map_or(Roughness::SMOOTH, |s| s.roughness)
        };
        active
            .iter()
            .map(|&k| {
                let row = &cluster.rows[k];
                let other = match (row.b, cluster.pairs[k]) {
                    (Some(b), _) => ball(b),
                    (None, Pair::Collider(_, slot)) => self
                        .colliders
                        .at(slot)
                        .map_or(Roughness::SMOOTH, |(_, c)| c.roughness()),
                    (None, Pair::Balls(..)) => Roughness::SMOOTH,
                };
                let mu = ball(row.a).pair(other).friction;
                let slip = row.tangent().relative(velocities);
                Rub { mu, slip }
            })
            .collect()
    }

    /// Resolves the jam at the current instant around the balls `seed` (the balls of the
    /// contact that came back), as the module documentation says.
    pub(crate) fn resolve_jam(&mut self, seed: &[u32]) {
        let cluster = self.cluster(seed);
        // Read before the jam lets its balls' groups go.
        let known = self.pushed_before(&cluster);
        let masses: Vec<f64> = cluster
            .balls
            .iter()
            .map(|&b| self.balls.mass_and_restitution(b).expect("live ball").0)
            .collect();
        let start: Vec<DVec2> = cluster
            .balls
            .iter()
            .map(|&b| {
                self.instant
                    .velocity_before(b)
                    .unwrap_or_else(|| self.velocity_now(b))
            })
            .collect();
        let now: Vec<DVec2> = cluster
            .balls
            .iter()
            .map(|&b| self.velocity_now(b))
            .collect();
        // Each contact's friction (none if no ball of the cluster has any).
        let mus: Vec<f64> = if self.any_rough(&cluster) {
            let all: Vec<usize> = (0..cluster.rows.len()).collect();
            self.rubs(&cluster, &all, &start)
                .iter()
                .map(|rub| rub.mu)
                .collect()
        } else {
            Vec::new()
        };
        let mut in_cluster = cluster.balls.clone();
        in_cluster.sort_unstable();
        // The observables: the impact's impulses, contact by contact. From the velocities
        // before the chain, they replace what the chain's responses among these balls gave.
        let positions: Vec<DVec2> = cluster
            .balls
            .iter()
            .map(|&b| self.position_now(b))
            .collect();
        let plastic = self.gravity != DVec2::ZERO
            && self.resting()
            && mus.is_empty()
            && self.resolve_plastic(
                &cluster,
                &masses,
                (&start, &now),
                &in_cluster,
                (&positions, &known),
            );
        if !plastic {
            let (after, impulses) = impact(&masses, &start, &now, &cluster, &mus);
            if let Some((impulses, from_start)) = impulses {
                if from_start {
                    self.undo_chain(&in_cluster);
                }
                if impulses.len() == cluster.rows.len() {
                    self.note_rows(&cluster.rows, &cluster.pairs, &positions, &impulses);
                } else {
                    // With friction: the normal impulses, then the tangential ones.
                    let rows: Vec<ContactRow> = (cluster.rows.iter().copied())
                        .chain(cluster.rows.iter().map(|row| row.tangent()))
                        .collect();
                    let pairs: Vec<Pair> = cluster.pairs.repeat(2);
                    self.note_rows(&rows, &pairs, &positions, &impulses);
                }
            }
            self.set_cluster_velocities(&cluster, &after, &in_cluster);
            if self.gravity != DVec2::ZERO {
                // The impact's rounding is that of the speeds it started from.
                let speed = fastest(&start, &after);
                self.hold(&cluster, &masses, &after, speed, (&positions, &known));
            }
        }
        self.instant.close(cluster.pairs.iter().copied());
        // On a table the cloth's holds take the hold's part (without gravity in the plane).
        self.hold_after_jam(&cluster.balls, &cluster.pairs);
        self.counts.jams += 1;
        // Every ball's partners learn of every change before any of them is predicted again.
        for &ball in &cluster.balls {
            self.schedule(ball);
        }
        // Those now at rest on colliders and sleeping balls alone sleep, the lowest first (so
        // that a ball resting on another finds it asleep).
        if self.resting() {
            let up = -self.gravity;
            let height = |ball: u32| {
                let record = self.balls.kinematics(ball).expect("live ball");
                record.trajectory.p0.dot(up)
            };
            let mut order = cluster.balls.clone();
            order.sort_by(|&a, &b| height(a).total_cmp(&height(b)).then(a.cmp(&b)));
            for ball in order {
                self.try_sleep(ball);
            }
        }
    }

    /// The cluster's balls take `velocities` now: each is restated now with its velocity, a
    /// group that held it lets go (its members in the cluster, `in_cluster`, sorted, are
    /// predicted with the rest of the cluster), and it is supported no longer.
    fn set_cluster_velocities(
        &mut self,
        cluster: &Cluster,
        velocities: &[DVec2],
        in_cluster: &[u32],
    ) {
        for (&ball, &v) in cluster.balls.iter().zip(velocities) {
            let (time, acceleration) = (self.time, self.acceleration(ball));
            self.balls.rebase(ball, time, acceleration);
            let record = self.balls.kinematics_mut(ball).expect("live ball");
            record.trajectory.v0 = v;
            if self.balls.is_supported(ball) {
                // A group a ball of the cluster was held by lets go; its members in the
                // cluster are predicted at the end of the jam, with the rest of the cluster.
                if let Some(group) = self.held_group(ball) {
                    self.let_go_but(group, in_cluster);
                }
                self.balls.set_support(ball, None, self.time);
            }
            self.balls.bump_version(ball);
        }
    }

    /// A slow jam of [`PLASTIC_FROM`] balls and more resolved as a plastic one (with sleeping
    /// on, under gravity, without friction; ARCHITECTURE.md, "a plastic jam"). Where no
    /// contact of the cluster would bounce off faster than it rests at (its restitution times
    /// its approach before the chain, `start`, within its rest speed, [`Self::rest_speeds`]),
    /// every bounce the impact
    /// would give is one the hold drops: the hold's projection holds every contact that parts
    /// no faster than it rests at touching, and an impulse along the contacts' normals has no
    /// part in the motions those equalities leave, so the projection annuls the impact's
    /// bounces. The projection alone then resolves the jam (the least change of the velocities
    /// that leaves no contact approaching, and those that approach or part no faster than they
    /// rest touching), and the impact, whose contacts join its solve one at a step, the
    /// dearest of a big jam's three solves, is not solved. Unless the projection pulls at a
    /// contact that neither parts nor approaches (beyond its rounding, [`PULL_ULPS`]): an
    /// impact would have let that contact part, maybe faster than it rests at, which the hold
    /// would not stop (a strike driving a pyramid's base apart); such a jam is the impact's.
    /// The projection starts from `start` (the chain's responses among these balls undone in
    /// the observables), or from `now` where the chain has taken energy from them, so that no
    /// energy is gained, as the impact does. Returns whether it resolved the jam (and held the
    /// balls); `false`, nothing changed, where the jam is not that slow or rounding refuses
    /// its solves: the impact then resolves it.
    fn resolve_plastic(
        &mut self,
        cluster: &Cluster,
        masses: &[f64],
        (start, now): (&[DVec2], &[DVec2]),
        in_cluster: &[u32],
        (positions, known): (&[DVec2], &[Pair]),
    ) -> bool {
        if cluster.balls.len() < PLASTIC_FROM {
            return false;
        }
        let rest = self.rest_speeds(cluster);
        let slow = (cluster.rows.iter().zip(&cluster.restitutions).zip(&rest))
            .all(|((row, e), rest)| e * (-row.relative(start)).max(0.0) <= *rest);
        if !slow {
            return false;
        }
        let from_start = kinetic(masses, start) <= kinetic(masses, now);
        let base = if from_start { start } else { now };
        let resting = resting_rows(cluster, base, &rest);
        let speed = fastest(start, base);
        let Some(projection) = self.projection(cluster, masses, base, speed, (&resting, &[]))
        else {
            return false;
        };
        // A contact that neither parts nor approaches, pulled: an impact would have let it
        // part (faster, maybe, than it rests at), which the hold would not stop. That jam is
        // the impact's.
        let tangential = tangential_within(speed);
        let heaviest = masses.iter().fold(0.0_f64, |m, &x| m.max(x));
        let pull = -PULL_ULPS * f64::EPSILON * speed * heaviest;
        let pulled = (0..cluster.rows.len())
            .any(|k| projection.impulses[k] < pull && cluster.rows[k].relative(base) <= tangential);
        if pulled {
            return false;
        }
        if from_start {
            self.undo_chain(in_cluster);
        }
        self.note_rows(
            &cluster.rows,
            &cluster.pairs,
            positions,
            &projection.impulses,
        );
        self.set_cluster_velocities(cluster, &projection.velocities, in_cluster);
        self.hold_projected(
            cluster,
            masses,
            &projection.velocities,
            (projection.factored, known),
            speed,
        );
        true
    }

    /// After the impact: the cluster's balls that its contacts hold against gravity. A ball
    /// held only by surfaces rests on them now ([`Self::settle`]: it slides, pivots or stays
    /// in a wedge), rather than settle after the impact has been undone by a second one; the
    /// balls held (also) by other balls form a group (`pipeline/group.rs`).
    fn hold(
        &mut self,
        cluster: &Cluster,
        masses: &[f64],
        velocities: &[DVec2],
        speed: f64,
        (positions, known): (&[DVec2], &[Pair]),
    ) {
        // The impact meets every contact to within its slack, and leaves some separating too
        // slowly to hop higher than a settling hop: those rest (the rule by which a ball
        // settles on a surface). The least change that makes no contact approach and none of
        // those separate (a projection onto a cone, which never adds kinetic energy) leaves
        // the contacts that stay touching exactly tangential, and enters nothing else.
        let rest = self.rest_speeds(cluster);
        let resting = resting_rows(cluster, velocities, &rest);
        // With friction, a resting contact also sticks if it slips no faster than it rests
        // at: such a slip is stopped now, as a bounce that slow is dropped
        // (`dynamics/contact_friction.rs`).
        let any_rough = self.any_rough(cluster);
        let stuck: Vec<usize> = if any_rough {
            let rubs = self.rubs(cluster, &resting, velocities);
            resting
                .iter()
                .zip(&rubs)
                .filter(|&(&k, rub)| rub.mu > 0.0 && rub.slip.abs() <= rest[k])
                .map(|(&k, _)| k)
                .collect()
        } else {
            Vec::new()
        };
        // Should rounding refuse the projection, the impact's velocities stand (they meet
        // every contact already).
        let (velocities, factored) = self
            .non_approaching(
                cluster,
                masses,
                velocities,
                speed,
                (&resting, &stuck),
                positions,
            )
            .unwrap_or_else(|| (velocities.to_vec(), None));
        self.hold_projected(cluster, masses, &velocities, (factored, known), speed);
    }

    /// [`Self::hold`] after its projection: `velocities` the projected ones, `factored` the
    /// projection's factorisation of the contacts it left touching, if it has one, and
    /// `known` the contacts that pushed when the groups of the cluster's balls were last
    /// solved ([`Self::pushed_before`]).
    fn hold_projected(
        &mut self,
        cluster: &Cluster,
        masses: &[f64],
        velocities: &[DVec2],
        (factored, known): (Option<Factored>, &[Pair]),
        speed: f64,
    ) {
        let g = self.gravity;
        let slack = JAM_SLACK_ULPS * f64::EPSILON;
        let tangential = tangential_within(speed);
        let any_rough = self.any_rough(cluster);
        // Active: tangential after that, to within its rounding. A contact left separating
        // faster carries no force: its ball hops off, and what it hops off decides afresh
        // when it comes back (a settle, a micro-hop).
        let mut active: Vec<usize> = (0..cluster.rows.len())
            .filter(|&k| cluster.rows[k].relative(velocities).abs() <= tangential)
            .collect();
        let rounding_a = 4.0 * (slack + 64.0 * f64::EPSILON) * g.length();
        // The group the solve over the contacts `active` would make (`factored`: the
        // projection's factorisation of them, to start from), and whether with friction.
        let decide = |active: &[usize], factored: Option<Factored>| -> (Option<Hold>, bool) {
            let rows: Vec<ContactRow> = active
                .iter()
                .map(|&k| ContactRow {
                    target: 0.0,
                    slack: slack * g.length(),
                    ..cluster.rows[k]
                })
                .collect();
            let gravity = vec![g; cluster.balls.len()];
            // With friction at any of those contacts, its forces too
            // (`dynamics/contact_friction.rs`): the sliding contacts slow, the others stick
            // while friction can hold them. Such a group keeps no contacts for a strike taken
            // as one body (its kinetic forces are its slips' at its formation), and lets go
            // when a slip would end.
            let rubs = if any_rough {
                self.rubs(cluster, active, velocities)
            } else {
                Vec::new()
            };
            let no_work = |h: &Hold| {
                h.members.is_empty()
                    || forces_do_no_work(
                        masses,
                        velocities,
                        &h.solved,
                        g,
                        (tangential, rounding_a),
                        h.lifetime,
                    )
            };
            // Accelerations the work check refuses, but none of them above `STILL` of
            // gravity's, are the rounding of a thin wedge's forces: the group is held still
            // instead, if that does no work either.
            let judged = |hold: Option<Hold>, rough: bool| {
                hold.and_then(|h| {
                    if no_work(&h) {
                        return Some(h);
                    }
                    let faint = |at: &usize| h.solved[*at].length() <= STILL * g.length();
                    if !h.members.iter().all(faint)
                        && !worse_than_still(masses, &h.solved, &h.members, g)
                    {
                        return None;
                    }
                    let mut still = h.solved.clone();
                    for &at in &h.members {
                        still[at] = DVec2::ZERO;
                    }
                    Some(self.group_of(cluster, &rows, active, velocities, still, rough))
                        .filter(no_work)
                })
            };
            // The group the solve would make: its members, the contacts that carry force
            // between them, and how long it would hold each. With friction first; should its
            // work check refuse it (a thin wedge's pinning forces times `mu` are kinetic
            // forces without bound: the contact would jam at once, an impulse no acceleration
            // gives), without.
            let mut rough = rubs.iter().any(|rub| rub.mu > 0.0);
            let mut hold = None;
            if rough {
                // A group held for less than the collapse floor would be formed again at once.
                let soon = COLLAPSE_FLOOR * self.time.seconds().abs().max(1.0);
                let solved = frictional_hold(masses, g, &rows, &rubs, tangential, soon);
                hold = judged(
                    solved.ok().map(|h| {
                        let mut hold = self.group_of(
                            cluster,
                            &rows,
                            active,
                            velocities,
                            h.accelerations,
                            true,
                        );
                        hold.end_slips(cluster, active, &h.slip_ends);
                        hold
                    }),
                    true,
                );
                rough = hold.is_some();
            }
            if !rough {
                // A big cluster whose groups' last solves say which of its contacts push
                // starts from those (`resolve_impact_guessed`, [`WARM_FROM`]); otherwise, or
                // where the Gram factor hands that back, the projection factorised the
                // contacts it left touching, and the accelerations' solve starts from there
                // (`resolve_impact_from`). Either way the same optimum, found without adding
                // the contacts one at a time again.
                let guessed = guess(cluster, active, known)
                    .and_then(|guess| resolve_impact_guessed(masses, &gravity, &rows, &guess));
                let solved = match (guessed, factored) {
                    (Some(answer), _) => Ok(answer),
                    (None, Some(factored)) => {
                        let mut position = vec![None; cluster.rows.len()];
                        for (i, &k) in active.iter().enumerate() {
                            position[k] = Some(i);
                        }
                        let start = factored.restate(|k| position[k]);
                        resolve_impact_from(masses, &gravity, &rows, start)
                    }
                    (None, None) => resolve_impact_with_impulses(masses, &gravity, &rows),
                };
                let (accelerations, impulses) =
                    solved.map_or((None, Vec::new()), |(x, impulses)| (Some(x), impulses));
                hold = judged(
                    accelerations.map(|accelerations| {
                        self.group_of(cluster, &rows, active, velocities, accelerations, false)
                    }),
                    false,
                );
                // What the group keeps for the next solve of its balls: its contacts that
                // pushed (read only with sleeping on, `pushed_before`).
                if let Some(h) = hold.as_mut().filter(|_| self.resting()) {
                    let mut pushing: Vec<Pair> = (active.iter().zip(&impulses))
                        .filter(|&(&k, &l)| {
                            let row = &cluster.rows[k];
                            l > 0.0 && h.held[row.a] && row.b.is_none_or(|b| h.held[b])
                        })
                        .map(|(&k, _)| cluster.pairs[k])
                        .collect();
                    pushing.sort_unstable();
                    h.pushing = pushing;
                }
            }
            (hold, rough)
        };
        let (mut hold, mut rough) = decide(&active, factored);
        // A ball the solve pressed onto a point or a circle alone, that the point cannot
        // hold (it passes it faster than it curves away: `Touch::holds`), takes no force
        // there: the programme's rows ask a contact's relative normal acceleration to be at
        // least zero, where about a point the gap's is `a.n + |v_t|^2 / reach`. Solved
        // again without those contacts (left to the kernels, which follow the curve exactly),
        // the balls it touches may press on it instead: a ball sliding down a ramp into a
        // ball flying off a peg was left unheld, pulled together with it and closed, and met
        // it every 3e-5 s, each time 15 ulps deeper (plain hunt seed 13246915). Kept only if
        // each such ball then leaves its point.
        let passing = hold
            .as_ref()
            .map(|h| self.passing_points(cluster, &active, h, velocities))
            .unwrap_or_default();
        if !passing.is_empty() {
            let fewer: Vec<usize> = active
                .iter()
                .copied()
                .filter(|k| !passing.contains(k))
                .collect();
            let (again, rough_again) = decide(&fewer, None);
            if let Some(again) =
                again.filter(|h| self.all_leave(cluster, &passing, &h.solved, velocities))
            {
                (hold, rough, active) = (Some(again), rough_again, fewer);
            }
        }
        let Some(Hold {
            accelerations,
            held,
            held_rows,
            members,
            until,
            pushing,
            ..
        }) = hold
        else {
            // Rounding refused the solve (it meets a set it could not verify), or its forces
            // would work on the balls: no ball is held by another, but each that a surface
            // holds rests on it.
            for (at, &ball) in cluster.balls.iter().enumerate() {
                if let Some(first) = self.holding_row(cluster, at, ball) {
                    if self.settle(ball, first) {
                        self.counts.settles += 1;
                    }
                }
            }
            return;
        };
        for (at, &ball) in cluster.balls.iter().enumerate() {
            if !held[at] && constrained(accelerations[at], g) {
                if let Some(first) = self.holding_row(cluster, at, ball) {
                    if self.settle(ball, first) {
                        self.counts.settles += 1;
                    }
                }
            }
        }
        if members.is_empty() {
            return;
        }
        let pairs = held_rows.iter().map(|&k| cluster.pairs[k]).collect();
        // What the group keeps for a hit (`pipeline/rigid.rs`): every active contact among its
        // members and of its members with colliders; nothing with friction (its kinetic forces
        // are its slips' at its formation, which a strike changes).
        let kept = (!rough).then(|| {
            let mut local = vec![usize::MAX; cluster.balls.len()];
            for (i, &at) in members.iter().enumerate() {
                local[at] = i;
            }
            let kept_rows: Vec<usize> = active
                .iter()
                .copied()
                .filter(|&k| {
                    let row = &cluster.rows[k];
                    held[row.a] && row.b.is_none_or(|b| held[b])
                })
                .collect();
            Box::new(Kept::new(
                members.iter().map(|&at| cluster.balls[at]).collect(),
                members.iter().map(|&at| masses[at]).collect(),
                kept_rows
                    .iter()
                    .map(|&k| {
                        let row = cluster.rows[k];
                        ContactRow {
                            a: local[row.a],
                            b: row.b.map(|b| local[b]),
                            target: 0.0,
                            slack: 0.0,
                            ..row
                        }
                    })
                    .collect(),
                kept_rows.iter().map(|&k| cluster.pairs[k]).collect(),
                kept_rows.iter().map(|&k| cluster.reaches[k]).collect(),
            ))
        });
        let group = self.new_group(
            members.iter().map(|&at| cluster.balls[at]).collect(),
            pairs,
            kept,
            pushing,
        );
        // Each member's active contacts with colliders, in the order of `active`: gathered in
        // one pass over them (a pass for each member was a cluster's members times its
        // contacts, 2.4 % of a drop-and-merge box's instructions).
        let mut touching: Vec<(usize, ColliderHandle)> = active
            .iter()
            .filter(|&&k| held[cluster.rows[k].a] && cluster.rows[k].b.is_none())
            .filter_map(|&k| match cluster.pairs[k] {
                Pair::Collider(_, slot) => {
                    self.colliders.at(slot).map(|(h, _)| (cluster.rows[k].a, h))
                }
                Pair::Balls(..) => None,
            })
            .collect();
        // A stable sort: each member's contacts keep their order.
        touching.sort_by_key(|&(at, _)| at);
        let mut from = 0;
        for &at in &members {
            let ball = cluster.balls[at];
            let to = from + touching[from..].partition_point(|&(a, _)| a <= at);
            let mine = touching[from..to].iter().map(|&(_, h)| h).collect();
            from = to;
            self.hold_member(ball, accelerations[at], (group, until[at]), mine);
        }
        // A group at rest sleeps whole (`pipeline/sleep.rs`).
        self.try_sleep_group(group);
    }

    /// The contacts that pushed when the groups holding the cluster's balls were last solved
    /// (sorted), for a cluster of [`WARM_FROM`] balls and more with sleeping on (none
    /// otherwise): read before the jam lets those groups go.
    fn pushed_before(&self, cluster: &Cluster) -> Vec<Pair> {
        if !self.resting() || cluster.balls.len() < WARM_FROM {
            return Vec::new();
        }
        let mut groups: Vec<u32> = (cluster.balls.iter())
            .filter_map(|&b| self.held_group(b))
            .collect();
        groups.sort_unstable();
        groups.dedup();
        let mut known = Vec::new();
        for group in &self.groups {
            if groups.binary_search(&group.id).is_ok() {
                known.extend_from_slice(&group.pushing);
            }
        }
        known.sort_unstable();
        known.dedup();
        known
    }

    /// The contacts of `active` (rows of the cluster) of a ball that `hold` presses onto a
    /// point or a circle alone (its acceleration not gravity's, no other ball held with it)
    /// while it touches another ball, where gravity presses it onto the point but, with the
    /// gap's curvature, does not pull it in ([`pulls`]: the ball passes the point faster than
    /// the point's surface curves away): see [`Self::hold`].
    fn passing_points(
        &self,
        cluster: &Cluster,
        active: &[usize],
        hold: &Hold,
        velocities: &[DVec2],
    ) -> Vec<usize> {
        let g = self.gravity;
        let pressed = |at: usize| {
            !hold.held[at]
                && constrained(hold.accelerations[at], g)
                && active.iter().any(|&k| {
                    cluster.rows[k]
                        .b
                        .is_some_and(|b| b == at || cluster.rows[k].a == at)
                })
        };
        active
            .iter()
            .copied()
            .filter(|&k| {
                let row = &cluster.rows[k];
                row.b.is_none()
                    && pressed(row.a)
                    && self.point_touch(cluster, k).is_some_and(|touch| {
                        g.dot(touch.normal) < -PARALLEL * g.length()
                            && !pulls(&touch, velocities[row.a], g)
                    })
            })
            .collect()
    }

    /// Whether each ball of the contacts `rows` (of the cluster, each with a point or a
    /// circle) leaves that point under the accelerations `solved` ([`pulls`]).
    fn all_leave(
        &self,
        cluster: &Cluster,
        rows: &[usize],
        solved: &[DVec2],
        velocities: &[DVec2],
    ) -> bool {
        rows.iter().all(|&k| {
            let at = cluster.rows[k].a;
            self.point_touch(cluster, k)
                .is_some_and(|touch| !pulls(&touch, velocities[at], solved[at]))
        })
    }

    /// Contact `k` of the cluster, a ball's with a collider, as the ball touches it now, if
    /// what it touches there is a point or a circle (not a segment's interior).
    fn point_touch(&self, cluster: &Cluster, k: usize) -> Option<Touch> {
        let Pair::Collider(_, slot) = cluster.pairs[k] else {
            return None;
        };
        let (_, collider) = self.colliders.at(slot)?;
        let record = self.balls.kinematics(cluster.balls[cluster.rows[k].a])?;
        let touch = Touch::of(&collider.shape, record.trajectory.p0, record.radius)?;
        touch.point.is_some().then_some(touch)
    }

    /// The group the hold's solved `accelerations` of the cluster's active contacts `rows`
    /// (rows `active` of the cluster) would make, computed without changing anything: a
    /// contact between two balls carries force only if it is tight (their relative normal
    /// acceleration zero) and one of them at least is not in free fall, and then both are
    /// held, together (a ball pressed sideways between a ball it holds up and a wall falls
    /// freely, and still holds the first where it is); a member pulled no harder than the
    /// rounding of gravity is not pulled at all (so a group at rest stays where it is); each
    /// member is held until [`Self::held_until`], and the group as long as the first of them.
    fn group_of(
        &self,
        cluster: &Cluster,
        rows: &[ContactRow],
        active: &[usize],
        velocities: &[DVec2],
        mut accelerations: Vec<DVec2>,
        rough: bool,
    ) -> Hold {
        let g = self.gravity;
        let held_up = |at: usize| constrained(accelerations[at], g);
        let tight = |row: &ContactRow| row.relative(&accelerations).abs() <= PARALLEL * g.length();
        let mut held = vec![false; cluster.balls.len()];
        let mut held_rows = Vec::new();
        for (k, row) in rows.iter().enumerate() {
            if let Some(b) = row.b {
                if (held_up(row.a) || held_up(b)) && tight(row) {
                    held[row.a] = true;
                    held[b] = true;
                    held_rows.push(active[k]);
                }
            }
        }
        // With friction every ball the solve constrains is held: a ball alone on a surface
        // beside the group would otherwise rest on it by the rules of a ball alone
        // (`dynamics/rolling.rs`: rolling, and frictionless while it presses a ball), not the
        // friction the group's solve gave it, and the two meet again at once.
        if rough {
            for (at, held) in held.iter_mut().enumerate() {
                *held |= held_up(at);
            }
        }
        let members: Vec<usize> = (0..cluster.balls.len()).filter(|&at| held[at]).collect();
        let solved = accelerations.clone();
        for &at in &members {
            if accelerations[at].length() <= PARALLEL * g.length() {
                accelerations[at] = DVec2::ZERO;
            }
        }
        let mut until = vec![f64::INFINITY; cluster.balls.len()];
        let rows_of = RowsOf::new(cluster, active);
        for &at in &members {
            let mine = rows_of.of(at);
            until[at] = self.held_until(cluster, mine, at, velocities, &accelerations, false);
        }
        let lifetime = members
            .iter()
            .map(|&at| until[at])
            .fold(f64::INFINITY, f64::min);
        Hold {
            accelerations,
            solved,
            held,
            held_rows,
            members,
            until,
            lifetime,
            pushing: Vec::new(),
        }
    }

    /// The velocities `velocities` of the cluster's balls changed least (in kinetic energy)
    /// so that no contact of the cluster approaches (the impact's own programme, every target
    /// zero) and, of `(resting, stuck)`, none of the contacts `resting` separates and none
    /// of the contacts `stuck` slips (they are the programme's equalities,
    /// `resolve_with_equalities_factored`), written into their trajectories (which start
    /// now), with the factorisation of the contacts it ended meeting exactly (indices of the
    /// cluster's rows) if none is stuck; `None`, nothing written, should rounding refuse the
    /// solve. Every row is met by zero velocities, so the projection never adds kinetic
    /// energy. Its impulses (the balls at `positions`) go to the observables.
    fn non_approaching(
        &mut self,
        cluster: &Cluster,
        masses: &[f64],
        velocities: &[DVec2],
        speed: f64,
        (resting, stuck): (&[usize], &[usize]),
        positions: &[DVec2],
    ) -> Option<(Vec<DVec2>, Option<Factored>)> {
        let Projection {
            velocities,
            factored,
            impulses,
        } = self.projection(cluster, masses, velocities, speed, (resting, stuck))?;
        for (&ball, &v) in cluster.balls.iter().zip(&velocities) {
            let record = self.balls.kinematics_mut(ball).expect("live ball");
            record.trajectory.v0 = v;
        }
        self.note_rows(&cluster.rows, &cluster.pairs, positions, &impulses);
        Some((velocities, factored))
    }

    /// [`Self::non_approaching`]'s solve alone: nothing is written.
    fn projection(
        &self,
        cluster: &Cluster,
        masses: &[f64],
        velocities: &[DVec2],
        speed: f64,
        (resting, stuck): (&[usize], &[usize]),
    ) -> Option<Projection> {
        let slack = JAM_SLACK_ULPS * f64::EPSILON * speed;
        let zero = |row: &ContactRow| ContactRow {
            target: 0.0,
            slack,
            ..*row
        };
        let mut is_resting = vec![false; cluster.rows.len()];
        for &k in resting {
            is_resting[k] = true;
        }
        // The stuck contacts' tangents come after the resting normals.
        let equalities: Vec<ContactRow> = resting
            .iter()
            .map(|&k| zero(&cluster.rows[k]))
            .chain(stuck.iter().map(|&k| zero(&cluster.rows[k]).tangent()))
            .collect();
        let others: Vec<usize> = (0..cluster.rows.len())
            .filter(|&k| !is_resting[k])
            .collect();
        let inequalities: Vec<ContactRow> =
            others.iter().map(|&k| zero(&cluster.rows[k])).collect();
        let r = resolve_with_equalities_factored(masses, velocities, &equalities, &inequalities);
        let (projected, factored, impulses) = r.ok()?;
        // The factorisation's contacts, as rows of the cluster (a stuck contact's tangent is
        // none: its impulse is not along the contact's normal).
        let row = |k: usize| {
            if k < resting.len() {
                Some(resting[k])
            } else if k < resting.len() + stuck.len() {
                None
            } else {
                Some(others[k - resting.len() - stuck.len()])
            }
        };
        let mut each = vec![0.0; cluster.rows.len()];
        for (k, &l) in impulses.iter().enumerate() {
            if let Some(at) = row(k) {
                each[at] = l;
            }
        }
        // With friction the accelerations' solve starts afresh.
        let factored = stuck.is_empty().then(|| {
            factored.restated(|k| {
                if k < resting.len() {
                    resting[k]
                } else {
                    others[k - resting.len()]
                }
            })
        });
        Some(Projection {
            velocities: projected,
            factored,
            impulses: each,
        })
    }

    /// For each contact of the cluster, the separation speed below which its bounce would be
    /// no higher than a settling hop ([`SETTLE_HEIGHT`] of its coordinate scale, under the
    /// full pull of gravity): the rule by which a ball settles on a surface (see
    /// [`Touch::holds`]). The hold asks such a contact to stay touching instead, so that a
    /// ball knocked against a ball wedged in a spout comes to rest there with it, rather than
    /// bounce off it again and again by less than the rounding of its position.
    ///
    /// With sleeping on, a contact also rests if it separates no faster than the slower of its
    /// balls would sleep at ([`sleep_speed`]): the bounce of a resting pair is dropped as a
    /// sleeping ball's speed is.
    pub(super) fn rest_speeds(&self, cluster: &Cluster) -> Vec<f64> {
        let coordinates = |at: usize| {
            let record = self.balls.kinematics(cluster.balls[at]).expect("live ball");
            record.trajectory.p0.abs().max_element()
        };
        let radius = |at: usize| {
            self.balls
                .kinematics(cluster.balls[at])
                .expect("live")
                .radius
        };
        cluster
            .rows
            .iter()
            .zip(&cluster.reaches)
            .map(|(row, &reach)| {
                let c = row.b.map_or(coordinates(row.a), |b| {
                    coordinates(row.a).max(coordinates(b))
                });
                let r = row
                    .b
                    .map_or(radius(row.a), |b| radius(row.a).min(radius(b)));
                self.rest_speed_at(c, reach, r)
            })
            .collect()
    }

    /// The separation speed at or below which a contact rests: a bounce no higher than a
    /// settling hop ([`SETTLE_HEIGHT`] of its coordinate scale, `coordinates + reach`, under
    /// gravity's full pull), and with sleeping on no faster than a ball of `radius` (the
    /// smaller of the two) sleeps.
    pub(super) fn rest_speed_at(&self, coordinates: f64, reach: f64, radius: f64) -> f64 {
        let g = self.gravity.length();
        let hop = (2.0 * g * SETTLE_HEIGHT * (coordinates + reach)).sqrt();
        if self.resting() {
            hop.max(sleep_speed(g, radius))
        } else {
            hop
        }
    }

    /// How long group member `at` may be held (see `pipeline/group.rs`): until its centre
    /// leaves a segment it is held against, or it could have slid the touching distance away
    /// from a ball or a point it is held against, over the contacts `active` (rows of the
    /// cluster; those not of `at` are passed over, so its own alone, [`RowsOf`], suffice).
    ///
    /// With `slid`, the members have moved since their contacts were found (the group's
    /// formation): what each has slid across a contact's normal, `sqrt(|d|^2 - reach^2)` for a
    /// distance `|d|` now, is taken from the distance it may slide.
    pub(super) fn held_until(
        &self,
        cluster: &Cluster,
        active: &[usize],
        at: usize,
        velocities: &[DVec2],
        accelerations: &[DVec2],
        slid: bool,
    ) -> f64 {
        let ball = cluster.balls[at];
        let record = self.balls.kinematics(ball).expect("live ball");
        let (p, r) = (record.trajectory.p0, record.radius);
        let mut until = f64::INFINITY;
        for &k in active {
            let row = &cluster.rows[k];
            let other = match row.b {
                Some(b) if row.a == at => Some(b),
                Some(b) if b == at => Some(row.a),
                None if row.a == at => None,
                _ => continue,
            };
            let (dv, da, reach, apart) = match other {
                Some(o) => {
                    let partner = self.balls.kinematics(cluster.balls[o]).expect("live");
                    let dv = velocities[o] - velocities[at];
                    let reach = r + partner.radius;
                    let apart = partner.trajectory.p0.distance(p);
                    (dv, accelerations[o] - accelerations[at], reach, apart)
                }
                None => {
                    let Pair::Collider(_, slot) = cluster.pairs[k] else {
                        continue;
                    };
                    let Some((_, collider)) = self.colliders.at(slot) else {
                        continue;
                    };
                    let Some(touch) = Touch::of(&collider.shape, p, r) else {
                        continue;
                    };
                    if let (Shape::Segment(s), None) = (&collider.shape, touch.point) {
                        let line = Support::on_segment(
                            NO_COLLIDER,
                            s.a(),
                            s.b(),
                            touch.normal,
                            r,
                            DVec2::ZERO,
                        );
                        let motion = Motion {
                            position: p,
                            velocity: velocities[at],
                            acceleration: accelerations[at],
                        };
                        until = until.min(line.leave_time(&motion).unwrap_or(f64::INFINITY));
                        continue;
                    }
                    let apart = touch.point.map_or(0.0, |(q, _)| q.distance(p));
                    (velocities[at], accelerations[at], touch.reach(r), apart)
                }
            };
            let height = if self.resting() {
                GROUP_GAP * reach
            } else {
                SETTLE_HEIGHT * (p.abs().max_element() + reach)
            };
            let mut distance = (2.0 * reach * height).sqrt();
            if slid {
                distance -= (apart * apart - reach * reach).max(0.0).sqrt();
                if !(distance > 0.0) {
                    return 0.0;
                }
            }
            until = until.min(sliding_time(dv.length(), da.length(), distance));
        }
        until.min(self.sinking_until(cluster, active, at, velocities, accelerations))
    }

    /// How long group member `at` may be held before the rounding left in its velocity and
    /// acceleration could take it a quarter of the touching distance into what it is held
    /// against (an active contact's relative normal velocity is zero only to within the
    /// solves' slack): from `|u| t + |a| t^2 / 2` for the approaching parts of each.
    pub(super) fn sinking_until(
        &self,
        cluster: &Cluster,
        active: &[usize],
        at: usize,
        velocities: &[DVec2],
        accelerations: &[DVec2],
    ) -> f64 {
        let coordinates = |at: usize| {
            let record = self.balls.kinematics(cluster.balls[at]).expect("live ball");
            record.trajectory.p0.abs().max_element()
        };
        let mut until = f64::INFINITY;
        for &k in active {
            let row = &cluster.rows[k];
            if row.a != at && row.b != Some(at) {
                continue;
            }
            let u = row.relative(velocities);
            let a = row.relative(accelerations);
            let c = row.b.map_or(coordinates(row.a), |b| {
                coordinates(row.a).max(coordinates(b))
            });
            let margin = 0.25 * SETTLE_HEIGHT * (c + cluster.reaches[k]);
            until = until.min(sliding_time((-u).max(0.0), (-a).max(0.0), margin));
        }
        until
    }

    /// The first collider of the cluster that holds ball `ball` (cluster index `at`) at rest
    /// with its velocity now (see [`Touch::holds`]), if any.
    fn holding_row(&self, cluster: &Cluster, at: usize, ball: u32) -> Option<ColliderHandle> {
        let record = self.balls.kinematics(ball)?;
        let (p, v) = (record.trajectory.p0, record.trajectory.v0);
        cluster
            .rows
            .iter()
            .zip(&cluster.pairs)
            .filter(|(row, _)| row.a == at && row.b.is_none())
            .find_map(|(_, pair)| {
                let Pair::Collider(_, slot) = *pair else {
                    return None;
                };
                let (handle, collider) = self.colliders.at(slot)?;
                let touch = Touch::of(&collider.shape, p, record.radius)?;
                // Touched by the rule the cluster found it by (a sleeping ball's circle as far
                // as two balls touch): a ball the hold rests on such a circle 2.5e-10 above it,
                // beyond a settling hop, flew instead, fell into the ball beside it, and met
                // it every 8e-8 s a rounding deeper (plain hunt seed 15046218).
                let g = self.gravity;
                (self.touches_collider_at(slot, &touch, p, record.radius)
                    && touch.pulled_in(p, v, g, record.radius, PARALLEL * g.length()))
                .then_some(handle)
            })
    }

    /// Ball `index`'s position now.
    pub(crate) fn position_now(&self, index: u32) -> DVec2 {
        let record = self.balls.kinematics(index).expect("live ball");
        record
            .trajectory
            .position_at(self.time, self.acceleration(index))
    }

    /// Ball `index`'s velocity now.
    pub(crate) fn velocity_now(&self, index: u32) -> DVec2 {
        let record = self.balls.kinematics(index).expect("live ball");
        record
            .trajectory
            .velocity_at(self.time, self.acceleration(index))
    }

    /// The balls connected to `seed` through contacts that touch now, and those contacts
    /// (balls in order of discovery, their colliders and neighbours in slot order).
    fn cluster(&mut self, seed: &[u32]) -> Cluster {
        let mut slots = std::mem::take(&mut self.cluster_slots);
        let cluster = self.find_cluster(seed, &mut slots);
        self.cluster_slots = slots;
        cluster
    }

    /// [`Self::cluster`], with `slots` each ball slot's index in the cluster (`u32::MAX` for
    /// none), left as it came: every entry `u32::MAX`.
    fn find_cluster(&self, seed: &[u32], slots: &mut Vec<u32>) -> Cluster {
        let mut cluster = Cluster {
            balls: seed.to_vec(),
            pairs: Vec::new(),
            rows: Vec::new(),
            restitutions: Vec::new(),
            reaches: Vec::new(),
        };
        if slots.len() < self.balls.slot_count() {
            slots.resize(self.balls.slot_count(), u32::MAX);
        }
        for (at, &ball) in seed.iter().enumerate() {
            slots[ball as usize] = at as u32;
        }
        // Where each ball's contacts start among the rows: a ball's are found together, when
        // it is reached (a pair of balls when the first of the two is), so whether a pair
        // was found already is a search of the earlier ball's few rows. (Sets of the pairs
        // found and of the balls' indices, searched for every ball near each, were 4 % of
        // the instructions of a Galton board's funnel, callgrind.)
        let mut starts = Vec::with_capacity(seed.len() + 32);
        // Each ball's candidates in turn: room for the balls of a packed 3 x 3 block of cells,
        // so that it rarely grows.
        let mut near = Vec::with_capacity(32);
        let mut next = 0;
        while next < cluster.balls.len() {
            let ball = cluster.balls[next];
            starts.push(cluster.rows.len());
            self.add_collider_contacts(&mut cluster, next, ball);
            self.add_ball_contacts(&mut cluster, (slots, &starts, &mut near), next, ball);
            next += 1;
        }
        for &ball in &cluster.balls {
            slots[ball as usize] = u32::MAX;
        }
        cluster
    }

    /// Adds the solid colliders that ball `ball` (cluster index `at`) touches now (those a
    /// settle would count: see [`World::touched_colliders`]).
    fn add_collider_contacts(&self, cluster: &mut Cluster, at: usize, ball: u32) {
        let (Some(record), Some((_, restitution))) = (
            self.balls.kinematics(ball),
            self.balls.mass_and_restitution(ball),
        ) else {
            return;
        };
        let p = record
            .trajectory
            .position_at(self.time, self.acceleration(ball));
        let first = cluster.rows.len();
        for (handle, collider, touch) in self.touched_colliders(ball, p, record.radius, NO_COLLIDER)
        {
            cluster.pairs.push(Pair::Collider(ball, handle.index));
            cluster.rows.push(ContactRow {
                a: at,
                b: None,
                normal: touch.normal,
                target: 0.0,
                slack: 0.0,
            });
            cluster
                .restitutions
                .push(restitution * collider.restitution);
            cluster.reaches.push(touch.reach(record.radius));
        }
        exact_fit_walls(&mut cluster.rows[first..]);
    }

    /// Whether balls `a` and `b`, `gap` apart (contact distance `reach`), are *fellows*: with
    /// sleeping on, members of one group no further apart than the group lets its members
    /// slide ([`GROUP_GAP`] of their contact distance). A jam takes them as touching, as
    /// their group did: a member a jam left out of its cluster (slid a hair away from it)
    /// was let go with its group, fell, and landed on the cluster's new groups some 1e-6 to
    /// 1e-4 s later, slower than a ball sleeps: another jam of the whole cluster (11,524 of the
    /// 22,982 slow strikes of free balls on groups in the rough 200-ball pile to t = 1.9).
    pub(super) fn fellows(&self, a: u32, b: u32, gap: f64, reach: f64) -> bool {
        self.resting()
            && gap <= GROUP_GAP * reach
            && self
                .held_group(a)
                .is_some_and(|group| self.held_group(b) == Some(group))
    }

    /// Adds the balls that ball `ball` (cluster index `at`) touches now (or whose fellow it
    /// is, [`World::fellows`]), and their contacts.
    fn add_ball_contacts(
        &self,
        cluster: &mut Cluster,
        (slots, starts, near): (&mut [u32], &[usize], &mut Vec<(u32, DVec2)>),
        at: usize,
        ball: u32,
    ) {
        let (Some(record), Some(properties)) =
            (self.balls.kinematics(ball), self.balls.properties(ball))
        else {
            return;
        };
        let p = record
            .trajectory
            .position_at(self.time, self.acceleration(ball));
        near.clear();
        self.grid
            .near(ball, |other, shift| near.push((other, shift)));
        near.sort_unstable_by_key(|&(other, _)| other);
        near.dedup_by_key(|&mut (other, _)| other);
        for &(other, shift) in near.iter() {
            // Found already from `other`, reached before this ball: among its rows.
            let seen = slots[other as usize] as usize;
            if seen < at
                && cluster.rows[starts[seen]..starts[seen + 1]]
                    .iter()
                    .any(|row| row.b == Some(at))
            {
                continue;
            }
            let (Some(partner), Some(theirs)) =
                (self.balls.kinematics(other), self.balls.properties(other))
            else {
                continue;
            };
            if !properties.groups.interact(theirs.groups) {
                continue;
            }
            let q = partner
                .trajectory
                .position_at(self.time, self.acceleration(other))
                + shift;
            let reach = record.radius + partner.radius;
            let d = q - p;
            let length = d.length();
            let coordinates = p.abs().max_element().max(q.abs().max_element());
            if !(length > 0.0)
                || !(balls_touch(length - reach, coordinates, reach)
                    || self.fellows(ball, other, length - reach, reach))
            {
                continue;
            }
            let to = if seen == u32::MAX as usize {
                cluster.balls.push(other);
                slots[other as usize] = (cluster.balls.len() - 1) as u32;
                cluster.balls.len() - 1
            } else {
                seen
            };
            cluster.pairs.push(Pair::balls(ball, other));
            cluster.rows.push(ContactRow {
                a: at,
                b: Some(to),
                normal: d / length,
                target: 0.0,
                slack: 0.0,
            });
            let restitution = |ball| self.balls.mass_and_restitution(ball).expect("live ball").1;
            cluster
                .restitutions
                .push(restitution(ball) * restitution(other));
            cluster.reaches.push(reach);
        }
    }
}

/// Each ball's share of some of a cluster's contacts: the contacts that involve it, in
/// their order there (one pass over them, where a pass over all of them for each ball made
/// [`World::held_until`] a cluster's members times its contacts).
pub(super) struct RowsOf {
    /// Where each ball's contacts start in `rows` (and, one on, end).
    start: Vec<usize>,
    rows: Vec<usize>,
}

impl RowsOf {
    /// The contacts `rows` (indices of the cluster's) of each of the cluster's balls.
    pub(super) fn new(cluster: &Cluster, rows: &[usize]) -> Self {
        let balls = cluster.balls.len();
        let mut start = vec![0; balls + 1];
        for &k in rows {
            let row = &cluster.rows[k];
            start[row.a + 1] += 1;
            if let Some(b) = row.b {
                start[b + 1] += 1;
            }
        }
        for at in 0..balls {
            start[at + 1] += start[at];
        }
        let mut next = start.clone();
        let mut list = vec![0; start[balls]];
        let mut put = |at: usize, k: usize| {
            list[next[at]] = k;
            next[at] += 1;
        };
        for &k in rows {
            let row = &cluster.rows[k];
            put(row.a, k);
            if let Some(b) = row.b {
                put(b, k);
            }
        }
        Self { start, rows: list }
    }

    /// Ball `at`'s contacts.
    pub(super) fn of(&self, at: usize) -> &[usize] {
        &self.rows[self.start[at]..self.start[at + 1]]
    }
}

/// The velocities after the cluster's impact, from `start`, the velocities before the
/// instant's first response (see the module documentation), with `now` those the responses
/// in sequence have left: each contact separating at its restitution times its approach;
/// else perfectly plastic; and never with more kinetic energy than either. Should that fail
/// (the sequence already took more energy than the impact would), the plastic impact from
/// `now` (a projection of `now`, with no more energy); should rounding refuse even that,
/// every ball stops.
///
/// With the velocities, each contact's impulse and whether it is reckoned from `start`
/// (`true`) or from `now`; none if every ball stopped (that stop's impulses are not known,
/// and the observables do not count it).
fn impact(
    masses: &[f64],
    start: &[DVec2],
    now: &[DVec2],
    cluster: &Cluster,
    mus: &[f64],
) -> (Vec<DVec2>, Option<(Vec<f64>, bool)>) {
    let mut rows = cluster.rows.clone();
    let speed = fastest(start, now);
    for (row, e) in rows.iter_mut().zip(&cluster.restitutions) {
        let u = row.relative(start);
        row.target = e * (-u).max(0.0);
        row.slack = JAM_SLACK_ULPS * f64::EPSILON * speed;
    }
    let limit = kinetic(masses, start).min(kinetic(masses, now));
    let within = |(v, _): &(Vec<DVec2>, Vec<f64>)| kinetic(masses, v) <= limit;
    let from_start = |(v, l): (Vec<DVec2>, Vec<f64>)| (v, Some((l, true)));
    let plastic = |rows: &[ContactRow]| {
        let mut rows = rows.to_vec();
        for row in &mut rows {
            row.target = 0.0;
        }
        rows
    };
    // With friction (`dynamics/impact_friction.rs`): its impulses are the normal ones, then
    // the tangential ones. Should neither of its impacts pass, the frictionless ones are
    // tried as without friction.
    if mus.iter().any(|&mu| mu > 0.0) {
        let rough = |rows: &[ContactRow]| {
            resolve_frictional_impact(masses, start, rows, mus)
                .ok()
                .map(|hit| {
                    let mut impulses = hit.normal;
                    impulses.extend(hit.tangential);
                    (hit.velocities, impulses)
                })
                .filter(within)
        };
        if let Some(answer) = rough(&rows).or_else(|| rough(&plastic(&rows))) {
            return from_start(answer);
        }
    }
    if let Some(answer) = resolve_impact_with_impulses(masses, start, &rows)
        .ok()
        .filter(within)
    {
        return from_start(answer);
    }
    let rows = plastic(&rows);
    resolve_impact_with_impulses(masses, start, &rows)
        .ok()
        .filter(within)
        .map(from_start)
        .or_else(|| {
            resolve_impact_with_impulses(masses, now, &rows)
                .ok()
                .map(|(v, l)| (v, Some((l, false))))
        })
        .unwrap_or_else(|| (vec![DVec2::ZERO; start.len()], None))
}

/// The guess a hold's accelerations over the cluster's contacts `active` start from
/// ([`WARM_FROM`]): the positions in `active` of the contacts `known` (sorted;
/// [`World::pushed_before`], none below `WARM_FROM` balls) says pushed at their last solve,
/// if they are at least half of them.
fn guess(cluster: &Cluster, active: &[usize], known: &[Pair]) -> Option<Vec<usize>> {
    if known.is_empty() {
        return None;
    }
    let guess: Vec<usize> = (0..active.len())
        .filter(|&i| known.binary_search(&cluster.pairs[active[i]]).is_ok())
        .collect();
    (2 * guess.len() >= active.len()).then_some(guess)
}

/// The fastest speed among the velocities `a` and `b`: the scale of a jam's rounding.
fn fastest(a: &[DVec2], b: &[DVec2]) -> f64 {
    a.iter().chain(b).fold(0.0_f64, |s, v| s.max(v.length()))
}

/// The contacts of `cluster` that rest at the velocities `v`: those separating no faster than
/// their rest speeds `rest` ([`World::rest_speeds`]), the approaching ones among them.
fn resting_rows(cluster: &Cluster, v: &[DVec2], rest: &[f64]) -> Vec<usize> {
    (0..cluster.rows.len())
        .filter(|&k| cluster.rows[k].relative(v) <= rest[k])
        .collect()
}

/// How near zero a contact's relative normal velocity counts as tangential after a jam's
/// solves at speeds up to `speed`: four times their slack and 64 ulps of the speed.
fn tangential_within(speed: f64) -> f64 {
    4.0 * (JAM_SLACK_ULPS * f64::EPSILON + 64.0 * f64::EPSILON) * speed
}

/// The kinetic energy of balls of `masses` at velocities `v`.
fn kinetic(masses: &[f64], v: &[DVec2]) -> f64 {
    v.iter()
        .zip(masses)
        .map(|(v, m)| 0.5 * m * v.length_squared())
        .sum()
}

/// Whether a ball touching a point or a circle (`touch`) at velocity `v` and acceleration `a`
/// is pulled into it: the gap's second derivative ([`Touch::pull`]) below the rounding of the
/// acceleration's direction ([`PARALLEL`] of it), as [`Touch::holds`] has it for a pivot.
fn pulls(touch: &Touch, v: DVec2, a: DVec2) -> bool {
    touch.pull(v, a) < -PARALLEL * a.length()
}

/// Whether a ball whose solved acceleration is `acceleration` is held by something: it differs
/// from gravity `g` by more than the rounding of its direction ([`PARALLEL`] of it).
fn constrained(acceleration: DVec2, g: DVec2) -> bool {
    (acceleration - g).length() > PARALLEL * g.length()
}

/// The earliest time by which two bodies whose relative motion across their contact is
/// `dv t + da t^2 / 2` (speeds `|dv|`, `|da|`) may have slid `distance` apart: the positive
/// root of `|da| t^2 / 2 + |dv| t = distance`, in the form that does not cancel; infinite if
/// they do not move.
fn sliding_time(dv: f64, da: f64, distance: f64) -> f64 {
    let root = (dv * dv + 2.0 * da * distance).sqrt();
    let t = 2.0 * distance / (dv + root);
    if t.is_nan() { f64::INFINITY } else { t }
}

/// Whether held accelerations `accelerations` of balls of `masses` moving at `velocities`
/// under gravity `g` leave the energy as it is while the group holds, `lifetime`: the work of
/// the contact forces over it, at most [`PARALLEL`] of the work gravity's own scale does over
/// it, plus what gravity does at `rounding`, the speed and the acceleration below which a
/// contact's counts as tangential.
///
/// The forces' power at `t` is `P + G t`, with `P = sum_i m_i (a_i - g) . v_i` and
/// `G = sum_i m_i (a_i - g) . a_i` (the velocities are `v + a t`); over `T` they do
/// `P T + G T^2 / 2`, against gravity's scale `S T + S_a T^2 / 2`, `S = sum_i m_i |g| |v_i|`
/// and `S_a = sum_i m_i |g| |a_i|`. So the check is `P + G T / 2 <= PARALLEL (S + S_a T / 2)`
/// plus the floors; a group that holds for ever must have `P` and `G` each within theirs.
///
/// In exact arithmetic `P` and `G` are zero: each force acts along a normal across which the
/// relative velocity and acceleration are zero (`pipeline/group.rs`). A thin wedge breaks
/// that to rounding: two walls of an exact-fit channel whose normals are opposite but for
/// 4e-14 radians pin a ball with forces of 1e13 times its weight, and those forces times the
/// rounding of its normal velocities held it still against gravity while it slid up the
/// channel at a constant speed, gaining the height it climbed (hunt seed 8216606). Three balls
/// stopped dead in such a channel tilted at 60 degrees (hunt seed 8289229) had no velocity
/// for the forces to work on, but the same rounding gave them an acceleration up the channel
/// of 6e-4 of gravity's: the power grew from zero as they rose, and they gained 6e-6 of their
/// energy in 0.09 s. Such accelerations are refused, and the balls rest on the surfaces that
/// hold them, one by one, as for a refused solve. (Checked on `G` alone, a ball sliding over
/// another pinned in a thin wedge of 1e-8 radians, whose rounding acceleration of 1.5e-7
/// worked on the slider at 4e-7 W for the hundredth of a second the group would hold, was
/// refused too, and micro-hopped over it every 7e-8 s instead, hunt seed 9179282.)
fn forces_do_no_work(
    masses: &[f64],
    velocities: &[DVec2],
    accelerations: &[DVec2],
    g: DVec2,
    (rounding, rounding_a): (f64, f64),
    lifetime: f64,
) -> bool {
    let (mut power, mut scale, mut floor) = (0.0, 0.0, 0.0);
    let (mut growth, mut growth_scale, mut growth_floor) = (0.0, 0.0, 0.0);
    for ((m, v), a) in masses.iter().zip(velocities).zip(accelerations) {
        power += m * (*a - g).dot(*v);
        scale += m * g.length() * v.length();
        floor += m * g.length() * rounding;
        growth += m * (*a - g).dot(*a);
        growth_scale += m * g.length() * a.length();
        growth_floor += m * g.length() * rounding_a;
    }
    let now = PARALLEL * scale + floor;
    let later = PARALLEL * growth_scale + growth_floor;
    if lifetime.is_finite() {
        let half = 0.5 * lifetime;
        power + growth * half <= now + later * half
    } else {
        power <= now && growth <= later
    }
}

/// Whether the hold's solved `accelerations` of the group's `members` (of `masses`, under
/// gravity `g`) are a worse answer of the hold's own programme than holding them still:
/// `sum m |a - g|^2 > sum m |g|^2` over the members, computed without cancellation as
/// `sum m a . (a - 2 g) > 0`. Zero accelerations meet every contact, so the programme's
/// optimum is never worse than rest, and a solve that ends worse has only rounding to show
/// for its departure from rest: that of a wedge of wedges, whose forces are
/// `1 / (angle angle')` times the weights. A ball beside a wall, on a ball pinned between a
/// floor's and a ceiling's end points 6.7e-9 radians apart, 8.2e-5 radians off level (hunt
/// seed 20017920), was solved to rise at 4.1e-5 of gravity's acceleration, above [`STILL`];
/// refused, it fell back into its wedge every 3.3e-6 s, a jam each time that closed the pair
/// `SNAP_ULPS` deeper than it stood, and sank into its neighbour 1e-9 of their contact
/// distance in 0.8 s.
fn worse_than_still(masses: &[f64], accelerations: &[DVec2], members: &[usize], g: DVec2) -> bool {
    members
        .iter()
        .map(|&at| {
            let a = accelerations[at];
            masses[at] * a.dot(a - 2.0 * g)
        })
        .sum::<f64>()
        > 0.0
}

/// Makes the surfaces of one ball that face each other to within [`PARALLEL`] (the walls
/// of an exact-fit channel, whose normals are opposite only as well as the scene's
/// coordinates allow) exactly opposite: the later one's normal becomes the earlier one's,
/// negated. A settle takes such walls for parallel ([`crate::dynamics::Hold`]): the ball
/// slides along the channel. The jam's programmes, given them as they are, found a wedge of
/// their rounding's angle (1e-12 radians for a channel a degree off upright, at scale 1e-3
/// and 1e3 from the origin), held the ball still in it where the settle after the jam let it
/// slide, and a ball under it was struck again every 0.24 ms, each time a rounding deeper
/// (hunt seed 10282927). Exactly opposite, the second wall depends on the first, and the
/// programmes let the ball move along both.
fn exact_fit_walls(rows: &mut [ContactRow]) {
    for j in 1..rows.len() {
        for i in 0..j {
            let (n, m) = (rows[i].normal, rows[j].normal);
            if n.dot(m) < 0.0 && (n + m).length() <= PARALLEL {
                rows[j].normal = -n;
                break;
            }
        }
    }
}

/// A contact's relative normal velocity for the cluster's velocities `v`.
#[cfg(test)]
mod tests {
    use super::*;
    use crate::{BallDesc, Body, ColliderDesc};

    /// A two-ball column on a floor, held as one group, its top ball `gap` (a share of the
    /// contact distance) above the bottom one: the world, the floor and the two balls.
    fn held_column(gap: f64) -> (World, ColliderHandle, u32, u32) {
        let r = 0.2;
        let mut world = World::with_gravity(DVec2::new(0.0, -9.81)).unwrap();
        world.set_sleeping(true);
        let floor = world
            .add_collider(ColliderDesc::segment(
                DVec2::new(-5.0, 0.0),
                DVec2::new(5.0, 0.0),
            ))
            .unwrap();
        let mut add = |y: f64| {
            let ball = BallDesc::new(DVec2::new(0.0, y), r).restitution(0.5);
            world.add_ball(ball).unwrap().index()
        };
        let bottom = add(r);
        let top = add(3.0 * r + gap * 2.0 * r);
        let group = world.new_group(
            vec![bottom, top],
            vec![Pair::balls(bottom, top)],
            None,
            Vec::new(),
        );
        world.hold_member(bottom, DVec2::ZERO, (group, f64::INFINITY), vec![floor]);
        world.hold_member(top, DVec2::ZERO, (group, f64::INFINITY), Vec::new());
        (world, floor, bottom, top)
    }

    /// A jam takes a group's members as touching up to the group gap (fellows), as their group
    /// did; and the group it leaves at rest sleeps whole, the top ball on the bottom one's
    /// circle. Left out of the cluster (a member slid a hair away), the top ball was let go with
    /// its group, fell, and met the bottom one again a moment later: another jam.
    #[test]
    fn a_jam_keeps_a_groups_fellows_within_the_group_gap() {
        let (mut world, floor, bottom, top) = held_column(0.5 * GROUP_GAP);
        assert_eq!(world.cluster(&[bottom]).balls, [bottom, top]);
        let y = world.position_now(top).y;
        world.resolve_jam(&[bottom]);
        let handle = |world: &World, index: u32| world.balls.handle(index);
        assert!(world.ball_asleep(handle(&world, bottom)));
        assert!(
            world.ball_asleep(handle(&world, top)),
            "the top ball sleeps"
        );
        assert_eq!(world.position_now(top).y, y, "where it was, to the bit");
        assert_eq!(
            world.ball_holders(handle(&world, bottom)).unwrap(),
            [Body::Collider(floor)]
        );
        assert_eq!(
            world.ball_holders(handle(&world, top)).unwrap(),
            [Body::Ball(handle(&world, bottom))]
        );
        // Beyond the gap the two are not fellows: the top ball is no part of the jam, and
        // falls onto the bottom one.
        let (mut world, _, bottom, top) = held_column(2.0 * GROUP_GAP);
        assert_eq!(world.cluster(&[bottom]).balls, [bottom]);
        world.resolve_jam(&[bottom]);
        assert!(!world.ball_asleep(handle(&world, top)));
        assert_eq!(world.acceleration(top), world.gravity());
    }

    /// A xorshift generator from `state`: each call a number below its argument.
    fn xorshift(mut state: u64) -> impl FnMut(u64) -> u64 {
        move |n| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state % n
        }
    }

    /// A triangle of touching balls of radius 0.2 on a frictionless floor, `rows` balls in its
    /// bottom row and one fewer in each row above, with a ball on its apex moving down at `u`,
    /// every pair's restitution `e`: the world, the striker and the apex first, then the rest
    /// of the triangle, row by row from the bottom.
    fn struck_triangle(rows: u32, u: f64, e: f64) -> (World, Vec<u32>) {
        let r = 0.2;
        let mut world = World::with_gravity(DVec2::new(0.0, -9.81)).unwrap();
        world.set_sleeping(true);
        let segment = |a: (f64, f64), b: (f64, f64)| {
            ColliderDesc::segment(DVec2::new(a.0, a.1), DVec2::new(b.0, b.1))
        };
        let width = 2.0 * r * f64::from(rows);
        world
            .add_collider(segment((-5.0, 0.0), (width + 5.0, 0.0)))
            .unwrap();
        let h = 3.0_f64.sqrt() * r;
        let mut add = |x: f64, y: f64, v: f64| {
            let ball = BallDesc::new(DVec2::new(x, y), r)
                .restitution(e.sqrt())
                .velocity(DVec2::new(0.0, -v));
            world.add_ball(ball).unwrap().index()
        };
        let mut triangle = Vec::new();
        for row in 0..rows {
            for i in 0..rows - row {
                let x = r * f64::from(2 * i + 1 + row);
                triangle.push(add(x, r + h * f64::from(row), 0.0));
            }
        }
        let apex = *triangle.last().expect("a triangle");
        let top = r + h * f64::from(rows - 1) + 2.0 * r;
        let striker = add(r * f64::from(rows), top, u);
        let mut balls = vec![striker, apex];
        balls.extend(&triangle[..triangle.len() - 1]);
        (world, balls)
    }

    /// The kinetic energy of `balls` now (all of one size: masses alike).
    fn energy_of(world: &World, balls: &[u32]) -> f64 {
        balls
            .iter()
            .map(|&i| world.velocity_now(i).length_squared())
            .sum()
    }

    /// A slow strike on a column of 44 balls standing on a floor (a cluster of 45, past
    /// `PLASTIC_FROM`) is a plastic jam: its bounce (`e u`) rests, so the hold's projection
    /// alone resolves it, every contact pushing (the strike passes down the column into the
    /// floor), and every ball stops, to rounding.
    #[test]
    fn a_slow_strike_on_a_column_stops_every_ball() {
        let (r, u) = (0.2, 0.005);
        let mut world = World::with_gravity(DVec2::new(0.0, -9.81)).unwrap();
        world.set_sleeping(true);
        let floor = ColliderDesc::segment(DVec2::new(-5.0, 0.0), DVec2::new(5.0, 0.0));
        world.add_collider(floor).unwrap();
        let balls: Vec<u32> = (0..45_u32)
            .rev()
            .map(|k| {
                let speed = if k == 44 { u } else { 0.0 };
                let ball = BallDesc::new(DVec2::new(0.0, r * f64::from(2 * k + 1)), r)
                    .restitution(0.5)
                    .velocity(DVec2::new(0.0, -speed));
                world.add_ball(ball).unwrap().index()
            })
            .collect();
        assert!(balls.len() > PLASTIC_FROM);
        let before = energy_of(&world, &balls);
        world.resolve_jam(&balls[..2]);
        for &ball in &balls {
            let v = world.velocity_now(ball);
            assert!(v.length() <= 1e-12 * u, "ball {ball}: {v}");
        }
        assert!(energy_of(&world, &balls) < 1e-20 * before);
    }

    /// A strike whose bounce would rest (`e u` within the rest speed) but which drives the
    /// triangle's base apart faster than a contact rests at: the projection would pull the
    /// base's contacts together, which no impact does, so the jam is the impact's, and the
    /// base parts (taken as the projection, every ball stopped).
    #[test]
    fn a_strike_that_parts_the_base_is_an_impact_not_a_plastic_jam() {
        let u = 1.0;
        let (mut world, balls) = struck_triangle(9, u, 0.01);
        let before = energy_of(&world, &balls);
        world.resolve_jam(&balls[..2]);
        let rest = world.rest_speed_at(1.0, 0.4, 0.2);
        // The bottom row, left to right: the balls after the striker and the apex.
        let bottom = &balls[2..11];
        let widest = bottom
            .windows(2)
            .map(|pair| world.velocity_now(pair[1]).x - world.velocity_now(pair[0]).x)
            .fold(0.0_f64, f64::max);
        assert!(widest > rest, "the base parts at {widest}, rests at {rest}");
        assert!(energy_of(&world, &balls) <= before);
    }

    /// A cluster is every ball reached from the seed through touching pairs, each touching
    /// pair among them once (its row naming its two balls), as a search of every pair of balls
    /// finds them; and the slots it marked are all cleared for the next jam.
    #[test]
    fn a_cluster_is_the_touching_component_of_its_seed_as_every_pair_finds_it() {
        let mut next = xorshift(0x9e37_79b9_7f4a_7c15);
        let r = 0.2;
        for _ in 0..40 {
            let mut world = World::new();
            // A grid of balls a micro-hop's tenth apart (touching), with some columns and
            // rows set a millimetre off (not touching) and some balls left out.
            let step = 2.0 * r + 1e-10;
            let (column_gap, row_gap) = (next(8), next(6));
            let mut balls = Vec::new();
            for j in 0..6_u32 {
                for i in 0..8_u32 {
                    if next(5) == 0 {
                        continue;
                    }
                    let x = f64::from(i) * step
                        + if u64::from(i) >= column_gap {
                            1e-3
                        } else {
                            0.0
                        };
                    let y = f64::from(j) * step + if u64::from(j) >= row_gap { 1e-3 } else { 0.0 };
                    let ball = BallDesc::new(DVec2::new(x, y), r);
                    balls.push(world.add_ball(ball).unwrap().index());
                }
            }
            let Some(&seed) = balls.get(next(balls.len().max(1) as u64) as usize) else {
                continue;
            };
            // Every pair of balls, searched for the seed's touching component.
            let touching = |a: u32, b: u32| {
                let (p, q) = (world.position_now(a), world.position_now(b));
                let coordinates = p.abs().max_element().max(q.abs().max_element());
                balls_touch((q - p).length() - 2.0 * r, coordinates, 2.0 * r)
            };
            let mut reached = vec![seed];
            let mut at = 0;
            while at < reached.len() {
                for &other in &balls {
                    if !reached.contains(&other) && touching(reached[at], other) {
                        reached.push(other);
                    }
                }
                at += 1;
            }
            let mut expected: Vec<Pair> = Vec::new();
            for (k, &a) in reached.iter().enumerate() {
                for &b in &reached[k + 1..] {
                    if touching(a, b) {
                        expected.push(Pair::balls(a, b));
                    }
                }
            }
            let cluster = world.cluster(&[seed]);
            let mut found_balls = cluster.balls.clone();
            found_balls.sort_unstable();
            reached.sort_unstable();
            assert_eq!(found_balls, reached);
            for (pair, row) in cluster.pairs.iter().zip(&cluster.rows) {
                let b = row.b.expect("no colliders here");
                assert_eq!(*pair, Pair::balls(cluster.balls[row.a], cluster.balls[b]));
            }
            let mut pairs = cluster.pairs.clone();
            pairs.sort_unstable();
            expected.sort_unstable();
            assert_eq!(pairs, expected, "each touching pair once");
            assert!(world.cluster_slots.iter().all(|&slot| slot == u32::MAX));
        }
    }

    /// Each ball's contacts are those of the list that involve it, in the list's order, as a
    /// filter of the whole list for each ball finds them.
    #[test]
    fn each_balls_contacts_are_the_filter_of_the_list() {
        let mut random = xorshift(0x2545_f491_4f6c_dd1d);
        let mut next = |n: usize| random(n as u64) as usize;
        for case in 0..200 {
            let balls = 1 + case % 40;
            let rows: Vec<ContactRow> = (0..next(3 * balls + 1))
                .map(|_| {
                    let a = next(balls);
                    let b = (next(3) > 0).then(|| next(balls)).filter(|&b| b != a);
                    ContactRow {
                        a,
                        b,
                        normal: DVec2::X,
                        target: 0.0,
                        slack: 0.0,
                    }
                })
                .collect();
            let cluster = Cluster {
                balls: (0..balls as u32).collect(),
                pairs: Vec::new(),
                rows,
                restitutions: Vec::new(),
                reaches: Vec::new(),
            };
            // Some of the rows, in a shuffled order.
            let mut some: Vec<usize> = (0..cluster.rows.len()).filter(|_| next(4) > 0).collect();
            for i in (1..some.len()).rev() {
                some.swap(i, next(i + 1));
            }
            let rows_of = RowsOf::new(&cluster, &some);
            for at in 0..balls {
                let filtered: Vec<usize> = some
                    .iter()
                    .copied()
                    .filter(|&k| cluster.rows[k].a == at || cluster.rows[k].b == Some(at))
                    .collect();
                assert_eq!(
                    rows_of.of(at),
                    filtered.as_slice(),
                    "case {case}, ball {at}"
                );
            }
        }
    }
}
