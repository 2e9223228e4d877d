//! Cards: the opaque panels of the menu screens (pause, settings, confirmations, game over)
//! over the dimmed board. A card has a large title, optionally the score in big figures with
//! the best score or a "new best" celebration, then up to [`MAX_LINES`] lines of information;
//! its buttons are stacked from its bottom edge up. Its height fits that much, centred on
//! the board. Where everything goes is pure maths ([`arrange`],
//! [`button_rects`]); [`draw`] paints it.

use macroquad::color::Color;
use macroquad::math::{Rect, Vec2};
use macroquad::shapes::{draw_rectangle, draw_rectangle_lines, draw_triangle};

use crate::layout::Layout;
use crate::palette;
use crate::widgets::fitted_text;

/// The card's fill (opaque: nothing of the board shows through).
pub const FILL: Color = Color::new(0.15, 0.16, 0.23, 1.0);
/// The dimming over the board behind a card.
pub const DIM: Color = Color::new(0.02, 0.02, 0.05, 0.78);
/// The celebration's gold.
pub const GOLD: Color = Color::new(1.0, 0.82, 0.28, 1.0);
/// The card's margin inside the board, in cells.
const INSET: f32 = 0.25;
/// The most lines of information a card shows (room is kept for them).
pub const MAX_LINES: usize = 2;
/// Space between the text and the buttons, in cells.
const MIDDLE: f32 = 0.4;
/// Space above the title, in cells.
const TOP: f32 = 0.3;
/// Heights of the rows, in cells: title, score label, score, best score, a line.
const TITLE: f32 = 1.1;
const SCORE_LABEL: f32 = 0.45;
const SCORE: f32 = 1.3;
const BEST: f32 = 0.65;
const LINE: f32 = 0.5;
/// Buttons: height, gap, the margin under the last one (cells) and their share of the width.
const BUTTON: f32 = 0.78;
const GAP: f32 = 0.24;
const BOTTOM: f32 = 0.35;
const BUTTON_WIDTH: f32 = 0.86;

/// The score shown on a card.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Score {
    /// This game's score.
    pub score: u64,
    /// The best score ever.
    pub best: u64,
    /// Whether the score is a new best (celebrated).
    pub new_best: bool,
}

/// What a card says.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Card {
    /// The title, large.
    pub title: String,
    /// The score, in big figures (game over).
    pub score: Option<Score>,
    /// Lines of information under the title (or the score), one per row.
    pub lines: Vec<String>,
}

/// Where a card's parts go.
#[derive(Clone, Debug, PartialEq)]
pub struct Arranged {
    /// The card itself.
    pub card: Rect,
    /// The title's row.
    pub title: Rect,
    /// The score's label, figures and best-score rows.
    pub score: Option<[Rect; 3]>,
    /// One row per line.
    pub lines: Vec<Rect>,
}

/// The card's rectangle, for a card with a score (`scored`) or not and `buttons` buttons:
/// as high as its text and buttons, centred on the board, never beyond a margin inside it.
pub fn card_rect(layout: &Layout, scored: bool, buttons: usize) -> Rect {
    let (b, m) = (layout.board, INSET * layout.cell);
    let score = if scored {
        SCORE_LABEL + SCORE + BEST
    } else {
        0.0
    };
    let text = TOP + TITLE + score + MAX_LINES as f32 * LINE;
    let cells = text + MIDDLE + buttons_height(buttons) + BOTTOM;
    let h = (cells * layout.cell).min(b.h - 2.0 * m);
    Rect::new(b.x + m, b.y + (b.h - h) / 2.0, b.w - 2.0 * m, h)
}

/// The height of `count` stacked buttons, in cells.
fn buttons_height(count: usize) -> f32 {
    count as f32 * BUTTON + count.saturating_sub(1) as f32 * GAP
}

/// A row of `cells` height across the card, `y` pixels down, advancing `y`.
fn row(card: Rect, cell: f32, y: &mut f32, cells: f32) -> Rect {
    let r = Rect::new(card.x, *y, card.w, cells * cell);
    *y += cells * cell;
    r
}

