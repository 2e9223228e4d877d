//! The world's API: changes between events, sensors, and errors for bad input.

mod common;

use common::v;
use exact2d::{BallDesc, ColliderDesc, CollisionGroups, DVec2, Event, Feature, World, WorldError};

#[test]
fn a_collider_removed_before_the_ball_arrives_is_passed_through() {
    let mut world = World::new();
    let wall = world
        .add_collider(ColliderDesc::segment(v(5.0, -1.0), v(5.0, 1.0)))
        .unwrap();
    let ball = world
        .add_ball(BallDesc::new(v(0.0, 0.0), 0.5).velocity(v(1.0, 0.0)))
        .unwrap();
    world.advance_to(2.0).unwrap();
    world.remove_collider(wall).unwrap();
    assert_eq!(world.advance_to(10.0).unwrap(), 0);
    assert_eq!(world.ball(ball).unwrap().position, v(10.0, 0.0));
}

#[test]
fn a_collider_added_in_a_balls_path_is_hit_at_the_exact_time() {
    let mut world = World::new();
    let ball = world
        .add_ball(BallDesc::new(v(0.0, 0.0), 0.5).velocity(v(1.0, 0.0)))
        .unwrap();
    world.advance_to(2.0).unwrap();
    world
        .add_collider(ColliderDesc::segment(v(5.0, -1.0), v(5.0, 1.0)))
        .unwrap();
    let Some(Event::Contact(hit)) = world.step() else {
        panic!("must hit the new wall")
    };
    assert_eq!(hit.time, 4.5);
    world.advance_to(6.5).unwrap();
    assert_eq!(world.ball(ball).unwrap().position, v(2.5, 0.0));
}

#[test]
fn a_collider_added_inside_the_broad_phase_cell_of_a_ball_among_balls_is_hit() {
    // Balls close enough together for small cells in the ball grid (a ball there searches for
    // colliders only up to its next cell crossing) and a far wall. The ball's cell had no
    // collider within reach when it entered it; a collider added there must still be hit by
    // a prediction made in that cell, long before the next crossing.
    let mut world = World::new();
    let ball = world
        .add_ball(BallDesc::new(v(0.0, 0.0), 0.5).velocity(v(0.25, 0.0)))
        .unwrap();
    for k in 0..200 {
        let (x, y) = (f64::from(k % 20), f64::from(k / 20));
        world
            .add_ball(BallDesc::new(v(1.25 * x - 12.0, 1.25 * y + 4.0), 0.5))
            .unwrap();
    }
    world
        .add_collider(ColliderDesc::segment(v(20.0, -20.0), v(20.0, 20.0)))
        .unwrap();
    // Another ball hits the far wall at t = 2, before the first ball's next crossing.
    world
        .add_ball(BallDesc::new(v(17.5, -10.0), 0.5).velocity(v(1.0, 0.0)))
        .unwrap();
    world.advance_to(1.0).unwrap();
    world
        .add_collider(ColliderDesc::segment(v(0.875, -0.25), v(0.875, 0.25)))
        .unwrap();
    // Predicted afresh in the same cell (its velocity set again).
    world.set_ball_velocity(ball, v(0.25, 0.0)).unwrap();
    let Some(Event::Contact(hit)) = world.step() else {
        panic!("must hit the new wall")
    };
    assert_eq!((hit.ball, hit.time), (ball, 1.5));
    world.advance_to(2.5).unwrap();
    assert_eq!(world.ball(ball).unwrap().position, v(0.125, 0.0));
}

#[test]
fn a_collider_added_where_a_ball_has_already_been_does_not_catch_it_retroactively() {
    let mut world = World::new();
    let ball = world
        .add_ball(BallDesc::new(v(0.0, 0.0), 0.5).velocity(v(1.0, 0.0)))
        .unwrap();
    world.advance_to(10.0).unwrap();
    // The ball passed x = 5 long ago; this wall is behind it now.
    world
        .add_collider(ColliderDesc::segment(v(5.0, -1.0), v(5.0, 1.0)))
        .unwrap();
    assert_eq!(world.advance_to(20.0).unwrap(), 0);
    assert_eq!(world.ball(ball).unwrap().position, v(20.0, 0.0));
}

