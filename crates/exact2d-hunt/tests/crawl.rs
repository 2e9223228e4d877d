//! The crawl check sees internal events: a run of them that `World::step_until` would handle
//! without returning is a finding, not a hunt that hangs inside one call.

use exact2d::{BallDesc, ColliderDesc, DVec2, World};
use exact2d_hunt::check::Class;
use exact2d_hunt::run::{Limits, run_world};

/// A ball sliding without friction along a floor of 100,100 collinear segments, each 1 long,
/// goes on from each to the next at their junction: internal events only (a leave at each
/// junction, now and then two), 100,000 of them by 664 s, and no event returned. Nothing is
/// wrong with the scene, but no hunt scene has anywhere near so many colliders (at most 713
/// internal events in a row were measured on them), so it stands for a crawl of internal
/// events that the clock outruns: the hunt, when it stepped with `step_until`, handled every
/// junction inside one call and found nothing.
#[test]
fn a_hundred_thousand_internal_events_in_a_row_are_a_crawl() {
    const SEGMENTS: u32 = 100_100;
    let mut world = World::with_gravity(DVec2::new(0.0, -9.81)).unwrap();
    // The far end first: the grids are fitted to the floor's extent once, not at every segment
    // (3.8 s instead of 0.06 s to build).
    let order = std::iter::once(SEGMENTS - 1).chain(0..SEGMENTS - 1);
    for i in order {
        let (a, b) = (f64::from(i), f64::from(i + 1));
        world
            .add_collider(ColliderDesc::segment(
                DVec2::new(a, 0.0),
                DVec2::new(b, 0.0),
            ))
            .unwrap();
    }
    world
        .add_ball(BallDesc::new(DVec2::new(0.5, 0.25), 0.25).velocity(DVec2::new(100.0, 0.0)))
        .unwrap();
    let bounds = (
        DVec2::new(-1.0, -1.0),
        DVec2::new(f64::from(SEGMENTS) + 1.0, 10.0),
    );
    let limits = Limits {
        until: 2000.0,
        events: 300_000,
        collapse: 0.0,
    };
    let outcome = run_world(world, bounds, limits);
    let finding = outcome.finding.clone().expect("a crawl");
    assert_eq!(finding.class, Class::Crawl, "{outcome:?}");
    assert!(
        finding.detail.contains("100000 internal events in a row"),
        "{outcome:?}"
    );
    // It was stopped there, on the floor, long before the ball could reach its end.
    assert_eq!(outcome.events, 0, "{outcome:?}");
    assert!(outcome.time < 700.0, "{outcome:?}");
}
