//! The engine's golden run: a closed arena (a rotated octagon holding two rotated polygons
//! and two pegs) with 25 balls under gravity, a sensor that launches every ball entering it,
//! and changes made between events. Every bit of every event and of the state at every frame
//! end is hashed.

use exact2d::{BallDesc, ColliderDesc, DVec2, Event, EventCounts, World};

use crate::fnv1a;
use crate::trig::sin_cos;

/// SplitMix64: a tiny deterministic generator, so the scenes need no RNG crate and never
/// change.
#[derive(Clone, Debug)]
pub struct SplitMix(pub u64);

impl SplitMix {
    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A double in `[0, 1)`, a multiple of 2^-53.
    pub fn next_f64(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A double in `[lo, hi)`.
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next_f64()
    }
}

/// What the golden run saw: its hash, and what proves it exercised what it should.
#[derive(Clone, Copy, Debug)]
pub struct GoldenRun {
    /// FNV-1a over every event's bits and the state at every frame end.
    pub hash: u64,
    /// The events the world handled.
    pub counts: EventCounts,
    /// Whether all four changes between events (a collider removed, one added, a ball
    /// removed, one added) were made.
    pub every_change_made: bool,
}

/// The golden run, its frames cut at `frames` (sorted times up to 40 s): gravity, ball-ball
/// contacts, end points, circles, a sensor, and changes made between events.
#[must_use]
pub fn golden_run(frames: &[f64]) -> GoldenRun {
    let arena = Arena::new();
    let mut world = arena.world(DVec2::new(0.0, -3.0));
    let mut rng = SplitMix(99);
    arena.add_balls(&mut world, &mut rng, 25, 5.0);
    let pickup = ColliderDesc::circle(DVec2::new(0.0, 0.0), 1.5).sensor(true);
    world.add_collider(pickup).expect("the sensor is valid");
    let mut words = Vec::new();
    let mut changed = [false; 4];
    for &frame in frames {
        while let Some(event) = world.step_until(frame).expect("a valid frame time") {
            words.extend(event_words(&event));
            react(&mut world, &event, &mut changed);
        }
        words.extend(state_words(&world));
    }
    GoldenRun {
        hash: fnv1a(words),
        counts: world.event_counts(),
        every_change_made: changed.iter().all(|&c| c),
    }
}

/// Another arena run (balls from seed 5, no sensor, no changes) hashing only what does not
/// depend on the frames: the events and the state at the last frame.
#[must_use]
pub fn events_and_end(frames: &[f64]) -> u64 {
    let arena = Arena::new();
    let mut world = arena.world(DVec2::new(0.0, -3.0));
    let mut rng = SplitMix(5);
    arena.add_balls(&mut world, &mut rng, 25, 5.0);
    let mut words = Vec::new();
    for &frame in frames {
        while let Some(event) = world.step_until(frame).expect("a valid frame time") {
            words.extend(event_words(&event));
        }
    }
    words.extend(state_words(&world));
    fnv1a(words)
}

/// Frames of `step` seconds up to 40 s.
#[must_use]
pub fn regular_frames(step: f64) -> Vec<f64> {
    (1..=(40.0 / step) as usize)
        .map(|k| k as f64 * step)
        .collect()
}

/// 3000 frame ends at random times (SplitMix seed 1) in `[0, 40)`, then 40, sorted.
#[must_use]
pub fn irregular_frames() -> Vec<f64> {
    let mut rng = SplitMix(1);
    let mut frames: Vec<f64> = (0..3000).map(|_| rng.range(0.0, 40.0)).collect();
    frames.push(40.0);
    frames.sort_by(f64::total_cmp);
    frames
}

/// Every bit of an event: its time, its kind, the bodies and the geometry.
fn event_words(event: &Event) -> Vec<u64> {
    match event {
        Event::Contact(c) => vec![
            0,
            c.time.to_bits(),
            u64::from(c.ball.index()),
            u64::from(c.collider.index()),
            c.feature as u64,
            c.point.x.to_bits(),
            c.point.y.to_bits(),
            c.normal.x.to_bits(),
            c.normal.y.to_bits(),
        ],
        Event::BallContact(c) => vec![
            1,
            c.time.to_bits(),
            u64::from(c.a.index()),
            u64::from(c.b.index()),
            c.point.x.to_bits(),
            c.point.y.to_bits(),
        ],
        Event::SensorEnter(s) | Event::SensorExit(s) => vec![
            2 + u64::from(matches!(event, Event::SensorExit(_))),
            s.time.to_bits(),
            u64::from(s.ball.index()),
            u64::from(s.collider.index()),
        ],
    }
}

