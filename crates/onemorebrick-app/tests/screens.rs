//! The screens over the board, rendered by `onemorebrick screenshot --view` under `xvfb-run`
//! and checked in the decoded PNG: the cards are opaque (no brick colour inside them), a new
//! best is celebrated, the warning marks bricks one step from the bottom and only then, and
//! the help screen shows every pick-up's icon in its own row. The screenshot names where
//! the board, the card and the help's rows are in its `tEXt` chunks.
//!
//! Skipped with a message without `xvfb-run`, unless `CI` is set.

mod common;

use std::path::{Path, PathBuf};
use std::process::Command;

use common::{BIN, decode, display_available, region, screenshot_ok, temp_dir};
use onemorebrick::{
    Aim, Board, Brick, Cell, Config, Game, GameState, Phase, PickupKind, Shape, save_game,
};

/// An RGB colour of 8-bit channels.
type Rgb = [u8; 3];

/// The card's fill, the celebration's gold and the warning's red, as `card.rs` and
/// `warning.rs` define them (0.15, 0.16, 0.23; 1.0, 0.82, 0.28; 1.0, 0.12, 0.12).
const FILL: Rgb = [38, 41, 59];
const GOLD: Rgb = [255, 209, 71];
const DANGER: Rgb = [255, 31, 31];

fn square(hp: u32) -> Cell {
    Cell::Brick(Brick {
        shape: Shape::Square,
        hp,
    })
}

fn near(a: Rgb, b: Rgb, tolerance: u8) -> bool {
    a.iter().zip(b).all(|(x, y)| x.abs_diff(y) <= tolerance)
}

/// A bright, saturated colour: a brick's (as `tests/screenshot.rs` tells them).
fn brick_like(p: Rgb) -> bool {
    let (max, min) = (p[0].max(p[1]).max(p[2]), p[0].min(p[1]).min(p[2]));
    max > 150 && max - min > 80
}

/// A decoded screenshot.
struct Frame {
    pixels: Vec<u8>,
    width: usize,
}

impl Frame {
    fn load(path: &Path) -> Self {
        let (pixels, width, _) = decode(path);
        Self {
            pixels,
            width: width as usize,
        }
    }

    fn at(&self, x: usize, y: usize) -> Rgb {
        let i = (y * self.width + x) * 4;
        [self.pixels[i], self.pixels[i + 1], self.pixels[i + 2]]
    }

    /// Every pixel inside `r`, shrunk by `inset` pixels on each side, with its position.
    fn inside(&self, r: [f32; 4], inset: f32) -> Vec<(usize, usize, Rgb)> {
        let (x0, y0) = (
            (r[0] + inset).ceil() as usize,
            (r[1] + inset).ceil() as usize,
        );
        let x1 = (r[0] + r[2] - inset).floor() as usize;
        let y1 = (r[1] + r[3] - inset).floor() as usize;
        (y0..y1)
            .flat_map(|y| (x0..x1).map(move |x| (x, y)))
            .map(|(x, y)| (x, y, self.at(x, y)))
            .collect()
    }

    fn count(&self, r: [f32; 4], colour: Rgb, tolerance: u8) -> usize {
        self.inside(r, 0.0)
            .iter()
            .filter(|(_, _, p)| near(*p, colour, tolerance))
            .count()
    }
}

/// A board with bricks of many hit points in rows 2 to 8 (the whole colour ramp at level
/// 30) and a brick too hard to break in row 1.
fn crowded_state() -> GameState {
    state(true)
}

/// The crowded board, or (not `crowded`) only its brick in row 1.
fn state(crowded: bool) -> GameState {
    let config = Config::default();
    let mut board = Board::new(config.columns, config.rows);
    let rows = if crowded { 2..config.rows } else { 0..0 };
    for row in rows {
        for column in 0..config.columns {
            if (row + column) % 2 == 0 {
                board
                    .set(column, row, square(1 + (row * 7 + column) * 3 % 90))
                    .unwrap();
            }
        }
    }
    board.set(3, 1, square(9999)).unwrap();
    GameState::custom(config, board, 30, 1, 3).unwrap()
}

