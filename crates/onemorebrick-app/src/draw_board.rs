//! The board: its background, bricks with their hit points, round obstacles and pick-ups (their icons: `pickups`).

use macroquad::math::Vec2;
use macroquad::shapes::{draw_circle, draw_circle_lines, draw_rectangle, draw_triangle};
use onemorebrick::{Board, Brick, Cell, Config, DVec2, Shape};
use onemorebrick_look as look;

use crate::layout::Layout;
use crate::palette;
use crate::pickups;
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
    let size = match brick.shape {
        Shape::Square => 0.42,
        Shape::Triangle(_) => 0.3,
    };
    let text = look::compact(brick.hp);
    let size = if text.len() >= 4 { size * 0.7 } else { size };
    centred_text(
        &text,
        layout.to_screen(c),
        layout.px(size),
        palette::HP_TEXT,
    );
}

fn draw_obstacle(layout: &Layout, origin: DVec2, radius: f64) {
    let c = layout.to_screen(origin + DVec2::splat(0.5));
    draw_circle(c.x, c.y, layout.px(radius), palette::OBSTACLE);
    draw_circle_lines(c.x, c.y, layout.px(radius * 0.6), 2.0, palette::BOARD);
}
