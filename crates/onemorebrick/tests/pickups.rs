//! Every pick-up's rule, on straight or simple shots whose paths are known exactly.

mod common;

use common::*;
use onemorebrick::{Aim, Cell, Config, PickupKind, Step};

/// Plays until the first sensor entry (the first event that is not a bounce is the entry
/// here: the shots below meet the pick-up before anything else).
fn until_first_event(game: &mut onemorebrick::Game) {
    while game.step(f64::INFINITY).unwrap() != Step::Event {}
}

/// A ball rising at x = 3.5 enters the pick-up at (3, 4) (radius 0.3) when its centre is
/// 0.45 below the pick-up's: y = 4.05, after 3.9 cells.
const ENTRY_TIME: f64 = 0.39;

#[test]
fn extra_ball_is_taken_at_once_and_counts_next_round() {
    let mut game = game_with(config(), &[(3, 4, pickup(PickupKind::ExtraBall))], 2);
    let report = play(&mut game, UP);
    assert_eq!(report.tally.extra_balls, 1, "the second ball finds it gone");
    assert_eq!(game.state().balls(), 3);
    assert_eq!(game.board().get(3, 3).unwrap(), Cell::Empty);
}

#[test]
fn split_makes_one_clone_that_does_not_count_as_a_ball() {
    // From (3.5, 0.15) along (1, 2): at y = 4.5 the centre is at x = 5.675, 0.175 from the
    // centre of cell (5, 4): inside the pick-up.
    let mut game = game_with(config(), &[(5, 4, pickup(PickupKind::Split))], 1);
    game.shoot(Aim::new(1.0, 2.0)).unwrap();
    until_first_event(&mut game);
    let balls = game.balls();
    assert_eq!(balls.len(), 2);
    assert!(balls[1].clone && !balls[0].clone);
    assert_eq!(balls[1].position, balls[0].position);
    assert_eq!(balls[1].velocity.x, -balls[0].velocity.x);
    assert_eq!(balls[1].velocity.y, balls[0].velocity.y);
    let report = game.finish_round().unwrap();
    assert_eq!(report.tally.clones, 1);
    assert_eq!(
        report.tally.collected, 1,
        "clones are not collected as balls"
    );
    assert_eq!(game.state().balls(), 1);
    assert_eq!(
        game.board().get(5, 3).unwrap(),
        Cell::Empty,
        "used: gone after the round"
    );
}

#[test]
fn hazard_takes_the_ball_out_for_this_round_only() {
    let mut game = game_with(config(), &[(3, 4, pickup(PickupKind::Hazard))], 1);
    let report = play(&mut game, UP);
    assert_eq!(report.tally.hazards, 1);
    assert_eq!(report.tally.collected, 0);
    assert_close(report.tally.end_time, ENTRY_TIME, ANALYTIC);
    assert_eq!(game.state().balls(), 1, "the ball is back next round");
}

#[test]
fn a_shield_absorbs_one_hazard() {
    let cells = [
        (3, 2, pickup(PickupKind::Shield)),
        (3, 4, pickup(PickupKind::Hazard)),
    ];
    let mut game = game_with(config(), &cells, 1);
    let report = play(&mut game, UP);
    assert_eq!(report.tally.shield_saves, 1);
    // Up through the hazard (shield spent), top wall, down through it again: taken out.
    assert_eq!(report.tally.hazards, 1);
    assert_eq!(report.tally.collected, 0);
}

#[test]
fn floor_bounce_sends_the_ball_up_once_more() {
    let mut game = game_with(config(), &[(3, 4, pickup(PickupKind::FloorBounce))], 1);
    let report = play(&mut game, UP);
    // Two full trips of 17.4 cells: the charge is spent at the floor, and passing the
    // pick-up again gives no second one.
    assert_close(report.tally.end_time, 3.48, ANALYTIC);
    assert_eq!(report.collisions, 4);
    assert_eq!(report.tally.collected, 1);
}

/// A ball rising at x = 0.5 passes a laser at (0, 4) twice (up and down) and bounces once
/// off the brick at (0, 7).
fn laser_board(kind: PickupKind) -> (onemorebrick::Game, onemorebrick::RoundReport) {
    let config = Config {
        fixed_launcher: Some(0.5),
        ..Config::default()
    };
    let cells = [
        (0, 4, pickup(kind)),
        (2, 4, square(5)),
        (5, 4, square(5)),
        (0, 7, square(5)),
    ];
    let mut game = game_with(config, &cells, 1);
    let report = play(&mut game, UP);
    (game, report)
}

