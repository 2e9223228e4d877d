//! The help screen: every pick-up's icon (drawn by the board's own `pickups::draw_icon`),
//! its name and its rule in one line (from `crates/onemorebrick/RULES.md`), and what the red
//! warning means. Opened from the pause menu, and once by itself on the first game.

use macroquad::math::Rect;
use macroquad::shapes::{draw_line, draw_rectangle, draw_rectangle_lines};
use onemorebrick::PickupKind;

use crate::card;
use crate::layout::Layout;
use crate::palette;
use crate::pickups;
use crate::warning;
use crate::widgets::fitted_text;

/// Margins around and inside the help card, in cells.
const MARGIN: f32 = 0.12;
/// Heights, in cells: the title, the warning's line, the back button.
const TITLE: f32 = 0.9;
const FOOTER: f32 = 0.5;
const BUTTON: f32 = 0.72;
/// Width of the icons' column, in cells.
const ICONS: f32 = 1.0;

/// A pick-up's name and its rule in one line.
pub fn entry(kind: PickupKind) -> (&'static str, &'static str) {
    use PickupKind as K;
    match kind {
        K::ExtraBall => ("+1 ball", "One more ball from the next round on."),
        K::Split => ("Split", "A ball splits in two; the copy lasts this round."),
        K::Hazard => (
            "Hazard",
            "Takes the ball out of this round (a shield saves it).",
        ),
        K::FloorBounce => (
            "Floor bounce",
            "The ball's next floor touch bounces it back up.",
        ),
        K::LaserHorizontal => (
            "Row laser",
            "Each ball through it hits every brick in its row.",
        ),
        K::LaserVertical => (
            "Column laser",
            "Each ball through it hits every brick in its column.",
        ),
        K::LaserCross => ("Cross laser", "Hits every brick in its row and its column."),
        K::RandomDirection => (
            "Random direction",
            "Sends the ball upward in a random direction.",
        ),
        K::Bigger => ("Bigger", "The ball grows to 1.5 times its size."),
        K::Smaller => ("Smaller", "The ball shrinks to two thirds of its size."),
        K::Boost => ("Boost", "The ball flies 1.5 times faster."),
        K::Shield => ("Shield", "The ball survives the next hazard it meets."),
    }
}

/// The warning's explanation, under the pick-ups.
pub const WARNING: &str = "Red edge: one more step down ends the game.";

/// One pick-up's row.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Row {
    /// The pick-up.
    pub kind: PickupKind,
    /// The whole row.
    pub rect: Rect,
    /// The icon's square.
    pub icon: Rect,
    /// The name's line.
    pub name: Rect,
    /// The rule's line.
    pub rule: Rect,
}

/// How many columns of rows: two when the window is wide enough for two boards side by
/// side (the rows are then twice as high, and their text larger).
fn columns(layout: &Layout) -> usize {
    // The board is centred: the window is as wide as the board and twice its left edge.
    let window = layout.board.w + 2.0 * layout.board.x;
    if window >= 2.0 * layout.board.w + 2.0 * MARGIN * layout.cell {
        2
    } else {
        1
    }
}

/// The help card: over the HUD, the board and the controls (twice the board's width, when
/// there are two columns), centred on the board.
pub fn card_rect(layout: &Layout) -> Rect {
    let m = MARGIN * layout.cell;
    let (top, bottom) = (layout.hud.y, layout.controls.bottom());
    let w = layout.board.w * columns(layout) as f32;
    let x = layout.board.center().x - w / 2.0;
    Rect::new(x, top + m, w, bottom - top - 2.0 * m)
}

/// The title's row.
fn title_rect(layout: &Layout) -> Rect {
    let c = card_rect(layout);
    Rect::new(c.x, c.y + MARGIN * layout.cell, c.w, TITLE * layout.cell)
}

