//! Input to commands: which key does what on which screen, and how a pointer position
//! becomes an aim. Pure functions; the play loop reads the devices and applies the result.

use macroquad::input::KeyCode;
use onemorebrick::{Aim, DVec2};

/// Something the player asked for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Action {
    /// Fire the volley along this aim.
    Shoot(Aim),
    /// Fire along the keyboard's aim.
    ShootKeyboardAim,
    /// Next simulation speed (1x, 2x, 4x).
    SpeedUp,
    /// Every ball returns at once.
    Recall,
    /// Open the pause menu.
    Pause,
    /// Close the pause menu.
    Resume,
    /// Ask whether to abandon this game for a new one.
    NewGame,
    /// Yes: abandon this game and start a new one.
    ConfirmNewGame,
    /// After a game over: start again from the checkpoint.
    RestartCheckpoint,
    /// Open the settings.
    Settings,
    /// Settings: switch between the short and the long trajectory preview.
    TogglePreview,
    /// Open the help screen (the pick-ups and the warning).
    Help,
    /// Leave the settings, the help screen or a confirmation.
    Back,
    /// Save and quit.
    Quit,
}

/// What the player sees, which decides what keys mean.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum View {
    /// Aiming a shot.
    Aiming,
    /// A volley in flight.
    Volley,
    /// The game-over screen.
    GameOver,
    /// The pause menu.
    Paused,
    /// The settings screen.
    Settings,
    /// "Start a new game?"
    Confirm,
    /// The help screen: every pick-up and the warning.
    Help,
}

/// The action of a key press on a view, if any.
pub fn key_action(view: View, key: KeyCode) -> Option<Action> {
    use KeyCode as K;
    match (view, key) {
        (View::Aiming | View::Volley, K::Escape | K::P) => Some(Action::Pause),
        (View::Aiming, K::Space | K::Enter | K::Up) => Some(Action::ShootKeyboardAim),
        (View::Volley, K::F | K::Space) => Some(Action::SpeedUp),
        (View::Volley, K::R) => Some(Action::Recall),
        (View::GameOver, K::Enter | K::R) => Some(Action::RestartCheckpoint),
        (View::GameOver | View::Paused, K::N) => Some(Action::NewGame),
        (View::GameOver | View::Paused, K::Q) => Some(Action::Quit),
        (View::Paused, K::Escape | K::P | K::Enter) => Some(Action::Resume),
        (View::Paused, K::S) => Some(Action::Settings),
        (View::Paused, K::H) => Some(Action::Help),
        (View::Help, K::Escape | K::Backspace | K::Enter | K::Space | K::H) => Some(Action::Back),
        (View::Settings, K::T) => Some(Action::TogglePreview),
        (View::Settings, K::Escape | K::Backspace | K::Enter) => Some(Action::Back),
        (View::Confirm, K::Y) => Some(Action::ConfirmNewGame),
        (View::Confirm, K::Escape | K::Backspace | K::N) => Some(Action::Back),
        _ => None,
    }
}

/// Every key that means something somewhere (the play loop polls these).
pub const KEYS: [KeyCode; 16] = [
    KeyCode::Escape,
    KeyCode::P,
    KeyCode::Space,
    KeyCode::Enter,
    KeyCode::Up,
    KeyCode::F,
    KeyCode::R,
    KeyCode::N,
    KeyCode::Q,
    KeyCode::S,
    KeyCode::T,
    KeyCode::Backspace,
    KeyCode::Y,
    KeyCode::H,
    KeyCode::Left,
    KeyCode::Right,
];

/// The aim from the launch point toward a pointer on the board, clamped to the minimum
/// elevation. `None` (a cancelled shot) when the pointer is at or below the launch point's
/// height: dragging down there is how a player takes a shot back.
pub fn aim_toward(launch: DVec2, pointer: DVec2, min_elevation_tan: f64) -> Option<Aim> {
    let d = pointer - launch;
    if !(d.y > 0.0) {
        return None;
    }
    Aim::new(d.x, d.y).clamped(min_elevation_tan)
}

/// The keyboard's aim turned by `radians` (positive: counter-clockwise, to the left),
/// clamped to the minimum elevation.
pub fn turn(aim: Aim, radians: f64, min_elevation_tan: f64) -> Aim {
    let (s, c) = radians.sin_cos();
    let turned = Aim::new(aim.dx * c - aim.dy * s, aim.dx * s + aim.dy * c);
    let len = (turned.dx * turned.dx + turned.dy * turned.dy).sqrt();
    Aim::new(turned.dx / len, turned.dy / len)
        .clamped(min_elevation_tan)
        .unwrap_or(aim)
}

