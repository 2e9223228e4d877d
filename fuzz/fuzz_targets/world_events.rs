//! Small worlds without gravity, every restitution 1, stepped event by event with every
//! invariant checked after each event. The low bit of the input's first byte picks the mode:
//!
//! - **random** (bit clear): a random world in general position (balls, segments, circles,
//!   groups on a 1/64 grid in a closed box) from the other bytes. After each event: time
//!   never goes back; the clock moves on (no more than
//!   `exact2d_hunt::check::EVENTS_PER_BALL` events, internal ones included, per ball that had
//!   one at a single instant, and the engine never reports `WorldError::Stalled`); no two
//!   interacting bodies overlap deeper than `exact2d::overlap_bound` of their coordinates and
//!   contact distance; and the kinetic energy is kept to 1e-9, both ways unless a jam (a
//!   simultaneous plastic impact, counted in `EventCounts::jams`) has happened, which may
//!   only remove energy. Worlds the API refuses (overlapping placements, degenerate segments)
//!   are errors, never panics.
//! - **adversarial** (bit set): a scene from `exact2d_hunt::generate` (exact fits, touching
//!   placements, wedges, funnels, round numbers, scales 1e-6 to 1e6, offsets to 1e9) with
//!   gravity off and every restitution 1, steered by the other bytes, run for 2 s or 20,000
//!   events with every check of `exact2d_hunt::check` after every event (time, stall,
//!   overlap, containment in its box, energy growth); any finding, or a generated scene the
//!   engine refuses, panics.
//!
//!   With the first byte's second bit set too, the scene is a periodic box instead, from
//!   `exact2d_hunt::periodic::generate_periodic` (balls on and through its edges, rows
//!   wrapping round it, boxes 6.6 radii across, scales 1e-6 to 1e6, restitutions 1 to 0),
//!   with the same checks (pairs through their nearest images, every ball in the box).
//!
//! `world_gravity` covers gravity, inelastic balls, resting contact and the TC model.
#![no_main]

use arbitrary::{Arbitrary, Unstructured};
use exact2d::{BallDesc, ColliderDesc, DVec2, World};
use libfuzzer_sys::fuzz_target;

mod common;
use common::{Mode, check_instant, coord, groups, next_event, overlap};
use exact2d_hunt::generate::Options;

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
    world.balls().map(|(_, b)| b.kinetic_energy()).sum()
}

fuzz_target!(|data: &[u8]| match common::mode(data) {
    None => {}
    Some(Mode::Random(bytes)) => {
        if let Ok(spec) = Spec::arbitrary_take_rest(Unstructured::new(bytes)) {
            random(&spec);
        }
    }
    // The second bit of the first byte picks a periodic box instead.
    Some(Mode::Adversarial(bytes)) if data[0] & 2 != 0 => common::periodic(bytes),
    Some(Mode::Adversarial(bytes)) => common::adversarial(
        bytes,
        Options {
            gravity: false,
            elastic: true,
        },
        false,
    ),
});

fn random(spec: &Spec) {
    let mut world = build(spec);
    let e0 = kinetic(&world);
    let tolerance = 1e-9 * e0.max(f64::MIN_POSITIVE);
    let mut last = world.time();
    for _ in 0..2000 {
        let Some(event) = next_event(&mut world, f64::INFINITY) else {
            break;
        };
        let t = event.time();
        assert!(t >= last, "time went back from {last} to {t}");
        last = t;
        check_instant(&world, t);
        if let Some(overlap) = overlap(&world) {
            panic!("{overlap} at t = {t} after {event:?}");
        }
        let e = kinetic(&world);
        // A jam may only remove energy; without one, energy is kept both ways.
        let jams = world.event_counts().jams;
        let lowest = if jams > 0 {
            f64::NEG_INFINITY
        } else {
            e0 - tolerance
        };
        assert!(
            e <= e0 + tolerance && e >= lowest,
            "energy {e0} -> {e} at t = {t} after {event:?} ({jams} jams)"
        );
    }
}
