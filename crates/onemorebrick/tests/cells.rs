//! Every cell kind against an analytic answer: straight-up shots from x = 3.5 travel a known
//! distance at 10 cells per second.

mod common;

use common::*;
use onemorebrick::{Cell, Corner, Phase, Shape, Step};

/// A square brick takes one hit point per bounce; the ball comes straight back. The board
/// has moved down a row after the round, so the brick is one row lower.
#[test]
fn a_square_brick_loses_one_hit_point_per_bounce() {
    let mut game = game_with(config(), &[(3, 4, square(3))], 1);
    let report = play(&mut game, UP);
    assert_eq!(report.tally.hits, 1);
    assert_eq!(hp_at(game.board(), 3, 3), 2);
    // Up from y = 0.15 to 4 - 0.15 and back: 7.4 cells.
    assert_close(report.tally.end_time, 0.74, ANALYTIC);
}

/// A brick at zero leaves at once: the second ball of the volley flies through its cell to
/// the top wall.
#[test]
fn a_destroyed_brick_leaves_the_world_at_once() {
    let mut game = game_with(config(), &[(3, 4, square(1))], 2);
    let report = play(&mut game, UP);
    assert_eq!(report.tally.hits, 1);
    assert_eq!(report.tally.bricks_destroyed, 1);
    let board = game.board();
    assert!(
        board.bricks().all(|(i, _)| board.position(i).1 == 8),
        "only the new row"
    );
    // The second ball leaves 0.045 s later (1.5 diameters of 0.3 at 10/s) and travels 2 x
    // 8.7 cells.
    let interval = config().launch_interval();
    assert_close(interval, 0.045, 1e-15);
    assert_close(report.tally.end_time, interval + 1.74, ANALYTIC);
}

/// A triangle with its bottom-left corner open meets a rising ball with its 45-degree
/// hypotenuse: the ball leaves horizontally, and the minimum-elevation rule turns it down to
/// exactly that elevation (horizontal: vertical direction taken as downward).
#[test]
fn a_triangle_reflects_off_its_hypotenuse_and_the_elevation_rule_applies() {
    let triangle = Cell::Brick(onemorebrick::Brick {
        shape: Shape::Triangle(Corner::BottomLeft),
        hp: 5,
    });
    let mut game = game_with(config(), &[(3, 4, triangle)], 1);
    game.shoot(UP).unwrap();
    while game.step(f64::INFINITY).unwrap() != Step::Event {}
    let ball = game.balls()[0];
    // The hypotenuse runs from (4, 4) to (3, 5): x + y = 8; touching at distance 0.15.
    assert_close(ball.position.y, 4.5 - 0.15 * 2f64.sqrt(), 1e-12);
    assert!(
        ball.velocity.x < 0.0 && ball.velocity.y < 0.0,
        "{:?}",
        ball.velocity
    );
    assert_close(ball.velocity.y / ball.velocity.x, 0.15, 1e-15);
    assert_close(ball.velocity.length(), 10.0, 1e-12);
    assert_eq!(hp_at(game.board(), 3, 4), 4);
}

/// A triangle with a top corner open keeps its whole bottom edge: a rising ball under the
/// cell's centre is hit there, as by a square.
#[test]
fn triangles_with_a_top_corner_open_are_hit_on_their_flat_bottom() {
    for corner in [Corner::TopLeft, Corner::TopRight] {
        let triangle = Cell::Brick(onemorebrick::Brick {
            shape: Shape::Triangle(corner),
            hp: 5,
        });
        let mut game = game_with(config(), &[(3, 4, triangle)], 1);
        let report = play(&mut game, UP);
        assert_eq!(report.tally.hits, 1, "{corner:?}");
        assert_close(report.tally.end_time, 0.74, ANALYTIC);
    }
}

/// A round obstacle (radius 0.42) is never destroyed; a ball rising under its centre meets it
/// at y = 4.5 - 0.42 - 0.15 and falls straight back.
#[test]
fn an_obstacle_bounces_balls_and_is_never_destroyed() {
    let mut game = game_with(config(), &[(3, 4, Cell::Obstacle)], 3);
    let report = play(&mut game, UP);
    assert_eq!(report.tally.hits, 0);
    assert_eq!(report.tally.damage(), 0);
    assert_eq!(game.board().get(3, 3).unwrap(), Cell::Obstacle);
    let fall = 2.0 * (4.5 - 0.42 - 0.15 - 0.15) / 10.0;
    assert_close(
        report.tally.end_time,
        2.0 * config().launch_interval() + fall,
        ANALYTIC,
    );
    assert_eq!(report.tally.collected, 3);
}

/// Empty cells: a ball rises to the top wall and back.
#[test]
fn an_empty_board_returns_every_ball_after_one_wall_bounce() {
    let mut game = game_with(config(), &[], 1);
    let report = play(&mut game, UP);
    assert_eq!(report.collisions, 2, "the top wall, then the floor");
    assert_close(report.tally.end_time, 1.74, ANALYTIC);
    assert_eq!(game.phase(), Phase::Aiming);
}
