//! The game's colours (`onemorebrick_look::palette`) as macroquad colours.

use macroquad::color::Color;
use onemorebrick_look::palette::{self as look, Rgba};

/// A shared colour as macroquad's.
pub const fn color(c: Rgba) -> Color {
    Color::new(c[0], c[1], c[2], c[3])
}

/// The window's background.
pub const BACKGROUND: Color = color(look::BACKGROUND);
/// The board's background.
pub const BOARD: Color = color(look::BOARD);
/// Text and the launcher.
pub const TEXT: Color = color(look::TEXT);
/// Dimmed text.
pub const TEXT_DIM: Color = color(look::TEXT_DIM);
/// A brick's hit points (white).
pub const HP_TEXT: Color = color(look::NUMBER);
/// Balls.
pub const BALL: Color = color(look::BALL);
/// The aim preview.
pub const PREVIEW: Color = color(look::PREVIEW);
/// Round obstacles.
pub const OBSTACLE: Color = color(look::OBSTACLE);
/// Laser beams.
pub const LASER: Color = color(look::LASER);

/// The colour of a brick with `hp` hit points when the ramp's top is `max_hp`
/// (`onemorebrick_look::palette::brick`).
pub fn brick(hp: u32, max_hp: u32) -> Color {
    color(look::brick(hp, max_hp))
}

/// `c` with alpha `a`.
pub fn with_alpha(c: Color, a: f32) -> Color {
    Color::new(c.r, c.g, c.b, a.clamp(0.0, 1.0))
}
