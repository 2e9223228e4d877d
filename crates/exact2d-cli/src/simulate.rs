//! `exact2d simulate`: read a scene, run it to time T, print the balls.

use std::path::Path;
use std::time::{Duration, Instant};

use exact2d::scene::{BuiltScene, Scene, SceneItem};
use exact2d::{BallHandle, World, WorldError};

use crate::bodies;
use crate::clock_progress::{ClockProgress, EVENTS_PER_LOOK};
use crate::failure::Failure;
use crate::output::{BallState, ColliderItem, ColliderState, EventLog, Report, print_json_line};

/// Runs the scene file at `scene_path` to time `until` (finite, >= 0), writing the events to
/// `events_path` if given, then prints the report on standard output, with the run's
/// observables if `observables`. Nothing is printed on standard output unless everything else
/// succeeded.
pub fn run(
    scene_path: &Path,
    until: f64,
    events_path: Option<&Path>,
    observables: bool,
) -> Result<(), Failure> {
    let scene = read_scene(scene_path)?;
    let bad_scene = |e| Failure::BadInput(format!("{}: {e}", scene_path.display()));
    let mut built = scene.build_world().map_err(bad_scene)?;
    let rough = scene.is_rough();
    let mut log = events_path
        .map(|path| EventLog::create(path, rough))
        .transpose()?;
    let wall = simulate(&mut built, until, log.as_mut())
        .map_err(|e| engine_failure(scene_path, built.world(), e))?;
    if let Some(log) = log {
        log.finish()?;
    }
    let mut report = report(&built, wall, rough)?;
    if observables {
        observed(&built, &mut report)?;
    }
    print_json_line(&report)
}

/// Reads and parses the scene file; a parse or validation problem is bad input (exit 2), an
/// unreadable file anything else (exit 1).
pub(crate) fn read_scene(path: &Path) -> Result<Scene, Failure> {
    let bytes = std::fs::read(path)
        .map_err(|e| Failure::Other(format!("{}: cannot read the scene: {e}", path.display())))?;
    let bad = |message: String| Failure::BadInput(format!("{}: {message}", path.display()));
    let text = std::str::from_utf8(&bytes).map_err(|e| {
        bad(format!(
            "not UTF-8 text (invalid byte at offset {})",
            e.valid_up_to()
        ))
    })?;
    Scene::from_json_str(text).map_err(|e| bad(e.to_string()))
}

/// Steps the world to `until` and returns the time spent in the engine. Without an events
/// log one clock brackets the whole run; with one, only the engine's calls are timed, so
/// writing the file is not counted.
///
/// # Errors
/// The engine's error (a stalled clock, [`WorldError::Stalled`]), or the events file's.
fn simulate(
    built: &mut BuiltScene,
    until: f64,
    log: Option<&mut EventLog>,
) -> Result<Duration, RunError> {
    let mut progress = ClockProgress::new(until);
    let mut events = 0u64;
    let mut wall = Duration::ZERO;
    let Some(log) = log else {
        // `advance_to`, event by event, so that a long run shows how far it has come.
        let start = Instant::now();
        while let Some(event) = built.world_mut().step_until(until)? {
            events += 1;
            if events % EVENTS_PER_LOOK == 0 {
                progress.at(event.time(), events);
            }
        }
        progress.finish();
        return Ok(start.elapsed());
    };
    loop {
        let start = Instant::now();
        let event = built.world_mut().step_until(until)?;
        wall += start.elapsed();
        match event {
            Some(event) => {
                log.write(&event, built)?;
                events += 1;
                if events % EVENTS_PER_LOOK == 0 {
                    progress.at(event.time(), events);
                }
            }
            None => {
                progress.finish();
                return Ok(wall);
            }
        }
    }
}

/// Why a run stopped short of its end time.
enum RunError {
    /// The engine refused to go on.
    Engine(WorldError),
    /// Anything else (writing the events file).
    Failure(Failure),
}

impl From<WorldError> for RunError {
    fn from(e: WorldError) -> Self {
        RunError::Engine(e)
    }
}

