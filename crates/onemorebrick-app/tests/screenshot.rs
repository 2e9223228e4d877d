//! `onemorebrick screenshot` renders a real frame of the board: run under `xvfb-run` (a
//! virtual X server), the PNG is decoded and checked against the game the bot played: brick
//! colours where the bricks are, the board's colour where cells are empty.
//!
//! Without `xvfb-run` the rendering test is skipped with a message, unless `CI` is set: CI
//! installs it (`.ci/run`) and the test must run there.

mod common;

use std::path::Path;
use std::process::Command;

use common::{
    BIN, board_rect, bot_game, custom_save, decode, display_available, only_wrote_line,
    screenshot_ok, temp_dir,
};
use onemorebrick::{Bot, Brick, Cell, Corner, Game, GreedyBot, Shape, save_game};

fn check_board_pixels(png: &Path, game: &Game) {
    let (pixels, width, height) = decode(png);
    assert_eq!((width, height), (540, 860));
    let [bx, by, bw, _] = board_rect(png);
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
                let [r, g, bl] = pixel(o.x + 0.1, o.y + 0.9);
                let (max, min) = (r.max(g).max(bl), r.min(g).min(bl));
                assert!(
                    max > 120 && max - min > 80,
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
    only_wrote_line(&stdout, &out, 540, 860);
    check_board_pixels(&out, &bot_game(7, 12));
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
    only_wrote_line(&stdout, &out, 1000, 500);
    let [x, y, w, h] = board_rect(&out);
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
    screenshot_ok(&[
        "--state",
        save.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    check_board_pixels(&out, &game);
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
    screenshot_ok(&[
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
    let [bx, by, bw, _] = board_rect(&out);
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

/// A decoded frame and where the board is in it.
struct Frame {
    pixels: Vec<u8>,
    width: usize,
    board: [f32; 4],
    rows: u32,
}

impl Frame {
    fn load(png: &Path, rows: u32) -> Self {
        let (pixels, width, _) = decode(png);
        Frame {
            pixels,
            width: width as usize,
            board: board_rect(png),
            rows,
        }
    }

    fn cell(&self) -> f32 {
        self.board[2] / 7.0
    }

    fn at(&self, x: usize, y: usize) -> [u8; 3] {
        let i = (y * self.width + x) * 4;
        [self.pixels[i], self.pixels[i + 1], self.pixels[i + 2]]
    }

    /// The pixel rectangle (x0, y0, x1, y1) of the board cell at `column`, `row`, with
    /// `inset` of a cell taken off each side.
    fn cell_rect(&self, column: u32, row: u32, inset: f32) -> (usize, usize, usize, usize) {
        let c = self.cell();
        let x = self.board[0] + column as f32 * c;
        let y = self.board[1] + (self.rows - 1 - row) as f32 * c;
        let k = inset * c;
        (
            (x + k).ceil() as usize,
            (y + k).ceil() as usize,
            (x + c - k).floor() as usize,
            (y + c - k).floor() as usize,
        )
    }
}

/// The white of the numbers (`onemorebrick_look::palette::HP_TEXT`).
const WHITE: [u8; 3] = [250, 250, 255];

fn is_number_white(p: [u8; 3]) -> bool {
    p.iter().zip(WHITE).all(|(a, b)| a.abs_diff(b) <= 12)
}

/// Where `p` lies on the line from `from` to `to`: the share of the way (0 at `from`) and the
/// distance off the line (in 0..=255 units).
fn along(p: [u8; 3], from: [u8; 3], to: [u8; 3]) -> (f32, f32) {
    let f = |c: [u8; 3]| c.map(f32::from);
    let (p, a, b) = (f(p), f(from), f(to));
    let d: Vec<f32> = (0..3).map(|k| b[k] - a[k]).collect();
    let len2: f32 = d.iter().map(|x| x * x).sum();
    let t = (0..3).map(|k| (p[k] - a[k]) * d[k]).sum::<f32>() / len2;
    let off = (0..3)
        .map(|k| (p[k] - (a[k] + t * d[k])).powi(2))
        .sum::<f32>()
        .sqrt();
    (t, off)
}

fn square(hp: u32) -> Brick {
    Brick {
        shape: Shape::Square,
        hp,
    }
}

/// A level-300 board: one-, two- and three-digit numbers, four digits, the compact form and
/// a triangle, all in the top rows (the aim preview stays below them).
fn numbers_board() -> Vec<(u32, u32, Brick)> {
    vec![
        (0, 8, square(7)),
        (1, 8, square(42)),
        (2, 8, square(300)),
        (3, 8, square(888)),
        (4, 8, square(600)),
        (5, 8, square(9999)),
        (6, 8, square(123_456)),
        (
            0,
            7,
            Brick {
                shape: Shape::Triangle(Corner::TopLeft),
                hp: 77,
            },
        ),
        (6, 7, square(150)),
    ]
}

#[test]
fn hit_points_fill_half_a_cell_and_their_edges_are_anti_aliased() {
    if !display_available() {
        return;
    }
    let dir = temp_dir("numbers");
    let save = dir.join("game.json");
    let bricks = numbers_board();
    let game = custom_save(&save, 300, &bricks, 0, 0);
    let out = dir.join("numbers.png");
    let stdout = screenshot_ok(&[
        "--state",
        save.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    only_wrote_line(&stdout, &out, 540, 860);
    let frame = Frame::load(&out, game.board().rows());
    let cell = frame.cell();
    for (column, row, brick) in &bricks {
        if brick.shape != Shape::Square {
            continue;
        }
        // The brick's own colour, in its corner; the number's pixels, in the middle.
        let (x0, y0, x1, y1) = frame.cell_rect(*column, *row, 0.06);
        let fill = frame.at(x0 + 1, y0 + 1);
        let (mut top, mut bottom, mut edges, mut whites) = (usize::MAX, 0, 0, 0);
        for y in y0..y1 {
            for x in x0..x1 {
                let p = frame.at(x, y);
                if is_number_white(p) {
                    whites += 1;
                    top = top.min(y);
                    bottom = bottom.max(y);
                }
                let (t, off) = along(p, fill, WHITE);
                if (0.15..=0.85).contains(&t) && off < 20.0 {
                    edges += 1;
                }
            }
        }
        assert!(bottom >= top, "hp {}: no white number pixels", brick.hp);
        let height = (bottom - top + 1) as f32;
        eprintln!(
            "hp {}: number {height} px high in a {cell} px cell, {edges} edge pixels, {whites} white",
            brick.hp
        );
        if brick.hp < 1000 {
            assert!(
                height >= 0.5 * cell,
                "hp {}: the number is {height} px high, under half of the {cell} px cell",
                brick.hp
            );
        }
        assert!(
            height <= 0.62 * cell,
            "hp {}: {height} px overflows",
            brick.hp
        );
        // Anti-aliased: many pixels between the brick's colour and the white, not just the
        // two (a pixel font's edges are hard).
        assert!(
            edges >= 12,
            "hp {}: only {edges} pixels between {fill:?} and white",
            brick.hp
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The runs of columns of the HUD band (the strip above the board) that hold anything but
/// the background, as (first, last) pixel columns, merged across gaps under `join` pixels
/// (the spaces between letters).
fn hud_runs(frame: &Frame, join: usize) -> Vec<(usize, usize)> {
    let [bx, by, bw, _] = frame.board;
    let hud_h = frame.cell() * 1.2;
    let background = [18u8, 20, 31];
    let (y0, y1) = ((by - hud_h).ceil() as usize, by.floor() as usize - 1);
    let mut runs: Vec<(usize, usize)> = Vec::new();
    for x in bx.ceil() as usize..(bx + bw).floor() as usize {
        let ink = (y0..y1).any(|y| {
            let p = frame.at(x, y);
            p.iter()
                .zip(background)
                .map(|(a, b)| a.abs_diff(b) as u32)
                .sum::<u32>()
                > 30
        });
        if !ink {
            continue;
        }
        match runs.last_mut() {
            Some(last) if x - last.1 <= join => last.1 = x,
            _ => runs.push((x, x)),
        }
    }
    runs
}

#[test]
fn big_scores_and_best_scores_stay_apart_in_the_hud() {
    if !display_available() {
        return;
    }
    let dir = temp_dir("hud");
    for (level, score, best) in [
        (12, 12_345, 9_999_999),
        (345, 123_456, 9_999_999),
        (99_999, 9_876_543_210, 98_765_432_109),
        (3, 0, 0),
    ] {
        let save = dir.join("game.json");
        let game = custom_save(&save, level, &[(3, 8, square(5))], score, best);
        let out = dir.join(format!("hud-{score}.png"));
        screenshot_ok(&[
            "--state",
            save.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        let frame = Frame::load(&out, game.board().rows());
        // Letters are closer than a fifth of the band's height (even a "1" and its
        // neighbour at the score's size); the slots are kept further apart.
        let join = (frame.cell() * 1.2 * 0.2) as usize;
        let runs = hud_runs(&frame, join);
        assert_eq!(
            runs.len(),
            4,
            "score {score}, best {best}: level, score, best and pause should be four runs, not {runs:?}"
        );
        for pair in runs.windows(2) {
            assert!(pair[1].0 - pair[0].1 > join, "score {score}: {runs:?}");
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
