//! `exact2d-bench piles`: many poured piles, each run to rest, a line each and their totals.
//!
//! A change that alters an engine's bits moves a single poured pile's wall time to rest by
//! factors of up to five either way (chaos: the same pile takes another path), so one pile
//! says little about a change. The measure is many piles: seeds 1 to `seeds` of each of the
//! four kinds of `rest`'s piles (restitution 0.5 and 0.8, without and with the peg lattice),
//! each advanced in steps of a tenth of a second until every ball sleeps or its wall budget
//! runs out. Run two engines side by side (one on each core) and compare the totals, and the
//! geometric mean of the piles' ratios, which a few piles that take long do not dominate.
//! With `--until`, each pile stops at that simulated time instead (a fixed amount of work,
//! for instruction counts: a wall budget cuts a run where the machine's load says).
//! With `EXACT2D_BENCH_VERBOSE` set, each tenth of a simulated second's progress goes to
//! standard error, as in `rest`.

use exact2d_bench::scenes;

use crate::rest::{Run, to_rest};

/// What to run: piles of `balls` balls, seeds 1 to `seeds` of each kind, `friction` on every
/// ball and collider (none if 0), `budget` wall seconds at most each, only those whose name
/// contains `only`, and no further than `until` simulated seconds.
pub struct Piles<'a> {
    pub balls: usize,
    pub seeds: u64,
    pub friction: f64,
    pub budget: f64,
    pub only: Option<&'a str>,
    pub until: f64,
}

/// Runs the piles and prints a markdown table: one row per pile, then the totals.
pub fn run(piles: &Piles) -> Result<(), String> {
    println!("| pile | at rest | simulated s | events | jams | rigid hits | wall s |");
    println!("| --- | --- | ---: | ---: | ---: | ---: | ---: |");
    let (mut events, mut wall, mut rested, mut simulated, mut count) = (0u64, 0.0, 0, 0.0, 0);
    let verbose = std::env::var_os("EXACT2D_BENCH_VERBOSE").is_some();
    for (e, pegs) in [(0.5, false), (0.8, false), (0.5, true), (0.8, true)] {
        for seed in 1..=piles.seeds {
            let name = format!(
                "{} balls, e = {e}{}, seed {seed}",
                piles.balls,
                if pegs { ", pegs" } else { "" }
            );
            if piles.only.is_some_and(|only| !name.contains(only)) {
                continue;
            }
            let mut scene = scenes::pile(piles.balls, e, pegs, seed);
            if piles.friction > 0.0 {
                scenes::roughen(&mut scene, piles.friction);
            }
            let mut world = scene
                .build_world()
                .map_err(|error| format!("{name}: {error}"))?
                .into_world();
            let Run {
                at_rest,
                t,
                wall: seconds,
            } = to_rest(
                &mut world,
                (piles.budget, piles.until),
                &name,
                |world, t, wall| {
                    if verbose {
                        let counts = world.event_counts();
                        eprintln!(
                            "{name}: t = {t:.1}, {} of {} asleep ({} sleeps, {} wakes so far), {} events, {} jams, wall {wall:.1} s",
                            world.sleeping_count(),
                            world.ball_count(),
                            counts.sleeps,
                            counts.wakes,
                            counts.handled(),
                            counts.jams,
                        );
                    }
                },
            )?;
            let counts = world.event_counts();
            println!(
                "| {name} | {} | {t:.1} | {} | {} | {} | {seconds:.2} |",
                if at_rest { "yes" } else { "no" },
                counts.handled(),
                counts.jams,
                counts.rigid_hits,
            );
            events += counts.handled();
            wall += seconds;
            rested += usize::from(at_rest);
            simulated += t;
            count += 1;
        }
    }
    println!("| all {count} | {rested} | {simulated:.1} | {events} | | | {wall:.1} |");
    Ok(())
}
