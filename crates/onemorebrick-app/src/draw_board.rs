//! The board: its background, bricks with their hit points, round obstacles and pick-ups (their icons: `pickups`).

use std::cell::RefCell;
use std::collections::HashMap;

use macroquad::math::Vec2;
use macroquad::shapes::{draw_circle, draw_circle_lines, draw_rectangle, draw_triangle};
use macroquad::window::screen_dpi_scale;
use onemorebrick::{Board, Brick, Cell, Config, Corner, DVec2, Shape};
use onemorebrick_look as look;

use crate::layout::Layout;
use crate::palette;
use crate::pickups;
use crate::text::{self, Style};

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
            Cell::Pickup(p) => pickups::draw_on_board(layout, p, origin, config.pickup_radius),
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
        let style = number_style(layout.cell, shape, number, screen_dpi_scale());
        styles.insert(key, style);
        style
    })
}

/// The style of a brick's number in a cell of `cell` pixels on a screen of DPI scale `dpi`:
/// bold, as large as its room in the brick allows (a square's box; in a triangle the largest
/// box of the number's shape at the centroid).
pub fn number_style(cell: f32, shape: Shape, number: &str, dpi: f32) -> Style {
    let base = Style {
        tracking: NUMBER_TRACKING,
        ..Style::bold(cell)
    };
    let (room, min_aspect) = match shape {
        Shape::Square => {
            let side = look::number_box(Shape::Square, 1.0).x;
            let room = DVec2::new(NUMBER_WIDTH.min(side), NUMBER_HEIGHT.min(side));
            (room, NUMBER_MIN_ASPECT)
        }
        Shape::Triangle(_) => {
            let ink = text::lay_out(number, &base, dpi).ink;
            let ratio = f64::from(ink.width() / ink.height().max(1.0));
            (look::number_box(shape, ratio), 0.85)
        }
    };
    let px = |cells: f64| cells as f32 * cell;
    text::fit_style(number, base, px(room.x), px(room.y), min_aspect, dpi)
}

fn draw_obstacle(layout: &Layout, origin: DVec2, radius: f64) {
    let c = layout.to_screen(origin + DVec2::splat(0.5));
    draw_circle(c.x, c.y, layout.px(radius), palette::OBSTACLE);
    draw_circle_lines(c.x, c.y, layout.px(radius * 0.6), 2.0, palette::BOARD);
}
#[cfg(test)]
mod tests {
    use super::*;
    use onemorebrick::cell::distance_to_outline;

    const DPIS: [f32; 3] = [1.0, 1.5, 2.0];

    #[test]
    fn one_to_three_digits_fill_at_least_half_a_square() {
        for cell in [30.0, 48.0, 72.0, 101.0, 150.0] {
            for dpi in DPIS {
                for number in ["1", "7", "42", "99", "100", "888", "999"] {
                    let style = number_style(cell, Shape::Square, number, dpi);
                    let ink = text::lay_out(number, &style, dpi).ink;
                    assert!(
                        ink.height() >= 0.5 * cell,
                        "{number} in {cell} px at {dpi}: {} px high",
                        ink.height()
                    );
                }
            }
        }
    }

    #[test]
    fn every_number_stays_inside_its_brick() {
        let mut shapes = vec![Shape::Square];
        shapes.extend(Corner::ALL.map(Shape::Triangle));
        for cell in [36.0, 72.0, 140.0] {
            for dpi in DPIS {
                for shape in &shapes {
                    let drawn = look::drawn_outline(*shape, DVec2::ZERO);
                    let centre = look::centroid(*shape, DVec2::ZERO);
                    for hp in [1, 9, 42, 512, 9999, 12_345, 123_456, 4_000_000, u32::MAX] {
                        let number = look::compact(hp);
                        let style = number_style(cell, *shape, &number, dpi);
                        let ink = text::lay_out(&number, &style, dpi).ink;
                        let half = DVec2::new(
                            f64::from(ink.width() / cell),
                            f64::from(ink.height() / cell),
                        ) / 2.0;
                        for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
                            let p = centre + DVec2::new(sx * half.x, sy * half.y);
                            assert_eq!(
                                distance_to_outline(&drawn, p),
                                0.0,
                                "{number} in a {cell} px {shape:?} at {dpi}"
                            );
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn longer_numbers_are_never_taller() {
        for dpi in DPIS {
            let heights: Vec<f32> = ["8", "88", "888", "8888"]
                .iter()
                .map(|n| {
                    let s = number_style(72.0, Shape::Square, n, dpi);
                    text::lay_out(n, &s, dpi).ink.height()
                })
                .collect();
            assert!(heights.windows(2).all(|w| w[1] <= w[0]), "{heights:?}");
        }
    }
}
