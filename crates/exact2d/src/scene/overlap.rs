//! Overlaps at time 0: the first ball, in scene order, that overlaps a static shape or (with
//! `ball_ball`) an earlier ball.
//!
//! The answer is the error [`World::add_ball`](crate::World::add_ball) would give when the
//! scene is built in order (segments, circles, then balls): the ball with the smallest index
//! that overlaps anything it meets; against it, the first segment, else the first circle,
//! else the earliest ball. The overlap test itself is the engine's, operation for operation,
//! so a scene that validates always builds.
//!
//! Candidates come from a [`Grid`] (balls against statics, statics against balls, and balls
//! against balls if they collide), so a scene of 10^6 balls is checked in O(n log n).

use glam::DVec2;

use super::grid::{Bounds, Grid};
use super::{Scene, SceneItem};
use crate::{Circle, OVERLAP_TOLERANCE, Segment, Shape};

/// How much every box is widened, relative to the coordinates: the engine's distance to a
/// segment carries a rounding error of a few ulps of the coordinates, which for a small ball
/// near a long segment can exceed the overlap tolerance. Widening by `1e-9` of them keeps
/// every pair the engine could call overlapping among the candidates.
const BOX_MARGIN: f64 = 1e-9;

enum Body {
    Ball {
        index: usize,
        center: DVec2,
        radius: f64,
    },
    Static {
        item: SceneItem,
        shape: Shape,
    },
}

/// The first overlap, as (ball index, the item it overlaps); `None` if there is none.
///
/// # Panics
/// If a shape is invalid: call this only on a scene whose numbers passed validation.
pub(super) fn first_overlap(scene: &Scene) -> Option<(usize, SceneItem)> {
    let (bodies, bounds) = bodies(scene);
    let is_ball = |i: &usize| matches!(bodies[*i], Body::Ball { .. });
    let (balls, statics): (Vec<usize>, Vec<usize>) = (0..bodies.len()).partition(is_ball);
    let ball_grid = grid(&balls, &bounds);
    let static_grid = grid(&statics, &bounds);
    let mut first = None;
    // In a periodic box two balls also meet through the images of the box's eight
    // neighbours: the candidate `j` is then seen moved by the image's shift, as the engine
    // sees a ball in a cell across an edge. (Colliders keep clear of the edges.)
    let images: &[DVec2] = &match scene.periodic {
        None => vec![DVec2::ZERO],
        Some([lx, ly]) => (-1..=1)
            .flat_map(|ky| {
                (-1..=1).map(move |kx| DVec2::new(f64::from(kx) * lx, f64::from(ky) * ly))
            })
            .collect(),
    };
    let mut search = |queries: &[usize], grid: &Grid, images: &[DVec2]| {
        for &i in queries {
            for &shift in images {
                let query = if shift == DVec2::ZERO {
                    bounds[i]
                } else {
                    bounds[i].moved(-shift)
                };
                grid.query(&query, &mut |j| {
                    let j = j as usize;
                    // Through an image, the pair is checked as the engine adds the later
                    // ball: the earlier one moved, once.
                    if !query.meets(&bounds[j]) || (shift != DVec2::ZERO && j >= i) {
                        return;
                    }
                    let found = if shift == DVec2::ZERO {
                        conflict(&bodies[i], &bodies[j])
                    } else {
                        conflict(&bodies[i], &bodies[j].moved(shift))
                    };
                    if let Some(found) = found {
                        first =
                            Some(first.map_or(found, |best: (usize, SceneItem)| best.min(found)));
                    }
                });
            }
        }
    };
    search(&balls, &static_grid, &[DVec2::ZERO]);
    search(&statics, &ball_grid, &[DVec2::ZERO]);
    if scene.ball_ball {
        search(&balls, &ball_grid, images);
    }
    first
}

impl Body {
    /// A ball seen moved by `shift` (a periodic box's image); statics are never moved.
    fn moved(&self, shift: DVec2) -> Self {
        match *self {
            Body::Ball {
                index,
                center,
                radius,
            } => Body::Ball {
                index,
                center: center + shift,
                radius,
            },
            Body::Static { item, shape } => Body::Static { item, shape },
        }
    }
}

fn grid(ids: &[usize], bounds: &[Bounds]) -> Grid {
    Grid::new(ids.iter().map(|&i| (i as u32, bounds[i])))
}

