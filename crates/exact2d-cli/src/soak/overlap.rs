//! Overlap: how deep balls sink into each other and into solid colliders.
//!
//! The depth of a pair is measured relative to its contact distance `reach` (the sum of the
//! radii for two balls or a ball and a static circle, the ball's radius against a segment):
//! `depth = (reach - distance) / reach`, positive when they overlap, 0 when they touch. This
//! is the measure of the engine's placement tolerance [`exact2d::OVERLAP_TOLERANCE`]. What
//! the engine allows a pair is [`exact2d::overlap_bound`], which depends on the pair's
//! coordinates too (the contact's coordinate scale, where rounding is coarser far from the
//! origin): each pair carries it, as `allowed`, in the same relative measure.
//!
//! Ball against ball uses a uniform grid kept as a sorted list of cell keys (no hash map, so
//! the order of the pairs visited, and hence every result, is deterministic): O(n log n) for
//! the sort plus the pairs of neighbouring cells. Ball against collider sorts the balls by x
//! once and visits, for each solid collider, only the balls whose x lies within its bounding
//! box widened by the largest radius.

use exact2d::{Ball, Collider, DVec2, Shape, overlap_bound};

/// Widens the grid's cells past twice the largest radius, so that rounding in the cell
/// coordinates `floor(p / cell)` can never put two overlapping balls two cells apart (a
/// relative error of 1e-6 in a quotient would need coordinates of 1e10 cells).
const CELL_PADDING: f64 = 1.0 + 1e-6;

/// Two balls (indices in the snapshot, `a < b`) closer than their contact distance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BallPair {
    /// The first ball's index in the snapshot.
    pub a: usize,
    /// The second ball's index in the snapshot.
    pub b: usize,
    /// How deep they overlap, relative to the sum of their radii (0: touching).
    pub depth: f64,
    /// How deep the engine lets them overlap ([`exact2d::overlap_bound`]), relative to the
    /// sum of their radii.
    pub allowed: f64,
}

/// A ball (index in the snapshot) closer to a solid collider (index in the collider list)
/// than its contact distance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ColliderContact {
    /// The ball's index in the snapshot.
    pub ball: usize,
    /// The collider's index in the collider list.
    pub collider: usize,
    /// How deep the ball overlaps the collider, relative to the contact distance (0: touching).
    pub depth: f64,
    /// How deep the engine lets it overlap ([`exact2d::overlap_bound`]), relative to the
    /// contact distance.
    pub allowed: f64,
}

/// What a scan of the pairs found.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Overlaps<T> {
    /// The deepest pair (touching counts, at depth 0); `None` if nothing touches.
    pub deepest: Option<T>,
    /// The pair deepest beyond what the engine allows it (the greatest `depth / allowed`),
    /// `None` if every pair is within its bound.
    pub beyond: Option<T>,
}

impl<T> Default for Overlaps<T> {
    fn default() -> Self {
        Self {
            deepest: None,
            beyond: None,
        }
    }
}

/// How far a pair is past its bound: `depth / allowed` (above 1: beyond it).
fn excess(depth: f64, allowed: f64) -> f64 {
    depth / allowed
}

/// The largest magnitude of a coordinate of `p`.
fn magnitude(p: DVec2) -> f64 {
    p.abs().max_element()
}

/// The relative depth [`exact2d::overlap_bound`] allows a contact of contact distance `reach`
/// at coordinates of magnitude `coordinates`.
#[must_use]
pub fn allowed_depth(coordinates: f64, reach: f64) -> f64 {
    overlap_bound(coordinates, reach) / reach
}

/// The depth of a pair at centre `distance` with contact distance `reach`.
#[must_use]
fn depth(distance: f64, reach: f64) -> f64 {
    (reach - distance) / reach
}

