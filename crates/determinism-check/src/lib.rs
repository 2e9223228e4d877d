//! The determinism checks of the engine and the game as plain functions, so that the native
//! tests and a wasm32 build compute the same runs and can be compared bit for bit.
//!
//! Every [`Case`] is a named run giving a 64-bit hash of every bit it produced: the engine's
//! golden run (`tests/determinism.rs` of `exact2d` checks its golden value), and whole games
//! of the rules replayed from a seed and commands (`tests/determinism.rs` of `onemorebrick`
//! checks theirs). The same list is printed natively by this crate's binary and computed in
//! wasm32 under Node.js's V8 by `web/hashes.mjs`, through the C functions of [`exports`]; CI
//! compares the two lists line by line.
//!
//! ```
//! use determinism_check::{cases, engine};
//!
//! let run = engine::golden_run(&engine::regular_frames(1.0 / 60.0));
//! let case = cases().find(|c| c.name == "engine/golden-run").unwrap();
//! assert_eq!((case.hash)(), run.hash);
//! ```
//!
//! Without the default `game` feature only the engine's cases exist (the engine's tests use
//! this crate so, and build without the rules).

pub mod engine;
pub mod exports;
#[cfg(feature = "game")]
pub mod game;
pub mod trig;

/// A named run and the function that hashes it.
#[derive(Clone, Copy, Debug)]
pub struct Case {
    /// A stable name, without spaces: `engine/...` or `game/...`.
    pub name: &'static str,
    /// Runs the case and returns its hash.
    pub hash: fn() -> u64,
}

/// Every case, the engine's first, in a fixed order.
pub fn cases() -> impl Iterator<Item = &'static Case> {
    ENGINE_CASES.iter().chain(GAME_CASES)
}

const ENGINE_CASES: &[Case] = &[
    Case {
        name: "engine/golden-run",
        hash: || engine::golden_run(&engine::regular_frames(1.0 / 60.0)).hash,
    },
    Case {
        name: "engine/events-in-one-frame",
        hash: || engine::events_and_end(&[40.0]),
    },
    Case {
        name: "engine/events-in-irregular-frames",
        hash: || engine::events_and_end(&engine::irregular_frames()),
    },
    Case {
        name: "engine/resting-pile-of-24",
        hash: || engine::resting_pile().0,
    },
    Case {
        name: "engine/rough-resting-pile-of-24",
        hash: || engine::rough_resting_pile().0,
    },
];

#[cfg(not(feature = "game"))]
const GAME_CASES: &[Case] = &[];

#[cfg(feature = "game")]
const GAME_CASES: &[Case] = &[
    Case {
        name: "game/seed-1-30-rounds",
        hash: || game::golden_game(1, 30),
    },
    Case {
        name: "game/seed-2024-60-rounds",
        hash: || game::golden_game(2024, 60),
    },
    Case {
        name: "game/seed-3-12-rounds-in-frames-of-0.0137-s",
        hash: || fnv1a(game::play(3, 12, game::frames(0.013_7)).1),
    },
    Case {
        name: "game/seed-21-mixed-25-rounds",
        hash: || onemorebrick::hash_game(&game::mixed_game()),
    },
    Case {
        name: "game/seed-21-replayed-from-json",
        hash: || onemorebrick::hash_game(&game::replayed_mixed_game()),
    },
    Case {
        name: "game/seed-4-in-flight-at-0.7-s",
        hash: || onemorebrick::hash_game(&game::mid_volley(4, 0.7)),
    },
    Case {
        name: "game/seed-5-saved-at-1.3-s-loaded-finished",
        hash: || onemorebrick::hash_game(&game::mid_volley_reloaded(5, 1.3)),
    },
    Case {
        name: "game/dense-volley-at-once",
        hash: || onemorebrick::hash_game(&game::dense_volley_at_once()),
    },
    Case {
        name: "game/dense-volley-in-frames-of-1/60-s",
        hash: || onemorebrick::hash_game(&game::dense_volley_in_frames()),
    },
    Case {
        name: "game/dense-volley-saved-after-500-events",
        hash: || onemorebrick::hash_game(&game::dense_volley_reloaded().0),
    },
];

/// FNV-1a (64-bit) over 64-bit words, little-endian: a stable hash for golden values (std's
/// hasher may change).
#[must_use]
pub fn fnv1a(words: impl IntoIterator<Item = u64>) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for w in words {
        for byte in w.to_le_bytes() {
            h = (h ^ u64::from(byte)).wrapping_mul(0x0100_0000_01b3);
        }
    }
    h
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_unique_and_have_no_spaces() {
        let names: Vec<&str> = cases().map(|c| c.name).collect();
        let mut sorted = names.clone();
        sorted.sort_unstable();
        sorted.dedup();
        assert_eq!(sorted.len(), names.len(), "{names:?}");
        assert!(
            names
                .iter()
                .all(|n| !n.is_empty() && !n.contains(char::is_whitespace))
        );
    }

    /// FNV-1a over bytes, the reference definition.
    fn fnv1a_bytes(bytes: &[u8]) -> u64 {
        bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
            (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
        })
    }

    #[test]
    fn fnv1a_is_the_published_hash_of_the_words_little_endian_bytes() {
        // The FNV authors' test vector for the one-byte string "a".
        assert_eq!(fnv1a_bytes(b"a"), 0xaf63_dc4c_8601_ec8c);
        assert_eq!(fnv1a([]), fnv1a_bytes(&[]));
        let words = [0x0102_0304_0506_0708, u64::MAX, 0];
        let bytes: Vec<u8> = words.iter().flat_map(|w| w.to_le_bytes()).collect();
        assert_eq!(fnv1a(words), fnv1a_bytes(&bytes));
    }
}
