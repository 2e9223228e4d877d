//! What the world fuzz targets share: coordinates on a dyadic grid, the two collision groups,
//! and the deepest overlap of a world.

use exact2d::{CollisionGroups, DVec2, Shape, World};

/// Coordinates on a 1/64 grid in [-8, 8): exact doubles, so touching placements, shared end
/// points, collinear and crossing segments come up often.
pub fn coord(c: i16) -> f64 {
    f64::from(c % 512) / 64.0
}

/// Everything interacts but balls of the second group pass through each other.
pub fn groups(second: bool) -> CollisionGroups {
    if second {
        CollisionGroups::new(2, !2)
    } else {
        CollisionGroups::ALL
    }
}

/// The gap between a ball (centre `p`, radius `r`) and a shape, and the contact distance.
pub fn gap(shape: &Shape, p: DVec2, r: f64) -> (f64, f64) {
    match shape {
        Shape::Segment(s) => (s.distance(p) - r, r),
        Shape::Circle(k) => (p.distance(k.center) - k.radius - r, k.radius + r),
    }
}

/// The most negative gap between interacting bodies, relative to their contact distance.
pub fn deepest_overlap(world: &World) -> f64 {
    let balls: Vec<_> = world.balls().map(|(_, b)| b).collect();
    let mut worst: f64 = 0.0;
    for (i, a) in balls.iter().enumerate() {
        for b in &balls[..i] {
            if a.groups.interact(b.groups) {
                let reach = a.radius + b.radius;
                worst = worst.min((a.position.distance(b.position) - reach) / reach);
            }
        }
        for (_, c) in world.colliders() {
            if c.sensor || !c.groups.interact(a.groups) {
                continue;
            }
            let (g, reach) = gap(&c.shape, a.position, a.radius);
            worst = worst.min(g / reach);
        }
    }
    worst
}
