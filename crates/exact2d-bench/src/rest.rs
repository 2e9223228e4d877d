//! `exact2d-bench rest`: piles, hoppers and Galton boards run until every ball sleeps.
//!
//! Each case is built from its seeded scene and advanced in steps of a tenth of a second
//! until every ball is asleep (or a wall-clock budget runs out, reported as such); then the
//! clock is moved on 1000 s, which must handle no event. The table gives the events handled
//! (every entry of the queue that changed a ball: collisions, settles, leaves, sleeps and
//! wakes), per ball, the simulated time at which the last ball fell asleep, the wall time to
//! get there, the deepest overlap of two bodies seen at the end (relative to their contact
//! distance), the events of the 1000 s after, and how far the pile at rest is from static
//! equilibrium (`balance.rs`: the largest force its frictionless contacts leave unbalanced on
//! one ball, as a share of that ball's weight; computed for piles of at most
//! [`BALANCE_MOST`] balls).

use std::time::Instant;

use exact2d::World;
use exact2d::scene::Scene;
use exact2d_bench::balance::out_of_balance;
use exact2d_bench::scenes;

/// The most balls a pile may have for its balance to be computed (the check is dense: its
/// cost grows as the cube of the contacts).
const BALANCE_MOST: usize = 300;

/// One case: a name and its scene.
struct Case {
    name: String,
    scene: Scene,
    /// Wall seconds after which the run gives up.
    budget: f64,
}

fn cases(quick: bool) -> Vec<Case> {
    let mut cases = Vec::new();
    for &(e, pegs) in &[(0.5, false), (0.8, false), (0.5, true), (0.8, true)] {
        let n = if quick { 100 } else { 400 };
        let n = std::env::var("EXACT2D_BENCH_N")
            .ok()
            .and_then(|v| v.parse().ok())
            .unwrap_or(n);
        cases.push(Case {
            name: format!("pile {n}, e = {e}{}", if pegs { ", pegs" } else { "" }),
            scene: scenes::pile(n, e, pegs, 1),
            budget: if quick { 30.0 } else { 120.0 },
        });
    }
    // A drop-and-merge game's box: its scale (some sixty balls of five sizes) and its
    // friction.
    for &(n, e) in &[(60, 0.3), (60, 0.6)] {
        cases.push(Case {
            name: format!("mixed {n}, e = {e}, mu = 0.5"),
            scene: scenes::mixed_pile(n, e, 0.5, 1),
            budget: if quick { 30.0 } else { 120.0 },
        });
    }
    let hopper = if quick { 300 } else { 2000 };
    cases.push(Case {
        name: format!("hopper {hopper}, e = 0.5"),
        scene: scenes::hopper(hopper, 0.5, 1),
        budget: if quick { 30.0 } else { 300.0 },
    });
    let galton = if quick { 200 } else { 1000 };
    cases.push(Case {
        name: format!("galton {galton}, e = 0.5"),
        scene: scenes::galton(galton, 0.5, 1),
        budget: if quick { 30.0 } else { 300.0 },
    });
    cases
}

/// How a run to rest ended: whether every ball sleeps, the simulated time reached (a whole
/// number of tenths), and the wall seconds it took.
pub(crate) struct Run {
    pub at_rest: bool,
    pub t: f64,
    pub wall: f64,
}

/// Advances `world` (named `name` in errors) in steps of a tenth of a second until every ball
/// sleeps, `budget` wall seconds have passed or the simulated time reaches `until` (rounded
/// up to a tenth), checking the budget every 256 events too (where every event is a large
/// jam, 65,536 of them took minutes). After each tenth that leaves a ball awake, `tenth` is
/// told the world, the time and the wall seconds so far.
pub(crate) fn to_rest(
    world: &mut World,
    (budget, until): (f64, f64),
    name: &str,
    mut tenth: impl FnMut(&World, f64, f64),
) -> Result<Run, String> {
    let n = world.ball_count();
    let start = Instant::now();
    let (mut t, mut at_rest, mut handled) = (0.0, false, 0u64);
    let tenths = (until * 10.0).ceil();
    let mut done = 0.0;
    'run: while start.elapsed().as_secs_f64() < budget && done < tenths {
        done += 1.0;
        t += 0.1;
        while world
            .step_until(t)
            .map_err(|e| format!("{name}: {e}"))?
            .is_some()
        {
            handled += 1;
            if handled % 256 == 0 && start.elapsed().as_secs_f64() >= budget {
                break 'run;
            }
        }
        if world.sleeping_count() == n {
            at_rest = true;
            break;
        }
        tenth(world, t, start.elapsed().as_secs_f64());
    }
    Ok(Run {
        at_rest,
        t,
        wall: start.elapsed().as_secs_f64(),
    })
}

