//! Rough contacts: spin, and the friction impulse of the three-parameter model of rough disks.
//!
//! # The model
//!
//! Walton's model, in the form of Luding, Huthmann, McNamara and Zippelius (Phys. Rev. E 58,
//! 3416, 1998), with a Coulomb cap. Two bodies meet at a contact of unit normal `n` (from body
//! 1 to body 2); `t = perp(n) = (-n.y, n.x)`. Body `i` has mass `m_i`, moment of inertia
//! `I_i = k_i m_i r_i^2` (`k` = 1/2 for a uniform disk, the default) and spin `w_i`
//! (counter-clockwise positive); its contact point sits at `+r_1 n` from centre 1 and at
//! `-r_2 n` from centre 2, so the contact points' velocities are `v_1 + w_1 r_1 t` and
//! `v_2 - w_2 r_2 t`, and their relative tangential velocity is
//!
//! ```text
//! g_t = (v_1 - v_2) . t + w_1 r_1 + w_2 r_2.
//! ```
//!
//! A tangential impulse `J t` on body 2 (and `-J t` on body 1) changes the velocities by
//! `-J t / m_1` and `+J t / m_2`, and the spins by the angular impulses `r_1 n x (-J t)` and
//! `(-r_2 n) x (J t)`, both `-r_i J`, over `I_i`. So `g_t` changes by `-J K` with
//!
//! ```text
//! K = 1/m_1 + r_1^2/I_1 + 1/m_2 + r_2^2/I_2 = 1/m_1 (1 + 1/k_1) + 1/m_2 (1 + 1/k_2)
//! ```
//!
//! (a static body adds nothing: it neither moves nor turns). The normal impulse `P` along `n`
//! acts through both centres, so it changes no spin and no `g_t`; the tangential one changes
//! no normal velocity. The model asks the contact to leave with `g_t' = -beta g_t` (the
//! tangential restitution: `beta = -1` smooth, no impulse; `beta = 0` the contact points
//! stick; `beta = 1` perfectly rough, the tangential motion reversed), unless that takes more
//! than Coulomb's `mu P`; then the contact slides and the impulse is `mu P` against the slip:
//!
//! ```text
//! J = sign(g_t) min((1 + beta) |g_t| / K, mu P).
//! ```
//!
//! *Energy.* The kinetic energy (translational and rotational) changes by
//! `-J (g_t + g_t') / 2` for an impulse `J` that takes `g_t` to `g_t'` (the mean of the
//! contact velocities before and after, times the impulse), that is by
//! `-(1 - beta^2) g_t^2 / (2 K)` when the contact sticks, never more; sliding, `g_t'` lies
//! between `-beta g_t` and `g_t`, and the change is negative too. With `e = 1` and `beta = 1`
//! a collision conserves energy; every collision conserves linear momentum, and angular
//! momentum about any point (equal and opposite impulses at one point).
//!
//! *A pair's material.* `mu` is the geometric mean of the two bodies' (as Box2D's default
//! mixing): a frictionless body makes a frictionless pair. For `beta` the geometric mean is
//! taken of `1 + beta`, the share of the sticking impulse each side allows: a smooth body
//! (`beta = -1`) makes the pair smooth, equal values give that value, and the pair's `beta`
//! stays in `[-1, 1]`.
//!
//! # Spin as state
//!
//! A ball's spin changes only at its contacts (nothing exerts a torque in flight), so between
//! events it is a constant and its angle is linear in time. Worlds where no ball has spin,
//! friction or a moment of inertia other than the default keep no spin at all (`BallSet`'s
//! spin table is empty): frictionless scenes pay nothing for it.

use glam::DVec2;

use super::Time;

/// How rough a body's surface is: Coulomb's friction coefficient `mu` and the tangential
/// restitution `beta` (see the module's documentation for the model).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Roughness {
    /// Coulomb's coefficient, `>= 0`; 0 is frictionless (the default).
    pub friction: f64,
    /// Tangential restitution in `[-1, 1]`: -1 smooth, 0 (the default) a sticking contact
    /// ends without slip, 1 perfectly rough.
    pub tangential_restitution: f64,
    /// Rolling resistance, `>= 0` (default 0): a ball rolling on a surface loses speed at
    /// this times the surface's normal pull (see `dynamics/rolling.rs`).
    pub rolling_resistance: f64,
}

impl Roughness {
    /// Frictionless: `mu = 0`, `beta = 0`.
    pub const SMOOTH: Roughness = Roughness {
        friction: 0.0,
        tangential_restitution: 0.0,
        rolling_resistance: 0.0,
    };

