//! Contacts whose outcome physics fixes exactly: Newton's cradles, shots into corners and end
//! points, grazing passes, simultaneous impacts, restitution.
//!
//! Every expected value is analytic and every input is chosen so it is exactly representable,
//! so most assertions compare bits.

mod common;

use common::v;
use exact2d::{BallDesc, BallHandle, ColliderDesc, DVec2, Event, Feature, World};

/// Five touching balls of radius 1 at rest, centred at x = 0, 2, 4, 6, 8.
fn touching_row(world: &mut World) -> Vec<BallHandle> {
    (0..5)
        .map(|k| {
            world
                .add_ball(BallDesc::new(v(2.0 * f64::from(k), 0.0), 1.0))
                .unwrap()
        })
        .collect()
}

fn events_until(world: &mut World, t: f64) -> Vec<Event> {
    let mut events = Vec::new();
    world.advance_to_collect(t, &mut events).unwrap();
    events
}

fn ball_pair(event: &Event) -> (u32, u32) {
    match event {
        Event::BallContact(c) => (c.a.index(), c.b.index()),
        other => panic!("expected a ball contact, got {other:?}"),
    }
}

#[test]
fn newtons_cradle_passes_the_momentum_down_the_row_in_one_instant() {
    let mut world = World::new();
    let row = touching_row(&mut world);
    let striker = world
        .add_ball(BallDesc::new(v(-5.0, 0.0), 1.0).velocity(v(1.0, 0.0)))
        .unwrap();
    let events = events_until(&mut world, 10.0);
    // The striker touches ball 0 at t = 3; the impulse then runs down the touching row as a
    // chain of zero-time collisions, in order.
    let pairs: Vec<_> = events.iter().map(ball_pair).collect();
    assert_eq!(pairs, vec![(0, 5), (0, 1), (1, 2), (2, 3), (3, 4)]);
    assert!(events.iter().all(|e| e.time() == 3.0));
    for &h in row.iter().take(4).chain([&striker]) {
        assert_eq!(world.ball(h).unwrap().velocity, DVec2::ZERO);
    }
    let last = world.ball(row[4]).unwrap();
    assert_eq!(last.velocity, v(1.0, 0.0));
    assert_eq!(last.position, v(8.0 + 7.0, 0.0));
}

#[test]
fn two_touching_strikers_send_two_balls_out() {
    let mut world = World::new();
    let row = touching_row(&mut world);
    for x in [-4.0, -2.0] {
        world
            .add_ball(BallDesc::new(v(x - 1.0, 0.0), 1.0).velocity(v(1.0, 0.0)))
            .unwrap();
    }
    world.advance_to(10.0).unwrap();
    let speeds: Vec<f64> = world.balls().map(|(_, b)| b.velocity.x).collect();
    // Slots: row 0..4, then the two strikers. Balls 3 and 4 leave; everything else stops.
    assert_eq!(speeds, vec![0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0]);
    assert_eq!(world.ball(row[4]).unwrap().position.x, 8.0 + 9.0);
}

#[test]
fn a_ball_aimed_exactly_into_a_box_corner_comes_straight_back() {
    let mut world = common::boxed(10.0, DVec2::ZERO);
    let ball = world
        .add_ball(BallDesc::new(v(3.0, 5.0), 1.0).velocity(v(6.0, 4.0)))
        .unwrap();
    // The centre reaches (9, 9), touching the right and top walls at once, at t = 1.
    let events = events_until(&mut world, 1.5);
    assert_eq!(events.len(), 2);
    assert!(events.iter().all(|e| e.time() == 1.0));
    let walls: Vec<_> = events
        .iter()
        .map(|e| match e {
            Event::Contact(c) => (c.collider.index(), c.feature, c.normal),
            other => panic!("{other:?}"),
        })
        .collect();
    assert_eq!(
        walls,
        vec![
            (1, Feature::SegmentInterior, v(-1.0, 0.0)),
            (2, Feature::SegmentInterior, v(0.0, -1.0))
        ]
    );
    let state = world.ball(ball).unwrap();
    assert_eq!(state.velocity, v(-6.0, -4.0));
    world.advance_to(2.0).unwrap();
    assert_eq!(world.ball(ball).unwrap().position, v(3.0, 5.0));
}

