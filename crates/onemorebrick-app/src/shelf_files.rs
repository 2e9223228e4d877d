//! The desktop's shelf: one file per entry in a directory (the platform's data directory),
//! written to a temporary file, synced and renamed over the old one.

use std::fs;
use std::io::{self, Write};
use std::path::{Path, PathBuf};

use crate::shelf::{Entry, Shelf};

/// Files in a directory (created when first written).
#[derive(Clone, Debug)]
pub struct Files {
    dir: PathBuf,
}

impl Files {
    /// The platform's data directory for the game.
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

    /// The file of `entry`.
    pub fn path(&self, entry: Entry) -> PathBuf {
        self.dir.join(entry.name())
    }
}

impl Shelf for Files {
    fn label(&self, entry: Entry) -> String {
        self.path(entry).display().to_string()
    }

    fn read(&self, entry: Entry) -> Result<Option<String>, String> {
        let path = self.path(entry);
        match fs::read_to_string(&path) {
            Ok(text) => Ok(Some(text)),
            Err(e) if e.kind() == io::ErrorKind::NotFound => Ok(None),
            Err(e) => Err(format!("{}: could not read: {e}", path.display())),
        }
    }

    fn write(&self, entry: Entry, text: &str) -> Result<(), String> {
        fs::create_dir_all(&self.dir)
            .map_err(|e| format!("{}: could not create: {e}", self.dir.display()))?;
        let path = self.path(entry);
        write_atomically(&path, text.as_bytes())
            .map_err(|e| format!("{}: could not write: {e}", path.display()))
    }

    fn set_aside(&self, entry: Entry) -> Result<String, String> {
        onemorebrick::set_aside(&self.path(entry))
            .map(|to| to.display().to_string())
            .map_err(|e| e.to_string())
    }
}

/// Writes `bytes` to a temporary file beside `path`, syncs it, renames it over `path`, and
/// syncs the directory so the rename itself is durable (where directories can be synced:
/// on Unix; elsewhere that open fails and the rename is as durable as the platform makes it).
fn write_atomically(path: &Path, bytes: &[u8]) -> io::Result<()> {
    let temp = onemorebrick::save::temp_path(path);
    let mut file = fs::File::create(&temp)?;
    file.write_all(bytes)?;
    file.sync_all()?;
    drop(file);
    fs::rename(&temp, path)?;
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        if let Ok(dir) = fs::File::open(dir) {
            let _ = dir.sync_all();
        }
    }
    Ok(())
}
