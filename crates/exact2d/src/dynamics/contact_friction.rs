//! Coulomb friction at the contacts of a group: balls pressed together, and against surfaces,
//! that slide on each other slow down, and those that do not slide stick while friction can
//! hold them.
//!
//! A group's accelerations (`pipeline/group.rs`) are those of frictionless bodies in contact:
//! the least change of gravity, in the kinetic-energy metric, that makes no contact approach.
//! With friction (a contact's coefficient `mu`, [`Roughness::pair`](super::Roughness::pair)
//! of its two bodies, above zero) a contact also carries a tangential force `T` along its
//! tangent `t` (its normal `n` turned a quarter counter-clockwise), within Coulomb's cone
//! `|T| <= mu N`. Which case a contact is in depends on its *slip* `s`, the relative velocity
//! along `t` (`(v_b - v_a) . t` for two balls, `v_a . t` for a ball on a surface):
//!
//! - *sliding* (`|s|` above the rounding of the velocities): kinetic friction, the force
//!   `-mu N sign(s)` along `t` on the pair (it slows their relative motion), with `N` the
//!   contact's normal force. The forces are known in direction, so they enter the programme as
//!   forces given to the balls, `g + F_i / m_i` in place of `g`; the normal forces that
//!   programme returns set them. Each *round* solves the programme with the kinetic forces of
//!   given normal forces, from none, until a round's normal forces at the sliding contacts
//!   agree with those it was given to [`AGREE`] of the largest, or for [`ROUNDS`] rounds.
//!   The rounds are *mixed* (Anderson mixing, `dynamics/mixing.rs`): each round is given the
//!   combination of the last rounds' answers whose mismatches cancel best. Plain, each
//!   round given the last one's answer, the iteration swings ever further apart wherever a
//!   contact's kinetic force presses another contact harder than it changes its own normal
//!   force (a gain above one round the loop), and in a poured pile settles slowly or not at
//!   all: in the rough 400-ball pile 74 % of the holds with a sliding contact reached the
//!   bound, and a third of them moved their balls with accelerations 1e-3 of gravity's or more
//!   away from those the mixed rounds agree on (6 % by more than gravity's). Mixed, 93 % agree,
//!   in 6.2 rounds on average where plain rounds took 12, for the same time (each mixed round
//!   moves the forces further, and its solve changes more of its active set). Rounds that
//!   end within [`COMPLEMENTARY`] of agreeing stand. Those that end further off give way to
//!   one linear complementarity problem over the same rows, each row's force along its
//!   normal or, at a sliding contact, leaning against the slip by `mu` (a matrix that is not
//!   symmetric, which no convex programme gives), checked against the problem: all but one
//!   in a hundred of the holds with a sliding contact are then Coulomb's. It is solved by
//!   block principal pivoting (`dynamics/principal.rs`) from the rows the last round's
//!   forces pushed at, which is the answer's active set or near it, and where that gives up
//!   by Lemke's method (`dynamics/lemke.rs`). Lemke's method alone pivots once for each row
//!   it makes active, each pivot a pass over a tableau of twice the rows' square: in the
//!   rough 200-ball pile, with holds of a hundred rows, it was a fifth of the wall. On the
//!   same holds the pivoting from the last round's rows finds an answer as often or more
//!   (3,607 of 3,629 where Lemke's method found 3,463; every answer both find within 1e-9 of
//!   each other) in a fifteenth of the time. Where neither finds one, the last round's
//!   forces are what the group moves with: its friction is Coulomb's to the share by which
//!   the last round's answer differs from what it was given.
//!   Each round's solve starts from the last one's end, its active set factorised: the
//!   rounds' programmes differ only in the forces given to the balls, so it ends in a few
//!   steps where that set holds, where a solve from nothing adds every contact again (a
//!   quarter of the time in poured piles). A pile's contacts outnumber its balls' freedoms,
//!   so their normal forces are not unique: the two solves may share a load differently,
//!   and with it the kinetic forces, each meeting every condition above;
//! - *sticking* (`|s|` within that rounding): the contact's normal row is replaced by the two
//!   edges of its cone, `(n + mu t) . x >= 0` and `(n - mu t) . x >= 0` on the relative
//!   acceleration `x`, whose multipliers `l+ n+ + l- n-` (both `>= 0`) span exactly the forces
//!   of the cone, so the programme's answer holds the contact still whenever some force within
//!   the cone can, however the group's forces are shared among its contacts (a pile's contacts
//!   are many more than its balls' freedoms, and the share of each is not unique). Where no
//!   force within the cone can, the contact starts to slide with the cone's edge force,
//!   against the slip, and (the cost of a programme) parts at `mu` times the slip's rate: a
//!   lift of `mu sigma t^2 / 2` over a slip `sigma t^2 / 2`, Anitescu and Potra's relaxation
//!   of Coulomb's law ("Formulating dynamic multi-rigid-body contact problems with friction as
//!   solvable linear complementarity problems", Nonlinear Dynamics 14, 1997). Once it slides,
//!   the next group's solve gives it Coulomb's kinetic force.
//!
//! A jam also stops, in its projection of the velocities (`pipeline/jam.rs`), the slip of a
//! rough resting contact that slips no faster than it rests at (with sleeping on, the sleep
//! speed of the smaller ball): its tangent is an equality of the projection, as the resting
//! normals are. Kinetic friction would stop such a slip within `s / (mu g)`; a bounce that slow
//! is dropped the same way.
//!
//! Why this never adds energy, nor overlap. Every programme here keeps the frictionless one's
//! condition that no contact approaches (a cone edge's row asks more: the contact parts at
//! least `mu |x . t|`), so the group's argument stands: two members only slide apart, a
//! member's distance to a surface only grows. The normal forces do no work. A sticking
//! contact's force acts where the relative velocity is zero, to the velocities' rounding, and
//! keeps the relative acceleration on its cone (no work but the rounding's); the projection is
//! onto a cone holding zero, which never lengthens the velocities. A kinetic force opposes its
//! slip, and the group lets go at the latest when that slip would reach zero
//! ([`FrictionalHold::slip_ends`]): the slip `s + sigma t` keeps its sign until then, so the
//! force only takes energy away. A slip that would end within `soon` of the clock (the collapse
//! floor) counts as ended and sticks: a group let go at once would form again at the same
//! instant. The world's check that a group's forces do no work (`pipeline/jam.rs`) still
//! judges every such solve.
//!
//! What it leaves out: spin. A group's members keep the spin they have, as without friction,
//! and the forces act on their centres only: two balls that would roll on each other slide,
//! as blocks would, and a ball alone on a surface beside a group is held with the group
//! rather than roll (a ball alone elsewhere rolls, `dynamics/rolling.rs`). A pile's balls,
//! packed among neighbours that keep each other from rolling, stop by sliding.

