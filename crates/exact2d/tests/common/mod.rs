//! Scene builders and checks shared by the integration tests.
#![allow(dead_code)]

use exact2d::{BallDesc, BallHandle, ColliderDesc, ColliderHandle, DVec2, Event, Shape, World};

/// The vector `(x, y)`, short.
pub fn v(x: f64, y: f64) -> DVec2 {
    DVec2::new(x, y)
}

/// SplitMix64, the golden run's generator (`determinism-check`), so tests need no RNG crate
/// and never change.
pub use determinism_check::engine::SplitMix;

/// A world (with `gravity`) in the fuzz targets' closed box `[-9, 9]^2`, its walls of
/// `restitution`.
pub fn fuzz_box(gravity: DVec2, restitution: f64) -> World {
    let mut world = World::with_gravity(gravity).unwrap();
    let c = [(-9.0, -9.0), (9.0, -9.0), (9.0, 9.0), (-9.0, 9.0)].map(|(x, y)| DVec2::new(x, y));
    add_polygon_of(&mut world, &c, restitution);
    world
}

/// A world (with `gravity`) inside the closed square box `[0, size]^2`: walls 0 (bottom), 1
/// (right), 2 (top), 3 (left), counter-clockwise.
pub fn boxed(size: f64, gravity: DVec2) -> World {
    boxed_rect(size, size, gravity)
}

/// A world (with `gravity`) inside the closed box `[0, width] x [0, height]`: walls 0
/// (bottom), 1 (right), 2 (top), 3 (left), counter-clockwise.
pub fn boxed_rect(width: f64, height: f64, gravity: DVec2) -> World {
    let mut world = World::with_gravity(gravity).unwrap();
    add_polygon(&mut world, &rectangle(width, height));
    world
}

/// The corners of the rectangle `[0, width] x [0, height]`, counter-clockwise from the origin.
pub fn rectangle(width: f64, height: f64) -> [DVec2; 4] {
    [
        DVec2::new(0.0, 0.0),
        DVec2::new(width, 0.0),
        DVec2::new(width, height),
        DVec2::new(0.0, height),
    ]
}

/// A floor: the segment from `(from, 0)` to `(to, 0)`, perfectly elastic.
pub fn floor(world: &mut World, from: f64, to: f64) -> ColliderHandle {
    world
        .add_collider(ColliderDesc::segment(v(from, 0.0), v(to, 0.0)))
        .unwrap()
}

/// Adds a ball at `p` of radius `r` and restitution `e` (unit mass, at rest).
pub fn ball(world: &mut World, p: DVec2, r: f64, e: f64) -> BallHandle {
    world.add_ball(BallDesc::new(p, r).restitution(e)).unwrap()
}

/// The vertices of a regular polygon, counter-clockwise, rotated by `angle` (radians).
pub fn regular_polygon(center: DVec2, radius: f64, sides: usize, angle: f64) -> Vec<DVec2> {
    (0..sides)
        .map(|k| {
            let a = angle + std::f64::consts::TAU * k as f64 / sides as f64;
            center + DVec2::new(a.cos(), a.sin()) * radius
        })
        .collect()
}

/// Adds a closed polygon as segments sharing their end points (perfectly elastic), each from
/// a vertex to the next.
pub fn add_polygon(world: &mut World, vertices: &[DVec2]) {
    add_polygon_of(world, vertices, 1.0);
}

/// Adds a closed polygon as segments of `restitution` sharing their end points, each from a
/// vertex to the next.
pub fn add_polygon_of(world: &mut World, vertices: &[DVec2], restitution: f64) {
    for i in 0..vertices.len() {
        let (a, b) = (vertices[i], vertices[(i + 1) % vertices.len()]);
        world
            .add_collider(ColliderDesc::segment(a, b).restitution(restitution))
            .unwrap();
    }
}

/// Whether `p` is inside the convex polygon (counter-clockwise vertices), at least `margin` from
/// every edge's line.
pub fn inside_convex(vertices: &[DVec2], p: DVec2, margin: f64) -> bool {
    signed_inset(vertices, p) >= margin
}

/// The smallest signed distance from `p` to the lines of a convex counter-clockwise polygon's
/// edges: positive inside.
pub fn signed_inset(vertices: &[DVec2], p: DVec2) -> f64 {
    (0..vertices.len())
        .map(|i| {
            let (a, b) = (vertices[i], vertices[(i + 1) % vertices.len()]);
            (b - a).perp_dot(p - a) / (b - a).length()
        })
        .fold(f64::INFINITY, f64::min)
}

/// A closed container (a rotated octagon, so no wall is axis-aligned and no normal is exact)
/// holding two rotated closed polygons and two static circles.
pub struct Arena {
    pub container: Vec<DVec2>,
    pub obstacles: Vec<Vec<DVec2>>,
    pub pegs: Vec<(DVec2, f64)>,
}

impl Arena {
    pub fn new() -> Self {
        Self {
            container: regular_polygon(DVec2::ZERO, 10.0, 8, 0.3),
            obstacles: vec![
                regular_polygon(DVec2::new(-3.0, 2.0), 1.5, 3, 0.1),
                regular_polygon(DVec2::new(3.0, -2.0), 1.2, 4, 0.7),
            ],
            pegs: vec![(DVec2::new(3.0, 3.5), 0.8), (DVec2::new(-3.0, -3.0), 1.0)],
        }
    }

