//! A ball's closed-form path between events.

use glam::DVec2;

use super::Time;
use super::time::two_sum;
use crate::toi::Motion;

/// A ball's path since its last event: position `p0` and velocity `v0` at time `t0`, then
/// `p(t) = p0 + v0 (t - t0) + g (t - t0)^2 / 2` under the world's gravity `g`.
///
/// The world stores only this and evaluates it on demand, so advancing the clock costs
/// nothing and gives the same bits however time is sliced into frames. A trajectory is
/// *rebased* (a new `p0`, `v0`, `t0`) only when the ball's own event happens. `t0` is an exact
/// [`Time`], so the precision of `t - t0` does not depend on how large `t` is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Trajectory {
    /// Position at `t0`.
    pub p0: DVec2,
    /// Velocity at `t0`.
    pub v0: DVec2,
    /// The time of the last event (or of creation).
    pub t0: Time,
}

impl Trajectory {
    /// The position at time `t`.
    ///
    /// Under gravity the displacement is summed first and added to `p0` once: one rounding at
    /// the coordinates' magnitude. Added in two steps, the gravity term (often under half a
    /// unit in the last place there) was rounded away or up at every event the same way: a
    /// ball at x = 1e6 sliding beside another, restated at every micro-hop of a ball on top of
    /// it, drifted 4.8e-7 a second into its neighbour, with no event to see it.
    #[must_use]
    #[inline]
    pub fn position_at(&self, t: Time, gravity: DVec2) -> DVec2 {
        self.p0 + self.displacement(t.since(self.t0), gravity)
    }

    /// The displacement `dt` after `t0`, summed before it is added to a position.
    #[inline]
    fn displacement(&self, dt: f64, gravity: DVec2) -> DVec2 {
        // Skipped without gravity: past dt = 1.3e154, dt^2 overflows and 0 * inf is NaN.
        if gravity == DVec2::ZERO {
            self.v0 * dt
        } else {
            self.v0 * dt + gravity * (0.5 * dt * dt)
        }
    }

    /// The velocity at time `t`.
    #[must_use]
    #[inline]
    pub fn velocity_at(&self, t: Time, gravity: DVec2) -> DVec2 {
        if gravity == DVec2::ZERO {
            self.v0
        } else {
            self.v0 + gravity * t.since(self.t0)
        }
    }

    /// The motion from time `t` on, with `t` as its zero.
    #[must_use]
    #[inline]
    pub fn motion_at(&self, t: Time, gravity: DVec2) -> Motion {
        Motion {
            position: self.position_at(t, gravity),
            velocity: self.velocity_at(t, gravity),
            acceleration: gravity,
        }
    }

    /// The same path, restated from time `t`.
    #[must_use]
    pub fn rebased(&self, t: Time, gravity: DVec2) -> Self {
        Self {
            p0: self.position_at(t, gravity),
            v0: self.velocity_at(t, gravity),
            t0: t,
        }
    }

    /// [`Self::rebased`] for a path whose `p0` left out `residual` (what its rounding lost,
    /// under half a unit in its last place): the displacement to `t` is summed with the
    /// residual before it is added to `p0`, and the new path's residual is that addition's
    /// rounding error, exactly (Knuth's two-sum). Restated so, a ball whose every restatement
    /// moves it by less than half an ulp in one coordinate still moves: the parts accumulate
    /// until they carry `p0` on, where rounding each away froze that coordinate (see
    /// ARCHITECTURE.md, "The frozen component").
    #[must_use]
    pub(crate) fn rebased_carrying(
        &self,
        t: Time,
        gravity: DVec2,
        residual: DVec2,
    ) -> (Self, DVec2) {
        let d = residual + self.displacement(t.since(self.t0), gravity);
        let (x, ex) = two_sum(self.p0.x, d.x);
        let (y, ey) = two_sum(self.p0.y, d.y);
        let path = Self {
            p0: DVec2::new(x, y),
            v0: self.velocity_at(t, gravity),
            t0: t,
        };
        (path, DVec2::new(ex, ey))
    }
}
