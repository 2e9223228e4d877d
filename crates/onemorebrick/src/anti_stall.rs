//! The anti-stall rule: no ball bounces forever, and a round's simulated time is bounded.
//!
//! Two parts, both deterministic and independent of how the round is played (frames or at
//! once), because they act only at event times and at deadlines the rules compute:
//!
//! 1. **Minimum elevation.** After every bounce, a velocity flatter than the minimum elevation
//!    (`|vy| < t |vx|`, `t` = [`Config::min_elevation_tan`](crate::Config::min_elevation_tan))
//!    is turned to exactly that elevation, keeping its speed, its horizontal direction and its
//!    vertical direction (downward if `vy` is zero). A ball can never skim along a row.
//! 2. **Damage deadline.** Each ball has a deadline, `T` =
//!    [`Config::stall_seconds`](crate::Config::stall_seconds) after its launch or after the
//!    last time it damaged a brick (a hit, or a laser it triggered). At a deadline it is
//!    *steered down* ([`steer_down`]) and gets a new deadline `T` later; at the deadline after
//!    `k` = [`Config::stall_steers`](crate::Config::stall_steers) steers it is recalled (it
//!    returns as if collected, without setting the launch position). Steers are not reset by
//!    damage.
//!
//! **Bound.** Split a ball's life into periods that each end with damage, a steer or the
//! recall. Each lasts at most `T`; at most `d + k + 1` of them exist for a ball that does `d`
//! damage. A clone is born during its parent's life, so a parent and its clone end within
//! `(d_p + d_c + 2k + 2) T` of the parent's launch; a clone never splits. Damage in a round is
//! at most the board's total hit points `H`, and the last ball leaves at `(n - 1) dt`. So a
//! round of `n` balls ends by [`round_time_bound`]` = (n - 1) dt + (H + 2k + 2) T`. Hazards and
//! recalls only end balls sooner. The invariant tests check every round against it.

use exact2d::DVec2;

use crate::config::Config;

/// The horizontal slope of a steered-down ball: `(±0.25, -1)`, 14 degrees off vertical, so
/// it reaches the floor within a quarter cell sideways per cell down (it may still bounce off
/// a brick on the way: the next deadline handles that).
pub const STEER_SLOPE: f64 = 0.25;

/// Rule 1: the velocity `v` just after a bounce off a surface with normal `normal` (towards
/// the ball), turned to the minimum elevation if it is flatter than that.
///
/// Of the four directions at exactly the minimum elevation, `(±1, ±t)`, the first that
/// moves away from the surface (`c . normal > 0`) is taken, in the order: both signs of `v`
/// kept (a zero `vy` counts as downward), vertical sign flipped, horizontal flipped, both
/// flipped. Keeping the signs alone could turn a ball that just left the underside of a
/// round obstacle back into it, and the same contact would repeat at the same instant
/// forever. One of the four always moves away: opposite directions cannot both be
/// perpendicular to `normal` unless it is zero.
#[must_use]
pub fn enforce_elevation(
    v: DVec2,
    normal: DVec2,
    speed: f64,
    min_elevation_tan: f64,
) -> Option<DVec2> {
    if v.y.abs() >= min_elevation_tan * v.x.abs() {
        return None;
    }
    // A direction (1, t) has length sqrt(1 + t^2); scale it to the ball's nominal speed.
    let scale = speed / (1.0 + min_elevation_tan * min_elevation_tan).sqrt();
    let sy = if v.y > 0.0 { 1.0 } else { -1.0 };
    let sx = if v.x < 0.0 { -1.0 } else { 1.0 };
    let candidates = [(sx, sy), (sx, -sy), (-sx, sy), (-sx, -sy)];
    let direction = |(x, y): (f64, f64)| DVec2::new(x * scale, y * min_elevation_tan * scale);
    candidates
        .into_iter()
        .map(direction)
        .find(|c| c.dot(normal) > 0.0)
        .or(Some(direction(candidates[0])))
}

/// Rule 2's steer: downward at [`STEER_SLOPE`], keeping the horizontal direction and speed.
#[must_use]
pub fn steer_down(v: DVec2, speed: f64) -> DVec2 {
    let sx = if v.x < 0.0 { -1.0 } else { 1.0 };
    let scale = speed / (1.0 + STEER_SLOPE * STEER_SLOPE).sqrt();
    DVec2::new(sx * STEER_SLOPE * scale, -scale)
}

/// The most simulated time a round of `balls` balls on a board of `total_hp` hit points can
/// take (see the module documentation for the proof).
#[must_use]
pub fn round_time_bound(config: &Config, balls: u32, total_hp: u64) -> f64 {
    let launches = f64::from(balls.saturating_sub(1)) * config.launch_interval();
    let periods = total_hp as f64 + 2.0 * f64::from(config.stall_steers) + 2.0;
    launches + periods * config.stall_seconds
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flat_velocities_turn_to_the_minimum_elevation_keeping_directions() {
        let t = 0.15;
        let wall = DVec2::new(-1.0, 0.0);
        let v = enforce_elevation(DVec2::new(-10.0, 0.5), wall, 10.0, t).expect("flat");
        assert!(v.x < 0.0 && v.y > 0.0);
        assert!((v.y / v.x.abs() - t).abs() < 1e-15);
        assert!((v.length() - 10.0).abs() < 1e-14);
        let v = enforce_elevation(DVec2::new(-3.0, 0.0), wall, 3.0, t).expect("flat");
        assert!(v.y < 0.0, "a horizontal ball is turned downward");
        assert_eq!(enforce_elevation(DVec2::new(1.0, 0.5), wall, 1.1, t), None);
        assert_eq!(enforce_elevation(DVec2::new(0.0, -1.0), wall, 1.0, t), None);
    }

    /// Regression (found by the random-bot soak, seed 14): a ball left the underside of a
    /// round obstacle almost horizontally and slightly upward; the rule kept the vertical
    /// sign, turned it up, back into the obstacle, and the same contact repeated at the same
    /// instant forever. The normal below is that contact's.
    #[test]
    fn elevation_rule_turned_a_ball_back_into_an_obstacle() {
        let normal = DVec2::new(0.129_839_829_667_407_37, -0.991_534_981_042_998_1);
        let v = DVec2::new(9.99, 0.05);
        assert!(v.dot(normal) > 0.0, "a velocity that leaves the obstacle");
        let c = enforce_elevation(v, normal, 10.0, 0.15).expect("flat");
        assert!(c.dot(normal) > 0.0, "{c:?}");
        assert!(c.x > 0.0 && c.y < 0.0);
    }

    #[test]
    fn steering_points_down_at_the_ball_speed() {
        let v = steer_down(DVec2::new(-3.0, 4.0), 5.0);
        assert!(v.x < 0.0 && v.y < 0.0);
        assert!((v.length() - 5.0).abs() < 1e-14);
        assert_eq!(v.x / v.y, STEER_SLOPE);
    }
}
