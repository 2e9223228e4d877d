//! The state of a game between volleys: everything a save file or a replay check needs.

use serde::{Deserialize, Serialize};

use crate::GameError;
use crate::board::Board;
use crate::cell::Cell;
use crate::config::Config;
use crate::rng::GameRng;
use crate::spawn::spawn_row;

/// A checkpoint: set when a round leaves the board without bricks; after a game over the
/// player may restart at this level with this many balls.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Checkpoint {
    /// The level to restart at.
    pub level: u32,
    /// The balls to restart with.
    pub balls: u32,
}

/// Running totals over the whole game (restarts included).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Totals {
    /// Volleys played.
    pub rounds: u32,
    /// Bricks destroyed.
    pub bricks_destroyed: u64,
    /// Hit points removed (hits plus laser damage).
    pub damage: u64,
    /// Collisions the engine handled.
    pub collisions: u64,
    /// Simulated seconds of volleys.
    pub simulated_seconds: f64,
}

/// Everything about a game when no volley is in flight.
///
/// **Score** is the hit points removed since the game (or the last restart) began: every
/// hit and every laser damage is one point. **Best score** is the highest score ever
/// reached; it survives restarts and is saved.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct GameState {
    pub(crate) config: Config,
    pub(crate) board: Board,
    pub(crate) rng: GameRng,
    pub(crate) level: u32,
    pub(crate) balls: u32,
    pub(crate) launch_x: f64,
    pub(crate) score: u64,
    pub(crate) best_score: u64,
    pub(crate) checkpoint: Option<Checkpoint>,
    pub(crate) game_over: bool,
    pub(crate) totals: Totals,
}

impl GameState {
    /// A new game: level 1, one ball, the first row drawn from `seed`.
    ///
    /// # Errors
    /// [`GameError::InvalidConfig`] if the configuration is invalid.
    pub fn new(config: Config, seed: u64) -> Result<Self, GameError> {
        config.validate()?;
        let mut rng = GameRng::from_seed(seed);
        let mut board = Board::new(config.columns, config.rows);
        spawn_row(&mut board, 1, &mut rng);
        Ok(Self::with(config, board, rng, 1, 1))
    }

    /// A game at `level` with `balls` balls on a board you built (tests, benchmarks,
    /// puzzles); the generator draws the following rows from `seed`.
    ///
    /// # Errors
    /// [`GameError::InvalidConfig`], or [`GameError::InvalidState`] if the board does not
    /// match the configuration's size, holds a brick with no hit points, a brick or an
    /// obstacle in the bottom row (the launcher's), or `level` or `balls` is zero.
    pub fn custom(
        config: Config,
        board: Board,
        level: u32,
        balls: u32,
        seed: u64,
    ) -> Result<Self, GameError> {
        config.validate()?;
        let state = Self::with(config, board, GameRng::from_seed(seed), level, balls);
        state.validate()?;
        Ok(state)
    }

    fn with(config: Config, board: Board, rng: GameRng, level: u32, balls: u32) -> Self {
        let launch_x = config.fixed_launcher.unwrap_or(config.width() / 2.0);
        Self {
            config,
            board,
            rng,
            level,
            balls,
            launch_x,
            score: 0,
            best_score: 0,
            checkpoint: None,
            game_over: false,
            totals: Totals::default(),
        }
    }

    /// Checks the invariants a loaded state must keep.
    ///
    /// # Errors
    /// [`GameError::InvalidConfig`] or [`GameError::InvalidState`] naming what is wrong.
    pub fn validate(&self) -> Result<(), GameError> {
        self.config.validate()?;
        let bad = |what: &str| Err(GameError::InvalidState(what.to_owned()));
        let board = &self.board;
        if board.columns() != self.config.columns
            || board.rows() != self.config.rows
            || board.cells().len() != (board.columns() * board.rows()) as usize
        {
            return bad("the board's size does not match the configuration");
        }
        if board.bricks().any(|(_, b)| b.hp == 0) {
            return bad("a brick has no hit points");
        }
        let bottom_blocked = (0..board.columns())
            .any(|c| matches!(board.get(c, 0), Some(Cell::Brick(_) | Cell::Obstacle)));
        if !self.game_over && bottom_blocked {
            return bad("a brick or an obstacle is in the bottom row of a game that is not over");
        }
        if self.level == 0 || self.balls == 0 {
            return bad("level and balls must be at least 1");
        }
        let r = self.config.ball_radius;
        if !(self.launch_x >= r && self.launch_x <= self.config.width() - r) {
            return bad("the launch position is outside the board");
        }
        if self.best_score < self.score {
            return bad("the best score is below the score");
        }
        Ok(())
    }

    /// The settings.
    #[must_use]
    pub fn config(&self) -> &Config {
        &self.config
    }

    /// The board.
    #[must_use]
    pub fn board(&self) -> &Board {
        &self.board
    }

    /// The level about to be played (or, after a game over, the level that ended it).
    #[must_use]
    pub fn level(&self) -> u32 {
        self.level
    }

    /// The balls of the next volley (clones never count).
    #[must_use]
    pub fn balls(&self) -> u32 {
        self.balls
    }

    /// Where the next volley leaves from (x; balls start touching the floor).
    #[must_use]
    pub fn launch_x(&self) -> f64 {
        self.launch_x
    }

    /// The score (see the type's documentation).
    #[must_use]
    pub fn score(&self) -> u64 {
        self.score
    }

    /// The best score.
    #[must_use]
    pub fn best_score(&self) -> u64 {
        self.best_score
    }

    /// The last checkpoint, if any.
    #[must_use]
    pub fn checkpoint(&self) -> Option<Checkpoint> {
        self.checkpoint
    }

    /// Whether a brick reached the bottom row.
    #[must_use]
    pub fn is_game_over(&self) -> bool {
        self.game_over
    }

    /// Running totals.
    #[must_use]
    pub fn totals(&self) -> &Totals {
        &self.totals
    }

    /// The generator (its state is part of the game).
    #[must_use]
    pub fn rng(&self) -> &GameRng {
        &self.rng
    }
}
