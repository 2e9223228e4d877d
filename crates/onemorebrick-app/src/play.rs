//! The game window: loads the saved game, runs the play loop, saves on quit (in the
//! browser, whenever the page is hidden: a page is never asked before it goes).

#[cfg(not(target_arch = "wasm32"))]
use macroquad::input::{is_quit_requested, prevent_quit};
use macroquad::time::get_frame_time;
use macroquad::window::{Conf, next_frame};
use onemorebrick::{Config, Game};

use crate::app::App;
#[cfg(not(target_arch = "wasm32"))]
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

#[cfg(not(target_arch = "wasm32"))]
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

#[cfg(not(target_arch = "wasm32"))]
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

#[cfg(not(target_arch = "wasm32"))]
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

/// Opens the game in the page's canvas (the whole page, at the device's pixel ratio) and
/// plays; `notices` (a bad address, say) are shown with loading's. The game is saved after
/// every shot and round as on the desktop, and when the page is hidden: after that no frame
/// may come (a reload, a closed tab, a phone putting the browser away).
#[cfg(target_arch = "wasm32")]
pub fn run_in_browser(seeds: Seeds, notices: Vec<String>) {
    macroquad::Window::from_config(conf("One More Brick", 390, 844, true), async move {
        let app = std::rc::Rc::new(std::cell::RefCell::new(start_with(
            Ok(Storage::browser()),
            seeds,
        )));
        for notice in notices {
            app.borrow_mut().notice(notice);
        }
        let hidden = std::rc::Rc::clone(&app);
        onemorebrick_web::on_page_hide(move || {
            if let Ok(mut app) = hidden.try_borrow_mut() {
                app.save();
            }
        });
        let mut frames = 0u64;
        loop {
            app.borrow_mut().frame(get_frame_time());
            frames += 1;
            crate::web::publish_status(&app.borrow(), frames);
            next_frame().await;
        }
    });
}

/// The saved game (or a new one from `seeds`) and the notices about what loading found.
#[cfg(not(target_arch = "wasm32"))]
fn start(seeds: Seeds) -> App {
    start_with(Storage::platform(), seeds)
}

/// As [`start`], with the game's files in `storage` (or none, and why).
fn start_with(storage: Result<Storage, String>, seeds: Seeds) -> App {
    let (storage, mut notices) = match storage {
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
#[cfg(not(target_arch = "wasm32"))]
fn clock_seed() -> u64 {
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_nanos() as u64);
    next_seed(nanos, std::process::id() as usize)
}

/// A seed from the page's clock: only when the browser's generator fails.
#[cfg(target_arch = "wasm32")]
fn clock_seed() -> u64 {
    next_seed(onemorebrick_web::now_ms().to_bits(), 0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::Action;
    use onemorebrick::load_game;

    fn temp_dir(name: &str) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("omb-play-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        dir
    }

    fn saved_seed(dir: &std::path::Path) -> u64 {
        load_game(&Storage::at(dir).game_path()).unwrap().seed()
    }

    #[test]
    fn a_fresh_install_draws_its_seed_from_the_system() {
        let (a, b) = (temp_dir("os-a"), temp_dir("os-b"));
        let first = start_with(Ok(Storage::at(&a)), Seeds::Os).game().seed();
        let second = start_with(Ok(Storage::at(&b)), Seeds::Os).game().seed();
        assert_ne!(first, second, "two fresh installs, two seeds");
        assert_ne!(first, 1, "not the old fixed seed");
        assert_eq!(saved_seed(&a), first, "the seed is in the save");
        for dir in [a, b] {
            std::fs::remove_dir_all(dir).unwrap();
        }
    }

    #[test]
    fn seed_fixes_the_new_games_and_a_saved_game_is_still_resumed() {
        let dir = temp_dir("fixed");
        let app = start_with(Ok(Storage::at(&dir)), Seeds::Fixed(42));
        assert_eq!((app.game().seed(), saved_seed(&dir)), (42, 42));
        drop(app);
        let mut resumed = start_with(Ok(Storage::at(&dir)), Seeds::Fixed(7));
        assert_eq!(
            resumed.game().seed(),
            42,
            "the saved game is never replaced"
        );
        resumed.apply(Action::Pause);
        resumed.apply(Action::NewGame);
        resumed.apply(Action::ConfirmNewGame);
        assert_eq!((resumed.game().seed(), saved_seed(&dir)), (7, 7));
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn after_a_damaged_save_the_new_game_draws_a_seed_too() {
        let dir = temp_dir("damaged");
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("game.json"), "{ damaged").unwrap();
        let app = start_with(Ok(Storage::at(&dir)), Seeds::Os);
        let other = temp_dir("damaged-other");
        let fresh = start_with(Ok(Storage::at(&other)), Seeds::Os);
        assert_ne!(app.game().seed(), fresh.game().seed());
        assert_eq!(saved_seed(&dir), app.game().seed());
        assert!(dir.join("game.json.bad-1").exists());
        for dir in [dir, other] {
            std::fs::remove_dir_all(dir).unwrap();
        }
    }

    #[test]
    fn two_new_games_from_the_menu_get_different_seeds() {
        let mut app = start_with(Err("no home".to_owned()), Seeds::Os);
        let mut seeds = vec![app.game().seed()];
        for _ in 0..2 {
            app.apply(Action::Pause);
            app.apply(Action::NewGame);
            app.apply(Action::ConfirmNewGame);
            seeds.push(app.game().seed());
        }
        assert!(seeds[0] != seeds[1] && seeds[1] != seeds[2] && seeds[0] != seeds[2]);
    }
}
