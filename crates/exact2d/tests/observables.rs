//! The observables (`World::observables`, `World::collider_momentum`,
//! `World::collider_impacts`) against answers found without them: counted from the geometry,
//! the textbook impulse, momentum bookkeeping, and the virial identity of a closed box.

mod common;

use common::{SplitMix, v};
use exact2d::{BallDesc, ColliderDesc, ColliderHandle, DVec2, World};

/// `G = sum_i m_i p_i . v_i`, the quantity whose rate is `2 K` plus the virial of the forces.
fn g_of(world: &World) -> f64 {
    world
        .balls()
        .map(|(_, b)| b.mass * b.position.dot(b.velocity))
        .sum()
}

fn kinetic(world: &World) -> f64 {
    world
        .balls()
        .map(|(_, b)| 0.5 * b.mass * b.velocity.length_squared())
        .sum()
}

fn momentum(world: &World) -> DVec2 {
    world.balls().map(|(_, b)| b.velocity * b.mass).sum()
}

/// A ball bouncing between two parallel elastic walls gives each wall `2 m v` per impact, and
/// hits each as often as the geometry says: walls at x = 0 and x = 10, a ball of radius 0.5
/// and mass 2.5 starting at x = 5 with `v = (4, 0.25)`. Its centre runs between 0.5 and 9.5,
/// so it meets the right wall at 1.125 s and every 4.5 s after, the left one 2.25 s after
/// each: by t = 100, 22 impacts each. Every number is a dyadic rational: the sums are exact.
#[test]
fn a_ball_between_two_walls_gives_each_wall_2mv_per_impact() {
    let mut world = World::new();
    let left = world
        .add_collider(ColliderDesc::segment(v(0.0, -100.0), v(0.0, 100.0)))
        .unwrap();
    let right = world
        .add_collider(ColliderDesc::segment(v(10.0, -100.0), v(10.0, 100.0)))
        .unwrap();
    world
        .add_ball(
            BallDesc::new(v(5.0, 0.0), 0.5)
                .velocity(v(4.0, 0.25))
                .mass(2.5),
        )
        .unwrap();
    let until = 100.0;
    world.advance_to(until).unwrap();
    let (first, period, across) = (1.125, 4.5, 2.25);
    let count = |start: f64| ((until - start) / period).floor() as u64 + 1;
    let (n_right, n_left) = (count(first), count(first + across));
    assert_eq!((n_right, n_left), (22, 22));
    assert_eq!(world.collider_impacts(right), Some(n_right));
    assert_eq!(world.collider_impacts(left), Some(n_left));
    let two_m_v = 2.0 * 2.5 * 4.0;
    assert_eq!(
        world.collider_momentum(right),
        Some(v(two_m_v * n_right as f64, 0.0))
    );
    assert_eq!(
        world.collider_momentum(left),
        Some(v(-two_m_v * n_left as f64, 0.0))
    );
    assert_eq!(world.observables().collision_virial(), 0.0);
    assert_eq!(world.observables().since(), 0.0);
    assert_eq!(
        world.event_counts().contacts,
        n_left + n_right,
        "every impact counted once"
    );
}

/// Two balls head on, unequal masses, restitution `e`: the virial is the contact distance
/// times the textbook impulse `(1 + e) m1 m2 / (m1 + m2) u`.
#[test]
fn two_balls_head_on_add_the_contact_distance_times_the_textbook_impulse() {
    let (m1, m2, e) = (1.0, 3.0, 0.8);
    let (r1, r2) = (0.5, 0.25);
    let (u1, u2) = (2.0, -1.0);
    let mut world = World::new();
    world
        .add_ball(
            BallDesc::new(v(0.0, 1.0), r1)
                .velocity(v(u1, 0.0))
                .mass(m1)
                .restitution(e),
        )
        .unwrap();
    world
        .add_ball(BallDesc::new(v(3.0, 1.0), r2).velocity(v(u2, 0.0)).mass(m2))
        .unwrap();
    let event = world.step().expect("they meet");
    assert_eq!(world.step(), None, "one collision only");
    let u = u1 - u2;
    let impulse = (1.0 + e) * m1 * m2 / (m1 + m2) * u;
    let expected = (r1 + r2) * impulse;
    let virial = world.observables().collision_virial();
    assert!(
        (virial - expected).abs() <= 1e-14 * expected,
        "{virial} against {expected} ({event:?})"
    );
}