/// Every segment, circle and ball with its widened bounding box, in scene order.
fn bodies(scene: &Scene) -> (Vec<Body>, Vec<Bounds>) {
    let mut bodies =
        Vec::with_capacity(scene.segments.len() + scene.circles.len() + scene.balls.len());
    let mut bounds = Vec::with_capacity(bodies.capacity());
    for (i, s) in scene.segments.iter().enumerate() {
        let (a, b) = (DVec2::from(s.a), DVec2::from(s.b));
        let segment = Segment::new(a, b).expect("validated segment");
        let margin = BOX_MARGIN * (a.abs().element_sum() + b.abs().element_sum());
        bounds.push(Bounds::new(a.min(b) - margin, a.max(b) + margin));
        bodies.push(Body::Static {
            item: SceneItem::Segment(i),
            shape: Shape::Segment(segment),
        });
    }
    for (i, c) in scene.circles.iter().enumerate() {
        let circle = Circle::new(DVec2::from(c.center), c.radius).expect("validated circle");
        bounds.push(disc_bounds(circle.center, circle.radius));
        bodies.push(Body::Static {
            item: SceneItem::Circle(i),
            shape: Shape::Circle(circle),
        });
    }
    for (index, ball) in scene.balls.iter().enumerate() {
        let center = DVec2::from(ball.pos);
        bounds.push(disc_bounds(center, ball.radius));
        bodies.push(Body::Ball {
            index,
            center,
            radius: ball.radius,
        });
    }
    (bodies, bounds)
}

fn disc_bounds(center: DVec2, radius: f64) -> Bounds {
    let reach = radius + BOX_MARGIN * (center.abs().element_sum() + radius);
    Bounds::new(center - reach, center + reach)
}

/// The overlap between two bodies, as (ball index, other item), with the later ball first
/// for two balls; `None` if they do not overlap or are both static.
fn conflict(a: &Body, b: &Body) -> Option<(usize, SceneItem)> {
    match (a, b) {
        (
            &Body::Ball {
                index: i,
                center: p,
                radius: r,
            },
            &Body::Ball {
                index: j,
                center: q,
                radius: s,
            },
        ) => {
            let (earlier, later) = if i < j {
                ((p, r), (q, s))
            } else {
                ((q, s), (p, r))
            };
            (i != j && balls_overlap(earlier, later))
                .then_some((i.max(j), SceneItem::Ball(i.min(j))))
        }
        (
            &Body::Ball {
                index,
                center,
                radius,
            },
            &Body::Static { item, shape },
        )
        | (
            &Body::Static { item, shape },
            &Body::Ball {
                index,
                center,
                radius,
            },
        ) => ball_overlaps_shape(center, radius, &shape).then_some((index, item)),
        (Body::Static { .. }, Body::Static { .. }) => None,
    }
}

/// `World::add_ball`'s test of a new ball against a solid collider, operation for operation:
/// the gap is compared with the tolerance times the contact distance.
fn ball_overlaps_shape(center: DVec2, radius: f64, shape: &Shape) -> bool {
    let (gap, reach) = match shape {
        Shape::Segment(s) => (s.distance(center) - radius, radius),
        Shape::Circle(c) => (
            center.distance(c.center) - c.radius - radius,
            c.radius + radius,
        ),
    };
    gap < -OVERLAP_TOLERANCE * reach
}

/// `World::add_ball`'s test of a new ball (`later`) against one already added (`earlier`),
/// each as (centre, radius), operation for operation.
fn balls_overlap(earlier: (DVec2, f64), later: (DVec2, f64)) -> bool {
    let reach = earlier.1 + later.1;
    earlier.0.distance(later.0) - reach < -OVERLAP_TOLERANCE * reach
}

#[cfg(test)]
mod tests {
    //! The engine is the reference: adding the scene's bodies to a `World` in order, the first
    //! refused ball and the body it overlaps must be what `first_overlap` reports.

    use super::*;
    use crate::scene::{SceneBall, SceneCircle, SceneSegment};
    use crate::{BallDesc, ColliderDesc, CollisionGroups, World, WorldError};

    struct SplitMix(u64);

    impl SplitMix {
        fn next(&mut self) -> f64 {
            self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = self.0;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
        }

        fn range(&mut self, lo: f64, hi: f64) -> f64 {
            lo + (hi - lo) * self.next()
        }

        /// Log-uniform in `[lo, hi]`: sizes over several orders of magnitude.
        fn size(&mut self, lo: f64, hi: f64) -> f64 {
            (lo.ln() + (hi.ln() - lo.ln()) * self.next()).exp()
        }

        fn point(&mut self) -> [f64; 2] {
            [self.range(0.0, 10.0), self.range(0.0, 10.0)]
        }
    }