#[test]
fn a_sensor_added_around_a_ball_reports_only_the_exit() {
    let mut world = World::new();
    let ball = world
        .add_ball(BallDesc::new(v(0.0, 0.0), 0.5).velocity(v(1.0, 0.0)))
        .unwrap();
    world.advance_to(1.0).unwrap();
    let zone = world
        .add_collider(ColliderDesc::circle(v(1.0, 0.0), 2.0).sensor(true))
        .unwrap();
    assert_eq!(world.ball_sensors(ball).unwrap(), &[zone]);
    let Some(Event::SensorExit(exit)) = world.step() else {
        panic!("must leave the zone")
    };
    // The centre is 2.5 from (1, 0) at x = 3.5.
    assert_eq!((exit.time, exit.collider), (3.5, zone));
    assert!(world.ball_sensors(ball).unwrap().is_empty());
    assert!(world.step().is_none());
}

#[test]
fn a_ball_passing_through_a_round_sensor_enters_and_leaves_without_deflection() {
    let mut world = World::new();
    let zone = world
        .add_collider(ColliderDesc::circle(v(5.0, 0.0), 1.0).sensor(true))
        .unwrap();
    let ball = world
        .add_ball(BallDesc::new(v(0.0, 0.0), 0.5).velocity(v(2.0, 0.0)))
        .unwrap();
    let mut events = Vec::new();
    world.advance_to_collect(10.0, &mut events).unwrap();
    let seen: Vec<_> = events
        .iter()
        .map(|e| match e {
            Event::SensorEnter(s) => ("enter", s.time, s.collider),
            Event::SensorExit(s) => ("exit", s.time, s.collider),
            other => panic!("{other:?}"),
        })
        .collect();
    // Overlap begins when the centre is 1.5 from (5, 0): x = 3.5, t = 1.75; ends at x = 6.5.
    assert_eq!(seen, vec![("enter", 1.75, zone), ("exit", 3.25, zone)]);
    let state = world.ball(ball).unwrap();
    assert_eq!(
        (state.position, state.velocity),
        (v(20.0, 0.0), v(2.0, 0.0))
    );
}

#[test]
fn a_floor_line_sensor_reports_each_ball_once_on_the_way_down() {
    let mut world = World::with_gravity(v(0.0, -10.0)).unwrap();
    let floor = world
        .add_collider(ColliderDesc::segment(v(-10.0, 0.0), v(10.0, 0.0)).sensor(true))
        .unwrap();
    for k in 0..5 {
        let x = f64::from(k) - 2.0;
        world
            .add_ball(BallDesc::new(v(x, 5.0 + f64::from(k)), 0.25).velocity(v(0.3, 2.0)))
            .unwrap();
    }
    let mut events = Vec::new();
    world.advance_to_collect(10.0, &mut events).unwrap();
    let enters = events
        .iter()
        .filter(|e| matches!(e, Event::SensorEnter(s) if s.collider == floor))
        .count();
    let exits = events
        .iter()
        .filter(|e| matches!(e, Event::SensorExit(s) if s.collider == floor))
        .count();
    assert_eq!((enters, exits), (5, 5));
    for e in &events {
        if let Event::SensorEnter(s) = e {
            // Entering means touching: the lowest point of the ball reaches the line.
            assert!((s.position.y - 0.25).abs() < 1e-12, "{:?}", s.position);
            assert_eq!(s.feature, Feature::SegmentInterior);
        }
    }
}

