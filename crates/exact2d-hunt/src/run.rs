//! Running one scene to its end, checking every event.

use exact2d::{EventCounts, Handled, World, WorldError};

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
    /// The world's collapse time (`World::set_collapse_time`, the TC model; not in the
    /// scene format): 0 for none.
    pub collapse: f64,
}

impl Default for Limits {
    fn default() -> Self {
        Self {
            until: 3.0,
            events: 300_000,
            collapse: 0.0,
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

/// Events, internal ones included, over which the clock must advance by more than
/// [`CRAWL_ADVANCE`].
const CRAWL_WINDOW: u64 = 100_000;

/// The least advance of the clock over [`CRAWL_WINDOW`] events, in seconds: 1e-9.
const CRAWL_ADVANCE: f64 = 1e-9;

/// Internal events in a row, with no event returned between them, that are a crawl however
/// far the clock moves: 100,000, one [`CRAWL_WINDOW`].
///
/// A hunt scene has at most 12 balls, and between two events a ball has only so many internal
/// ones: a settle, a leave at each end of a segment or edge of a pivot it passes, its phase
/// ends on a cloth. Measured, at most 713 in a row (a ball rolling over sleeping balls, a
/// leave at every half-degree edge of its pivots: seed 17583 of 20,000 plain seeds from 0);
/// 591 over 21,703 `--rough` seeds from 400,000, 27 over 166,133 `--table` seeds from
/// 1,000,000, 33 over 50,000 `--rough --table` seeds from 2,000,000. A run past this goes round
/// where no caller sees it (`World::step_until` would not return), however much the clock
/// moves over each window: a ball at 1e3 rolling into the box's floor by a rounding, cut and
/// laid afresh on the cloth every 2.1e-5 s without moving, then ever more often (`--table`
/// seed 1060307, with the cut the engine had while it was being made), advanced the clock by
/// 2.8e-8 s, 28 times [`CRAWL_ADVANCE`], over each 100,000 internal events, and would have
/// needed 1.4e12 of them to reach 3 s.
const INTERNAL_RUN: u64 = CRAWL_WINDOW;

/// Runs `generated` as `limits` say, checking every invariant after every event.
#[must_use]
pub fn run(generated: &Generated, limits: Limits) -> Outcome {
    let built = generated
        .scene
        .build_world()
        .map_err(|e| format!("the scene was refused: {e}"))
        .and_then(|built| {
            let mut world = built.into_world();
            world
                .set_collapse_time(limits.collapse)
                .map_err(|e| format!("the collapse time was refused: {e}"))?;
            Ok(world)
        });
    let world = match built {
        Ok(world) => world,
        Err(e) => {
            return Outcome {
                events: 0,
                time: 0.0,
                finding: Some(Finding {
                    class: Class::Stall,
                    detail: e,
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
///
/// The world is stepped one change at a time ([`World::handle_next_until`]), internal ones
/// included, so that a crawl of internal events is a finding (see `Crawl`) rather than a
/// `step_until` that never returns; it takes the very steps `step_until` would.
#[must_use]
pub fn run_world(
    mut world: World,
    bounds: (exact2d::DVec2, exact2d::DVec2),
    limits: Limits,
) -> Outcome {
    let mut checker = Checker::new(&world, bounds);
    let mut crawl = Crawl::new(world.time());
    let mut events = 0u64;
    let finding = loop {
        if events >= limits.events {
            break None;
        }
        let event = match world.handle_next_until(limits.until) {
            Ok(Handled::Event(event)) => event,
            Ok(Handled::Internal) => match crawl.after(world.time(), false) {
                Ok(()) => continue,
                Err(finding) => break Some(finding),
            },
            Ok(Handled::Nothing) => break None,
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
        if let Err(finding) = crawl.after(world.time(), true) {
            break Some(finding);
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

/// The crawl check: over every [`CRAWL_WINDOW`] events, internal ones included, the clock
/// advances by at least [`CRAWL_ADVANCE`]; and fewer than [`INTERNAL_RUN`] internal events
/// come in a row.
#[derive(Clone, Copy, Debug)]
struct Crawl {
    /// Events so far, internal ones included.
    handled: u64,
    /// The clock at the start of the current window.
    mark: f64,
    /// Internal events since the last returned one, and the clock at that one.
    run: (u64, f64),
}

impl Crawl {
    /// The check for a run whose clock starts at `time`.
    fn new(time: f64) -> Self {
        Self {
            handled: 0,
            mark: time,
            run: (0, time),
        }
    }

    /// Checks after an event, `returned` (or internal), that left the clock at `time`.
    ///
    /// # Errors
    /// A [`Class::Crawl`] finding if the clock advanced too little over the window this event
    /// ends, or it is the [`INTERNAL_RUN`]th internal event in a row.
    fn after(&mut self, time: f64, returned: bool) -> Result<(), Finding> {
        self.handled += 1;
        if self.handled % CRAWL_WINDOW == 0 {
            if time - self.mark < CRAWL_ADVANCE {
                return Err(Finding {
                    class: Class::Crawl,
                    detail: format!(
                        "{CRAWL_WINDOW} events took the clock from {:?} to {time:?}",
                        self.mark
                    ),
                });
            }
            self.mark = time;
        }
        if returned {
            self.run = (0, time);
            return Ok(());
        }
        self.run.0 += 1;
        if self.run.0 >= INTERNAL_RUN {
            return Err(Finding {
                class: Class::Crawl,
                detail: format!(
                    "{INTERNAL_RUN} internal events in a row, none returned, took the clock \
                     from {:?} to {time:?}",
                    self.run.1
                ),
            });
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Internal events count towards the window: 100,000 events, all but one in a thousand
    /// internal, that take the clock 1e-15 s each are a crawl at the 100,000th, an internal
    /// one. (Counted as the hunt once counted, returned events only, they were 100.)
    #[test]
    fn internal_events_count_towards_the_window() {
        let mut crawl = Crawl::new(1.0);
        let mut time = 1.0;
        for k in 1..CRAWL_WINDOW {
            time += 1e-15;
            assert_eq!(crawl.after(time, k % 1000 == 0), Ok(()), "event {k}");
        }
        let finding = crawl.after(time + 1e-15, false).expect_err("a crawl");
        assert_eq!(finding.class, Class::Crawl);
        assert!(
            finding
                .detail
                .starts_with("100000 events took the clock from 1.0 to 1.0000000001"),
            "{finding}"
        );
    }

    /// The window starts again where the last one ended, and a clock that moves on is no
    /// crawl however many of the events are internal.
    #[test]
    fn a_clock_that_moves_on_is_no_crawl() {
        let mut crawl = Crawl::new(0.0);
        for k in 1..=3 * CRAWL_WINDOW {
            // 2e-14 s an event: 2e-9 s a window, twice the least.
            let time = k as f64 * 2e-14;
            assert_eq!(crawl.after(time, k % 7 == 0), Ok(()), "event {k}");
        }
    }

    /// [`INTERNAL_RUN`] internal events in a row are a crawl even when the clock moves on
    /// (here 1 ms each); one returned event between them starts the run again.
    #[test]
    fn a_run_of_internal_events_is_a_crawl_however_far_the_clock_moves() {
        let mut crawl = Crawl::new(0.0);
        let mut time = 0.0;
        for _ in 1..INTERNAL_RUN {
            time += 1e-3;
            assert_eq!(crawl.after(time, false), Ok(()));
        }
        time += 1e-3;
        assert_eq!(crawl.after(time, true), Ok(()));
        let since = time;
        for _ in 1..INTERNAL_RUN {
            time += 1e-3;
            assert_eq!(crawl.after(time, false), Ok(()));
        }
        time += 1e-3;
        let finding = crawl.after(time, false).expect_err("a crawl");
        assert_eq!(finding.class, Class::Crawl);
        let from = format!("from {since:?} to {time:?}");
        assert!(
            finding.detail.contains("internal events in a row"),
            "{finding}"
        );
        assert!(finding.detail.ends_with(&from), "{finding}");
    }
}
