//! The browser's services for One More Brick's web build, through a miniquad loader plugin
//! (`web/onemorebrick.js`, registered with `miniquad_add_plugin`): the page's `localStorage`
//! for saves, `crypto.getRandomValues` for new games' seeds, the page's URL query, its
//! clock, its hiding (a phone switching apps, a tab closed or reloaded), and a channel to
//! the outside (`window.onemorebrick`, read by the browser test and the benchmark).
//!
//! The plugin's functions are `extern "C"` imports of the wasm module (the `env` module,
//! where miniquad's own are), called in one module ([`ffi`](self)); the page calls back
//! through two exports, `onemorebrick_web_crate_version` (miniquad's plugin version check)
//! and `onemorebrick_web_page_hidden`. Text crosses as UTF-8: from Rust as a pointer and a
//! length into the wasm memory, which the plugin reads; to Rust by the plugin keeping the
//! answer aside ("staged") until Rust asks for its length and gives it a buffer to copy it
//! into. No wasm-bindgen: miniquad's loader is the page's only JavaScript runtime.
//!
//! On every other target the crate is empty: the desktop build has files and the operating
//! system's generator.

#[cfg(target_arch = "wasm32")]
mod ffi;
#[cfg(target_arch = "wasm32")]
mod local_storage;
#[cfg(target_arch = "wasm32")]
mod page;

#[cfg(target_arch = "wasm32")]
pub use local_storage::{get, remove, set};
#[cfg(target_arch = "wasm32")]
pub use page::{now_ms, on_page_hide, publish, query, random_u64};
