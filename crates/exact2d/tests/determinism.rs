//! Bit-for-bit reproducibility.
//!
//! The same inputs must give the same bits: twice in one process, however the caller slices
//! time into frames, and in every build profile. The golden hash below was produced by this
//! test; CI runs it in the dev profile and in release (`cargo test --release --test
//! determinism`), and both must reproduce it. If an intended change of the engine's arithmetic
//! moves it, the new value must be justified in the commit that changes it.
//!
//! The runs themselves live in the `determinism-check` crate, so that its wasm32 build computes
//! the very same ones (`web/hashes.mjs`, in CI) and they must give the same bits there too.

use determinism_check::engine::{
    events_and_end, golden_run, irregular_frames, regular_frames, resting_pile_world,
};
use exact2d::{BallDesc, DVec2, World};

/// The golden run's hash, after checking that it exercised what it should.
fn run(frames: &[f64]) -> u64 {
    let run = golden_run(frames);
    let counts = run.counts;
    assert!(
        counts.ball_contacts > 300 && counts.contacts > 500 && counts.sensor_enters > 10,
        "{counts:?}"
    );
    assert!(run.every_change_made, "every mutation happened");
    run.hash
}

/// The golden value, identical in the dev and release profiles and in wasm32 (`web/hashes.mjs`
/// in CI): the engine uses only correctly rounded operations, and so does the scene's setup. It
/// changed on purpose twice: the closed form under gravity rounds once at the coordinates'
/// magnitude (`Trajectory::position_at`), which changes the last bits of every position under
/// gravity (was `0xe6d2_5694_afca_e922`); a bounce under gravity restated beyond its exact
/// contact line by a rounding leaves with the energy it has from the line (`restated_bounce`),
/// which changes the last bits of slow bounces (was `0x4083_0524_07c5_4f3f`); a restatement
/// under gravity carries what its position's rounding left out into the next
/// (`Trajectory::rebased_carrying`), which changes the last bits of positions again (was
/// `0xf164_c991_1728_7259`).
const GOLDEN: u64 = 0x5e17_d9f5_abbf_2f74;

#[test]
fn the_same_run_twice_gives_the_same_bits() {
    let frames = regular_frames(1.0 / 60.0);
    assert_eq!(run(&frames), run(&frames));
}

#[test]
fn the_golden_hash_is_reproduced() {
    let hash = run(&regular_frames(1.0 / 60.0));
    println!("golden hash: {hash:#018x}");
    assert_eq!(hash, GOLDEN, "hash {hash:#018x}");
}

#[test]
fn frame_boundaries_do_not_change_the_events_or_the_final_state() {
    // Hash only what does not depend on the frames: the events and the state at t = 40.
    let one_go = events_and_end(&[40.0]);
    assert_eq!(events_and_end(&regular_frames(1.0 / 60.0)), one_go);
    assert_eq!(events_and_end(&irregular_frames()), one_go);
}

/// The resting pile's golden value (`determinism_check::engine::resting_pile`): its jams drop
/// constraints in the impact solve and its balls sleep and wake, which the arena run never
/// does. Identical in the dev and release profiles and in wasm32 (`web/hashes.mjs`), since the
/// solve's Givens rotations take their lengths from `+ - * /` and `sqrt` alone. (Re-derived
/// when the hold's accelerations were first started from its projection's factorisation,
/// and again when the contacts that start pulls were factorised again instead of rotated
/// out: the same optimum, other roundings; the pile still comes to rest whole. And once
/// more when a group took whole a strike that parts none of its contacts faster than they
/// rest at, `pipeline/rigid.rs`: other events; was `0x20af_cc7b_0ad8_bd03`. And when a
/// bounce under gravity came to leave with the energy it has from the exact contact line,
/// `restated_bounce`, and a settle after a jam came to take a sleeping ball's circle as
/// touched by the jam's own rule, `touches_collider_at`: was `0xcad1_4517_aa8d_47b9`. And when
/// restatements came to carry what the rounding of a position left out: was
/// `0x85ea_186f_d1c8_45c4`. And when the hold's projection came to start from its resting
/// contacts met at once, `Problem::equalities_met`: the same optimum, other roundings; was
/// `0x49ea_35ac_9943_ede8`. And when a slow pair falling freely together came to stop against
/// each other, `apply_ball_contact`: was `0xcbdd_01ce_c821_5dd5`. And when a group's members
/// came to keep the colliders they are held against through a strike the group takes as one
/// body, and a group such a strike leaves at rest to sleep, `pipeline/rigid.rs`: was
/// `0xed3c_e15a_c927_b177`. And when a jam came to take a group's members as touching up to
/// the group gap, and such a group to sleep on them, `World::fellows`: was
/// `0x2e15_97a1_27d4_f45f`.)
const RESTING_PILE: u64 = 0x5035_f5f4_7b5b_bf19;

/// A pile's run, `(hash, asleep)`, against its golden hash: every one of its 24 balls asleep.
fn assert_pile(name: &str, (hash, asleep): (u64, usize), golden: u64) {
    println!("{name}: {hash:#018x}, {asleep} of 24 asleep");
    assert_eq!(hash, golden, "{name}: hash {hash:#018x}");
    assert_eq!(asleep, 24, "{name}");
}

#[test]
fn the_resting_pile_reproduces_its_golden_hash_and_comes_to_rest() {
    let run = determinism_check::engine::resting_pile();
    assert_pile("resting pile", run, RESTING_PILE);
}

