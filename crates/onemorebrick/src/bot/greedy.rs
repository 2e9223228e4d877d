//! The greedy bot: plays every candidate shot to the end with the exact engine and takes
//! the best.

use super::{Bot, fan};
use crate::GameError;
use crate::aim::Aim;
use crate::game::Game;
use crate::round::RoundReport;
use crate::state::GameState;

/// Tries a fan of shots ([`fan`]) on copies of the game, each played to the end of the
/// round, and takes the best by [`GreedyBot::score`]; ties go to the leftmost candidate.
#[derive(Clone, Debug)]
pub struct GreedyBot {
    candidates: u32,
    simulated_collisions: u64,
}

impl GreedyBot {
    /// A greedy bot trying `candidates` directions (at least 2).
    #[must_use]
    pub fn new(candidates: u32) -> Self {
        Self {
            candidates: candidates.max(2),
            simulated_collisions: 0,
        }
    }

    /// Collisions the engine handled in all the trial rounds so far (a benchmark figure).
    #[must_use]
    pub fn simulated_collisions(&self) -> u64 {
        self.simulated_collisions
    }

    /// How good a round's outcome is: a game over is the worst; otherwise 100 per brick
    /// destroyed, 1 per hit point removed, 50 per ball gained, minus 200 per brick left one
    /// step from the bottom (it ends the game next round unless destroyed).
    #[must_use]
    pub fn score(report: &RoundReport, after: &GameState) -> i64 {
        if report.game_over {
            return i64::MIN;
        }
        let t = &report.tally;
        let gained = i64::from(after.balls()) - i64::from(report.balls);
        let board = after.board();
        let danger = board
            .bricks()
            .filter(|&(i, _)| board.position(i).1 == 1)
            .count() as i64;
        100 * i64::from(t.bricks_destroyed) + t.damage() as i64 + 50 * gained - 200 * danger
    }
}

impl Bot for GreedyBot {
    fn choose(&mut self, game: &Game) -> Result<Aim, GameError> {
        let aims = fan(self.candidates, game.state().config().min_elevation_tan);
        let mut best: Option<(i64, Aim)> = None;
        for aim in aims {
            let (report, after) = game.preview(aim)?;
            self.simulated_collisions += report.collisions;
            let score = Self::score(&report, &after);
            if best.is_none_or(|(b, _)| score > b) {
                best = Some((score, aim));
            }
        }
        Ok(best.expect("at least two candidates").1)
    }
}