#[test]
fn setting_a_velocity_between_events_redirects_the_ball_from_where_it_is() {
    let mut world = World::new();
    world
        .add_collider(ColliderDesc::segment(v(10.0, -10.0), v(10.0, 10.0)))
        .unwrap();
    let ball = world
        .add_ball(BallDesc::new(v(0.0, 0.0), 0.5).velocity(v(1.0, 0.0)))
        .unwrap();
    world.advance_to(4.0).unwrap();
    world.set_ball_velocity(ball, v(0.0, 1.0)).unwrap();
    assert_eq!(world.advance_to(8.0).unwrap(), 0);
    assert_eq!(world.ball(ball).unwrap().position, v(4.0, 4.0));
}

#[test]
fn removing_a_ball_cancels_the_collision_its_partner_expected() {
    let mut world = World::new();
    let a = world
        .add_ball(BallDesc::new(v(0.0, 0.0), 0.5).velocity(v(1.0, 0.0)))
        .unwrap();
    let b = world.add_ball(BallDesc::new(v(5.0, 0.0), 0.5)).unwrap();
    world.advance_to(1.0).unwrap();
    world.remove_ball(b).unwrap();
    assert_eq!(world.advance_to(10.0).unwrap(), 0);
    assert_eq!(world.ball(a).unwrap().position, v(10.0, 0.0));
    assert!(world.ball(b).is_none());
}

#[test]
fn a_ball_added_in_the_path_of_another_is_hit() {
    let mut world = World::new();
    let a = world
        .add_ball(BallDesc::new(v(0.0, 0.0), 0.5).velocity(v(1.0, 0.0)))
        .unwrap();
    world.advance_to(1.0).unwrap();
    let b = world.add_ball(BallDesc::new(v(5.0, 0.0), 0.5)).unwrap();
    let Some(Event::BallContact(c)) = world.step() else {
        panic!("must collide")
    };
    // Centres 1 apart: a at x = 4.
    assert_eq!((c.time, c.a, c.b), (4.0, a, b));
    assert_eq!(world.ball(b).unwrap().velocity, v(1.0, 0.0));
}

#[test]
fn balls_that_filter_out_each_other_pass_through_each_other_but_not_walls() {
    let mut world = World::new();
    world
        .add_collider(ColliderDesc::segment(v(10.0, -5.0), v(10.0, 5.0)))
        .unwrap();
    let groups = CollisionGroups::new(1, !1);
    let a = world
        .add_ball(
            BallDesc::new(v(0.0, 0.0), 0.5)
                .velocity(v(1.0, 0.0))
                .groups(groups),
        )
        .unwrap();
    // Overlapping placement is allowed between balls that do not interact.
    world
        .add_ball(BallDesc::new(v(0.5, 0.0), 0.5).groups(groups))
        .unwrap();
    let Some(Event::Contact(hit)) = world.step() else {
        panic!("must hit the wall")
    };
    assert_eq!((hit.time, hit.ball), (9.5, a));
}

#[test]
fn a_removed_handle_is_never_confused_with_a_new_body_in_the_same_slot() {
    let mut world = World::new();
    let old = world.add_ball(BallDesc::new(v(0.0, 0.0), 0.5)).unwrap();
    world.remove_ball(old).unwrap();
    let new = world.add_ball(BallDesc::new(v(3.0, 0.0), 0.5)).unwrap();
    assert_eq!(old.index(), new.index());
    assert!(world.ball(old).is_none());
    assert_eq!(world.remove_ball(old), Err(WorldError::NoSuchBall(old)));
    assert_eq!(
        world.set_ball_velocity(old, v(1.0, 0.0)),
        Err(WorldError::NoSuchBall(old))
    );
    let wall = world
        .add_collider(ColliderDesc::circle(v(9.0, 9.0), 1.0))
        .unwrap();
    world.remove_collider(wall).unwrap();
    assert_eq!(
        world.remove_collider(wall).unwrap_err(),
        WorldError::NoSuchCollider(wall)
    );
}

