//! The invariants of a soak run, checked on snapshots, with the worst values seen so far.

use std::fmt;

use exact2d::{Ball, Collider, DVec2};

use super::containment::{self, Bounds};
use super::energy;
use super::overlap;
use crate::bodies::collider_name;

/// How deep two bodies may overlap before the run fails: what the engine states it allows,
/// [`exact2d::overlap_bound`], pair by pair: [`exact2d::OVERLAP_TOLERANCE`] (1e-9) of the
/// contact distance, as deep as a placement may be, plus 256 units in the last place of the
/// contact's coordinate scale (the largest coordinate magnitude of the two bodies plus the
/// contact distance), the touching distance of resting contact. The engine never pushes
/// bodies apart, and its times of impact are exact up to a few ulps of the coordinates, so a
/// sound engine stays about 1e-13 deep in a unit box; sinking by 1e-9 of a radius there (or
/// by hundreds of ulps far from the origin) means a missed or late collision.
const OVERLAP_BOUND: &str = "1e-9 of the contact distance plus 256 units in the last place of the contact's coordinate scale";

/// Events at one instant allowed per ball that had one, and once more (the bound is
/// `EVENTS_PER_BALL * (balls + 1)`, the engine's internal events counted, as
/// [`exact2d::World::instant_events`] counts them): 64.
///
/// The clock must move on: at one instant each contact responds in sequence at most twice
/// before its jam is resolved (`ARCHITECTURE.md`, zero-time chains), and each ball settles on
/// or leaves a support a bounded number of times. The exact2d-hunt crate's scenes (balls
/// pressed into corners, wedges, exact fits) take at most 14 per ball at one instant, and
/// its check allows the same 64 (`exact2d_hunt::check::EVENTS_PER_BALL`). The engine's own
/// safety net, [`exact2d::STALL_EVENTS_PER_BALL`] (1000, an error from `World::step_until`),
/// is far above: this catches a stalling clock well before it.
pub const EVENTS_PER_BALL: u64 = 64;

/// How far the total energy of an elastic world may drift, relative to its initial value,
/// before the run fails: 1e-9. Each elastic event changes the energy by rounding only, a few
/// ulps (2.2e-16 each) of the energy of the bodies involved, in either direction; over 10^8
/// events such errors add up, as a random walk, to about 1e-12 of the total, so 1e-9 leaves a
/// margin of a thousand while catching any systematic gain or loss.
pub const ENERGY_TOLERANCE: f64 = 1e-9;

/// A broken invariant: which one, and what broke it.
#[derive(Debug, Clone, PartialEq)]
pub struct Violation {
    /// The invariant's name: `finite`, `time` (back, or stalled), `overlap`, `containment` or
    /// `energy`.
    pub invariant: &'static str,
    /// The bodies and values involved.
    pub detail: String,
}

impl fmt::Display for Violation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "invariant {} broken: {}", self.invariant, self.detail)
    }
}

/// The invariants of one run and the worst values they have seen.
pub struct Watch {
    colliders: Vec<Collider>,
    gravity: DVec2,
    /// The periodic box's sides, if the world is one: pairs are measured through their
    /// nearest images, and with `--closed` it is the box balls must stay in.
    periodic: Option<DVec2>,
    /// The box the balls must stay in (`--closed`), else `None`.
    bounds: Option<Bounds>,
    /// The energy at the start, if energy is conserved, else `None`.
    initial_energy: Option<f64>,
    last_time: f64,
    /// The deepest overlap seen, relative to the contact distance (0 if none).
    pub worst_overlap: f64,
    /// The largest relative energy drift seen, if energy is conserved.
    pub worst_energy_drift: Option<f64>,
    /// The most balls seen outside the box at once, with `--closed`.
    pub balls_escaped: Option<u64>,
    /// Snapshots checked.
    pub checks: u64,
}

