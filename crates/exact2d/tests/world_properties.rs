//! Properties of whole worlds, on random small elastic worlds without gravity.
//!
//! Each case is a closed square box of side 8 to 12 holding up to three random segments and
//! three random static circles, and one to eight balls (random radius, mass and velocity)
//! placed where the world accepts them (a refused placement is skipped). Every ball and
//! collider is perfectly elastic and there is no gravity: resting contact and inelastic
//! bounces are out of scope here. The properties:
//!
//! - **no overlap, no escape**: after every event, no ball overlaps another ball or a solid
//!   collider by more than [`OVERLAP_TOLERANCE`] of their contact distance, and every ball is
//!   inside the box (to the same tolerance);
//! - **energy**: the kinetic energy after every event equals the initial one to 1e-12,
//!   relative;
//! - **momentum**: each ball-ball collision conserves the momentum of its two balls to 1e-12 of
//!   their momenta, and changes no other ball's velocity (comparing the reported states before
//!   and after);
//! - **determinism**: the same world run twice gives the same events and the same final state,
//!   bit for bit;
//! - **frames**: slicing time into arbitrary frames with `advance_to` (frame ends at random
//!   times, on event times, repeated) gives the same events and the same final state, bit for
//!   bit, as one `advance_to` straight through.
//!
//! Each property was checked to fail on a deliberately broken engine or world (a ball-ball time
//! of impact 1e-6 late, a velocity changed by 1e-11 relative, one ulp of one initial velocity, a
//! trajectory restated at every frame end).
//!
//! 64 cases from a fixed seed, like `toi_properties.rs`; `PROPTEST_CASES` and
//! `PROPTEST_RNG_SEED` explore further.

mod common;

use common::{boxed, energy, gap, v};
use exact2d::{
    BallContactEvent, BallDesc, BallHandle, ColliderDesc, DVec2, Event, OVERLAP_TOLERANCE, World,
};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

/// How many events a run handles (properties checked after each).
const EVENTS: usize = 300;

/// Relative tolerance on energy and momentum.
const CONSERVED: f64 = 1e-12;

/// 64 cases from a fixed seed (see `common::proptest_config`).
fn config() -> ProptestConfig {
    common::proptest_config(2718, 64)
}

/// A ball as drawn: its place as fractions of the room left by its radius.
#[derive(Clone, Debug)]
struct BallSpec {
    at: (f64, f64),
    radius: f64,
    mass: f64,
    velocity: (f64, f64),
}

/// A random world, before it is built.
#[derive(Clone, Debug)]
struct Spec {
    size: f64,
    segments: Vec<((f64, f64), (f64, f64))>,
    circles: Vec<((f64, f64), f64)>,
    balls: Vec<BallSpec>,
}

fn spec() -> impl Strategy<Value = Spec> {
    let unit = || 0.0..1.0f64;
    let point = move || (unit(), unit());
    let ball = (
        point(),
        0.2..0.8f64,
        0.5..3.0f64,
        (-5.0..5.0f64, -5.0..5.0f64),
    )
        .prop_map(|(at, radius, mass, velocity)| BallSpec {
            at,
            radius,
            mass,
            velocity,
        });
    (
        8.0..12.0f64,
        prop::collection::vec((point(), point()), 0..=3),
        prop::collection::vec((point(), 0.3..1.2f64), 0..=3),
        prop::collection::vec(ball, 1..=8),
    )
        .prop_map(|(size, segments, circles, balls)| Spec {
            size,
            segments,
            circles,
            balls,
        })
}

/// A built world: the world, the handles of the balls it accepted, and its box.
struct Built {
    world: World,
    balls: Vec<BallHandle>,
    size: f64,
}

/// Builds the world: the box, the obstacles (a segment whose end points coincide is skipped),
/// then the balls the world accepts. `None` if no ball fits.
fn build(spec: &Spec) -> Option<Built> {
    let l = spec.size;
    let mut world = boxed(l, DVec2::ZERO);
    // Obstacles keep a margin of 1 from the walls.
    let inner = |(x, y): (f64, f64)| v(1.0 + x * (l - 2.0), 1.0 + y * (l - 2.0));
    for &(a, b) in &spec.segments {
        let _ = world.add_collider(ColliderDesc::segment(inner(a), inner(b)));
    }
    for &(c, r) in &spec.circles {
        world
            .add_collider(ColliderDesc::circle(inner(c), r))
            .expect("no ball yet");
    }
    let mut balls = Vec::new();
    for b in &spec.balls {
        let room = l - 2.0 * b.radius;
        let at = v(b.radius + b.at.0 * room, b.radius + b.at.1 * room);
        let desc = BallDesc::new(at, b.radius)
            .mass(b.mass)
            .velocity(v(b.velocity.0, b.velocity.1));
        if let Ok(handle) = world.add_ball(desc) {
            balls.push(handle);
        }
    }
    (!balls.is_empty()).then_some(Built {
        world,
        balls,
        size: l,
    })
}