#[test]
fn a_ball_aimed_along_a_segment_at_its_end_point_bounces_straight_back() {
    let mut world = World::new();
    let wall = world
        .add_collider(ColliderDesc::segment(v(0.0, 0.0), v(4.0, 0.0)))
        .unwrap();
    let ball = world
        .add_ball(BallDesc::new(v(10.0, 0.0), 1.0).velocity(v(-1.0, 0.0)))
        .unwrap();
    let Some(Event::Contact(hit)) = world.step() else {
        panic!("must hit the end point")
    };
    assert_eq!(
        (hit.time, hit.collider, hit.feature),
        (5.0, wall, Feature::SegmentEndB)
    );
    assert_eq!((hit.point, hit.normal), (v(4.0, 0.0), v(1.0, 0.0)));
    assert_eq!(world.ball(ball).unwrap().velocity, v(1.0, 0.0));
    assert!(world.step().is_none());
}

#[test]
fn a_ball_hitting_an_end_point_obliquely_reflects_about_the_corner_to_centre_normal() {
    let mut world = World::new();
    world
        .add_collider(ColliderDesc::segment(v(-4.0, 0.0), v(0.0, 0.0)))
        .unwrap();
    // Aim the centre's path so it is at distance 1 from the end point (0, 0) when the ball is
    // at (0.6, 0.8): start 10 units back along the direction (-0.6, -0.8) from that point...
    let contact = v(0.6, 0.8);
    let dir = v(-1.0, -1.0).normalize();
    let start = contact - dir * 10.0;
    let ball = world
        .add_ball(BallDesc::new(start, 1.0).velocity(dir))
        .unwrap();
    let Some(Event::Contact(hit)) = world.step() else {
        panic!("must hit the end point")
    };
    assert_eq!(hit.feature, Feature::SegmentEndB);
    // ... so the contact is at t = 10 with normal (0.6, 0.8), up to the rounding of the inputs
    // (0.6, 0.8 and 1/sqrt 2 are not representable; the start point is computed): a few ulps.
    assert!((hit.time - 10.0).abs() < 1e-13, "{}", hit.time);
    assert!((hit.normal - contact).length() < 1e-14);
    let n = contact;
    let expected = dir - n * (2.0 * dir.dot(n));
    assert!((world.ball(ball).unwrap().velocity - expected).length() < 1e-14);
}

#[test]
fn a_ball_grazing_a_wall_at_exactly_its_radius_is_never_deflected() {
    let mut world = World::new();
    world
        .add_collider(ColliderDesc::segment(v(0.0, 0.0), v(10.0, 0.0)))
        .unwrap();
    let ball = world
        .add_ball(BallDesc::new(v(-5.0, 0.5), 0.5).velocity(v(1.0, 0.0)))
        .unwrap();
    // Tangential along the interior, and a double root (tangency) at both end points.
    assert_eq!(world.advance_to(20.0).unwrap(), 0);
    let state = world.ball(ball).unwrap();
    assert_eq!(
        (state.position, state.velocity),
        (v(15.0, 0.5), v(1.0, 0.0))
    );
}

#[test]
fn a_ball_grazing_a_static_circle_is_never_deflected() {
    let mut world = World::new();
    world
        .add_collider(ColliderDesc::circle(v(0.0, 0.0), 0.5))
        .unwrap();
    let ball = world
        .add_ball(BallDesc::new(v(-10.0, 1.0), 0.5).velocity(v(1.0, 0.0)))
        .unwrap();
    assert_eq!(world.advance_to(20.0).unwrap(), 0);
    assert_eq!(world.ball(ball).unwrap().position, v(10.0, 1.0));
}

#[test]
fn two_balls_striking_a_third_from_both_sides_at_once_rebound_symmetrically() {
    let mut world = World::new();
    let left = world
        .add_ball(BallDesc::new(v(-3.0, 0.0), 1.0).velocity(v(1.0, 0.0)))
        .unwrap();
    let middle = world.add_ball(BallDesc::new(v(0.0, 0.0), 1.0)).unwrap();
    let right = world
        .add_ball(BallDesc::new(v(3.0, 0.0), 1.0).velocity(v(-1.0, 0.0)))
        .unwrap();
    let events = events_until(&mut world, 2.0);
    assert!(events.iter().all(|e| e.time() == 1.0));
    assert_eq!(world.ball(left).unwrap().velocity, v(-1.0, 0.0));
    assert_eq!(world.ball(middle).unwrap().velocity, DVec2::ZERO);
    assert_eq!(world.ball(right).unwrap().velocity, v(1.0, 0.0));
}

