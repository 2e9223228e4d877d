//! Scene files (format version 1): a JSON description of a world at time 0.
//!
//! Users write scenes by hand or generate them, run them with `exact2d simulate`, and compare
//! the results with other engines; the format (`docs/scene-format.md`) is a public contract.
//! This module reads a scene ([`Scene::from_json_str`]), checks every rule of the format
//! ([`Scene::validate`]), builds its [`World`](crate::World) ([`Scene::build_world`]) and writes
//! it back ([`Scene::to_json_string`]) so that every `f64` survives the round trip.
//!
//! A rejected scene gives one [`SceneError`] whose message names the offending item by its
//! path in the file: `balls[3].radius must be > 0`, `balls[2] overlaps balls[0]`,
//! `balls[0].foo: unknown field ...`. The rules are the engine's own, so a scene that
//! validates always builds.
//!
//! ```
//! use exact2d::scene::{Scene, SceneItem};
//! use exact2d::Event;
//!
//! let scene = Scene::from_json_str(r#"{
//!     "segments": [ { "a": [10.0, -5.0], "b": [10.0, 5.0] } ],
//!     "balls": [ { "id": 7, "pos": [0.0, 0.0], "vel": [2.0, 0.0], "radius": 0.5 } ]
//! }"#)?;
//! let mut built = scene.build_world()?;
//!
//! // The ball's centre reaches x = 9.5 at t = 4.75, and the event maps back to the scene.
//! let Some(Event::Contact(hit)) = built.world_mut().step() else { panic!("no contact") };
//! assert_eq!(hit.time, 4.75);
//! assert_eq!(built.ball_id(hit.ball), Some(7));
//! assert_eq!(built.collider_item(hit.collider), Some(SceneItem::Segment(0)));
//!
//! let error = Scene::from_json_str(r#"{ "balls": [ { "id": 0, "pos": [0, 0], "vel": [0, 0], "radius": 0 } ] }"#)
//!     .unwrap_err();
//! assert_eq!(error.to_string(), "balls[0].radius must be > 0");
//! # Ok::<(), exact2d::scene::SceneError>(())
//! ```

mod build;
mod error;
mod format;
mod grid;
mod overlap;
mod parse;
mod validate;

pub use build::BuiltScene;
pub use error::{SceneError, SceneItem};
pub use format::{Scene, SceneBall, SceneCircle, SceneSegment, SceneTable};
