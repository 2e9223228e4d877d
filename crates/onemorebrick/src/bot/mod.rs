//! Bots: players that choose a shot. They soak-test the rules and the engine, and drive the
//! `onemorebrick sim` command.
//!
//! Directions are built without trigonometry, so a bot chooses the same bits on every
//! platform: the upward unit vector at angle `2 atan(s)` from the horizontal is
//! `((1 - s^2), 2 s) / (1 + s^2)` (the half-angle substitution); the bots use the unscaled
//! vector `(1 - s^2, 2 s)` (an aim may have any length) with `s` between
//! `s_min = t / (1 + sqrt(1 + t^2))` (the minimum elevation, `t` its tangent) and 1
//! (straight up), mirrored for the left half.

mod greedy;
mod random;

pub use greedy::GreedyBot;
pub use random::RandomBot;

use crate::GameError;
use crate::aim::Aim;
use crate::game::Game;

/// A player.
pub trait Bot {
    /// The shot to take now (the game is in [`Phase::Aiming`](crate::Phase::Aiming)).
    ///
    /// # Errors
    /// If simulating candidate shots fails (an engine refusal: a bug).
    fn choose(&mut self, game: &Game) -> Result<Aim, GameError>;
}

/// The aim at parameter `u` in `[0, 1]` on one side: `u = 0` is the minimum elevation,
/// `u = 1` straight up; `left` mirrors it.
#[must_use]
pub fn aim_at(u: f64, left: bool, min_elevation_tan: f64) -> Aim {
    let t = min_elevation_tan;
    let s_min = t / (1.0 + (1.0 + t * t).sqrt());
    let s = s_min + (1.0 - s_min) * u;
    let dx = 1.0 - s * s;
    Aim::new(if left { -dx } else { dx }, 2.0 * s)
}

/// `count` aims spread over both sides, left to right, none exactly at the minimum elevation
/// (rounding could make that one flatter than allowed) nor straight up twice.
#[must_use]
pub fn fan(count: u32, min_elevation_tan: f64) -> Vec<Aim> {
    let per_side = count.div_ceil(2).max(1);
    let u = |k: u32| (f64::from(k) + 0.5) / f64::from(per_side);
    let left = (0..per_side).map(|k| aim_at(u(k), true, min_elevation_tan));
    let right = (0..per_side)
        .rev()
        .map(|k| aim_at(u(k), false, min_elevation_tan));
    left.chain(right).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_fan_is_valid_and_spans_both_sides() {
        let aims = fan(32, 0.15);
        assert_eq!(aims.len(), 32);
        assert!(aims.iter().all(|a| a.validate(0.15).is_ok()));
        assert!(aims.windows(2).all(|w| w[0].dx < w[1].dx), "left to right");
        // The extreme aims are within a few degrees of the minimum elevation.
        assert!(aims[0].dy / aims[0].dx.abs() < 0.25);
    }

    #[test]
    fn the_half_angle_form_reaches_the_minimum_elevation() {
        let aim = aim_at(0.0, false, 0.15);
        assert!((aim.dy / aim.dx - 0.15).abs() < 1e-15);
    }
}
