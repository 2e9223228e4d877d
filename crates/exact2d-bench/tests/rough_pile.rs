//! A poured pile of rough balls comes to rest in static equilibrium with friction, checked apart
//! from the engine (`exact2d_bench::balance`), never gaining energy on the way.

use exact2d_bench::balance::out_of_balance;
use exact2d_bench::scenes;

/// Poured piles of 40 balls (friction 0.5, restitution 0.5 and 0.8) in the 10 x 30 box:
/// every ball asleep within 20 simulated seconds, the pile then in balance with its friction
/// to rounding (where without friction most poured piles rest out of balance), the energy
/// (kinetic and potential) never above where it was a step before, no two balls deeper into
/// each other than the engine's bound.
#[test]
fn a_poured_rough_pile_rests_in_balance_with_its_friction() {
    for (e, seed) in [(0.5, 1), (0.8, 2)] {
        let mut scene = scenes::pile(40, e, false, seed);
        scenes::roughen(&mut scene, 0.5);
        let mut world = scene.build_world().expect("scene").into_world();
        let g = world.gravity();
        let energy = |world: &exact2d::World| -> f64 {
            world
                .balls()
                .map(|(_, b)| b.kinetic_energy() - b.mass * g.dot(b.position))
                .sum()
        };
        let scale: f64 = world.balls().map(|(_, b)| b.mass * g.length() * 30.0).sum();
        let mut last = energy(&world);
        let mut t = 0.0;
        while world.balls().any(|(h, _)| !world.ball_asleep(h)) {
            assert!(t < 20.0, "e = {e}: not at rest at t = {t}");
            t += 0.1;
            world.advance_to(t).expect("advance");
            let now = energy(&world);
            assert!(
                now <= last + 1e-9 * scale,
                "e = {e}: energy {last} -> {now} at t = {t}"
            );
            last = now;
        }
        let (worst, _) = out_of_balance(&world);
        assert!(worst < 1e-9, "e = {e}: {worst} of a weight out of balance");
        let balls: Vec<_> = world.balls().map(|(_, b)| b).collect();
        for (i, a) in balls.iter().enumerate() {
            for b in &balls[..i] {
                let reach = a.radius + b.radius;
                let depth = reach - a.position.distance(b.position);
                assert!(depth < 1e-9 * reach, "e = {e}: overlap {}", depth / reach);
            }
        }
        let events = world.event_counts().handled();
        assert!(events < 3000 * 40, "e = {e}: {events} events");
    }
}
