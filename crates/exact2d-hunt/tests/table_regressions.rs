//! Every seed a table hunt (`exact2d-hunt --table`) once broke, replayed: the scene of
//! `SplitMix64(seed)` with the default [`Options`], laid on a table from
//! `SplitMix64(seed ^ TABLE_SEED)` as the command does, run to 3 simulated seconds or 300,000
//! events, keeps every invariant.

use exact2d_hunt::generate::{Options, ROUGH_SEED, TABLE_SEED, generate, lay_on_table, roughen};
use exact2d_hunt::run::{Limits, run};
use exact2d_hunt::source::SplitMix64;

/// [`replay`], the scene made rough first (`--rough --table`) if `rough`.
fn replay_as(seed: u64, broke: &str, rough: bool) {
    let mut generated = generate(&mut SplitMix64(seed), Options::default());
    if rough {
        roughen(&mut generated.scene, &mut SplitMix64(seed ^ ROUGH_SEED));
    }
    let scale = generated.scale;
    lay_on_table(
        &mut generated.scene,
        scale,
        &mut SplitMix64(seed ^ TABLE_SEED),
    );
    let outcome = run(
        &generated,
        Limits {
            until: 3.0,
            events: 300_000,
            collapse: 0.0,
        },
    );
    if let Some(finding) = outcome.finding {
        panic!(
            "table seed {seed} (once broke: {broke}), after {} events at t = {:?}: {finding}",
            outcome.events, outcome.time
        );
    }
}

