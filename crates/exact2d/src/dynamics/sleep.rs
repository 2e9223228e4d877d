//! Sleep: when a ball at rest on what it touches may stop costing anything, and which pushes
//! what holds it can take.
//!
//! A ball touches surfaces (segments, end points, static circles, sleeping balls) with unit
//! normals `n_i`, each from the surface to its centre; frictionless, each can push it along
//! `n_i`, never pull it. Under gravity `g` it can stay where it is exactly when some pushes
//! `l_i >= 0` balance its weight, `m g + sum_i l_i n_i = 0`: when `-g` lies in the cone of
//! the normals (the projection of `g` onto the cone `{a : a . n_i >= 0}` of `dynamics/hold.rs`
//! is zero). In the plane that cone is spanned by one normal (`-g` along it: a level floor,
//! the top of a peg) or by two at an angle below a half turn (`-g` between them: a wedge, a
//! pocket of two balls).
//!
//! # The sleep criterion
//!
//! A ball *sleeps* when, at one of its events,
//! 1. it rests on what it touches, `-g` in the cone of their normals to within [`PARALLEL`]
//!    of `|g|` (sine 1e-9: a floor tilted by 1e-9 radians holds it, far below any slope a
//!    scene means, far above the rounding of unit normals, 1e-16), and
//! 2. it is slow: its speed is at most [`SLEEP_SPEED`] `sqrt(|g| r)` (1e-2 of the speed a
//!    ball reaches falling a height of `r / 2`), and
//! 3. what holds it is static: the contacts of (1) are colliders and sleeping balls (an
//!    awake ball touching it meets it as a static circle from then on).
//!
//! A resting ball under (1) can only move by the velocity along a surface left to it (a
//! frictionless floor keeps a slide for ever); (2) drops that velocity once it is too small to
//! matter: at `SLEEP_SPEED sqrt(|g| r)` a ball takes `100 sqrt(r / |g|)` to move its own
//! radius (14 s for a ball of radius 0.2 m on Earth, moving at 1.4 cm/s; for a ball of
//! radius 20 px under 2000 px/s^2, 2 px a second). It is the scale at which game engines let
//! bodies sleep (Box2D's linear sleep tolerance is 1 cm/s), and it only ever removes kinetic
//! energy. A ball balanced on the top of a peg or a ball sleeps too: the balance is exact, and
//! it stays.
//!
//! # What a sleeping ball can take
//!
//! To every other ball a sleeping ball is a static circle at its position. A ball that meets
//! it pushes it along `-d`, `d` the unit vector from the sleeper's centre to the mover's. Its
//! contacts take that push if `d` is in the cone of their normals, `d = sum_i l_i n_i` with
//! `l_i >= 0` (only the direction matters for an impulse: the finite weight is negligible
//! against it). The push is passed on, `l_i` of it, to each contact: a static collider takes
//! anything; a sleeping ball under it is pushed along `-n_i` and must take that in turn, the
//! same way ([`takes`] follows the chain). The mover then bounces off the sleeper as off a
//! static circle, with the pair's restitution; a push the chain cannot take wakes the sleeper
//! and is a normal collision of two balls.
//!
//! A push too gentle to matter is taken whatever its direction ([`gentle`]): a mover of mass
//! `m` meeting a sleeper of mass `M` at normal speed `u` would give it at most
//! `(1 + e) m u / (m + M) <= 2 m u / (m + M)` in a collision of two balls; when that is at
//! most the sleeper's sleep speed, it is a velocity that criterion (2) drops, and waking the
//! sleeper for it would only start it moving at a speed at which it falls asleep again. So a
//! slow ball landing on a pile rests on it instead of waking it, as a time-stepped engine's
//! sleeping island ignores a contact below its sleep tolerance.

use glam::DVec2;

use super::hold::PARALLEL;
use super::time::Time;
use crate::geometry::ColliderHandle;

/// What the world keeps of a sleeping ball (in its rarely used data).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Sleep {
    /// The static circle it is to every other ball while it sleeps.
    pub proxy: ColliderHandle,
    /// When it fell asleep.
    pub since: Time,
    /// What it rests on and against when it fell asleep (colliders, and the circles of balls
    /// asleep before it), with the unit normal from each to its centre; a contact is dropped
    /// when it goes away, and the ball wakes if the rest no longer hold it.
    pub contacts: Vec<(ColliderHandle, DVec2)>,
    /// The balls asleep on or against it: their contacts list its circle.
    pub dependents: Vec<u32>,
}

