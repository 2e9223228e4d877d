//! Casts and bounce paths (the aim preview) against analytic answers.

mod common;

use common::{boxed, v};
use exact2d::{CastOptions, ColliderDesc, CollisionGroups, DVec2, Feature, World};

#[test]
fn a_cast_finds_the_first_wall_and_its_normal() {
    let world = boxed(10.0, DVec2::ZERO);
    let hit = world
        .cast_ball(v(2.0, 5.0), v(4.0, 2.0), 0.5, &CastOptions::default())
        .unwrap()
        .unwrap();
    // x reaches 9.5 at t = 1.875; y would reach 9.5 only at t = 2.25.
    assert_eq!(
        (hit.time, hit.position, hit.normal),
        (1.875, v(9.5, 8.75), v(-1.0, 0.0))
    );
    assert_eq!(
        (hit.point, hit.feature),
        (v(10.0, 8.75), Feature::SegmentInterior)
    );
}

#[test]
fn a_cast_that_starts_touching_a_wall_and_moves_away_ignores_it() {
    let world = boxed(10.0, DVec2::ZERO);
    let hit = world
        .cast_ball(v(5.0, 0.5), v(0.0, 1.0), 0.5, &CastOptions::default())
        .unwrap()
        .unwrap();
    assert_eq!((hit.time, hit.normal), (9.0, v(0.0, -1.0)));
}

#[test]
fn a_bounce_path_in_a_box_follows_mirror_folding() {
    let world = boxed(10.0, DVec2::ZERO);
    let hits = world
        .bounce_path(v(1.0, 1.0), v(3.0, 1.0), 0.5, 5, &CastOptions::default())
        .unwrap();
    assert_eq!(hits.len(), 5);
    // The first wall: x reaches 9.5 at t = 8.5 / 3, when y = 1 + 8.5 / 3.
    assert!((hits[0].time - 8.5 / 3.0).abs() < 1e-15);
    assert!((hits[0].position - v(9.5, 1.0 + 8.5 / 3.0)).length() < 1e-14);
    // Every hit lies on a wall line, the time between hits matches the straight paths, and the
    // speed is conserved.
    for (a, b) in hits.iter().zip(&hits[1..]) {
        let travel = (b.position - a.position).length() / 10f64.sqrt();
        assert!((travel - (b.time - a.time)).abs() < 1e-13);
        assert!((b.velocity.length() - 10f64.sqrt()).abs() < 1e-14);
    }
    for h in &hits {
        let p = h.position;
        let on_wall = [p.x - 0.5, 9.5 - p.x, p.y - 0.5, 9.5 - p.y]
            .iter()
            .any(|d| d.abs() < 1e-13);
        assert!(on_wall, "{p}");
    }
}

#[test]
fn a_cast_under_gravity_lands_where_the_parabola_meets_the_floor() {
    let world = boxed(10.0, v(0.0, -4.0));
    let hit = world
        .cast_ball(v(1.0, 8.5), v(2.0, 0.0), 0.5, &CastOptions::default())
        .unwrap()
        .unwrap();
    // The centre falls from 8.5 to 0.5: 8 = 2 t^2, t = 2, x = 5.
    assert_eq!(
        (hit.time, hit.position, hit.velocity),
        (2.0, v(5.0, 0.5), v(2.0, -8.0))
    );
}

#[test]
fn sensors_are_ignored_unless_asked_for_and_groups_filter_colliders() {
    let mut world = World::new();
    let sensor = world
        .add_collider(ColliderDesc::circle(v(5.0, 0.0), 1.0).sensor(true))
        .unwrap();
    let ghost = world
        .add_collider(
            ColliderDesc::segment(v(3.0, -5.0), v(3.0, 5.0)).groups(CollisionGroups::new(2, 2)),
        )
        .unwrap();
    let wall = world
        .add_collider(ColliderDesc::segment(v(8.0, -5.0), v(8.0, 5.0)))
        .unwrap();
    let cast = |options: CastOptions| {
        world
            .cast_ball(v(0.0, 0.0), v(1.0, 0.0), 0.5, &options)
            .unwrap()
            .unwrap()
    };
    let balls_only = CollisionGroups::new(1, 1);
    assert_eq!(
        cast(CastOptions {
            groups: balls_only,
            ..Default::default()
        })
        .collider,
        wall
    );
    assert_eq!(cast(CastOptions::default()).collider, ghost);
    let with_sensors = CastOptions {
        include_sensors: true,
        groups: balls_only,
        ..Default::default()
    };
    assert_eq!(cast(with_sensors).collider, sensor);
    let short = CastOptions {
        max_time: 7.0,
        groups: balls_only,
        ..Default::default()
    };
    assert!(
        world
            .cast_ball(v(0.0, 0.0), v(1.0, 0.0), 0.5, &short)
            .unwrap()
            .is_none()
    );
}

#[test]
fn bad_cast_arguments_are_errors() {
    let world = boxed(10.0, DVec2::ZERO);
    let o = CastOptions::default();
    assert!(
        world
            .cast_ball(v(f64::NAN, 1.0), v(1.0, 0.0), 0.5, &o)
            .is_err()
    );
    assert!(world.cast_ball(v(1.0, 1.0), v(1.0, 0.0), 0.0, &o).is_err());
    let negative = CastOptions {
        max_time: -1.0,
        ..o
    };
    assert!(
        world
            .cast_ball(v(1.0, 1.0), v(1.0, 0.0), 0.5, &negative)
            .is_err()
    );
}
