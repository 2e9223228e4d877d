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

/// Whether the player can quit: not in a web page (closing or leaving it is quitting, and
/// the game is saved then).
pub const CAN_QUIT: bool = !cfg!(target_arch = "wasm32");

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
        (View::GameOver | View::Paused, K::Q) if CAN_QUIT => Some(Action::Quit),
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

/// How far one tap of Left or Right turns the keyboard's aim: one degree.
pub const TAP_STEP: f64 = std::f64::consts::PI / 180.0;
/// How long a key is held before the aim goes on turning by itself, seconds.
pub const HOLD_DELAY: f64 = 0.25;
/// The turn rate as holding starts, radians per second: the rate of a step every 1/20 s
/// (20 degrees a second).
pub const HOLD_SLOW: f64 = 20.0 * TAP_STEP;
/// The fastest turn, reached [`HOLD_RAMP`] seconds after the delay: 120 degrees a second.
pub const HOLD_FAST: f64 = 120.0 * TAP_STEP;
/// How long the turn takes to speed up from [`HOLD_SLOW`] to [`HOLD_FAST`], seconds.
pub const HOLD_RAMP: f64 = 0.6;

/// The turn rate of the keyboard's aim after a key was held `held` seconds, radians per
/// second: none during [`HOLD_DELAY`], then from [`HOLD_SLOW`] up to [`HOLD_FAST`] in a
/// straight line over [`HOLD_RAMP`], then that. ([`held_turn`] is its integral; the tests
/// check the one against the other.)
#[cfg(test)]
pub fn turn_rate(held: f64) -> f64 {
    let u = held - HOLD_DELAY;
    if u < 0.0 {
        0.0
    } else {
        HOLD_SLOW + (HOLD_FAST - HOLD_SLOW) * (u / HOLD_RAMP).min(1.0)
    }
}

/// How far a key pressed and held `held` seconds has turned the keyboard's aim in all,
/// radians: the tap's [`TAP_STEP`] at once, then the integral of [`turn_rate`].
pub fn held_turn(held: f64) -> f64 {
    let u = (held - HOLD_DELAY).max(0.0);
    let ramp = u.min(HOLD_RAMP);
    let ramping = HOLD_SLOW * ramp + (HOLD_FAST - HOLD_SLOW) * ramp * ramp / (2.0 * HOLD_RAMP);
    TAP_STEP + ramping + HOLD_FAST * (u - ramp)
}

/// A turning key held down: which way (+1 left, -1 right) and for how long, seconds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hold {
    /// +1.0 turns left (counter-clockwise), -1.0 right.
    pub sign: f64,
    /// Seconds since it was pressed.
    pub held: f64,
}

/// The keys pressed in one frame, in order, every one (a slow frame may hold several
/// taps). Fed with the frame's key events (`macroquad`'s input subscription); a key's
/// auto-repeat is not a press.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Presses {
    /// The keys, first pressed first.
    pub keys: Vec<KeyCode>,
}

impl macroquad::miniquad::EventHandler for Presses {
    fn update(&mut self) {}

    fn draw(&mut self) {}

    fn key_down_event(&mut self, key: KeyCode, _: macroquad::miniquad::KeyMods, repeat: bool) {
        if !repeat {
            self.keys.push(key);
        }
    }
}

/// Which way a key turns the keyboard's aim: +1 left (Left), -1 right (Right).
pub fn turn_sign(key: KeyCode) -> Option<f64> {
    match key {
        KeyCode::Left => Some(1.0),
        KeyCode::Right => Some(-1.0),
        _ => None,
    }
}