    /// The roughness of a contact between two bodies: `mu` and the rolling resistance the
    /// geometric means of theirs, and `1 + beta` the geometric mean of their `1 + beta`.
    #[must_use]
    pub fn pair(self, other: Roughness) -> Roughness {
        let mean = |a: f64, b: f64| {
            if a == 0.0 || b == 0.0 {
                0.0
            } else {
                (a * b).sqrt()
            }
        };
        let share =
            ((1.0 + self.tangential_restitution) * (1.0 + other.tangential_restitution)).sqrt();
        Roughness {
            friction: mean(self.friction, other.friction),
            tangential_restitution: (share - 1.0).clamp(-1.0, 1.0),
            rolling_resistance: mean(self.rolling_resistance, other.rolling_resistance),
        }
    }

    /// Whether a contact of this roughness can exert a tangential impulse.
    #[must_use]
    pub fn is_rough(self) -> bool {
        self.friction > 0.0 && self.tangential_restitution > -1.0
    }
}

impl Default for Roughness {
    fn default() -> Self {
        Roughness::SMOOTH
    }
}

/// One body's side of a rough contact: its velocity and spin, its mass, its moment of inertia
/// as a factor of `m r^2`, and its radius (the lever arm from its centre to the contact).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpinningBody {
    /// Velocity of the centre.
    pub velocity: DVec2,
    /// Angular velocity, counter-clockwise positive (radians per second).
    pub spin: f64,
    /// Mass, `> 0`.
    pub mass: f64,
    /// Moment of inertia over `m r^2`, `> 0` (a uniform disk 1/2, a ring 1).
    pub inertia: f64,
    /// Radius, `> 0`.
    pub radius: f64,
}

impl SpinningBody {
    /// `1/m (1 + 1/k)`: how much the tangential velocity of its contact point changes per unit
    /// of tangential impulse.
    fn compliance(&self) -> f64 {
        (1.0 + 1.0 / self.inertia) / self.mass
    }

    /// The velocity of its contact point along `t`, where the contact is at `side * r n`.
    fn tangential(&self, t: DVec2, side: f64) -> f64 {
        self.velocity.dot(t) + side * self.spin * self.radius
    }
}

/// The tangential impulse `J` (on body 2 along `t = perp(n)`; body 1 takes `-J t`) of a
/// contact whose bodies move as `a` and `b` (`None`: a static body) after a normal impulse of
/// `normal_impulse` (`>= 0`) along the unit normal `n` from body 1 to body 2.
#[must_use]
pub fn friction_impulse(
    a: &SpinningBody,
    b: Option<&SpinningBody>,
    n: DVec2,
    normal_impulse: f64,
    roughness: Roughness,
) -> f64 {
    if !roughness.is_rough() || !(normal_impulse > 0.0) {
        return 0.0;
    }
    let t = n.perp();
    let slip = a.tangential(t, 1.0) - b.map_or(0.0, |b| b.tangential(t, -1.0));
    let k = a.compliance() + b.map_or(0.0, SpinningBody::compliance);
    let stick = (1.0 + roughness.tangential_restitution) * slip.abs() / k;
    let cap = roughness.friction * normal_impulse;
    let magnitude = if stick <= cap { stick } else { cap };
    if !magnitude.is_finite() {
        return 0.0;
    }
    magnitude.copysign(slip)
}

/// Bodies `a` and `b` after the tangential impulse `impulse` of [`friction_impulse`] (on `b`
/// along `perp(n)`, on `a` against it): their velocities and spins.
#[must_use]
pub fn apply_friction(
    a: &SpinningBody,
    b: Option<&SpinningBody>,
    n: DVec2,
    impulse: f64,
) -> (SpinningBody, Option<SpinningBody>) {
    let t = n.perp();
    let turn = |body: &SpinningBody, sign: f64| SpinningBody {
        velocity: body.velocity + t * (sign * impulse / body.mass),
        spin: body.spin - impulse / (body.inertia * body.mass * body.radius),
        ..*body
    };
    (turn(a, -1.0), b.map(|b| turn(b, 1.0)))
}

/// A ball's spin: its angular velocity and angle at `t0` and their rate of change (nonzero
/// only while friction turns it on a surface, `dynamics/rolling.rs`), its moment of inertia
/// (a factor of `m r^2`) and its roughness.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Spin {
    /// When `angle` and `omega` were taken (the spin's last change).
    pub t0: Time,
    /// The angle at `t0`, in `[-pi, pi]`.
    pub angle: f64,
    /// Angular velocity at `t0`, counter-clockwise positive.
    pub omega: f64,
    /// Angular acceleration since `t0`.
    pub alpha: f64,
    /// Moment of inertia over `m r^2`.
    pub inertia: f64,
    /// The ball's surface.
    pub roughness: Roughness,
    /// On a table (`dynamics/table.rs`): the roll at `t0`, as the velocity it gives the
    /// contact point with the cloth; zero elsewhere.
    pub roll: DVec2,
    /// The roll's rate of change since `t0`.
    pub roll_rate: DVec2,
}

