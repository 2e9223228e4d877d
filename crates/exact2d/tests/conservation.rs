//! Conservation laws and invariants over long runs.
//!
//! - Energy: elastic runs keep the total energy to 1e-12 (relative) over 10^6 collisions with
//!   ball-ball contacts, and to 1e-9 under gravity (kinetic plus potential).
//! - Momentum: ball-ball impulses conserve it, so the total momentum must equal its initial value
//!   plus the impulses the walls delivered, summed from the events (`2 m v_n n` per elastic
//!   bounce) and plus gravity's `M g t`. That bookkeeping rebuilds each impulse from the event's
//!   rounded unit normal and speed and sums hundreds of thousands of them, so it is itself only
//!   good to about 1e-12 of the momentum scale; the bound is 1e-11. A response that ignored the
//!   masses or got a sign wrong would be off by order one.
//! - Invariants, checked after every event and at many frames in between: no overlap deeper than
//!   1e-9, no ball outside its closed container, no ball inside a closed polygon.
//!
//! The container is a rotated octagon and the obstacles are rotated polygons and circles, so no
//! normal is exact and rounding has every chance to accumulate.

mod common;

use common::{Arena, SplitMix, deepest_overlap, energy, signed_inset};
use exact2d::{DVec2, Event, World};

/// Runs until `collisions` collisions, checking the invariants; returns the worst relative
/// energy error, the worst overlap, and the worst momentum mismatch (relative).
fn run(world: &mut World, arena: &Arena, collisions: u64) -> (f64, f64, f64) {
    let e0 = energy(world);
    let mass: f64 = world.balls().map(|(_, b)| b.mass).sum();
    let momentum = |w: &World| w.balls().map(|(_, b)| b.mass * b.velocity).sum::<DVec2>();
    let scale = world
        .balls()
        .map(|(_, b)| b.mass * b.velocity.length())
        .sum::<f64>();
    let p0 = momentum(world);
    let mut wall_impulse = DVec2::ZERO;
    let (mut worst_energy, mut worst_overlap, mut worst_momentum) = (0.0_f64, 0.0_f64, 0.0_f64);
    let mut frame = 0.0;
    while world.event_counts().collisions() < collisions {
        frame += 0.37;
        while let Some(event) = world.step_until(frame).unwrap() {
            match event {
                Event::Contact(c) => {
                    let ball = world.ball(c.ball).unwrap();
                    wall_impulse += c.normal * (2.0 * ball.mass * c.normal_speed);
                    check_contained(arena, ball.position, ball.radius);
                }
                Event::BallContact(c) => {
                    for h in [c.a, c.b] {
                        let ball = world.ball(h).unwrap();
                        check_contained(arena, ball.position, ball.radius);
                    }
                }
                _ => {}
            }
        }
        worst_energy = worst_energy.max(((energy(world) - e0) / e0).abs());
        if frame as u64 % 50 == 0 {
            worst_overlap = worst_overlap.min(deepest_overlap(world));
            for (_, b) in world.balls() {
                check_contained(arena, b.position, b.radius);
            }
        }
        let expected = p0 + wall_impulse + world.gravity() * (mass * world.time());
        worst_momentum = worst_momentum.max((momentum(world) - expected).length() / scale);
    }
    (
        worst_energy,
        worst_overlap.min(deepest_overlap(world)),
        worst_momentum,
    )
}

/// The ball is inside the container and outside every obstacle, to within 1e-9.
fn check_contained(arena: &Arena, p: DVec2, r: f64) {
    assert!(
        signed_inset(&arena.container, p) >= r - 1e-9,
        "ball at {p} left the container"
    );
    assert!(
        !arena.in_obstacle(p),
        "ball centre at {p} inside an obstacle"
    );
}

#[test]
fn a_million_elastic_collisions_with_ball_ball_contacts_conserve_energy_to_1e_12() {
    let arena = Arena::new();
    let mut world = arena.world(DVec2::ZERO);
    let mut rng = SplitMix(7);
    arena.add_balls(&mut world, &mut rng, 40, 3.0);
    let (energy_error, overlap, momentum_error) = run(&mut world, &arena, 1_000_000);
    let counts = world.event_counts();
    println!(
        "{} collisions ({} ball-ball): energy {energy_error:e}, deepest overlap {overlap:e}, \
         momentum {momentum_error:e}",
        counts.collisions(),
        counts.ball_contacts
    );
    assert!(counts.ball_contacts > 200_000);
    assert!(
        energy_error <= 1e-12,
        "relative energy error {energy_error:e}"
    );
    assert!(overlap >= -1e-9, "overlap {overlap:e}");
    assert!(
        momentum_error <= 1e-11,
        "relative momentum error {momentum_error:e}"
    );
}

#[test]
fn elastic_balls_under_gravity_conserve_energy_to_1e_9() {
    let arena = Arena::new();
    let mut world = arena.world(DVec2::new(0.0, -9.81));
    let mut rng = SplitMix(11);
    arena.add_balls(&mut world, &mut rng, 20, 4.0);
    let (energy_error, overlap, momentum_error) = run(&mut world, &arena, 200_000);
    println!(
        "{} collisions under gravity: energy {energy_error:e}, deepest overlap {overlap:e}, \
         momentum {momentum_error:e}",
        world.event_counts().collisions()
    );
    assert!(
        energy_error <= 1e-9,
        "relative energy error {energy_error:e}"
    );
    assert!(overlap >= -1e-9, "overlap {overlap:e}");
    assert!(
        momentum_error <= 1e-9,
        "relative momentum error {momentum_error:e}"
    );
}
