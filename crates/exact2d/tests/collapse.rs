//! Inelastic collapse and the TC model (`World::set_collapse_time`): a cooling granular gas.
//!
//! Inelastic balls cluster as they cool, and in a cluster collisions come ever closer together
//! (McNamara and Young, 1994): infinitely many in a finite time. The TC model (Luding and
//! McNamara, 1998) makes a collision elastic when its ball collided less than `t_c` before, so
//! a cluster cannot collapse and the gas cools on by Haff's law, `E(t) ~ E0 / (1 + t / t0)^2`.

mod common;

use exact2d::{BallDesc, DVec2, World};

/// 150 balls of radius 0.35 with restitution 0.5 in a 12 x 12 box (packing about 0.4).
fn cooling_gas(collapse_time: f64) -> World {
    let mut rng = common::SplitMix(7);
    let mut world = common::boxed(12.0, DVec2::ZERO);
    world.set_collapse_time(collapse_time).unwrap();
    let mut placed = 0;
    while placed < 150 {
        let p = DVec2::new(rng.range(0.5, 11.5), rng.range(0.5, 11.5));
        let v = DVec2::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0));
        if world
            .add_ball(BallDesc::new(p, 0.35).velocity(v).restitution(0.5))
            .is_ok()
        {
            placed += 1;
        }
    }
    world
}

fn kinetic(world: &World) -> f64 {
    world
        .balls()
        .map(|(_, b)| 0.5 * b.mass * b.velocity.length_squared())
        .sum()
}

/// Runs `events` events, checking overlaps every 500; returns (clock, energy) samples every
/// 5000 events, the longest run of events within 1e-6 s, and the longest at one exact instant.
fn run(world: &mut World, events: usize) -> (Vec<(f64, f64)>, usize, usize) {
    let mut samples = Vec::new();
    let (mut run_start, mut run, mut longest) = (0.0, 0, 0);
    let (mut last, mut same, mut stalled) = (world.exact_time(), 0, 0);
    for k in 1..=events {
        let event = world
            .step()
            .expect("a gas in a box never runs out of events");
        same = if world.exact_time() == last {
            same + 1
        } else {
            0
        };
        stalled = stalled.max(same);
        last = world.exact_time();
        if event.time() - run_start < 1e-6 {
            run += 1;
            longest = longest.max(run);
        } else {
            (run_start, run) = (event.time(), 0);
        }
        if k % 500 == 0 {
            let overlap = common::deepest_overlap(world);
            assert!(overlap > -1e-9, "overlap {overlap} at t = {}", world.time());
        }
        if k % 5000 == 0 {
            samples.push((world.time(), kinetic(world)));
        }
    }
    (samples, longest, stalled)
}

/// Without the TC model a cluster collapses: its collisions come closer and closer until its
/// balls touch, and then it is a zero-time chain that comes back to its contacts, a jam,
/// resolved as one simultaneous impact (`pipeline/jam.rs`). Before jams, tens of thousands of
/// collisions fell within a microsecond (35,611 at one instant, measured) and the clock stayed
/// below 100 s for 200,000 events; now (measured) at most 5 events share an instant, the
/// longest run within a microsecond is 63 events, and the gas cools on to t = 759 s.
#[test]
fn without_the_tc_model_a_cooling_gas_jams_instead_of_collapsing_and_cools_on() {
    let mut world = cooling_gas(0.0);
    let e0 = kinetic(&world);
    let (samples, longest, stalled) = run(&mut world, 200_000);
    assert!(stalled < 64, "{stalled} events at one instant");
    assert!(longest < 2_000, "longest run within 1e-6 s: {longest}");
    assert!(
        world.event_counts().jams > 100,
        "{:?}",
        world.event_counts()
    );
    let (t, e) = *samples.last().unwrap();
    assert!(t > 100.0, "the clock only reached {t}");
    assert!(e < 1e-2 * e0, "energy {e} of {e0}");
    for pair in samples.windows(2) {
        assert!(pair[1].1 <= pair[0].1, "energy rose: {pair:?}");
    }
}

#[test]
fn with_the_tc_model_a_cooling_gas_cools_on_by_haff_s_law() {
    let mut world = cooling_gas(1e-3);
    let e0 = kinetic(&world);
    let (samples, longest, _) = run(&mut world, 60_000);
    assert!(longest < 2_000, "longest run within 1e-6 s: {longest}");
    let (t, e) = *samples.last().unwrap();
    assert!(t > 500.0, "the clock only reached {t}");
    assert!(e < 1e-3 * e0, "energy {e} of {e0}");
    for pair in samples.windows(2) {
        assert!(pair[1].1 <= pair[0].1, "energy rose: {pair:?}");
    }
    // Late in the cooling, E ~ t^-2: the exponent between the middle and the last sample.
    let (tm, em) = samples[samples.len() / 2];
    let exponent = (e / em).ln() / (t / tm).ln();
    assert!(
        (-2.6..=-1.4).contains(&exponent),
        "energy falls as t^{exponent}"
    );
}
