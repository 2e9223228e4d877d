//! `onemorebrick`: One More Brick. With no subcommand it opens the game window; `watch`
//! shows a bot playing and `replay` a saved game played again, in the window; `sim` plays a
//! game with a bot headlessly, `bench` and `bench-frame` time the rules, the engine and the
//! drawing, and `screenshot` renders one frame of a game to a PNG; `icon` and `bricks`
//! serve the web build (its icons, and where the browser test looks for bricks).
//!
//! The front end only draws the rules' state and turns input into the rules' commands:
//! input (`input`, `widgets`, `menus`) -> commands (`app`) -> rules and engine
//! (`onemorebrick`) -> state -> view (`layout`, `draw_board`, `draw_play`, `effects`, `hud`).
//! `watch` and `replay` drive the same front end from a script (`playback`, `watch`).
//!
//! Built for `wasm32-unknown-unknown` (`web/build.sh`) it is the game in a web page: no
//! command line, `main` opens the game (`web`); saves go to the page's `localStorage`
//! (`storage`'s browser shelf) instead of files, through `onemorebrick-web`.

// The web build leaves out the desktop's subcommands and sound; what only they use (the
// viewers' setters, the sound probes) is dead there.
#![cfg_attr(target_arch = "wasm32", allow(dead_code))]

mod app;
#[cfg(not(target_arch = "wasm32"))]
mod bench;
mod bench_frame;
#[cfg(not(target_arch = "wasm32"))]
mod bots;
#[cfg(not(target_arch = "wasm32"))]
mod bricks;
mod card;
mod draw_board;
mod draw_play;
mod effects;
#[cfg(not(target_arch = "wasm32"))]
mod failure;
mod help;
mod hud;
#[cfg(not(target_arch = "wasm32"))]
mod icon;
mod input;
mod layout;
mod menus;
mod palette;
mod pickups;
mod play;
#[cfg(not(target_arch = "wasm32"))]
mod playback;
#[cfg(not(target_arch = "wasm32"))]
mod screenshot;
mod shelf;
#[cfg(not(target_arch = "wasm32"))]
mod shelf_files;
#[cfg(any(target_arch = "wasm32", test))]
mod shelf_keys;
#[cfg(not(target_arch = "wasm32"))]
mod sim;
mod sound;
mod storage;
mod text;
mod warning;
#[cfg(not(target_arch = "wasm32"))]
mod watch;
#[cfg(target_arch = "wasm32")]
mod web;
mod widgets;

#[cfg(not(target_arch = "wasm32"))]
use std::process::ExitCode;

#[cfg(not(target_arch = "wasm32"))]
use clap::{Args, Parser, Subcommand};

#[cfg(not(target_arch = "wasm32"))]
use crate::storage::Seeds;

#[cfg(not(target_arch = "wasm32"))]
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

#[cfg(not(target_arch = "wasm32"))]
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
    /// Render the game's icon (bricks and a ball in the palette's colours) to a PNG.
    Icon(icon::IconArgs),
    /// Print where a new game's bricks are drawn on a screen of a given size, and their
    /// colours, one JSON line each (the browser test looks for them on the canvas).
    Bricks(bricks::BricksArgs),
}

#[cfg(not(target_arch = "wasm32"))]
/// Options of the game window.
#[derive(Args, Debug)]
struct PlayArgs {
    /// The seed of new games (the first, one after a damaged save, "new game"); without it
    /// each new game draws one from the system's generator. A saved game is still resumed.
    #[arg(long, value_parser = parse_seed, allow_negative_numbers = true)]
    seed: Option<u64>,
}

#[cfg(not(target_arch = "wasm32"))]
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

#[cfg(not(target_arch = "wasm32"))]
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
        Some(Command::Icon(args)) => icon::run(&args).map_err(failure::Failure::Message),
        Some(Command::Bricks(args)) => bricks::run(&args),
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

/// In the browser: the game (or, with `?bench=frame` in the address, the frame benchmark).
#[cfg(target_arch = "wasm32")]
fn main() {
    web::main();
}
