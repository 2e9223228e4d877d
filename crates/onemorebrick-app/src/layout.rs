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

/// Where each part of the HUD band goes: level, score and best score side by side, then the
/// pause button, with gaps between them so no number can run into the next.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HudSlots {
    /// The level (its label above its number).
    pub level: Rect,
    /// The score, in the middle.
    pub score: Rect,
    /// The best score (its label above its number).
    pub best: Rect,
    /// The pause button (a square of [`PAUSE_SHARE`] of the band's height at its right).
    pub pause: Rect,
}

/// The pause button's side as a share of the HUD band's height.
pub const PAUSE_SHARE: f32 = 0.7;
/// The gap between the HUD's slots as a share of its height.
const HUD_GAP: f32 = 0.3;
/// The shares of the width left of the pause button: level, score, best score.
const HUD_SHARES: [f32; 3] = [0.27, 0.40, 0.33];

impl Layout {
    /// The HUD band's slots.
    pub fn hud_slots(&self) -> HudSlots {
        let h = self.hud;
        let size = h.h * PAUSE_SHARE;
        let pause = Rect::new(h.right() - size, h.y + (h.h - size) / 2.0, size, size);
        let gap = h.h * HUD_GAP;
        let room = (pause.x - gap - h.x - 2.0 * gap).max(0.0);
        let mut x = h.x;
        let [level, score, best] = HUD_SHARES.map(|share| {
            let r = Rect::new(x, h.y, room * share, h.h);
            x += r.w + gap;
            r
        });
        HudSlots {
            level,
            score,
            best,
            pause,
        }
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

    #[test]
    fn the_hud_slots_fill_the_band_in_order_with_gaps() {
        for (w, h) in [(540.0, 860.0), (1000.0, 500.0), (333.0, 777.0)] {
            let l = Layout::new(w, h, 7, 9);
            let s = l.hud_slots();
            let gap = l.hud.h * HUD_GAP;
            let order = [s.level, s.score, s.best, s.pause];
            for pair in order.windows(2) {
                assert!(
                    pair[1].x - pair[0].right() >= gap - 1e-3,
                    "{w}x{h}: {pair:?}"
                );
            }
            for r in order {
                assert!(r.x >= l.hud.x - 1e-3 && r.right() <= l.hud.right() + 1e-3);
                assert!(r.y >= l.hud.y - 1e-3 && r.bottom() <= l.hud.bottom() + 1e-3);
            }
            assert!((s.pause.w - l.hud.h * PAUSE_SHARE).abs() < 1e-3);
            assert!((s.pause.right() - l.hud.right()).abs() < 1e-3);
        }
    }
}
