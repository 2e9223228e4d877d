//! Ball against a static circle.

use glam::DVec2;

use super::{Crossing, Motion, time_of_impact_ball_point};

/// The first time in `[0, horizon]` at which a ball of `ball_radius` touches (or, for
/// `Crossing::Exit`, stops overlapping) the static circle of `circle_radius` at `center`.
///
/// The ball touches the circle when its centre is `ball_radius + circle_radius` from `center`,
/// so this is [`time_of_impact_ball_point`] with the summed radius; the same policy and
/// exactness apply.
#[must_use]
pub fn time_of_impact_ball_circle(
    motion: &Motion,
    ball_radius: f64,
    center: DVec2,
    circle_radius: f64,
    crossing: Crossing,
    horizon: f64,
) -> Option<f64> {
    time_of_impact_ball_point(
        motion,
        center,
        ball_radius + circle_radius,
        crossing,
        horizon,
    )
}