impl From<Failure> for RunError {
    fn from(f: Failure) -> Self {
        RunError::Failure(f)
    }
}

/// The failure of a run that stopped short: a stalled clock (exit code 1) names the scene
/// file, the time and the bodies of the last event as the scene names them (see
/// [`bodies::stall`]); any other engine error is internal.
fn engine_failure(scene_path: &Path, world: &World, error: RunError) -> Failure {
    match error {
        RunError::Failure(f) => f,
        RunError::Engine(e) => match bodies::stall(world, &e) {
            Some(stall) => Failure::Other(format!("{}: {stall}", scene_path.display())),
            None => Failure::Other(format!("internal error: {e}")),
        },
    }
}

/// The result at the end; with `spin`, each ball's spin too (a scene with spin or friction).
fn report(built: &BuiltScene, wall: Duration, spin: bool) -> Result<Report, Failure> {
    let world = built.world();
    let balls = built
        .ball_handles()
        .iter()
        .zip(built.ball_ids())
        .map(|(&handle, &id)| ball_state(world, handle, id, spin))
        .collect::<Result<_, _>>()?;
    Ok(Report {
        time: world.time(),
        events: world.event_counts().collisions(),
        wall_s: wall.as_secs_f64(),
        balls,
        asleep: world.sleeping().then(|| world.sleeping_count()),
        virial: None,
        since: None,
        colliders: None,
    })
}

/// Adds the run's observables to `report`: the collision virial, the time it counts from,
/// and each scene collider's momentum and impacts, in scene order (segments, then circles).
fn observed(built: &BuiltScene, report: &mut Report) -> Result<(), Failure> {
    let world = built.world();
    let observables = world.observables();
    let mut colliders = Vec::with_capacity(world.collider_count());
    for (handle, collider) in world.colliders() {
        let name = bodies::collider_name(collider);
        let lost = || Failure::Other(format!("internal error: {name} lost"));
        let item = match built.collider_item(handle).ok_or_else(lost)? {
            SceneItem::Segment(i) => ColliderItem::Segment(i),
            SceneItem::Circle(i) => ColliderItem::Circle(i),
            SceneItem::Ball(_) => return Err(lost()),
        };
        let momentum = world.collider_momentum(handle).ok_or_else(lost)?;
        if !momentum.is_finite() {
            let time = world.time();
            return Err(Failure::Other(format!(
                "{name}: its momentum overflowed by time {time}"
            )));
        }
        colliders.push(ColliderState {
            item,
            momentum: momentum.to_array(),
            impacts: world.collider_impacts(handle).ok_or_else(lost)?,
        });
    }
    let virial = observables.collision_virial();
    if !virial.is_finite() {
        let time = world.time();
        return Err(Failure::Other(format!(
            "the collision virial overflowed by time {time}"
        )));
    }
    report.virial = Some(virial);
    report.since = Some(observables.since());
    report.colliders = Some(colliders);
    Ok(())
}

fn ball_state(
    world: &World,
    handle: BallHandle,
    id: u64,
    spin: bool,
) -> Result<BallState, Failure> {
    let ball = world
        .ball(handle)
        .ok_or_else(|| Failure::Other(format!("internal error: ball {id} lost")))?;
    // JSON has no infinity: serde_json would print `null`, which does not read back.
    let finite = ball.position.is_finite() && ball.velocity.is_finite() && ball.spin.is_finite();
    if !(finite && ball.roll.is_finite()) {
        let time = world.time();
        return Err(Failure::Other(format!(
            "ball {id}: its state overflowed by time {time}"
        )));
    }
    Ok(BallState {
        id,
        pos: ball.position.to_array(),
        vel: ball.velocity.to_array(),
        spin: spin.then_some(ball.spin),
        roll: world.table().map(|_| ball.roll.to_array()),
        unwrapped: world
            .periodic_box()
            .and_then(|_| world.ball_unwrapped_position(handle))
            .map(|p| p.to_array()),
    })
}
