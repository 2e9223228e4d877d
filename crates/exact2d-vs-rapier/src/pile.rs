//! `--pile N`: N balls poured into a 10 x 30 box (`exact2d_bench::scenes::pile`, radius 0.2,
//! restitution 0.5 or 0.8, with and without a lattice of pegs) until they rest, in exact2d
//! (sleeping on) and in Rapier at 60 Hz (its own sleeping, default thresholds), both watched
//! at 60 Hz for the same simulated seconds; and in Rapier once more as a game would set the
//! pile up there, with its default friction (0.5) and the balls free to roll, where exact2d
//! (and the first Rapier run) have no friction; and in exact2d with that friction too. For
//! each: from when every ball is asleep for good (the frame after the last one with a ball
//! awake), the wall time of the whole run, and the deepest overlap seen at any frame, as a
//! fraction of the ball radius.

use std::time::{Duration, Instant};

use exact2d_bench::scenes;

use crate::engines::{
    FRAME_HZ, exact2d_states, frame_time, frames, rapier_states, rapier_world_with_friction,
};

/// Rapier's default friction coefficient, for the row of the table that shows the pile as a
/// game would have it in Rapier (friction on, balls free to roll).
const RAPIER_DEFAULT_FRICTION: f64 = 0.5;
use crate::measure::{BallState, SceneGeometry};

/// What one engine did with one pile.
#[derive(Default)]
struct Outcome {
    /// The frame time from which every ball slept to the end, if they did.
    asleep_from: Option<f64>,
    /// Wall time stepping the engine.
    wall: Duration,
    /// The deepest overlap over the radius, at any frame.
    penetration: f64,
    /// The simulated seconds run (less than asked if the wall budget ran out).
    seconds: f64,
    /// exact2d's events (collisions and internal changes), if it is exact2d.
    events: Option<u64>,
}

impl Outcome {
    /// Frame time `t` came after `wall` of stepping, with the balls `states`, all asleep or not.
    fn frame(
        &mut self,
        t: f64,
        wall: Duration,
        geometry: &SceneGeometry,
        states: &[BallState],
        all_asleep: bool,
    ) {
        self.wall += wall;
        self.seconds = t;
        self.penetration = self.penetration.max(geometry.max_penetration(states).1);
        if all_asleep {
            self.asleep_from.get_or_insert(t);
        } else {
            self.asleep_from = None;
        }
    }
}

/// Runs the four piles of `balls` balls for `seconds` simulated seconds each (exact2d stops
/// early, reported, once it has used `budget` wall seconds) and prints the table.
pub fn run(balls: usize, seconds: f64, budget: f64) -> Result<(), String> {
    println!(
        "| pile | engine | simulated s | every ball asleep from (s) | wall s | deepest overlap (/ radius) | events |"
    );
    println!("| --- | --- | ---: | ---: | ---: | ---: | ---: |");
    for &(e, pegs) in &[(0.5, false), (0.8, false), (0.5, true), (0.8, true)] {
        let scene = scenes::pile(balls, e, pegs, 1);
        let name = format!("{balls} balls, e = {e}{}", if pegs { ", pegs" } else { "" });
        eprintln!("pile {name}: exact2d");
        let exact = run_exact2d(&scene, seconds, budget)?;
        eprintln!("pile {name}: exact2d, friction {RAPIER_DEFAULT_FRICTION}");
        let mut rough_scene = scene.clone();
        scenes::roughen(&mut rough_scene, RAPIER_DEFAULT_FRICTION);
        let exact_rough = run_exact2d(&rough_scene, seconds, budget)?;
        let exact_rough_name = format!("exact2d, friction {RAPIER_DEFAULT_FRICTION}");
        eprintln!("pile {name}: Rapier 60 Hz");
        let rapier = run_rapier(&scene, seconds, None);
        eprintln!("pile {name}: Rapier 60 Hz, friction {RAPIER_DEFAULT_FRICTION}");
        let rough = run_rapier(&scene, seconds, Some(RAPIER_DEFAULT_FRICTION));
        let rough_name = format!("Rapier 60 Hz, friction {RAPIER_DEFAULT_FRICTION}, rolling");
        for (engine, outcome) in [
            ("exact2d", &exact),
            ("Rapier 60 Hz", &rapier),
            (exact_rough_name.as_str(), &exact_rough),
            (rough_name.as_str(), &rough),
        ] {
            println!(
                "| {name} | {engine} | {:.2} | {} | {:.2} | {:.1e} | {} |",
                outcome.seconds,
                outcome
                    .asleep_from
                    .map_or_else(|| "not at rest".to_owned(), |t| format!("{t:.2}")),
                outcome.wall.as_secs_f64(),
                outcome.penetration,
                outcome
                    .events
                    .map_or_else(|| "-".to_owned(), |n| n.to_string()),
            );
        }
    }
    Ok(())
}

fn run_exact2d(
    scene: &exact2d::scene::Scene,
    seconds: f64,
    budget: f64,
) -> Result<Outcome, String> {
    let geometry = SceneGeometry::new(scene);
    let mut built = scene.build_world().map_err(|e| e.to_string())?;
    let handles = built.ball_handles().to_vec();
    let mut outcome = Outcome::default();
    let mut states = Vec::with_capacity(handles.len());
    for k in 1..=frames(seconds) {
        let t = frame_time(k);
        let start = Instant::now();
        built.world_mut().advance_to(t).map_err(|e| e.to_string())?;
        let wall = start.elapsed();
        let world = built.world();
        exact2d_states(world, &handles, &mut states)?;
        let all_asleep = world.sleeping_count() == handles.len();
        outcome.frame(t, wall, &geometry, &states, all_asleep);
        if outcome.wall.as_secs_f64() >= budget {
            break;
        }
    }
    outcome.events = Some(built.world().event_counts().handled());
    Ok(outcome)
}

/// Rapier at 60 Hz on `scene`: frictionless as exact2d, or with `friction` and rolling.
fn run_rapier(scene: &exact2d::scene::Scene, seconds: f64, friction: Option<f64>) -> Outcome {
    let geometry = SceneGeometry::new(scene);
    let (mut world, handles) =
        rapier_world_with_friction(scene, 1.0 / f64::from(FRAME_HZ), friction);
    let mut outcome = Outcome::default();
    let mut states = Vec::with_capacity(handles.len());
    for k in 1..=frames(seconds) {
        let start = Instant::now();
        world.step();
        let wall = start.elapsed();
        rapier_states(&world, &handles, &mut states);
        let all_asleep = handles.iter().all(|&h| world.bodies[h].is_sleeping());
        outcome.frame(frame_time(k), wall, &geometry, &states, all_asleep);
    }
    outcome
}
