//! Every seed a hunt once broke, replayed: the scene of `SplitMix64(seed)` with the default
//! [`Options`], run as the `exact2d-hunt` command runs it (to 3 simulated seconds or 300,000
//! events), keeps every invariant.
//!
//! To look at one by hand: `exact2d-hunt --from SEED --count 1` prints the finding (its class
//! and detail) if there is one, and `--out DIR` writes the scene for `exact2d soak`.

use exact2d_hunt::generate::{Options, ROUGH_SEED, generate, roughen};
use exact2d_hunt::run::{Limits, run};
use exact2d_hunt::source::SplitMix64;

/// The events the `exact2d-hunt` command allows a scene by default.
const EVENTS: u64 = 300_000;

/// Replays the scene of `seed` to 3 simulated seconds or `events` events; `broke` is what it
/// once broke.
fn replay(seed: u64, broke: &str, events: u64) {
    let generated = generate(&mut SplitMix64(seed), Options::default());
    let outcome = run(
        &generated,
        Limits {
            until: 3.0,
            events,
            collapse: 0.0,
        },
    );
    if let Some(finding) = outcome.finding {
        let motifs: Vec<&str> = generated.motifs.iter().map(|m| m.name()).collect();
        panic!(
            "seed {seed} (once broke: {broke}) [{}] scale {:e} offset {:e}, after {} events at t = {:?}: {finding}",
            motifs.join(","),
            generated.scale,
            generated.offset,
            outcome.events,
            outcome.time
        );
    }
}

/// One test per seed (so they run in parallel and fail by name), and the table of them all.
macro_rules! replays {
    ($($name:ident = $seed:literal, $broke:literal, $events:expr;)*) => {
        $(
            #[test]
            fn $name() {
                replay($seed, $broke, $events);
            }
        )*

        /// Every seed replayed, with what it once broke.
        const TABLE: &[(u64, &str)] = &[$(($seed, $broke)),*];
    };
}

