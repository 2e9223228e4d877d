//! Rolling and sliding on surfaces with friction (`dynamics/rolling.rs`): each phase against
//! its closed form, each transition at its analytic time, no events returned for any of it.

mod common;

use common::close;

use exact2d::{BallDesc, BallHandle, ColliderDesc, DVec2, World};

const G: f64 = 10.0;

/// A world with gravity `-G y` and a rough floor from x = -50 to 50 (friction `mu`, rolling
/// resistance `c`).
fn floor_world(mu: f64, c: f64) -> World {
    let mut world = World::with_gravity(DVec2::new(0.0, -G)).unwrap();
    world
        .add_collider(
            ColliderDesc::segment(DVec2::new(-50.0, 0.0), DVec2::new(50.0, 0.0))
                .friction(mu)
                .rolling_resistance(c),
        )
        .unwrap();
    world
}

/// A uniform disk of radius 0.5 resting on the floor at x, with friction `mu`, resistance `c`.
fn disk(world: &mut World, x: f64, v: f64, spin: f64, mu: f64, c: f64) -> BallHandle {
    world
        .add_ball(
            BallDesc::new(DVec2::new(x, 0.5), 0.5)
                .velocity(DVec2::new(v, 0.0))
                .spin(spin)
                .friction(mu)
                .rolling_resistance(c),
        )
        .unwrap()
}

#[test]
fn a_disk_thrown_sliding_rolls_from_the_analytic_time_at_the_analytic_speed() {
    // v0 = 3, no spin, mu = 0.2: kinetic friction decelerates it at mu g = 2 and spins it up
    // at mu g / (k r) = 8; the slip 3 falls at 3 mu g = 6, so it rolls from t = 0.5, at
    // v0 / (1 + k) = 2, turning at -4 (clockwise), and rolls on: no resistance.
    let mut world = floor_world(0.2, 0.0);
    let ball = disk(&mut world, 0.0, 3.0, 0.0, 0.2, 0.0);
    assert_eq!(world.advance_to(0.25).unwrap(), 0);
    let b = world.ball(ball).unwrap();
    close(
        b.position.x,
        3.0 * 0.25 - 0.5 * 2.0 * 0.0625,
        "x while sliding",
    );
    close(b.velocity.x, 2.5, "v while sliding");
    close(b.spin, -2.0, "spin while sliding");
    assert_eq!(b.position.y, 0.5);
    assert_eq!(world.advance_to(1.5).unwrap(), 0);
    let b = world.ball(ball).unwrap();
    close(b.position.x, 1.25 + 2.0, "x rolling");
    close(b.velocity.x, 2.0, "v rolling");
    close(b.spin, -4.0, "spin rolling");
    // Energy: 4.5 before, 2 + 1 rolling; friction took 1.5.
    close(b.kinetic_energy(), 3.0, "energy");
}

#[test]
fn a_backspun_disk_stops_turns_back_and_rolls_back() {
    // v0 = 2 forward, spin +12 (counter-clockwise: backspin for a ball going right): slip
    // v_t - w r along t = -x is -2 - 6 = -8... friction pushes it back at mu g = 5 and slows
    // the spin at 20; the slip falls at 15, so it rolls from 8/15 s, at 2 - 5 * 8/15 = -2/3.
    let mut world = floor_world(0.5, 0.0);
    let ball = disk(&mut world, 0.0, 2.0, 12.0, 0.5, 0.0);
    world.advance_to(2.0).unwrap();
    let b = world.ball(ball).unwrap();
    close(b.velocity.x, -2.0 / 3.0, "rolling back");
    close(b.spin, 4.0 / 3.0, "rolling back, turning");
    let t = 8.0 / 15.0;
    let x_roll = 2.0 * t - 2.5 * t * t;
    close(b.position.x, x_roll - 2.0 / 3.0 * (2.0 - t), "x");
}

