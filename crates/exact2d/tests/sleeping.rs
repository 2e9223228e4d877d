//! Sleeping balls: balls at rest on balls, against analytic answers (see `pipeline/sleep.rs`,
//! `dynamics/sleep.rs` and ARCHITECTURE.md, "Sleeping balls").

mod common;

use common::{ball, floor, run_dissipative, v};
use exact2d::{BallDesc, BallHandle, Body, ColliderDesc, DVec2, Event, SETTLE_HEIGHT, World};

/// A world with gravity `g` in which balls at rest fall asleep.
fn sleepy(g: DVec2) -> World {
    let mut world = World::with_gravity(g).unwrap();
    world.set_sleeping(true);
    world
}

fn asleep_all(world: &World) -> bool {
    world.balls().all(|(h, _)| world.ball_asleep(h))
}

/// A ball resting on a floor sleeps at once; a ball dropped onto it from a gap `h0` lands at
/// `t1 = sqrt(2 h0 / g)` with speed `w1 = g t1`, and bounce `k` (from 1) leaves with
/// `e^k w1`, `e` the pair's restitution, landing `2 e^k w1 / g` later: the bounces accumulate
/// at `t* = t1 + 2 e w1 / (g (1 - e))`. The lower ball never wakes (each push is straight
/// down, into its floor), and the upper one sleeps balanced on its top after the bounces,
/// within the settling rule's bound of `t*`.
#[test]
fn a_ball_dropped_on_a_sleeping_ball_bounces_analytically_and_sleeps_on_its_top() {
    let (g, e_top, e_bottom) = (8.0, 0.8, 0.9);
    let mut world = sleepy(v(0.0, -g));
    floor(&mut world, -10.0, 10.0);
    let bottom = ball(&mut world, v(0.0, 0.5), 0.5, e_bottom);
    let h0 = 1.0;
    let top = ball(&mut world, v(0.0, 1.5 + h0), 0.5, e_top);
    world.advance_to(0.0).unwrap();
    assert!(
        world.ball_asleep(bottom),
        "the ball on the floor sleeps at once"
    );
    assert_eq!(world.ball_holders(bottom).unwrap().len(), 1);
    let events = run_dissipative(&mut world, 100.0, 1000);
    let e = e_top * e_bottom;
    let t1 = (2.0 * h0 / g).sqrt();
    let w1 = g * t1;
    let mut expected = t1;
    let mut w = w1;
    for (k, event) in events.iter().enumerate() {
        let Event::BallContact(contact) = event else {
            panic!("event {k} is {event:?}");
        };
        assert!(
            (contact.time - expected).abs() <= 1e-9 * expected,
            "bounce {k} at {} against {expected}",
            contact.time
        );
        assert!(
            (contact.normal_speed - w).abs() <= 1e-9 * w1,
            "bounce {k} at speed {} against {w}",
            contact.normal_speed
        );
        w *= e;
        expected += 2.0 * w / g;
    }
    assert!(events.len() > 10, "only {} bounces", events.len());
    assert!(world.ball_asleep(bottom), "the lower ball never woke");
    assert_eq!(world.event_counts().wakes, 0);
    assert!(world.ball_asleep(top), "the upper ball sleeps on its top");
    let accumulation = t1 + 2.0 * e * w1 / (g * (1.0 - e));
    let settle_speed = (2.0 * g * SETTLE_HEIGHT * 2.0).sqrt();
    let since = world.ball_asleep_since(top).unwrap();
    assert!(
        since <= accumulation && accumulation - since <= 2.0 * settle_speed / (g * (1.0 - e)),
        "asleep at {since}, the bounces accumulate at {accumulation}"
    );
    let p = world.ball(top).unwrap().position;
    assert_eq!(p.x, 0.0);
    assert!((p.y - 1.5).abs() <= 1e-12, "{p}");
    assert_eq!(
        world.ball_holders(top).unwrap(),
        vec![Body::Ball(bottom)],
        "it rests on the lower ball"
    );
    // Nothing more ever happens.
    assert_eq!(world.advance_to(1e4).unwrap(), 0);
}

/// Three balls placed as a triangle on a floor (the top one touching both) sleep at the
/// first instant and never cost an event.
#[test]
fn a_triangle_of_three_balls_on_a_floor_sleeps_at_once_and_costs_no_events() {
    let mut world = sleepy(v(0.0, -9.81));
    floor(&mut world, -10.0, 10.0);
    let a = ball(&mut world, v(-0.5, 0.5), 0.5, 0.5);
    let b = ball(&mut world, v(0.5, 0.5), 0.5, 0.5);
    let c = ball(&mut world, v(0.0, 0.5 + 0.75_f64.sqrt()), 0.5, 0.5);
    assert_eq!(world.advance_to(0.0).unwrap(), 0, "no event is returned");
    assert!(asleep_all(&world));
    let placed: Vec<DVec2> = [a, b, c].map(|h| world.ball(h).unwrap().position).to_vec();
    assert_eq!(world.advance_to(1000.0).unwrap(), 0, "no event is returned");
    let counts = world.event_counts();
    assert_eq!(counts.collisions(), 0, "{counts:?}");
    assert_eq!(counts.sleeps, 3, "{counts:?}");
    assert!(asleep_all(&world));
    let holders = world.ball_holders(c).unwrap();
    assert!(holders.contains(&Body::Ball(a)) && holders.contains(&Body::Ball(b)));
    // Asleep, each is kept to the bit; placed touching, it moved by rounding at most.
    for (k, h) in [a, b, c].into_iter().enumerate() {
        assert_eq!(world.ball(h).unwrap().position, placed[k]);
    }
    assert!((placed[2] - v(0.0, 0.5 + 0.75_f64.sqrt())).length() <= 1e-15);
}

