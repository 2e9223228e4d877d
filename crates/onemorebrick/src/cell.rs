//! Cells of the grid: what each holds, and the outline of a brick.

use exact2d::DVec2;
use serde::{Deserialize, Serialize};

use crate::pickup::Pickup;

/// The corner of a cell that a triangular brick leaves open: the triangle is the half of the
/// cell on the other side of the diagonal that cuts that corner off.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Corner {
    /// The top-left corner is open.
    TopLeft,
    /// The top-right corner is open.
    TopRight,
    /// The bottom-left corner is open.
    BottomLeft,
    /// The bottom-right corner is open.
    BottomRight,
}

impl Corner {
    /// The four corners, in a fixed order.
    pub const ALL: [Corner; 4] = [
        Corner::TopLeft,
        Corner::TopRight,
        Corner::BottomLeft,
        Corner::BottomRight,
    ];
}

/// The shape of a brick.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Shape {
    /// The whole cell: four segments.
    Square,
    /// A right triangle with the given corner open: three segments.
    Triangle(Corner),
}

/// A destructible brick.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Brick {
    /// Its outline.
    pub shape: Shape,
    /// Hit points left (a brick on the board always has at least one).
    pub hp: u32,
}

/// What a cell holds.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Cell {
    /// Nothing.
    #[default]
    Empty,
    /// A brick.
    Brick(Brick),
    /// A round, indestructible obstacle centred in the cell.
    Obstacle,
    /// A pick-up (a sensor: balls pass through).
    Pickup(Pickup),
}

impl Cell {
    /// The brick here, if any.
    #[must_use]
    pub fn brick(&self) -> Option<&Brick> {
        match self {
            Cell::Brick(b) => Some(b),
            _ => None,
        }
    }
}

/// The outline of a brick of shape `shape` in the cell whose lower-left corner is `origin`,
/// counter-clockwise (so the interior is on the left of each edge).
#[must_use]
pub fn outline(shape: Shape, origin: DVec2) -> Vec<DVec2> {
    let [bl, br, tr, tl] = [
        origin,
        origin + DVec2::X,
        origin + DVec2::ONE,
        origin + DVec2::Y,
    ];
    match shape {
        Shape::Square => vec![bl, br, tr, tl],
        Shape::Triangle(Corner::TopRight) => vec![bl, br, tl],
        Shape::Triangle(Corner::TopLeft) => vec![bl, br, tr],
        Shape::Triangle(Corner::BottomRight) => vec![bl, tr, tl],
        Shape::Triangle(Corner::BottomLeft) => vec![br, tr, tl],
    }
}

/// The distance from `p` to the brick with this outline: 0 inside (or on the edge), else the
/// distance to the nearest edge.
#[must_use]
pub fn distance_to_outline(outline: &[DVec2], p: DVec2) -> f64 {
    let n = outline.len();
    let mut inside = true;
    let mut nearest = f64::INFINITY;
    for i in 0..n {
        let (a, b) = (outline[i], outline[(i + 1) % n]);
        let edge = b - a;
        // Counter-clockwise: the interior is where the cross product is positive.
        if edge.perp_dot(p - a) < 0.0 {
            inside = false;
        }
        let t = ((p - a).dot(edge) / edge.length_squared()).clamp(0.0, 1.0);
        nearest = nearest.min(p.distance(a + edge * t));
    }
    if inside { 0.0 } else { nearest }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn triangles_leave_their_open_corner_empty() {
        let o = DVec2::ZERO;
        let near = |c: DVec2| DVec2::new(0.5, 0.5) + (c - DVec2::new(0.5, 0.5)) * 0.9;
        let cases = [
            (Corner::TopLeft, DVec2::new(0.0, 1.0)),
            (Corner::TopRight, DVec2::new(1.0, 1.0)),
            (Corner::BottomLeft, DVec2::new(0.0, 0.0)),
            (Corner::BottomRight, DVec2::new(1.0, 0.0)),
        ];
        for (corner, open) in cases {
            let shape = outline(Shape::Triangle(corner), o);
            assert!(distance_to_outline(&shape, near(open)) > 0.0, "{corner:?}");
            // The opposite corner is inside.
            let opposite = DVec2::ONE - open;
            assert_eq!(
                distance_to_outline(&shape, near(opposite)),
                0.0,
                "{corner:?}"
            );
        }
    }
}