/// A ball is slow enough to sleep at `SLEEP_SPEED sqrt(|g| r)`: `1e-2` (see the module
/// documentation).
pub const SLEEP_SPEED: f64 = 1e-2;

/// The speed at or below which a ball of `radius` under gravity of magnitude `g` is slow
/// enough to sleep (see [`SLEEP_SPEED`]).
#[must_use]
pub(crate) fn sleep_speed(g: f64, radius: f64) -> f64 {
    SLEEP_SPEED * (g * radius).sqrt()
}

/// Whether contacts of unit normals `normals` hold a ball against `gravity` where it is: `-g`
/// in their cone, to within [`PARALLEL`] (see the module documentation).
#[must_use]
pub(crate) fn rests(gravity: DVec2, normals: &[DVec2]) -> bool {
    let g = gravity.length();
    g > 0.0 && in_cone(-gravity / g, normals).is_some()
}

/// How the unit direction `d` is made of the unit normals `normals`, if it is in their cone
/// to within [`PARALLEL`]: one normal along it (index, weight 1), or two at an angle below a
/// half turn with `d` between them (indices and non-negative weights).
pub(crate) fn in_cone(d: DVec2, normals: &[DVec2]) -> Option<[(usize, f64); 2]> {
    // Along one normal (within the tolerance's angle).
    if let Some(k) = normals
        .iter()
        .position(|&n| n.dot(d) > 0.0 && n.perp_dot(d).abs() <= PARALLEL)
    {
        return Some([(k, 1.0), (k, 0.0)]);
    }
    // Between two: `a` clockwise of `d`, `b` counter-clockwise, less than a half turn apart.
    for (a, &na) in normals.iter().enumerate() {
        for (b, &nb) in normals.iter().enumerate() {
            let span = na.perp_dot(nb);
            if a == b || span <= PARALLEL {
                continue;
            }
            let wa = d.perp_dot(nb);
            let wb = na.perp_dot(d);
            if wa >= -PARALLEL && wb >= -PARALLEL {
                return Some([(a, wa.max(0.0) / span), (b, wb.max(0.0) / span)]);
            }
        }
    }
    None
}

/// Whether a push is too gentle to wake a sleeper of mass `sleeper_mass` and sleep speed
/// `sleep_speed` (see the module documentation): a mover of mass `mover_mass` meeting it at
/// normal speed `speed` would give it at most `2 m u / (m + M)`, no more than that speed.
#[must_use]
pub(crate) fn gentle(speed: f64, mover_mass: f64, sleeper_mass: f64, sleep_speed: f64) -> bool {
    2.0 * mover_mass * speed <= sleep_speed * (mover_mass + sleeper_mass)
}

/// How many sleeping balls one push may be followed through before it is taken as held (a
/// deep pile passes a push on through every layer; the budget bounds the work of one impact).
pub(crate) const PUSH_BUDGET: usize = 256;

/// Whether the contacts of a sleeper take a push from direction `d` (unit, from its centre to
/// the pusher), following the push through the sleeping balls under it: `contacts(body)` gives
/// a body's contact normals and, for each, the sleeper behind it if it is one (`None`: a
/// static collider). `body` is the sleeper pushed. A chain deeper than [`PUSH_BUDGET`]
/// sleepers, or one that comes back to a sleeper it passed, counts as held.
pub(crate) fn takes<F>(body: u32, d: DVec2, contacts: &F) -> bool
where
    F: Fn(u32) -> Vec<(DVec2, Option<u32>)>,
{
    let mut budget = PUSH_BUDGET;
    let mut path = Vec::new();
    takes_from(body, d, contacts, &mut budget, &mut path)
}

