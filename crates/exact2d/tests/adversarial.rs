//! Adversarial geometry, each case against an answer worked out independently of the engine:
//! wedges (by unfolding), crossing and collinear segments, end points shared by many
//! segments, extreme speeds, radii and coordinates (by mirror folding), and a packing near
//! jamming (by conservation laws and containment).

mod common;

use std::f64::consts::PI;

use common::{add_polygon, boxed_rect, v};
use exact2d::{BallDesc, ColliderDesc, DVec2, Event, Feature, World};

fn unit(angle: f64) -> DVec2 {
    v(angle.cos(), angle.sin())
}

/// Every contact event until no event is left (or `limit` events, a failure).
fn contacts_to_the_end(world: &mut World, limit: usize) -> Vec<exact2d::ContactEvent> {
    let mut out = Vec::new();
    while let Some(event) = world.step() {
        match event {
            Event::Contact(c) => out.push(c),
            other => panic!("unexpected {other:?}"),
        }
        assert!(out.len() <= limit, "more than {limit} contacts");
    }
    out
}

/// The direction a ray ends with after bouncing in a wedge of angle `alpha` whose centre
/// region has its apex at `apex` and its first wall along +x, by unfolding: the ray is
/// straight in the plane of reflected copies of the wedge; it ends in copy `k` (between
/// angles `k alpha` and `(k + 1) alpha`), and copy `k` maps back to the wedge by a rotation
/// by `-k alpha` (k even) or a reflection across the line at angle `(k + 1) alpha / 2` (k
/// odd). Returns the number of bounces `|k|` and the final direction.
fn unfolded(alpha: f64, apex: DVec2, start: DVec2, direction: DVec2) -> (usize, DVec2) {
    let r = start - apex;
    let theta0 = r.y.atan2(r.x);
    // The polar angle seen from the apex sweeps monotonically towards the direction's angle,
    // counterclockwise when the ray passes the apex on its right.
    let mut psi = direction.y.atan2(direction.x);
    if r.perp_dot(direction) > 0.0 {
        while psi <= theta0 {
            psi += 2.0 * PI;
        }
    } else {
        while psi >= theta0 {
            psi -= 2.0 * PI;
        }
    }
    let k = (psi / alpha).floor() as i64;
    let d = direction;
    let back = if k % 2 == 0 {
        let a = -(k as f64) * alpha;
        v(a.cos() * d.x - a.sin() * d.y, a.sin() * d.x + a.cos() * d.y)
    } else {
        let b = 2.0 * ((k + 1) as f64 * alpha / 2.0);
        v(b.cos() * d.x + b.sin() * d.y, b.sin() * d.x - b.cos() * d.y)
    };
    (k.unsigned_abs() as usize, back)
}

/// A ball sent deep into a wedge of `alpha` (walls from the origin along +x and along angle
/// `alpha`, each `length` long, or crossing at the origin when `crossing`), against the
/// unfolded answer: the exact number of bounces and the final direction.
fn wedge_case(alpha: f64, crossing: bool, miss: f64) {
    let (r, length, speed) = (0.25, 400.0, 3.0);
    let mut world = World::new();
    let back = if crossing { -20.0 } else { 0.0 };
    world
        .add_collider(ColliderDesc::segment(v(back, 0.0), v(length, 0.0)))
        .unwrap();
    world
        .add_collider(ColliderDesc::segment(
            unit(alpha) * back,
            unit(alpha) * length,
        ))
        .unwrap();
    // The centre stays in a wedge of the same angle whose apex is r / sin(alpha / 2) along
    // the bisector: where it touches both walls.
    let bisector = unit(alpha / 2.0);
    let apex = bisector * (r / (alpha / 2.0).sin());
    let start = bisector * 100.0;
    // Aimed at a point `miss` beside the apex, so the ray never meets the apex itself.
    let target = apex + bisector.perp() * miss;
    let direction = (target - start).normalize();
    let ball = world
        .add_ball(BallDesc::new(start, r).velocity(direction * speed))
        .unwrap();
    let contacts = contacts_to_the_end(&mut world, 10_000);
    let (bounces, expected) = unfolded(alpha, apex, start, direction);
    assert_eq!(contacts.len(), bounces, "alpha {alpha}, miss {miss}");
    assert!(
        contacts
            .iter()
            .all(|c| c.feature == Feature::SegmentInterior)
    );
    let out = world.ball(ball).unwrap().velocity;
    assert!((out.length() - speed).abs() < 1e-12 * speed, "{out:?}");
    assert!(
        (out / speed - expected).length() < 1e-9,
        "{out:?} vs {expected:?}"
    );
}

#[test]
fn a_ball_deep_in_an_acute_wedge_bounces_as_often_as_unfolding_says() {
    for (degrees, miss) in [(10.0, 0.3), (5.0, 0.05), (2.0, 0.01), (1.0, 0.004)] {
        wedge_case(f64::to_radians(degrees), false, miss);
    }
}

