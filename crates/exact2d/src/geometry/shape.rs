//! The shape of a static collider.

use glam::DVec2;

use super::{Circle, Segment};

/// The shape of a static collider.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shape {
    /// A line segment; balls hit its interior from both sides and both end points.
    Segment(Segment),
    /// A disc; balls hit its boundary from outside.
    Circle(Circle),
}

impl Shape {
    /// The distance from `p` to the shape (to its boundary, negative inside a circle).
    #[must_use]
    pub fn distance(&self, p: DVec2) -> f64 {
        match self {
            Shape::Segment(s) => s.distance(p),
            Shape::Circle(c) => c.distance(p),
        }
    }

    /// The axis-aligned bounding box, as (min, max).
    #[must_use]
    pub fn aabb(&self) -> (DVec2, DVec2) {
        match self {
            Shape::Segment(s) => (s.a().min(s.b()), s.a().max(s.b())),
            Shape::Circle(c) => (c.center - c.radius, c.center + c.radius),
        }
    }
}
