//! Small worlds under gravity, stepped event by event with every invariant checked after each
//! event. The low bit of the input's first byte picks the mode:
//!
//! - **random** (bit clear): a random world (balls and colliders on a 1/64 grid in a closed
//!   box, inelastic, gravity down, tilted or sideways, optionally the TC model) from the
//!   other bytes. After each event: time never goes back; the clock moves on (no more than
//!   `exact2d_hunt::check::EVENTS_PER_BALL` events, internal ones included, per ball that had
//!   one at a single instant, and the engine never reports `WorldError::Stalled`); no two
//!   interacting bodies overlap deeper than `exact2d::overlap_bound` of their coordinates and
//!   contact distance; no ball leaves the closed box; a supported ball touches its support;
//!   and the energy (kinetic plus potential) never grows by more than the micro-hop floor
//!   allows. With the gravity byte's bit 6 set the world is a table seen from above instead
//!   (no gravity in the plane, a cloth of sliding friction 0.2 or 1, balls with rolls).
//! - **adversarial** (bit set): a scene from `exact2d_hunt::generate` (exact fits, touching
//!   placements, wedges, funnels, round numbers, scales 1e-6 to 1e6, offsets to 1e9) with
//!   gravity, elastic or not as the second byte's low bit says (and laid on a table seen
//!   from above, `generate::lay_on_table`, if its second bit is set), steered by the other bytes,
//!   run for 2 s or 20,000 events with every check of `exact2d_hunt::check` after every event
//!   (time, stall, overlap, containment in its box, energy growth beyond the engine's
//!   floors); any finding, or a generated scene the engine refuses, panics.
//!
//! A random run stops when the clock passes 1e12 s. Inelastic balls slow down for ever and
//! the clock runs away; past that, an event closer than the clock resolves (2^-100 of the
//! time, `exact2d::RESOLUTION`) is dropped, as documented, so a slow ball may pass a wall;
//! and further on squared speeds leave the kernels' domain (findings at t = 4e42 and 2e159).
#![no_main]

use arbitrary::{Arbitrary, Unstructured};
use exact2d::{BallDesc, ColliderDesc, DVec2, MICRO_HOP, Table, World};
use libfuzzer_sys::fuzz_target;

mod common;
use common::{Mode, check_instant, coord, gap, groups, next_event, overlap};
use exact2d_hunt::generate::Options;

/// Restitutions from a small set that includes the extremes (the byte's low two bits).
fn restitution(r: u8) -> f64 {
    [1.0, 0.9, 0.5, 0.0][usize::from(r % 4)]
}

/// Friction and tangential restitution from the same byte's next four bits: frictionless
/// half the time, otherwise mu 0.3 or 1 with beta -1, 0, 0.5 or 1 (friction at impacts).
fn roughness(r: u8) -> (f64, f64) {
    let mu = [0.0, 0.0, 0.3, 1.0][usize::from((r >> 2) % 4)];
    let beta = [0.0, -1.0, 0.5, 1.0][usize::from((r >> 4) % 4)];
    (mu, beta)
}

/// A ball's spin from the byte's top two bits.
fn spin(r: u8) -> f64 {
    [0.0, 0.0, 5.0, -20.0][usize::from(r >> 6)]
}

#[derive(Arbitrary, Debug)]
struct BallSpec {
    x: i16,
    y: i16,
    vx: i16,
    vy: i16,
    radius: u8,
    restitution: u8,
    group: bool,
}

#[derive(Arbitrary, Debug)]
enum ColliderSpec {
    Segment {
        ax: i16,
        ay: i16,
        bx: i16,
        by: i16,
        restitution: u8,
    },
    Circle {
        x: i16,
        y: i16,
        radius: u8,
        restitution: u8,
    },
}

#[derive(Arbitrary, Debug)]
struct Spec {
    /// Gravity: straight down, tilted, or sideways (the low two bits); the top bit turns
    /// sleeping on.
    gravity: u8,
    /// Whether the TC model is on.
    collapse: bool,
    colliders: Vec<ColliderSpec>,
    balls: Vec<BallSpec>,
}