/// All events the world handled, internal ones included.
fn events(world: &World) -> u64 {
    world.event_counts().handled()
}

/// The deepest overlap of two balls, or of a ball and a collider, relative to their
/// contact distance (0 if none overlap).
fn deepest_overlap(world: &World) -> f64 {
    let balls: Vec<_> = world.balls().map(|(_, b)| b).collect();
    let mut worst = 0.0_f64;
    for (i, a) in balls.iter().enumerate() {
        for b in &balls[i + 1..] {
            let reach = a.radius + b.radius;
            let d = a.position.distance(b.position);
            if d < reach {
                worst = worst.max((reach - d) / reach);
            }
        }
        for (_, c) in world.colliders() {
            if c.sensor {
                continue;
            }
            let gap = c.shape.distance(a.position) - a.radius;
            if gap < 0.0 {
                worst = worst.max(-gap / a.radius);
            }
        }
    }
    worst
}

/// Runs every case (every ball and collider given Coulomb friction `friction`, if above 0)
/// and prints the table.
pub fn run(quick: bool, only: Option<&str>, friction: f64) -> Result<(), String> {
    println!(
        "| scene | balls | events to rest | per ball | simulated s to rest | wall s | deepest overlap | events in the next 1000 s | out of balance |"
    );
    println!("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
    for mut case in cases(quick) {
        if only.is_some_and(|o| !case.name.contains(o)) {
            continue;
        }
        if friction > 0.0 {
            scenes::roughen(&mut case.scene, friction);
            // A case that has a friction of its own (the drop-and-merge box) has this one
            // instead: its name says so once.
            let name = case.name.split(", mu = ").next().unwrap_or(&case.name);
            case.name = format!("{name}, mu = {friction}");
        }
        let built = case
            .scene
            .build_world()
            .map_err(|e| format!("{}: {e}", case.name))?;
        let mut world = built.into_world();
        let n = world.ball_count();
        let verbose = std::env::var_os("EXACT2D_BENCH_VERBOSE").is_some();
        let Run {
            at_rest: rested,
            wall,
            ..
        } = to_rest(
            &mut world,
            (case.budget, f64::INFINITY),
            &case.name,
            |world, t, wall| {
                if verbose {
                    eprintln!(
                        "{}: t = {t:.1}, {} of {n} asleep, {} events, wall {wall:.1} s, {:?}",
                        case.name,
                        world.sleeping_count(),
                        events(world),
                        world.event_counts()
                    );
                }
            },
        )?;
        let to_rest = events(&world);
        let last = world
            .balls()
            .filter_map(|(h, _)| world.ball_asleep_since(h))
            .fold(0.0_f64, f64::max);
        let overlap = deepest_overlap(&world);
        let after = if rested {
            let before = events(&world);
            world
                .advance_to(world.time() + 1000.0)
                .map_err(|e| format!("{}: {e}", case.name))?;
            format!("{}", events(&world) - before)
        } else {
            "-".to_string()
        };
        // At rest, every ball sleeps where it fell asleep (the 1000 s after moved none).
        let balance = if rested && n <= BALANCE_MOST {
            let (worst, _) = out_of_balance(&world);
            format!("{worst:.1e}")
        } else {
            "-".to_string()
        };
        let rest = if rested {
            format!("{last:.2}")
        } else {
            format!(
                "not at rest at {:.2} ({} of {n} asleep)",
                world.time(),
                world.sleeping_count()
            )
        };
        println!(
            "| {} | {n} | {to_rest} | {:.0} | {rest} | {wall:.2} | {overlap:.1e} | {after} | {balance} |",
            case.name,
            to_rest as f64 / n as f64,
        );
    }
    Ok(())
}