/// A jam: a heavy inelastic ball drives a row of two light ones touching each other and a
/// wall. In sequence the light balls would rattle between the wall and the heavy one for ever;
/// the chain comes back to a contact and the touching cluster is resolved as one impact. The
/// virial is then, from momentum bookkeeping along the line (every impulse is along x), the
/// contact distance times the impulse each ball pushes its right-hand neighbour with: the
/// striker's change of momentum for the contact it struck, that plus the middle ball's for the
/// next; the wall takes the rest. The chain's responses before the jam are taken back (the jam
/// starts again from the velocities before the chain), or they would count twice.
#[test]
fn a_jam_adds_each_contact_row_s_impulse_from_momentum_bookkeeping() {
    for (heavy, e) in [(10.0, 0.5), (4.0, 0.0), (100.0, 0.25)] {
        let mut world = World::new();
        let wall = world
            .add_collider(ColliderDesc::segment(v(0.0, -5.0), v(0.0, 5.0)))
            .unwrap();
        // From the wall: a at x = 0.5, b at 1.5 (touching a), the striker coming from the right.
        let r = 0.5;
        let ball = |world: &mut World, x: f64, vx: f64, m: f64| {
            world
                .add_ball(
                    BallDesc::new(v(x, 0.0), r)
                        .velocity(v(vx, 0.0))
                        .mass(m)
                        .restitution(e),
                )
                .unwrap()
        };
        let a = ball(&mut world, 0.5, 0.0, 1.0);
        let b = ball(&mut world, 1.5, 0.0, 0.5);
        let striker = ball(&mut world, 4.0, -1.0, heavy);
        let before: Vec<DVec2> = [a, b, striker]
            .iter()
            .map(|&h| world.ball(h).unwrap().velocity)
            .collect();
        world.advance_to(3.0).unwrap();
        assert!(world.event_counts().jams >= 1, "{:?}", world.event_counts());
        let after: Vec<DVec2> = [a, b, striker]
            .iter()
            .map(|&h| world.ball(h).unwrap().velocity)
            .collect();
        let change = |k: usize, m: f64| m * (after[k] - before[k]).x;
        // Impulses along +x on the right-hand ball of each contact.
        let on_striker = change(2, heavy);
        let on_b = change(1, 0.5) + on_striker;
        let on_a_from_wall = change(0, 1.0) + on_b;
        let reach = 2.0 * r;
        let expected = reach * (on_striker + on_b);
        let virial = world.observables().collision_virial();
        let scale = reach * (on_striker.abs() + on_b.abs());
        assert!(
            (virial - expected).abs() <= 1e-12 * scale,
            "heavy {heavy}, e {e}: virial {virial} against {expected} ({before:?} -> {after:?})"
        );
        let given = world.collider_momentum(wall).unwrap();
        assert!(
            (given - v(-on_a_from_wall, 0.0)).length() <= 1e-12 * on_a_from_wall.abs(),
            "{given:?} against {}",
            -on_a_from_wall
        );
        assert!(on_b > 0.0 && on_striker > 0.0 && on_a_from_wall > 0.0);
    }
}

/// The walls of the box `[0, width] x [0, height]` (bottom, right, top, left), and where a
/// ball's centre is along each wall's normal when it touches it (`r` or the far side less
/// `r`): `sum over impacts of p . J` is that times the impulses' normal part, which is minus
/// the wall's momentum along its normal axis.
fn wall_term(
    world: &World,
    walls: &[ColliderHandle; 4],
    (width, height, r): (f64, f64, f64),
) -> f64 {
    let m = walls.map(|w| world.collider_momentum(w).unwrap());
    -(r * m[0].y + (width - r) * m[1].x + (height - r) * m[2].y + r * m[3].x)
}