    pub fn world(&self, gravity: DVec2) -> World {
        let mut world = World::with_gravity(gravity).unwrap();
        add_polygon(&mut world, &self.container);
        for polygon in &self.obstacles {
            add_polygon(&mut world, polygon);
        }
        for &(c, r) in &self.pegs {
            world.add_collider(ColliderDesc::circle(c, r)).unwrap();
        }
        world
    }

    /// Adds `n` balls at random free places with random velocities, radii and masses.
    pub fn add_balls(&self, world: &mut World, rng: &mut SplitMix, n: usize, speed: f64) {
        let mut added = 0;
        while added < n {
            let r = rng.range(0.15, 0.4);
            let p = DVec2::new(rng.range(-9.0, 9.0), rng.range(-9.0, 9.0));
            let dir = rng.range(0.0, std::f64::consts::TAU);
            let v = DVec2::new(dir.cos(), dir.sin()) * speed * rng.range(0.5, 1.5);
            let desc = BallDesc::new(p, r).velocity(v).mass(rng.range(0.5, 3.0));
            if !inside_convex(&self.container, p, r) || self.in_obstacle(p) {
                continue;
            }
            if world.add_ball(desc).is_ok() {
                added += 1;
            }
        }
    }

    pub fn in_obstacle(&self, p: DVec2) -> bool {
        self.obstacles.iter().any(|o| inside_convex(o, p, 0.0))
    }
}

/// The most negative gap between any two balls, and between any ball and any solid collider,
/// at the world's current time (0 if nothing overlaps).
pub fn deepest_overlap(world: &World) -> f64 {
    let balls: Vec<_> = world.balls().map(|(_, b)| b).collect();
    let mut worst: f64 = 0.0;
    for (i, a) in balls.iter().enumerate() {
        for b in &balls[..i] {
            if a.groups.interact(b.groups) {
                worst = worst.min(a.position.distance(b.position) - a.radius - b.radius);
            }
        }
        for (_, c) in world.colliders() {
            if !c.sensor {
                worst = worst.min(gap(&c.shape, a.position, a.radius));
            }
        }
    }
    worst
}

/// The gap between a ball and a shape (negative when overlapping).
pub fn gap(shape: &Shape, p: DVec2, r: f64) -> f64 {
    match shape {
        Shape::Segment(s) => s.distance(p) - r,
        Shape::Circle(c) => p.distance(c.center) - c.radius - r,
    }
}

/// Kinetic plus potential energy (potential zero at the origin).
pub fn energy(world: &World) -> f64 {
    energy_about(world, DVec2::ZERO)
}

/// Kinetic plus potential energy, the potential zero at `origin`.
pub fn energy_about(world: &World, origin: DVec2) -> f64 {
    let g = world.gravity();
    world
        .balls()
        .map(|(_, b)| b.mass * (0.5 * b.velocity.length_squared() - g.dot(b.position - origin)))
        .sum()
}

/// Steps until nothing happens before `until` (at most `limit` events), checking after each
/// event that nothing overlaps deeper than 1e-9 of a contact distance; returns the events.
pub fn run(world: &mut World, until: f64, limit: usize) -> Vec<Event> {
    checked_run(world, until, limit, false)
}

/// As [`run`], checking as well after each event that the [`energy`] never grows past its
/// start (to 1e-9 of it, or of 1).
pub fn run_dissipative(world: &mut World, until: f64, limit: usize) -> Vec<Event> {
    checked_run(world, until, limit, true)
}

fn checked_run(
    world: &mut World,
    until: f64,
    limit: usize,
    energy_never_grows: bool,
) -> Vec<Event> {
    let mut events = Vec::new();
    let start = energy(world);
    while let Some(event) = world.step_until(until).unwrap() {
        events.push(event);
        let overlap = deepest_overlap(world);
        assert!(
            overlap > -1e-9,
            "overlap {overlap} at t = {} after {event:?}",
            world.time()
        );
        if energy_never_grows {
            let now = energy(world);
            assert!(
                now <= start + 1e-9 * start.abs().max(1.0),
                "energy grew from {start} to {now} at t = {}",
                world.time()
            );
        }
        assert!(
            events.len() < limit,
            "more than {limit} events by t = {}",
            world.time()
        );
    }
    events
}

/// FNV-1a over 64-bit words: a stable hash for golden values (std's hasher may change).
pub fn fnv1a(words: impl IntoIterator<Item = u64>) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for w in words {
        for byte in w.to_le_bytes() {
            h = (h ^ u64::from(byte)).wrapping_mul(0x0100_0000_01b3);
        }
    }
    h
}

/// A proptest configuration with `cases` cases (or `PROPTEST_CASES`) from the fixed `seed`
/// (or `PROPTEST_RNG_SEED`), so that every run checks the same inputs; no regression files
/// are written into the source tree.
pub fn proptest_config(seed: u64, cases: u32) -> proptest::test_runner::Config {
    use proptest::test_runner::{Config, RngSeed};
    let default = Config::default();
    let rng_seed = match default.rng_seed {
        RngSeed::Random => RngSeed::Fixed(seed),
        chosen => chosen,
    };
    let cases = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(cases);
    Config {
        cases,
        max_global_rejects: 4 * cases,
        failure_persistence: None,
        rng_seed,
        ..default
    }
}

/// Asserts `a` equals `b` to 1e-12 of `1 + |b|`, naming `what`.
pub fn close(a: f64, b: f64, what: &str) {
    assert!(
        (a - b).abs() <= 1e-12 * (1.0 + b.abs()),
        "{what}: {a} where {b}"
    );
}
