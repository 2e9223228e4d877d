//! A static circle.

use glam::DVec2;

/// A solid static disc (or a round sensor) with a centre and a radius.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Circle {
    /// The centre.
    pub center: DVec2,
    /// The radius, `> 0`.
    pub radius: f64,
}

impl Circle {
    /// The circle, or `None` if the centre is not finite or the radius is not positive and
    /// finite.
    #[must_use]
    pub fn new(center: DVec2, radius: f64) -> Option<Self> {
        (center.is_finite() && radius > 0.0 && radius.is_finite())
            .then_some(Self { center, radius })
    }

    /// The distance from `p` to the circle's boundary; negative inside.
    #[must_use]
    pub fn distance(&self, p: DVec2) -> f64 {
        p.distance(self.center) - self.radius
    }
}