#[test]
fn segments_crossing_at_the_apex_make_the_same_wedge() {
    // The apex is now an interior point of both segments: no end point is involved.
    for (degrees, miss) in [(10.0, 0.3), (3.0, 0.02)] {
        wedge_case(f64::to_radians(degrees), true, miss);
    }
}

#[test]
fn segments_crossing_in_an_x_are_hit_like_any_segment() {
    // An X of two segments crossing at right angles; a ball in the right-hand quarter,
    // moving up, meets the arm y = x and turns right.
    let mut world = World::new();
    world
        .add_collider(ColliderDesc::segment(v(-5.0, -5.0), v(5.0, 5.0)))
        .unwrap();
    world
        .add_collider(ColliderDesc::segment(v(-5.0, 5.0), v(5.0, -5.0)))
        .unwrap();
    // Centre (3, 0), radius sqrt(2) / 4, heading up: it touches the arm y = x when the
    // distance to it, (x - y) / sqrt(2), equals the radius: at y = 2.5, t = 2.5.
    let r = 2f64.sqrt() / 4.0;
    let ball = world
        .add_ball(BallDesc::new(v(3.0, 0.0), r).velocity(v(0.0, 1.0)))
        .unwrap();
    let Some(Event::Contact(first)) = world.step() else {
        panic!("must hit the arm y = x")
    };
    assert!((first.time - 2.5).abs() < 1e-14, "{}", first.time);
    assert_eq!(first.feature, Feature::SegmentInterior);
    let after = world.ball(ball).unwrap().velocity;
    assert!((after - v(1.0, 0.0)).length() < 1e-15, "{after:?}");
}

#[test]
fn overlapping_collinear_segments_give_one_bounce() {
    // Three segments on y = 0: two overlapping on [2, 6], a third meeting one end to end at
    // x = 8. A ball falling onto the overlap (touching at x = 4.625), and one onto the
    // junction (at x = 8 exactly), bounce once each: the second segment's contact at the
    // same instant finds the ball already leaving.
    for x in [4.0, 7.375] {
        let mut world = World::new();
        for (a, b) in [(0.0, 6.0), (2.0, 8.0), (8.0, 12.0)] {
            world
                .add_collider(ColliderDesc::segment(v(a, 0.0), v(b, 0.0)))
                .unwrap();
        }
        let ball = world
            .add_ball(BallDesc::new(v(x, 3.0), 0.5).velocity(v(0.25, -1.0)))
            .unwrap();
        let contacts = contacts_to_the_end(&mut world, 10);
        assert_eq!(contacts.len(), 1, "x = {x}");
        assert!(
            (contacts[0].time - 2.5).abs() < 1e-14,
            "{}",
            contacts[0].time
        );
        assert!((contacts[0].normal - v(0.0, 1.0)).length() < 1e-12);
        let out = world.ball(ball).unwrap().velocity;
        assert!((out - v(0.25, 1.0)).length() < 1e-12, "{out:?}");
    }
}

#[test]
fn an_end_point_shared_by_many_segments_is_hit_once() {
    // Eight segments fan out downwards from one tip at the origin. A ball falling on the tip
    // touches all eight end points at the same instant: the first in the total order (the
    // lowest collider slot) reflects it, and the others then find it leaving.
    let mut world = World::new();
    for k in 0..8 {
        let foot = v(-2.0 + 4.0 * f64::from(k) / 7.0, -3.0);
        world
            .add_collider(ColliderDesc::segment(DVec2::ZERO, foot))
            .unwrap();
    }
    let ball = world
        .add_ball(BallDesc::new(v(0.0, 5.0), 0.5).velocity(v(0.0, -1.0)))
        .unwrap();
    let contacts = contacts_to_the_end(&mut world, 10);
    assert_eq!(contacts.len(), 1);
    let hit = &contacts[0];
    assert_eq!((hit.time, hit.collider.index()), (4.5, 0));
    assert_eq!(
        (hit.feature, hit.normal),
        (Feature::SegmentEndA, v(0.0, 1.0))
    );
    assert_eq!(world.ball(ball).unwrap().velocity, v(0.0, 1.0));
}

/// The mirror-folded coordinate of a ball of radius `r` in `[0, size]`, from `x0` at speed
/// `v` after time `t` (the analytic answer for a box).
fn fold(x0: f64, v: f64, t: f64, r: f64, size: f64) -> f64 {
    let span = size - 2.0 * r;
    let u = (x0 - r + v * t).rem_euclid(2.0 * span);
    r + if u <= span { u } else { 2.0 * span - u }
}