/// One frame of a turning key held down: `down` is which way the key held at the frame's
/// end turns (+1 left, -1 right, 0 none), `pressed` whether it was pressed in this frame,
/// `dt` the frame's seconds. Returns the hold after the frame and the angle the hold turns
/// the aim now (signed, left positive); the press's own [`TAP_STEP`] is the caller's. A
/// press starts the hold again; a key held on adds what [`held_turn`] adds over the
/// frame, so a hold's turn does not depend on the frame rate.
pub fn hold_step(hold: Option<Hold>, pressed: bool, down: f64, dt: f64) -> (Option<Hold>, f64) {
    match hold {
        _ if down == 0.0 => (None, 0.0),
        Some(h) if h.sign == down && !pressed => {
            let held = h.held + dt;
            let angle = down * (held_turn(held) - held_turn(h.held));
            (Some(Hold { sign: down, held }), angle)
        }
        _ => (
            Some(Hold {
                sign: down,
                held: 0.0,
            }),
            0.0,
        ),
    }
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
    fn a_tap_turns_by_the_step_and_a_hold_speeds_up() {
        assert_eq!(held_turn(0.0), TAP_STEP);
        assert_eq!(
            held_turn(HOLD_DELAY),
            TAP_STEP,
            "no turning before the delay"
        );
        assert_eq!(turn_rate(HOLD_DELAY * 0.5), 0.0);
        assert_eq!(turn_rate(HOLD_DELAY), HOLD_SLOW);
        assert_eq!(turn_rate(HOLD_DELAY + HOLD_RAMP), HOLD_FAST);
        assert_eq!(turn_rate(HOLD_DELAY + 5.0), HOLD_FAST);
        const { assert!(HOLD_FAST > 5.0 * HOLD_SLOW) };
        // The rate rises all through the ramp, and the total is its integral.
        let h = 1e-4;
        let mut last = 0.0;
        for k in 1..=40 {
            let t = HOLD_DELAY + HOLD_RAMP * 1.5 * f64::from(k) / 41.0;
            let slope = (held_turn(t + h) - held_turn(t - h)) / (2.0 * h);
            assert!((slope - turn_rate(t)).abs() < 1e-6, "at {t}: {slope}");
            assert!(turn_rate(t) >= last);
            last = turn_rate(t);
        }
        // Analytic: after the delay, the ramp's trapezium, then the fast rate.
        let after = HOLD_DELAY + HOLD_RAMP + 1.0;
        let expected = TAP_STEP + (HOLD_SLOW + HOLD_FAST) / 2.0 * HOLD_RAMP + HOLD_FAST;
        assert!((held_turn(after) - expected).abs() < 1e-12);
    }

    #[test]
    fn a_hold_turns_as_held_turn_says_at_any_frame_rate() {
        // Right pressed, then held one second, at 30 and at 144 frames a second: the step
        // (the caller's) and the hold's turn make `held_turn(1.0)`.
        for fps in [30.0, 144.0] {
            let (mut hold, mut total) = hold_step(None, true, -1.0, 1.0 / fps);
            total -= TAP_STEP;
            for _ in 0..fps as usize {
                let (next, angle) = hold_step(hold, false, -1.0, 1.0 / fps);
                hold = next;
                total += angle;
            }
            assert!((total + held_turn(1.0)).abs() < 1e-9, "{fps}: {total}");
        }
        // Released: the hold ends. Pressed again, or the other way: a new hold.
        let (hold, _) = hold_step(None, true, 1.0, 0.1);
        let (hold, _) = hold_step(hold, false, 1.0, 0.5);
        assert_eq!(hold.unwrap().held, 0.5);
        assert_eq!(hold_step(hold, false, 0.0, 0.1), (None, 0.0));
        let (again, angle) = hold_step(hold, true, 1.0, 0.1);
        assert_eq!((again.unwrap().held, angle), (0.0, 0.0));
        let (other, _) = hold_step(hold, false, -1.0, 0.1);
        assert_eq!(
            other.unwrap(),
            Hold {
                sign: -1.0,
                held: 0.0
            }
        );
    }

    #[test]
    fn left_and_right_turn_and_nothing_else_does() {
        assert_eq!(turn_sign(KeyCode::Left), Some(1.0));
        assert_eq!(turn_sign(KeyCode::Right), Some(-1.0));
        assert_eq!(turn_sign(KeyCode::Up), None);
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
