//! The board: its background, bricks with their hit points, round obstacles and pick-ups.

use std::cell::RefCell;
use std::collections::HashMap;

use macroquad::math::Vec2;
use macroquad::shapes::{draw_circle, draw_circle_lines, draw_line, draw_rectangle, draw_triangle};
use macroquad::window::screen_dpi_scale;
use onemorebrick::{Board, Brick, Cell, Config, Corner, DVec2, Pickup, Shape};
use onemorebrick_look as look;

use crate::layout::Layout;
use crate::palette;
use crate::text::{self, Style};
use crate::widgets::centred_text;

/// Draws the board and everything on it.
pub fn draw(layout: &Layout, board: &Board, config: &Config, level: u32) {
    let r = layout.board;
    draw_rectangle(r.x, r.y, r.w, r.h, palette::BOARD);
    let top = look::palette::ramp_top(board, level);
    for (i, cell) in board.cells().iter().enumerate() {
        let origin = board.origin(i);
        match cell {
            Cell::Empty => {}
            Cell::Brick(b) => draw_brick(layout, b, origin, top),
            Cell::Obstacle => draw_obstacle(layout, origin, config.obstacle_radius),
            Cell::Pickup(p) => draw_pickup(layout, p, origin, config.pickup_radius),
        }
    }
}

fn draw_brick(layout: &Layout, brick: &Brick, origin: DVec2, top: u32) {
    let colour = palette::brick(brick.hp, top);
    let c = look::centroid(brick.shape, origin);
    let points: Vec<Vec2> = look::drawn_outline(brick.shape, origin)
        .into_iter()
        .map(|p| layout.to_screen(p))
        .collect();
    for k in 1..points.len() - 1 {
        draw_triangle(points[0], points[k], points[k + 1], colour);
    }
    let number = look::compact(brick.hp);
    let style = remembered_style(layout, brick.shape, &number);
    text::draw_centred(&number, layout.to_screen(c), &style, palette::HP_TEXT);
}

/// The tallest a square brick's number is, in cells (short numbers reach it; longer ones
/// are condensed, then shrunk, to the width).
const NUMBER_HEIGHT: f64 = 0.55;
/// The widest a square brick's number is, in cells (the drawn brick is 0.93 wide).
const NUMBER_WIDTH: f64 = 0.82;
/// How far a brick's number may be condensed (its glyphs' width scale).
const NUMBER_MIN_ASPECT: f32 = 0.7;
/// A brick number's letter spacing (a share of its size: digits set close).
const NUMBER_TRACKING: f32 = -0.03;

/// [`number_style`], remembered: a board shows few distinct numbers, and fitting one lays
/// it out a few dozen times.
fn remembered_style(layout: &Layout, shape: Shape, number: &str) -> Style {
    type Key = (String, Option<usize>, u32, u32);
    thread_local! {
        static STYLES: RefCell<HashMap<Key, Style>> = RefCell::new(HashMap::new());
    }
    let corner = match shape {
        Shape::Square => None,
        Shape::Triangle(c) => Corner::ALL.iter().position(|k| *k == c),
    };
    let key = (
        number.to_owned(),
        corner,
        layout.cell.to_bits(),
        screen_dpi_scale().to_bits(),
    );
    STYLES.with(|styles| {
        let mut styles = styles.borrow_mut();
        if let Some(style) = styles.get(&key) {
            return *style;
        }
        // A bound on memory: forget everything once in a while (a resize, a long game).
        if styles.len() > 2048 {
            styles.clear();
        }
        let style = number_style(layout, shape, number);
        styles.insert(key, style);
        style
    })
}

/// The style of a brick's number: bold, as large as its room in the brick allows (a
/// square's box; in a triangle the largest box of the number's shape at the centroid).
pub fn number_style(layout: &Layout, shape: Shape, number: &str) -> Style {
    let base = Style {
        tracking: NUMBER_TRACKING,
        ..Style::bold(layout.px(1.0))
    };
    let (room, min_aspect) = match shape {
        Shape::Square => {
            let side = look::number_box(Shape::Square, 1.0).x;
            let room = DVec2::new(NUMBER_WIDTH.min(side), NUMBER_HEIGHT.min(side));
            (room, NUMBER_MIN_ASPECT)
        }
        Shape::Triangle(_) => {
            let ink = text::measure(number, &base);
            let ratio = f64::from(ink.width() / ink.height().max(1.0));
            (look::number_box(shape, ratio), 0.85)
        }
    };
    text::fit(
        number,
        base,
        layout.px(room.x),
        layout.px(room.y),
        min_aspect,
    )
}

fn draw_obstacle(layout: &Layout, origin: DVec2, radius: f64) {
    let c = layout.to_screen(origin + DVec2::splat(0.5));
    draw_circle(c.x, c.y, layout.px(radius), palette::OBSTACLE);
    draw_circle_lines(c.x, c.y, layout.px(radius * 0.6), 2.0, palette::BOARD);
}

fn draw_pickup(layout: &Layout, pickup: &Pickup, origin: DVec2, radius: f64) {
    let (colour, label) = look::palette::pickup(pickup.kind);
    let colour = palette::color(colour);
    let colour = if pickup.used {
        palette::with_alpha(colour, 0.35)
    } else {
        colour
    };
    let c = layout.to_screen(origin + DVec2::splat(0.5));
    let r = layout.px(radius);
    draw_circle(c.x, c.y, r, palette::with_alpha(colour, 0.18));
    draw_circle_lines(c.x, c.y, r, (r * 0.12).max(1.5), colour);
    let arm = r * 0.65;
    let w = (r * 0.16).max(1.5);
    if pickup.kind.hits_row() {
        draw_line(c.x - arm, c.y, c.x + arm, c.y, w, colour);
    }
    if pickup.kind.hits_column() {
        draw_line(c.x, c.y - arm, c.x, c.y + arm, w, colour);
    }
    if !label.is_empty() {
        centred_text(label, c, r * 1.05, colour);
    }
}
