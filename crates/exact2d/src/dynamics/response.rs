//! Collision response: reflection off static shapes, impulse exchange between balls.
//!
//! Both take contact normals that need not be unit vectors. Dividing by `n.n` instead of
//! normalising first keeps each formula exactly energy-conserving in real arithmetic for any
//! `n`: with a normalised `n` whose length is `1 + δ`, every elastic bounce off the same wall
//! would change the energy by about `4δ` times the normal part, always with the same sign, a
//! drift that adds up over millions of bounces instead of averaging out.

use glam::DVec2;

/// The velocity after a ball with velocity `v` hits a static surface with normal `n` (pointing
/// from the surface to the ball, any length) and coefficient of restitution `restitution`.
///
/// `v' = v - (1 + e) (v.n / n.n) n`: the normal component is reversed and scaled by `e`, the
/// tangential one is kept. A ball that is not approaching (`v.n >= 0`) is returned unchanged,
/// so a response can never pull a ball into a surface or add energy.
#[must_use]
#[inline]
pub fn reflect(v: DVec2, n: DVec2, restitution: f64) -> DVec2 {
    let vn = v.dot(n);
    if vn >= 0.0 {
        return v;
    }
    v - n * ((1.0 + restitution) * vn / n.dot(n))
}

/// The velocities after two balls collide: `v1`, `m1` and `v2`, `m2`, with `n` pointing from
/// ball 1's centre to ball 2's (any length) and coefficient of restitution `restitution`.
///
/// The impulse acts along `n`. With `u = (v1 - v2).n / n.n` the approach rate, the relative
/// normal velocity goes from `u n` to `-e u n`, and momentum is conserved:
///
/// ```text
/// v1' = v1 - (1 + e) u  m2 / (m1 + m2)  n
/// v2' = v2 + (1 + e) u  m1 / (m1 + m2)  n
/// ```
///
/// With `e = 1` this conserves kinetic energy too. Balls that are not approaching (`u <= 0`)
/// are returned unchanged.
#[must_use]
#[inline]
pub fn collide_balls(
    v1: DVec2,
    m1: f64,
    v2: DVec2,
    m2: f64,
    n: DVec2,
    restitution: f64,
) -> (DVec2, DVec2) {
    let approach = (v1 - v2).dot(n);
    if approach <= 0.0 {
        return (v1, v2);
    }
    let k = (1.0 + restitution) * approach / n.dot(n);
    let (m1, m2) = finite_sum(m1, m2);
    let total = m1 + m2;
    (v1 - n * (k * (m2 / total)), v2 + n * (k * (m1 / total)))
}

#[must_use]
/// A collision of ball 1 (touching a wall of unit normal `wall`, from the wall to the ball)
/// with ball 2, resolved together with the wall's contact if the collision alone would drive
/// ball 1 into the wall: then the pair separates at `restitution` times their approach and
/// ball 1 stops moving into the wall (two impulses solving both conditions at once).
///
/// The world uses it in inelastic zero-time chains (a ball collided with the wall at this very
/// instant): in sequence, the two contacts would repeat at one instant, the pair's approach
/// shrinking by a factor near `m2 / (m1 + m2)` a round: millions of events for a light ball
/// pressed by a heavy one (measured: more than 3e6 for masses 1e-3 and 1).
pub fn collide_balls_backed(
    v1: DVec2,
    m1: f64,
    v2: DVec2,
    m2: f64,
    n: DVec2,
    restitution: f64,
    wall: DVec2,
) -> (DVec2, DVec2) {
    rebound_backed(v1, m1, v2, m2, n, restitution, 0.0, wall)
}

/// Two masses halved (exactly) if their sum would overflow, so that the ratios `m / (m1 + m2)`
/// stay right for masses near `f64::MAX`; unchanged otherwise.
#[inline]
fn finite_sum(m1: f64, m2: f64) -> (f64, f64) {
    if (m1 + m2).is_finite() {
        (m1, m2)
    } else {
        (m1 * 0.5, m2 * 0.5)
    }
}

/// [`collide_balls`], with the balls leaving each other at least at `floor` (the impulse may
/// then add a little energy: the world's micro-hop floor, `MICRO_HOP`).
pub(crate) fn rebound(
    v1: DVec2,
    m1: f64,
    v2: DVec2,
    m2: f64,
    n: DVec2,
    restitution: f64,
    floor: f64,
) -> (DVec2, DVec2) {
    if !(floor > 0.0) {
        return collide_balls(v1, m1, v2, m2, n, restitution);
    }
    let unit = n / n.length();
    let approach = (v1 - v2).dot(unit);
    let target = (restitution * approach).max(floor);
    // The change of the relative normal velocity, from -approach to target.
    let change = target + approach;
    if !(change > 0.0) {
        return (v1, v2);
    }
    let (m1, m2) = finite_sum(m1, m2);
    let total = m1 + m2;
    (
        v1 - unit * (change * (m2 / total)),
        v2 + unit * (change * (m1 / total)),
    )
}

