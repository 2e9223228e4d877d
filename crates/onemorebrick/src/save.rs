//! Save files: versioned JSON, written atomically, never overwritten silently.
//!
//! A save holds the state between volleys and, if a volley is live, its aim and clock: the
//! volley is rebuilt by re-simulating it from the state, which gives the same bits as the
//! game that was saved (the engine and the rules are deterministic, and frames change
//! nothing). Doubles are written with `serde_json`'s `float_roundtrip`, so they read back
//! exactly.
//!
//! A file that cannot be read as a save (corrupt, another program's, a newer version) is
//! reported with its path and the problem, and [`save_game`] refuses to replace it: a front
//! end first moves it away with [`set_aside`], so the player's data is never lost silently.

use std::fmt;
use std::fs::{self, File};
use std::io::Write;
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use crate::aim::Aim;
use crate::game::Game;
use crate::replay::Command;
use crate::state::GameState;

/// The `format` field of every save file.
pub const SAVE_FORMAT: &str = "onemorebrick-save";

/// The version this build writes and the newest it reads.
///
/// Version 2: after a game over, `state.level` is the level that ended the game (the last
/// round played). Version 1 counted one more; reading a version-1 file takes that one off,
/// so an old save shows the same game with the one level number used everywhere.
pub const SAVE_VERSION: u32 = 2;

#[derive(Serialize, Deserialize)]
struct SaveFile {
    format: String,
    version: u32,
    seed: u64,
    state: GameState,
    history: Vec<Command>,
    volley: Option<SavedVolley>,
}

#[derive(Serialize, Deserialize)]
struct SavedVolley {
    aim: Aim,
    elapsed: f64,
}

/// Why a save file could not be read or written. Every variant names the file.
#[derive(Debug)]
pub enum SaveError {
    /// The file system refused (`action` says what was being done).
    Io {
        /// The file.
        path: PathBuf,
        /// What was being done: "read", "write", "rename".
        action: &'static str,
        /// The operating system's error.
        source: std::io::Error,
    },
    /// Not a readable save file: bad JSON, a missing field, another format.
    Corrupt {
        /// The file.
        path: PathBuf,
        /// What is wrong, with the line and column when JSON says so.
        detail: String,
    },
    /// Written by a newer version of the game.
    FutureVersion {
        /// The file.
        path: PathBuf,
        /// Its version.
        found: u64,
        /// The newest version this build reads.
        supported: u32,
    },
    /// Readable, but the game it describes breaks a rule (or its volley does not replay).
    Invalid {
        /// The file.
        path: PathBuf,
        /// What is wrong.
        detail: String,
    },
    /// Saving would replace a file that is not a save this build can read.
    WouldOverwrite {
        /// The file.
        path: PathBuf,
        /// Why it cannot be read.
        reason: Box<SaveError>,
    },
}

impl fmt::Display for SaveError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SaveError::Io {
                path,
                action,
                source,
            } => write!(f, "{}: could not {action}: {source}", path.display()),
            SaveError::Corrupt { path, detail } => {
                write!(f, "{}: not a valid save file: {detail}", path.display())
            }
            SaveError::FutureVersion {
                path,
                found,
                supported,
            } => write!(
                f,
                "{}: saved by a newer version (file version {found}, this build reads up to {supported})",
                path.display()
            ),
            SaveError::Invalid { path, detail } => {
                write!(
                    f,
                    "{}: the saved game is inconsistent: {detail}",
                    path.display()
                )
            }
            SaveError::WouldOverwrite { path, reason } => write!(
                f,
                "{}: refusing to overwrite a file that is not a readable save ({reason}); set it aside first",
                path.display()
            ),
        }
    }
}

impl std::error::Error for SaveError {}

/// The save file's JSON text for `game`.
#[must_use]
pub fn to_json(game: &Game) -> String {
    let file = SaveFile {
        format: SAVE_FORMAT.to_owned(),
        version: SAVE_VERSION,
        seed: game.seed(),
        state: game.state().clone(),
        history: game.history().to_vec(),
        volley: game.volley_aim().map(|aim| SavedVolley {
            aim,
            elapsed: game.volley_time().unwrap_or(0.0),
        }),
    };
    serde_json::to_string_pretty(&file).expect("a game always serialises")
}