/// Balls dropped into a V of two 45-degree walls stack in it and sleep. Independent check:
/// every ball is in static equilibrium on the bodies it touches (computed here from the
/// positions alone: `-g` in the cone of the contact normals).
#[test]
fn a_stack_in_a_wedge_comes_to_rest_in_equilibrium() {
    let mut world = sleepy(v(0.0, -9.81));
    let walls = [(v(-4.0, 4.0), v(0.0, 0.0)), (v(0.0, 0.0), v(4.0, 4.0))];
    for (a, b) in walls {
        world
            .add_collider(ColliderDesc::segment(a, b).restitution(0.7))
            .unwrap();
    }
    for (k, x) in [0.013, -0.21, 0.37, -0.05, 0.6].into_iter().enumerate() {
        ball(&mut world, v(x, 1.5 + 1.2 * k as f64), 0.4, 0.7);
    }
    run_dissipative(&mut world, 60.0, 100_000);
    assert!(asleep_all(&world), "{} asleep", world.sleeping_count());
    let balls: Vec<_> = world.balls().map(|(_, b)| b).collect();
    for (i, b) in balls.iter().enumerate() {
        let mut normals = Vec::new();
        for (a, c) in walls {
            let s = exact2d::Segment::new(a, c).unwrap();
            if (s.distance(b.position) - b.radius).abs() <= 1e-9 {
                let foot = s.closest_point(b.position);
                normals.push((b.position - foot).normalize());
            }
        }
        for (j, o) in balls.iter().enumerate() {
            if i != j && (o.position.distance(b.position) - b.radius - o.radius).abs() <= 1e-9 {
                normals.push((b.position - o.position).normalize());
            }
        }
        assert!(
            held_up(&normals),
            "ball {i} at {} on {normals:?}",
            b.position
        );
    }
    assert_eq!(world.advance_to(world.time() + 1000.0).unwrap(), 0);
}

/// Whether `+y` is in the cone of `normals` (to 1e-9).
fn held_up(normals: &[DVec2]) -> bool {
    let up = DVec2::Y;
    if normals.iter().any(|n| (*n - up).length() <= 1e-9) {
        return true;
    }
    normals.iter().any(|a| {
        normals
            .iter()
            .any(|b| a.perp_dot(up) >= -1e-9 && up.perp_dot(*b) >= -1e-9 && a.perp_dot(*b) > 0.0)
    })
}

/// A pyramid of six balls asleep on a floor: the floor removed, every ball wakes at rest and
/// the pile falls as a whole at `g t^2 / 2`, without a single collision.
#[test]
fn a_pile_whose_floor_is_removed_falls_as_a_whole() {
    let g = 9.81;
    let mut world = sleepy(v(0.0, -g));
    let ground = floor(&mut world, -10.0, 10.0);
    let h = 0.75_f64.sqrt();
    let mut handles = Vec::new();
    for (row, count) in [3, 2, 1].into_iter().enumerate() {
        for k in 0..count {
            let x = k as f64 - (count - 1) as f64 / 2.0;
            handles.push(ball(&mut world, v(x, 0.5 + h * row as f64), 0.5, 0.3));
        }
    }
    world.advance_to(1.0).unwrap();
    assert!(asleep_all(&world));
    let before: Vec<DVec2> = handles
        .iter()
        .map(|&b| world.ball(b).unwrap().position)
        .collect();
    let collisions = world.event_counts().collisions();
    world.remove_collider(ground).unwrap();
    assert_eq!(world.sleeping_count(), 0, "every ball woke");
    assert_eq!(world.event_counts().wakes, 6);
    let t = 0.75;
    world.advance_to(1.0 + t).unwrap();
    assert_eq!(
        world.event_counts().collisions(),
        collisions,
        "no collision"
    );
    for (&b, p0) in handles.iter().zip(&before) {
        let p = world.ball(b).unwrap().position;
        assert_eq!(p.x, p0.x);
        let fall = p0.y - p.y;
        assert!((fall - 0.5 * g * t * t).abs() <= 1e-12, "fell {fall}");
    }
}

