//! `onemorebrick screenshot` renders a real frame of the board: run under `xvfb-run` (a
//! virtual X server), the PNG is decoded and checked against the game the bot played: brick
//! colours where the bricks are, the board's colour where cells are empty.
//!
//! Without `xvfb-run` the rendering test is skipped with a message, unless `CI` is set: CI
//! installs it (`.ci/run`) and the test must run there.

mod common;

use std::path::Path;
use std::process::Command;

use common::{BIN, board_rect, bot_game, decode, display_available, screenshot_ok, temp_dir};
use onemorebrick::{Bot, Cell, Game, GreedyBot, Shape, save_game};

fn check_board_pixels(png: &Path, stdout: &str, game: &Game) {
    let (pixels, width, height) = decode(png);
    assert_eq!((width, height), (540, 860));
    let [bx, by, bw, _] = board_rect(stdout);
    let board = game.board();
    let cell = bw / board.columns() as f32;
    let pixel = |x: f64, y: f64| {
        let px = (bx + x as f32 * cell) as usize;
        let py = (by + (board.rows() as f32 - y as f32) * cell) as usize;
        let i = (py * width as usize + px) * 4;
        [pixels[i], pixels[i + 1], pixels[i + 2]]
    };
    let (mut squares, mut empty, mut empty_ok) = (0, 0, 0);
    for (i, c) in board.cells().iter().enumerate() {
        let o = board.origin(i);
        match c {
            Cell::Brick(b) if b.shape == Shape::Square => {
                // Near the top-left corner, clear of the number in the middle.
                let [r, g, bl] = pixel(o.x + 0.2, o.y + 0.8);
                let (max, min) = (r.max(g).max(bl), r.min(g).min(bl));
                assert!(
                    max > 150 && max - min > 80,
                    "cell {i}: {:?} is not a brick colour",
                    [r, g, bl]
                );
                squares += 1;
            }
            Cell::Empty => {
                empty += 1;
                let p = pixel(o.x + 0.5, o.y + 0.5);
                let board_colour = [28, 31, 46];
                if p.iter().zip(board_colour).all(|(a, b)| a.abs_diff(b) < 16) {
                    empty_ok += 1;
                }
            }
            _ => {}
        }
    }
    assert!(squares > 0, "the test needs a board with square bricks");
    assert!(
        empty_ok * 10 >= empty * 8,
        "{empty_ok} of {empty} empty cells look empty"
    );
    let mut colours: Vec<[u8; 4]> = pixels
        .chunks_exact(4)
        .map(|p| [p[0], p[1], p[2], p[3]])
        .collect();
    colours.sort_unstable();
    colours.dedup();
    assert!(
        colours.len() > 50,
        "only {} colours: a blank frame",
        colours.len()
    );
}

#[test]
fn a_screenshot_shows_the_bots_board() {
    if !display_available() {
        return;
    }
    let dir = temp_dir("bot");
    let out = dir.join("shot.png");
    let stdout = screenshot_ok(&[
        "--seed",
        "7",
        "--rounds",
        "12",
        "--out",
        out.to_str().unwrap(),
    ]);
    check_board_pixels(&out, &stdout, &bot_game(7, 12));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_board_keeps_its_aspect_ratio_in_a_wide_window() {
    if !display_available() {
        return;
    }
    let dir = temp_dir("wide");
    let out = dir.join("wide.png");
    let path = out.to_str().unwrap();
    let stdout = screenshot_ok(&[
        "--rounds", "2", "--out", path, "--width", "1000", "--height", "500",
    ]);
    let [x, y, w, h] = board_rect(&stdout);
    assert!((w / h - 7.0 / 9.0).abs() < 0.01, "{w} x {h}");
    assert!(x > 0.0 && y > 0.0 && x + w < 1000.0 && y + h < 500.0);
    let (_, width, height) = decode(&out);
    assert_eq!((width, height), (1000, 500));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_screenshot_of_a_saved_game_shows_that_game() {
    if !display_available() {
        return;
    }
    let dir = temp_dir("state");
    let game = bot_game(3, 9);
    let save = dir.join("game.json");
    save_game(&game, &save).unwrap();
    let out = dir.join("shot.png");
    let stdout = screenshot_ok(&[
        "--state",
        save.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    check_board_pixels(&out, &stdout, &game);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bad_input_is_a_clear_error_before_any_window_opens() {
    let dir = temp_dir("bad");
    let missing = dir.join("missing.json");
    let damaged = dir.join("damaged.json");
    std::fs::write(&damaged, "{").unwrap();
    for state in [&missing, &damaged] {
        let out = Command::new(BIN)
            .args([
                "screenshot",
                "--out",
                "x.png",
                "--state",
                state.to_str().unwrap(),
            ])
            .env_remove("DISPLAY")
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{stderr}");
        assert!(stderr.contains(state.to_str().unwrap()), "{stderr}");
        assert!(!stderr.contains("panicked"), "{stderr}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[cfg(target_os = "linux")]
#[test]
fn without_a_display_the_window_commands_say_so() {
    let dir = temp_dir("nodisplay");
    let out = dir.join("x.png");
    for args in [
        vec![
            "screenshot",
            "--rounds",
            "1",
            "--out",
            out.to_str().unwrap(),
        ],
        vec![],
    ] {
        let run = Command::new(BIN)
            .args(&args)
            .env_remove("DISPLAY")
            .env_remove("WAYLAND_DISPLAY")
            .env("HOME", &dir)
            .env("XDG_DATA_HOME", &dir)
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&run.stderr);
        assert_eq!(run.status.code(), Some(1), "{args:?}: {stderr}");
        assert!(stderr.contains("no X display"), "{stderr}");
        assert!(!out.exists());
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_volley_screenshot_draws_each_ball_where_the_engine_has_it() {
    if !display_available() {
        return;
    }
    let dir = temp_dir("volley");
    let out = dir.join("volley.png");
    let path = out.to_str().unwrap();
    let stdout = screenshot_ok(&[
        "--seed", "7", "--rounds", "12", "--volley", "0.5", "--out", path,
    ]);
    // The same volley, advanced by the same 30 frames of 1/60 s (as f32, as the game does).
    let mut game = bot_game(7, 12);
    game.shoot(GreedyBot::new(common::CANDIDATES).choose(&game).unwrap())
        .unwrap();
    for _ in 0..30 {
        let now = game.volley_time().unwrap();
        game.advance_to(now + f64::from(1.0f32 / 60.0)).unwrap();
    }
    let balls = game.balls();
    assert!(balls.len() >= 3, "{} balls", balls.len());
    let (pixels, width, _) = decode(&out);
    let [bx, by, bw, _] = board_rect(&stdout);
    let cell = bw / game.board().columns() as f32;
    for ball in &balls {
        let px = (bx + ball.position.x as f32 * cell).round() as usize;
        let py =
            (by + (game.board().rows() as f32 - ball.position.y as f32) * cell).round() as usize;
        let i = (py * width as usize + px) * 4;
        let p = &pixels[i..i + 3];
        assert!(
            p.iter().all(|c| *c > 200),
            "ball {} at {px},{py}: {p:?}",
            ball.id
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
