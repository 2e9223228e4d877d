//! Never lose progress: the game, the best score and the settings, each written whole
//! (atomically) on a [`Shelf`] (files in the platform's data directory, or the browser's
//! `localStorage`); a damaged entry is reported and set aside, never silently replaced.
//! The format and the checks are this module's, the same on every shelf.

use std::path::Path;

use onemorebrick::save::{from_json, to_json};
use onemorebrick::{Game, SaveError};

pub use crate::shelf::{Entry, Shelf};
#[cfg(not(target_arch = "wasm32"))]
use crate::shelf_files::Files;
#[cfg(target_arch = "wasm32")]
use crate::shelf_keys::{Keys, LocalStorage};

/// The platform's shelf: files on the desktop, `localStorage` in the browser.
#[cfg(not(target_arch = "wasm32"))]
pub type Platform = Files;
/// The platform's shelf: files on the desktop, `localStorage` in the browser.
#[cfg(target_arch = "wasm32")]
pub type Platform = Keys<LocalStorage>;

/// Where the game keeps its saves, and the rules for keeping them.
#[derive(Clone, Debug)]
pub struct Storage<S: Shelf = Platform> {
    shelf: S,
}

/// The player's settings.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Settings {
    /// The long aim preview (six bounces) instead of the first contact and a stub.
    pub long_preview: bool,
    /// Whether the help screen was shown (it opens by itself once, on the first game). A
    /// settings file from before it existed has no such line: the help shows once more.
    pub help_seen: bool,
}
impl Settings {
    /// The settings file's text.
    pub fn to_text(self) -> String {
        format!(
            "long_preview = {}\nhelp_seen = {}\n",
            self.long_preview, self.help_seen
        )
    }

    /// Reads a settings file's text: `key = value` lines.
    ///
    /// # Errors
    /// A message naming the line that is not a known setting with a valid value.
    pub fn parse(text: &str) -> Result<Self, String> {
        let mut settings = Settings::default();
        for (n, line) in text.lines().enumerate() {
            if line.trim().is_empty() {
                continue;
            }
            let bad = || format!("line {}: {line:?} is not a setting", n + 1);
            let (key, value) = line.split_once('=').ok_or_else(bad)?;
            match (key.trim(), value.trim()) {
                ("long_preview", "true") => settings.long_preview = true,
                ("long_preview", "false") => settings.long_preview = false,
                ("help_seen", "true") => settings.help_seen = true,
                ("help_seen", "false") => settings.help_seen = false,
                _ => return Err(bad()),
            }
        }
        Ok(settings)
    }
}

/// What loading found.
pub struct Loaded {
    /// The saved game, if there was a readable one.
    pub game: Option<Game>,
    /// The best score ever (the file's, or the game's if higher).
    pub best: u64,
    /// The settings (the defaults if there were none).
    pub settings: Settings,
    /// Problems to show the player (a damaged file and where it went).
    pub notices: Vec<String>,
}

#[cfg(not(target_arch = "wasm32"))]
impl Storage<Files> {
    /// The platform's data directory for the game (created when first saving).
    ///
    /// # Errors
    /// When the platform has no home directory to put it in.
    pub fn platform() -> Result<Self, String> {
        Files::platform().map(Self::on)
    }

    #[cfg(test)]
    /// Files in `dir`.
    pub fn at(dir: &Path) -> Self {
        Self::on(Files::at(dir))
    }

    #[cfg(test)]
    /// The saved game.
    pub fn game_path(&self) -> std::path::PathBuf {
        self.shelf.path(Entry::Game)
    }

    #[cfg(test)]
    /// The best score (a decimal number).
    pub fn best_path(&self) -> std::path::PathBuf {
        self.shelf.path(Entry::Best)
    }

    #[cfg(test)]
    /// The settings.
    pub fn settings_path(&self) -> std::path::PathBuf {
        self.shelf.path(Entry::Settings)
    }
}

#[cfg(target_arch = "wasm32")]
impl Storage<Keys<LocalStorage>> {
    /// The page's `localStorage`.
    pub fn browser() -> Self {
        Self::on(Keys::new(LocalStorage))
    }
}

