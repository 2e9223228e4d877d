//! The page: its URL query, its clock, its random source, its hiding, and what it shows the
//! outside.

use crate::ffi::{self, Status};

/// The URL query parameter `name` (`?name=value`), if the page's address has it.
pub fn query(name: &str) -> Option<String> {
    match ffi::query(name) {
        Status::Found => Some(ffi::take_staged()),
        _ => None,
    }
}

/// Milliseconds since the page started loading (`performance.now()`); for timing only.
pub fn now_ms() -> f64 {
    ffi::now()
}

/// 64 random bits from the browser's cryptographic generator (`crypto.getRandomValues`).
///
/// # Errors
/// The browser's message if it has no such generator.
pub fn random_u64() -> Result<u64, String> {
    let mut bytes = [0u8; 8];
    match ffi::random_fill(&mut bytes) {
        Status::Failed => Err(ffi::take_staged()),
        _ => Ok(u64::from_le_bytes(bytes)),
    }
}

/// Runs `hook` whenever the page is hidden (the player switches apps or tabs, reloads or
/// closes it): the last moment the page may run code, and no frame follows it. Replaces
/// the previous hook.
pub fn on_page_hide(hook: impl FnMut() + 'static) {
    ffi::ON_PAGE_HIDE.with(|h| *h.borrow_mut() = Some(Box::new(hook)));
}

/// Sets `window.onemorebrick[key]` to the value of the JSON text `json`: what the page tells
/// scripts driving it (the browser test, the benchmark).
pub fn publish(key: &str, json: &str) {
    ffi::publish(key, json);
}