/// A row of five sleeping balls on a floor; a ball set on the first one's top with a speed
/// along the row pivots over the row's surface (frictionless: it slides over the bumps) and
/// comes to rest in a pocket between two of them, at the triangle's height, without waking
/// the row.
#[test]
fn a_ball_rolls_over_a_sleeping_row_and_rests_in_a_pocket() {
    let mut world = sleepy(v(0.0, -9.81));
    floor(&mut world, -1.0, 10.0);
    world
        .add_collider(ColliderDesc::segment(v(-0.5, 0.0), v(-0.5, 5.0)))
        .unwrap();
    world
        .add_collider(ColliderDesc::segment(v(5.5, 0.0), v(5.5, 5.0)))
        .unwrap();
    let row: Vec<BallHandle> = (0..6)
        .map(|k| ball(&mut world, v(k as f64, 0.5), 0.5, 0.5))
        .collect();
    world.advance_to(0.1).unwrap();
    assert!(asleep_all(&world));
    let h = 0.75_f64.sqrt();
    let mover = world
        .add_ball(
            BallDesc::new(v(0.0, 1.5), 0.5)
                .velocity(v(1.0, 0.0))
                .restitution(0.5),
        )
        .unwrap();
    run_dissipative(&mut world, 200.0, 100_000);
    assert!(world.ball_asleep(mover), "the mover rests");
    assert_eq!(world.event_counts().wakes, 0, "the row never woke");
    for &b in &row {
        assert!(world.ball_asleep(b));
    }
    let p = world.ball(mover).unwrap().position;
    let pocket = p.x.floor() + 0.5;
    assert!(
        (p.x - pocket).abs() <= 1e-6 && (p.y - (0.5 + h)).abs() <= 1e-6,
        "rests at {p}"
    );
}

/// A ball sliding fast into a sleeping ball on a frictionless floor pushes it sideways: a
/// push its floor cannot take, so it wakes and the two collide as balls do (equal masses,
/// elastic: the mover stops, the other goes on at its speed).
#[test]
fn a_sideways_push_wakes_a_sleeping_ball_and_they_collide() {
    let mut world = sleepy(v(0.0, -9.81));
    floor(&mut world, -10.0, 10.0);
    let still = ball(&mut world, v(0.0, 0.5), 0.5, 1.0);
    world.advance_to(0.1).unwrap();
    assert!(world.ball_asleep(still));
    let mover = world
        .add_ball(
            BallDesc::new(v(-3.0, 0.5), 0.5)
                .velocity(v(2.0, 0.0))
                .restitution(1.0),
        )
        .unwrap();
    let events = run_dissipative(&mut world, 1.1, 100);
    assert!(
        matches!(events.as_slice(), [Event::BallContact(c)] if (c.time - 1.1).abs() < 1e-12),
        "{events:?}"
    );
    assert_eq!(world.event_counts().wakes, 1);
    let (a, b) = (world.ball(mover).unwrap(), world.ball(still).unwrap());
    assert!(a.velocity.length() <= 1e-12, "{}", a.velocity);
    assert!(
        (b.velocity - v(2.0, 0.0)).length() <= 1e-12,
        "{}",
        b.velocity
    );
}

/// Two elastic balls falling side by side, one overtaking the other at `u`: with sleeping on
/// and `u` no faster than a ball sleeps at (`SLEEP_SPEED sqrt(g r)`, 0.014 m/s for radius
/// 0.2 under 9.81), the bounce is dropped: both go on at `u / 2` across (momentum kept, no
/// relative normal velocity), still falling at `g t` together, and never meet again. Faster,
/// or with sleeping off, they bounce elastically: the two exchange their speeds across.
#[test]
fn a_slow_pair_falling_freely_together_stops_against_each_other() {
    let g = 9.81;
    let run = |sleeping: bool, u: f64| {
        let mut world = World::with_gravity(v(0.0, -g)).unwrap();
        world.set_sleeping(sleeping);
        let desc = |x: f64, speed: f64| {
            BallDesc::new(v(x, 100.0), 0.2)
                .velocity(v(speed, 0.0))
                .restitution(1.0)
        };
        let a = world.add_ball(desc(0.0, u)).unwrap();
        let b = world.add_ball(desc(0.4 + 1e-3, 0.0)).unwrap();
        let events = run_dissipative(&mut world, 1.0, 100);
        let (a, b) = (world.ball(a).unwrap(), world.ball(b).unwrap());
        (events.len(), a.velocity, b.velocity)
    };
    let fall = v(0.0, -g);
    let slow = 0.01;
    assert!(slow <= exact2d::SLEEP_SPEED * (g * 0.2).sqrt());
    let (events, a, b) = run(true, slow);
    assert_eq!(events, 1);
    for w in [a, b] {
        assert!((w - v(slow / 2.0, 0.0) - fall).length() <= 1e-12, "{w}");
    }
    for (sleeping, u) in [(false, slow), (true, 0.5)] {
        let (events, a, b) = run(sleeping, u);
        assert_eq!(events, 1, "sleeping {sleeping}, {u}");
        assert!((a - fall).length() <= 1e-12, "{a}");
        assert!((b - v(u, 0.0) - fall).length() <= 1e-12, "{b}");
    }
}

/// A ball dropped onto a sleeping ball's top from off its axis bounces off it (the push is
/// into the floor's cone only when it is straight down: this one is not) - but dropped
/// straight down, the lower ball takes the push and stays asleep, and the upper one bounces
/// with the pair's restitution.
#[test]
fn a_push_into_the_floor_is_taken_and_the_mover_bounces_with_the_pair_restitution() {
    let g = 10.0;
    let mut world = sleepy(v(0.0, -g));
    floor(&mut world, -10.0, 10.0);
    let still = ball(&mut world, v(0.0, 0.5), 0.5, 0.5);
    let mover = ball(&mut world, v(0.0, 3.5), 0.5, 0.6);
    let events = run_dissipative(&mut world, 0.78, 10);
    let [Event::BallContact(c)] = events.as_slice() else {
        panic!("{events:?}");
    };
    // Lands after a 2 m fall at sqrt(40), leaves at 0.3 of it.
    assert!((c.normal_speed - 40_f64.sqrt()).abs() < 1e-12);
    let up = world.ball(mover).unwrap().velocity.y;
    let expected = 0.3 * 40_f64.sqrt() - g * (0.78 - c.time);
    assert!((up - expected).abs() < 1e-9, "{up} against {expected}");
    assert!(world.ball_asleep(still));
}

