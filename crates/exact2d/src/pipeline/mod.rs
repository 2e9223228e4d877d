//! The event loop: the world, its queue of predicted events, and the events it reports.

// Both queues give the same events bit for bit; the `heap-queue` feature picks the heap instead
// of the calendar (see BENCHMARKS.md for the measurement that chose the calendar), and the
// tests compare them operation by operation.
#[cfg_attr(feature = "heap-queue", allow(dead_code))]
mod calendar;
mod error;
mod event;
mod friction;
mod group;
#[cfg(any(test, feature = "bench-internals"))]
pub(crate) mod hold;
mod instant;
mod jam;
mod observables;
mod pending;
mod periodic;
mod predict;
#[cfg_attr(not(feature = "heap-queue"), allow(dead_code))]
mod queue;
mod rigid;
mod rolling;
mod sleep;
mod step;
mod table;
mod world;

pub use error::WorldError;
pub use event::{BallContactEvent, ContactEvent, Event, SensorEvent};
pub use observables::Observables;
pub use sleep::{Body, SLEEPS_PER_INSTANT};
pub use step::{
    COLLAPSE_FLOOR, Handled, MICRO_HOP, MICRO_HOP_ULPS, STALL_EVENTS_PER_BALL, micro_hop,
};
pub use world::{EventCounts, OVERLAP_TOLERANCE, World, overlap_bound};