#[test]
fn on_an_incline_a_disk_rolls_below_the_critical_slope_and_slides_above() {
    // mu = 0.2 holds a disk rolling on slopes up to tan a = 3 mu = 0.6.
    for (tan, rolls) in [(0.5, true), (0.7, false)] {
        let a = f64::atan(tan);
        let (sin, cos) = (a.sin(), a.cos());
        let mut world = World::with_gravity(DVec2::new(0.0, -G)).unwrap();
        let down = DVec2::new(cos, -sin);
        world
            .add_collider(ColliderDesc::segment(DVec2::ZERO, down * 100.0).friction(0.2))
            .unwrap();
        let normal = DVec2::new(sin, cos);
        let start = down * 5.0 + normal * 0.5;
        let ball = world
            .add_ball(BallDesc::new(start, 0.5).friction(0.2))
            .unwrap();
        assert_eq!(world.advance_to(1.0).unwrap(), 0);
        let b = world.ball(ball).unwrap();
        let along = (b.position - start).dot(down);
        let speed = b.velocity.dot(down);
        let accel = if rolls {
            2.0 / 3.0 * G * sin
        } else {
            G * (sin - 0.2 * cos)
        };
        close(along, 0.5 * accel, &format!("tan {tan}: distance"));
        close(speed, accel, &format!("tan {tan}: speed"));
        // Rolling, the spin is -v / r (clockwise going down to the right); sliding, friction
        // spins it up at mu g cos a / (k r) and it lags behind.
        let spin = if rolls {
            -speed / 0.5
        } else {
            -0.2 * G * cos / 0.25
        };
        close(b.spin, spin, &format!("tan {tan}: spin"));
        assert!((b.position - start).dot(normal).abs() < 1e-12);
    }
}

#[test]
fn rolling_resistance_stops_a_rolling_disk_at_its_analytic_time_and_place() {
    // Rolling at 2 (spin -4), resistance 0.05 on both: it loses 0.05 g = 0.5 a second and
    // stops at t = 4, 4 further on, and stays: no event ever after.
    let mut world = floor_world(0.3, 0.05);
    let ball = disk(&mut world, 1.0, 2.0, -4.0, 0.3, 0.05);
    world.advance_to(2.0).unwrap();
    let b = world.ball(ball).unwrap();
    close(b.velocity.x, 1.0, "half-way speed");
    close(b.position.x, 1.0 + 4.0 - 1.0, "half-way");
    close(b.spin, -2.0, "half-way spin");
    world.advance_to(4.0).unwrap();
    let stop = world.ball(ball).unwrap();
    close(stop.position.x, 5.0, "stopped");
    assert_eq!((stop.velocity, stop.spin), (DVec2::ZERO, 0.0));
    assert_eq!(world.advance_to(1000.0).unwrap(), 0);
    assert_eq!(world.ball(ball).unwrap().position, stop.position);
    assert!(world.next_event_time().is_none());
}

#[test]
fn a_spin_given_to_a_resting_rough_disk_sets_it_rolling() {
    // Spin -4 (clockwise) at rest: the slip 2 drives it forward at mu g = 5 while the spin
    // slows at 20; it rolls from 2/15 s at 2/3 (a third of w r for a disk).
    let mut world = floor_world(0.5, 0.0);
    let ball = disk(&mut world, 0.0, 0.0, 0.0, 0.5, 0.0);
    world.advance_to(1.0).unwrap();
    world.set_ball_spin(ball, -4.0).unwrap();
    world.advance_to(3.0).unwrap();
    let b = world.ball(ball).unwrap();
    close(b.velocity.x, 2.0 / 3.0, "rolling speed");
    close(b.spin, -4.0 / 3.0, "rolling spin");
    let t = 2.0 / 15.0;
    close(b.position.x, 2.5 * t * t + 2.0 / 3.0 * (2.0 - t), "x");
}

