//! `onemorebrick sim`: a bot plays a game; standard output depends only on the arguments.

use std::io::{self, Write};
use std::time::Instant;

use clap::Args;
use onemorebrick::{Config, Game, Phase, RoundReport};
use serde::Serialize;

use crate::bots::BotArgs;
use crate::failure::Failure;

/// Arguments of `sim`.
#[derive(Args, Debug)]
pub struct SimArgs {
    /// The game's seed (the random bot's too).
    #[arg(long, value_parser = crate::parse_seed, allow_negative_numbers = true)]
    seed: u64,
    /// The bot and its options.
    #[command(flatten)]
    bot: BotArgs,
    /// Rounds to play (fewer if the game ends first).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=100_000), allow_negative_numbers = true)]
    rounds: u32,
    /// End with one JSON object on the last line.
    #[arg(long)]
    json: bool,
}

/// The summary of a game: its last line, and the JSON object of `--json`.
#[derive(Serialize)]
pub struct Summary {
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
    let mut bot = args.bot.make(args.seed);
    for round in 1..=args.rounds {
        if game.phase() == Phase::GameOver {
            break;
        }
        let aim = bot.choose(&game)?;
        game.shoot(aim)?;
        let report = game.finish_round()?;
        writeln!(out, "{}", round_line(round, &report, &game))?;
    }
    let summary = Summary::of(&game, args.seed, args.bot.name());
    writeln!(out, "{}", summary.line())?;
    if args.json {
        writeln!(out, "{}", summary.json())?;
    }
    out.flush()?;
    let wall = started.elapsed().as_secs_f64();
    eprintln!(
        "wall time {wall:.3} s, {:.0} collisions/s",
        summary.collisions as f64 / wall.max(1e-9)
    );
    Ok(())
}

/// The line of round `round` just resolved (`report`) of `game`: the level played, and
/// the game's score after it.
pub fn round_line(round: u32, report: &RoundReport, game: &Game) -> String {
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

impl Summary {
    /// The summary of `game`, of seed `seed`, played by the bot named `bot`.
    pub fn of(game: &Game, seed: u64, bot: &'static str) -> Self {
        let state = game.state();
        let totals = state.totals();
        Summary {
            seed,
            bot,
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

    /// The summary line: rounds, the level (the next to play, or the one that ended the
    /// game), the score and the totals.
    pub fn line(&self) -> String {
        format!(
            "summary: {} rounds, level {}, score {}, {} balls, {} bricks destroyed, {} collisions, {:.6} simulated seconds{}",
            self.rounds,
            self.level,
            self.score,
            self.balls,
            self.bricks_destroyed,
            self.collisions,
            self.simulated_seconds,
            if self.game_over { ", game over" } else { "" }
        )
    }

    /// The summary as one line of JSON.
    pub fn json(&self) -> String {
        serde_json::to_string(self).expect("plain data")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use onemorebrick::{Aim, Board, Brick, Cell, GameState, Shape};

    /// The number after `key` in `line`.
    fn number_after(line: &str, key: &str) -> u64 {
        let at = line.find(key).unwrap_or_else(|| panic!("{key} in {line}")) + key.len();
        line[at..]
            .split(',')
            .next()
            .unwrap()
            .trim()
            .parse()
            .unwrap()
    }

    /// A game at level 12 whose next round ends it: a brick no ball can break sits one row
    /// above the bottom.
    fn ending_at_level_12() -> Game {
        let config = Config::default();
        let mut board = Board::new(config.columns, config.rows);
        let wall = Cell::Brick(Brick {
            shape: Shape::Square,
            hp: 9999,
        });
        board.set(3, 1, wall).unwrap();
        Game::from_state(8, GameState::custom(config, board, 12, 2, 8).unwrap())
    }

    #[test]
    fn the_level_is_one_number_in_the_round_line_the_summary_the_json_and_the_save() {
        let mut game = ending_at_level_12();
        game.shoot(Aim::new(0.4, 1.0)).unwrap();
        let report = game.finish_round().unwrap();
        let line = round_line(1, &report, &game);
        assert!(line.ends_with(", game over"), "{line}");
        let summary = Summary::of(&game, 8, "greedy");
        let json: serde_json::Value = serde_json::from_str(&summary.json()).unwrap();
        let save: serde_json::Value =
            serde_json::from_str(&onemorebrick::save::to_json(&game)).unwrap();
        let levels = [
            number_after(&line, "level "),
            number_after(&summary.line(), "level "),
            json["level"].as_u64().unwrap(),
            save["state"]["level"].as_u64().unwrap(),
            u64::from(game.state().level()),
        ];
        assert_eq!(levels, [12; 5]);
    }

    #[test]
    fn while_the_game_goes_on_the_summary_has_the_next_level() {
        let mut game = Game::new(Config::default(), 3).unwrap();
        game.shoot(Aim::new(0.2, 1.0)).unwrap();
        let report = game.finish_round().unwrap();
        let line = round_line(1, &report, &game);
        let summary = Summary::of(&game, 3, "greedy");
        assert_eq!(number_after(&line, "level "), 1);
        assert_eq!(number_after(&summary.line(), "level "), 2);
        assert!(!summary.line().contains("game over"));
    }
}
