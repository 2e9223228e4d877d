//! Random small worlds (balls, segments, circles, groups), stepped event by event with every
//! invariant checked after each event: time never goes back, no two interacting bodies
//! overlap deeper than `exact2d::OVERLAP_TOLERANCE` of their contact distance, and the
//! kinetic energy is kept. Worlds the API refuses (overlapping placements, degenerate
//! segments) are errors, never panics.
//!
//! Elastic and without gravity, so that the kinetic energy is an invariant; `world_gravity`
//! covers gravity, inelastic balls, resting contact and the TC model.
#![no_main]

use arbitrary::Arbitrary;
use exact2d::{BallDesc, ColliderDesc, DVec2, World};
use libfuzzer_sys::fuzz_target;

mod common;
use common::{coord, deepest_overlap, groups};

#[derive(Arbitrary, Debug)]
struct BallSpec {
    x: i16,
    y: i16,
    vx: i16,
    vy: i16,
    radius: u8,
    group: bool,
}

#[derive(Arbitrary, Debug)]
enum ColliderSpec {
    Segment { ax: i16, ay: i16, bx: i16, by: i16 },
    Circle { x: i16, y: i16, radius: u8 },
}

#[derive(Arbitrary, Debug)]
struct Spec {
    colliders: Vec<ColliderSpec>,
    balls: Vec<BallSpec>,
}

fn build(spec: &Spec) -> World {
    let mut world = World::new();
    // A closed box around everything, so balls stay near the action.
    let c = [(-9.0, -9.0), (9.0, -9.0), (9.0, 9.0), (-9.0, 9.0)].map(|(x, y)| DVec2::new(x, y));
    for i in 0..4 {
        world
            .add_collider(ColliderDesc::segment(c[i], c[(i + 1) % 4]))
            .expect("the box is valid");
    }
    for collider in spec.colliders.iter().take(12) {
        let desc = match *collider {
            ColliderSpec::Segment { ax, ay, bx, by } => ColliderDesc::segment(
                DVec2::new(coord(ax), coord(ay)),
                DVec2::new(coord(bx), coord(by)),
            ),
            ColliderSpec::Circle { x, y, radius } => {
                ColliderDesc::circle(DVec2::new(coord(x), coord(y)), f64::from(radius) / 64.0)
            }
        };
        // Degenerate shapes are refused with an error: fine.
        let _ = world.add_collider(desc);
    }
    for ball in spec.balls.iter().take(12) {
        let desc = BallDesc::new(
            DVec2::new(coord(ball.x), coord(ball.y)),
            f64::from(ball.radius) / 64.0,
        )
        .velocity(DVec2::new(coord(ball.vx), coord(ball.vy)) * 4.0)
        .groups(groups(ball.group));
        // Overlapping or invalid placements are refused with an error: fine.
        let _ = world.add_ball(desc);
    }
    world
}

fn kinetic(world: &World) -> f64 {
    world
        .balls()
        .map(|(_, b)| 0.5 * b.mass * b.velocity.length_squared())
        .sum()
}

fuzz_target!(|spec: Spec| {
    let mut world = build(&spec);
    let e0 = kinetic(&world);
    let mut last = world.time();
    for _ in 0..2000 {
        let Some(event) = world.step() else {
            break;
        };
        let t = event.time();
        assert!(t >= last, "time went back from {last} to {t}");
        last = t;
        let overlap = deepest_overlap(&world);
        assert!(
            overlap >= -exact2d::OVERLAP_TOLERANCE,
            "overlap {overlap} at t = {t} after {event:?}"
        );
        let e = kinetic(&world);
        assert!(
            (e - e0).abs() <= 1e-9 * e0.max(f64::MIN_POSITIVE),
            "energy {e0} -> {e} at t = {t}"
        );
    }
});