impl<S: Shelf> Storage<S> {
    /// The saves on `shelf`.
    pub fn on(shelf: S) -> Self {
        Self { shelf }
    }

    /// Loads the game, the best score and the settings. A missing entry is a fresh start; a
    /// damaged one is reported in the notices and moved aside ([`Shelf::set_aside`]).
    pub fn load(&self) -> Loaded {
        let mut notices = Vec::new();
        let game = self.load_game(&mut notices);
        let mut best = self.load_best(&mut notices);
        if let Some(g) = &game {
            best = best.max(g.state().best_score());
        }
        let settings = self.load_settings(&mut notices);
        Loaded {
            game,
            best,
            settings,
            notices,
        }
    }

    fn load_game(&self, notices: &mut Vec<String>) -> Option<Game> {
        let label = self.shelf.label(Entry::Game);
        let loaded = match self.shelf.read(Entry::Game) {
            Ok(None) => return None,
            Ok(Some(text)) => from_json(&text, Path::new(&label)).map_err(|e| e.to_string()),
            Err(e) => Err(e),
        };
        match loaded {
            Ok(game) => Some(game),
            Err(e) => {
                notices.push(format!("Your saved game could not be loaded: {e}"));
                notices.push(self.set_aside_notice(Entry::Game));
                None
            }
        }
    }

    fn load_settings(&self, notices: &mut Vec<String>) -> Settings {
        match self.shelf.read(Entry::Settings) {
            Ok(Some(text)) => Settings::parse(&text).unwrap_or_else(|e| {
                notices.push(format!("{}: {e}", self.shelf.label(Entry::Settings)));
                notices.push(self.set_aside_notice(Entry::Settings));
                Settings::default()
            }),
            Ok(None) => Settings::default(),
            Err(e) => {
                notices.push(e);
                Settings::default()
            }
        }
    }

    /// Saves the settings whole.
    ///
    /// # Errors
    /// A message naming the entry if it cannot be written, or if the entry there is not a
    /// settings file (it is never overwritten).
    pub fn save_settings(&self, settings: Settings) -> Result<(), String> {
        if let Ok(Some(text)) = self.shelf.read(Entry::Settings) {
            if Settings::parse(&text).is_err() {
                return Err(format!(
                    "{}: not a settings file; not overwritten",
                    self.shelf.label(Entry::Settings)
                ));
            }
        }
        self.shelf.write(Entry::Settings, &settings.to_text())
    }

    fn load_best(&self, notices: &mut Vec<String>) -> u64 {
        match self.shelf.read(Entry::Best) {
            Ok(Some(text)) => match text.trim().parse::<u64>() {
                Ok(best) => best,
                Err(e) => {
                    let label = self.shelf.label(Entry::Best);
                    notices.push(format!("{label}: not a best score ({e})"));
                    notices.push(self.set_aside_notice(Entry::Best));
                    0
                }
            },
            Ok(None) => 0,
            Err(e) => {
                notices.push(e);
                0
            }
        }
    }

    /// Saves the game and, if it went up, the best score; each whole.
    ///
    /// # Errors
    /// A message naming the entry that could not be written, or the saved game's entry if
    /// it holds something that is not a readable save (it is never overwritten).
    pub fn save(&self, game: &Game, best: u64) -> Result<(), String> {
        let label = self.shelf.label(Entry::Game);
        let unreadable = match self.shelf.read(Entry::Game) {
            Ok(None) => None,
            Ok(Some(text)) => from_json(&text, Path::new(&label)).err(),
            Err(e) => Some(SaveError::Corrupt {
                path: label.clone().into(),
                detail: e,
            }),
        };
        if let Some(reason) = unreadable {
            let refusal = SaveError::WouldOverwrite {
                path: label.into(),
                reason: Box::new(reason),
            };
            return Err(refusal.to_string());
        }
        self.shelf.write(Entry::Game, &to_json(game))?;
        self.save_best(best)
    }