#[test]
fn bad_input_is_an_error_that_names_the_problem_and_leaves_the_world_unchanged() {
    let mut world = World::new();
    world
        .add_collider(ColliderDesc::segment(v(-5.0, 0.0), v(5.0, 0.0)))
        .unwrap();
    let nan = f64::NAN;
    let cases = [
        (
            BallDesc::new(v(nan, 1.0), 0.5),
            WorldError::NotFinite("ball position"),
        ),
        (
            BallDesc::new(v(0.0, 1.0), 0.5).velocity(v(f64::INFINITY, 0.0)),
            WorldError::NotFinite("ball velocity"),
        ),
        (
            BallDesc::new(v(0.0, 1.0), 0.0),
            WorldError::InvalidRadius(0.0),
        ),
        (
            BallDesc::new(v(0.0, 1.0), -1.0),
            WorldError::InvalidRadius(-1.0),
        ),
        (
            BallDesc::new(v(0.0, 1.0), 0.5).mass(0.0),
            WorldError::InvalidMass(0.0),
        ),
        (
            BallDesc::new(v(0.0, 1.0), 0.5).restitution(1.5),
            WorldError::InvalidRestitution(1.5),
        ),
    ];
    for (desc, expected) in cases {
        assert_eq!(world.add_ball(desc), Err(expected));
    }
    let Err(WorldError::InvalidRadius(r)) = world.add_ball(BallDesc::new(v(0.0, 1.0), nan)) else {
        panic!("NaN radius must be rejected");
    };
    assert!(r.is_nan());
    // Overlapping a solid wall by more than the tolerance, versus touching it exactly.
    assert!(matches!(
        world.add_ball(BallDesc::new(v(0.0, 0.4), 0.5)),
        Err(WorldError::OverlapsCollider(_))
    ));
    let touching = world.add_ball(BallDesc::new(v(0.0, 0.5), 0.5)).unwrap();
    assert!(matches!(
        world.add_collider(ColliderDesc::circle(v(0.0, 1.5), 0.6)),
        Err(WorldError::OverlapsBall(h)) if h == touching
    ));
    assert_eq!(
        world.add_collider(ColliderDesc::segment(v(1.0, 1.0), v(1.0, 1.0))),
        Err(WorldError::DegenerateSegment)
    );
    assert_eq!(
        world.add_collider(ColliderDesc::circle(v(0.0, 0.0), -2.0)),
        Err(WorldError::InvalidRadius(-2.0))
    );
    assert!(World::with_gravity(v(0.0, nan)).is_err());
    world.advance_to(3.0).unwrap();
    assert!(matches!(
        world.advance_to(2.0),
        Err(WorldError::TimeBeforeNow { .. })
    ));
    assert!(matches!(
        world.advance_to(nan),
        Err(WorldError::TimeBeforeNow { .. })
    ));
    assert_eq!(
        (world.ball_count(), world.collider_count(), world.time()),
        (1, 1, 3.0)
    );
    let message = WorldError::InvalidRadius(-1.0).to_string();
    assert_eq!(message, "radius must be > 0 (got -1)");
}

/// Regression: a ball that falls forever outside every container used to cross broad-phase
/// cells forever, so `step` never returned. It leaves the cells' region and is kept far.
#[test]
fn a_ball_falling_forever_lets_step_report_that_no_event_is_left() {
    let mut world = World::with_gravity(DVec2::new(0.0, -9.81)).unwrap();
    world
        .add_collider(ColliderDesc::segment(
            DVec2::new(-1.0, 0.0),
            DVec2::new(1.0, 0.0),
        ))
        .unwrap();
    // Two balls that can meet each other (so both use the ball grid), beside the floor.
    let a = world
        .add_ball(BallDesc::new(DVec2::new(5.0, 1.0), 0.1).velocity(DVec2::new(1.0, 0.0)))
        .unwrap();
    world
        .add_ball(BallDesc::new(DVec2::new(-5.0, 1.0), 0.1).velocity(DVec2::new(-1.0, 0.0)))
        .unwrap();
    assert_eq!(world.step(), None);
    assert_eq!(world.event_counts().collisions(), 0);
    // Both still fall along their closed-form paths.
    world.advance_to(100.0).unwrap();
    let y = world.ball(a).unwrap().position.y;
    assert_eq!(y, 1.0 - 0.5 * 9.81 * 100.0 * 100.0);
}

