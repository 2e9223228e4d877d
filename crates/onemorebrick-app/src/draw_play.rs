//! What moves: the launcher with its ball count, the aim preview and the balls.

use macroquad::color::Color;
use macroquad::shapes::{draw_circle, draw_circle_lines};
use onemorebrick::{BallView, DVec2};

use crate::layout::Layout;
use crate::palette;
use crate::text::{self, Style};

/// Length of the reflected stub after the first contact, in cells.
pub const STUB: f64 = 1.2;

/// The preview's segments from the bounce path (launch point, then each contact): the
/// short preview is the path to the first contact plus a stub of the reflection; the long
/// one is the whole path.
pub fn preview_segments(path: &[DVec2], long: bool) -> Vec<(DVec2, DVec2)> {
    let mut segments: Vec<(DVec2, DVec2)> = path.windows(2).map(|w| (w[0], w[1])).collect();
    if !long {
        segments.truncate(2);
        if let Some((a, b)) = segments.get_mut(1) {
            let d = *b - *a;
            if d.length() > STUB {
                *b = *a + d * (STUB / d.length());
            }
        }
    }
    segments
}

/// Draws the aim preview: dotted along the path, a ring at each contact.
pub fn draw_preview(layout: &Layout, path: &[DVec2], long: bool, radius: f64) {
    let segments = preview_segments(path, long);
    let dot = layout.px(radius * 0.45).max(1.5);
    for (k, (a, b)) in segments.iter().enumerate() {
        let length = a.distance(*b);
        let steps = (length / 0.3).ceil().max(1.0) as usize;
        for s in 0..=steps {
            let p = layout.to_screen(*a + (*b - *a) * (s as f64 / steps as f64));
            draw_circle(p.x, p.y, dot, palette::PREVIEW);
        }
        let is_contact = k + 1 < path.len() && (k == 0 || long);
        if is_contact {
            let c = layout.to_screen(*b);
            draw_circle_lines(c.x, c.y, layout.px(radius), 2.0, palette::PREVIEW);
        }
    }
}

/// Draws the launcher: a ball at the launch point and the count beside it ("x 35"), on
/// the side away from the aim (`aim_dx`) so the preview does not cross it.
pub fn draw_launcher(layout: &Layout, x: f64, radius: f64, count: u32, aim_dx: f64) {
    let p = layout.to_screen(DVec2::new(x, radius));
    draw_circle(p.x, p.y, layout.px(radius), palette::BALL);
    if count > 0 {
        let label = format!("x {count}");
        let size = layout.px(0.38);
        let offset = layout.px(radius) + size * 1.1;
        let width = f64::from(layout.board.w / layout.cell);
        let left = if x < 1.5 {
            false
        } else if x > width - 1.5 {
            true
        } else {
            aim_dx > 0.0
        };
        let cx = if left { p.x - offset } else { p.x + offset };
        text::draw_centred(
            &label,
            macroquad::math::Vec2::new(cx, p.y - size * 0.6),
            &Style::bold(size),
            palette::TEXT,
        );
    }
}

/// Where the next volley will leave from, once the first ball is back: a hollow ball.
pub fn draw_next_launch(layout: &Layout, x: f64, radius: f64) {
    let p = layout.to_screen(DVec2::new(x, radius));
    draw_circle_lines(p.x, p.y, layout.px(radius), 2.0, palette::BALL);
}

/// A ball's colour: clones are tinted, charges show.
pub fn ball_colour(ball: &BallView) -> Color {
    if ball.clone {
        Color::new(1.0, 0.9, 0.45, 1.0)
    } else if ball.floor_bounce {
        Color::new(0.55, 0.85, 1.0, 1.0)
    } else {
        palette::BALL
    }
}

/// Draws every ball where the engine has it now.
pub fn draw_balls(layout: &Layout, balls: &[BallView]) {
    for ball in balls {
        let p = layout.to_screen(ball.position);
        let r = layout.px(ball.radius).max(1.0);
        draw_circle(p.x, p.y, r, ball_colour(ball));
        if ball.shield {
            draw_circle_lines(p.x, p.y, r * 1.5, 1.5, Color::new(0.4, 0.6, 1.0, 1.0));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn path() -> Vec<DVec2> {
        vec![
            DVec2::new(3.5, 0.15),
            DVec2::new(6.85, 3.5),
            DVec2::new(3.0, 7.35),
            DVec2::new(0.15, 4.5),
        ]
    }

    #[test]
    fn the_short_preview_is_the_first_leg_and_a_stub() {
        let s = preview_segments(&path(), false);
        assert_eq!(s.len(), 2);
        assert_eq!(s[0], (path()[0], path()[1]));
        assert!((s[1].0.distance(s[1].1) - STUB).abs() < 1e-12);
        let dir = (s[1].1 - s[1].0).normalize();
        assert!((dir - (path()[2] - path()[1]).normalize()).length() < 1e-12);
    }

    #[test]
    fn the_long_preview_is_the_whole_path() {
        assert_eq!(preview_segments(&path(), true).len(), 3);
    }

    #[test]
    fn a_short_second_leg_is_kept_whole() {
        let p = vec![DVec2::ZERO, DVec2::new(0.0, 1.0), DVec2::new(0.5, 1.0)];
        assert_eq!(preview_segments(&p, false)[1].1, DVec2::new(0.5, 1.0));
    }
}