/// Waking by the API: a new velocity, a removal under another ball, a change of gravity.
#[test]
fn a_velocity_a_removal_or_new_gravity_wakes_a_ball_and_what_rests_on_it() {
    let mut world = sleepy(v(0.0, -9.81));
    floor(&mut world, -10.0, 10.0);
    let a = ball(&mut world, v(-0.5, 0.5), 0.5, 0.5);
    let b = ball(&mut world, v(0.5, 0.5), 0.5, 0.5);
    let c = ball(&mut world, v(0.0, 0.5 + 0.75_f64.sqrt()), 0.5, 0.5);
    world.advance_to(0.1).unwrap();
    assert!(asleep_all(&world));
    // A new velocity wakes the ball (and those on it: the top one loses a support).
    world.set_ball_velocity(b, v(0.0, 0.0)).unwrap();
    assert!(!world.ball_asleep(b) && !world.ball_asleep(c) && world.ball_asleep(a));
    world.advance_to(0.2).unwrap();
    assert!(asleep_all(&world), "all asleep again where they rest");
    // Removing a lower ball: the top one rolls off the other onto the floor.
    world.remove_ball(b).unwrap();
    assert!(!world.ball_asleep(c) && world.ball_asleep(a));
    run_dissipative(&mut world, 2.0, 100_000);
    assert!(
        (world.ball(c).unwrap().position.y - 0.5).abs() < 1e-9
            && world.ball(c).unwrap().position.x > 0.5,
        "{}",
        world.ball(c).unwrap().position
    );
    // A sideways gravity wakes what sleeps: it slides away along the floor.
    assert!(world.ball_asleep(a));
    world.set_gravity(v(5.0, -9.81)).unwrap();
    assert_eq!(world.sleeping_count(), 0);
    let t = world.time();
    world.advance_to(t + 0.5).unwrap();
    assert!(world.ball(a).unwrap().velocity.x > 1.0);
}

/// A ball asleep on top of another and in a V of two short walls is supported by the lower
/// ball (gravity presses it there hardest). When the lower ball wakes, the walls alone still
/// hold it: it stays asleep, and what it reports as its support is a live collider, one of
/// the walls (the world gravity fuzzer found a sleeper left on its woken support's circle).
#[test]
fn a_sleeper_whose_support_wakes_but_which_the_rest_still_hold_keeps_a_live_support() {
    let mut world = sleepy(v(0.0, -9.81));
    floor(&mut world, -10.0, 10.0);
    let lower = ball(&mut world, v(0.0, 1.0), 1.0, 0.5);
    let upper = ball(&mut world, v(0.0, 3.0), 1.0, 0.5);
    // Walls touching the upper ball at 45 degrees below its centre, short enough to miss the
    // lower one.
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let mut walls = Vec::new();
    for side in [-1.0, 1.0] {
        let touch = v(0.0, 3.0) + v(side * h, -h);
        let along = v(h, side * h) * 0.2;
        let wall = world
            .add_collider(ColliderDesc::segment(touch - along, touch + along).restitution(0.5))
            .unwrap();
        walls.push(wall);
    }
    world.advance_to(0.1).unwrap();
    assert!(asleep_all(&world), "{} asleep", world.sleeping_count());
    assert_eq!(
        world.ball_support(upper),
        None,
        "on the lower ball's circle, not a collider"
    );
    world.set_ball_velocity(lower, v(0.0, 0.0)).unwrap();
    assert!(!world.ball_asleep(lower));
    assert!(world.ball_asleep(upper), "the walls hold it");
    let (support, _) = world.ball_support(upper).expect("a collider holds it");
    assert!(world.collider(support).is_some(), "a live support");
    assert!(walls.contains(&support), "{support:?}");
    world.advance_to(1.0).unwrap();
    assert!(asleep_all(&world));
}

/// Sleeping is off by default: a ball on a ball then never rests, exactly as before.
#[test]
fn sleeping_is_off_by_default_and_turning_it_off_wakes_every_ball() {
    let mut world = World::with_gravity(v(0.0, -9.81)).unwrap();
    assert!(!world.sleeping());
    floor(&mut world, -10.0, 10.0);
    let a = ball(&mut world, v(0.0, 0.5), 0.5, 0.5);
    world.advance_to(0.1).unwrap();
    assert!(!world.ball_asleep(a));
    world.set_sleeping(true);
    world.set_ball_velocity(a, DVec2::ZERO).unwrap();
    world.advance_to(0.2).unwrap();
    assert!(world.ball_asleep(a));
    world.set_sleeping(false);
    assert!(!world.ball_asleep(a) && world.sleeping_count() == 0);
    assert_eq!(world.collider_count(), 1);
}

