//! A ball on the cloth of a table seen from above (billiards, pool, air-less pucks with
//! friction): sliding, rolling and spinning, in closed form, with the time each phase ends.
//!
//! # The maths
//!
//! The plane of the world is the table; gravity `g` points into it (out of the world's
//! plane), so the world's own gravity is zero. A ball of radius `r`, mass `m` and moment of
//! inertia `k m r^2` (a solid sphere has `k = 2/5`) turns about the vertical axis at `w_z` (the
//! world's spin) and about the horizontal axes at `w_h` (its *roll*). Its contact point with
//! the cloth sits at `-r z` from the centre and moves at the *slip*
//!
//! ```text
//! u = v + r z x w_h = v + c,        c = r (-w_h.y, w_h.x)
//! ```
//!
//! (`c`, the contact point's velocity due to the roll, is what is stored: a rolling ball has
//! `c = -v` exactly, with no rounding of a division by `r`). The cloth pushes up with `m g`.
//!
//! *Sliding* (`u != 0`): kinetic friction `-mu_s m g u/|u|` acts at the contact point, so
//! `dv/dt = -mu_s g u^`, and its torque `(-r z) x F` turns the roll by
//! `dc/dt = -(mu_s g / k) u^`. Then `du/dt = -mu_s g (1 + 1/k) u^`: the slip keeps its
//! direction and shrinks at a constant rate, so every acceleration is constant for the phase
//! and the centre moves on a parabola. The slip vanishes at `|u0| / (mu_s g (1 + 1/k))`
//! (`2 |u0| / (7 mu_s g)` for a sphere, pooltool's transition), when the ball rolls at
//! `v0 - k u0 / (1 + k)`, `(5 v0 - 2 c0) / 7` for a sphere.
//!
//! *Rolling* (`u = 0`): the cloth's rolling resistance slows the ball at `mu_r g` along its
//! velocity, the roll following (`c = -v`); it stops at `|v0| / (mu_r g)` after
//! `|v0|^2 / (2 mu_r g)`.
//!
//! *Spinning*: the cloth resists a turn about the vertical with a torque `mu_sp m g r`
//! (pooltool's spinning friction, with its coefficient over the radius), so
//! `dw_z/dt = -mu_sp g / (k r)` against the spin, whatever the ball does besides, until the
//! spin stops at `|w_z0| k r / (mu_sp g)`.
//!
//! A phase ends at the first of its ends (the slip vanishes, the ball stops, the spin stops);
//! there the engine snaps what ended to its exact value (`c = -v`, `v = c = 0`, `w_z = 0`)
//! and takes the next phase from that state. At rest with no spin a ball has no phase.
//!
//! Sources: the sliding and rolling laws are the standard ones of billiards physics (Leckie
//! and Greenspan's event-based pool model, and pooltool's motion states, which use the same
//! three coefficients).

use glam::DVec2;

/// The cloth of a table seen from above: the world's plane is the table's, and these are the
/// friction coefficients between the cloth and every ball on it.
///
/// With a table, balls slide, roll and spin to rest on their own (see the module's maths):
/// each ball carries a *roll* (its angular velocity about the horizontal axes) besides its
/// spin about the vertical, and the world's gravity must be zero.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Table {
    /// The acceleration of gravity into the table, positive (9.81 in metres).
    pub gravity: f64,
    /// Coulomb's coefficient between a sliding ball and the cloth, `mu_s >= 0` (pool: 0.2).
    pub sliding_friction: f64,
    /// The rolling resistance of the cloth, `mu_r >= 0` (pool: 0.01).
    pub rolling_friction: f64,
    /// The spinning friction, `mu_sp >= 0`: a spin about the vertical slows at
    /// `mu_sp g / (k r)` (pool: about 0.0127 for a ball of radius 0.028575 m).
    pub spinning_friction: f64,
}

