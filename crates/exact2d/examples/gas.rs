//! A hard-disk gas in a box: prints collisions per second and checks energy conservation.
//!
//! ```text
//! cargo run --release -p exact2d --example gas -- [BALLS] [COLLISIONS] [PACKING]
//! ```
//!
//! Defaults: 1000 balls, 10^6 collisions, packing fraction 0.4. Balls start on a square
//! lattice with seeded random velocities (unit mass, unit mean speed) and interact with each
//! other and with the four walls. The full benchmark suite (more scenes, up to 10^6 balls, bytes
//! per ball) is `cargo run --release -p exact2d-bench -- suite`.

use std::time::Instant;

use exact2d::{BallDesc, ColliderDesc, DVec2, World};

fn main() {
    let mut args = std::env::args().skip(1);
    let balls: usize = args
        .next()
        .map_or(1000, |s| s.parse().expect("BALLS must be a number"));
    let target: u64 = args.next().map_or(1_000_000, |s| {
        s.parse().expect("COLLISIONS must be a number")
    });
    let packing: f64 = args
        .next()
        .map_or(0.4, |s| s.parse().expect("PACKING must be a number"));
    let (mut world, radius) = gas(balls, packing, 42);
    let kinetic = |w: &World| {
        w.balls()
            .map(|(_, b)| 0.5 * b.mass * b.velocity.length_squared())
            .sum::<f64>()
    };
    let e0 = kinetic(&world);
    let start = Instant::now();
    let mut t = 0.0;
    while world.event_counts().collisions() < target {
        t += 0.1 * radius;
        world.advance_to(t).expect("time moves forward");
    }
    let elapsed = start.elapsed().as_secs_f64();
    let counts = world.event_counts();
    // FNV-1a over the bits of every position and velocity: the same on every machine, in debug
    // and release, so two builds can be compared for bit-identical runs.
    let fingerprint = world.balls().fold(0xcbf2_9ce4_8422_2325_u64, |h, (_, b)| {
        [b.position.x, b.position.y, b.velocity.x, b.velocity.y]
            .iter()
            .fold(h, |h, x| (h ^ x.to_bits()).wrapping_mul(0x0100_0000_01b3))
    });
    println!(
        "{balls} balls, packing {packing}: {} collisions ({} ball-ball) in {elapsed:.2} s = {:.0} collisions/s; \
         relative energy error {:.1e}; state {fingerprint:016x} at t = {t}",
        counts.collisions(),
        counts.ball_contacts,
        counts.collisions() as f64 / elapsed,
        (kinetic(&world) - e0).abs() / e0,
    );
}

/// `n` balls of equal radius at packing fraction `packing` in a unit-density square box.
fn gas(n: usize, packing: f64, seed: u64) -> (World, f64) {
    let side = (n as f64).sqrt().ceil() as usize;
    let size = side as f64;
    let radius = (packing * size * size / (n as f64 * std::f64::consts::PI)).sqrt();
    assert!(radius < 0.5, "packing too high for a square lattice start");
    let mut world = World::new();
    let c = [
        DVec2::ZERO,
        DVec2::new(size, 0.0),
        DVec2::new(size, size),
        DVec2::new(0.0, size),
    ];
    for i in 0..4 {
        world
            .add_collider(ColliderDesc::segment(c[i], c[(i + 1) % 4]))
            .expect("valid wall");
    }
    let mut state = seed;
    let mut uniform = move || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    for k in 0..n {
        let p = DVec2::new((k % side) as f64 + 0.5, (k / side) as f64 + 0.5);
        let angle = std::f64::consts::TAU * uniform();
        let v = DVec2::new(angle.cos(), angle.sin());
        world
            .add_ball(BallDesc::new(p, radius).velocity(v))
            .expect("lattice sites do not overlap");
    }
    (world, radius)
}
