//! Energy: with perfectly elastic bodies, kinetic plus gravitational energy never changes.
//!
//! A ball of mass `m` at `p` moving at `v` under uniform gravity `g` has energy
//! `m |v|^2 / 2 - m g . p` (the potential is the work against `g` from the origin). Elastic
//! bounces off static colliders keep each ball's energy; elastic ball-ball impulses keep
//! the pair's. So the total is conserved exactly when every ball and every solid collider has
//! restitution 1 (a pair's restitution is the product of its two values), and rounding is the
//! only thing that can move it, with one exception: a simultaneous impact the engine resolves
//! as a jam ([`exact2d::EventCounts::jams`]) may absorb energy (never add it), so once there
//! has been one the watch counts only a gain as drift.

use exact2d::{Ball, Collider, DVec2};

/// Whether energy is conserved: every ball and every solid collider has restitution 1, and
/// no ball has friction (a rough contact that slides loses energy).
#[must_use]
pub fn is_conserved(balls: &[Ball], colliders: &[Collider]) -> bool {
    balls
        .iter()
        .all(|b| b.restitution == 1.0 && b.friction == 0.0)
        && colliders
            .iter()
            .filter(|c| !c.sensor)
            .all(|c| c.restitution == 1.0)
}

/// The total kinetic (translational and rotational) plus gravitational energy, summed with Neumaier's compensation so that
/// the sum over a million balls adds no rounding of its own to the drift being measured.
#[must_use]
pub fn total_energy(balls: &[Ball], gravity: DVec2) -> f64 {
    let (mut sum, mut compensation) = (0.0_f64, 0.0_f64);
    for ball in balls {
        let term = ball.kinetic_energy() - ball.mass * gravity.dot(ball.position);
        let next = sum + term;
        compensation += if sum.abs() >= term.abs() {
            (sum - next) + term
        } else {
            (term - next) + sum
        };
        sum = next;
    }
    sum + compensation
}

/// `|energy - initial| / |initial|`; the absolute change when `initial` is 0 (a world at rest
/// at the origin's level has no scale to measure against).
#[must_use]
pub fn relative_drift(initial: f64, energy: f64) -> f64 {
    let change = (energy - initial).abs();
    if initial == 0.0 {
        change
    } else {
        change / initial.abs()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use exact2d::CollisionGroups;

    fn ball(position: DVec2, velocity: DVec2, mass: f64) -> Ball {
        Ball {
            position,
            velocity,
            radius: 0.1,
            mass,
            restitution: 1.0,
            groups: CollisionGroups::ALL,
            user_data: 0,
            spin: 0.0,
            angle: 0.0,
            inertia: 0.5,
            friction: 0.0,
            tangential_restitution: 0.0,
            rolling_resistance: 0.0,
            roll: DVec2::ZERO,
        }
    }

    #[test]
    fn energy_is_kinetic_plus_potential_against_gravity() {
        let g = DVec2::new(0.0, -10.0);
        // 2 * 25 / 2 + 2 * 10 * 5 = 125; 1 * 1 / 2 - 1 * (-10 * -1) = -9.5.
        let balls = [
            ball(DVec2::new(7.0, 5.0), DVec2::new(3.0, 4.0), 2.0),
            ball(DVec2::new(0.0, -1.0), DVec2::new(-1.0, 0.0), 1.0),
        ];
        assert_eq!(total_energy(&balls, g), 115.5);
        assert_eq!(total_energy(&balls, DVec2::ZERO), 25.5);
        // Turning at 4 rad/s: 0.5 * 0.1^2 * 16 / 2 * mass 2 = 0.08 more.
        let mut spinning = balls;
        spinning[0].spin = 4.0;
        assert!((total_energy(&spinning, DVec2::ZERO) - 25.58).abs() < 1e-12);
    }

    #[test]
    fn the_sum_is_compensated() {
        // 1e16 + 1 + ... + 1 - 1e16: a plain sum loses every 1.
        let mut balls = vec![ball(DVec2::ZERO, DVec2::new(2e8, 0.0), 0.5)];
        balls.extend((0..1000).map(|_| ball(DVec2::ZERO, DVec2::new(2.0_f64.sqrt(), 0.0), 1.0)));
        balls.push(ball(DVec2::new(1e16, 0.0), DVec2::ZERO, 1.0));
        let g = DVec2::new(1.0, 0.0);
        assert!((total_energy(&balls, g) - 1000.0).abs() < 1e-9);
    }

    #[test]
    fn drift_is_relative_to_the_initial_energy_or_absolute_from_zero() {
        assert_eq!(relative_drift(125.0, 125.5), 0.004);
        assert_eq!(relative_drift(-8.0, -10.0), 0.25);
        assert_eq!(relative_drift(0.0, 1e-3), 1e-3);
        assert_eq!(relative_drift(3.0, 3.0), 0.0);
    }

    #[test]
    fn energy_is_conserved_only_when_every_solid_body_is_elastic() {
        let mut balls = [ball(DVec2::ZERO, DVec2::X, 1.0)];
        let wall = exact2d::Collider {
            shape: exact2d::Shape::Circle(exact2d::Circle::new(DVec2::X * 5.0, 1.0).unwrap()),
            sensor: false,
            restitution: 0.5,
            groups: CollisionGroups::ALL,
            user_data: 0,
            friction: 0.0,
            tangential_restitution: 0.0,
            rolling_resistance: 0.0,
        };
        let sensor = exact2d::Collider {
            sensor: true,
            ..wall
        };
        assert!(is_conserved(&balls, &[sensor]));
        assert!(!is_conserved(&balls, &[sensor, wall]));
        balls[0].restitution = 0.9;
        assert!(!is_conserved(&balls, &[]));
    }
}
