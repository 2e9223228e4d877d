//! Friction among balls in contact (`dynamics/contact_friction.rs`): a group of rough balls
//! slows by Coulomb's kinetic friction while it slides and sticks while friction can hold it,
//! checked against answers derived by hand.

use exact2d::{BallDesc, BallHandle, ColliderDesc, DVec2, World};

const G: f64 = 9.81;

fn v(x: f64, y: f64) -> DVec2 {
    DVec2::new(x, y)
}

/// A world with gravity along `-y` turned by `tilt` radians (a slope of that angle, seen along
/// a level floor), sleeping on, and a long floor of friction `floor_mu`.
fn world(tilt: f64, floor_mu: f64) -> World {
    let mut world = World::new();
    world
        .set_gravity(G * v(tilt.sin(), -tilt.cos()))
        .expect("gravity");
    world.set_sleeping(true);
    world
        .add_collider(ColliderDesc::segment(v(-100.0, 0.0), v(100.0, 0.0)).friction(floor_mu))
        .expect("floor");
    world
}

/// A stack of two balls of radius 0.5 at `x`, the lower on the floor, of friction `mu`.
fn stack(world: &mut World, x: f64, speed: f64, mu: f64) -> [BallHandle; 2] {
    [0.5, 1.5].map(|y| {
        world
            .add_ball(
                BallDesc::new(v(x, y), 0.5)
                    .velocity(v(speed, 0.0))
                    .friction(mu),
            )
            .expect("ball")
    })
}

/// Two balls stacked on a level floor, sliding together at `v0`: the pair's contact sticks
/// (it needs `mu_floor` of the top ball's weight across it, and has `mu_balls` of it), and the
/// two slow as one body at `mu g` (`mu` the floor's pair: the geometric mean of 1 and 0.25,
/// 0.5), stopping `v0 / (mu g)` later, `v0^2 / (2 mu g)` on, then fall asleep.
#[test]
fn a_stack_sliding_on_a_rough_floor_stops_where_coulomb_says() {
    let mut world = world(0.0, 0.25);
    let v0 = 2.0;
    let balls = stack(&mut world, 0.0, v0, 1.0);
    let mu = 0.5;
    let stop = v0 / (mu * G);
    let distance = v0 * v0 / (2.0 * mu * G);
    // Half way, both have the speed Coulomb gives them.
    world.advance_to(stop / 2.0).expect("advance");
    for &ball in &balls {
        let b = world.ball(ball).expect("ball");
        assert!((b.velocity.x - v0 / 2.0).abs() < 1e-9, "{:?}", b.velocity);
        let x = v0 * stop / 2.0 - mu * G * (stop / 2.0).powi(2) / 2.0;
        assert!((b.position.x - x).abs() < 1e-9, "{} {x}", b.position.x);
    }
    world.advance_to(stop + 1.0).expect("advance");
    for &ball in &balls {
        let b = world.ball(ball).expect("ball");
        assert!(world.ball_asleep(ball), "{:?}", b.velocity);
        assert!(
            (b.position.x - distance).abs() < 1e-9,
            "{} {distance}",
            b.position.x
        );
    }
    assert!((world.ball(balls[1]).unwrap().position.x - distance).abs() < 1e-9);
    let events = world.event_counts().handled();
    assert!(events < 50, "{events} events");
}

/// A stack at rest on a slope of angle `theta`: held by friction while `tan theta <= mu`
/// (every contact of friction 0.5 here), asleep where it was put, costing a handful of events;
/// on a steeper slope it slides off down it.
#[test]
fn a_stack_on_a_slope_stays_below_the_angle_of_friction() {
    for (theta, held) in [(0.3_f64, true), (0.45, true), (0.5, false)] {
        assert_eq!(theta.tan() <= 0.5, held);
        let mut world = world(theta, 0.5);
        let balls = stack(&mut world, 0.0, 0.0, 0.5);
        world.advance_to(2.0).expect("advance");
        for &ball in &balls {
            let b = world.ball(ball).expect("ball");
            if held {
                assert!(world.ball_asleep(ball), "theta {theta}: {:?}", b.velocity);
                assert!(b.position.x.abs() < 1e-9, "theta {theta}: {}", b.position.x);
            } else {
                assert!(b.position.x > 0.5, "theta {theta}: {}", b.position.x);
            }
        }
        if held {
            let events = world.event_counts().handled();
            assert!(events < 20, "theta {theta}: {events} events");
        }
    }
}

/// Without friction the same stack on the gentlest slope slides off: friction is what held it.
#[test]
fn a_frictionless_stack_on_a_slope_slides() {
    let mut world = world(0.3, 0.0);
    let balls = stack(&mut world, 0.0, 0.0, 0.0);
    world.advance_to(1.0).expect("advance");
    for &ball in &balls {
        assert!(world.ball(ball).unwrap().position.x > 1.0);
    }
}
