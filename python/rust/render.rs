//! The board drawn in software with tiny-skia (no window, no GPU), as the desktop game draws
//! it, from the same palette and rules of look (`onemorebrick_look`): dark board, bricks on a
//! ramp from green (few hit points) to violet (the level's hardest) with their hit points
//! (shortened as "12.3k" past four digits) at the centroid, grey obstacles, pick-ups as
//! coloured rings with their labels or beams, balls in flight, or the launcher ball with the
//! ball count beside it ("x 35").

use numpy::ndarray::Array3;
use onemorebrick::{Cell, Game, Shape};
use onemorebrick_look::palette::{self, Rgba};
use onemorebrick_look::{centroid, compact, drawn_outline};
use tiny_skia::{Color, FillRule, Paint, PathBuilder, Pixmap, Rect, Stroke, Transform};

use crate::text::{Align, draw};

fn paint(c: Rgba) -> Paint<'static> {
    let mut p = Paint::default();
    p.set_color(Color::from_rgba(c[0], c[1], c[2], c[3]).unwrap_or(Color::WHITE));
    p.anti_alias = true;
    p
}

/// A frame of the game now, `cell` pixels per cell: RGB, shape `(height, width, 3)`.
pub fn frame(game: &Game, cell: u32) -> Option<Array3<u8>> {
    let board = game.board();
    let config = game.state().config();
    let (w, h) = (board.columns() * cell, board.rows() * cell);
    let mut pixmap = Pixmap::new(w, h)?;
    let [r, g, b, a] = palette::BOARD;
    pixmap.fill(Color::from_rgba(r, g, b, a)?);
    let s = cell as f32;
    // World (cells, y up) to pixels (y down).
    let to_px = |x: f64, y: f64| (x as f32 * s, h as f32 - y as f32 * s);
    let top = palette::ramp_top(board, game.state().level());
    let id = Transform::identity();
    for (i, cell_value) in board.cells().iter().enumerate() {
        let origin = board.origin(i);
        let centre = to_px(origin.x + 0.5, origin.y + 0.5);
        match cell_value {
            Cell::Empty => {}
            Cell::Brick(brick) => {
                let c = centroid(brick.shape, origin);
                let c = to_px(c.x, c.y);
                let corners: Vec<(f32, f32)> = drawn_outline(brick.shape, origin)
                    .into_iter()
                    .map(|p| to_px(p.x, p.y))
                    .collect();
                let mut pb = PathBuilder::new();
                pb.move_to(corners[0].0, corners[0].1);
                for &(x, y) in &corners[1..] {
                    pb.line_to(x, y);
                }
                pb.close();
                let fill = paint(palette::brick(brick.hp, top));
                pixmap.fill_path(&pb.finish()?, &fill, FillRule::Winding, id, None);
                // The number as large as the shape allows: a square's inner box, or the
                // box a triangle's centroid can hold.
                let (width, height) = match brick.shape {
                    Shape::Square => (0.68, 0.38),
                    Shape::Triangle(_) => (0.42, 0.24),
                };
                let text = compact(brick.hp);
                let ink = paint(palette::HP_TEXT);
                draw(
                    &mut pixmap,
                    &text,
                    c,
                    Align::Centre,
                    width * s,
                    height * s,
                    &ink,
                );
            }
            Cell::Obstacle => {
                let radius = config.obstacle_radius as f32 * s;
                let path = PathBuilder::from_circle(centre.0, centre.1, radius)?;
                pixmap.fill_path(
                    &path,
                    &paint(palette::OBSTACLE),
                    FillRule::Winding,
                    id,
                    None,
                );
                let ring = PathBuilder::from_circle(centre.0, centre.1, radius * 0.6)?;
                let stroke = Stroke {
                    width: (s * 0.03).max(1.0),
                    ..Stroke::default()
                };
                pixmap.stroke_path(&ring, &paint(palette::BOARD), &stroke, id, None);
            }
            Cell::Pickup(pickup) => {
                let (colour, label) = palette::pickup(pickup.kind);
                let colour = if pickup.used {
                    palette::with_alpha(colour, 0.35)
                } else {
                    colour
                };
                let radius = config.pickup_radius as f32 * s;
                let path = PathBuilder::from_circle(centre.0, centre.1, radius)?;
                let halo = paint(palette::with_alpha(colour, 0.18));
                pixmap.fill_path(&path, &halo, FillRule::Winding, id, None);
                let stroke = Stroke {
                    width: (radius * 0.12).max(1.0),
                    ..Stroke::default()
                };
                let p = paint(colour);
                pixmap.stroke_path(&path, &p, &stroke, id, None);
                let arm = radius * 0.65;
                let beam = Stroke {
                    width: (radius * 0.16).max(1.0),
                    ..Stroke::default()
                };
                let mut beams = PathBuilder::new();
                if pickup.kind.hits_row() {
                    beams.move_to(centre.0 - arm, centre.1);
                    beams.line_to(centre.0 + arm, centre.1);
                }
                if pickup.kind.hits_column() {
                    beams.move_to(centre.0, centre.1 - arm);
                    beams.line_to(centre.0, centre.1 + arm);
                }
                if let Some(beams) = beams.finish() {
                    pixmap.stroke_path(&beams, &p, &beam, id, None);
                }
                if !label.is_empty() {
                    draw(
                        &mut pixmap,
                        label,
                        centre,
                        Align::Centre,
                        radius * 1.3,
                        radius * 0.8,
                        &p,
                    );
                }
            }
        }
    }
    // The floor line, then the balls: those in flight, or the launcher's between volleys
    // with the count beside it.
    let floor = Rect::from_xywh(0.0, h as f32 - 1.0, w as f32, 1.0)?;
    pixmap.fill_rect(floor, &paint(palette::OBSTACLE), id, None);
    let balls = game.balls();
    let ball = paint(palette::BALL);
    if balls.is_empty() {
        let (x, radius) = (game.state().launch_x(), config.ball_radius);
        let (px, py) = to_px(x, radius);
        let path = PathBuilder::from_circle(px, py, (radius as f32 * s).max(1.0))?;
        pixmap.fill_path(&path, &ball, FillRule::Winding, id, None);
        let label = format!("x {}", compact(game.state().balls()));
        // Beside the ball, on the side with more room.
        let (width, height) = (2.2 * s, 0.36 * s);
        let offset = radius as f32 * s + 0.15 * s;
        let (anchor, align) = if x > f64::from(board.columns()) / 2.0 {
            ((px - offset, py), Align::Right)
        } else {
            ((px + offset, py), Align::Left)
        };
        let text = paint(palette::TEXT);
        draw(&mut pixmap, &label, anchor, align, width, height, &text);
    } else {
        for b in &balls {
            let (px, py) = to_px(b.position.x, b.position.y);
            let path = PathBuilder::from_circle(px, py, (b.radius as f32 * s).max(1.0))?;
            pixmap.fill_path(&path, &ball, FillRule::Winding, id, None);
        }
    }
    let rgb: Vec<u8> = pixmap
        .data()
        .chunks_exact(4)
        .flat_map(|px| [px[0], px[1], px[2]])
        .collect();
    Array3::from_shape_vec((h as usize, w as usize, 3), rgb).ok()
}