impl Spin {
    /// Whether the ball neither turns nor has a roughness or inertia of its own: a world of
    /// such balls keeps no spins.
    pub(crate) fn is_still(&self) -> bool {
        self.omega == 0.0
            && self.alpha == 0.0
            && self.roll == DVec2::ZERO
            && self.roll_rate == DVec2::ZERO
            && self.inertia == DEFAULT_INERTIA
            && self.roughness == Roughness::SMOOTH
    }

    /// A ball that does not turn: a uniform disk, frictionless.
    pub(crate) const STILL: Spin = Spin {
        t0: Time::ZERO,
        angle: 0.0,
        omega: 0.0,
        alpha: 0.0,
        inertia: DEFAULT_INERTIA,
        roughness: Roughness::SMOOTH,
        roll: DVec2::ZERO,
        roll_rate: DVec2::ZERO,
    };

    /// The angular velocity at time `t` (not before `t0`).
    pub(crate) fn omega_at(&self, t: Time) -> f64 {
        if self.alpha == 0.0 {
            return self.omega;
        }
        self.omega + self.alpha * t.since(self.t0)
    }

    /// The angle at time `t` (not before `t0`), in `[-pi, pi]`.
    pub(crate) fn angle_at(&self, t: Time) -> f64 {
        if self.omega == 0.0 && self.alpha == 0.0 {
            return self.angle;
        }
        let dt = t.since(self.t0);
        wrap(self.angle + dt * (self.omega + 0.5 * self.alpha * dt))
    }

    /// The roll at time `t` (not before `t0`), as the contact point's velocity.
    pub(crate) fn roll_at(&self, t: Time) -> DVec2 {
        if self.roll_rate == DVec2::ZERO {
            return self.roll;
        }
        self.roll + self.roll_rate * t.since(self.t0)
    }

    /// Restates the spin at time `t`.
    fn rebase(&mut self, t: Time) {
        (self.angle, self.omega) = (self.angle_at(t), self.omega_at(t));
        self.roll = self.roll_at(t);
        self.t0 = t;
    }

    /// Sets the roll (as the contact point's velocity) and its rate from time `t` on.
    pub(crate) fn set_roll(&mut self, t: Time, roll: DVec2, rate: DVec2) {
        self.rebase(t);
        (self.roll, self.roll_rate) = (roll, rate);
    }

    /// Sets the angle at time `t` (brought into `[-pi, pi]`); the spin goes on as it was.
    pub(crate) fn set_angle(&mut self, t: Time, angle: f64) {
        self.rebase(t);
        self.angle = wrap(angle);
    }

    /// Sets the angular velocity from time `t` on (the angle is carried over, the angular
    /// acceleration kept).
    pub(crate) fn set_omega(&mut self, t: Time, omega: f64) {
        self.rebase(t);
        self.omega = omega;
    }

    /// Sets the angular velocity and acceleration from time `t` on.
    pub(crate) fn set_motion(&mut self, t: Time, omega: f64, alpha: f64) {
        self.rebase(t);
        (self.omega, self.alpha) = (omega, alpha);
    }
}

/// The moment of inertia of a uniform disk, over `m r^2`: the default.
pub const DEFAULT_INERTIA: f64 = 0.5;