replays! {
    // Overlap: two bodies sank into each other deeper than `exact2d::overlap_bound` (a
    // missed or late contact, or a resting ball creeping into its support).
    seed_486 = 486, "overlap", EVENTS; // a funnel at offset 1e6 (once also a stall error)
    seed_1801 = 1801, "overlap", EVENTS;
    seed_2555 = 2555, "overlap", EVENTS; // 7e-5 of the contact distance: a corner shot in a channel
    seed_3120 = 3120, "overlap", EVENTS;
    seed_3200 = 3200, "overlap, crawl", EVENTS; // 2.6e-2 at scale 1e6, then a crawl
    seed_3355 = 3355, "overlap", EVENTS; // 2.9e-2: a ball slid through a ball held beside it
    seed_3845 = 3845, "overlap", EVENTS; // creeping past the bound: a ball re-settling on a slope
    seed_3958 = 3958, "overlap", EVENTS;
    seed_5104 = 5104, "overlap", EVENTS;
    seed_5189 = 5189, "overlap", EVENTS;
    seed_5248 = 5248, "overlap", EVENTS;
    seed_7975 = 7975, "overlap", EVENTS;
    seed_8262 = 8262, "overlap", EVENTS;
    seed_8512 = 8512, "overlap", EVENTS;
    seed_9147 = 9147, "overlap", EVENTS;
    seed_10660 = 10660, "overlap", EVENTS;
    seed_10939 = 10939, "overlap", EVENTS;
    seed_11260 = 11260, "overlap", EVENTS;
    seed_11319 = 11319, "overlap", EVENTS;
    seed_11326 = 11326, "overlap", EVENTS;
    seed_12920 = 12920, "overlap", EVENTS; // an overlap of a whole contact distance
    seed_12955 = 12955, "overlap", EVENTS;
    seed_13128 = 13128, "overlap", EVENTS;
    seed_15435 = 15435, "overlap", EVENTS;
    seed_15558 = 15558, "overlap", EVENTS;
    seed_16258 = 16258, "overlap", EVENTS;
    seed_16321 = 16321, "overlap", EVENTS;
    seed_16651 = 16651, "overlap", EVENTS;
    seed_17924 = 17924, "overlap", EVENTS;
    seed_17999 = 17999, "overlap", EVENTS;
    seed_20355 = 20355, "overlap", EVENTS;
    seed_20567 = 20567, "overlap", EVENTS;
    seed_22948 = 22948, "overlap", EVENTS;
    seed_23112 = 23112, "overlap", EVENTS;
    seed_24899 = 24899, "overlap", EVENTS;
    seed_26080 = 26080, "overlap", EVENTS;
    seed_26649 = 26649, "overlap", EVENTS;
    // A ball at x = 1e6 sliding beside another, restated at every micro-hop of a ball on top
    // of it: the closed form rounded twice and drifted it into its neighbour.
    seed_402229 = 402229, "overlap", EVENTS;
    // With sleeping on (issue 16): a ball sliding along an exact-fit channel stopped by a
    // rounding of its direction into the opposite wall (803817, 825093, 946810, 1034623); a
    // pair closed by its jam set approaching again at the same instant and never sought
    // again (884915); a touching pair or a ball touching a collider meeting sooner than the
    // clock resolves, and that contact dropped (1023263, 1026556, 804897, 969842, 705547:
    // a ball woken in a channel 0.4 + 4e-13 wide sank into a shelf's end).
    seed_705547 = 705547, "overlap", EVENTS;
    seed_803817 = 803817, "overlap", EVENTS;
    seed_804897 = 804897, "overlap", EVENTS; // 1.6e-2 of the contact distance
    seed_825093 = 825093, "overlap", EVENTS;
    seed_884915 = 884915, "overlap", EVENTS;
    seed_946810 = 946810, "overlap", EVENTS;
    seed_969842 = 969842, "overlap", EVENTS; // a whole contact distance
    seed_1023263 = 1023263, "overlap", EVENTS;
    seed_1026556 = 1026556, "overlap", EVENTS;
    seed_1034623 = 1034623, "overlap", EVENTS;
    // A ball falling beside a sleeping ball by 8e-11 m/s met it tangentially again and again,
    // 2e-18 s apart: the jam's closure lasted one instant, not the chain.
    seed_1232388 = 1232388, "crawl", EVENTS;
    // Balls of two ulps of their coordinates (scale 1e-6 at 1e9), placed touching: a closed
    // pair sought deeper than its size met again at every response (a stall at t = 0).
    seed_1908277 = 1908277, "stall", EVENTS;
    // A stack on a polyline at scale 1e6: two balls 1.0002e-9 of their contact distance into
    // each other, found before the sleeping changes that made piles rest (gentle pushes,
    // rattles resolved, islands, sleeping circles touched as balls); clean since, and kept
    // to guard them.
    seed_2330820 = 2330820, "overlap", EVENTS;
    // Energy: the total grew past the floors the engine states (micro-hops, rounding):
    // stacks of balls, a ball bouncing on a ball that rests on the floor.
    seed_2537 = 2537, "energy", EVENTS; // a stack
    seed_4050 = 4050, "energy", EVENTS;
    seed_4443 = 4443, "energy", EVENTS;
    seed_4614 = 4614, "energy", EVENTS;
    seed_5769 = 5769, "energy", EVENTS;
    seed_6307 = 6307, "energy", EVENTS;
    seed_9755 = 9755, "energy", EVENTS;
    seed_11525 = 11525, "energy", EVENTS;
    seed_12477 = 12477, "energy", EVENTS;
    seed_12623 = 12623, "energy", EVENTS;
    seed_13110 = 13110, "energy", EVENTS;
    seed_13553 = 13553, "energy", EVENTS;
    seed_13891 = 13891, "energy", EVENTS;
    seed_19691 = 19691, "energy", EVENTS;
    seed_25420 = 25420, "energy", EVENTS;
    seed_25598 = 25598, "energy", EVENTS;
    seed_26221 = 26221, "energy", EVENTS;
    // A jam's projection of a ball on a floor just past the end point of a second floor
    // segment (a wedge of 1.6e-11 radians, both contacts resting), at scale 1e3: the rounding
    // of its huge impulses left a ball landing beside it at 1.2e6 units/s, every constraint
    // met to its tolerance; the energy rose 27,000-fold. Such an answer, longer than what it
    // projects, is now refused (`dynamics/impact.rs`).
    seed_8061178 = 8061178, "energy", EVENTS;
    // Two balls in an exact-fit channel at 45 degrees whose walls' normals are opposite but
    // for 4e-14 radians, at scale 1e-3: the group's solve held them still (a thin wedge)
    // while they slid up the channel, its forces doing work through the rounding of the
    // normal velocities; energy up 1.7e-2 of the scale. Held accelerations whose forces work
    // are now refused (`pipeline/jam.rs`).
    seed_8216606 = 8216606, "energy", EVENTS;
    seed_8289229 = 8289229, "energy", EVENTS; // a channel and a funnel, the same class
    // A ball pressed on a ball pinned in a thin wedge (the work check refused the group: the
    // pinned ball's rounding acceleration worked on it) micro-hopped on it every 1e-7 to 1e-5
    // s, a jam each time, sinking a rounding deeper at each: now the work is taken over the
    // group's lifetime, and a group whose solve is refused but whose accelerations are all
    // below `STILL` of gravity's is held still (`pipeline/jam.rs`).
    seed_9032964 = 9032964, "overlap", EVENTS; // a box fit, a funnel and a stack at scale 1e3
    seed_9063215 = 9063215, "overlap", EVENTS; // rising at 7.4e-8 g beside a 2.5e-6 wedge
    seed_9179282 = 9179282, "overlap", EVENTS; // sliding over a ball pinned 1e-8 rad apart
    // A ball in an exact-fit channel a degree off upright, at scale 1e-3 and 1e3 from the
    // origin, whose walls face each other but for 1e-12 radians: the jam's solve held it still
    // in that wedge, the settle after it slid it down the channel, and a ball under it was
    // struck every 0.24 ms, a rounding deeper each time, to 1.02 times the overlap bound.
    // Walls of one ball opposite to within `PARALLEL` are now exactly opposite in a jam
    // (`exact_fit_walls`, `pipeline/jam.rs`).
    seed_10282927 = 10282927, "overlap", EVENTS;
    // A ball sliding down one side of a wedge towards its apex, through which a wall of the
    // scene passes upright (its interior holds the apex): taken for the segment that goes on
    // from the apex, the wall was the support's `next`, not predicted against, and the ball
    // slid through the wall's upper end, 0.35 of its contact distance in (a crossing segment
    // goes on from an end only if it runs along the support, `next_segment`).
    seed_13016448 = 13016448, "overlap", EVENTS;
    // A ball a jam left sliding along a wall, approaching it by a rounding (4.3e-18 m/s), was
    // predicted again from its next cell crossing after the jam's instant had passed: the
    // closure forgotten, the wall was met at the trajectory's origin, an event dated now,
    // while the grid already listed the ball in the cell beyond the crossing. It stopped
    // outside that cell, and a ball drifting in never saw it: 0.22 of the contact distance
    // (scale 1e-1, no gravity). A contact at an origin before the current chain is now closed
    // (`Instant::is_closed`).
    seed_14109010 = 14109010, "overlap", EVENTS;
    // The same rule without asking when the collider came: a ball resting against a ball
    // that fell asleep after its origin was closed against the sleeper's new circle and sank
    // through it (overlap 1.0; 17 seeds in 383,343). Only a collider there before the origin
    // is closed.
    seed_14241017 = 14241017, "overlap", EVENTS;
    // A ball sliding down a funnel's ramp into a ball that passed over a peg's top faster than
    // the peg curves away (scale 1e3, at 1e9): the hold's programme, whose rows ask a contact's
    // relative normal acceleration to be at least zero where about a point the gap's is
    // `a.n + |v_t|^2 / reach`, pressed the second ball onto the peg and left the pair without
    // force; the peg could not hold it, so it flew, pulled together with the first, and the
    // pair met every 3.1e-5 s, each jam leaving it 15 ulps deeper (`closed_depth`), to 1.01
    // times the overlap bound. Such a contact is now left out of the solve
    // (`passing_points`, `pipeline/jam.rs`), and the pair is held.
    seed_13246915 = 13246915, "overlap", EVENTS;
    // A stack in a thin wedge (scale 1, at the origin): a jam rested a ball on a sleeping
    // ball's circle 2.5e-10 above it, touching as two balls touch (within their micro-hop),
    // but the settle after it asked whether the circle holds the ball by a settling hop's
    // band, 1.7e-13: the ball flew, fell into the ball beside it, and the pair, closed, met
    // every 8e-8 s a rounding deeper, 126,000 jams, to 1.0004 times the overlap bound. The
    // settle now takes a sleeping ball's circle as touched by the rule the jam found it by
    // (`touches_collider_at`). Found with `restated_bounce`, which changed the scene's path;
    // the mismatch is older.
    seed_15046218 = 15046218, "overlap", EVENTS;
    // A ball whose trajectory began exactly on its grown cell's boundary, moving out (a
    // collision tied with its crossing and handled first): its exit was the root at the
    // origin itself, which the search after it passed over, and it stayed registered in the
    // cell it had left. A ball that then fell asleep two rows below told only its own block of
    // its circle, and the first ball ran 6.0e-2 of a contact distance into it (scale 10, at
    // the origin). Such a ball now crosses at once (`BallGrid::crossing`).
    seed_16038924 = 16038924, "overlap", EVENTS;
    // A ball falling beside a wall onto a ball pinned between a floor's and a ceiling's end
    // points 6.7e-9 radians apart (scale 1e-3): the group's solve raised it at 4.1e-5 of
    // gravity's acceleration, the rounding of a wedge of wedges, above `STILL`, and was
    // refused; it fell back every 3.3e-6 s, a jam each time that closed the pair 8 ulps
    // deeper than it stood, to 1.0001 times the overlap bound at t = 1.9. A solve that is a
    // worse answer of its own programme than rest is now held still (`worse_than_still`,
    // `pipeline/jam.rs`).
    seed_20017920 = 20017920, "overlap", EVENTS;
    // Stall and crawl (the clock stuck at one instant, or creeping by less than 1e-9 s over
    // 100,000 events) came with seeds above: 486 (a stall error) and 3200 (a crawl).
}

