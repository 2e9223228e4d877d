//! `onemorebrick sim`: a bot plays a game; standard output depends only on the arguments.

use std::io::{self, Write};
use std::time::Instant;

use clap::Args;
use onemorebrick::{Bot, Config, Game, GreedyBot, Phase, RandomBot, RoundReport};
use serde::Serialize;

use crate::BotName;
use crate::failure::Failure;

/// Arguments of `sim`.
#[derive(Args, Debug)]
pub struct SimArgs {
    /// The game's seed (the random bot's too).
    #[arg(long, value_parser = crate::parse_seed, allow_negative_numbers = true)]
    seed: u64,
    /// Which bot plays.
    #[arg(long, value_enum)]
    bot: BotName,
    /// Rounds to play (fewer if the game ends first).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=100_000), allow_negative_numbers = true)]
    rounds: u32,
    /// Candidate shots the greedy bot tries per round.
    #[arg(long, default_value_t = 32, value_parser = clap::value_parser!(u32).range(2..=1024), allow_negative_numbers = true)]
    candidates: u32,
    /// End with one JSON object on the last line.
    #[arg(long)]
    json: bool,
}

/// The summary printed as JSON with `--json`.
#[derive(Serialize)]
struct Summary {
    seed: u64,
    bot: &'static str,
    rounds: u32,
    level: u32,
    score: u64,
    best_score: u64,
    balls: u32,
    bricks_destroyed: u64,
    collisions: u64,
    simulated_seconds: f64,
    game_over: bool,
    hash: String,
}

/// Plays the game, prints a line per round and the summary.
pub fn run(args: &SimArgs) -> Result<(), Failure> {
    let started = Instant::now();
    let mut out = io::stdout().lock();
    let mut game = Game::new(Config::default(), args.seed)?;
    let mut bot: Box<dyn Bot> = match args.bot {
        BotName::Random => Box::new(RandomBot::new(args.seed)),
        BotName::Greedy => Box::new(GreedyBot::new(args.candidates)),
    };
    for round in 1..=args.rounds {
        if game.phase() == Phase::GameOver {
            break;
        }
        let aim = bot.choose(&game)?;
        game.shoot(aim)?;
        let report = game.finish_round()?;
        writeln!(out, "{}", round_line(round, &report, &game))?;
    }
    let summary = summarise(&game, args);
    writeln!(
        out,
        "summary: {} rounds, level {}, score {}, {} balls, {} bricks destroyed, {} collisions, {:.6} simulated seconds{}",
        summary.rounds,
        summary.level,
        summary.score,
        summary.balls,
        summary.bricks_destroyed,
        summary.collisions,
        summary.simulated_seconds,
        if summary.game_over { ", game over" } else { "" }
    )?;
    if args.json {
        let json = serde_json::to_string(&summary).expect("plain data");
        writeln!(out, "{json}")?;
    }
    out.flush()?;
    let wall = started.elapsed().as_secs_f64();
    eprintln!(
        "wall time {wall:.3} s, {:.0} collisions/s",
        summary.collisions as f64 / wall.max(1e-9)
    );
    Ok(())
}

fn round_line(round: u32, report: &RoundReport, game: &Game) -> String {
    let t = &report.tally;
    format!(
        "round {round}: level {}, balls {}, damage {}, destroyed {}, collisions {}, simulated {:.6} s, score {}{}",
        report.level,
        report.balls,
        t.damage(),
        t.bricks_destroyed,
        report.collisions,
        t.end_time,
        game.state().score(),
        if report.game_over { ", game over" } else { "" }
    )
}

fn summarise(game: &Game, args: &SimArgs) -> Summary {
    let state = game.state();
    let totals = state.totals();
    Summary {
        seed: args.seed,
        bot: match args.bot {
            BotName::Random => "random",
            BotName::Greedy => "greedy",
        },
        rounds: totals.rounds,
        level: state.level(),
        score: state.score(),
        best_score: state.best_score(),
        balls: state.balls(),
        bricks_destroyed: totals.bricks_destroyed,
        collisions: totals.collisions,
        simulated_seconds: totals.simulated_seconds,
        game_over: state.is_game_over(),
        hash: format!("{:016x}", onemorebrick::hash_game(game)),
    }
}
