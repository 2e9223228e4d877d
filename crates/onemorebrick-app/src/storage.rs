//! Never lose progress: the game and the best score in the platform's data directory,
//! written atomically; a damaged file is reported and set aside, never silently replaced.

use std::fs;
use std::io::{self, Write};
use std::path::{Path, PathBuf};

use onemorebrick::{Game, SaveError, load_game, save_game, set_aside};

/// Where the game keeps its files.
#[derive(Clone, Debug)]
pub struct Storage {
    dir: PathBuf,
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

impl Storage {
    /// The platform's data directory for the game (created when first saving).
    ///
    /// # Errors
    /// When the platform has no home directory to put it in.
    pub fn platform() -> Result<Self, String> {
        directories::ProjectDirs::from("", "", "onemorebrick")
            .map(|d| Self::at(d.data_dir()))
            .ok_or_else(|| "no home directory: progress will not be saved".to_owned())
    }

    /// Files in `dir`.
    pub fn at(dir: &Path) -> Self {
        Self {
            dir: dir.to_path_buf(),
        }
    }

    /// The saved game.
    pub fn game_path(&self) -> PathBuf {
        self.dir.join("game.json")
    }

    /// The best score (a decimal number).
    pub fn best_path(&self) -> PathBuf {
        self.dir.join("best-score.txt")
    }

    /// The settings.
    pub fn settings_path(&self) -> PathBuf {
        self.dir.join("settings.txt")
    }

    /// Loads the game, the best score and the settings. A missing file is a fresh start; a damaged one is
    /// reported in the notices and moved aside with [`set_aside`].
    pub fn load(&self) -> Loaded {
        let mut notices = Vec::new();
        let game = match load_game(&self.game_path()) {
            Ok(game) => Some(game),
            Err(SaveError::Io { source, .. }) if source.kind() == io::ErrorKind::NotFound => None,
            Err(e) => {
                notices.push(format!("Your saved game could not be loaded: {e}"));
                notices.push(set_aside_notice(&self.game_path()));
                None
            }
        };
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

    fn load_settings(&self, notices: &mut Vec<String>) -> Settings {
        let path = self.settings_path();
        match fs::read_to_string(&path) {
            Ok(text) => Settings::parse(&text).unwrap_or_else(|e| {
                notices.push(format!("{}: {e}", path.display()));
                notices.push(set_aside_notice(&path));
                Settings::default()
            }),
            Err(e) if e.kind() == io::ErrorKind::NotFound => Settings::default(),
            Err(e) => {
                notices.push(format!("{}: could not read: {e}", path.display()));
                Settings::default()
            }
        }
    }

    /// Saves the settings atomically.
    ///
    /// # Errors
    /// A message naming the file if it cannot be written, or if the file there is not a
    /// settings file (it is never overwritten).
    pub fn save_settings(&self, settings: Settings) -> Result<(), String> {
        let path = self.settings_path();
        if let Ok(text) = fs::read_to_string(&path) {
            if Settings::parse(&text).is_err() {
                return Err(format!(
                    "{}: not a settings file; not overwritten",
                    path.display()
                ));
            }
        }
        fs::create_dir_all(&self.dir)
            .and_then(|()| write_atomically(&path, settings.to_text().as_bytes()))
            .map_err(|e| format!("{}: could not write: {e}", path.display()))
    }

    fn load_best(&self, notices: &mut Vec<String>) -> u64 {
        let path = self.best_path();
        match fs::read_to_string(&path) {
            Ok(text) => match text.trim().parse::<u64>() {
                Ok(best) => best,
                Err(e) => {
                    notices.push(format!("{}: not a best score ({e})", path.display()));
                    notices.push(set_aside_notice(&path));
                    0
                }
            },
            Err(e) if e.kind() == io::ErrorKind::NotFound => 0,
            Err(e) => {
                notices.push(format!("{}: could not read: {e}", path.display()));
                0
            }
        }
    }

    /// Saves the game and, if it went up, the best score; both atomically.
    ///
    /// # Errors
    /// A message naming the file that could not be written.
    pub fn save(&self, game: &Game, best: u64) -> Result<(), String> {
        fs::create_dir_all(&self.dir)
            .map_err(|e| format!("{}: could not create: {e}", self.dir.display()))?;
        save_game(game, &self.game_path()).map_err(|e| e.to_string())?;
        self.save_best(best)
    }

    fn save_best(&self, best: u64) -> Result<(), String> {
        let path = self.best_path();
        let old = fs::read_to_string(&path)
            .ok()
            .and_then(|t| t.trim().parse::<u64>().ok());
        if old.is_some_and(|old| old >= best) {
            return Ok(());
        }
        if old.is_none() && path.exists() {
            return Err(format!(
                "{}: not a best score; not overwritten (move it away)",
                path.display()
            ));
        }
        write_atomically(&path, format!("{best}\n").as_bytes())
            .map_err(|e| format!("{}: could not write: {e}", path.display()))
    }
}

fn set_aside_notice(path: &Path) -> String {
    match set_aside(path) {
        Ok(to) => format!("It was kept as {} and a new one started.", to.display()),
        Err(e) => format!("It could not be moved aside ({e}); it will not be overwritten."),
    }
}

/// Writes `bytes` to a temporary file beside `path`, syncs it, and renames it over `path`.
fn write_atomically(path: &Path, bytes: &[u8]) -> io::Result<()> {
    let temp = onemorebrick::save::temp_path(path);
    let mut file = fs::File::create(&temp)?;
    file.write_all(bytes)?;
    file.sync_all()?;
    drop(file);
    fs::rename(&temp, path)
}

/// Where new games get their seeds.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Seeds {
    /// Each new game's seed is drawn from the operating system's generator.
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
                getrandom::u64().map_err(|e| format!("the system's random generator failed ({e})"))
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
    use onemorebrick::{Aim, Config, Phase};

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

    #[test]
    fn new_games_get_new_seeds() {
        assert_ne!(next_seed(1, 0), next_seed(1, 1));
        assert_ne!(next_seed(1, 5), next_seed(2, 5));
        assert_eq!(next_seed(9, 3), next_seed(9, 3));
    }
}
