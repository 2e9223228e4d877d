//! Helpers shared by the rules tests: custom boards, one-call rounds, analytic tolerances.
#![allow(dead_code)]

use onemorebrick::{
    Aim, Board, Brick, Cell, Config, Game, GameState, Pickup, PickupKind, RoundReport, Shape,
};

/// Analytic times and positions in these tests are a few roundings of numbers of order 1-10:
/// they agree with the engine to well under 1e-12.
pub const ANALYTIC: f64 = 1e-12;

/// Straight up.
pub const UP: Aim = Aim { dx: 0.0, dy: 1.0 };

/// The default settings with the launcher fixed at the middle of column 3 (x = 3.5), so
/// straight-up shots run along the centre of that column.
pub fn config() -> Config {
    Config {
        fixed_launcher: Some(3.5),
        ..Config::default()
    }
}

/// A game on a board holding only `cells`, at level 1.
pub fn game_with(config: Config, cells: &[(u32, u32, Cell)], balls: u32) -> Game {
    let mut board = Board::new(config.columns, config.rows);
    for &(column, row, cell) in cells {
        board.set(column, row, cell).unwrap();
    }
    let state = GameState::custom(config, board, 1, balls, 99).expect("a valid custom game");
    Game::from_state(99, state)
}

/// A square brick.
pub fn square(hp: u32) -> Cell {
    Cell::Brick(Brick {
        shape: Shape::Square,
        hp,
    })
}

/// An unused pick-up.
pub fn pickup(kind: PickupKind) -> Cell {
    Cell::Pickup(Pickup::new(kind))
}

/// Shoots and finishes the round.
pub fn play(game: &mut Game, aim: Aim) -> RoundReport {
    game.shoot(aim).expect("a valid shot");
    game.finish_round().expect("the round ends")
}

/// Asserts `|a - b| <= tol`.
#[track_caller]
pub fn assert_close(a: f64, b: f64, tol: f64) {
    assert!(
        (a - b).abs() <= tol,
        "{a} vs {b} (difference {})",
        (a - b).abs()
    );
}

/// The hit points of the brick at `(column, row)` (0 if none).
pub fn hp_at(board: &Board, column: u32, row: u32) -> u32 {
    board.get(column, row).unwrap().brick().map_or(0, |b| b.hp)
}
