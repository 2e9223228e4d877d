//! The broad phase: which bodies a ball's next event can involve.
//!
//! [`StaticGrid`] answers "which colliders lie along this ball's path" by walking a uniform
//! grid in time order; [`BallGrid`] keeps balls in cells with crossing events so that a ball is
//! predicted only against the balls of its 3 x 3 block. Both only *select* candidates: every
//! time of impact still comes from [`crate::toi`], so the broad phase changes the cost of a
//! prediction, never its result.

mod ball_grid;
mod path;
mod static_grid;
mod torus;

/// For the scene's validation, which checks a periodic box's radii as the grid will.
#[cfg(feature = "scene")]
pub(crate) use ball_grid::largest_periodic_radius;
pub(crate) use ball_grid::{BallGrid, Place};
pub(crate) use path::Aabb;
pub(crate) use static_grid::StaticGrid;
pub(crate) use torus::Torus;
