//! Micro-benchmarks of the time-of-impact kernels, of one event of a small gas, and of the
//! event queues (the hold model).
//!
//! ```text
//! cargo bench -p exact2d-bench --bench kernels            # full measurement
//! cargo bench -p exact2d-bench --bench kernels -- --quick # a rough one, in seconds
//! ```
//!
//! Each kernel is measured on a hit (the ball reaches the shape) and on a miss, with straight
//! motion and under gravity; ball-ball contacts do not depend on gravity (both balls fall
//! alike), so they have straight motion only.

use std::hint::black_box;

use criterion::{Criterion, criterion_main};
use exact2d::bench_internals::{HoldModel, QueueKind};
use exact2d::toi::{
    Crossing, Motion, time_of_impact_ball_ball, time_of_impact_ball_circle,
    time_of_impact_ball_segment,
};
use exact2d::{DVec2, Segment};
use exact2d_bench::scenes;

const GRAVITY: DVec2 = DVec2::new(0.0, -9.81);

/// A ball at the origin moving with `velocity`, straight or under gravity.
fn motion(velocity: DVec2, gravity: bool) -> Motion {
    Motion {
        position: DVec2::ZERO,
        velocity,
        acceleration: if gravity { GRAVITY } else { DVec2::ZERO },
    }
}

/// The velocities of the hit and miss cases: towards the shapes (which stand to the right and
/// a little up), and away from them.
const CASES: [(&str, DVec2); 2] = [
    ("hit", DVec2::new(8.0, 6.0)),
    ("miss", DVec2::new(-8.0, 2.0)),
];

/// Makes sure a case measures what its name says.
fn check(id: &str, hit: bool) {
    assert_eq!(
        hit,
        id.starts_with("hit"),
        "case {id} does not do what its name says"
    );
}

fn ball_ball(c: &mut Criterion) {
    let mut group = c.benchmark_group("toi/ball_ball");
    for (name, velocity) in CASES {
        let toi = || {
            time_of_impact_ball_ball(
                black_box(DVec2::ZERO),
                black_box(velocity),
                0.25,
                black_box(DVec2::new(3.0, 2.0)),
                black_box(DVec2::new(-1.0, 0.0)),
                0.5,
                f64::INFINITY,
            )
        };
        check(name, toi().is_some());
        group.bench_function(name, |b| b.iter(toi));
    }
    group.finish();
}

fn ball_segment(c: &mut Criterion) {
    let segment = Segment::new(DVec2::new(3.0, -1.0), DVec2::new(3.5, 4.0))
        .expect("distinct, finite end points");
    let mut group = c.benchmark_group("toi/ball_segment");
    for gravity in [false, true] {
        for (name, velocity) in CASES {
            let motion = motion(velocity, gravity);
            let id = format!("{name}{}", if gravity { "/gravity" } else { "" });
            let toi = || {
                time_of_impact_ball_segment(
                    black_box(&motion),
                    0.25,
                    black_box(&segment),
                    Crossing::Enter,
                    f64::INFINITY,
                )
            };
            check(&id, toi().is_some());
            group.bench_function(id, |b| b.iter(toi));
        }
    }
    group.finish();
}

fn ball_circle(c: &mut Criterion) {
    let center = DVec2::new(3.0, 1.5);
    let mut group = c.benchmark_group("toi/ball_circle");
    for gravity in [false, true] {
        for (name, velocity) in CASES {
            let motion = motion(velocity, gravity);
            let id = format!("{name}{}", if gravity { "/gravity" } else { "" });
            let toi = || {
                time_of_impact_ball_circle(
                    black_box(&motion),
                    0.25,
                    black_box(center),
                    0.5,
                    Crossing::Enter,
                    f64::INFINITY,
                )
            };
            check(&id, toi().is_some());
            group.bench_function(id, |b| b.iter(toi));
        }
    }
    group.finish();
}

/// One event of a hard-disk gas of 100 balls at packing 0.4 (the gas goes on across
/// iterations: each one handles the next collision).
fn world_step(c: &mut Criterion) {
    let scene = scenes::gas(100, 0.4, 1);
    let mut world = match scene.build_world() {
        Ok(built) => built.into_world(),
        Err(error) => panic!("the gas scene does not build: {error}"),
    };
    c.bench_function("world/step/gas_100", |b| b.iter(|| world.step()));
}

/// One hold of the event queue (take the earliest event, give its ball a new one), for the
/// world's 4-ary heap and the calendar queue, with one pending event per ball.
fn queue_hold(c: &mut Criterion) {
    let mut group = c.benchmark_group("queue/hold");
    for balls in [1_000u32, 100_000, 1_000_000] {
        for (name, kind) in [("heap", QueueKind::Heap), ("calendar", QueueKind::Calendar)] {
            let mut model = HoldModel::new(kind, balls, 7);
            group.bench_function(format!("{name}/{balls}"), |b| b.iter(|| model.hold()));
        }
    }
    group.finish();
}

/// Every benchmark of this file, configured from the command line (what `criterion_group!`
/// would write, less its undocumented public function).
fn benches() {
    let mut c = Criterion::default().configure_from_args();
    ball_ball(&mut c);
    ball_segment(&mut c);
    ball_circle(&mut c);
    world_step(&mut c);
    queue_hold(&mut c);
}

criterion_main!(benches);