use glam::DVec2;

use super::impact::{ContactRow, ImpactError, resolve_impact_with_impulses_from};
use super::lemke::lemke;
use super::mixing::{MEMORY, Mixing};
use super::principal::from_guess;

/// How closely successive rounds' normal forces must agree, as a share of the largest, for
/// the iteration to stop: `1e-12`, a few thousand ulps: the kinetic forces are then the
/// normal forces' to that share.
pub(crate) const AGREE: f64 = 1e-12;

/// The most rounds of the iteration: `16`. Each round is one solve of the group's
/// programme, started from the last round's end (its active set, factorised): the rounds
/// differ only in the forces given to the balls. A block on a floor or a stack agrees in one
/// or two; in the rough 400-ball pile (mixed rounds) 93 % of the holds with a sliding contact
/// agree within this bound, in 6.2 rounds on average; the rest end with the last round's
/// forces (the bound keeps the cost of a hold to 16 solves).
pub(crate) const ROUNDS: usize = 16;

/// A contact's friction: its coefficient, and its slip now.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Rub {
    /// Coulomb's coefficient of the pair (0: frictionless).
    pub mu: f64,
    /// The relative velocity along the contact's tangent (`normal.perp()`): of `b` relative to
    /// `a` for two balls, of `a` for a surface.
    pub slip: f64,
}