/// One test per seed (so they run in parallel and fail by name), made rough first if the
/// list says `true`.
macro_rules! replays {
    ($rough:literal; $($(#[$doc:meta])* $name:ident = $seed:literal, $broke:literal;)*) => {
        $(
            $(#[$doc])*
            #[test]
            fn $name() {
                replay_as($seed, $broke, $rough);
            }
        )*
    };
}

replays! {
    false;
    // A ball the cloth drives into a cushion bounced towards an accumulation point: a stall
    // (the cushion hold, `World::hold_at_cushion`); in a wedge, handed from wall to wall at
    // one instant, its slip shrinking by a projection each time (both walls hold it).
    seed_163 = 163, "overlap, stall";
    seed_215 = 215, "overlap, stall";
    seed_442 = 442, "overlap, stall";
    seed_571 = 571, "overlap, stall";
    // Touching stacks the cloth presses together: micro-hops for ever (a crawl), then pairs
    // joined one after another (the cluster join, `World::join_on_table`).
    seed_958 = 958, "crawl";
    seed_290 = 290, "overlap, stall";
    seed_250 = 250, "crawl, stall";
    seed_512 = 512, "overlap, stall";
    seed_4331 = 4331, "overlap";
    seed_6098 = 6098, "crawl";
    seed_10204 = 10204, "crawl";
    seed_63500 = 63500, "overlap";
    seed_669 = 669, "overlap";
    seed_804 = 804, "overlap";
    seed_866 = 866, "crawl";
    // A slip of 1e-25 kept its phase's full acceleration: its end, sooner than the clock
    // can tell, was dropped, and the ball sped up for 0.6 s (what ends within a tick ends
    // now, `World::lay_on_table`).
    seed_37151 = 37151, "energy";
    seed_134056 = 134056, "energy";
    seed_138551 = 138551, "energy";
    seed_311 = 311, "energy";
    // A ball sliding along an exact-fit channel, both walls touched, met one then the other
    // a tick later (walls it slides along for its phase, `World::slid_along`).
    seed_125604 = 125604, "crawl";
    seed_77775 = 77775, "crawl"; // and with a band of 128 ulps instead of the overlap bound
    seed_148667 = 148667, "crawl"; // likewise
    // Slid along within the touching band, not the overlap bound; a cluster joined against
    // two walls of a wedge, bouncing off each alone.
    seed_286336 = 286336, "overlap";
    seed_61715 = 61715, "overlap";
    seed_162523 = 162523, "overlap";
    seed_6067 = 6067, "stall";
    // Balls of radius 2e-7 at 1e9 (a unit in the last place is 1.2e-7): one rounding of a
    // position put a centre on a wall's line, no longer touching it by the half-reach rule;
    // met at once and again, its jam found nothing to push against (a ball touches within
    // the touching band too, `touching_gap`).
    seed_2638 = 2638, "stall";
    seed_19422 = 19422, "stall";
    seed_33417 = 33417, "stall";
    seed_690523 = 690523, "stall";
    // A slip of 3e-30 at t = 1.16 ended 1e-30 later, just resolvable; read back from the time
    // it was stored as, its end fell below the clock's resolution and was dropped, and the
    // ball slid on at mu g for 0.4 s into a wall it slid along for that instant, and through
    // it (a phase end the clock cannot tell from now is due now).
    seed_5494070 = 5494070, "overlap, escape";
    // A ball the cloth drives down an exact-fit channel onto one sliding past below it at
    // 1 m/s, where `v^2 = a d`: their gap fell from touching at third order (`f'` and `f''`
    // both zero), which the kernel took for tangential, and they sank 9.2e-2 of their contact
    // distance into each other (`ParabolicGap`: pulled in at third order is contact now).
    seed_1178732 = 1178732, "overlap";
    // A ball sliding down a funnel's neck wall, its slip all but along the wall: the cloth
    // pulled it in at 5.7e-10 of its acceleration, under the `PARALLEL` the hold took for
    // rounding, so it was never held; its bounces shortened until the collapse floor made
    // them elastic, then repeated every 8.7e-17 s (the hold takes any pull beyond the slip's
    // own rounding, `ClothPhase::slack`).
    seed_1048239 = 1048239, "crawl";
    // A ball rolling into the box's floor by a rounding, on a cloth without rolling friction:
    // slid along and cut where it would be half the overlap bound in, it was cut after a
    // travel its position never took, and laid afresh every 2.1e-5 s (internal events: the
    // hunt hung on it). A cushion is slid along so only with a quarter of the bound to go.
    seed_1060307 = 1060307, "crawl of internal events";
    // A ball in a funnel's neck, a hair (4e-13) wider than it, struck sideways at 44 m/s by
    // a corner shot: it crossed the neck every 9.1e-15 s, each bounce elastic within the
    // collapse floor of the last, and the zero-time chain that would have made the rattle a
    // jam was reckoned from its first event, 3.4e-14 s long at t = 0.037: four bounces, each
    // wall twice, then a new chain, for ever (a chain now goes on while each event follows the
    // last within the floor, `pipeline/instant.rs`).
    seed_1826674 = 1826674, "crawl";
}

// The `--rough --table` seeds, made rough before they are laid on the table.
replays! {
    true;
    /// `--rough --table` seed 2299300: a ball at the end of a channel's ceiling, pressed into it by
    /// the cloth, bounced on the ceiling's interior towards an accumulation point (a crawl): the
    /// hold tested the end point, the nearest feature a hair past the end, whose curvature let the
    /// ball fly off in the test; it now tests the feature the contact met.
    rough_seed_2299300 = 2_299_300, "crawl";
    /// `--rough --table` seed 2778192: a ball moving along an exact-fit channel whose walls face
    /// each other but for 5.7e-13 radians, on a cloth without sliding friction (an endless phase),
    /// met one wall, then the other 1e-14 s later when the spin the first one's friction gave it
    /// stopped, for ever (a crawl). An endless phase slides along the walls a ball touches until it
    /// would be half the overlap bound into one (`World::slid_along`).
    rough_seed_2778192 = 2_778_192, "crawl";
    /// `--rough --table` seed 2657960: a cluster the cloth drove against a ball at a cushion
    /// bounced off it and jammed; the jam's impact left two of its balls tangential, but their new
    /// phases pressed them together, and, closed for the chain, their contact was sought again only
    /// 8 ulps deeper, where they were joined and driven back: 6.8e-9 of their contact distance deep
    /// at x = 1e6 after some 55 rounds. After a jam the cloth's holds act at once
    /// (`World::hold_after_jam`).
    rough_seed_2657960 = 2_657_960, "overlap";
    /// `--rough --table` seed 5230472 (a funnel, scale 1 at 1e9): a ball rolling at 0.145 m/s into
    /// the funnel's neck, which the offset's rounding makes 1.6 ulps narrower than it, its centre
    /// 16 ulps above the neck's end points. Each end point, met in turn, left the ball approaching
    /// the other at 5.5e-6 m/s and a slip whose slide lasted 4e-7 s, and the slide counted the
    /// other as slid along (it would go no deeper into it than half the overlap bound), so it was
    /// not met again until the slide ended: three events every 4e-7 s, each restating the ball,
    /// whose 5.8e-8 of travel in that time is under half an ulp of its coordinates, so it never
    /// moved while its path said it fell. A ball from above ran into it, 2.8e-4 of their contact
    /// distance deep by t = 2.02. A slide too short to move its ball slides along no cushion the
    /// ball moves into beyond the rounding of its direction (`World::slid_along`): met at once, the
    /// neck's two points are a jam, which stops it.
    rough_seed_5230472 = 5_230_472, "overlap";
    /// `--rough --table` seed 5442333 (a corner shot and a stack, scale 1e-6 at 1e9, a box of 34 by
    /// 84 ulps, smaller than the overlap bound there, 5.7e-5): a ball bounced between the box's
    /// side walls at t = 0 and left the last bounce moving into one of them at 62 % of its speed,
    /// on a slide of 0.36 s that would take it 2.6e-5 into that wall, under half the bound, so the
    /// wall counted as slid along and was never met: its centre crossed the wall's line, and the
    /// ball left the box, 5.8e-5 outside it by t = 0.73. A slide now goes no deeper into a cushion
    /// it slides along than half the ball's radius either.
    rough_seed_5442333 = 5_442_333, "escape";
    /// `--rough --table` seed 5024241 (scale 1e-6 at 1): never broke the engine, but broke a first
    /// form of the rule of seed 5230472 that met every cushion a slide moves into beyond the
    /// rounding of its direction. A ball rolling at 2e-7 m/s along the floor under a ball pinned by
    /// the ceiling (an exact-fit column, their normal 9.6e-5 off the vertical) was pressed into the
    /// floor at 6e-14 m/s at each of their contacts; met each time, the floor's friction left a
    /// slide of 6.4e-9 s, and the three contacts came again at its end, a crawl in which a ball
    /// beside it sank 1.1e-7 of their contact distance into it. Such a slide moves the ball on (six
    /// ulps of its coordinates), and slides along the floor.
    rough_seed_5024241 = 5_024_241, "overlap, under a rule since narrowed";
    /// `--rough --table` seed 6746486 (a peg beside a wall, scale 1e6 at 1e9, their gap 1.4e-9
    /// of the contact distance narrower than the ball): a ball driven down between them by its
    /// roll met the peg, which turned it into the wall at 0.44 m/s while it fell at 17,000; the
    /// slide after slid along the wall, and at each restatement the ball's move towards the
    /// wall, 2e-8, under half an ulp at 1e9, was rounded away while its fall was not: 2.3e-8
    /// deeper into the peg a round, just past the overlap bound after 28,000 rounds. On a
    /// table too, restatements now carry what a position's rounding leaves out.
    rough_seed_6746486 = 6_746_486, "overlap";
}