impl Watch {
    /// The invariants of a world whose balls are `balls` at time `time`.
    ///
    /// # Errors
    /// With `closed`, if there is no solid collider to make a box of.
    pub fn new(
        balls: &[Ball],
        colliders: Vec<Collider>,
        gravity: DVec2,
        periodic: Option<DVec2>,
        time: f64,
        closed: bool,
    ) -> Result<Self, String> {
        let bounds = match (closed, containment::solid_bounds(&colliders), periodic) {
            (false, _, _) => None,
            // A periodic box closes itself: every ball stays in it.
            (true, _, Some(size)) => Some(Bounds {
                min: DVec2::ZERO,
                max: size,
            }),
            (true, Some(bounds), None) => Some(bounds),
            (true, None, None) => {
                return Err("--closed needs at least one solid collider".to_owned());
            }
        };
        let initial_energy =
            energy::is_conserved(balls, &colliders).then(|| energy::total_energy(balls, gravity));
        Ok(Self {
            colliders,
            gravity,
            periodic,
            bounds,
            initial_energy,
            last_time: time,
            worst_overlap: 0.0,
            worst_energy_drift: initial_energy.map(|_| 0.0),
            balls_escaped: bounds.map(|_| 0),
            checks: 0,
        })
    }

    /// Checks that time `time` (an event's, or the clock's) is not before the last one seen.
    ///
    /// # Errors
    /// The `time` invariant.
    pub fn check_time(&mut self, time: f64) -> Result<(), Violation> {
        if !(time >= self.last_time) {
            let detail = format!("time went back from {:?} to {time:?}", self.last_time);
            return Err(Violation {
                invariant: "time",
                detail,
            });
        }
        self.last_time = time;
        Ok(())
    }

    /// Checks that the clock moves on, after an event at `time` of the bodies `bodies` (named
    /// only if the check fails): the events at the current instant, `(events, balls)` as
    /// [`exact2d::World::instant_events`] counts them, stay within [`EVENTS_PER_BALL`] per
    /// ball, plus [`EVENTS_PER_BALL`].
    ///
    /// # Errors
    /// The `time` invariant, naming the bodies and the time.
    pub fn check_instant(
        &self,
        (events, balls): (u64, usize),
        time: f64,
        bodies: impl FnOnce() -> String,
    ) -> Result<(), Violation> {
        let bound = EVENTS_PER_BALL.saturating_mul(balls as u64 + 1);
        if events <= bound {
            return Ok(());
        }
        let detail = format!(
            "the clock stalled at t = {time:?}: {events} events at that instant among {balls} \
             balls (bound {bound}: {EVENTS_PER_BALL} per ball, plus {EVENTS_PER_BALL}); the last \
             between {}",
            bodies()
        );
        Err(Violation {
            invariant: "time",
            detail,
        })
    }

    /// Checks every invariant on a snapshot of the balls at time `time`, recording the worst
    /// values first, so the report shows them even when the check fails. `jams` is the
    /// number of simultaneous impacts the world has resolved so far
    /// ([`exact2d::EventCounts::jams`]): once there is one, energy may have been absorbed,
    /// and only a gain counts as drift.
    ///
    /// # Errors
    /// The first broken invariant, in the order finite, time, overlap, containment, energy.
    pub fn check(&mut self, balls: &[Ball], time: f64, jams: u64) -> Result<(), Violation> {
        self.checks += 1;
        check_finite(balls)?;
        self.check_time(time)?;
        self.check_overlap(balls)?;
        self.check_containment(balls)?;
        self.check_energy(balls, jams)
    }