/// The API never shows a sleeping ball's circle as a collider.
#[test]
fn a_sleeping_ball_is_never_a_collider_to_the_api() {
    let mut world = sleepy(v(0.0, -9.81));
    let ground = floor(&mut world, -10.0, 10.0);
    let a = ball(&mut world, v(0.0, 0.5), 0.5, 0.5);
    world.advance_to(0.1).unwrap();
    assert!(world.ball_asleep(a));
    assert_eq!(world.collider_count(), 1);
    assert_eq!(world.colliders().count(), 1);
    assert_eq!(world.ball_holders(a).unwrap(), vec![Body::Collider(ground)]);
    // A new ball placed into it is refused as overlapping the ball.
    let err = world.add_ball(BallDesc::new(v(0.2, 0.6), 0.5)).unwrap_err();
    assert_eq!(err, exact2d::WorldError::OverlapsBall(a));
    // A collider added later gets a handle of its own, and the sleeping ball stays.
    let wall = world
        .add_collider(ColliderDesc::segment(v(3.0, 0.0), v(3.0, 3.0)))
        .unwrap();
    assert!(world.collider(wall).is_some());
    assert_eq!(world.collider_count(), 2);
    assert!(world.ball_asleep(a));
}

/// The exact-fit channel of the issue: a ball of radius 0.2 between walls at x = 0 and 0.4,
/// with a small sideways speed, falls at g with a few events.
#[test]
fn a_ball_in_a_channel_exactly_its_diameter_wide_falls_at_g() {
    let g = 9.81;
    let mut world = sleepy(v(0.0, -g));
    for x in [0.0, 0.4] {
        world
            .add_collider(ColliderDesc::segment(v(x, -100.0), v(x, 10.0)).restitution(0.8))
            .unwrap();
    }
    let b = world
        .add_ball(
            BallDesc::new(v(0.2, 5.0), 0.2)
                .velocity(v(0.01, 0.0))
                .restitution(0.8),
        )
        .unwrap();
    let events = run_dissipative(&mut world, 2.0, 20);
    assert!(events.len() <= 6, "{} events", events.len());
    let p = world.ball(b).unwrap().position;
    assert!((p.y - (5.0 - 0.5 * g * 4.0)).abs() < 1e-9, "{p}");
    assert!(p.x >= 0.2 - 1e-9 && p.x <= 0.2 + 1e-9, "{p}");
}

/// A channel a hair wider than the ball (1e-12, above the touching distance at these
/// coordinates, 3e-13), entered late (at t = 1000 s, when the collapse floor is
/// `1000 x 2^-40` s, 9e-10 s): a sideways speed of 1 cm/s crosses the gap in 1e-10 s, inside
/// the collapse floor, where bounces are elastic. With sleeping's rattle rule the first such
/// bounce is resolved as an impact (with the wall's restitution, then held: a contact leaving
/// slower than a ball sleeps rests), the sideways speed is gone at once, and the ball falls
/// freely at `g`; without it the ball bounces elastically across the gap and the rounding of
/// those bounces is left in its fall.
#[test]
fn a_ball_rattling_in_a_gap_a_hair_wider_than_it_falls_at_g() {
    let g = 9.81;
    let mut world = sleepy(v(0.0, -g));
    let hair = 1e-12;
    for x in [0.0, 0.4 + hair] {
        world
            .add_collider(ColliderDesc::segment(v(x, -200.0), v(x, 10.0)).restitution(0.8))
            .unwrap();
    }
    world.advance_to(1000.0).unwrap();
    let b = world
        .add_ball(
            BallDesc::new(v(0.2 + hair / 2.0, 5.0), 0.2)
                .velocity(v(0.01, 0.0))
                .restitution(0.8),
        )
        .unwrap();
    let events = run_dissipative(&mut world, 1002.0, 1000);
    let ball = world.ball(b).unwrap();
    assert!(events.len() <= 2, "{} events", events.len());
    // Free fall from the first bounce on, to the rounding of the parabola.
    assert!(
        (ball.position.y - (5.0 - 0.5 * g * 4.0)).abs() < 1e-12,
        "{ball:?}"
    );
    assert!((ball.velocity.y + 2.0 * g).abs() < 1e-12, "{ball:?}");
    assert_eq!(ball.velocity.x, 0.0, "{ball:?}");
}