#[test]
fn a_rolling_disk_rolls_off_the_edge_and_keeps_turning_in_flight() {
    // A table from x = -5 to 0: rolling at 3 (faster than sqrt(g r) = 2.24, so it flies off
    // at the edge), spin -6, no resistance: it keeps its spin in flight.
    let mut world = World::with_gravity(DVec2::new(0.0, -G)).unwrap();
    world
        .add_collider(
            ColliderDesc::segment(DVec2::new(-5.0, 0.0), DVec2::new(0.0, 0.0)).friction(0.4),
        )
        .unwrap();
    let ball = disk(&mut world, -4.0, 3.0, -6.0, 0.4, 0.0);
    // It reaches the edge at t = 4/3 and falls from there: at t = 2, 2/3 s later.
    world.advance_to(2.0).unwrap();
    let b = world.ball(ball).unwrap();
    // (The slide ends END_MARGIN, 4e-12 of the table's length, past the edge: the fall
    // starts 7e-12 s late.)
    let fall = 0.5 - 0.5 * G * (2.0 / 3.0) * (2.0 / 3.0);
    assert!(
        (b.position - DVec2::new(2.0, fall)).length() < 1e-10,
        "{b:?}"
    );
    close(b.spin, -6.0, "spin in flight");
    close(b.velocity.x, 3.0, "speed in flight");
}

#[test]
fn frictionless_balls_still_slide_as_before() {
    let mut world = floor_world(0.0, 0.0);
    let ball = disk(&mut world, 0.0, 3.0, 5.0, 0.0, 0.0);
    world.advance_to(2.0).unwrap();
    let b = world.ball(ball).unwrap();
    assert_eq!((b.position.x, b.velocity.x, b.spin), (6.0, 3.0, 5.0));
}

/// The angle from the top (radians, clockwise positive) at which a ball starting at rest
/// `start` radians off the apex of a peg of radius 1 leaves it, and its speed and spin then.
fn leave_angle_off_a_peg(mu: f64, start: f64) -> (f64, f64, f64) {
    let mut world = World::with_gravity(DVec2::new(0.0, -G)).unwrap();
    world
        .add_collider(ColliderDesc::circle(DVec2::ZERO, 1.0).friction(mu))
        .unwrap();
    let reach = 1.5;
    let at = DVec2::new(start.sin(), start.cos()) * reach;
    let ball = world.add_ball(BallDesc::new(at, 0.5).friction(mu)).unwrap();
    let mut t = 0.0;
    loop {
        t += 1e-4;
        world.advance_to(t).unwrap();
        if world.ball_support(ball).is_none() {
            let b = world.ball(ball).unwrap();
            let angle = b.position.x.atan2(b.position.y);
            return (angle, b.velocity.length(), b.spin);
        }
        assert!(t < 10.0, "never left");
    }
}

#[test]
fn a_disk_rolls_over_a_peg_and_leaves_it_where_rolling_says() {
    // Rolling, its kinetic energy is (1 + k) m v^2 / 2, so v^2 = 2 g rho (cos a0 - cos a) /
    // (1 + k), and the peg lets go when v^2 = g rho cos a: cos a = 2 cos a0 / (3 + k) (a disk:
    // 55.2 degrees from a0 = 0.01), where a frictionless ball goes at cos a = 2 cos a0 / 3
    // (48.2 degrees). The pivot's polygon has half-degree edges.
    let a0: f64 = 0.01;
    let (rolling, speed, spin) = leave_angle_off_a_peg(1e3, a0);
    eprintln!(
        "rolling off a peg: left at {:.3} degrees, speed {speed:.4}, spin {spin:.4}",
        rolling.to_degrees()
    );
    let expected = (2.0 * a0.cos() / 3.5).acos();
    assert!(
        (rolling - expected).abs() < 1.0_f64.to_radians(),
        "left at {} degrees where {}",
        rolling.to_degrees(),
        expected.to_degrees()
    );
    // Rolling to the end (friction slips only as the push vanishes): w r = -v.
    assert!((spin * 0.5 + speed).abs() < 0.02 * speed, "{spin} {speed}");
    let (smooth, _, smooth_spin) = leave_angle_off_a_peg(0.0, a0);
    let frictionless = (2.0 * a0.cos() / 3.0).acos();
    assert!((smooth - frictionless).abs() < 1.0_f64.to_radians());
    assert_eq!(smooth_spin, 0.0);
}