/// The back button, at the card's bottom.
pub fn back_button(layout: &Layout) -> Rect {
    let (c, cell) = (card_rect(layout), layout.cell);
    let w = c.w * 0.6;
    let bottom = c.bottom() - MARGIN * 2.0 * cell;
    Rect::new(
        c.x + (c.w - w) / 2.0,
        bottom - BUTTON * cell,
        w,
        BUTTON * cell,
    )
}

/// The warning's line, above the button.
fn footer_rect(layout: &Layout) -> Rect {
    let (c, cell) = (card_rect(layout), layout.cell);
    let bottom = back_button(layout).y - MARGIN * cell;
    Rect::new(c.x, bottom - FOOTER * cell, c.w, FOOTER * cell)
}

/// Every pick-up's row, in `PickupKind::ALL`'s order, between the title and the warning.
pub fn rows(layout: &Layout) -> Vec<Row> {
    let (c, cell) = (card_rect(layout), layout.cell);
    let top = title_rect(layout).bottom();
    let bottom = footer_rect(layout).y;
    let columns = columns(layout);
    let per_column = PickupKind::ALL.len().div_ceil(columns);
    let h = (bottom - top) / per_column as f32;
    let w = c.w / columns as f32;
    let side = (h * 0.86).min(0.62 * cell);
    let icons = ICONS * cell;
    PickupKind::ALL
        .iter()
        .enumerate()
        .map(|(k, &kind)| {
            let x = c.x + (k / per_column) as f32 * w;
            let rect = Rect::new(x, top + (k % per_column) as f32 * h, w, h);
            let icon = Rect::new(
                x + (icons - side) / 2.0,
                rect.y + (h - side) / 2.0,
                side,
                side,
            );
            let text_x = x + icons;
            let text_w = rect.right() - text_x - MARGIN * cell;
            Row {
                kind,
                rect,
                icon,
                name: Rect::new(text_x, rect.y + h * 0.06, text_w, h * 0.46),
                rule: Rect::new(text_x, rect.y + h * 0.52, text_w, h * 0.42),
            }
        })
        .collect()
}

/// Draws the help screen over everything.
pub fn draw(layout: &Layout) {
    let c = card_rect(layout);
    let (w, h) = (
        macroquad::window::screen_width(),
        macroquad::window::screen_height(),
    );
    draw_rectangle(0.0, 0.0, w, h, card::DIM);
    draw_rectangle(c.x, c.y, c.w, c.h, card::FILL);
    draw_rectangle_lines(
        c.x,
        c.y,
        c.w,
        c.h,
        (layout.cell * 0.05).max(2.0),
        palette::TEXT_DIM,
    );
    let title = title_rect(layout);
    fitted_text(
        "Pick-ups",
        title.center(),
        title.h * 0.7,
        title.w * 0.9,
        palette::TEXT,
    );
    for (k, row) in rows(layout).iter().enumerate() {
        if k % 2 == 1 {
            let r = row.rect;
            draw_rectangle(r.x, r.y, r.w, r.h, palette::with_alpha(palette::BOARD, 0.8));
        }
        pickups::draw_icon(row.kind, row.icon.center(), row.icon.w / 2.0, 1.0);
        let (name, rule) = entry(row.kind);
        let (n, r) = (row.name, row.rule);
        fitted_text(name, n.center(), n.h * 0.8, n.w, palette::TEXT);
        fitted_text(rule, r.center(), r.h * 0.8, r.w, palette::TEXT_DIM);
    }
    let f = footer_rect(layout);
    let icons = ICONS * layout.cell;
    let y = f.center().y;
    let (a, b) = (f.x + icons * 0.2, f.x + icons * 0.8);
    draw_line(a, y, b, y, (layout.cell * 0.08).max(2.0), warning::DANGER);
    let text = Rect::new(f.x + icons, f.y, f.w - icons - MARGIN * layout.cell, f.h);
    fitted_text(WARNING, text.center(), f.h * 0.55, text.w, palette::TEXT);
}

#[cfg(test)]
mod tests {
    use super::*;
    use onemorebrick::Config;