/// A push too gentle to matter leaves a sleeper asleep whatever its direction: a ball meeting
/// a sleeping ball of its own mass at normal speed `u` would give it at most `u`; at half the
/// sleep speed (`1e-2 sqrt(g r)`) that is a speed sleeping drops. Here a ball dropped onto the
/// sleeper 30 degrees off its top (a push the floor's cone cannot take: only straight down
/// is) bounces off it as off a static circle, leaving along the normal at `e u` (`e = 0.5`).
/// Dropped from higher, meeting it at twice the sleep speed, it wakes the sleeper.
#[test]
fn a_gentle_push_off_the_cone_leaves_a_sleeper_asleep_and_a_firmer_one_wakes_it() {
    let (g, r): (f64, f64) = (9.81, 0.5);
    let slow = 1e-2 * (g * r).sqrt();
    let angle = 30f64.to_radians();
    let n = v(angle.sin(), angle.cos());
    for (u, wakes) in [(0.5 * slow, false), (2.0 * slow, true)] {
        let mut world = sleepy(v(0.0, -g));
        floor(&mut world, -10.0, 10.0);
        let still = ball(&mut world, v(0.0, r), r, 1.0);
        world.advance_to(0.1).unwrap();
        assert!(world.ball_asleep(still));
        // Falling straight down onto the point of the circle of radius 2r at that angle.
        let w = u / angle.cos();
        let h = w * w / (2.0 * g);
        let contact = v(0.0, r) + n * (2.0 * r);
        let mover = ball(&mut world, contact + v(0.0, h), r, 0.5);
        let meet = 0.1 + w / g;
        let events = run_dissipative(&mut world, meet + 1e-9, 100);
        let Some(Event::BallContact(c)) = events.first() else {
            panic!("{events:?}");
        };
        assert!((c.time - meet).abs() < 1e-9, "{} against {meet}", c.time);
        assert!(
            (c.normal_speed - u).abs() < 1e-9 * slow,
            "{}",
            c.normal_speed
        );
        assert_eq!(world.ball_asleep(still), !wakes, "u = {u}");
        assert_eq!(world.event_counts().wakes, u64::from(wakes), "u = {u}");
        if !wakes {
            let away = world.ball(mover).unwrap().velocity.dot(n);
            assert!(
                (away - 0.5 * u).abs() < 1e-6 * slow,
                "{away} against {}",
                0.5 * u
            );
        }
    }
}

/// The exact-fit cusp of the issue: a wall at x = 0 and a peg of radius 0.1 centred at
/// (0.5, 0), restitution 0.8: a ball of radius 0.2 dropped into the gap passes it or rests
/// in it, in bounded events.
#[test]
fn a_ball_dropped_into_a_cusp_exactly_its_diameter_wide_passes_in_bounded_events() {
    let mut world = sleepy(v(0.0, -9.81));
    world
        .add_collider(ColliderDesc::segment(v(0.0, -10.0), v(0.0, 10.0)).restitution(0.8))
        .unwrap();
    world
        .add_collider(ColliderDesc::circle(v(0.5, 0.0), 0.1).restitution(0.8))
        .unwrap();
    let b = ball(&mut world, v(0.2, 2.0), 0.2, 0.8);
    run_dissipative(&mut world, 3.0, 10_000);
    let p = world.ball(b).unwrap();
    assert!(p.position.y < -5.0 || world.ball_asleep(b), "{p:?}");
}

/// A ball balanced on the top of a ball that slides along a frictionless floor rides it (with
/// sleeping on, the two rest together as a group, `pipeline/group.rs`): both move at the
/// speed they were given, `x(t) = x0 + u t`, the upper one exactly above the lower, costing
/// no more than the few events that start the ride. Without sleeping the upper one hops on
/// the lower one at the micro-hop floor, tens of thousands of times a second.
#[test]
fn a_ball_balanced_on_a_sliding_ball_rides_it_at_no_cost() {
    let (g, r, u) = (9.81, 0.2, 0.5);
    let mut counts = Vec::new();
    for sleeping in [true, false] {
        let mut world = World::with_gravity(v(0.0, -g)).unwrap();
        world.set_sleeping(sleeping);
        floor(&mut world, -10.0, 10.0);
        let bottom = world
            .add_ball(
                BallDesc::new(v(0.0, r), r)
                    .velocity(v(u, 0.0))
                    .restitution(0.5),
            )
            .unwrap();
        let top = world
            .add_ball(
                BallDesc::new(v(0.0, 3.0 * r), r)
                    .velocity(v(u, 0.0))
                    .restitution(0.5),
            )
            .unwrap();
        let t = 2.0;
        let events = run_dissipative(&mut world, t, 1_000_000);
        counts.push(events.len());
        if sleeping {
            for (handle, y) in [(bottom, r), (top, 3.0 * r)] {
                let ball = world.ball(handle).unwrap();
                assert!((ball.position.x - u * t).abs() < 1e-12, "{ball:?}");
                assert!((ball.position.y - y).abs() < 1e-12, "{ball:?}");
                assert!((ball.velocity - v(u, 0.0)).length() < 1e-12, "{ball:?}");
            }
            assert!(events.len() <= 4, "{} events: {events:?}", events.len());
        }
    }
    assert!(counts[1] > 1000, "without sleeping: {} events", counts[1]);
}

/// The next collision of two balls before `until`, the events before it handled.
fn next_ball_contact(world: &mut World, until: f64) -> exact2d::BallContactEvent {
    loop {
        match world.step_until(until).unwrap() {
            Some(Event::BallContact(c)) => break c,
            Some(_) => continue,
            None => panic!("no two balls met before {until}"),
        }
    }
}

/// On a frictionless floor along the x axis, two balls of radius `r` and restitution `e`, one
/// on the other at x = 0, both sliding at `u` along it: (bottom, top).
fn sliding_stack(world: &mut World, r: f64, u: f64, e: f64) -> (BallHandle, BallHandle) {
    floor(world, -100.0, 100.0);
    let mut add = |y: f64| {
        world
            .add_ball(
                BallDesc::new(v(0.0, y), r)
                    .velocity(v(u, 0.0))
                    .restitution(e),
            )
            .unwrap()
    };
    (add(r), add(3.0 * r))
}