    fn check_overlap(&mut self, balls: &[Ball]) -> Result<(), Violation> {
        let pairs = match self.periodic {
            None => overlap::ball_overlaps(balls),
            Some(size) => overlap::ball_overlaps_periodic(balls, size),
        };
        let contacts = overlap::collider_overlaps(balls, &self.colliders);
        let pair_depth = pairs.deepest.map_or(0.0, |p| p.depth);
        let contact_depth = contacts.deepest.map_or(0.0, |c| c.depth);
        self.worst_overlap = self.worst_overlap.max(pair_depth).max(contact_depth);
        let too_deep = |depth: f64, allowed: f64| {
            format!(
                "{depth:e} of the contact distance deep (bound {allowed:e} of it: {OVERLAP_BOUND})"
            )
        };
        let excess = |depth: f64, allowed: f64| depth / allowed;
        let contact_excess = contacts.beyond.map_or(0.0, |c| excess(c.depth, c.allowed));
        match (pairs.beyond, contacts.beyond) {
            (Some(p), _) if excess(p.depth, p.allowed) >= contact_excess => {
                let (a, b) = (balls[p.a].user_data, balls[p.b].user_data);
                let detail = format!("balls {a} and {b} overlap {}", too_deep(p.depth, p.allowed));
                Err(overlap_violation(detail))
            }
            (_, Some(c)) => {
                let ball = balls[c.ball].user_data;
                let name = collider_name(&self.colliders[c.collider]);
                let deep = too_deep(c.depth, c.allowed);
                let detail = format!("ball {ball} is in {name} {deep}");
                Err(overlap_violation(detail))
            }
            _ => Ok(()),
        }
    }

    fn check_containment(&mut self, balls: &[Ball]) -> Result<(), Violation> {
        let Some(bounds) = self.bounds else {
            return Ok(());
        };
        let escaped = containment::escaped_balls(balls, bounds);
        let count = escaped.len() as u64;
        self.balls_escaped = self.balls_escaped.map(|worst| worst.max(count));
        let Some(&first) = escaped.first() else {
            return Ok(());
        };
        let ball = &balls[first];
        let detail = format!(
            "{count} ball(s) outside the colliders' box [{:?}, {:?}]-[{:?}, {:?}], first ball {} at [{:?}, {:?}]",
            bounds.min.x,
            bounds.min.y,
            bounds.max.x,
            bounds.max.y,
            ball.user_data,
            ball.position.x,
            ball.position.y
        );
        Err(Violation {
            invariant: "containment",
            detail,
        })
    }

    fn check_energy(&mut self, balls: &[Ball], jams: u64) -> Result<(), Violation> {
        let Some(initial) = self.initial_energy else {
            return Ok(());
        };
        let energy = energy::total_energy(balls, self.gravity);
        // A jam (a simultaneous impact) may absorb energy, never add it: after one, only a
        // gain is drift.
        let counted = if jams > 0 {
            energy.max(initial)
        } else {
            energy
        };
        let drift = energy::relative_drift(initial, counted);
        self.worst_energy_drift = self.worst_energy_drift.map(|worst| worst.max(drift));
        if drift <= ENERGY_TOLERANCE {
            return Ok(());
        }
        let losses = if jams > 0 {
            format!("; losses allowed after {jams} jam(s)")
        } else {
            String::new()
        };
        let detail = format!(
            "total energy {energy:?} drifted {drift:e} from {initial:?} (tolerance {ENERGY_TOLERANCE:e}{losses})"
        );
        Err(Violation {
            invariant: "energy",
            detail,
        })
    }
}

fn overlap_violation(detail: String) -> Violation {
    Violation {
        invariant: "overlap",
        detail,
    }
}