#[test]
fn the_table_replays_every_seed_once() {
    let mut seeds: Vec<u64> = TABLE.iter().map(|&(seed, _)| seed).collect();
    seeds.sort_unstable();
    seeds.dedup();
    assert_eq!(seeds.len(), TABLE.len());
    assert_eq!(TABLE.len(), 82);
}

/// Replays seed `seed` made rough as `exact2d-hunt --rough` makes it; `broke` is what it once
/// broke.
fn replay_rough(seed: u64, broke: &str) {
    let mut generated = generate(&mut SplitMix64(seed), Options::default());
    roughen(&mut generated.scene, &mut SplitMix64(seed ^ ROUGH_SEED));
    let outcome = run(
        &generated,
        Limits {
            until: 3.0,
            events: EVENTS,
            collapse: 0.0,
        },
    );
    assert!(
        outcome.finding.is_none(),
        "rough seed {seed} (once broke: {broke}): {:?}",
        outcome.finding.map(|f| f.to_string())
    );
}

/// `--rough` seed 236585: a ball rolling at 1.1 m/s on a floor into a ball that a jam had left
/// with an acceleration of (3, 2e-79) beside it, the rounding of a solved zero: their quartic's
/// root bound lay at 1e158 s, where the gap overflowed, so the contact was never predicted and
/// the balls went 1.5 % of their contact distance into each other (`roots/parabolic_gap.rs`,
/// `upper_bracket`).
#[test]
fn rough_seed_236585() {
    replay_rough(236_585, "overlap");
}