/// A stack of two balls sliding on a frictionless floor as a group, struck by a third ball,
/// takes the strike as one body while every contact it keeps pushes (`pipeline/rigid.rs`):
/// - dropped fast onto the top ball from straight above (moving along with the stack), the
///   ball bounces off the stack as off the floor under it, up at the pair's restitution times
///   its speed, and the stack slides on at its speed, exactly where it was, held: the strike
///   is the one rigid hit, and no jam follows;
/// - struck from behind at the top ball's height, across every normal the group keeps, the
///   top ball alone takes the impulse, as in a collision of two free balls.
#[test]
fn a_sliding_stack_takes_a_strike_as_one_body() {
    let (g, r, u, e) = (9.81, 0.2, 0.5, 0.5);
    let stack = |world: &mut World| sliding_stack(world, r, u, e);
    // From above.
    let mut world = sleepy(v(0.0, -g));
    let (bottom, top) = stack(&mut world);
    run_dissipative(&mut world, 0.5, 1000);
    let t0 = world.time();
    let (h, w0) = (1.0, 2.0);
    let striker = world
        .add_ball(
            BallDesc::new(v(u * t0, 5.0 * r + h), r)
                .velocity(v(u, -w0))
                .restitution(e),
        )
        .unwrap();
    let before = world.event_counts();
    // It meets the top ball after falling `h`: w0 t + g t^2 / 2 = h.
    let fall = 2.0 * h / (w0 + (w0 * w0 + 2.0 * g * h).sqrt());
    let w = w0 + g * fall;
    let event = next_ball_contact(&mut world, t0 + 1.0);
    assert!((event.time - (t0 + fall)).abs() < 1e-12, "{event:?}");
    let after = world.event_counts();
    assert_eq!(after.rigid_hits, before.rigid_hits + 1, "{after:?}");
    assert_eq!(after.jams, before.jams, "{after:?}");
    let bounced = world.ball(striker).unwrap().velocity;
    assert!(
        (bounced - v(u, e * e * w)).length() < 1e-12,
        "{bounced} against {}",
        e * e * w
    );
    // The stack slides on, held, exactly as before the strike.
    let t1 = event.time + 0.05;
    world.advance_to(t1).unwrap();
    for (handle, y) in [(bottom, r), (top, 3.0 * r)] {
        let ball = world.ball(handle).unwrap();
        assert!((ball.position - v(u * t1, y)).length() < 1e-12, "{ball:?}");
        assert!((ball.velocity - v(u, 0.0)).length() < 1e-12, "{ball:?}");
    }
    assert_eq!(world.event_counts().jams, before.jams);

    // From behind, level with the top ball, at `s` faster than the stack.
    let mut world = sleepy(v(0.0, -g));
    let (_, top) = stack(&mut world);
    run_dissipative(&mut world, 0.5, 1000);
    let t0 = world.time();
    let (gap, s) = (0.3, 1.5);
    let striker = world
        .add_ball(
            BallDesc::new(v(u * t0 - 2.0 * r - gap, 3.0 * r), r)
                .velocity(v(u + s, 0.5 * g * gap / s))
                .restitution(e)
                .mass(2.0),
        )
        .unwrap();
    let before = world.event_counts();
    let event = next_ball_contact(&mut world, t0 + 1.0);
    // Level with the top ball when they meet: its rise and fall over `gap / s` cancel.
    assert!((event.time - (t0 + gap / s)).abs() < 1e-9, "{event:?}");
    assert!(event.normal.y.abs() < 1e-9, "{event:?}");
    assert_eq!(world.event_counts().rigid_hits, before.rigid_hits + 1);
    // The top ball (mass 1) and the striker (mass 2) as two free balls: the top ball leaves
    // at (1 + e^2) 2 s / 3 faster than before, the striker at (2 - e^2) s / 3.
    let hit = world.ball(top).unwrap().velocity;
    assert!(
        (hit.x - (u + (1.0 + e * e) * 2.0 * s / 3.0)).abs() < 1e-9,
        "{hit}"
    );
    let struck = world.ball(striker).unwrap().velocity;
    assert!(
        (struck.x - (u + (2.0 - e * e) * s / 3.0)).abs() < 1e-9,
        "{struck}"
    );
}

