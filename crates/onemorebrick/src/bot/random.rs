//! The random bot: a uniformly drawn side and parameter, from its own seeded generator.

use super::{Bot, aim_at};
use crate::GameError;
use crate::aim::Aim;
use crate::game::Game;
use crate::rng::GameRng;

/// How far (in the parameter of [`aim_at`]) random aims stay above the minimum elevation:
/// `u = 0` sits exactly on it, where rounding may put the aim just below and the game would
/// reject it; 1e-6 is about 1e-6 radians, far above rounding and invisible in play.
const ELEVATION_MARGIN: f64 = 1e-6;

/// Shoots in a random direction (its own generator, so it never disturbs the game's).
#[derive(Clone, Debug)]
pub struct RandomBot {
    rng: GameRng,
}

impl RandomBot {
    /// A random bot from a seed.
    #[must_use]
    pub fn new(seed: u64) -> Self {
        Self {
            rng: GameRng::from_seed(seed),
        }
    }
}

impl Bot for RandomBot {
    fn choose(&mut self, game: &Game) -> Result<Aim, GameError> {
        let u = ELEVATION_MARGIN + (1.0 - ELEVATION_MARGIN) * self.rng.unit();
        let left = self.rng.chance(1, 2);
        Ok(aim_at(u, left, game.state().config().min_elevation_tan))
    }
}
