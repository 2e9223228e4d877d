//! `exact2d`: the command-line tool of the exact2d engine.
//!
//! `exact2d simulate SCENE.json --until T [--events EVENTS.jsonl] [--observables]` runs a scene
//! file (format version 1, see `docs/scene-format.md`) from time 0 to `T` and prints the balls'
//! states at exactly `T` as one JSON object (with the run's collision virial and each
//! collider's momentum and impacts if asked). Exit codes: 0 success, 2 bad input (one line on standard
//! error naming the file and the item), 1 anything else (a stalled clock among them).
//!
//! `exact2d soak SCENE.json --events N [--check-every K] [--closed]` runs a scene for N events,
//! checking invariants (no overlap, containment, energy, time that goes back or stalls) every
//! K events (time after every event), and prints a one-line JSON report.

// The subcommands' doc comments are their `--help` text, with JSON examples such as
// `[x,y]` that rustdoc would otherwise read as links.
#![allow(rustdoc::broken_intra_doc_links)]

mod bodies;
mod clock_progress;
mod failure;
mod output;
mod simulate;
mod soak;

use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand};

/// Exact, event-driven 2D physics for balls: every collision at its exact time of impact.
#[derive(Parser)]
#[command(name = "exact2d", version)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run a scene file from time 0 to time T and print every ball's state at T
    ///
    /// Prints one JSON object, on one line, on standard output:
    ///
    ///   {"time":T,"events":N,"wall_s":S,"balls":[{"id":ID,"pos":[x,y],"vel":[x,y]},...]}
    ///
    /// with the balls in the order of the scene, at exactly time T. `events` counts the
    /// collisions handled; `wall_s` is the time spent simulating, in seconds, reading and
    /// writing files excluded. A scene with "sleep": true adds "asleep":K, the number of
    /// balls asleep at T. In a periodic box ("periodic": [Lx, Ly]) positions are in the box
    /// and each ball adds "unwrapped":[x,y] last, its position plus the box lengths it
    /// crossed. Every number reads back to the same f64.
    ///
    /// With --observables, the accumulators of the run follow, last:
    ///
    ///   "virial":W,"since":0,"colliders":[{"segment":I,"momentum":[x,y],"impacts":N},...,{"circle":I,...}]
    ///
    /// W: the collision virial, the sum over every impulse two balls exchanged of
    /// (p_i - p_j) . J_i (centres p at the impact, J_i the impulse ball i received), so each
    /// collision adds its contact distance times its normal impulse (mass x length^2 / time).
    /// Each collider (I its index in the scene's segments or circles, in scene order):
    /// the momentum the balls gave it (minus the sum of the impulses it gave them: a ball
    /// bouncing off a wall on its right gives it +x), and its impacts, the collisions
    /// with it. Resting contact under gravity (a ball resting, sliding or rolling on a
    /// surface, balls a group holds together) is a continuous force, not an impulse:
    /// excluded. See ARCHITECTURE.md, "Observables".
    ///
    /// A long run shows how far its clock has come on standard error: a bar on a terminal,
    /// otherwise a line at most every 10 s of wall (a run of a few seconds writes nothing).
    ///
    /// Exit codes: 0 success; 2 bad input (an invalid scene or argument, with one line on
    /// standard error naming the file and the item); 1 anything else (such as an unreadable
    /// file, or a clock that stalls: more events at one instant than the engine takes, named
    /// with the time and the bodies of the last event), with a message.
    ///
    /// Example: exact2d simulate examples/sinai.json --until 10 --events events.jsonl
    #[command(verbatim_doc_comment)]
    Simulate(SimulateArgs),
    /// Run a scene file for N events, checking invariants as it goes
    ///
    /// Handles events one at a time (collisions and sensor events) until N are handled or none
    /// is left. After every event it checks that time never goes back and moves on: at most
    /// 64 events at one instant per ball that had one, plus 64 (the engine's own internal
    /// events counted). At the start, every K events and at the end it checks that no two
    /// interacting bodies overlap deeper than 1e-9 of their contact distance plus 256 units in
    /// the last place of the contact's coordinate scale (the largest coordinate magnitude of
    /// the two plus the contact distance), that the energy of an elastic world drifts less
    /// than 1e-9 relative (once a simultaneous impact has been resolved as a jam, which may
    /// absorb energy, only a gain counts), and with --closed that no ball leaves the box around
    /// the solid colliders. Progress goes to standard error (a bar on a terminal, plain lines
    /// otherwise); the end prints one JSON line on standard output:
    ///
    ///   {"events":N,"collisions":C,"sensor_events":S,"time":T,"stopped":"events"|"no_events_left"|"invariant",
    ///    "wall_s":W,"events_per_s":R,"check_every":K,"checks":M,"check_wall_s":X,"worst_overlap":O,
    ///    "worst_energy_drift":D|null,"balls_escaped":E|null,"invariants_ok":true|false}
    ///
    /// Exit codes: 0 success (also when no event is left); 1 a broken invariant, a stalled
    /// clock among them (the report is printed, and one line on standard error names the
    /// invariant, the event count, the time and the bodies) or anything else; 2 bad input, as
    /// for simulate.
    ///
    /// Example: exact2d soak examples/sinai.json --events 100000000
    #[command(verbatim_doc_comment)]
    Soak(SoakArgs),
}