/// Every ball's handle index, position and velocity.
fn state_words(world: &World) -> Vec<u64> {
    world
        .balls()
        .flat_map(|(h, b)| {
            [
                u64::from(h.index()),
                b.position.x.to_bits(),
                b.position.y.to_bits(),
                b.velocity.x.to_bits(),
                b.velocity.y.to_bits(),
            ]
        })
        .collect()
}

/// Deterministic reactions to events, as a game would make them.
fn react(world: &mut World, event: &Event, changed: &mut [bool; 4]) {
    let t = event.time();
    if let Event::SensorEnter(s) = event {
        // Every ball entering the pick-up is launched upwards at a fixed speed.
        world
            .set_ball_velocity(s.ball, DVec2::new(0.5, 6.0))
            .expect("the ball exists");
    }
    if t > 10.0 && !changed[0] {
        changed[0] = true;
        let tenth = world.colliders().nth(9).map(|(h, _)| h);
        world
            .remove_collider(tenth.expect("ten colliders"))
            .expect("the collider exists");
    }
    if t > 15.0 && !changed[1] {
        changed[1] = true;
        let wall = ColliderDesc::segment(DVec2::new(-2.0, -7.0), DVec2::new(2.0, -6.5));
        // The engine may refuse a wall through a ball; the run goes on either way.
        let _ = world.add_collider(wall);
    }
    if t > 20.0 && !changed[2] {
        changed[2] = true;
        let fourth = world.balls().nth(3).map(|(h, _)| h);
        world
            .remove_ball(fourth.expect("four balls"))
            .expect("the ball exists");
    }
    if t > 25.0 && !changed[3] {
        changed[3] = true;
        // Refused if the place is taken; the run goes on either way.
        let _ =
            world.add_ball(BallDesc::new(DVec2::new(0.0, 8.5), 0.3).velocity(DVec2::new(3.0, 0.0)));
    }
}

/// A closed container (a rotated octagon, so no wall is axis-aligned and no normal is exact)
/// holding two rotated closed polygons and two static circles.
///
/// Its vertices and the balls' directions take their sines and cosines from [`sin_cos`],
/// correctly rounded in plain arithmetic: the platforms' `f64::sin` and `f64::cos` differ
/// in their last bits (see [`crate::trig`]).
struct Arena {
    container: Vec<DVec2>,
    obstacles: Vec<Vec<DVec2>>,
    pegs: Vec<(DVec2, f64)>,
}

impl Arena {
    fn new() -> Self {
        Self {
            container: regular_polygon(DVec2::ZERO, 10.0, 8, 0.3),
            obstacles: vec![
                regular_polygon(DVec2::new(-3.0, 2.0), 1.5, 3, 0.1),
                regular_polygon(DVec2::new(3.0, -2.0), 1.2, 4, 0.7),
            ],
            pegs: vec![(DVec2::new(3.0, 3.5), 0.8), (DVec2::new(-3.0, -3.0), 1.0)],
        }
    }

    fn world(&self, gravity: DVec2) -> World {
        let mut world = World::with_gravity(gravity).expect("a finite gravity");
        add_polygon(&mut world, &self.container);
        for polygon in &self.obstacles {
            add_polygon(&mut world, polygon);
        }
        for &(c, r) in &self.pegs {
            world
                .add_collider(ColliderDesc::circle(c, r))
                .expect("a valid peg");
        }
        world
    }

    /// Adds `n` balls at random free places with random velocities, radii and masses.
    fn add_balls(&self, world: &mut World, rng: &mut SplitMix, n: usize, speed: f64) {
        let mut added = 0;
        while added < n {
            let r = rng.range(0.15, 0.4);
            let p = DVec2::new(rng.range(-9.0, 9.0), rng.range(-9.0, 9.0));
            let dir = rng.range(0.0, std::f64::consts::TAU);
            let (sin, cos) = sin_cos(dir);
            let v = DVec2::new(cos, sin) * speed * rng.range(0.5, 1.5);
            let desc = BallDesc::new(p, r).velocity(v).mass(rng.range(0.5, 3.0));
            if !inside_convex(&self.container, p, r) || self.in_obstacle(p) {
                continue;
            }
            if world.add_ball(desc).is_ok() {
                added += 1;
            }
        }
    }

    fn in_obstacle(&self, p: DVec2) -> bool {
        self.obstacles.iter().any(|o| inside_convex(o, p, 0.0))
    }
}

