//! Ball against a fixed point: a segment's end point, or (with a summed radius) a static circle.

use glam::DVec2;

use super::{Crossing, Motion};
use crate::roots::{ParabolicGap, first_contact, first_descent};

/// The first time in `[0, horizon]` at which a ball of `radius` moving with `motion` touches
/// (`Crossing::Enter`) or stops overlapping (`Crossing::Exit`) the fixed `point`.
///
/// Straight motion: the squared gap `|q + v t|^2 - r^2 = |v|^2 t^2 + 2 (q.v) t + |q|^2 - r^2`,
/// with `q` the ball's position relative to the point, is a quadratic solved in closed form.
/// Under acceleration it is a quartic, whose roots are isolated and refined to the first
/// representable time of contact (see [`ParabolicGap`]).
///
/// Follows the touching-contact policy of [`crate::toi`]: touching and approaching is
/// `Some(0.0)`; touching and separating or tangential is no event now. `None` if there is no
/// crossing by `horizon` (which may be `f64::INFINITY`).
#[must_use]
pub fn time_of_impact_ball_point(
    motion: &Motion,
    point: DVec2,
    radius: f64,
    crossing: Crossing,
    horizon: f64,
) -> Option<f64> {
    point_crossing(motion, point, radius, crossing, horizon, true, |_| true)
}

/// [`time_of_impact_ball_point`], with the touching-contact policy switched on or off, for the
/// first crossing whose time `accept`s. Without the policy, only a crossing from the far side
/// counts (`Enter`: from outside; `Exit`: from inside): a segment applies the policy only to the
/// feature (interior or end point) whose region holds the ball's centre now, and accepts an
/// end-point crossing only where the ball projects beyond that end.
///
/// `#[inline]`: a segment's end points ask it on the hot path of every prediction against a
/// segment, and whether a generic's copy may be inlined otherwise depends on the codegen unit
/// the copy falls into (an unrelated change elsewhere once moved it out of line and cost a
/// brick board 6 % of its instructions).
#[inline]
pub(crate) fn point_crossing<A: Fn(f64) -> bool>(
    motion: &Motion,
    point: DVec2,
    radius: f64,
    crossing: Crossing,
    horizon: f64,
    touching_policy: bool,
    accept: A,
) -> Option<f64> {
    let q = motion.position - point;
    let v = motion.velocity;
    // Leaving is the first descent of the negated gap.
    let sign = match crossing {
        Crossing::Enter => 1.0,
        Crossing::Exit => -1.0,
    };
    if motion.acceleration == DVec2::ZERO {
        let (a, b, c) = (
            sign * v.dot(v),
            sign * q.dot(v),
            sign * (q.dot(q) - radius * radius),
        );
        // A quadratic crosses zero at most once in each direction: one candidate.
        let t = if touching_policy {
            first_contact(a, b, c)
        } else {
            first_descent(a, b, c)
        }?;
        return (t <= horizon && accept(t)).then_some(t);
    }
    let gap = ParabolicGap {
        q,
        v,
        g: motion.acceleration,
        radius,
    };
    gap.first_crossing(sign, horizon, touching_policy, accept)
}
