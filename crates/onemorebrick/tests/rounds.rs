//! The round: phases, launch position, recall, the new row, game over, checkpoints, restart.

mod common;

use common::*;
use onemorebrick::{Aim, Cell, Checkpoint, Config, Game, GameError, Phase, PickupKind};

#[test]
fn commands_outside_their_phase_are_errors_not_panics() {
    let mut game = Game::new(Config::default(), 1).unwrap();
    assert!(matches!(game.recall(), Err(GameError::WrongPhase { .. })));
    assert!(matches!(
        game.finish_round(),
        Err(GameError::WrongPhase { .. })
    ));
    assert!(matches!(game.restart(), Err(GameError::WrongPhase { .. })));
    assert!(matches!(
        game.advance_to(1.0),
        Err(GameError::WrongPhase { .. })
    ));
    assert!(matches!(
        game.shoot(Aim::new(1.0, 0.0)),
        Err(GameError::InvalidAim(_))
    ));
    assert!(matches!(
        game.shoot(Aim::new(f64::NAN, 1.0)),
        Err(GameError::InvalidAim(_))
    ));
    assert_eq!(
        game.phase(),
        Phase::Aiming,
        "a refused shot changes nothing"
    );
    game.shoot(UP).unwrap();
    assert!(matches!(game.shoot(UP), Err(GameError::WrongPhase { .. })));
    game.advance_to(0.5).unwrap();
    assert!(matches!(
        game.advance_to(0.25),
        Err(GameError::TimeBeforeNow { .. })
    ));
    assert!(matches!(
        game.advance_to(f64::NAN),
        Err(GameError::TimeBeforeNow { .. })
    ));
}

#[test]
fn invalid_configurations_are_refused() {
    for config in [
        Config {
            columns: 2,
            ..Config::default()
        },
        Config {
            ball_radius: 0.0,
            ..Config::default()
        },
        Config {
            ball_speed: f64::NAN,
            ..Config::default()
        },
        Config {
            fixed_launcher: Some(0.1),
            ..Config::default()
        },
        Config {
            min_elevation_tan: -1.0,
            ..Config::default()
        },
    ] {
        assert!(matches!(
            Game::new(config, 1),
            Err(GameError::InvalidConfig(_))
        ));
    }
}

/// From x = 3.5 along (1, 3), the ball meets the right wall and the top and lands where the
/// mirror-folded straight line says: the unfolded path covers 17.4 cells up and down, so
/// 5.8 sideways, to x = 9.3, folded into [0.15, 6.85] at 13.4 - 9.15 + 0.15 = 4.4.
#[test]
fn the_first_ball_back_sets_the_next_launch_position() {
    let config = Config::default();
    let mut game = game_with(config, &[], 1);
    assert_eq!(game.state().launch_x(), 3.5);
    play(&mut game, Aim::new(1.0, 3.0));
    assert_close(game.state().launch_x(), 4.4, 1e-12);
}

#[test]
fn a_fixed_launcher_never_moves() {
    let mut game = game_with(config(), &[], 1);
    play(&mut game, Aim::new(1.0, 3.0));
    assert_eq!(game.state().launch_x(), 3.5);
}

#[test]
fn recall_returns_every_ball_at_once_launched_or_not() {
    let mut game = game_with(Config::default(), &[(3, 6, square(50))], 10);
    game.shoot(UP).unwrap();
    game.advance_to(0.2).unwrap();
    assert_eq!(
        game.balls().len(),
        5,
        "launched at 0, 0.045, 0.09, 0.135, 0.18"
    );
    assert_eq!(game.balls_waiting(), 5);
    let report = game.recall().unwrap();
    assert_eq!(report.tally.end_time, 0.2);
    assert_eq!(report.tally.collected, 0);
    assert_eq!(game.phase(), Phase::Aiming);
    assert_eq!(game.state().balls(), 10);
    assert_eq!(
        game.state().launch_x(),
        3.5,
        "no ball came back: the launcher stays"
    );
    assert!(game.balls().is_empty());
}

#[test]
fn after_a_round_rows_move_down_and_a_new_row_enters_at_the_top() {
    let mut game = Game::new(Config::default(), 11).unwrap();
    let before: Vec<Cell> = (0..7).map(|c| game.board().get(c, 8).unwrap()).collect();
    game.shoot(UP).unwrap();
    game.recall().unwrap();
    let moved: Vec<Cell> = (0..7).map(|c| game.board().get(c, 7).unwrap()).collect();
    assert_eq!(
        moved, before,
        "recalled before any hit: the row is unchanged, one lower"
    );
    let top: Vec<Cell> = (0..7).map(|c| game.board().get(c, 8).unwrap()).collect();
    let pickups = top.iter().filter(|c| matches!(c, Cell::Pickup(_))).count();
    let extra = top
        .iter()
        .filter(|c| matches!(c, Cell::Pickup(p) if p.kind == PickupKind::ExtraBall))
        .count();
    assert_eq!((pickups, extra), (2, 1));
    assert!(
        top.iter()
            .filter_map(Cell::brick)
            .all(|b| [2, 4, 6].contains(&b.hp))
    );
    assert_eq!(game.state().level(), 2);
}