    fn inside(inner: Rect, outer: Rect) -> bool {
        inner.x >= outer.x - 1e-3
            && inner.y >= outer.y - 1e-3
            && inner.right() <= outer.right() + 1e-3
            && inner.bottom() <= outer.bottom() + 1e-3
    }

    #[test]
    fn every_pick_up_has_a_row_inside_the_window_and_none_overlap() {
        for (w, h) in [
            (540.0, 860.0),
            (1000.0, 500.0),
            (333.0, 777.0),
            (1600.0, 1000.0),
        ] {
            let layout = Layout::new(w, h, 7, 9);
            let card = card_rect(&layout);
            assert!(card.x >= 0.0 && card.y >= 0.0 && card.right() <= w && card.bottom() <= h);
            let rows = rows(&layout);
            let kinds: Vec<PickupKind> = rows.iter().map(|r| r.kind).collect();
            assert_eq!(kinds, PickupKind::ALL);
            for row in &rows {
                for part in [row.icon, row.name, row.rule] {
                    assert!(
                        inside(part, row.rect),
                        "{w}x{h}: {part:?} not in {:?}",
                        row.rect
                    );
                }
                assert!(inside(row.rect, card));
                assert!(row.icon.right() <= row.name.x && row.name.bottom() <= row.rule.y + 1e-3);
                assert!(row.icon.w > layout.cell * 0.3, "{w}x{h}: icons too small");
            }
            for (i, a) in rows.iter().enumerate() {
                for b in &rows[i + 1..] {
                    let overlap = a.rect.x + 1e-3 < b.rect.right()
                        && b.rect.x + 1e-3 < a.rect.right()
                        && a.rect.y + 1e-3 < b.rect.bottom()
                        && b.rect.y + 1e-3 < a.rect.bottom();
                    assert!(!overlap, "{w}x{h}: {:?} and {:?}", a.kind, b.kind);
                }
            }
            let title = title_rect(&layout);
            let (footer, back) = (footer_rect(&layout), back_button(&layout));
            let first = rows.iter().map(|r| r.rect.y).fold(f32::MAX, f32::min);
            let last = rows.iter().map(|r| r.rect.bottom()).fold(0.0, f32::max);
            assert!(title.bottom() <= first + 1e-3);
            assert!(last <= footer.y + 1e-3);
            assert!(footer.bottom() <= back.y && inside(back, card));
        }
    }

    #[test]
    fn a_wide_window_has_two_columns_of_taller_rows() {
        let narrow = Layout::new(540.0, 860.0, 7, 9);
        let wide = Layout::new(1000.0, 500.0, 7, 9);
        assert_eq!((columns(&narrow), columns(&wide)), (1, 2));
        let (n, w) = (rows(&narrow), rows(&wide));
        let relative = |r: &Row, l: &Layout| r.rect.h / l.cell;
        assert!(relative(&w[0], &wide) > 1.8 * relative(&n[0], &narrow));
        assert!(w[6].rect.x > w[0].rect.right() - 1e-3, "the second column");
    }

    #[test]
    fn names_are_distinct_and_rules_fit_one_line() {
        let mut names: Vec<&str> = PickupKind::ALL.iter().map(|k| entry(*k).0).collect();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), PickupKind::ALL.len());
        for kind in PickupKind::ALL {
            assert!(entry(kind).1.len() <= 55, "{kind:?}: a rule for one line");
        }
    }

    #[test]
    fn the_rules_numbers_are_the_defaults() {
        let c = Config::default();
        assert!((c.big_radius / c.ball_radius - 1.5).abs() < 1e-9);
        assert!((c.small_radius / c.ball_radius - 2.0 / 3.0).abs() < 1e-9);
        assert_eq!(c.boost_factor, 1.5);
        assert!(entry(PickupKind::Bigger).1.contains("1.5"));
        assert!(entry(PickupKind::Boost).1.contains("1.5"));
    }
}
