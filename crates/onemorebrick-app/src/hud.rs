//! The HUD (level, score, best score), the hint under the board and the notices panel.

use macroquad::color::Color;
use macroquad::math::{Rect, Vec2};
use macroquad::shapes::draw_rectangle;
use macroquad::text::draw_text;

use crate::layout::Layout;
use crate::palette;
use crate::widgets::fitted_text;

/// Draws level, score and best score in the band above the board.
pub fn draw_hud(layout: &Layout, level: u32, score: u64, best: u64) {
    let h = layout.hud;
    let size = h.h * 0.42;
    let y = h.y + h.h * 0.62;
    draw_text(format!("LEVEL {level}"), h.x, y, size, palette::TEXT);
    // Between the level and the best score, however many digits.
    let centre = Vec2::new(h.center().x, h.center().y);
    fitted_text(
        &score.to_string(),
        centre,
        h.h * 0.6,
        h.w * 0.22,
        palette::TEXT,
    );
    // Right of the score, left of the pause button (a square as high as 0.7 of the band).
    let best_text = format!("BEST {best}");
    let left = h.center().x + h.w * 0.12;
    let right = h.right() - h.h * 0.85;
    let centre = Vec2::new((left + right) / 2.0, h.y + h.h * 0.5);
    fitted_text(
        &best_text,
        centre,
        size * 0.8,
        right - left,
        palette::TEXT_DIM,
    );
}

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
    let width = ((layout.board.w / (size * 0.5)) as usize).max(20);
    let mut lines: Vec<String> = notices.iter().flat_map(|n| wrap(n, width)).collect();
    lines.push("(click or press any key to dismiss)".to_owned());
    let r = notice_rect(layout, lines.len());
    draw_rectangle(r.x, r.y, r.w, r.h, Color::new(0.45, 0.12, 0.10, 0.95));
    for (k, line) in lines.iter().enumerate() {
        let y = r.y + layout.cell * 0.32 * (k as f32 + 1.2);
        draw_text(line, r.x + size * 0.5, y, size, palette::TEXT);
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
