//! Buttons: a rectangle, a label, the key that does the same, and the action.

use macroquad::color::Color;
use macroquad::math::{Rect, Vec2};
use macroquad::shapes::{draw_rectangle, draw_rectangle_lines};

use crate::input::Action;
use crate::palette;
use crate::text::{self, Style};

/// A clickable button.
#[derive(Clone, Debug, PartialEq)]
pub struct Button {
    /// Where it is on screen.
    pub rect: Rect,
    /// What it says.
    pub label: String,
    /// The key that does the same (shown on the button).
    pub key: &'static str,
    /// What it does.
    pub action: Action,
}

impl Button {
    /// A button.
    pub fn new(rect: Rect, label: impl Into<String>, key: &'static str, action: Action) -> Self {
        Self {
            rect,
            label: label.into(),
            key,
            action,
        }
    }

    /// Whether a pointer at `p` is on it.
    pub fn contains(&self, p: Vec2) -> bool {
        self.rect.contains(p)
    }

    /// Draws it, highlighted when `hover`.
    pub fn draw(&self, hover: bool) {
        let r = self.rect;
        let fill = if hover {
            Color::new(0.30, 0.34, 0.48, 0.95)
        } else {
            Color::new(0.19, 0.21, 0.30, 0.95)
        };
        draw_rectangle(r.x, r.y, r.w, r.h, fill);
        draw_rectangle_lines(r.x, r.y, r.w, r.h, 2.0, palette::TEXT_DIM);
        let size = (r.h * 0.42).max(8.0);
        let label = if self.key.is_empty() {
            self.label.clone()
        } else {
            format!("{}  [{}]", self.label, self.key)
        };
        fitted_text(&label, r.center(), size, r.w * 0.92, palette::TEXT);
    }
}

/// The first button under `p`, if any.
pub fn hit(buttons: &[Button], p: Vec2) -> Option<&Button> {
    buttons.iter().find(|b| b.contains(p))
}

/// Draws `text` centred on `centre` at `size` pixels (the typeface's regular weight; see
/// [`crate::text`] for bold, condensed and fitted text).
pub fn centred_text(text: &str, centre: Vec2, size: f32, colour: Color) {
    text::draw_centred(text, centre, &Style::regular(size), colour);
}

/// Draws `text` centred on `centre`, at `size` pixels or smaller so it fits in `width`.
pub fn fitted_text(text: &str, centre: Vec2, size: f32, width: f32, colour: Color) {
    let style = text::fit(text, Style::regular(size), width, f32::INFINITY, 1.0);
    text::draw_centred(text, centre, &style, colour);
}

/// `count` buttons' rectangles stacked in the middle of `area`, each `width` of its width.
pub fn stack(area: Rect, count: usize, width: f32) -> Vec<Rect> {
    let h = (area.h / 9.0).min(area.w / 5.0);
    let gap = h * 0.35;
    let w = area.w * width;
    let total = count as f32 * h + count.saturating_sub(1) as f32 * gap;
    let top = area.y + (area.h - total) / 2.0 + h * 0.8;
    (0..count)
        .map(|i| {
            Rect::new(
                area.x + (area.w - w) / 2.0,
                top + i as f32 * (h + gap),
                w,
                h,
            )
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_click_finds_the_button_under_it() {
        let buttons = vec![
            Button::new(Rect::new(0.0, 0.0, 10.0, 10.0), "a", "", Action::Pause),
            Button::new(Rect::new(20.0, 0.0, 10.0, 10.0), "b", "", Action::Recall),
        ];
        assert_eq!(
            hit(&buttons, Vec2::new(25.0, 5.0)).unwrap().action,
            Action::Recall
        );
        assert_eq!(
            hit(&buttons, Vec2::new(5.0, 5.0)).unwrap().action,
            Action::Pause
        );
        assert!(hit(&buttons, Vec2::new(15.0, 5.0)).is_none());
    }

    #[test]
    fn stacked_buttons_fit_and_do_not_overlap() {
        let area = Rect::new(10.0, 20.0, 300.0, 400.0);
        let rects = stack(area, 4, 0.8);
        for pair in rects.windows(2) {
            assert!(pair[0].bottom() < pair[1].y);
        }
        for r in &rects {
            assert!(r.x >= area.x && r.right() <= area.right());
            assert!(r.y >= area.y && r.bottom() <= area.bottom());
        }
    }
}
