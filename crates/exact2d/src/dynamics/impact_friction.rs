//! Coulomb friction in a jam's impact: the simultaneous impact of a cluster of touching balls
//! (`pipeline/jam.rs`) with a tangential impulse at each rough contact, within Coulomb's cone
//! of its normal impulse.
//!
//! The frictionless impact (`dynamics/impact.rs`) is a projection: the least change of the
//! velocities, in the kinetic-energy metric, that meets every contact's target (its
//! restitution times its approach, or zero), the normal impulses `l_k >= 0` its multipliers.
//! With friction (a contact's coefficient `mu_k`, [`Roughness::pair`](super::Roughness::pair)
//! of its two bodies, above zero) each contact also carries an impulse `f_k` along its tangent
//! `t_k` (its normal turned a quarter counter-clockwise), with `|f_k| <= mu_k l_k`: the
//! impulses of Coulomb's law over an impact, and of the most dissipative choice among them
//! (the tangential impulses take as much kinetic energy as the cone lets them).
//!
//! Both parts are found by *staggered projections* (Kaufman, Sueda, James and Pai,
//! "Staggered projections for frictional contact in multibody systems", ACM Transactions on
//! Graphics 27(5), 2008), each a convex programme this engine already solves or can solve
//! exactly:
//!
//! 1. the normal impulses, for the tangential ones fixed: the frictionless impact of the
//!    velocities `v + M^-1 sum_k f_k t_k` (the same programme, the same targets);
//! 2. the tangential impulses, for the normal ones fixed: the least kinetic energy over the
//!    box `|f_k| <= mu_k l_k`, by projected Gauss-Seidel: each contact in turn takes the
//!    impulse that stops its slip, clamped to its box (each step is the exact minimum along
//!    one coordinate of a convex quadratic, so the energy never rises), for at most
//!    [`SWEEPS`] sweeps or until a sweep changes no velocity by more than the rounding;
//!
//! from no tangential impulse, until successive normal impulses agree to [`AGREE`] of the
//! largest, or for [`ROUNDS`] rounds. Each round's step 1 starts from the last one's end, its
//! active set factorised: the same programme from other velocities, the same optimum, found in
//! a few steps where the active set holds (from nothing, the rough 400-ball pile's first
//! 55,000 impacts took 10.4 s of these solves where they take 4.2 s). The answer is always a
//! step 1: every contact meets its target (to the solve's slack), whatever the friction did;
//! its tangential impulses are the last step 2's, Coulomb's to the share by which the last two
//! normal solves differ. That share is often large: in the rough 400-ball pile 90 % of the
//! jams' frictional impacts reach the 8 rounds without agreeing (43,633 of 48,207), and on
//! 2,000 random rows of balls on a floor only 24 % of the answers meet Coulomb's conditions
//! (targets met, each impulse within its cone, at the edge against any slip left) to 1e-9 of
//! their scale, 69 % to 1e-2, 97 % to 1e-1; with 32 rounds, 57 % to 1e-9. The iteration
//! creeps (damping it, or Anderson mixing as a group's rounds are mixed, agreed less often).
//! Solving for each rough contact's state instead (sticking: its slip an equality of the
//! programme; sliding: its impulse at the cone's edge, the normal impulses mixed), from the
//! states two rounds of this iteration suggest, met Coulomb's conditions in 74 % of those
//! rows, but cost the rough 100-ball piles 1.66 times the wall (a programme with equalities
//! solved from nothing, seven a jam): not kept (BENCHMARKS.md, stop 51).
//!
//! Why not the cone's two edges as rows of one projection (Anitescu and Potra's relaxation,
//! which the group's forces use for a sticking contact, `dynamics/contact_friction.rs`)? Its
//! impulses are Coulomb's, but its velocities part every sliding contact at `mu` times its
//! slip, and where a contact cannot part it cannot slide: measured, a rough ball falling
//! through an exact-fit channel (both walls touched) stopped dead at its first jam, held by
//! impulses of any size the two walls could press it with. Here a normal impulse is only what
//! the impact needs (the ball loses at most `mu` times its approach across the channel of its
//! speed along it), and nothing parts.
//!
//! What it leaves out, as the group's forces do: spin. The impulses act on the balls' centres;
//! a ball's spin is the same after a jam as before.

