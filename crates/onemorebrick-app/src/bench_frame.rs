//! `onemorebrick bench-frame`: the cost of one frame with 1000 balls in flight, the physics
//! (the engine advancing the volley by 1/60 s, and reading the balls back) and the drawing.
//! The web build runs the same scene with `?bench=frame` and publishes the figures as
//! `window.onemorebrick.bench` (`web/test/bench.mjs` prints them).

#[cfg(not(target_arch = "wasm32"))]
use clap::Args;
use macroquad::window::next_frame;
use onemorebrick::{Aim, Board, Brick, Cell, Config, Game, GameError, GameState, Shape};

use crate::app::App;

/// One frame of simulated time.
const FRAME: f64 = 1.0 / 60.0;
/// Balls launched by the benchmark's volley.
const BALLS: u32 = 1000;
/// Frames timed in the browser (the desktop's default).
#[cfg(target_arch = "wasm32")]
const BROWSER_FRAMES: u32 = 60;

/// Arguments of `onemorebrick bench-frame`.
#[cfg(not(target_arch = "wasm32"))]
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

/// Mean and worst of some durations in milliseconds.
fn summary(times: &[f64]) -> (f64, f64) {
    let mean = times.iter().sum::<f64>() / times.len().max(1) as f64;
    let worst = times.iter().copied().fold(0.0, f64::max);
    (mean, worst)
}

/// The physics of up to `frames` frames timed by `now` (a clock in milliseconds): each
/// frame's time, and the balls in flight on average.
fn time_physics(frames: u32, now: impl Fn() -> f64) -> Result<(Vec<f64>, f64), String> {
    let mut game = volley().map_err(|e| e.to_string())?;
    let mut times = Vec::new();
    let mut in_flight = 0usize;
    for _ in 0..frames {
        let start = now();
        let until = game.volley_time().unwrap_or(0.0) + FRAME;
        if game.advance_to(until).map_err(|e| e.to_string())?.is_some() {
            break;
        }
        in_flight += game.balls().len();
        times.push(now() - start);
    }
    let balls = in_flight as f64 / times.len().max(1) as f64;
    Ok((times, balls))
}

/// The drawing's figures: frames, balls on average, building the frame (mean, worst) and
/// the whole frame with rendering and present (mean, worst), in milliseconds.
struct Drawing {
    frames: usize,
    balls: f64,
    build: (f64, f64),
    whole: (f64, f64),
}

/// Draws `frames` frames of the volley, timed by `now` (milliseconds).
async fn time_drawing(mut app: App, frames: u32, now: impl Fn() -> f64) -> Drawing {
    let mut draw = Vec::new();
    let mut total = Vec::new();
    let mut balls = 0;
    for _ in 0..frames {
        let start = now();
        app.tick(FRAME as f32);
        let drawn = now();
        let layout = app.layout();
        app.draw(&layout);
        balls += app.balls_in_flight();
        draw.push(now() - drawn);
        next_frame().await;
        total.push(now() - start);
    }
    Drawing {
        frames: draw.len(),
        balls: balls as f64 / f64::from(frames.max(1)),
        build: summary(&draw),
        whole: summary(&total),
    }
}

/// Milliseconds on the process's clock.
#[cfg(not(target_arch = "wasm32"))]
fn clock() -> impl Fn() -> f64 {
    let origin = std::time::Instant::now();
    move || origin.elapsed().as_secs_f64() * 1e3
}

/// Times the physics headlessly, then (unless `--no-draw`) the drawing in a window.
#[cfg(not(target_arch = "wasm32"))]
pub fn run(args: &BenchFrameArgs) -> Result<(), String> {
    let frames = args.frames;
    let (times, balls) = time_physics(frames, clock())?;
    let (mean, worst) = summary(&times);
    println!(
        "physics: {} frames of 1/60 s, {balls:.0} balls in flight on average: mean {mean:.3} ms, worst {worst:.3} ms per frame",
        times.len()
    );
    if !args.no_draw {
        crate::play::check_display()?;
        let game = volley().map_err(|e| e.to_string())?;
        let conf = crate::play::conf("One More Brick bench", 540, 860, false);
        macroquad::Window::from_config(conf, async move {
            let app = App::new(game, None, 0, Vec::new());
            let d = time_drawing(app, frames, clock()).await;
            println!(
                "drawing: {} frames, {:.0} balls on average: building the frame mean {:.3} ms (worst {:.3}); whole frame with rendering and present mean {:.3} ms (worst {:.3})",
                d.frames, d.balls, d.build.0, d.build.1, d.whole.0, d.whole.1,
            );
            std::process::exit(0);
        });
    }
    Ok(())
}

/// The benchmark in the page (`?bench=frame`): the physics, then the drawing in the page's
/// canvas (at the device's pixel ratio), published as `window.onemorebrick.bench` (or
/// `{"error": ...}`).
#[cfg(target_arch = "wasm32")]
pub fn run_in_browser() {
    let conf = crate::play::conf("One More Brick bench", 390, 844, true);
    macroquad::Window::from_config(conf, async move {
        let published = match bench_in_browser().await {
            Ok(figures) => figures,
            Err(e) => serde_json::json!({ "error": e }),
        };
        onemorebrick_web::publish("bench", &published.to_string());
        loop {
            next_frame().await;
        }
    });
}

#[cfg(target_arch = "wasm32")]
async fn bench_in_browser() -> Result<serde_json::Value, String> {
    let (times, balls) = time_physics(BROWSER_FRAMES, onemorebrick_web::now_ms)?;
    let (mean, worst) = summary(&times);
    let game = volley().map_err(|e| e.to_string())?;
    let app = App::new(game, None, 0, Vec::new());
    let d = time_drawing(app, BROWSER_FRAMES, onemorebrick_web::now_ms).await;
    Ok(serde_json::json!({
        "physics": { "frames": times.len(), "balls": balls, "mean_ms": mean, "worst_ms": worst },
        "drawing": {
            "frames": d.frames, "balls": d.balls,
            "build_mean_ms": d.build.0, "build_worst_ms": d.build.1,
            "frame_mean_ms": d.whole.0, "frame_worst_ms": d.whole.1,
        },
        "screen": [
            macroquad::window::screen_width(),
            macroquad::window::screen_height(),
            macroquad::window::screen_dpi_scale(),
        ],
    }))
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