/// `--rough` seed 469781: a ball sliding on a short segment that lies on a longer one
/// (collinear, overlapping) reached the short one's end, pivoted on it and dropped 5e-7 into
/// the long one, and with restitution 1 hopped on it for ever, gaining the rounding of its
/// height (offset 1e6) at each hop, 4.6e-9 of the energy's scale in 0.05 s. A segment whose
/// interior holds the end goes on from it (`next_segment`, `pipeline/step.rs`): the ball
/// slides onto it.
#[test]
fn rough_seed_469781() {
    replay_rough(469_781, "energy");
}

/// `--rough` seed 371712: a spinning rough ball in an exact-fit channel at 60 degrees (scale
/// 1e-1, at 1e3), whose walls face each other but for 1.6e-13 radians. The end of each
/// friction phase on the lower wall forgot the upper one, which it touched: met again at
/// once, its friction left a slip of a rounding and a slide of 2.5e-16 s, whose end forgot
/// it again (a crawl: 100,000 events in 2.5e-11 s). A phase's end now keeps the surfaces
/// its ball touches (`pipeline/rolling.rs`, `end_phase`).
#[test]
fn rough_seed_371712() {
    replay_rough(371_712, "crawl");
}

/// `--rough` seed 358890: a spinning rough ball (radius 5e-7, at 1e6) whose slide on a shelf
/// ended, at t = 0.21, just over a ball passing below the shelf: touching a ball, it moved on
/// frictionless, but with the ended slide's acceleration (`mu g`) and its spin fixed, and
/// gained 2 % of the energy's scale by t = 0.47. The next phase now starts from gravity's
/// part alone (`Support::smooth`, `end_phase` in `pipeline/rolling.rs`).
#[test]
fn rough_seed_358890() {
    replay_rough(358_890, "energy");
}

