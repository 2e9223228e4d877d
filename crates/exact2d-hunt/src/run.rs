//! Running one scene to its end, checking every event.

use exact2d::{EventCounts, World, WorldError};

use crate::check::{Checker, Class, Finding};
use crate::generate::Generated;

/// How far to run a scene.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Limits {
    /// Simulated seconds.
    pub until: f64,
    /// Events at most: a scene that needs more is *slow* (a pile jostling in a wedge: the
    /// piles issue's territory), not broken.
    pub events: u64,
}

impl Default for Limits {
    fn default() -> Self {
        Self {
            until: 3.0,
            events: 300_000,
        }
    }
}

/// How a run went.
#[derive(Clone, Debug, PartialEq)]
pub struct Outcome {
    /// Events handled (returned ones).
    pub events: u64,
    /// The clock at the end.
    pub time: f64,
    /// The first broken invariant, if any.
    pub finding: Option<Finding>,
    /// Whether the event budget ran out before the end time.
    pub slow: bool,
    /// The world's counts at the end.
    pub counts: EventCounts,
    /// The most events at one instant, with the balls that had them.
    pub busiest: (u64, usize),
}

/// Events over which the clock must advance by more than [`CRAWL_ADVANCE`].
const CRAWL_WINDOW: u64 = 100_000;

/// The least advance of the clock over [`CRAWL_WINDOW`] events, in seconds: 1e-9.
const CRAWL_ADVANCE: f64 = 1e-9;

/// Runs `generated` as `limits` say, checking every invariant after every event.
#[must_use]
pub fn run(generated: &Generated, limits: Limits) -> Outcome {
    let world = match generated.scene.build_world() {
        Ok(built) => built.into_world(),
        Err(e) => {
            return Outcome {
                events: 0,
                time: 0.0,
                finding: Some(Finding {
                    class: Class::Stall,
                    detail: format!("the scene was refused: {e}"),
                }),
                slow: false,
                counts: EventCounts::default(),
                busiest: (0, 0),
            };
        }
    };
    run_world(world, generated.bounds, limits)
}

/// Runs `world` in the closed box `bounds` as `limits` say.
#[must_use]
pub fn run_world(
    mut world: World,
    bounds: (exact2d::DVec2, exact2d::DVec2),
    limits: Limits,
) -> Outcome {
    let mut checker = Checker::new(&world, bounds);
    let (mut events, mut mark) = (0u64, world.time());
    let finding = loop {
        if events >= limits.events {
            break None;
        }
        let event = match world.step_until(limits.until) {
            Ok(Some(event)) => event,
            Ok(None) => break None,
            Err(e @ WorldError::Stalled { .. }) => {
                break Some(Finding {
                    class: Class::Stall,
                    detail: e.to_string(),
                });
            }
            Err(e) => {
                break Some(Finding {
                    class: Class::TimeBack,
                    detail: e.to_string(),
                });
            }
        };
        events += 1;
        if let Err(finding) = checker.after(&world, &event) {
            break Some(finding);
        }
        if events % CRAWL_WINDOW == 0 {
            if world.time() - mark < CRAWL_ADVANCE {
                break Some(Finding {
                    class: Class::Crawl,
                    detail: format!(
                        "{CRAWL_WINDOW} events took the clock from {mark:?} to {:?}",
                        world.time()
                    ),
                });
            }
            mark = world.time();
        }
    };
    Outcome {
        events,
        time: world.time(),
        slow: finding.is_none() && events >= limits.events,
        finding,
        counts: world.event_counts(),
        busiest: checker.busiest,
    }
}