/// Regression (found by the `world_events` fuzz target): one inelastic ball in a box slows
/// down by half at every bounce, so its bounces come ever further apart, and past t = 1e303
/// its next cell crossing rounded to the current time: the crossing was handled at the same
/// instant forever and `step` never returned. A ball whose crossing the clock cannot place
/// later now leaves the cells for the far list. The ball bounces until its next bounce would
/// come after the largest double, as a plain model of the geometric series says.
#[test]
fn an_inelastic_ball_slowing_in_a_box_reaches_the_end_of_time_without_stalling() {
    let mut world = common::fuzz_box(DVec2::ZERO, 1.0);
    let (x, r, speed) = (271.0 / 64.0, 254.0 / 64.0, 0.4375);
    world
        .add_ball(
            BallDesc::new(v(x, 0.0), r)
                .velocity(v(speed, 0.0))
                .restitution(0.5),
        )
        .unwrap();
    let mut times = Vec::new();
    while let Some(event) = world.step() {
        times.push(event.time());
        assert!(times.len() < 1100, "more bounces than the model allows");
    }
    // The model: first bounce after (9 - r - x) / speed, then a wall-to-wall flight of
    // (18 - 2r) / v at half the speed each time, while the time stays finite.
    let mut model = Vec::new();
    let (mut t, mut v) = ((9.0 - r - x) / speed, speed);
    while t.is_finite() {
        model.push(t);
        v *= 0.5;
        t += (18.0 - 2.0 * r) / v;
    }
    assert!(
        times.len().abs_diff(model.len()) <= 1,
        "{} vs {}",
        times.len(),
        model.len()
    );
    for (k, (a, b)) in times.iter().zip(&model).enumerate().take(1000) {
        assert!((a - b).abs() <= 1e-9 * b, "bounce {k}: {a} vs {b}");
    }
}

/// Regression (found by the `world_events` fuzz target): a ball whose groups could meet no
/// ball yet (group 2, filtering group 2 out) stayed out of the ball grid; when a ball it can
/// meet arrived, it joined the grid, but the cells were sized for the newcomer's radius (1.9)
/// only, not its own (3.2). Its 3 x 3 block of cells was then too small to hold every ball it
/// could touch, and 1458 events later the two balls passed 0.73 into each other. A joining
/// ball's radius now sizes the cells too. Checked against the invariant itself: no overlap
/// deeper than rounding after any of 3000 events.
#[test]
fn a_large_ball_joining_the_ball_grid_late_still_meets_every_ball() {
    let mut world = common::fuzz_box(DVec2::ZERO, 1.0);
    let loner = exact2d::CollisionGroups::new(2, !2);
    let a = BallDesc::new(v(305.0 / 64.0, -4.0), 203.0 / 64.0)
        .velocity(v(-3.3125, -3.3125))
        .groups(loner);
    let b =
        BallDesc::new(v(-53.0 / 64.0, -53.0 / 64.0), 122.0 / 64.0).velocity(v(-3.3125, 12.6875));
    let (a, b) = (world.add_ball(a).unwrap(), world.add_ball(b).unwrap());
    let mut ball_contacts = 0;
    for _ in 0..3000 {
        if let Some(exact2d::Event::BallContact(_)) = world.step() {
            ball_contacts += 1;
        }
        let (a, b) = (world.ball(a).unwrap(), world.ball(b).unwrap());
        let gap = a.position.distance(b.position) - a.radius - b.radius;
        assert!(gap > -1e-12, "overlap {gap} at t = {}", world.time());
    }
    assert!(ball_contacts > 0, "the two balls meet");
}