/// Where `card`'s text goes, from the top down, on a card with `buttons` buttons.
pub fn arrange(layout: &Layout, card: &Card, buttons: usize) -> Arranged {
    let rect = card_rect(layout, card.score.is_some(), buttons);
    let cell = layout.cell;
    let mut y = rect.y + TOP * cell;
    let title = row(rect, cell, &mut y, TITLE);
    let score = card.score.map(|_| {
        [
            row(rect, cell, &mut y, SCORE_LABEL),
            row(rect, cell, &mut y, SCORE),
            row(rect, cell, &mut y, BEST),
        ]
    });
    let lines = card
        .lines
        .iter()
        .take(MAX_LINES)
        .map(|_| row(rect, cell, &mut y, LINE))
        .collect();
    Arranged {
        card: rect,
        title,
        score,
        lines,
    }
}

/// `count` buttons' rectangles, stacked up from the bottom edge of a card with a score
/// (`scored`) or not, top to bottom.
pub fn button_rects(layout: &Layout, scored: bool, count: usize) -> Vec<Rect> {
    let (card, cell) = (card_rect(layout, scored, count), layout.cell);
    let (h, gap) = (BUTTON * cell, GAP * cell);
    let w = card.w * BUTTON_WIDTH;
    let top = card.bottom() - (BOTTOM + buttons_height(count)) * cell;
    (0..count)
        .map(|i| {
            Rect::new(
                card.x + (card.w - w) / 2.0,
                top + i as f32 * (h + gap),
                w,
                h,
            )
        })
        .collect()
}

/// Dims the board and draws `card` (with room for `buttons` buttons) on it; `time`
/// (seconds) moves the celebration.
pub fn draw(layout: &Layout, card: &Card, buttons: usize, time: f32) {
    let b = layout.board;
    draw_rectangle(b.x, b.y, b.w, b.h, DIM);
    let a = arrange(layout, card, buttons);
    let r = a.card;
    draw_rectangle(r.x, r.y, r.w, r.h, FILL);
    let celebrating = card.score.is_some_and(|s| s.new_best);
    let edge = if celebrating { GOLD } else { palette::TEXT_DIM };
    draw_rectangle_lines(r.x, r.y, r.w, r.h, (layout.cell * 0.05).max(2.0), edge);
    let width = r.w * 0.9;
    let text = |s: &str, row: Rect, share: f32, colour| {
        fitted_text(s, row.center(), row.h * share, width, colour);
    };
    text(&card.title, a.title, 0.72, palette::TEXT);
    if let (Some(score), Some([label, figures, best])) = (card.score, a.score) {
        text("SCORE", label, 0.7, palette::TEXT_DIM);
        text(&score.score.to_string(), figures, 0.85, palette::TEXT);
        if score.new_best {
            celebrate(figures, best, time);
        } else {
            text(
                &format!("Best {}", score.best),
                best,
                0.62,
                palette::TEXT_DIM,
            );
        }
    }
    for (line, row) in card.lines.iter().zip(&a.lines) {
        text(line, *row, 0.62, palette::TEXT_DIM);
    }
}

/// "New best!" in gold, beating, with sparkles beside the score.
fn celebrate(figures: Rect, best: Rect, time: f32) {
    let beat = 1.0 + 0.08 * (time * 6.0).sin();
    fitted_text(
        "NEW BEST!",
        best.center(),
        best.h * 0.7 * beat,
        best.w * 0.9,
        GOLD,
    );
    // Three twinkling sparkles on each side of the figures, clear of the text rows.
    let centre = figures.center();
    for k in 0..6 {
        let side = if k < 3 { -1.0 } else { 1.0 };
        let step = (k % 3) as f32 - 1.0;
        let x = centre.x + side * figures.w * (0.36 - 0.04 * step.abs());
        let p = Vec2::new(x, centre.y + step * figures.h * 0.3);
        let twinkle = 0.7 + 0.3 * (time * 5.0 + k as f32).sin();
        sparkle(p, figures.h * 0.16 * twinkle, GOLD);
    }
}

