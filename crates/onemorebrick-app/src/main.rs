//! `onemorebrick`: the One More Brick command. For now headless: `sim` plays a game with a
//! bot, `bench` times the rules and the engine. (The window comes with the front end.)

mod bench;
mod failure;
mod sim;

use std::process::ExitCode;

use clap::{Parser, Subcommand, ValueEnum};

/// One More Brick, on the exact2d engine.
#[derive(Parser, Debug)]
#[command(name = "onemorebrick", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Play a game with a bot, headless; one line per round, then a summary.
    Sim(sim::SimArgs),
    /// Time a 100-round greedy-bot game and finish-round-now on 500-ball volleys.
    Bench(bench::BenchArgs),
}

/// Which bot plays.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum BotName {
    /// Random directions (its own generator seeded from --seed).
    Random,
    /// Tries a fan of shots with the exact engine and takes the best.
    Greedy,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Sim(args) => sim::run(&args),
        Command::Bench(args) => bench::run(&args),
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