/// A gas of `n` balls of radius `r` in the box `[0, size]^2`, restitution `e` (each ball's;
/// a pair's is the product, a wall's `e` too), velocities up to 1 along each axis.
fn boxed_gas(n: usize, size: f64, r: f64, e: f64, seed: u64) -> (World, [ColliderHandle; 4]) {
    let mut world = World::new();
    let corners = common::rectangle(size, size);
    let walls = [0, 1, 2, 3].map(|k| {
        world
            .add_collider(ColliderDesc::segment(corners[k], corners[(k + 1) % 4]))
            .unwrap()
    });
    let mut rng = SplitMix(seed);
    let mut placed = 0;
    while placed < n {
        let p = v(rng.range(r, size - r), rng.range(r, size - r));
        let vel = v(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0));
        let mass = rng.range(0.5, 2.0);
        if world
            .add_ball(BallDesc::new(p, r).velocity(vel).mass(mass).restitution(e))
            .is_ok()
        {
            placed += 1;
        }
    }
    (world, walls)
}

/// Runs `events` events from now, event by event, and checks the virial identity of a
/// closed box without gravity,
/// `G(t1) - G(t0) = int 2 K dt + W + sum over wall impacts of p . J`,
/// `K` constant between events (summed interval by interval), `W` the collision virial, the
/// wall term from each wall's momentum ([`wall_term`]); and that momentum is conserved: the
/// balls' plus what the walls took. Returns the jams seen.
fn check_the_virial_identity(
    world: &mut World,
    walls: &[ColliderHandle; 4],
    (size, r): (f64, f64),
    events: usize,
    what: &str,
) -> u64 {
    world.reset_observables();
    let (g0, t0, p0) = (g_of(world), world.exact_time(), momentum(world));
    let jams0 = world.event_counts().jams;
    let mut integral = 0.0;
    let (mut last, mut k) = (world.exact_time(), kinetic(world));
    for _ in 0..events {
        world
            .step()
            .expect("a gas in a box never runs out of events");
        let now = world.exact_time();
        integral += 2.0 * k * now.since(last);
        (last, k) = (now, kinetic(world));
    }
    let g1 = g_of(world);
    let w = world.observables().collision_virial();
    let walls_term = wall_term(world, walls, (size, size, r));
    assert_eq!(world.observables().exact_since(), t0);
    let lhs = g1 - g0;
    let rhs = integral + w + walls_term;
    let scale = integral.abs() + w.abs() + walls_term.abs();
    assert!(
        (lhs - rhs).abs() <= 1e-9 * scale,
        "{what}: G rose by {lhs:e}, the identity says {rhs:e} (2 int K dt {integral:e}, W {w:e}, \
         walls {walls_term:e}): off by {:e} of {scale:e}",
        (lhs - rhs).abs() / scale
    );
    assert!(w > 0.0, "{what}: balls push each other apart: {w}");
    let given: DVec2 = walls
        .iter()
        .map(|&h| world.collider_momentum(h).unwrap())
        .sum();
    let total = momentum(world) + given - p0;
    let swept = walls
        .iter()
        .map(|&h| world.collider_momentum(h).unwrap().length())
        .sum::<f64>();
    assert!(
        total.length() <= 1e-11 * swept,
        "{what}: momentum changed by {total:?} (walls took {swept:e} in all)"
    );
    world.event_counts().jams - jams0
}

/// The exact virial identity in a closed box, elastic: 200 balls, `2 K (t1 - t0)` with `K`
/// constant, after 10^4 events of equilibration and over 4 x 10^4 more. Any impulse left out
/// (or counted twice) breaks it by that impulse times a distance of the box's order.
#[test]
fn the_virial_identity_holds_in_an_elastic_box() {
    let (size, r) = (40.0, 0.5);
    let (mut world, walls) = boxed_gas(200, size, r, 1.0, 11);
    for _ in 0..10_000 {
        world.step().unwrap();
    }
    check_the_virial_identity(&mut world, &walls, (size, r), 40_000, "elastic");
}

