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
//!   programme returns set them, and the two are iterated from no kinetic force until the
//!   normal forces agree to [`AGREE`] of the largest, or for [`ROUNDS`] rounds (the last
//!   round's forces are what the group moves with: its friction is Coulomb's to the share by
//!   which the last two rounds differ, which in a poured pile is often far above [`AGREE`]:
//!   the iteration is a plain fixed point, and converges slowly where many contacts slide).
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

/// How closely successive rounds' normal forces must agree, as a share of the largest, for
/// the iteration to stop: `1e-12`, a few thousand ulps: the kinetic forces are then the
/// normal forces' to that share.
pub(crate) const AGREE: f64 = 1e-12;

/// The most rounds of the iteration: `16`. Each round is one solve of the group's
/// programme, started from the last round's end (its active set, factorised): the rounds
/// differ only in the forces given to the balls. A block on a floor or a stack agrees in one or two; in poured piles most holds
/// with a sliding contact reach this bound, their last two rounds' normal forces still apart
/// by 1e-5 to 1e-1 of the largest (some by more): their kinetic forces are Coulomb's to
/// that, against the slip as ever (the bound keeps the cost of a hold to 16 solves).
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
        let (accelerations, slip_ends) = rounds(masses, gravity, rows, rubs, &sliding)?;
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

/// The rounds of the iteration (see the module documentation), with the contacts `sliding`:
/// the accelerations, and each contact's slip end.
fn rounds(
    masses: &[f64],
    gravity: DVec2,
    rows: &[ContactRow],
    rubs: &[Rub],
    sliding: &[bool],
) -> Result<(Vec<DVec2>, Vec<f64>), ImpactError> {
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
    let mut normal = vec![0.0; rows.len()];
    let mut accelerations = vec![gravity; masses.len()];
    let mut start = None;
    for _ in 0..ROUNDS {
        // The kinetic forces from the last round's normal forces.
        let mut forces = vec![DVec2::ZERO; masses.len()];
        for (k, row) in rows.iter().enumerate() {
            if sliding[k] {
                let force = -rubs[k].slip.signum() * rubs[k].mu * normal[k];
                push(row, row.normal.perp(), force, &mut forces);
            }
        }
        let free: Vec<DVec2> = masses
            .iter()
            .zip(&forces)
            .map(|(&m, &f)| gravity + f / m)
            .collect();
        // Each round's programme is the last one's with other forces: it starts from the
        // last one's end (the same optimum, found in a few steps where the active set holds).
        let (x, multipliers, end) =
            resolve_impact_with_impulses_from(masses, &free, &programme, start.take())?;
        start = Some(end);
        accelerations = x;
        let fresh: Vec<f64> = normal_at
            .iter()
            .map(|at| at.map_or(0.0, |i| multipliers[i]))
            .collect();
        let largest = fresh.iter().fold(0.0_f64, |m, &l| m.max(l.abs()));
        let agree = fresh
            .iter()
            .zip(&normal)
            .all(|(&new, &old)| (new - old).abs() <= AGREE * largest);
        normal = fresh;
        if agree || !any_sliding {
            break;
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
    Ok((accelerations, slip_ends))
}

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
