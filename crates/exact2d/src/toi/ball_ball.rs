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
    } else if b >= 0.0 && c > 0.0 && a > 0.0 {
        // Apart and not approaching: never (as `first_contact` decides, without its call;
        // about half of a gas's candidates).
        return None;
    }
    let t = first_contact(a, b, c)?;
    (t <= horizon).then_some(t)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The kernel's shortcuts (the bound past the horizon, the pair apart and not
    /// approaching) decide exactly as the plain formula, over random and touching pairs.
    #[test]
    fn shortcuts_agree_with_the_plain_formula() {
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        for k in 0..200_000 {
            let scale = [1e-6, 1.0, 1e3][k % 3];
            let p1 = DVec2::new(next(), next()) * scale;
            let v1 = DVec2::new(next(), next()) * [0.0, 1.0, 1e2][k / 3 % 3];
            let v2 = DVec2::new(next(), next());
            let (r1, r2) = (
                (next().abs() + 0.01) * 0.3 * scale,
                (next().abs() + 0.01) * 0.3 * scale,
            );
            // One in four pairs touching (to rounding), the rest anywhere near.
            let p2 = if k % 4 == 0 {
                p1 + DVec2::from_angle(next() * 3.2) * (r1 + r2)
            } else {
                DVec2::new(next(), next()) * scale
            };
            let horizon = [f64::INFINITY, 0.0, next().abs(), next().abs() * 1e-3][k / 9 % 4];
            let (q, v, r) = (p2 - p1, v2 - v1, r1 + r2);
            let plain =
                first_contact(v.dot(v), q.dot(v), q.dot(q) - r * r).filter(|&t| t <= horizon);
            let kernel = time_of_impact_ball_ball(p1, v1, r1, p2, v2, r2, horizon);
            assert_eq!(
                kernel.map(f64::to_bits),
                plain.map(f64::to_bits),
                "pair {k}: {p1} {v1} {r1} / {p2} {v2} {r2} by {horizon}"
            );
        }
    }
}
