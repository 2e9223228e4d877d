//! The page's `localStorage`: text by key, for this site only, kept across reloads.

use crate::ffi::{self, Status};

/// The text stored under `key`, or `None` if there is none.
///
/// # Errors
/// The browser's message when the storage cannot be read (turned off, for example).
pub fn get(key: &str) -> Result<Option<String>, String> {
    match ffi::storage_get(key) {
        Status::Found => Ok(Some(ffi::take_staged())),
        Status::Absent | Status::Done => Ok(None),
        Status::Failed => Err(ffi::take_staged()),
    }
}

/// Stores `value` under `key`, whole: `localStorage.setItem` replaces the old text in one
/// step or, failing, leaves it.
///
/// # Errors
/// The browser's message (the storage full or turned off).
pub fn set(key: &str, value: &str) -> Result<(), String> {
    match ffi::storage_set(key, value) {
        Status::Failed => Err(ffi::take_staged()),
        _ => Ok(()),
    }
}

/// Removes `key` (nothing if there is none).
///
/// # Errors
/// The browser's message.
pub fn remove(key: &str) -> Result<(), String> {
    match ffi::storage_remove(key) {
        Status::Failed => Err(ffi::take_staged()),
        _ => Ok(()),
    }
}