/// Every ball's position and velocity are finite (the other checks assume it).
fn check_finite(balls: &[Ball]) -> Result<(), Violation> {
    match balls
        .iter()
        .find(|b| !(b.position.is_finite() && b.velocity.is_finite()))
    {
        None => Ok(()),
        Some(ball) => Err(Violation {
            invariant: "finite",
            detail: format!(
                "ball {} has position {:?} and velocity {:?}",
                ball.user_data, ball.position, ball.velocity
            ),
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use exact2d::{CollisionGroups, Segment, Shape};

    fn ball(id: u64, x: f64, y: f64, vx: f64) -> Ball {
        Ball {
            position: DVec2::new(x, y),
            velocity: DVec2::new(vx, 0.0),
            radius: 0.5,
            mass: 1.0,
            restitution: 1.0,
            groups: CollisionGroups::ALL,
            user_data: id,
            spin: 0.0,
            angle: 0.0,
            inertia: 0.5,
            friction: 0.0,
            tangential_restitution: 0.0,
            rolling_resistance: 0.0,
            roll: DVec2::ZERO,
        }
    }

    fn floor(index: u64) -> Collider {
        Collider {
            shape: Shape::Segment(Segment::new(DVec2::ZERO, DVec2::new(10.0, 0.0)).unwrap()),
            sensor: false,
            restitution: 1.0,
            groups: CollisionGroups::ALL,
            user_data: index,
            friction: 0.0,
            tangential_restitution: 0.0,
            rolling_resistance: 0.0,
        }
    }

    fn watch(balls: &[Ball], closed: bool) -> Watch {
        Watch::new(
            balls,
            vec![floor(3)],
            DVec2::new(0.0, -1.0),
            None,
            0.0,
            closed,
        )
        .unwrap()
    }

    #[test]
    fn an_overlap_deeper_than_the_tolerance_names_the_balls_ids() {
        let balls = [ball(10, 1.0, 1.0, 0.0), ball(20, 1.999, 1.0, 0.0)];
        let mut watch = watch(&balls, false);
        let violation = watch.check(&balls, 0.0, 0).unwrap_err();
        assert_eq!(violation.invariant, "overlap");
        assert!(violation.detail.contains("balls 10 and 20"), "{violation}");
        assert!((watch.worst_overlap - 0.001).abs() < 1e-12);
    }

    #[test]
    fn an_overlap_within_the_tolerance_passes_and_is_recorded() {
        let balls = [ball(
            1,
            1.0,
            0.5 - 0.5 * exact2d::OVERLAP_TOLERANCE / 2.0,
            0.0,
        )];
        let mut watch = watch(&balls, false);
        assert_eq!(watch.check(&balls, 0.0, 0), Ok(()));
        assert!(watch.worst_overlap > 0.0 && watch.worst_overlap <= exact2d::OVERLAP_TOLERANCE);
        let sunk = [ball(1, 1.0, 0.49, 0.0)];
        let violation = watch.check(&sunk, 0.0, 0).unwrap_err();
        assert!(
            violation.detail.contains("ball 1 is in segments[3]"),
            "{violation}"
        );
    }

    #[test]
    fn time_going_back_is_a_violation() {
        let balls = [ball(1, 1.0, 1.0, 0.0)];
        let mut watch = watch(&balls, false);
        assert_eq!(watch.check_time(2.0), Ok(()));
        assert_eq!(watch.check_time(2.0), Ok(()));
        assert_eq!(watch.check_time(1.5).unwrap_err().invariant, "time");
    }

    #[test]
    fn escaping_balls_are_counted_only_when_closed() {
        let balls = [ball(1, 1.0, 1.0, 0.0), ball(2, 11.0, 1.0, 0.0)];
        assert_eq!(watch(&balls, false).check(&balls, 0.0, 0), Ok(()));
        let mut ceiling = floor(4);
        ceiling.shape =
            Shape::Segment(Segment::new(DVec2::Y * 5.0, DVec2::new(10.0, 5.0)).unwrap());
        let colliders = vec![floor(3), ceiling];
        let mut closed = Watch::new(&balls, colliders, DVec2::ZERO, None, 0.0, true).unwrap();
        let violation = closed.check(&balls, 0.0, 0).unwrap_err();
        assert_eq!(violation.invariant, "containment");
        assert!(violation.detail.contains("first ball 2"), "{violation}");
        assert_eq!(closed.balls_escaped, Some(1));
        assert!(Watch::new(&balls, vec![], DVec2::ZERO, None, 0.0, true).is_err());
    }

    #[test]
    fn energy_drift_is_recorded_and_too_much_fails() {
        // Energy 1 * 2^2 / 2 + 1 * 1 * 4 = 6 at height 4.
        let balls = [ball(1, 1.0, 4.0, 2.0)];
        let mut watch = watch(&balls, false);
        // Falling to height 2 at speed sqrt(8): the same energy, up to rounding.
        let fallen = [ball(1, 1.0, 2.0, 8.0_f64.sqrt())];
        assert_eq!(watch.check(&fallen, 1.0, 0), Ok(()));
        assert!(watch.worst_energy_drift.unwrap() < 1e-15);
        let faster = [ball(1, 1.0, 2.0, 3.0)];
        assert_eq!(
            watch.check(&faster, 2.0, 0).unwrap_err().invariant,
            "energy"
        );
        assert_eq!(watch.worst_energy_drift, Some(0.5 / 6.0));
        assert_eq!(watch.checks, 2);
    }

    #[test]
    fn a_non_finite_ball_is_a_violation() {
        let balls = [ball(1, 1.0, 4.0, f64::NAN)];
        let mut watch = watch(&[ball(1, 1.0, 4.0, 0.0)], false);
        assert_eq!(watch.check(&balls, 0.0, 0).unwrap_err().invariant, "finite");
    }

    #[test]
    fn far_from_the_origin_an_overlap_within_the_engines_bound_passes() {
        // 4e-8 of the radius into a floor at x = 1e6: past 1e-9, within 256 ulps of 1e6.
        let far_floor = Collider {
            shape: Shape::Segment(
                Segment::new(DVec2::new(1e6 - 5.0, 0.0), DVec2::new(1e6 + 5.0, 0.0)).unwrap(),
            ),
            ..floor(3)
        };
        let balls = [ball(1, 1e6, 0.5 - 2e-8, 0.0)];
        let mut watch = Watch::new(&balls, vec![far_floor], DVec2::ZERO, None, 0.0, false).unwrap();
        assert_eq!(watch.check(&balls, 0.0, 0), Ok(()));
        assert!(watch.worst_overlap > 3e-8, "{}", watch.worst_overlap);
        let sunk = [ball(1, 1e6, 0.5 - 1e-6, 0.0)];
        let violation = watch.check(&sunk, 0.0, 0).unwrap_err();
        assert_eq!(violation.invariant, "overlap");
        for part in [
            "ball 1 is in segments[3]",
            "bound 1.1",
            "256 units in the last place",
        ] {
            assert!(violation.detail.contains(part), "{part}: {violation}");
        }
    }

    #[test]
    fn after_a_jam_energy_may_fall_but_never_rise() {
        // Energy 6 at height 4 (as above); at height 2 at speed 2 it is 2 + 2 = 4: lost.
        let balls = [ball(1, 1.0, 4.0, 2.0)];
        let slower = [ball(1, 1.0, 2.0, 2.0)];
        let mut watch = watch(&balls, false);
        assert_eq!(
            watch.check(&slower, 1.0, 0).unwrap_err().invariant,
            "energy"
        );
        let mut jammed = self::watch(&balls, false);
        assert_eq!(jammed.check(&slower, 1.0, 1), Ok(()));
        assert_eq!(jammed.worst_energy_drift, Some(0.0));
        let faster = [ball(1, 1.0, 2.0, 3.0)];
        let violation = jammed.check(&faster, 2.0, 1).unwrap_err();
        assert_eq!(violation.invariant, "energy");
        assert!(violation.detail.contains("after 1 jam(s)"), "{violation}");
        assert_eq!(jammed.worst_energy_drift, Some(0.5 / 6.0));
    }

    #[test]
    fn too_many_events_at_one_instant_is_a_stalled_clock_naming_the_bodies() {
        let balls = [ball(1, 1.0, 1.0, 0.0)];
        let watch = watch(&balls, false);
        let bodies = || "ball 7 and segments[2]".to_owned();
        assert_eq!(watch.check_instant((0, 0), 0.5, bodies), Ok(()));
        // 64 per ball that had one, plus 64.
        assert_eq!(watch.check_instant((192, 2), 0.5, bodies), Ok(()));
        let violation = watch.check_instant((193, 2), 0.5, bodies).unwrap_err();
        assert_eq!(violation.invariant, "time");
        assert_eq!(
            violation.detail,
            "the clock stalled at t = 0.5: 193 events at that instant among 2 balls (bound 192: \
             64 per ball, plus 64); the last between ball 7 and segments[2]"
        );
        assert!(watch.check_instant((65, 0), 0.5, bodies).is_err());
        // The bodies are named only when the check fails.
        assert!(watch.check_instant((64, 0), 0.5, || unreachable!()).is_ok());
    }
}