#[test]
fn a_spinning_rough_ball_in_a_corner_rests_there_without_a_stall() {
    // Regression (a poured rough pile stalled at t = 1.75): a ball in the corner of the floor
    // and the left wall, turning counter-clockwise, is driven into the wall by the floor's
    // friction. It settled, met the wall at once, settled again, for ever at one instant;
    // now that corner holds it, at rest.
    for spin in [2.64, 40.0] {
        let mut world = World::with_gravity(DVec2::new(0.0, -G)).unwrap();
        world.set_sleeping(true);
        for (a, b) in [((-1.0, 0.0), (5.0, 0.0)), ((0.0, -1.0), (0.0, 5.0))] {
            world
                .add_collider(
                    ColliderDesc::segment(DVec2::new(a.0, a.1), DVec2::new(b.0, b.1)).friction(0.5),
                )
                .unwrap();
        }
        let ball = world
            .add_ball(
                BallDesc::new(DVec2::new(0.2, 0.2), 0.2)
                    .spin(spin)
                    .friction(0.5)
                    .restitution(0.5),
            )
            .unwrap();
        world.advance_to(10.0).unwrap();
        let b = world.ball(ball).unwrap();
        assert!(
            (b.position - DVec2::new(0.2, 0.2)).length() < 1e-12,
            "{b:?}"
        );
        assert!(world.ball_asleep(ball));
        assert!(
            world.event_counts().handled() < 100,
            "{:?}",
            world.event_counts()
        );
    }
}

#[test]
fn a_rough_ball_rolls_down_an_exact_fit_channel_without_a_crawl() {
    // Regression (rough hunt seed 371712): a spinning rough ball in a channel at 60 degrees
    // exactly one diameter wide, at x = 1e3, whose walls face each other but for 1.6e-13
    // radians (their rounded end points). Each end of a friction phase on the lower wall
    // forgot the upper one it touched: met again at once by the rounding of the walls'
    // angle, its friction left a slip of a rounding, a slide of 2.5e-16 s, whose end forgot
    // it again (100,000 events in 2.5e-11 s). The wall stays touched through the phases.
    let mut world = World::with_gravity(DVec2::new(0.0, -0.981)).unwrap();
    world.set_sleeping(true);
    let p = DVec2::new;
    let lower = ColliderDesc::segment(
        p(1000.2913397459622, 999.9351923788647),
        p(999.9913397459621, 1000.4548076211354),
    );
    let upper = ColliderDesc::segment(
        p(1000.3086602540378, 999.9451923788647),
        p(1000.0086602540379, 1000.4648076211354),
    );
    world
        .add_collider(lower.restitution(0.8).friction(0.5))
        .unwrap();
    world
        .add_collider(
            upper
                .restitution(0.8)
                .friction(0.2)
                .tangential_restitution(0.5)
                .rolling_resistance(0.1),
        )
        .unwrap();
    world
        .add_ball(
            BallDesc::new(p(1000.075, 1000.3299038105677), 0.010000000000000002)
                .velocity(p(0.008660254037844388, 0.005))
                .spin(6.772438684997514)
                .friction(1.5)
                .tangential_restitution(0.5)
                .rolling_resistance(0.1),
        )
        .unwrap();
    let mut events = 0;
    while world.step_until(0.01).unwrap().is_some() {
        events += 1;
        assert!(events < 100, "a crawl at t = {}", world.time());
    }
    assert_eq!(world.time(), 0.01);
}

