//! The HUD (level, score, best score), the hint under the board and the notices panel.

use macroquad::color::Color;
use macroquad::math::{Rect, Vec2};
use macroquad::shapes::draw_rectangle;
use macroquad::window::screen_dpi_scale;
use onemorebrick_look as look;

use crate::layout::Layout;
use crate::palette;
use crate::text::{self, Style};
use crate::widgets::fitted_text;

/// A text placed on the screen: what, where its pen starts (on the baseline), how and in
/// which colour.
#[derive(Clone, Debug, PartialEq)]
pub struct Placed {
    /// What it says.
    pub text: String,
    /// The pen's start on the baseline.
    pub origin: Vec2,
    /// Its style.
    pub style: Style,
    /// Its colour.
    pub colour: Color,
}

/// Draws level, score and best score in the band above the board ([`hud_texts`]).
pub fn draw_hud(layout: &Layout, level: u32, score: u64, best: u64) {
    for t in hud_texts(layout, level, score, best, screen_dpi_scale()) {
        text::draw(&t.text, t.origin, &t.style, t.colour);
    }
}

/// The HUD's texts, each in its own slot ([`Layout::hud_slots`]): however many digits, a
/// number shrinks (and at worst turns compact, "12.3M") to stay in its slot, so it never
/// runs into its neighbour.
pub fn hud_texts(layout: &Layout, level: u32, score: u64, best: u64, dpi: f32) -> Vec<Placed> {
    let slots = layout.hud_slots();
    let mut out = labelled(slots.level, "LEVEL", u64::from(level), dpi);
    let s = slots.score;
    let score_box = Rect::new(s.x, s.y + s.h * 0.14, s.w, s.h * 0.72);
    let (shown, style) = number_fit(score, score_box, Style::bold(score_box.h * 2.0), dpi);
    let ink = text::lay_out(&shown, &style, dpi).ink;
    out.push(Placed {
        text: shown,
        origin: score_box.center() - ink.centre(),
        style,
        colour: palette::TEXT,
    });
    out.extend(labelled(slots.best, "BEST", best, dpi));
    out
}

/// A small dim label over a number, both left-aligned in `slot`.
fn labelled(slot: Rect, label: &str, value: u64, dpi: f32) -> Vec<Placed> {
    let label_box = Rect::new(slot.x, slot.y + slot.h * 0.12, slot.w, slot.h * 0.22);
    let value_box = Rect::new(slot.x, slot.y + slot.h * 0.42, slot.w, slot.h * 0.44);
    let label_style = text::fit_style(
        label,
        Style::regular(slot.h),
        label_box.w,
        label_box.h,
        1.0,
        dpi,
    );
    let (shown, value_style) = number_fit(value, value_box, Style::bold(slot.h), dpi);
    let place = |t: String, style: Style, area: Rect, colour: Color| {
        let ink = text::lay_out(&t, &style, dpi).ink;
        Placed {
            origin: Vec2::new(area.x - ink.left, area.center().y - ink.centre().y),
            text: t,
            style,
            colour,
        }
    };
    vec![
        place(label.to_owned(), label_style, label_box, palette::TEXT_DIM),
        place(shown, value_style, value_box, palette::TEXT),
    ]
}

/// How `value` is shown in `area`: every digit while they stand at least [`FULL_DIGITS`] of
/// the height that one digit would, else the compact form ("12.3M") if that is larger.
fn number_fit(value: u64, area: Rect, base: Style, dpi: f32) -> (String, Style) {
    let full = value.to_string();
    let fit = |t: &str| text::fit_style(t, base, area.w, area.h, 1.0, dpi);
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
const FULL_DIGITS: f32 = 0.4;

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

    /// The screen box a placed text's ink covers.
    fn ink(t: &Placed, dpi: f32) -> Rect {
        let i = text::lay_out(&t.text, &t.style, dpi).ink;
        Rect::new(
            t.origin.x + i.left,
            t.origin.y + i.top,
            i.width(),
            i.height(),
        )
    }

    /// Whether two boxes overlap.
    fn overlap(a: Rect, b: Rect) -> bool {
        a.x < b.right() && b.x < a.right() && a.y < b.bottom() && b.y < a.bottom()
    }

    #[test]
    fn any_score_and_best_stay_in_their_slots_apart() {
        let values = [0, 7, 12_345, 123_456, 9_999_999, 123_456_789_012, u64::MAX];
        for (w, h) in [
            (540.0, 860.0),
            (320.0, 480.0),
            (1400.0, 2200.0),
            (1000.0, 500.0),
        ] {
            let layout = Layout::new(w, h, 7, 9);
            let slots = layout.hud_slots();
            for dpi in [1.0, 2.0] {
                for &score in &values {
                    for &best in values.iter().filter(|b| **b >= score) {
                        for level in [1, 345, 99_999, u32::MAX] {
                            let texts = hud_texts(&layout, level, score, best, dpi);
                            let inks: Vec<Rect> = texts.iter().map(|t| ink(t, dpi)).collect();
                            let homes = [
                                slots.level,
                                slots.level,
                                slots.score,
                                slots.best,
                                slots.best,
                            ];
                            for (ink, home) in inks.iter().zip(homes) {
                                let inside = ink.x >= home.x - 0.5
                                    && ink.right() <= home.right() + 0.5
                                    && ink.y >= home.y - 0.5
                                    && ink.bottom() <= home.bottom() + 0.5;
                                assert!(
                                    inside,
                                    "{score}/{best} at {w}x{h}: {ink:?} out of {home:?}"
                                );
                                assert!(!overlap(*ink, slots.pause));
                            }
                            for (i, a) in inks.iter().enumerate() {
                                for b in &inks[i + 1..] {
                                    assert!(!overlap(*a, *b), "{score}/{best}: {a:?} {b:?}");
                                }
                            }
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn scores_keep_every_digit_until_they_would_be_too_small() {
        let layout = Layout::new(540.0, 860.0, 7, 9);
        let texts = hud_texts(&layout, 12, 123_456, 9_999_999, 1.0);
        assert_eq!(texts[2].text, "123456");
        assert_eq!(texts[4].text, "9999999");
        let texts = hud_texts(&layout, 12, 123_456_789_012_345, u64::MAX, 1.0);
        assert_eq!(texts[2].text, "123T");
        assert_eq!(texts[4].text, "18.4E");
    }
}