fn build(spec: &Spec) -> World {
    let g = [(0.0, -10.0), (3.0, -8.0), (-10.0, 0.0), (0.0, -1.0)][usize::from(spec.gravity % 4)];
    let table = spec.gravity & 0x40 != 0;
    let mut world = if table {
        let mut world = World::new();
        let cloth = Table {
            gravity: 10.0,
            sliding_friction: [0.2, 1.0][usize::from(spec.gravity >> 2 & 1)],
            rolling_friction: 0.01,
            spinning_friction: 0.01,
        };
        world.set_table(Some(cloth)).expect("a valid table");
        world
    } else {
        World::with_gravity(DVec2::new(g.0, g.1)).expect("finite gravity")
    };
    world.set_sleeping(spec.gravity & 0x80 != 0);
    if spec.collapse {
        world
            .set_collapse_time(1e-3)
            .expect("a valid collapse time");
    }
    let c = [(-9.0, -9.0), (9.0, -9.0), (9.0, 9.0), (-9.0, 9.0)].map(|(x, y)| DVec2::new(x, y));
    for i in 0..4 {
        world
            .add_collider(ColliderDesc::segment(c[i], c[(i + 1) % 4]).restitution(0.5))
            .expect("the box is valid");
    }
    for collider in spec.colliders.iter().take(12) {
        let desc = match *collider {
            ColliderSpec::Segment {
                ax,
                ay,
                bx,
                by,
                restitution: r,
            } => ColliderDesc::segment(
                DVec2::new(coord(ax), coord(ay)),
                DVec2::new(coord(bx), coord(by)),
            )
            .restitution(restitution(r))
            .friction(roughness(r).0)
            .tangential_restitution(roughness(r).1),
            ColliderSpec::Circle {
                x,
                y,
                radius,
                restitution: r,
            } => ColliderDesc::circle(DVec2::new(coord(x), coord(y)), f64::from(radius) / 64.0)
                .restitution(restitution(r))
                .friction(roughness(r).0)
                .tangential_restitution(roughness(r).1),
        };
        let _ = world.add_collider(desc);
    }
    for ball in spec.balls.iter().take(12) {
        let desc = BallDesc::new(
            DVec2::new(coord(ball.x), coord(ball.y)),
            f64::from(ball.radius) / 64.0,
        )
        .velocity(DVec2::new(coord(ball.vx), coord(ball.vy)))
        .restitution(restitution(ball.restitution))
        .friction(roughness(ball.restitution).0)
        .tangential_restitution(roughness(ball.restitution).1)
        .spin(spin(ball.restitution))
        .groups(groups(ball.group));
        // On a table, a roll of up to eight times the speed scale over the radius.
        let desc = if table {
            let r = f64::from(ball.radius.max(1)) / 64.0;
            desc.roll(DVec2::new(coord(ball.vy), -coord(ball.vx)) / r)
        } else {
            desc
        };
        let _ = world.add_ball(desc);
    }
    world
}

fn energy(world: &World) -> f64 {
    let g = world.gravity();
    world
        .balls()
        .map(|(_, b)| b.kinetic_energy() - b.mass * g.dot(b.position))
        .sum()
}

fuzz_target!(|data: &[u8]| match common::mode(data) {
    None => {}
    Some(Mode::Random(bytes)) => {
        if let Ok(spec) = Spec::arbitrary_take_rest(Unstructured::new(bytes)) {
            random(&spec);
        }
    }
    Some(Mode::Adversarial(bytes)) => {
        // The input's second byte: its low bit says every restitution is 1; the bytes after it
        // steer the generator.
        let (elastic, bytes) = bytes
            .split_first()
            .map_or((false, bytes), |(b, rest)| (b & 1 == 1, rest));
        let table = bytes.first().is_some_and(|b| b & 2 != 0);
        common::adversarial(
            bytes,
            Options {
                gravity: true,
                elastic,
            },
            table,
        );
    }
});

fn random(spec: &Spec) {
    let mut world = build(spec);
    let e0 = energy(&world);
    let g = world.gravity().length();
    let mass: f64 = world.balls().map(|(_, b)| b.mass).sum();
    let mut last = world.exact_time();
    let mut micro_hops = 0.0;
    for _ in 0..2000 {
        let Some(event) = next_event(&mut world, 1e12) else {
            break;
        };
        let now = world.exact_time();
        assert!(now >= last, "time went back from {last:?} to {now:?}");
        last = now;
        let t = event.time();
        check_instant(&world, t);
        if let Some(overlap) = overlap(&world) {
            panic!("{overlap} at t = {t} after {event:?}");
        }
        for (h, b) in world.balls() {
            // Out of the box by no more than the engine lets a ball into a wall.
            let slack = exact2d::overlap_bound(9.0, b.radius).max(1e-9);
            assert!(
                b.position.abs().max_element() <= 9.0 - b.radius + slack,
                "ball {h:?} left the box: {b:?}"
            );
            if let Some((c, _)) = world.ball_support(h) {
                let Some(col) = world.collider(c) else {
                    panic!(
                        "ball {h:?} (asleep since {:?}) reports {c:?} as its support, not a live collider, at t = {t} after {event:?}",
                        world.ball_asleep_since(h)
                    );
                };
                let shape = col.shape;
                let (gap, reach) = gap(&shape, b.position, b.radius);
                assert!(
                    gap <= 1e-5 * reach,
                    "ball {h:?} is {gap} off its support {c:?} at t = {t}"
                );
            }
        }
        // A micro-hop floor may add up to m |pull| MICRO_HOP scale per ball-ball contact.
        if matches!(event, exact2d::Event::BallContact(_)) {
            micro_hops += 2.0 * mass * g * MICRO_HOP * 20.0;
        }
        let e = energy(&world);
        let scale = e0.abs().max(mass * g * 20.0).max(f64::MIN_POSITIVE);
        assert!(
            e <= e0 + 1e-9 * scale + micro_hops,
            "energy grew from {e0} to {e} at t = {t} after {event:?}"
        );
    }
}
