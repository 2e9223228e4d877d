//! `exact2d soak`: run a scene for many events, checking invariants as it goes.
//!
//! The loop asks [`World::step_until`] for every event; every `check_every` events (and at the
//! start and the end) it takes a snapshot of the balls and checks the invariants of [`watch`];
//! after every event it checks that time did not go back and that the clock moves on (the
//! events at one instant within [`watch::EVENTS_PER_BALL`] per ball). The engine's own stall
//! error ([`exact2d::WorldError::Stalled`]) is a broken time invariant too. The first broken
//! invariant stops the run.

mod containment;
mod energy;
mod overlap;
mod progress;
mod report;
mod watch;

use std::io::Write;
use std::path::Path;
use std::time::{Duration, Instant};

use exact2d::{Ball, Collider, World};

use crate::bodies;
use crate::failure::Failure;
use crate::output::print_json_line;
use crate::simulate::read_scene;
use progress::Progress;
use report::{SoakReport, Stop};
use watch::{Violation, Watch};

/// Events between checks per ball and collider, by default. A check costs at most about
/// as much per body as one event (a copy, a sort and a few distances, against an event's queue
/// work), so this bounds the checks near 1/64 of the run; measured in release, they took
/// 0.3% of a 10^8-event run of a gas of 10^4 balls and 0.2% on brick boards.
const DEFAULT_EVENTS_PER_BODY: u64 = 64;

/// The least default number of events between checks, so a scene of one ball is not checked
/// after every event.
const MIN_DEFAULT_CHECK_EVERY: u64 = 1000;

/// What `exact2d soak` was asked to do.
pub struct SoakOptions {
    /// Events to handle, >= 1.
    pub events: u64,
    /// Events between checks, >= 1; `None` for the default.
    pub check_every: Option<u64>,
    /// Check that no ball leaves the box around the solid colliders.
    pub closed: bool,
}

/// A run in progress: the world, its invariants and the clocks.
struct Run {
    world: World,
    watch: Watch,
    progress: Progress,
    /// Events handled.
    events: u64,
    /// Reused for every snapshot.
    balls: Vec<Ball>,
    check_wall: Duration,
}

/// Runs the scene at `scene_path` as `options` say, then prints the report on standard
/// output. A broken invariant prints the report too, and fails with exit code 1.
pub fn run(scene_path: &Path, options: &SoakOptions) -> Result<(), Failure> {
    let bad = |e: String| Failure::BadInput(format!("{}: {e}", scene_path.display()));
    let scene = read_scene(scene_path)?;
    let world = scene
        .build_world()
        .map_err(|e| bad(e.to_string()))?
        .into_world();
    let balls = snapshot(&world, Vec::new());
    let colliders: Vec<Collider> = world.colliders().map(|(_, c)| *c).collect();
    let check_every = options
        .check_every
        .unwrap_or_else(|| default_check_every(balls.len(), colliders.len()));
    let (gravity, time) = (world.gravity(), world.time());
    let periodic = world.periodic_box();
    let watch =
        Watch::new(&balls, colliders, gravity, periodic, time, options.closed).map_err(bad)?;
    let mut run = Run {
        world,
        watch,
        progress: Progress::new(options.events),
        events: 0,
        balls,
        check_wall: Duration::ZERO,
    };
    let start = Instant::now();
    let (stopped, violation) = run.soak(options.events, check_every);
    let wall = start.elapsed();
    run.progress.finish();
    print_json_line(&run.report(stopped, check_every, wall))?;
    match violation {
        None => Ok(()),
        Some(v) => Err(Failure::Other(format!(
            "{}: at event {}, time {:?}: {v}",
            scene_path.display(),
            run.events,
            run.world.time()
        ))),
    }
}

/// The default events between checks for `balls` balls and `colliders` colliders.
#[must_use]
fn default_check_every(balls: usize, colliders: usize) -> u64 {
    let bodies = (balls + colliders) as u64;
    (DEFAULT_EVENTS_PER_BODY * bodies).max(MIN_DEFAULT_CHECK_EVERY)
}