#[test]
fn four_balls_striking_a_fifth_from_four_sides_at_once_all_rebound() {
    let mut world = World::new();
    let centre = world.add_ball(BallDesc::new(DVec2::ZERO, 1.0)).unwrap();
    let dirs = [v(1.0, 0.0), v(-1.0, 0.0), v(0.0, 1.0), v(0.0, -1.0)];
    let outer: Vec<_> = dirs
        .iter()
        .map(|&d| {
            world
                .add_ball(BallDesc::new(d * 3.0, 1.0).velocity(-d))
                .unwrap()
        })
        .collect();
    world.advance_to(2.0).unwrap();
    assert_eq!(world.ball(centre).unwrap().velocity, DVec2::ZERO);
    for (h, d) in outer.iter().zip(dirs) {
        let ball = world.ball(*h).unwrap();
        assert_eq!(ball.velocity, d);
        assert_eq!(ball.position, d * 3.0);
    }
}

#[test]
fn two_balls_hitting_opposite_walls_at_the_same_instant_are_both_handled() {
    let mut world = common::boxed(10.0, DVec2::ZERO);
    let a = world
        .add_ball(BallDesc::new(v(2.0, 3.0), 1.0).velocity(v(-1.0, 0.0)))
        .unwrap();
    let b = world
        .add_ball(BallDesc::new(v(8.0, 7.0), 1.0).velocity(v(1.0, 0.0)))
        .unwrap();
    let events = events_until(&mut world, 1.0);
    assert_eq!(events.len(), 2);
    assert_eq!(world.ball(a).unwrap().velocity, v(1.0, 0.0));
    assert_eq!(world.ball(b).unwrap().velocity, v(-1.0, 0.0));
}

#[test]
fn restitution_is_the_product_of_ball_and_collider() {
    let mut world = World::new();
    world
        .add_collider(ColliderDesc::segment(v(-5.0, 0.0), v(5.0, 0.0)).restitution(0.5))
        .unwrap();
    let ball = world
        .add_ball(
            BallDesc::new(v(0.0, 3.0), 1.0)
                .velocity(v(1.0, -4.0))
                .restitution(0.5),
        )
        .unwrap();
    let Some(Event::Contact(hit)) = world.step() else {
        panic!()
    };
    assert_eq!((hit.time, hit.normal_speed), (0.5, 4.0));
    assert_eq!(world.ball(ball).unwrap().velocity, v(1.0, 1.0));
}

#[test]
fn inelastic_ball_ball_contact_conserves_momentum_and_loses_the_right_energy() {
    let mut world = World::new();
    let a = world
        .add_ball(
            BallDesc::new(v(-3.0, 0.0), 1.0)
                .velocity(v(2.0, 0.0))
                .mass(3.0)
                .restitution(0.5),
        )
        .unwrap();
    let b = world
        .add_ball(BallDesc::new(v(3.0, 0.0), 1.0).mass(1.0))
        .unwrap();
    world.advance_to(5.0).unwrap();
    let (va, vb) = (
        world.ball(a).unwrap().velocity.x,
        world.ball(b).unwrap().velocity.x,
    );
    // 1D: v1' = (m1 u1 + m2 u2 - m2 e (u1 - u2)) / (m1 + m2) = (6 - 1) / 4,
    //     v2' = (m1 u1 + m2 u2 + m1 e (u1 - u2)) / (m1 + m2) = (6 + 3) / 4.
    assert_eq!((va, vb), (1.25, 2.25));
}

#[test]
fn a_ball_dropped_under_gravity_hits_the_floor_at_the_analytic_time() {
    let mut world = World::with_gravity(v(0.0, -8.0)).unwrap();
    world
        .add_collider(ColliderDesc::segment(v(-5.0, 0.0), v(5.0, 0.0)))
        .unwrap();
    let ball = world.add_ball(BallDesc::new(v(0.0, 4.5), 0.5)).unwrap();
    // The bottom falls 4 units: t = sqrt(2 * 4 / 8) = 1, at speed 8.
    let Some(Event::Contact(hit)) = world.step() else {
        panic!()
    };
    assert_eq!((hit.time, hit.normal_speed), (1.0, 8.0));
    // Elastic: back at the top, at rest, at t = 2, and again at t = 4.
    world.advance_to(4.0).unwrap();
    let state = world.ball(ball).unwrap();
    assert_eq!((state.position, state.velocity), (v(0.0, 4.5), DVec2::ZERO));
}