impl Table {
    /// A pool table's cloth, in metres and seconds: `g = 9.81`, `mu_s = 0.2`, `mu_r = 0.01`,
    /// `mu_sp = 0.0127` (pooltool's defaults for a ball of radius 0.028575 m).
    pub const POOL: Table = Table {
        gravity: 9.81,
        sliding_friction: 0.2,
        rolling_friction: 0.01,
        spinning_friction: 0.0127,
    };

    /// The first value out of its range, as `(name, value, range)`: gravity must be finite
    /// and positive, every coefficient finite and non-negative.
    pub(crate) fn invalid(&self) -> Option<(&'static str, f64, &'static str)> {
        if !(self.gravity > 0.0 && self.gravity.is_finite()) {
            return Some(("gravity", self.gravity, "finite and > 0"));
        }
        let coefficients = [
            ("sliding_friction", self.sliding_friction),
            ("rolling_friction", self.rolling_friction),
            ("spinning_friction", self.spinning_friction),
        ];
        coefficients
            .into_iter()
            .find(|(_, x)| !(*x >= 0.0 && x.is_finite()))
            .map(|(name, x)| (name, x, "finite and >= 0"))
    }
}

/// A ball on the cloth now: its velocity, the contact point's velocity due to its roll, its
/// spin about the vertical, radius and moment of inertia over `m r^2`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct OnCloth {
    pub v: DVec2,
    pub c: DVec2,
    pub w: f64,
    pub radius: f64,
    pub inertia: f64,
}

/// One phase of a ball on the cloth: constant accelerations, and when it ends.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct ClothPhase {
    /// The centre's acceleration.
    pub accel: DVec2,
    /// `dc/dt`, the roll's rate of change (as the contact point's velocity).
    pub roll_rate: DVec2,
    /// The spin's rate of change.
    pub alpha: f64,
    /// How long until the slip vanishes (sliding) or the ball stops (rolling), if ever.
    pub translation_end: Option<f64>,
    /// How long until the spin stops, if ever.
    pub spin_end: Option<f64>,
    /// Whether the ball rolls (`c = -v`).
    pub rolling: bool,
    /// How far the acceleration may point off its true direction, as an acceleration: the
    /// rounding of the slip (or of the velocity, rolling) it is opposed to, a few ulps of the
    /// speeds it is formed from, `4 eps max(|v|, |c|) / |u|` of `|accel|` (at most
    /// [`PARALLEL`](super::PARALLEL) of it, which it reaches at [`SLIP_RESOLUTION`]). A pull
    /// into a cushion beyond this is the cloth's, not rounding's (see
    /// [`Touch::holds_within`](super::Touch::holds_within)).
    pub slack: f64,
}

impl ClothPhase {
    /// When the phase ends: the first of its ends.
    pub(crate) fn end(&self) -> Option<f64> {
        super::sooner(self.translation_end, self.spin_end)
    }
}

/// A slip below this fraction of the speeds it is formed from (`|v|`, `|c|`) has no
/// direction the engine can trust, and ends at once (the ball rolls, as the slide would leave
/// it, see [`OnCloth::rolled`]): `4 eps / PARALLEL`, about `8.9e-7`. The slip's rounding is a
/// few ulps of those speeds, so below this its direction is uncertain by more than
/// [`PARALLEL`](super::PARALLEL), the sine below which the engine calls two directions
/// parallel; a friction along such a direction would press a ball into a cushion it slides
/// along by rounding alone, at every event. The slide so cut short would have lasted
/// `|u| / (mu_s g (1 + 1/k))`, and the ball ends where it would within `|u|^2 / (mu_s g)`
/// (`1e-13` of the speeds squared over `mu_s g`).
pub(crate) const SLIP_RESOLUTION: f64 = 4.0 * f64::EPSILON / super::PARALLEL;

impl OnCloth {
    /// The slip `v + c`, or zero if it has no direction to trust (see
    /// [`SLIP_RESOLUTION`]).
    pub(crate) fn slip(&self) -> DVec2 {
        let u = self.v + self.c;
        let scale = self.v.length().max(self.c.length());
        if u.length() <= SLIP_RESOLUTION * scale {
            DVec2::ZERO
        } else {
            u
        }
    }