/// A game from a save file's JSON text; `path` only names the source in errors.
///
/// # Errors
/// [`SaveError::Corrupt`], [`SaveError::FutureVersion`] or [`SaveError::Invalid`].
pub fn from_json(text: &str, path: &Path) -> Result<Game, SaveError> {
    let corrupt = |detail: String| SaveError::Corrupt {
        path: path.to_owned(),
        detail,
    };
    let value: serde_json::Value =
        serde_json::from_str(text).map_err(|e| corrupt(e.to_string()))?;
    check_header(&value, path)?;
    let mut file: SaveFile = serde_json::from_value(value).map_err(|e| corrupt(e.to_string()))?;
    if file.version == 1 {
        upgrade_from_v1(&mut file.state);
    }
    let invalid = |detail: String| SaveError::Invalid {
        path: path.to_owned(),
        detail,
    };
    file.state.validate().map_err(|e| invalid(e.to_string()))?;
    let volley = file.volley.map(|v| (v.aim, v.elapsed));
    Game::rebuild(file.seed, file.state, file.history, volley).map_err(|e| invalid(e.to_string()))
}

/// Version 1 raised the level once more at a game over (see [`SAVE_VERSION`]).
fn upgrade_from_v1(state: &mut GameState) {
    if state.game_over && state.level > 1 {
        state.level -= 1;
    }
}

/// Checks the format name and the version before anything else is read, so a newer file is
/// reported as newer rather than as a list of unknown fields.
fn check_header(value: &serde_json::Value, path: &Path) -> Result<(), SaveError> {
    let corrupt = |detail: &str| SaveError::Corrupt {
        path: path.to_owned(),
        detail: detail.to_owned(),
    };
    if value.get("format").and_then(|f| f.as_str()) != Some(SAVE_FORMAT) {
        return Err(corrupt("the \"format\" field is not \"onemorebrick-save\""));
    }
    let Some(found) = value.get("version").and_then(serde_json::Value::as_u64) else {
        return Err(corrupt(
            "the \"version\" field is missing or not a whole number",
        ));
    };
    if found > u64::from(SAVE_VERSION) {
        return Err(SaveError::FutureVersion {
            path: path.to_owned(),
            found,
            supported: SAVE_VERSION,
        });
    }
    if found == 0 {
        return Err(corrupt("version 0 does not exist"));
    }
    Ok(())
}

/// Loads a game from a save file.
///
/// # Errors
/// [`SaveError::Io`] if the file cannot be read, else as [`from_json`].
pub fn load_game(path: &Path) -> Result<Game, SaveError> {
    let text = fs::read_to_string(path).map_err(|source| SaveError::Io {
        path: path.to_owned(),
        action: "read",
        source,
    })?;
    from_json(&text, path)
}

/// The temporary file a save is written to before it replaces `path`: the same directory,
/// so the final rename stays on one file system and is atomic.
#[must_use]
pub fn temp_path(path: &Path) -> PathBuf {
    let mut name = path.file_name().unwrap_or_default().to_os_string();
    name.push(".tmp");
    path.with_file_name(name)
}

/// Saves a game atomically: the text goes to [`temp_path`], is flushed to disk (`fsync`),
/// then renamed over `path`; a crash at any point leaves either the old file or the new one.
///
/// # Errors
/// [`SaveError::WouldOverwrite`] if `path` exists and is not a save this build reads (see
/// [`set_aside`]); [`SaveError::Io`] if writing fails (the old file is then untouched).
pub fn save_game(game: &Game, path: &Path) -> Result<(), SaveError> {
    if path.exists() {
        if let Err(reason) = load_game(path) {
            return Err(SaveError::WouldOverwrite {
                path: path.to_owned(),
                reason: Box::new(reason),
            });
        }
    }
    let temp = temp_path(path);
    let io = |action: &'static str, at: &Path| {
        let at = at.to_owned();
        move |source| SaveError::Io {
            path: at,
            action,
            source,
        }
    };
    let mut file = File::create(&temp).map_err(io("create", &temp))?;
    file.write_all(to_json(game).as_bytes())
        .and_then(|()| file.sync_all())
        .map_err(io("write", &temp))?;
    drop(file);
    fs::rename(&temp, path).map_err(io("rename", path))?;
    // Make the rename itself durable (directories can be synced on Unix; elsewhere this
    // open fails and the rename is as durable as the platform makes it).
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        if let Ok(dir) = File::open(dir) {
            let _ = dir.sync_all();
        }
    }
    Ok(())
}

/// Moves an unreadable save out of the way: renames it to `NAME.bad-N` with the smallest
/// free `N` from 1, and returns the new path. The front end offers this after a load error.
///
/// # Errors
/// [`SaveError::Io`] if the rename fails.
pub fn set_aside(path: &Path) -> Result<PathBuf, SaveError> {
    let name = path.file_name().unwrap_or_default().to_os_string();
    let target = (1u32..)
        .map(|n| {
            let mut candidate = name.clone();
            candidate.push(format!(".bad-{n}"));
            path.with_file_name(candidate)
        })
        .find(|candidate| !candidate.exists())
        .expect("some suffix is free");
    fs::rename(path, &target).map_err(|source| SaveError::Io {
        path: path.to_owned(),
        action: "rename",
        source,
    })?;
    Ok(target)
}
