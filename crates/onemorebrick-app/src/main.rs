//! `onemorebrick`: One More Brick. With no subcommand it opens the game window; `watch`
//! shows a bot playing and `replay` a saved game played again, in the window; `sim` plays a
//! game with a bot headlessly, `bench` and `bench-frame` time the rules, the engine and the
//! drawing, and `screenshot` renders one frame of a game to a PNG.
//!
//! The front end only draws the rules' state and turns input into the rules' commands:
//! input (`input`, `widgets`, `menus`) -> commands (`app`) -> rules and engine
//! (`onemorebrick`) -> state -> view (`layout`, `draw_board`, `draw_play`, `effects`, `hud`).
//! `watch` and `replay` drive the same front end from a script (`playback`, `watch`).

mod app;
mod bench;
mod bench_frame;
mod bots;
mod card;
mod draw_board;
mod draw_play;
mod effects;
mod failure;
mod help;
mod hud;
mod input;
mod layout;
mod menus;
mod palette;
mod pickups;
mod play;
mod playback;
mod screenshot;
mod sim;
mod sound;
mod storage;
mod text;
mod warning;
mod watch;
mod widgets;

use std::process::ExitCode;

use clap::{Args, Parser, Subcommand};

use crate::storage::Seeds;

/// One More Brick, on the exact2d engine. Without a subcommand, opens the game.
#[derive(Parser, Debug)]
#[command(
    name = "onemorebrick",
    version,
    about,
    args_conflicts_with_subcommands = true
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    #[command(flatten)]
    play: PlayArgs,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Open the game window (the same as no subcommand).
    Play(PlayArgs),
    /// Watch a bot play in the window, at a speed the keys change; nothing is saved.
    Watch(watch::WatchArgs),
    /// Play a saved game's commands again from its seed, in the window, to the state saved.
    Replay(watch::ReplayArgs),
    /// Play a game with a bot, headless; one line per round, then a summary.
    Sim(sim::SimArgs),
    /// Time a 100-round greedy-bot game and finish-round-now on 500-ball volleys.
    Bench(bench::BenchArgs),
    /// Time one frame with 1000 balls in flight: the physics, then the drawing (a window).
    BenchFrame(bench_frame::BenchFrameArgs),
    /// A bot plays some rounds (or a save is loaded); one frame is rendered to a PNG.
    Screenshot(screenshot::ScreenshotArgs),
}

/// Options of the game window.
#[derive(Args, Debug)]
struct PlayArgs {
    /// The seed of new games (the first, one after a damaged save, "new game"); without it
    /// each new game draws one from the system's generator. A saved game is still resumed.
    #[arg(long, value_parser = parse_seed, allow_negative_numbers = true)]
    seed: Option<u64>,
}

impl PlayArgs {
    fn seeds(&self) -> Seeds {
        self.seed.map_or(Seeds::Os, Seeds::Fixed)
    }
}

/// A game's seed on the command line: a whole number in `[0, 2^64 - 1]`.
pub fn parse_seed(text: &str) -> Result<u64, String> {
    text.trim()
        .parse::<u64>()
        .map_err(|_| format!("a seed is a whole number in [0, {}]", u64::MAX))
}

fn main() -> ExitCode {
    sound::catch_library_failures();
    let cli = Cli::parse();
    let result = match cli.command {
        None => play::run(cli.play.seeds()).map_err(failure::Failure::Message),
        Some(Command::Play(args)) => play::run(args.seeds()).map_err(failure::Failure::Message),
        Some(Command::Watch(args)) => watch::run_watch(&args),
        Some(Command::Replay(args)) => watch::run_replay(&args),
        Some(Command::Sim(args)) => sim::run(&args),
        Some(Command::Bench(args)) => bench::run(&args),
        Some(Command::BenchFrame(args)) => {
            bench_frame::run(&args).map_err(failure::Failure::Message)
        }
        Some(Command::Screenshot(args)) => {
            screenshot::run(&args).map_err(failure::Failure::Message)
        }
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) if e.is_broken_pipe() => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("onemorebrick: {e}");
            ExitCode::from(e.exit_code())
        }
    }
}
