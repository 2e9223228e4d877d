//! Colours: the background, the brick ramp that follows hit points, the pick-ups' colours
//! and labels. RGBA in `0..=1`, the red, green and blue as written to the screen (sRGB).

use onemorebrick::{Board, PickupKind};

/// A colour: red, green, blue, alpha in `0..=1`.
pub type Rgba = [f32; 4];

/// The window's background.
pub const BACKGROUND: Rgba = [0.07, 0.08, 0.12, 1.0];
/// The board's background.
pub const BOARD: Rgba = [0.11, 0.12, 0.18, 1.0];
/// Text and the launcher.
pub const TEXT: Rgba = [0.95, 0.95, 0.97, 1.0];
/// Dimmed text.
pub const TEXT_DIM: Rgba = [0.62, 0.65, 0.72, 1.0];
/// A brick's hit points in the game window: white, bold, on every colour of the [`RAMP`]
/// (see [`contrast`]).
pub const NUMBER: Rgba = [0.98, 0.98, 1.0, 1.0];
/// A brick's hit points in the Python frames: nearly black, in thin outline text (their
/// pixel tests find the numbers as the dark pixels inside a brick); it also clears 3:1 on
/// every ramp colour.
pub const HP_TEXT: Rgba = [0.06, 0.06, 0.10, 1.0];
/// Balls.
pub const BALL: Rgba = [0.96, 0.97, 1.0, 1.0];
/// The aim preview.
pub const PREVIEW: Rgba = [1.0, 1.0, 1.0, 0.75];
/// Round obstacles.
pub const OBSTACLE: Rgba = [0.55, 0.58, 0.66, 1.0];
/// Laser beams.
pub const LASER: Rgba = [0.35, 0.95, 1.0, 1.0];

/// The brick ramp, from one hit point (cool) to the most the board can hold (hot): a walk
/// round the hue wheel (green, teal, blue, violet, magenta, red, orange) at one lightness, so
/// that neighbouring bands differ in hue, every colour holds white numbers (and the Python
/// frames' dark ones) at a contrast of at least 3:1 and stands out from the board (at least
/// 3:1).
pub const RAMP: [Rgba; 7] = [
    [0.12, 0.60, 0.36, 1.0],
    [0.04, 0.54, 0.62, 1.0],
    [0.18, 0.44, 0.92, 1.0],
    [0.52, 0.36, 0.94, 1.0],
    [0.78, 0.24, 0.74, 1.0],
    [0.90, 0.20, 0.36, 1.0],
    [0.92, 0.38, 0.08, 1.0],
];