/// Calls `visit` once for every pair of interacting balls whose centres are closer than or
/// exactly at the sum of their radii (touching included), with `a < b`. Positions must be
/// finite.
pub fn for_each_close_ball_pair(balls: &[Ball], mut visit: impl FnMut(BallPair)) {
    if !any_balls_interact(balls) {
        return;
    }
    let max_radius = balls.iter().map(|b| b.radius).fold(0.0, f64::max);
    let cell = 2.0 * max_radius * CELL_PADDING;
    let origin = balls
        .iter()
        .map(|b| b.position)
        .fold(DVec2::INFINITY, DVec2::min);
    let keys = sorted_cell_keys(balls, origin, cell);
    let mut start = 0;
    while start < keys.len() {
        let (cx, cy, _) = keys[start];
        let end = start + keys[start..].partition_point(|k| (k.0, k.1) == (cx, cy));
        let here = &keys[start..end];
        for (i, key) in here.iter().enumerate() {
            visit_run(balls, key.2, &here[i + 1..], &mut visit);
        }
        // Half of the neighbourhood, so each pair of cells is visited once.
        for (dx, dy) in [(1, -1), (1, 0), (1, 1), (0, 1)] {
            let there = cell_run(&keys, cx.saturating_add(dx), cy.saturating_add(dy));
            for key in here {
                visit_run(balls, key.2, there, &mut visit);
            }
        }
        start = end;
    }
}

/// Whether any two balls (or one ball with itself, standing for two balls of the same
/// groups) could interact: otherwise the ball-ball check has nothing to do, however close the
/// balls (balls that pass through each other may all sit in one cell).
fn any_balls_interact(balls: &[Ball]) -> bool {
    let mut groups: Vec<_> = balls
        .iter()
        .map(|b| (b.groups.memberships, b.groups.filter))
        .collect();
    groups.sort_unstable();
    groups.dedup();
    let groups: Vec<_> = groups
        .into_iter()
        .map(|(m, f)| exact2d::CollisionGroups::new(m, f))
        .collect();
    groups
        .iter()
        .enumerate()
        .any(|(i, g)| groups[i..].iter().any(|h| g.interact(*h)))
}

/// Every ball's cell `(cx, cy, index)`, sorted.
fn sorted_cell_keys(balls: &[Ball], origin: DVec2, cell: f64) -> Vec<(i64, i64, usize)> {
    // `as` saturates: a ball absurdly far away shares a cell key with others, which costs
    // time, never a missed pair (distances are computed exactly).
    let mut keys: Vec<_> = balls
        .iter()
        .enumerate()
        .map(|(i, b)| {
            let q = (b.position - origin) / cell;
            (q.x.floor() as i64, q.y.floor() as i64, i)
        })
        .collect();
    keys.sort_unstable();
    keys
}

/// The keys of cell `(cx, cy)`: a binary search in the sorted keys.
fn cell_run(keys: &[(i64, i64, usize)], cx: i64, cy: i64) -> &[(i64, i64, usize)] {
    let start = keys.partition_point(|k| (k.0, k.1) < (cx, cy));
    let len = keys[start..].partition_point(|k| (k.0, k.1) == (cx, cy));
    &keys[start..start + len]
}

/// Visits the close, interacting pairs of ball `i` with the balls of `run`.
fn visit_run(
    balls: &[Ball],
    i: usize,
    run: &[(i64, i64, usize)],
    visit: &mut impl FnMut(BallPair),
) {
    let ball = &balls[i];
    for &(_, _, j) in run {
        let other = &balls[j];
        let reach = ball.radius + other.radius;
        let distance = ball.position.distance(other.position);
        if distance <= reach && ball.groups.interact(other.groups) {
            let (a, b) = (i.min(j), i.max(j));
            let depth = depth(distance, reach);
            let coordinates = magnitude(ball.position).max(magnitude(other.position));
            let allowed = allowed_depth(coordinates, reach);
            visit(BallPair {
                a,
                b,
                depth,
                allowed,
            });
        }
    }
}