/// The same identity with restitution 0.9 (walls 0.9 too), `2 int K dt` summed interval by
/// interval; and, in a denser gas at 0.5 without the TC model, through its jams (clusters that
/// collapse are resolved as simultaneous impacts, and the chains' responses before each are
/// taken back).
#[test]
fn the_virial_identity_holds_in_an_inelastic_box_through_its_jams() {
    let (size, r) = (40.0, 0.5);
    let (mut world, walls) = boxed_gas(200, size, r, 0.9, 12);
    check_the_virial_identity(&mut world, &walls, (size, r), 30_000, "e = 0.9");
    // The cooling gas of `tests/collapse.rs`: it jams.
    let (size, r) = (12.0, 0.35);
    let (mut world, walls) = boxed_gas(150, size, r, 0.5, 7);
    let mut jams = 0;
    for round in 0..8 {
        jams += check_the_virial_identity(
            &mut world,
            &walls,
            (size, r),
            10_000,
            &format!("e = 0.5, round {round}"),
        );
    }
    assert!(jams >= 10, "only {jams} jams");
}

/// Rough disks in a box: friction at the walls and between balls. The walls' momentum,
/// friction included, is what the balls lost: total momentum is conserved.
#[test]
fn friction_at_the_walls_is_in_their_momentum() {
    let size = 20.0;
    let mut world = World::new();
    let corners = common::rectangle(size, size);
    let walls = [0, 1, 2, 3].map(|k| {
        world
            .add_collider(
                ColliderDesc::segment(corners[k], corners[(k + 1) % 4])
                    .friction(0.4)
                    .tangential_restitution(0.2),
            )
            .unwrap()
    });
    let mut rng = SplitMix(5);
    let mut placed = 0;
    while placed < 60 {
        let p = v(rng.range(1.0, size - 1.0), rng.range(1.0, size - 1.0));
        let desc = BallDesc::new(p, 0.5)
            .velocity(v(rng.range(-2.0, 2.0), rng.range(-2.0, 2.0)))
            .spin(rng.range(-5.0, 5.0))
            .friction(0.3)
            .tangential_restitution(-0.5)
            .restitution(0.95);
        if world.add_ball(desc).is_ok() {
            placed += 1;
        }
    }
    let p0 = momentum(&world);
    for _ in 0..5_000 {
        world.step().unwrap();
    }
    let taken: Vec<DVec2> = walls
        .iter()
        .map(|&h| world.collider_momentum(h).unwrap())
        .collect();
    let total = momentum(&world) + taken.iter().copied().sum::<DVec2>() - p0;
    let swept: f64 = taken.iter().map(|m| m.length()).sum();
    assert!(total.length() <= 1e-11 * swept, "{total:?} of {swept}");
    // The bottom wall took momentum along x too: friction.
    assert!(taken[0].x.abs() > 1e-3 * taken[0].y.abs(), "{taken:?}");
    assert!(world.observables().collision_virial() > 0.0);
}

/// A pile under gravity, sleeping on: the identity does not hold (the forces of resting
/// contact are excluded), but nothing panics, every number is finite, and the floor has taken
/// impacts and momentum downwards. (The virial's sign is not asked: a jam's projection in a
/// thin wedge, a row of balls between two sleeping balls 1e-12 radians off one line, gives
/// its resting contacts impulses of the velocities' rounding over that angle, +-1.07e10 in
/// this pile, ARCHITECTURE.md, "Observables".)
#[test]
fn a_pile_under_gravity_gives_finite_observables() {
    let mut world = World::with_gravity(v(0.0, -9.81)).unwrap();
    world.set_sleeping(true);
    let corners = common::rectangle(6.0, 40.0);
    let walls = [0, 1, 3].map(|k| {
        world
            .add_collider(ColliderDesc::segment(corners[k], corners[(k + 1) % 4]))
            .unwrap()
    });
    let mut rng = SplitMix(3);
    let mut placed = 0;
    while placed < 60 {
        let p = v(rng.range(0.3, 5.7), rng.range(0.3, 30.0));
        let desc = BallDesc::new(p, 0.25)
            .velocity(v(rng.range(-1.0, 1.0), 0.0))
            .restitution(0.5);
        if world.add_ball(desc).is_ok() {
            placed += 1;
        }
    }
    world.advance_to(6.0).unwrap();
    let counts = world.event_counts();
    assert!(counts.jams > 0 && counts.settles > 0, "{counts:?}");
    let w = world.observables().collision_virial();
    assert!(w.is_finite(), "{w}");
    for &h in &walls {
        assert!(world.collider_momentum(h).unwrap().is_finite());
    }
    let floor = world.collider_momentum(walls[0]).unwrap();
    assert!(floor.y < 0.0, "{floor:?}");
    assert!(world.collider_impacts(walls[0]).unwrap() > 0);
}

