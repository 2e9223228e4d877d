//! # exact2d-hunt: adversarial scenes for exact2d, and the invariants they must keep
//!
//! The fuzz targets' worlds are random, in general position, where contacts never tie. Scenes
//! that users write are the opposite: round numbers, channels exactly one diameter wide, pegs
//! one diameter from a wall, balls placed touching, wedges, funnels, shared end points, at
//! every scale and far from the origin. This crate generates such scenes ([`generate`]),
//! seeded or from a fuzzer's bytes ([`source`]), and runs them with every invariant checked
//! after every event ([`check`], [`run`]): time moves on, nothing overlaps deeper than the
//! engine's stated bound, nothing leaves the box, energy grows by no more than the engine's
//! floors.
//!
//! The `exact2d-hunt` command runs seeds for a while and tallies what it finds; the fuzz
//! targets `world_events` and `world_gravity` draw from the same generator; this crate's tests
//! run it as a property test and replay every scene a hunt once broke.
//!
//! ```
//! use exact2d_hunt::{generate::{generate, Options}, run::{run, Limits}, source::SplitMix64};
//!
//! let scene = generate(&mut SplitMix64(42), Options::default());
//! let outcome = run(&scene, Limits { until: 1.0, events: 20_000, collapse: 0.0 });
//! assert_eq!(outcome.finding, None);
//! ```

pub mod check;
pub mod generate;
pub mod periodic;
pub mod run;
pub mod source;