#[cfg(test)]
mod tests {
    use super::*;

    const TAN: f64 = 0.15;

    #[test]
    fn each_control_has_a_key() {
        assert_eq!(key_action(View::Volley, KeyCode::F), Some(Action::SpeedUp));
        assert_eq!(key_action(View::Volley, KeyCode::R), Some(Action::Recall));
        assert_eq!(
            key_action(View::Aiming, KeyCode::Escape),
            Some(Action::Pause)
        );
        assert_eq!(
            key_action(View::Paused, KeyCode::Escape),
            Some(Action::Resume)
        );
        assert_eq!(key_action(View::Paused, KeyCode::N), Some(Action::NewGame));
        assert_eq!(key_action(View::Paused, KeyCode::S), Some(Action::Settings));
        assert_eq!(key_action(View::Paused, KeyCode::Q), Some(Action::Quit));
        assert_eq!(key_action(View::Paused, KeyCode::H), Some(Action::Help));
        assert_eq!(key_action(View::Help, KeyCode::Escape), Some(Action::Back));
        assert_eq!(key_action(View::Help, KeyCode::H), Some(Action::Back));
        assert_eq!(
            key_action(View::GameOver, KeyCode::Enter),
            Some(Action::RestartCheckpoint)
        );
        assert_eq!(
            key_action(View::Settings, KeyCode::T),
            Some(Action::TogglePreview)
        );
    }

    #[test]
    fn keys_only_act_where_they_make_sense() {
        assert_eq!(key_action(View::Aiming, KeyCode::R), None);
        assert_eq!(key_action(View::Paused, KeyCode::Y), None);
        assert_eq!(
            key_action(View::Confirm, KeyCode::Enter),
            None,
            "no accidental new game"
        );
        assert_eq!(key_action(View::Aiming, KeyCode::F), None);
        assert_eq!(key_action(View::GameOver, KeyCode::Escape), None);
        assert_eq!(key_action(View::Volley, KeyCode::Enter), None);
        assert_eq!(
            key_action(View::Help, KeyCode::Q),
            None,
            "no quitting from the help"
        );
        assert_eq!(key_action(View::Aiming, KeyCode::H), None);
    }

    #[test]
    fn every_mapped_key_is_polled() {
        let views = [
            View::Aiming,
            View::Volley,
            View::GameOver,
            View::Paused,
            View::Settings,
            View::Confirm,
            View::Help,
        ];
        // Every key the game polls, and a few it ignores.
        let all: Vec<KeyCode> = KEYS
            .iter()
            .copied()
            .chain([KeyCode::A, KeyCode::B, KeyCode::Down, KeyCode::Tab])
            .collect();
        for view in views {
            for &key in &all {
                if key_action(view, key).is_some() {
                    assert!(KEYS.contains(&key), "{key:?}");
                }
            }
        }
    }

    #[test]
    fn the_aim_points_from_the_launcher_to_the_pointer() {
        let aim = aim_toward(DVec2::new(3.5, 0.15), DVec2::new(5.5, 2.15), TAN).unwrap();
        assert!((aim.dx - aim.dy).abs() < 1e-12 && aim.dx > 0.0);
    }

    #[test]
    fn a_pointer_below_the_launcher_cancels() {
        assert_eq!(
            aim_toward(DVec2::new(3.5, 0.15), DVec2::new(1.0, 0.1), TAN),
            None
        );
        assert_eq!(
            aim_toward(DVec2::new(3.5, 0.15), DVec2::new(1.0, 0.15), TAN),
            None
        );
    }

    #[test]
    fn a_flat_aim_is_raised_to_the_minimum_elevation() {
        let aim = aim_toward(DVec2::new(3.5, 0.15), DVec2::new(-20.0, 0.2), TAN).unwrap();
        assert!(aim.validate(TAN).is_ok());
        assert!(aim.dx < 0.0);
    }

    #[test]
    fn turning_the_keyboard_aim_stays_valid() {
        let mut aim = Aim::new(0.0, 1.0);
        for _ in 0..200 {
            aim = turn(aim, 0.05, TAN);
            assert!(aim.validate(TAN).is_ok());
        }
        assert!(aim.dx < 0.0, "turned left as far as allowed");
        let right = turn(Aim::new(0.0, 1.0), -0.1, TAN);
        assert!(right.dx > 0.0);
    }
}
