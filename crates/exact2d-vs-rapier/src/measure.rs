//! What is measured on every frame, independently of either engine: energy, penetration,
//! escapes, and the analytic mirror-folded path of a free ball in an axis-aligned box.

use exact2d::DVec2;
use exact2d::scene::Scene;

/// A ball's state at one frame, in scene order.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BallState {
    /// Centre.
    pub position: DVec2,
    /// Velocity.
    pub velocity: DVec2,
}

/// The static geometry and the balls' constant properties, read once from the scene.
#[derive(Clone, Debug)]
pub struct SceneGeometry {
    segments: Vec<(DVec2, DVec2)>,
    circles: Vec<(DVec2, f64)>,
    radii: Vec<f64>,
    masses: Vec<f64>,
    gravity: DVec2,
    ball_ball: bool,
    /// Bounding box of the statics (min, max); `None` without statics.
    container: Option<(DVec2, DVec2)>,
    /// The box a free ball folds into, if the scene is analytic.
    analytic: Option<AnalyticBox>,
    /// The balls at time 0, for the analytic path.
    initial: Vec<BallState>,
}

/// An axis-aligned box made of exactly four elastic segments, holding balls that fly freely.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AnalyticBox {
    /// Lower-left corner.
    pub min: DVec2,
    /// Upper-right corner.
    pub max: DVec2,
}

impl SceneGeometry {
    /// Reads what the measures need from a scene.
    #[must_use]
    pub fn new(scene: &Scene) -> Self {
        let segments: Vec<_> = scene
            .segments
            .iter()
            .map(|s| (DVec2::from(s.a), DVec2::from(s.b)))
            .collect();
        let circles: Vec<_> = scene
            .circles
            .iter()
            .map(|c| (DVec2::from(c.center), c.radius))
            .collect();
        let corners = segments.iter().flat_map(|&(a, b)| [(a, 0.0), (b, 0.0)]);
        let container = corners
            .chain(circles.iter().copied())
            .map(|(c, r)| (c - DVec2::splat(r), c + DVec2::splat(r)))
            .reduce(|(lo, hi), (l, h)| (lo.min(l), hi.max(h)));
        Self {
            analytic: AnalyticBox::of(scene),
            segments,
            circles,
            radii: scene.balls.iter().map(|b| b.radius).collect(),
            masses: scene.balls.iter().map(|b| b.mass).collect(),
            gravity: DVec2::from(scene.gravity),
            ball_ball: scene.ball_ball,
            container,
            initial: scene
                .balls
                .iter()
                .map(|b| BallState {
                    position: DVec2::from(b.pos),
                    velocity: DVec2::from(b.vel),
                })
                .collect(),
        }
    }

    /// Whether the scene has an analytic solution (see [`AnalyticBox::of`]).
    #[must_use]
    pub fn is_analytic(&self) -> bool {
        self.analytic.is_some()
    }

    /// Kinetic plus potential energy (the potential is zero at the origin).
    #[must_use]
    pub fn energy(&self, balls: &[BallState]) -> f64 {
        balls
            .iter()
            .zip(&self.masses)
            .map(|(b, &m)| 0.5 * m * b.velocity.length_squared() - m * self.gravity.dot(b.position))
            .sum()
    }

    /// The deepest overlap of any ball with any segment or circle (and with another ball if
    /// balls collide in this scene), and that depth divided by the ball's radius (the smaller
    /// radius for two balls). Zero when nothing overlaps.
    #[must_use]
    pub fn max_penetration(&self, balls: &[BallState]) -> (f64, f64) {
        let mut worst = (0.0, 0.0);
        let mut note = |depth: f64, radius: f64| {
            if depth > worst.0 {
                worst = (depth, depth / radius);
            }
        };
        for (ball, &r) in balls.iter().zip(&self.radii) {
            let p = ball.position;
            for &(a, b) in &self.segments {
                note(r - segment_distance(p, a, b), r);
            }
            for &(c, radius) in &self.circles {
                note(r + radius - p.distance(c), r);
            }
        }
        if self.ball_ball {
            ball_overlaps(balls, &self.radii, &mut note);
        }
        worst
    }

    /// The number of balls whose centre is outside the bounding box of the statics.
    #[must_use]
    pub fn escaped(&self, balls: &[BallState]) -> usize {
        let Some((min, max)) = self.container else {
            return 0;
        };
        let inside = |p: DVec2| p.cmpge(min).all() && p.cmple(max).all();
        balls.iter().filter(|b| !inside(b.position)).count()
    }