/// No two balls, and no ball and solid collider, overlap by more than the tolerance of their
/// contact distance; every ball is inside the box.
fn check_no_overlap(built: &Built, event: usize) -> Result<(), TestCaseError> {
    let world = &built.world;
    let balls: Vec<_> = world.balls().collect();
    for (i, (ha, a)) in balls.iter().enumerate() {
        for (hb, b) in &balls[..i] {
            let reach = a.radius + b.radius;
            let depth = a.position.distance(b.position) - reach;
            prop_assert!(
                depth >= -OVERLAP_TOLERANCE * reach,
                "event {}: balls {:?} and {:?} overlap by {:e}",
                event,
                ha,
                hb,
                -depth
            );
        }
        for (hc, c) in world.colliders() {
            let reach = match c.shape {
                exact2d::Shape::Segment(_) => a.radius,
                exact2d::Shape::Circle(circle) => a.radius + circle.radius,
            };
            let depth = gap(&c.shape, a.position, a.radius);
            prop_assert!(
                depth >= -OVERLAP_TOLERANCE * reach,
                "event {}: ball {:?} overlaps collider {:?} by {:e}",
                event,
                ha,
                hc,
                -depth
            );
        }
        let slack = a.radius * (1.0 - OVERLAP_TOLERANCE);
        let inside = slack..=built.size - slack;
        prop_assert!(
            inside.contains(&a.position.x) && inside.contains(&a.position.y),
            "event {}: ball {:?} left the box: {}",
            event,
            ha,
            a.position
        );
    }
    Ok(())
}

/// A ball's momentum, from the world's state.
fn momentum(world: &World, ball: BallHandle) -> DVec2 {
    let b = world.ball(ball).expect("live ball");
    b.velocity * b.mass
}

/// Every number of an event, as bits (`-0.0` and `0.0` differ).
fn event_bits(event: &Event) -> Vec<u64> {
    let vec = |p: DVec2| [p.x.to_bits(), p.y.to_bits()];
    let handle = |h: BallHandle| [u64::from(h.index()), u64::from(h.generation())];
    let mut bits = Vec::new();
    match event {
        Event::Contact(c) => {
            bits.extend([0, c.time.to_bits()]);
            bits.extend(handle(c.ball));
            bits.extend([
                u64::from(c.collider.index()),
                u64::from(c.collider.generation()),
            ]);
            bits.push(c.feature as u64);
            bits.extend(vec(c.point));
            bits.extend(vec(c.normal));
            bits.push(c.normal_speed.to_bits());
        }
        Event::BallContact(c) => {
            bits.extend([1, c.time.to_bits()]);
            bits.extend(handle(c.a));
            bits.extend(handle(c.b));
            bits.extend(vec(c.point));
            bits.extend(vec(c.normal));
            bits.push(c.normal_speed.to_bits());
        }
        Event::SensorEnter(s) | Event::SensorExit(s) => {
            let kind = if matches!(event, Event::SensorEnter(_)) {
                2
            } else {
                3
            };
            bits.extend([kind, s.time.to_bits()]);
            bits.extend(handle(s.ball));
            bits.extend([
                u64::from(s.collider.index()),
                u64::from(s.collider.generation()),
            ]);
            bits.push(s.feature as u64);
            bits.extend(vec(s.position));
        }
    }
    bits
}

/// The clock and every ball's state, as bits.
fn state_bits(world: &World) -> Vec<u64> {
    let t = world.exact_time();
    let mut bits = vec![t.seconds().to_bits(), t.residual().to_bits()];
    for (h, b) in world.balls() {
        bits.extend([u64::from(h.index()), u64::from(h.generation())]);
        bits.extend([b.position.x, b.position.y, b.velocity.x, b.velocity.y].map(f64::to_bits));
    }
    bits
}