    fn save_best(&self, best: u64) -> Result<(), String> {
        let current = self.shelf.read(Entry::Best);
        let old = match &current {
            Ok(Some(text)) => text.trim().parse::<u64>().ok(),
            _ => None,
        };
        if old.is_some_and(|old| old >= best) {
            return Ok(());
        }
        if old.is_none() && !matches!(current, Ok(None)) {
            return Err(format!(
                "{}: not a best score; not overwritten (move it away)",
                self.shelf.label(Entry::Best)
            ));
        }
        self.shelf.write(Entry::Best, &format!("{best}\n"))
    }

    fn set_aside_notice(&self, entry: Entry) -> String {
        match self.shelf.set_aside(entry) {
            Ok(to) => format!("It was kept as {to} and a new one started."),
            Err(e) => format!("It could not be moved aside ({e}); it will not be overwritten."),
        }
    }
}

/// Where new games get their seeds.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Seeds {
    /// Each new game's seed is drawn from the system's generator: the operating system's,
    /// or in the browser `crypto.getRandomValues`.
    #[default]
    Os,
    /// Every new game has this seed (`--seed`).
    Fixed(u64),
}

impl Seeds {
    /// The seed of a new game.
    ///
    /// # Errors
    /// When the operating system's generator fails (a message saying so).
    pub fn draw(self) -> Result<u64, String> {
        match self {
            Seeds::Fixed(seed) => Ok(seed),
            Seeds::Os => {
                system_random().map_err(|e| format!("the system's random generator failed ({e})"))
            }
        }
    }

    /// The seed of a new game, or if the system's generator fails, `fallback` and a notice
    /// saying so.
    pub fn draw_or(self, fallback: u64) -> (u64, Option<String>) {
        match self.draw() {
            Ok(seed) => (seed, None),
            Err(e) => (
                fallback,
                Some(format!("{e}: the new game's seed was derived otherwise")),
            ),
        }
    }
}

/// 64 bits from the operating system's generator.
#[cfg(not(target_arch = "wasm32"))]
fn system_random() -> Result<u64, String> {
    getrandom::u64().map_err(|e| e.to_string())
}

/// 64 bits from the browser's generator (`crypto.getRandomValues`).
#[cfg(target_arch = "wasm32")]
fn system_random() -> Result<u64, String> {
    onemorebrick_web::random_u64()
}

