//! `exact2d-bench`: the benchmark suite of exact2d, and the scenes compared with other
//! engines.
//!
//! ```text
//! exact2d-bench suite [--quick] [--only SUBSTRING]
//! exact2d-bench scenes --out DIR
//! exact2d-bench minimal [--quick] [--rounds K]
//! exact2d-bench latency
//! exact2d-bench rest [--quick]
//! ```

mod counting_alloc;
mod piles;
mod resident;
mod rest;
mod suite;

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use exact2d::scene::Scene;
use exact2d_bench::scenes;

#[global_allocator]
static ALLOCATOR: counting_alloc::CountingAlloc = counting_alloc::CountingAlloc;

/// Benchmarks of the exact2d engine.
#[derive(Parser)]
#[command(name = "exact2d-bench", version)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run the benchmark suite and print a markdown table of the results.
    Suite {
        /// Stop the hard-disk gases at 10^4 balls (instead of 10^6).
        #[arg(long)]
        quick: bool,
        /// Run only the cases whose name ("gas 0.4 1000", "brick_board 200", ...) contains
        /// this.
        #[arg(long, value_name = "SUBSTRING")]
        only: Option<String>,
    },
    /// Run the suite's gases in the engine and in a minimal, inexact hard-disk code (the
    /// floor the machine gives the leanest design), alternately, and print both rates.
    Minimal {
        /// Stop at 10^4 balls (instead of 10^6).
        #[arg(long)]
        quick: bool,
        /// Run each pair this many times and report the medians.
        #[arg(long, value_name = "K", default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=99))]
        rounds: u32,
    },
    /// Run piles, a hopper and a Galton board until every ball sleeps, and print events and
    /// wall time to rest, and how far each pile at rest is from static equilibrium.
    Rest {
        /// Smaller scenes (100-ball piles, a 300-ball hopper, a 200-ball Galton board).
        #[arg(long)]
        quick: bool,
        /// Run only the cases whose name contains this.
        #[arg(long, value_name = "SUBSTRING")]
        only: Option<String>,
        /// Give every ball and collider this Coulomb friction (the piles frictionless
        /// otherwise, as the issue first measured them).
        #[arg(long, value_name = "MU", default_value_t = 0.0, value_parser = parse_friction)]
        friction: f64,
    },
    /// Pour many seeded piles of four kinds (restitution 0.5 and 0.8, without and with pegs)
    /// and run each to rest: a line per pile and the totals, the measure of a change to how
    /// piles rest (a single pile's wall time moves by factors of five under any change of
    /// bits).
    Piles {
        /// Seeds 1 to this of each kind.
        #[arg(long, value_name = "N", default_value_t = 8, value_parser = clap::value_parser!(u64).range(1..=1000))]
        seeds: u64,
        /// Balls in each pile.
        #[arg(long, value_name = "N", default_value_t = 100, value_parser = clap::value_parser!(u64).range(1..=5000))]
        balls: u64,
        /// Give every ball and collider this Coulomb friction (frictionless otherwise).
        #[arg(long, value_name = "MU", default_value_t = 0.0, value_parser = parse_friction)]
        friction: f64,
        /// Wall seconds at most for each pile.
        #[arg(long, value_name = "SECONDS", default_value_t = 30.0, value_parser = parse_budget)]
        budget: f64,
        /// Run only the piles whose name ("100 balls, e = 0.5, pegs, seed 3") contains this.
        #[arg(long, value_name = "SUBSTRING")]
        only: Option<String>,
        /// Stop each pile at this simulated time (seconds, rounded up to a tenth) if it is
        /// not at rest by then: a fixed amount of work, for instruction counts.
        #[arg(long, value_name = "SECONDS", value_parser = parse_until)]
        until: Option<f64>,
    },
    /// Print the machine's memory latency (one dependent load) by working-set size, from
    /// 64 KB to 256 MB.
    Latency,
    /// Run one gas of `minimal`'s table in one code and print its peak resident bytes
    /// during the run, the world built (what `minimal` runs in a child process per column).
    #[command(hide = true)]
    Peak {
        /// The case's label ("periodic 0.7", ...).
        #[arg(long)]
        label: String,
        /// Its number of balls.
        #[arg(long)]
        balls: usize,
        /// Collisions to run.
        #[arg(long)]
        collisions: u64,
        /// Run the minimal code instead of the engine.
        #[arg(long)]
        minimal: bool,
    },
    /// Write the scenes compared with other engines as JSON files into DIR.
    Scenes {
        /// The directory to write to (created if missing).
        #[arg(long, value_name = "DIR")]
        out: PathBuf,
    },
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Suite { quick, only } => suite_command(quick, only.as_deref()),
        Command::Minimal { quick, rounds } => suite::run_minimal(quick, rounds),
        Command::Rest {
            quick,
            only,
            friction,
        } => rest::run(quick, only.as_deref(), friction),
        Command::Piles {
            seeds,
            balls,
            friction,
            budget,
            only,
            until,
        } => piles::run(&piles::Piles {
            balls: usize::try_from(balls).unwrap_or(usize::MAX),
            seeds,
            friction,
            budget,
            only: only.as_deref(),
            until: until.unwrap_or(f64::INFINITY),
        }),
        Command::Latency => {
            print_latency();
            Ok(())
        }
        Command::Peak {
            label,
            balls,
            collisions,
            minimal,
        } => suite::print_peak(&label, balls, collisions, minimal),
        Command::Scenes { out } => write_scenes(&out),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("exact2d-bench: {message}");
            ExitCode::FAILURE
        }
    }
}

