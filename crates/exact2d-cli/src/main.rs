//! `exact2d`: the command-line tool of the exact2d engine.
//!
//! `exact2d simulate SCENE.json --until T [--events EVENTS.jsonl]` runs a scene file (format
//! version 1, see `docs/scene-format.md`) from time 0 to `T` and prints the balls' states at
//! exactly `T` as one JSON object. Exit codes: 0 success, 2 bad input (one line on standard
//! error naming the file and the item), 1 anything else.

mod failure;
mod output;
mod simulate;

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
    /// writing files excluded. Every number reads back to the same f64.
    ///
    /// Exit codes: 0 success; 2 bad input (an invalid scene or argument, with one line on
    /// standard error naming the file and the item); 1 anything else (such as an unreadable
    /// file), with a message.
    ///
    /// Example: exact2d simulate examples/sinai.json --until 10 --events events.jsonl
    #[command(verbatim_doc_comment)]
    Simulate(SimulateArgs),
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
    /// centre, or from the first ball's centre towards the second's):
    ///
    ///   {"time":t,"kind":"ball_segment","ball":ID,"segment":I,"point":[x,y],"normal":[x,y]}
    ///   {"time":t,"kind":"ball_end_point","ball":ID,"segment":I,"end":"a"|"b","point":[x,y],"normal":[x,y]}
    ///   {"time":t,"kind":"ball_circle","ball":ID,"circle":I,"point":[x,y],"normal":[x,y]}
    ///   {"time":t,"kind":"ball_ball","balls":[ID,ID],"point":[x,y],"normal":[x,y]}
    #[arg(long, value_name = "EVENTS.jsonl", verbatim_doc_comment)]
    events: Option<PathBuf>,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match &cli.command {
        Command::Simulate(args) => simulate::run(&args.scene, args.until, args.events.as_deref()),
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
