//! `onemorebrick bench-frame`: the cost of one frame with 1000 balls in flight, the physics
//! (the engine advancing the volley by 1/60 s, and reading the balls back) and the drawing.

use std::time::{Duration, Instant};

use clap::Args;
use macroquad::window::next_frame;
use onemorebrick::{Aim, Board, Brick, Cell, Config, Game, GameError, GameState, Shape};

use crate::app::App;

/// One frame of simulated time.
const FRAME: f64 = 1.0 / 60.0;
/// Balls launched by the benchmark's volley.
const BALLS: u32 = 1000;

/// Arguments of `onemorebrick bench-frame`.
#[derive(Args, Debug)]
pub struct BenchFrameArgs {
    /// Frames timed (1 to 10000).
    #[arg(long, default_value_t = 60, value_parser = clap::value_parser!(u32).range(1..=10_000), allow_negative_numbers = true)]
    pub frames: u32,
    /// Time the physics only (no window needed).
    #[arg(long)]
    pub no_draw: bool,
}

/// A volley of 1000 balls, launched close together (0.6 s for all of them) at a board whose
/// two top rows are bricks too hard to break, with obstacles in between; the clock is
/// moved to the moment the last ball leaves, when all of them are in flight.
pub fn volley() -> Result<Game, GameError> {
    let config = Config {
        spacing_diameters: 0.02,
        ..Config::default()
    };
    let mut board = Board::new(config.columns, config.rows);
    for column in 0..config.columns {
        for row in [config.rows - 1, config.rows - 2] {
            let brick = Brick {
                shape: Shape::Square,
                hp: 9999,
            };
            board.set(column, row, Cell::Brick(brick))?;
        }
    }
    for column in [1, 3, 5] {
        board.set(column, 4, Cell::Obstacle)?;
    }
    let launch = config.launch_interval() * f64::from(BALLS);
    let state = GameState::custom(config, board, 1, BALLS, 1)?;
    let mut game = Game::from_state(1, state);
    game.shoot(Aim::new(0.3, 1.0))?;
    game.advance_to(launch)?;
    Ok(game)
}

/// Mean and worst of some durations, in milliseconds.
fn summary(times: &[Duration]) -> (f64, f64) {
    let ms = |d: &Duration| d.as_secs_f64() * 1e3;
    let mean = times.iter().map(ms).sum::<f64>() / times.len().max(1) as f64;
    let worst = times.iter().map(ms).fold(0.0, f64::max);
    (mean, worst)
}

/// Times the physics headlessly, then (unless `--no-draw`) the drawing in a window.
pub fn run(args: &BenchFrameArgs) -> Result<(), String> {
    let frames = args.frames;
    let mut game = volley().map_err(|e| e.to_string())?;
    let mut times = Vec::new();
    let mut in_flight = 0usize;
    for _ in 0..frames {
        let start = Instant::now();
        let until = game.volley_time().unwrap_or(0.0) + FRAME;
        if game.advance_to(until).map_err(|e| e.to_string())?.is_some() {
            break;
        }
        in_flight += game.balls().len();
        times.push(start.elapsed());
    }
    let (mean, worst) = summary(&times);
    let balls = in_flight as f64 / times.len().max(1) as f64;
    println!(
        "physics: {} frames of 1/60 s, {balls:.0} balls in flight on average: mean {mean:.3} ms, worst {worst:.3} ms per frame",
        times.len()
    );
    if !args.no_draw {
        crate::play::check_display()?;
        let game = volley().map_err(|e| e.to_string())?;
        let conf = crate::play::conf("One More Brick bench", 540, 860, false);
        macroquad::Window::from_config(
            conf,
            draw_frames(App::new(game, None, 0, Vec::new()), frames),
        );
    }
    Ok(())
}

async fn draw_frames(mut app: App, frames: u32) {
    let mut draw = Vec::new();
    let mut total = Vec::new();
    let mut balls = 0;
    for _ in 0..frames {
        let start = Instant::now();
        app.tick(FRAME as f32);
        let drawn = Instant::now();
        let layout = app.layout();
        app.draw(&layout);
        balls += app.balls_in_flight();
        draw.push(drawn.elapsed());
        next_frame().await;
        total.push(start.elapsed());
    }
    let (mean, worst) = summary(&draw);
    let (frame_mean, frame_worst) = summary(&total);
    println!(
        "drawing: {} frames, {:.0} balls on average: building the frame mean {mean:.3} ms (worst {worst:.3}); whole frame with rendering and present mean {frame_mean:.3} ms (worst {frame_worst:.3})",
        draw.len(),
        balls as f64 / f64::from(frames.max(1)),
    );
    std::process::exit(0);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_benchmark_volley_has_1000_balls_in_flight() {
        let game = volley().unwrap();
        assert_eq!(game.balls_waiting(), 0);
        assert!(game.balls().len() >= 990, "{}", game.balls().len());
    }
}