/// A group's accelerations with friction, and how long they hold.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct FrictionalHold {
    /// Each ball's acceleration.
    pub accelerations: Vec<DVec2>,
    /// For each contact that slides now, the time from now at which its slip reaches zero
    /// under these accelerations (its kinetic force would turn round there); infinite for
    /// the rest (one that starts to slide only now slips against its force from zero).
    pub slip_ends: Vec<f64>,
}

/// Adds the force `force` along `direction` of `row` to the balls' forces: `+force` on `b` and
/// `-force` on `a` for two balls, `+force` on `a` for a surface (the sign a multiplier of the
/// programme gives).
fn push(row: &ContactRow, direction: DVec2, force: f64, forces: &mut [DVec2]) {
    match row.b {
        None => forces[row.a] += force * direction,
        Some(b) => {
            forces[b] += force * direction;
            forces[row.a] -= force * direction;
        }
    }
}

/// The two edges of a sticking contact's cone: unit normals `(n +- mu t) / sqrt(1 + mu^2)`.
fn cone_edges(row: &ContactRow, mu: f64) -> [ContactRow; 2] {
    let t = row.normal.perp();
    let scale = 1.0 / (1.0 + mu * mu).sqrt();
    [1.0, -1.0].map(|side| ContactRow {
        normal: (row.normal + side * mu * t) * scale,
        ..*row
    })
}

/// The accelerations of balls of `masses` under `gravity`, held by the contacts `rows` (each a
/// normal row of the group's programme, target zero) with the friction `rubs` (one for each
/// row), a slip of at most `still` counting as none, and one that friction would end within
/// `soon` counting as ended (see the module documentation).
///
/// # Errors
/// [`ImpactError::Infeasible`] if a round's programme has no solution (rounding: every
/// acceleration zero meets it).
pub(crate) fn frictional_hold(
    masses: &[f64],
    gravity: DVec2,
    rows: &[ContactRow],
    rubs: &[Rub],
    still: f64,
    soon: f64,
) -> Result<FrictionalHold, ImpactError> {
    debug_assert_eq!(rows.len(), rubs.len());
    let rough = |k: usize| rubs[k].mu > 0.0;
    let mut sliding: Vec<bool> = (0..rows.len())
        .map(|k| rough(k) && rubs[k].slip.abs() > still)
        .collect();
    loop {
        let (accelerations, slip_ends, _) =
            rounds(masses, gravity, rows, rubs, &sliding, MEMORY, true)?;
        // A slip that would end sooner than `soon` has ended: it sticks from now on (a group
        // that let go at once would be formed again at the same instant).
        let mut ended = false;
        for (k, &end) in slip_ends.iter().enumerate() {
            if end < soon {
                sliding[k] = false;
                ended = true;
            }
        }
        if !ended {
            return Ok(FrictionalHold {
                accelerations,
                slip_ends,
            });
        }
    }
}