/// `reset_observables` zeroes the accumulators and records when they start; a removed
/// collider has no record, and a new one starts at zero.
#[test]
fn resetting_zeroes_the_observables_and_records_since_when() {
    let (size, r) = (10.0, 0.5);
    let (mut world, walls) = boxed_gas(20, size, r, 1.0, 1);
    world.advance_to(5.0).unwrap();
    assert!(world.observables().collision_virial() > 0.0);
    assert!(world.collider_impacts(walls[0]).unwrap() > 0);
    let events = world.event_counts();
    world.reset_observables();
    assert_eq!(world.observables().collision_virial(), 0.0);
    assert_eq!(world.observables().since(), 5.0);
    for &h in &walls {
        assert_eq!(world.collider_momentum(h), Some(DVec2::ZERO));
        assert_eq!(world.collider_impacts(h), Some(0));
    }
    assert_eq!(
        world.event_counts(),
        events,
        "the counts are not observables"
    );
    world.advance_to(8.0).unwrap();
    let impacts: u64 = walls
        .iter()
        .map(|&h| world.collider_impacts(h).unwrap())
        .sum();
    assert_eq!(impacts, world.event_counts().contacts - events.contacts);
    // Removed: no record; a new collider starts at zero.
    world.remove_collider(walls[2]).unwrap();
    assert_eq!(world.collider_momentum(walls[2]), None);
    assert_eq!(world.collider_impacts(walls[2]), None);
    let lid = world
        .add_collider(ColliderDesc::segment(v(size, size), v(0.0, size)))
        .unwrap();
    assert_eq!(world.collider_momentum(lid), Some(DVec2::ZERO));
    assert_eq!(world.collider_impacts(lid), Some(0));
    world.advance_to(12.0).unwrap();
    assert!(world.collider_impacts(lid).unwrap() > 0);
}

/// Watching changes nothing: a world whose observables are reset at every event has the same
/// events, bit for bit, as one left alone.
#[test]
fn resetting_the_observables_changes_no_event() {
    let run = |reset: bool| {
        let (mut world, _) = boxed_gas(100, 30.0, 0.5, 0.7, 9);
        let mut events = Vec::new();
        for _ in 0..5_000 {
            events.push(world.step().unwrap());
            if reset {
                world.reset_observables();
            }
        }
        events
    };
    assert_eq!(run(false), run(true));
}

/// The 16-ball break on a table (`examples/pool_break.json`): the cloth's friction is
/// continuous and excluded, so momentum is not conserved here, but every cushion takes
/// momentum outwards only (each pushes balls back onto the table; friction at an impact acts
/// along it), its impacts are the contact events, and the balls push each other apart.
#[cfg(feature = "scene")]
#[test]
fn the_cushions_of_a_pool_break_take_momentum_outwards() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/pool_break.json"
    );
    let scene =
        exact2d::scene::Scene::from_json_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    let mut built = scene.build_world().unwrap();
    let world = built.world_mut();
    while world.step().is_some() {}
    let centre = v(2.54 / 2.0, 1.27 / 2.0);
    let mut impacts = 0;
    for (handle, collider) in world.colliders() {
        let exact2d::Shape::Segment(s) = collider.shape else {
            continue;
        };
        let outwards = (0.5 * (s.a() + s.b()) - centre).normalize();
        let given = world.collider_momentum(handle).unwrap();
        assert!(given.is_finite(), "{given:?}");
        assert!(given.dot(outwards) >= 0.0, "{given:?} against {outwards:?}");
        impacts += world.collider_impacts(handle).unwrap();
    }
    assert!(impacts > 0);
    assert_eq!(impacts, world.event_counts().contacts);
    let w = world.observables().collision_virial();
    assert!(w.is_finite() && w > 0.0, "{w}");
}