use glam::DVec2;

use super::impact::{ContactRow, ImpactError, resolve_impact_with_impulses_from};

/// How closely successive rounds' normal impulses must agree, as a share of the largest, for
/// the iteration to stop: `1e-12`, a few thousand ulps, as for a group's forces.
pub(crate) const AGREE: f64 = 1e-12;

/// The most rounds (normal solves) of the iteration: `8`. A ball on a surface or in a channel
/// agrees at the second; the bound keeps a jam's cost to eight solves of its impact.
pub(crate) const ROUNDS: usize = 8;

/// The most sweeps of projected Gauss-Seidel over the rough contacts in one step 2: `64`.
pub(crate) const SWEEPS: usize = 64;

/// A jam's impact with friction: the velocities after it, and each contact's impulses.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct FrictionalImpact {
    /// Each ball's velocity after the impact.
    pub velocities: Vec<DVec2>,
    /// Each contact's normal impulse (the multiplier of its row).
    pub normal: Vec<f64>,
    /// Each contact's impulse along its tangent (`normal.perp()`), with the sign of a row's
    /// multiplier: on `b`, and its opposite on `a`, for two balls; on `a` for a surface.
    pub tangential: Vec<f64>,
}

/// Adds `impulse` along `direction` of `row` to the velocities `v` of balls of `masses`.
fn give(row: &ContactRow, direction: DVec2, impulse: f64, masses: &[f64], v: &mut [DVec2]) {
    match row.b {
        None => v[row.a] += impulse * direction / masses[row.a],
        Some(b) => {
            v[b] += impulse * direction / masses[b];
            v[row.a] -= impulse * direction / masses[row.a];
        }
    }
}

/// The impact of balls of `masses` with `velocities` at the contacts `rows` (each with its
/// target and slack, as for
/// [`resolve_impact_with_impulses`](super::impact::resolve_impact_with_impulses)), with
/// friction `mus` (one for each row; zero for none): see the module documentation.
///
/// # Errors
/// [`ImpactError::Infeasible`] if a round's normal programme has no solution.
pub(crate) fn resolve_frictional_impact(
    masses: &[f64],
    velocities: &[DVec2],
    rows: &[ContactRow],
    mus: &[f64],
) -> Result<FrictionalImpact, ImpactError> {
    // Each round's programme is the last one's from other velocities: it starts from the
    // last one's end (the same optimum, found in a few steps where the active set holds).
    let mut start = None;
    staggered(masses, velocities, rows, mus, |given| {
        let (after, fresh, end) =
            resolve_impact_with_impulses_from(masses, given, rows, start.take())?;
        start = Some(end);
        Ok((after, fresh))
    })
}

