//! The anti-stall rule: steering at deadlines, recalls, and the bound on a round's time.

mod common;

use common::*;
use onemorebrick::anti_stall::{STEER_SLOPE, round_time_bound};
use onemorebrick::{Board, Cell, Config, Game, GameState};

/// A straight-up ball with a 0.5 s deadline and no brick to hit: at 0.5 s it is at
/// y = 5.15 and is steered down at the steer slope; it then falls 5 cells at 10/s along a
/// line whose vertical speed is 10 / sqrt(1 + 0.25^2). The fall takes 0.515 s, so the next
/// deadline (at 1.0 s) steers it again, along the same line.
#[test]
fn a_ball_without_damage_is_steered_down_at_its_deadline() {
    let config = Config {
        stall_seconds: 0.5,
        fixed_launcher: None,
        ..Config::default()
    };
    let mut game = game_with(config, &[], 1);
    let report = play(&mut game, UP);
    assert_eq!(report.tally.steers, 2);
    let fall = 5.0 * (1.0 + STEER_SLOPE * STEER_SLOPE).sqrt() / 10.0;
    assert_close(report.tally.end_time, 0.5 + fall, ANALYTIC);
    // Landed 0.25 per cell fallen to the right of x = 3.5.
    assert_close(game.state().launch_x(), 3.5 + 5.0 * STEER_SLOPE, ANALYTIC);
}

#[test]
fn after_its_steers_a_ball_is_recalled() {
    let config = Config {
        stall_seconds: 0.5,
        stall_steers: 0,
        fixed_launcher: None,
        ..Config::default()
    };
    let mut game = game_with(config, &[], 1);
    let report = play(&mut game, UP);
    assert_eq!((report.tally.steers, report.tally.stall_recalls), (0, 1));
    assert_eq!(report.tally.end_time, 0.5);
    assert_eq!(
        game.state().launch_x(),
        3.5,
        "a recalled ball does not move the launcher"
    );
}

/// Damage moves the deadline: a ball bouncing on a brick of many hit points under a short
/// deadline is never steered while it keeps hitting.
#[test]
fn damage_resets_the_deadline() {
    let config = Config {
        stall_seconds: 0.8,
        ..config()
    };
    // Up 3.7 cells to the brick and back down: 0.74 s between hits and the floor, under the
    // 0.8 s deadline.
    let mut game = game_with(config, &[(3, 4, square(100))], 1);
    let report = play(&mut game, UP);
    assert_eq!(report.tally.steers, 0);
    assert_close(report.tally.end_time, 0.74, ANALYTIC);
}

/// A cage of obstacles and walls that no ball can damage: every round still ends within the
/// proven bound, whatever the shot.
#[test]
fn rounds_in_an_indestructible_cage_end_within_the_bound() {
    let config = Config {
        stall_seconds: 2.0,
        ..Config::default()
    };
    let mut board = Board::new(config.columns, config.rows);
    for row in 2..9 {
        for column in 0..7 {
            if (row + column) % 2 == 0 {
                board.set(column, row, Cell::Obstacle).unwrap();
            }
        }
    }
    let state = GameState::custom(config.clone(), board, 1, 12, 3).unwrap();
    for k in 0..16 {
        let mut game = Game::from_state(3, state.clone());
        let u = (f64::from(k) + 0.5) / 16.0;
        let aim = onemorebrick::bot::aim_at(u, k % 2 == 0, config.min_elevation_tan);
        let report = play(&mut game, aim);
        let bound = round_time_bound(&config, 12, 0);
        assert!(
            report.tally.end_time <= bound,
            "{} > {bound}",
            report.tally.end_time
        );
    }
}
