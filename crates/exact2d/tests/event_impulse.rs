//! The impulse reported on contact events: a bounce's change of momentum along the normal,
//! checked against the textbook values `(1 + e) m v` (a wall) and the exchange of a head-on
//! collision of two balls, and against the momentum the balls actually gained.

use exact2d::{BallDesc, ColliderDesc, DVec2, Event, World};

#[test]
fn a_bounce_off_a_wall_reports_one_plus_e_times_m_v() {
    let mut world = World::new();
    let wall = ColliderDesc::segment(DVec2::new(10.0, -5.0), DVec2::new(10.0, 5.0));
    world.add_collider(wall.restitution(0.5)).unwrap();
    let ball = BallDesc::new(DVec2::ZERO, 0.5)
        .velocity(DVec2::new(3.0, 0.0))
        .mass(2.0);
    let handle = world.add_ball(ball).unwrap();
    let Some(Event::Contact(hit)) = world.step() else {
        panic!("the ball must hit the wall")
    };
    assert_eq!(hit.normal, DVec2::new(-1.0, 0.0));
    // 2 kg at 3 m/s, restitution 0.5: leaves at 1.5 m/s, impulse 2 (3 + 1.5) = 9.
    assert_eq!(hit.impulse, 9.0);
    let after = world.ball(handle).unwrap().velocity;
    assert_eq!(
        hit.impulse,
        2.0 * (after - DVec2::new(3.0, 0.0)).dot(hit.normal)
    );
}

#[test]
fn a_head_on_collision_reports_the_momentum_passed_on() {
    let mut world = World::new();
    let a = BallDesc::new(DVec2::new(0.0, 0.0), 0.5)
        .velocity(DVec2::new(4.0, 0.0))
        .mass(3.0);
    let b = BallDesc::new(DVec2::new(5.0, 0.0), 0.5).mass(1.0);
    let (a, b) = (world.add_ball(a).unwrap(), world.add_ball(b).unwrap());
    let Some(Event::BallContact(hit)) = world.step() else {
        panic!("the balls must collide")
    };
    assert_eq!(hit.normal, DVec2::new(1.0, 0.0));
    // Elastic, masses 3 and 1, 4 m/s onto a ball at rest: b leaves at 2 m1 v / (m1 + m2) = 6,
    // so it received 1 * 6 = 6, and a lost as much.
    assert!((hit.impulse - 6.0).abs() < 1e-12, "{}", hit.impulse);
    let (va, vb) = (
        world.ball(a).unwrap().velocity,
        world.ball(b).unwrap().velocity,
    );
    assert!((1.0 * vb.x - hit.impulse).abs() < 1e-12);
    assert!((3.0 * (4.0 - va.x) - hit.impulse).abs() < 1e-12);
}
