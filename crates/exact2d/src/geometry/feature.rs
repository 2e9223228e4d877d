//! The parts of a collider a ball can touch.

use glam::DVec2;

use super::Shape;
use crate::toi::SegmentFeature;

/// Which part of a collider a ball touched.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Feature {
    /// A segment's interior.
    SegmentInterior,
    /// A segment's end point `a`.
    SegmentEndA,
    /// A segment's end point `b`.
    SegmentEndB,
    /// A static circle.
    Circle,
}

impl From<SegmentFeature> for Feature {
    fn from(f: SegmentFeature) -> Self {
        match f {
            SegmentFeature::Interior => Feature::SegmentInterior,
            SegmentFeature::EndA => Feature::SegmentEndA,
            SegmentFeature::EndB => Feature::SegmentEndB,
        }
    }
}

impl Feature {
    /// A small number giving the tie-breaking order of features at equal times.
    pub(crate) fn rank(self) -> u8 {
        self as u8
    }
}

impl Shape {
    /// The contact normal (from the shape towards the ball's centre, not normalised) and the
    /// contact point on the shape, for a ball centred at `center` touching `feature`.
    ///
    /// At an end point the normal points from the corner to the ball's centre; on a segment's
    /// interior it is the segment's normal on the ball's side; on a circle it points from the
    /// circle's centre to the ball's.
    #[must_use]
    pub fn contact(&self, feature: Feature, center: DVec2) -> (DVec2, DVec2) {
        match (self, feature) {
            (Shape::Segment(s), Feature::SegmentEndA) => (center - s.a(), s.a()),
            (Shape::Segment(s), Feature::SegmentEndB) => (center - s.b(), s.b()),
            (Shape::Segment(s), _) => {
                let distance = s.signed_distance(center);
                // `ZERO - n` rather than `-n`: no -0 components.
                let normal = if distance >= 0.0 {
                    s.normal()
                } else {
                    DVec2::ZERO - s.normal()
                };
                (normal, center - s.normal() * distance)
            }
            (Shape::Circle(c), _) => {
                let n = center - c.center;
                (n, c.center + n * (c.radius / n.length()))
            }
        }
    }
}