/// `angle` brought into `[-pi, pi]` (one remainder, exact, then one subtraction).
fn wrap(angle: f64) -> f64 {
    use std::f64::consts::{PI, TAU};
    if (-PI..=PI).contains(&angle) {
        return angle;
    }
    let r = angle % TAU;
    if r > PI {
        r - TAU
    } else if r < -PI {
        r + TAU
    } else {
        r
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn disk(velocity: DVec2, spin: f64) -> SpinningBody {
        SpinningBody {
            velocity,
            spin,
            mass: 1.0,
            inertia: 0.5,
            radius: 1.0,
        }
    }

    fn energy(body: &SpinningBody) -> f64 {
        let i = body.inertia * body.mass * body.radius * body.radius;
        0.5 * body.mass * body.velocity.length_squared() + 0.5 * i * body.spin * body.spin
    }

    #[test]
    fn a_sliding_disk_on_a_floor_sticks_and_rolls_when_friction_allows() {
        // A disk moving at 3 along a floor (normal from the disk down to the floor: n = -y),
        // not turning, pressed by a normal impulse of 10: sticking takes (1 + 0) 3 / 3 = 1.
        let a = disk(DVec2::new(3.0, 0.0), 0.0);
        let rough = Roughness {
            friction: 0.5,
            ..Roughness::SMOOTH
        };
        let j = friction_impulse(&a, None, -DVec2::Y, 10.0, rough);
        let (after, _) = apply_friction(&a, None, -DVec2::Y, j);
        // Rolling: the contact point at the bottom is still, v = -w r: 2 and -2.
        assert_eq!((after.velocity, after.spin), (DVec2::new(2.0, 0.0), -2.0));
        // With mu P = 0.5 the contact slides: the impulse is the cap.
        let j = friction_impulse(&a, None, -DVec2::Y, 1.0, rough);
        assert_eq!(j.abs(), 0.5);
        let (after, _) = apply_friction(&a, None, -DVec2::Y, j);
        assert_eq!((after.velocity.x, after.spin), (2.5, -1.0));
    }

    #[test]
    fn elastic_rough_collisions_keep_energy_and_sticking_loses_the_predicted_share() {
        let a = disk(DVec2::new(0.3, -1.2), 2.5);
        let b = SpinningBody {
            mass: 2.0,
            radius: 0.5,
            ..disk(DVec2::new(-0.7, 0.4), -1.0)
        };
        let n = DVec2::new(0.6, 0.8);
        for beta in [-1.0, -0.5, 0.0, 0.5, 1.0] {
            let rough = Roughness {
                friction: 1e9,
                tangential_restitution: beta,
                ..Roughness::SMOOTH
            };
            let j = friction_impulse(&a, Some(&b), n, 1.0, rough);
            let (a2, b2) = apply_friction(&a, Some(&b), n, j);
            let b2 = b2.unwrap();
            let t = n.perp();
            let slip = |a: &SpinningBody, b: &SpinningBody| {
                (a.velocity - b.velocity).dot(t) + a.spin * a.radius + b.spin * b.radius
            };
            let (g, g2) = (slip(&a, &b), slip(&a2, &b2));
            assert!((g2 + beta * g).abs() < 1e-14, "beta {beta}: {g} -> {g2}");
            let k = a.compliance() + b.compliance();
            let lost = energy(&a) + energy(&b) - energy(&a2) - energy(&b2);
            let predicted = (1.0 - beta * beta) * g * g / (2.0 * k);
            assert!((lost - predicted).abs() < 1e-14, "{lost} {predicted}");
            // Momentum and angular momentum about the origin (contact at 0).
            let p = a.velocity * a.mass + b.velocity * b.mass;
            let p2 = a2.velocity * a2.mass + b2.velocity * b2.mass;
            assert!((p - p2).length() < 1e-15);
        }
    }

    #[test]
    fn a_pairs_roughness_mixes_as_documented() {
        let r = |friction, tangential_restitution| Roughness {
            friction,
            tangential_restitution,
            ..Roughness::SMOOTH
        };
        assert_eq!(r(0.0, 0.5).pair(r(0.8, 0.5)), r(0.0, 0.5));
        assert_eq!(r(0.25, 0.0).pair(r(1.0, 0.0)), r(0.5, 0.0));
        assert_eq!(r(0.4, -1.0).pair(r(0.4, 1.0)).tangential_restitution, -1.0);
        assert_eq!(r(0.4, 1.0).pair(r(0.4, 1.0)).tangential_restitution, 1.0);
        assert!(!r(0.4, -1.0).pair(r(0.4, 1.0)).is_rough());
    }

    #[test]
    fn a_spin_is_104_bytes() {
        // Kept per ball only by worlds with spin or friction (ARCHITECTURE.md).
        assert_eq!(std::mem::size_of::<Spin>(), 104);
    }

    #[test]
    fn angles_wrap_and_carry_over() {
        let mut spin = Spin::STILL;
        spin.set_omega(Time::ZERO, 1.0);
        assert_eq!(spin.angle_at(Time::new(1.0)), 1.0);
        let a = spin.angle_at(Time::new(4.0));
        assert!((a - (4.0 - std::f64::consts::TAU)).abs() < 1e-15);
        spin.set_omega(Time::new(4.0), -2.0);
        let b = a - 2.0 + std::f64::consts::TAU;
        assert!((spin.angle_at(Time::new(5.0)) - b).abs() < 1e-15);
    }
}