/// A mix of a seed and a count (splitmix64): the fallback seed of a new game when the
/// system's generator fails.
pub fn next_seed(seed: u64, commands: usize) -> u64 {
    let mut z = seed ^ (commands as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15);
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shelf_keys::{KeyValue, Keys, Memory};
    use onemorebrick::{Aim, Config, Phase};
    use std::fs;
    use std::path::PathBuf;

    fn temp_dir(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("omb-storage-{}-{name}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        dir
    }

    #[test]
    fn a_first_start_has_nothing_to_load() {
        let dir = temp_dir("first");
        let loaded = Storage::at(&dir).load();
        assert!(loaded.game.is_none() && loaded.notices.is_empty());
        assert_eq!(loaded.best, 0);
    }

    #[test]
    fn a_game_saved_mid_volley_resumes_in_the_same_volley() {
        let dir = temp_dir("resume");
        let storage = Storage::at(&dir);
        let mut game = Game::new(Config::default(), 5).unwrap();
        game.shoot(Aim::new(0.2, 1.0)).unwrap();
        game.advance_to(0.3).unwrap();
        storage.save(&game, 17).unwrap();
        let loaded = storage.load();
        let resumed = loaded.game.expect("the saved game");
        assert_eq!(resumed.phase(), Phase::Volley);
        assert_eq!(resumed.volley_time(), game.volley_time());
        assert_eq!(resumed.balls(), game.balls());
        assert_eq!(loaded.best, 17);
        assert!(loaded.notices.is_empty());
        fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn the_best_score_only_goes_up() {
        let dir = temp_dir("best");
        let storage = Storage::at(&dir);
        let game = Game::new(Config::default(), 5).unwrap();
        storage.save(&game, 40).unwrap();
        storage.save(&game, 12).unwrap();
        assert_eq!(storage.load().best, 40);
        fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_damaged_save_is_reported_and_set_aside() {
        let dir = temp_dir("damaged");
        fs::create_dir_all(&dir).unwrap();
        let storage = Storage::at(&dir);
        fs::write(storage.game_path(), "{ not json").unwrap();
        fs::write(storage.best_path(), "lots").unwrap();
        let loaded = storage.load();
        assert!(loaded.game.is_none());
        assert_eq!(loaded.notices.len(), 4, "{:?}", loaded.notices);
        assert!(loaded.notices[0].contains("could not be loaded"));
        let kept = fs::read_to_string(dir.join("game.json.bad-1")).unwrap();
        assert_eq!(kept, "{ not json", "the damaged file is kept as it was");
        assert!(dir.join("best-score.txt.bad-1").exists());
        // The next save writes a fresh file where the damaged one was.
        let game = Game::new(Config::default(), 1).unwrap();
        storage.save(&game, 3).unwrap();
        assert!(storage.load().game.is_some());
        fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_damaged_best_score_is_never_overwritten() {
        let dir = temp_dir("keep-best");
        fs::create_dir_all(&dir).unwrap();
        let storage = Storage::at(&dir);
        fs::write(storage.best_path(), "lots").unwrap();
        let game = Game::new(Config::default(), 1).unwrap();
        assert!(storage.save(&game, 3).is_err());
        assert_eq!(fs::read_to_string(storage.best_path()).unwrap(), "lots");
        fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn settings_round_trip_and_bad_ones_are_set_aside() {
        let dir = temp_dir("settings");
        let storage = Storage::at(&dir);
        assert_eq!(storage.load().settings, Settings::default());
        let long = Settings {
            long_preview: true,
            help_seen: true,
        };
        storage.save_settings(long).unwrap();
        assert_eq!(storage.load().settings, long);
        fs::write(storage.settings_path(), "long_preview = maybe\n").unwrap();
        assert!(storage.save_settings(long).is_err(), "never overwritten");
        let loaded = storage.load();
        assert_eq!(loaded.settings, Settings::default());
        assert!(loaded.notices[0].contains("line 1"), "{:?}", loaded.notices);
        assert!(dir.join("settings.txt.bad-1").exists());
        storage.save_settings(long).unwrap();
        fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn settings_text_parses_back() {
        for long_preview in [true, false] {
            for help_seen in [true, false] {
                let s = Settings {
                    long_preview,
                    help_seen,
                };
                assert_eq!(Settings::parse(&s.to_text()), Ok(s));
            }
        }
        assert!(Settings::parse("colour = red").is_err());
        assert!(Settings::parse("long_preview").is_err());
    }

    #[test]
    fn two_new_games_get_different_seeds_from_the_system() {
        let (a, b) = (Seeds::Os.draw().unwrap(), Seeds::Os.draw().unwrap());
        // Two 64-bit draws agree with probability 2^-64.
        assert_ne!(a, b);
        assert_eq!(Seeds::Os.draw_or(3).1, None);
    }

    #[test]
    fn a_fixed_seed_is_the_seed() {
        assert_eq!(Seeds::Fixed(42).draw(), Ok(42));
        assert_eq!(Seeds::Fixed(0).draw_or(9), (0, None));
    }

    #[test]
    fn an_old_settings_file_without_the_help_flag_still_loads() {
        let dir = temp_dir("old-settings");
        fs::create_dir_all(&dir).unwrap();
        let storage = Storage::at(&dir);
        fs::write(storage.settings_path(), "long_preview = true\n").unwrap();
        let loaded = storage.load();
        assert!(loaded.notices.is_empty(), "{:?}", loaded.notices);
        assert_eq!(
            loaded.settings,
            Settings {
                long_preview: true,
                help_seen: false
            }
        );
        // Saving the flag keeps the other setting and replaces the old file.
        let seen = Settings {
            help_seen: true,
            ..loaded.settings
        };
        storage.save_settings(seen).unwrap();
        assert_eq!(storage.load().settings, seen);
        assert!(!dir.join("settings.txt.bad-1").exists());
        fs::remove_dir_all(&dir).unwrap();
    }

    /// The browser's shelf, on a map standing in for `localStorage`.
    fn browser() -> (Storage<Keys<Memory>>, Memory) {
        let memory = Memory::default();
        (Storage::on(Keys::new(memory.clone())), memory)
    }

    #[test]
    fn in_the_browser_a_game_saved_mid_volley_resumes_in_the_same_volley() {
        let (storage, memory) = browser();
        let mut game = Game::new(Config::default(), 5).unwrap();
        game.shoot(Aim::new(0.2, 1.0)).unwrap();
        game.advance_to(0.3).unwrap();
        storage.save(&game, 17).unwrap();
        let keys: Vec<String> = memory.entries().into_iter().map(|(k, _)| k).collect();
        assert_eq!(
            keys,
            ["onemorebrick/best-score.txt", "onemorebrick/game.json"]
        );
        // The text is the save file's, byte for byte.
        assert_eq!(memory.entries()[1].1, onemorebrick::save::to_json(&game));
        let loaded = storage.load();
        let resumed = loaded.game.expect("the saved game");
        assert_eq!(resumed.volley_time(), game.volley_time());
        assert_eq!(resumed.balls(), game.balls());
        assert_eq!(loaded.best, 17);
        assert!(loaded.notices.is_empty());
    }

    #[test]
    fn in_the_browser_a_damaged_entry_is_reported_kept_aside_and_never_overwritten() {
        let (storage, memory) = browser();
        let game = Game::new(Config::default(), 1).unwrap();
        memory.set("onemorebrick/game.json", "{ not json").unwrap();
        memory
            .set("onemorebrick/game.json.bad-1", "an older one")
            .unwrap();
        // Saving over it is refused; the damaged text stays.
        let refused = storage.save(&game, 3).unwrap_err();
        assert!(refused.contains("refusing to overwrite"), "{refused}");
        assert_eq!(
            memory.get("onemorebrick/game.json"),
            Ok(Some("{ not json".into()))
        );
        let loaded = storage.load();
        assert!(loaded.game.is_none());
        assert!(
            loaded.notices[0].starts_with(
                "Your saved game could not be loaded: localStorage \"onemorebrick/game.json\": not a valid save file"
            ),
            "{:?}",
            loaded.notices
        );
        assert_eq!(
            loaded.notices[1],
            "It was kept as localStorage \"onemorebrick/game.json.bad-2\" and a new one started."
        );
        assert_eq!(
            memory.get("onemorebrick/game.json.bad-2"),
            Ok(Some("{ not json".into()))
        );
        assert_eq!(
            memory.get("onemorebrick/game.json.bad-1"),
            Ok(Some("an older one".into())),
            "an earlier damaged entry is kept too"
        );
        assert_eq!(memory.get("onemorebrick/game.json"), Ok(None));
        storage.save(&game, 3).unwrap();
        assert!(storage.load().game.is_some());
    }

    #[test]
    fn in_the_browser_bad_settings_and_best_scores_are_set_aside() {
        let (storage, memory) = browser();
        memory
            .set("onemorebrick/settings.txt", "colour = red\n")
            .unwrap();
        memory.set("onemorebrick/best-score.txt", "lots").unwrap();
        let game = Game::new(Config::default(), 1).unwrap();
        assert!(
            storage.save(&game, 3).is_err(),
            "the best score is not overwritten"
        );
        let long = Settings {
            long_preview: true,
            help_seen: true,
        };
        assert!(storage.save_settings(long).is_err(), "nor the settings");
        let loaded = storage.load();
        assert_eq!(loaded.notices.len(), 4, "{:?}", loaded.notices);
        assert_eq!(loaded.settings, Settings::default());
        assert_eq!(
            memory.get("onemorebrick/settings.txt.bad-1"),
            Ok(Some("colour = red\n".into()))
        );
        assert_eq!(
            memory.get("onemorebrick/best-score.txt.bad-1"),
            Ok(Some("lots".into()))
        );
        storage.save_settings(long).unwrap();
        storage.save(&game, 3).unwrap();
        let again = storage.load();
        assert_eq!((again.settings, again.best), (long, 3));
    }

    #[test]
    fn new_games_get_new_seeds() {
        assert_ne!(next_seed(1, 0), next_seed(1, 1));
        assert_ne!(next_seed(1, 5), next_seed(2, 5));
        assert_eq!(next_seed(9, 3), next_seed(9, 3));
    }
}