/// The arguments of `exact2d soak`.
#[derive(Args)]
struct SoakArgs {
    /// The scene file (JSON, scene format version 1)
    #[arg(value_name = "SCENE.json")]
    scene: PathBuf,
    /// The number of events to handle: an integer >= 1
    #[arg(long, value_name = "N", value_parser = parse_count, allow_negative_numbers = true)]
    events: u64,
    /// Check the invariants every K events (an integer >= 1); by default 64 per ball and
    /// collider, at least 1000 (the checks then took under 1% of the run on a gas of 10^4
    /// balls and on brick boards)
    #[arg(long, value_name = "K", value_parser = parse_count, allow_negative_numbers = true)]
    check_every: Option<u64>,
    /// The scene is a closed container: no ball's centre may leave the bounding box of the
    /// solid colliders
    #[arg(long)]
    closed: bool,
}

/// The arguments of `exact2d simulate`.
#[derive(Args)]
struct SimulateArgs {
    /// The scene file (JSON, scene format version 1)
    #[arg(value_name = "SCENE.json")]
    scene: PathBuf,
    /// The time to simulate to: a finite number >= 0
    #[arg(long, value_name = "T", value_parser = parse_until, allow_negative_numbers = true)]
    until: f64,
    /// Also write one JSON line per collision to this file, in time order
    ///
    /// The lines, by kind (ID: a ball's scene id; I: an index in the scene's segments or
    /// circles; the normal is a unit vector from the segment or circle towards the ball's
    /// centre, or from the first ball's centre towards the second's; J: the normal impulse
    /// applied, mass times change of normal velocity, on the second ball of a pair):
    ///
    ///   {"time":t,"kind":"ball_segment","ball":ID,"segment":I,"point":[x,y],"normal":[x,y],"impulse":J}
    ///   {"time":t,"kind":"ball_end_point","ball":ID,"segment":I,"end":"a"|"b","point":[x,y],"normal":[x,y],"impulse":J}
    ///   {"time":t,"kind":"ball_circle","ball":ID,"circle":I,"point":[x,y],"normal":[x,y],"impulse":J}
    ///   {"time":t,"kind":"ball_ball","balls":[ID,ID],"point":[x,y],"normal":[x,y],"impulse":J}
    #[arg(long, value_name = "EVENTS.jsonl", verbatim_doc_comment)]
    events: Option<PathBuf>,
    /// Also print the run's observables: the collision virial and each collider's momentum
    /// and impacts (keys "virial", "since" and "colliders", last)
    #[arg(long)]
    observables: bool,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match &cli.command {
        Command::Simulate(args) => simulate::run(
            &args.scene,
            args.until,
            args.events.as_deref(),
            args.observables,
        ),
        Command::Soak(args) => soak::run(
            &args.scene,
            &soak::SoakOptions {
                events: args.events,
                check_every: args.check_every,
                closed: args.closed,
            },
        ),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(failure) => {
            // Nothing more can be done if standard error itself fails.
            let _ = writeln!(std::io::stderr(), "{failure}");
            ExitCode::from(failure.exit_code())
        }
    }
}

/// `--until`: a finite time >= 0 (`-0` is read as 0 so the output never says `-0.0`).
fn parse_until(text: &str) -> Result<f64, String> {
    let t: f64 = text.trim().parse().map_err(|_| "not a number".to_owned())?;
    if t.is_finite() && t >= 0.0 {
        Ok(t + 0.0)
    } else {
        Err("must be a finite number >= 0".to_owned())
    }
}

/// `--events` and `--check-every` of soak: an integer >= 1.
fn parse_count(text: &str) -> Result<u64, String> {
    match text.trim().parse::<u64>() {
        Ok(0) => Err("must be at least 1".to_owned()),
        Ok(n) => Ok(n),
        Err(_) => Err("not a whole number >= 1".to_owned()),
    }
}