/// The rounds of the iteration (see the module documentation), with the contacts `sliding`,
/// mixed over the last `memory` rounds (`dynamics/mixing.rs`), and if `complementary`, where
/// they end short of agreeing, the complementarity solve: the accelerations, each contact's
/// slip end, and whether they are Coulomb's (the rounds agreed to [`AGREE`], or ended within
/// [`COMPLEMENTARY`] of it, or the complementarity solve found them).
fn rounds(
    masses: &[f64],
    gravity: DVec2,
    rows: &[ContactRow],
    rubs: &[Rub],
    sliding: &[bool],
    memory: usize,
    complementary: bool,
) -> Result<(Vec<DVec2>, Vec<f64>, bool), ImpactError> {
    // The programme's rows: a sliding or frictionless contact's normal, a sticking contact's
    // two cone edges; `normal_at[k]` is where contact `k`'s normal force is read.
    let mut programme = Vec::with_capacity(rows.len() + 8);
    let mut normal_at = vec![None; rows.len()];
    for (k, row) in rows.iter().enumerate() {
        if rubs[k].mu > 0.0 && !sliding[k] {
            programme.extend(cone_edges(row, rubs[k].mu));
        } else {
            normal_at[k] = Some(programme.len());
            programme.push(*row);
        }
    }
    let any_sliding = sliding.iter().any(|&s| s);
    // The sliding contacts, whose normal forces set the kinetic forces: the iterate.
    let slides: Vec<usize> = (0..rows.len()).filter(|&k| sliding[k]).collect();
    let mut given = vec![0.0; slides.len()];
    let mut mixing = Mixing::new(memory);
    let mut converged = !any_sliding;
    let mut last_miss = 0.0_f64;
    let mut accelerations = vec![gravity; masses.len()];
    let mut start = None;
    // Each round's kinetic forces and the accelerations they leave free (one pair of
    // vectors for every round).
    let (mut forces, mut free) = (Vec::new(), Vec::with_capacity(masses.len()));
    // The rows the last round's forces push at: where the complementarity solve starts.
    let mut pushing = Vec::with_capacity(programme.len());
    for _ in 0..ROUNDS {
        // The kinetic forces of the normal forces this round is given.
        forces.clear();
        forces.resize(masses.len(), DVec2::ZERO);
        for (&k, &normal) in slides.iter().zip(&given) {
            let force = -rubs[k].slip.signum() * rubs[k].mu * normal;
            push(&rows[k], rows[k].normal.perp(), force, &mut forces);
        }
        free.clear();
        free.extend(masses.iter().zip(&forces).map(|(&m, &f)| gravity + f / m));
        // Each round's programme is the last one's with other forces: it starts from the
        // last one's end (the same optimum, found in a few steps where the active set holds).
        let (x, multipliers, end) =
            resolve_impact_with_impulses_from(masses, &free, &programme, start.take())?;
        start = Some(end);
        pushing.clear();
        pushing.extend(multipliers.iter().map(|&l| l > 0.0));
        accelerations = x;
        let largest = normal_at
            .iter()
            .flatten()
            .fold(0.0_f64, |m, &i| m.max(multipliers[i].abs()));
        let answer: Vec<f64> = slides
            .iter()
            .map(|&k| normal_at[k].map_or(0.0, |i| multipliers[i]))
            .collect();
        let agree = answer
            .iter()
            .zip(&given)
            .all(|(&new, &old)| (new - old).abs() <= AGREE * largest);
        if agree || !any_sliding {
            converged = true;
            break;
        }
        last_miss =
            (answer.iter().zip(&given)).fold(0.0_f64, |m, (a, b)| m.max((a - b).abs())) / largest;
        given = mixing.next(&given, answer);
    }
    // Rounds that end short of agreeing by more than a complementarity solve would miss its
    // problem by give way to that solve (`by_complementarity`), where it finds an answer.
    if !converged && last_miss <= COMPLEMENTARY {
        converged = true;
    } else if !converged && complementary {
        let solved = by_complementarity(
            masses,
            gravity,
            (rows, rubs, sliding),
            &programme,
            (&normal_at, &pushing),
        );
        if let Some(solved) = solved {
            accelerations = solved;
            converged = true;
        }
    }
    let slip_ends = rows
        .iter()
        .zip(rubs)
        .zip(sliding)
        .map(|((row, rub), &slides)| {
            if !slides {
                return f64::INFINITY;
            }
            let rate = row.tangent().relative(&accelerations);
            if rub.slip * rate < 0.0 {
                -rub.slip / rate
            } else {
                f64::INFINITY
            }
        })
        .collect();
    Ok((accelerations, slip_ends, converged))
}

