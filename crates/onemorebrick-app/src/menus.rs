//! The buttons of each view: the play controls, and the menus' buttons on their cards (the
//! pause menu, the settings, the confirmation, the game-over screen) or on the help screen.

use macroquad::math::Rect;

use crate::card;
use crate::help;
use crate::input::{Action, View};
use crate::layout::Layout;
use crate::widgets::Button;

/// Simulated seconds of volley after which the speed-up button appears.
pub const SPEED_BUTTON_AFTER: f64 = 3.0;

/// What the buttons depend on besides the view.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Context {
    /// The volley's clock, if one is live.
    pub volley_time: Option<f64>,
    /// The current speed factor.
    pub speed: u32,
    /// Whether the speed button has been shown in this volley (it then stays).
    pub speed_shown: bool,
    /// Whether the long preview is on.
    pub long_preview: bool,
    /// The level a restart from the checkpoint starts at.
    pub restart_level: u32,
}

/// The buttons of `view`.
pub fn buttons(view: View, layout: &Layout, ctx: &Context) -> Vec<Button> {
    if matches!(view, View::Aiming | View::Volley) {
        return play_buttons(view, layout, ctx);
    }
    let items = menu_items(view, ctx);
    let rects = if view == View::Help {
        vec![help::back_button(layout)]
    } else {
        card::button_rects(layout, view == View::GameOver, items.len())
    };
    rects
        .into_iter()
        .zip(items)
        .map(|(rect, (label, key, action))| Button::new(rect, label, key, action))
        .collect()
}

/// The label, key and action of each button of a menu view, top to bottom. A web page
/// cannot quit (the game is saved as it goes, and when the page is hidden): no "Save and
/// quit" there.
fn menu_items(view: View, ctx: &Context) -> Vec<(String, &'static str, Action)> {
    let mut items = all_menu_items(view, ctx);
    if !crate::input::CAN_QUIT {
        items.retain(|(_, _, action)| *action != Action::Quit);
    }
    items
}

fn all_menu_items(view: View, ctx: &Context) -> Vec<(String, &'static str, Action)> {
    let item = |label: &str, key, action| (label.to_owned(), key, action);
    match view {
        View::Aiming | View::Volley => Vec::new(),
        View::Paused => vec![
            item("Resume", "Esc", Action::Resume),
            item("Pick-ups and help", "H", Action::Help),
            item("New game", "N", Action::NewGame),
            item("Settings", "S", Action::Settings),
            item("Save and quit", "Q", Action::Quit),
        ],
        View::Confirm => vec![
            item("Yes, start a new game", "Y", Action::ConfirmNewGame),
            item("No, go back", "Esc", Action::Back),
        ],
        View::Settings => {
            let preview = if ctx.long_preview { "long" } else { "short" };
            vec![
                item(
                    &format!("Aim preview: {preview}"),
                    "T",
                    Action::TogglePreview,
                ),
                item("Back", "Esc", Action::Back),
            ]
        }
        View::GameOver => vec![
            item(
                &format!("Restart at level {}", ctx.restart_level),
                "Enter",
                Action::RestartCheckpoint,
            ),
            item("New game", "N", Action::NewGame),
            item("Save and quit", "Q", Action::Quit),
        ],
        View::Help => vec![item("Back", "Esc", Action::Back)],
    }
}

fn play_buttons(view: View, layout: &Layout, ctx: &Context) -> Vec<Button> {
    let (h, c) = (layout.hud, layout.controls);
    let size = h.h * 0.7;
    let pause = Rect::new(h.right() - size, h.y + (h.h - size) / 2.0, size, size);
    let mut out = vec![Button::new(pause, "II", "", Action::Pause)];
    if view == View::Volley {
        let bh = c.h * 0.7;
        let y = c.y + (c.h - bh) / 2.0;
        out.push(Button::new(
            Rect::new(c.x, y, c.w * 0.42, bh),
            "Recall",
            "R",
            Action::Recall,
        ));
        if speed_button_shown(ctx) {
            let next = next_speed(ctx.speed);
            let rect = Rect::new(c.right() - c.w * 0.42, y, c.w * 0.42, bh);
            out.push(Button::new(
                rect,
                format!("Speed x{next}"),
                "F",
                Action::SpeedUp,
            ));
        }
    }
    out
}

/// Whether a volley shows the speed button: once it has lasted [`SPEED_BUTTON_AFTER`], or
/// the speed was changed (the F key), and from then on until the volley ends, even back
/// at x1.
pub fn speed_button_shown(ctx: &Context) -> bool {
    let dragging_on = ctx.volley_time.is_some_and(|t| t >= SPEED_BUTTON_AFTER);
    dragging_on || ctx.speed > 1 || ctx.speed_shown
}

