//! A round: Aiming -> Volley -> RoundOver (resolved at once) -> Aiming, or GameOver.
//!
//! Resolving a round, in order:
//! 1. the volley's board replaces the game's (bricks lost hit points, some are gone);
//! 2. +1 balls taken are added; the launch position becomes the first ball back's (unless
//!    the launcher is fixed, or no ball came back at the floor line);
//! 3. the score grows by the damage dealt; the best score follows it;
//! 4. used pick-ups leave; every row moves down one step (see
//!    [`Board::shift_down`](crate::Board::shift_down));
//! 5. a brick in the bottom row ends the game, and the level stays the one just played (the
//!    level that ended it); otherwise the level goes up, a board without bricks sets a
//!    checkpoint (this level, these balls), and a new row enters at the top.

use serde::{Deserialize, Serialize};

use crate::board::Board;
use crate::rng::GameRng;
use crate::spawn::spawn_row;
use crate::state::{Checkpoint, GameState};
use crate::volley::Tally;

/// Where a game is in its round.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Phase {
    /// Waiting for a shot.
    Aiming,
    /// Balls are in flight (or waiting to be launched).
    Volley,
    /// A brick reached the bottom row; only a restart is possible.
    GameOver,
}

/// What a round did, reported when it is resolved.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoundReport {
    /// The level that was played.
    pub level: u32,
    /// Balls launched.
    pub balls: u32,
    /// The volley's counts.
    pub tally: Tally,
    /// Collisions the engine handled.
    pub collisions: u64,
    /// Whether this round set a checkpoint.
    pub checkpoint_set: bool,
    /// Whether this round ended the game.
    pub game_over: bool,
}

/// Resolves a finished volley into the next state (see the module documentation).
pub(crate) fn resolve(
    state: &mut GameState,
    board: Board,
    rng: GameRng,
    tally: Tally,
    collisions: u64,
) -> RoundReport {
    let (level, balls) = (state.level, state.balls);
    state.board = board;
    state.rng = rng;
    state.balls += tally.extra_balls;
    if state.config.fixed_launcher.is_none() {
        state.launch_x = tally.first_back_x.unwrap_or(state.launch_x);
    }
    state.score += tally.damage();
    state.best_score = state.best_score.max(state.score);
    add_totals(state, &tally, collisions);
    let checkpoint_set = advance_rows(state);
    RoundReport {
        level,
        balls,
        tally,
        collisions,
        checkpoint_set,
        game_over: state.game_over,
    }
}

/// Used pick-ups leave, the rows move down; then game over (the level stays the one that
/// ended it), or the level goes up, a checkpoint if the board is clear, and a new row.
/// Returns whether a checkpoint was set.
fn advance_rows(state: &mut GameState) -> bool {
    state.board.remove_used_pickups();
    let shift = state.board.shift_down();
    state.balls += shift.extra_balls;
    if shift.brick_reached_bottom {
        state.game_over = true;
        return false;
    }
    state.level += 1;
    let clear = state.board.is_clear();
    if clear {
        state.checkpoint = Some(Checkpoint {
            level: state.level,
            balls: state.balls,
        });
    }
    spawn_row(&mut state.board, state.level, &mut state.rng);
    clear
}

fn add_totals(state: &mut GameState, tally: &Tally, collisions: u64) {
    let totals = &mut state.totals;
    totals.rounds += 1;
    totals.bricks_destroyed += u64::from(tally.bricks_destroyed);
    totals.damage += tally.damage();
    totals.collisions += collisions;
    totals.simulated_seconds += tally.end_time;
}

/// Starts again after a game over: from the checkpoint if there is one (its level and
/// balls), else from level 1 with one ball. The board is emptied and a new row drawn; the
/// score starts from zero, the best score and the generator go on.
pub(crate) fn restart(state: &mut GameState) {
    let Checkpoint { level, balls } = state
        .checkpoint
        .unwrap_or(Checkpoint { level: 1, balls: 1 });
    state.level = level;
    state.balls = balls;
    state.score = 0;
    state.game_over = false;
    state.launch_x = state
        .config
        .fixed_launcher
        .unwrap_or(state.config.width() / 2.0);
    state.board = Board::new(state.config.columns, state.config.rows);
    spawn_row(&mut state.board, level, &mut state.rng);
}
