//! Where things go on the screen: the board keeps its aspect ratio and scales to the
//! window, with a HUD band above it and a control band below. Pure maths, no drawing.

use macroquad::math::{Rect, Vec2};
use onemorebrick::DVec2;

/// Height of the HUD band above the board, in cells.
const HUD_CELLS: f32 = 1.2;
/// Height of the control band below the board, in cells.
const CONTROL_CELLS: f32 = 1.2;
/// Margin around everything, in cells.
const MARGIN_CELLS: f32 = 0.25;

/// The screen layout for one frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Layout {
    /// The board's rectangle on screen.
    pub board: Rect,
    /// The HUD band above the board.
    pub hud: Rect,
    /// The control band below the board.
    pub controls: Rect,
    /// Pixels per cell.
    pub cell: f32,
    /// Board height in cells (to flip y: the board's y grows upward).
    rows: f32,
}

impl Layout {
    /// The layout of a `columns x rows` board in a `width x height` screen: the largest cell
    /// size that fits the board, the bands and the margins, centred.
    pub fn new(width: f32, height: f32, columns: u32, rows: u32) -> Self {
        let (cols, rows) = (columns as f32, rows as f32);
        let across = cols + 2.0 * MARGIN_CELLS;
        let down = rows + HUD_CELLS + CONTROL_CELLS + 2.0 * MARGIN_CELLS;
        let cell = (width / across).min(height / down).max(1.0);
        let board_w = cols * cell;
        let board_h = rows * cell;
        let x = (width - board_w) / 2.0;
        let total_h = (rows + HUD_CELLS + CONTROL_CELLS) * cell;
        let top = (height - total_h) / 2.0;
        let hud = Rect::new(x, top, board_w, HUD_CELLS * cell);
        let board = Rect::new(x, hud.bottom(), board_w, board_h);
        let controls = Rect::new(x, board.bottom(), board_w, CONTROL_CELLS * cell);
        Self {
            board,
            hud,
            controls,
            cell,
            rows,
        }
    }

    /// A board point (cells, y up) on screen (pixels, y down).
    pub fn to_screen(self, p: DVec2) -> Vec2 {
        Vec2::new(
            self.board.x + p.x as f32 * self.cell,
            self.board.y + (self.rows - p.y as f32) * self.cell,
        )
    }

    /// A screen point as a board point.
    pub fn to_board(self, p: Vec2) -> DVec2 {
        DVec2::new(
            f64::from((p.x - self.board.x) / self.cell),
            f64::from(self.rows - (p.y - self.board.y) / self.cell),
        )
    }

    /// A length in cells as pixels.
    pub fn px(&self, cells: f64) -> f32 {
        cells as f32 * self.cell
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_board_keeps_its_aspect_ratio_in_any_window() {
        for (w, h) in [
            (800.0, 600.0),
            (600.0, 1200.0),
            (3000.0, 900.0),
            (333.0, 777.0),
        ] {
            let l = Layout::new(w, h, 7, 9);
            assert!((l.board.w / l.board.h - 7.0 / 9.0).abs() < 1e-4, "{w}x{h}");
            assert!(l.hud.y >= 0.0 && l.controls.bottom() <= h + 1e-3, "{w}x{h}");
            assert!(l.board.x >= 0.0 && l.board.right() <= w + 1e-3, "{w}x{h}");
        }
    }

    #[test]
    fn the_board_scales_with_the_window() {
        let small = Layout::new(400.0, 600.0, 7, 9);
        let big = Layout::new(800.0, 1200.0, 7, 9);
        assert!((big.cell / small.cell - 2.0).abs() < 1e-4);
    }

    #[test]
    fn board_and_screen_coordinates_round_trip_with_y_flipped() {
        let l = Layout::new(700.0, 1000.0, 7, 9);
        let bottom_left = l.to_screen(DVec2::ZERO);
        assert!((bottom_left - Vec2::new(l.board.x, l.board.bottom())).length() < 1e-3);
        let top_right = l.to_screen(DVec2::new(7.0, 9.0));
        assert!((top_right - Vec2::new(l.board.right(), l.board.y)).length() < 1e-3);
        let p = DVec2::new(2.25, 6.5);
        assert!((l.to_board(l.to_screen(p)) - p).length() < 1e-4);
    }

    #[test]
    fn the_bands_sit_above_and_below_the_board() {
        let l = Layout::new(700.0, 1000.0, 7, 9);
        assert_eq!(l.hud.bottom(), l.board.y);
        assert_eq!(l.controls.y, l.board.bottom());
    }
}