/// A ball in a box `[origin, origin + size]^2` against mirror folding after `bounces`
/// contacts; returns the worst distance from the folded position, relative to `scale`.
fn box_error(origin: DVec2, size: f64, r: f64, velocity: DVec2, bounces: usize) -> f64 {
    let mut world = World::new();
    let c = [v(0.0, 0.0), v(size, 0.0), v(size, size), v(0.0, size)].map(|p| origin + p);
    add_polygon(&mut world, &c);
    let start = origin + v(0.3, 0.45) * size;
    let ball = world
        .add_ball(BallDesc::new(start, r).velocity(velocity))
        .unwrap();
    let mut worst: f64 = 0.0;
    for _ in 0..bounces {
        let Some(Event::Contact(hit)) = world.step() else {
            panic!("a ball in a box always hits a wall")
        };
        let p = world.ball(ball).unwrap().position - origin;
        let expected = v(
            fold(start.x - origin.x, velocity.x, hit.time, r, size),
            fold(start.y - origin.y, velocity.y, hit.time, r, size),
        );
        worst = worst.max((p - expected).abs().max_element());
        // Never outside the box the centre can reach, beyond rounding: relative to the box,
        // and to the coordinates' own spacing far from the origin.
        let slack = 1e-9 * size + 4.0 * origin.abs().max_element() * f64::EPSILON;
        let inside =
            p.cmpge(DVec2::splat(r - slack)).all() && p.cmple(DVec2::splat(size - r + slack)).all();
        assert!(inside, "escaped: {p:?}");
    }
    worst
}

#[test]
fn speeds_from_1e_minus_12_to_1e12_fold_like_mirrors() {
    // Times scale as 1 / speed, positions do not: the fold holds to the same relative error
    // at every speed (the clock keeps the exact sum of event times).
    for speed in [1e-12, 1e-6, 1.0, 1e6, 1e12] {
        let error = box_error(DVec2::ZERO, 1.0, 0.1, v(0.8, 0.6) * speed, 2000);
        assert!(error < 1e-12, "speed {speed}: {error}");
    }
}

#[test]
fn radii_from_1e_minus_9_fold_like_mirrors() {
    for r in [1e-9, 1e-6, 1e-3, 0.3] {
        let error = box_error(DVec2::ZERO, 1.0, r, v(0.8, 0.6), 2000);
        assert!(error < 1e-12, "radius {r}: {error}");
    }
}

#[test]
fn a_small_box_far_from_the_origin_drifts_by_at_most_a_coordinate_spacing_per_bounce() {
    // At 1e9 doubles are 1.2e-7 apart, so a 1e-3 box is 8,400 doubles wide. Every bounce
    // restates the ball at a contact point rounded to that spacing, so the phase along the
    // path drifts by up to one spacing per bounce (an absolute coordinate cannot do better);
    // the ball never leaves the box (checked at every bounce inside `box_error`).
    let far = v(1e9, -1e9);
    // The spacing of doubles in [2^29, 2^30), which holds 1e9.
    let spacing = 2f64.powi(-23);
    for bounces in [10, 2000] {
        let error = box_error(far, 1e-3, 1e-4, v(0.8, 0.6) * 1e-3, bounces);
        assert!(error <= bounces as f64 * spacing, "{bounces}: {error}");
    }
}

#[test]
fn a_packing_near_jamming_conserves_energy_and_stays_apart_and_inside() {
    // 300 balls filling 77% of a box (85% of the densest packing), on a triangular lattice
    // 2% wider than contact: collisions come in rapid chains.
    let n_side = 20;
    let spacing = 1.0;
    let r = 0.5 * spacing * 0.98;
    let width = n_side as f64 * spacing + 1.0;
    let height = 15.0 * spacing * 3f64.sqrt() / 2.0 + 1.0;
    let mut world = boxed_rect(width, height, DVec2::ZERO);
    let mut rng = common::SplitMix(11);
    for row in 0..15 {
        for col in 0..n_side {
            let shift = if row % 2 == 1 { 0.5 } else { 0.0 };
            let p = v(
                0.5 + (col as f64 + shift) * spacing,
                0.5 + row as f64 * spacing * 3f64.sqrt() / 2.0,
            );
            let angle = 2.0 * PI * rng.next_f64();
            if p.x + r <= width {
                world
                    .add_ball(BallDesc::new(p, r).velocity(unit(angle)))
                    .unwrap();
            }
        }
    }
    let e0 = common::energy(&world);
    let mut handled = 0u64;
    while handled < 200_000 {
        handled += world.advance_to(world.time() + 0.05).unwrap();
    }
    let drift = (common::energy(&world) - e0).abs() / e0;
    assert!(drift < 1e-12, "energy drift {drift}");
    let overlap = common::deepest_overlap(&world);
    assert!(overlap > -1e-9, "overlap {overlap}");
    for (_, b) in world.balls() {
        assert!(
            b.position.x >= b.radius - 1e-9
                && b.position.x <= width - b.radius + 1e-9
                && b.position.y >= b.radius - 1e-9
                && b.position.y <= height - b.radius + 1e-9,
            "escaped: {:?}",
            b.position
        );
    }
}