#[test]
fn a_brick_reaching_the_bottom_row_ends_the_game() {
    let mut game = game_with(config(), &[(0, 1, square(100))], 1);
    let report = play(&mut game, UP);
    assert!(report.game_over);
    assert_eq!(game.phase(), Phase::GameOver);
    assert!(matches!(game.shoot(UP), Err(GameError::WrongPhase { .. })));
}

#[test]
fn clearing_the_board_sets_a_checkpoint_and_restart_uses_it() {
    let mut board_cells = vec![(3, 4, square(1))];
    board_cells.push((0, 2, pickup(PickupKind::Shield)));
    let state = {
        let config = config();
        let mut board = onemorebrick::Board::new(config.columns, config.rows);
        for &(c, r, cell) in &board_cells {
            board.set(c, r, cell).unwrap();
        }
        onemorebrick::GameState::custom(config, board, 5, 3, 4).unwrap()
    };
    let mut game = Game::from_state(4, state);
    let report = play(&mut game, UP);
    assert!(report.checkpoint_set);
    let checkpoint = Checkpoint { level: 6, balls: 3 };
    assert_eq!(game.state().checkpoint(), Some(checkpoint));
    // Recall at once, round after round, until the new rows reach the bottom.
    let mut rounds = 0;
    while game.phase() != Phase::GameOver {
        game.shoot(UP).unwrap();
        game.recall().unwrap();
        rounds += 1;
    }
    assert_eq!(
        rounds, 8,
        "a row needs 8 steps from the top row to the bottom"
    );
    let best = game.state().best_score();
    assert_eq!(best, 1);
    game.restart().unwrap();
    let state = game.state();
    assert_eq!((state.level(), state.balls(), state.score()), (6, 3, 0));
    assert_eq!(state.best_score(), best);
    assert!((0..8).all(|r| (0..7).all(|c| game.board().get(c, r).unwrap() == Cell::Empty)));
    assert!(game.board().bricks().count() > 0);
}

#[test]
fn without_a_checkpoint_restart_begins_at_level_one() {
    let mut game = game_with(config(), &[(0, 1, square(100)), (3, 5, square(9))], 4);
    play(&mut game, UP);
    assert_eq!(game.phase(), Phase::GameOver);
    game.restart().unwrap();
    assert_eq!((game.state().level(), game.state().balls()), (1, 1));
}

#[test]
fn score_is_damage_and_best_score_keeps_the_maximum() {
    let mut game = game_with(config(), &[(3, 4, square(5))], 3);
    let report = play(&mut game, UP);
    assert_eq!(report.tally.damage(), 3);
    assert_eq!(game.state().score(), 3);
    assert_eq!(game.state().best_score(), 3);
}

/// The preview follows the engine's bounces: straight up to the brick's underside at
/// y = 4 - 0.15, back down to the floor line, and up again; a brick does not lose hit points.
#[test]
fn the_aim_preview_traces_the_first_bounces() {
    let game = game_with(config(), &[(3, 4, square(3))], 1);
    let path = game.aim_preview(UP, 3).unwrap();
    let ys: Vec<f64> = path.iter().map(|p| p.y).collect();
    assert_eq!(path.len(), 4);
    assert!(path.iter().all(|p| p.x == 3.5));
    for (y, expected) in ys.iter().zip([0.15, 3.85, 0.15, 3.85]) {
        assert_close(*y, expected, ANALYTIC);
    }
    assert_eq!(hp_at(game.board(), 3, 4), 3);
    assert!(matches!(
        game.aim_preview(Aim::new(1.0, 0.0), 3),
        Err(GameError::InvalidAim(_))
    ));
}

#[test]
fn custom_states_that_break_the_rules_are_refused() {
    use onemorebrick::{Board, GameState};
    let small = Board::new(5, 5);
    let err = GameState::custom(Config::default(), small, 1, 1, 0)
        .err()
        .unwrap();
    assert!(matches!(err, GameError::InvalidState(_)), "{err}");
    let mut board = Board::new(7, 9);
    board.set(2, 0, Cell::Obstacle).unwrap();
    let err = GameState::custom(Config::default(), board, 1, 1, 0)
        .err()
        .unwrap();
    assert!(matches!(err, GameError::InvalidState(_)), "{err}");
    let board = Board::new(7, 9);
    let err = GameState::custom(Config::default(), board, 1, 0, 0)
        .err()
        .unwrap();
    assert!(matches!(err, GameError::InvalidState(_)), "{err}");
    assert!(Board::new(7, 9).set(7, 0, Cell::Obstacle).is_err());
}