/// The deepest pair of interacting balls (touching counts, at depth 0), and the pair deepest
/// beyond its bound; ties go to the pair visited first. Positions must be finite.
#[must_use]
pub fn ball_overlaps(balls: &[Ball]) -> Overlaps<BallPair> {
    let mut found = Overlaps::default();
    for_each_close_ball_pair(balls, |pair| {
        if found.deepest.is_none_or(|d: BallPair| pair.depth > d.depth) {
            found.deepest = Some(pair);
        }
        let over = excess(pair.depth, pair.allowed);
        if over > 1.0
            && found
                .beyond
                .is_none_or(|b: BallPair| over > excess(b.depth, b.allowed))
        {
            found.beyond = Some(pair);
        }
    });
    found
}

/// [`ball_overlaps`] in a periodic box of sides `size`: each ball also seen through the images
/// of the box's eight neighbours that come within reach of the box, so that pairs across an
/// edge are measured at their nearest images. Indices are the snapshot's.
#[must_use]
pub fn ball_overlaps_periodic(balls: &[Ball], size: DVec2) -> Overlaps<BallPair> {
    let reach = 2.0 * balls.iter().map(|b| b.radius).fold(0.0, f64::max) * CELL_PADDING;
    let mut seen: Vec<Ball> = balls.to_vec();
    let mut owner: Vec<usize> = (0..balls.len()).collect();
    for (i, ball) in balls.iter().enumerate() {
        for ky in -1..=1 {
            for kx in -1..=1 {
                let shift = DVec2::new(f64::from(kx) * size.x, f64::from(ky) * size.y);
                let p = ball.position + shift;
                let near = p.cmpge(DVec2::splat(-reach)).all() && p.cmple(size + reach).all();
                if (kx, ky) != (0, 0) && near {
                    seen.push(Ball {
                        position: p,
                        ..*ball
                    });
                    owner.push(i);
                }
            }
        }
    }
    let back = |pair: BallPair| {
        let (a, b) = (owner[pair.a], owner[pair.b]);
        BallPair {
            a: a.min(b),
            b: a.max(b),
            ..pair
        }
    };
    let found = ball_overlaps(&seen);
    Overlaps {
        deepest: found.deepest.map(back),
        beyond: found.beyond.map(back),
    }
}

/// The deepest contact of a ball with a solid collider it interacts with, and the contact
/// deepest beyond its bound; ties go to the lowest collider, then the lowest ball. A contact's
/// coordinates are the ball's (and a circle's centre's); sensors are skipped. Positions must
/// be finite.
#[must_use]
pub fn collider_overlaps(balls: &[Ball], colliders: &[Collider]) -> Overlaps<ColliderContact> {
    let max_radius = balls.iter().map(|b| b.radius).fold(0.0, f64::max);
    let mut by_x: Vec<(f64, usize)> = balls
        .iter()
        .enumerate()
        .map(|(i, b)| (b.position.x, i))
        .collect();
    by_x.sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
    let mut found: Overlaps<ColliderContact> = Overlaps::default();
    for (c, collider) in colliders.iter().enumerate().filter(|(_, c)| !c.sensor) {
        let (min, max) = collider.shape.aabb();
        let (low, high) = (min - max_radius, max + max_radius);
        let start = by_x.partition_point(|&(x, _)| x < low.x);
        for &(_, i) in by_x[start..].iter().take_while(|&&(x, _)| x <= high.x) {
            let ball = &balls[i];
            let y = ball.position.y;
            if y < low.y || y > high.y || !ball.groups.interact(collider.groups) {
                continue;
            }
            let Some(depth) = collider_depth(ball, &collider.shape) else {
                continue;
            };
            let (coordinates, reach) = match collider.shape {
                Shape::Segment(_) => (magnitude(ball.position), ball.radius),
                Shape::Circle(k) => (
                    magnitude(ball.position).max(magnitude(k.center)),
                    ball.radius + k.radius,
                ),
            };
            let contact = ColliderContact {
                ball: i,
                collider: c,
                depth,
                allowed: allowed_depth(coordinates, reach),
            };
            if found
                .deepest
                .is_none_or(|d| better(contact.depth, contact, d.depth, d))
            {
                found.deepest = Some(contact);
            }
            let over = excess(contact.depth, contact.allowed);
            let beyond = |b: ColliderContact| better(over, contact, excess(b.depth, b.allowed), b);
            if over > 1.0 && found.beyond.is_none_or(beyond) {
                found.beyond = Some(contact);
            }
        }
    }
    found
}

