//! # exact2d: exact, event-driven 2D physics for balls
//!
//! Most physics engines advance the world in fixed time steps and then look for overlaps.
//! Between two steps a fast ball can pass straight through a thin wall, and the overlaps they do
//! find are pushed apart after the fact. exact2d takes no time steps at all. Balls (circles)
//! move in closed form, straight or on parabolas under uniform gravity, and every collision
//! is computed *in advance*, algebraically, at its exact time of impact:
//!
//! 1. for every ball, predict its earliest event: the first time it touches a segment (the
//!    interior or an end point), a static circle, or another ball;
//! 2. take the earliest event in the whole world and move only the balls involved to that
//!    moment;
//! 3. respond (reflection with restitution, or an impulse between two balls), predict those
//!    balls again, and repeat.
//!
//! Nothing is ever missed, whatever the speed, nothing is ever pushed apart, and the same
//! inputs give the same bits on every run, in debug and in release.
//!
//! ```
//! use exact2d::{BallDesc, ColliderDesc, DVec2, Event, World};
//!
//! let mut world = World::new();
//! // A wall along x = 10 and a ball of radius 0.5 flying at it at 1024 units per second.
//! world.add_collider(ColliderDesc::segment(DVec2::new(10.0, -5.0), DVec2::new(10.0, 5.0)))?;
//! let ball = world.add_ball(BallDesc::new(DVec2::ZERO, 0.5).velocity(DVec2::new(1024.0, 0.0)))?;
//!
//! // The ball touches the wall when its centre reaches x = 9.5, at t = 9.5 / 1024.
//! let Some(Event::Contact(hit)) = world.step() else { panic!("the ball must hit the wall") };
//! assert_eq!(hit.time, 9.5 / 1024.0);
//! assert_eq!(hit.normal, DVec2::new(-1.0, 0.0));
//!
//! // Frames are just clock values: every ball is exactly where its closed form puts it.
//! world.advance_to(19.5 / 1024.0)?;
//! assert_eq!(world.ball(ball).unwrap().position, DVec2::new(-0.5, 0.0));
//! # Ok::<(), exact2d::WorldError>(())
//! ```
//!
//! ## Map of the crate
//!
//! - [`World`]: bodies, colliders and the clock; [`World::step_until`] hands events to the
//!   caller one at a time so a game can react before the world goes on; [`World::advance_to`]
//!   runs to a frame time. [`World::cast_ball`] and [`World::bounce_path`] answer "where would a
//!   ball go" without changing anything (an aim preview).
//! - [`toi`]: the exact time-of-impact kernels, one shape pair per file, usable on their own.
//! - [`roots`]: the root finders behind them: a cancellation-free quadratic, and a bracketed
//!   refinement of the quartic that a ball under gravity has against a corner or a circle.
//! - [`response`](reflect): reflection and the mass-weighted impulse.
//!
//! ## Contracts
//!
//! - **Touching contacts.** Touching (or overlapping by rounding) and approaching, at first or
//!   second order, is a contact *now*; touching and separating or tangential is no event. See
//!   [`toi`]. Touching bodies overlap by no more than [`overlap_bound`]: 1e-9 of their contact
//!   distance near the origin, a fixed number of units in the last place of their coordinates
//!   far from it.
//! - **Ties.** Events at the same time are handled one after another in a total order: time,
//!   then kind (collider contacts, ball-ball contacts, sensor crossings), then slot indices.
//!   A Newton's cradle of touching balls therefore passes its momentum down the row in one
//!   instant, as a sequence of zero-time collisions. A chain that comes back to a contact a
//!   third time (a ball between the walls of an exact fit, a wedge) is a *jam*, resolved as
//!   one simultaneous impact of every body touching it, so the clock always moves on after a
//!   bounded number of events ([`World::instant_events`]; [`WorldError::Stalled`] is the
//!   safety net).
//! - **Resting contact.** Under gravity, a ball that touches a solid collider, is pulled into
//!   it and would hop less than [`SETTLE_HEIGHT`] comes to rest on it: it slides under the
//!   tangential part of gravity, pivots over corners and pegs, leaves where the surface ends
//!   or turns away, and wakes when hit ([`World::ball_support`]). Bouncing on a floor with
//!   restitution below 1 therefore ends after finitely many events, at the accumulation time
//!   of the bounces. Inelastic collapse is held off by the TC model
//!   ([`World::set_collapse_time`], and always at [`COLLAPSE_FLOOR`] of the clock).
//! - **Determinism.** Only `+ - * /` and `sqrt` are used on the simulation path, no hash maps,
//!   no clocks: runs are bit-for-bit reproducible across runs, platforms and build profiles.
//! - **Errors, not panics.** Every call that takes numbers from outside validates them and
//!   returns a [`WorldError`].
#![forbid(unsafe_code)]

mod broad;
pub mod dynamics;
pub mod geometry;
mod pipeline;
pub mod query;
pub mod roots;
#[cfg(feature = "scene")]
pub mod scene;
pub mod toi;

pub use dynamics::{
    Ball, BallDesc, BallHandle, DEFAULT_INERTIA, PIVOT_STEP, RESOLUTION, Roughness, SETTLE_HEIGHT,
    SLEEP_SPEED, SpinningBody, Table, Time, Trajectory, apply_friction, collide_balls,
    collide_balls_backed, friction_impulse, reflect, restated_bounce,
};
pub use geometry::{
    Circle, Collider, ColliderDesc, ColliderHandle, CollisionGroups, Feature, Segment, Shape,
};
pub use glam::DVec2;
pub use pipeline::{
    BallContactEvent, Body, COLLAPSE_FLOOR, ContactEvent, Event, EventCounts, Handled, MICRO_HOP,
    MICRO_HOP_ULPS, OVERLAP_TOLERANCE, Observables, SLEEPS_PER_INSTANT, STALL_EVENTS_PER_BALL,
    SensorEvent, World, WorldError, micro_hop, overlap_bound,
};
pub use query::{CastHit, CastOptions};

/// Internals exposed for the benchmark crate only (feature `bench-internals`): no stability
/// promise, not part of the API.
#[cfg(feature = "bench-internals")]
#[doc(hidden)]
pub mod bench_internals {
    pub use crate::pipeline::hold::{HoldModel, QueueKind};
}

/// The README's examples, compiled and run as doctests so they stay true.
#[cfg(doctest)]
#[doc = include_str!("../../../README.md")]
struct ReadmeDoctests;
