//! The minimal gas (`exact2d_bench::minimal`) checked against independent references: energy
//! conservation, no overlap and no escape (brute force over every pair), and the engine's own
//! sequence of collisions.

use exact2d::Event;
use exact2d::scene::Scene;
use exact2d_bench::minimal::MinimalGas;
use exact2d_bench::scenes;

fn kinetic(gas: &MinimalGas) -> f64 {
    gas.state()
        .iter()
        .map(|(_, [vx, vy])| 0.5 * (vx * vx + vy * vy))
        .sum()
}

#[test]
fn energy_is_conserved_and_no_disk_overlaps_or_escapes() {
    for packing in [0.4, 0.7] {
        let mut gas = MinimalGas::new(&scenes::gas(300, packing, 7)).expect("a gas");
        let (radius, side) = gas.geometry();
        let e0 = kinetic(&gas);
        let mut worst_overlap: f64 = 0.0;
        let mut worst_escape: f64 = f64::NEG_INFINITY;
        for chunk in 1..=100 {
            gas.run(chunk * 1_000, |_, _| {});
            let state = gas.state();
            for (k, ([x, y], _)) in state.iter().enumerate() {
                worst_escape = worst_escape
                    .max(radius - x.min(*y))
                    .max(x.max(*y) - (side - radius));
                for ([u, v], _) in &state[k + 1..] {
                    let d = ((u - x).powi(2) + (v - y).powi(2)).sqrt();
                    worst_overlap = worst_overlap.max(2.0 * radius - d);
                }
            }
        }
        assert_eq!(gas.collisions(), 100_000);
        let drift = ((kinetic(&gas) - e0) / e0).abs();
        assert!(drift < 1e-12, "packing {packing}: energy drift {drift:e}");
        assert!(
            worst_overlap < 1e-9 * radius,
            "packing {packing}: overlap {worst_overlap:e}"
        );
        assert!(
            worst_escape < 1e-9 * radius,
            "packing {packing}: a centre {worst_escape:e} beyond its reach of a wall"
        );
    }
}

/// The collisions compared. The two codes round differently (the minimal one solves in plain
/// doubles from each disk's own clock), and a gas is chaotic: on this scene the pairs agree
/// for the first 1 177 collisions, then part.
const AGREE: usize = 500;

/// Asserts that the first [`AGREE`] ball-ball collisions of `scene` are the same pairs in the
/// engine and in the minimal gas.
fn assert_first_collisions_agree(scene: &Scene) {
    let mut built = scene.build_world().expect("the gas builds");
    let mut engine = Vec::new();
    while engine.len() < AGREE {
        let event = built
            .world_mut()
            .step()
            .expect("a gas never runs out of events");
        if let Event::BallContact(c) = event {
            let index = |h| built.ball_index(h).expect("a ball of the scene") as u32;
            let (a, b) = (index(c.a), index(c.b));
            engine.push((a.min(b), a.max(b)));
        }
    }
    let mut gas = MinimalGas::new(scene).expect("a gas");
    let mut minimal = Vec::new();
    while minimal.len() < AGREE {
        let more = gas.collisions() + 1;
        gas.run(more, |a, b| minimal.push((a, b)));
    }
    assert_eq!(minimal[..AGREE], engine[..]);
}

#[test]
fn its_first_collisions_are_the_engines() {
    assert_first_collisions_agree(&scenes::gas(100, 0.4, 3));
}

#[test]
fn scenes_it_cannot_run_are_refused_with_a_reason() {
    let mut scene = scenes::gas(100, 0.4, 3);
    scene.gravity = [0.0, -1.0];
    let error = MinimalGas::new(&scene).err().expect("gravity is refused");
    assert!(error.contains("gravity"), "{error}");
    let mut scene = scenes::gas(100, 0.4, 3);
    scene.balls[5].radius *= 0.5;
    let error = MinimalGas::new(&scene)
        .err()
        .expect("unequal radii are refused");
    assert!(error.contains("radii"), "{error}");
    let mut scene = scenes::periodic_gas(100, 0.4, 3);
    scene.periodic = Some([40.0, 41.0]);
    let error = MinimalGas::new(&scene)
        .err()
        .expect("a periodic box that is not square is refused");
    assert!(error.contains("not square"), "{error}");
    let scene = scenes::brick_board(10, 1);
    let error = MinimalGas::new(&scene)
        .err()
        .expect("a brick board is refused");
    assert!(error.contains("hard-disk gas"), "{error}");
    let mut scene = scenes::gas(100, 0.4, 3);
    scene.balls[1].pos = scene.balls[0].pos;
    scene.balls[1].pos[0] += 0.1 * scene.balls[0].radius;
    let error = MinimalGas::new(&scene)
        .err()
        .expect("overlapping balls are refused");
    assert!(error.contains("overlap"), "{error}");
    let mut scene = scenes::gas(100, 0.4, 3);
    scene.balls[0].pos = [-1.0, 1.0];
    let error = MinimalGas::new(&scene)
        .err()
        .expect("a ball outside is refused");
    assert!(error.contains("outside"), "{error}");
}

/// The distance of two points of the periodic square of side `side` through their nearest
/// images.
fn torus_distance([x, y]: [f64; 2], [u, v]: [f64; 2], side: f64) -> f64 {
    let fold = |d: f64| d - (d / side).round() * side;
    (fold(u - x).powi(2) + fold(v - y).powi(2)).sqrt()
}

#[test]
fn in_a_periodic_box_energy_and_momentum_are_kept_and_no_pair_overlaps_through_an_edge() {
    for packing in [0.4, 0.7] {
        let mut gas = MinimalGas::new(&scenes::periodic_gas(300, packing, 7)).expect("a gas");
        let (radius, side) = gas.geometry();
        let momentum = |gas: &MinimalGas| {
            gas.state()
                .iter()
                .fold([0.0, 0.0], |[px, py], (_, [vx, vy])| [px + vx, py + vy])
        };
        let (e0, p0) = (kinetic(&gas), momentum(&gas));
        let mut worst_overlap: f64 = 0.0;
        for chunk in 1..=100 {
            gas.run(chunk * 1_000, |_, _| {});
            let state = gas.state();
            for (k, (p, _)) in state.iter().enumerate() {
                for (q, _) in &state[k + 1..] {
                    worst_overlap = worst_overlap.max(2.0 * radius - torus_distance(*p, *q, side));
                }
            }
        }
        assert_eq!(gas.collisions(), 100_000);
        let drift = ((kinetic(&gas) - e0) / e0).abs();
        assert!(drift < 1e-12, "packing {packing}: energy drift {drift:e}");
        let p = momentum(&gas);
        let speed = (2.0 * e0 / 300.0).sqrt();
        assert!(
            (p[0] - p0[0]).abs().max((p[1] - p0[1]).abs()) < 1e-9 * speed,
            "packing {packing}: momentum {p:?} from {p0:?}"
        );
        assert!(
            worst_overlap < 1e-9 * radius,
            "packing {packing}: overlap {worst_overlap:e}"
        );
    }
}

#[test]
fn in_a_periodic_box_its_first_collisions_are_the_engines() {
    assert_first_collisions_agree(&scenes::periodic_gas(100, 0.4, 3));
}