/// The accelerations of the programme `programme` (the rows [`rounds`] builds for `rows`,
/// `rubs` and `sliding`, contact `k`'s normal row at `normal_at[k]`) solved as one linear
/// complementarity problem, each row's force along its own normal, or, at a sliding contact,
/// leaning against its slip by `mu`: by block principal pivoting from the rows the last round
/// pushed at, `pushing` (`dynamics/principal.rs`: a solve or two where that guess is near),
/// or failing that by Lemke's method (`dynamics/lemke.rs`); checked against the problem (no
/// row's relative acceleration below zero, none above it where its row pushes, to
/// [`COMPLEMENTARY`] of the largest acceleration), else none.
fn by_complementarity(
    masses: &[f64],
    gravity: DVec2,
    (rows, rubs, sliding): (&[ContactRow], &[Rub], &[bool]),
    programme: &[ContactRow],
    (normal_at, pushing): (&[Option<usize>], &[bool]),
) -> Option<Vec<DVec2>> {
    // Each programme row's force acts along its normal, a sliding contact's leaning.
    let mut direction: Vec<DVec2> = programme.iter().map(|row| row.normal).collect();
    for (k, row) in rows.iter().enumerate() {
        if let (true, Some(at)) = (sliding[k], normal_at[k]) {
            direction[at] -= rubs[k].slip.signum() * rubs[k].mu * row.normal.perp();
        }
    }
    let n = programme.len();
    let accelerations = |forces: &[f64]| -> Vec<DVec2> {
        let mut f = vec![DVec2::ZERO; masses.len()];
        for ((row, &d), &l) in programme.iter().zip(&direction).zip(forces) {
            if l != 0.0 {
                push(row, d, l, &mut f);
            }
        }
        masses
            .iter()
            .zip(&f)
            .map(|(&m, &f)| gravity + f / m)
            .collect()
    };
    let free = vec![gravity; masses.len()];
    let q: Vec<f64> = programme.iter().map(|row| row.relative(&free)).collect();
    let mut m = vec![vec![0.0; n]; n];
    for c in 0..n {
        let mut f = vec![DVec2::ZERO; masses.len()];
        push(&programme[c], direction[c], 1.0, &mut f);
        let unit: Vec<DVec2> = masses.iter().zip(&f).map(|(&mass, &f)| f / mass).collect();
        for (r, row) in programme.iter().enumerate() {
            m[r][c] = row.relative(&unit);
        }
    }
    let meets = |z: &[f64]| {
        let a = accelerations(z);
        let scale = a.iter().fold(gravity.length(), |s, x| s.max(x.length()));
        let tolerance = COMPLEMENTARY * scale;
        programme
            .iter()
            .zip(z)
            .all(|(row, &l)| {
                let w = row.relative(&a);
                w >= -tolerance && (l == 0.0 || w <= tolerance)
            })
            .then_some(a)
    };
    from_guess(&m, &q, pushing)
        .and_then(|z| meets(&z))
        .or_else(|| lemke(&m, &q).and_then(|z| meets(&z)))
}

/// How far a complementarity solution's relative accelerations may miss the problem, as a
/// share of the largest acceleration: `1e-9`.
const COMPLEMENTARY: f64 = 1e-9;

#[cfg(test)]
mod tests {
    use super::*;

    const G: DVec2 = DVec2::new(0.0, -9.81);

    fn floor(a: usize) -> ContactRow {
        ContactRow {
            a,
            b: None,
            normal: DVec2::Y,
            target: 0.0,
            slack: 0.0,
        }
    }

    /// Ball 0 on a slope rising at `theta` to the left: its row, and the slope's normal.
    fn slope(theta: f64) -> (ContactRow, DVec2) {
        let n = DVec2::new(-theta.sin(), theta.cos());
        (
            ContactRow {
                normal: n,
                ..floor(0)
            },
            n,
        )
    }

