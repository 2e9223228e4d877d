//! The game window: loads the saved game, runs the play loop, saves on quit.

use macroquad::input::{is_quit_requested, prevent_quit};
use macroquad::time::get_frame_time;
use macroquad::window::{Conf, next_frame};
use onemorebrick::{Config, Game};

use crate::app::App;
use crate::sound::Sounds;
use crate::storage::{Seeds, Storage, next_seed};

/// The window's settings: resizable, high DPI, antialiased.
pub fn conf(title: &str, width: i32, height: i32, high_dpi: bool) -> Conf {
    Conf {
        window_title: title.to_owned(),
        window_width: width,
        window_height: height,
        high_dpi,
        window_resizable: true,
        sample_count: 4,
        ..Conf::default()
    }
}

/// Checks that a window can open: on Linux the window needs an X display (miniquad's
/// default backend), and without one it would panic.
///
/// # Errors
/// A message saying how to get a display.
pub fn check_display() -> Result<(), String> {
    if cfg!(target_os = "linux") && std::env::var_os("DISPLAY").is_none_or(|d| d.is_empty()) {
        return Err(
            "no X display (DISPLAY is not set): run this on a desktop, or headless under `xvfb-run -a`"
                .to_owned(),
        );
    }
    Ok(())
}

/// Opens the window and plays until the player quits. New games (the first, one after a
/// damaged save, "new game") take their seeds from `seeds`; a saved game is resumed.
///
/// # Errors
/// When no window can open (see [`check_display`]).
pub fn run(seeds: Seeds) -> Result<(), String> {
    check_display()?;
    crate::sound::check_device();
    macroquad::Window::from_config(conf("One More Brick", 540, 860, true), play(seeds));
    Ok(())
}

async fn play(seeds: Seeds) {
    let mut app = start(seeds);
    if cfg!(feature = "audio") {
        app.set_sounds(Sounds::load().await);
    }
    // Closing the window asks first, so the game is saved before it goes.
    prevent_quit();
    loop {
        app.frame(get_frame_time());
        if app.wants_quit() || is_quit_requested() {
            app.save();
            break;
        }
        next_frame().await;
    }
    std::process::exit(0);
}

/// The saved game (or a new one from `seeds`) and the notices about what loading found.
fn start(seeds: Seeds) -> App {
    let (storage, mut notices) = match Storage::platform() {
        Ok(s) => (Some(s), Vec::new()),
        Err(e) => (None, vec![e]),
    };
    let loaded = storage.as_ref().map(Storage::load);
    let best = loaded.as_ref().map_or(0, |l| l.best);
    let settings = loaded.as_ref().map(|l| l.settings).unwrap_or_default();
    let mut saved = None;
    if let Some(l) = loaded {
        notices.extend(l.notices);
        saved = l.game;
    }
    if let (Some(_), Seeds::Fixed(seed)) = (&saved, seeds) {
        notices.push(format!(
            "Your saved game was resumed: seed {seed} is for the next new game."
        ));
    }
    let game = saved.unwrap_or_else(|| {
        let (seed, trouble) = seeds.draw_or(clock_seed());
        notices.extend(trouble);
        Game::new(Config::default(), seed).expect("the default configuration is valid")
    });
    let mut app = App::new(game, storage, best, notices);
    app.set_settings(settings);
    app.set_seeds(seeds);
    app.save();
    app
}

/// A seed from the clock and the process id: only when the system's generator fails.
fn clock_seed() -> u64 {
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_nanos() as u64);
    next_seed(nanos, std::process::id() as usize)
}