/// A stack of two balls sliding on a frictionless floor as a group, struck on its top ball
/// from a little below the top ball's centre (contact normal `theta` above the horizontal),
/// would have the top ball part from the bottom one at `J' sin(theta) / m` in the impact
/// itself (`J'` the impulse of a free collision), pulled by nothing but the strike
/// (`pipeline/rigid.rs`):
/// - at `theta = 0.005` that parting, 6e-3 m/s, is slower than the contact rests at (the sleep
///   speed, 1.4e-2 m/s here): the group takes the strike whole, the top ball held on the
///   bottom one. The answer is the impact with the kept contacts held: the top ball moves
///   on level, taking `J cos(theta)` of the impulse, `J = (1 + e^2) w / (cos^2(theta) / m_t +
///   1 / m_s)` for an approach `w`; the striker takes `J` along the normal; the top ball
///   slides on level over the bottom one, which slides on as before, and no jam follows;
/// - at `theta = 0.05` (a parting of 6e-2 m/s) the group lets go, and the two balls collide
///   as free ones.
#[test]
fn a_stack_struck_from_a_little_below_holds_if_it_would_part_slower_than_it_rests() {
    let (g, r, u, e) = (9.81, 0.2, 0.5, 0.5);
    let (gap, s, m_s) = (0.3, 1.5, 2.0);
    for (theta, holds) in [(0.005_f64, true), (0.05, false)] {
        let mut world = sleepy(v(0.0, -g));
        let (bottom, top) = sliding_stack(&mut world, r, u, e);
        run_dissipative(&mut world, 0.5, 1000);
        let t0 = world.time();
        // Launched on an arc that comes back to its height `gap / s` later, touching the top
        // ball along `n = (cos(theta), sin(theta))` then.
        let n = v(theta.cos(), theta.sin());
        let lift = 0.5 * g * gap / s;
        let striker = world
            .add_ball(
                BallDesc::new(v(u * t0, 3.0 * r) - n * (2.0 * r) - v(gap, 0.0), r)
                    .velocity(v(u + s, lift))
                    .restitution(e)
                    .mass(m_s),
            )
            .unwrap();
        let before = world.event_counts();
        let event = next_ball_contact(&mut world, t0 + 1.0);
        assert!((event.time - (t0 + gap / s)).abs() < 1e-9, "{event:?}");
        let normal = if event.a == striker {
            event.normal
        } else {
            -event.normal
        };
        assert!((normal - n).length() < 1e-9, "{event:?}");
        let after = world.event_counts();
        // The approach along `n`: the striker at `(u + s, -lift)`, the top ball at `(u, 0)`.
        let w = s * n.x - lift * n.y;
        let top_v = world.ball(top).unwrap().velocity;
        let striker_v = world.ball(striker).unwrap().velocity;
        if holds {
            assert_eq!(after.rigid_hits, before.rigid_hits + 1, "{after:?}");
            assert_eq!(after.jams, before.jams, "{after:?}");
            let j = (1.0 + e * e) * w / (n.x * n.x + 1.0 / m_s);
            assert!((top_v - v(u + j * n.x, 0.0)).length() < 1e-9, "{top_v}");
            let expected = v(u + s, -lift) - n * (j / m_s);
            assert!(
                (striker_v - expected).length() < 1e-9,
                "{striker_v} against {expected}"
            );
            // The top ball slides over the bottom one, held level on it (until it has slid
            // 0.018 across it, as far as `GROUP_GAP` lets a group hold), and the bottom one
            // slides on as before.
            let t1 = event.time + 0.005;
            let x_top = world.ball(top).unwrap().position.x;
            world.advance_to(t1).unwrap();
            let (b, t) = (world.ball(bottom).unwrap(), world.ball(top).unwrap());
            assert!((b.position - v(u * t1, r)).length() < 1e-12, "{b:?}");
            assert!((b.velocity - v(u, 0.0)).length() < 1e-12, "{b:?}");
            assert!((t.position.y - 3.0 * r).abs() < 1e-12, "{t:?}");
            assert!(
                (t.position.x - (x_top + (u + j * n.x) * (t1 - event.time))).abs() < 1e-9,
                "{t:?}"
            );
            assert_eq!(world.event_counts().jams, before.jams);
        } else {
            assert_eq!(after.rigid_hits, before.rigid_hits, "{after:?}");
            // Two free balls: `J' = (1 + e^2) w / (1 / m_t + 1 / m_s)` along `n`.
            let j = (1.0 + e * e) * w / (1.0 + 1.0 / m_s);
            let expected = v(u, 0.0) + n * j;
            assert!(
                (top_v - expected).length() < 1e-9,
                "{top_v} against {expected}"
            );
            assert!(j * n.y > 0.05, "parting at {}", j * n.y);
        }
    }
}

/// Balls poured into a narrow box (five diameters wide) come to rest with sleeping on: every
/// ball asleep after a finite simulated time, then nothing at all for 1000 s; on the way no
/// overlap past 1e-9 of a contact distance, nothing out of the box, the energy never above
/// its start.
#[test]
fn balls_poured_into_a_box_all_fall_asleep_and_then_cost_nothing() {
    let (g, r, width) = (9.81, 0.2, 2.0);
    let mut world = sleepy(v(0.0, -g));
    common::add_polygon_of(&mut world, &common::rectangle(width, 20.0), 0.7);
    // Three staggered rows of four, a little apart, dropped from rest.
    for row in 0..3 {
        for col in 0..4 {
            let x = 0.3 + 0.45 * col as f64 + if row % 2 == 1 { 0.15 } else { 0.0 };
            let y = 0.6 + 0.5 * row as f64 + 0.01 * col as f64;
            ball(&mut world, v(x, y), r, 0.5);
        }
    }
    let mut t = 0.0;
    while !asleep_all(&world) {
        t += 0.25;
        assert!(
            t <= 30.0,
            "not at rest by t = 30: {} asleep",
            world.sleeping_count()
        );
        run_dissipative(&mut world, t, 2_000_000);
        for (_, b) in world.balls() {
            let p = b.position;
            assert!(p.x > 0.0 && p.x < width && p.y > 0.0 && p.y < 20.0, "{b:?}");
        }
    }
    assert_eq!(world.sleeping_count(), 12);
    let before = world.event_counts().collisions();
    assert_eq!(world.advance_to(world.time() + 1000.0).unwrap(), 0);
    assert_eq!(world.event_counts().collisions(), before);
}
