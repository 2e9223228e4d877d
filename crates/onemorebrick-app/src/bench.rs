//! `onemorebrick bench`: wall-clock figures, printed (timings never gate a test).

use std::io::{self, Write};
use std::time::Instant;

use clap::Args;
use onemorebrick::{
    Board, Bot, Brick, Cell, Config, Corner, Game, GameState, GreedyBot, Phase, Shape,
};

use crate::failure::Failure;

/// Arguments of `bench`.
#[derive(Args, Debug)]
pub struct BenchArgs {
    /// Seed of the greedy game.
    #[arg(long, default_value_t = 1, value_parser = crate::parse_seed, allow_negative_numbers = true)]
    seed: u64,
    /// Rounds of the greedy game (it restarts after a game over).
    #[arg(long, default_value_t = 100, value_parser = clap::value_parser!(u32).range(1..=100_000), allow_negative_numbers = true)]
    rounds: u32,
    /// Candidate shots the greedy bot tries per round.
    #[arg(long, default_value_t = 32, value_parser = clap::value_parser!(u32).range(2..=1024), allow_negative_numbers = true)]
    candidates: u32,
    /// Balls in the finish-round-now volleys.
    #[arg(long, default_value_t = 500, value_parser = clap::value_parser!(u32).range(1..=100_000), allow_negative_numbers = true)]
    balls: u32,
}

/// Runs the benchmarks and prints their figures.
pub fn run(args: &BenchArgs) -> Result<(), Failure> {
    let mut out = io::stdout().lock();
    greedy_game(args, &mut out)?;
    let realistic = greedy_board(args.seed)?;
    big_volley(
        "board of a 30-round greedy game",
        realistic,
        args.balls,
        &mut out,
    )?;
    big_volley("dense board", dense_board(), args.balls, &mut out)?;
    out.flush()?;
    Ok(())
}

/// A greedy-bot game of `args.rounds` rounds, timed as a whole (the bot's trial rounds
/// included: they are most of the work).
fn greedy_game(args: &BenchArgs, out: &mut impl Write) -> Result<(), Failure> {
    let mut game = Game::new(Config::default(), args.seed)?;
    let mut bot = GreedyBot::new(args.candidates);
    let started = Instant::now();
    let mut restarts = 0;
    for _ in 0..args.rounds {
        if game.phase() == Phase::GameOver {
            game.restart()?;
            restarts += 1;
        }
        let aim = bot.choose(&game)?;
        game.shoot(aim)?;
        game.finish_round()?;
    }
    let wall = started.elapsed().as_secs_f64();
    let state = game.state();
    let in_game = state.totals().collisions;
    let all = in_game + bot.simulated_collisions();
    writeln!(
        out,
        "greedy game: seed {}, {} rounds, {} candidates, {restarts} restarts after game over; ends at level {} with {} balls",
        args.seed,
        args.rounds,
        args.candidates,
        state.level(),
        state.balls()
    )?;
    writeln!(
        out,
        "  wall {wall:.3} s; collisions {in_game} in the game, {all} with the bot's trials: {:.0} collisions/s",
        all as f64 / wall
    )?;
    Ok(())
}

/// The board a greedy game (8 candidates) reaches after 30 rounds, at its level.
fn greedy_board(seed: u64) -> Result<(Board, u32), Failure> {
    let mut game = Game::new(Config::default(), seed)?;
    let mut bot = GreedyBot::new(8);
    for _ in 0..30 {
        if game.phase() == Phase::GameOver {
            game.restart()?;
        }
        let aim = bot.choose(&game)?;
        game.shoot(aim)?;
        game.finish_round()?;
    }
    Ok((game.state().board().clone(), game.state().level()))
}

/// Rows 2 to 8 full: squares and triangles of 200 hit points, obstacles and gaps.
fn dense_board() -> (Board, u32) {
    let config = Config::default();
    let mut board = Board::new(config.columns, config.rows);
    for row in 2..config.rows {
        for column in 0..config.columns {
            let cell = match (row * 3 + column * 2) % 5 {
                0 => Cell::Obstacle,
                1 => Cell::Empty,
                2 => Cell::Brick(Brick {
                    shape: Shape::Triangle(Corner::ALL[(row % 4) as usize]),
                    hp: 200,
                }),
                _ => Cell::Brick(Brick {
                    shape: Shape::Square,
                    hp: 200,
                }),
            };
            board.set(column, row, cell).expect("inside the board");
        }
    }
    (board, 100)
}

/// A volley of `balls` balls on `board`, aimed where the greedy bot (8 candidates) would aim,
/// finished at once and timed (the bot's choice is not timed).
fn big_volley(
    name: &str,
    (board, level): (Board, u32),
    balls: u32,
    out: &mut impl Write,
) -> Result<(), Failure> {
    let (bricks, hp) = (board.bricks().count(), board.total_hp());
    let state = GameState::custom(Config::default(), board, level, balls, 7)?;
    let mut game = Game::from_state(7, state);
    let aim = GreedyBot::new(8).choose(&game)?;
    game.shoot(aim)?;
    let started = Instant::now();
    let report = game.finish_round()?;
    let wall = started.elapsed().as_secs_f64();
    writeln!(
        out,
        "finish-round-now, {name}: {balls} balls, {bricks} bricks of {hp} hit points in all"
    )?;
    writeln!(
        out,
        "  wall {wall:.4} s; {} collisions ({:.0}/s), {} damage, {} bricks destroyed, {:.3} simulated s",
        report.collisions,
        report.collisions as f64 / wall,
        report.tally.damage(),
        report.tally.bricks_destroyed,
        report.tally.end_time
    )?;
    Ok(())
}
