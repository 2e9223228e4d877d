//! Random small worlds under gravity, with inelastic balls and colliders and optionally the TC
//! model, stepped event by event with every invariant checked after each event: time never
//! goes back and keeps moving (no more than `STALL` events at one exact instant), no two
//! interacting bodies overlap deeper than `exact2d::OVERLAP_TOLERANCE` of their contact
//! distance, no ball leaves the closed box, a supported ball touches its support, and the
//! energy (kinetic plus potential) never grows by more than the micro-hop floor allows.
//!
//! A run stops when the clock passes 1e12 s. Inelastic balls slow down for ever and the clock
//! runs away; past that, an event closer than the clock resolves (2^-100 of the time,
//! `exact2d::RESOLUTION`) is dropped, as documented, so a slow ball may pass a wall; and
//! further on squared speeds leave the kernels' domain (findings at t = 4e42 and 2e159).
#![no_main]

use arbitrary::Arbitrary;
use exact2d::{BallDesc, ColliderDesc, DVec2, MICRO_HOP, World};
use libfuzzer_sys::fuzz_target;

mod common;
use common::{coord, deepest_overlap, gap, groups};

/// Events at one exact instant before the clock counts as stalled. A jammed column (a ball
/// pushing another into a wall, perfectly inelastic) converges by halving its speed twice per
/// cycle of two zero-time collisions, until it underflows: about 2200 events for unit masses.
const STALL: usize = 10_000;

/// Restitutions from a small set that includes the extremes.
fn restitution(r: u8) -> f64 {
    [1.0, 0.9, 0.5, 0.0][usize::from(r % 4)]
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
    /// Gravity: straight down, tilted, or sideways.
    gravity: u8,
    /// Whether the TC model is on.
    collapse: bool,
    colliders: Vec<ColliderSpec>,
    balls: Vec<BallSpec>,
}

fn build(spec: &Spec) -> World {
    let g = [(0.0, -10.0), (3.0, -8.0), (-10.0, 0.0), (0.0, -1.0)][usize::from(spec.gravity % 4)];
    let mut world = World::with_gravity(DVec2::new(g.0, g.1)).expect("finite gravity");
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
            .restitution(restitution(r)),
            ColliderSpec::Circle {
                x,
                y,
                radius,
                restitution: r,
            } => ColliderDesc::circle(DVec2::new(coord(x), coord(y)), f64::from(radius) / 64.0)
                .restitution(restitution(r)),
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
        .groups(groups(ball.group));
        let _ = world.add_ball(desc);
    }
    world
}

fn energy(world: &World) -> f64 {
    let g = world.gravity();
    world
        .balls()
        .map(|(_, b)| b.mass * (0.5 * b.velocity.length_squared() - g.dot(b.position)))
        .sum()
}

fuzz_target!(|spec: Spec| {
    let mut world = build(&spec);
    let e0 = energy(&world);
    let g = world.gravity().length();
    let mass: f64 = world.balls().map(|(_, b)| b.mass).sum();
    let mut last = world.exact_time();
    let mut same = 0;
    let mut micro_hops = 0.0;
    for _ in 0..2000 {
        let Some(event) = world.step() else {
            break;
        };
        if world.time() > 1e12 {
            break;
        }
        let now = world.exact_time();
        assert!(now >= last, "time went back from {last:?} to {now:?}");
        same = if now == last { same + 1 } else { 0 };
        assert!(same < STALL, "{STALL} events at t = {now:?}: {event:?}");
        last = now;
        let t = event.time();
        let overlap = deepest_overlap(&world);
        assert!(
            overlap >= -exact2d::OVERLAP_TOLERANCE,
            "overlap {overlap} at t = {t} after {event:?}"
        );
        for (h, b) in world.balls() {
            assert!(
                b.position.abs().max_element() <= 9.0 - b.radius + 1e-9,
                "ball {h:?} left the box: {b:?}"
            );
            if let Some((c, _)) = world.ball_support(h) {
                let shape = world.collider(c).expect("a live support").shape;
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
});