/// The speed after pressing speed-up: 1x, 2x, 4x, then back to 1x.
pub fn next_speed(speed: u32) -> u32 {
    match speed {
        1 => 2,
        2 => 4,
        _ => 1,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ctx(volley_time: Option<f64>, speed: u32) -> Context {
        Context {
            volley_time,
            speed,
            speed_shown: false,
            long_preview: false,
            restart_level: 4,
        }
    }

    fn actions(view: View, c: &Context) -> Vec<Action> {
        let layout = Layout::new(600.0, 900.0, 7, 9);
        buttons(view, &layout, c)
            .into_iter()
            .map(|b| b.action)
            .collect()
    }

    #[test]
    fn the_speed_button_appears_when_a_volley_drags_on() {
        assert!(!actions(View::Volley, &ctx(Some(0.5), 1)).contains(&Action::SpeedUp));
        assert!(
            actions(View::Volley, &ctx(Some(SPEED_BUTTON_AFTER), 1)).contains(&Action::SpeedUp)
        );
        assert!(actions(View::Volley, &ctx(Some(0.5), 2)).contains(&Action::SpeedUp));
        assert!(!actions(View::Aiming, &ctx(None, 1)).contains(&Action::SpeedUp));
    }

    #[test]
    fn the_speed_button_once_shown_stays_back_at_x1() {
        let shown = Context {
            speed_shown: true,
            ..ctx(Some(0.5), 1)
        };
        let speed = |c: &Context| {
            let layout = Layout::new(600.0, 900.0, 7, 9);
            buttons(View::Volley, &layout, c)
                .into_iter()
                .find(|b| b.action == Action::SpeedUp)
                .map(|b| b.label)
        };
        assert_eq!(speed(&shown).as_deref(), Some("Speed x2"));
        assert_eq!(speed(&ctx(Some(0.5), 1)), None, "not before it was shown");
        let aiming = actions(View::Aiming, &shown);
        assert!(!aiming.contains(&Action::SpeedUp), "only in a volley");
    }

    #[test]
    fn recall_only_during_a_volley() {
        assert!(actions(View::Volley, &ctx(Some(0.1), 1)).contains(&Action::Recall));
        assert!(!actions(View::Aiming, &ctx(None, 1)).contains(&Action::Recall));
    }

    #[test]
    fn the_menus_offer_what_they_should() {
        let c = ctx(None, 1);
        assert_eq!(
            actions(View::Paused, &c),
            [
                Action::Resume,
                Action::Help,
                Action::NewGame,
                Action::Settings,
                Action::Quit
            ]
        );
        assert_eq!(
            actions(View::GameOver, &c),
            [Action::RestartCheckpoint, Action::NewGame, Action::Quit]
        );
        assert_eq!(
            actions(View::Settings, &c),
            [Action::TogglePreview, Action::Back]
        );
        assert_eq!(
            actions(View::Confirm, &c),
            [Action::ConfirmNewGame, Action::Back]
        );
        assert_eq!(actions(View::Help, &c), [Action::Back]);
    }

    #[test]
    fn buttons_stay_on_screen_and_apart() {
        let layout = Layout::new(500.0, 800.0, 7, 9);
        let c = ctx(Some(10.0), 1);
        for view in [
            View::Aiming,
            View::Volley,
            View::Paused,
            View::Settings,
            View::GameOver,
            View::Confirm,
            View::Help,
        ] {
            let bs = buttons(view, &layout, &c);
            let panel = match view {
                View::Aiming | View::Volley => Rect::new(0.0, 0.0, 500.0, 800.0),
                View::Help => help::card_rect(&layout),
                _ => card::card_rect(&layout, view == View::GameOver, bs.len()),
            };
            for (i, a) in bs.iter().enumerate() {
                let inside = a.rect.x >= panel.x
                    && a.rect.y >= panel.y
                    && a.rect.right() <= panel.right()
                    && a.rect.bottom() <= panel.bottom();
                assert!(inside, "{view:?}: {:?} outside {panel:?}", a.rect);
                assert!(a.rect.x >= 0.0 && a.rect.right() <= 500.0 && a.rect.bottom() <= 800.0);
                for b in &bs[i + 1..] {
                    assert!(a.rect.intersect(b.rect).is_none(), "{view:?}");
                }
            }
        }
    }

    #[test]
    fn speed_cycles() {
        assert_eq!(next_speed(1), 2);
        assert_eq!(next_speed(2), 4);
        assert_eq!(next_speed(4), 1);
    }
}