    /// A ball sliding on a level floor decelerates at `mu g`, and its slip ends at
    /// `v / (mu g)`.
    #[test]
    fn a_block_sliding_on_a_floor_decelerates_at_mu_g() {
        let rubs = [Rub { mu: 0.5, slip: 2.0 }];
        let hold = frictional_hold(&[2.0], G, &[floor(0)], &rubs, 1e-12, 0.0).unwrap();
        // The slip is along the tangent, `-x`: the force slows it.
        let a = hold.accelerations[0];
        assert!((a.dot(DVec2::Y.perp()) + 0.5 * 9.81).abs() < 1e-12, "{a}");
        assert!(a.y.abs() < 1e-12, "{a}");
        let end = 2.0 / (0.5 * 9.81);
        assert!((hold.slip_ends[0] - end).abs() < 1e-12 * end);
    }

    /// On a slope of angle `theta`, a ball at rest sticks while `tan theta <= mu`; past it, it
    /// starts down the slope as the cone's programme has it: at
    /// `g (sin theta - mu cos theta) / (1 + mu^2)` along it and `mu` times that off it (the
    /// relaxation's lift at a slip's start; see the module documentation).
    #[test]
    fn a_ball_on_a_slope_sticks_below_the_angle_of_friction() {
        for (theta, mu) in [(0.3_f64, 0.5_f64), (0.3, 0.2), (0.6, 0.7), (0.6, 0.5)] {
            let (row, n) = slope(theta);
            let rubs = [Rub { mu, slip: 0.0 }];
            let hold = frictional_hold(&[1.0], G, &[row], &rubs, 1e-12, 0.0).unwrap();
            let a = hold.accelerations[0];
            // The tangent points down the slope.
            let t = n.perp();
            if theta.tan() <= mu {
                assert!(a.length() < 1e-12, "theta {theta} mu {mu}: {a}");
            } else {
                let expected = 9.81 * (theta.sin() - mu * theta.cos()) / (1.0 + mu * mu);
                assert!(
                    (a.dot(t) - expected).abs() < 1e-12,
                    "{} {expected}",
                    a.dot(t)
                );
                assert!((a.dot(n) - mu * expected).abs() < 1e-12, "{}", a.dot(n));
            }
        }
    }

    /// Sliding, the ball on a slope steeper than the angle of friction is slowed by Coulomb's
    /// kinetic friction, `g (sin theta - mu cos theta)` down the slope, and stays on it.
    #[test]
    fn a_ball_sliding_down_a_slope_feels_kinetic_friction() {
        let (theta, mu) = (0.6_f64, 0.5_f64);
        let (row, n) = slope(theta);
        let rubs = [Rub { mu, slip: 0.8 }];
        let hold = frictional_hold(&[1.0], G, &[row], &rubs, 1e-12, 0.0).unwrap();
        let a = hold.accelerations[0];
        let expected = 9.81 * (theta.sin() - mu * theta.cos());
        assert!((a.dot(n.perp()) - expected).abs() < 1e-12, "{a}");
        assert!(a.dot(n).abs() < 1e-12, "{a}");
        assert!(hold.slip_ends[0].is_infinite());
    }

    /// Two balls stacked on a floor, sliding together: the pair sticks, and the two
    /// decelerate as one body at `mu g` (the floor carries both weights).
    #[test]
    fn a_stack_sliding_on_a_floor_stops_as_one_body() {
        let rows = [
            floor(0),
            ContactRow {
                a: 0,
                b: Some(1),
                normal: DVec2::Y,
                target: 0.0,
                slack: 0.0,
            },
        ];
        let rubs = [Rub { mu: 0.4, slip: 1.5 }, Rub { mu: 0.4, slip: 0.0 }];
        let hold = frictional_hold(&[1.0, 1.0], G, &rows, &rubs, 1e-12, 0.0).unwrap();
        for a in &hold.accelerations {
            assert!((a.dot(DVec2::Y.perp()) + 0.4 * 9.81).abs() < 1e-12, "{a}");
            assert!(a.y.abs() < 1e-12, "{a}");
        }
        assert!((hold.slip_ends[0] - 1.5 / (0.4 * 9.81)).abs() < 1e-12);
        assert!(hold.slip_ends[1].is_infinite());
    }