/// A four-pointed star of `size` half-height at `p`.
fn sparkle(p: Vec2, size: f32, colour: Color) {
    let thin = size * 0.28;
    for (long, short) in [(Vec2::Y, Vec2::X), (Vec2::X, Vec2::Y)] {
        let (tip, side) = (long * size, short * thin);
        draw_triangle(p + tip, p + side, p - side, colour);
        draw_triangle(p - tip, p + side, p - side, colour);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn biggest_card() -> Card {
        Card {
            title: "Game over".to_owned(),
            score: Some(Score {
                score: 1,
                best: 2,
                new_best: false,
            }),
            lines: vec!["Seed 123".to_owned(), "Level 40".to_owned()],
        }
    }

    fn inside(inner: Rect, outer: Rect) -> bool {
        inner.x >= outer.x - 1e-3
            && inner.y >= outer.y - 1e-3
            && inner.right() <= outer.right() + 1e-3
            && inner.bottom() <= outer.bottom() + 1e-3
    }

    #[test]
    fn the_card_lies_on_the_board_inside_any_window() {
        for (w, h) in [(540.0, 860.0), (1000.0, 500.0), (333.0, 777.0)] {
            let layout = Layout::new(w, h, 7, 9);
            for (scored, buttons) in [(true, 3), (false, 5), (false, 2)] {
                let r = card_rect(&layout, scored, buttons);
                assert!(inside(r, layout.board), "{w}x{h}");
                assert!(r.x >= 0.0 && r.right() <= w && r.y >= 0.0 && r.bottom() <= h);
                assert!(r.w > layout.board.w * 0.8, "{w}x{h}");
                let middle = r.center().y - layout.board.center().y;
                assert!(middle.abs() < 1e-3, "centred on the board");
            }
            let small = card_rect(&layout, false, 2);
            assert!(
                small.h < card_rect(&layout, true, 3).h,
                "as high as it needs"
            );
        }
    }

    #[test]
    fn text_and_buttons_stay_in_the_card_and_apart() {
        // The most a card holds: a score with two lines over three buttons, or two lines
        // over the pause menu's five.
        for (w, h) in [(540.0, 860.0), (1000.0, 500.0), (333.0, 777.0)] {
            let layout = Layout::new(w, h, 7, 9);
            let scored = biggest_card();
            let paused = Card {
                score: None,
                ..biggest_card()
            };
            for (card, buttons) in [(scored, 3), (paused, 5)] {
                let a = arrange(&layout, &card, buttons);
                let rects = button_rects(&layout, card.score.is_some(), buttons);
                let mut text = vec![a.title];
                text.extend(a.score.into_iter().flatten());
                text.extend(a.lines.iter().copied());
                for pair in text.windows(2) {
                    assert!(pair[0].bottom() <= pair[1].y + 1e-3);
                }
                let last = text.last().unwrap();
                assert!(
                    last.bottom() <= rects[0].y,
                    "{w}x{h}: text runs into buttons"
                );
                for pair in rects.windows(2) {
                    assert!(pair[0].bottom() < pair[1].y);
                }
                for r in text.iter().chain(&rects) {
                    assert!(inside(*r, a.card), "{w}x{h}: {r:?} outside {:?}", a.card);
                }
            }
        }
    }

    #[test]
    fn a_card_without_a_score_has_no_score_rows() {
        let layout = Layout::new(540.0, 860.0, 7, 9);
        let card = Card {
            title: "Paused".to_owned(),
            score: None,
            lines: Vec::new(),
        };
        let a = arrange(&layout, &card, 2);
        assert!(a.score.is_none() && a.lines.is_empty());
        let many = Card {
            lines: vec!["a".to_owned(); MAX_LINES + 3],
            ..card
        };
        assert_eq!(arrange(&layout, &many, 2).lines.len(), MAX_LINES);
    }
}
