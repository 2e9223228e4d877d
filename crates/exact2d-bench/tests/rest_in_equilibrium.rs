//! A poured pile comes to rest in static equilibrium when balls touching balls sleep only in
//! equilibrium (`World::set_sleep_in_equilibrium`), checked apart from the engine by
//! `exact2d_bench::balance` (non-negative least squares over every contact).

use exact2d_bench::balance::out_of_balance;
use exact2d_bench::scenes;

/// Poured frictionless balls, `n` of them, at restitution `e`: every ball asleep in finite
/// simulated time, no ball left with more than 1e-9 of its weight unbalanced, and nothing
/// more in the next 1000 s.
fn rests_in_balance(n: usize, e: f64, pegs: bool, seed: u64) {
    let mut world = scenes::pile(n, e, pegs, seed)
        .build_world()
        .unwrap()
        .into_world();
    world.set_sleep_in_equilibrium(true);
    let mut t = 0.0;
    while world.sleeping_count() < n && t < 120.0 {
        t += 0.5;
        world.advance_to(t).unwrap();
    }
    assert_eq!(world.sleeping_count(), n, "every ball asleep by t = {t}");
    let (worst, total) = out_of_balance(&world);
    assert!(
        worst < 1e-9 && total < 1e-9,
        "out of balance: {worst:e}, {total:e}"
    );
    assert_eq!(world.advance_to(t + 1000.0).unwrap(), 0);
}

/// Off, this pile rests with a ball 7.1e-2 of its weight out of balance.
#[test]
fn a_poured_pile_rests_in_equilibrium() {
    rests_in_balance(50, 0.5, false, 1);
}

/// Off, this pile rests with a ball 0.15 of its weight out of balance.
#[test]
fn a_poured_pile_among_pegs_rests_in_equilibrium() {
    rests_in_balance(50, 0.5, true, 3);
}