/// The vertices of a regular polygon, counter-clockwise, rotated by `angle` (radians).
fn regular_polygon(center: DVec2, radius: f64, sides: usize, angle: f64) -> Vec<DVec2> {
    (0..sides)
        .map(|k| {
            let a = angle + std::f64::consts::TAU * k as f64 / sides as f64;
            let (sin, cos) = sin_cos(a);
            center + DVec2::new(cos, sin) * radius
        })
        .collect()
}

/// Adds a closed polygon as perfectly elastic segments sharing their end points.
fn add_polygon(world: &mut World, vertices: &[DVec2]) {
    for i in 0..vertices.len() {
        let (a, b) = (vertices[i], vertices[(i + 1) % vertices.len()]);
        world
            .add_collider(ColliderDesc::segment(a, b).restitution(1.0))
            .expect("a valid segment");
    }
}

/// Whether `p` is inside the convex polygon (counter-clockwise vertices), at least `margin`
/// from every edge's line.
fn inside_convex(vertices: &[DVec2], p: DVec2, margin: f64) -> bool {
    let inset = (0..vertices.len())
        .map(|i| {
            let (a, b) = (vertices[i], vertices[(i + 1) % vertices.len()]);
            (b - a).perp_dot(p - a) / (b - a).length()
        })
        .fold(f64::INFINITY, f64::min);
    inset >= margin
}

/// The resting pile's world at its start (see [`resting_pile`]): 24 balls (radius 0.2,
/// restitution 0.5) on a jittered grid over the floor of a box 3 wide, sleeping on.
#[must_use]
pub fn resting_pile_world() -> World {
    pile_world(0.0)
}

/// The resting pile's world with Coulomb friction `mu` on every ball and wall (none if 0).
fn pile_world(mu: f64) -> World {
    let mut world = World::with_gravity(DVec2::new(0.0, -9.81)).expect("a finite gravity");
    world.set_sleeping(true);
    let corners = [
        DVec2::new(0.0, 0.0),
        DVec2::new(3.0, 0.0),
        DVec2::new(3.0, 12.0),
        DVec2::new(0.0, 12.0),
    ];
    for i in 0..4 {
        let mut segment = ColliderDesc::segment(corners[i], corners[(i + 1) % 4]).restitution(0.5);
        if mu > 0.0 {
            segment = segment.friction(mu);
        }
        world.add_collider(segment).expect("the box is valid");
    }
    let mut rng = SplitMix(7);
    for k in 0..24 {
        let (column, row) = (f64::from(k % 6), f64::from(k / 6));
        let position = DVec2::new(
            0.35 + 0.46 * column + rng.range(-0.02, 0.02),
            1.0 + 0.5 * row + rng.range(-0.02, 0.02),
        );
        let mut ball = BallDesc::new(position, 0.2)
            .velocity(DVec2::new(rng.range(-0.5, 0.5), 0.0))
            .restitution(0.5);
        if mu > 0.0 {
            ball = ball.friction(mu);
        }
        world
            .add_ball(ball)
            .expect("the grid's balls do not overlap");
    }
    world
}

/// A pile at rest: 24 balls (radius 0.2, restitution 0.5) dropped on a jittered grid into a
/// box 3 wide, with sleeping on, to 5 s in frames of 0.1 s, every event and every frame end's
/// state hashed, and the number asleep at the end. Its jams are solved by the impact
/// programme, dropping constraints on the way (the Givens rotations of its downdate), and its
/// balls fall asleep and wake: paths the arena run never reaches.
#[must_use]
pub fn resting_pile() -> (u64, usize) {
    pile_to_rest(resting_pile_world())
}

/// The resting pile with friction 0.5 on every ball and wall, hashed as [`resting_pile`]:
/// its groups slide against kinetic friction and stick (`dynamics/contact_friction.rs`), a
/// path the frictionless pile never reaches.
#[must_use]
pub fn rough_resting_pile() -> (u64, usize) {
    pile_to_rest(pile_world(0.5))
}

/// Runs a pile's `world` to 5 s in frames of 0.1 s: the hash of every event and every frame
/// end's state, and the number asleep at the end.
fn pile_to_rest(mut world: World) -> (u64, usize) {
    let mut words = Vec::new();
    for frame in 1..=50 {
        let until = f64::from(frame) * 0.1;
        while let Some(event) = world.step_until(until).expect("a valid frame time") {
            words.extend(event_words(&event));
        }
        words.extend(state_words(&world));
    }
    let asleep = world.sleeping_count();
    words.push(asleep as u64);
    (fnv1a(words), asleep)
}