#[test]
fn horizontal_laser_hits_every_brick_in_its_row_each_time_a_ball_enters() {
    let (game, report) = laser_board(PickupKind::LaserHorizontal);
    assert_eq!((report.tally.hits, report.tally.laser_damage), (1, 4));
    // Rows moved down by one after the round.
    let b = game.board();
    assert_eq!((hp_at(b, 2, 3), hp_at(b, 5, 3), hp_at(b, 0, 6)), (3, 3, 4));
}

#[test]
fn vertical_laser_hits_every_brick_in_its_column() {
    let (game, report) = laser_board(PickupKind::LaserVertical);
    assert_eq!((report.tally.hits, report.tally.laser_damage), (1, 2));
    let b = game.board();
    assert_eq!((hp_at(b, 2, 3), hp_at(b, 5, 3), hp_at(b, 0, 6)), (5, 5, 2));
}

#[test]
fn cross_laser_hits_row_and_column() {
    let (game, report) = laser_board(PickupKind::LaserCross);
    assert_eq!((report.tally.hits, report.tally.laser_damage), (1, 6));
    let b = game.board();
    assert_eq!((hp_at(b, 2, 3), hp_at(b, 5, 3), hp_at(b, 0, 6)), (3, 3, 2));
}

#[test]
fn random_direction_points_up_at_the_same_speed_and_is_seeded() {
    let direction = || {
        let mut game = game_with(config(), &[(3, 4, pickup(PickupKind::RandomDirection))], 1);
        game.shoot(UP).unwrap();
        until_first_event(&mut game);
        game.balls()[0].velocity
    };
    let v = direction();
    assert!(v.y > 0.0 && v.y >= 0.15 * v.x.abs(), "{v:?}");
    assert_close(v.length(), 10.0, 1e-12);
    assert_ne!(v.x, 0.0);
    assert_eq!(v, direction(), "the same seed draws the same direction");
}

#[test]
fn bigger_and_smaller_change_the_radius_in_place() {
    for (kind, radius) in [(PickupKind::Bigger, 0.225), (PickupKind::Smaller, 0.1)] {
        let mut game = game_with(config(), &[(3, 4, pickup(kind))], 1);
        game.shoot(UP).unwrap();
        until_first_event(&mut game);
        let ball = game.balls()[0];
        assert_eq!(ball.radius, radius, "{kind:?}");
        assert_close(ball.position.y, 4.05, 1e-12);
        assert_eq!(ball.position.x, 3.5);
        game.finish_round().unwrap();
    }
}

/// A grown ball would overlap the left wall: the engine refuses the placement and the ball
/// keeps its size (a ball never sits inside geometry).
#[test]
fn bigger_is_refused_where_the_grown_ball_would_overlap_a_wall() {
    let config = Config {
        fixed_launcher: Some(0.16),
        ..Config::default()
    };
    let mut game = game_with(config, &[(0, 4, pickup(PickupKind::Bigger))], 1);
    game.shoot(UP).unwrap();
    until_first_event(&mut game);
    assert_eq!(game.balls()[0].radius, 0.15);
    let report = game.finish_round().unwrap();
    assert_eq!(report.tally.refused_resizes, 2, "up and down");
}

#[test]
fn boost_multiplies_the_speed_once() {
    let mut game = game_with(config(), &[(3, 4, pickup(PickupKind::Boost))], 1);
    let report = play(&mut game, UP);
    // 3.9 cells at 10/s, then 4.8 up and 8.7 down at 15/s (the second pass adds nothing).
    assert_close(report.tally.end_time, ENTRY_TIME + 13.5 / 15.0, ANALYTIC);
}

#[test]
fn unused_pickups_stay_and_move_down_used_ones_leave() {
    let cells = [
        (3, 4, pickup(PickupKind::Boost)),
        (0, 4, pickup(PickupKind::Shield)),
    ];
    let mut game = game_with(config(), &cells, 1);
    play(&mut game, UP);
    assert_eq!(game.board().get(3, 3).unwrap(), Cell::Empty);
    assert_eq!(game.board().get(0, 3).unwrap(), pickup(PickupKind::Shield));
}

/// Straight up through two split pick-ups: the first splits the ball (the clone, mirrored
/// from a vertical velocity, follows the same line); at the second neither splits again, the
/// ball because it already split, the clone because clones never split.
#[test]
fn a_ball_splits_once_and_clones_never_split() {
    let cells = [
        (3, 3, pickup(PickupKind::Split)),
        (3, 5, pickup(PickupKind::Split)),
    ];
    let mut game = game_with(config(), &cells, 1);
    let report = play(&mut game, UP);
    assert_eq!(report.tally.clones, 1);
    assert_eq!(report.tally.collected, 1);
    assert_eq!(game.state().balls(), 1);
}
