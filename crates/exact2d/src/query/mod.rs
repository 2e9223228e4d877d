//! Questions about the world that change nothing: where would a ball go?

mod bounce_path;
mod cast;

pub use cast::{CastHit, CastOptions};