/// Every ball of `world` now, in slot order, into `buffer` (cleared first).
fn snapshot(world: &World, mut buffer: Vec<Ball>) -> Vec<Ball> {
    buffer.clear();
    buffer.extend(world.balls().map(|(_, ball)| ball));
    buffer
}

impl Run {
    /// Handles events until `target` are handled, none is left or an invariant breaks.
    fn soak(&mut self, target: u64, check_every: u64) -> (Stop, Option<Violation>) {
        if let Err(v) = self.check() {
            return (Stop::Invariant, Some(v));
        }
        while self.events < target {
            let event = match self.world.step_until(f64::INFINITY) {
                Ok(Some(event)) => event,
                Ok(None) => {
                    let outcome = self.final_check(check_every, Stop::NoEventsLeft);
                    self.note_no_events_left();
                    return outcome;
                }
                Err(e) => return (Stop::Invariant, Some(self.engine_violation(&e))),
            };
            self.events += 1;
            let time = event.time();
            if let Err(v) = self.watch.check_time(time) {
                return (Stop::Invariant, Some(v));
            }
            let instant = self.world.instant_events();
            let world = &self.world;
            let bodies = || bodies::of_event(world, &event);
            if let Err(v) = self.watch.check_instant(instant, time, bodies) {
                return (Stop::Invariant, Some(v));
            }
            if self.events % check_every == 0 {
                if let Err(v) = self.check() {
                    return (Stop::Invariant, Some(v));
                }
            } else if self.events % PROGRESS_EVERY == 0 {
                self.progress.advance(self.events);
            }
        }
        self.final_check(check_every, Stop::Events)
    }

    /// The engine refused to go on: its stall error (the clock stalled) is the `time`
    /// invariant, naming the bodies; any other error (none is expected: the clock is asked
    /// for no time in particular) too, as the engine words it.
    fn engine_violation(&self, error: &exact2d::WorldError) -> Violation {
        let detail = bodies::stall(&self.world, error)
            .unwrap_or_else(|| format!("the engine refused to go on: {error}"));
        Violation {
            invariant: "time",
            detail,
        }
    }

    /// The check at the end, unless the last event was just checked.
    fn final_check(&mut self, check_every: u64, stop: Stop) -> (Stop, Option<Violation>) {
        if self.events % check_every == 0 && self.events > 0 {
            return (stop, None);
        }
        match self.check() {
            Ok(()) => (stop, None),
            Err(v) => (Stop::Invariant, Some(v)),
        }
    }

    /// Checks every invariant on a snapshot of the world now.
    fn check(&mut self) -> Result<(), Violation> {
        let start = Instant::now();
        self.balls = snapshot(&self.world, std::mem::take(&mut self.balls));
        let time = self.world.time();
        let jams = self.world.event_counts().jams;
        let result = self.watch.check(&self.balls, time, jams);
        self.check_wall += start.elapsed();
        let overlap = self.watch.worst_overlap;
        self.progress.checked(self.events, time, overlap);
        result
    }

    fn note_no_events_left(&self) {
        let (events, time) = (self.events, self.world.time());
        let line = format!("soak: no event left after {events} events, at time {time:?}");
        // A note for a person; the report on standard output says the same.
        let _ = writeln!(std::io::stderr(), "{line}");
    }

    fn report(&self, stopped: Stop, check_every: u64, wall: Duration) -> SoakReport {
        let counts = self.world.event_counts();
        let wall_s = wall.as_secs_f64();
        SoakReport {
            events: self.events,
            collisions: counts.collisions(),
            sensor_events: counts.sensor_enters + counts.sensor_exits,
            time: self.world.time(),
            stopped,
            wall_s,
            events_per_s: self.events as f64 / wall_s.max(f64::MIN_POSITIVE),
            check_every,
            checks: self.watch.checks,
            check_wall_s: self.check_wall.as_secs_f64(),
            worst_overlap: self.watch.worst_overlap,
            worst_energy_drift: self.watch.worst_energy_drift,
            balls_escaped: self.watch.balls_escaped,
            invariants_ok: stopped != Stop::Invariant,
        }
    }
}

/// Events between two updates of the progress bar's count (between checks).
const PROGRESS_EVERY: u64 = 1 << 16;