/// `--rough` seed 856949: a rough ball (restitution 0) struck the second segment of a valley
/// (scale 1e0, at 1e3) at its bottom and slid up it under constant accelerations (a slipping
/// phase), back to the very position it set off from. The phase's end, predicted as the
/// trajectory's origin plus a rounded duration, came 2.2e-16 s early; the ball had not moved
/// from its origin, which the leave took for a centre stuck at the end of its extent, 0.1
/// short of it: it was handed to the first segment without a collision, its velocity
/// mirrored, and with the second one as `from` (never predicted against) rolled back 0.4 of
/// its radius into it at t = 2.78. An unmoved centre counts as at its end only for the
/// extent's own leave (`apply_leave`, `pipeline/step.rs`); an early phase end is predicted
/// again.
#[test]
fn rough_seed_856949() {
    replay_rough(856_949, "overlap");
}

/// `--rough` seeds 109817, 182915, 246439 and 289049, found with friction among balls in
/// contact (`dynamics/contact_friction.rs`), each an overlap of 1.0004 to 1.12 times
/// `overlap_bound`. In 182915 a ball is pushed up an exact-fit channel whose walls face each
/// other but for 5e-8 radians, beside a ball sliding on a rough wall: the channel pins them
/// with normal forces of some 1e7 weights, and `mu` times those is a kinetic force no
/// acceleration answers (the contact would jam at once, an impulse). The work check refused
/// the frictional group, the cluster settled ball by ball, and a jam every 4e-8 s sank a pair
/// a rounding deeper each time. A refused frictional solve now gives way to the frictionless
/// one (`pipeline/jam.rs`, `hold`), which cures all four.
#[test]
fn rough_seeds_of_friction_in_a_pinned_channel() {
    for seed in [109_817, 182_915, 246_439, 289_049] {
        replay_rough(seed, "overlap");
    }
}

/// `--rough` seed 1029293 (scale 10): two balls 0.56 of their contact distance into each
/// other at t = 2.33. A ball sliding up a 45-degree exact-fit channel at t = 1.006 passed,
/// tangentially, the place where another came to rest at t = 1.535, beyond the 3 x 3 block of
/// cells told of the new sleeper's circle. At t = 2.15 its walk through the static grid met
/// that circle, and the contact solved from its trajectory's origin was the graze at 1.006
/// (touching, with a rounding of approach): taken now, a collision at a distance, which left
/// the ball registered in a cell it had not reached, where its block missed the ball it then
/// ran into. A contact before the collider was added is none: the walk seeks the first from
/// its birth on (`since_born`, `pipeline/predict.rs`).
#[test]
fn rough_seed_1029293() {
    replay_rough(1_029_293, "overlap");
}