/// The resting pile with friction 0.5 on every ball and wall
/// (`determinism_check::engine::rough_resting_pile`): its groups slide against kinetic friction
/// and stick (`dynamics/contact_friction.rs`; each round of the friction's iteration starts from
/// the last one's factorisation; its bounces leave with the energy they have from the exact
/// contact line, `restated_bounce`). Identical in the dev and release profiles and in wasm32
/// (`web/hashes.mjs`): the cone's edges take their length from `sqrt` alone. (Was
/// `0x8d38_8329_8518_3c82` before restatements carried what a position's rounding left out,
/// and `0x7015_cd69_80c2_802c` before a jam's impulses had friction,
/// `dynamics/impact_friction.rs`, and `0x3902_7b1e_d16f_397b` before the hold's projection
/// started from its resting and stuck contacts met at once, `Problem::equalities_met`, and
/// `0x5b7d_106d_803b_42a5` before a slow pair falling freely together stopped against each
/// other, and `0x5f7f_05a7_9664_c3f0` before each round of a jam's frictional impact started
/// from the last round's end, `dynamics/impact_friction.rs`, and `0x7573_5294_ea90_229c` before
/// a group's friction rounds were mixed, `dynamics/mixing.rs`, and `0xe520_78c8_0216_9bfc`
/// before rounds that end short of agreeing gave way to a complementarity solve,
/// `dynamics/lemke.rs`, and `0x8d60_c6fc_cf45_1a3c` before that solve started by block
/// principal pivoting from the rows the last round pushed at, `dynamics/principal.rs`, and
/// `0x1d1b_66b2_ef15_d68e` before a jam took a group's members as touching up to the group
/// gap, `World::fellows`.)
const ROUGH_RESTING_PILE: u64 = 0x1e8f_6531_72a8_7b16;

#[test]
fn the_rough_resting_pile_reproduces_its_golden_hash_and_comes_to_rest() {
    let run = determinism_check::engine::rough_resting_pile();
    assert_pile("rough resting pile", run, ROUGH_RESTING_PILE);
}

/// Everything a world says about itself that a run can change, as text that keeps every bit
/// (`{:?}` prints each `f64` so that it reads back to the same value).
fn state_of(world: &World) -> String {
    let balls: Vec<String> = world
        .balls()
        .map(|(handle, ball)| format!("{handle:?} {ball:?} {:?}", world.ball_asleep_since(handle)))
        .collect();
    format!(
        "{:?} {:?} {:?} {} {balls:?}",
        world.time(),
        world.event_counts(),
        world.observables(),
        world.sleeping_count()
    )
}

/// 36 elastic disks in a periodic box (wraps, images), one inelastic pair for the TC rule.
fn periodic_gas() -> World {
    let mut world = World::new();
    world
        .set_periodic(DVec2::new(6.0, 6.0))
        .expect("an empty world");
    world
        .set_collapse_time(1e-3)
        .expect("a valid collapse time");
    for k in 0..36 {
        let (i, j) = (f64::from(k % 6), f64::from(k / 6));
        let angle = 0.7 * f64::from(k) + 0.3;
        let ball = BallDesc::new(DVec2::new(0.5 + i, 0.5 + j), 0.3)
            .velocity(DVec2::new(angle.cos(), angle.sin()) * 2.0)
            .restitution(if k < 2 { 0.5 } else { 1.0 });
        world
            .add_ball(ball)
            .expect("the lattice's disks do not overlap");
    }
    world
}

/// A world to clone: its name, how it is made, and how long it runs.
type Case = (&'static str, fn() -> World, f64);

#[test]
fn a_clone_goes_on_exactly_as_the_original() {
    let cases: [Case; 2] = [
        ("pile", resting_pile_world, 5.0),
        ("periodic gas", periodic_gas, 100.0),
    ];
    for (name, make, until) in cases {
        // The original's events, and a clone after 1, 4, 16, ... of them (the later ones
        // inside zero-time chains, jams and held groups, or with balls asleep).
        let mut original = make();
        let (mut events, mut clones, mut asleep) = (Vec::new(), Vec::new(), 0);
        while let Some(event) = original.step_until(until).expect("a valid time") {
            events.push(format!("{event:?}"));
            if events.len().is_power_of_two() && events.len().trailing_zeros() % 2 == 0 {
                asleep = asleep.max(original.sleeping_count());
                clones.push((events.len(), original.clone()));
            }
        }
        assert!(events.len() > 2_000, "{name}: {} events", events.len());
        assert!(
            name != "pile" || (asleep > 0 && original.sleeping_count() == 24),
            "the pile is cloned with balls asleep ({asleep}), and comes to rest"
        );
        // And every 13th instant's clone for the 30 events after it: a part of the state that
        // a clone lost (a zero-time chain's records, a held group) shows there.
        let mut again = make();
        for taken in 1..events.len() {
            again.step_until(until).expect("a valid time");
            if taken % 13 == 0 {
                let mut clone = again.clone();
                for (k, expected) in events[taken..].iter().take(30).enumerate() {
                    let event = clone.step_until(until).expect("a valid time");
                    let event = event.map(|e| format!("{e:?}"));
                    assert!(
                        event.as_ref() == Some(expected),
                        "{name}: the clone after {taken} events parted {k} events later"
                    );
                }
            }
        }
        let end = state_of(&original);
        for (taken, mut clone) in clones {
            let mut rest = Vec::new();
            while let Some(event) = clone.step_until(until).expect("a valid time") {
                rest.push(format!("{event:?}"));
            }
            assert!(
                rest == events[taken..],
                "{name}: the clone after {taken} events parted"
            );
            assert_eq!(state_of(&clone), end, "{name}: clone after {taken} events");
        }
    }
}