#[test]
fn a_slide_that_ends_beside_a_ball_rolls_on_without_gaining_energy() {
    // Regression (rough hunt seed 358890, there at x = 1e6 and a millionth of this size): a
    // disk spun clockwise at 12 on a rough shelf (y = 1, mu = 0.5, g = 8) is driven right at
    // mu g = 4 while its slip 6 falls at 12: it rolls from t = 0.5, at 2, turning at -4, at
    // x = 0.5, just over a ball resting under the shelf. Touching a ball, it moves on its
    // support frictionless; the ended slide's acceleration, kept, went on pushing it at 4 with
    // its spin fixed, adding energy.
    let mut world = World::with_gravity(DVec2::new(0.0, -8.0)).unwrap();
    for y in [0.0, 1.0] {
        world
            .add_collider(
                ColliderDesc::segment(DVec2::new(-50.0, y), DVec2::new(50.0, y)).friction(0.5),
            )
            .unwrap();
    }
    let ball = world
        .add_ball(
            BallDesc::new(DVec2::new(0.0, 1.5), 0.5)
                .spin(-12.0)
                .friction(0.5),
        )
        .unwrap();
    world
        .add_ball(BallDesc::new(DVec2::new(0.5, 0.5), 0.5))
        .unwrap();
    assert_eq!(world.advance_to(0.5).unwrap(), 0);
    let rolling = world.ball(ball).unwrap();
    close(rolling.velocity.x, 2.0, "v at the slide's end");
    close(rolling.spin, -4.0, "spin at the slide's end");
    assert_eq!(world.advance_to(1.0).unwrap(), 0);
    let b = world.ball(ball).unwrap();
    close(b.velocity.x, 2.0, "v rolling on");
    close(b.spin, -4.0, "spin rolling on");
    close(b.position.x, 1.5, "x rolling on");
    assert!(
        b.kinetic_energy() <= rolling.kinetic_energy() * (1.0 + 1e-12),
        "{} from {}",
        b.kinetic_energy(),
        rolling.kinetic_energy()
    );
}

/// A pile of 40 rough balls (radius 0.2, restitution 0.5, friction 0.5) poured into a box 4
/// wide: handled events per ball until every ball sleeps, and the time then.
fn rough_pile_events() -> (f64, f64) {
    let mut world = common::boxed_rect(4.0, 12.0, DVec2::new(0.0, -9.81));
    world.set_sleeping(true);
    let walls: Vec<_> = world.colliders().map(|(h, c)| (h, *c)).collect();
    for (h, c) in walls {
        world.remove_collider(h).unwrap();
        let exact2d::Shape::Segment(s) = c.shape else {
            continue;
        };
        world
            .add_collider(
                ColliderDesc::segment(s.a(), s.b())
                    .restitution(0.5)
                    .friction(0.5),
            )
            .unwrap();
    }
    let mut rng = common::SplitMix(40);
    for k in 0..40 {
        let (i, j) = ((k % 8) as f64, (k / 8) as f64);
        let p = DVec2::new(0.3 + 0.48 * i, 3.0 + 0.6 * j);
        let v = DVec2::new(rng.range(-1.0, 1.0), rng.range(-1.0, 0.0));
        world
            .add_ball(
                BallDesc::new(p, 0.2)
                    .velocity(v)
                    .restitution(0.5)
                    .friction(0.5),
            )
            .unwrap();
    }
    let mut t = 0.0;
    while world.sleeping_count() < 40 && t < 60.0 {
        t += 0.25;
        world.advance_to(t).unwrap();
    }
    assert_eq!(world.sleeping_count(), 40, "not at rest by t = {t}");
    (world.event_counts().handled() as f64 / 40.0, t)
}

#[test]
fn a_rough_pile_comes_to_rest_in_few_events() {
    // A ball rubbing its support among frictionless neighbours (friction between balls in
    // contact is not modelled yet) was driven into them by its friction at every settle,
    // a jam of the cluster each time; it now moves on its support frictionless while it
    // touches a ball. Measured: 2,131 events a ball to rest at t = 4, where that took 32,371.
    let (events, t) = rough_pile_events();
    assert!(
        events < 5000.0,
        "{events} events a ball (at rest at t = {t})"
    );
}
