//! The invariants of a soak run, checked on snapshots, with the worst values seen so far.

use std::fmt;

use exact2d::{Ball, Collider, DVec2, Shape};

use super::containment::{self, Bounds};
use super::energy;
use super::overlap;

/// How deep two bodies may overlap, relative to their contact distance, before the run
/// fails: the engine's placement tolerance [`exact2d::OVERLAP_TOLERANCE`] (1e-9). The engine
/// lets bodies touch "up to rounding" at placement and never pushes them apart, and its times
/// of impact are exact up to a few ulps of the coordinates, so a sound engine stays about
/// 1e-13 deep in a unit box; sinking by 1e-9 of a radius means a missed or late collision.
pub const OVERLAP_TOLERANCE: f64 = exact2d::OVERLAP_TOLERANCE;

/// How far the total energy of an elastic world may drift, relative to its initial value,
/// before the run fails: 1e-9. Each elastic event changes the energy by rounding only, a few
/// ulps (2.2e-16 each) of the energy of the bodies involved, in either direction; over 10^8
/// events such errors add up, as a random walk, to about 1e-12 of the total, so 1e-9 leaves a
/// margin of a thousand while catching any systematic gain or loss.
pub const ENERGY_TOLERANCE: f64 = 1e-9;

/// A broken invariant: which one, and what broke it.
#[derive(Debug, Clone, PartialEq)]
pub struct Violation {
    /// The invariant's name: `finite`, `time`, `overlap`, `containment` or `energy`.
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
        time: f64,
        closed: bool,
    ) -> Result<Self, String> {
        let bounds = match (closed, containment::solid_bounds(&colliders)) {
            (false, _) => None,
            (true, Some(bounds)) => Some(bounds),
            (true, None) => return Err("--closed needs at least one solid collider".to_owned()),
        };
        let initial_energy =
            energy::is_conserved(balls, &colliders).then(|| energy::total_energy(balls, gravity));
        Ok(Self {
            colliders,
            gravity,
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

    /// Checks every invariant on a snapshot of the balls at time `time`, recording the worst
    /// values first, so the report shows them even when the check fails.
    ///
    /// # Errors
    /// The first broken invariant, in the order finite, time, overlap, containment, energy.
    pub fn check(&mut self, balls: &[Ball], time: f64) -> Result<(), Violation> {
        self.checks += 1;
        check_finite(balls)?;
        self.check_time(time)?;
        self.check_overlap(balls)?;
        self.check_containment(balls)?;
        self.check_energy(balls)
    }

    fn check_overlap(&mut self, balls: &[Ball]) -> Result<(), Violation> {
        let pair = overlap::deepest_ball_pair(balls);
        let contact = overlap::deepest_collider_contact(balls, &self.colliders);
        let pair_depth = pair.map_or(0.0, |p| p.depth);
        let contact_depth = contact.map_or(0.0, |c| c.depth);
        self.worst_overlap = self.worst_overlap.max(pair_depth).max(contact_depth);
        let too_deep = |depth: f64| format!("{depth:e} of the contact distance deep");
        let tolerance = format!("(tolerance {OVERLAP_TOLERANCE:e})");
        match (pair, contact) {
            (Some(p), _) if p.depth > OVERLAP_TOLERANCE && p.depth >= contact_depth => {
                let (a, b) = (balls[p.a].user_data, balls[p.b].user_data);
                let detail = format!(
                    "balls {a} and {b} overlap {} {tolerance}",
                    too_deep(p.depth)
                );
                Err(overlap_violation(detail))
            }
            (_, Some(c)) if c.depth > OVERLAP_TOLERANCE => {
                let (ball, name) = (balls[c.ball].user_data, name(&self.colliders[c.collider]));
                let detail = format!("ball {ball} is in {name} {} {tolerance}", too_deep(c.depth));
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

    fn check_energy(&mut self, balls: &[Ball]) -> Result<(), Violation> {
        let Some(initial) = self.initial_energy else {
            return Ok(());
        };
        let energy = energy::total_energy(balls, self.gravity);
        let drift = energy::relative_drift(initial, energy);
        self.worst_energy_drift = self.worst_energy_drift.map(|worst| worst.max(drift));
        if drift <= ENERGY_TOLERANCE {
            return Ok(());
        }
        let detail = format!(
            "total energy {energy:?} drifted {drift:e} from {initial:?} (tolerance {ENERGY_TOLERANCE:e})"
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

/// A collider's scene name, `segments[i]` or `circles[i]` (a scene stores the index in
/// `user_data`).
#[must_use]
pub fn name(collider: &Collider) -> String {
    match collider.shape {
        Shape::Segment(_) => format!("segments[{}]", collider.user_data),
        Shape::Circle(_) => format!("circles[{}]", collider.user_data),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use exact2d::{CollisionGroups, Segment};

    fn ball(id: u64, x: f64, y: f64, vx: f64) -> Ball {
        Ball {
            position: DVec2::new(x, y),
            velocity: DVec2::new(vx, 0.0),
            radius: 0.5,
            mass: 1.0,
            restitution: 1.0,
            groups: CollisionGroups::ALL,
            user_data: id,
        }
    }

    fn floor(index: u64) -> Collider {
        Collider {
            shape: Shape::Segment(Segment::new(DVec2::ZERO, DVec2::new(10.0, 0.0)).unwrap()),
            sensor: false,
            restitution: 1.0,
            groups: CollisionGroups::ALL,
            user_data: index,
        }
    }

    fn watch(balls: &[Ball], closed: bool) -> Watch {
        Watch::new(balls, vec![floor(3)], DVec2::new(0.0, -1.0), 0.0, closed).unwrap()
    }

    #[test]
    fn an_overlap_deeper_than_the_tolerance_names_the_balls_ids() {
        let balls = [ball(10, 1.0, 1.0, 0.0), ball(20, 1.999, 1.0, 0.0)];
        let mut watch = watch(&balls, false);
        let violation = watch.check(&balls, 0.0).unwrap_err();
        assert_eq!(violation.invariant, "overlap");
        assert!(violation.detail.contains("balls 10 and 20"), "{violation}");
        assert!((watch.worst_overlap - 0.001).abs() < 1e-12);
    }

    #[test]
    fn an_overlap_within_the_tolerance_passes_and_is_recorded() {
        let balls = [ball(1, 1.0, 0.5 - 0.5 * OVERLAP_TOLERANCE / 2.0, 0.0)];
        let mut watch = watch(&balls, false);
        assert_eq!(watch.check(&balls, 0.0), Ok(()));
        assert!(watch.worst_overlap > 0.0 && watch.worst_overlap <= OVERLAP_TOLERANCE);
        let sunk = [ball(1, 1.0, 0.49, 0.0)];
        let violation = watch.check(&sunk, 0.0).unwrap_err();
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
        assert_eq!(watch(&balls, false).check(&balls, 0.0), Ok(()));
        let mut ceiling = floor(4);
        ceiling.shape =
            Shape::Segment(Segment::new(DVec2::Y * 5.0, DVec2::new(10.0, 5.0)).unwrap());
        let colliders = vec![floor(3), ceiling];
        let mut closed = Watch::new(&balls, colliders, DVec2::ZERO, 0.0, true).unwrap();
        let violation = closed.check(&balls, 0.0).unwrap_err();
        assert_eq!(violation.invariant, "containment");
        assert!(violation.detail.contains("first ball 2"), "{violation}");
        assert_eq!(closed.balls_escaped, Some(1));
        assert!(Watch::new(&balls, vec![], DVec2::ZERO, 0.0, true).is_err());
    }

    #[test]
    fn energy_drift_is_recorded_and_too_much_fails() {
        // Energy 1 * 2^2 / 2 + 1 * 1 * 4 = 6 at height 4.
        let balls = [ball(1, 1.0, 4.0, 2.0)];
        let mut watch = watch(&balls, false);
        // Falling to height 2 at speed sqrt(8): the same energy, up to rounding.
        let fallen = [ball(1, 1.0, 2.0, 8.0_f64.sqrt())];
        assert_eq!(watch.check(&fallen, 1.0), Ok(()));
        assert!(watch.worst_energy_drift.unwrap() < 1e-15);
        let faster = [ball(1, 1.0, 2.0, 3.0)];
        assert_eq!(watch.check(&faster, 2.0).unwrap_err().invariant, "energy");
        assert_eq!(watch.worst_energy_drift, Some(0.5 / 6.0));
        assert_eq!(watch.checks, 2);
    }

    #[test]
    fn a_non_finite_ball_is_a_violation() {
        let balls = [ball(1, 1.0, 4.0, f64::NAN)];
        let mut watch = watch(&[ball(1, 1.0, 4.0, 0.0)], false);
        assert_eq!(watch.check(&balls, 0.0).unwrap_err().invariant, "finite");
    }
}