/// [`collide_balls_backed`] with the separation floor of [`rebound`].
#[allow(clippy::too_many_arguments)]
pub(crate) fn rebound_backed(
    v1: DVec2,
    m1: f64,
    v2: DVec2,
    m2: f64,
    n: DVec2,
    restitution: f64,
    floor: f64,
    wall: DVec2,
) -> (DVec2, DVec2) {
    let alone = rebound(v1, m1, v2, m2, n, restitution, floor);
    if alone.0.dot(wall) >= 0.0 {
        // The collision alone leaves ball 1 off the wall: the wall does nothing.
        return alone;
    }
    let unit = n / n.length();
    let approach = (v1 - v2).dot(unit);
    let change = approach + (restitution * approach).max(floor);
    let (c, into) = (unit.dot(wall), v1.dot(wall));
    let denominator = 1.0 / m1 + 1.0 / m2 - c * c / m1;
    let pair = (change - c * into) / denominator;
    let push = pair * c - m1 * into;
    if !(pair > 0.0 && push >= 0.0 && denominator > 0.0) {
        return alone;
    }
    let after = (
        v1 + (wall * push - unit * pair) / m1,
        v2 + unit * (pair / m2),
    );
    // Asked to separate at the restitution times an approach that the wall then takes part
    // of (ball 1 moving off the wall into ball 2), the pair could leave with more energy than
    // it came with: then the impact is perfectly plastic, which never adds any.
    let kinetic = |a: DVec2, b: DVec2| m1 * a.length_squared() + m2 * b.length_squared();
    if restitution > 0.0 && kinetic(after.0, after.1) > kinetic(v1, v2) {
        return rebound_backed(v1, m1, v2, m2, n, 0.0, floor, wall);
    }
    after
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reflection_off_an_axis_aligned_wall_is_exact() {
        let v = reflect(DVec2::new(0.3, -0.7), DVec2::new(0.0, 1.0), 1.0);
        assert_eq!(v, DVec2::new(0.3, 0.7));
    }

    #[test]
    fn restitution_scales_the_normal_component_only() {
        let v = reflect(DVec2::new(2.0, -4.0), DVec2::new(0.0, 3.0), 0.5);
        assert_eq!(v, DVec2::new(2.0, 2.0));
    }

    #[test]
    fn a_separating_ball_is_left_alone() {
        let v = DVec2::new(1.0, 1.0);
        assert_eq!(reflect(v, DVec2::Y, 1.0), v);
    }

    #[test]
    fn a_ball_backed_by_a_wall_stops_the_ball_that_hits_it_when_perfectly_inelastic() {
        // Ball 1 touches a wall above it (normal -y); ball 2 hits it from below at 1.
        let wall = DVec2::new(0.0, -1.0);
        let (a, b) = collide_balls_backed(DVec2::ZERO, 0.001, DVec2::Y, 1.0, -DVec2::Y, 0.0, wall);
        assert_eq!((a, b), (DVec2::ZERO, DVec2::ZERO));
        // With restitution 1/2 the pair separates at half its approach; ball 1 stays put.
        let (a, b) = collide_balls_backed(DVec2::ZERO, 1.0, DVec2::Y, 1.0, -DVec2::Y, 0.5, wall);
        assert!(a.length() < 1e-15 && (b.y + 0.5).abs() < 1e-15, "{a} {b}");
        // Hit sideways, it is not pushed into the wall: an ordinary collision.
        let (a, b) = collide_balls_backed(DVec2::ZERO, 1.0, DVec2::X, 1.0, -DVec2::X, 1.0, wall);
        assert_eq!(
            (a, b),
            collide_balls(DVec2::ZERO, 1.0, DVec2::X, 1.0, -DVec2::X, 1.0)
        );
    }

    #[test]
    fn a_backed_collision_never_adds_energy() {
        // Ball 1 touches a wall behind it (normal +x) but moves off it, into ball 2, which
        // comes the other way: asked to separate at 0.9 of their approach of 1 with ball 1
        // pinned, ball 2 would leave at 0.9 where it came at 0.5.
        let wall = DVec2::X;
        let (v1, v2) = (DVec2::new(0.5, 0.0), DVec2::new(-0.5, 0.0));
        let (a, b) = collide_balls_backed(v1, 1.0, v2, 1.0, DVec2::X, 0.9, wall);
        let energy = |a: DVec2, b: DVec2| a.length_squared() + b.length_squared();
        assert!(energy(a, b) <= energy(v1, v2), "{a} {b}");
        assert!(a.x >= 0.0 && b.x - a.x >= -1e-15, "{a} {b}");
    }

    #[test]
    fn equal_masses_head_on_exchange_velocities_exactly() {
        let (a, b) = collide_balls(DVec2::X, 1.0, -DVec2::X, 1.0, DVec2::new(2.0, 0.0), 1.0);
        assert_eq!((a, b), (-DVec2::X, DVec2::X));
    }

    #[test]
    fn unequal_masses_follow_the_textbook_one_dimensional_formula() {
        // v1' = (m1 - m2) / (m1 + m2) v1 = -1/3, v2' = 2 m1 / (m1 + m2) v1 = 2/3.
        let (a, b) = collide_balls(DVec2::X, 1.0, DVec2::ZERO, 2.0, DVec2::X, 1.0);
        assert!((a.x + 1.0 / 3.0).abs() < 1e-15 && (b.x - 2.0 / 3.0).abs() < 1e-15);
        let momentum = a.x + 2.0 * b.x;
        let energy = a.x * a.x + 2.0 * b.x * b.x;
        assert!((momentum - 1.0).abs() < 1e-15 && (energy - 1.0).abs() < 1e-15);
    }
}
