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
    let total = m1 + m2;
    (v1 - n * (k * (m2 / total)), v2 + n * (k * (m1 / total)))
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
