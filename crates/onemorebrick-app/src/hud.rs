//! The HUD (level, score, best score), the hint under the board and the notices panel.

use macroquad::color::Color;
use macroquad::math::{Rect, Vec2};
use macroquad::shapes::draw_rectangle;
use onemorebrick_look as look;

use crate::layout::Layout;
use crate::palette;
use crate::text::{self, Style};
use crate::widgets::fitted_text;

/// Draws level, score and best score in the band above the board, each in its own slot
/// ([`Layout::hud_slots`]): however many digits, a number shrinks (and at worst turns
/// compact, "12.3M") to stay in its slot, so it never runs into its neighbour.
pub fn draw_hud(layout: &Layout, level: u32, score: u64, best: u64) {
    let slots = layout.hud_slots();
    labelled(slots.level, "LEVEL", u64::from(level), palette::TEXT);
    let s = slots.score;
    let score_box = Rect::new(s.x, s.y + s.h * 0.14, s.w, s.h * 0.72);
    draw_number(score, score_box, palette::TEXT);
    labelled(slots.best, "BEST", best, palette::TEXT);
}

/// A small dim label over a number, in `slot`.
fn labelled(slot: Rect, label: &str, value: u64, colour: Color) {
    let label_box = Rect::new(slot.x, slot.y + slot.h * 0.12, slot.w, slot.h * 0.22);
    let style = text::fit(label, Style::regular(slot.h), label_box.w, label_box.h, 1.0);
    let ink = text::measure(label, &style);
    // Left-aligned with the number under it, centred in its box's height.
    let origin = Vec2::new(
        label_box.x - ink.left,
        label_box.center().y - ink.centre().y,
    );
    text::draw(label, origin, &style, palette::TEXT_DIM);
    let value_box = Rect::new(slot.x, slot.y + slot.h * 0.42, slot.w, slot.h * 0.44);
    let (shown, style) = number_fit(value, value_box, Style::bold(slot.h));
    let ink = text::measure(&shown, &style);
    let origin = Vec2::new(
        value_box.x - ink.left,
        value_box.center().y - ink.centre().y,
    );
    text::draw(&shown, origin, &style, colour);
}

/// Draws `value` centred in `area`, as large as fits.
fn draw_number(value: u64, area: Rect, colour: Color) {
    let (shown, style) = number_fit(value, area, Style::bold(area.h * 2.0));
    text::draw_centred(&shown, area.center(), &style, colour);
}

/// How `value` is shown in `area`: every digit while they stand at least [`FULL_DIGITS`] of
/// the height that one digit would, else the compact form ("12.3M") if that is larger.
fn number_fit(value: u64, area: Rect, base: Style) -> (String, Style) {
    let full = value.to_string();
    let fit = |t: &str| text::fit(t, base, area.w, area.h, 1.0);
    let tallest = fit("0").size;
    let full_style = fit(&full);
    if full_style.size >= tallest * FULL_DIGITS {
        return (full, full_style);
    }
    let short = look::compact_wide(value);
    let short_style = fit(&short);
    if short_style.size > full_style.size {
        (short, short_style)
    } else {
        (full, full_style)
    }
}

/// The least share of its full height a number keeps before it turns compact.
const FULL_DIGITS: f32 = 0.6;

/// Draws a hint centred in the band below the board.
pub fn draw_hint(layout: &Layout, text: &str) {
    let c = layout.controls;
    fitted_text(text, c.center(), c.h * 0.32, c.w, palette::TEXT_DIM);
}

/// The notices panel's rectangle for `lines` wrapped lines (at the top of the board).
pub fn notice_rect(layout: &Layout, lines: usize) -> Rect {
    let b = layout.board;
    let line = layout.cell * 0.32;
    Rect::new(b.x, b.y, b.w, line * (lines as f32 + 1.6))
}

/// Draws the notices (wrapped) with a hint that a click dismisses them.
pub fn draw_notices(layout: &Layout, notices: &[String]) -> Option<Rect> {
    if notices.is_empty() {
        return None;
    }
    let size = layout.cell * 0.26;
    // Ubuntu's letters average about half the size wide; a little more, to be safe.
    let width = (((layout.board.w - size) / (size * 0.55)) as usize).max(20);
    let mut lines: Vec<String> = notices.iter().flat_map(|n| wrap(n, width)).collect();
    lines.push("(click or press any key to dismiss)".to_owned());
    let r = notice_rect(layout, lines.len());
    draw_rectangle(r.x, r.y, r.w, r.h, Color::new(0.45, 0.12, 0.10, 0.95));
    for (k, line) in lines.iter().enumerate() {
        let y = r.y + layout.cell * 0.32 * (k as f32 + 1.2);
        text::draw(
            line,
            Vec2::new(r.x + size * 0.5, y),
            &Style::regular(size),
            palette::TEXT,
        );
    }
    Some(r)
}

/// Splits `text` into lines of at most `width` characters, at spaces where it can (a
/// long path is cut wherever it must be).
pub fn wrap(text: &str, width: usize) -> Vec<String> {
    let width = width.max(1);
    let mut lines = Vec::new();
    let mut line = String::new();
    for word in text.split(' ') {
        let mut word: Vec<char> = word.chars().collect();
        while word.len() > width {
            if !line.is_empty() {
                lines.push(std::mem::take(&mut line));
            }
            lines.push(word.drain(..width).collect());
        }
        let word: String = word.into_iter().collect();
        if !line.is_empty() && line.chars().count() + 1 + word.chars().count() > width {
            lines.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(&word);
    }
    if !line.is_empty() {
        lines.push(line);
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrapping_keeps_every_word_and_the_width() {
        let text = "Your saved game could not be loaded: /home/someone/.local/share/onemorebrick/game.json: not valid";
        let lines = wrap(text, 24);
        assert!(lines.iter().all(|l| l.chars().count() <= 24), "{lines:?}");
        let joined: String = lines.concat().chars().filter(|c| *c != ' ').collect();
        let expected: String = text.chars().filter(|c| *c != ' ').collect();
        assert_eq!(joined, expected);
    }

    #[test]
    fn short_text_is_one_line() {
        assert_eq!(wrap("hello there", 40), ["hello there"]);
    }

    #[test]
    fn the_notice_panel_grows_with_its_lines() {
        let layout = Layout::new(600.0, 900.0, 7, 9);
        assert!(notice_rect(&layout, 4).h > notice_rect(&layout, 2).h);
        assert_eq!(notice_rect(&layout, 2).y, layout.board.y);
    }
}
