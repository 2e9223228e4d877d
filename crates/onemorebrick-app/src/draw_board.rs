//! The board: its background, bricks with their hit points, round obstacles and pick-ups.

use macroquad::color::Color;
use macroquad::math::Vec2;
use macroquad::shapes::{draw_circle, draw_circle_lines, draw_line, draw_rectangle, draw_triangle};
use onemorebrick::cell::outline;
use onemorebrick::{Board, Brick, Cell, Config, DVec2, Pickup, PickupKind, Shape};

use crate::layout::Layout;
use crate::palette;
use crate::widgets::centred_text;

/// The gap between neighbouring bricks, in cells.
const GAP: f64 = 0.05;
/// Hit-point text colour (dark on the bright ramp).
const HP_TEXT: Color = Color::new(0.06, 0.06, 0.10, 1.0);

/// The centroid of a brick's outline: the cell centre for a square, the triangle's
/// centroid for a triangle (where its hit points are written, inside the triangle).
pub fn centroid(shape: Shape, origin: DVec2) -> DVec2 {
    let points = outline(shape, origin);
    if points.len() == 4 {
        return origin + DVec2::splat(0.5);
    }
    points.iter().copied().sum::<DVec2>() / points.len() as f64
}

/// The outline moved `gap` inward toward `centre` (so neighbours show a seam).
fn inset(points: &[DVec2], centre: DVec2, gap: f64) -> Vec<DVec2> {
    points
        .iter()
        .map(|p| {
            let d = *p - centre;
            let len = d.length();
            if len <= gap {
                centre
            } else {
                centre + d * ((len - gap) / len)
            }
        })
        .collect()
}

/// The hit points the hottest colour stands for at `level` (the spawn's maximum is three
/// times the level) or more if the board holds more.
pub fn ramp_top(board: &Board, level: u32) -> u32 {
    board
        .bricks()
        .map(|(_, b)| b.hp)
        .max()
        .unwrap_or(1)
        .max(level.saturating_mul(3))
}

/// Draws the board and everything on it.
pub fn draw(layout: &Layout, board: &Board, config: &Config, level: u32) {
    let r = layout.board;
    draw_rectangle(r.x, r.y, r.w, r.h, palette::BOARD);
    let top = ramp_top(board, level);
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
    let c = centroid(brick.shape, origin);
    let points: Vec<Vec2> = inset(&outline(brick.shape, origin), c, GAP)
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
    let size = if brick.hp >= 1000 { size * 0.7 } else { size };
    centred_text(
        &brick.hp.to_string(),
        layout.to_screen(c),
        layout.px(size),
        HP_TEXT,
    );
}

fn draw_obstacle(layout: &Layout, origin: DVec2, radius: f64) {
    let c = layout.to_screen(origin + DVec2::splat(0.5));
    draw_circle(c.x, c.y, layout.px(radius), palette::OBSTACLE);
    draw_circle_lines(c.x, c.y, layout.px(radius * 0.6), 2.0, palette::BOARD);
}

/// A pick-up's colour and the short label drawn in it.
pub fn pickup_look(kind: PickupKind) -> (Color, &'static str) {
    use PickupKind as K;
    match kind {
        K::ExtraBall => (Color::new(0.30, 0.90, 0.45, 1.0), "+1"),
        K::Split => (Color::new(0.98, 0.85, 0.25, 1.0), "x2"),
        K::Hazard => (Color::new(0.95, 0.25, 0.25, 1.0), "X"),
        K::FloorBounce => (Color::new(0.45, 0.75, 1.0, 1.0), "^"),
        K::LaserHorizontal | K::LaserVertical | K::LaserCross => (palette::LASER, ""),
        K::RandomDirection => (Color::new(0.80, 0.50, 1.0, 1.0), "?"),
        K::Bigger => (Color::new(1.0, 0.60, 0.30, 1.0), "B+"),
        K::Smaller => (Color::new(1.0, 0.60, 0.30, 1.0), "b-"),
        K::Boost => (Color::new(1.0, 0.45, 0.70, 1.0), ">>"),
        K::Shield => (Color::new(0.40, 0.60, 1.0, 1.0), "S"),
    }
}

fn draw_pickup(layout: &Layout, pickup: &Pickup, origin: DVec2, radius: f64) {
    let (colour, label) = pickup_look(pickup.kind);
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

#[cfg(test)]
mod tests {
    use super::*;
    use onemorebrick::Corner;

    #[test]
    fn a_triangles_number_sits_inside_the_triangle() {
        let origin = DVec2::new(2.0, 3.0);
        for corner in Corner::ALL {
            let shape = Shape::Triangle(corner);
            let c = centroid(shape, origin);
            let d = onemorebrick::cell::distance_to_outline(&outline(shape, origin), c);
            assert_eq!(d, 0.0, "{corner:?}");
            assert!(
                (c - (origin + DVec2::splat(0.5))).length() > 0.2,
                "{corner:?}"
            );
        }
        assert_eq!(centroid(Shape::Square, origin), DVec2::new(2.5, 3.5));
    }

    #[test]
    fn inset_moves_every_corner_inward() {
        let square = outline(Shape::Square, DVec2::ZERO);
        let centre = DVec2::splat(0.5);
        let inner = inset(&square, centre, 0.1);
        for (a, b) in square.iter().zip(&inner) {
            assert!((a.distance(centre) - b.distance(centre) - 0.1).abs() < 1e-12);
        }
    }

    #[test]
    fn the_ramp_top_covers_the_level_and_the_board() {
        let mut board = Board::new(7, 9);
        assert_eq!(ramp_top(&board, 4), 12);
        let hard = Cell::Brick(Brick {
            shape: Shape::Square,
            hp: 50,
        });
        board.set(0, 5, hard).unwrap();
        assert_eq!(ramp_top(&board, 4), 50);
    }

    #[test]
    fn every_pickup_kind_looks_different() {
        let looks: Vec<_> = PickupKind::ALL
            .iter()
            .filter(|k| !(k.hits_row() || k.hits_column()))
            .map(|k| pickup_look(*k).1)
            .collect();
        for (i, a) in looks.iter().enumerate() {
            assert!(!a.is_empty());
            assert!(!looks[i + 1..].contains(a), "{a}");
        }
    }
}
