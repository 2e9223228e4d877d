//! Balls in an axis-aligned box against the analytic answer: mirror folding.
//!
//! A ball of radius `r` bouncing elastically inside `[0, W] x [0, H]` moves on each axis
//! independently: its centre is the free straight-line position *folded* back into
//! `[r, W - r]` by mirroring at both ends, whatever the number of bounces. The fold of an
//! unbounded coordinate `u = x0 - r + vx t` is `r + m` if `m <= L` else `r + 2L - m`, with
//! `L = W - 2r` and `m = u mod 2L`. We evaluate `vx t` exactly (as the unevaluated sum of two
//! doubles) so the reference is accurate to a few ulps of the box size, far below what we test.
//!
//! The required accuracy is 1e-9 at moderate speeds and 1e-6 for a ball at 10^4 units/s over
//! 10^5 bounces. Measured: 6e-13 and 3.4e-11. The asserted bounds (1e-10, 1e-8) keep a margin
//! of 100 over the measurement and would catch a regression such as rounding event times to one
//! double (which measured 1.6e-10 and 5.5e-7: see `dynamics/time.rs`).

mod common;

use common::{SplitMix, boxed_rect};
use exact2d::roots::two_product;
use exact2d::{BallDesc, CollisionGroups, DVec2};

/// The analytic position of one coordinate after time `t`.
fn fold(x0: f64, v: f64, t: f64, r: f64, size: f64) -> f64 {
    let length = size - 2.0 * r;
    let (vt, vt_err) = two_product(v, t);
    // u = (x0 - r) + vt + vt_err, reduced modulo 2L in steps that are exact or nearly so.
    let period = 2.0 * length;
    let m = ((vt.rem_euclid(period) + (x0 - r)) + vt_err).rem_euclid(period);
    if m <= length { r + m } else { r + period - m }
}

const NO_BALL_CONTACTS: CollisionGroups = CollisionGroups::new(1, !1);

#[test]
fn moderate_speeds_follow_mirror_folding_to_1e_9_at_every_frame() {
    let (width, height) = (10.0, 7.0);
    let mut world = boxed_rect(width, height, DVec2::ZERO);
    let mut rng = SplitMix(2024);
    let mut starts = Vec::new();
    for _ in 0..12 {
        let r = rng.range(0.05, 0.5);
        let p = DVec2::new(rng.range(r, width - r), rng.range(r, height - r));
        let v = DVec2::new(rng.range(-5.0, 5.0), rng.range(-5.0, 5.0));
        let h = world
            .add_ball(BallDesc::new(p, r).velocity(v).groups(NO_BALL_CONTACTS))
            .unwrap();
        starts.push((h, p, v, r));
    }
    let mut worst: f64 = 0.0;
    // Frames of irregular length, as a renderer would produce them.
    let mut t = 0.0;
    while t < 1000.0 {
        t += rng.range(0.001, 0.05) + if rng.next_f64() < 0.01 { 20.0 } else { 0.0 };
        world.advance_to(t).unwrap();
        for &(h, p, v, r) in &starts {
            let ball = world.ball(h).unwrap();
            let expected = DVec2::new(fold(p.x, v.x, t, r, width), fold(p.y, v.y, t, r, height));
            worst = worst.max((ball.position - expected).abs().max_element());
            // Reflection off axis-aligned walls only flips signs: velocities stay exact.
            assert_eq!(ball.velocity.abs(), v.abs());
        }
    }
    let bounces = world.event_counts().contacts;
    println!("{bounces} bounces over 1000 s, worst position error {worst:e}");
    assert!(bounces > 5_000, "{bounces} bounces");
    assert!(worst <= 1e-10, "worst position error {worst:e}");
}

#[test]
fn a_ball_at_ten_thousand_units_per_second_stays_on_the_analytic_path_for_100_000_bounces() {
    let size = 10.0;
    let mut world = boxed_rect(size, size, DVec2::ZERO);
    let (p, r) = (DVec2::new(3.3, 4.7), 0.25);
    let v = DVec2::new(7071.067811865475, 7071.067811865476) * 1.000_000_123;
    let ball = world.add_ball(BallDesc::new(p, r).velocity(v)).unwrap();
    // Each axis bounces every (size - 2r) / |v_axis| seconds.
    let per_bounce = (size - 2.0 * r) / v.x.abs() / 2.0;
    let t = 100_000.0 * per_bounce;
    let mut worst: f64 = 0.0;
    for k in 1..=100 {
        let frame = t * f64::from(k) / 100.0;
        world.advance_to(frame).unwrap();
        let got = world.ball(ball).unwrap().position;
        let expected = DVec2::new(
            fold(p.x, v.x, frame, r, size),
            fold(p.y, v.y, frame, r, size),
        );
        worst = worst.max((got - expected).abs().max_element());
    }
    let bounces = world.event_counts().contacts;
    println!("{bounces} bounces at |v| = 1e4, worst position error {worst:e}");
    assert!((99_990..=100_010).contains(&bounces), "{bounces} bounces");
    assert!(worst <= 1e-8, "worst position error {worst:e}");
}
