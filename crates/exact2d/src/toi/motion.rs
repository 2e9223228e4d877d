//! The closed-form motion of a ball: position, velocity and constant acceleration.

use glam::DVec2;

/// The motion of a ball's centre from `t = 0`: `position + velocity t + acceleration t^2 / 2`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Motion {
    /// Position at `t = 0`.
    pub position: DVec2,
    /// Velocity at `t = 0`.
    pub velocity: DVec2,
    /// Constant acceleration (gravity); zero for straight motion.
    pub acceleration: DVec2,
}

impl Motion {
    /// Straight motion without acceleration.
    #[must_use]
    pub fn linear(position: DVec2, velocity: DVec2) -> Self {
        Self {
            position,
            velocity,
            acceleration: DVec2::ZERO,
        }
    }

    /// The position at time `t`.
    #[must_use]
    #[inline]
    pub fn position_at(&self, t: f64) -> DVec2 {
        let p = self.position + self.velocity * t;
        // Skipped without acceleration: for huge t, t^2 overflows and 0 * inf is NaN.
        if self.acceleration == DVec2::ZERO {
            p
        } else {
            p + self.acceleration * (0.5 * t * t)
        }
    }

    /// The velocity at time `t`.
    #[must_use]
    #[inline]
    pub fn velocity_at(&self, t: f64) -> DVec2 {
        if self.acceleration == DVec2::ZERO {
            self.velocity
        } else {
            self.velocity + self.acceleration * t
        }
    }
}