/// The colour of a brick with `hp` hit points when the hardest brick of the level has
/// `max_hp`: the ramp is spread over `1..=max_hp`, so colour follows hit points, and the
/// hardest bricks are always the hottest.
pub fn brick(hp: u32, max_hp: u32) -> Rgba {
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

/// The hit points the hottest colour stands for at `level`: the spawn's maximum, three times
/// the level, or more if the board holds more. A new row's bricks (one, two or three times
/// the level) so fall at a third, two thirds and the end of the ramp at every level, three
/// hues apart; bricks worn down slide toward the cool end.
pub fn ramp_top(board: &Board, level: u32) -> u32 {
    board
        .bricks()
        .map(|(_, b)| b.hp)
        .max()
        .unwrap_or(1)
        .max(level.saturating_mul(3))
}

/// The relative luminance of a colour (WCAG 2: its sRGB channels made linear, weighted).
pub fn luminance(c: Rgba) -> f32 {
    let linear = |v: f32| {
        if v <= 0.040_45 {
            v / 12.92
        } else {
            ((v + 0.055) / 1.055).powf(2.4)
        }
    };
    0.2126 * linear(c[0]) + 0.7152 * linear(c[1]) + 0.0722 * linear(c[2])
}

/// The WCAG 2 contrast ratio of two opaque colours, from 1 (the same) to 21 (black and
/// white).
pub fn contrast(a: Rgba, b: Rgba) -> f32 {
    let (la, lb) = (luminance(a), luminance(b));
    (la.max(lb) + 0.05) / (la.min(lb) + 0.05)
}

/// Linear interpolation of two colours, `t` clamped to `0..=1`.
pub fn mix(a: Rgba, b: Rgba, t: f32) -> Rgba {
    let t = t.clamp(0.0, 1.0);
    std::array::from_fn(|k| a[k] + (b[k] - a[k]) * t)
}

/// `c` with alpha `a` (clamped to `0..=1`).
pub fn with_alpha(c: Rgba, a: f32) -> Rgba {
    [c[0], c[1], c[2], a.clamp(0.0, 1.0)]
}

/// A pick-up's colour and the short label drawn in it (empty for the lasers, drawn as
/// their beams' directions).
pub fn pickup(kind: PickupKind) -> (Rgba, &'static str) {
    use PickupKind as K;
    match kind {
        K::ExtraBall => ([0.30, 0.90, 0.45, 1.0], "+1"),
        K::Split => ([0.98, 0.85, 0.25, 1.0], "x2"),
        K::Hazard => ([0.95, 0.25, 0.25, 1.0], "X"),
        K::FloorBounce => ([0.45, 0.75, 1.0, 1.0], "^"),
        K::LaserHorizontal | K::LaserVertical | K::LaserCross => (LASER, ""),
        K::RandomDirection => ([0.80, 0.50, 1.0, 1.0], "?"),
        K::Bigger => ([1.0, 0.60, 0.30, 1.0], "B+"),
        K::Smaller => ([1.0, 0.60, 0.30, 1.0], "b-"),
        K::Boost => ([1.0, 0.45, 0.70, 1.0], ">>"),
        K::Shield => ([0.40, 0.60, 1.0, 1.0], "S"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use onemorebrick::{Brick, Cell, Shape};

    fn same(a: Rgba, b: Rgba) -> bool {
        (a[0] - b[0]).abs() + (a[1] - b[1]).abs() + (a[2] - b[2]).abs() < 1e-5
    }

    #[test]
    fn the_ramp_runs_from_cool_to_hot() {
        assert!(same(brick(1, 30), RAMP[0]));
        assert!(same(brick(30, 30), RAMP[RAMP.len() - 1]));
        assert!(same(brick(1, 1), RAMP[0]));
    }

    #[test]
    fn colour_changes_with_every_hit_point_step() {
        let colours: Vec<Rgba> = (1..=12).map(|hp| brick(hp, 12)).collect();
        for pair in colours.windows(2) {
            assert!(!same(pair[0], pair[1]));
        }
    }

    #[test]
    fn out_of_range_hit_points_stay_on_the_ramp() {
        assert!(same(brick(0, 10), RAMP[0]));
        assert!(same(brick(50, 10), RAMP[RAMP.len() - 1]));
    }

    /// Every colour the ramp can give: its stops and 40 steps between each pair.
    fn ramp_colours() -> Vec<Rgba> {
        (0..=240).map(|k| brick(k + 1, 241)).collect()
    }

    #[test]
    fn the_contrast_ratio_matches_wcag_examples() {
        let (black, white) = ([0.0, 0.0, 0.0, 1.0], [1.0, 1.0, 1.0, 1.0]);
        assert!((contrast(black, white) - 21.0).abs() < 1e-3);
        assert!((contrast(white, white) - 1.0).abs() < 1e-6);
        // #767676 on white is the classic 4.54:1.
        let grey = [118.0 / 255.0; 4];
        assert!((contrast(grey, white) - 4.54).abs() < 0.01);
    }

    /// The floor for the numbers on the bricks: WCAG AA asks 4.5:1 of body text and 3:1 of
    /// large text (24 px, or 18.7 px bold). A brick's number is large text: bold, at least
    /// half a cell high for up to three digits (over 30 px in the default window); a white
    /// that clears 4.5:1 on every brick would leave only dark, dull bricks (no orange or
    /// green holds it), which is what the originals' bright bricks avoid.
    const NUMBER_FLOOR: f32 = 3.0;

    #[test]
    fn numbers_are_readable_on_every_ramp_colour() {
        for c in ramp_colours() {
            for ink in [NUMBER, HP_TEXT] {
                let ratio = contrast(ink, c);
                assert!(ratio >= NUMBER_FLOOR, "{ink:?} on {c:?}: {ratio:.2}:1");
            }
        }
    }

    #[test]
    fn bricks_stand_out_from_the_board() {
        // WCAG's 3:1 for the parts of an interface one must see (non-text contrast).
        for c in ramp_colours() {
            let ratio = contrast(BOARD, c);
            assert!(ratio >= 3.0, "{c:?}: {ratio:.2}:1");
        }
    }

    /// The distance of two colours (sRGB, Euclidean).
    fn distance(a: Rgba, b: Rgba) -> f32 {
        (0..3).map(|k| (a[k] - b[k]).powi(2)).sum::<f32>().sqrt()
    }

    #[test]
    fn a_new_rows_three_kinds_of_brick_differ_at_every_level() {
        for level in (1..=60).chain([99, 250, 1000, 5000, 1_000_000]) {
            let top = level * 3;
            let [one, two, three] = [1, 2, 3].map(|k| brick(level * k, top));
            for (a, b) in [(one, two), (two, three), (one, three)] {
                assert!(distance(a, b) > 0.35, "level {level}: {a:?} {b:?}");
            }
        }
    }

    #[test]
    fn neighbouring_stops_differ_in_hue() {
        for pair in RAMP.windows(2) {
            assert!(distance(pair[0], pair[1]) > 0.25, "{pair:?}");
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
            .map(|k| pickup(*k).1)
            .collect();
        for (i, a) in looks.iter().enumerate() {
            assert!(!a.is_empty());
            assert!(!looks[i + 1..].contains(a), "{a}");
        }
    }
}