/// `--rough` seed 2513226 (scale 1, at 1e3): a rough ball pivoting round a corner, the end of
/// a horizontal segment and of one at 45 degrees below it, went on pivoting past the edge
/// that ends on the second segment's line and was 2.1e-3 of its radius into it before it met
/// it. The pivot's steps of half a degree land on 45 degrees exactly but for the rounding of
/// the rotations: the edge one step before the segment had its cosine one ulp below
/// `PIVOT_COS`, the edge on it its sine at -1.1e-16, and neither was taken as reaching the
/// segment. Both checks now allow the rounding of their products (`PIVOT_ROUNDING`,
/// `dynamics/support.rs`). The engine before stop 46 has it too.
#[test]
fn rough_seed_2513226() {
    replay_rough(2_513_226, "overlap");
}

/// `--rough` seed 285473 (scale 1e-6, at 1): energy up 1.9e-9 of the scale. An elastic ball
/// hopping 8.5e-13 high on the floor, restated 7e-17 above the contact line at every bounce,
/// fell those 7e-17 more at every hop and gained their energy, 3,283 hops in 3 s. A bounce
/// now leaves with the energy it has from the exact line (`restated_bounce`,
/// `dynamics/response.rs`). Open since stop 41.
#[test]
fn rough_seed_285473() {
    replay_rough(285_473, "energy");
}

/// `--rough` seed 3105368 (a box exactly three wide and a corner shot, scale 1e-3 at 1): three
/// rough balls pressed by tilted gravity into a box exactly three balls wide jammed some
/// 28,000 times by t = 1.31, and balls 1 and 2 went 1.28e-9 of their contact distance into
/// each other by t = 1.279, past `overlap_bound`. The middle ball slid down its neighbour
/// 1.7e-10 above its centre's level, where staying tangential takes a sideways move of about
/// 1e-16 a jam, under half an ulp: every restatement rounded it away. Open since stop 47.
/// Restatements under gravity now carry what the rounding of a position leaves out
/// (`Trajectory::rebased_carrying`), so such moves add up.
#[test]
fn rough_seed_3105368() {
    replay_rough(3_105_368, "overlap");
}

/// `--rough` seed 110883, found while friction in a jam's impulses was being written
/// (`dynamics/impact_friction.rs`): a jam's solve left a contact's normal impulse at
/// -2.4e-16, a rounding below zero, and its friction's box `|f| <= mu l` was then empty (a
/// panic). A normal impulse below zero bounds the friction at zero.
#[test]
fn rough_seed_110883() {
    replay_rough(110_883, "a panic");
}

/// `--rough` seed 2312899 (a box exactly three balls wide, scale 1e-6 at 1), which kept
/// friction out of a jam's impulses in stop 46: three balls jammed every half millisecond
/// against the box's walls, friction at the walls slowing the fall of two of them past the
/// third, and the pair's depth grew by rounding, 5.8e-8 of its contact distance after 1,085
/// jams. The sideways moves that keep the slide tangential were under half an ulp and each
/// restatement rounded them away; restatements now carry that residual.
#[test]
fn rough_seed_2312899() {
    replay_rough(2_312_899, "overlap");
}

/// `--rough` seed 20402167 (two balls filling a box's width exactly at x = 1e3, gravity
/// tilted into one wall, rough walls): the pair slid down the box hardly at all, an instant of
/// a wall's bounce, the pair's contact and a jam every 1.4e-4 s. Each time the right ball came
/// back to its wall, a rounding nearer it than the line it last slid on, settling put it back
/// on that line: 7 ulps of its coordinates away from the wall and into its partner, until at t
/// = 0.029 the pair overlapped 2.147e-9 of its contact distance, past `overlap_bound` (2.14e-9
/// there). A ball settles back on its last line only as far out as it is into the wall.
#[test]
fn rough_seed_20402167() {
    replay_rough(20_402_167, "overlap");
}
