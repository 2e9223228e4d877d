//! `onemorebrick`: One More Brick. With no subcommand it opens the game window; `sim` plays
//! a game with a bot headlessly, `bench` and `bench-frame` time the rules, the engine and the
//! drawing, and `screenshot` renders one frame of a game to a PNG.
//!
//! The front end only draws the rules' state and turns input into the rules' commands:
//! input (`input`, `widgets`, `menus`) -> commands (`app`) -> rules and engine
//! (`onemorebrick`) -> state -> view (`layout`, `draw_board`, `draw_play`, `effects`, `hud`).

mod app;
mod bench;
mod bench_frame;
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
mod screenshot;
mod sim;
mod sound;
mod storage;
mod text;
mod warning;
mod widgets;

use std::process::ExitCode;

use clap::{Parser, Subcommand, ValueEnum};

/// One More Brick, on the exact2d engine. Without a subcommand, opens the game.
#[derive(Parser, Debug)]
#[command(name = "onemorebrick", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Open the game window (the same as no subcommand).
    Play,
    /// Play a game with a bot, headless; one line per round, then a summary.
    Sim(sim::SimArgs),
    /// Time a 100-round greedy-bot game and finish-round-now on 500-ball volleys.
    Bench(bench::BenchArgs),
    /// Time one frame with 1000 balls in flight: the physics, then the drawing (a window).
    BenchFrame(bench_frame::BenchFrameArgs),
    /// A bot plays some rounds (or a save is loaded); one frame is rendered to a PNG.
    Screenshot(screenshot::ScreenshotArgs),
}

/// Which bot plays.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum BotName {
    /// Random directions (its own generator seeded from --seed).
    Random,
    /// Tries a fan of shots with the exact engine and takes the best.
    Greedy,
}

/// A game's seed on the command line: a whole number in `[0, 2^64 - 1]`.
pub fn parse_seed(text: &str) -> Result<u64, String> {
    text.trim()
        .parse::<u64>()
        .map_err(|_| format!("a seed is a whole number in [0, {}]", u64::MAX))
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        None | Some(Command::Play) => play::run().map_err(failure::Failure::Message),
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
            ExitCode::FAILURE
        }
    }
}
