//! Colours: the background, the brick ramp that follows hit points, pick-up colours.

use macroquad::color::Color;

/// The window's background.
pub const BACKGROUND: Color = Color::new(0.07, 0.08, 0.12, 1.0);
/// The board's background.
pub const BOARD: Color = Color::new(0.11, 0.12, 0.18, 1.0);
/// Text and the launcher.
pub const TEXT: Color = Color::new(0.95, 0.95, 0.97, 1.0);
/// Dimmed text.
pub const TEXT_DIM: Color = Color::new(0.62, 0.65, 0.72, 1.0);
/// Balls.
pub const BALL: Color = Color::new(0.96, 0.97, 1.0, 1.0);
/// The aim preview.
pub const PREVIEW: Color = Color::new(1.0, 1.0, 1.0, 0.75);
/// Round obstacles.
pub const OBSTACLE: Color = Color::new(0.55, 0.58, 0.66, 1.0);
/// Laser beams.
pub const LASER: Color = Color::new(0.35, 0.95, 1.0, 1.0);

/// The brick ramp, from one hit point (cool) to the most the board can hold (hot).
const RAMP: [Color; 5] = [
    Color::new(0.20, 0.80, 0.55, 1.0),
    Color::new(0.95, 0.80, 0.20, 1.0),
    Color::new(0.98, 0.50, 0.18, 1.0),
    Color::new(0.92, 0.22, 0.30, 1.0),
    Color::new(0.75, 0.20, 0.85, 1.0),
];

/// The colour of a brick with `hp` hit points when the hardest brick of the level has
/// `max_hp`: the ramp is spread over `1..=max_hp`, so colour follows hit points, and the
/// hardest bricks are always the hottest.
pub fn brick(hp: u32, max_hp: u32) -> Color {
    let max_hp = max_hp.max(hp).max(1);
    let t = if max_hp == 1 {
        0.0
    } else {
        (hp.max(1) - 1) as f32 / (max_hp - 1) as f32
    };
    let scaled = t * (RAMP.len() - 1) as f32;
    let i = (scaled.floor() as usize).min(RAMP.len() - 2);
    mix(RAMP[i], RAMP[i + 1], scaled - i as f32)
}

/// Linear interpolation of two colours.
pub fn mix(a: Color, b: Color, t: f32) -> Color {
    let t = t.clamp(0.0, 1.0);
    Color::new(
        a.r + (b.r - a.r) * t,
        a.g + (b.g - a.g) * t,
        a.b + (b.b - a.b) * t,
        a.a + (b.a - a.a) * t,
    )
}

/// `c` with alpha `a`.
pub fn with_alpha(c: Color, a: f32) -> Color {
    Color::new(c.r, c.g, c.b, a.clamp(0.0, 1.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn same(a: Color, b: Color) -> bool {
        (a.r - b.r).abs() + (a.g - b.g).abs() + (a.b - b.b).abs() < 1e-5
    }

    #[test]
    fn the_ramp_runs_from_cool_to_hot() {
        assert!(same(brick(1, 30), RAMP[0]));
        assert!(same(brick(30, 30), RAMP[4]));
        assert!(same(brick(1, 1), RAMP[0]));
    }

    #[test]
    fn colour_changes_with_every_hit_point_step() {
        let colours: Vec<Color> = (1..=12).map(|hp| brick(hp, 12)).collect();
        for pair in colours.windows(2) {
            assert!(!same(pair[0], pair[1]));
        }
    }

    #[test]
    fn out_of_range_hit_points_stay_on_the_ramp() {
        assert!(same(brick(0, 10), RAMP[0]));
        assert!(same(brick(50, 10), RAMP[4]));
    }

    #[test]
    fn bricks_stand_out_from_the_board() {
        for hp in 1..=20 {
            let c = brick(hp, 20);
            let contrast = (c.r - BOARD.r).abs() + (c.g - BOARD.g).abs() + (c.b - BOARD.b).abs();
            assert!(contrast > 0.8, "hp {hp}");
        }
    }
}