    /// The largest distance of any ball from its mirror-folded analytic position at time `t`;
    /// `None` if the scene is not analytic.
    #[must_use]
    pub fn position_error(&self, t: f64, balls: &[BallState]) -> Option<f64> {
        let bounds = self.analytic?;
        let errors = balls.iter().zip(&self.initial).zip(&self.radii);
        let max = errors
            .map(|((now, start), &r)| {
                let exact = bounds.fold(start.position, start.velocity, t, r);
                now.position.distance(exact)
            })
            .fold(0.0, f64::max);
        Some(max)
    }
}

impl AnalyticBox {
    /// The box of a scene whose balls fly freely between elastic reflections off four walls:
    /// no gravity, no ball-ball contacts, no circles, exactly four segments that are the four
    /// sides of an axis-aligned rectangle, every restitution 1 and every ball inside the box.
    #[must_use]
    pub fn of(scene: &Scene) -> Option<Self> {
        let elastic = scene.segments.iter().all(|s| s.restitution == 1.0)
            && scene.balls.iter().all(|b| b.restitution == 1.0);
        if scene.gravity != [0.0, 0.0] || scene.ball_ball || !scene.circles.is_empty() || !elastic {
            return None;
        }
        let [s0, s1, s2, s3] = scene.segments.as_slice() else {
            return None;
        };
        let ends = [s0, s1, s2, s3].map(|s| (DVec2::from(s.a), DVec2::from(s.b)));
        let min = ends.iter().map(|&(a, b)| a.min(b)).reduce(DVec2::min)?;
        let max = ends.iter().map(|&(a, b)| a.max(b)).reduce(DVec2::max)?;
        let side = |a: DVec2, b: DVec2| {
            let (lo, hi) = (a.min(b), a.max(b));
            let horizontal = a.y == b.y && lo.x == min.x && hi.x == max.x;
            let vertical = a.x == b.x && lo.y == min.y && hi.y == max.y;
            (horizontal && a.y == min.y) as u8
                | ((horizontal && a.y == max.y) as u8) << 1
                | ((vertical && a.x == min.x) as u8) << 2
                | ((vertical && a.x == max.x) as u8) << 3
        };
        let sides = ends.iter().fold(0, |seen, &(a, b)| seen | side(a, b));
        let inside = scene.balls.iter().all(|b| {
            let p = DVec2::from(b.pos);
            let r = DVec2::splat(b.radius);
            p.cmpge(min + r).all() && p.cmple(max - r).all()
        });
        (sides == 0b1111 && min.cmplt(max).all() && inside).then_some(Self { min, max })
    }

    /// Where a ball of radius `r` that starts at `p0` with velocity `v` is at time `t`.
    #[must_use]
    pub fn fold(&self, p0: DVec2, v: DVec2, t: f64, r: f64) -> DVec2 {
        DVec2::new(
            mirror_fold(p0.x, v.x, t, self.min.x + r, self.max.x - r),
            mirror_fold(p0.y, v.y, t, self.min.y + r, self.max.y - r),
        )
    }
}

/// The position at time `t` of a point that starts at `x0` with velocity `v` and reflects
/// elastically between `lo` and `hi`: its free-flight position folded into `[lo, hi]`.
#[must_use]
pub fn mirror_fold(x0: f64, v: f64, t: f64, lo: f64, hi: f64) -> f64 {
    let len = hi - lo;
    if len <= 0.0 {
        return lo;
    }
    let u = (x0 - lo + v * t).rem_euclid(2.0 * len);
    if u <= len { lo + u } else { hi - (u - len) }
}