/// Whether `new` (measured `new_value`) beats `old` (measured `old_value`): more, or as much
/// and earlier (lower collider, then ball).
fn better(new_value: f64, new: ColliderContact, old_value: f64, old: ColliderContact) -> bool {
    new_value > old_value
        || (new_value == old_value && (new.collider, new.ball) < (old.collider, old.ball))
}

/// The depth of a ball in a shape if it touches or overlaps it; `None` if it is clear.
#[must_use]
pub fn collider_depth(ball: &Ball, shape: &Shape) -> Option<f64> {
    let (distance, reach) = match shape {
        Shape::Segment(s) => (s.distance(ball.position), ball.radius),
        Shape::Circle(c) => (ball.position.distance(c.center), c.radius + ball.radius),
    };
    (distance <= reach).then(|| depth(distance, reach))
}

#[cfg(test)]
mod tests {
    use super::*;
    use exact2d::{CollisionGroups, Segment};

    fn ball(x: f64, y: f64, radius: f64) -> Ball {
        Ball {
            position: DVec2::new(x, y),
            velocity: DVec2::ZERO,
            radius,
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

    fn solid(shape: Shape) -> Collider {
        Collider {
            shape,
            sensor: false,
            restitution: 1.0,
            groups: CollisionGroups::ALL,
            user_data: 0,
            friction: 0.0,
            tangential_restitution: 0.0,
            rolling_resistance: 0.0,
        }
    }

    fn wall() -> Shape {
        Shape::Segment(Segment::new(DVec2::new(-5.0, 0.0), DVec2::new(5.0, 0.0)).unwrap())
    }

    /// SplitMix64, for reproducible random inputs.
    struct Rng(u64);

    impl Rng {
        fn next(&mut self) -> f64 {
            self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = self.0;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
        }
    }

    fn all_pairs(balls: &[Ball]) -> Vec<(usize, usize, f64)> {
        let mut pairs = Vec::new();
        for a in 0..balls.len() {
            for b in a + 1..balls.len() {
                let (p, q) = (&balls[a], &balls[b]);
                let (distance, reach) = (p.position.distance(q.position), p.radius + q.radius);
                if distance <= reach && p.groups.interact(q.groups) {
                    pairs.push((a, b, (reach - distance) / reach));
                }
            }
        }
        pairs
    }

    #[test]
    fn a_periodic_box_sees_pairs_through_its_edges() {
        let size = DVec2::new(10.0, 8.0);
        // 0.9 apart through the left and right edges, 0.95 through the top and bottom:
        // both overlap (contact distance 1), the first deeper.
        let balls = [
            ball(0.2, 4.0, 0.5),
            ball(9.3, 4.0, 0.5),
            ball(5.0, 0.1, 0.5),
            ball(5.0, 7.15, 0.5),
        ];
        assert!(ball_overlaps(&balls).deepest.is_none());
        let found = ball_overlaps_periodic(&balls, size);
        let deepest = found.deepest.unwrap();
        assert_eq!((deepest.a, deepest.b), (0, 1));
        assert!((deepest.depth - 0.1).abs() < 1e-12, "{deepest:?}");
        assert_eq!(found.beyond.map(|p| (p.a, p.b)), Some((0, 1)));
        // Far from the edges nothing changes.
        let inside = [ball(3.0, 3.0, 0.5), ball(3.9, 3.0, 0.5)];
        assert_eq!(
            ball_overlaps_periodic(&inside, size),
            ball_overlaps(&inside)
        );
    }

    #[test]
    fn an_overlapping_pair_is_found_with_its_depth() {
        let balls = [
            ball(0.0, 0.0, 1.0),
            ball(9.0, 9.0, 1.0),
            ball(1.5, 0.0, 1.0),
        ];
        let pair = ball_overlaps(&balls).deepest.unwrap();
        assert_eq!((pair.a, pair.b, pair.depth), (0, 2, 0.25));
    }

    #[test]
    fn touching_balls_have_depth_zero_and_apart_balls_none() {
        assert_eq!(
            ball_overlaps(&[ball(0.0, 0.0, 1.0), ball(2.0, 0.0, 1.0)])
                .deepest
                .unwrap()
                .depth,
            0.0
        );
        assert_eq!(
            ball_overlaps(&[ball(0.0, 0.0, 1.0), ball(2.5, 0.0, 1.0)]).deepest,
            None
        );
    }

    #[test]
    fn balls_that_do_not_interact_are_not_an_overlap() {
        let ghost = CollisionGroups::new(1, !1);
        let (mut a, mut b) = (ball(0.0, 0.0, 1.0), ball(0.5, 0.0, 1.0));
        (a.groups, b.groups) = (ghost, ghost);
        assert_eq!(ball_overlaps(&[a, b]).deepest, None);
        b.groups = CollisionGroups::ALL;
        assert_eq!(ball_overlaps(&[a, b]).deepest.unwrap().depth, 0.75);
    }

    #[test]
    fn the_grid_finds_exactly_the_pairs_that_all_pairs_find() {
        let groups = [
            CollisionGroups::ALL,
            CollisionGroups::new(1, !1),
            CollisionGroups::new(2, 1),
        ];
        for seed in 0..20 {
            let mut rng = Rng(seed);
            let n = 50 + (rng.next() * 400.0) as usize;
            let balls: Vec<Ball> = (0..n)
                .map(|_| {
                    let mut b = ball(
                        rng.next() * 20.0 - 3.0,
                        rng.next() * 10.0,
                        0.02 + rng.next() * 0.5,
                    );
                    b.groups = groups[(rng.next() * 3.0) as usize];
                    b
                })
                .collect();
            let mut found = Vec::new();
            for_each_close_ball_pair(&balls, |p| found.push((p.a, p.b, p.depth)));
            found.sort_by_key(|x| (x.0, x.1));
            let expected = all_pairs(&balls);
            assert!(
                !expected.is_empty(),
                "seed {seed}: a test without pairs proves nothing"
            );
            assert_eq!(found, expected, "seed {seed}");
        }
    }

    #[test]
    fn a_ball_sunk_into_a_wall_is_found() {
        let balls = [
            ball(0.0, 2.0, 1.0),
            ball(3.0, 0.5, 1.0),
            ball(4.0, -0.75, 1.0),
        ];
        let contact = collider_overlaps(&balls, &[solid(wall())]).deepest.unwrap();
        assert_eq!((contact.ball, contact.collider, contact.depth), (1, 0, 0.5));
    }

    #[test]
    fn a_ball_in_a_static_circle_is_measured_against_the_sum_of_radii() {
        let circle = Shape::Circle(exact2d::Circle::new(DVec2::new(20.0, 0.0), 3.0).unwrap());
        let balls = [ball(16.0, 0.0, 2.0)];
        let contact = collider_overlaps(&balls, &[solid(wall()), solid(circle)])
            .deepest
            .unwrap();
        assert_eq!((contact.collider, contact.depth), (1, 0.2));
    }

    #[test]
    fn sensors_and_colliders_in_other_groups_are_skipped() {
        let mut balls = [ball(0.0, 0.5, 1.0)];
        balls[0].groups = CollisionGroups::new(1, 1);
        let mut sensor = solid(wall());
        sensor.sensor = true;
        let mut other = solid(wall());
        other.groups = CollisionGroups::new(2, 2);
        assert_eq!(collider_overlaps(&balls, &[sensor, other]).deepest, None);
        assert!(
            collider_overlaps(&balls, &[sensor, other, solid(wall())])
                .deepest
                .is_some()
        );
    }

    #[test]
    fn the_collider_check_finds_what_every_ball_against_every_collider_finds() {
        let mut rng = Rng(7);
        let balls: Vec<Ball> = (0..300)
            .map(|_| {
                ball(
                    rng.next() * 10.0,
                    rng.next() * 10.0,
                    0.05 + rng.next() * 0.3,
                )
            })
            .collect();
        let colliders: Vec<Collider> = (0..30)
            .map(|_| {
                let a = DVec2::new(rng.next() * 10.0, rng.next() * 10.0);
                let b = a + DVec2::new(rng.next() - 0.5, rng.next() - 0.5);
                solid(Shape::Segment(Segment::new(a, b).unwrap()))
            })
            .collect();
        let mut expected: Option<(f64, usize, usize)> = None;
        for (c, collider) in colliders.iter().enumerate() {
            for (i, b) in balls.iter().enumerate() {
                let d = (b.radius - collider.shape.distance(b.position)) / b.radius;
                if d >= 0.0 && expected.is_none_or(|e| d > e.0) {
                    expected = Some((d, c, i));
                }
            }
        }
        let found = collider_overlaps(&balls, &colliders).deepest.unwrap();
        assert_eq!(Some((found.depth, found.collider, found.ball)), expected);
    }

    #[test]
    fn the_bound_is_the_engines_and_grows_with_the_coordinates() {
        // 3e-8 of the contact distance deep: beyond 1e-9 near the origin, within the 256 ulps
        // of the coordinate scale (5.7e-8 here) at x = 1e6.
        let near = [ball(0.0, 0.0, 0.5), ball(1.0 - 3e-8, 0.0, 0.5)];
        let found = ball_overlaps(&near);
        let beyond = found.beyond.unwrap();
        assert_eq!(found.deepest, Some(beyond));
        assert!((beyond.depth - 3e-8).abs() < 1e-15, "{beyond:?}");
        assert_eq!(beyond.allowed, exact2d::overlap_bound(1.0 - 3e-8, 1.0));
        let far = [ball(1e6, 0.0, 0.5), ball(1e6 + 1.0 - 3e-8, 0.0, 0.5)];
        let found = ball_overlaps(&far);
        assert_eq!(found.beyond, None);
        let pair = found.deepest.unwrap();
        assert!(pair.depth > 2e-8 && pair.depth < pair.allowed, "{pair:?}");
        assert_eq!(pair.allowed, exact2d::overlap_bound(1e6 + 1.0 - 3e-8, 1.0));
        let deeper = [ball(1e6, 0.0, 0.5), ball(1e6 + 1.0 - 1e-7, 0.0, 0.5)];
        assert!(ball_overlaps(&deeper).beyond.is_some());
    }

    #[test]
    fn a_contact_with_a_collider_is_bounded_at_the_ball_and_the_circle_centre() {
        let far_floor = Segment::new(DVec2::new(1e6 - 5.0, 0.0), DVec2::new(1e6 + 5.0, 0.0));
        let far_floor = solid(Shape::Segment(far_floor.unwrap()));
        // 4e-8 of the radius deep: within 1e-9 + 256 ulps of 1e6 + 0.5, relative to 0.5.
        let balls = [ball(1e6, 0.5 - 2e-8, 0.5)];
        let found = collider_overlaps(&balls, &[far_floor]);
        assert_eq!(found.beyond, None);
        let contact = found.deepest.unwrap();
        assert_eq!(contact.allowed, exact2d::overlap_bound(1e6, 0.5) / 0.5);
        // The same depth at the origin is beyond.
        let balls = [ball(0.0, 0.5 - 2e-8, 0.5)];
        let beyond = collider_overlaps(&balls, &[solid(wall())]).beyond.unwrap();
        assert!(beyond.depth > beyond.allowed);
        // A circle far away counts its centre's coordinates.
        let peg = Shape::Circle(exact2d::Circle::new(DVec2::new(0.0, 1e6), 0.5).unwrap());
        let balls = [ball(0.0, 1e6 - 1.0 + 3e-8, 0.5)];
        let found = collider_overlaps(&balls, &[solid(peg)]);
        assert_eq!(found.beyond, None);
        assert_eq!(
            found.deepest.unwrap().allowed,
            exact2d::overlap_bound(1e6, 1.0)
        );
    }
}
