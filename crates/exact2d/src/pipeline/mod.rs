//! The event loop: the world, its queue of predicted events, and the events it reports.

mod error;
mod event;
mod pending;
mod predict;
mod queue;
mod step;
mod world;

pub use error::WorldError;
pub use event::{BallContactEvent, ContactEvent, Event, SensorEvent};
pub use world::{EventCounts, OVERLAP_TOLERANCE, World};
