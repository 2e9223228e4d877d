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

/// Draws `text` centred on `centre`, at `size` pixels or smaller so it fits in `width`.
pub fn fitted_text(text: &str, centre: Vec2, size: f32, width: f32, colour: Color) {
    let style = text::fit(text, Style::regular(size), width, f32::INFINITY, 1.0);
    text::draw_centred(text, centre, &style, colour);
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
}