fn suite_command(quick: bool, only: Option<&str>) -> Result<(), String> {
    let mut cases = suite::cases(quick);
    // The pool breaks, after the table (matched by `--only pool`).
    let pool = only.is_none_or(|o| "pool break 16".contains(o));
    if let Some(only) = only {
        cases.retain(|case| case.name().contains(only));
        if cases.is_empty() && pool {
            return suite::run_pool(POOL_BREAKS);
        }
        if cases.is_empty() {
            let names: Vec<String> = suite::cases(quick).iter().map(suite::Case::name).collect();
            return Err(format!(
                "no case matches --only {only:?}; the cases are: {}",
                names.join(", ")
            ));
        }
    }
    suite::run_all(&cases)?;
    if pool {
        println!();
        suite::run_pool(POOL_BREAKS)?;
    }
    Ok(())
}

/// A friction coefficient: a finite number >= 0.
fn parse_friction(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(mu) if mu >= 0.0 && mu.is_finite() => Ok(mu),
        _ => Err("must be a finite number >= 0".to_owned()),
    }
}

/// A wall budget: seconds, finite and above zero, at most a day.
fn parse_budget(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(seconds) if seconds > 0.0 && seconds <= 86_400.0 => Ok(seconds),
        _ => Err("must be a number of seconds above 0 and at most 86400".to_owned()),
    }
}

/// A simulated time to stop at: seconds, above 0 and at most a day of simulated time.
fn parse_until(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(seconds) if seconds > 0.0 && seconds <= 86_400.0 => Ok(seconds),
        _ => Err("must be a simulated time in seconds above 0 and at most 86400".to_owned()),
    }
}

/// The pool breaks the suite runs.
const POOL_BREAKS: u64 = 1_000;

/// Prints the latency table: one row per working-set size, 64 KB to 256 MB.
fn print_latency() {
    println!("| working set | ns per dependent load |\n| ---: | ---: |");
    let mut bytes = 64 << 10;
    while bytes <= 256 << 20 {
        let ns = exact2d_bench::latency::dependent_load_ns(bytes, 10_000_000);
        let size = if bytes >= 1 << 20 {
            format!("{} MB", bytes >> 20)
        } else {
            format!("{} KB", bytes >> 10)
        };
        println!("| {size} | {ns:.1} |");
        bytes *= 4;
    }
}

/// The scenes compared with other engines, with their file names.
fn comparison_scenes() -> Vec<(&'static str, Scene)> {
    vec![
        ("brick_board_200.json", scenes::brick_board(200, 1)),
        ("brick_board_1000.json", scenes::brick_board(1000, 1)),
        (
            "free_balls_in_box_1000.json",
            scenes::free_balls_in_box(1000, 1),
        ),
        (
            "free_balls_in_box_10.json",
            scenes::free_balls_in_box(10, 1),
        ),
        ("pegs_gravity_100.json", scenes::pegs_gravity(100, 1)),
    ]
}

fn write_scenes(dir: &Path) -> Result<(), String> {
    std::fs::create_dir_all(dir)
        .map_err(|e| format!("cannot create the directory {}: {e}", dir.display()))?;
    for (name, scene) in comparison_scenes() {
        let path = dir.join(name);
        let mut text = scene.to_json_string();
        text.push('\n');
        std::fs::write(&path, text).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
        println!("{}", path.display());
    }
    Ok(())
}
