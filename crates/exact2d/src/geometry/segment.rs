//! A static line segment.

use glam::DVec2;

/// `2^600`, built from its bits: an exact power of two.
const TWO_POW_600: f64 = f64::from_bits((1023 + 600) << 52);

/// A line segment from `a` to `b`, with its unit normal precomputed.
///
/// Balls collide with its interior on both sides and with both end points, so a segment acts
/// like a capsule of zero thickness: its boundary, for a ball of radius `r`, is the set of points
/// at distance `r` from the segment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Segment {
    a: DVec2,
    b: DVec2,
    /// `b - a`.
    direction: DVec2,
    /// The left unit normal, `perp(b - a) / |b - a|`. For axis-aligned segments this is
    /// exact, so walls of a box reflect balls without rounding.
    normal: DVec2,
}

impl Segment {
    /// The segment from `a` to `b`, or `None` if the end points are equal or not finite, or if
    /// the square of the length, `|b - a|^2`, is not a positive finite `f64`: segments longer
    /// than about `1.3e154` or shorter than about `2.2e-162` (the engine needs the squared
    /// length to project onto the segment). [`World::add_collider`](crate::World::add_collider)
    /// reports all of these as [`WorldError::DegenerateSegment`](crate::WorldError::DegenerateSegment).
    ///
    /// The normal is a unit vector to within an ulp or two whatever the length: for a squared
    /// length below the normal range of `f64` (segments shorter than about `1.5e-154`) it is
    /// computed from the direction scaled by `2^600`, exactly, rather than from the few bits a
    /// subnormal square keeps.
    #[must_use]
    pub fn new(a: DVec2, b: DVec2) -> Option<Self> {
        let direction = b - a;
        let squared = direction.length_squared();
        if !(a.is_finite() && b.is_finite()) || a == b || !(squared > 0.0 && squared.is_finite()) {
            return None;
        }
        let normal = if squared >= f64::MIN_POSITIVE {
            direction.perp() / squared.sqrt()
        } else {
            // 2^600 scales exactly, and `|b - a| >= 2.2e-162` times it stays far from overflow.
            let scaled = direction * TWO_POW_600;
            scaled.perp() / scaled.length()
        };
        // Adding +0 turns a -0 component into +0, so normals print and hash cleanly.
        let normal = normal + DVec2::ZERO;
        Some(Self {
            a,
            b,
            direction,
            normal,
        })
    }

    /// The first end point.
    #[must_use]
    pub fn a(&self) -> DVec2 {
        self.a
    }

    /// The second end point.
    #[must_use]
    pub fn b(&self) -> DVec2 {
        self.b
    }

    /// `b - a`.
    #[must_use]
    pub fn direction(&self) -> DVec2 {
        self.direction
    }

    /// The left unit normal, pointing to the side where `(b - a).perp_dot(p - a) > 0`.
    #[must_use]
    pub fn normal(&self) -> DVec2 {
        self.normal
    }

    /// Signed distance from the segment's line to `p`, positive on the normal's side.
    #[must_use]
    #[inline]
    pub fn signed_distance(&self, p: DVec2) -> f64 {
        self.normal.dot(p - self.a)
    }

    /// Position of the projection of `p` along the segment: 0 at `a`, 1 at `b`.
    #[must_use]
    #[inline]
    pub fn projection(&self, p: DVec2) -> f64 {
        self.direction.dot(p - self.a) / self.direction.length_squared()
    }

    /// The point of the segment closest to `p`.
    #[must_use]
    pub fn closest_point(&self, p: DVec2) -> DVec2 {
        let u = self.projection(p).clamp(0.0, 1.0);
        self.a + self.direction * u
    }

    /// The distance from `p` to the segment.
    #[must_use]
    pub fn distance(&self, p: DVec2) -> f64 {
        let u = self.projection(p);
        if u <= 0.0 {
            p.distance(self.a)
        } else if u >= 1.0 {
            p.distance(self.b)
        } else {
            self.signed_distance(p).abs()
        }
    }
}