    /// The ball as its slide would leave it, rolling: `v' = (v - k c) / (1 + k)`, `c' = -v'`
    /// (linear momentum and angular momentum about the contact point kept). Applied at once
    /// to a slip below [`SLIP_RESOLUTION`]; it takes `k m |u|^2 / (2 (1 + k))` of energy, as
    /// the slide would.
    pub(crate) fn rolled(&self) -> Self {
        let k = self.inertia;
        let v = (self.v - self.c * k) / (1.0 + k);
        Self { v, c: -v, ..*self }
    }

    /// The phase the ball is in on `table`, or `None` at rest (no motion, no roll, no spin).
    pub(crate) fn phase(&self, table: &Table) -> Option<ClothPhase> {
        let g = table.gravity;
        let u = self.slip();
        if self.v == DVec2::ZERO && u == DVec2::ZERO && self.w == 0.0 {
            return None;
        }
        let (accel, roll_rate, translation_end, rolling, slack) = if u != DVec2::ZERO {
            let mu = table.sliding_friction;
            let (length, direction) = (u.length(), u / u.length());
            let decel = mu * g;
            let slip_rate = decel * (1.0 + 1.0 / self.inertia);
            let scale = self.v.length().max(self.c.length());
            (
                -direction * decel,
                -direction * (decel / self.inertia),
                (slip_rate > 0.0).then(|| length / slip_rate),
                false,
                decel * (4.0 * f64::EPSILON * scale / length),
            )
        } else if self.v != DVec2::ZERO {
            let decel = table.rolling_friction * g;
            let (speed, direction) = (self.v.length(), self.v / self.v.length());
            (
                -direction * decel,
                direction * decel,
                (decel > 0.0).then(|| speed / decel),
                true,
                decel * 4.0 * f64::EPSILON,
            )
        } else {
            (DVec2::ZERO, DVec2::ZERO, None, true, 0.0)
        };
        let spin_decel = table.spinning_friction * g / (self.inertia * self.radius);
        let (alpha, spin_end) = if self.w != 0.0 && spin_decel > 0.0 {
            (
                -self.w.signum() * spin_decel,
                Some(self.w.abs() / spin_decel),
            )
        } else {
            (0.0, None)
        };
        Some(ClothPhase {
            accel,
            roll_rate,
            alpha,
            translation_end,
            spin_end,
            rolling,
            slack,
        })
    }
}

/// The contact point's velocity `c = r (-w_h.y, w_h.x)` of a roll `w_h` (radians per second
/// about the horizontal axes) for a ball of radius `r`.
pub(crate) fn contact_velocity(roll: DVec2, radius: f64) -> DVec2 {
    DVec2::new(-roll.y, roll.x) * radius
}

/// The roll `w_h` of a contact point's velocity `c` (the inverse of [`contact_velocity`]).
pub(crate) fn roll_of(c: DVec2, radius: f64) -> DVec2 {
    // (`+ 0.0` turns a `-0.0` of the negation into `0.0`, so a ball without roll reads 0.)
    DVec2::new(c.y, -c.x) / radius + DVec2::ZERO
}

#[cfg(test)]
mod tests {
    use super::*;

    const SPHERE: f64 = 0.4;

    fn ball(v: DVec2, c: DVec2, w: f64) -> OnCloth {
        OnCloth {
            v,
            c,
            w,
            radius: 0.5,
            inertia: SPHERE,
        }
    }