    /// Every answer of Coulomb's law over the programme `rows` with `rubs` (contacts
    /// `sliding` slide, the rest stick), by brute force: for each set of the programme's rows
    /// taken as active (relative normal acceleration zero), the forces that hold them, the
    /// normal forces found from a linear system in which a sliding contact's force leans
    /// against its slip by `mu`; kept if no force pulls and no inactive row approaches.
    fn coulomb_by_enumeration(
        masses: &[f64],
        rows: &[ContactRow],
        rubs: &[Rub],
        sliding: &[bool],
    ) -> Vec<Vec<DVec2>> {
        // Each programme row with the direction its force acts along.
        let mut programme: Vec<(ContactRow, DVec2)> = Vec::new();
        for (k, row) in rows.iter().enumerate() {
            if rubs[k].mu > 0.0 && !sliding[k] {
                for edge in cone_edges(row, rubs[k].mu) {
                    programme.push((edge, edge.normal));
                }
            } else {
                let lean = if sliding[k] {
                    -rubs[k].slip.signum() * rubs[k].mu * row.normal.perp()
                } else {
                    DVec2::ZERO
                };
                programme.push((*row, row.normal + lean));
            }
        }
        let count = programme.len();
        let accelerations = |forces: &[f64]| {
            let mut f = vec![DVec2::ZERO; masses.len()];
            for ((row, direction), &l) in programme.iter().zip(forces) {
                push(row, *direction, l, &mut f);
            }
            (masses.iter().zip(&f))
                .map(|(&m, &f)| G + f / m)
                .collect::<Vec<DVec2>>()
        };
        let mut answers = Vec::new();
        for set in 0..(1_u32 << count) {
            let active: Vec<usize> = (0..count).filter(|&r| set >> r & 1 == 1).collect();
            let n = active.len();
            // Row `i`: the relative acceleration of active row `i` is zero.
            let mut a = vec![vec![0.0; n + 1]; n];
            let base = accelerations(&vec![0.0; count]);
            for (i, &r) in active.iter().enumerate() {
                for (j, &c) in active.iter().enumerate() {
                    let mut unit = vec![0.0; count];
                    unit[c] = 1.0;
                    let x = accelerations(&unit);
                    a[i][j] = programme[r].0.relative(&x) - programme[r].0.relative(&base);
                }
                a[i][n] = -programme[r].0.relative(&base);
            }
            // A singular set is skipped.
            let Some(solved) = crate::dynamics::dense::solve_dense(a, 1e-9) else {
                continue;
            };
            let mut forces = vec![0.0; count];
            for (&r, l) in active.iter().zip(solved) {
                forces[r] = l;
            }
            let x = accelerations(&forces);
            let pushes = forces.iter().all(|&l| l >= -1e-9);
            let apart = programme.iter().all(|(row, _)| row.relative(&x) >= -1e-9);
            if pushes && apart {
                answers.push(x);
            }
        }
        answers
    }

    /// A programme drawn at random: one to three balls, their contacts with each other and
    /// with surfaces at random normals, most of them sliding either way (what slides need not
    /// be a motion the balls could have: the law is asked of the programme alone).
    fn random_programme(next: &mut impl FnMut() -> f64) -> (Vec<f64>, Vec<ContactRow>, Vec<Rub>) {
        let n = 1 + (next() * 3.0) as usize;
        let count = n + (next() * 3.0) as usize;
        let mut rows = Vec::new();
        let mut rubs = Vec::new();
        for _ in 0..count {
            let a = (next() * n as f64) as usize;
            let b =
                (n > 1 && next() < 0.5).then(|| (a + 1 + (next() * (n - 1) as f64) as usize) % n);
            let angle = next() * std::f64::consts::TAU;
            rows.push(ContactRow {
                a,
                b,
                normal: DVec2::new(angle.cos(), angle.sin()),
                target: 0.0,
                slack: 0.0,
            });
            let slip = if next() < 0.7 {
                (next() - 0.5) * 4.0
            } else {
                0.0
            };
            rubs.push(Rub {
                mu: 0.2 + next() * 0.8,
                slip,
            });
        }
        let masses = (0..n).map(|_| 0.5 + next()).collect();
        (masses, rows, rubs)
    }

