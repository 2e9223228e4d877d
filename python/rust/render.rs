//! The board drawn in software with tiny-skia (no window, no GPU), in the colours of the
//! desktop game (`crates/onemorebrick-app/src/palette.rs`): dark board, bricks on a ramp from
//! green (few hit points) to violet (the level's hardest), grey obstacles, pick-ups as
//! coloured rings, balls in flight and the launcher ball in white.

use numpy::ndarray::Array3;
use onemorebrick::{Cell, Corner, Game, PickupKind, Shape};
use tiny_skia::{Color, FillRule, Paint, PathBuilder, Pixmap, Rect, Stroke, Transform};

const BACKGROUND: [f32; 3] = [0.11, 0.12, 0.18];
const BALL: [f32; 3] = [0.96, 0.97, 1.0];
const OBSTACLE: [f32; 3] = [0.55, 0.58, 0.66];
const RAMP: [[f32; 3]; 5] = [
    [0.20, 0.80, 0.55],
    [0.95, 0.80, 0.20],
    [0.98, 0.50, 0.18],
    [0.92, 0.22, 0.30],
    [0.75, 0.20, 0.85],
];

fn paint(rgb: [f32; 3]) -> Paint<'static> {
    let mut p = Paint::default();
    p.set_color(Color::from_rgba(rgb[0], rgb[1], rgb[2], 1.0).unwrap_or(Color::WHITE));
    p.anti_alias = true;
    p
}

/// The app's brick colour: the ramp spread over `1..=max_hp`.
fn brick_color(hp: u32, max_hp: u32) -> [f32; 3] {
    let max_hp = max_hp.max(hp).max(1);
    let t = if max_hp == 1 {
        0.0
    } else {
        (hp.max(1) - 1) as f32 / (max_hp - 1) as f32
    };
    let scaled = t * (RAMP.len() - 1) as f32;
    let i = (scaled.floor() as usize).min(RAMP.len() - 2);
    let f = (scaled - i as f32).clamp(0.0, 1.0);
    let (a, b) = (RAMP[i], RAMP[i + 1]);
    [
        a[0] + (b[0] - a[0]) * f,
        a[1] + (b[1] - a[1]) * f,
        a[2] + (b[2] - a[2]) * f,
    ]
}

fn pickup_color(kind: PickupKind) -> [f32; 3] {
    match kind {
        PickupKind::ExtraBall => [0.30, 0.90, 0.45],
        PickupKind::Split => [0.98, 0.85, 0.25],
        PickupKind::Hazard => [0.95, 0.25, 0.25],
        PickupKind::FloorBounce => [0.45, 0.75, 1.0],
        PickupKind::LaserHorizontal | PickupKind::LaserVertical | PickupKind::LaserCross => {
            [0.35, 0.95, 1.0]
        }
        PickupKind::RandomDirection => [0.80, 0.50, 1.0],
        PickupKind::Bigger | PickupKind::Smaller => [1.0, 0.60, 0.30],
        PickupKind::Boost => [1.0, 0.45, 0.70],
        PickupKind::Shield => [0.40, 0.60, 1.0],
    }
}

/// A frame of the game now, `cell` pixels per cell: RGB, shape `(height, width, 3)`.
pub fn frame(game: &Game, cell: u32) -> Option<Array3<u8>> {
    let board = game.board();
    let config = game.state().config();
    let (w, h) = (board.columns() * cell, board.rows() * cell);
    let mut pixmap = Pixmap::new(w, h)?;
    let [r, g, b] = BACKGROUND;
    pixmap.fill(Color::from_rgba(r, g, b, 1.0)?);
    let s = cell as f32;
    // World (cells, y up) to pixels (y down).
    let to_px = |x: f64, y: f64| (x as f32 * s, h as f32 - y as f32 * s);
    let max_hp = board.bricks().map(|(_, b)| b.hp).max().unwrap_or(1);
    let id = Transform::identity();
    let gap = (s * 0.04).max(1.0);
    for (i, cell_value) in board.cells().iter().enumerate() {
        let (column, row) = board.position(i);
        let (x0, y1) = to_px(f64::from(column), f64::from(row));
        let (x1, y0) = (x0 + s, y1 - s);
        let centre = (x0 + s / 2.0, y0 + s / 2.0);
        match cell_value {
            Cell::Empty => {}
            Cell::Brick(brick) => {
                let p = paint(brick_color(brick.hp, max_hp));
                let (l, r, t, b) = (x0 + gap, x1 - gap, y0 + gap, y1 - gap);
                let corners = match brick.shape {
                    Shape::Square => vec![(l, t), (r, t), (r, b), (l, b)],
                    Shape::Triangle(Corner::TopLeft) => vec![(r, t), (r, b), (l, b)],
                    Shape::Triangle(Corner::TopRight) => vec![(l, t), (r, b), (l, b)],
                    Shape::Triangle(Corner::BottomLeft) => vec![(l, t), (r, t), (r, b)],
                    Shape::Triangle(Corner::BottomRight) => vec![(l, t), (r, t), (l, b)],
                };
                let mut pb = PathBuilder::new();
                pb.move_to(corners[0].0, corners[0].1);
                for &(x, y) in &corners[1..] {
                    pb.line_to(x, y);
                }
                pb.close();
                pixmap.fill_path(&pb.finish()?, &p, FillRule::Winding, id, None);
            }
            Cell::Obstacle => {
                let radius = config.obstacle_radius as f32 * s;
                let path = PathBuilder::from_circle(centre.0, centre.1, radius)?;
                pixmap.fill_path(&path, &paint(OBSTACLE), FillRule::Winding, id, None);
            }
            Cell::Pickup(pickup) => {
                let radius = config.pickup_radius as f32 * s;
                let path = PathBuilder::from_circle(centre.0, centre.1, radius)?;
                let stroke = Stroke {
                    width: (s * 0.08).max(1.0),
                    ..Stroke::default()
                };
                let p = paint(pickup_color(pickup.kind));
                pixmap.stroke_path(&path, &p, &stroke, id, None);
                let dot = PathBuilder::from_circle(centre.0, centre.1, radius * 0.35)?;
                pixmap.fill_path(&dot, &p, FillRule::Winding, id, None);
            }
        }
    }
    // The floor line, then the balls: those in flight, or the launcher's between volleys.
    let floor = Rect::from_xywh(0.0, h as f32 - 1.0, w as f32, 1.0)?;
    pixmap.fill_rect(floor, &paint(OBSTACLE), id, None);
    let balls = game.balls();
    let launcher = [(
        game.state().launch_x(),
        config.ball_radius,
        config.ball_radius,
    )];
    let circles: Vec<(f64, f64, f64)> = if balls.is_empty() {
        launcher.to_vec()
    } else {
        balls
            .iter()
            .map(|b| (b.position.x, b.position.y, b.radius))
            .collect()
    };
    for (x, y, radius) in circles {
        let (px, py) = to_px(x, y);
        let path = PathBuilder::from_circle(px, py, (radius as f32 * s).max(1.0))?;
        pixmap.fill_path(&path, &paint(BALL), FillRule::Winding, id, None);
    }
    let rgb: Vec<u8> = pixmap
        .data()
        .chunks_exact(4)
        .flat_map(|px| [px[0], px[1], px[2]])
        .collect();
    Array3::from_shape_vec((h as usize, w as usize, 3), rgb).ok()
}