/// Runs `EVENTS` events (fewer if the world runs out), returning every event's bits and the
/// final state's.
fn run(built: &mut Built) -> (Vec<Vec<u64>>, Vec<u64>) {
    let mut events = Vec::new();
    for _ in 0..EVENTS {
        match built.world.step() {
            Some(event) => events.push(event_bits(&event)),
            None => break,
        }
    }
    (events, state_bits(&built.world))
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn no_ball_overlaps_anything_or_leaves_its_box(spec in spec()) {
        let built = build(&spec);
        prop_assume!(built.is_some());
        let mut built = built.unwrap();
        check_no_overlap(&built, 0)?;
        for event in 1..=EVENTS {
            if built.world.step().is_none() {
                break;
            }
            check_no_overlap(&built, event)?;
        }
    }

    #[test]
    fn kinetic_energy_is_conserved(spec in spec()) {
        let built = build(&spec);
        prop_assume!(built.is_some());
        let mut world = built.unwrap().world;
        let initial = energy(&world);
        for event in 1..=EVENTS {
            if world.step().is_none() {
                break;
            }
            let now = energy(&world);
            prop_assert!(
                (now - initial).abs() <= CONSERVED * initial,
                "event {}: energy {} -> {} ({:e} relative)",
                event,
                initial,
                now,
                (now - initial) / initial
            );
        }
    }

    #[test]
    fn ball_ball_collisions_conserve_the_momentum_of_the_pair(spec in spec()) {
        let built = build(&spec);
        prop_assume!(built.is_some());
        let Built { mut world, balls, .. } = built.unwrap();
        let mut velocities: Vec<DVec2> =
            balls.iter().map(|&b| world.ball(b).unwrap().velocity).collect();
        let slot = |h: BallHandle| balls.iter().position(|&b| b == h).expect("a ball of ours");
        for event in 1..=EVENTS {
            let Some(happened) = world.step() else { break };
            let involved: Vec<BallHandle> = match happened {
                Event::Contact(c) => vec![c.ball],
                Event::BallContact(BallContactEvent { a, b, .. }) => {
                    let mass = |h| world.ball(h).unwrap().mass;
                    let before = velocities[slot(a)] * mass(a) + velocities[slot(b)] * mass(b);
                    let after = momentum(&world, a) + momentum(&world, b);
                    let scale = (velocities[slot(a)] * mass(a)).length()
                        + (velocities[slot(b)] * mass(b)).length();
                    prop_assert!(
                        (after - before).length() <= CONSERVED * scale,
                        "event {}: momentum {} -> {}",
                        event,
                        before,
                        after
                    );
                    vec![a, b]
                }
                Event::SensorEnter(_) | Event::SensorExit(_) => {
                    return Err(TestCaseError::fail("no sensor in these worlds"));
                }
            };
            for (k, &h) in balls.iter().enumerate() {
                let now = world.ball(h).unwrap().velocity;
                if involved.contains(&h) {
                    velocities[k] = now;
                } else {
                    prop_assert_eq!(
                        now,
                        velocities[k],
                        "event {}: ball {:?} changed velocity without an event",
                        event,
                        h
                    );
                }
            }
        }
    }

    #[test]
    fn the_same_world_runs_to_the_same_bits_twice(spec in spec()) {
        let first = build(&spec);
        prop_assume!(first.is_some());
        let mut first = first.unwrap();
        let mut second = build(&spec).expect("built once");
        let (events_1, state_1) = run(&mut first);
        let (events_2, state_2) = run(&mut second);
        prop_assert_eq!(events_1.len(), events_2.len());
        for (k, (a, b)) in events_1.iter().zip(&events_2).enumerate() {
            prop_assert_eq!(a, b, "event {} differs", k);
        }
        prop_assert_eq!(state_1, state_2);
    }

    #[test]
    fn frames_change_no_event_and_no_bit(
        spec in spec(),
        end in 2.0..40.0f64,
        cuts in prop::collection::vec(0.0..1.0f64, 0..24),
        on_events in prop::collection::vec(any::<prop::sample::Index>(), 0..6),
    ) {
        let straight = build(&spec);
        prop_assume!(straight.is_some());
        let mut straight = straight.unwrap().world;
        let mut expected = Vec::new();
        straight.advance_to_collect(end, &mut expected).unwrap();
        // Frame ends: random times, some events' own times, and the end itself (twice).
        let mut frames: Vec<f64> = cuts.iter().map(|c| c * end).collect();
        if !expected.is_empty() {
            frames.extend(on_events.iter().map(|i| expected[i.index(expected.len())].time()));
        }
        frames.extend([end, end]);
        frames.sort_by(f64::total_cmp);
        let mut sliced = build(&spec).expect("built once").world;
        let mut got = Vec::new();
        for &frame in &frames {
            sliced.advance_to_collect(frame, &mut got).unwrap();
        }
        prop_assert_eq!(got.len(), expected.len());
        for (k, (a, b)) in got.iter().zip(&expected).enumerate() {
            prop_assert_eq!(event_bits(a), event_bits(b), "event {} differs", k);
        }
        prop_assert_eq!(state_bits(&sliced), state_bits(&straight));
    }
}

/// The generator is not vacuous: most worlds hold several balls that meet each other, and
/// obstacles of both kinds occur.
#[test]
fn the_random_worlds_are_crowded_enough_to_test_something() {
    use proptest::strategy::ValueTree;
    let mut runner = proptest::test_runner::TestRunner::new(config());
    let (mut crowded, mut meeting, mut segments, mut circles) = (0, 0, 0, 0);
    for _ in 0..64 {
        let spec = spec().new_tree(&mut runner).unwrap().current();
        segments += spec.segments.len();
        circles += spec.circles.len();
        let Some(mut built) = build(&spec) else {
            continue;
        };
        if built.balls.len() >= 2 {
            crowded += 1;
            run(&mut built);
            if built.world.event_counts().ball_contacts >= 10 {
                meeting += 1;
            }
        }
    }
    assert!(
        crowded >= 48,
        "{crowded} of 64 worlds hold two balls or more"
    );
    assert!(
        meeting >= 40,
        "{meeting} of 64 worlds see ten ball-ball collisions"
    );
    assert!(
        segments >= 32 && circles >= 32,
        "{segments} segments, {circles} circles"
    );
}