    fn random_scene(rng: &mut SplitMix) -> Scene {
        let mut scene = Scene {
            ball_ball: rng.next() < 0.5,
            ..Scene::default()
        };
        for _ in 0..6 {
            let (a, length, angle) = (rng.point(), rng.size(0.01, 20.0), rng.range(0.0, 6.3));
            let b = [a[0] + length * angle.cos(), a[1] + length * angle.sin()];
            scene.segments.push(SceneSegment {
                a,
                b,
                restitution: 1.0,
                friction: 0.0,
                tangential_restitution: 0.0,
                rolling_resistance: 0.0,
            });
        }
        for _ in 0..4 {
            let (center, radius) = (rng.point(), rng.size(0.01, 2.0));
            scene.circles.push(SceneCircle {
                center,
                radius,
                restitution: 1.0,
                friction: 0.0,
                tangential_restitution: 0.0,
                rolling_resistance: 0.0,
            });
        }
        for id in 0..60 {
            let radius = rng.size(0.001, 1.0);
            let pos = if rng.next() < 0.3 {
                near_a_segment(rng, &scene, radius)
            } else {
                rng.point()
            };
            let ball = SceneBall {
                id,
                pos,
                vel: [0.0; 2],
                radius,
                mass: 1.0,
                restitution: 1.0,
                spin: 0.0,
                inertia: 0.5,
                friction: 0.0,
                tangential_restitution: 0.0,
                rolling_resistance: 0.0,
                roll: [0.0, 0.0],
            };
            scene.balls.push(ball);
        }
        scene
    }

    /// A centre at distance `radius * (1 + d)` from a segment's interior, with `d` around the
    /// overlap tolerance, to exercise the borderline.
    fn near_a_segment(rng: &mut SplitMix, scene: &Scene, radius: f64) -> [f64; 2] {
        let s = &scene.segments[(rng.next() * scene.segments.len() as f64) as usize];
        let segment = Segment::new(DVec2::from(s.a), DVec2::from(s.b)).unwrap();
        let deltas = [-2e-9, -1e-9, -0.5e-9, 0.0, 0.5e-9, 1e-6];
        let d = deltas[(rng.next() * deltas.len() as f64) as usize];
        let on = segment.a() + segment.direction() * rng.range(0.1, 0.9);
        (on + segment.normal() * (radius * (1.0 + d))).to_array()
    }

    /// The engine's answer: the first ball `add_ball` refuses, and the body it names.
    fn engine_first_overlap(scene: &Scene) -> Option<(usize, SceneItem)> {
        let mut world = World::new();
        let mut colliders = Vec::new();
        for s in &scene.segments {
            let desc = ColliderDesc::segment(DVec2::from(s.a), DVec2::from(s.b));
            colliders.push(world.add_collider(desc).unwrap());
        }
        for c in &scene.circles {
            colliders.push(
                world
                    .add_collider(ColliderDesc::circle(DVec2::from(c.center), c.radius))
                    .unwrap(),
            );
        }
        let groups = if scene.ball_ball {
            CollisionGroups::ALL
        } else {
            CollisionGroups::new(1, !1)
        };
        let mut balls = Vec::new();
        for (i, b) in scene.balls.iter().enumerate() {
            let desc = BallDesc::new(DVec2::from(b.pos), b.radius).groups(groups);
            match world.add_ball(desc) {
                Ok(handle) => balls.push(handle),
                Err(WorldError::OverlapsCollider(h)) => {
                    let k = colliders.iter().position(|&c| c == h).unwrap();
                    let n = scene.segments.len();
                    let item = if k < n {
                        SceneItem::Segment(k)
                    } else {
                        SceneItem::Circle(k - n)
                    };
                    return Some((i, item));
                }
                Err(WorldError::OverlapsBall(h)) => {
                    return Some((
                        i,
                        SceneItem::Ball(balls.iter().position(|&b| b == h).unwrap()),
                    ));
                }
                Err(e) => panic!("unexpected {e}"),
            }
        }
        None
    }

    #[test]
    fn first_overlap_matches_the_engine_on_random_scenes() {
        let mut rng = SplitMix(2024);
        let mut checked = 0;
        for _ in 0..200 {
            let mut scene = random_scene(&mut rng);
            // Remove each refused ball in turn, so later and later overlaps are compared,
            // down to a scene without any.
            loop {
                let expected = engine_first_overlap(&scene);
                assert_eq!(first_overlap(&scene), expected);
                checked += 1;
                let Some((ball, _)) = expected else { break };
                scene.balls.remove(ball);
            }
        }
        assert!(checked > 2000, "only {checked} comparisons");
    }

    #[test]
    fn a_large_touching_lattice_is_valid_and_one_overlap_in_it_is_found() {
        let (n, radius) = (300, 0.5);
        let mut scene = Scene {
            ball_ball: true,
            ..Scene::default()
        };
        for k in 0..n * n {
            let pos = [(k % n) as f64, (k / n) as f64];
            scene.balls.push(SceneBall {
                id: k as u64,
                pos,
                vel: [0.0; 2],
                radius,
                mass: 1.0,
                restitution: 1.0,
                spin: 0.0,
                inertia: 0.5,
                friction: 0.0,
                tangential_restitution: 0.0,
                rolling_resistance: 0.0,
                roll: [0.0, 0.0],
            });
        }
        assert_eq!(first_overlap(&scene), None);
        scene.balls[n * n - 1].pos[0] -= 0.01;
        assert_eq!(
            first_overlap(&scene),
            Some((n * n - 1, SceneItem::Ball(n * n - 2)))
        );
    }
}
