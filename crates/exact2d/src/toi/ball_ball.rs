//! Ball against ball.

use glam::DVec2;

use crate::roots::first_contact;

/// The first time in `[0, horizon]` at which two balls touch, given their positions and
/// velocities now.
///
/// Both balls feel the same gravity, so their relative motion is straight:
/// `|q + v t|^2 - (r1 + r2)^2 = |v|^2 t^2 + 2 (q.v) t + |q|^2 - (r1 + r2)^2` with
/// `q = p2 - p1`, `v = v2 - v1`, a quadratic solved in closed form. The result is bit for bit
/// the same with the balls swapped (negating `q` and `v` is exact), so a pair predicted from
/// either side agrees.
///
/// Follows the touching-contact policy of [`crate::toi`]: touching and approaching is
/// `Some(0.0)`; touching and separating or tangential is no event now.
#[must_use]
pub fn time_of_impact_ball_ball(
    p1: DVec2,
    v1: DVec2,
    r1: f64,
    p2: DVec2,
    v2: DVec2,
    r2: f64,
    horizon: f64,
) -> Option<f64> {
    let q = p2 - p1;
    let v = v2 - v1;
    let r = r1 + r2;
    let (a, b, c) = (v.dot(v), q.dot(v), q.dot(q) - r * r);
    // Approaching from apart, the contact comes no sooner than `c / (-2 b)` (the root
    // `c / (sqrt(d) - b)` has `sqrt(d) <= -b`): a bound past the horizon (with room for
    // rounding) rules it out before the discriminant is formed.
    if b < 0.0 && c > 0.0 {
        let soonest = c / (-2.0 * b);
        if soonest > f64::MIN_POSITIVE && soonest > horizon * (1.0 + 1e-9) {
            return None;
        }
    }
    let t = first_contact(a, b, c)?;
    (t <= horizon).then_some(t)
}