#[test]
fn a_ball_dropped_onto_a_peg_top_hits_it_at_the_analytic_time_through_the_quartic() {
    let mut world = World::with_gravity(v(0.0, -2.0)).unwrap();
    let peg = world
        .add_collider(ColliderDesc::circle(v(0.0, 0.0), 1.0))
        .unwrap();
    world.add_ball(BallDesc::new(v(0.0, 10.0), 1.0)).unwrap();
    // Contact when the centre is at height 2: it falls 8 units, t = sqrt(2 * 8 / 2) = 2 * sqrt 2.
    let Some(Event::Contact(hit)) = world.step() else {
        panic!()
    };
    assert_eq!((hit.collider, hit.feature), (peg, Feature::Circle));
    let exact = 2.0 * 2f64.sqrt();
    assert!(
        (hit.time - exact).abs() <= 2.0 * f64::EPSILON * exact,
        "{} vs {exact}",
        hit.time
    );
    assert!((hit.point - v(0.0, 1.0)).length() < 1e-14);
}

/// Found by the `world_events` fuzz target: an inelastic ball (restitution 0.5, no gravity)
/// driven into the cusp between a wall and a round obstacle slows at every bounce, without its
/// bounces coming closer together: by t = 2e162 its speed is 1e-160, and squared speeds
/// underflow (below 1e-308) in the kernels, which lose contacts (outside their domain: speeds
/// and lengths between about 1e-150 and 1e150, see `toi`). Within that domain (the clock below
/// 1e100 here) it never sinks into either.
#[test]
fn an_inelastic_ball_jammed_between_a_wall_and_a_circle_never_sinks_into_either() {
    let mut world = common::fuzz_box(DVec2::ZERO, 1.0);
    world
        .add_collider(ColliderDesc::circle(
            v(-1.0 / 64.0, 255.0 / 64.0),
            255.0 / 64.0,
        ))
        .unwrap();
    world
        .add_ball(
            BallDesc::new(v(-197.0 / 64.0, -257.0 / 64.0), 255.0 / 64.0)
                .velocity(v(-0.0625, -0.0625))
                .restitution(0.5),
        )
        .unwrap();
    for _ in 0..2000 {
        if world.step().is_none() || world.time() > 1e100 {
            break;
        }
        let overlap = common::deepest_overlap(&world);
        assert!(overlap > -1e-9, "overlap {overlap} at t = {}", world.time());
    }
}

/// A heavy ball driving a light one into a wall, perfectly inelastic: in sequence the light
/// ball bounces between the wall and the heavy one at one instant, the approach shrinking by
/// 1000/1001 a round: more than 3e6 events (measured) before the speeds underflowed. Resolved
/// together (`collide_balls_backed`) both stop at once: the heavy ball's momentum goes into the
/// wall.
#[test]
fn a_heavy_ball_pressing_a_light_one_into_a_wall_stops_in_a_few_events() {
    for (light, e) in [(0.001, 0.0), (1.0, 0.0), (0.001, 0.5)] {
        let mut world = World::new();
        world
            .add_collider(ColliderDesc::segment(v(-10.0, 2.0), v(10.0, 2.0)))
            .unwrap();
        let a = world
            .add_ball(BallDesc::new(v(0.0, 1.5), 0.5).mass(light).restitution(e))
            .unwrap();
        let b = world
            .add_ball(
                BallDesc::new(v(0.0, 0.0), 0.5)
                    .velocity(v(0.0, 1.0))
                    .restitution(e),
            )
            .unwrap();
        let mut events = 0;
        while world.step_until(10.0).unwrap().is_some() {
            events += 1;
            assert!(events < 10, "{events} events");
        }
        let (va, vb) = (
            world.ball(a).unwrap().velocity,
            world.ball(b).unwrap().velocity,
        );
        assert!(va.y.abs() < 1e-12, "{va}");
        if e == 0.0 {
            assert!(vb.y.abs() < 1e-12, "{vb}");
        } else {
            // It bounces off the pinned light ball: down, slower than it came.
            assert!(vb.y < 0.0 && vb.y > -1.0, "{vb}");
        }
    }
}
