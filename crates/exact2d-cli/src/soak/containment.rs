//! Containment: in a closed scene no ball's centre leaves the box around the solid colliders.
//!
//! A ball that tunnelled through a wall of a closed container flies off for ever; its centre
//! then leaves the bounding box of the walls. The test is exact (no tolerance): a ball inside
//! a container has its centre at least its radius inside every wall, far more than any
//! rounding error.

use exact2d::{Ball, Collider, DVec2};

/// An axis-aligned box, as its lowest and highest corners.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounds {
    /// The lowest corner.
    pub min: DVec2,
    /// The highest corner.
    pub max: DVec2,
}

/// The bounding box of the solid colliders (sensors do not hold anything in); `None` if
/// there is none.
#[must_use]
pub fn solid_bounds(colliders: &[Collider]) -> Option<Bounds> {
    colliders
        .iter()
        .filter(|c| !c.sensor)
        .map(|c| c.shape.aabb())
        .fold(None, |bounds: Option<Bounds>, (min, max)| {
            Some(match bounds {
                None => Bounds { min, max },
                Some(b) => Bounds {
                    min: b.min.min(min),
                    max: b.max.max(max),
                },
            })
        })
}

/// The indices of the balls whose centres are outside `bounds` (on the boundary is inside),
/// in snapshot order. A NaN position counts as outside.
#[must_use]
pub fn escaped_balls(balls: &[Ball], bounds: Bounds) -> Vec<usize> {
    balls
        .iter()
        .enumerate()
        .filter(|(_, b)| {
            let p = b.position;
            let inside = p.x >= bounds.min.x
                && p.x <= bounds.max.x
                && p.y >= bounds.min.y
                && p.y <= bounds.max.y;
            !inside
        })
        .map(|(i, _)| i)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use exact2d::{CollisionGroups, Segment, Shape};

    fn ball_at(x: f64, y: f64) -> Ball {
        Ball {
            position: DVec2::new(x, y),
            velocity: DVec2::ZERO,
            radius: 0.1,
            mass: 1.0,
            restitution: 1.0,
            groups: CollisionGroups::ALL,
            user_data: 0,
            spin: 0.0,
            angle: 0.0,
            inertia: 0.5,
            friction: 0.0,
            tangential_restitution: 0.0,
            rolling_resistance: 0.0,
            roll: DVec2::ZERO,
        }
    }

    fn segment(a: [f64; 2], b: [f64; 2], sensor: bool) -> Collider {
        Collider {
            shape: Shape::Segment(Segment::new(a.into(), b.into()).unwrap()),
            sensor,
            restitution: 1.0,
            groups: CollisionGroups::ALL,
            user_data: 0,
            friction: 0.0,
            tangential_restitution: 0.0,
            rolling_resistance: 0.0,
        }
    }

    #[test]
    fn the_box_spans_the_solid_colliders_only() {
        let colliders = [
            segment([0.0, 0.0], [4.0, 0.0], false),
            segment([4.0, 0.0], [4.0, 3.0], false),
            segment([-10.0, 0.0], [0.0, 50.0], true),
        ];
        let bounds = solid_bounds(&colliders).unwrap();
        assert_eq!(
            (bounds.min, bounds.max),
            (DVec2::ZERO, DVec2::new(4.0, 3.0))
        );
        assert_eq!(solid_bounds(&colliders[2..]), None);
    }

    #[test]
    fn balls_outside_the_box_are_found_and_the_boundary_is_inside() {
        let bounds = Bounds {
            min: DVec2::ZERO,
            max: DVec2::new(4.0, 3.0),
        };
        let balls = [
            ball_at(2.0, 1.0),
            ball_at(4.0, 3.0),
            ball_at(4.000_000_001, 1.0),
            ball_at(2.0, -1e-300),
            ball_at(f64::NAN, 1.0),
        ];
        assert_eq!(escaped_balls(&balls, bounds), [2, 3, 4]);
    }
}