/// The crowded board's game after one round, which ends it: recalled at once (nothing
/// scored) or played out (a score, which is the best).
fn game_over(played_out: bool) -> Game {
    ended(crowded_state(), played_out)
}

fn ended(state: GameState, played_out: bool) -> Game {
    let mut game = Game::from_state(3, state);
    game.shoot(Aim::new(-0.3, 1.0)).unwrap();
    if played_out {
        game.finish_round().unwrap();
    } else {
        game.recall().unwrap();
    }
    assert_eq!(game.phase(), Phase::GameOver);
    game
}

/// Saves `game` in `dir` as `name.json` and renders it with these extra arguments.
fn shot(dir: &Path, name: &str, game: &Game, args: &[&str]) -> PathBuf {
    let save = dir.join(format!("{name}.json"));
    save_game(game, &save).unwrap();
    let out = dir.join(format!("{name}.png"));
    let mut all = vec![
        "--state",
        save.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ];
    all.extend_from_slice(args);
    screenshot_ok(&all);
    out
}

#[test]
fn the_game_over_card_hides_the_board_behind_it() {
    if !display_available() {
        return;
    }
    let dir = temp_dir("card");
    let over = game_over(false);
    assert_eq!(over.state().score(), 0, "recalled before any hit");
    let card_png = shot(&dir, "over", &over, &[]);
    let card = region(&card_png, "card");
    let board = region(&card_png, "board");
    assert!(card[0] >= board[0] && card[0] + card[2] <= board[0] + board[2]);
    assert!(
        card[2] * card[3] > 0.7 * board[2] * board[3],
        "a card, not a banner"
    );
    let frame = Frame::load(&card_png);
    // The card's edge is antialiased; inside it, only the card's own colours.
    let inside = frame.inside(card, 3.0);
    let bricks: Vec<_> = inside.iter().filter(|(_, _, p)| brick_like(*p)).collect();
    assert!(
        bricks.is_empty(),
        "{} brick-coloured pixels inside the card, e.g. {:?}",
        bricks.len(),
        bricks.first()
    );
    let fill = inside.iter().filter(|(_, _, p)| near(*p, FILL, 3)).count();
    assert!(
        fill * 2 > inside.len(),
        "opaque: {fill} of {}",
        inside.len()
    );

    // Without the card the same rectangle is full of brick colours: the check can fail.
    let open = Game::from_state(3, crowded_state());
    let board_png = shot(&dir, "open", &open, &[]);
    let open_frame = Frame::load(&board_png);
    let seen = open_frame
        .inside(card, 3.0)
        .iter()
        .filter(|(_, _, p)| brick_like(*p))
        .count();
    assert!(seen > 10_000, "only {seen} brick pixels on the open board");

    // Over an almost empty board the card is the same to the last pixel.
    let sparse = ended(state(false), false);
    assert_eq!(sparse.state().score(), 0);
    let sparse_png = shot(&dir, "sparse", &sparse, &[]);
    assert_eq!(region(&sparse_png, "card"), card);
    same_inside(&frame, &Frame::load(&sparse_png), card);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Asserts that `a` and `b` have the same pixels inside `r` wherever `a` shows the card's
/// plain fill (most of it): nothing behind shows through. Text is left out: its edge pixels
/// may differ a little, as glyphs land in the font's atlas in the order they were first
/// drawn, which the bricks' numbers change.
fn same_inside(a: &Frame, b: &Frame, r: [f32; 4]) {
    let (pa, pb) = (a.inside(r, 0.0), b.inside(r, 0.0));
    let plain: Vec<_> = pa
        .iter()
        .zip(&pb)
        .filter(|(x, _)| near(x.2, FILL, 1))
        .collect();
    assert!(
        plain.len() * 3 > pa.len(),
        "{} of {} pixels are the card's fill",
        plain.len(),
        pa.len()
    );
    let differ: Vec<_> = plain
        .iter()
        .filter(|(x, y)| !near(x.2, y.2, 1))
        .map(|(x, _)| (x.0, x.1))
        .collect();
    assert!(
        differ.len() * 100 < plain.len(),
        "{} of {} pixels of the card change with the board behind it, e.g. {:?}",
        differ.len(),
        plain.len(),
        &differ[..differ.len().min(10)]
    );
}

#[test]
fn the_menu_cards_are_opaque_too() {
    if !display_available() {
        return;
    }
    let dir = temp_dir("menus");
    let crowded = Game::from_state(3, crowded_state());
    let sparse = Game::from_state(3, state(false));
    for view in ["pause", "settings", "confirm", "help"] {
        let png = shot(&dir, view, &crowded, &["--view", view]);
        let frame = Frame::load(&png);
        let card = region(&png, "card");
        let inside = frame.inside(card, 3.0);
        let bricks = inside.iter().filter(|(_, _, p)| brick_like(*p)).count();
        if view != "help" {
            assert_eq!(bricks, 0, "{view}: brick colours inside the card");
        }
        let other = shot(&dir, &format!("{view}-sparse"), &sparse, &["--view", view]);
        same_inside(&frame, &Frame::load(&other), card);
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_new_best_is_celebrated_and_only_then() {
    if !display_available() {
        return;
    }
    let dir = temp_dir("best");
    let best = game_over(true);
    let state = best.state();
    assert!(state.score() > 0 && state.score() == state.best_score());
    let png = shot(&dir, "best", &best, &[]);
    let gold = Frame::load(&png).count(region(&png, "card"), GOLD, 10);
    assert!(gold > 150, "{gold} gold pixels");
    let plain = shot(&dir, "plain", &game_over(false), &[]);
    let gold = Frame::load(&plain).count(region(&plain, "card"), GOLD, 10);
    assert_eq!(gold, 0, "no celebration for a score of 0");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A game aiming at level 5 with a brick in `row` of column 2 and one high up.
fn one_brick_in_row(row: u32) -> Game {
    let config = Config::default();
    let mut board = Board::new(config.columns, config.rows);
    board.set(2, row, square(5)).unwrap();
    board.set(4, 6, square(5)).unwrap();
    Game::from_state(1, GameState::custom(config, board, 5, 3, 1).unwrap())
}

#[test]
fn the_warning_marks_a_row_one_step_from_the_bottom_and_only_then() {
    if !display_available() {
        return;
    }
    let dir = temp_dir("warning");
    let danger = shot(&dir, "danger", &one_brick_in_row(1), &[]);
    let board = region(&danger, "board");
    let cell = board[2] / 7.0;
    let red: Vec<(usize, usize)> = Frame::load(&danger)
        .inside(board, 0.0)
        .into_iter()
        .filter(|(_, _, p)| near(*p, DANGER, 16))
        .map(|(x, y, _)| (x, y))
        .collect();
    assert!(red.len() > 300, "{} red pixels", red.len());
    // All of it on the brick's row or the line under it: 0.8 to 2.2 cells up.
    let bottom = board[1] + board[3];
    for (x, y) in &red {
        let up = (bottom - *y as f32) / cell;
        assert!((0.8..=2.2).contains(&up), "red at {x},{y}: {up} cells up");
    }
    // Around the brick in column 2: its cell's left and right edges are red.
    let row_y = (bottom - 1.5 * cell) as usize;
    let left = red
        .iter()
        .any(|&(x, y)| y == row_y && (x as f32 - board[0] - 2.0 * cell).abs() < 3.0);
    let right = red
        .iter()
        .any(|&(x, y)| y == row_y && (x as f32 - board[0] - 3.0 * cell).abs() < 3.0);
    assert!(left && right, "the brick's edges are marked");

    let safe = shot(&dir, "safe", &one_brick_in_row(2), &[]);
    let red = Frame::load(&safe).count(region(&safe, "board"), DANGER, 16);
    assert_eq!(red, 0, "two rows up: no warning yet");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_help_screen_shows_every_pick_up_in_its_own_row() {
    if !display_available() {
        return;
    }
    let dir = temp_dir("help");
    let png = shot(&dir, "help", &one_brick_in_row(2), &["--view", "help"]);
    let frame = Frame::load(&png);
    let colour = |kind: PickupKind| -> Rgb {
        let c = onemorebrick_look::palette::pickup(kind).0;
        std::array::from_fn(|k| (c[k] * 255.0).round() as u8)
    };
    let icons: Vec<[f32; 4]> = (0..PickupKind::ALL.len())
        .map(|k| region(&png, &format!("help-icon-{k}")))
        .collect();
    for (k, kind) in PickupKind::ALL.iter().enumerate() {
        for (j, other) in PickupKind::ALL.iter().enumerate() {
            let n = frame.count(icons[j], colour(*kind), 8);
            if j == k {
                assert!(n > 40, "{kind:?}: {n} pixels of its colour in its row");
            } else if colour(*other) != colour(*kind) {
                assert_eq!(n, 0, "{kind:?}'s colour in {other:?}'s row");
            }
        }
    }
    // Kinds of one colour differ in shape: their icons' pixels differ.
    let mask = |k: usize| -> Vec<bool> {
        let c = colour(PickupKind::ALL[k]);
        let r = icons[k];
        let side = r[2].min(icons[0][2]) as usize;
        (0..side * side)
            .map(|i| {
                let (x, y) = (r[0] as usize + i % side, r[1] as usize + i / side);
                near(frame.at(x, y), c, 8)
            })
            .collect()
    };
    for k in 0..icons.len() {
        for j in k + 1..icons.len() {
            if colour(PickupKind::ALL[k]) != colour(PickupKind::ALL[j]) {
                continue;
            }
            let (a, b) = (mask(k), mask(j));
            let side = (a.len() as f64).sqrt() as usize;
            // Pixels of one with none of the other within a pixel (icons sit at different
            // fractions of a pixel, so their edges differ a little).
            let alone = |m: &[bool], other: &[bool]| {
                (0..m.len())
                    .filter(|&i| m[i])
                    .filter(|&i| {
                        let (x, y) = ((i % side) as i64, (i / side) as i64);
                        !(-1..=1).any(|dy| {
                            (-1..=1).any(|dx| {
                                let (u, v) = (x + dx, y + dy);
                                let inside =
                                    (0..side as i64).contains(&u) && (0..side as i64).contains(&v);
                                inside && other[(v * side as i64 + u) as usize]
                            })
                        })
                    })
                    .count()
            };
            let differ = alone(&a, &b) + alone(&b, &a);
            let union = a.iter().zip(&b).filter(|(x, y)| **x || **y).count();
            assert!(
                differ * 8 > union,
                "{:?} and {:?} look alike: {differ} of {union} pixels differ",
                PickupKind::ALL[k],
                PickupKind::ALL[j]
            );
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_game_over_view_of_a_game_that_is_not_over_is_a_usage_error() {
    let dir = temp_dir("not-over");
    let save = dir.join("aiming.json");
    save_game(&one_brick_in_row(2), &save).unwrap();
    let out = Command::new(BIN)
        .args([
            "screenshot",
            "--view",
            "game-over",
            "--out",
            "x.png",
            "--state",
        ])
        .arg(&save)
        .env_remove("DISPLAY")
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("--view game-over"), "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    let bad = Command::new(BIN)
        .args(["screenshot", "--view", "credits", "--out", "x.png"])
        .output()
        .unwrap();
    assert_eq!(bad.status.code(), Some(2));
    std::fs::remove_dir_all(&dir).unwrap();
}