fn takes_from<F>(body: u32, d: DVec2, contacts: &F, budget: &mut usize, path: &mut Vec<u32>) -> bool
where
    F: Fn(u32) -> Vec<(DVec2, Option<u32>)>,
{
    if *budget == 0 || path.contains(&body) {
        return true;
    }
    *budget -= 1;
    let list = contacts(body);
    let normals: Vec<DVec2> = list.iter().map(|&(n, _)| n).collect();
    let Some(shares) = in_cone(d, &normals) else {
        return false;
    };
    path.push(body);
    let held = shares.iter().all(|&(k, weight)| {
        weight <= 0.0
            || match list[k].1 {
                None => true,
                Some(next) => takes_from(next, normals[k], contacts, budget, path),
            }
    });
    path.pop();
    held
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit(degrees: f64) -> DVec2 {
        let a = degrees.to_radians();
        DVec2::new(a.cos(), a.sin())
    }

    #[test]
    fn a_floor_holds_a_ball_and_a_tilted_one_does_not() {
        let g = DVec2::new(0.0, -9.81);
        assert!(rests(g, &[DVec2::Y]));
        assert!(!rests(g, &[unit(89.0)]));
        assert!(!rests(g, &[]));
        assert!(!rests(DVec2::ZERO, &[DVec2::Y]));
        // Within the tolerance's angle (sine 1e-9), a floor is level.
        assert!(rests(g, &[unit(90.0 + 0.5e-9_f64.to_degrees())]));
    }

    #[test]
    fn a_pocket_of_two_balls_holds_a_ball_and_two_walls_apart_do_not() {
        let g = DVec2::new(0.0, -1.0);
        assert!(rests(g, &[unit(60.0), unit(120.0)]));
        assert!(!rests(g, &[unit(30.0), unit(60.0)]));
        // An exact-fit channel: opposite walls hold nothing up.
        assert!(!rests(g, &[DVec2::X, -DVec2::X]));
        // Three at a third of a turn hold any push.
        let all = [unit(90.0), unit(210.0), unit(330.0)];
        for k in 0..36 {
            assert!(in_cone(unit(f64::from(k) * 10.0), &all).is_some());
        }
    }

    #[test]
    fn the_weights_rebuild_the_direction() {
        let normals = [unit(20.0), unit(100.0), unit(170.0)];
        let d = unit(70.0);
        let shares = in_cone(d, &normals).expect("in the cone");
        let rebuilt: DVec2 = shares.iter().map(|&(k, w)| normals[k] * w).sum();
        assert!(
            (rebuilt.normalize() - d).length() < 1e-12,
            "{rebuilt} against {d}"
        );
        assert!(shares.iter().all(|&(_, w)| w >= 0.0));
    }

    #[test]
    fn a_push_is_followed_through_the_sleepers_under_it() {
        // Ball 0 rests in the pocket of balls 1 and 2, each on a floor; ball 2 also against a
        // wall on its right. A push straight down on 0 reaches 1 and 2 along their normals to
        // 0, down and outwards: 2's wall takes its part, 1 has nothing on its left.
        let contacts = |body: u32| match body {
            0 => vec![(unit(60.0), Some(1)), (unit(120.0), Some(2))],
            1 => vec![(DVec2::Y, None)],
            2 => vec![(DVec2::Y, None), (-DVec2::X, None)],
            _ => Vec::new(),
        };
        // Ball 1 alone on the floor cannot take the push down and to the left.
        assert!(!takes(0, DVec2::Y, &contacts));
        // Nor directly, from up and to the right.
        assert!(!takes(1, unit(60.0), &contacts));
        // Ball 2 can: the wall and the floor take it.
        assert!(takes(2, unit(120.0), &contacts));
        // A push along 0's normal to 2 alone goes into 2 only.
        assert!(takes(0, unit(120.0), &contacts));
        // Straight down onto a ball on the floor: taken.
        assert!(takes(1, DVec2::Y, &contacts));
        // Sideways onto a ball on the floor: not taken.
        assert!(!takes(1, DVec2::X, &contacts));
    }

    #[test]
    fn a_cycle_of_sleepers_or_a_deep_chain_counts_as_held() {
        let cycle = |body: u32| vec![(DVec2::Y, Some(1 - body))];
        assert!(takes(0, DVec2::Y, &cycle));
        let chain = |body: u32| vec![(DVec2::Y, Some(body + 1))];
        assert!(takes(0, DVec2::Y, &chain));
    }
}