/// The distance from `p` to the segment `a`-`b`.
#[must_use]
pub fn segment_distance(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    let ab = b - a;
    let s = ((p - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0);
    p.distance(a + s * ab)
}

/// Calls `note(depth, smaller radius)` for every overlapping pair of balls (sweep and prune
/// along x).
fn ball_overlaps(balls: &[BallState], radii: &[f64], note: &mut impl FnMut(f64, f64)) {
    let mut order: Vec<usize> = (0..balls.len()).collect();
    order.sort_by(|&i, &j| balls[i].position.x.total_cmp(&balls[j].position.x));
    let widest = radii.iter().copied().fold(0.0, f64::max);
    for (k, &i) in order.iter().enumerate() {
        let pi = balls[i].position;
        for &j in &order[k + 1..] {
            let pj = balls[j].position;
            if pj.x - pi.x > radii[i] + widest {
                break;
            }
            note(
                radii[i] + radii[j] - pi.distance(pj),
                radii[i].min(radii[j]),
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ball(x: f64, y: f64) -> BallState {
        BallState {
            position: DVec2::new(x, y),
            velocity: DVec2::ZERO,
        }
    }

    #[test]
    fn mirror_fold_matches_hand_computed_bounces() {
        // Between 1 and 3 (length 2, period 4), from 2 at speed 1.
        assert_eq!(mirror_fold(2.0, 1.0, 0.5, 1.0, 3.0), 2.5);
        assert_eq!(mirror_fold(2.0, 1.0, 1.0, 1.0, 3.0), 3.0); // at the wall
        assert_eq!(mirror_fold(2.0, 1.0, 1.5, 1.0, 3.0), 2.5); // back from 3
        assert_eq!(mirror_fold(2.0, 1.0, 3.5, 1.0, 3.0), 1.5); // back from 1
        assert_eq!(mirror_fold(2.0, 1.0, 4.0, 1.0, 3.0), 2.0); // one period
        assert_eq!(mirror_fold(2.0, -1.0, 1.5, 1.0, 3.0), 1.5); // leftwards first
        // 1 + 82 units = 20 periods + 3: on the way back from 3, at 2.
        assert_eq!(mirror_fold(2.0, 8.0, 10.25, 1.0, 3.0), 2.0);
        assert_eq!(mirror_fold(2.0, 8.0, 10.375, 1.0, 3.0), 1.0);
        assert_eq!(mirror_fold(2.0, 0.0, 7.0, 1.0, 3.0), 2.0);
    }

    #[test]
    fn box_fold_reduces_the_box_by_the_radius() {
        let bounds = AnalyticBox {
            min: DVec2::ZERO,
            max: DVec2::new(10.0, 4.0),
        };
        // x in [1, 9], y in [1, 3]: after 3 s at (4, 1), x = 2 + 12 -> 14 -> 4 (from 9),
        // y = 2 + 3 -> 5 -> 1 (from 3).
        let p = bounds.fold(DVec2::new(2.0, 2.0), DVec2::new(4.0, 1.0), 3.0, 1.0);
        assert_eq!(p, DVec2::new(4.0, 1.0));
    }

    fn box_scene(extra: &str) -> Scene {
        Scene::from_json_str(&format!(
            r#"{{ "segments": [
                {{ "a": [0, 0], "b": [10, 0] }}, {{ "a": [10, 0], "b": [10, 4] }},
                {{ "a": [10, 4], "b": [0, 4] }}, {{ "a": [0, 4], "b": [0, 0] }} ],
              "balls": [ {{ "id": 0, "pos": [2, 2], "vel": [4, 1], "radius": 1 }},
                         {{ "id": 1, "pos": [8, 2], "vel": [0, 0], "radius": 1 }} ] {extra} }}"#
        ))
        .unwrap()
    }

    #[test]
    fn only_free_balls_in_an_axis_aligned_box_are_analytic() {
        let bounds = AnalyticBox::of(&box_scene("")).unwrap();
        assert_eq!(
            (bounds.min, bounds.max),
            (DVec2::ZERO, DVec2::new(10.0, 4.0))
        );
        assert!(AnalyticBox::of(&box_scene(r#", "ball_ball": true"#)).is_none());
        assert!(AnalyticBox::of(&box_scene(r#", "gravity": [0, -1]"#)).is_none());
        let mut tilted = box_scene("");
        tilted.segments[0].b = [10.0, 0.5];
        assert!(AnalyticBox::of(&tilted).is_none());
    }

    #[test]
    fn penetration_is_the_deepest_overlap_relative_to_the_radius() {
        let geometry = SceneGeometry::new(&box_scene(r#", "ball_ball": true"#));
        // Touching the floor and the other ball: no penetration.
        assert_eq!(
            geometry.max_penetration(&[ball(2.0, 1.0), ball(4.0, 1.0)]),
            (0.0, 0.0)
        );
        // Both 0.25 into the floor; the balls overlap by 0.5.
        let (depth, relative) = geometry.max_penetration(&[ball(2.0, 0.75), ball(3.5, 0.75)]);
        assert!((depth - 0.5).abs() < 1e-15 && (relative - 0.5).abs() < 1e-15);
        // Past the end of the floor the distance is to its end point (0, 0): 1 - sqrt(0.5).
        let (depth, _) = geometry.max_penetration(&[ball(-0.5, -0.5), ball(5.0, 2.0)]);
        assert!((depth - (1.0 - 0.5f64.sqrt())).abs() < 1e-15);
        assert_eq!(geometry.escaped(&[ball(-0.5, -0.5), ball(5.0, 2.0)]), 1);
    }

    #[test]
    fn energy_counts_potential_energy_under_gravity() {
        let geometry = SceneGeometry::new(&box_scene(r#", "gravity": [0, -2]"#));
        let mut balls = [ball(2.0, 3.0), ball(8.0, 1.0)];
        balls[0].velocity = DVec2::new(3.0, 4.0);
        assert_eq!(geometry.energy(&balls), 12.5 + 6.0 + 2.0);
    }
}
