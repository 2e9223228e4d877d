//! The danger warning: bricks that the next shift of the board would bring into the bottom
//! row, which ends the game, get a pulsing red edge, and a red line runs along the top of
//! the bottom row. Nothing is marked otherwise, so the mark always means "one more step".

use macroquad::color::Color;
use macroquad::shapes::draw_line;
use onemorebrick::cell::outline;
use onemorebrick::{Board, Cell, DVec2};
use onemorebrick_look as look;

use crate::layout::Layout;
use crate::palette;

/// The warning's red (unlike any brick or pick-up colour).
pub const DANGER: Color = Color::new(1.0, 0.12, 0.12, 1.0);
/// Seconds of one pulse of the warning.
const PULSE: f32 = 0.9;

/// The indices of the bricks that the next round's shift would bring into the bottom row,
/// which ends the game: decided by the rules' own shift (`Board::shift_down`) on a copy.
pub fn endangered(board: &Board) -> Vec<usize> {
    let mut next = board.clone();
    if !next.shift_down().brick_reached_bottom {
        return Vec::new();
    }
    (0..board.columns())
        .filter(|&c| matches!(next.get(c, 0), Some(Cell::Brick(_))))
        .filter_map(|c| board.index(c, 1))
        .collect()
}

/// The warning's opacity `time` seconds into the pulse: full at 0 (a screenshot's still
/// frame), never below 0.45 so it stays visible.
pub fn pulse(time: f32) -> f32 {
    0.725 + 0.275 * (time * std::f32::consts::TAU / PULSE).cos()
}

/// Draws the warning over the board, if any brick is one step from the bottom.
pub fn draw(layout: &Layout, board: &Board, time: f32) {
    let bricks = endangered(board);
    if bricks.is_empty() {
        return;
    }
    let colour = palette::with_alpha(DANGER, pulse(time));
    let width = layout.px(look::GAP * 1.4).max(2.0);
    for &index in &bricks {
        if let Cell::Brick(brick) = board.cells()[index] {
            // On the cell's own edge: the board's colour shows between it and the brick
            // (drawn `GAP` inside), so the edge stands out on a red brick too.
            let outline = outline(brick.shape, board.origin(index));
            for k in 0..outline.len() {
                let a = layout.to_screen(outline[k]);
                let b = layout.to_screen(outline[(k + 1) % outline.len()]);
                draw_line(a.x, a.y, b.x, b.y, width, colour);
            }
        }
    }
    danger_line(layout, board.columns(), colour);
}

/// A dashed line along the top of the bottom row: the line a brick must not cross.
fn danger_line(layout: &Layout, columns: u32, colour: Color) {
    let dashes = columns * 4;
    let step = f64::from(columns) / f64::from(dashes);
    for k in 0..dashes {
        let x = f64::from(k) * step;
        let a = layout.to_screen(DVec2::new(x + step * 0.15, 1.0));
        let b = layout.to_screen(DVec2::new(x + step * 0.85, 1.0));
        draw_line(a.x, a.y, b.x, b.y, layout.px(0.05).max(1.5), colour);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use onemorebrick::{Brick, Shape};

    fn brick() -> Cell {
        Cell::Brick(Brick {
            shape: Shape::Square,
            hp: 3,
        })
    }

    #[test]
    fn only_bricks_one_row_from_the_bottom_are_in_danger() {
        let mut board = Board::new(7, 9);
        assert!(endangered(&board).is_empty());
        board.set(3, 2, brick()).unwrap();
        board.set(5, 8, brick()).unwrap();
        board.set(1, 1, Cell::Obstacle).unwrap();
        assert!(
            endangered(&board).is_empty(),
            "two rows up is not yet danger"
        );
        board.set(0, 1, brick()).unwrap();
        board.set(6, 1, brick()).unwrap();
        let expected = vec![board.index(0, 1).unwrap(), board.index(6, 1).unwrap()];
        assert_eq!(endangered(&board), expected);
    }

    #[test]
    fn the_pulse_is_full_at_rest_and_never_fades_out() {
        assert!((pulse(0.0) - 1.0).abs() < 1e-6);
        let lowest = (0..100)
            .map(|k| pulse(k as f32 * PULSE / 100.0))
            .fold(1.0, f32::min);
        assert!((0.45..0.5).contains(&lowest), "{lowest}");
    }
}