    #[test]
    fn a_stun_shot_slides_for_two_sevenths_of_its_slip_over_mu_g_then_rolls_at_five_sevenths() {
        let table = Table {
            gravity: 10.0,
            sliding_friction: 0.2,
            rolling_friction: 0.0,
            spinning_friction: 0.0,
        };
        let b = ball(DVec2::new(3.5, 0.0), DVec2::ZERO, 0.0);
        let p = b.phase(&table).unwrap();
        let t = p.translation_end.unwrap();
        assert!((t - 2.0 * 3.5 / (7.0 * 0.2 * 10.0)).abs() < 1e-15);
        let v = b.v + p.accel * t;
        let c = b.c + p.roll_rate * t;
        assert!((v.x - 2.5).abs() < 1e-14 && v.y == 0.0);
        // Rolling then: the contact point is still.
        assert!((v + c).length() < 1e-14);
        assert!(!p.rolling && p.end() == Some(t));
    }

    #[test]
    fn a_rolling_ball_stops_under_rolling_friction_and_a_spin_under_spinning_friction() {
        let table = Table {
            gravity: 10.0,
            sliding_friction: 0.2,
            rolling_friction: 0.01,
            spinning_friction: 0.02,
        };
        let v = DVec2::new(0.6, -0.8);
        let b = ball(v, -v, 3.0);
        let p = b.phase(&table).unwrap();
        assert!(p.rolling);
        assert_eq!(p.translation_end, Some(1.0 / 0.1));
        // The spin slows at mu_sp g / (k r) = 0.2 / 0.2 = 1.
        assert!((p.alpha + 1.0).abs() < 1e-15);
        assert!((p.spin_end.unwrap() - 3.0).abs() < 1e-15);
        assert_eq!(p.end(), p.spin_end);
        // The roll follows the velocity.
        assert_eq!(p.roll_rate, -p.accel);
    }

    #[test]
    fn a_slip_too_small_to_point_anywhere_rolls_at_once_losing_energy() {
        let table = Table::POOL;
        let v = DVec2::new(1.0, 0.5);
        let b = ball(v, -v + DVec2::new(1e-9, -3e-10), 0.0);
        assert!(b.phase(&table).unwrap().rolling);
        let r = b.rolled();
        assert_eq!(r.c, -r.v);
        let energy = |b: &OnCloth| b.v.length_squared() + SPHERE * b.c.length_squared();
        // The slide's loss, k |u|^2 / (1 + k) here, is below the rounding of the energy.
        assert!(energy(&r) <= energy(&b) * (1.0 + 4.0 * f64::EPSILON));
        // A slip the engine can point is a slide.
        let b = ball(v, -v + DVec2::new(1e-5, 0.0), 0.0);
        assert!(!b.phase(&table).unwrap().rolling);
    }

    #[test]
    fn at_rest_without_spin_there_is_no_phase_and_a_roll_alone_sets_the_ball_moving() {
        let table = Table::POOL;
        assert_eq!(ball(DVec2::ZERO, DVec2::ZERO, 0.0).phase(&table), None);
        let p = ball(DVec2::ZERO, DVec2::new(1.0, 0.0), 0.0)
            .phase(&table)
            .unwrap();
        assert!(p.accel.x < 0.0 && !p.rolling);
    }

    #[test]
    fn the_roll_and_the_contact_velocity_are_inverse() {
        let roll = DVec2::new(2.0, -3.0);
        let c = contact_velocity(roll, 0.5);
        // Rolling along +x at speed 1 with radius 0.5 turns about +y at 2.
        assert_eq!(
            contact_velocity(DVec2::new(0.0, 2.0), 0.5),
            DVec2::new(-1.0, 0.0)
        );
        assert_eq!(roll_of(c, 0.5), roll);
    }

    #[test]
    fn a_table_names_its_first_bad_value() {
        let bad = Table {
            rolling_friction: -1.0,
            ..Table::POOL
        };
        assert_eq!(
            bad.invalid(),
            Some(("rolling_friction", -1.0, "finite and >= 0"))
        );
        assert_eq!(Table::POOL.invalid(), None);
        let flat = Table {
            gravity: 0.0,
            ..Table::POOL
        };
        assert_eq!(flat.invalid().map(|x| x.0), Some("gravity"));
    }
}