    /// The hold's answer is Coulomb's: on 4,000 random programmes, every answer the rounds
    /// give as Coulomb's, mixed or with the complementarity solve after them, is one of the
    /// answers found by enumeration (to 1e-9 of the largest acceleration). Mixed rounds agree
    /// on far more of them than plain rounds (measured: 3,803 against 3,059 of 3,995; on
    /// 200,000, 95 % against 75 %): plain, where one contact's kinetic force presses another
    /// harder than its own normal force would change (a gain above one), the rounds swing
    /// further apart each time. With the complementarity solve, every programme that has an
    /// answer gets one but a few (measured: 5 of 3,868 missed; the other 127 have none, the
    /// programme's friction locking it, as in Painleve's paradox, or its rows dependent).
    #[test]
    fn the_rounds_find_coulombs_answer() {
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1_u64 << 53) as f64
        };
        let (mut plain_agree, mut mixed_agree, mut tried) = (0, 0, 0);
        let (mut solvable, mut missed) = (0, 0);
        for _ in 0..4000 {
            let (masses, rows, rubs) = random_programme(&mut next);
            let sliding: Vec<bool> = rubs.iter().map(|r| r.slip != 0.0).collect();
            let (Ok(plain), Ok(mixed), Ok(whole)) = (
                rounds(&masses, G, &rows, &rubs, &sliding, 1, false),
                rounds(&masses, G, &rows, &rubs, &sliding, MEMORY, false),
                rounds(&masses, G, &rows, &rubs, &sliding, MEMORY, true),
            ) else {
                continue;
            };
            tried += 1;
            plain_agree += usize::from(plain.2);
            mixed_agree += usize::from(mixed.2);
            let answers = coulomb_by_enumeration(&masses, &rows, &rubs, &sliding);
            solvable += usize::from(!answers.is_empty());
            missed += usize::from(!answers.is_empty() && !whole.2);
            for (given, accelerations) in [(mixed.2, &mixed.0), (whole.2, &whole.0)] {
                if given {
                    let scale = accelerations
                        .iter()
                        .fold(G.length(), |m, a| m.max(a.length()));
                    let near = |x: &Vec<DVec2>| {
                        x.iter()
                            .zip(accelerations)
                            .all(|(a, b)| (*a - *b).length() <= 1e-9 * scale)
                    };
                    assert!(
                        answers.iter().any(near),
                        "{masses:?} {rows:?} {rubs:?}: {accelerations:?} not among {answers:?}"
                    );
                }
            }
        }
        assert!(tried > 3900, "{tried}");
        assert!(mixed_agree * 100 >= 90 * tried, "{mixed_agree} of {tried}");
        assert!(
            mixed_agree > plain_agree + tried / 10,
            "{mixed_agree} {plain_agree}"
        );
        assert!(missed * 200 <= solvable, "{missed} of {solvable}");
    }

    /// Frictionless rows leave the frictionless answer.
    #[test]
    fn without_friction_it_is_the_frictionless_programme() {
        let (row, n) = slope(0.6_f64.asin());
        let rubs = [Rub { mu: 0.0, slip: 3.0 }];
        let hold = frictional_hold(&[1.0], G, &[row], &rubs, 1e-12, 0.0).unwrap();
        let expected = G - G.dot(n) * n;
        assert!((hold.accelerations[0] - expected).length() < 1e-12);
        assert!(hold.slip_ends[0].is_infinite());
    }
}
