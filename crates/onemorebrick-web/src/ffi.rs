//! The calls into the page's JavaScript (`web/onemorebrick.js`) and its calls back: the only
//! `unsafe` code of the web build. Each import only reads the memory it is given (a
//! pointer and a length of a live `&[u8]`), or writes into the `&mut [u8]` it is given and
//! no further; none keeps a pointer after it returns.
#![allow(unsafe_code)]

use std::cell::RefCell;

/// The plugin's version (`version` in `web/onemorebrick.js`); miniquad's loader compares the
/// two and reports a mismatch in the console.
const PLUGIN_VERSION: u32 = 1;

/// What a call to the plugin answered (its return value).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// Done; nothing to read.
    Done,
    /// Done; the answer is staged (read it with [`take_staged`]).
    Found,
    /// There was nothing by that name.
    Absent,
    /// It failed; the browser's message is staged.
    Failed,
}

impl Status {
    fn from_code(code: i32) -> Self {
        match code {
            0 => Status::Done,
            1 => Status::Found,
            2 => Status::Absent,
            _ => Status::Failed,
        }
    }
}

#[link(wasm_import_module = "env")]
unsafe extern "C" {
    fn onemorebrick_storage_get(key: *const u8, key_len: usize) -> i32;
    fn onemorebrick_storage_set(
        key: *const u8,
        key_len: usize,
        value: *const u8,
        value_len: usize,
    ) -> i32;
    fn onemorebrick_storage_remove(key: *const u8, key_len: usize) -> i32;
    fn onemorebrick_random_fill(into: *mut u8, len: usize) -> i32;
    fn onemorebrick_query(name: *const u8, name_len: usize) -> i32;
    fn onemorebrick_now() -> f64;
    fn onemorebrick_publish(key: *const u8, key_len: usize, json: *const u8, json_len: usize);
    fn onemorebrick_staged_len() -> usize;
    fn onemorebrick_staged_take(into: *mut u8, len: usize);
}

/// `localStorage.getItem(key)`, staged.
pub fn storage_get(key: &str) -> Status {
    Status::from_code(unsafe { onemorebrick_storage_get(key.as_ptr(), key.len()) })
}

/// `localStorage.setItem(key, value)`.
pub fn storage_set(key: &str, value: &str) -> Status {
    let code =
        unsafe { onemorebrick_storage_set(key.as_ptr(), key.len(), value.as_ptr(), value.len()) };
    Status::from_code(code)
}

/// `localStorage.removeItem(key)`.
pub fn storage_remove(key: &str) -> Status {
    Status::from_code(unsafe { onemorebrick_storage_remove(key.as_ptr(), key.len()) })
}

/// Fills `into` from `crypto.getRandomValues`.
pub fn random_fill(into: &mut [u8]) -> Status {
    Status::from_code(unsafe { onemorebrick_random_fill(into.as_mut_ptr(), into.len()) })
}

/// The URL query parameter `name`, staged.
pub fn query(name: &str) -> Status {
    Status::from_code(unsafe { onemorebrick_query(name.as_ptr(), name.len()) })
}

/// `performance.now()`: milliseconds since the page started loading.
pub fn now() -> f64 {
    unsafe { onemorebrick_now() }
}

/// Sets `window.onemorebrick[key]` to the value of the JSON text `json`.
pub fn publish(key: &str, json: &str) {
    unsafe { onemorebrick_publish(key.as_ptr(), key.len(), json.as_ptr(), json.len()) }
}

/// The staged answer of the last call, as text (the plugin stages UTF-8, so a failure to
/// decode would be the plugin's bug; it is replaced, not trusted).
pub fn take_staged() -> String {
    let len = unsafe { onemorebrick_staged_len() };
    let mut bytes = vec![0u8; len];
    unsafe { onemorebrick_staged_take(bytes.as_mut_ptr(), bytes.len()) };
    String::from_utf8_lossy(&bytes).into_owned()
}

thread_local! {
    /// What to do when the page is hidden ([`crate::on_page_hide`]).
    pub static ON_PAGE_HIDE: RefCell<Option<Box<dyn FnMut()>>> = RefCell::new(None);
}

/// miniquad's loader checks that the plugin and the crate agree.
#[unsafe(no_mangle)]
pub extern "C" fn onemorebrick_web_crate_version() -> u32 {
    PLUGIN_VERSION
}

/// The page calls this when it is hidden (`visibilitychange` to hidden, `pagehide`), before
/// any later frame; it runs the hook of [`crate::on_page_hide`]. A hook busy already (the
/// page hidden from inside a frame) is not run twice.
#[unsafe(no_mangle)]
pub extern "C" fn onemorebrick_web_page_hidden() {
    ON_PAGE_HIDE.with(|hook| {
        if let Ok(mut hook) = hook.try_borrow_mut() {
            if let Some(hook) = hook.as_mut() {
                hook();
            }
        }
    });
}