/// The staggered projections of [`resolve_frictional_impact`], each round's step 1 the
/// frictionless impact `normal_solve` gives of the velocities (its velocities and the rows'
/// normal impulses).
fn staggered(
    masses: &[f64],
    velocities: &[DVec2],
    rows: &[ContactRow],
    mus: &[f64],
    mut normal_solve: impl FnMut(&[DVec2]) -> Result<(Vec<DVec2>, Vec<f64>), ImpactError>,
) -> Result<FrictionalImpact, ImpactError> {
    debug_assert_eq!(rows.len(), mus.len());
    let rough: Vec<usize> = (0..rows.len()).filter(|&k| mus[k] > 0.0).collect();
    let mut tangential = vec![0.0; rows.len()];
    let mut normal: Vec<f64> = Vec::new();
    for round in 0..ROUNDS {
        // Step 1: the normal impulses, the tangential ones given.
        let mut given = velocities.to_vec();
        for &k in &rough {
            give(
                &rows[k],
                rows[k].normal.perp(),
                tangential[k],
                masses,
                &mut given,
            );
        }
        let (after, fresh) = normal_solve(&given)?;
        let largest = fresh.iter().fold(0.0_f64, |m, &l| m.max(l.abs()));
        let agree = round > 0
            && fresh
                .iter()
                .zip(&normal)
                .all(|(&new, &old)| (new - old).abs() <= AGREE * largest);
        normal = fresh;
        if agree || round + 1 == ROUNDS {
            return Ok(FrictionalImpact {
                velocities: after,
                normal,
                tangential,
            });
        }
        // Step 2: the tangential impulses, the normal ones given.
        let before = tangential.clone();
        let mut v = after.clone();
        let scale = v.iter().fold(0.0_f64, |s, x| s.max(x.length()));
        for _ in 0..SWEEPS {
            let mut change = 0.0_f64;
            for &k in &rough {
                let row = &rows[k];
                // (A normal impulse the solve left a rounding below zero is none.)
                let bound = (mus[k] * normal[k]).max(0.0);
                let inverse = 1.0 / masses[row.a] + row.b.map_or(0.0, |b| 1.0 / masses[b]);
                let slip = row.tangent().relative(&v);
                let next = (tangential[k] - slip / inverse).clamp(-bound, bound);
                let step = next - tangential[k];
                if step != 0.0 {
                    give(row, row.normal.perp(), step, masses, &mut v);
                    tangential[k] = next;
                    change = change.max((step * inverse).abs());
                }
            }
            if change <= 4.0 * f64::EPSILON * scale {
                break;
            }
        }
        // No tangential impulse changed: step 1 would give the same answer again.
        if tangential == before {
            return Ok(FrictionalImpact {
                velocities: after,
                normal,
                tangential,
            });
        }
    }
    unreachable!("the last round returns")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn wall(a: usize, normal: DVec2) -> ContactRow {
        ContactRow {
            a,
            b: None,
            normal,
            target: 0.0,
            slack: 0.0,
        }
    }

    #[test]
    fn a_ball_struck_into_a_rough_floor_loses_mu_times_its_approach_of_its_slide() {
        // Plastic: the normal impulse is m u; the slide 3 of speed loses at most mu m u / m.
        let (m, u, s, mu) = (2.0, 1.5, 3.0, 0.4);
        let rows = [wall(0, DVec2::Y)];
        let hit = resolve_frictional_impact(&[m], &[DVec2::new(s, -u)], &rows, &[mu]).unwrap();
        assert!((hit.normal[0] - m * u).abs() < 1e-12);
        assert!(
            (hit.velocities[0].x - (s - mu * u)).abs() < 1e-12,
            "{hit:?}"
        );
        assert!(hit.velocities[0].y.abs() < 1e-12);
        // Along the tangent (-x for the floor's normal +y): against the slide.
        assert!((hit.tangential[0] - mu * m * u).abs() < 1e-12);
    }

    #[test]
    fn a_slow_slide_stops_where_the_cone_can_stop_it() {
        let (m, u, s, mu) = (1.0, 2.0, 0.5, 0.5);
        let rows = [wall(0, DVec2::Y)];
        let hit = resolve_frictional_impact(&[m], &[DVec2::new(s, -u)], &rows, &[mu]).unwrap();
        assert!(hit.velocities[0].length() < 1e-12, "{hit:?}");
        assert!(hit.tangential[0].abs() <= mu * hit.normal[0] + 1e-12);
    }

    #[test]
    fn an_exact_fit_channel_does_not_catch_a_falling_ball() {
        // Walls at both sides, the ball driven into the right one at u, falling at w: the
        // impact stops u, and friction takes at most mu u of the fall (the anitescu-potra
        // cone would stop the fall too).
        let (m, u, w, mu) = (1.0, 0.3, -2.0, 0.5);
        let rows = [wall(0, DVec2::X), wall(0, -DVec2::X)];
        let hit = resolve_frictional_impact(&[m], &[DVec2::new(u, w)], &rows, &[mu, mu]).unwrap();
        let v = hit.velocities[0];
        assert!(v.x.abs() < 1e-12);
        assert!((v.y - (w + mu * u)).abs() < 1e-12, "{hit:?}");
    }

    #[test]
    fn two_balls_driven_together_on_a_rough_floor_keep_their_momentum_along_it() {
        // Ball 0 on the floor struck by ball 1 from above-right: friction on the floor takes
        // horizontal momentum, friction between the balls does not change their total.
        let masses = [1.0, 3.0];
        let n = DVec2::new(1.0, 1.0).normalize();
        let rows = [
            wall(0, DVec2::Y),
            ContactRow {
                a: 0,
                b: Some(1),
                normal: n,
                target: 0.0,
                slack: 0.0,
            },
        ];
        let v = [DVec2::new(0.2, 0.0), DVec2::new(-1.0, -0.5)];
        let rough = resolve_frictional_impact(&masses, &v, &rows, &[0.0, 0.6]).unwrap();
        let momentum = |v: &[DVec2]| v[0] * masses[0] + v[1] * masses[1];
        let before = momentum(&v);
        let after = momentum(&rough.velocities);
        // The floor is frictionless: only its normal impulse changes the total.
        assert!((after.x - before.x).abs() < 1e-12, "{before} {after}");
        let kinetic = |v: &[DVec2]| {
            0.5 * (masses[0] * v[0].length_squared() + masses[1] * v[1].length_squared())
        };
        let smooth = resolve_frictional_impact(&masses, &v, &rows, &[0.0, 0.0]).unwrap();
        assert!(kinetic(&rough.velocities) <= kinetic(&smooth.velocities) + 1e-12);
        assert!(rough.tangential[1].abs() <= 0.6 * rough.normal[1] * (1.0 + 1e-12));
        // Every contact still meets its target.
        for row in &rows {
            assert!(row.relative(&rough.velocities) >= -1e-12);
        }
    }

    /// Each round starting from the last one's end finds what rounds solved from nothing find
    /// (the same staggered projections with every normal solve from nothing):
    /// the velocities agree to 1e-9 of the fastest speed over 2,000 random rows of balls on a
    /// floor, each touching the next, struck with random velocities, restitutions and
    /// frictions (at most as many contacts as freedoms, so the impulses are unique too).
    #[test]
    fn rounds_started_from_the_last_ones_end_agree_with_rounds_from_nothing() {
        use super::super::impact::resolve_impact_with_impulses;
        let from_nothing = |masses: &[f64], v: &[DVec2], rows: &[ContactRow], mus: &[f64]| {
            staggered(masses, v, rows, mus, |given| {
                resolve_impact_with_impulses(masses, given, rows)
            })
            .unwrap()
            .velocities
        };
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut rubbed = 0;
        for _ in 0..2000 {
            let balls = 2 + (next() * 5.0) as usize;
            let masses: Vec<f64> = (0..balls).map(|_| 0.5 + 2.0 * next()).collect();
            let v: Vec<DVec2> = (0..balls)
                .map(|_| DVec2::new(2.0 * next() - 1.0, 2.0 * next() - 1.0))
                .collect();
            let mut rows = Vec::new();
            for a in 0..balls {
                rows.push(wall(a, DVec2::Y));
                if a + 1 < balls {
                    let normal = DVec2::new(1.0, 0.6 * next() - 0.3).normalize();
                    rows.push(ContactRow {
                        a,
                        b: Some(a + 1),
                        normal,
                        target: 0.0,
                        slack: 0.0,
                    });
                }
            }
            let e = next();
            for row in &mut rows {
                row.target = e * (-row.relative(&v)).max(0.0);
            }
            let mus: Vec<f64> = (0..rows.len())
                .map(|_| if next() < 0.2 { 0.0 } else { next() })
                .collect();
            let warm = resolve_frictional_impact(&masses, &v, &rows, &mus).unwrap();
            let cold = from_nothing(&masses, &v, &rows, &mus);
            let speed = (v.iter().chain(&cold)).fold(0.0_f64, |s, x| s.max(x.length()));
            for (a, b) in warm.velocities.iter().zip(&cold) {
                assert!((*a - *b).length() <= 1e-9 * speed, "{a} against {b}");
            }
            if warm.tangential.iter().any(|&f| f != 0.0) {
                rubbed += 1;
            }
        }
        // Most of them with friction at work (a round after the first).
        assert!(rubbed > 1000, "{rubbed}");
    }
}
